#pragma once
// Internal: GL side of the canvas primitives (shaders/shapes.*.glsl). Each primitive is a quad
// whose four vertices carry the same flat shape parameters; the fragment shader evaluates an SDF.
#include "fv/gfx/gl_api.hpp"
#include "fv/gfx/shader_program.hpp"

#include <cstdint>
#include <vector>

namespace fv::gfx::detail {

enum ShapeKind : int { kSegment = 1, kMarker = 2, kTriangle = 3, kRect = 4 };

struct ShapeVertex {
    float pos[2];
    float a[4];
    float b[4];
    float c[4];
    float d[4]; // d[0] = kind
    std::uint32_t color;
};

class ShapeRenderer {
  public:
    explicit ShapeRenderer(const GlApi& gl);
    ~ShapeRenderer();
    ShapeRenderer(const ShapeRenderer&) = delete;
    ShapeRenderer& operator=(const ShapeRenderer&) = delete;

    /// Uploads all vertices/indices of the frame once.
    void upload(const std::vector<ShapeVertex>& vertices, const std::vector<std::uint32_t>& indices);
    /// Binds program and state for drawing at the given logical size and framebuffer height.
    void bind(float logical_w, float logical_h, float pixel_ratio, int fb_height);
    /// Draws `count` indices starting at `first` (after bind()).
    void draw(std::size_t first, std::size_t count);

  private:
    const GlApi& gl_;
    ShaderProgram program_;
    GLint loc_size_ = -1, loc_fb_height_ = -1, loc_ratio_ = -1;
    GLuint vao_ = 0, vbo_ = 0, ebo_ = 0;
};

} // namespace fv::gfx::detail
