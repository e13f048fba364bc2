#include "lesson_render.hpp"

#include "errors.hpp"
#include "output.hpp"

#include "figures/render_figures.hpp"
#include "gui/lessons.hpp"

#include "fv/atomic_file.hpp"
#include "fv/gfx/vector_output.hpp"
#include "fv/share_link.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>

#ifndef FV_VERSION
#define FV_VERSION "dev"
#endif

namespace fv::cli {

namespace {

// A printed column's page for the lesson's picture: its width times this tall, upright enough (more than 1.1)
// that the dashboard stacks its three panels, each the column's width (figures/dashboard_painter.hpp). In
// compare mode taller, so that A's and B's top views (in the top view's 40 %) are one above the other, each
// the column's width, rather than side by side at half of it, where their axis titles run into each other.
constexpr float kColumnPageAspect = 1.6f, kColumnCompareAspect = 2.7f;
// On an A4 or Letter sheet the picture is at least this tall over its width (a figure's page: 3/4): the
// dashboard has two rows, the top view and the plots under it, and at 3/4 the plots' data areas are some 90
// pt tall.
constexpr float kSheetAspect = 0.9f;

} // namespace

anim::Spec lesson_spec(int lesson) {
    const app::LessonSetup& u = app::lesson_steps().at(static_cast<std::size_t>(lesson - 1)).setup;
    anim::Spec s;
    s.model = u.model;
    s.params = u.params;
    s.steady.start = u.start;
    s.frame = u.frame;
    s.panel = u.panel;
    s.view = anim::View::dashboard;
    if (u.b) s.view = anim::View::compare, s.b = *u.b;
    s.data = u.data;
    return s;
}

void render_lesson(int lesson, const std::string& dir_arg, const PixelSize& size, OutputArgs& output,
                   app::PaperPage paper, bool caption) {
    const app::LessonStep& step = app::lesson_steps().at(static_cast<std::size_t>(lesson - 1));
    check_output_args(output, size.w, size.h);
    check_out_dir(dir_arg);
    std::string dir = dir_arg;
    while (dir.size() > 1 && dir.back() == '/') dir.pop_back();
    const std::string id = "lesson-" + std::to_string(lesson);
    std::vector<std::string> names;
    for (const std::string& ext : output.extensions()) names.push_back(id + "." + ext);
    names.push_back(id + ".json");
    for (const std::string& name : names) check_out(dir + "/" + name); // nothing written if one is in the way

    anim::Spec s = lesson_spec(lesson);
    s.width = size.w;
    s.height = size.h;
    s.scale = static_cast<float>(output.scale);
    s.title = "Lesson " + std::to_string(lesson) + ": " + step.title;
    // The page of the SVG and PDF and the caption under every picture, as render --figure lays them out.
    const float scale = static_cast<float>(output.scale);
    const gfx::Vec2 logical{static_cast<float>(size.w) / scale, static_cast<float>(size.h) / scale};
    app::PrintLayout layout = app::print_layout(paper, logical.x, logical.y, caption);
    if (layout.column)
        layout.logical.y =
            layout.logical.x * (s.view == anim::View::compare ? kColumnCompareAspect : kColumnPageAspect);
    else if (layout.logical.x > 0)
        layout.logical.y = std::max(layout.logical.y, layout.logical.x * kSheetAspect);
    // A handout carries the step's explanation: its title and its plain-words text (the JSON's title and
    // caption).
    const std::string caption_text = caption ? s.title + ". " + step.text : "";
    anim::Still still;
    try {
        const bool vectors = output.pictures().svg || output.pictures().pdf;
        still = anim::render_still(s, vectors ? layout.logical : gfx::Vec2{0, 0});
    } catch (const std::exception& e) {
        throw RuntimeFailure(std::string("cannot render headless: ") + e.what());
    }
    if (caption && output.pictures().png)
        still.image = gfx::stack_images(
            still.image, gfx::render_caption_image(caption_text, logical.x, layout.png_caption, 12, scale));
    gfx::VectorPage page = layout.vector;
    page.caption = caption_text;
    std::vector<app::NamedFile> files =
        app::encode_pictures(id, output.pictures(), still.image, still.list, page);
    nlohmann::ordered_json j;
    j["id"] = id;
    j["title"] = s.title;
    j["caption"] = step.text;
    j["link"] = "?lesson=" + std::to_string(lesson); // what opens the step in the app and the browser
    j["panel"] = panel_name(s.panel);                // the lower-right panel drawn, as the step sets it
    j["setup"] = share_link(s.model, s.params, s.steady.start, s.frame);
    if (step.setup.b) j["setup_b"] = share_link(s.b.model, s.b.params, s.b.start, s.frame); // compare mode
    if (s.data) // the step's example points, on the r_x(zeta) panel
        j["data"] = {
            {"name", s.data->file}, {"points", s.data->points.size()}, {"synthetic", s.data->synthetic}};
    j["files"] = names;
    j["version"] = "frictionviz " FV_VERSION;
    files.emplace_back(id + ".json", j.dump(2) + "\n");
    for (const auto& [name, content] : files)
        if (std::string err = write_file_atomic(dir + "/" + name, content); !err.empty())
            throw RuntimeFailure(err);
    std::string line = "wrote " + dir + "/" + id + ".";
    for (const std::string& ext : output.extensions())
        line += (ext == output.extensions().front() ? "" : ", .") + ext;
    // The PNG's pixels (its caption's band under them); with --page the SVG/PDF are on that sheet.
    const std::string sheet =
        paper == app::PaperPage::none ? "" : std::string("; SVG/PDF: page ") + app::to_string(paper);
    std::printf("%s (%dx%d%s) and %s.json\n", line.c_str(), size.w, size.h, sheet.c_str(), id.c_str());
}

} // namespace fv::cli
