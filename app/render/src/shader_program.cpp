#include "fv/gfx/shader_program.hpp"

#include "fv/gfx/embedded_shaders.hpp"

#include <stdexcept>
#include <string>
#include <vector>

namespace fv::gfx {
namespace {

GLuint compile(const GlApi& gl, GLenum type, std::string_view file, std::string_view defines) {
    // The GLSL ES 3.00 twin of each source is embedded under "es300/" (cmake/embed_files.cmake).
    std::string src(gl.glsl == GlslDialect::es300 ? shader_source("es300/" + std::string(file))
                                                  : shader_source(file));
    if (!defines.empty()) {
        const std::size_t eol = src.find('\n'); // #version must stay the first line.
        src.insert(eol == std::string::npos ? src.size() : eol + 1, defines);
    }
    const GLchar* ptr = src.data();
    const GLint len = static_cast<GLint>(src.size());
    GLuint sh = gl.CreateShader(type);
    gl.ShaderSource(sh, 1, &ptr, &len);
    gl.CompileShader(sh);
    GLint ok = 0;
    gl.GetShaderiv(sh, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        std::vector<GLchar> log(4096);
        gl.GetShaderInfoLog(sh, static_cast<GLsizei>(log.size()), nullptr, log.data());
        gl.DeleteShader(sh);
        throw std::runtime_error("compiling " + std::string(file) + ": " + log.data());
    }
    return sh;
}

} // namespace

ShaderProgram::ShaderProgram(const GlApi& gl, std::string_view vertex_file, std::string_view fragment_file,
                             std::string_view fragment_defines)
    : gl_(gl) {
    GLuint vs = compile(gl, GL_VERTEX_SHADER, vertex_file, {});
    GLuint fs = compile(gl, GL_FRAGMENT_SHADER, fragment_file, fragment_defines);
    id_ = gl.CreateProgram();
    gl.AttachShader(id_, vs);
    gl.AttachShader(id_, fs);
    gl.LinkProgram(id_);
    gl.DeleteShader(vs); // Flagged for deletion; freed with the program.
    gl.DeleteShader(fs);
    GLint ok = 0;
    gl.GetProgramiv(id_, GL_LINK_STATUS, &ok);
    if (!ok) {
        std::vector<GLchar> log(4096);
        gl.GetProgramInfoLog(id_, static_cast<GLsizei>(log.size()), nullptr, log.data());
        gl.DeleteProgram(id_);
        throw std::runtime_error("linking " + std::string(vertex_file) + "+" + std::string(fragment_file) +
                                 ": " + log.data());
    }
}

ShaderProgram::~ShaderProgram() {
    gl_.DeleteProgram(id_);
}

} // namespace fv::gfx
