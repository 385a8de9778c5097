// gl_state.cpp — saving and restoring the GL state the renderer touches, and
// the debug-output route to the logger.
#include "gl_state.hpp"

#include "gpu_types.hpp"

#include <cstdio>
#include <string>

namespace aerial::renderer::detail {
namespace {

struct DebugRoute {
    const Logger* logger = nullptr;
    int* errorCounter = nullptr;
};
thread_local DebugRoute tDebugRoute;

void GLAPIENTRY debugCallback(GLenum /*source*/, GLenum type, GLuint id, GLenum severity, GLsizei length,
                              const GLchar* message, const void* /*user*/) {
    if (tDebugRoute.logger == nullptr || severity == GL_DEBUG_SEVERITY_NOTIFICATION) {
        return;
    }
    LogLevel level = LogLevel::Info;
    if (type == GL_DEBUG_TYPE_ERROR) {
        level = LogLevel::Error;
        if (tDebugRoute.errorCounter != nullptr) ++*tDebugRoute.errorCounter;
    } else if (severity == GL_DEBUG_SEVERITY_HIGH || severity == GL_DEBUG_SEVERITY_MEDIUM) {
        level = LogLevel::Warning;
    }
    std::string text = "GL debug (id " + std::to_string(id) + "): ";
    text.append(message,
                length > 0 ? static_cast<std::size_t>(length) : std::char_traits<char>::length(message));
    logMessage(*tDebugRoute.logger, level, text.c_str());
}

constexpr GLuint kUniformIndices[] = {kFrameBinding, kVolumeBinding, kObjectBinding, kCloudBinding,
                                      kShadowBinding};

}  // namespace

void logMessage(const Logger& logger, LogLevel level, const char* message) {
    if (logger.function != nullptr) {
        logger.function(level, message, logger.userData);
    }
}

GLuint makeTargetTexture(GLenum format, int w, int h) {
    GLuint t = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &t);
    glTextureStorage2D(t, 1, format, w, h);
    glTextureParameteri(t, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(t, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTextureParameteri(t, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(t, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return t;
}

int drainGlErrors(const Logger& logger, const char* where) {
    int count = 0;
    for (GLenum e = glGetError(); e != GL_NO_ERROR && count < 64; e = glGetError()) {
        char text[160];
        std::snprintf(text, sizeof text, "GL error 0x%04X in %s", static_cast<unsigned>(e), where);
        logMessage(logger, LogLevel::Error, text);
        ++count;
    }
    return count;
}

GlStateGuard::GlStateGuard(const Logger* logger, bool routeDebugOutput, int* errorCounter) {
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFramebuffer_);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readFramebuffer_);
    glGetIntegerv(GL_VIEWPORT, viewport_);
    glGetIntegerv(GL_CURRENT_PROGRAM, &program_);
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertexArray_);
    glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &arrayBuffer_);
    glGetIntegerv(GL_UNIFORM_BUFFER_BINDING, &uniformBuffer_);
    glGetIntegerv(GL_SHADER_STORAGE_BUFFER_BINDING, &storageBuffer_);
    blend_ = glIsEnabled(GL_BLEND);
    depthTest_ = glIsEnabled(GL_DEPTH_TEST);
    depthClamp_ = glIsEnabled(GL_DEPTH_CLAMP);
    cull_ = glIsEnabled(GL_CULL_FACE);
    scissor_ = glIsEnabled(GL_SCISSOR_TEST);
    stencil_ = glIsEnabled(GL_STENCIL_TEST);
    polygonOffsetFill_ = glIsEnabled(GL_POLYGON_OFFSET_FILL);
    glGetFloatv(GL_POLYGON_OFFSET_FACTOR, &polygonOffsetFactor_);
    glGetFloatv(GL_POLYGON_OFFSET_UNITS, &polygonOffsetUnits_);
    glGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask_);
    glGetBooleanv(GL_COLOR_WRITEMASK, colourMask_);
    glGetIntegerv(GL_BLEND_SRC_RGB, &blendSrcRgb_);
    glGetIntegerv(GL_BLEND_DST_RGB, &blendDstRgb_);
    glGetIntegerv(GL_BLEND_SRC_ALPHA, &blendSrcAlpha_);
    glGetIntegerv(GL_BLEND_DST_ALPHA, &blendDstAlpha_);
    glGetIntegerv(GL_BLEND_EQUATION_RGB, &blendEquationRgb_);
    glGetIntegerv(GL_BLEND_EQUATION_ALPHA, &blendEquationAlpha_);
    glGetIntegerv(GL_DEPTH_FUNC, &depthFunc_);
    glGetIntegerv(GL_CULL_FACE_MODE, &cullMode_);
    glGetIntegerv(GL_FRONT_FACE, &frontFace_);
    glGetIntegerv(GL_ACTIVE_TEXTURE, &activeTexture_);
    glGetIntegerv(GL_PACK_ALIGNMENT, &packAlignment_);
    for (unsigned unit = 0; unit < kSavedUnits; ++unit) {
        glActiveTexture(GL_TEXTURE0 + unit);
        const GLenum target = savedTarget(unit);
        glGetIntegerv(target == GL_TEXTURE_3D         ? GL_TEXTURE_BINDING_3D
                      : target == GL_TEXTURE_2D_ARRAY ? GL_TEXTURE_BINDING_2D_ARRAY
                                                      : GL_TEXTURE_BINDING_2D,
                      &textures_[unit]);
        glGetIntegerv(GL_SAMPLER_BINDING, &samplers_[unit]);
    }
    glActiveTexture(static_cast<GLenum>(activeTexture_));
    for (GLuint index : kUniformIndices) {
        IndexedBuffer& b = uniformBindings_[index];
        glGetIntegeri_v(GL_UNIFORM_BUFFER_BINDING, index, &b.buffer);
        glGetInteger64i_v(GL_UNIFORM_BUFFER_START, index, &b.start);
        glGetInteger64i_v(GL_UNIFORM_BUFFER_SIZE, index, &b.size);
    }
    glGetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, kEmitterBinding, &storageBinding_.buffer);
    glGetInteger64i_v(GL_SHADER_STORAGE_BUFFER_START, kEmitterBinding, &storageBinding_.start);
    glGetInteger64i_v(GL_SHADER_STORAGE_BUFFER_SIZE, kEmitterBinding, &storageBinding_.size);

    if (routeDebugOutput && logger != nullptr) {
        debugRouted_ = true;
        debugOutput_ = glIsEnabled(GL_DEBUG_OUTPUT);
        debugSynchronous_ = glIsEnabled(GL_DEBUG_OUTPUT_SYNCHRONOUS);
        glGetPointerv(GL_DEBUG_CALLBACK_FUNCTION, reinterpret_cast<void**>(&debugCallback_));
        glGetPointerv(GL_DEBUG_CALLBACK_USER_PARAM, &debugUserParam_);
        tDebugRoute = {logger, errorCounter};
        glDebugMessageCallback(debugCallback, nullptr);
        glEnable(GL_DEBUG_OUTPUT);
        glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    }
}

