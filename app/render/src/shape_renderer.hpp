#pragma once
// Internal: GL side of the canvas primitives (shaders/shapes.*.glsl). Each primitive is a quad
// whose four vertices carry the same flat shape parameters; the fragment shader evaluates an SDF.
// One program per primitive kind (see the comment in shapes.frag.glsl for why).
#include "fv/gfx/gl_api.hpp"
#include "fv/gfx/shader_program.hpp"

#include <cstdint>
#include <memory>
#include <vector>

namespace fv::gfx::detail {

// kFlat: the inside of a large translucent fill, where the SDF's coverage is 1 anyway (no SDF at all).
enum ShapeKind : int { kSegment = 1, kMarker = 2, kTriangle = 3, kRect = 4, kSolidSegment = 5, kFlat = 6 };
constexpr int kShapeKindCount = 6;

struct ShapeVertex {
    float pos[2];
    float a[4];
    float b[4];
    float c[4];
    float d[4]; // d[0] = kind (informative; the program decides)
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
    /// Sets blend state and the VAO for drawing at the given logical size and framebuffer height.
    void bind(float logical_w, float logical_h, float pixel_ratio, int fb_height);
    /// Draws `count` indices starting at `first` with the program of `kind` (after bind()).
    void draw(ShapeKind kind, std::size_t first, std::size_t count);

  private:
    struct Program {
        std::unique_ptr<ShaderProgram> program;
        GLint loc_size = -1, loc_fb_height = -1, loc_ratio = -1;
    };
    const GlApi& gl_;
    Program programs_[kShapeKindCount];
    float size_[2] = {0, 0}, ratio_ = 1, fb_height_ = 0;
    GLuint vao_ = 0, vbo_ = 0, ebo_ = 0;
};

} // namespace fv::gfx::detail
