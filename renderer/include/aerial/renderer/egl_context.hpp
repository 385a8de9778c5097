// aerial/renderer/egl_context.hpp — a headless OpenGL 4.5 core context on
// EGL without a display (Mesa's surfaceless platform), for the CLI's
// `render` and the tests. The renderer itself never creates contexts: it
// uses whatever context is current.
//
// Usage:
//   aerial::renderer::HeadlessContext context;
//   if (!context.create()) { fail(context.error()); }   // makes it current
//   aerial::renderer::Renderer renderer(desc);           // renders into its FBOs
#pragma once

#include <memory>
#include <string>

namespace aerial::renderer {

struct HeadlessContextDesc {
    int majorVersion = 4;  ///< 0 = 4
    int minorVersion = 5;  ///< with majorVersion 0: 5
    /// Ask for a debug context (KHR_debug messages for every GL error).
    bool debug = true;
};

/// LeakSanitizer suppressions for allocations inside Mesa's own libraries
/// (llvmpipe's JIT, the DRI loader): not Aerial's leaks. A sanitizer build of
/// a program that renders headless returns this from its
/// __lsan_default_suppressions(), and keeps its context alive until exit
/// (once Mesa's driver is unloaded its allocations can no longer be named).
inline constexpr const char* kMesaLeakSuppressions =
    "leak:libEGL_mesa\nleak:libgallium\nleak:libLLVM\nleak:swrast_dri\nleak:libglapi\nleak:libdrm\n"
    "leak:llvmpipe\nleak:libEGL.so\nleak:libepoxy\n";

/// Owns an EGL display connection and a context with no surface; the
/// context renders only into framebuffer objects.
class HeadlessContext {
public:
    HeadlessContext();
    ~HeadlessContext();
    HeadlessContext(const HeadlessContext&) = delete;
    HeadlessContext& operator=(const HeadlessContext&) = delete;

    /// Creates the context and makes it current on this thread. Returns
    /// false with error() naming the step that failed (no EGL, no
    /// surfaceless platform, no 4.5 core context...).
    bool create(const HeadlessContextDesc& desc = {});
    /// Makes the context current on the calling thread.
    bool makeCurrent();
    bool valid() const;
    const std::string& error() const;
    /// GL_RENDERER and GL_VERSION of the created context ("" before).
    const std::string& rendererName() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace aerial::renderer
