// Layout of every registered figure, read from its display list:
// - no legend box touches a plotted sample: a series' samples and the segments between them, markers;
// - no text reads as a negative zero ("-0", "−0.0000");
// - on a narrow page (640x400 logical, the "clipped at 640x400") no text leaves the page;
// - no two texts of a figure overlap (labels, ticks, titles, legends), on the default page and the
// snapshots';
// - every force plot states its sign convention, F = (P − T) F_c / z_ss, on its axis and in its caption;
// - format_number never prints a negative zero;
// - the app's live top view, through a steady period at theta = 0, 30, 90 and 150 degrees in the body and the
// ground frame: no two texts overlap, no label lies on an arrow or a marker, no arrow lies along another;
// - on a journal column (render --page column, full-size text on 330 units): no two texts overlap, no label
// on an arrow or a marker, no text off the page or below 12 units, every panel's legend drawn and off the
// data, every data area at least 150 x 90 units; and the same check flags the side-by-side layout it
// replaced.
#include "figures/figure_painter.hpp"
#include "figures/render_figures.hpp"
#include "figures/render_session.hpp"
#include "gui/app_state.hpp"
#include "gui/dashboard.hpp"

#include "fv/figure_data.hpp"
#include "fv/figure_registry.hpp"
#include "fv/figures.hpp"
#include "fv/format.hpp"
#include "fv/live_panels.hpp"
#include "fv/ode_solver.hpp"
#include "fv/setup_picture.hpp"
#include "tools/figure_examples.hpp"

#include "layout_checks.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <random>
#include <regex>
#include <string>
#include <tuple>
#include <utility>
#include <variant>
#include <vector>

namespace {

using fv::gfx::DisplayList;
using fv::gfx::Rect;
using fv::gfx::Vec2;
using fv::test::arrow_on_arrow;
using fv::test::label_on_shape;
using fv::test::overlapping_texts;

// Every registered figure with its example inputs (fig19 with the synthetic example data), and the scene at
// θ = 90° where r_y is zero up to round-off (it printed "r_y = -0.0000" in the title); computed once.
const std::vector<fv::FigureData>& figures() {
    static const std::vector<fv::FigureData> out = [] {
        std::vector<fv::FigureData> v;
        for (const fv::FigureEntry& e : fv::figure_registry()) {
            v.push_back(fv::compute_figure(e.make(fv::test::example_inputs(e))));
        }
        v.push_back(fv::compute_figure(fv::scene_figure({0.5, fv::kPi / 2, 3.02, 0})));
        // Families of maps as small multiples (a full 2 x 3 grid, and 2 x 2 Dahl maps and the rigid one: a
        // last row with a gap), on a coarse grid of cells: the layout, not the numbers.
        for (const auto& [rdisp, i, models] :
             {std::tuple{std::vector<double>{1, 3, 10}, std::vector<double>{0.5, 1},
                         std::vector{fv::Model::dahl}},
              std::tuple{std::vector<double>{1, 3}, std::vector<double>{0.5, 1},
                         std::vector{fv::Model::dahl, fv::Model::rigid}}}) {
            fv::FigureInputs in;
            in.rdisp = rdisp, in.i = i, in.models = models;
            fv::FigureSpec spec = fv::find_registered("map")->make(in);
            auto& m = std::get<fv::MapFigure>(spec.content);
            m.zetas = fv::linspace(0.02, 3, 20);
            m.theta_count = 10;
            v.push_back(fv::compute_figure(spec));
        }
        return v;
    }();
    return out;
}

// A session drawing on a logical page of width x height (default 1280x800, render's default), one per size.
fv::app::RenderSession& session(int width = 1280, int height = 800) {
    static std::map<std::pair<int, int>, std::unique_ptr<fv::app::RenderSession>> sessions;
    auto& s = sessions[{width, height}];
    if (!s) {
        fv::gfx::ContextOptions o;
        o.backend = fv::gfx::Backend::Headless;
        o.width = width;
        o.height = height;
        s = std::make_unique<fv::app::RenderSession>(o);
    }
    return *s;
}

// Whether a point lies in the rectangle grown by `pad`.
bool inside(Vec2 p, const Rect& r, float pad) {
    return p.x >= r.x0 - pad && p.x <= r.x1 + pad && p.y >= r.y0 - pad && p.y <= r.y1 + pad;
}

// Whether the straight segment a-b passes through the rectangle: walked in steps of a quarter pixel.
bool segment_enters(Vec2 a, Vec2 b, const Rect& r, float pad) {
    if (!std::isfinite(a.x) || !std::isfinite(a.y) || !std::isfinite(b.x) || !std::isfinite(b.y))
        return false;
    const float len = std::hypot(b.x - a.x, b.y - a.y);
    const int n = 1 + static_cast<int>(len * 4);
    for (int k = 0; k <= n; ++k) {
        const float t = static_cast<float>(k) / static_cast<float>(n);
        if (inside({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)}, r, pad)) return true;
    }
    return false;
}

