#include "data_controls.hpp"
#include "dialog_footer.hpp"
#include "lesson_card.hpp"

#include "measured_data.hpp"

#include "fv/param_ranges.hpp"
#include "fv/share_link.hpp"
#include "fv/units.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <filesystem>
#include <system_error>
#include <utility>
#include <vector>

namespace fv::app {
namespace {

// Commits every keystroke that parses to an admissible value; a half-typed "0." is simply not applied.
bool input_positive(const char* label, double* v, const char* format) {
    double x = *v;
    if (!ImGui::InputDouble(label, &x, 0, 0, format)) return false;
    if (!(x > 0) || !std::isfinite(x)) return false;
    *v = x;
    return true;
}

// The files with extension `ext` in `dir` (sorted), at most 200: enough to pick from, never a stall on a huge
// directory.
std::vector<std::string> files_with(const std::filesystem::path& dir, const char* ext) {
    std::vector<std::string> out;
    std::error_code ec;
    for (std::filesystem::directory_iterator it(dir, ec), end; !ec && it != end && out.size() < 200;
         it.increment(ec)) {
        const auto& p = it->path();
        if (p.extension() == ext && it->is_regular_file(ec)) out.push_back(p.filename().string());
    }
    std::sort(out.begin(), out.end());
    return out;
}

} // namespace

UiEdits draw_vibration_controls(const UiState& ui) {
    UiEdits e;
    // The physical view was converted once this frame (AppState::sync); typed values go back as edits.
    ImGui::Text("Physical units  (v_v = 2π f A = %.4g m/s)", ui.vv_m_s);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("ζ = v_b / (2π f A), Eq. (6); r_disp = A / z_ss, Eq. (34).\n"
                          "Changing A or f keeps v_b and z_ss: ζ and r_disp follow.");
    // Two inputs to a line, each label beside its field.
    const ImGuiStyle& st = ImGui::GetStyle();
    const float half = (ImGui::GetContentRegionAvail().x - st.ItemSpacing.x) / 2 -
                       ImGui::CalcTextSize("z_ss [µm]").x - st.ItemInnerSpacing.x;
    ImGui::PushItemWidth(half);
    double a = ui.session.amplitude_um, f = ui.session.frequency_khz;
    if (input_positive("A [µm]", &a, "%.4g")) e.amplitude_um = a;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("vibration amplitude x_v in µm, allowed %s; v_b and z_ss stay, ζ and r_disp follow",
                          describe(kAmplitudeRange).c_str());
    ImGui::SameLine();
    if (input_positive("f [kHz]", &f, "%.4g")) e.frequency_khz = f;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("vibration frequency f in kHz, allowed %s; v_v = 2π f A",
                          describe(kFrequencyRange).c_str());
    double vb = ui.vb_m_s, zss = ui.zss_um;
    if (ImGui::InputDouble("v_b [m/s]", &vb, 0, 0, "%.4g") && std::isfinite(vb)) e.vb_m_s = vb;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("sliding velocity of the body in m/s, allowed %s; sets ζ = v_b / v_v (ζ in %s)",
                          describe(kVbRange).c_str(), describe(kZetaRange).c_str());
    ImGui::SameLine();
    if (ui.session.model == Model::rigid) ImGui::BeginDisabled();
    if (input_positive("z_ss [µm]", &zss, "%.4g")) e.zss_um = zss;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("steady deflection of the asperity F_c / σ₀ in µm, Eq. (15), allowed %s; sets "
                          "r_disp = A / z_ss (r_disp in %s)",
                          describe(kZssRange).c_str(), describe(kRdispRange).c_str());
    if (ui.session.model == Model::rigid) ImGui::EndDisabled();
    ImGui::PopItemWidth();
    return e;
}

UiEdits draw_data_controls(const UiState& ui, FileDialogs& dialog) {
    UiEdits e;
    ImGui::TextUnformatted("Measured data");
    if (ui.data) {
        const MeasurementSet& d = *ui.data;
        ImGui::TextWrapped("%s", std::filesystem::path(d.file).filename().string().c_str());
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", d.file.c_str());
        ImGui::Text("%zu points%s%s", d.points.size(), d.has_sigma ? ", ± σ" : "",
                    d.has_theta ? ", θ per point" : ", at the θ shown");
    } else {
        ImGui::TextWrapped("none: File > Open, or drop a CSV file onto the window");
    }
    if (ImGui::Button("Open…")) dialog.data.open_requested = true;
    if (ui.data) {
        ImGui::SameLine();
        const bool can_fit = !ui.fitting && ui.session.model == Model::dahl;
        if (!can_fit) ImGui::BeginDisabled();
        if (ImGui::Button(ui.fitting ? "Fitting…" : "Fit r_disp, i")) e.fit_data = true;
        if (!can_fit) ImGui::EndDisabled();
        if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
            ImGui::SetTooltip("least-squares r_disp for i = 0 and i = 1, keeps the smaller AIC\n"
                              "(as `frictionviz fit`); points without θ use the θ shown");
        ImGui::SameLine();
        if (ImGui::Button("Clear")) e.clear_data = true;
    }
    return e;
}

UiEdits draw_menu(const UiState& ui, FileDialogs& dialog) {
    UiEdits e;
    if (!ImGui::BeginMenuBar()) return e;
    if (ImGui::BeginMenu("File")) {
        if (ImGui::MenuItem("Open data file…")) dialog.data.open_requested = true;
        if (ImGui::MenuItem("Clear data", nullptr, false, ui.data.has_value())) e.clear_data = true;
        ImGui::Separator();
        if (ImGui::MenuItem("Open session…")) dialog.open_session.open_requested = true;
        if (ImGui::MenuItem("Save session…")) dialog.save_session.open_requested = true;
        ImGui::Separator();
        if (ImGui::MenuItem("Export trace CSV")) e.export_csv = true;
        if (ImGui::MenuItem("Screenshot", "S")) e.screenshot = true;
        if (ImGui::MenuItem("Export animation…")) e.open_export_dialog = true;
        ImGui::Separator();
        if (ImGui::MenuItem("Quit", "Esc")) e.quit = true;
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("View")) {
        if (ImGui::MenuItem("Presentation mode", "P", ui.session.presentation))
            e.presentation = !ui.session.presentation;
        if (ImGui::MenuItem("Compare A | B", "C", ui.session.compare)) e.compare = !ui.session.compare;
        ImGui::EndMenu();
    }
    e.merge(draw_lessons_menu(ui));
    if (ImGui::BeginMenu("Help")) {
        if (ImGui::MenuItem("What you see", "F1, ?", ui.show_help)) e.show_help = !ui.show_help;
        ImGui::EndMenu();
    }
    ImGui::EndMenuBar();
    return e;
}

namespace {

struct PathDialogText {
    const char* title;  // also the ImGui id
    const char* help;   // a line above the path field
    const char* ext;    // ".csv": the files listed
    const char* action; // the button: "Open", "Save"
};

// A modal dialog with a path field and the files of one kind in the directory typed so far (or the working
// directory): returns the path chosen (Enter, the button, a double click), nothing while it is open.
std::optional<std::string> path_dialog(PathDialog& d, const PathDialogText& t) {
    if (d.open_requested) {
        ImGui::OpenPopup(t.title);
        d.open_requested = false;
    }
    // At most the page's width less a margin (a phone's page is 390 wide).
    ImGui::SetNextWindowSize(ImVec2(std::min(440.0f, ImGui::GetIO().DisplaySize.x - 16), 0),
                             ImGuiCond_Appearing);
    if (!ImGui::BeginPopupModal(t.title, nullptr, ImGuiWindowFlags_NoSavedSettings)) return std::nullopt;
    ImGui::TextWrapped("%s", t.help);
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    ImGui::SetNextItemWidth(-1);
    const bool enter = ImGui::InputText("##path", &d.path, ImGuiInputTextFlags_EnterReturnsTrue);
    std::filesystem::path dir = std::filesystem::path(d.path).parent_path();
    const bool is_dir = [&] {
        std::error_code ec;
        return std::filesystem::is_directory(d.path, ec);
    }();
    if (is_dir) dir = d.path;
    const std::vector<std::string> files = files_with(dir.empty() ? "." : dir, t.ext);
    bool chosen = enter;
    if (ImGui::BeginListBox("##files", ImVec2(-1, 8 * ImGui::GetTextLineHeightWithSpacing()))) {
        for (const std::string& name : files) {
            const std::string full = (dir / name).string();
            if (ImGui::Selectable(name.c_str(), full == d.path, ImGuiSelectableFlags_AllowDoubleClick)) {
                d.path = full;
                if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) chosen = true;
            }
        }
        if (files.empty()) ImGui::TextDisabled("no %s files in %s", t.ext, dir.empty() ? "." : dir.c_str());
        ImGui::EndListBox();
    }
    std::optional<std::string> out;
    if ((ImGui::Button(t.action) || chosen) && !d.path.empty() && !is_dir) {
        out = d.path;
        ImGui::CloseCurrentPopup();
    }
    end_dialog_with_cancel();
    return out;
}

} // namespace

