#include "fv/parse_number.hpp"

#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>

namespace fv {

namespace {

bool is_digit(char c) {
    return c >= '0' && c <= '9';
}

char lower(char c) {
    return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c;
}

// [p, last) starts with `word` (lower case), letters compared without case.
bool starts_with_word(const char* p, const char* last, const char* word) {
    for (; *word != '\0'; ++p, ++word) {
        if (p == last || lower(*p) != *word) return false;
    }
    return true;
}

} // namespace

ParseNumberResult parse_number(const char* first, const char* last, double& value) {
    const char* p = first;
    const bool negative = p != last && *p == '-';
    if (negative) ++p;

    // Infinity and NaN by name.
    if (starts_with_word(p, last, "inf")) {
        p += starts_with_word(p, last, "infinity") ? 8 : 3;
        value = negative ? -std::numeric_limits<double>::infinity() : std::numeric_limits<double>::infinity();
        return {p, std::errc()};
    }
    if (starts_with_word(p, last, "nan")) {
        p += 3;
        if (p != last && *p == '(') {
            const char* q = p + 1;
            while (q != last && (is_digit(*q) || (lower(*q) >= 'a' && lower(*q) <= 'z') || *q == '_')) ++q;
            if (q != last && *q == ')') p = q + 1;
        }
        const double nan = std::numeric_limits<double>::quiet_NaN();
        value = negative ? -nan : nan;
        return {p, std::errc()};
    }

    // Mantissa: digits with an optional point, at least one digit.
    const char* const mantissa = p;
    bool nonzero = false;
    std::size_t digits = 0;
    for (; p != last && is_digit(*p); ++p, ++digits) nonzero = nonzero || *p != '0';
    if (p != last && *p == '.') {
        ++p;
        for (; p != last && is_digit(*p); ++p, ++digits) nonzero = nonzero || *p != '0';
    }
    if (digits == 0) return {first, std::errc::invalid_argument};
    // Exponent: consumed only when it has a digit.
    if (p != last && (*p == 'e' || *p == 'E')) {
        const char* q = p + 1;
        if (q != last && (*q == '+' || *q == '-')) ++q;
        if (q != last && is_digit(*q)) {
            while (q != last && is_digit(*q)) ++q;
            p = q;
        }
    }

    // The matched text is plain decimal notation, which strtod rounds correctly in every C library this
    // builds with (glibc, musl); its decimal point is '.' in the "C" locale, which the program never changes.
    const std::string text(mantissa, p);
    const double magnitude = std::strtod(text.c_str(), nullptr);
    if (std::isinf(magnitude) || (magnitude == 0 && nonzero)) return {p, std::errc::result_out_of_range};
    value = negative ? -magnitude : magnitude;
    return {p, std::errc()};
}

} // namespace fv