// What in the data regions of a display list touches `box`: a description, empty when nothing does.
std::string sample_in(const DisplayList& list, const Rect& box) {
    for (const fv::gfx::Region& data : list.regions) {
        if (data.role != "data") continue;
        for (std::size_t k = data.first; k < data.last; ++k) {
            const auto& c = list.commands[k];
            if (const auto* pl = std::get_if<fv::gfx::dl::Polyline>(&c)) {
                const float w = 0.5f * pl->stroke.width;
                for (std::size_t i = 0; i < pl->points.size(); ++i) {
                    const Vec2 a = pl->points[i], b = pl->points[i + 1 < pl->points.size() ? i + 1 : i];
                    if (segment_enters(a, b, box, w))
                        return "a line through (" + std::to_string(a.x) + ", " + std::to_string(a.y) + ")";
                }
            } else if (const auto* m = std::get_if<fv::gfx::dl::Marker>(&c)) {
                if (inside(m->center, box, 0.5f * m->style.size))
                    return "a marker at (" + std::to_string(m->center.x) + ", " +
                           std::to_string(m->center.y) + ")";
            }
        }
    }
    return "";
}

// Render's default page, the snapshots', and narrower ones down to the smallest allowed, 320x240.
const Vec2 kPages[] = {{1280, 800}, {960, 600}, {640, 400}, {480, 320}, {320, 240}};

} // namespace

TEST_CASE("table_suffixes names every table compute_figure makes, for every registered figure",
          "[figures][render]") {
    // render checks each file it will write before computing anything (docs/reliability.md): the names must
    // be known from the definition alone.
    std::size_t k = 0;
    for (const fv::FigureEntry& e : fv::figure_registry()) {
        std::vector<std::string> computed;
        for (const fv::TableData& t : figures().at(k++).tables) computed.push_back(t.suffix);
        CAPTURE(e.id);
        CHECK(fv::table_suffixes(e.make(fv::test::example_inputs(e))) == computed);
    }
}

TEST_CASE("Legends: no legend box covers a plotted sample, in any registered figure", "[layout][legend]") {
    // On render's default page, the snapshots', narrow ones where panels are too small for a legend inside
    // (fig19's (b) covered its curves at 960x600; at 640x400 fig4's and fig19's go below the axes), down to
    // the smallest page, 320x240 (a one-column journal figure), where legends go below in columns.
    int legends = 0;
    for (const Vec2 page : kPages)
        for (const fv::FigureData& fig : figures()) {
            const DisplayList list =
                session(static_cast<int>(page.x), static_cast<int>(page.y)).record_figure(fig);
            for (const fv::gfx::Region& r : list.regions) {
                if (r.role != "legend") continue;
                ++legends;
                INFO(fig.id << " on " << page.x << "x" << page.y << ": legend at (" << r.rect.x0 << ", "
                            << r.rect.y0 << ")-(" << r.rect.x1 << ", " << r.rect.y1 << ")");
                CHECK(sample_in(list, r.rect) == "");
            }
        }
    // Most figures have a legend: the check above ran on them (their number only grows).
    CHECK(legends >= 12);
}

TEST_CASE("Legends: the app's live force plot covers none of its curves as they scroll", "[layout][legend]") {
    // The benchmark's scene (theta 60, r_disp 2, i 0) from the start, through the transient (the period
    // mean joins after a period) into the steady state: F_x, F_y and |F| pass through every part of the axes.
    fv::app::AppState a(fv::Model::dahl, fv::Params{0.3, fv::kPi / 3, 2, 0}, 0.7, 60);
    a.worker().wait_idle(); // the steady r_x line too
    fv::app::UiEdits e;
    e.playing = true;
    e.speed = 1;
    a.sync(e);
    const Rect force = fv::app::layout_dashboard({346, 4, 1276, 796}).force;
    int legends = 0;
    for (int frame = 0; frame < 5 * 60; ++frame) {
        a.advance(1.0 / 60);
        if (frame % 7 != 0) continue;
        fv::gfx::Canvas& canvas = session().canvas();
        canvas.begin({1280, 800}, 1, fv::gfx::colors::white);
        fv::app::paint_panel(canvas, fv::force_panel_live(a.sim(), a.worker().latest()), force);
        canvas.end_recording();
        const DisplayList& list = canvas.display_list();
        for (const fv::gfx::Region& r : list.regions) {
            if (r.role != "legend") continue;
            ++legends;
            INFO("frame " << frame << ": legend at (" << r.rect.x0 << ", " << r.rect.y0 << ")-(" << r.rect.x1
                          << ", " << r.rect.y1 << ")");
            CHECK(sample_in(list, r.rect) == "");
            CHECK(r.rect.x0 >= force.x0);
            CHECK(r.rect.x1 <= force.x1); // within the panel
        }
    }
    CHECK(legends == 43);
}

