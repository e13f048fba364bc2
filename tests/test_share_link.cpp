// The share link (fv/share_link.hpp): the query the app shows, `gui --link` takes and the browser build
// reads. Accepted forms, every refusal with its column, and the round trip app state -> link -> state.
#include "fv/param_ranges.hpp"
#include "fv/share_link.hpp"

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>

using namespace fv;

namespace {

// The message of the LinkError `text` raises ("" when it parses).
std::string refusal(const std::string& text) {
    try {
        parse_share_link(text);
    } catch (const LinkError& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST_CASE("share link: the query alone, with '?', or inside a URL, any subset of the keys", "[link]") {
    for (const std::string text :
         {"zeta=0.3&theta=60&rdisp=5&i=1&model=dahl", "?zeta=0.3&theta=60&rdisp=5&i=1&model=dahl",
          "https://example.org/frictionviz/index.html?zeta=0.3&theta=60&rdisp=5&i=1&model=dahl#top",
          "?model=dahl&i=1&rdisp=5&theta=60&zeta=0.3", "?zeta=3e-1&theta=6%30&rdisp=5.0&i=1e0&model=%64ahl",
          "?zeta=0.3&theta=60&rdisp=0.5e1&i=1&model=dahl"}) {
        INFO(text);
        const ShareLink l = parse_share_link(text);
        CHECK(l.zeta == 0.3);
        CHECK(l.theta_deg == 60.0);
        CHECK(l.rdisp == 5.0);
        CHECK(l.i == 1.0);
        CHECK(l.model == Model::dahl);
    }
    // Missing keys keep what they are; '+' is a plus sign (an exponent's), not a space; -0 is 0.
    const ShareLink l = parse_share_link("?zeta=1e+1&model=rigid&theta=-0");
    CHECK(l.zeta == 10.0);
    CHECK_FALSE(l.rdisp);
    CHECK_FALSE(l.i);
    CHECK(l.model == Model::rigid);
    CHECK_FALSE(std::signbit(*l.theta_deg));
    Model m = Model::dahl;
    Params p{0.15, kPi / 2, 2, 1};
    apply_share_link(l, m, p);
    CHECK(m == Model::rigid);
    CHECK(p.zeta == 10.0);
    CHECK(p.theta == 0.0);
    CHECK(p.rdisp == 2.0);
    CHECK(p.i == 1.0);
}

TEST_CASE("share link: unknown key, bad number, out of range, duplicate key and malformed items are refused "
          "with the column and what is allowed",
          "[link]") {
    struct Case {
        const char* text;
        const char* message;
    };
    for (const Case& c : {
             Case{"?zeta=0.3&thetta=60",
                  "column 11: unknown key 'thetta'; allowed: zeta, theta, rdisp, i, model, start, frame, "
                  "amplitude, frequency, panel, present, speed, play, trail, zoom, pan, follow, pins, "
                  "lesson, compare"},
             Case{"?zeta=abc", "column 7: zeta = 'abc' is not a decimal number; allowed: zeta in [0, 100]"},
             Case{"?zeta=0x10", "column 7: zeta = '0x10' is not a decimal number; allowed: zeta in [0, 100]"},
             Case{"?zeta=inf", "column 7: zeta = 'inf' is not a decimal number; allowed: zeta in [0, 100]"},
             Case{"?zeta=nan", "column 7: zeta = 'nan' is not a decimal number; allowed: zeta in [0, 100]"},
             Case{"?zeta=", "column 7: zeta is empty; allowed: zeta in [0, 100]"},
             Case{"?zeta= 1", "column 7: zeta = ' 1' is not a decimal number; allowed: zeta in [0, 100]"},
             Case{"?zeta=1x", "column 7: zeta = '1x' is not a decimal number; allowed: zeta in [0, 100]"},
             Case{"?zeta=++1", "column 7: zeta = '++1' is not a decimal number; allowed: zeta in [0, 100]"},
             Case{"?zeta=1e400", "column 7: zeta = 1e400 is out of range (beyond double precision); allowed: "
                                 "zeta in [0, 100]"},
             Case{"?zeta=200", "column 7: zeta = 200 is out of range; allowed: zeta in [0, 100]"},
             Case{"?zeta=-1", "column 7: zeta = -1 is out of range; allowed: zeta in [0, 100]"},
             Case{"?theta=181", "column 8: theta = 181 is out of range; allowed: theta in [0, 180]"},
             Case{"?rdisp=0", "column 8: rdisp = 0 is out of range; allowed: rdisp in (0, 10000]"},
             Case{"?i=11", "column 4: i = 11 is out of range; allowed: i in [0, 10]"},
             Case{"?model=coulomb", "column 8: model = 'coulomb'; allowed: dahl, rigid"},
             Case{"?start=moving", "column 8: start = 'moving'; allowed: rest, sliding"},
             Case{"?start=", "column 8: start = ''; allowed: rest, sliding"},
             Case{"?start=rest&start=sliding", "column 13: 'start' is given twice; each key at most once"},
             Case{"?frame=floor", "column 8: frame = 'floor'; allowed: body, ground"},
             Case{"?frame=body&frame=ground", "column 13: 'frame' is given twice; each key at most once"},
             Case{"?zeta=1&i=1&zeta=2", "column 13: 'zeta' is given twice; each key at most once"},
             Case{"?model=dahl&model=dahl", "column 13: 'model' is given twice; each key at most once"},
             Case{"?zeta=1&&i=1", "column 9: empty item (a stray '&'); expected KEY=VALUE"},
             Case{"?zeta=1&", "column 9: empty item (a stray '&'); expected KEY=VALUE"},
             Case{"?zeta", "column 2: 'zeta' has no value; expected KEY=VALUE"},
             Case{"?zeta=%2", "column 7: '%' must start an escape %XX (two hex digits)"},
             Case{"?zeta=1%zz", "column 8: '%' must start an escape %XX (two hex digits)"},
             Case{"", "column 1: no parameters; expected KEY=VALUE pairs joined by '&'"},
             Case{"?ze%0Ata=1", "column 2: unknown key 'ze\\x0Ata'; allowed:"},
             Case{"?model=da%0D%0Ahl", "column 8: model = 'da\\x0D\\x0Ahl'; allowed: dahl, rigid"},
             Case{"https://example.org/?#zeta=1", "column 22: no parameters"},
         }) {
        INFO(c.text);
        const std::string why = refusal(c.text);
        CHECK(why.rfind(c.message, 0) == 0);
        CHECK(why.find('\n') == std::string::npos);
    }
    // The ranges are the shared table's.
    CHECK(refusal("?zeta=" + std::to_string(kZetaRange.hi)).empty());
    CHECK(refusal("?rdisp=" + std::to_string(kRdispRange.hi * 1.001)).find(describe(kRdispRange)) !=
          std::string::npos);
}

TEST_CASE("share link: the app's link reads back as the same parameters, bit for bit", "[link]") {
    CHECK(share_link(Model::dahl, Params{0.3, 60 * kPi / 180, 5, 1}) ==
          "?zeta=0.3&theta=60&rdisp=5&i=1&model=dahl");
    CHECK(share_link(Model::rigid, Params{0.15, kPi / 2, 2, 0}) ==
          "?zeta=0.15&theta=90&rdisp=2&i=0&model=rigid");
    // Every whole degree comes back as itself, in the link as in radians.
    for (int d = 0; d <= 180; ++d) {
        INFO(d);
        CHECK(theta_degrees(d * kPi / 180) == d);
    }
    std::mt19937_64 rng(14);
    std::uniform_real_distribution<double> zeta(0, 3), theta(0, kPi), logr(-1, 4), i(0, 10);
    for (int k = 0; k < 20000; ++k) {
        const Params p{zeta(rng), theta(rng), std::pow(10.0, logr(rng)), i(rng)};
        const Model m = k % 2 ? Model::rigid : Model::dahl;
        const std::string link = share_link(m, p);
        INFO(link);
        Model m2 = Model::dahl;
        Params q{};
        apply_share_link(parse_share_link(link), m2, q);
        REQUIRE(m2 == m);
        REQUIRE(q.zeta == p.zeta);
        REQUIRE(q.rdisp == p.rdisp);
        REQUIRE(q.i == p.i);
        // Degrees to radians rounds; where no double of degrees maps back exactly, one ulp is the most.
        REQUIRE(std::abs(q.theta - p.theta) <= std::nextafter(p.theta, 4.0) - p.theta);
    }
}

TEST_CASE("share link: the start goes through the link, and a link from rest has no start key", "[link]") {
    const Params p{0.075, kPi / 2, 0.1, 5};
    const std::string sliding = share_link(Model::dahl, p, Start::sliding);
    CHECK(sliding == "?zeta=0.075&theta=90&rdisp=0.1&i=5&model=dahl&start=sliding");
    Model m = Model::rigid;
    Params q{0.15, 0, 2, 1};
    Start start = Start::rest;
    apply_share_link(parse_share_link(sliding), m, q, start);
    CHECK(start == Start::sliding);
    CHECK(m == Model::dahl);
    CHECK(q.zeta == p.zeta);
    CHECK(q.theta == p.theta);
    CHECK(q.rdisp == p.rdisp);
    CHECK(q.i == p.i);
    // The paper's start is the default: its link is the one written before the start could be chosen.
    const std::string rest = share_link(Model::dahl, p, Start::rest);
    CHECK(rest == "?zeta=0.075&theta=90&rdisp=0.1&i=5&model=dahl");
    CHECK(rest == share_link(Model::dahl, p));
    CHECK(rest.find("start") == std::string::npos);
    // start=rest is read as well; a link without the key keeps the start it is applied over.
    apply_share_link(parse_share_link("?start=rest&zeta=0.2"), m, q, start);
    CHECK(start == Start::rest);
    CHECK_FALSE(parse_share_link(rest).start.has_value());
    start = Start::sliding;
    apply_share_link(parse_share_link(rest), m, q, start);
    CHECK(start == Start::sliding);
    // The three-argument form reads the parameters alone.
    Model m3 = Model::rigid;
    Params q3{};
    apply_share_link(parse_share_link(sliding), m3, q3);
    CHECK(m3 == Model::dahl);
    CHECK(q3.zeta == p.zeta);
}

TEST_CASE("shortest_decimal: the shortest text strtod reads back exactly, no '+' in it", "[link]") {
    CHECK(shortest_decimal(60) == "60");
    CHECK(shortest_decimal(0.15) == "0.15");
    CHECK(shortest_decimal(0.1 + 0.2) == "0.30000000000000004");
    CHECK(shortest_decimal(1e-7) == "1e-07");
    CHECK(shortest_decimal(1e20) == "1e20");
    CHECK(shortest_decimal(-0.0) == "0");
    CHECK(shortest_decimal(5e-324) == "5e-324");
    std::mt19937_64 rng(6);
    for (int k = 0; k < 100000; ++k) {
        const std::uint64_t bits = rng();
        double v;
        std::memcpy(&v, &bits, sizeof v);
        if (!std::isfinite(v)) continue;
        const std::string s = shortest_decimal(v);
        INFO(s);
        REQUIRE(std::strtod(s.c_str(), nullptr) == (v == 0 ? 0.0 : v));
        REQUIRE(s.find('+') == std::string::npos);
        REQUIRE(s.size() <= 24);
    }
}

TEST_CASE("share link: damaged links are refused with one line, never anything else", "[link]") {
    const std::string good = "https://example.org/app?zeta=0.3&theta=60&rdisp=5&i=1&model=dahl#x";
    const std::string alphabet = "?&=#%0aA9.eE+-zetahrdispmolgic\n\r ";
    std::mt19937 rng(2006);
    for (int k = 0; k < 50000; ++k) {
        std::string t = good;
        for (int e = 0, n = 1 + static_cast<int>(rng() % 4); e < n && !t.empty(); ++e) {
            const std::size_t at = rng() % t.size();
            if (rng() % 2)
                t[at] = alphabet[rng() % alphabet.size()];
            else
                t.erase(at, 1 + rng() % 6);
        }
        try {
            parse_share_link(t);
        } catch (const LinkError& e) {
            const std::string w = e.what();
            INFO(t << " -> " << w);
            REQUIRE(w.rfind("column ", 0) == 0);
            REQUIRE(w.find_first_of("\r\n") == std::string::npos);
        }
    }
}

TEST_CASE("share link: the ground frame goes through the link, and a body-frame link has no frame key",
          "[link]") {
    const Params p{0.3, 0, 2, 0};
    const std::string ground = share_link(Model::dahl, p, Start::rest, FrameChoice::ground);
    CHECK(ground == "?zeta=0.3&theta=0&rdisp=2&i=0&model=dahl&frame=ground");
    CHECK(share_link(Model::dahl, p, Start::sliding, FrameChoice::ground) ==
          "?zeta=0.3&theta=0&rdisp=2&i=0&model=dahl&start=sliding&frame=ground");
    Model m = Model::rigid;
    Params q{};
    Start start = Start::rest;
    FrameChoice frame = FrameChoice::body;
    apply_share_link(parse_share_link(ground), m, q, start, frame);
    CHECK(frame == FrameChoice::ground);
    CHECK(start == Start::rest);
    CHECK(q.zeta == p.zeta);
    // The body frame is the default: its link is the one written before the frame could be chosen, and a
    // link without the key keeps the frame it is applied over.
    const std::string body = share_link(Model::dahl, p, Start::rest, FrameChoice::body);
    CHECK(body == share_link(Model::dahl, p));
    CHECK(body.find("frame") == std::string::npos);
    apply_share_link(parse_share_link(body), m, q, start, frame);
    CHECK(frame == FrameChoice::ground);
    apply_share_link(parse_share_link("?frame=body"), m, q, start, frame);
    CHECK(frame == FrameChoice::body);
}

TEST_CASE("share link: the view's keys (panel, presentation, speed, pins) read back as written", "[link]") {
    ShareLink view;
    view.panel = LowerPanel::map;
    view.presentation = true;
    view.speed = 1.0 / 3; // no short decimal: written as the shortest that reads back
    view.pins = std::vector<PinSource>{{Model::dahl, 60 * kPi / 180, 2, 1, Start::rest},
                                       {Model::rigid, 30 * kPi / 180, 1, 1, Start::rest},
                                       {Model::dahl, kPi / 2, 0.1, 5, Start::sliding}};
    const std::string keys = view_link_keys(view);
    CHECK(keys ==
          "&panel=map&present=1&speed=0.3333333333333333&pins=dahl:60:2:1,rigid:30,dahl:90:0.1:5:sliding");
    const ShareLink l = parse_share_link(share_link(Model::dahl, Params{0.3, kPi / 3, 5, 1}) + keys);
    CHECK(l.notices.empty());
    CHECK(l.zeta == 0.3);
    CHECK(l.panel == LowerPanel::map);
    CHECK(l.presentation == true);
    CHECK(l.speed == 1.0 / 3);
    REQUIRE(l.pins);
    REQUIRE(l.pins->size() == 3);
    for (std::size_t k = 0; k < 3; ++k) {
        const PinSource &a = (*view.pins)[k], &b = (*l.pins)[k];
        INFO(k);
        CHECK(a.model == b.model);
        CHECK(a.theta == b.theta);
        if (a.model == Model::dahl) { // the rigid curve depends on theta alone: the link carries nothing else
            CHECK(a.rdisp == b.rdisp);
            CHECK(a.i == b.i);
            CHECK(a.start == b.start);
        }
    }
    // Every panel, and presentation off, by name.
    for (LowerPanel p : kLowerPanels)
        CHECK(parse_share_link(std::string("?panel=") + panel_name(p)).panel == p);
    CHECK(parse_share_link("?present=0").presentation == false);
    // Random pins come back bit for bit (theta within the one ulp degrees to radians may cost).
    std::mt19937_64 rng(23);
    std::uniform_real_distribution<double> theta(0, kPi), logr(-1, 4), i(0, 10), speed(0.05, 10);
    for (int k = 0; k < 2000; ++k) {
        ShareLink v;
        v.speed = speed(rng);
        std::vector<PinSource> pins;
        for (std::size_t n = 0; n <= k % kMaxPins; ++n)
            pins.push_back({n % 3 ? Model::dahl : Model::rigid, theta(rng), std::pow(10.0, logr(rng)), i(rng),
                            n % 2 ? Start::sliding : Start::rest});
        v.pins = pins;
        const std::string keys2 = view_link_keys(v);
        INFO(keys2);
        REQUIRE(keys2.size() < 1 + kMaxPinsText + 40); // bounded: the longest pins value fits the limit
        const ShareLink r = parse_share_link("?model=dahl" + keys2);
        REQUIRE(r.notices.empty());
        REQUIRE(r.speed == v.speed);
        REQUIRE(r.pins->size() == pins.size());
        for (std::size_t n = 0; n < pins.size(); ++n) {
            REQUIRE(std::abs((*r.pins)[n].theta - pins[n].theta) <=
                    std::nextafter(pins[n].theta, 4.0) - pins[n].theta);
            if (pins[n].model == Model::rigid) continue;
            REQUIRE((*r.pins)[n].rdisp == pins[n].rdisp);
            REQUIRE((*r.pins)[n].i == pins[n].i);
            REQUIRE((*r.pins)[n].start == pins[n].start);
        }
    }
}

TEST_CASE("share link: old links read as before, with no view keys and nothing noted", "[link]") {
    for (const std::string text :
         {"?zeta=0.3&theta=60&rdisp=5&i=1&model=dahl",
          "?zeta=0.075&theta=90&rdisp=0.1&i=5&model=dahl&start=sliding", "?zeta=0.5"}) {
        INFO(text);
        const ShareLink l = parse_share_link(text);
        CHECK_FALSE(l.panel);
        CHECK_FALSE(l.presentation);
        CHECK_FALSE(l.speed);
        CHECK_FALSE(l.pins);
        CHECK(l.notices.empty());
    }
    // A view with nothing set writes nothing: the app's link of a default view is the five keys.
    CHECK(view_link_keys(ShareLink{}).empty());
    ShareLink none;
    none.pins = std::vector<PinSource>{};
    CHECK(view_link_keys(none).empty());
}

TEST_CASE(
    "share link: a view value that does not read is ignored with a notice, the rest of the link applied",
    "[link]") {
    struct Case {
        std::string text, notice;
    };
    const std::string long_pins(kMaxPinsText + 1, '1');
    for (const Case& c : {
             Case{"?zeta=0.4&panel=graph",
                  "column 17: panel = 'graph'; allowed: curves, map, loop, why, setup; ignored"},
             Case{"?zeta=0.4&present=yes", "column 19: present = 'yes'; allowed: 1, 0; ignored"},
             Case{"?zeta=0.4&speed=100",
                  "column 17: speed = 100 is out of range; allowed: speed in [0.05, 10]; "
                  "ignored"},
             Case{"?zeta=0.4&speed=fast",
                  "column 17: speed = 'fast' is not a decimal number; allowed: speed in [0.05, 10]; ignored"},
             Case{"?zeta=0.4&pins=",
                  "column 16: pins is empty; expected MODEL:THETA[:RDISP:I[:START]] joined by "
                  "','; ignored"},
             Case{"?zeta=0.4&pins=dahl:60", "column 16: pin 1 ('dahl:60'): a Dahl pin is "
                                            "dahl:THETA:RDISP:I[:START]; ignored"},
             Case{"?zeta=0.4&pins=rigid:30,rigid:30:2", "column 16: pin 2 ('rigid:30:2'): a rigid pin is "
                                                        "rigid:THETA; ignored"},
             Case{"?zeta=0.4&pins=coulomb:30",
                  "column 16: pin 1 ('coulomb:30'): model 'coulomb'; allowed: dahl, "
                  "rigid; ignored"},
             Case{"?zeta=0.4&pins=dahl:400:2:1",
                  "column 16: pin 1 ('dahl:400:2:1'): theta = 400 is out of range; "
                  "allowed: theta in [0, 180]; ignored"},
             Case{"?zeta=0.4&pins=dahl:60:2:1:later",
                  "column 16: pin 1 ('dahl:60:2:1:later'): start 'later'; "
                  "allowed: rest, sliding; ignored"},
             Case{"?zeta=0.4&pins=rigid:1,rigid:2,rigid:3,rigid:4,rigid:5,rigid:6,rigid:7",
                  "column 16: 7 pins; allowed: at most 6; ignored"},
             Case{"?zeta=0.4&pins=" + long_pins,
                  "column 16: pins is 601 characters long; allowed: at most 600; "
                  "ignored"},
         }) {
        INFO(c.text);
        ShareLink l;
        REQUIRE_NOTHROW(l = parse_share_link(c.text));
        CHECK(l.zeta == 0.4);
        REQUIRE(l.notices.size() == 1);
        CHECK(l.notices[0] == c.notice);
        CHECK_FALSE(l.panel);
        CHECK_FALSE(l.presentation);
        CHECK_FALSE(l.speed);
        CHECK_FALSE(l.pins);
    }
    // A view key given twice is a damaged link like any other key given twice, ignored value or not.
    CHECK(refusal("?panel=map&panel=loop") == "column 12: 'panel' is given twice; each key at most once");
    CHECK(refusal("?panel=graph&panel=loop") == "column 14: 'panel' is given twice; each key at most once");
}

TEST_CASE("share link: lesson=N within the reader's steps, else ignored with a notice naming them",
          "[link]") {
    // Read with 8 steps (the app passes its lessons.json's count; see app::parse_link).
    const ShareLink l = parse_share_link("?lesson=3", 8);
    CHECK(l.lesson == 3);
    CHECK(l.notices.empty());
    CHECK(parse_share_link("?lesson=8", 8).lesson == 8);
    CHECK(parse_share_link("?lesson=1", 8).lesson == 1);
    ShareLink v;
    v.lesson = 3;
    v.panel = LowerPanel::why;
    CHECK(view_link_keys(v) == "&panel=why&lesson=3"); // the last view key
    CHECK(parse_share_link("?model=dahl" + view_link_keys(v), 8).lesson == 3);
    struct Case {
        std::string text;
        int steps;
        std::string notice;
    };
    for (const Case& c : {
             Case{"?zeta=0.4&lesson=99", 8,
                  "column 18: lesson = 99 is out of range; allowed: lesson in [1, 8]; "
                  "ignored"},
             Case{"?zeta=0.4&lesson=0", 8,
                  "column 18: lesson = 0 is out of range; allowed: lesson in [1, 8]; "
                  "ignored"},
             Case{"?zeta=0.4&lesson=x", 8,
                  "column 18: lesson = 'x' is not an integer; allowed: lesson in [1, 8]; "
                  "ignored"},
             Case{"?zeta=0.4&lesson=2.5", 8,
                  "column 18: lesson = '2.5' is not an integer; allowed: lesson in [1, 8]; ignored"},
             Case{"?zeta=0.4&lesson=", 8,
                  "column 18: lesson = '' is not an integer; allowed: lesson in [1, 8]; "
                  "ignored"},
             Case{"?zeta=0.4&lesson=3", 0, "column 18: lesson = '3': this reader has no lessons; ignored"},
         }) {
        INFO(c.text);
        ShareLink r;
        REQUIRE_NOTHROW(r = parse_share_link(c.text, c.steps));
        CHECK(r.zeta == 0.4); // the rest of the link applies
        CHECK_FALSE(r.lesson);
        REQUIRE(r.notices.size() == 1);
        CHECK(r.notices[0] == c.notice);
    }
    CHECK(refusal("?lesson=2&lesson=3") == "column 11: 'lesson' is given twice; each key at most once");
}

TEST_CASE(
    "share link: the vibration (amplitude, frequency) and the rest of the view (play, trail, zoom, pan, "
    "follow) read back as written",
    "[link]") {
    ShareLink v;
    v.amplitude_um = 1;
    v.frequency_khz = 40;
    v.playing = false;
    v.trail_periods = 3;
    v.zoom = 2;
    v.pan = std::array<double, 2>{0.5, -1};
    v.follow = false;
    // The order of share_link.hpp, each key once; short enough to paste.
    CHECK(view_link_keys(v) == "&amplitude=1&frequency=40&play=0&trail=3&zoom=2&pan=0.5,-1&follow=0");
    const ShareLink l = parse_share_link("?zeta=0.3" + view_link_keys(v));
    CHECK(l.notices.empty());
    CHECK(l.zeta == 0.3);
    CHECK(l.amplitude_um == 1.0);
    CHECK(l.frequency_khz == 40.0);
    CHECK(l.playing == false);
    CHECK(l.trail_periods == 3.0);
    CHECK(l.zoom == 2.0);
    REQUIRE(l.pan);
    CHECK((*l.pan)[0] == 0.5);
    CHECK((*l.pan)[1] == -1.0);
    CHECK(l.follow == false);
    // The other value of each flag, and the ends of each range (the shared table's), as a user types them.
    const ShareLink on = parse_share_link("?play=1&follow=1");
    CHECK(on.playing == true);
    CHECK(on.follow == true);
    const ShareLink ends = parse_share_link("?amplitude=1e6&frequency=1e-3&trail=0.1&zoom=20&pan=-1e6,1e6");
    CHECK(ends.notices.empty());
    CHECK(ends.amplitude_um == kAmplitudeRange.hi);
    CHECK(ends.trail_periods == kTrailRange.lo);
    CHECK(ends.zoom == kZoomRange.hi);
    CHECK((*ends.pan)[0] == kPanRange.lo);
    CHECK((*ends.pan)[1] == kPanRange.hi);
    // Random values inside the ranges come back bit for bit.
    std::mt19937_64 rng(2323);
    std::uniform_real_distribution<double> loga(-3, 6), trail(kTrailRange.lo, kTrailRange.hi),
        zoom(kZoomRange.lo, kZoomRange.hi), pan(-50, 50);
    for (int k = 0; k < 2000; ++k) {
        ShareLink w;
        w.amplitude_um = std::pow(10.0, loga(rng));
        w.frequency_khz = std::pow(10.0, loga(rng));
        w.trail_periods = trail(rng);
        w.zoom = zoom(rng);
        w.pan = std::array<double, 2>{pan(rng), pan(rng)};
        w.playing = k % 2 == 0;
        w.follow = k % 3 == 0;
        const std::string keys = view_link_keys(w);
        INFO(keys);
        const ShareLink r = parse_share_link("?model=dahl" + keys);
        REQUIRE(r.notices.empty());
        REQUIRE(r.amplitude_um == w.amplitude_um);
        REQUIRE(r.frequency_khz == w.frequency_khz);
        REQUIRE(r.trail_periods == w.trail_periods);
        REQUIRE(r.zoom == w.zoom);
        REQUIRE(r.pan == w.pan);
        REQUIRE(r.playing == w.playing);
        REQUIRE(r.follow == w.follow);
    }
    // Old links have none of them.
    const ShareLink old = parse_share_link("?zeta=0.3&theta=60&rdisp=5&i=1&model=dahl");
    CHECK_FALSE(old.amplitude_um);
    CHECK_FALSE(old.frequency_khz);
    CHECK_FALSE(old.playing);
    CHECK_FALSE(old.trail_periods);
    CHECK_FALSE(old.zoom);
    CHECK_FALSE(old.pan);
    CHECK_FALSE(old.follow);
}

TEST_CASE("share link: a bad amplitude or frequency is refused naming the key and its range (as --amplitude "
          "and --frequency), a bad view value is ignored with a notice naming them",
          "[link]") {
    // The vibration is the setup's (what v_b and z_ss are, how measured data convert): an error.
    const std::string a = describe(kAmplitudeRange), f = describe(kFrequencyRange);
    struct Refused {
        std::string text, message;
    };
    for (const Refused& c : {
             Refused{"?zeta=0.3&amplitude=0",
                     "column 21: amplitude = 0 is out of range; allowed: amplitude in " + a},
             Refused{"?zeta=0.3&amplitude=-1",
                     "column 21: amplitude = -1 is out of range; allowed: amplitude in " + a},
             Refused{"?zeta=0.3&amplitude=2e6",
                     "column 21: amplitude = 2e6 is out of range; allowed: amplitude in " + a},
             Refused{"?zeta=0.3&frequency=0",
                     "column 21: frequency = 0 is out of range; allowed: frequency in " + f},
             Refused{"?zeta=0.3&frequency=fast",
                     "column 21: frequency = 'fast' is not a decimal number; allowed: frequency in " + f},
             Refused{"?amplitude=1&amplitude=2",
                     "column 14: 'amplitude' is given twice; each key at most once"},
             Refused{"?b.amplitude=1", "column 2: unknown key 'b.amplitude'; allowed:"},
             Refused{"?zoom=2&zoom=3", "column 9: 'zoom' is given twice; each key at most once"},
         }) {
        INFO(c.text);
        const std::string why = refusal(c.text);
        CHECK(why.rfind(c.message, 0) == 0);
        CHECK(why.find('\n') == std::string::npos);
    }
    // The view's values: how the setup is shown, so the link still opens (as speed=100 does).
    struct Noted {
        std::string text, notice;
    };
    for (const Noted& c : {
             Noted{"?zeta=0.4&play=2", "column 16: play = '2'; allowed: 1, 0; ignored"},
             Noted{"?zeta=0.4&follow=yes", "column 18: follow = 'yes'; allowed: 1, 0; ignored"},
             Noted{"?zeta=0.4&trail=20", "column 17: trail = 20 is out of range; allowed: trail in " +
                                             describe(kTrailRange) + "; ignored"},
             Noted{"?zeta=0.4&zoom=0", "column 16: zoom = 0 is out of range; allowed: zoom in " +
                                           describe(kZoomRange) + "; ignored"},
             Noted{"?zeta=0.4&zoom=big",
                   "column 16: zoom = 'big' is not a decimal number; allowed: zoom in " +
                       describe(kZoomRange) + "; ignored"},
             Noted{"?zeta=0.4&pan=1",
                   "column 15: pan = '1'; expected X,Y (two numbers joined by ','); ignored"},
             Noted{"?zeta=0.4&pan=1,2,3",
                   "column 15: pan = '1,2,3'; expected X,Y (two numbers joined by ','); ignored"},
             Noted{"?zeta=0.4&pan=0,2e6", "column 15: pan y = 2e6 is out of range; allowed: pan y in " +
                                              describe(kPanRange) + "; ignored"},
             Noted{"?zeta=0.4&pan=x,0", "column 15: pan x = 'x' is not a decimal number; allowed: pan x in " +
                                            describe(kPanRange) + "; ignored"},
         }) {
        INFO(c.text);
        ShareLink l;
        REQUIRE_NOTHROW(l = parse_share_link(c.text));
        CHECK(l.zeta == 0.4);
        REQUIRE(l.notices.size() == 1);
        CHECK(l.notices[0] == c.notice);
        CHECK_FALSE(l.playing);
        CHECK_FALSE(l.follow);
        CHECK_FALSE(l.trail_periods);
        CHECK_FALSE(l.zoom);
        CHECK_FALSE(l.pan);
    }
}
