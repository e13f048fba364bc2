#include "fv/printable_text.hpp"

#include <cstdio>

namespace fv {
namespace {

// The length of the UTF-8 sequence at s[k] if it is a valid, printable one (not a C1 control, not an
// overlong form or a surrogate), else 0.
std::size_t utf8_char(std::string_view s, std::size_t k) {
    const auto b = [&](std::size_t n) { return static_cast<unsigned char>(s[k + n]); };
    const unsigned char c = b(0);
    std::size_t len = 0;
    unsigned cp = 0;
    if (c >= 0x20 && c < 0x7f) return 1;
    if (c >= 0xC2 && c <= 0xDF)
        len = 2, cp = c & 0x1Fu;
    else if (c >= 0xE0 && c <= 0xEF)
        len = 3, cp = c & 0x0Fu;
    else if (c >= 0xF0 && c <= 0xF4)
        len = 4, cp = c & 0x07u;
    else
        return 0;
    if (k + len > s.size()) return 0;
    for (std::size_t n = 1; n < len; ++n) {
        if ((b(n) & 0xC0) != 0x80) return 0;
        cp = (cp << 6) | (b(n) & 0x3Fu);
    }
    const bool overlong = (len == 3 && cp < 0x800) || (len == 4 && cp < 0x10000);
    if (overlong || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF) || (cp >= 0x80 && cp <= 0x9F)) return 0;
    return len;
}

std::string escaped(std::string_view s, std::size_t max_bytes, bool quote) {
    std::string out;
    std::size_t k = 0;
    while (k < s.size() && k < max_bytes) {
        const std::size_t len = utf8_char(s, k);
        if (len > 0 && k + len > max_bytes) break; // a character is cut off whole, never in half
        if (len > 0 && !(quote && s[k] == '\'')) {
            out.append(s.substr(k, len));
            k += len;
            continue;
        }
        char buf[8];
        std::snprintf(buf, sizeof buf, "\\x%02X", static_cast<unsigned char>(s[k]));
        out += buf;
        ++k;
    }
    if (k < s.size()) out += "... (" + std::to_string(s.size()) + " bytes)";
    return out;
}

} // namespace

std::string printable_text(std::string_view s, std::size_t max_bytes) {
    return escaped(s, max_bytes, false);
}

std::string quoted_text(std::string_view s, std::size_t max_bytes) {
    return "'" + escaped(s, max_bytes, true) + "'";
}

std::string text_error(std::string_view s, std::size_t max_bytes) {
    const std::string allowed =
        "; allowed: printable text of at most " + std::to_string(max_bytes) + " bytes";
    if (s.size() > max_bytes) return std::to_string(s.size()) + " bytes" + allowed;
    for (std::size_t k = 0; k < s.size();) {
        const std::size_t len = utf8_char(s, k);
        if (len == 0) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\x%02X", static_cast<unsigned char>(s[k]));
            return std::string("a control or non-UTF-8 byte ") + buf + " at byte " + std::to_string(k + 1) +
                   allowed;
        }
        k += len;
    }
    return {};
}

} // namespace fv
