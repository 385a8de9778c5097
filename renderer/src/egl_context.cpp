// egl_context.cpp — a headless OpenGL 4.5 core context on EGL's Mesa
// surfaceless platform (no X, no window): eglGetPlatformDisplay(EXT) with
// EGL_PLATFORM_SURFACELESS_MESA, a config with EGL_PBUFFER_BIT and
// EGL_OPENGL_BIT, eglBindAPI(EGL_OPENGL_API), a 4.5 core context made current
// with no surface (EGL_KHR_surfaceless_context). On llvmpipe this is Mesa's
// software rasteriser.
#include <aerial/renderer/egl_context.hpp>

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <cstdio>
#include <cstring>
#include <string>

namespace aerial::renderer {

struct HeadlessContext::Impl {
    EGLDisplay display = EGL_NO_DISPLAY;
    EGLContext context = EGL_NO_CONTEXT;
    std::string error;
    std::string rendererName;

    ~Impl() {
        if (display != EGL_NO_DISPLAY) {
            if (context != EGL_NO_CONTEXT) {
                if (eglGetCurrentContext() == context) {
                    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
                }
                eglDestroyContext(display, context);
            }
            eglTerminate(display);
        }
    }

    bool fail(const std::string& step) {
        char code[32];
        std::snprintf(code, sizeof code, "0x%04X", static_cast<unsigned>(eglGetError()));
        error = "headless EGL: " + step + " (EGL error " + code +
                "); is Mesa's EGL installed (libegl-mesa0, libgl1-mesa-dri)?";
        return false;
    }
};

HeadlessContext::HeadlessContext() : impl_(std::make_unique<Impl>()) {}
HeadlessContext::~HeadlessContext() = default;

bool HeadlessContext::create(const HeadlessContextDesc& desc) {
    Impl& s = *impl_;
    if (s.context != EGL_NO_CONTEXT) {
        return makeCurrent();
    }
    const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (clientExtensions == nullptr ||
        std::strstr(clientExtensions, "EGL_MESA_platform_surfaceless") == nullptr) {
        return s.fail("the EGL client has no EGL_MESA_platform_surfaceless");
    }
    // EGL_EXT_platform_base is what every Mesa exposes on the client side;
    // libepoxy resolves the core 1.5 entry point only once a display exists.
    if (std::strstr(clientExtensions, "EGL_EXT_platform_base") != nullptr) {
        s.display = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    } else {
        s.display = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    }
    if (s.display == EGL_NO_DISPLAY) {
        return s.fail("eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA) failed");
    }
    EGLint major = 0;
    EGLint minor = 0;
    if (!eglInitialize(s.display, &major, &minor)) {
        s.display = EGL_NO_DISPLAY;
        return s.fail("eglInitialize failed");
    }
    const EGLint configAttributes[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                                       EGL_NONE};
    EGLConfig config = nullptr;
    EGLint configCount = 0;
    if (!eglChooseConfig(s.display, configAttributes, &config, 1, &configCount) || configCount < 1) {
        return s.fail("no EGL config with EGL_PBUFFER_BIT and EGL_OPENGL_BIT");
    }
    if (!eglBindAPI(EGL_OPENGL_API)) {
        return s.fail("eglBindAPI(EGL_OPENGL_API) failed");
    }
    const int wantMajor = desc.majorVersion > 0 ? desc.majorVersion : 4;
    const int wantMinor = desc.majorVersion > 0 ? desc.minorVersion : 5;
    const EGLint contextAttributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                        wantMajor,
                                        EGL_CONTEXT_MINOR_VERSION,
                                        wantMinor,
                                        EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                        EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                        EGL_CONTEXT_OPENGL_DEBUG,
                                        desc.debug ? EGL_TRUE : EGL_FALSE,
                                        EGL_NONE};
    s.context = eglCreateContext(s.display, config, EGL_NO_CONTEXT, contextAttributes);
    if (s.context == EGL_NO_CONTEXT) {
        return s.fail("no OpenGL " + std::to_string(wantMajor) + "." + std::to_string(wantMinor) +
                      " core context");
    }
    if (!makeCurrent()) {
        return false;
    }
    const char* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    s.rendererName = std::string(name ? name : "?") + ", OpenGL " + (version ? version : "?");
    return true;
}

bool HeadlessContext::makeCurrent() {
    Impl& s = *impl_;
    if (s.context == EGL_NO_CONTEXT) {
        s.error = "headless EGL: no context";
        return false;
    }
    if (!eglMakeCurrent(s.display, EGL_NO_SURFACE, EGL_NO_SURFACE, s.context)) {
        return s.fail("eglMakeCurrent without a surface failed");
    }
    return true;
}

bool HeadlessContext::valid() const { return impl_->context != EGL_NO_CONTEXT; }
const std::string& HeadlessContext::error() const { return impl_->error; }
const std::string& HeadlessContext::rendererName() const { return impl_->rendererName; }

}  // namespace aerial::renderer
