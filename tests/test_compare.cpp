// Compare mode (setup B beside A): the default B, one time base, B through the share link, the session file,
// the script and the sync point, the two top views' places, and `animate --view compare`'s loop holding every
// axis reading over all its frames. (The lesson step with B and both r_x against Eqs. (10)-(11):
// test_lessons.cpp.)
#include "anim/animation.hpp"
#include "figures/dashboard_painter.hpp"
#include "figures/render_session.hpp"
#include "gui/app_state.hpp"
#include "gui/lessons.hpp"
#include "gui/screen_layout.hpp"
#include "gui/script.hpp"
#include "gui/session.hpp"
#include "gui/session_link.hpp"
#include "tools/tick_numbers.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

using namespace fv;
using namespace fv::app;

namespace {

bool same(const Setup& a, const Setup& b) {
    return a == b;
}

// The steps compare mode was turned on at tau = 0: both simulations at the same tau within one step of the
// coarser.
void check_one_time_base(const AppState& a) {
    const double step = std::max(a.sim().dtau(), a.sim_b().dtau());
    CHECK(std::abs(a.sim().tau() - a.sim_b().tau()) <= step);
}

bool overlap(const gfx::Rect& a, const gfx::Rect& b) {
    return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}

} // namespace

TEST_CASE("compare: B starts as A at the other angle, 90 degrees or else 0", "[compare]") {
    Setup a;
    a.params = Params{0.3, 30 * kPi / 180, 5, 0};
    a.start = Start::sliding;
    Setup b = compare_default(a);
    CHECK(b.params.theta == kPi / 2);
    CHECK(b.params.zeta == 0.3);
    CHECK(b.params.rdisp == 5);
    CHECK(b.params.i == 0);
    CHECK(b.start == Start::sliding);
    a.params.theta = 90 * kPi / 180; // as a link or a flag gives it
    CHECK(compare_default(a).params.theta == 0);
    a.params.theta = 0;
    CHECK(compare_default(a).params.theta == kPi / 2);
}

TEST_CASE("compare: turned on at the sync point, B beside A on one time base, B's edits its own",
          "[compare]") {
    AppState a(Model::dahl, Params{0.15, 60 * kPi / 180, 2, 1}, 0.7, 60);
    for (int k = 0; k < 30; ++k) a.sync({}), a.advance(1.0 / 60);
    UiEdits on;
    on.compare = true;
    on.params = Params{0.2, 60 * kPi / 180, 2, 1}; // A's edit of the same frame comes first
    CHECK_FALSE(a.ui().session.compare);
    a.sync(on);
    REQUIRE(a.ui().session.compare);
    CHECK(a.ui().session.b.params.zeta == 0.2);
    CHECK(a.ui().session.b.params.theta == kPi / 2);
    CHECK(a.sim().tau() == 0); // both start again together
    CHECK(a.sim_b().tau() == 0);
    CHECK(a.sim_b().params().theta == kPi / 2);
    for (int k = 0; k < 45; ++k) a.sync({}), a.advance(1.0 / 60);
    CHECK(a.sim().tau() > 1);
    check_one_time_base(a);

    // B's edits: checked against the same table as A's, and B's alone.
    UiEdits eb;
    eb.b.params = Params{0.5, 0, 3, 0};
    a.sync(eb);
    CHECK(a.ui().session.b.params.rdisp == 3);
    CHECK(a.sim_b().params().rdisp == 3);
    CHECK(a.ui().session.params.rdisp == 2);
    CHECK(a.sim().params().rdisp == 2);
    UiEdits bad;
    bad.b.params = Params{500, 0, 3, 0};
    a.sync(bad);
    CHECK(a.ui().session.b.params.zeta == 0.5);
    CHECK(a.ui().status == "setup B: zeta = 500; allowed: zeta in [0, 100]");
    // B's curves come from its own worker, never A's.
    a.worker_b().wait_idle();
    const auto cb = a.worker_b().latest();
    REQUIRE(cb);
    CHECK(cb->request.params.zeta == 0.5);
    CHECK(cb->request.params.theta == 0);
    // Reset: both from tau = 0.
    for (int k = 0; k < 10; ++k) a.sync({}), a.advance(1.0 / 60);
    UiEdits reset;
    reset.reset = true;
    a.sync(reset);
    CHECK(a.sim().tau() == 0);
    CHECK(a.sim_b().tau() == 0);
    // The panel edits B when asked, A otherwise; compare off ends that.
    UiEdits edit;
    edit.editing_b = true;
    a.sync(edit);
    CHECK(a.ui().editing_b);
    UiEdits off;
    off.compare = false;
    a.sync(off);
    CHECK_FALSE(a.ui().session.compare);
    CHECK_FALSE(a.ui().editing_b);
}

