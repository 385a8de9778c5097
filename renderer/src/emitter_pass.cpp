// emitter_pass.cpp — pass 5: the in-scatter of every point emitter along
// each pixel's eye -> scene segment, added on top (shaders/emitters.glsl):
// L <- L + S_e. Also the upload of the emitters, which the scene,
// transparent and particle shaders read too.
//
// Reads:  FrameBlock (eye, corner rays, emitter count), the emitter buffer
//         (std430, binding 2), linear depth (unit 4).
// Writes: the colour, through compositeTarget (no depth writes); at upload,
//         the emitter buffer.
// GL state: beginComposite with glBlendFunc(GL_ONE, GL_ONE) for colour
//         (alpha kept), depth test off; endComposite on exit.
#include "frame_block.hpp"
#include "render_pass.hpp"

#include <aerial/finite.hpp>

#include <algorithm>
#include <cmath>

namespace aerial::renderer::detail {

int uploadEmitters(RendererResources& gpu, const std::vector<Emitter>& emitters) {
    std::vector<EmitterGpu> packed;
    packed.reserve(emitters.size());
    for (const Emitter& e : emitters) {
        const bool positionOk = withinCoordinateRange(e.position);
        const double intensity = nonNegative(e.intensity, 1e30);
        const double illuminance = emitterIlluminance(e);
        if (!positionOk || !(intensity > 0.0 || illuminance > 0.0)) continue;
        EmitterGpu g;
        g.position = toVec3(e.position);
        g.intensity = static_cast<float>(intensity);
        g.illuminance = static_cast<float>(std::min(illuminance, 1e30));
        g.extinction = static_cast<float>(nonNegative(e.extinction, 1e30));
        g.colour = toVec3(colourOf(e.colour));
        g.attenuation = static_cast<float>(nonNegative(e.attenuation, 1e30));
        packed.push_back(g);
    }
    const auto bytes = static_cast<GLsizeiptr>(std::max<std::size_t>(packed.size(), 1) * sizeof(EmitterGpu));
    if (bytes > gpu.emitterCapacity) {
        glDeleteBuffers(1, &gpu.emitterBuffer);
        glCreateBuffers(1, &gpu.emitterBuffer);
        glNamedBufferData(gpu.emitterBuffer, bytes, nullptr, GL_DYNAMIC_DRAW);
        gpu.emitterCapacity = bytes;
    }
    if (!packed.empty()) {
        glNamedBufferSubData(gpu.emitterBuffer, 0,
                             static_cast<GLsizeiptr>(packed.size() * sizeof(EmitterGpu)), packed.data());
    }
    return static_cast<int>(packed.size());
}

namespace {

bool runs(const FrameContext& f) {
    return f.desc.fogMode == FogMode::Analytic && f.desc.passes.emitters && f.block.emitterCount > 0;
}

void draw(FrameContext& f) { compositeFullscreen(f.gpu, Pass::Emitters, GL_ONE, GL_ONE); }

}  // namespace

const RenderPass kEmitterPass{&PassTimes::emitters, runs, draw};

}  // namespace aerial::renderer::detail
