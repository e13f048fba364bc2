// The app's whole picture as it paints it (figures/dashboard_painter.hpp), read from its display list: the
// live top view (Dahl and rigid, in the body and the ground frame) and the why panel below, in presentation
// mode (text, lines and markers 1.4 times larger), in compare mode (A's and B's top views side by side) and
// in both, on a 1280 x 800 window and on a 1920 x 1080 screen at scale 1.5 (1280 x 720 logical), at
// theta = 0, 30, 90 and 150 degrees, through a steady period. Nothing may be hidden or unreadable: no two
// texts overlap (within a panel or across panels: the two top views' axis titles overlapped in the ground
// frame), no label lies on an arrow, a marker or the body's outline, no arrow runs along another or hides
// under a marker (B's v arrow at theta = 0 was shorter than P's marker in presentation mode), and every
// text stays inside its panel (the ground frame's long x title was cut off at both edges).
#include "layout_checks.hpp"

#include "figures/figure_painter.hpp"
#include "figures/render_session.hpp"
#include "gui/dashboard.hpp"
#include "gui/screen_layout.hpp"

#include "fv/live_panels.hpp"
#include "fv/live_sim.hpp"
#include "fv/ode_solver.hpp"

#include <catch2/catch.hpp>

#include <memory>
#include <optional>
#include <string>
#include <variant>

namespace {

using fv::gfx::DisplayList;
using fv::gfx::Rect;
using fv::gfx::Vec2;

fv::app::RenderSession& session() {
    static const std::unique_ptr<fv::app::RenderSession> s = [] {
        fv::gfx::ContextOptions o;
        o.backend = fv::gfx::Backend::Headless;
        o.width = 1280, o.height = 800;
        return std::make_unique<fv::app::RenderSession>(o);
    }();
    return *s;
}

// A simulation in its steady period (Dahl: from the steady lag; rigid: two periods in, where it is periodic).
std::unique_ptr<fv::LiveSim> steady_sim(fv::Model model, double zeta, double theta_deg) {
    const fv::Params p{zeta, theta_deg * fv::kPi / 180, 2, 0};
    auto sim = std::make_unique<fv::LiveSim>(model, p);
    if (model == fv::Model::dahl) sim->start_steady(fv::ode_solve(p).lag);
    sim->step(2 * sim->steps_per_period());
    return sim;
}

struct Mode {
    const char* name;
    bool presentation, compare;
};

// What a panel painted into `bounds` recorded: its commands [first, last).
struct Painted {
    Rect bounds;
    std::size_t first, last;
};

} // namespace

