#include "session.hpp"

#include "app_state.hpp"
#include "lessons.hpp"

#include "fv/atomic_file.hpp"
#include "fv/input_file.hpp"
#include "fv/printable_text.hpp"
#include "fv/read_number.hpp"
#include "fv/share_link.hpp"
#include "fv/units.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <vector>

namespace fv::app {
namespace {

using Json = nlohmann::ordered_json;

constexpr std::size_t kMaxSessionBytes = 1u << 20;

// Where each key and each value of a (valid) JSON text starts, by JSON pointer ("/view/zoom"), and the first
// key given twice in one object. nlohmann's parser keeps no positions; the text is re-scanned after it has
// accepted it, so the scan need not check anything. Containers deeper than kDepth are skipped unrecorded.
class Positions {
  public:
    explicit Positions(const std::string& text) : s_(text) {
        if (s_.compare(0, 3, "\xEF\xBB\xBF") == 0) k_ = 3; // the BOM nlohmann skips
        value("", 0);
    }
    std::size_t value_at(const std::string& ptr) const { return find(values_, ptr); }
    std::size_t key_at(const std::string& ptr) const { return find(keys_, ptr); }
    // The pointer of the value that starts at `offset`, or "".
    std::string pointer_at(std::size_t offset) const {
        for (const auto& [ptr, at] : values_)
            if (at == offset) return ptr;
        return {};
    }
    const std::string& duplicate() const { return duplicate_; } // pointer, or ""

  private:
    static constexpr int kDepth = 8;
    static std::size_t find(const std::map<std::string, std::size_t>& m, const std::string& ptr) {
        const auto it = m.find(ptr);
        return it == m.end() ? 0 : it->second;
    }
    void blank() {
        while (k_ < s_.size() && (s_[k_] == ' ' || s_[k_] == '\t' || s_[k_] == '\n' || s_[k_] == '\r')) ++k_;
    }
    // A key as nlohmann gives it: escapes (\n, \u00e9) decoded.
    static std::string decoded(const std::string& raw) {
        try {
            return Json::parse("\"" + raw + "\"").get<std::string>();
        } catch (const nlohmann::json::exception&) {
            return raw; // text the parser refused is scanned too (to place a number it could not hold)
        }
    }
    std::string string() { // at the opening quote; escapes kept as written
        const std::size_t from = ++k_;
        while (k_ < s_.size() && s_[k_] != '"') k_ += s_[k_] == '\\' ? 2 : 1;
        k_ = std::min(k_, s_.size());
        return s_.substr(from, k_++ - from);
    }
    void skip_container() { // at '{' or '['
        int depth = 0;
        do {
            if (s_[k_] == '"') {
                string();
                continue;
            }
            if (s_[k_] == '{' || s_[k_] == '[') ++depth;
            if (s_[k_] == '}' || s_[k_] == ']') --depth;
            ++k_;
        } while (depth > 0 && k_ < s_.size());
    }
    void value(const std::string& ptr, int depth) {
        blank();
        if (k_ >= s_.size()) return;
        values_.emplace(ptr, k_);
        const char open = s_[k_];
        if ((open == '{' || open == '[') && depth >= kDepth) return skip_container();
        if (open == '"') {
            string();
        } else if (open == '{' || open == '[') {
            ++k_;
            for (int index = 0;; ++index) {
                blank();
                // Text the JSON parser refused is scanned too (to place a number it could not hold): stop
                // at its end, wherever that falls.
                if (k_ >= s_.size() || s_[k_] == '}' || s_[k_] == ']') break;
                std::string child = ptr + "/" + std::to_string(index);
                if (open == '{') {
                    const std::size_t at = k_;
                    child = ptr + "/" + decoded(string());
                    // A repeated key: keep the first one found, pointing at its second occurrence.
                    if (!keys_.emplace(child, at).second && duplicate_.empty())
                        duplicate_ = child, keys_[child] = at;
                    blank();
                    ++k_; // ':'
                }
                value(child, depth + 1);
                blank();
                if (k_ < s_.size() && s_[k_] == ',') ++k_;
            }
            ++k_;
        } else {
            while (k_ < s_.size() && std::string_view(",]} \t\r\n").find(s_[k_]) == std::string_view::npos)
                ++k_;
        }
    }

