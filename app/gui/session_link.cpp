#include "session_link.hpp"

#include "fv/live_panels.hpp" // ratio_zeta_max
#include "fv/printable_text.hpp"

namespace fv::app {

std::string web_base_error(const std::string& base) {
    const bool http = base.rfind("http://", 0) == 0 || base.rfind("https://", 0) == 0;
    if (!http || base.size() > 2000 || base.find_first_of("?# ") != std::string::npos ||
        printable_text(base, 2000) != base)
        return "web base " + quoted_text(base) +
               " is not a site address; allowed: http:// or https:// and a path, no '?', '#' or spaces, e.g. "
               "https://example.org/frictionviz/";
    return "";
}

std::string session_link(const SessionState& s) {
    const SessionState defaults;
    ShareLink view;
    if (s.panel != defaults.panel) view.panel = s.panel;
    if (s.presentation != defaults.presentation) view.presentation = s.presentation;
    if (s.speed != defaults.speed) view.speed = s.speed;
    std::vector<PinSource> pins;
    for (const PinnedCurve& p : s.pins)
        if (p.source) pins.push_back(*p.source);
    if (!pins.empty()) view.pins = std::move(pins);
    return share_link(s.model, s.params, s.start, s.view.frame) +
           (s.compare ? compare_link_keys(s.b.model, s.b.params, s.b.start) : "") + view_link_keys(view);
}

std::string share_address(const ShareAddress& where, const SessionState& s) {
    return where.base + session_link(s);
}

std::size_t pins_not_in_link(const SessionState& s) {
    std::size_t n = 0;
    for (const PinnedCurve& p : s.pins) n += p.source ? 0 : 1;
    return n;
}

void apply_link(const ShareLink& link, Session& s) {
    apply_share_link(link, s.model, s.params, s.start, s.view.frame);
    // Any of B's keys: compare mode, B from A (as the link left it) at the other angle, then B's keys.
    if (link.b.any()) {
        s.compare = true;
        s.b = compare_default(s.a());
        apply_share_link(link.b, s.b.model, s.b.params, s.b.start);
    }
    if (link.panel) s.panel = *link.panel;
    if (link.presentation) s.presentation = *link.presentation;
    if (link.speed) s.speed = *link.speed;
    if (link.pins) {
        s.pins.clear();
        for (const PinSource& p : *link.pins) s.pins.push_back(compute_pin(p, ratio_zeta_max(nullptr)));
    }
}

} // namespace fv::app
