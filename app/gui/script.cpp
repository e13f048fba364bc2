#include "script.hpp"

#include "fv/atomic_file.hpp"
#include "fv/figure_registry.hpp"
#include "fv/input_file.hpp"
#include "fv/units.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace fv::app {
namespace {

bool numeric(const std::string& a) {
    return a == "zeta" || a == "theta" || a == "rdisp" || a == "i" || a == "speed" || a == "trail" ||
           a == "amplitude" || a == "frequency" || a == "vb" || a == "zss" || a == "rewind";
}
bool is_path(const std::string& a) {
    return a == "load" || a == "save-session" || a == "open-session" || a == "animate";
}
bool needs_value(const std::string& a) {
    return numeric(a) || is_path(a) || a == "model" || a == "preset";
}
constexpr const char* kActions =
    "zeta theta rdisp i model play pause step reset speed trail preset map curves "
    "amplitude frequency vb zss load clear fit back rewind steady help loop why pin unpin present "
    "save-session open-session animate export";
// One list of the actions: the message's.
bool known(const std::string& a) {
    return !a.empty() && (" " + std::string(kActions) + " ").find(" " + a + " ") != std::string::npos;
}

} // namespace

Script load_script(const std::string& path) {
    std::string text;
    if (auto why = read_input_file(path, text); !why.empty()) throw std::runtime_error(path + ": " + why);
    std::istringstream in(text);
    Script s;
    std::string line;
    int no = 0;
    while (std::getline(in, line)) {
        ++no;
        if (const auto h = line.find('#'); h != std::string::npos) line.erase(h);
        std::istringstream ls(line);
        int frame = 0;
        std::string action, value, extra;
        if (!(ls >> frame)) {
            if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
            throw std::runtime_error(path + ":" + std::to_string(no) + ": expected 'FRAME ACTION [VALUE]'");
        }
        const auto where = path + ":" + std::to_string(no) + ": ";
        if (frame < 0) throw std::runtime_error(where + "frame must be >= 0");
        if (!(ls >> action) || !known(action))
            throw std::runtime_error(where + "unknown action '" + action + "'; allowed: " + kActions);
        if (needs_value(action)) {
            if (!(ls >> value)) throw std::runtime_error(where + "'" + action + "' needs a value");
            if (action == "model" && value != "dahl" && value != "rigid")
                throw std::runtime_error(where + "model must be dahl or rigid");
            if (action == "preset" && !find_figure(value))
                throw std::runtime_error(where + "unknown preset '" + value + "'; allowed: " + figure_ids());
            if (numeric(action)) {
                char* end = nullptr;
                const double v = std::strtod(value.c_str(), &end);
                if (*end != '\0' || !std::isfinite(v))
                    throw std::runtime_error(where + "'" + value + "' is not a number");
                if ((action == "amplitude" || action == "frequency" || action == "zss") && !(v > 0))
                    throw std::runtime_error(where + "'" + action + "' must be > 0");
                if (action == "vb" && v < 0) throw std::runtime_error(where + "'vb' must be >= 0");
            }
        }
        if (ls >> extra) throw std::runtime_error(where + "unexpected '" + extra + "'");
        // Files are found next to the script, wherever the script is run from.
        if (is_path(action) && value.front() != '/')
            value = (std::filesystem::path(path).parent_path() / value).lexically_normal().string();
        // A session that cannot be written is refused before the run, like --screenshot.
        if (action == "save-session")
            if (const std::string why = check_writable(value); !why.empty())
                throw std::runtime_error(where + "save-session " + value + ": " + why);
        s.lines[frame].push_back(action + " " + value);
    }
    return s;
}

UiEdits script_edits(const Script& s, int frame, const UiState& ui) {
    UiEdits e;
    const auto it = s.lines.find(frame);
    if (it == s.lines.end()) return e;
    Params p = ui.params;
    bool params_changed = false;
    for (const std::string& entry : it->second) {
        std::istringstream ls(entry);
        std::string a, v;
        ls >> a >> v;
        const double x = numeric(a) ? std::stod(v) : 0;
        if (a == "zeta")
            p.zeta = x, params_changed = true;
        else if (a == "theta")
            p.theta = x * kPi / 180, params_changed = true;
        else if (a == "rdisp")
            p.rdisp = x, params_changed = true;
        else if (a == "i")
            p.i = x, params_changed = true;
        else if (a == "model")
            e.model = v == "rigid" ? Model::rigid : Model::dahl;
        else if (a == "play")
            e.playing = true;
        else if (a == "pause")
            e.playing = false;
        else if (a == "step")
            e.step = true;
        else if (a == "reset")
            e.reset = true;
        else if (a == "back")
            e.step_back = true;
        else if (a == "rewind")
            e.rewind = x * 2 * kPi; // periods
        else if (a == "steady")
            e.jump_steady = true;
        else if (a == "help")
            e.show_help = !ui.show_help;
        else if (a == "loop")
            e.show_loop = true, e.show_map = false, e.show_mechanism = false;
        else if (a == "why")
            e.show_mechanism = true, e.show_loop = false, e.show_map = false;
        else if (a == "pin")
            e.pin = true;
        else if (a == "unpin")
            e.clear_pins = true;
        else if (a == "present")
            e.presentation = !ui.presentation;
        else if (a == "map")
            e.show_map = true, e.show_loop = false, e.show_mechanism = false;
        else if (a == "curves")
            e.show_map = false, e.show_loop = false, e.show_mechanism = false;
        else if (a == "speed")
            e.speed = x;
        else if (a == "trail")
            e.trail_periods = x;
        else if (a == "preset")
            e.preset = v;
        else if (a == "amplitude")
            e.amplitude_um = x;
        else if (a == "frequency")
            e.frequency_khz = x;
        else if (a == "vb" || a == "zss") {
            // With the A and f in effect before this frame's edits, like the panel's inputs. A value beyond
            // the doubles gives NaN: the loop rejects it with a status line, like any inadmissible edit.
            try {
                if (a == "vb")
                    p.zeta = units::zeta_from_vb(x, ui.amplitude_um, ui.frequency_khz);
                else
                    p.rdisp = units::rdisp_from_zss(ui.amplitude_um, x);
            } catch (const units::UnitError&) {
                (a == "vb" ? p.zeta : p.rdisp) = std::nan("");
            }
            params_changed = true;
        } else if (a == "load")
            e.load_data = v;
        else if (a == "export") // File > Export animation…: the dialog (for screenshots of it)
            e.open_export_dialog = true;
        else if (a == "animate") { // a GIF or MP4 of the current parameters, the export dialog's defaults
            AnimationRequest r;
            r.path = v;
            r.speed = ui.speed;
            e.export_animation = r;
        } else if (a == "clear")
            e.clear_data = true;
        else if (a == "fit")
            e.fit_data = true;
        else if (a == "save-session")
            e.save_session = v;
        else if (a == "open-session")
            e.open_session = v;
    }
    if (params_changed) e.params = p;
    return e;
}

Params bench_params(Params p, int frame) {
    p.zeta = 0.1 + 0.8 * (0.5 + 0.5 * std::sin(frame * 0.05));
    return p;
}

} // namespace fv::app
