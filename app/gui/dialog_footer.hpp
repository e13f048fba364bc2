// The end of the app's modal dialogs (file dialogs, animation export): Cancel beside the dialog's action,
// Escape doing the same, and the popup's end.
#pragma once

#include <imgui.h>

namespace fv::app {

inline void end_dialog_with_cancel() {
    ImGui::SameLine();
    if (ImGui::Button("Cancel") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false))
        ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
}

} // namespace fv::app
