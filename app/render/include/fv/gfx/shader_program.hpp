#pragma once
// Small RAII wrapper around a linked GL program built from two embedded shader files.
#include "fv/gfx/gl_api.hpp"

#include <string_view>

namespace fv::gfx {

class ShaderProgram {
  public:
    /// Compiles and links; throws std::runtime_error with the GL info log on failure.
    /// `fragment_defines` (e.g. "#define KIND 2\n") is inserted after the fragment shader's #version line.
    ShaderProgram(const GlApi& gl, std::string_view vertex_file, std::string_view fragment_file,
                  std::string_view fragment_defines = {});
    ~ShaderProgram();
    ShaderProgram(const ShaderProgram&) = delete;
    ShaderProgram& operator=(const ShaderProgram&) = delete;

    GLuint id() const { return id_; }
    GLint uniform(const char* name) const { return gl_.GetUniformLocation(id_, name); }

  private:
    const GlApi& gl_;
    GLuint id_ = 0;
};

} // namespace fv::gfx
