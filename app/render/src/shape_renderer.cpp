#include "shape_renderer.hpp"

#include <cstddef>
#include <string>

namespace fv::gfx::detail {

ShapeRenderer::ShapeRenderer(const GlApi& gl) : gl_(gl) {
    for (int k = 0; k < kShapeKindCount; ++k) {
        Program& p = programs_[k];
        const std::string defines = "#define KIND " + std::to_string(k + 1) + "\n";
        p.program = std::make_unique<ShaderProgram>(gl, "shapes.vert.glsl", "shapes.frag.glsl", defines);
        p.loc_size = p.program->uniform("u_size");
        p.loc_fb_height = p.program->uniform("u_fb_height");
        p.loc_ratio = p.program->uniform("u_ratio");
    }
    gl_.GenVertexArrays(1, &vao_);
    gl_.GenBuffers(1, &vbo_);
    gl_.GenBuffers(1, &ebo_);
    gl_.BindVertexArray(vao_);
    gl_.BindBuffer(GL_ARRAY_BUFFER, vbo_);
    gl_.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo_);
    const auto stride = static_cast<GLsizei>(sizeof(ShapeVertex));
    auto attrib = [&](GLuint loc, GLint n, GLenum type, GLboolean norm, std::size_t off) {
        gl_.EnableVertexAttribArray(loc);
        gl_.VertexAttribPointer(loc, n, type, norm, stride, reinterpret_cast<void*>(off));
    };
    attrib(0, 2, GL_FLOAT, GL_FALSE, offsetof(ShapeVertex, pos));
    attrib(1, 4, GL_FLOAT, GL_FALSE, offsetof(ShapeVertex, a));
    attrib(2, 4, GL_FLOAT, GL_FALSE, offsetof(ShapeVertex, b));
    attrib(3, 4, GL_FLOAT, GL_FALSE, offsetof(ShapeVertex, c));
    attrib(4, 4, GL_FLOAT, GL_FALSE, offsetof(ShapeVertex, d));
    attrib(5, 4, GL_UNSIGNED_BYTE, GL_TRUE, offsetof(ShapeVertex, color));
    gl_.BindVertexArray(0);
}

ShapeRenderer::~ShapeRenderer() {
    gl_.DeleteBuffers(1, &ebo_);
    gl_.DeleteBuffers(1, &vbo_);
    gl_.DeleteVertexArrays(1, &vao_);
}

void ShapeRenderer::upload(const std::vector<ShapeVertex>& vertices,
                           const std::vector<std::uint32_t>& indices) {
    gl_.BindVertexArray(vao_);
    gl_.BindBuffer(GL_ARRAY_BUFFER, vbo_);
    gl_.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(ShapeVertex)),
                   vertices.data(), GL_STREAM_DRAW);
    gl_.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo_);
    gl_.BufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * sizeof(std::uint32_t)),
                   indices.data(), GL_STREAM_DRAW);
    gl_.BindVertexArray(0);
}

void ShapeRenderer::bind(float logical_w, float logical_h, float pixel_ratio, int fb_height) {
    size_[0] = logical_w, size_[1] = logical_h, ratio_ = pixel_ratio,
    fb_height_ = static_cast<float>(fb_height);
    gl_.Enable(GL_BLEND);
    gl_.BlendEquation(GL_FUNC_ADD);
    gl_.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    gl_.Disable(GL_DEPTH_TEST);
    gl_.Disable(GL_CULL_FACE);
    gl_.BindVertexArray(vao_);
}

void ShapeRenderer::draw(ShapeKind kind, std::size_t first, std::size_t count) {
    const Program& p = programs_[kind - 1];
    gl_.UseProgram(p.program->id());
    gl_.Uniform2f(p.loc_size, size_[0], size_[1]);
    gl_.Uniform1f(p.loc_fb_height, fb_height_);
    gl_.Uniform1f(p.loc_ratio, ratio_);
    gl_.DrawElements(GL_TRIANGLES, static_cast<GLsizei>(count), GL_UNSIGNED_INT,
                     reinterpret_cast<void*>(first * sizeof(std::uint32_t)));
}

} // namespace fv::gfx::detail