TEST_CASE("Legends: a label too long for the axes is elided, the box stays inside them", "[layout][legend]") {
    // A pinned curve's label from a hand-written session may be 80 bytes of wide letters (issue: a 1 MB label
    // ran off the plot). The ratio panel at the app's 1280x800 layout.
    fv::app::AppState a(fv::Model::dahl, fv::Params{0.3, fv::kPi / 3, 2, 0}, 0.7, 60);
    a.worker().wait_idle();
    const std::vector<fv::PinnedCurve> pins{
        {std::string(40, 'W') + std::string(40, 'M'), {0.1, 1, 2}, {0.9, 0.5, 0.4}}};
    const Rect ratio = fv::app::layout_dashboard({346, 4, 1276, 796}).ratio;
    fv::gfx::Canvas& canvas = session().canvas();
    canvas.begin({1280, 800}, 1, fv::gfx::colors::white);
    const fv::gfx::PlotTransform tf = fv::app::paint_panel(
        canvas, fv::ratio_panel_live(a.worker().latest(), false, {nullptr, 0, &pins}), ratio);
    canvas.end_recording();
    int legends = 0;
    bool elided = false;
    for (const fv::gfx::Region& r : canvas.display_list().regions) {
        if (r.role != "legend") continue;
        ++legends;
        CHECK(r.rect.x0 >= tf.area.x0);
        CHECK(r.rect.x1 <= tf.area.x1); // inside the axes
        for (std::size_t k = r.first; k < r.last; ++k)
            if (const auto* t = std::get_if<fv::gfx::dl::Text>(&canvas.display_list().commands[k]))
                elided = elided || t->text.find("WWW…") != std::string::npos;
    }
    CHECK(legends == 1);
    CHECK(elided);
}

TEST_CASE("Legends: the check sees a legend over a curve", "[layout][legend]") {
    // The same check on a box put over the first plotted sample of Fig. 5 reports it.
    const auto fig5 = std::find_if(figures().begin(), figures().end(),
                                   [](const fv::FigureData& f) { return f.id == "fig5"; });
    REQUIRE(fig5 != figures().end());
    const DisplayList list = session().record_figure(*fig5);
    bool checked = false;
    for (const fv::gfx::Region& data : list.regions)
        for (std::size_t k = data.first; k < data.last && !checked && data.role == "data"; ++k)
            if (const auto* pl = std::get_if<fv::gfx::dl::Polyline>(&list.commands[k]);
                pl && pl->points.size() > 10) {
                const Vec2 p = pl->points[5];
                CHECK(sample_in(list, {p.x - 30, p.y - 10, p.x + 30, p.y + 10}) != "");
                checked = true;
            }
    CHECK(checked);
}

TEST_CASE("No text of any figure reads as a negative zero", "[layout][minus-zero]") {
    // A minus (ASCII or U+2212) before a number all of whose digits are 0, e.g. "-0", "−0.0000", "-0.00e+00".
    const std::regex negative_zero("(^|[^0-9.])(-|\xE2\x88\x92)0+(\\.0*)?([eE][-+]?[0-9]+)?($|[^0-9.])");
    int texts = 0;
    for (const fv::FigureData& fig : figures()) {
        const DisplayList list = session().record_figure(fig);
        for (const auto& c : list.commands)
            if (const auto* t = std::get_if<fv::gfx::dl::Text>(&c)) {
                ++texts;
                INFO(fig.id << ": \"" << t->text << "\"");
                CHECK_FALSE(std::regex_search(t->text, negative_zero));
            }
    }
    CHECK(texts > 100);
}

TEST_CASE("No text of any figure leaves a narrow page", "[layout][page]") {
    // 640x400 logical units: titles that fit 1280 wide are too long for it (Fig. 15's was cut at both ends);
    // 480x320 and the smallest page, 320x240, shorter still.
    for (const Vec2 page : {Vec2{640, 400}, Vec2{480, 320}, Vec2{320, 240}}) {
        fv::app::RenderSession& narrow = session(static_cast<int>(page.x), static_cast<int>(page.y));
        int texts = 0;
        for (const fv::FigureData& fig : figures()) {
            const DisplayList list = narrow.record_figure(fig);
            REQUIRE(list.size.x == page.x);
            for (const auto& c : list.commands)
                if (const auto* t = std::get_if<fv::gfx::dl::Text>(&c)) {
                    ++texts;
                    const Rect b = fv::gfx::text_bounds(*t, narrow.fonts());
                    INFO(fig.id << " on " << page.x << "x" << page.y << ": \"" << t->text << "\" at (" << b.x0
                                << ", " << b.y0 << ")-(" << b.x1 << ", " << b.y1 << ")");
                    CHECK(b.x0 >= 0);
                    CHECK(b.y0 >= 0);
                    CHECK(b.x1 <= list.size.x);
                    CHECK(b.y1 <= list.size.y);
                }
        }
        CHECK(texts > 100);
    }
}

TEST_CASE("Text stays legible on the smallest page: no text below 7 units", "[layout][page]") {
    // A one-column journal figure is ~250 pt wide; its text is 7-9 pt. At 320x240 (points in the SVG and
    // PDF) text shrinks with the page, but no text of any figure is below 7 units, and tick labels are 7.8.
    for (const Vec2 page : {Vec2{480, 320}, Vec2{320, 240}}) {
        fv::app::RenderSession& s = session(static_cast<int>(page.x), static_cast<int>(page.y));
        float smallest = 1e9f;
        for (const fv::FigureData& fig : figures())
            for (const auto& c : s.record_figure(fig).commands)
                if (const auto* t = std::get_if<fv::gfx::dl::Text>(&c)) {
                    INFO(fig.id << " on " << page.x << "x" << page.y << ": \"" << t->text << "\" at "
                                << t->style.size);
                    CHECK(t->style.size >= 7.0f);
                    smallest = std::min(smallest, t->style.size);
                }
        CHECK(smallest < 12.0f); // the page's text did shrink
    }
}

