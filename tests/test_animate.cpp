// frictionviz animate through the real executable: the GIF and the MP4 decoded back
// (frame count = periods x frames per period, size, frames differ, GIF loops, MP4 is H.264 in yuv420p), the
// loop is seamless (the picture repeats every period and the step from the last frame to the first is like
// any other), and bad input exits 2 with one line, nothing written, an existing file untouched. Also `render
// --lesson N`, which draws the first frame of `animate --lesson N` as a picture.
#include "tools/anim_decode.hpp"
#include "tools/image_files.hpp"
#include "tools/run_command.hpp"

#include <catch2/catch.hpp>
#include <cstdio>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace {

using fv::test::Run;

const std::string& root() {
    return fv::test::scratch_dir("fv-animate");
}

Run animate(const std::string& args) {
    return fv::test::run_command(std::string(FV_EXE) + " animate " + args, root());
}

std::string slurp(const std::string& p) {
    std::ifstream f(p, std::ios::binary);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

const std::string kModel = "--zeta 0.15 --theta 60 --rdisp 2 --i 1 ";

// Consecutive frames differ (it moves), frame k and frame k + per_period are the same picture up to
// `same_tol` (the steady state repeats every period), and the last frame steps to the first like any other
// frame to the next (within a factor of the largest and smallest consecutive steps).
void check_loop(const std::vector<fv::gfx::Image>& frames, int per_period, double same_tol) {
    REQUIRE(frames.size() > static_cast<std::size_t>(per_period));
    double lo = 1e9, hi = 0;
    for (std::size_t k = 0; k + 1 < frames.size(); ++k) {
        const double d = fv::test::mean_abs_diff(frames[k], frames[k + 1]);
        lo = std::min(lo, d), hi = std::max(hi, d);
    }
    INFO("consecutive frames differ by " << lo << " .. " << hi);
    CHECK(lo > 0.05);
    for (std::size_t k = 0; k + per_period < frames.size(); ++k) {
        INFO("frame " << k << " vs " << k + per_period);
        CHECK(fv::test::mean_abs_diff(frames[k], frames[k + per_period]) <= same_tol);
    }
    const double wrap = fv::test::mean_abs_diff(frames.back(), frames.front());
    INFO("last -> first: " << wrap);
    CHECK(wrap >= 0.5 * lo);
    CHECK(wrap <= 1.5 * hi);
}

} // namespace

TEST_CASE("animate GIF: periods x frames per period, size, loops forever, seamless", "[animate][gif]") {
    const std::string out = root() + "/loop.gif";
    // 2 periods at 10 fps and 1 period per second: 10 frames per period.
    const Run r = animate(kModel + "--fps 10 --speed 1 --size 480x300 --out " + out);
    INFO(r.err);
    REQUIRE(r.code == 0);
    CHECK(r.err.empty()); // no progress bar when stderr is not a terminal
    const fv::test::DecodedGif g = fv::test::decode_gif(out);
    REQUIRE(g.error.empty());
    CHECK(g.image_count == 20);
    CHECK(g.width == 480);
    CHECK(g.height == 300);
    CHECK(g.loops);
    int total = 0;
    for (int d : g.delays_cs) total += d;
    CHECK(total == 200); // 20 frames at 10 fps
    check_loop(g.frames, 10, 0.02);
}

TEST_CASE("animate GIF: the scene view and the default loop length", "[animate][gif]") {
    const std::string out = root() + "/scene.gif";
    // Defaults: 2 periods, 30 fps, 0.5 periods per second -> 120 frames.
    const Run r = animate("--zeta 0.3 --theta 0 --rdisp 5 --i 0 --view scene --size 640x400 --out " + out);
    INFO(r.err);
    REQUIRE(r.code == 0);
    const fv::test::DecodedGif g = fv::test::decode_gif(out);
    REQUIRE(g.error.empty());
    CHECK(g.image_count == 120);
    CHECK(g.loops);
    check_loop(g.frames, 60, 0.02);
}

