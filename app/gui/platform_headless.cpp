// The headless platform: an OSMesa framebuffer, no input, a fixed 1/60 s per frame (scripted tests,
// screenshots, benchmarks). Same pixels as the window for the same frames.
#include "platform.hpp"

#include <imgui.h>

#include <cfloat>
#include <cmath>

namespace fv::app {
namespace {

class HeadlessPlatform final : public Platform {
  public:
    explicit HeadlessPlatform(const PlatformOptions& o)
        : scale_(o.scale > 0 ? o.scale : 1.0f),
          ctx_(o.width > 0 ? o.width : static_cast<int>(std::lround(1280 * scale_)),
               o.height > 0 ? o.height : static_cast<int>(std::lround(800 * scale_)), scale_) {}

    std::string_view name() const override { return "headless"; }
    gfx::GpuContext& context() override { return ctx_; }
    float pixel_ratio() const override { return scale_; }
    bool interactive() const override { return false; }
    void connect_imgui() override {}
    void disconnect_imgui() override {}
    PlatformEvents poll() override { return {}; }
    void imgui_new_frame(gfx::Vec2 logical) override {
        ImGuiIO& io = ImGui::GetIO();
        io.DisplaySize = ImVec2(logical.x, logical.y);
        io.DisplayFramebufferScale = ImVec2(scale_, scale_);
        io.DeltaTime = 1.0f / 60;
        io.MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
    }
    void present() override { ctx_.present(); }

  private:
    float scale_;
    gfx::HeadlessContext ctx_;
};

} // namespace

std::unique_ptr<Platform> make_headless_platform(const PlatformOptions& options) {
    return std::make_unique<HeadlessPlatform>(options);
}

} // namespace fv::app
