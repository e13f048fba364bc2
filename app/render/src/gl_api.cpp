#include "fv/gfx/gl_api.hpp"

#include <cstring>
#include <stdexcept>

namespace fv::gfx {

void GlApi::load(ProcLoader loader) {
#define FV_GL_LOAD(type, member, symbol)                                                                     \
    member = reinterpret_cast<type>(loader(#symbol));                                                        \
    if (member == nullptr) throw std::runtime_error("OpenGL entry point " #symbol " not available");
    FV_GL_FUNCTIONS(FV_GL_LOAD)
#undef FV_GL_LOAD
    DrawElementsBaseVertex = reinterpret_cast<PfnDrawElementsBaseVertex>(loader("glDrawElementsBaseVertex"));
}

std::string GlApi::describe() const {
    auto str = [this](GLenum e) {
        const GLubyte* s = GetString(e);
        return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
    };
    return "OpenGL " + str(GL_VERSION) + ", " + str(GL_RENDERER);
}

} // namespace fv::gfx
