// frictionviz render: the registered figures (fv/figure_registry.hpp) as PNG + CSV + caption JSON, headless.
#include "commands.hpp"
#include "errors.hpp"
#include "figure_flags.hpp"
#include "figure_listing.hpp"
#include "lesson_render.hpp"
#include "model_options.hpp"
#include "output.hpp"
#include "render_flags.hpp"
#include "render_output.hpp"
#include "test_hook.hpp"

#include "figures/figure_renderer.hpp"
#include "figures/figure_spec_file.hpp"
#include "figures/render_figures.hpp"
#include "figures/render_session.hpp"

#include "fv/atomic_file.hpp"
#include "fv/figure_data.hpp"
#include "fv/figure_registry.hpp"
#include "fv/fit.hpp"
#include "fv/input_file.hpp"
#include "fv/measurements.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <sstream>
#include <thread>

#ifndef FV_VERSION
#define FV_VERSION "dev"
#endif

namespace fv::cli {
namespace {

// PNG encodings run in parallel as long as their frames fit in this budget: each holds about two frames (the
// pixels and stb's filtered copy of them). At least one runs, at most one per core: 2 at 1280x800 (3.9 MiB
// frames), 1 above 2^20 pixels (1920x1080, 7680x4320). tests/reliability/render_memory_test.cpp holds the
// growth of memory with the number of figures to this budget plus one frame.
constexpr std::size_t kEncodeBudget = std::size_t{16} << 20;

// A spec file is a figure's ID.json: a few kB (a caption and a file list); anything near this is not one.
constexpr std::size_t kMaxSpecBytes = std::size_t{1} << 20;

std::size_t encoders_for(int w, int h) {
    const std::size_t job = std::size_t{2} * static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 4;
    const std::size_t cores = std::max(1u, std::thread::hardware_concurrency());
    return std::clamp<std::size_t>(kEncodeBudget / job, 1, cores);
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

// Every name --figure takes, for its error messages.
std::string figure_names() {
    return "all, " + figure_ids();
}

// The flag of the first required parameter of `e` that `in` does not give, empty if none.
std::string missing_flag(const FigureEntry& e, const FigureInputs& in) {
    const std::optional<FigureParam> p = missing_param(e, in);
    return p ? param_flag_text(*p) : "";
}

// --figure's help: the ids, and which flags the figures that take flags need.
std::string figure_help() {
    std::string s = "figure ids, comma separated: " + figure_names() + " (titles: --list). all: every figure";
    for (const FigureEntry& e : figure_registry()) {
        if (e.params.empty()) continue;
        s += "; " + e.id + " (" + flags_text(e);
        if (missing_param(e, e.example))
            s += "; in all only with them";
        else if (missing_param(e, {}))
            s += "; in all " + plain_text(e.make(e.example).title) + " where not given";
        s += ")";
    }
    return s;
}

// Every file render writes for `spec`: ID.png/.svg/.pdf as asked, the CSV tables and ID.json.
std::vector<std::string> figure_files(const FigureSpec& spec, const OutputArgs& output) {
    std::vector<std::string> names;
    for (const std::string& ext : output.extensions()) names.push_back(spec.id + "." + ext);
    for (const std::string& suffix : table_suffixes(spec)) names.push_back(spec.id + suffix + ".csv");
    names.push_back(spec.id + ".json");
    return names;
}

// ID.json beside the image: what it shows and everything it depends on.
// `parameters`: every input, as a spec file takes them (figures/figure_spec_file.hpp).
std::string caption_json(const FigureSpec& spec, const std::vector<std::string>& files,
                         const std::string& status, const std::string& parameters) {
    nlohmann::ordered_json j;
    j["id"] = spec.id;
    j["title"] = plain_text(spec.title);
    j["caption"] = spec.caption + " " + figure_parameters(spec);
    j["parameters"] = nlohmann::ordered_json::parse(parameters);
    j["files"] = files;
    j["status"] = status.empty() ? "ok" : status;
    j["version"] = "frictionviz " FV_VERSION;
    return j.dump(2) + "\n";
}

// The spec file's figure and inputs; its size, scale and format where the flags do not give them.
std::pair<const FigureEntry*, FigureInputs> read_spec(const std::string& path, const CLI::App& cmd,
                                                      std::string& size, OutputArgs& output,
                                                      std::string& page, bool& caption) {
    std::string text;
    if (std::string why = read_input_file(path, text, {kMaxSpecBytes}); !why.empty())
        throw UsageError("--spec " + path + ": " + why);
    if (text.size() > kMaxSpecBytes)
        throw UsageError("--spec " + path + ": larger than " + std::to_string(kMaxSpecBytes) +
                         " bytes; allowed: a figure's ID.json or its parameters object");
    try {
        app::FigureSpecFile spec = app::parse_spec_file(text);
        if (cmd.get_option("--size")->count() == 0) {
            std::string s = spec.size;
            if (std::string why = size_spec()(s); !why.empty()) throw app::SpecError("size: " + why);
            size = spec.size;
        }
        if (cmd.get_option("--scale")->count() == 0) output.scale = spec.scale;
        if (cmd.get_option("--format")->count() == 0) output.format = spec.format;
        if (cmd.get_option("--page")->count() == 0) page = app::to_string(spec.page);
        if (cmd.get_option("--caption")->count() == 0) caption = spec.caption;
        return {spec.entry, std::move(spec.inputs)};
    } catch (const app::SpecError& err) {
        throw UsageError("--spec " + path + ": " + err.what());
    }
}

} // namespace

Command add_render_command(CLI::App& root) {
    struct Args {
        std::string figure;
        std::string out;
        std::string size = "1280x800";
        RenderFlags flags; // the figures' parameters
        std::string list;  // --list [tsv|markdown]
        std::string spec;  // --spec FILE.json
        OutputArgs output; // --format, --scale
        int lesson = 0;    // --lesson N
        std::string page;  // --page a4|letter|column
        bool caption = false;
    };
    auto a = std::make_shared<Args>();
    CLI::App* cmd =
        root.add_subcommand("render", "render figures headless (OSMesa) as PNG, with the data behind "
                                      "each one as CSV and its caption as JSON beside it");
    cmd->add_option("--figure", a->figure, figure_help() + " (required unless --list or --spec)");
    cmd->add_option(
        "--out", a->out,
        "output directory (must exist); ID.png, its CSV and ID.json (id, title, caption naming every "
        "parameter, parameters: every input as --spec reads it, files, version) are replaced atomically "
        "(required unless --list)");
    cmd->add_option(
           "--spec", a->spec,
           "draw the figure a spec file describes: a figure's ID.json (its parameters object) or that "
           "object alone; the same inputs give the same files byte for byte. Not with --figure or the "
           "figure's flags; --size, --scale, --format given replace the file's")
        ->check(file_name());
    cmd->add_option(
           "--list", a->list,
           "print the figures and exit: ID<TAB>TITLE per line (tsv, the default), or the README's table "
           "(markdown)")
        ->expected(0, 1)
        ->check(CLI::IsMember({"tsv", "markdown"}));
    cmd->add_option("--size", a->size, "image size WxH in pixels")->check(size_spec())->capture_default_str();
    add_output_options(*cmd, a->output);
    cmd->add_option(
           "--page", a->page,
           "a page that prints right for SVG and PDF: a4 or letter (portrait, the figure at the width "
           "inside 2/3 in margins, 9 pt type at 100 %) or column (3.3 in wide, 8 pt type); the PNG "
           "stays --size pixels")
        ->check(CLI::Validator(
            [](std::string& s) -> std::string {
                bool ok = false;
                app::paper_page(s, ok);
                return ok ? "" : "'" + s + "' is not a page; allowed: a4, letter, column";
            },
            "a4|letter|column"));
    cmd->add_flag(
        "--caption", a->caption,
        "put the figure's caption (as in its ID.json; --lesson: the step's title and text) under it, wrapped "
        "to its width, in the PNG, SVG and PDF");
    add_render_flags(*cmd, a->flags);
    // After the figure flags: --lesson excludes them (its setup stands for them).
    CLI::Option* lesson = add_lesson_option(
        *cmd, a->lesson,
        "draw guided lesson step N as lesson-N.png (.svg, .pdf by --format) with lesson-N.json (the step's "
        "title, text, link and panel): a frame of animate --lesson N (the step's lower panel, frame and "
        "compare "
        "mode, as the app shows it), under the step's title; --page and --caption (the step's title and "
        "text) as for figures");
    lesson->excludes("--figure")->excludes("--spec")->excludes("--list")->excludes("--data");
    return {
        cmd, [a, cmd] {
            if (cmd->get_option("--list")->count() > 0) {
                std::fputs((a->list == "markdown" ? figure_table_markdown() : figure_list_tsv()).c_str(),
                           stdout);
                return;
            }
            if (a->lesson > 0) {
                if (a->out.empty())
                    throw UsageError("--out is required: the directory to write the picture into");
                bool page_ok = true; // checked by --page's validator
                render_lesson(a->lesson, a->out, parse_size(a->size), a->output,
                              a->page.empty() ? app::PaperPage::none : app::paper_page(a->page, page_ok),
                              a->caption);
                return;
            }
            const bool from_spec = cmd->get_option("--spec")->count() > 0;
            if (from_spec && cmd->get_option("--figure")->count() > 0)
                throw UsageError("--spec and --figure: give one of them (the spec file names its figure)");
            if (const std::string flag = first_given(a->flags); from_spec && !flag.empty())
                throw UsageError("--spec and " + flag +
                                 ": the spec file gives the figure's parameters; allowed with --spec: --out, "
                                 "--size, --scale, --format, --page, --caption");
            if (a->figure.empty() && !from_spec)
                throw UsageError("--figure is required (or --spec, --lesson, --list); allowed: " +
                                 figure_names());
            if (a->out.empty() && cmd->get_option("--out")->count() == 0)
                throw UsageError("--out is required: the directory to write the figures into");
            // Resolve the list of figures first (an unknown id lists the valid ones), each with its
            // inputs.
            std::vector<std::pair<const FigureEntry*, FigureInputs>> chosen;
            if (from_spec)
                chosen.push_back(read_spec(a->spec, *cmd, a->size, a->output, a->page, a->caption));
            const FigureInputs in = from_spec ? FigureInputs{} : inputs_of(a->flags);
            std::stringstream ids(from_spec ? std::string() : a->figure);
            // Several figures named (fig5,fig14,scene): one that is given none of its required parameters
            // is drawn with its example inputs, as --figure all draws it (said on stderr); named alone, or
            // given some of them, it needs them all.
            const bool several = a->figure.find(',') != std::string::npos;
            std::string id;
            while (std::getline(ids, id, ',')) {
                if (id == "all") {
                    for (const FigureEntry& e : figure_registry()) {
                        const FigureInputs fit = fitting(e, in);
                        if (!missing_param(e, fit))
                            chosen.emplace_back(&e, fit);
                        else if (!missing_param(e, over(e.example, fit)))
                            chosen.emplace_back(&e, over(e.example, fit));
                        else
                            std::fprintf(stderr, "frictionviz: --figure all: %s left out (it needs %s)\n",
                                         e.id.c_str(), missing_flag(e, in).c_str());
                    }
                } else if (const FigureEntry* e = find_registered(id)) {
                    // A value of the wrong shape (--zeta 0.1:1 for scene) is named before a missing one.
                    if (std::string why = input_error(*e, in, flag_name); !why.empty()) throw UsageError(why);
                    if (const std::string m = missing_flag(*e, in); !m.empty()) {
                        const bool none_given =
                            std::none_of(e->params.begin(), e->params.end(), [&in](const FigureParamUse& u) {
                                return u.required && given(in, u.param);
                            });
                        const FigureInputs example = over(e->example, in);
                        if (!several || !none_given || missing_param(*e, example))
                            throw UsageError("--figure " + id + " needs " + m + " (it " + flags_text(*e) +
                                             ")");
                        std::fprintf(stderr,
                                     "frictionviz: --figure %s: none of %s given: drawn with its "
                                     "example values, as --figure all draws it\n",
                                     id.c_str(), m.c_str());
                        chosen.emplace_back(e, example);
                        continue;
                    }
                    chosen.emplace_back(e, in);
                } else {
                    throw UsageError("--figure: unknown figure '" + id + "'; allowed: " + figure_names());
                }
            }
            if (chosen.empty()) throw UsageError("--figure: no figure named; allowed: " + figure_names());
            // Each figure's inputs as it takes them: a list where it takes one value, a family of too many
            // curves (a spec file's inputs are checked already, under its keys).
            for (const auto& [e, inputs] : chosen)
                if (std::string why = input_error(*e, inputs, flag_name); !why.empty()) throw UsageError(why);
            const PixelSize sz = parse_size(a->size);
            try {
                check_output_args(a->output, sz.w, sz.h);
            } catch (const UsageError& err) {
                if (!from_spec) throw;
                throw UsageError("--spec " + a->spec + ": " + err.what());
            }
            bool page_ok = true;
            const app::PaperPage paper =
                a->page.empty() ? app::PaperPage::none : app::paper_page(a->page, page_ok);
            check_out_dir(a->out);
            std::string dir = a->out;
            while (dir.size() > 1 && dir.back() == '/') dir.pop_back();
            // The figures' definitions: fig19 reads and fits its data here, before any rendering, so
            // that a malformed file is a usage error with nothing written.
            std::vector<FigureSpec> specs;
            std::vector<std::string> parameters; // each figure's, for its ID.json
            for (const auto& [e, inputs] : chosen) {
                const FigureInputs resolved = with_defaults(*e, inputs);
                parameters.push_back(app::parameters_json(*e, resolved, sz.w, sz.h, a->output.scale,
                                                          a->output.pictures(), paper, a->caption));
                try {
                    specs.push_back(e->make(resolved));
                } catch (const DataError& err) {
                    throw UsageError(err.what());
                } catch (const FitError& err) {
                    throw UsageError(std::string("--data: ") + err.what());
                }
            }
            // Every file of every figure, before anything is computed (say a directory called
            // fig8.csv, or a socket called fig8.png, is in the way): a usage error with nothing written.
            for (const FigureSpec& spec : specs)
                for (const std::string& name : figure_files(spec, a->output)) check_out(dir + "/" + name);
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
            // Each figure's tables (CSV) and caption beside its pictures, and the note of its failed
            // points.
            app::RenderJob job;
            job.dir = dir;
            job.formats = a->output.pictures();
            job.encoders = encoders_for(sz.w, sz.h);
            job.paper = paper;
            job.caption = a->caption;
            // render_figures calls extras once per figure, in order.
            std::size_t next = 0;
            job.extras = [&output = a->output, &parameters, &next](const FigureSpec& spec, FigureData& data) {
                for (TableData& t : data.tables) apply_test_hook(t);
                std::optional<FitResult> fit;
                if (const auto* m = std::get_if<MeasurementsFigure>(&spec.content); m && m->fit)
                    apply_test_hook(fit.emplace(*m->fit));
                app::FigureExtras extras;
                std::vector<std::string> names;
                for (const std::string& ext : output.extensions()) names.push_back(data.id + "." + ext);
                for (app::FigureTableFile& t : app::figure_tables(data)) {
                    names.push_back(t.name);
                    extras.files.push_back({t.name, std::move(t.csv)});
                }
                names.push_back(data.id + ".json");
                extras.failed = check_figure(data, fit ? &*fit : nullptr);
                extras.files.push_back(
                    {names.back(), caption_json(spec, names, extras.failed, parameters.at(next++))});
                return extras;
            };
            job.wrote = [&](const std::string& written) {
                std::string line = "wrote " + dir + "/" + written + ".";
                for (const std::string& ext : a->output.extensions())
                    line += (ext == a->output.extensions().front() ? "" : ", .") + ext;
                // The PNG's pixels; with --page the SVG/PDF are on that sheet, not at --size.
                const std::string sheet = a->page.empty() ? "" : "; SVG/PDF: page " + a->page;
                std::printf("%s (%dx%d%s), its CSV and %s.json\n", line.c_str(), sz.w, sz.h, sheet.c_str(),
                            written.c_str());
            };
            const std::size_t nfigures = specs.size();
            const app::RenderOutcome r = app::render_figures(*session, specs, job);
            std::fflush(stdout);
            if (!r.write_error.empty())
                throw RuntimeFailure(r.write_error +
                                     " (stopped there: the figures after it were not written)");
            // Every figure is written; those with failed points make the exit status 3.
            if (r.failed_figures > 0)
                throw NumericalFailure(std::to_string(r.failed_figures) + " of " + std::to_string(nfigures) +
                                       " figures have failed points (" + r.failed +
                                       "); all figures are written");
        }};
}

} // namespace fv::cli
