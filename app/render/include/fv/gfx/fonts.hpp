#pragma once
// Font atlas (Dear ImGui 1.86) with DejaVu Sans at a few sizes, including Greek, super/subscript
// digits and the minus sign. The same atlas can be shared with the app's ImGui context.
#include <memory>
#include <string>
#include <vector>

struct ImFont;
struct ImFontAtlas;
using ImWchar = unsigned short;

namespace fv::gfx {

struct FontSetOptions {
    std::string path = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
    std::vector<float> sizes = {10, 12, 13, 14, 16, 18, 22, 28}; ///< Logical pixel sizes to rasterise.
    float pixel_ratio = 1.0f; ///< Glyphs are rasterised at size*ratio so HiDPI text stays crisp.
};

class FontSet {
  public:
    /// Loads and builds the atlas (CPU only; upload with ImGuiRenderer::upload_font_atlas).
    /// Throws std::runtime_error if the font file can't be read.
    explicit FontSet(const FontSetOptions& options = {});
    ~FontSet();
    FontSet(const FontSet&) = delete;
    FontSet& operator=(const FontSet&) = delete;

    ImFontAtlas& atlas() { return *atlas_; }
    const ImFontAtlas& atlas() const { return *atlas_; }
    /// Font to draw at `size` logical px: the closest rasterised size (ties: the larger one).
    ImFont* font_for(float size) const;
    float pixel_ratio() const { return ratio_; }

    /// Latin-1, Greek, punctuation, super/subscripts (U+2070..209F), arrows, math operators (minus U+2212,
    /// √).
    static const ImWchar* glyph_ranges();

  private:
    std::unique_ptr<ImFontAtlas> atlas_;
    std::vector<ImFont*> fonts_; // Sorted by size.
    float ratio_;
};

} // namespace fv::gfx