TEST_CASE("The app's picture reads in presentation and compare mode at every angle, on two screens",
          "[layout][labels][live][why][present]") {
    fv::app::RenderSession& s = session();
    const Vec2 pages[] = {{1280, 800}, {1280, 720}}; // the window; 1920 x 1080 at scale 1.5
    const Mode modes[] = {{"presentation", true, false}, {"compare", false, true}, {"both", true, true}};
    constexpr int kSteps = 6;
    int paints = 0, arrows = 0, labels = 0;
    for (const Vec2 page : pages)
        for (const Mode& mode : modes)
            for (const fv::Model model : {fv::Model::dahl, fv::Model::rigid})
                for (const double zeta : {0.15, 0.5})
                    for (const double theta : {0.0, 30.0, 90.0, 150.0})
                        for (const fv::FrameChoice frame : {fv::FrameChoice::body, fv::FrameChoice::ground}) {
                            // B at the next angle round (0 beside A's 150): each angle is drawn as A and as
                            // B. The panels are painted as paint_dashboard paints them, one at a time so
                            // that each one's commands are known.
                            const double theta_b =
                                theta == 0 ? 30 : (theta == 30 ? 90 : (theta == 90 ? 150 : 0));
                            auto a = steady_sim(model, zeta, theta);
                            auto b = steady_sim(model, zeta, theta_b);
                            const Rect pictures = fv::app::screen_layout(page, mode.presentation).pictures;
                            const fv::app::DashboardLayout l =
                                fv::app::layout_dashboard(pictures, mode.compare);
                            const float k = mode.presentation ? fv::app::kPresentationScale : 1.0f;
                            fv::ViewState view;
                            view.frame = frame;
                            // The top view's aspect as the app sets it: the data area's, from a frame before.
                            fv::MechanismBase base;
                            const std::optional<fv::RatioCurves> none;
                            for (int step = 0; step < kSteps; ++step) {
                                const int n = a->steps_per_period() / kSteps;
                                a->step(n), b->step(b->steps_per_period() / kSteps);
                                const fv::app::CompareSetup setup{*b, view, none, false};
                                const fv::app::DashboardPanels panels =
                                    fv::app::dashboard_panels(*a, view, none, false, fv::app::LowerPanel::why,
                                                              {}, &base, mode.compare ? &setup : nullptr);
                                fv::gfx::Canvas& canvas = s.canvas();
                                canvas.begin(page, 1, fv::gfx::colors::white);
                                std::vector<Painted> painted;
                                auto paint = [&](const fv::PanelData& p, const Rect& r) {
                                    const std::size_t first = canvas.display_list().commands.size();
                                    const Rect area =
                                        fv::app::paint_panel(canvas, fv::app::enlarged(p, k), r).area;
                                    painted.push_back({r, first, canvas.display_list().commands.size()});
                                    return area;
                                };
                                const Rect top = paint(panels.top_view, l.top_view);
                                if (panels.top_view_b) paint(*panels.top_view_b, l.top_view_b);
                                paint(panels.force, l.force);
                                paint(panels.lower, l.ratio);
                                canvas.end_recording();
                                const DisplayList& list = canvas.display_list();
                                if (view.aspect == 0) {
                                    // The first frame only measures the data area (the app's first frame).
                                    view.aspect = static_cast<double>(top.width()) / top.height();
                                    --step;
                                    continue;
                                }
                                ++paints;
                                for (const auto& c : list.commands) {
                                    labels += std::holds_alternative<fv::gfx::dl::Text>(c);
                                    arrows += std::holds_alternative<fv::gfx::dl::Arrow>(c);
                                }
                                INFO(page.x << "x" << page.y << " " << mode.name << ", "
                                            << fv::to_string(model) << ", zeta " << zeta << ", theta "
                                            << theta << " (B " << theta_b << "), " << fv::to_string(frame)
                                            << " frame, step " << step);
                                CHECK(fv::test::overlapping_texts(list, s.fonts(), 1.0f) == "");
                                CHECK(fv::test::label_on_shape(list, s.fonts(), true) == "");
                                CHECK(fv::test::arrow_on_arrow(list) == "");
                                CHECK(fv::test::hidden_arrow(list, 6) == "");
                                for (const Painted& p : painted)
                                    CHECK(fv::test::text_outside(list, s.fonts(), p.first, p.last,
                                                                 p.bounds) == "");
                            }
                        }
    CHECK(paints == 2 * 3 * 2 * 2 * 4 * 2 * kSteps);
    CHECK(labels > 10 * paints);
    CHECK(arrows > 4 * paints);
}

TEST_CASE("The app's picture checks see what they look for", "[layout][labels][live]") {
    // An arrow 5 units long from the middle of an 11-unit marker is hidden; 20 units long it is not.
    fv::gfx::Canvas& canvas = session().canvas();
    canvas.begin({200, 200}, 1, fv::gfx::colors::white);
    canvas.arrow({50, 50}, {55, 50}, {{fv::gfx::colors::black, 2.5f, fv::gfx::LineStyle::Solid}, 3, 2});
    canvas.arrow({100, 100}, {120, 100}, {{fv::gfx::colors::black, 2.5f, fv::gfx::LineStyle::Solid}, 8, 5});
    canvas.marker({50, 50},
                  {fv::gfx::MarkerShape::Circle, 11, fv::gfx::colors::black, fv::gfx::colors::white, 1.5f});
    canvas.marker({100, 100},
                  {fv::gfx::MarkerShape::Circle, 11, fv::gfx::colors::black, fv::gfx::colors::white, 1.5f});
    canvas.text({10, 150}, "a title too long for a narrow box", {});
    canvas.end_recording();
    const DisplayList& list = canvas.display_list();
    const std::string hidden = fv::test::hidden_arrow(list, 6);
    CHECK(hidden.find("(50.0") != std::string::npos);
    CHECK(fv::test::text_outside(list, session().fonts(), 0, list.commands.size(), {0, 0, 80, 200}) != "");
    CHECK(fv::test::text_outside(list, session().fonts(), 0, list.commands.size(), {0, 0, 400, 200}) == "");
}
