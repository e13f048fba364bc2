// The top view's steady camera (top_view_frame.hpp): an animate loop keeps every axis reading over all its
// frames (the cases: zeta 0.15, theta 90 or 0, r_disp 2, i 0), the frame holds everything drawn at
// every instant, the app eases to a new parameter set's frame monotonically within kFrameEaseSeconds, and in
// the ground frame a stuck tip stands still on screen while the body drifts and wraps round.
#include "anim/animation.hpp"
#include "figures/render_session.hpp"
#include "gui/app_state.hpp"
#include "tools/tick_numbers.hpp"

#include "fv/live_panels.hpp"
#include "fv/ode_solver.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

using namespace fv;
using namespace fv::app;
using fv::test::numbers_on;

namespace {

gfx::ContextOptions headless(int w, int h) {
    gfx::ContextOptions o;
    o.backend = gfx::Backend::Headless;
    o.width = w;
    o.height = h;
    return o;
}

// A steady simulation of p at a period start.
LiveSim steady_sim(const Params& p) {
    LiveSim sim(Model::dahl, p);
    sim.start_steady(ode_solve(p).lag);
    sim.step(2 * sim.steps_per_period());
    return sim;
}

} // namespace

TEST_CASE("Top view frame: an animate loop keeps every axis reading in every frame", "[frame][animate]") {
    struct Case {
        double theta_deg;
        int periods, frames;
    };
    // The loops: at theta 90 the x range took 28 values in 120 frames, at theta 0 13 in 60.
    for (const Case c : {Case{90, 2, 120}, Case{0, 1, 60}}) {
        anim::Spec spec;
        spec.params = Params{0.15, c.theta_deg * kPi / 180, 2, 0};
        spec.periods = c.periods;
        RenderSession session(headless(spec.width, spec.height));
        anim::Frames frames(spec);
        REQUIRE(frames.count() == c.frames);
        const gfx::Vec2 page = session.logical_page();
        frames.fit(session.canvas(), page, session.pixel_ratio());
        std::vector<std::string> first;
        for (int k = 0; k < frames.count(); ++k) {
            gfx::Canvas& canvas = session.canvas();
            canvas.begin(page, session.pixel_ratio(), gfx::colors::white);
            frames.paint(canvas, page, k);
            canvas.end_recording();
            const std::vector<std::string> numbers = numbers_on(canvas.display_list());
            if (k == 0) {
                first = numbers;
                REQUIRE(first.size() > 10); // the tick labels are there to compare
                continue;
            }
            INFO("theta " << c.theta_deg << ", frame " << k);
            CHECK(numbers == first);
        }
    }
}

TEST_CASE(
    "Top view frame: it holds the body, P, T, the spring, the arrows and the recent trails at every instant",
    "[frame]") {
    for (const double theta_deg : {0.0, 30.0, 90.0, 150.0})
        for (const double rdisp : {0.5, 2.0, 10.0}) {
            const Params p{0.3, theta_deg * kPi / 180, rdisp, 0};
            LiveSim sim = steady_sim(p);
            const int n = sim.steps_per_period();
            for (int k = 0; k < 24; ++k) {
                sim.step(n / 24);
                const PanelData panel = top_view_panel(sim, ViewState{});
                INFO("theta " << theta_deg << ", r_disp " << rdisp << ", step " << k);
                REQUIRE(panel.x_min);
                const double x0 = *panel.x_min, x1 = *panel.x_max, y0 = *panel.y_min, y1 = *panel.y_max;
                auto in = [&](const Vec2& q) {
                    return q.x() >= x0 && q.x() <= x1 && q.y() >= y0 && q.y() <= y1;
                };
                // Every series but the trails' older, faded parts (the newest fifth of the 1.5 periods drawn
                // is in the frame's half period), which may leave at the edge.
                for (const SeriesData& s : panel.series)
                    for (std::size_t j = 0; j < s.x.size() && s.opacity == 1; ++j)
                        CHECK(in(Vec2(s.x[j], s.y[j])));
                for (const ArrowData& a : panel.arrows) CHECK((in(a.from) && in(a.to)));
                for (const PointData& q : panel.points) CHECK(in(q.at));
                for (const CircleData& c : panel.circles) {
                    CHECK(in(c.center + Vec2(c.radius, c.radius)));
                    CHECK(in(c.center - Vec2(c.radius, c.radius)));
                }
                // The frame's size is the parameters', not the moment's.
                CHECK(x1 - x0 == Approx(steady_frame(Model::dahl, p, 1.5).width()).epsilon(1e-12));
            }
        }
}

