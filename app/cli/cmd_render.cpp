// frictionviz render: every figure of the paper (or a scene of any parameters) as PNG + CSV, headless.
#include "commands.hpp"
#include "errors.hpp"
#include "model_options.hpp"
#include "output.hpp"
#include "render_output.hpp"
#include "test_hook.hpp"

#include "figures/render_session.hpp"

#include "fv/atomic_file.hpp"
#include "fv/figure_data.hpp"
#include "fv/figures.hpp"
#include "fv/fit_figure.hpp"
#include "fv/measurements.hpp"

#include "fv/gfx/png.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <deque>
#include <future>
#include <memory>
#include <optional>
#include <sstream>
#include <thread>

namespace fv::cli {
namespace {

struct Size {
    int w = 1280, h = 800;
};

constexpr int kMinW = 320, kMinH = 240, kMaxW = 7680, kMaxH = 4320;

// PNG encodings run in parallel as long as their frames fit in this budget: each holds about two frames (the
// pixels and stb's filtered copy of them). At least one runs, at most one per core: 2 at 1280x800 (3.9 MiB
// frames), 1 above 2^20 pixels (1920x1080, 7680x4320). tests/reliability/render_memory_test.cpp holds the
// growth of memory with the number of figures to this budget plus one frame.
constexpr std::size_t kEncodeBudget = std::size_t{16} << 20;

std::size_t encoders_for(int w, int h) {
    const std::size_t job = std::size_t{2} * static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 4;
    const std::size_t cores = std::max(1u, std::thread::hardware_concurrency());
    return std::clamp<std::size_t>(kEncodeBudget / job, 1, cores);
}

CLI::Validator size_spec() {
    return CLI::Validator(
        [](std::string& s) -> std::string {
            int w = 0, h = 0;
            char x = 0, extra = 0;
            std::ostringstream allowed;
            allowed << "allowed: WxH with W in [" << kMinW << ", " << kMaxW << "] and H in [" << kMinH << ", "
                    << kMaxH << "]";
            if (std::sscanf(s.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || (x != 'x' && x != 'X'))
                return "'" + s + "' is not a size; " + allowed.str();
            if (w < kMinW || w > kMaxW || h < kMinH || h > kMaxH)
                return "'" + s + "' is out of range; " + allowed.str();
            return {};
        },
        "WxH");
}

std::string csv_of(const TableData& t) {
    if (!t.text.empty()) return t.text;
    if (!t.ratios.empty()) return ratio_table(t.ratios, Format::csv);
    SweepPoint row;
    row.result.period = t.trace;
    row.result.status = t.status;
    return trace_table(row, Format::csv);
}

// The numerical failures behind one figure: ratio rows (the map's grid too) carry the solver's status per
// point, trace tables the status of their steady period (and values that are not finite count as failed).
// Prints one stderr line per failure (at most a few rows per table) and returns a one-line summary, empty
// when nothing failed.
std::string check_figure(const FigureData& fig, const FitResult* fit) {
    std::vector<std::string> what;
    for (const TableData& t : fig.tables) {
        const std::string name = fig.id + t.suffix;
        if (!t.ratios.empty()) {
            if (const Failures f = failures_of(t.ratios); f.count > 0) {
                print_failures(t.ratios, name + ": ", 5);
                what.push_back(name + ": " + std::to_string(f.count) + " of " +
                               std::to_string(t.ratios.size()) + " points (" + f.by_reason + ")");
            }
        } else if (!t.trace.empty()) {
            const SteadyStatus st =
                ok(t.status) && !all_finite(t.trace) ? SteadyStatus::non_finite : t.status;
            if (ok(st)) continue;
            std::fprintf(stderr, "frictionviz: %s: failed: %s: the steady period drawn is not verified\n",
                         name.c_str(), to_string(st));
            what.push_back(name + ": the steady period (" + to_string(st) + ")");
        }
    }
    if (fit)
        for (const FitCandidate& c : fit->candidates)
            if (c.unsteady > 0) {
                std::fprintf(stderr,
                             "frictionviz: %s: failed: not_converged: %d of %d model evaluations (i = %g) "
                             "did not reach the steady state\n",
                             fig.id.c_str(), c.unsteady, c.evaluations, c.i);
                what.push_back(fig.id + ": " + std::to_string(c.unsteady) + " model evaluations of the fit");
            }
    std::string s;
    for (const std::string& w : what) s += (s.empty() ? "" : "; ") + w;
    return s;
}

// Every name --figure takes, for its help and its error messages.
std::string figure_names() {
    return "all, scene, map, fig19, " + figure_ids();
}

} // namespace

Command add_render_command(CLI::App& root) {
    struct Args {
        std::string figure;
        std::string out;
        std::string size = "1280x800";
        ModelArgs model; // its units: --amplitude, --frequency (fig19, scene, map), --vb, --zss (scene, map)
        std::string data;
        OutputArgs output; // --format, --scale
    };
    auto a = std::make_shared<Args>();
    CLI::App* cmd = root.add_subcommand(
        "render", "render figures headless (OSMesa) as PNG, with the data behind each one as CSV beside it");
    cmd->add_option(
           "--figure", a->figure,
           "figure ids, comma separated: " + figure_names() +
               " (all: every figure of the paper; scene: any parameters; map: r_x over zeta and theta; "
               "fig19: measured data with --data)")
        ->required();
    cmd->add_option("--out", a->out,
                    "output directory (must exist); FIGURE.png and its CSV are replaced atomically")
        ->required();
    cmd->add_option("--data", a->data,
                    "fig19: CSV of measured r_x (columns zeta,r_x or vb,r_x; optional theta_deg, sigma)")
        ->check(file_name());
    add_vibration_options(*cmd, a->model.units,
                          "fig19: for a vb column (A and f) and z_ss (A); scene, map: for --vb, --zss");
    cmd->add_option("--size", a->size, "image size WxH in pixels")->check(size_spec())->capture_default_str();
    add_output_options(*cmd, a->output);
    // The scene's parameters: the same flags as `ratio` (required only for --figure scene).
    a->model.zeta_opt =
        cmd->add_option("--zeta", a->model.zeta, "scene: velocity ratio")->check(number_in(kZetaRange));
    cmd->add_option("--theta", a->model.theta_deg, "scene: vibration angle in degrees")
        ->check(number_in(kThetaRange));
    a->model.rdisp_opt = cmd->add_option("--rdisp", a->model.rdisp, "scene, map: displacement ratio")
                             ->check(number_in(kRdispRange));
    a->model.i_opt =
        cmd->add_option("--i", a->model.i, "scene, map: Dahl exponent")->check(number_in(kIRange));
    add_vb_zss_options(*cmd, a->model.units, UnitShape::single);
    return {cmd, [a, cmd] {
                // Resolve the list of figures first: an unknown id lists the valid ones.
                std::vector<FigureSpec> specs;
                bool data_fig = false;
                std::stringstream ids(a->figure);
                std::string id;
                while (std::getline(ids, id, ',')) {
                    if (id == "all") {
                        for (const auto& f : paper_figures()) specs.push_back(f);
                    } else if (id == "scene") {
                        struct Need {
                            const char *flag, *alt;
                        };
                        for (const Need n : {Need{"--zeta", "--vb"}, Need{"--theta", nullptr},
                                             Need{"--rdisp", "--zss"}, Need{"--i", nullptr}})
                            if (cmd->get_option(n.flag)->count() == 0 &&
                                !(n.alt && cmd->get_option(n.alt)->count() > 0))
                                throw UsageError(std::string("--figure scene needs ") + n.flag +
                                                 (n.alt ? std::string(" or ") + n.alt : "") +
                                                 " (the same flags as `ratio`)");
                        specs.push_back(scene_figure(to_params(a->model)));
                    } else if (id == "fig19") {
                        if (a->data.empty())
                            throw UsageError("--figure fig19 needs --data FILE (measured r_x; see README, "
                                             "Fitting measured data)");
                        data_fig = true;
                    } else if (id == "map") {
                        // Beyond the paper: r_x over (zeta, theta) for one r_disp and i (default 2 and 1).
                        const double rdisp =
                            rdisp_of(a->model.rdisp_opt, a->model.rdisp, a->model.units, false).value_or(2.0);
                        const double i = cmd->get_option("--i")->count() ? a->model.i : 1.0;
                        specs.push_back(map_figure(rdisp, i));
                    } else if (const FigureSpec* f = find_figure(id)) {
                        specs.push_back(*f);
                    } else {
                        throw UsageError("--figure: unknown figure '" + id + "'; allowed: " + figure_names());
                    }
                }
                if (specs.empty() && !data_fig)
                    throw UsageError("--figure: no figure named; allowed: " + figure_names());
                Size sz;
                std::sscanf(a->size.c_str(), "%d%*c%d", &sz.w, &sz.h);
                check_output_args(a->output, sz.w, sz.h);
                check_out_dir(a->out);
                std::string dir = a->out;
                while (dir.size() > 1 && dir.back() == '/') dir.pop_back();
                // Each image's own name too (say a directory or a socket called fig8.png is in the way).
                for (const std::string& ext : a->output.extensions()) {
                    for (const FigureSpec& f : specs) check_out(dir + "/" + f.id + "." + ext);
                    if (data_fig) check_out(dir + "/fig19." + ext);
                }
                // fig19 reads and fits the data before any rendering: a malformed file is a usage error.
                std::optional<FigureData> fig19;
                FitResult fig19_fit;
                if (data_fig) {
                    const UnitArgs& u = a->model.units;
                    ReadOptions ro;
                    FitOptions fo;
                    if (*u.amplitude_opt) ro.amplitude_um = fo.amplitude_um = u.amplitude;
                    if (*u.frequency_opt) ro.frequency_khz = u.frequency;
                    if (cmd->get_option("--theta")->count()) fo.theta_deg = a->model.theta_deg;
                    try {
                        fig19 = measurement_figure(read_measurements(a->data, ro), fo, &fig19_fit);
                    } catch (const DataError& e) {
                        throw UsageError(e.what());
                    } catch (const FitError& e) {
                        throw UsageError(std::string("--data: ") + e.what());
                    }
                }
                gfx::ContextOptions co;
                co.backend = gfx::Backend::Headless;
                co.width = sz.w;
                co.height = sz.h;
                co.scale = static_cast<float>(a->output.scale);
                std::unique_ptr<app::RenderSession> session;
                try {
                    session = std::make_unique<app::RenderSession>(co);
                } catch (const std::exception& e) {
                    throw RuntimeFailure(std::string("cannot render headless: ") + e.what());
                }
                check_gl_limits(*session, a->output);
                // One figure at a time, so that memory does not grow with the number of figures: figure k is
                // computed and drawn (GL is single-threaded) while the frames before it are PNG-encoded (the
                // slow part) and written on other threads; it is handed over when fewer than `encoders` are
                // in flight, and the frame is freed once encoded. Alive at any time: the context's
                // framebuffer, the frame being drawn, the encoders' frames, the data of one figure.
                struct Output {
                    std::string id;
                    gfx::Image image;
                    gfx::DisplayList list;                                // for SVG and PDF
                    std::vector<std::pair<std::string, std::string>> csv; // file, content
                };
                const OutputArgs& output = a->output;
                // Owns the frame and the display list, and frees them as soon as they are written.
                auto write = [dir, &output](Output o) {
                    std::string err = write_figure_files(dir, o.id, output, o.image, o.list);
                    std::vector<std::uint8_t>().swap(o.image.rgba);
                    o.list = {};
                    for (const auto& [file, content] : o.csv)
                        if (err.empty()) err = write_file_atomic(file, content);
                    return err;
                };
                const std::size_t encoders = encoders_for(sz.w, sz.h);
                std::deque<std::pair<std::future<std::string>, std::string>> pending; // jobs, "wrote" lines
                auto finish_oldest = [&] { // in order, so that the "wrote" lines are too
                    std::string err = pending.front().first.get(), line = std::move(pending.front().second);
                    pending.pop_front();
                    if (!err.empty()) throw RuntimeFailure(err);
                    std::printf("%s\n", line.c_str());
                };
                if (fig19) apply_test_hook(fig19_fit);
                // Every figure is written; those with failed points make the exit status 3.
                const std::size_t nfigures = specs.size() + (fig19 ? 1 : 0);
                std::string failed;
                int nfailed = 0;
                for (std::size_t k = 0; k < nfigures; ++k) {
                    const bool is_fit = k == specs.size(); // fig19 comes last
                    FigureData data = is_fit ? std::move(*fig19) : compute_figure(specs[k]);
                    for (TableData& t : data.tables) apply_test_hook(t);
                    Output o{data.id, {}, {}, {}};
                    if (output.png) {
                        o.image = session->render_figure(data);
                        if (output.svg || output.pdf) o.list = session->canvas().display_list();
                    } else {
                        o.list = session->record_figure(data);
                    }
                    for (const TableData& t : data.tables)
                        o.csv.push_back({dir + "/" + data.id + t.suffix + ".csv", csv_of(t)});
                    if (const std::string w = check_figure(data, is_fit ? &fig19_fit : nullptr); !w.empty()) {
                        ++nfailed;
                        failed += (failed.empty() ? "" : "; ") + w;
                    }
                    while (pending.size() >= encoders) finish_oldest();
                    std::string line = "wrote " + dir + "/" + o.id + ".";
                    for (const std::string& ext : output.extensions())
                        line += (ext == output.extensions().front() ? "" : ", .") + ext;
                    line += " (" + std::to_string(sz.w) + "x" + std::to_string(sz.h) + ") and its CSV";
                    auto job = std::async(std::launch::async, write, std::move(o));
                    pending.emplace_back(std::move(job), std::move(line));
                }
                while (!pending.empty()) finish_oldest();
                std::fflush(stdout);
                if (nfailed > 0)
                    throw NumericalFailure(std::to_string(nfailed) + " of " + std::to_string(nfigures) +
                                           " figures have failed points (" + failed +
                                           "); all figures are written");
            }};
}

} // namespace fv::cli
