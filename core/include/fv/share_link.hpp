// The share link: the model and its four parameters as a URL query,
//
//   ?zeta=0.3&theta=60&rdisp=5&i=1&model=dahl        (theta in degrees, as on the command line)
//   ?zeta=0.075&theta=90&rdisp=0.1&i=5&model=dahl&start=sliding   (the history: written only when sliding)
//   ?zeta=0.3&theta=0&rdisp=2&i=0&model=dahl&frame=ground   (the top view's frame: written only for ground)
//
// The app shows it for the state on screen (with a Copy button), `frictionviz gui --link STRING` starts from
// it, and the browser build reads the same keys from its page address; so this parser has no GUI in it and
// lives in core, which both builds compile.
//
// The vibration behind the physical units may follow, each written only when it is not the app's default
// (0.7 um at 60 kHz, the paper's Fig. 19), read and checked as the command line's --amplitude and --frequency
// (an error, not a notice: they change the v_b and z_ss shown and how measured data convert):
//
//   &amplitude=1            the vibration amplitude A in um (kAmplitudeRange)
//   &frequency=40           its frequency f in kHz (kFrequencyRange)
//
// The app's view may follow (each written only when it is not the app's default or, in a lesson, the step's,
// so the link of a default view is the five keys above, as before these were added):
//
//   &panel=map              the lower-right panel: curves | map | loop | why
//   &present=1              presentation mode (1 | 0)
//   &speed=1.5              animation speed, vibration periods per second (kSpeedRange)
//   &play=0                 the animation paused (1 | 0: running, the default)
//   &trail=3                the trail behind P and T in vibration periods (kTrailRange)
//   &zoom=2                 the top view's zoom factor (kZoomRange)
//   &pan=0.5,-1             the top view's pan X,Y in units of x_v, its axes' (each in kPanRange)
//   &follow=0               the camera stays where it was put rather than following the body (1 | 0)
//   &pins=dahl:60:2:1,rigid:30,dahl:90:0.1:5:sliding
//                           pinned r_x(zeta) curves by what they were computed at (at most kMaxPins, ','
//                           between them): MODEL:THETA_DEG[:RDISP:I[:START]] (the Dahl model needs r_disp
//                           and i; the rigid curve depends on theta alone); the page computes them again
//   &lesson=3               the guided lesson's step shown (1 to the reader's number of steps,
//                           docs/lessons.md): its setup first, then the link's other keys over it
//
// and the compare mode's setup B beside the setup above (A), each key as A's, read and checked alike (an
// error, not a notice: they are a setup); any of them turns compare mode on, and what they leave out is
// fv::compare_default of A (A's values at the other angle):
//
//   &b.zeta=0.15&b.theta=0&b.rdisp=2&b.i=1&b.model=dahl&b.start=sliding
//
// and `compare=0` turns compare mode off where a lesson step turns it on (`compare=1`: on with the default B;
// compare=0 with B's keys is an error). The app writes start=rest, frame=body, b.start=rest and compare=0
// only where the reader would otherwise take the other value (a lesson step's, or B's start from A's), so
// that a link reopens the state it was written from.
//
// A view value that does not read is ignored with a notice (ShareLink::notices: "column N: what; allowed:
// ...; ignored"), never an error: it changes how the setup is shown, not the setup, so the link still opens.
//
// Accepted: the query alone ("zeta=0.3&theta=60"), with its '?' or a whole URL. As in a browser, everything
// from the first '#' on is a fragment and ignored; the query is what follows the first '?' before it
// ("#?zeta=0.5" has no query). Keys are those of kLinkKeys, each at most once, any subset (the rest keeps its
// value); values are numbers read by the shared reader (read_number.hpp, as on the command line) inside the
// shared range table (param_ranges.hpp), dahl|rigid, rest|sliding or body|ground; %XX escapes are decoded
// ('+' stays a plus sign, so "1e+3" is a number). Anything else is a LinkError naming the column, what was
// wrong and what is allowed, except the app's view values (panel, present, speed, play, trail, zoom, pan,
// follow, pins), which are ignored with a notice (lesson too: the steps are the app's data, so the reader
// says how many there are).
#pragma once

#include "fv/lower_panel.hpp"
#include "fv/params.hpp"
#include "fv/pinned_curve.hpp"   // PinSource
#include "fv/read_number.hpp"    // shortest_decimal
#include "fv/steady_state.hpp"   // Start
#include "fv/top_view_frame.hpp" // FrameChoice

#include <array>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace fv {