namespace {

// The share of the image's pixels right of x0 and below y0 (fractions of its size) in the colour map's top
// end (viridis' yellow, about (253, 231, 37)): the (zeta, theta) map's high r_x.
double yellow_share(const fv::gfx::Image& img, double x0, double y0) {
    std::size_t n = 0, hits = 0;
    for (int y = static_cast<int>(y0 * img.height); y < img.height; ++y)
        for (int x = static_cast<int>(x0 * img.width); x < img.width; ++x, ++n) {
            const std::uint8_t* p = &img.rgba[(static_cast<std::size_t>(y) * img.width + x) * 4];
            hits += p[0] > 200 && p[1] > 190 && p[2] < 100;
        }
    return n ? static_cast<double>(hits) / static_cast<double>(n) : 0;
}

} // namespace

TEST_CASE("animate --lesson N: the step's lower panel (the map of step 7) unless --panel says another",
          "[animate][gif][lessons]") {
    const auto lessons = nlohmann::json::parse(slurp(FV_LESSONS_JSON));
    int map_step = 0;
    for (std::size_t k = 0; k < lessons["steps"].size(); ++k)
        if (lessons["steps"][k]["setup"].value("panel", "curves") == "map")
            map_step = static_cast<int>(k) + 1;
    REQUIRE(map_step > 0);
    const auto lower_right_yellow = [&](const std::string& more) {
        const std::string out = root() + "/lesson-map.gif";
        const Run r = animate("--lesson " + std::to_string(map_step) +
                              " --periods 1 --fps 4 --speed 1 --size 640x400 " + more + " --out " + out);
        INFO(r.err);
        REQUIRE(r.code == 0);
        const fv::test::DecodedGif g = fv::test::decode_gif(out);
        REQUIRE(g.error.empty());
        REQUIRE(g.image_count == 4);
        return yellow_share(g.frames[0], 0.5, 0.62);
    };
    CHECK(lower_right_yellow("") > 0.05);                // the step's map
    CHECK(lower_right_yellow("--panel curves") < 0.001); // asked for the curves instead
}

TEST_CASE("animate MP4: H.264 in yuv420p, odd sizes rounded up to even, seamless", "[animate][mp4]") {
    const std::string out = root() + "/loop.mp4";
    const Run r = animate(kModel + "--fps 10 --speed 1 --size 481x301 --out " + out);
    INFO(r.err);
    REQUIRE(r.code == 0);
    CHECK(r.err.find("482x302") != std::string::npos); // says so
    const fv::test::DecodedVideo v = fv::test::decode_video(out);
    REQUIRE(v.error.empty());
    CHECK(v.container.find("mp4") != std::string::npos);
    CHECK(v.codec == "h264");
    CHECK(v.pix_fmt == "yuv420p");
    CHECK(v.width == 482);
    CHECK(v.height == 302);
    CHECK(v.fps == Approx(10));
    CHECK(v.frames.size() == 20);
    check_loop(v.frames, 10, 0.6); // lossy: the same picture encoded twice differs a little
}

