#include "fv/gfx/ticks.hpp"

#include <catch2/catch.hpp>

using namespace fv::gfx;

static const std::string kMinus = "\xE2\x88\x92";

TEST_CASE("nice steps are 1, 2 or 5 times a power of ten") {
    CHECK(nice_step(1.0, 5) == Approx(0.2));
    CHECK(nice_step(3.0, 6) == Approx(0.5));
    CHECK(nice_step(100.0, 10) == Approx(10));
    CHECK(nice_step(0.0, 5) == 1.0); // Degenerate: no throw, a usable step.
}

TEST_CASE("linear tick labels are exact decimals with a Unicode minus") {
    const auto ticks = linear_ticks(-0.3, 0.35, 6);
    std::vector<std::string> labels;
    for (const auto& t : ticks) labels.push_back(t.label);
    CHECK(labels ==
          std::vector<std::string>{kMinus + "0.3", kMinus + "0.2", kMinus + "0.1", "0", "0.1", "0.2", "0.3"});
}

TEST_CASE("tick formatting avoids -0 and float noise") {
    CHECK(format_tick(0.1 + 0.2, 0.1) == "0.3");
    CHECK(format_tick(-1e-17, 0.1) == "0");
    CHECK(format_tick(2.5, 0.5) == "2.5");
    CHECK(format_tick(1500, 500) == "1500");
    CHECK(format_tick(2e5, 1e5) == "2\xC3\x97"
                                   "10^{5}");
    CHECK(format_tick(1e-4, 1e-4) == "10^{" + kMinus + "4}");
}

TEST_CASE("linear ticks: at least two in the range") {
    // The nice step for 2 ticks over [-1.45, 1.45] is 2: only 0 lay inside (fig4 at 640x400).
    const auto t = linear_ticks(-1.45, 1.45, 2);
    REQUIRE(t.size() >= 2);
    CHECK(t.front().value >= -1.45);
    CHECK(t.back().value <= 1.45);
    CHECK(linear_ticks(0, 1, 2).size() == 3); // 0, 0.5, 1 as before
    CHECK(linear_ticks(0.3, 0.31, 1).size() >= 2);
}

TEST_CASE("log ticks sit on decades with unlabelled minor ticks") {
    const auto ticks = log_ticks(0.05, 200, 6);
    std::vector<std::string> major;
    int minor = 0;
    for (const auto& t : ticks) {
        if (t.major)
            major.push_back(t.label);
        else
            ++minor;
    }
    CHECK(major == std::vector<std::string>{"0.1", "1", "10", "100"});
    CHECK(minor > 10);
}
