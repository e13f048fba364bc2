// The app in the browser: the dashboard of the desktop app (app/gui, run_gui) on the web platform (the page's
// canvas, WebGL 2). The page is web/index.html.
#include "gui/gui_app.hpp"

#include <cstdio>
#include <exception>

int main() {
    try {
        fv::app::GuiOptions o;
        o.platform = "web";
        return fv::app::run_gui(o);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "frictionviz: %s\n", e.what());
        return 1;
    }
}
