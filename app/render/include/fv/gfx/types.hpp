#pragma once
// Basic value types of the render layer: points, rectangles (pixels, top-left origin) and colours.
#include <cstdint>

namespace fv::gfx {

struct Vec2 {
    float x = 0, y = 0;
};
inline Vec2 operator+(Vec2 a, Vec2 b) {
    return {a.x + b.x, a.y + b.y};
}
inline Vec2 operator-(Vec2 a, Vec2 b) {
    return {a.x - b.x, a.y - b.y};
}
inline Vec2 operator*(Vec2 a, float s) {
    return {a.x * s, a.y * s};
}

/// Axis-aligned rectangle [x0,x1) x [y0,y1) in logical pixels, y down.
struct Rect {
    float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    float width() const { return x1 - x0; }
    float height() const { return y1 - y0; }
    bool contains(Vec2 p) const { return p.x >= x0 && p.x <= x1 && p.y >= y0 && p.y <= y1; }
    bool overlaps(const Rect& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
    Rect inset(float d) const { return {x0 + d, y0 + d, x1 - d, y1 - d}; }
};

/// Straight (non-premultiplied) RGBA colour, components in [0,1].
struct Color {
    float r = 0, g = 0, b = 0, a = 1;

    /// From 0xRRGGBB and an alpha.
    static constexpr Color hex(std::uint32_t rgb, float alpha = 1.0f) {
        return {static_cast<float>((rgb >> 16) & 0xFF) / 255.0f,
                static_cast<float>((rgb >> 8) & 0xFF) / 255.0f, static_cast<float>(rgb & 0xFF) / 255.0f,
                alpha};
    }
    constexpr Color with_alpha(float alpha) const { return {r, g, b, alpha}; }
    /// Packed as bytes R,G,B,A in memory (same layout as ImGui's IM_COL32).
    std::uint32_t packed() const;
};

namespace colors {
constexpr Color black = Color::hex(0x000000);
constexpr Color white = Color::hex(0xFFFFFF);
constexpr Color axis = Color::hex(0x202020);
constexpr Color text = Color::hex(0x101010);
constexpr Color grid = Color::hex(0xDCDCDC);
constexpr Color minor_grid = Color::hex(0xEFEFEF);
} // namespace colors

} // namespace fv::gfx