TEST_CASE("animate: bad input exits 2 with one line naming what is allowed, nothing written",
          "[animate][cli]") {
    struct Case {
        std::string args;
        std::string out; // file name inside root()
        const char* says;
    };
    for (const Case& c : {
             Case{kModel, "x.avi", "FILE.gif, FILE.mp4"},
             Case{kModel, "noext", "FILE.gif, FILE.mp4"},
             Case{kModel, "x.gif.png", "FILE.gif, FILE.mp4"},
             Case{kModel + "--fps 60", "x.gif", "[1, 50]"},
             Case{kModel + "--fps 0", "x.mp4", "[1, 60]"},
             Case{kModel + "--fps abc", "x.mp4", "[1, 60]"},
             Case{kModel + "--periods 0", "x.gif", "[1, 20]"},
             Case{kModel + "--periods 2.5", "x.gif", "[1, 20]"},
             Case{kModel + "--speed 0.01", "x.gif", "[0.05, 10]"},
             Case{kModel + "--periods 20 --fps 60 --speed 0.05", "x.mp4", "at most 3600"},
             Case{kModel + "--size 100x100", "x.gif", "320"},
             Case{kModel + "--size 640x400 --scale 4", "x.gif", "320x240"},
             Case{kModel + "--scale 9", "x.gif", "[0.25, 8]"},
             Case{kModel + "--view side", "x.gif", "scene"},
             Case{kModel + "--panel chart", "x.gif", "curves"},
             Case{kModel + "--view scene --panel map", "x.gif", "not with --view scene"},
             Case{"--lesson 7 --view scene --panel map", "x.gif", "not with --view scene"},
             Case{"--zeta 0.15 --theta 60 --rdisp 2", "x.gif", "--i"},
             Case{"--zeta 200 --theta 60 --rdisp 2 --i 1", "x.gif", "100"},
             Case{kModel, "missing-dir/x.gif", "does not exist"},
         }) {
        const std::string out = root() + "/" + c.out;
        const Run r = animate(c.args + " --out " + out);
        INFO(c.args << " --out " << c.out << " -> " << r.err);
        CHECK(r.code == 2);
        CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
        CHECK(r.err.find(c.says) != std::string::npos);
        CHECK(::access(out.c_str(), F_OK) != 0);
        // The same mistake aimed at an existing file leaves it as it was.
        if (c.out.find('/') != std::string::npos) continue;
        std::ofstream(out) << "keep";
        const Run again = animate(c.args + " --out " + out);
        CHECK(again.code == 2);
        CHECK(slurp(out) == "keep");
        ::unlink(out.c_str());
    }
    // No --out at all.
    const Run r = animate(kModel);
    CHECK(r.code == 2);
    CHECK(r.err.find("--out") != std::string::npos);
}

TEST_CASE("app: File > Export animation (the script's animate) writes the loop in the background",
          "[animate][gui]") {
    const std::string gif = root() + "/app.gif", script = root() + "/export.txt";
    // Speed 2 periods/s: 2 periods at 30 fps are 30 frames.
    std::ofstream(script) << "1 zeta 0.3\n2 speed 2\n3 animate " << gif << "\n";
    auto check = [&](const std::string& prefix, const std::string& platform) {
        ::unlink(gif.c_str());
        const Run r = fv::test::run_command(
            prefix + " " + FV_EXE + " gui --platform " + platform + " --frames 8 --script " + script, root());
        INFO(platform << ": " << r.err);
        REQUIRE(r.code == 0);
        const fv::test::DecodedGif g = fv::test::decode_gif(gif);
        REQUIRE(g.error.empty());
        CHECK(g.image_count == 30);
        CHECK(g.width == 960);
        CHECK(g.height == 600);
        CHECK(g.loops);
        check_loop(g.frames, 15, 0.02);
    };
    check("", "headless");
    // The window's GL context on the main thread, the export's OSMesa context on its worker thread. Without
    // leak detection under the sanitizers, as gui_window_matches_headless (the DRI driver is unloaded before
    // LeakSanitizer looks; tests/CMakeLists.txt says why); harmless otherwise.
    if (std::system("command -v xvfb-run >/dev/null 2>&1") == 0)
        check("ASAN_OPTIONS=detect_leaks=0:halt_on_error=1 xvfb-run -a", "window");
}

