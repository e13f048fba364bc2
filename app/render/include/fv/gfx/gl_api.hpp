#pragma once
// GL function table. Nothing in fvrender calls gl* symbols directly: headless mode resolves
// entry points from a dlopen'ed OSMesa, a window from GLFW. Linking libGL and libOSMesa
// together clashes (both export every gl* symbol), so the table is the only way in.
#include <GL/glcorearb.h>

#include <string>

namespace fv::gfx {

/// Signature of OSMesaGetProcAddress / glfwGetProcAddress, adapted to return void*.
using ProcLoader = void* (*)(const char* name);

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
    X(PFNGLDRAWELEMENTSPROC, DrawElements, glDrawElements)                                                   \
    X(PFNGLDRAWELEMENTSBASEVERTEXPROC, DrawElementsBaseVertex, glDrawElementsBaseVertex)

/// Table of GL entry points for one context. Members are named like the GL call without "gl".
struct GlApi {
#define FV_GL_MEMBER(type, member, symbol) type member = nullptr;
    FV_GL_FUNCTIONS(FV_GL_MEMBER)
#undef FV_GL_MEMBER

    /// Fills the table from `loader` (context must be current). Throws std::runtime_error
    /// naming the first missing entry point.
    void load(ProcLoader loader);

    /// "OpenGL 4.5 (Core Profile) Mesa ..., llvmpipe" style one-line description.
    std::string describe() const;
};

} // namespace fv::gfx
