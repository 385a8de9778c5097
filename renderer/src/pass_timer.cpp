// pass_timer.cpp — running the frame's passes, and timing them
// (FrameDesc::gpuTimers -> RenderStats::gpuMilliseconds, wallMilliseconds):
// the one place where a pass is timed. Also the helpers the passes share and
// the frame's lazily built CPU fog (render_pass.hpp).
//
// Timing: glFinish, then the CPU clock starts and a GL_TIME_ELAPSED query
// begins; after the pass the query ends and glFinish again, and the clock
// stops. The query results are read at endFrame. Waiting for the GPU after
// every pass is for benchmarks, not for an interactive frame.
#include "render_pass.hpp"

#include <aerial/evaluate.hpp>

#include <chrono>

namespace aerial::renderer::detail {

const FogScene& FrameContext::localFog() {
    if (!localFog_) {
        FogSceneDesc fogDesc =
            fogSceneDesc(state, gpu.sunTable, gpu.moonTable, overcast ? *overcast : OvercastLight{});
        fogDesc.heightFog.density = 0.0;
        if (!desc.passes.volumes) fogDesc.volumes.clear();
        if (!desc.passes.emitters) fogDesc.emitters.clear();
        localFog_ = std::make_unique<FogScene>(fogDesc);
    }
    return *localFog_;
}

void PassTimer::create() { glCreateQueries(GL_TIME_ELAPSED, kMaxPasses, queries_); }

void PassTimer::destroy() { glDeleteQueries(kMaxPasses, queries_); }

void PassTimer::beginFrame(bool enabled) {
    enabled_ = enabled;
    used_ = 0;
}

void PassTimer::run(const RenderPass& pass, FrameContext& frame) {
    if (!pass.runs(frame)) return;
    if (!enabled_ || used_ >= kMaxPasses) {
        pass.draw(frame);
        return;
    }
    const int k = used_++;
    glFinish();
    const auto start = std::chrono::steady_clock::now();
    glBeginQuery(GL_TIME_ELAPSED, queries_[k]);
    pass.draw(frame);
    glEndQuery(GL_TIME_ELAPSED);
    glFinish();
    wallMs_[k] = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    slots_[k] = pass.time;
}

void PassTimer::endFrame(RenderStats& stats) {
    if (!enabled_) return;
    for (int k = 0; k < used_; ++k) {
        GLuint64 ns = 0;
        glGetQueryObjectui64v(queries_[k], GL_QUERY_RESULT, &ns);
        stats.gpuMilliseconds.*slots_[k] = static_cast<double>(ns) * 1e-6;
        stats.wallMilliseconds.*slots_[k] = wallMs_[k];
    }
    stats.timed = true;
}

void drawFullscreen(const RendererResources& gpu, Pass program) {
    glUseProgram(gpu.shaders.program(program));
    glBindVertexArray(gpu.emptyVertexArray);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

void beginComposite(const RendererResources& gpu, GLenum srcRgb, GLenum dstRgb) {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, gpu.compositeTarget);
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendEquationSeparate(GL_FUNC_ADD, GL_FUNC_ADD);
    glBlendFuncSeparate(srcRgb, dstRgb, GL_ZERO, GL_ONE);
}

void endComposite(const RendererResources& gpu) {
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, gpu.sceneTarget);
}

void compositeFullscreen(const RendererResources& gpu, Pass program, GLenum srcRgb, GLenum dstRgb) {
    beginComposite(gpu, srcRgb, dstRgb);
    drawFullscreen(gpu, program);
    endComposite(gpu);
}

}  // namespace aerial::renderer::detail
