#include "fv/gfx/embedded_shaders.hpp"

#include <stdexcept>
#include <string>

namespace fv::gfx {

std::string_view shader_source(std::string_view name) {
    for (std::size_t i = 0; i < kEmbeddedShaderCount; ++i) {
        if (name == kEmbeddedShaders[i].name)
            return {reinterpret_cast<const char*>(kEmbeddedShaders[i].data), kEmbeddedShaders[i].size};
    }
    throw std::runtime_error("shader not embedded: " + std::string(name));
}

} // namespace fv::gfx
