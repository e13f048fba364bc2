#include "help_overlay.hpp"

#include "figures/figure_painter.hpp"

#include <imgui.h>

#include <algorithm>
#include <iterator>

namespace fv::app {
namespace {

struct Entry {
    Ink ink; // the swatch's colour (Ink::automatic: no swatch)
    const char* symbol;
    const char* meaning;
};

// What the top view, the force plot and the ratio plot draw (dashboard.cpp), in the order a first look meets
// them.
constexpr Entry kScene[] = {
    {Ink::body, "P",
     "a point of the sliding body: drifts at v_b along x and vibrates ±x_v along the dotted "
     "line at angle θ (Eqs. 28–29)"},
    {Ink::spring, "body (dashed box)",
     "the sliding body (the block) that carries P; v_b arrow: its mean velocity"},
    {Ink::tip, "T",
     "the tip of the asperity: where the contact meets the fixed plane (its trail vermillion)"},
    {Ink::pull, "spring, green",
     "the asperity P–T sticks (i = 0) or creeps (i > 0): z = |P − T| < z_ss, T "
     "barely moves"},
    {Ink::slip, "spring, purple", "the asperity slips: z = z_ss, T is dragged behind P (Eq. 27)"},
    {Ink::pull, "circle", "radius z_ss around P: how far the asperity stretches before it slips"},
    {Ink::body, "v", "P's velocity: v_b plus the vibration velocity (Eq. 1), drawn at 0.4 x_v per v_v"},
    {Ink::black, "−F", "the friction force on the body: the asperity pulls P back towards T"},
};
constexpr Entry kPlots[] = {
    {Ink::force, "F_x, F_y, |F|",
     "friction force F/F_c = (P − T)/z_ss (Dahl; rigid: F_c along the velocity), "
     "positive F_x resists v_b"},
    {Ink::slip, "shading", "times the tip slips"},
    {Ink::slip, "loop", "the hysteresis loop: green where the tip sticks or creeps, purple where it slips"},
    {Ink::black, "setup",
     "the experiment: a block pressed on a rough floor, pulled at v_b, shaken ±x_v at θ"},
    {Ink::black, "period mean F_x",
     "F_x averaged over the period before each instant (Eq. 30): it settles on "
     "r_x once the start-up transient is over"},
    {Ink::automatic, "r_x, r_y",
     "the period-mean friction along and across v_b in the periodic steady state, "
     "over F_c (Eqs. 31, 33): below 1 means vibration reduces friction"},
    {Ink::automatic, "ζ, θ, r_disp, i",
     "v_b/v_v (velocity ratio), vibration angle, x_v/z_ss (amplitude over "
     "the asperity's reach), Dahl shape exponent (Eq. 12)"},
    {Ink::automatic, "start",
     "where the motion begins: from rest (T = P, the paper's start) or switched on while sliding (the "
     "asperity fully stretched); where two steady states coexist it decides which one the body settles into"},
    {Ink::setup_b, "A | B",
     "compare mode (C, View menu): setup A (blue) and B (orange) side by side on one time base, both "
     "force traces and both r_x points; the parameter controls edit the one chosen (B key)"},
    {Ink::automatic, "keys",
     "Space play/pause, ← → one frame, J steady state, R reset, C compare, B edit A or B, S screenshot, "
     "F1 or ? this help, Esc quit"},
};

// The meanings' column starts after the widest term of both tables, so that no term runs into its meaning at
// any font size (presentation mode: 22 px instead of 15).
float meaning_column(float swatch) {
    float widest = 0;
    for (const Entry& e : kScene) widest = std::max(widest, ImGui::CalcTextSize(e.symbol).x);
    for (const Entry& e : kPlots) widest = std::max(widest, ImGui::CalcTextSize(e.symbol).x);
    const ImGuiStyle& style = ImGui::GetStyle();
    return style.WindowPadding.x + swatch + style.ItemSpacing.x + widest + 2 * style.ItemSpacing.x;
}

template <std::size_t N>
void section(const char* title, const Entry (&entries)[N], float column, HelpLayout& layout) {
    const float swatch = ImGui::GetFontSize() * 0.9f;
    ImGui::TextUnformatted(title);
    ImGui::Separator();
    for (const Entry& e : entries) {
        if (e.ink != Ink::automatic) {
            const gfx::Color c = ink_color(e.ink, 0);
            ImGui::ColorButton(e.symbol, ImVec4(c.r, c.g, c.b, 1),
                               ImGuiColorEditFlags_NoTooltip | ImGuiColorEditFlags_NoDragDrop,
                               ImVec2(swatch, swatch));
        } else {
            ImGui::Dummy(ImVec2(swatch, swatch));
        }
        ImGui::SameLine();
        ImGui::TextUnformatted(e.symbol);
        layout.term_right = std::max(layout.term_right, ImGui::GetItemRectMax().x);
        ImGui::SameLine(column);
        layout.meaning_left = std::min(layout.meaning_left, ImGui::GetCursorScreenPos().x);
        ImGui::PushTextWrapPos(0);
        ImGui::TextUnformatted(e.meaning);
        ImGui::PopTextWrapPos();
    }
}

} // namespace

bool draw_help_overlay(bool open, const gfx::Rect& area, HelpLayout* layout) {
    if (!open) return false;
    // 48 em wide (720 at the 15 px font), within the area; as tall as its rows, at most the area less its
    // margins, scrolling beyond.
    const float margin = 20;
    const float w = std::min(area.width() - 2 * margin, 48 * ImGui::GetFontSize());
    const float h_max = area.height() - 2 * margin;
    ImGui::SetNextWindowPos(ImVec2(area.x0 + (area.width() - w) / 2, area.y0 + margin), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(w, 0), ImGuiCond_Always);
    // No taller than the area (a phone, a small window): the overlay scrolls beyond it.
    ImGui::SetNextWindowSizeConstraints(ImVec2(w, 0), ImVec2(w, std::max(100.0f, h_max)));
    ImGui::SetNextWindowBgAlpha(0.96f);
    bool keep = true;
    ImGui::Begin("What you see (F1 or ? closes)", &keep,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                     ImGuiWindowFlags_NoSavedSettings);
    HelpLayout where;
    const float column = meaning_column(ImGui::GetFontSize() * 0.9f);
    section("Top view", kScene, column, where);
    ImGui::Spacing();
    section("Plots and numbers", kPlots, column, where);
    const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
    where.window = {pos.x, pos.y, pos.x + size.x, pos.y + size.y};
    where.scroll_max = ImGui::GetScrollMaxY();
    ImGui::End();
    if (layout) *layout = where;
    return keep;
}

bool help_key_pressed() {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantTextInput) return false;
    for (int k = 0; k < io.InputQueueCharacters.Size; ++k)
        if (io.InputQueueCharacters[k] == '?') return true;
    return false;
}

} // namespace fv::app
