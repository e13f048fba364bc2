#include "port.hpp"

#include "fv/gfx/context.hpp"

#include <cstring>
#include <stdexcept>

namespace fv::gfx {

float GpuContext::pixel_ratio() const {
    const Size fb = framebuffer_size();
    const Size lg = logical_size();
    return lg.width > 0 ? static_cast<float>(fb.width) / static_cast<float>(lg.width) : 1.0f;
}

Image GpuContext::read_pixels() const {
    const Size fb = framebuffer_size();
    Image img(fb.width, fb.height);
    if (img.empty()) return img;
    gl_.Finish();
    gl_.PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl_.ReadPixels(0, 0, fb.width, fb.height, GL_RGBA, GL_UNSIGNED_BYTE, img.rgba.data());
    // glReadPixels returns the bottom row first; Image is top-down.
    const std::size_t row = static_cast<std::size_t>(fb.width) * 4;
    std::vector<std::uint8_t> tmp(row);
    for (int y = 0; y < fb.height / 2; ++y) {
        std::uint8_t* a = img.pixel(0, y);
        std::uint8_t* b = img.pixel(0, fb.height - 1 - y);
        std::memcpy(tmp.data(), a, row);
        std::memcpy(a, b, row);
        std::memcpy(b, tmp.data(), row);
    }
    return img;
}

std::unique_ptr<GpuContext> create_context(const ContextOptions& options) {
    switch (options.backend) {
    case Backend::Window:
        return std::make_unique<WindowContext>(
            WindowOptions{options.width, options.height, options.title, options.visible, true});
    case Backend::Headless:
        break;
    }
    return port::make_headless(options);
}

} // namespace fv::gfx
