#pragma once
// PNG encoding/decoding in memory via stb (libstb exports both; no STB_*_IMPLEMENTATION needed).
// Writing files is the caller's job (the product writes atomically through fv::write_file_atomic).
#include "fv/gfx/image.hpp"

#include <cstddef>
#include <vector>

namespace fv::gfx {

/// RGBA8 PNG bytes of the image. Throws std::runtime_error on failure.
std::vector<unsigned char> encode_png(const Image& image);

/// Decodes any PNG (converted to RGBA8). Throws std::runtime_error with stb's reason on failure.
Image decode_png(const unsigned char* data, std::size_t size);
inline Image decode_png(const std::vector<unsigned char>& bytes) {
    return decode_png(bytes.data(), bytes.size());
}

} // namespace fv::gfx