    const std::string& s_;
    std::size_t k_ = 0;
    std::map<std::string, std::size_t> values_, keys_;
    std::string duplicate_;
};

// A message on one line whatever the file holds (keys, values and paths may contain line breaks).
[[noreturn]] void fail_with(const std::string& what) {
    // Values are quoted printable where they are put in; this is for what escaped that (the JSON parser's
    // own message quotes the byte it stopped at, raw), and keeps the message one bounded line.
    throw SessionError(printable_text(what, 1000));
}

// "FILE:LINE:COL" of a byte offset (line and column from 1, the column in bytes).
std::string where(const std::string& file, const std::string& text, std::size_t offset) {
    offset = std::min(offset, text.size());
    const std::size_t line =
        1 + static_cast<std::size_t>(std::count(text.begin(), text.begin() + offset, '\n'));
    const std::size_t nl = offset == 0 ? std::string::npos : text.rfind('\n', offset - 1);
    const std::size_t col = nl == std::string::npos ? offset + 1 : offset - nl;
    return printable_text(file, 4096) + ":" + std::to_string(line) + ":" + std::to_string(col);
}

// The raw text of the scalar value at `offset` (a number as written: "1e-400", not the 0 nlohmann made of
// it).
std::string_view token_at(const std::string& text, std::size_t offset) {
    std::size_t end = offset;
    while (end < text.size() && std::string_view(",]} \t\r\n").find(text[end]) == std::string_view::npos)
        ++end;
    return std::string_view(text).substr(offset, end - offset);
}

// A JSON value shown in a message: its text, printable and short whatever it holds.
std::string shown(const Json& v) {
    return printable_text(v.dump(), 40);
}

// How deep objects and arrays may nest (a session needs 4: {"pins": [{"zeta": [..]}]}). Checked before the
// JSON parser sees the text, so that no input can make anything recurse deeply on it.
constexpr int kMaxDepth = 16;

// The byte offset of the first bracket nested deeper than kMaxDepth, or npos. Strings are skipped (a '['
// inside one is text); the text need not be valid JSON (the parser judges that afterwards).
std::size_t too_deep(const std::string& text) {
    int depth = 0;
    for (std::size_t k = 0; k < text.size(); ++k) {
        const char c = text[k];
        if (c == '"') {
            for (++k; k < text.size() && text[k] != '"'; ++k)
                if (text[k] == '\\') ++k;
        } else if (c == '{' || c == '[') {
            if (++depth > kMaxDepth) return k;
        } else if (c == '}' || c == ']') {
            --depth;
        }
    }
    return std::string::npos;
}

std::string type_name(const Json& v) {
    if (v.is_number()) return "a number";
    if (v.is_string()) return "a string";
    if (v.is_boolean()) return "true/false";
    if (v.is_null()) return "null";
    if (v.is_array()) return "an array";
    return "an object";
}

// Reads the checked values of one object (the top level or "view") and says where a bad one is.
class Reader {
  public:
    Reader(const std::string& file, const std::string& text, const Positions& pos)
        : file_(file), text_(text), pos_(pos) {}

    [[noreturn]] void fail_at(const std::string& ptr, const std::string& what, bool key = false) const {
        fail_with(where(file_, text_, key ? pos_.key_at(ptr) : pos_.value_at(ptr)) + ": " + what);
    }

    // Every key of `obj` (at `ptr`) must be one of `allowed`.
    void only(const Json& obj, const std::string& ptr, const std::vector<std::string>& allowed) const {
        std::string unknown, first, list;
        for (const auto& [k, v] : obj.items())
            if (std::find(allowed.begin(), allowed.end(), k) == allowed.end()) {
                if (first.empty()) first = ptr + "/" + k;
                if (unknown.size() < 200) unknown += (unknown.empty() ? "" : ", ") + shown(Json(k));
            }
        for (const std::string& a : allowed) list += (list.empty() ? "" : ", ") + a;
        if (!first.empty())
            fail_at(first,
                    "unknown key" + std::string(unknown.find(',') != std::string::npos ? "s " : " ") +
                        unknown + (ptr.empty() ? "" : " in \"" + printable_text(ptr.substr(1)) + "\"") +
                        "; allowed: " + list,
                    true);
    }