TEST_CASE("Top view frame: the app eases to a new parameter set's frame, monotonically, in 0.3 s",
          "[frame][gui]") {
    AppState a(Model::dahl, Params{0.15, kPi / 2, 2, 0}, 0.7, 60);
    const FrameBox before = *a.view().box;
    CHECK(before == steady_frame(Model::dahl, Params{0.15, kPi / 2, 2, 0}, 1.5));
    UiEdits e;
    e.params = Params{0.6, 0, 5, 0};
    a.sync(e);
    const FrameBox target = steady_frame(Model::dahl, *e.params, 1.5);
    REQUIRE(target != before);
    CHECK(*a.view().box == before); // not a jump: it starts where it was
    FrameBox last = before;
    auto between = [](double v, double lo, double hi) {
        return v >= std::min(lo, hi) - 1e-12 && v <= std::max(lo, hi) + 1e-12;
    };
    auto towards = [](double now, double prev, double to) {
        return std::abs(to - now) <= std::abs(to - prev);
    };
    int frames = 0;
    while (!(*a.view().box == target) && frames < 100) {
        a.advance(1.0 / 60);
        ++frames;
        const FrameBox b = *a.view().box;
        INFO("frame " << frames);
        CHECK(between(b.x0, before.x0, target.x0));
        CHECK(between(b.x1, before.x1, target.x1));
        CHECK(between(b.y0, before.y0, target.y0));
        CHECK(between(b.y1, before.y1, target.y1));
        CHECK((towards(b.x0, last.x0, target.x0) && towards(b.x1, last.x1, target.x1) &&
               towards(b.y0, last.y0, target.y0) && towards(b.y1, last.y1, target.y1)));
        last = b;
    }
    // 0.3 s at 60 frames per second: 18 frames, neither a jump nor a crawl.
    CHECK(frames == 18);
    a.advance(1.0 / 60);
    CHECK(*a.view().box == target); // and it stays
    // Playing or paused, the frame does not move with the motion.
    UiEdits play;
    play.playing = true;
    a.sync(play);
    for (int k = 0; k < 120; ++k) {
        a.advance(1.0 / 60);
        REQUIRE(*a.view().box == target);
    }
}

TEST_CASE("Top view frame: in the ground frame a stuck tip stands still while the body drifts past",
          "[frame][ground]") {
    // theta = 0, i = 0 (as the scene test): the tip sticks from tau1 (P turns back: zeta + cos tau = 0)
    // until P has come forward to where it turned (tau3 > tau2 = 2 pi - tau1).
    const Params p{0.3, 0, 1, 0};
    const double tau1 = std::acos(-p.zeta), tau2 = 2 * kPi - tau1;
    LiveSim sim = steady_sim(p);
    auto go_to = [&](double phase) {
        const double target = std::floor(sim.tau() / (2 * kPi)) * 2 * kPi + phase;
        sim.step(std::max(0, static_cast<int>(std::lround((target - sim.tau()) / sim.dtau()))));
    };
    go_to(tau1 + 0.05);
    ViewState ground, body;
    ground.frame = FrameChoice::ground;
    // The T marks drawn inside the axes (the wrap draws copies one window apart; the ones outside are not
    // drawn), and P's.
    auto marks = [](const PanelData& panel, Mark mark) {
        std::vector<Vec2> v;
        for (const PointData& q : panel.points)
            if (q.mark == mark && q.at.x() >= *panel.x_min && q.at.x() <= *panel.x_max) v.push_back(q.at);
        return v;
    };
    const PanelData g0 = top_view_panel(sim, ground), b0 = top_view_panel(sim, body);
    const std::vector<Vec2> t0 = marks(g0, Mark::square);
    REQUIRE(!t0.empty());
    const Vec2 P0 = marks(g0, Mark::circle).at(0);
    const double body_t0 = marks(b0, Mark::square).at(0).x() - *b0.x_min;
    int checked = 0;
    double body_moved = 0, p_moved = 0;
    while (sim.tau() - std::floor(sim.tau() / (2 * kPi)) * 2 * kPi < tau2 - 0.05) {
        sim.step(4);
        REQUIRE(!sim.slipping());
        const PanelData g = top_view_panel(sim, ground), b = top_view_panel(sim, body);
        CHECK(*g.x_min == *g0.x_min); // the floor's window stands
        CHECK(*g.x_max == *g0.x_max);
        const std::vector<Vec2> t = marks(g, Mark::square);
        bool same = false;
        for (const Vec2& q : t)
            for (const Vec2& q0 : t0) same = same || (q - q0).norm() < 1e-9;
        INFO("tau " << sim.tau());
        CHECK(same);
        body_moved = std::max(body_moved, std::abs(marks(b, Mark::square).at(0).x() - *b.x_min - body_t0));
        p_moved = std::max(p_moved, (marks(g, Mark::circle).at(0) - P0).norm());
        ++checked;
    }
    CHECK(checked > 20);
    CHECK(p_moved > 0.3);    // P goes back and forth meanwhile
    CHECK(body_moved > 0.1); // and in the body frame the stuck tip slides across the screen
    // Over many periods the body drifts through the window and wraps round: P is always drawn in it.
    for (int k = 0; k < 200; ++k) {
        sim.step(sim.steps_per_period() / 10);
        const PanelData g = top_view_panel(sim, ground);
        CHECK(marks(g, Mark::circle).size() >= 1);
    }
}

TEST_CASE("Top view frame: the choice goes from the panel to the view and to an exported animation",
          "[frame][gui]") {
    AppState a(Model::dahl, Params{0.3, 0, 2, 0}, 0.7, 60);
    CHECK(a.view().frame == FrameChoice::body); // the default, as before the choice
    UiEdits e;
    e.frame = FrameChoice::ground;
    e.export_animation = AnimationRequest{"loop.gif", AnimationSpec{}};
    const AppState::Actions act = a.sync(e);
    CHECK(a.view().frame == FrameChoice::ground);
    REQUIRE(act.export_animation);
    CHECK(act.export_animation->spec.frame == FrameChoice::ground);
    // A double-click resets zoom and pan, not the frame.
    UiEdits reset;
    reset.reset_view = true;
    a.sync(reset);
    CHECK(a.view().frame == FrameChoice::ground);
}
