// The window platform: a GLFW window (its GL context lives in the render layer, gfx::WindowContext) with
// Dear ImGui's GLFW input backend (platform_glfw.hpp, shared with the web platform).
#include "platform_glfw.hpp"

#include <cmath>

namespace fv::app {
namespace {

gfx::WindowOptions window_options(const PlatformOptions& o) {
    gfx::WindowOptions w;
    w.title = o.title;
    if (o.width > 0 || o.scale > 0) {
        // A size or scale given: the framebuffer in pixels is what was asked for (window units are pixels
        // on X11), so that --size/--scale mean the same picture as headless.
        const float s = o.scale > 0 ? o.scale : 1.0f;
        w.width = o.width > 0 ? o.width : static_cast<int>(std::lround(1280 * s));
        w.height = o.height > 0 ? o.height : static_cast<int>(std::lround(800 * s));
        w.scale_to_monitor = false;
    }
    return w;
}

class WindowPlatform final : public GlfwPlatform {
  public:
    explicit WindowPlatform(const PlatformOptions& o) : GlfwPlatform(window_options(o)), scale_(o.scale) {}

    std::string_view name() const override { return "window"; }
    // Given: as asked. Else the monitor's content scale (2 on a HiDPI screen, also on X11 where the window
    // is counted in pixels).
    float pixel_ratio() const override { return scale_ > 0 ? scale_ : ctx_.content_scale(); }
    void present() override { ctx_.present(); }

  private:
    float scale_;
};

} // namespace

std::unique_ptr<Platform> make_window_platform(const PlatformOptions& options) {
    return std::make_unique<WindowPlatform>(options);
}

} // namespace fv::app
