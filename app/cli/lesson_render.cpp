#include "lesson_render.hpp"

#include "errors.hpp"
#include "output.hpp"

#include "anim/animation.hpp"
#include "gui/lessons.hpp"

#include "fv/atomic_file.hpp"
#include "fv/share_link.hpp"

#include <nlohmann/json.hpp>

#include <cstdio>

#ifndef FV_VERSION
#define FV_VERSION "dev"
#endif

namespace fv::cli {

void render_lesson(int lesson, const std::string& dir_arg, const PixelSize& size, OutputArgs& output) {
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

    anim::Spec s;
    s.model = step.setup.model;
    s.params = step.setup.params;
    s.steady.start = step.setup.start;
    s.frame = step.setup.frame;
    s.view = anim::View::dashboard;
    if (step.setup.b) s.view = anim::View::compare, s.b = *step.setup.b; // as animate --lesson shows the step
    s.width = size.w;
    s.height = size.h;
    s.scale = static_cast<float>(output.scale);
    s.title = "Lesson " + std::to_string(lesson) + ": " + step.title;
    anim::Still still;
    try {
        still = anim::render_still(s);
    } catch (const std::exception& e) {
        throw RuntimeFailure(std::string("cannot render headless: ") + e.what());
    }
    std::vector<app::NamedFile> files = app::encode_pictures(id, output.pictures(), still.image, still.list);
    nlohmann::ordered_json j;
    j["id"] = id;
    j["title"] = s.title;
    j["caption"] = step.text;
    j["link"] = "?lesson=" + std::to_string(lesson); // what opens the step in the app and the browser
    j["setup"] = share_link(s.model, s.params, s.steady.start, s.frame);
    if (step.setup.b) j["setup_b"] = share_link(s.b.model, s.b.params, s.b.start, s.frame); // compare mode
    j["files"] = names;
    j["version"] = "frictionviz " FV_VERSION;
    files.emplace_back(id + ".json", j.dump(2) + "\n");
    for (const auto& [name, content] : files)
        if (std::string err = write_file_atomic(dir + "/" + name, content); !err.empty())
            throw RuntimeFailure(err);
    std::string line = "wrote " + dir + "/" + id + ".";
    for (const std::string& ext : output.extensions())
        line += (ext == output.extensions().front() ? "" : ", .") + ext;
    std::printf("%s (%dx%d) and %s.json\n", line.c_str(), size.w, size.h, id.c_str());
}

} // namespace fv::cli
