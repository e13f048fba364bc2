#pragma once
// The cairo backend: replays a DisplayList (display_list.hpp) into an SVG or PDF document in memory. The page
// is the list's logical size in points (one logical unit = 1 pt). Shapes and text stay vectors: text is set
// in DejaVu Sans (the font the GL path draws with, loaded through FreeType from the same file), so a PDF
// carries real text with the font subset embedded; only images (a heat map, a colour bar) are images.
// Thread-safe: documents may be made on several threads at once.
#include "fv/gfx/display_list.hpp"
#include "fv/gfx/image.hpp"

#include <string>
#include <vector>

namespace fv::gfx {

enum class VectorFormat { Svg, Pdf };

/// Where the list goes on a printed page, and a caption under it. The default is the list's own page, one
/// logical unit a point, with no caption: the document render_vector made before pages existed, byte for
/// byte.
struct VectorPage {
    Vec2 size{0, 0};   ///< The page in points; {0, 0}: the figure and its caption with `origin` around them.
    Vec2 origin{0, 0}; ///< Where the figure's top-left corner goes, in points.
    float scale = 1;   ///< Points per logical unit of the list.
    std::string caption;     ///< Drawn under the figure, wrapped to its width (UTF-8, no markup).
    float caption_size = 13; ///< The caption's text size in points (line box, as TextStyle::size).
};

/// The document's bytes. Throws std::runtime_error (one line) if cairo or the font fails. An SVG with a
/// caption carries it as text in its <desc> too (its drawn text is glyph outlines).
std::string render_vector(const DisplayList& list, VectorFormat format, const VectorPage& page = {});

/// `caption` wrapped to `width` logical units at `size` units a line box, drawn by cairo in the vector
/// output's font on white, `scale` pixels a unit, with `pad` units of margin around it: the band a PNG's
/// caption takes under the figure.
Image render_caption_image(const std::string& caption, float width, float size, float pad, float scale);

/// `top` with `bottom` under it (as wide as `top`; a narrower one is padded white on the right).
Image stack_images(const Image& top, const Image& bottom);

/// The same replay into an RGBA image of `scale` pixels per logical unit (for tests and comparisons).
Image render_cairo_image(const DisplayList& list, float scale);

} // namespace fv::gfx
