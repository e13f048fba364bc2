// fv::parse_number against the standard library's std::from_chars (libstdc++ here): the same characters
// consumed, the same error, the same value, for hand-picked edge cases and for random strings. The browser
// build has no floating-point std::from_chars and relies on parse_number behaving identically.
#include "fv/parse_number.hpp"

#include <catch2/catch.hpp>

#include <charconv>
#include <cmath>
#include <cstring>
#include <random>
#include <string>

namespace {

void check_same(const std::string& s) {
    const char* first = s.data();
    const char* last = s.data() + s.size();
    double expected = -7.25, got = -7.25; // untouched on failure
    const auto want = std::from_chars(first, last, expected);
    const auto have = fv::parse_number(first, last, got);
    INFO("input '" << s << "'");
    CHECK(have.ptr - first == want.ptr - first);
    CHECK(static_cast<int>(have.ec) == static_cast<int>(want.ec));
    if (std::isnan(expected)) {
        CHECK(std::isnan(got));
    } else {
        CHECK(std::memcmp(&got, &expected, sizeof got) == 0); // bit for bit, -0 included
    }
}

} // namespace

TEST_CASE("parse_number matches std::from_chars on edge cases", "[parse_number]") {
    const char* cases[] = {
        "0",
        "-0",
        "1",
        "-1",
        "+1",
        " 1",
        "1 ",
        "00012",
        "1.5",
        ".5",
        "5.",
        ".",
        "-.",
        "-",
        "",
        "-.e1",
        "e5",
        "1e5",
        "1E5",
        "1e+5",
        "1e-5",
        "1e",
        "1e+",
        "1e-",
        "1.e5",
        ".5e-3",
        "1e5.5",
        "1..2",
        "1,5",
        "1.5x",
        "0x10",
        "0X1p3",
        "inf",
        "INF",
        "-inf",
        "Infinity",
        "infinityx",
        "infin",
        "in",
        "nan",
        "NaN",
        "-nan",
        "nan(abc_9)",
        "nan(",
        "nan()",
        "nan(a b)",
        "nanx",
        "1e400",
        "-1e400",
        "1e-400",
        "4e-320",
        "2.4e-324",
        "2.5e-324",
        "2.4703282292062328e-324",
        "2.4703282292062327e-324",
        "0e-999",
        "0e999",
        "0.0000e400",
        "1.7976931348623157e308",
        "1.7976931348623158e308",
        "1.797693134862315808e308",
        "1e309",
        "2.2250738585072011e-308",
        "2.2250738585072014e-308",
        "0.1",
        "0.30000000000000004",
        "123456789012345678901",
        "9007199254740993",
        "1e-5x",
        "1e400x",
        "--1",
        "-+1",
        "1e++5",
        "1e--5",
        "0.000000000000000000000000001e-300",
        "100000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000e-400"};
    for (const char* c : cases) check_same(c);
}

TEST_CASE("parse_number matches std::from_chars on random strings", "[parse_number]") {
    std::mt19937 rng(20061115);
    const std::string alphabet = "0123456789000111.....eeEE++--infatyINFATY()_ x9";
    std::uniform_int_distribution<std::size_t> pick(0, alphabet.size() - 1), length(0, 14);
    for (int n = 0; n < 200000; ++n) {
        std::string s(length(rng), ' ');
        for (char& c : s) c = alphabet[pick(rng)];
        check_same(s);
    }
    // Plain numbers with long mantissas and extreme exponents: rounding and the range ends.
    std::uniform_int_distribution<int> digit(0, 9), exponent(-340, 320), ndigits(1, 25);
    for (int n = 0; n < 100000; ++n) {
        std::string s = n % 2 ? "-" : "";
        const int k = ndigits(rng);
        for (int d = 0; d < k; ++d) {
            if (d == 1) s += '.';
            s += static_cast<char>('0' + digit(rng));
        }
        s += "e" + std::to_string(exponent(rng));
        check_same(s);
    }
}
