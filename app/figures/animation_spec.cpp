#include "figures/animation_spec.hpp"

#include <cctype>

namespace fv {

std::optional<AnimationFormat> animation_format(const std::string& path) {
    const auto dot = path.find_last_of('.');
    const auto slash = path.find_last_of('/');
    const std::size_t name = slash == std::string::npos ? 0 : slash + 1;
    if (dot == std::string::npos || dot <= name) return std::nullopt; // no extension, or a dot file
    std::string ext = path.substr(dot + 1);
    for (char& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (ext == "gif") return AnimationFormat::gif;
    if (ext == "mp4") return AnimationFormat::mp4;
    return std::nullopt;
}

} // namespace fv
