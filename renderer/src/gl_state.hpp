// gl_state.hpp — private: saves the GL state the renderer touches and
// restores it on destruction (Dear ImGui's backends do the same), and routes
// GL debug output to the renderer's logger meanwhile.
#pragma once

#include <aerial/renderer/log.hpp>

#include <epoxy/gl.h>

namespace aerial::renderer::detail {

/// Saved on construction, restored on destruction: framebuffer bindings,
/// viewport, program, vertex array, array buffer, blend (enable, functions,
/// equations), depth (test, mask, function, clamp), culling (enable, mode,
/// front face), scissor and stencil tests, colour mask, active texture, the
/// texture and sampler bound to units 0..10 (the cloud units 8, 9 as 3D), the uniform buffer
/// bindings 0, 1, 3, 4 and shader storage binding 2 (with ranges), pack
/// alignment, and the debug-output callback and enable.
class GlStateGuard {
public:
    GlStateGuard(const Logger* logger, bool routeDebugOutput, int* errorCounter);
    ~GlStateGuard();
    GlStateGuard(const GlStateGuard&) = delete;
    GlStateGuard& operator=(const GlStateGuard&) = delete;

private:
    struct IndexedBuffer {
        GLint buffer = 0;
        GLint64 start = 0;
        GLint64 size = 0;
    };
    GLint drawFramebuffer_ = 0, readFramebuffer_ = 0;
    GLint viewport_[4] = {};
    GLint program_ = 0, vertexArray_ = 0, arrayBuffer_ = 0, uniformBuffer_ = 0, storageBuffer_ = 0;
    GLboolean blend_ = GL_FALSE, depthTest_ = GL_FALSE, depthMask_ = GL_TRUE, depthClamp_ = GL_FALSE;
    GLboolean cull_ = GL_FALSE, scissor_ = GL_FALSE, stencil_ = GL_FALSE, polygonOffsetFill_ = GL_FALSE;
    GLfloat polygonOffsetFactor_ = 0.0f, polygonOffsetUnits_ = 0.0f;
    GLboolean colourMask_[4] = {GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE};
    GLint blendSrcRgb_ = GL_ONE, blendDstRgb_ = GL_ZERO, blendSrcAlpha_ = GL_ONE, blendDstAlpha_ = GL_ZERO;
    GLint blendEquationRgb_ = GL_FUNC_ADD, blendEquationAlpha_ = GL_FUNC_ADD;
    GLint depthFunc_ = GL_LESS, cullMode_ = GL_BACK, frontFace_ = GL_CCW;
    GLint activeTexture_ = GL_TEXTURE0, packAlignment_ = 4;
    /// Units 0..7 (2D) and the cloud units 8, 9 (3D) and 10 (2D).
    static constexpr unsigned kSavedUnits = 15;
    static GLenum savedTarget(unsigned unit) {
        return unit == 8 || unit == 9 ? GL_TEXTURE_3D : unit == 11 ? GL_TEXTURE_2D_ARRAY : GL_TEXTURE_2D;
    }
    GLint textures_[kSavedUnits] = {};
    GLint samplers_[kSavedUnits] = {};
    IndexedBuffer uniformBindings_[6];
    IndexedBuffer storageBinding_;
    bool debugRouted_ = false;
    GLboolean debugOutput_ = GL_FALSE, debugSynchronous_ = GL_FALSE;
    GLDEBUGPROC debugCallback_ = nullptr;
    void* debugUserParam_ = nullptr;
};

/// Drains glGetError, logging each error with `where`; returns the count.
int drainGlErrors(const Logger& logger, const char* where);

/// A w x h 2D texture of `format` for a render target: one level, nearest
/// filtering, clamped at the edges (the frame's targets, the cloud history).
GLuint makeTargetTexture(GLenum format, int w, int h);

/// Sends a message to the logger (no-op for a null function).
void logMessage(const Logger& logger, LogLevel level, const char* message);

}  // namespace aerial::renderer::detail
