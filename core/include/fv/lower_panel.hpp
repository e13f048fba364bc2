// What the dashboard's lower-right panel shows: one value from the panel's radio buttons through the app's
// state, sessions, scripts and share links to the drawing. Its names are the words of sessions, scripts and
// share links (`panel=map`); in core because the share link's parser (fv/share_link.hpp) checks them.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fv {

enum class LowerPanel {
    curves, // r_x(zeta): the Dahl and rigid curves at the current theta, r_disp, i
    map,    // the (zeta, theta) map of r_x with the best angle
    loop,   // the asperity's hysteresis loop over the last period
    why,    // the mechanism (the paper's Fig. 4) live: velocity and friction on the body now
    setup,  // the experiment the model stands for: a block pressed on a floor, pulled, shaken at theta
};

inline constexpr LowerPanel kLowerPanels[] = {LowerPanel::curves, LowerPanel::map, LowerPanel::loop,
                                              LowerPanel::why, LowerPanel::setup};

// "curves", "map", "loop", "why", "setup".
constexpr const char* panel_name(LowerPanel p) {
    switch (p) {
    case LowerPanel::curves:
        return "curves";
    case LowerPanel::map:
        return "map";
    case LowerPanel::loop:
        return "loop";
    case LowerPanel::why:
        return "why";
    case LowerPanel::setup:
        return "setup";
    }
    return "curves";
}

// Every panel's name, in kLowerPanels' order (a command-line or session check's allowed values).
inline std::vector<std::string> panel_name_list() {
    std::vector<std::string> v;
    for (LowerPanel p : kLowerPanels) v.push_back(panel_name(p));
    return v;
}

// "curves, map, loop, why, setup": what a message allows.
inline std::string panel_names() {
    std::string s;
    for (const std::string& name : panel_name_list()) s += (s.empty() ? "" : ", ") + name;
    return s;
}

// The panel of that name, if any.
inline std::optional<LowerPanel> panel_from_name(std::string_view name) {
    for (LowerPanel p : kLowerPanels)
        if (name == panel_name(p)) return p;
    return std::nullopt;
}

} // namespace fv
