// global_fog_pass.cpp — pass 3: the global height fog over every pixel
// (shaders/global_fog.glsl): L <- L T_g + L_fog (1 - T_g).
//
// Reads:  FrameBlock (eye, corner rays, fog density / falloff / base height,
//         colour mode and colour, lights), linear depth (unit 4).
// Writes: the colour, through compositeTarget (no depth writes).
// GL state: beginComposite with glBlendFunc(GL_ONE, GL_SRC_ALPHA) for colour
//         (alpha kept), depth test off; endComposite on exit. Runs only when
//         the fog density is positive.
#include "render_pass.hpp"

namespace aerial::renderer::detail {
namespace {

bool runs(const FrameContext& f) {
    return f.desc.fogMode == FogMode::Analytic && f.desc.passes.globalFog && f.block.fogDensity > 0.0f;
}

void draw(FrameContext& f) { compositeFullscreen(f.gpu, Pass::GlobalFog, GL_ONE, GL_SRC_ALPHA); }

}  // namespace

const RenderPass kGlobalFogPass{&PassTimes::globalFog, runs, draw};

}  // namespace aerial::renderer::detail
