// Headless backend: OSMesa (Mesa llvmpipe), loaded with dlopen so that the binary never links
// libOSMesa (which would clash with glvnd's libGL in window mode).
#include "fv/gfx/context.hpp"

#include <dlfcn.h>

#include <cmath>
#include <cstdlib>

#include <stdexcept>
#include <string>
#include <type_traits>
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

// The frame is drawn into a framebuffer object of the context's size, not into OSMesa's default framebuffer:
// OSMesa keeps that one in a resource of its own and copies it into the client's buffer at every
// glFinish (1920x1080: 8 MB, about 1 ms of the app thread per frame). Nothing reads the client's buffer
// (read_pixels reads the bound framebuffer), so it is 1x1. The entry points are loaded here, not in
// GlApi: only this backend needs them.
struct HeadlessContext::Impl {
    OSMesaContext ctx = nullptr;
    std::vector<unsigned char> buffer = std::vector<unsigned char>(4); // OSMesa's default framebuffer
    int buffer_width = 1, buffer_height = 1;
    PFNGLGENFRAMEBUFFERSPROC GenFramebuffers = nullptr;
    PFNGLBINDFRAMEBUFFERPROC BindFramebuffer = nullptr;
    PFNGLFRAMEBUFFERTEXTURE2DPROC FramebufferTexture2D = nullptr;
    PFNGLCHECKFRAMEBUFFERSTATUSPROC CheckFramebufferStatus = nullptr;
    PFNGLFRAMEBUFFERPARAMETERIPROC FramebufferParameteri = nullptr;
    GLuint framebuffer = 0; // the frame's (0: OSMesa's default framebuffer of the context's size)
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
    make_current();
    gl_.load(&osmesa_loader);
    if (!draw_into_framebuffer_object()) { // an OSMesa without GL_MESA_framebuffer_flip_y: the default one
        impl_->buffer.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4, 0);
        impl_->buffer_width = width, impl_->buffer_height = height;
        make_current();
    }
}

bool HeadlessContext::draw_into_framebuffer_object() {
    Impl& m = *impl_;
    auto load = [](auto& fn, const char* name) {
        fn = reinterpret_cast<std::remove_reference_t<decltype(fn)>>(osmesa_loader(name));
        return fn != nullptr;
    };
    if (!load(m.GenFramebuffers, "glGenFramebuffers") || !load(m.BindFramebuffer, "glBindFramebuffer") ||
        !load(m.FramebufferTexture2D, "glFramebufferTexture2D") ||
        !load(m.CheckFramebufferStatus, "glCheckFramebufferStatus") ||
        !load(m.FramebufferParameteri, "glFramebufferParameteri"))
        return false;
    while (gl_.GetError() != GL_NO_ERROR) {
    }
    GLuint colour = 0, framebuffer = 0;
    gl_.GenTextures(1, &colour);
    gl_.BindTexture(GL_TEXTURE_2D, colour);
    gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl_.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width_, height_, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    gl_.BindTexture(GL_TEXTURE_2D, 0);
    m.GenFramebuffers(1, &framebuffer);
    m.BindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    m.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour, 0);
    // Rows kept top-down, as in a window system's framebuffer (Gallium draws those flipped): the same
    // rasterization, so the same pixels as OSMesa's default framebuffer and a window (without it, glyph edges
    // differ by 1 in a few pixels).
    constexpr GLenum kFramebufferFlipYMesa = 0x8BBB; // GL_MESA_framebuffer_flip_y
    m.FramebufferParameteri(GL_FRAMEBUFFER, kFramebufferFlipYMesa, GL_TRUE);
    if (gl_.GetError() != GL_NO_ERROR ||
        m.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        m.BindFramebuffer(GL_FRAMEBUFFER, 0);
        gl_.DeleteTextures(1, &colour);
        return false;
    }
    m.framebuffer = framebuffer;
    gl_.Viewport(0, 0, width_, height_);
    return true;
}

HeadlessContext::~HeadlessContext() {
    if (impl_->ctx) osmesa().destroy(impl_->ctx); // with the context go its framebuffer object and texture
}

Size HeadlessContext::logical_size() const {
    return {static_cast<int>(std::lround(static_cast<double>(width_) / scale_)),
            static_cast<int>(std::lround(static_cast<double>(height_) / scale_))};
}

void HeadlessContext::make_current() {
    if (!osmesa().make_current(impl_->ctx, impl_->buffer.data(), GL_UNSIGNED_BYTE, impl_->buffer_width,
                               impl_->buffer_height))
        throw std::runtime_error("OSMesaMakeCurrent failed");
    if (impl_->framebuffer) impl_->BindFramebuffer(GL_FRAMEBUFFER, impl_->framebuffer);
}

void HeadlessContext::present() {
    gl_.Finish();
}

std::string HeadlessContext::describe() const {
    return "headless OSMesa, " + gl_.describe();
}

} // namespace fv::gfx