TEST_CASE("compare: B goes through the share link and back, bit for bit, and b.* keys turn compare on",
          "[compare]") {
    Session s;
    s.params = Params{0.3, 60 * kPi / 180, 5, 1};
    s.compare = true;
    s.b = Setup{Model::rigid, Params{0.7, 0.1, 0.5, 2.5}, Start::sliding};
    const std::string link = session_link(s);
    CHECK(link.find("&b.zeta=0.7&b.theta=") != std::string::npos);
    CHECK(link.find("&b.model=rigid&b.start=sliding") != std::string::npos);
    Session back;
    apply_link(parse_share_link(link), back);
    CHECK(back.compare);
    CHECK(same(back.b, s.b));
    CHECK(same(back.a(), s.a()));
    // Without compare the link has no b.* key (links from before compare read as before).
    s.compare = false;
    CHECK(session_link(s).find("b.") == std::string::npos);
    // One b.* key: compare on, the rest A's at the other angle.
    Session one;
    apply_link(parse_share_link("?zeta=0.4&theta=90&rdisp=3&i=0&b.zeta=0.2"), one);
    CHECK(one.compare);
    CHECK(one.b.params.zeta == 0.2);
    CHECK(one.b.params.theta == 0);
    CHECK(one.b.params.rdisp == 3);
    CHECK(one.b.params.i == 0);
    // A lesson step's B comes with ?lesson=N, and b.* keys go over it (or over the step's A at the other
    // angle where the step has none).
    const LessonStep& mean = *find_lesson_step("mean");
    int mean_n = 0;
    while (&lesson_steps()[static_cast<std::size_t>(mean_n)] != &mean) ++mean_n;
    Session l4;
    apply_link(parse_link("?lesson=" + std::to_string(mean_n + 1)), l4);
    CHECK(l4.compare);
    CHECK(same(l4.b, *mean.setup.b));
    Session l4z;
    apply_link(parse_link("?lesson=" + std::to_string(mean_n + 1) + "&b.zeta=0.9"), l4z);
    CHECK(l4z.b.params.zeta == 0.9);
    CHECK(l4z.b.params.theta == mean.setup.b->params.theta);
    const LessonStep& across = *find_lesson_step("across");
    REQUIRE_FALSE(across.setup.b);
    Session l3;
    apply_link(parse_link("?lesson=3&b.theta=0"), l3);
    CHECK(l3.compare);
    CHECK(l3.b.model == across.setup.model);
    CHECK(l3.b.params.zeta == across.setup.params.zeta);
    CHECK(l3.b.params.theta == 0);
    Session l1;
    l1.compare = true; // a step without B turns compare mode off
    apply_link(parse_link("?lesson=1"), l1);
    CHECK_FALSE(l1.compare);
    // B's keys are checked as A's: a setup, so an error (not a notice), with B's key named.
    auto refusal = [](const std::string& text) {
        try {
            parse_share_link(text);
        } catch (const LinkError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    CHECK(refusal("?b.theta=400") ==
          "column 10: b.theta = 400 is out of range; allowed: b.theta in [0, 180]");
    CHECK(refusal("?b.model=coulomb") == "column 10: b.model = 'coulomb'; allowed: dahl, rigid");
    CHECK(refusal("?b.zeta=1&b.zeta=2") == "column 11: 'b.zeta' is given twice; each key at most once");
    CHECK(refusal("?b.frame=ground").rfind("column 2: unknown key 'b.frame'; allowed: ", 0) == 0);
}

TEST_CASE("compare: B goes through the session file and back, and a bad B is refused where it is",
          "[compare]") {
    Session s;
    s.compare = true;
    s.b = Setup{Model::dahl, Params{0.45, 20 * kPi / 180, 7, 0.5}, Start::sliding};
    const std::string text = session_json(s);
    CHECK(text.find("\"compare\": {") != std::string::npos);
    const Session back = parse_session(text, "s.json");
    CHECK(back.compare);
    CHECK(same(back.b, s.b));
    // Off: no "compare" key, and a file without one is off.
    s.compare = false;
    const std::string off = session_json(s);
    CHECK(off.find("compare") == std::string::npos);
    CHECK_FALSE(parse_session(off, "s.json").compare);
    // A key left out is A's, theta at the other angle.
    const Session part =
        parse_session(R"({"version": 1, "theta": 90, "zeta": 0.4, "compare": {"i": 0}})", "p.json");
    CHECK(part.compare);
    CHECK(part.b.params.zeta == 0.4);
    CHECK(part.b.params.theta == 0);
    CHECK(part.b.params.i == 0);
    auto refusal = [](const std::string& file_text) {
        try {
            parse_session(file_text, "b.json");
        } catch (const SessionError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    CHECK(refusal(R"({"version": 1, "compare": {"theta": 400}})") ==
          "b.json:1:37: theta = 400 is out of range; allowed: theta in [0, 180]");
    CHECK(refusal(R"({"version": 1, "compare": {"frame": "body"}})") ==
          "b.json:1:28: unknown key \"frame\" in \"compare\"; allowed: model, zeta, theta, rdisp, i, start");
    CHECK(refusal(R"({"version": 1, "compare": 3})") ==
          "b.json:1:27: compare: expected an object {\"theta\": 0, ..} (setup B) or null, got a number");
}

TEST_CASE("compare: the script turns it on and sets B, checked when loaded", "[compare][script]") {
    char tmpl[] = "/tmp/fv-compare-XXXXXX";
    const std::string dir = ::mkdtemp(tmpl);
    const std::string path = dir + "/c.txt";
    std::ofstream(path) << "0 theta 90\n2 b.theta 30\n2 b.model rigid\n4 edit b\n6 compare off\n";
    const Script script = load_script(path);
    AppState a(Model::dahl, Params{0.15, kPi / 2, 2, 1}, 0.7, 60);
    for (int f = 0; f < 8; ++f) {
        a.sync(script_edits(script, f, a.ui()));
        if (f == 2) {
            REQUIRE(a.ui().session.compare); // a b.* key turns it on
            CHECK(a.ui().session.b.params.theta == 30 * kPi / 180);
            CHECK(a.ui().session.b.model == Model::rigid);
            CHECK(a.ui().session.b.params.zeta == 0.15); // the rest: A's
        }
        if (f == 4) CHECK(a.ui().editing_b);
    }
    CHECK_FALSE(a.ui().session.compare);
    for (const char* bad : {"0 compare maybe\n", "0 b.theta 400\n", "0 edit c\n", "0 b.model x\n"}) {
        std::ofstream(path) << bad;
        INFO(bad);
        CHECK_THROWS_AS(load_script(path), std::runtime_error);
    }
}

TEST_CASE("compare: the two top views share the top view's place without overlapping each other or the plots",
          "[compare][layout]") {
    for (const gfx::Vec2 page :
         {gfx::Vec2{1024, 640}, gfx::Vec2{1280, 800}, gfx::Vec2{1280, 720}, gfx::Vec2{390, 844}}) {
        for (const bool present : {false, true}) {
            INFO(page.x << "x" << page.y << (present ? " presentation" : ""));
            const ScreenLayout s = screen_layout(page, present);
            const DashboardLayout one = layout_dashboard(s.pictures),
                                  two = layout_dashboard(s.pictures, true);
            CHECK(two.force.x0 == one.force.x0);
            CHECK(two.ratio.y1 == one.ratio.y1);
            const std::vector<gfx::Rect> rects{two.top_view, two.top_view_b, two.force, two.ratio};
            for (std::size_t i = 0; i < rects.size(); ++i) {
                CHECK(rects[i].width() > 100);
                CHECK(rects[i].height() > 100);
                // Inside the pictures' area, and off the control panel.
                CHECK(rects[i].x0 >= s.pictures.x0);
                CHECK(rects[i].x1 <= s.pictures.x1);
                CHECK(rects[i].y0 >= s.pictures.y0);
                CHECK(rects[i].y1 <= s.pictures.y1);
                CHECK_FALSE(overlap(rects[i], s.controls));
                for (std::size_t j = i + 1; j < rects.size(); ++j) CHECK_FALSE(overlap(rects[i], rects[j]));
            }
            // The same size each, A's first (left, or above on an upright page).
            CHECK(two.top_view.width() == Approx(two.top_view_b.width()));
            CHECK(two.top_view.height() == Approx(two.top_view_b.height()));
            CHECK((two.top_view.x1 <= two.top_view_b.x0 || two.top_view.y1 <= two.top_view_b.y0));
        }
    }
}

TEST_CASE("compare: an animate --view compare loop keeps every axis reading of both top views and the plots",
          "[compare][animate]") {
    for (const FrameChoice frame : {FrameChoice::body, FrameChoice::ground}) {
        anim::Spec spec;
        spec.view = anim::View::compare;
        spec.params = Params{0.15, kPi / 2, 2, 0};
        spec.b = compare_default({spec.model, spec.params, Start::rest});
        spec.frame = frame;
        spec.periods = 1;
        gfx::ContextOptions o;
        o.backend = gfx::Backend::Headless;
        o.width = spec.width;
        o.height = spec.height;
        RenderSession session(o);
        anim::Frames frames(spec);
        REQUIRE(frames.count() == 60);
        REQUIRE(frames.frame_box_b());
        const gfx::Vec2 page = session.logical_page();
        frames.fit(session.canvas(), page, session.pixel_ratio());
        std::vector<std::string> first;
        bool saw_a = false, saw_b = false;
        for (int k = 0; k < frames.count(); ++k) {
            gfx::Canvas& canvas = session.canvas();
            canvas.begin(page, session.pixel_ratio(), gfx::colors::white);
            frames.paint(canvas, page, k);
            canvas.end_recording();
            const std::vector<std::string> numbers = fv::test::numbers_on(canvas.display_list());
            for (const auto& c : canvas.display_list().commands)
                if (const auto* t = std::get_if<gfx::dl::Text>(&c)) {
                    saw_a = saw_a || t->text.rfind("A: θ = 90°", 0) == 0;
                    saw_b = saw_b || t->text.rfind("B: θ = 0°", 0) == 0;
                }
            if (k == 0) {
                first = numbers;
                REQUIRE(first.size() > 20); // four panels' tick labels
                continue;
            }
            INFO((frame == FrameChoice::body ? "body" : "ground") << " frame " << k);
            CHECK(numbers == first);
        }
        CHECK(saw_a);
        CHECK(saw_b);
    }
}
