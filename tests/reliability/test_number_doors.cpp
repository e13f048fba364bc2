// One list of hostile numbers through every door a number comes in by: a command-line flag (the real
// executable), a share link (which the browser build also reads from its address), a session file, a script
// line and a measured-data file. Each door must take the same numbers, as the same doubles, and refuse the
// same ones, for the same reason. The only allowed difference is JSON's own grammar: a session cannot hold
// "+1", ".5" or "5." (the JSON parser refuses them as syntax before any number is read).
#include "exe_under_test.hpp"
#include "scratch.hpp"

#include "gui/script.hpp"
#include "gui/session.hpp"

#include "fv/measurements.hpp"
#include "fv/share_link.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <sys/wait.h>

using fv::test::Scratch;
using fv::test::slurp;

using fv::test::exe;

namespace {

enum class Why { ok, not_decimal, beyond_double, out_of_range };

struct Hostile {
    std::string text;
    Why why;
    double value;     // when ok
    bool json = true; // a number token in JSON's grammar
};

// Each case says what a careful reader must make of it; none of these verdicts comes from the code.
const Hostile kHostile[] = {
    {"0.3", Why::ok, 0.3},
    {"-0", Why::ok, 0.0},        // -0 is the angle, ratio or exponent 0 (and prints as 0)
    {"5e-324", Why::ok, 5e-324}, // a subnormal is the number it names
    {"1e+1", Why::ok, 10},
    {"1E1", Why::ok, 10},
    {"+1", Why::ok, 1, false}, // a sign people write; not JSON
    {".5", Why::ok, 0.5, false},
    {"5.", Why::ok, 5, false},
    {"0.30000000000000004", Why::ok, 0.30000000000000004},
    {"1e-400", Why::beyond_double, 0}, // underflows to 0: not the number asked for
    {"-1e-400", Why::beyond_double, 0},
    {"1e400", Why::beyond_double, 0}, // overflows
    {"0x10", Why::not_decimal, 0, false},
    {"0x1p3", Why::not_decimal, 0, false},
    {"inf", Why::not_decimal, 0, false},
    {"nan", Why::not_decimal, 0, false},
    {"1e", Why::not_decimal, 0, false},
    {"1_0", Why::not_decimal, 0, false},
    {"--1", Why::not_decimal, 0, false},
    {"\xD9\xA3", Why::not_decimal, 0, false},     // an Arabic-Indic digit three
    {"\xEF\xBC\x91", Why::not_decimal, 0, false}, // a full-width digit one
    {"200", Why::out_of_range, 0},
    {"-0.1", Why::out_of_range, 0},
};

// The phrase a refusal must contain.
const char* phrase(Why w) {
    switch (w) {
    case Why::not_decimal:
        return "is not a decimal number";
    case Why::beyond_double:
        return "is out of range (beyond double precision)";
    case Why::out_of_range:
        return "is out of range; allowed: ";
    case Why::ok:
        break;
    }
    return "";
}

// What a door made of the text: the value, or the refusal's message.
struct Verdict {
    std::optional<double> value;
    std::string message;
};

// The command line: `ratio --model rigid --zeta TEXT` (the rigid model: fast), zeta read back from JSON.
Verdict cli_door(const Scratch& s, const std::string& text) {
    const std::string out = s / "out.json", err = s / "err.txt";
    std::ofstream(s / "arg") << text;
    const std::string cmd = std::string(exe()) +
                            " ratio --model rigid --theta 30 --format json --zeta \"$(cat '" + (s / "arg") +
                            "')\" >'" + out + "' 2>'" + err + "'";
    const int status = std::system(cmd.c_str());
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    if (code != 0) return {std::nullopt, slurp(err) + " (exit " + std::to_string(code) + ")"};
    const std::string json = slurp(out);
    const auto at = json.find("\"zeta\": ");
    REQUIRE(at != std::string::npos);
    return {std::strtod(json.c_str() + at + 8, nullptr), ""};
}

std::string percent_encoded(const std::string& s) {
    std::string out;
    for (unsigned char c : s) {
        char buf[4];
        std::snprintf(buf, sizeof buf, "%%%02X", c);
        out += std::isalnum(c) || c == '.' || c == '-' ? std::string(1, static_cast<char>(c)) : buf;
    }
    return out;
}

Verdict link_door(const std::string& text) {
    try {
        return {fv::parse_share_link("?zeta=" + percent_encoded(text)).zeta, ""};
    } catch (const fv::LinkError& e) {
        return {std::nullopt, e.what()};
    }
}

Verdict session_door(const std::string& text) {
    try {
        return {fv::app::parse_session("{\"version\": 1, \"zeta\": " + text + "}", "s.json").params.zeta, ""};
    } catch (const fv::app::SessionError& e) {
        return {std::nullopt, e.what()};
    }
}

Verdict script_door(const Scratch& s, const std::string& text) {
    std::ofstream(s / "script.txt") << "0 zeta " << text << "\n";
    try {
        const fv::app::Script script = fv::app::load_script(s / "script.txt");
        const fv::app::UiEdits e = fv::app::script_edits(script, 0, fv::app::UiState{});
        REQUIRE(e.params);
        return {e.params->zeta, ""};
    } catch (const std::runtime_error& e) {
        return {std::nullopt, e.what()};
    }
}

Verdict data_door(const std::string& text) {
    try {
        return {fv::parse_measurements("zeta,r_x\n" + text + ",0.5\n", "m.csv").points.at(0).zeta, ""};
    } catch (const fv::DataError& e) {
        return {std::nullopt, e.what()};
    }
}

} // namespace