TEST_CASE("Small multiples: every map's data area the same size, in rows and columns, one colour bar",
          "[layout][grid]") {
    for (const Vec2 page : kPages) {
        fv::app::RenderSession& s = session(static_cast<int>(page.x), static_cast<int>(page.y));
        for (const fv::FigureData& fig : figures()) {
            if (fig.columns == 0) continue;
            INFO(fig.panels.size() << " maps on " << page.x << "x" << page.y);
            const DisplayList list = s.record_figure(fig);
            std::vector<Rect> areas;
            for (const fv::gfx::Region& r : list.regions)
                if (r.role == "data") areas.push_back(r.rect);
            REQUIRE(areas.size() == fig.panels.size());
            const auto cols = static_cast<std::size_t>(fig.columns);
            for (std::size_t k = 0; k < areas.size(); ++k) {
                CHECK(areas[k].width() == Approx(areas[0].width()).margin(1.0));
                CHECK(areas[k].height() == Approx(areas[0].height()).margin(1.0));
                CHECK(areas[k].x0 == Approx(areas[k % cols].x0).margin(0.5));        // its column's
                CHECK(areas[k].y0 == Approx(areas[k / cols * cols].y0).margin(0.5)); // its row's
                for (std::size_t j = 0; j < k; ++j)                                  // apart
                    CHECK((areas[k].x0 >= areas[j].x1 || areas[j].x0 >= areas[k].x1 ||
                           areas[k].y0 >= areas[j].y1 || areas[j].y0 >= areas[k].y1));
            }
            // One legend (below the grid) and one colour bar (one gradient image besides the maps').
            CHECK(std::count_if(list.regions.begin(), list.regions.end(),
                                [](const fv::gfx::Region& r) { return r.role == "legend"; }) == 1);
            CHECK(std::count_if(list.commands.begin(), list.commands.end(), [](const auto& c) {
                      return std::holds_alternative<fv::gfx::dl::Picture>(c);
                  }) == static_cast<long>(fig.panels.size()) + 1);
        }
    }
}

TEST_CASE("Small multiples: one legend names every line and mark of any map once", "[layout][grid]") {
    const auto family = std::find_if(figures().begin(), figures().end(),
                                     [](const fv::FigureData& f) { return f.columns > 0; });
    REQUIRE(family != figures().end());
    fv::FigureData fig = *family;
    // A mark only the second map has (its cells of two stable states), and one more of a line every map has.
    fig.panels.at(1).series.push_back(
        {"2 stable states", {1.0}, {45.0}, fv::Ink::black, fv::Dash::solid, fv::Mark::circle, 0});
    const DisplayList list = session().record_figure(fig);
    std::map<std::string, int> legend_texts;
    for (const fv::gfx::Region& r : list.regions)
        if (r.role == "legend")
            for (std::size_t k = r.first; k < r.last; ++k)
                if (const auto* t = std::get_if<fv::gfx::dl::Text>(&list.commands[k]))
                    ++legend_texts[t->text];
    CHECK(legend_texts["2 stable states"] == 1);
    CHECK(legend_texts["best angle θ*, Dahl"] == 1);
    CHECK(legend_texts["best angle θ*, rigid"] == 1);
    CHECK(legend_texts.size() == 3);
}

TEST_CASE("No two texts of a figure overlap", "[layout][labels]") {
    for (const Vec2 page : kPages) {
        fv::app::RenderSession& s = session(static_cast<int>(page.x), static_cast<int>(page.y));
        for (const fv::FigureData& fig : figures()) {
            INFO(fig.id << " on " << page.x << "x" << page.y);
            CHECK(overlapping_texts(s.record_figure(fig), s.fonts(), 1.0f) == "");
        }
    }
    // The check sees a text moved 3 units onto a copy of itself.
    DisplayList list = session().record_figure(figures().front());
    const auto t = std::find_if(list.commands.begin(), list.commands.end(),
                                [](const auto& c) { return std::holds_alternative<fv::gfx::dl::Text>(c); });
    REQUIRE(t != list.commands.end());
    fv::gfx::dl::Text copy = std::get<fv::gfx::dl::Text>(*t);
    copy.anchor.x += 3, copy.anchor.y += 3;
    list.commands.push_back(copy);
    CHECK(overlapping_texts(list, session().fonts(), 1.0f) != "");
}

TEST_CASE("No label of a figure lies on an arrow or a marker", "[layout][labels]") {
    // Fig. 4's "mean friction" and "π/2" sat on arrows at 640x400.
    int labels = 0;
    for (const Vec2 page : kPages) {
        fv::app::RenderSession& s = session(static_cast<int>(page.x), static_cast<int>(page.y));
        for (const fv::FigureData& fig : figures()) {
            const DisplayList list = s.record_figure(fig);
            for (const fv::gfx::Region& data : list.regions)
                for (std::size_t k = data.first; k < data.last && data.role == "data"; ++k)
                    labels += std::holds_alternative<fv::gfx::dl::Text>(list.commands[k]);
            INFO(fig.id << " on " << page.x << "x" << page.y);
            CHECK(label_on_shape(list, s.fonts()) == "");
        }
    }
    CHECK(labels > 50);
}

