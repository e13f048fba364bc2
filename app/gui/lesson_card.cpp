#include "lesson_card.hpp"

#include "lessons.hpp"

#include <imgui.h>

#include <string>

namespace fv::app {
namespace {

int step_count() {
    return static_cast<int>(lesson_steps().size());
}

bool pressed(ImGuiKey key) {
    return ImGui::IsKeyPressed(ImGui::GetKeyIndex(key), false);
}

} // namespace

UiEdits draw_lessons_menu(const UiState& ui) {
    UiEdits e;
    if (!ImGui::BeginMenu("Lessons")) return e;
    const auto& steps = lesson_steps();
    for (int k = 1; k <= step_count(); ++k) {
        const std::string label = std::to_string(k) + ". " + steps[static_cast<std::size_t>(k - 1)].title;
        if (ImGui::MenuItem(label.c_str(), nullptr, ui.session.lesson == k)) e.lesson = k;
    }
    ImGui::Separator();
    if (ImGui::MenuItem("Close the lesson", nullptr, false, ui.session.lesson > 0)) e.lesson = 0;
    ImGui::EndMenu();
    return e;
}

UiEdits draw_lesson_card(const UiState& ui) {
    UiEdits e;
    if (ui.session.lesson < 1 || ui.session.lesson > step_count()) return e;
    const LessonStep& step = lesson_steps()[static_cast<std::size_t>(ui.session.lesson - 1)];
    ImGui::PushID("lesson");
    ImGui::TextDisabled("Lesson %d of %d", ui.session.lesson, step_count());
    ImGui::PushTextWrapPos(0);
    ImGui::TextUnformatted(step.title.c_str());
    ImGui::Spacing();
    ImGui::TextUnformatted(step.text.c_str());
    // The equations and the teacher's tip stay folded until asked for: plain words first (PhET).
    if (ImGui::TreeNode("The equations")) {
        ImGui::TextUnformatted(step.details.c_str());
        ImGui::TreePop();
    }
    if (!step.tip.empty() && ImGui::TreeNode("Teacher tip")) {
        ImGui::TextUnformatted(step.tip.c_str());
        ImGui::TreePop();
    }
    ImGui::PopTextWrapPos();
    if (ui.session.lesson <= 1) ImGui::BeginDisabled();
    if (ImGui::Button("< Back")) e.lesson = ui.session.lesson - 1;
    if (ui.session.lesson <= 1) ImGui::EndDisabled();
    ImGui::SameLine();
    if (ui.session.lesson >= step_count()) ImGui::BeginDisabled();
    if (ImGui::Button("Next >")) e.lesson = ui.session.lesson + 1;
    if (ui.session.lesson >= step_count()) ImGui::EndDisabled();
    ImGui::SameLine();
    if (ImGui::Button("Again")) e.lesson = ui.session.lesson; // the step's setup once more, from its start
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("this step's setup again, played from the start");
    ImGui::SameLine();
    if (ImGui::Button("Close")) e.lesson = 0;
    ImGui::PopID();
    ImGui::Separator();
    return e;
}

UiEdits lesson_keys(const UiState& ui) {
    UiEdits e;
    if (ui.session.lesson == 0) return e;
    if (pressed(ImGuiKey_PageDown) && ui.session.lesson < step_count()) e.lesson = ui.session.lesson + 1;
    if (pressed(ImGuiKey_PageUp) && ui.session.lesson > 1) e.lesson = ui.session.lesson - 1;
    return e;
}

} // namespace fv::app
