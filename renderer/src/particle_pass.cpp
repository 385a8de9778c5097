// particle_pass.cpp — pass 7: soft fog particles (SceneDesc::sprites),
// camera-facing sprites back to front by view depth, faded by the scene
// depth (shaders/particles.glsl): premultiplied "over" the frame.
//
// Reads:  the scene's sprites (sanitised at setScene), FrameBlock (lights,
//         sky ambient, global fog per vertex), the emitters, linear depth
//         (unit 4), the frame's CPU fog (FrameContext::localFog: one query
//         per sprite, at its centre), the depth buffer.
// Writes: the sprite instance buffer; the colour, through compositeTarget
//         (no depth writes); RenderStats::spritesDrawn.
// GL state: beginComposite with glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA)
//         for colour (alpha kept), depth test on (GL_LEQUAL); off again and
//         endComposite on exit.
#include "frame_block.hpp"
#include "render_pass.hpp"

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <utility>

namespace aerial::renderer::detail {
namespace {

bool runs(const FrameContext& f) { return f.desc.passes.particles && !f.gpu.sprites.empty(); }

void draw(FrameContext& f) {
    RendererResources& gpu = f.gpu;
    const std::vector<FogSprite>& sprites = gpu.sprites;
    const CameraFrame& cam = f.view;
    const FogScene& fog = f.localFog();
    std::vector<std::pair<double, std::size_t>> order;  // (view depth, sprite)
    order.reserve(sprites.size());
    for (std::size_t i = 0; i < sprites.size(); ++i)
        order.emplace_back(glm::dot(sprites[i].position - cam.eye, cam.forward), i);
    std::stable_sort(order.begin(), order.end(),
                     [](const auto& a, const auto& b) { return a.first > b.first; });
    std::vector<SpriteInstance> instances;
    instances.reserve(order.size());
    for (const auto& entry : order) {
        const FogSprite& p = sprites[entry.second];
        if (entry.first + p.radius < cam.nearDistance) continue;  // wholly behind the eye
        SpriteInstance in;
        // The volumes' and emitters' fog in front of the sprite, at its centre.
        const FogQueryResult q = fog.query(cam.eye, p.position);
        const glm::dvec4 values[4] = {
            glm::dvec4(p.position, p.radius), glm::dvec4(p.albedo, p.opacity),
            glm::dvec4(p.emission, p.fadeDistance),
            glm::dvec4(colourOf(q.inScatter), std::clamp(q.transmittance.x, 0.0, 1.0))};
        float* targets[4] = {in.centreRadius, in.albedoOpacity, in.emissionFade, in.localFog};
        for (int a = 0; a < 4; ++a) {
            for (int c = 0; c < 4; ++c) targets[a][c] = static_cast<float>(values[a][c]);
        }
        instances.push_back(in);
    }
    if (instances.empty()) return;
    glNamedBufferData(gpu.spriteBuffer, static_cast<GLsizeiptr>(instances.size() * sizeof(SpriteInstance)),
                      instances.data(), GL_STREAM_DRAW);
    beginComposite(gpu, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glUseProgram(gpu.shaders.program(Pass::Particles));
    glBindVertexArray(gpu.spriteArray);
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(instances.size()));
    glDisable(GL_DEPTH_TEST);
    endComposite(gpu);
    f.stats.spritesDrawn = static_cast<int>(instances.size());
}

}  // namespace

const RenderPass kParticlePass{&PassTimes::particles, runs, draw};

}  // namespace aerial::renderer::detail
