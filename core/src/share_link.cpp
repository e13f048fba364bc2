#include "fv/share_link.hpp"

#include "fv/param_ranges.hpp"
#include "fv/printable_text.hpp"
#include "fv/read_number.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <set>
#include <string>

namespace fv {
namespace {

// `what` quotes the link's text through printable_text, so the message is one line of printable text
// whatever the link holds (%0A, %1B and %00 decode to control bytes).
[[noreturn]] void fail(std::size_t offset, const std::string& what) {
    throw LinkError("column " + std::to_string(offset + 1) + ": " + what);
}

int hex_digit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

// %XX escapes decoded; `offset` is where s starts in the text (for the message).
std::string decode(std::string_view s, std::size_t offset) {
    std::string out;
    for (std::size_t k = 0; k < s.size(); ++k) {
        if (s[k] != '%') {
            out += s[k];
            continue;
        }
        const int hi = k + 1 < s.size() ? hex_digit(s[k + 1]) : -1;
        const int lo = k + 2 < s.size() ? hex_digit(s[k + 2]) : -1;
        if (hi < 0 || lo < 0) fail(offset + k, "'%' must start an escape %XX (two hex digits)");
        out += static_cast<char>(hi * 16 + lo);
        k += 2;
    }
    return out;
}

// A number by the shared reader (fv/read_number.hpp): the same verdict and message as on the command line.
double number(const std::string& key, const std::string& v, std::size_t offset, ParamRange r) {
    double x = 0;
    if (std::string why = read_number(key, v, r, x); !why.empty()) fail(offset, why);
    return x;
}

// The entry of `table` for `key`, or null.
template <class T, std::size_t N> const T* find_key(const T (&table)[N], const std::string& key) {
    const T* it = std::find_if(std::begin(table), std::end(table), [&](const T& t) { return key == t.key; });
    return it == std::end(table) ? nullptr : it;
}

// The numeric keys: where each goes and its range in the shared table.
struct NumberKey {
    const char* key;
    std::optional<double> SetupKeys::*slot;
    ParamRange range;
};
constexpr NumberKey kNumberKeys[] = {{"zeta", &SetupKeys::zeta, kZetaRange},
                                     {"theta", &SetupKeys::theta_deg, kThetaRange},
                                     {"rdisp", &SetupKeys::rdisp, kRdispRange},
                                     {"i", &SetupKeys::i, kIRange}};

// A setup's key (without its "b." prefix) into `s`: false when `key` is not one. `name` is the key as
// written, for messages.
bool read_setup_key(SetupKeys& s, const std::string& key, const std::string& name, const std::string& value,
                    std::size_t at, std::size_t vat) {
    const auto once = [&](bool given) {
        if (given) fail(at, quoted_text(name) + " is given twice; each key at most once");
    };
    if (const NumberKey* nk = find_key(kNumberKeys, key)) {
        once((s.*nk->slot).has_value());
        s.*nk->slot = number(name, value, vat, nk->range);
    } else if (key == "model") {
        once(s.model.has_value());
        s.model = parse_model(value);
        if (!s.model) fail(vat, name + " = " + quoted_text(value) + "; allowed: dahl, rigid");
    } else if (key == "start") {
        once(s.start.has_value());
        Start st = Start::rest;
        if (!parse_start(value, st))
            fail(vat, name + " = " + quoted_text(value) + "; allowed: " + kStartNames);
        s.start = st;
    } else {
        return false;
    }
    return true;
}

// The view's numbers and flags (1 | 0): where each goes and, for a number, its range in the shared table.
struct ViewNumber {
    const char* key;
    std::optional<double> ShareLink::*slot;
    ParamRange range;
};
constexpr ViewNumber kViewNumbers[] = {{"speed", &ShareLink::speed, kSpeedRange},
                                       {"trail", &ShareLink::trail_periods, kTrailRange},
                                       {"zoom", &ShareLink::zoom, kZoomRange}};
struct ViewFlag {
    const char* key;
    std::optional<bool> ShareLink::*slot;
};
constexpr ViewFlag kViewFlags[] = {
    {"present", &ShareLink::presentation}, {"play", &ShareLink::playing}, {"follow", &ShareLink::follow}};

// A view value that does not read: noted and ignored (share_link.hpp).
void notice(ShareLink& link, std::size_t offset, const std::string& what) {
    link.notices.push_back("column " + std::to_string(offset + 1) + ": " + what + "; ignored");
}

std::vector<std::string_view> split(std::string_view s, char sep) {
    std::vector<std::string_view> out;
    for (std::size_t at = 0;;) {
        const std::size_t end = s.find(sep, at);
        out.push_back(s.substr(at, end == std::string_view::npos ? std::string_view::npos : end - at));
        if (end == std::string_view::npos) return out;
        at = end + 1;
    }
}

// The pan value "X,Y": "" or why it does not read (the whole value is then ignored).
std::string read_pan(std::string_view value, std::array<double, 2>& pan) {
    const std::vector<std::string_view> xy = split(value, ',');
    if (xy.size() != 2)
        return "pan = " + quoted_text(std::string(value)) + "; expected X,Y (two numbers joined by ',')";
    for (std::size_t k = 0; k < 2; ++k)
        if (std::string why = read_number(k ? "pan y" : "pan x", xy[k], kPanRange, pan[k]); !why.empty())
            return why;
    return "";
}

// The pins value: "" or why it does not read (the whole value is then ignored).
std::string read_pins(std::string_view value, std::vector<PinSource>& pins) {
    if (value.empty()) return "pins is empty; expected MODEL:THETA[:RDISP:I[:START]] joined by ','";
    if (value.size() > kMaxPinsText)
        return "pins is " + std::to_string(value.size()) + " characters long; allowed: at most " +
               std::to_string(kMaxPinsText);
    const std::vector<std::string_view> items = split(value, ',');
    if (items.size() > kMaxPins)
        return std::to_string(items.size()) + " pins; allowed: at most " + std::to_string(kMaxPins);
    for (std::size_t k = 0; k < items.size(); ++k) {
        PinSource pin;
        if (const std::string why = read_pin_link_text(items[k], pin); !why.empty())
            return "pin " + std::to_string(k + 1) + " (" + quoted_text(std::string(items[k])) + "): " + why;
        pins.push_back(pin);
    }
    return "";
}

} // namespace

ShareLink parse_share_link(std::string_view text, int lesson_steps) {
    // A browser ignores everything from the first '#' (the fragment) and reads the query before it; so
    // does the link: "#?zeta=0.5" sets nothing in a browser, and is no link here either.
    std::size_t from = 0, to = text.size();
    if (const auto h = text.find('#'); h != std::string_view::npos) to = h;
    if (const auto q = text.substr(0, to).find('?'); q != std::string_view::npos) from = q + 1;
    if (from == to)
        fail(from, "no parameters" +
                       std::string(to < text.size() ? " before the '#' (a fragment, which a browser ignores)"
                                                    : "") +
                       "; expected KEY=VALUE pairs joined by '&', e.g. "
                       "?zeta=0.3&theta=60&rdisp=5&i=1&model=dahl (keys: " +
                       std::string(kLinkKeys) + ")");
    ShareLink link;
    std::set<std::string> seen_view; // the view's keys given so far (a value ignored leaves no trace in link)
    std::size_t compare_at = 0;      // where compare= is, for a message
    for (std::size_t at = from; at <= to;) {
        std::size_t end = text.find('&', at);
        if (end == std::string_view::npos || end > to) end = to;
        const std::string_view item = text.substr(at, end - at);
        if (item.empty()) fail(at, "empty item (a stray '&'); expected KEY=VALUE");
        const std::size_t eq = item.find('=');
        const std::string key = decode(item.substr(0, eq), at);
        if (eq == std::string_view::npos) fail(at, quoted_text(key) + " has no value; expected KEY=VALUE");
        const std::size_t vat = at + eq + 1;
        const std::string value = decode(item.substr(eq + 1), vat);
        const auto once = [&](bool given) {
            if (given) fail(at, quoted_text(key) + " is given twice; each key at most once");
        };
        const bool b = key.rfind("b.", 0) == 0;
        if (read_setup_key(b ? link.b : link, b ? key.substr(2) : key, key, value, at, vat)) {
            // A's or B's key, read.
        } else if (key == "frame") {
            once(link.frame.has_value());
            link.frame = parse_frame(value);
            if (!link.frame) fail(vat, "frame = " + quoted_text(value) + "; allowed: body, ground");
        } else if (key == "amplitude" || key == "frequency") {
            const bool amplitude = key == "amplitude";
            std::optional<double>& slot = amplitude ? link.amplitude_um : link.frequency_khz;
            once(slot.has_value());
            slot = number(key, value, vat, amplitude ? kAmplitudeRange : kFrequencyRange);
        } else if (key == "compare") {
            once(link.compare.has_value());
            if (value != "1" && value != "0")
                fail(vat, "compare = " + quoted_text(value) + "; allowed: 1, 0");
            link.compare = value == "1";
            compare_at = at;
        } else if (const ViewFlag* flag = find_key(kViewFlags, key)) {
            once(!seen_view.insert(key).second);
            if (value == "1" || value == "0")
                link.*flag->slot = value == "1";
            else
                notice(link, vat, key + " = " + quoted_text(value) + "; allowed: 1, 0");
        } else if (const ViewNumber* vn = find_key(kViewNumbers, key)) {
            once(!seen_view.insert(key).second);
            double x = 0;
            if (std::string why = read_number(key, value, vn->range, x); why.empty())
                link.*vn->slot = x;
            else
                notice(link, vat, why);
        } else if (key == "panel") {
            once(!seen_view.insert(key).second);
            if (const auto panel = panel_from_name(value))
                link.panel = *panel;
            else
                notice(link, vat, "panel = " + quoted_text(value) + "; allowed: " + panel_names());
        } else if (key == "pan") {
            once(!seen_view.insert(key).second);
            std::array<double, 2> pan{};
            if (const std::string why = read_pan(value, pan); why.empty())
                link.pan = pan;
            else
                notice(link, vat, why);
        } else if (key == "pins") {
            once(!seen_view.insert(key).second);
            std::vector<PinSource> pins;
            if (const std::string why = read_pins(value, pins); why.empty())
                link.pins = std::move(pins);
            else
                notice(link, vat, why);
        } else if (key == "lesson") {
            once(!seen_view.insert(key).second);
            long long step = 0;
            if (lesson_steps < 1)
                notice(link, vat, "lesson = " + quoted_text(value) + ": this reader has no lessons");
            else if (std::string why = read_integer(key, value, 1, lesson_steps, step); why.empty())
                link.lesson = static_cast<int>(step);
            else
                notice(link, vat, why);
        } else {
            fail(at, "unknown key " + quoted_text(key) + "; allowed: " + kLinkKeys);
        }
        at = end + 1;
    }
    if (link.compare == false && link.b.any())
        fail(compare_at,
             "compare=0 turns compare mode off, yet setup B's keys (b.*) are given; give one of them");
    return link;
}

void apply_share_link(const SetupKeys& link, Model& model, Params& params) {
    if (link.zeta) params.zeta = *link.zeta;
    if (link.theta_deg) params.theta = *link.theta_deg * kPi / 180;
    if (link.rdisp) params.rdisp = *link.rdisp;
    if (link.i) params.i = *link.i;
    if (link.model) model = *link.model;
}

void apply_share_link(const SetupKeys& link, Model& model, Params& params, Start& start) {
    apply_share_link(link, model, params);
    if (link.start) start = *link.start;
}

void apply_share_link(const ShareLink& link, Model& model, Params& params, Start& start, FrameChoice& frame) {
    apply_share_link(link, model, params, start);
    if (link.frame) frame = *link.frame;
}

std::string read_pin_link_text(std::string_view text, PinSource& pin) {
    const std::vector<std::string_view> f = split(text, ':');
    const std::optional<Model> model = parse_model(std::string(f[0]));
    if (!model) return "model " + quoted_text(std::string(f[0])) + "; allowed: dahl, rigid";
    pin.model = *model;
    const bool rigid = pin.model == Model::rigid;
    if (rigid ? f.size() != 2 : f.size() < 4 || f.size() > 5)
        return rigid ? "a rigid pin is rigid:THETA" : "a Dahl pin is dahl:THETA:RDISP:I[:START]";
    double theta_deg = 0;
    if (std::string why = read_number("theta", f[1], kThetaRange, theta_deg); !why.empty()) return why;
    pin.theta = theta_deg * kPi / 180;
    if (rigid) return "";
    if (std::string why = read_number("rdisp", f[2], kRdispRange, pin.rdisp); !why.empty()) return why;
    if (std::string why = read_number("i", f[3], kIRange, pin.i); !why.empty()) return why;
    if (f.size() == 5 && !parse_start(std::string(f[4]), pin.start))
        return "start " + quoted_text(std::string(f[4])) + "; allowed: " + kStartNames;
    return "";
}

std::string pin_link_text(const PinSource& pin) {
    std::string s = std::string(to_string(pin.model)) + ":" + shortest_decimal(theta_degrees(pin.theta));
    if (pin.model == Model::rigid) return s;
    s += ":" + shortest_decimal(pin.rdisp) + ":" + shortest_decimal(pin.i);
    return pin.start == Start::rest ? s : s + ":" + to_string(pin.start);
}

std::string compare_link_keys(Model model, const Params& p, Start start) {
    return "&b.zeta=" + shortest_decimal(p.zeta) + "&b.theta=" + shortest_decimal(theta_degrees(p.theta)) +
           "&b.rdisp=" + shortest_decimal(p.rdisp) + "&b.i=" + shortest_decimal(p.i) +
           "&b.model=" + to_string(model) +
           (start == Start::rest ? "" : std::string("&b.start=") + to_string(start));
}

std::string view_link_keys(const ShareLink& link) {
    std::string s;
    const auto number = [&s](const char* key, const std::optional<double>& v) {
        if (v) s += std::string("&") + key + "=" + shortest_decimal(*v);
    };
    const auto flag = [&s](const char* key, const std::optional<bool>& v) {
        if (v) s += std::string("&") + key + (*v ? "=1" : "=0");
    };
    number("amplitude", link.amplitude_um);
    number("frequency", link.frequency_khz);
    if (link.panel) s += std::string("&panel=") + panel_name(*link.panel);
    flag("present", link.presentation);
    number("speed", link.speed);
    flag("play", link.playing);
    number("trail", link.trail_periods);
    number("zoom", link.zoom);
    if (link.pan) s += "&pan=" + shortest_decimal((*link.pan)[0]) + "," + shortest_decimal((*link.pan)[1]);
    flag("follow", link.follow);
    if (link.pins && !link.pins->empty()) {
        s += "&pins=";
        for (std::size_t k = 0; k < link.pins->size(); ++k)
            s += (k ? "," : "") + pin_link_text((*link.pins)[k]);
    }
    if (link.lesson) s += "&lesson=" + std::to_string(*link.lesson);
    return s;
}

double theta_degrees(double theta_rad) {
    const double deg = theta_rad * 180 / kPi;
    double best = deg;
    std::size_t best_len = 0;
    // Degrees to radians rounds: look a few doubles either side for one that maps back exactly, and take
    // the shortest to write.
    double d = deg;
    for (int k = 0; k < 4; ++k) d = std::nextafter(d, -HUGE_VAL);
    for (int k = 0; k < 9; ++k, d = std::nextafter(d, HUGE_VAL)) {
        if (d * kPi / 180 != theta_rad) continue;
        const std::size_t len = shortest_decimal(d).size();
        if (best_len == 0 || len < best_len) best = d, best_len = len;
    }
    return best + 0.0; // -0.0 maps back to 0 as well: never print -0
}

std::string share_link(Model model, const Params& p, Start start, FrameChoice frame) {
    return "?zeta=" + shortest_decimal(p.zeta) + "&theta=" + shortest_decimal(theta_degrees(p.theta)) +
           "&rdisp=" + shortest_decimal(p.rdisp) + "&i=" + shortest_decimal(p.i) +
           "&model=" + to_string(model) +
           (start == Start::rest ? "" : std::string("&start=") + to_string(start)) +
           (frame == FrameChoice::body ? "" : std::string("&frame=") + to_string(frame));
}

} // namespace fv