TEST_CASE("command_bounds holds all a command can touch: the labels' quick test skips nothing they cover",
          "[layout][labels]") {
    // The label placer skips a command whose box stays away from a label's; were the box too small, a label
    // would be placed on what it should avoid. Random commands of every kind against random rectangles:
    // whatever touches a rectangle (within pad) has a box that reaches it.
    namespace dl = fv::gfx::dl;
    const fv::gfx::FontSet& fonts = session().fonts();
    std::mt19937 rng(20061);
    std::uniform_real_distribution<float> at(-50, 150), len(0, 40), width(0, 6);
    const auto point = [&] { return Vec2{at(rng), at(rng)}; };
    const auto stroke = [&] { return fv::gfx::Stroke{fv::gfx::colors::black, width(rng)}; };
    int touching = 0;
    for (int n = 0; n < 4000; ++n) {
        dl::Command c;
        switch (n % 8) {
        case 0: {
            dl::Polyline p{{point(), point(), point()}, stroke(), n % 16 == 0};
            if (n % 24 == 0) p.points[1] = {NAN, NAN}; // a break in the line
            c = p;
            break;
        }
        case 1: {
            dl::Marker m{point(), {}};
            m.style.size = len(rng), m.style.edge_width = width(rng);
            c = m;
            break;
        }
        case 2:
            c = dl::Circle{point(), len(rng), stroke()};
            break;
        case 3:
            c = dl::FillCircle{point(), len(rng), fv::gfx::colors::black};
            break;
        case 4: {
            dl::Arrow a{point(), point(), {}};
            a.style.shaft = stroke(), a.style.head_width = len(rng);
            c = a;
            break;
        }
        case 5:
            c = dl::FillTriangle{point(), point(), point(), fv::gfx::colors::black};
            break;
        case 6: {
            dl::Text t{point(), "r_x = 0.25", {}, {}};
            t.style.size = 8 + len(rng) / 2;
            c = t;
            break;
        }
        default: {
            const Vec2 a = point();
            c = dl::StrokeRect{{a.x, a.y, a.x + len(rng), a.y + len(rng)}, stroke()};
        }
        }
        const Vec2 a = point();
        const Rect r{a.x, a.y, a.x + len(rng), a.y + len(rng)};
        const float pad = n % 3 == 0 ? 0.0f : 1.5f;
        if (!fv::gfx::command_touches(c, r, fonts, pad)) continue;
        ++touching;
        const Rect box = fv::gfx::command_bounds(c, fonts);
        INFO("command " << n << " (kind " << n % 8 << ")");
        CHECK(box.x0 <= r.x1 + pad);
        CHECK(box.x1 >= r.x0 - pad);
        CHECK(box.y0 <= r.y1 + pad);
        CHECK(box.y1 >= r.y0 - pad);
    }
    CHECK(touching > 200); // the rectangles met enough commands of every kind to say something
}

TEST_CASE("Every force plot states its sign convention on the figure and in its caption", "[layout][force]") {
    int plots = 0;
    for (const fv::FigureData& fig : figures())
        for (const fv::PanelData& p : fig.panels) {
            const bool force = std::any_of(p.series.begin(), p.series.end(),
                                           [](const fv::SeriesData& s) { return s.label == "F_{x}"; });
            if (!force) continue;
            ++plots;
            INFO(fig.id << ": y axis \"" << p.y_title << "\"");
            CHECK(p.y_title == "F / F_{c} = (P − T) / z_{ss}");
            const fv::FigureEntry* e = fv::find_registered(fig.id);
            REQUIRE(e != nullptr);
            CHECK(e->make(e->example).caption.find(fv::kForceConvention) != std::string::npos);
        }
    CHECK(plots == 5); // fig15, fig16, fig18, the scene twice
}

TEST_CASE("format_number: a value that rounds to zero has no sign", "[layout][minus-zero]") {
    CHECK(fv::format_number("%.4f", -1e-9) == "0.0000");
    CHECK(fv::format_number("%.5f", -0.0) == "0.00000");
    CHECK(fv::format_number("%g", -0.0) == "0");
    CHECK(fv::format_number("%.0f", -0.4) == "0");
    CHECK(fv::format_number("%.2g", -1e-300) == "-1e-300");
    // Negative numbers and exponents keep their signs.
    CHECK(fv::format_number("%.4f", -0.00006) == "-0.0001");
    CHECK(fv::format_number("%.4f", -0.1553) == "-0.1553");
    CHECK(fv::format_number("%.0e", 1e-8) == "1e-08");
    CHECK(fv::format_number("%g", -2.5) == "-2.5");
}

