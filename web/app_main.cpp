// The app in the browser: the dashboard of the desktop app (app/gui, run_gui) on the web platform (the page's
// canvas, WebGL 2). The page is web/index.html.
//
// The page's address is a share link (fv/share_link.hpp, what `frictionviz gui --link` reads): its query sets
// the model, parameters, start, vibration (amplitude, frequency) and view (panel, presentation, speed,
// playing, trail, zoom, pan, follow, pins, lesson step) at start, and as the state changes the address
// follows (history.replaceState), so a copied address reopens the same setup; Copy link copies it. A link
// that does not read shows the defaults and says why on the page, never a blank page; a view value that does
// not read is ignored with a notice. Every frame the page's layout goes to Module.fvLayout (and the body's
// data-fv-layout attribute) for the tests (tests/web/page_fits.sh).
#include "gui/gui_app.hpp"
#include "gui/session_link.hpp"

#include "fv/share_link.hpp"
#include "fv/units.hpp"

#include <emscripten.h>
#include <sys/stat.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

namespace {

// location.search ("" or "?...").
EM_JS(char*, fv_page_query, (), { return allocateUTF8(window.location.search); });

// location.origin + location.pathname: the address a share link is appended to.
EM_JS(char*, fv_page_base, (), { return allocateUTF8(window.location.origin + window.location.pathname); });

// The page's message line (index.html's #status), in red (an error) or grey (a notice).
EM_JS(void, fv_show_page_message, (const char* text, int error), {
    var line = document.getElementById("status");
    if (!line) return;
    line.textContent = UTF8ToString(text);
    line.className = error ? "error" : "notice";
});

// The app's status line as the body's data-fv-status (the tests read it from the DOM).
EM_JS(void, fv_publish_status, (const char* text), {
    if (document.body) document.body.setAttribute("data-fv-status", UTF8ToString(text));
});

// The layout as JSON, for the tests: the app's (`json`) with what the browser says of the window and the
// canvas, as Module.fvLayout and the body's data-fv-layout (chromium --dump-dom).
// clang-format off
EM_JS(void, fv_publish_layout, (const char* json), {
    var c = Module["canvas"];
    var r = c.getBoundingClientRect();
    var j = "{\"app\":" + UTF8ToString(json) + ",\"window\":[" + window.innerWidth + "," + window.innerHeight +
            "],\"dpr\":" + window.devicePixelRatio + ",\"canvas_css\":[" + r.left + "," + r.top + "," + r.width +
            "," + r.height + "],\"canvas\":[" + c.width + "," + c.height + "]}";
    Module["fvLayout"] = j;
    if (document.body) document.body.setAttribute("data-fv-layout", j);
});
// clang-format on

// The link of the state on screen as the body's data-fv-link (the tests read it from the DOM: the address
// keeps the query it was opened with until the state changes).
EM_JS(void, fv_publish_link, (const char* query), {
    if (document.body) document.body.setAttribute("data-fv-link", UTF8ToString(query));
});

// Replaces the address's query (the hash stays), without a new history entry.
EM_JS(void, fv_replace_page_query, (const char* query),
      { history.replaceState(history.state, "", UTF8ToString(query) + window.location.hash); });

std::string taken(char* q) {
    std::string s = q ? q : "";
    std::free(q);
    return s;
}

std::string rect_json(const fv::gfx::Rect& r) {
    char b[128];
    std::snprintf(b, sizeof b, "[%.1f,%.1f,%.1f,%.1f]", r.x0, r.y0, r.x1, r.y1);
    return b;
}

// What the page's layout test checks (tests/web/page_fits.py): the page and the canvas's backing store, and
// every rectangle the app drew into, in CSS pixels.
std::string layout_json(const fv::app::ShownLayout& l) {
    char b[256];
    std::snprintf(b, sizeof b,
                  "{\"page\":[%.1f,%.1f],\"ratio\":%.3f,\"framebuffer\":[%d,%d],\"stacked\":%s,"
                  "\"controls_scroll_max\":%.1f,",
                  l.page.x, l.page.y, l.pixel_ratio, l.framebuffer.width, l.framebuffer.height,
                  l.screen.stacked ? "true" : "false", l.controls_scroll_max);
    return b + std::string("\"controls\":") + rect_json(l.screen.controls) +
           ",\"top_view\":" + rect_json(l.panels.top_view) + ",\"force\":" + rect_json(l.panels.force) +
           ",\"lower\":" + rect_json(l.panels.ratio) +
           (l.panels.top_view_b.width() > 0 ? ",\"top_view_b\":" + rect_json(l.panels.top_view_b) : "") + "}";
}

// Which of the vibration's values a link left at the page's default, for a message about the physical view:
// " (the app's default amplitude and frequency)", " (the app's default frequency)", ..., or "".
std::string default_vibration(const fv::ShareLink& link) {
    if (link.amplitude_um && link.frequency_khz) return "";
    return std::string(" (the app's default ") +
           (link.amplitude_um    ? "frequency"
            : link.frequency_khz ? "amplitude"
                                 : "amplitude and frequency") +
           ")";
}

} // namespace

