#include "platform.hpp"

#include <cstdlib>
#include <stdexcept>

namespace fv::app {
namespace {

[[maybe_unused]] bool env_set(const char* name) {
    const char* v = std::getenv(name);
    return v != nullptr && *v != '\0';
}

} // namespace

#if defined(__EMSCRIPTEN__)
// The browser build: the page's canvas is the only platform.
const std::vector<std::string_view>& platform_names() {
    static const std::vector<std::string_view> names{"web", "auto"};
    return names;
}

std::string_view resolve_platform_name(std::string_view name) {
    return name == "auto" ? "web" : name;
}

std::unique_ptr<Platform> make_platform(std::string_view name, const PlatformOptions& options) {
    const std::string_view resolved = resolve_platform_name(name);
    if (resolved == "web") return make_web_platform(options);
#else
const std::vector<std::string_view>& platform_names() {
    static const std::vector<std::string_view> names{"window", "headless", "auto"};
    return names;
}

std::string_view resolve_platform_name(std::string_view name) {
    if (name != "auto") return name;
    return env_set("DISPLAY") || env_set("WAYLAND_DISPLAY") ? "window" : "headless";
}

std::unique_ptr<Platform> make_platform(std::string_view name, const PlatformOptions& options) {
    const std::string_view resolved = resolve_platform_name(name);
    if (resolved == "window") return make_window_platform(options);
    if (resolved == "headless") return make_headless_platform(options);
#endif
    std::string allowed;
    for (std::string_view n : platform_names()) allowed += (allowed.empty() ? "" : ", ") + std::string(n);
    throw std::invalid_argument("unknown platform '" + std::string(name) + "' (allowed: " + allowed + ")");
}

} // namespace fv::app