TEST_CASE("The live top view reads at every angle: no text on text, label on a shape or arrow on arrow",
          "[layout][labels][live]") {
    // The app's top view at 1280x800 (the panel beside it), through a steady period. At theta = 0 P, T, the
    // spring and both arrows lie on one line: the labels collided and the v arrow hid under the friction's.
    const Rect top = fv::app::layout_dashboard({346, 4, 1276, 796}).top_view;
    fv::app::RenderSession& s = session();
    int labels = 0, arrows = 0;
    for (const double theta_deg : {0.0, 30.0, 90.0, 150.0})
        for (const double zeta : {0.15, 0.5}) {
            const fv::Params p{zeta, theta_deg * fv::kPi / 180, 2, 0};
            fv::LiveSim sim(fv::Model::dahl, p);
            sim.start_steady(fv::ode_solve(p).lag);
            sim.step(2 * sim.steps_per_period());
            const int n = sim.steps_per_period();
            for (int k = 0; k < 16; ++k) {
                sim.step(n / 16);
                for (const fv::FrameChoice frame : {fv::FrameChoice::body, fv::FrameChoice::ground}) {
                    fv::ViewState view;
                    view.frame = frame;
                    fv::gfx::Canvas& canvas = s.canvas();
                    canvas.begin({1280, 800}, 1, fv::gfx::colors::white);
                    fv::app::paint_panel(canvas, fv::top_view_panel(sim, view), top);
                    canvas.end_recording();
                    const DisplayList& list = canvas.display_list();
                    for (const auto& c : list.commands) {
                        labels += std::holds_alternative<fv::gfx::dl::Text>(c);
                        arrows += std::holds_alternative<fv::gfx::dl::Arrow>(c);
                    }
                    INFO("theta " << theta_deg << ", zeta " << zeta << ", step " << k << ", "
                                  << fv::to_string(frame) << " frame");
                    CHECK(overlapping_texts(list, s.fonts(), 1.0f) == "");
                    CHECK(label_on_shape(list, s.fonts()) == "");
                    CHECK(arrow_on_arrow(list) == "");
                }
            }
        }
    CHECK(labels > 1000);
    CHECK(arrows > 3 * 4 * 2 * 16 * 2);
}

TEST_CASE("The why panel reads at every angle: no text on text, label on a shape or arrow on arrow",
          "[layout][labels][live][why]") {
    // The app's lower panel at 1280x800 showing the mechanism (the paper's Fig. 4 live), through a steady
    // period. At theta = 0 every velocity and friction arrow lay on one line; the panel now draws them up a
    // time axis there, and drops a faded arrow the live one would hide.
    const Rect lower = fv::app::layout_dashboard({346, 4, 1276, 796}).ratio;
    fv::app::RenderSession& s = session();
    int labels = 0, arrows = 0;
    for (const double theta_deg : {0.0, 30.0, 90.0, 150.0})
        for (const double zeta : {0.15, 0.5})
            for (const fv::Model model : {fv::Model::rigid, fv::Model::dahl}) {
                const fv::Params p{zeta, theta_deg * fv::kPi / 180, 2, 0};
                fv::LiveSim sim(model, p);
                if (model == fv::Model::dahl) sim.start_steady(fv::ode_solve(p).lag);
                sim.step(2 * sim.steps_per_period());
                fv::MechanismBase base;
                const int n = sim.steps_per_period();
                for (int k = 0; k < 16; ++k) {
                    sim.step(n / 16);
                    const fv::PanelData why = fv::mechanism_panel_live(sim, base);
                    // The title says what happens: v reverses at theta = 0 (zeta < 1), it turns otherwise.
                    CHECK(why.title.find(theta_deg == 0 ? "v reverses" : "v turns") != std::string::npos);
                    fv::gfx::Canvas& canvas = s.canvas();
                    canvas.begin({1280, 800}, 1, fv::gfx::colors::white);
                    fv::app::paint_panel(canvas, why, lower);
                    canvas.end_recording();
                    const DisplayList& list = canvas.display_list();
                    for (const auto& c : list.commands) {
                        labels += std::holds_alternative<fv::gfx::dl::Text>(c);
                        arrows += std::holds_alternative<fv::gfx::dl::Arrow>(c);
                    }
                    INFO("theta " << theta_deg << ", zeta " << zeta << ", " << fv::to_string(model)
                                  << ", step " << k);
                    CHECK(overlapping_texts(list, s.fonts(), 1.0f) == "");
                    CHECK(label_on_shape(list, s.fonts()) == "");
                    CHECK(arrow_on_arrow(list) == "");
                }
            }
    CHECK(labels > 1000);
    CHECK(arrows > 4 * 2 * 2 * 16 * 8); // the live two and the faded instants
}

