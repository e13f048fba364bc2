#include "script.hpp"

#include "app_state.hpp"
#include "controls.hpp"
#include "lessons.hpp"

#include "fv/atomic_file.hpp"
#include "fv/figure_registry.hpp"
#include "fv/input_file.hpp"
#include "fv/printable_text.hpp"
#include "fv/read_number.hpp"

#include <cmath>
#include <filesystem>
#include <sstream>
#include <stdexcept>

namespace fv::app {

enum class ScriptArg { none, number, path, word };

// What one entry does to the frame's edits.
struct ScriptContext {
    const UiState& ui;
    UiEdits& edits;
    Params& params; // the frame's parameter edits so far (set params_changed when touched)
    bool& params_changed;
    Params& b_params; // the same for compare mode's setup B
    bool& b_changed;
};

struct ScriptAction {
    const char* name;
    ScriptArg arg;
    ParamRange range; // for ScriptArg::number
    const char* help;
    void (*apply)(const ScriptEntry&, ScriptContext&);
};

namespace {

void set_param(ScriptContext& c, double Params::*field, double v) {
    c.params.*field = v;
    c.params_changed = true;
}
// Setup B's parameter (compare mode; turns it on as a link's b.* key does).
void set_b_param(ScriptContext& c, double Params::*field, double v) {
    c.b_params.*field = v;
    c.b_changed = true;
}

constexpr ParamRange kRewindRange{0, 1e6};

// Every action, once: the parser, the help, the messages and the edits all read this table.
const ScriptAction kActions[] = {
    {"zeta", ScriptArg::number, kZetaRange, "speed ratio zeta",
     [](const ScriptEntry& s, ScriptContext& c) { set_param(c, &Params::zeta, s.number); }},
    {"theta", ScriptArg::number, kThetaRange, "vibration angle in degrees",
     [](const ScriptEntry& s, ScriptContext& c) { set_param(c, &Params::theta, s.number * kPi / 180); }},
    {"rdisp", ScriptArg::number, kRdispRange, "displacement ratio r_disp",
     [](const ScriptEntry& s, ScriptContext& c) { set_param(c, &Params::rdisp, s.number); }},
    {"i", ScriptArg::number, kIRange, "Dahl exponent i",
     [](const ScriptEntry& s, ScriptContext& c) { set_param(c, &Params::i, s.number); }},
    {"model",
     ScriptArg::word,
     {},
     "dahl | rigid",
     [](const ScriptEntry& s, ScriptContext& c) { c.edits.model = *parse_model(s.text); }},
    {"start",
     ScriptArg::word,
     {},
     "rest | sliding: the motion starts again from it",
     [](const ScriptEntry& s, ScriptContext& c) {
         Start start = Start::rest;
         parse_start(s.text, start);
         c.edits.start = start;
     }},
    {"compare",
     ScriptArg::word,
     {},
     "on | off: compare mode, setup B beside A (on: B is A at the other angle)",
     [](const ScriptEntry& s, ScriptContext& c) { c.edits.compare = s.text == "on"; }},
    {"b.zeta", ScriptArg::number, kZetaRange, "setup B's zeta (compare mode on)",
     [](const ScriptEntry& s, ScriptContext& c) { set_b_param(c, &Params::zeta, s.number); }},
    {"b.theta", ScriptArg::number, kThetaRange, "setup B's angle in degrees (compare mode on)",
     [](const ScriptEntry& s, ScriptContext& c) { set_b_param(c, &Params::theta, s.number * kPi / 180); }},
    {"b.rdisp", ScriptArg::number, kRdispRange, "setup B's r_disp (compare mode on)",
     [](const ScriptEntry& s, ScriptContext& c) { set_b_param(c, &Params::rdisp, s.number); }},
    {"b.i", ScriptArg::number, kIRange, "setup B's Dahl exponent i (compare mode on)",
     [](const ScriptEntry& s, ScriptContext& c) { set_b_param(c, &Params::i, s.number); }},
    {"b.model",
     ScriptArg::word,
     {},
     "dahl | rigid: setup B's model (compare mode on)",
     [](const ScriptEntry& s, ScriptContext& c) {
         c.edits.b.model = *parse_model(s.text);
         c.b_changed = true;
     }},
    {"edit",
     ScriptArg::word,
     {},
     "a | b: which setup the panel's parameter controls edit in compare mode",
     [](const ScriptEntry& s, ScriptContext& c) { c.edits.editing_b = s.text == "b"; }},
    {"vb", ScriptArg::number, kVbRange, "v_b in m/s (with the A and f in effect, as the panel's input)",
     [](const ScriptEntry& s, ScriptContext& c) { c.edits.vb_m_s = s.number; }},
    {"zss", ScriptArg::number, kZssRange, "z_ss in um (with the A in effect)",
     [](const ScriptEntry& s, ScriptContext& c) { c.edits.zss_um = s.number; }},
    {"amplitude", ScriptArg::number, kAmplitudeRange, "vibration amplitude A in um",
     [](const ScriptEntry& s, ScriptContext& c) { c.edits.amplitude_um = s.number; }},
    {"frequency", ScriptArg::number, kFrequencyRange, "vibration frequency f in kHz",
     [](const ScriptEntry& s, ScriptContext& c) { c.edits.frequency_khz = s.number; }},
    {"preset",
     ScriptArg::word,
     {},
     "a preset's id (the panel's preset buttons: a concept or a paper figure)",
     [](const ScriptEntry& s, ScriptContext& c) { c.edits.preset = s.text; }},
    {"lesson",
     ScriptArg::word,
     {},
     "show lesson step N and set it up (0 closes the lesson)",
     [](const ScriptEntry& s, ScriptContext& c) { c.edits.lesson = std::stoi(s.text); }},
    {"play",
     ScriptArg::none,
     {},
     "run the animation",
     [](const ScriptEntry&, ScriptContext& c) { c.edits.playing = true; }},
    {"pause",
     ScriptArg::none,
     {},
     "pause it",
     [](const ScriptEntry&, ScriptContext& c) { c.edits.playing = false; }},
    {"step",
     ScriptArg::none,
     {},
     "one frame forward",
     [](const ScriptEntry&, ScriptContext& c) { c.edits.step = true; }},
    {"back",
     ScriptArg::none,
     {},
     "one frame back in time",
     [](const ScriptEntry&, ScriptContext& c) { c.edits.step_back = true; }},
    {"reset",
     ScriptArg::none,
     {},
     "restart the simulation",
     [](const ScriptEntry&, ScriptContext& c) { c.edits.reset = true; }},
    {"rewind", ScriptArg::number, kRewindRange, "show the state this many periods ago (pauses)",
     [](const ScriptEntry& s, ScriptContext& c) { c.edits.rewind = s.number * 2 * kPi; }},
    {"steady",
     ScriptArg::none,
     {},
     "jump onto the periodic steady state",
     [](const ScriptEntry&, ScriptContext& c) { c.edits.jump_steady = true; }},
    {"speed", ScriptArg::number, kSpeedRange, "animation speed in periods per second",
     [](const ScriptEntry& s, ScriptContext& c) { c.edits.speed = s.number; }},
    {"trail", ScriptArg::number, kTrailRange, "trail length in periods",
     [](const ScriptEntry& s, ScriptContext& c) { c.edits.trail_periods = s.number; }},
    {"frame",
     ScriptArg::word,
     {},
     "body | ground: what stands still in the top view",
     [](const ScriptEntry& s, ScriptContext& c) { c.edits.frame = parse_frame(s.text); }},
    {"curves",
     ScriptArg::none,
     {},
     "lower panel: the r_x(zeta) curves",
     [](const ScriptEntry&, ScriptContext& c) { c.edits.panel = LowerPanel::curves; }},
    {"map",
     ScriptArg::none,
     {},
     "lower panel: the (zeta, theta) map",
     [](const ScriptEntry&, ScriptContext& c) { c.edits.panel = LowerPanel::map; }},
    {"loop",
     ScriptArg::none,
     {},
     "lower panel: the hysteresis loop",
     [](const ScriptEntry&, ScriptContext& c) { c.edits.panel = LowerPanel::loop; }},
    {"why",
     ScriptArg::none,
     {},
     "lower panel: why friction drops (Fig. 4)",
     [](const ScriptEntry&, ScriptContext& c) { c.edits.panel = LowerPanel::why; }},
    {"setup",
     ScriptArg::none,
     {},
     "lower panel: the experiment (a block pressed, pulled and shaken)",
     [](const ScriptEntry&, ScriptContext& c) { c.edits.panel = LowerPanel::setup; }},
    {"help",
     ScriptArg::none,
     {},
     "show or hide the help overlay",
     [](const ScriptEntry&, ScriptContext& c) { c.edits.show_help = !c.ui.show_help; }},
    {"present",
     ScriptArg::none,
     {},
     "presentation mode on or off",
     [](const ScriptEntry&, ScriptContext& c) { c.edits.presentation = !c.ui.session.presentation; }},
    {"pin",
     ScriptArg::none,
     {},
     "pin the current r_x(zeta) curve (waits for it)",
     [](const ScriptEntry&, ScriptContext& c) { c.edits.pin = true; }},
    {"unpin",
     ScriptArg::none,
     {},
     "remove every pinned curve",
     [](const ScriptEntry&, ScriptContext& c) { c.edits.clear_pins = true; }},
    {"load",
     ScriptArg::path,
     {},
     "a measured-data CSV (as from the menu or a drop)",
     [](const ScriptEntry& s, ScriptContext& c) { c.edits.load_data = s.text; }},
    {"clear",
     ScriptArg::none,
     {},
     "remove the data",
     [](const ScriptEntry&, ScriptContext& c) { c.edits.clear_data = true; }},
    {"fit",
     ScriptArg::none,
     {},
     "fit r_disp and i to the data (waits for it)",
     [](const ScriptEntry&, ScriptContext& c) { c.edits.fit_data = true; }},
    {"save-session",
     ScriptArg::path,
     {},
     "save the state after this frame's edits (checked before the run)",
     [](const ScriptEntry& s, ScriptContext& c) { c.edits.save_session = s.text; }},
    {"open-session",
     ScriptArg::path,
     {},
     "open a session (a bad file keeps the state, says why)",
     [](const ScriptEntry& s, ScriptContext& c) { c.edits.open_session = s.text; }},
    {"screenshot",
     ScriptArg::none,
     {},
     "the S key: frictionviz-screenshot-N.png, N the next free number",
     [](const ScriptEntry&, ScriptContext& c) { c.edits.screenshot = true; }},
    {"export-trace",
     ScriptArg::none,
     {},
     "File > Export trace CSV: frictionviz-trace-N.csv, N the next free number",
     [](const ScriptEntry&, ScriptContext& c) { c.edits.export_csv = true; }},
    {"export",
     ScriptArg::none,
     {},
     "open the Export animation dialog",
     [](const ScriptEntry&, ScriptContext& c) { c.edits.open_export_dialog = true; }},
    {"animate",
     ScriptArg::path,
     {},
     "write a GIF or MP4 of the current parameters (checked before the run)",
     [](const ScriptEntry& s, ScriptContext& c) {
         AnimationRequest r;
         r.path = s.text;
         r.spec.speed = c.ui.session.speed;
         c.edits.export_animation = r;
     }},
};

std::string action_names() {
    std::string s;
    for (const ScriptAction& a : kActions) s += (s.empty() ? "" : " ") + std::string(a.name);
    return s;
}

const ScriptAction* find_action(const std::string& name) {
    for (const ScriptAction& a : kActions)
        if (name == a.name) return &a;
    return nullptr;
}

std::string preset_ids() {
    std::string s;
    for (const LessonStep& l : lesson_steps()) s += (s.empty() ? "" : ", ") + l.id;
    for (const FigureSpec* f : presets()) s += ", " + f->id;
    return s;
}

// The value of a word action, or why it is not one.
std::string word_error(const ScriptAction& a, const std::string& v) {
    if (std::string(a.name) == "model" || std::string(a.name) == "b.model")
        return parse_model(v) ? "" : std::string(a.name) + " = " + quoted_text(v) + "; allowed: dahl, rigid";
    if (std::string(a.name) == "compare")
        return v == "on" || v == "off" ? "" : "compare = " + quoted_text(v) + "; allowed: on, off";
    if (std::string(a.name) == "edit")
        return v == "a" || v == "b" ? "" : "edit = " + quoted_text(v) + "; allowed: a, b";
    if (std::string(a.name) == "start") {
        Start unused = Start::rest;
        return parse_start(v, unused) ? "" : "start = " + quoted_text(v) + "; allowed: " + kStartNames;
    }
    if (std::string(a.name) == "frame")
        return parse_frame(v) ? "" : "frame = " + quoted_text(v) + "; allowed: body, ground";
    if (std::string(a.name) == "lesson") {
        long long n = 0;
        return read_integer("lesson", v, 0, static_cast<long long>(lesson_steps().size()), n);
    }
    if (find_lesson_step(v)) return "";
    for (const FigureSpec* f : presets())
        if (f->id == v) return "";
    return "unknown preset " + quoted_text(v) + "; allowed: " + preset_ids();
}

// What a path action writes must be writable before the run (as --screenshot), and an animation needs a
// format the exporter knows.
std::string path_error(const ScriptAction& a, const std::string& path) {
    const std::string name = a.name;
    if (name == "animate" && !animation_format(path))
        return "animate " + quoted_text(path, 200) + ": the file name must end in .gif or .mp4";
    if (name == "save-session" || name == "animate")
        if (const std::string why = check_writable(path); !why.empty())
            return name + " " + printable_text(path, 200) + ": " + why;
    return {};
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
        std::string frame_text, action, value, extra;
        if (!(ls >> frame_text)) continue; // blank or comment
        const auto where = path + ":" + std::to_string(no) + ": ";
        const auto fail = [&](const std::string& why) { throw std::runtime_error(where + why); };
        long long frame = 0;
        if (std::string why = read_integer("frame", frame_text, 0, kMaxScriptFrame, frame); !why.empty())
            fail(why + " (each line is 'FRAME ACTION [VALUE]')");
        ls >> action;
        const ScriptAction* a = find_action(action);
        if (!a) fail("unknown action " + quoted_text(action) + "; allowed: " + action_names());
        ScriptEntry e{a, {}, 0};
        if (a->arg != ScriptArg::none) {
            if (!(ls >> value)) fail("'" + action + "' needs a value");
            e.text = value;
        }
        if (ls >> extra) fail("unexpected " + quoted_text(extra) + " after '" + action + "'");
        switch (a->arg) {
        case ScriptArg::none:
            break;
        case ScriptArg::number:
            if (std::string why = read_number(a->name, value, a->range, e.number); !why.empty()) fail(why);
            break;
        case ScriptArg::word:
            if (std::string why = word_error(*a, value); !why.empty()) fail(why);
            break;
        case ScriptArg::path:
            // Files are found next to the script, wherever the script is run from.
            if (value.front() != '/')
                e.text = (std::filesystem::path(path).parent_path() / value).lexically_normal().string();
            if (std::string why = path_error(*a, e.text); !why.empty()) fail(why);
            break;
        }
        s.lines[static_cast<int>(frame)].push_back(std::move(e));
    }
    return s;
}

UiEdits script_edits(const Script& s, int frame, const UiState& ui) {
    UiEdits e;
    const auto it = s.lines.find(frame);
    if (it == s.lines.end()) return e;
    // B's keys set B over the B shown, or with compare mode off over the B it would turn on with (A's
    // setup before this frame's edits, at the other angle), and turn it on, as a link's b.* keys do.
    const Setup b = ui.session.compare ? ui.session.b : compare_default(ui.session.a());
    Params p = ui.session.params, pb = b.params;
    bool params_changed = false, b_changed = false;
    ScriptContext c{ui, e, p, params_changed, pb, b_changed};
    for (const ScriptEntry& entry : it->second) entry.action->apply(entry, c);
    if (params_changed) e.params = p;
    if (b_changed) {
        if (!ui.session.compare) e.compare = true, e.b_setup = b;
        e.b.params = pb;
    }
    return e;
}

std::string script_actions() {
    std::string s;
    for (const ScriptAction& a : kActions) {
        const char* arg = a.arg == ScriptArg::number ? " NUMBER"
                          : a.arg == ScriptArg::path ? " PATH"
                          : a.arg == ScriptArg::word ? " WORD"
                                                     : "";
        s += (s.empty() ? "" : ", ") + std::string(a.name) + arg;
    }
    return s;
}

Params bench_params(Params p, int frame) {
    p.zeta = 0.1 + 0.8 * (0.5 + 0.5 * std::sin(frame * 0.05));
    return p;
}

} // namespace fv::app
