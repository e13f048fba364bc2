#include "fv/gfx/colormap.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace fv::gfx {

Color viridis(double t) {
    static constexpr std::array<std::uint32_t, 9> kKeys = {0x440154, 0x482878, 0x3E4A89, 0x31688E, 0x26828E,
                                                           0x1F9E89, 0x35B779, 0x6DCD59, 0xFDE725};
    if (!std::isfinite(t)) t = 0;
    const double s = std::clamp(t, 0.0, 1.0) * (kKeys.size() - 1);
    const std::size_t i = std::min(static_cast<std::size_t>(s), kKeys.size() - 2);
    const float f = static_cast<float>(s - static_cast<double>(i));
    const Color a = Color::hex(kKeys[i]), b = Color::hex(kKeys[i + 1]);
    return {a.r + (b.r - a.r) * f, a.g + (b.g - a.g) * f, a.b + (b.b - a.b) * f, 1.0f};
}

Image heatmap_image(const double* values, int nx, int ny, double vmin, double vmax) {
    Image img(nx, ny);
    const double span = vmax > vmin ? vmax - vmin : 1.0;
    for (int j = 0; j < ny; ++j) {
        for (int i = 0; i < nx; ++i) {
            const double v = values[static_cast<std::size_t>(j) * static_cast<std::size_t>(nx) + i];
            std::uint8_t* p = img.pixel(i, ny - 1 - j); // Data rows go up, image rows go down.
            if (!std::isfinite(v)) {
                p[0] = p[1] = p[2] = p[3] = 0;
                continue;
            }
            const std::uint32_t c = viridis((v - vmin) / span).packed();
            p[0] = static_cast<std::uint8_t>(c), p[1] = static_cast<std::uint8_t>(c >> 8);
            p[2] = static_cast<std::uint8_t>(c >> 16), p[3] = 255;
        }
    }
    return img;
}

} // namespace fv::gfx
