// cloud_amortised.cpp — the amortised cloud path (FrameDesc::cloudQuality
// Amortised, lit output): the cloud layer traced for one pixel of each
// n x n block per frame (n = FrameDesc::cloudAmortisedBlock, 2 or 4: a
// quarter or a sixteenth of the pixels, Schneider 2015/2017's Nubis traces
// 1/16), the other pixels reprojected from the previous frames.
//
// Choice: the traced pixel of a block walks a Bayer order of the n^2 pixels
// (for n = 4 the first four form a 2 x 2-spaced grid, the first eight a
// checkerboard of it), so n^2 still frames trace every full-resolution pixel
// exactly once, with exactly the reference's ray and scene depth. The march
// is deterministic (no noise), so a traced pixel takes its new value
// outright (history weight 0) and a still view converges to the reference
// itself after n^2 frames, not to a blurred average.
//
// Pass 1, trace (shaders/clouds.glsl with uTrace = (jitter, n)): into the
//   trace target, ceil(w/n) x ceil(h/n), RGBA16F (RGBA32F with
//   ColourPrecision::Float, so S keeps the reference's range): rgb = S,
//   a = T of the block's pixel.
// Pass 2, reconstruction (shaders/cloud_reconstruct.glsl), one draw with two
//   outputs: the frame's colour through L <- L T + S (glBlendFunc(GL_ONE,
//   GL_SRC_ALPHA) on draw buffer 0, alpha kept, exactly the reference's
//   composite) and the new history (unblended, draw buffer 1). Per pixel:
//   traced now: the new sample; otherwise the history, reprojected with the
//   previous clipFromWorld at the point where the ray enters the cloud layer
//   (or the scene point, if nearer; the direction for rays that miss the
//   layer: clouds are far, so this is the first-order motion), moved back
//   by the wind's drift since the previous frame, nearest
//   texel, kept when the previous frame's linear depth there agrees with
//   this pixel's (within 10 %) and it holds a traced (not estimated) value,
//   then clamped per channel to the min/max of the new samples of the 3 x 3
//   blocks around (no ghosting; not clamped when nothing at all changed
//   since the last frame, where the history is exact); failing that, an
//   estimate: a Gaussian (sigma 0.7 px) of the 5 x 5 pixels around that hold
//   a value traced this frame (or, in a still frame, in the history),
//   weighted down 1000x where their scene depth disagrees (no cloud bleeds
//   onto a ridge). The history marks estimates as T + 2 so they are
//   re-estimated, never kept as if traced.
// History rejection (CPU, each frame): reset (no history, sample index 0)
//   on FrameDesc::cloudResetHistory, a time step above
//   cloudHistoryMaxTimeStepHours, an eye step above cloudHistoryMaxMoveM, a
//   turn above cloudHistoryMaxTurnRad, the cloud block (except the wind
//   offsets and the shadow map's placement) changed while the time stood
//   still, new targets (size, precision, block), a re-solved sky, or a
//   previous frame without amortised clouds. A reset frame depends on
//   nothing from before: it is bit-identical to the first frame of a fresh
//   renderer.
//
// Reads:  as the reference (clouds.glsl), plus the previous history (unit
//         12) and linear depth (unit 13), the trace (unit 11).
// Writes: the colour (through its own two-attachment target), the history,
//         a copy of the linear depth.
// GL state: its own framebuffers and viewport during the trace; per-buffer
//         blending during the reconstruction; returns to the baseline
//         (sceneTarget, full viewport, blending off, depth writes on).
#include "frame_block.hpp"
#include "gl_state.hpp"
#include "render_pass.hpp"

#include <aerial/evaluate.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