    // The number at `ptr` (given as one: `v`), read from its text by the shared reader (read_number.hpp), so
    // that 1e-400 is refused as on the command line rather than taken as the 0 the JSON parser made of it.
    double number(const Json& v, const std::string& ptr, const std::string& name, ParamRange r) const {
        if (!v.is_number()) fail_at(ptr, name + ": expected a number, got " + type_name(v));
        double x = 0;
        if (std::string why = read_number(name, token_at(text_, pos_.value_at(ptr)), r, x); !why.empty())
            fail_at(ptr, why);
        return x;
    }

    void get(const Json& obj, const std::string& ptr, const char* key, double& out, ParamRange r) const {
        if (obj.contains(key)) out = number(obj.at(key), ptr + "/" + key, key, r);
    }

    template <class T, class Check>
    void get(const Json& obj, const std::string& ptr, const char* key, T& out, Check check) const {
        if (!obj.contains(key)) return;
        const std::string p = ptr + "/" + key;
        const Json& v = obj.at(key);
        if constexpr (std::is_same_v<T, bool>) {
            if (!v.is_boolean())
                fail_at(p, std::string(key) + ": expected true or false, got " + type_name(v));
            out = v.get<bool>();
        } else {
            if (!v.is_string()) fail_at(p, std::string(key) + ": expected a string, got " + type_name(v));
            if (const std::string why = check(v.get<std::string>()); !why.empty()) fail_at(p, why);
            out = v.get<std::string>();
        }
    }