int main() {
    // emscripten starts with a umask of 0777, so files the app writes (exports, sessions) would have no
    // permissions and could not be read back (the download, File > Open session): a desktop's default.
    ::umask(022);
    try {
        fv::app::GuiOptions o;
        o.platform = "web";
        o.share.base = taken(fv_page_base());
        o.share.from_page = true;
        const std::string query = taken(fv_page_query());
        if (!query.empty()) {
            try {
                const fv::ShareLink link = fv::app::parse_link(query);
                fv::app::apply_link(link, o.start);
                // A view value that did not read: ignored, said on the page and in the status line.
                for (const std::string& n : link.notices)
                    o.start_notice += (o.start_notice.empty() ? "link: " : "; ") + n;
                if (!o.start_notice.empty()) fv_show_page_message(o.start_notice.c_str(), 0);
                // As gui --link does: the physical view (with the link's A and f, else the page's default)
                // must be finite.
                const std::string defaults = default_vibration(link);
                if (const std::string why = fv::units::physical_view_error(
                        o.start.params, o.start.amplitude_um, o.start.frequency_khz);
                    !why.empty())
                    throw fv::LinkError(why + defaults);
                if (o.start.compare)
                    if (const std::string why = fv::units::physical_view_error(
                            o.start.b.params, o.start.amplitude_um, o.start.frequency_khz);
                        !why.empty())
                        throw fv::LinkError("setup B: " + why + defaults);
            } catch (const fv::LinkError& e) {
                o.start = fv::app::Session{}; // the defaults, whatever the link had set before its error
                o.start_notice.clear();
                const std::string msg =
                    "This link could not be read (" + std::string(e.what()) + "); showing the default setup.";
                fv_show_page_message(msg.c_str(), 1);
            }
        }
        // The address changes only when the state does: a page opened without a query (or with a bad one)
        // keeps its address until a slider moves.
        std::string shown = fv::app::session_link(o.start);
        fv_publish_link(shown.c_str());
        std::string status;
        o.on_state = [&shown, &status](const fv::app::UiState& ui) {
            if (ui.status != status) fv_publish_status((status = ui.status).c_str());
            std::string link = fv::app::session_link(ui.session);
            if (link == shown) return;
            shown = std::move(link);
            fv_replace_page_query(shown.c_str());
            fv_publish_link(shown.c_str());
        };
        std::string published;
        o.on_layout = [&published](const fv::app::ShownLayout& l) {
            std::string j = layout_json(l);
            if (j == published) return;
            published = std::move(j);
            fv_publish_layout(published.c_str());
        };
        return fv::app::run_gui(o);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "frictionviz: %s\n", e.what());
        return 1;
    }
}
