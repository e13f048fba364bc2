// Headless backend: OSMesa (Mesa llvmpipe), loaded with dlopen so that the binary never links
// libOSMesa (which would clash with glvnd's libGL in window mode).
#include "fv/gfx/context.hpp"

#include <dlfcn.h>

#include <cmath>
#include <cstdlib>

#include <stdexcept>
#include <vector>

namespace fv::gfx {
namespace {

// From <GL/osmesa.h>; declared here because that header drags in <GL/gl.h>, which clashes with glcorearb.h.
using OSMesaContext = struct osmesa_context*;
using PfnCreateContextAttribs = OSMesaContext (*)(const int* attribs, OSMesaContext share);
using PfnMakeCurrent = GLboolean (*)(OSMesaContext, void* buffer, GLenum type, GLsizei w, GLsizei h);
using PfnDestroyContext = void (*)(OSMesaContext);
using PfnGetProcAddress = void (*(*)(const char*))();
constexpr int kOsmesaFormat = 0x22, kOsmesaDepthBits = 0x30, kOsmesaStencilBits = 0x31, kOsmesaProfile = 0x33,
              kOsmesaCoreProfile = 0x34, kOsmesaMajor = 0x36, kOsmesaMinor = 0x37;

struct OsmesaLib {
    PfnCreateContextAttribs create = nullptr;
    PfnMakeCurrent make_current = nullptr;
    PfnDestroyContext destroy = nullptr;
    PfnGetProcAddress get_proc = nullptr;
};

// Loaded once per process and never dlclose'd: Mesa registers process-wide state
// (llvmpipe threads, atexit handlers) that must outlive every context.
const OsmesaLib& osmesa() {
    static const OsmesaLib lib = [] {
        // FV_OSMESA_LIBRARY names another OSMesa build (and lets the tests exercise the failure path).
        const char* override_path = std::getenv("FV_OSMESA_LIBRARY");
        void* h = nullptr;
        if (override_path && *override_path) {
            h = dlopen(override_path, RTLD_NOW | RTLD_LOCAL);
        } else {
            h = dlopen("libOSMesa.so.8", RTLD_NOW | RTLD_LOCAL);
            if (!h) h = dlopen("libOSMesa.so", RTLD_NOW | RTLD_LOCAL);
        }
        if (!h)
            throw std::runtime_error(
                std::string("headless rendering needs libOSMesa.so.8 (Debian: libosmesa6): ") + dlerror());
        OsmesaLib l;
        l.create = reinterpret_cast<PfnCreateContextAttribs>(dlsym(h, "OSMesaCreateContextAttribs"));
        l.make_current = reinterpret_cast<PfnMakeCurrent>(dlsym(h, "OSMesaMakeCurrent"));
        l.destroy = reinterpret_cast<PfnDestroyContext>(dlsym(h, "OSMesaDestroyContext"));
        l.get_proc = reinterpret_cast<PfnGetProcAddress>(dlsym(h, "OSMesaGetProcAddress"));
        if (!l.create || !l.make_current || !l.destroy || !l.get_proc)
            throw std::runtime_error("libOSMesa lacks OSMesaCreateContextAttribs (Mesa too old?)");
        return l;
    }();
    return lib;
}

void* osmesa_loader(const char* name) {
    return reinterpret_cast<void*>(osmesa().get_proc(name));
}

} // namespace

struct HeadlessContext::Impl {
    OSMesaContext ctx = nullptr;
    std::vector<unsigned char> buffer; // The default framebuffer lives here (RGBA8, bottom-up).
};

HeadlessContext::HeadlessContext(int width, int height, float scale)
    : impl_(std::make_unique<Impl>()), width_(width), height_(height), scale_(scale) {
    if (width <= 0 || height <= 0) throw std::runtime_error("headless context: size must be positive");
    if (!(scale > 0) || !std::isfinite(scale))
        throw std::runtime_error("headless context: scale must be > 0");
    const OsmesaLib& lib = osmesa();
    const int attribs[] = {kOsmesaFormat,
                           GL_RGBA,
                           kOsmesaDepthBits,
                           0,
                           kOsmesaStencilBits,
                           0,
                           kOsmesaProfile,
                           kOsmesaCoreProfile,
                           kOsmesaMajor,
                           3,
                           kOsmesaMinor,
                           3,
                           0};
    impl_->ctx = lib.create(attribs, nullptr);
    if (!impl_->ctx) throw std::runtime_error("OSMesa could not create a core-profile 3.3 context");
    impl_->buffer.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
    make_current();
    gl_.load(&osmesa_loader);
}

HeadlessContext::~HeadlessContext() {
    if (impl_->ctx) osmesa().destroy(impl_->ctx);
}

Size HeadlessContext::logical_size() const {
    return {static_cast<int>(std::lround(static_cast<double>(width_) / scale_)),
            static_cast<int>(std::lround(static_cast<double>(height_) / scale_))};
}

void HeadlessContext::make_current() {
    if (!osmesa().make_current(impl_->ctx, impl_->buffer.data(), GL_UNSIGNED_BYTE, width_, height_))
        throw std::runtime_error("OSMesaMakeCurrent failed");
}

void HeadlessContext::present() {
    gl_.Finish();
}

std::string HeadlessContext::describe() const {
    return "headless OSMesa, " + gl_.describe();
}

} // namespace fv::gfx