  private:
    const std::string& file_;
    const std::string& text_;
    const Positions& pos_;
};

auto one_of(const char* name, std::vector<std::string> allowed) {
    return [name, allowed](const std::string& v) -> std::string {
        if (std::find(allowed.begin(), allowed.end(), v) != allowed.end()) return "";
        std::string list;
        for (const std::string& a : allowed) list += (list.empty() ? "" : ", ") + a;
        return std::string(name) + " = " + shown(Json(v)) + "; allowed: " + list;
    };
}

// The message of nlohmann's parse_error without its id and position (those are given as FILE:LINE:COL).
std::string parse_detail(const nlohmann::json::parse_error& e) {
    std::string w = e.what();
    const auto col = w.find("column ");
    const auto colon = w.find(": ", col == std::string::npos ? 0 : col);
    return colon == std::string::npos ? w : w.substr(colon + 2);
}

// The name and range of the number at a JSON pointer, as the reader below checks it ("/view/pan/0" is
// "pan x"); for messages about a number the JSON parser could not hold.
std::pair<std::string, ParamRange> number_key(const std::string& ptr) {
    static const std::pair<const char*, ParamRange> keys[] = {{"zeta", kZetaRange},
                                                              {"theta", kThetaRange},
                                                              {"rdisp", kRdispRange},
                                                              {"i", kIRange},
                                                              {"amplitude_um", kAmplitudeRange},
                                                              {"frequency_khz", kFrequencyRange},
                                                              {"speed", kSpeedRange},
                                                              {"zoom", kZoomRange},
                                                              {"trail_periods", kTrailRange},
                                                              {"r_x", kRxDataRange}};
    if (ptr == "/view/pan/0" || ptr == "/view/pan/1")
        return {ptr.back() == '0' ? "pan x" : "pan y", kPanRange};
    for (const auto& [key, range] : keys)
        if (ptr == std::string("/") + key || ptr == std::string("/view/") + key ||
            ptr == std::string("/compare/") + key ||
            ptr.find(std::string("/") + key + "/") != std::string::npos)
            return {key, range};
    return {"", ParamRange{-DBL_MAX, DBL_MAX}};
}

} // namespace

Session session_of(const UiState& ui) {
    Session s;
    static_cast<SessionState&>(s) = ui.session;
    if (ui.data && !ui.data_is_example) { // a lesson's example points come with the lesson, not from a file
        std::error_code ec;
        const auto abs = std::filesystem::absolute(ui.data->file, ec);
        s.data_file = ec ? ui.data->file : abs.lexically_normal().string();
    }
    return s;
}

namespace {

// JSON with objects and arrays of objects one item a line, arrays of numbers on one line ("pan": [0.3, -1]).
void pretty(const Json& j, int indent, std::string& out) {
    const bool flat =
        j.is_array() && std::none_of(j.begin(), j.end(), [](const Json& v) { return v.is_structured(); });
    if (!j.is_structured() || j.empty() || flat) {
        if (!flat) {
            out += j.dump();
            return;
        }
        out += '[';
        for (std::size_t k = 0; k < j.size(); ++k) out += (k ? ", " : "") + j[k].dump();
        out += ']';
        return;
    }
    const std::string pad(static_cast<std::size_t>(indent) + 2, ' ');
    out += j.is_object() ? "{\n" : "[\n";
    std::size_t k = 0;
    for (auto it = j.begin(); it != j.end(); ++it, ++k) {
        out += pad;
        if (j.is_object()) out += Json(it.key()).dump() + ": ";
        pretty(*it, indent + 2, out);
        out += k + 1 < j.size() ? ",\n" : "\n";
    }
    out += std::string(static_cast<std::size_t>(indent), ' ') + (j.is_object() ? "}" : "]");
}

} // namespace

std::string session_json(const Session& s) {
    Json j;
    j["version"] = kSessionVersion;
    j["model"] = to_string(s.model);
    j["zeta"] = s.params.zeta;
    j["theta"] = theta_degrees(s.params.theta);
    j["rdisp"] = s.params.rdisp;
    j["i"] = s.params.i;
    j["start"] = to_string(s.start);
    j["amplitude_um"] = s.amplitude_um;
    j["frequency_khz"] = s.frequency_khz;
    j["speed"] = s.speed;
    j["playing"] = s.playing;
    j["panel"] = panel_name(s.panel);
    if (s.lesson != 0) j["lesson"] = s.lesson; // only during a lesson: other sessions read as before
    j["view"] = Json{{"zoom", s.view.zoom},
                     {"pan", {s.view.pan.x(), s.view.pan.y()}},
                     {"follow", s.view.follow},
                     {"trail_periods", s.view.trail_periods},
                     {"frame", to_string(s.view.frame)},
                     {"presentation", s.presentation}};
    if (s.compare)
        j["compare"] = Json{{"model", to_string(s.b.model)},
                            {"zeta", s.b.params.zeta},
                            {"theta", theta_degrees(s.b.params.theta)},
                            {"rdisp", s.b.params.rdisp},
                            {"i", s.b.params.i},
                            {"start", to_string(s.b.start)}};
    j["pins"] = Json::array();
    for (const PinnedCurve& p : s.pins) {
        Json rx = Json::array();
        for (double v : p.rx)
            rx.push_back(std::isfinite(v) ? Json(v) : Json(nullptr)); // a failed point: a gap
        Json pin{{"label", p.label}, {"zeta", p.zeta}, {"r_x", rx}};
        if (p.source) pin["link"] = pin_link_text(*p.source); // what a share link carries for it
        j["pins"].push_back(std::move(pin));
    }
    j["data"] = s.data_file.empty() ? Json(nullptr) : Json(s.data_file);
    std::string out;
    pretty(j, 0, out);
    return out + "\n";
}

namespace {

// "pins": [{"label": "..", "zeta": [..], "r_x": [.., null, ..], "link": ".."}, ...]: at most kMaxPins curves,
// zeta in its range, r_x a number or null (a point the solver did not vouch for: a gap), both of one length;
// "link" (optional) what the curve was computed at, as in a share link ("dahl:60:2:1").
std::vector<PinnedCurve> read_pins(const Json& pins, const Reader& r) {
    if (!pins.is_array()) r.fail_at("/pins", "pins: expected an array of curves, got " + type_name(pins));
    if (pins.size() > kMaxPins)
        r.fail_at("/pins", "pins: " + std::to_string(pins.size()) + " curves; allowed: at most " +
                               std::to_string(kMaxPins));
    std::vector<PinnedCurve> out;
    for (std::size_t k = 0; k < pins.size(); ++k) {
        const std::string ptr = "/pins/" + std::to_string(k);
        const Json& c = pins[k];
        if (!c.is_object())
            r.fail_at(ptr,
                      "pins: expected {\"label\": .., \"zeta\": [..], \"r_x\": [..]}, got " + type_name(c));
        r.only(c, ptr, {"label", "zeta", "r_x", "link"});
        for (const char* key : {"label", "zeta", "r_x"})
            if (!c.contains(key)) r.fail_at(ptr, std::string("pin without \"") + key + "\"");
        PinnedCurve pin;
        r.get(c, ptr, "label", pin.label, [](const std::string& label) {
            const std::string why = text_error(label, kMaxLabelBytes);
            return why.empty() ? why : "label: " + why;
        });
        // Optional: what the curve was computed at, as a share link's pins= writes one (share_link.hpp).
        std::string link;
        r.get(c, ptr, "link", link, [&pin](const std::string& text) {
            PinSource source;
            const std::string why = read_pin_link_text(text, source);
            if (why.empty()) pin.source = source;
            return why.empty() ? why : "link: " + why;
        });
        const Json &zeta = c["zeta"], &rx = c["r_x"];
        for (const auto& [key, a] : {std::pair<const char*, const Json*>{"zeta", &zeta}, {"r_x", &rx}})
            if (!a->is_array() || a->empty() || a->size() > 100000)
                r.fail_at(ptr + "/" + key,
                          std::string(key) + ": expected an array of 1 to 100000 numbers, got " +
                              (a->is_array() ? std::to_string(a->size()) + " items" : type_name(*a)));
        if (zeta.size() != rx.size())
            r.fail_at(ptr + "/r_x", "r_x: " + std::to_string(rx.size()) + " values for " +
                                        std::to_string(zeta.size()) + " zeta values; allowed: one per zeta");
        for (std::size_t n = 0; n < zeta.size(); ++n) {
            const std::string at = "/" + std::to_string(n);
            pin.zeta.push_back(r.number(zeta[n], ptr + "/zeta" + at, "zeta", kZetaRange));
            if (!rx[n].is_number() && !rx[n].is_null())
                r.fail_at(ptr + "/r_x" + at,
                          "r_x: expected a number or null (a gap), got " + type_name(rx[n]));
            pin.rx.push_back(rx[n].is_null() ? std::nan("")
                                             : r.number(rx[n], ptr + "/r_x" + at, "r_x", kRxDataRange));
        }
        out.push_back(std::move(pin));
    }
    return out;
}

// "compare": {"model": .., "zeta": .., "theta": .., "rdisp": .., "i": .., "start": ..}: compare mode on with
// this setup B; a key left out is compare_default's of A (A's value, theta at the other angle).
void read_compare(const Json& c, const Reader& r, Session& s) {
    if (!c.is_object())
        r.fail_at("/compare",
                  "compare: expected an object {\"theta\": 0, ..} (setup B) or null, got " + type_name(c));
    r.only(c, "/compare", {"model", "zeta", "theta", "rdisp", "i", "start"});
    Setup b = compare_default(s.a());
    std::string model = to_string(b.model), start = to_string(b.start);
    r.get(c, "/compare", "model", model, one_of("model", {"dahl", "rigid"}));
    b.model = *parse_model(model);
    double theta_deg = theta_degrees(b.params.theta);
    r.get(c, "/compare", "zeta", b.params.zeta, kZetaRange);
    r.get(c, "/compare", "theta", theta_deg, kThetaRange);
    if (c.contains("theta")) b.params.theta = theta_deg * kPi / 180;
    r.get(c, "/compare", "rdisp", b.params.rdisp, kRdispRange);
    r.get(c, "/compare", "i", b.params.i, kIRange);
    r.get(c, "/compare", "start", start, one_of("start", {"rest", "sliding"}));
    parse_start(start, b.start);
    if (const std::string why = units::physical_view_error(b.params, s.amplitude_um, s.frequency_khz);
        !why.empty())
        r.fail_at(why.rfind("zeta", 0) == 0 && c.contains("zeta") ? "/compare/zeta"
                  : c.contains("rdisp")                           ? "/compare/rdisp"
                                                                  : "/compare",
                  "setup B: " + why);
    s.compare = true;
    s.b = b;
}

} // namespace

Session parse_session(const std::string& text, const std::string& file) {
    // A session is text: a NUL would end it early for some readers and hide what follows from others.
    if (const std::size_t nul = text.find('\0'); nul != std::string::npos)
        fail_with(where(file, text, nul) + ": a NUL byte; a session file is JSON text");
    if (const std::size_t deep = too_deep(text); deep != std::string::npos)
        fail_with(where(file, text, deep) + ": objects and arrays nested deeper than " +
                  std::to_string(kMaxDepth) + " levels; a session needs 4");
    Json j;
    try {
        j = Json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        fail_with(where(file, text, e.byte > 0 ? e.byte - 1 : 0) +
                  ": not valid JSON: " + printable_text(parse_detail(e), 120));
    } catch (const nlohmann::json::exception& e) {
        // A number beyond the doubles ("number overflow parsing '1e400'"): no byte position, so look for it,
        // and say it as the shared reader does ("zeta = 1e400 is out of range (beyond double precision)").
        const std::string w = e.what();
        const auto q = w.find('\'');
        const std::string token = q == std::string::npos ? "" : w.substr(q + 1, w.find('\'', q + 1) - q - 1);
        const std::size_t at = token.empty() ? std::string::npos : text.find(token);
        if (at == std::string::npos) fail_with(where(file, text, 0) + ": " + printable_text(w, 200));
        const auto [name, range] = number_key(Positions(text).pointer_at(at));
        double unused = 0;
        fail_with(where(file, text, at) + ": " + read_number(name, token, range, unused));
    }
    const Positions pos(text);
    const Reader r(file, text, pos);
    if (!j.is_object())
        r.fail_at("", "a session is a JSON object ({\"version\": 1, ...}), not " + type_name(j));
    if (!pos.duplicate().empty())
        r.fail_at(pos.duplicate(),
                  "key \"" + pos.duplicate().substr(1) + "\" is given twice; each key at most once", true);
    r.only(j, "",
           {"version", "model", "zeta", "theta", "rdisp", "i", "start", "amplitude_um", "frequency_khz",
            "speed", "playing", "panel", "lesson", "view", "compare", "pins", "data"});
    if (!j.contains("version"))
        r.fail_at("", "no \"version\"; a frictionviz session starts {\"version\": " +
                          std::to_string(kSessionVersion) + ", ...}");
    const Json& version = j["version"];
    if (!version.is_number_integer() || version.get<long long>() != kSessionVersion)
        r.fail_at("/version", "version " + shown(version) + " is not one this frictionviz reads; allowed: " +
                                  std::to_string(kSessionVersion));

    Session s;
    std::string model = to_string(s.model), panel = panel_name(s.panel);
    r.get(j, "", "model", model, one_of("model", {"dahl", "rigid"}));
    s.model = *parse_model(model);
    double theta_deg = s.params.theta * 180 / kPi;
    r.get(j, "", "zeta", s.params.zeta, kZetaRange);
    r.get(j, "", "theta", theta_deg, kThetaRange);
    if (j.contains("theta")) s.params.theta = theta_deg * kPi / 180;
    r.get(j, "", "rdisp", s.params.rdisp, kRdispRange);
    r.get(j, "", "i", s.params.i, kIRange);
    // The history; a session saved before the start could be chosen has none: rest, as it was then.
    std::string start = to_string(s.start);
    r.get(j, "", "start", start, one_of("start", {"rest", "sliding"}));
    parse_start(start, s.start);
    r.get(j, "", "amplitude_um", s.amplitude_um, kAmplitudeRange);
    r.get(j, "", "frequency_khz", s.frequency_khz, kFrequencyRange);
    // The physical view the app shows (v_v, v_b, z_ss) must be finite, as for the command line's flags.
    if (const std::string why = units::physical_view_error(s.params, s.amplitude_um, s.frequency_khz);
        !why.empty()) {
        const char* at = why.rfind("rdisp", 0) == 0    ? "/rdisp"
                         : why.rfind("zeta", 0) == 0   ? "/zeta"
                         : j.contains("frequency_khz") ? "/frequency_khz"
                                                       : "/amplitude_um";
        r.fail_at(j.contains(at + 1) ? at : "", why);
    }
    r.get(j, "", "speed", s.speed, kSpeedRange);
    r.get(j, "", "playing", s.playing, nullptr);
    r.get(j, "", "panel", panel, one_of("panel", panel_name_list()));
    s.panel = *panel_from_name(panel);
    // The lesson step on screen (0: none), a whole number up to the app's steps.
    if (j.contains("lesson")) {
        const Json& v = j["lesson"];
        const long long n = static_cast<long long>(lesson_steps().size());
        if (!v.is_number_integer() || v.get<long long>() < 0 || v.get<long long>() > n)
            r.fail_at("/lesson",
                      "lesson = " + shown(v) + "; allowed: 0 (none) or a step " + lesson_range_text());
        s.lesson = v.get<int>();
    }

    if (j.contains("view")) {
        const Json& v = j["view"];
        if (!v.is_object())
            r.fail_at("/view", "view: expected an object {\"zoom\": ..}, got " + type_name(v));
        r.only(v, "/view", {"zoom", "pan", "follow", "trail_periods", "frame", "presentation"});
        r.get(v, "/view", "presentation", s.presentation, nullptr);
        r.get(v, "/view", "zoom", s.view.zoom, kZoomRange);
        r.get(v, "/view", "follow", s.view.follow, nullptr);
        r.get(v, "/view", "trail_periods", s.view.trail_periods, kTrailRange);
        // The top view's frame; a session saved before it could be chosen has none: body, as it was then.
        std::string frame = to_string(s.view.frame);
        r.get(v, "/view", "frame", frame, one_of("frame", {"body", "ground"}));
        s.view.frame = parse_frame(frame).value_or(FrameChoice::body);
        if (v.contains("pan")) {
            const Json& p = v["pan"];
            if (!p.is_array() || p.size() != 2)
                r.fail_at("/view/pan",
                          "pan: expected [x, y], got " + (p.is_array() ? shown(p) : type_name(p)));
            for (int k = 0; k < 2; ++k) {
                const std::string ptr = "/view/pan/" + std::to_string(k);
                s.view.pan[k] = r.number(p[k], ptr, k == 0 ? "pan x" : "pan y", kPanRange);
            }
        }
    }
    if (j.contains("compare") && !j["compare"].is_null()) read_compare(j["compare"], r, s);
    if (j.contains("pins")) s.pins = read_pins(j["pins"], r);
    if (j.contains("data") && !j["data"].is_null()) {
        r.get(j, "", "data", s.data_file, [](const std::string& f) {
            return f.empty() ? std::string("data: an empty path; give a CSV file or null") : std::string();
        });
        const std::filesystem::path p(s.data_file);
        if (p.is_relative())
            s.data_file = (std::filesystem::path(file).parent_path() / p).lexically_normal().string();
    }
    return s;
}

LoadedSession load_session(const std::string& path) {
    std::string text;
    InputLimits limits;
    limits.max_bytes = kMaxSessionBytes;
    if (const std::string why = read_input_file(path, text, limits); !why.empty())
        fail_with(path + ": " + why);
    if (text.size() > kMaxSessionBytes)
        fail_with(path + ": larger than 1 MiB; a session file is a few hundred bytes");
    LoadedSession out{parse_session(text, path), std::nullopt};
    const Session& s = out.session;
    if (!s.data_file.empty()) {
        ReadOptions ro;
        ro.amplitude_um = s.amplitude_um;
        ro.frequency_khz = s.frequency_khz;
        const std::string at = where(path, text, Positions(text).value_at("/data")) + ": data: ";
        try {
            out.data = read_measurements(s.data_file, ro);
        } catch (const DataError& e) {
            fail_with(at + e.what());
        }
        if (out.data->points.empty()) fail_with(at + s.data_file + " has no data rows");
    }
    return out;
}

std::string write_session(const std::string& path, const Session& s) {
    return write_file_atomic(path, session_json(s));
}

} // namespace fv::app