TEST_CASE("The setup picture: the shake at theta from v_b, no axes, readable at every angle and size",
          "[layout][labels][live][setup]") {
    // The lower panel "setup" (the experiment) at 1280x800 and 1920x1080, enlarged as in presentation mode,
    // and on a phone (390 x 844, the panels stacked: 390 x 170): no text on text, no label on a shape, no
    // arrow on another; a drawing, so no tick labels; the shake in the view from above along (cos theta,
    // sin theta), v_b along x. Words that find no room (on the phone; the long ones with presentation's
    // larger text) are left out; at text size 1 on the screens all are there.
    fv::app::RenderSession& s = session();
    for (const Vec2 screen : {Vec2{1280, 800}, Vec2{1920, 1080}, Vec2{390, 844}})
        for (const float k : {1.0f, 1.5f})
            for (const double theta_deg : {0.0, 30.0, 90.0, 150.0, 180.0}) {
                const bool phone = screen.x < 400;
                if (phone && k > 1) continue;
                const double theta = theta_deg * fv::kPi / 180;
                const fv::PanelData setup = fv::setup_panel(theta);
                CHECK_FALSE(setup.axes);
                CHECK(setup.title.find(fv::format_number("%.0f", theta_deg) + "°") != std::string::npos);
                // The view from above: the shake's arrows from the block's centre both ways along the angle.
                int shakes = 0;
                for (const fv::ArrowData& a : setup.arrows) {
                    const fv::Vec2 d = a.to - a.from;
                    if (a.ink != fv::Ink::tip || a.from.x() < 6) continue; // the side view's along x
                    ++shakes;
                    CHECK(std::abs(d.x() * std::sin(theta) - d.y() * std::cos(theta)) < 1e-12);
                }
                CHECK(shakes == 2);
                const Rect lower =
                    phone ? Rect{0, 600, 390, 770}
                          : fv::app::layout_dashboard({346 * screen.x / 1280, 4, screen.x - 4, screen.y - 4})
                                .ratio;
                fv::gfx::Canvas& canvas = s.canvas();
                canvas.begin(screen, 1, fv::gfx::colors::white);
                fv::app::paint_panel(canvas, fv::app::enlarged(setup, k), lower);
                canvas.end_recording();
                const DisplayList& list = canvas.display_list();
                INFO("theta " << theta_deg << " on " << screen.x << "x" << screen.y << ", text x" << k);
                CHECK(overlapping_texts(list, s.fonts(), 1.0f) == "");
                CHECK(label_on_shape(list, s.fonts()) == "");
                CHECK(arrow_on_arrow(list) == "");
                int words = 0;
                std::string all = "|";
                for (const auto& c : list.commands)
                    if (const auto* t = std::get_if<fv::gfx::dl::Text>(&c)) {
                        ++words;
                        all += t->text + "|";
                        // No tick labels: no text is a number.
                        CHECK(t->text.find_first_not_of("0123456789.−-") != std::string::npos);
                    }
                INFO("texts " << all);
                CHECK(words >= (phone ? 6 : 12));
                for (const char* must : {"v_{b}", "±x_{v}", "P", "T"})
                    CHECK(all.find(std::string("|") + must + "|") != std::string::npos);
                if (!phone)
                    for (const char* word : {"seen from above", "|floor|", "|block|"})
                        CHECK(all.find(word) != std::string::npos);
                if (!phone && k == 1) CHECK(all.find("magnified") != std::string::npos);
                // The data area takes the room the axes would have (a few units from the panel's sides).
                for (const fv::gfx::Region& r : list.regions)
                    if (r.role == "data") CHECK(r.rect.x0 - lower.x0 < 10);
            }
}

namespace {

// The registered fig4 at zeta and theta (degrees), computed.
fv::FigureData fig4(double zeta, double theta_deg) {
    fv::FigureInputs in;
    in.zeta = zeta;
    in.theta_deg = {theta_deg};
    return fv::compute_figure(fv::find_registered("fig4")->make(in));
}

} // namespace

TEST_CASE("Fig. 4 along the sliding line: the instants up a time axis, no arrow on another",
          "[layout][labels][why]") {
    // theta = 0 and 180: each instant tau = k pi/4 (k = 0..8) a row with v's arrow above it and the
    // friction's below: 18 arrows, none along another, no label on one; the title says
    // that v reverses (zeta < 1) or never does (zeta > 1). At 90 deg the plane picture, unchanged.
    for (const double theta_deg : {0.0, 5.0, 175.0, 180.0})
        for (const double zeta : {0.15, 0.5, 1.5}) {
            const fv::FigureData fig = fig4(zeta, theta_deg);
            INFO("theta " << theta_deg << ", zeta " << zeta);
            const fv::PanelData& rows = fig.panels.at(0);
            CHECK(rows.arrows.size() == 18);
            CHECK(rows.title.find(zeta < 1 ? "v reverses" : "v never reverses") != std::string::npos);
            // Each row's two arrows: v_x = zeta + cos theta cos tau (Eq. 1), F_x = -sgn v_x (Eq. 2).
            for (int k = 0; k <= 8; ++k) {
                const double tau = fv::kPi * k / 4,
                             vx = zeta + std::cos(theta_deg * fv::kPi / 180) * std::cos(tau);
                CHECK(rows.arrows[2 * k].to.x() == Approx(vx).margin(1e-12));
                CHECK(rows.arrows[2 * k].to.y() > tau);
                CHECK(rows.arrows[2 * k + 1].to.y() < tau);
                if (std::abs(vx) > 1e-9) CHECK(rows.arrows[2 * k + 1].to.x() * vx < 0);
            }
            // On the smallest page, 320x240, the nine rows are 15 units apart and a label may touch the
            // next row's arrow.
            for (const Vec2 page : kPages) {
                if (page.x < 480) continue;
                fv::app::RenderSession& s = session(static_cast<int>(page.x), static_cast<int>(page.y));
                const DisplayList list = s.record_figure(fig);
                INFO("on " << page.x << "x" << page.y);
                CHECK(arrow_on_arrow(list) == "");
                CHECK(label_on_shape(list, s.fonts()) == "");
                CHECK(overlapping_texts(list, s.fonts(), 1.0f) == "");
            }
        }
    CHECK(fig4(0.5, 90).panels.at(0).title == "velocity v/v_{v} and friction F/F_{c} at τ = kπ/4");
}

