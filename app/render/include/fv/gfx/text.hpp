#pragma once
// Text layout on top of the FontSet: alignment, rotation, measurement, and a tiny markup for
// sub/superscripts: "r_{disp}" draws "disp" smaller and lowered, "10^{-3}" raises "-3".
// A bare '_' or '^' (not followed by '{') is literal. Single line only.
#include "fv/gfx/fonts.hpp"
#include "fv/gfx/types.hpp"

#include <string_view>

struct ImDrawList;

namespace fv::gfx {

enum class HAlign { Left, Center, Right };
/// Middle centres the capital-letter height (looks centred for digits and capitals).
enum class VAlign { Top, Middle, Baseline, Bottom };

struct TextStyle {
    float size = 14; ///< Logical pixels (line height).
    Color color = colors::text;
    HAlign halign = HAlign::Left;
    VAlign valign = VAlign::Top;
    float angle_deg = 0; ///< Counter-clockwise on screen; 90 reads bottom-to-top (y-axis titles).
    bool markup = true;  ///< Interpret _{..} and ^{..}.
};

/// Width and height (line box) of the text when drawn unrotated, in logical pixels.
Vec2 measure_text(const FontSet& fonts, std::string_view text, float size, bool markup = true);

/// Appends glyph quads to `list` (which must have the atlas texture pushed), anchored at `anchor`.
void emit_text(ImDrawList& list, const FontSet& fonts, Vec2 anchor, std::string_view text,
               const TextStyle& style);

} // namespace fv::gfx