TEST_CASE("render --lesson N: the step's picture in every format, its JSON from the lessons file, bad input "
          "exits 2 with nothing written",
          "[animate][cli][lessons]") {
    const auto render = [](const std::string& args) {
        return fv::test::run_command(std::string(FV_EXE) + " render " + args, root());
    };
    const std::string dir = root() + "/lesson";
    REQUIRE(std::system(("mkdir -p " + dir).c_str()) == 0);
    const Run ok = render("--lesson 5 --format png,svg,pdf --size 640x400 --out " + dir);
    INFO(ok.err);
    REQUIRE(ok.code == 0);
    const fv::gfx::Image png = fv::test::load_png(dir + "/lesson-5.png");
    CHECK(png.width == 640);
    CHECK(png.height == 400);
    // Drawn, not blank: a white page with lines and text in the scheme's colours.
    std::size_t ink = 0;
    for (std::size_t k = 0; k + 3 < png.rgba.size(); k += 4)
        ink += png.rgba[k] < 200 || png.rgba[k + 1] < 200 || png.rgba[k + 2] < 200;
    CHECK(ink > png.rgba.size() / 4 / 50);
    CHECK(slurp(dir + "/lesson-5.svg").find("<svg") != std::string::npos);
    CHECK(slurp(dir + "/lesson-5.pdf").rfind("%PDF-", 0) == 0);
    // The JSON names the step as the lessons file has it, and the link that opens it.
    const auto lessons = nlohmann::json::parse(slurp(FV_LESSONS_JSON));
    const auto& step = lessons["steps"][4];
    const auto j = nlohmann::json::parse(slurp(dir + "/lesson-5.json"));
    CHECK(j["title"] == "Lesson 5: " + step["title"].get<std::string>());
    CHECK(j["caption"] == step["text"]);
    CHECK(j["link"] == "?lesson=5");
    const std::string setup = j["setup"];
    CHECK(setup.find("model=" + step["setup"]["model"].get<std::string>()) != std::string::npos);
    CHECK(setup.find("&frame=ground") != std::string::npos); // step 5 stands on the ground
    CHECK(j["files"] ==
          nlohmann::json::array({"lesson-5.png", "lesson-5.svg", "lesson-5.pdf", "lesson-5.json"}));
    CHECK_FALSE(j.contains("setup_b")); // step 5 has no setup B
    // A step with setup B (compare mode) shows it, as animate --lesson does: its JSON names B's setup too.
    for (std::size_t k = 0; k < lessons["steps"].size(); ++k) {
        const auto& st = lessons["steps"][k];
        if (!st["setup"].contains("b")) continue;
        const std::string n = std::to_string(k + 1);
        const Run b = render("--lesson " + n + " --size 640x400 --out " + dir);
        INFO(b.err);
        REQUIRE(b.code == 0);
        const auto jb = nlohmann::json::parse(slurp(dir + "/lesson-" + n + ".json"));
        REQUIRE(jb.contains("setup_b"));
        const std::string setup_b = jb["setup_b"];
        if (st["setup"]["b"].contains("theta")) {
            char theta[32];
            std::snprintf(theta, sizeof theta, "theta=%g", st["setup"]["b"]["theta"].get<double>());
            CHECK(setup_b.find(theta) != std::string::npos);
        }
    }

    const std::string steps = "[1, " + std::to_string(lessons["steps"].size()) + "]";
    std::ofstream(dir + "/lesson-3.png") << "keep";
    struct Case {
        std::string args;
        const char* says;
    };
    for (const Case& c : {
             Case{"--lesson 99 --out " + dir, steps.c_str()},
             Case{"--lesson x --out " + dir, steps.c_str()},
             Case{"--lesson 0 --out " + dir, steps.c_str()},
             Case{"--lesson 3 --figure scene --out " + dir, "--figure"},
             Case{"--lesson 3 --zeta 0.3 --out " + dir, "--zeta"},
             Case{"--lesson 3 --format bmp --out " + dir, "png"},
             Case{"--lesson 3 --size 100x100 --out " + dir, "320"},
             Case{"--lesson 3 --out " + dir + "/missing", "does not exist"},
             Case{"--lesson 3", "--out"},
             Case{"--lesson 3 --page a3 --caption --format pdf --out " + dir, "a4, letter, column"},
             Case{"--lesson 3 --spec " + dir + "/lesson-3.png --out " + dir, "--spec"},
         }) {
        const Run r = render(c.args);
        INFO(c.args << " -> " << r.err);
        CHECK(r.code == 2);
        CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
        CHECK(r.err.find(c.says) != std::string::npos);
        CHECK(slurp(dir + "/lesson-3.png") == "keep");
        CHECK(::access((dir + "/lesson-3.json").c_str(), F_OK) != 0);
    }
    // A directory where a file of it goes: refused before anything is drawn or written.
    REQUIRE(std::system(("mkdir -p " + dir + "/lesson-3.json").c_str()) == 0);
    const Run blocked = render("--lesson 3 --out " + dir);
    CHECK(blocked.code == 2);
    CHECK(slurp(dir + "/lesson-3.png") == "keep");
}
