// Snapshot tests: every figure rendered headless at a fixed size and compared with the baseline PNG in
// tests/snapshots/ with a tolerance (max channel difference + share of differing pixels).
// On failure the actual image and a diff image are written into the build tree and named in the message.
// Baselines change only on purpose:  FV_UPDATE_SNAPSHOTS=1 ctest -R snapshot   (then review and commit).
#include "figures/render_session.hpp"

#include "fv/atomic_file.hpp"
#include "fv/figure_data.hpp"
#include "fv/figure_registry.hpp"
#include "fv/figures.hpp"
#include "fv/gfx/compare.hpp"
#include "fv/gfx/png.hpp"
#include "fv/sweep.hpp"
#include "tools/figure_examples.hpp"

#include <catch2/catch.hpp>

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>
#include <sys/stat.h>

namespace {

constexpr int kWidth = 960, kHeight = 600;
// llvmpipe output is byte-identical run to run on one Mesa version; the tolerance absorbs antialiasing
// differences of another build without letting a moved curve (hundreds of pixels) through.
constexpr int kMaxChannelDiff = 32;
constexpr double kMaxShare = 0.0005;

std::string read_all(const std::string& path, bool& ok) {
    std::ifstream f(path, std::ios::binary);
    ok = static_cast<bool>(f);
    return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

std::string png_bytes(const fv::gfx::Image& img) {
    const auto v = fv::gfx::encode_png(img);
    return {reinterpret_cast<const char*>(v.data()), v.size()};
}

void check_snapshot(fv::app::RenderSession& session, const fv::FigureSpec& spec) {
    const std::string baseline = std::string(FV_SNAPSHOT_DIR) + "/" + spec.id + ".png";
    const std::string outdir = FV_SNAPSHOT_OUT;
    ::mkdir(outdir.c_str(), 0755);
    const fv::gfx::Image actual = session.render_figure(fv::compute_figure(spec));
    const char* update = std::getenv("FV_UPDATE_SNAPSHOTS");
    if (update && std::string(update) == "1") {
        REQUIRE(fv::write_file_atomic(baseline, png_bytes(actual)).empty());
        WARN("updated baseline " << baseline);
        return;
    }
    bool ok = false;
    const std::string bytes = read_all(baseline, ok);
    const std::string actual_path = outdir + "/" + spec.id + ".actual.png";
    if (!ok) {
        fv::write_file_atomic(actual_path, png_bytes(actual));
        FAIL("missing baseline " << baseline << " (actual image: " << actual_path
                                 << "; create baselines with FV_UPDATE_SNAPSHOTS=1)");
    }
    const fv::gfx::Image expected =
        fv::gfx::decode_png(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size());
    const auto cmp = fv::gfx::compare_images(actual, expected, kMaxChannelDiff, kMaxShare);
    if (!cmp.passed) {
        const std::string diff_path = outdir + "/" + spec.id + ".diff.png";
        fv::write_file_atomic(actual_path, png_bytes(actual));
        if (!cmp.diff.empty()) fv::write_file_atomic(diff_path, png_bytes(cmp.diff));
        FAIL_CHECK(spec.id << " differs from " << baseline << ": max channel difference "
                           << cmp.max_channel_diff << ", " << cmp.differing_share * 100
                           << "% of pixels differ (allowed " << kMaxShare * 100
                           << "%); actual: " << actual_path << ", diff: " << diff_path);
    }
}

// The snapshots' page: headless, kWidth x kHeight.
fv::gfx::ContextOptions snapshot_options() {
    fv::gfx::ContextOptions o;
    o.backend = fv::gfx::Backend::Headless;
    o.width = kWidth;
    o.height = kHeight;
    return o;
}

} // namespace

TEST_CASE("Snapshot: every registered figure matches its baseline", "[snapshot]") {
    fv::app::RenderSession session(snapshot_options());
    // Each with the inputs of its example (those of README.md and screenshots/), fig19 with the synthetic
    // example data.
    for (const fv::FigureEntry& e : fv::figure_registry())
        check_snapshot(session, e.make(fv::test::example_inputs(e)));
}

TEST_CASE("Snapshot: a family of maps as small multiples matches its baseline", "[snapshot]") {
    fv::app::RenderSession session(snapshot_options());
    // Two Dahl maps and the rigid one (render --figure map --rdisp 1,3 --model dahl,rigid) on a coarse grid
    // of cells (40 x 19, a second of computing): the grid, the shared titles, colour bar and legend.
    fv::FigureInputs in;
    in.rdisp = {1, 3};
    in.models = {fv::Model::dahl, fv::Model::rigid};
    fv::FigureSpec spec = fv::find_registered("map")->make(in);
    auto& m = std::get<fv::MapFigure>(spec.content);
    m.zetas = fv::linspace(0.02, 3, 40);
    m.theta_count = 19;
    spec.id = "map-family";
    check_snapshot(session, spec);
}

TEST_CASE("Snapshot comparison catches a changed picture", "[snapshot]") {
    // The tolerance must not swallow a real change: one figure against another's baseline fails.
    fv::gfx::ContextOptions o;
    o.width = kWidth;
    o.height = kHeight;
    fv::app::RenderSession session(o);
    const auto a = session.render_figure(fv::compute_figure(*fv::find_figure("fig14a")));
    const auto b = session.render_figure(fv::compute_figure(*fv::find_figure("fig14b")));
    CHECK_FALSE(fv::gfx::compare_images(a, b, kMaxChannelDiff, kMaxShare).passed);
    CHECK(fv::gfx::compare_images(a, a, 0, 0).passed);
}
