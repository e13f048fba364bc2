// Checks on a recorded display list that the layout tests share: what would make a picture hard to read
// (text on text, a label on an arrow, a marker or the body's outline, an arrow along another or hidden under
// a marker, text outside its panel). Each returns a description of the first problem, or "" when none.
#pragma once

#include "fv/gfx/display_list.hpp"
#include "fv/gfx/fonts.hpp"

#include <cstddef>
#include <string>

namespace fv::test {

// The first pair of texts in `list` whose boxes overlap by more than `slack` units each way.
std::string overlapping_texts(const gfx::DisplayList& list, const gfx::FontSet& fonts, float slack);

// The first label in a data region of `list` (a point's, an arrow's or a segment's name) that lies on an
// arrow or a marker drawn there (its own included: labels sit beside what they name); with `outlines`, also
// one on a closed rectangle drawn there (the top view's body outline).
std::string label_on_shape(const gfx::DisplayList& list, const gfx::FontSet& fonts, bool outlines = false);

// The first pair of arrows in `list` of which one runs along the other (more than a third of its shaft
// within the two shafts' half widths plus a pixel of the other's): one would hide the other.
std::string arrow_on_arrow(const gfx::DisplayList& list);

// The first arrow in `list` hidden under the markers drawn after it in its data region: less than
// `min_visible` units of it outside them, or its head's tip under one.
std::string hidden_arrow(const gfx::DisplayList& list, float min_visible);

// The first text among commands [first, last) of `list` whose box leaves `bounds` by more than 1 unit.
std::string text_outside(const gfx::DisplayList& list, const gfx::FontSet& fonts, std::size_t first,
                         std::size_t last, const gfx::Rect& bounds);

} // namespace fv::test
