#pragma once
// GL function table. Nothing in fvrender calls gl* symbols directly: headless mode resolves
// entry points from a dlopen'ed OSMesa, a window from GLFW. Linking libGL and libOSMesa
// together clashes (both export every gl* symbol), so the table is the only way in.
// The browser build fills the same table from emscripten's WebGL 2 library (src/port_web.cpp): WebGL 2 is
// OpenGL ES 3.0, whose headers declare the same calls and PFN types as desktop GL's glcorearb.h.
#if defined(__EMSCRIPTEN__)
#include <GLES3/gl3.h>
#else
#include <GL/glcorearb.h>
#endif

#include <string>

namespace fv::gfx {

/// Signature of OSMesaGetProcAddress / glfwGetProcAddress, adapted to return void*.
using ProcLoader = void* (*)(const char* name);

/// The GLSL the shaders are compiled as. The sources (shaders/*.glsl) are `#version 330 core`; the build
/// embeds each also as `#version 300 es` with default precisions (app/render/cmake/embed_files.cmake).
enum class GlslDialect {
    glsl330, ///< desktop OpenGL 3.3 core and later
    es300,   ///< OpenGL ES 3.0 / WebGL 2 (the browser build); desktop GL 4.3+ accepts it too
};

/// glDrawElementsBaseVertex (GL 3.2; not in GLES 3.0 or WebGL 2).
#if defined(__EMSCRIPTEN__)
using PfnDrawElementsBaseVertex = void (*)(GLenum mode, GLsizei count, GLenum type, const void* indices,
                                           GLint basevertex);
#else
using PfnDrawElementsBaseVertex = PFNGLDRAWELEMENTSBASEVERTEXPROC;
#endif

// X-macro list: (PFN type, member name, GL symbol). Add here when a new call is needed.
#define FV_GL_FUNCTIONS(X)                                                                                   \
    X(PFNGLGETSTRINGPROC, GetString, glGetString)                                                            \
    X(PFNGLGETERRORPROC, GetError, glGetError)                                                               \
    X(PFNGLGETINTEGERVPROC, GetIntegerv, glGetIntegerv)                                                      \
    X(PFNGLCLEARPROC, Clear, glClear)                                                                        \
    X(PFNGLCLEARCOLORPROC, ClearColor, glClearColor)                                                         \
    X(PFNGLVIEWPORTPROC, Viewport, glViewport)                                                               \
    X(PFNGLSCISSORPROC, Scissor, glScissor)                                                                  \
    X(PFNGLENABLEPROC, Enable, glEnable)                                                                     \
    X(PFNGLDISABLEPROC, Disable, glDisable)                                                                  \
    X(PFNGLBLENDEQUATIONPROC, BlendEquation, glBlendEquation)                                                \
    X(PFNGLBLENDFUNCSEPARATEPROC, BlendFuncSeparate, glBlendFuncSeparate)                                    \
    X(PFNGLPIXELSTOREIPROC, PixelStorei, glPixelStorei)                                                      \
    X(PFNGLREADPIXELSPROC, ReadPixels, glReadPixels)                                                         \
    X(PFNGLFINISHPROC, Finish, glFinish)                                                                     \
    X(PFNGLCREATESHADERPROC, CreateShader, glCreateShader)                                                   \
    X(PFNGLSHADERSOURCEPROC, ShaderSource, glShaderSource)                                                   \
    X(PFNGLCOMPILESHADERPROC, CompileShader, glCompileShader)                                                \
    X(PFNGLGETSHADERIVPROC, GetShaderiv, glGetShaderiv)                                                      \
    X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog, glGetShaderInfoLog)                                       \
    X(PFNGLDELETESHADERPROC, DeleteShader, glDeleteShader)                                                   \
    X(PFNGLCREATEPROGRAMPROC, CreateProgram, glCreateProgram)                                                \
    X(PFNGLATTACHSHADERPROC, AttachShader, glAttachShader)                                                   \
    X(PFNGLLINKPROGRAMPROC, LinkProgram, glLinkProgram)                                                      \
    X(PFNGLGETPROGRAMIVPROC, GetProgramiv, glGetProgramiv)                                                   \
    X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog, glGetProgramInfoLog)                                    \
    X(PFNGLDELETEPROGRAMPROC, DeleteProgram, glDeleteProgram)                                                \
    X(PFNGLUSEPROGRAMPROC, UseProgram, glUseProgram)                                                         \
    X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation, glGetUniformLocation)                                 \
    X(PFNGLUNIFORM1IPROC, Uniform1i, glUniform1i)                                                            \
    X(PFNGLUNIFORM1FPROC, Uniform1f, glUniform1f)                                                            \
    X(PFNGLUNIFORM2FPROC, Uniform2f, glUniform2f)                                                            \
    X(PFNGLUNIFORMMATRIX4FVPROC, UniformMatrix4fv, glUniformMatrix4fv)                                       \
    X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays, glGenVertexArrays)                                          \
    X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays, glDeleteVertexArrays)                                 \
    X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray, glBindVertexArray)                                          \
    X(PFNGLGENBUFFERSPROC, GenBuffers, glGenBuffers)                                                         \
    X(PFNGLDELETEBUFFERSPROC, DeleteBuffers, glDeleteBuffers)                                                \
    X(PFNGLBINDBUFFERPROC, BindBuffer, glBindBuffer)                                                         \
    X(PFNGLBUFFERDATAPROC, BufferData, glBufferData)                                                         \
    X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer, glVertexAttribPointer)                              \
    X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray, glEnableVertexAttribArray)                  \
    X(PFNGLGENTEXTURESPROC, GenTextures, glGenTextures)                                                      \
    X(PFNGLDELETETEXTURESPROC, DeleteTextures, glDeleteTextures)                                             \
    X(PFNGLBINDTEXTUREPROC, BindTexture, glBindTexture)                                                      \
    X(PFNGLACTIVETEXTUREPROC, ActiveTexture, glActiveTexture)                                                \
    X(PFNGLTEXIMAGE2DPROC, TexImage2D, glTexImage2D)                                                         \
    X(PFNGLTEXPARAMETERIPROC, TexParameteri, glTexParameteri)                                                \
    X(PFNGLDRAWELEMENTSPROC, DrawElements, glDrawElements)

/// Table of GL entry points for one context. Members are named like the GL call without "gl".
struct GlApi {
#define FV_GL_MEMBER(type, member, symbol) type member = nullptr;
    FV_GL_FUNCTIONS(FV_GL_MEMBER)
#undef FV_GL_MEMBER
    /// Optional: null where the context has no glDrawElementsBaseVertex (WebGL 2); the ImGui renderer then
    /// points its vertex attributes at the base vertex instead.
    PfnDrawElementsBaseVertex DrawElementsBaseVertex = nullptr;

#if defined(__EMSCRIPTEN__)
    GlslDialect glsl = GlslDialect::es300;
#else
    GlslDialect glsl = GlslDialect::glsl330;
#endif

    /// Fills the table from `loader` (context must be current). Throws std::runtime_error
    /// naming the first missing entry point (DrawElementsBaseVertex may stay null).
    void load(ProcLoader loader);

    /// "OpenGL 4.5 (Core Profile) Mesa ..., llvmpipe" style one-line description.
    std::string describe() const;
};

} // namespace fv::gfx
