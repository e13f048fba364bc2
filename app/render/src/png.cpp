#include "fv/gfx/png.hpp"

#include <stb_image.h>
#include <stb_image_write.h>

#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

namespace fv::gfx {

std::vector<unsigned char> encode_png(const Image& image) {
    if (image.empty()) throw std::runtime_error("encode_png: empty image");
    std::vector<unsigned char> out;
    auto sink = [](void* ctx, void* data, int size) {
        auto* v = static_cast<std::vector<unsigned char>*>(ctx);
        const auto* p = static_cast<const unsigned char*>(data);
        v->insert(v->end(), p, p + size);
    };
    const int ok =
        stbi_write_png_to_func(sink, &out, image.width, image.height, 4, image.rgba.data(), image.width * 4);
    if (!ok) throw std::runtime_error("encode_png: stb failed");
    return out;
}

Image decode_png(const unsigned char* data, std::size_t size) {
    if (size > static_cast<std::size_t>(std::numeric_limits<int>::max()))
        throw std::runtime_error("decode_png: input too large");
    int w = 0, h = 0, channels = 0;
    unsigned char* px = stbi_load_from_memory(data, static_cast<int>(size), &w, &h, &channels, 4);
    if (!px) throw std::runtime_error(std::string("decode_png: ") + stbi_failure_reason());
    Image img(w, h);
    std::memcpy(img.rgba.data(), px, img.rgba.size());
    stbi_image_free(px);
    return img;
}

} // namespace fv::gfx
