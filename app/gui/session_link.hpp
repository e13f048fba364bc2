// The share link of the app's whole state and back (fv/share_link.hpp has the format): the setup's keys, and
// the vibration's (amplitude, frequency) and the view's (panel, presentation, speed, playing, trail, zoom,
// pan, follow, pins, lesson step) where they differ from the app's defaults, so that a session goes through a
// link and back whole but for its data file; and the address a student clicks (the site's address with the
// link as its query). The desktop's Copy link, `gui --link` and the browser page all go through here, so the
// three agree.
#pragma once

#include "session.hpp"
#include "ui_state.hpp"

#include "fv/share_link.hpp"

#include <string>

namespace fv::app {

// Where the desktop's Copy link points when nothing else is said (`gui --link-base URL` or the environment's
// FRICTIONVIZ_LINK_BASE): scripts/serve-web.sh's address on the machine that serves the site.
inline constexpr const char* kDefaultLinkBase = "http://127.0.0.1:8000/";

// The address the share link is appended to: the page's own (origin + path) in the browser, a setting on the
// desktop, which has no address of its own (the panel says which).
struct ShareAddress {
    std::string base = kDefaultLinkBase;
    bool from_page = false;
};

// "" when `base` can take a link (http:// or https://, printable, no query or fragment), else why not.
std::string link_base_error(const std::string& base);

// The link of the state: share_link() of the setup (A's), compare_link_keys() of B in compare mode, then
// view_link_keys() of what differs from a default SessionState (the link of a default view is the setup's
// keys alone, as before the view keys existed). Pins whose source is not known (an older session file) are
// left out.
std::string session_link(const SessionState& s);
// base + link ("http://host/frictionviz/?zeta=...").
std::string share_address(const ShareAddress& where, const SessionState& s);
// How many of the pins a link cannot carry (no source).
std::size_t pins_not_in_link(const SessionState& s);

// parse_share_link with the app's lesson steps (a lesson value outside them is ignored with a notice).
ShareLink parse_link(std::string_view text);

// The link's setup and view onto `s` (what the link does not give keeps its value); its pins are computed
// again (compute_pin, on this thread: the app's curves for each, tens of milliseconds). A lesson step's
// setup comes first, the link's own keys over it, so that a link copied during a lesson, sliders moved,
// reopens what was on screen, and `?lesson=3` alone opens step 3 as the Lessons menu does.
void apply_link(const ShareLink& link, Session& s);

} // namespace fv::app