namespace aerial::renderer::detail {
namespace {

/// The Bayer value of (x, y) in an n x n matrix (n a power of two).
int bayer(int x, int y, int n) {
    int value = 0;
    for (int bit = n / 2, weight = 1; bit > 0; bit /= 2) {
        const bool bx = (x & bit) != 0, by = (y & bit) != 0;
        value += weight * (by ? (bx ? 1 : 3) : (bx ? 2 : 0));  // 0 (0,0), 1 (1,1), 2 (1,0), 3 (0,1)
        weight *= 4;
    }
    return value;
}

/// The pixel of each block traced at sample index k (0..n^2 - 1).
std::array<int, 2> jitterOf(int k, int n) {
    // The coarsest bit gives the least significant digit, so consecutive
    // indices spread over the block; inverted by search (n^2 <= 16).
    for (int y = 0; y < n; ++y) {
        for (int x = 0; x < n; ++x) {
            if (bayer(x, y, n) == k) return {x, y};
        }
    }
    return {0, 0};
}

void deleteTargets(RendererResources::CloudHistory& h) {
    glDeleteTextures(1, &h.trace);
    glDeleteFramebuffers(1, &h.traceTarget);
    glDeleteTextures(2, h.history);
    glDeleteFramebuffers(2, h.target);
    glDeleteTextures(1, &h.previousDepth);
    h.trace = h.traceTarget = h.previousDepth = 0;
    h.history[0] = h.history[1] = h.target[0] = h.target[1] = 0;
    h.width = h.height = h.block = 0;
    h.valid = false;
}

void ensureTargets(RendererResources& gpu, int w, int h, int n, ColourPrecision precision) {
    RendererResources::CloudHistory& c = gpu.cloudHistory;
    if (c.width == w && c.height == h && c.block == n && c.precision == precision && c.trace != 0) return;
    deleteTargets(c);
    c.width = w;
    c.height = h;
    c.block = n;
    c.precision = precision;
    const GLenum format = precision == ColourPrecision::Float ? GL_RGBA32F : GL_RGBA16F;
    c.trace = makeTargetTexture(format, (w + n - 1) / n, (h + n - 1) / n);
    glCreateFramebuffers(1, &c.traceTarget);
    glNamedFramebufferTexture(c.traceTarget, GL_COLOR_ATTACHMENT0, c.trace, 0);
    const GLenum two[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    for (int k = 0; k < 2; ++k) {
        c.history[k] = makeTargetTexture(format, w, h);
        glCreateFramebuffers(1, &c.target[k]);
        glNamedFramebufferTexture(c.target[k], GL_COLOR_ATTACHMENT0, gpu.colour, 0);
        glNamedFramebufferTexture(c.target[k], GL_COLOR_ATTACHMENT1, c.history[k], 0);
        glNamedFramebufferDrawBuffers(c.target[k], 2, two);
    }
    c.previousDepth = makeTargetTexture(GL_R32F, w, h);
    c.valid = false;
}

/// The emitters' numbers (a change there, e.g. a lightning flash, means the
/// frame is not still).
std::vector<double> emitterNumbers(const PresetState& state, bool on) {
    std::vector<double> out;
    if (!on) return out;
    for (const Emitter& e : state.emitters) {
        out.insert(out.end(), {e.position.x, e.position.y, e.position.z, e.intensity, e.intensityCd, e.attenuation,
                               e.colour.x, e.colour.y, e.colour.z});
    }
    return out;
}

/// The cloud block's bytes that describe the clouds: all but the wind
/// offsets (the first 16 bytes) and the shadow map's placement (112..160).
bool sameCloudParameters(const CloudBlock& a, const CloudBlock& b) {
    const auto* pa = reinterpret_cast<const unsigned char*>(&a);
    const auto* pb = reinterpret_cast<const unsigned char*>(&b);
    constexpr std::size_t shadowBegin = offsetof(CloudBlock, shadowOrigin);
    constexpr std::size_t shadowEnd = offsetof(CloudBlock, groundAlbedo);
    constexpr std::size_t paramsBegin = offsetof(CloudBlock, planetRadius);
    return std::memcmp(pa + paramsBegin, pb + paramsBegin, shadowBegin - paramsBegin) == 0 &&
           std::memcmp(pa + shadowEnd, pb + shadowEnd, sizeof(CloudBlock) - shadowEnd) == 0;
}

double finiteOr(double v, double fallback) { return std::isfinite(v) && v >= 0.0 ? v : fallback; }

}  // namespace

void forgetCloudHistory(RendererResources& gpu) { gpu.cloudHistory.valid = false; }

void destroyCloudHistory(RendererResources& gpu) { deleteTargets(gpu.cloudHistory); }

void drawAmortisedClouds(FrameContext& f) {
    RendererResources& gpu = f.gpu;
    RendererResources::CloudHistory& c = gpu.cloudHistory;
    const int w = int(f.block.viewportSize[0]), h = int(f.block.viewportSize[1]);
    const int n = std::clamp(f.desc.cloudAmortisedBlock, 2, 4) == 2 ? 2 : 4;
    ensureTargets(gpu, w, h, n, f.desc.precision);

    // Keep the history, or say why not.
    CloudHistoryStats& stats = f.stats.cloudHistory;
    stats = CloudHistoryStats{};
    stats.amortised = true;
    const std::vector<double> emitters = emitterNumbers(f.state, f.desc.passes.emitters);
    double timeStep = std::fabs(f.state.timeHours - c.timeHours);
    timeStep = std::isfinite(timeStep) ? std::min(timeStep, std::fabs(24.0 - timeStep)) : 1e30;  // 24 h wrap
    const double turn = std::acos(std::clamp(glm::dot(f.view.forward, c.forward), -1.0, 1.0));
    const bool sameParameters = sameCloudParameters(f.cloudBlock, c.cloudBlock);
    if (!c.valid) {
        stats.resetReason = "first frame";
    } else if (f.desc.cloudResetHistory) {
        stats.resetReason = "requested";
    } else if (!(timeStep <= finiteOr(f.desc.cloudHistoryMaxTimeStepHours, 2.0 / 60.0))) {
        stats.resetReason = "time jump";
    } else if (!(glm::length(f.view.eye - c.eye) <= finiteOr(f.desc.cloudHistoryMaxMoveM, 25.0)) ||
               !(turn <= finiteOr(f.desc.cloudHistoryMaxTurnRad, 0.26))) {
        stats.resetReason = "camera jump";
    } else if (!sameParameters && timeStep == 0.0) {
        stats.resetReason = "cloud parameters";
    }
    stats.historyUsed = stats.resetReason[0] == '\0';
    stats.still = stats.historyUsed && sameParameters &&
                  std::memcmp(&f.block, &c.frameBlock, sizeof(FrameBlock)) == 0 &&
                  std::memcmp(&f.cloudBlock, &c.cloudBlock, sizeof(CloudBlock)) == 0 &&
                  emitters == c.emitters;
    stats.sampleIndex = stats.historyUsed ? (c.sampleIndex + 1) % (n * n) : 0;
    const std::array<int, 2> jitter = jitterOf(stats.sampleIndex, n);

    // Pass 1: the trace.
    const GLuint trace = gpu.shaders.program(Pass::Clouds);
    glProgramUniform3i(trace, 0, jitter[0], jitter[1], n);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, c.traceTarget);
    glViewport(0, 0, (w + n - 1) / n, (h + n - 1) / n);
    glDepthMask(GL_FALSE);
    drawFullscreen(gpu, Pass::Clouds);
    glViewport(0, 0, w, h);

