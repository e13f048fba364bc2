#include "session_link.hpp"

#include "lessons.hpp"

#include "fv/live_panels.hpp" // ratio_zeta_max
#include "fv/printable_text.hpp"

namespace fv::app {

std::string link_base_error(const std::string& base) {
    const bool http = base.rfind("http://", 0) == 0 || base.rfind("https://", 0) == 0;
    if (!http || base.size() > 2000 || base.find_first_of("?# ") != std::string::npos ||
        printable_text(base, 2000) != base)
        return "link base " + quoted_text(base) +
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
    if (s.lesson != 0) view.lesson = s.lesson;
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

ShareLink parse_link(std::string_view text) {
    return parse_share_link(text, static_cast<int>(lesson_steps().size()));
}

void apply_link(const ShareLink& link, Session& s) {
    if (link.lesson) {
        const LessonSetup& u = lesson_steps()[static_cast<std::size_t>(*link.lesson - 1)].setup;
        s.model = u.model, s.params = u.params, s.start = u.start;
        s.panel = u.panel, s.speed = u.speed, s.view.frame = u.frame;
        s.lesson = *link.lesson;
        s.compare = u.b.has_value(); // compare mode as the step has it
        if (u.b) s.b = *u.b;
    }
    apply_share_link(link, s.model, s.params, s.start, s.view.frame);
    // Any of B's keys: compare mode, B's keys over the step's B, or over A (as the link left it) at the other
    // angle.
    if (link.b.any()) {
        if (!s.compare) s.b = compare_default(s.a());
        s.compare = true;
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