namespace {

// What makes a figure on a journal column (render --page column: 3.3 in, tick labels 8 pt at 13 units) hard
// to read, as a description ("" when nothing): text on text, a label on an arrow or a marker, text off the
// page or below 12 units (7.4 pt), a data area smaller than 150 x 90 units (1.5 x 0.9 in; 60 units tall for
// a family of more than three maps), a panel's legend left out, a legend box over the data.
std::string column_problem(const fv::FigureData& fig, const DisplayList& list,
                           const fv::gfx::FontSet& fonts) {
    if (std::string o = overlapping_texts(list, fonts, 1.0f); !o.empty()) return "overlap: " + o;
    if (std::string o = label_on_shape(list, fonts); !o.empty()) return o;
    for (const auto& c : list.commands)
        if (const auto* t = std::get_if<fv::gfx::dl::Text>(&c)) {
            const Rect b = fv::gfx::text_bounds(*t, fonts);
            if (b.x0 < 0 || b.y0 < 0 || b.x1 > list.size.x || b.y1 > list.size.y)
                return "\"" + t->text + "\" leaves the page";
            if (t->style.size < 12)
                return "\"" + t->text + "\" at " + std::to_string(t->style.size) + " units";
        }
    int legends = 0, data_areas = 0;
    for (const fv::gfx::Region& r : list.regions) {
        if (r.role == "data") {
            ++data_areas;
            // Small multiples of more than three maps take shorter rows (six stay within about 8 in).
            const float least_h = fig.columns > 0 && fig.panels.size() > 3 ? 60.0f : 90.0f;
            if (r.rect.width() < 150 || r.rect.height() < least_h)
                return "a data area of " + std::to_string(r.rect.width()) + " x " +
                       std::to_string(r.rect.height());
        }
        if (r.role != "legend") continue;
        ++legends;
        if (std::string s = sample_in(list, r.rect); !s.empty()) return "the legend over " + s;
    }
    // Small multiples share one legend under the grid (not a panel's); every other panel with labelled
    // series keeps its legend.
    int asked = 0;
    for (const fv::PanelData& p : fig.panels)
        asked +=
            fig.columns == 0 && p.legend != fv::Legend::none &&
            std::any_of(p.series.begin(), p.series.end(), [](const auto& s) { return !s.label.empty(); });
    if (legends < asked) return std::to_string(asked - legends) + " legend(s) left out";
    if (data_areas < static_cast<int>(fig.panels.size())) return "a panel not drawn";
    return "";
}

// The column's logical width, as render --page column lays a figure out.
float column_width() {
    return fv::app::print_layout(fv::app::PaperPage::column, 1280, 800, true).logical.x;
}

} // namespace

TEST_CASE("On a journal column every figure reads at 8 pt: no overlap, every legend off the data, panels "
          "large enough",
          "[layout][column]") {
    // Side by side on 330 units two panels got 160 each: Fig. 4's labels ran together, Fig. 6's and the
    // scene's legends were elided to "…" over the curves, Fig. 10-13's, rx's and ry's were left out.
    std::vector<fv::FigureData> figs = figures();
    fv::FigureInputs along; // Fig. 4 along the sliding line: nine rows of labelled arrows up a time axis
    along.theta_deg = {0}, along.zeta = 0.5;
    figs.push_back(fv::compute_figure(fv::find_registered("fig4")->make(along)));
    fv::app::RenderSession& s = session();
    const float width = column_width();
    REQUIRE(width == Approx(237.6f / (8.0f / (13 * 2048.0f / 2384))).epsilon(1e-4)); // 3.3 in at 8 pt
    for (const fv::FigureData& fig : figs) {
        const DisplayList list = s.record_column_figure(fig, width);
        INFO(fig.id << " (" << fig.panels.size() << " panels) on the column, " << list.size.x << " x "
                    << list.size.y);
        CHECK(list.size.x == width);
        CHECK(column_problem(fig, list, s.fonts()) == "");
    }
}

TEST_CASE("On a journal column: the check sees the side-by-side layout's cramping", "[layout][column]") {
    // The layout before: the figure on a 3:4 page the column's width, full-size text, panels side by side.
    fv::app::RenderSession& s = session();
    const float width = column_width();
    int cramped = 0, multi = 0;
    for (const fv::FigureData& fig : figures()) {
        if (fig.panels.size() < 2) continue;
        ++multi;
        const DisplayList list = s.record_figure(fig, {width, 0.75f * width}, 1);
        const std::string problem = column_problem(fig, list, s.fonts());
        INFO(fig.id << ": " << problem);
        cramped += !problem.empty();
    }
    CHECK(multi >= 4);       // fig4, fig6, fig14, the scenes, the families of maps
    CHECK(cramped == multi); // every one of them
}
