#pragma once
// The cairo backend: replays a DisplayList (display_list.hpp) into an SVG or PDF document in memory. The page
// is the list's logical size in points (one logical unit = 1 pt). Shapes and text stay vectors: text is set
// in DejaVu Sans (the font the GL path draws with, loaded through FreeType from the same file), so a PDF
// carries real text with the font subset embedded; only images (a heat map, a colour bar) are images.
// Thread-safe: documents may be made on several threads at once.
#include "fv/gfx/display_list.hpp"
#include "fv/gfx/image.hpp"

#include <string>

namespace fv::gfx {

enum class VectorFormat { Svg, Pdf };

/// The document's bytes. Throws std::runtime_error (one line) if cairo or the font fails.
std::string render_vector(const DisplayList& list, VectorFormat format);

/// The same replay into an RGBA image of `scale` pixels per logical unit (for tests and comparisons).
Image render_cairo_image(const DisplayList& list, float scale);

} // namespace fv::gfx