    // Pass 2: reconstruction and composite.
    const int previous = c.current, next = 1 - c.current;
    const GLuint reconstruct = gpu.shaders.program(Pass::CloudReconstruct);
    float previousClip[16];
    for (int col = 0; col < 4; ++col) {
        for (int row = 0; row < 4; ++row) previousClip[4 * col + row] = float(c.clipFromWorld[col][row]);
    }
    const int mode = !stats.historyUsed ? 0 : stats.still ? 2 : 1;
    glProgramUniformMatrix4fv(reconstruct, 0, 1, GL_FALSE, previousClip);
    glProgramUniform4i(reconstruct, 1, jitter[0], jitter[1], n, mode);
    // The layer's drift since the previous frame [m] (the wind offset of
    // clouds.hpp is wind x time): the signed time step, across midnight too.
    double stepHours = f.state.timeHours - c.timeHours;
    stepHours -= 24.0 * std::round(stepHours / 24.0);
    const glm::dvec2 wind = f.clouds->params.windMPerS * (stepHours * 3600.0);
    const bool windOk = std::isfinite(wind.x) && std::isfinite(wind.y) && stats.historyUsed;
    glProgramUniform2f(reconstruct, 2, windOk ? float(wind.x) : 0.0f, windOk ? float(wind.y) : 0.0f);
    glBindTextureUnit(kCloudTraceUnit, c.trace);
    glBindTextureUnit(kCloudHistoryUnit, c.history[previous]);
    glBindTextureUnit(kPreviousDepthUnit, c.previousDepth);
    for (unsigned unit : {kCloudTraceUnit, kCloudHistoryUnit, kPreviousDepthUnit}) glBindSampler(unit, 0);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, c.target[next]);
    glEnablei(GL_BLEND, 0);
    glDisablei(GL_BLEND, 1);
    glBlendEquationSeparate(GL_FUNC_ADD, GL_FUNC_ADD);
    glBlendFuncSeparate(GL_ONE, GL_SRC_ALPHA, GL_ZERO, GL_ONE);
    drawFullscreen(gpu, Pass::CloudReconstruct);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, gpu.sceneTarget);

    // Remember this frame.
    glCopyImageSubData(gpu.linearDepth, GL_TEXTURE_2D, 0, 0, 0, 0, c.previousDepth, GL_TEXTURE_2D, 0, 0, 0, 0,
                       w, h, 1);
    c.current = next;
    c.valid = true;
    c.sampleIndex = stats.sampleIndex;
    c.clipFromWorld = f.view.clipFromWorld;
    c.eye = f.view.eye;
    c.forward = f.view.forward;
    c.timeHours = f.state.timeHours;
    c.frameBlock = f.block;
    c.cloudBlock = f.cloudBlock;
    c.emitters = emitters;
}

}  // namespace aerial::renderer::detail
