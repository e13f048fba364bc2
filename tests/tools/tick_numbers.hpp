// The numbers a drawn frame writes (its tick labels), for the tests that hold a loop's axes still.
#pragma once

#include "fv/gfx/display_list.hpp"

#include <cstdlib>
#include <string>
#include <variant>
#include <vector>

namespace fv::test {

// Whether a text is a number as a tick label writes it ("-1.5" with a minus sign, "0", "2.5").
inline bool is_number(std::string t) {
    for (std::size_t at; (at = t.find("\u2212")) != std::string::npos;) t.replace(at, 3, "-");
    if (t.empty()) return false;
    char* end = nullptr;
    std::strtod(t.c_str(), &end);
    return end == t.c_str() + t.size();
}

// Every number written on a frame (the tick labels of all its panels) with where it is written.
inline std::vector<std::string> numbers_on(const gfx::DisplayList& list) {
    std::vector<std::string> out;
    for (const auto& c : list.commands)
        if (const auto* t = std::get_if<gfx::dl::Text>(&c); t && is_number(t->text))
            out.push_back(t->text + " at " + std::to_string(t->anchor.x) + "," + std::to_string(t->anchor.y));
    return out;
}

} // namespace fv::test
