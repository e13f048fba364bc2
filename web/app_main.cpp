// The app in the browser: the dashboard of the desktop app (app/gui, run_gui) on the web platform (the page's
// canvas, WebGL 2). The page is web/index.html.
//
// The page's address is a share link (fv/share_link.hpp, what `frictionviz gui --link` reads): its query sets
// the model, parameters and start (rest or sliding) at start, and as the sliders move the address follows
// (history.replaceState), so a copied address reopens the same setup. A link that does not read shows the
// defaults and says why on the page, never a blank page.
#include "gui/gui_app.hpp"

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

// The page's message line (index.html's #status), in red.
EM_JS(void, fv_show_page_error, (const char* text), {
    var line = document.getElementById("status");
    if (!line) return;
    line.textContent = UTF8ToString(text);
    line.className = "error";
});

// Replaces the address's query (the hash stays), without a new history entry.
EM_JS(void, fv_replace_page_query, (const char* query),
      { history.replaceState(history.state, "", UTF8ToString(query) + window.location.hash); });

std::string page_query() {
    char* q = fv_page_query();
    std::string s = q ? q : "";
    std::free(q);
    return s;
}

} // namespace

int main() {
    // emscripten starts with a umask of 0777, so files the app writes (exports, sessions) would have no
    // permissions and could not be read back (the download, File > Open session): a desktop's default.
    ::umask(022);
    try {
        fv::app::GuiOptions o;
        o.platform = "web";
        const std::string query = page_query();
        if (!query.empty()) {
            try {
                fv::apply_share_link(fv::parse_share_link(query), o.start.model, o.start.params,
                                     o.start.start, o.start.view.frame);
                // As gui --link does: the physical view (with the page's default A and f) must be finite.
                if (const std::string why = fv::units::physical_view_error(
                        o.start.params, o.start.amplitude_um, o.start.frequency_khz);
                    !why.empty())
                    throw fv::LinkError(why + " (the app's default amplitude and frequency)");
            } catch (const fv::LinkError& e) {
                o.start = fv::app::Session{}; // the defaults, whatever the link had set before its error
                const std::string msg =
                    "This link could not be read (" + std::string(e.what()) + "); showing the default setup.";
                fv_show_page_error(msg.c_str());
            }
        }
        // The address changes only when the state does: a page opened without a query (or with a bad one)
        // keeps its address until a slider moves.
        std::string shown = fv::share_link(o.start.model, o.start.params, o.start.start, o.start.view.frame);
        o.on_state = [&shown](const fv::app::UiState& ui) {
            std::string link =
                fv::share_link(ui.session.model, ui.session.params, ui.session.start, ui.session.view.frame);
            if (link == shown) return;
            shown = std::move(link);
            fv_replace_page_query(shown.c_str());
        };
        return fv::app::run_gui(o);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "frictionviz: %s\n", e.what());
        return 1;
    }
}
