#include "fv/gfx/fonts.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>

namespace fv::gfx {

const ImWchar* FontSet::glyph_ranges() {
    static const ImWchar ranges[] = {
        0x0020, 0x00FF, // Basic Latin + Latin-1 (°, ±, ·, ×, ²)
        0x0370, 0x03FF, // Greek (ζ, θ, σ, τ, ...)
        0x2010, 0x2044, // dashes, quotes, bullet, ellipsis, primes
        0x2070, 0x209F, // superscripts and subscripts
        0x2190, 0x21FF, // arrows
        0x2200, 0x22FF, // mathematical operators (minus sign U+2212, √, ∞, ≈, ≤)
        0,
    };
    return ranges;
}

FontSet::FontSet(const FontSetOptions& options)
    : atlas_(std::make_unique<ImFontAtlas>()), ratio_(options.pixel_ratio) {
    // ImGui asserts (or returns null) on a missing file; give a clear error instead.
    if (!std::ifstream(options.path, std::ios::binary))
        throw std::runtime_error("font not found: " + options.path + " (Debian: fonts-dejavu-core)");
    if (options.sizes.empty()) throw std::runtime_error("FontSet: no sizes");
    std::vector<float> sizes = options.sizes;
    std::sort(sizes.begin(), sizes.end());
    for (float s : sizes) {
        ImFontConfig cfg;
        // Sub-pixel horizontal positioning keeps proportional text even; from 2 pixels per unit up whole
        // pixels are fine enough, and the atlas (which grows with the square of the ratio) stays within GL
        // limits up to a ratio of 8.
        cfg.OversampleH = ratio_ >= 2 ? 1 : 3;
        cfg.OversampleV = 1;
        cfg.PixelSnapH = false;
        ImFont* f =
            atlas_->AddFontFromFileTTF(options.path.c_str(), std::round(s * ratio_), &cfg, glyph_ranges());
        if (!f) throw std::runtime_error("could not load font " + options.path);
        fonts_.push_back(f);
    }
    if (!atlas_->Build()) throw std::runtime_error("font atlas build failed");
}

FontSet::~FontSet() = default;

ImFont* FontSet::font_for(float size) const {
    const float want = size * ratio_;
    ImFont* best = fonts_.front();
    for (ImFont* f : fonts_) {
        if (std::fabs(f->FontSize - want) <= std::fabs(best->FontSize - want)) best = f;
    }
    return best;
}

} // namespace fv::gfx
