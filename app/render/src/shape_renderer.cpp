#include "shape_renderer.hpp"

#include <cstddef>

namespace fv::gfx::detail {

ShapeRenderer::ShapeRenderer(const GlApi& gl)
    : gl_(gl), program_(gl, "shapes.vert.glsl", "shapes.frag.glsl") {
    loc_size_ = program_.uniform("u_size");
    loc_fb_height_ = program_.uniform("u_fb_height");
    loc_ratio_ = program_.uniform("u_ratio");
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
    gl_.UseProgram(program_.id());
    gl_.Uniform2f(loc_size_, logical_w, logical_h);
    gl_.Uniform1f(loc_fb_height_, static_cast<float>(fb_height));
    gl_.Uniform1f(loc_ratio_, pixel_ratio);
    gl_.Enable(GL_BLEND);
    gl_.BlendEquation(GL_FUNC_ADD);
    gl_.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    gl_.Disable(GL_DEPTH_TEST);
    gl_.Disable(GL_CULL_FACE);
    gl_.BindVertexArray(vao_);
}

void ShapeRenderer::draw(std::size_t first, std::size_t count) {
    gl_.DrawElements(GL_TRIANGLES, static_cast<GLsizei>(count), GL_UNSIGNED_INT,
                     reinterpret_cast<void*>(first * sizeof(std::uint32_t)));
}

} // namespace fv::gfx::detail
