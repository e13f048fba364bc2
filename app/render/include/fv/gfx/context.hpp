#pragma once
// GL contexts. The backend (headless OSMesa or GLFW window) is chosen in one place,
// create_context(); everything that draws only sees GpuContext and its GlApi.
#include "fv/gfx/gl_api.hpp"
#include "fv/gfx/image.hpp"

#include <memory>
#include <string>
#include <vector>

struct GLFWwindow;

namespace fv::gfx {

enum class Backend { Headless, Window };

struct ContextOptions {
    Backend backend = Backend::Headless;
    int width = 1280; ///< Headless: framebuffer pixels. Window: window size in screen units.
    int height = 800;
    std::string title = "frictionviz"; ///< Window only.
    bool visible = true;               ///< Window only.
    /// Headless only: framebuffer pixels per logical unit (device pixel ratio); the logical page is
    /// width/scale x height/scale. A window takes its ratio from the screen.
    float scale = 1.0f;
};

struct Size {
    int width = 0;
    int height = 0;
};

/// A current GL 3.3+ core context with a default framebuffer to draw into.
class GpuContext {
  public:
    virtual ~GpuContext() = default;
    GpuContext(const GpuContext&) = delete;
    GpuContext& operator=(const GpuContext&) = delete;

    const GlApi& gl() const { return gl_; }
    /// Size of the framebuffer in pixels (what glViewport and readback use).
    virtual Size framebuffer_size() const = 0;
    /// Size in logical units (window size; equals the framebuffer size headless).
    virtual Size logical_size() const = 0;
    /// Framebuffer pixels per logical unit (2 on a HiDPI screen; headless: ContextOptions::scale).
    virtual float pixel_ratio() const;
    virtual void make_current() = 0;
    /// Ends a frame: swaps buffers in a window, glFinish headless.
    virtual void present() = 0;
    /// Reads the current draw framebuffer (before present()) as RGBA8, rows top-down.
    Image read_pixels() const;
    /// One line: backend and GL version/renderer.
    virtual std::string describe() const = 0;

  protected:
    GpuContext() = default;
    GlApi gl_;
};

/// OSMesa (llvmpipe) core-profile 3.3 context rendering into a memory buffer.
/// Throws std::runtime_error with a one-line message if libOSMesa can't be loaded or the context can't be
/// made.
class HeadlessContext final : public GpuContext {
  public:
    HeadlessContext(int width, int height, float scale = 1.0f);
    ~HeadlessContext() override;
    Size framebuffer_size() const override { return {width_, height_}; }
    /// Rounded; the exact logical page is framebuffer_size() / pixel_ratio().
    Size logical_size() const override;
    float pixel_ratio() const override { return scale_; }
    void make_current() override;
    void present() override;
    std::string describe() const override;

  private:
    /// Creates the frame's framebuffer object and binds it; false where OSMesa cannot (nothing changed).
    bool draw_into_framebuffer_object();

    struct Impl;
    std::unique_ptr<Impl> impl_;
    int width_;
    int height_;
    float scale_;
};

struct WindowOptions {
    int width = 1280, height = 800; ///< Window size in screen units (see scale_to_monitor).
    std::string title = "frictionviz";
    bool visible = true;
    /// true: the size is in logical units, grown by the monitor's content scale (GLFW_SCALE_TO_MONITOR);
    /// false: exactly the size asked (pixels on X11).
    bool scale_to_monitor = true;
};

/// GLFW 3.3 window with a core forward-compatible 3.3 context. HiDPI aware: the framebuffer may
/// be larger than the window. Throws std::runtime_error if there is no display or no context.
class WindowContext final : public GpuContext {
  public:
    explicit WindowContext(const WindowOptions& options);
    ~WindowContext() override;
    Size framebuffer_size() const override;
    Size logical_size() const override;
    void make_current() override;
    void present() override;
    std::string describe() const override;

    /// The monitor's content scale (glfwGetWindowContentScale, x): 2 on a HiDPI screen, 1 under Xvfb.
    float content_scale() const;
    bool should_close() const;
    void poll_events();
    GLFWwindow* native() const { return window_; } ///< For the ImGui GLFW input backend.

    /// Paths of files dropped onto the window since the last call (GLFW's drop callback collects them
    /// during poll_events()), oldest first.
    std::vector<std::string> take_dropped_paths();

  private:
    GLFWwindow* window_ = nullptr;
    std::vector<std::string> dropped_;
};

/// The one place that picks a backend.
std::unique_ptr<GpuContext> create_context(const ContextOptions& options);

} // namespace fv::gfx
