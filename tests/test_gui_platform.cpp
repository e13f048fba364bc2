// The app's platforms through the real executable:
// - --platform picks the adapter by name; unknown names, --headless against --platform window, headless
//   without a frame count and pages too small for the app exit 2 with one line, nothing written;
// - --size 2Wx2H --scale 2, averaged over 2x2 pixels, is the WxH screen (the app's scale equivalence).
#include "fv/gfx/compare.hpp"

#include "tools/image_files.hpp"
#include "tools/run_command.hpp"

#include <catch2/catch.hpp>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace {

using fv::test::Run;

const std::string& root() {
    return fv::test::scratch_dir("fv-platform");
}

Run gui(const std::string& args) {
    return fv::test::run_command(std::string(FV_EXE) + " gui " + args, root());
}

bool exists(const std::string& p) {
    return ::access(p.c_str(), F_OK) == 0;
}

} // namespace

TEST_CASE("gui --platform: bad choices exit 2 with one line naming what is allowed, nothing written",
          "[gui][platform][cli]") {
    struct Case {
        const char* args;
        const char* says;
    };
    const std::string shot = root() + "/never.png";
    for (const Case& c :
         {Case{"--platform nope --frames 1", "window,headless,auto"},
          Case{"--platform '' --frames 1", "window,headless,auto"},
          Case{"--headless --platform window --frames 1", "--headless"}, Case{"--headless", "--frames"},
          Case{"--platform headless", "--frames"}, Case{"--headless --frames 1 --size 400x300", "320x320"},
          Case{"--headless --frames 1 --size 700x1000 --scale 2.5", "320x320"},
          Case{"--headless --frames 1 --size 9000x800", "7680"},
          Case{"--headless --frames 1 --scale 0.1", "0.25"}, Case{"--headless --frames 1 --scale 9", "8"}}) {
        const Run r = gui(std::string(c.args) + " --screenshot " + shot);
        INFO(c.args << " -> " << r.err);
        CHECK(r.code == 2);
        CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
        CHECK(r.err.find(c.says) != std::string::npos);
        CHECK_FALSE(exists(shot));
    }
}

TEST_CASE("gui --scale: 2x the size at scale 2 is the same screen at twice the resolution",
          "[gui][platform][scale][long]") {
    const std::string one = root() + "/scale1.png", two = root() + "/scale2.png";
    // The same frames (a fixed 1/60 s each), the same parameters; only the pixel density differs.
    REQUIRE(gui("--headless --frames 20 --size 1280x800 --screenshot " + one).code == 0);
    REQUIRE(gui("--platform headless --frames 20 --size 2560x1600 --scale 2 --screenshot " + two).code == 0);
    const fv::gfx::Image big = fv::test::load_png(two);
    REQUIRE(big.width == 2560);
    REQUIRE(big.height == 1600);
    // Glyphs rasterised at twice the size and averaged are not the 1x glyphs: compared at half the
    // resolution, text agrees like everything else. A moved panel, curve or widget differs on far more.
    const auto cmp = fv::gfx::compare_images(fv::test::half(fv::test::half(big)),
                                             fv::test::half(fv::test::load_png(one)), 64, 0.004);
    INFO(cmp.differing_share * 100 << "% of pixels differ (" << root() << ")");
    CHECK(cmp.passed);
    if (!cmp.passed && !cmp.diff.empty()) fv::test::write_png(root() + "/scale.diff.png", cmp.diff);
    // Without --size, --scale keeps the logical page: 1280x800 at the scale.
    const std::string def = root() + "/scale-default.png";
    REQUIRE(gui("--headless --frames 2 --scale 1.5 --screenshot " + def).code == 0);
    const fv::gfx::Image d = fv::test::load_png(def);
    CHECK(d.width == 1920);
    CHECK(d.height == 1200);
}
