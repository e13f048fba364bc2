#pragma once
// Shader sources compiled into the binary from shaders/*.glsl (see cmake/embed_files.cmake).
#include <cstddef>
#include <string_view>

namespace fv::gfx {

struct EmbeddedFile {
    const char* name; ///< File name, e.g. "shapes.frag.glsl".
    const unsigned char* data;
    std::size_t size;
};

extern const EmbeddedFile kEmbeddedShaders[];
extern const std::size_t kEmbeddedShaderCount;

/// Source text of an embedded shader by file name; throws std::runtime_error if unknown.
std::string_view shader_source(std::string_view name);

} // namespace fv::gfx