TEST_CASE("Every door reads numbers one way: CLI, link, session, script and data file agree",
          "[reliability][numbers]") {
    Scratch s;
    for (const Hostile& h : kHostile) {
        const std::vector<std::pair<const char*, Verdict>> doors = {{"command line", cli_door(s, h.text)},
                                                                    {"link", link_door(h.text)},
                                                                    {"session", session_door(h.text)},
                                                                    {"script", script_door(s, h.text)},
                                                                    {"data file", data_door(h.text)}};
        for (const auto& [door, v] : doors) {
            CAPTURE(h.text, door, v.message);
            const bool json_syntax = std::string(door) == "session" && !h.json;
            if (json_syntax) { // refused by JSON's grammar, before any number is read
                CHECK_FALSE(v.value);
                CHECK_THAT(v.message, Catch::Contains("not valid JSON"));
                continue;
            }
            if (h.why == Why::ok) {
                REQUIRE(v.value);
                CHECK(*v.value == h.value);
                CHECK_FALSE(std::signbit(*v.value)); // -0 reads as 0 everywhere
            } else {
                CHECK_FALSE(v.value);
                CHECK_THAT(v.message, Catch::Contains(phrase(h.why)));
                // The same message body (the shared reader's), whatever the door; the CLI names no key.
                if (std::string(door) != "command line")
                    CHECK_THAT(v.message,
                               Catch::Contains("zeta") && Catch::Contains("allowed: zeta in [0, 100]"));
                CHECK(v.message.find('\x1b') == std::string::npos);
            }
        }
    }
}

TEST_CASE("Sizes: --size is read by the shared integer reader: an overflow is refused, never wrapped",
          "[reliability][numbers]") {
    Scratch s;
    s.mkdir("out");
    for (const std::string& cmd :
         {std::string("render --figure fig5 --out out --size "),
          std::string("animate --out out/a.gif --zeta 0.3 --theta 30 --rdisp 2 --i 1 --size "),
          std::string("gui --headless --frames 1 --size ")}) {
        for (const char* size :
             {"4294967616x240", "320x4294967536", "18446744073709551936x240", "0x10x240", "+320x240x"}) {
            const std::string err = s / "err.txt";
            const int status = std::system(
                ("cd '" + s.dir() + "' && " + exe() + " " + cmd + size + " >/dev/null 2>'" + err + "'")
                    .c_str());
            CAPTURE(cmd, size, slurp(err));
            CHECK(WEXITSTATUS(status) == 2);
            CHECK_THAT(slurp(err), Catch::Contains("--size") && Catch::Contains("allowed: WxH"));
        }
        CHECK(s.entries() == std::vector<std::string>{"err.txt", "out"});
        CHECK(std::filesystem::is_empty(s / "out"));
    }
}