namespace {
void setEnabled(GLenum cap, GLboolean on) { on ? glEnable(cap) : glDisable(cap); }
void restoreIndexed(GLenum target, GLuint index, GLint buffer, GLint64 start, GLint64 size) {
    if (buffer != 0 && !glIsBuffer(static_cast<GLuint>(buffer))) buffer = 0;  // deleted meanwhile
    if (buffer != 0 && size > 0) {
        glBindBufferRange(target, index, static_cast<GLuint>(buffer), static_cast<GLintptr>(start),
                          static_cast<GLsizeiptr>(size));
    } else {
        glBindBufferBase(target, index, static_cast<GLuint>(buffer));
    }
}
}  // namespace

GlStateGuard::~GlStateGuard() {
    // An object the guarded call deleted (a target or texture made again at
    // a new size that the caller still had bound, such as the frame it
    // displayed) is not bound again: GL already unbound it, and binding a
    // deleted name is GL_INVALID_OPERATION.
    const auto live = [](GLboolean (*isObject)(GLuint), GLint name) {
        return name != 0 && isObject(static_cast<GLuint>(name)) ? static_cast<GLuint>(name) : 0u;
    };
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, live(glIsFramebuffer, drawFramebuffer_));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, live(glIsFramebuffer, readFramebuffer_));
    glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
    glUseProgram(live(glIsProgram, program_));
    glBindVertexArray(live(glIsVertexArray, vertexArray_));
    glBindBuffer(GL_ARRAY_BUFFER, live(glIsBuffer, arrayBuffer_));
    setEnabled(GL_BLEND, blend_);
    setEnabled(GL_DEPTH_TEST, depthTest_);
    setEnabled(GL_DEPTH_CLAMP, depthClamp_);
    setEnabled(GL_CULL_FACE, cull_);
    setEnabled(GL_SCISSOR_TEST, scissor_);
    setEnabled(GL_STENCIL_TEST, stencil_);
    setEnabled(GL_POLYGON_OFFSET_FILL, polygonOffsetFill_);
    glPolygonOffset(polygonOffsetFactor_, polygonOffsetUnits_);
    glDepthMask(depthMask_);
    glColorMask(colourMask_[0], colourMask_[1], colourMask_[2], colourMask_[3]);
    glBlendFuncSeparate(static_cast<GLenum>(blendSrcRgb_), static_cast<GLenum>(blendDstRgb_),
                        static_cast<GLenum>(blendSrcAlpha_), static_cast<GLenum>(blendDstAlpha_));
    glBlendEquationSeparate(static_cast<GLenum>(blendEquationRgb_), static_cast<GLenum>(blendEquationAlpha_));
    glDepthFunc(static_cast<GLenum>(depthFunc_));
    glCullFace(static_cast<GLenum>(cullMode_));
    glFrontFace(static_cast<GLenum>(frontFace_));
    glPixelStorei(GL_PACK_ALIGNMENT, packAlignment_);
    for (unsigned unit = 0; unit < kSavedUnits; ++unit) {
        glActiveTexture(GL_TEXTURE0 + unit);
        glBindTexture(savedTarget(unit), live(glIsTexture, textures_[unit]));
        glBindSampler(unit, live(glIsSampler, samplers_[unit]));
    }
    glActiveTexture(static_cast<GLenum>(activeTexture_));
    for (GLuint index : kUniformIndices) {
        const IndexedBuffer& b = uniformBindings_[index];
        restoreIndexed(GL_UNIFORM_BUFFER, index, b.buffer, b.start, b.size);
    }
    restoreIndexed(GL_SHADER_STORAGE_BUFFER, kEmitterBinding, storageBinding_.buffer, storageBinding_.start,
                   storageBinding_.size);
    glBindBuffer(GL_UNIFORM_BUFFER, live(glIsBuffer, uniformBuffer_));
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, live(glIsBuffer, storageBuffer_));
    if (debugRouted_) {
        glDebugMessageCallback(debugCallback_, debugUserParam_);
        setEnabled(GL_DEBUG_OUTPUT, debugOutput_);
        setEnabled(GL_DEBUG_OUTPUT_SYNCHRONOUS, debugSynchronous_);
        tDebugRoute = {};
    }
}

}  // namespace aerial::renderer::detail