UiEdits draw_file_dialogs(FileDialogs& dialog) {
    UiEdits e;
    for (auto [d, accept] : {std::pair{&dialog.data, ".csv"}, std::pair{&dialog.open_session, ".json"}})
        if (d->open_requested && dialog.choose && dialog.choose(accept)) d->open_requested = false;
    e.load_data =
        path_dialog(dialog.data, {"Open data file",
                                  "CSV with a header: zeta,r_x or vb,r_x (v_b converted with the A and f "
                                  "set in the panel); optional theta_deg, sigma, label.",
                                  ".csv", "Open"});
    e.open_session =
        path_dialog(dialog.open_session,
                    {"Open session",
                     "A session file (JSON) saved by File > Save session: parameters, model, start, units, "
                     "animation, view and data file. The animation restarts from it.",
                     ".json", "Open"});
    if (dialog.save_session.open_requested && dialog.save_session.path.empty())
        dialog.save_session.path = "frictionviz-session.json";
    e.save_session =
        path_dialog(dialog.save_session,
                    {"Save session",
                     "Saves parameters, model, start, units, animation, view and the data file's path as "
                     "JSON (File > Open session, or frictionviz gui --session FILE).",
                     ".json", "Save"});
    return e;
}

UiEdits draw_share_link(const UiState& ui, const ShareAddress& where) {
    UiEdits e;
    // The field shows the link (what fits on the row); Copy link copies the whole address.
    std::string link = session_link(ui.session);
    const std::string address = where.base + link;
    // As tall as a line of text (no vertical frame padding): it shares the header's row, which keeps its
    // height, so the panel's rows below stay where they are.
    const ImGuiStyle& st = ImGui::GetStyle();
    ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, ImVec2(st.FramePadding.x, 0));
    const char* copy = "Copy link";
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - ImGui::CalcTextSize(copy).x -
                            2 * st.FramePadding.x - st.ItemSpacing.x);
    ImGui::InputText("##link", &link, ImGuiInputTextFlags_ReadOnly);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "Share link: the model, its parameters (θ in degrees), the start when it is not "
            "from rest, and the panel, presentation mode, speed, pinned curves and lesson step when they "
            "are not the defaults\n%s\n%s"
            "frictionviz gui --link '%s' starts from it, and the browser version opens it.%s",
            address.c_str(),
            where.from_page ? "This page's address.\n"
                            : "The site's address is a setting: gui --link-base URL or "
                              "FRICTIONVIZ_LINK_BASE (docs/web.md), where your class's site is.\n",
            link.c_str(),
            pins_not_in_link(ui.session) > 0
                ? "\nPins opened from an older session file are not in it (their parameters "
                  "are not known)."
                : "");
    ImGui::SameLine();
    if (ImGui::SmallButton(copy)) {
        ImGui::SetClipboardText(address.c_str());
        e.status = "Copy link: " + address;
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("copy this address to the clipboard");
    ImGui::PopStyleVar();
    return e;
}

} // namespace fv::app