inline constexpr const char* kLinkKeys = "zeta, theta, rdisp, i, model, start, frame, amplitude, frequency, "
                                         "panel, present, speed, play, trail, zoom, pan, follow, pins, "
                                         "lesson, compare, b.zeta, b.theta, b.rdisp, b.i, b.model, b.start";
// A pins value longer than this is ignored (kMaxPins pins of shortest decimals fit with room to spare).
inline constexpr std::size_t kMaxPinsText = 600;

// The keys of one setup (A's without a prefix, B's with "b.").
struct SetupKeys {
    std::optional<double> zeta, theta_deg, rdisp, i;
    std::optional<Model> model;
    std::optional<Start> start; // the history (docs/model.md, "Which steady state")
    bool any() const { return zeta || theta_deg || rdisp || i || model || start; }
};

// A's keys are the link's own (link.zeta, ...); B's are link.b.
struct ShareLink : SetupKeys {
    std::optional<FrameChoice> frame; // what stands still in the app's top view
    // The vibration (A's and B's): amplitude in um, frequency in kHz.
    std::optional<double> amplitude_um, frequency_khz;
    // The app's view.
    std::optional<LowerPanel> panel;
    std::optional<bool> presentation;
    std::optional<double> speed;
    std::optional<bool> playing;
    std::optional<double> trail_periods, zoom;
    std::optional<std::array<double, 2>> pan;
    std::optional<bool> follow;
    std::optional<std::vector<PinSource>> pins;
    std::optional<int> lesson;   // a guided lesson's step, 1-based
    SetupKeys b;                 // compare mode's setup B (any key given: compare on)
    std::optional<bool> compare; // compare mode on (with the default B) or off
    // View values that did not read and were ignored, each "column N: what; allowed: ...; ignored".
    std::vector<std::string> notices;
};

// what(): "column N: message" (N counts bytes of the text given, from 1).
struct LinkError : std::invalid_argument {
    using std::invalid_argument::invalid_argument;
};

// `lesson_steps`: how many lesson steps the reader has (the app's lessons.json; app::parse_link passes
// them); a lesson value outside 1..lesson_steps is ignored with a notice naming that range.
ShareLink parse_share_link(std::string_view text, int lesson_steps = 0);

// The link's values over `model` and `params` (theta converted from degrees as the command line does), and
// its start over `start`. (The three-argument form leaves the start to the caller.) Given link.b, B's.
void apply_share_link(const SetupKeys& link, Model& model, Params& params);
void apply_share_link(const SetupKeys& link, Model& model, Params& params, Start& start);
void apply_share_link(const ShareLink& link, Model& model, Params& params, Start& start, FrameChoice& frame);

// "?zeta=Z&theta=DEG&rdisp=R&i=I&model=M" for the state given, every number the shortest decimal that reads
// back as the same double (theta: see theta_degrees), so parsing the link gives the same parameters; then
// "&start=sliding" for that start only, so that the link of the paper's start (rest, the default) is the
// same as before the start could be chosen; and "&frame=ground" for that frame only, likewise.
std::string share_link(Model model, const Params& params, Start start = Start::rest,
                       FrameChoice frame = FrameChoice::body);

// "&b.zeta=Z&b.theta=DEG&b.rdisp=R&b.i=I&b.model=M" (and "&b.start=sliding" for that start only): setup B's
// keys, numbers as share_link() writes them; appended by the app in compare mode.
std::string compare_link_keys(Model model, const Params& params, Start start = Start::rest);

// The vibration's and the view's keys for the fields `link` sets, in the order above ("&amplitude=1&
// frequency=40&panel=map&present=1&speed=1.5&play=0&trail=3&zoom=2&pan=0.5,-1&follow=0&pins=dahl:60:2:1&
// lesson=3"), or "": appended to share_link() by the app for what differs from its defaults.
std::string view_link_keys(const ShareLink& link);

// One pin as the link writes it ("dahl:60:2:1", "dahl:90:0.1:5:sliding", "rigid:30"), numbers that read
// back bit for bit.
std::string pin_link_text(const PinSource& pin);
// Reads one pin as pin_link_text writes it (also a session file's "link" of a pin): "" or why it does not
// read (pin then partly set).
std::string read_pin_link_text(std::string_view text, PinSource& pin);

// theta in degrees such that degrees * kPi / 180 gives theta_rad back bit for bit where a nearby double does
// (the nicest of them: 60, not 60.00000000000001), else theta_rad * 180 / kPi.
double theta_degrees(double theta_rad);

} // namespace fv
