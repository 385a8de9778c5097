// transparent_pass.cpp — pass 6: alpha-blended meshes (glTF alpha mode
// "blend"), back to front by the distance from the eye to the centre of
// their world bounds, back faces of a mesh before its front faces
// (shaders/transparent.glsl): premultiplied "over" the fogged frame.
//
// Reads:  the scene's blend meshes and textures, FrameBlock (global fog per
//         vertex), the emitters, the sky tables, the frame's CPU fog
//         (FrameContext::localFog: volumes and emitters, queried at the 8
//         corners of each mesh's world bounds), the depth buffer.
// Writes: the colour, through compositeTarget (no depth writes); the
//         ObjectBlock per mesh (with its corner fog);
//         RenderStats::transparentDrawn.
// GL state: beginComposite with glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA)
//         for colour (alpha kept), depth test on (GL_LEQUAL, against the
//         opaque scene), face culling on (front, then back, per mesh); all
//         off again and endComposite on exit.
#include "frame_block.hpp"
#include "render_pass.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <utility>

namespace aerial::renderer::detail {
namespace {

bool runs(const FrameContext& f) {
    return f.desc.passes.transparent &&
           std::any_of(f.gpu.meshes.begin(), f.gpu.meshes.end(),
                       [](const GpuMesh& m) { return m.alphaMode == AlphaMode::Blend; });
}

void draw(FrameContext& f) {
    RendererResources& gpu = f.gpu;
    const std::vector<GpuMesh>& meshes = gpu.meshes;
    const CameraFrame& cam = f.view;
    const FogScene& fog = f.localFog();
    std::vector<std::pair<double, std::size_t>> order;  // (distance to the bounds centre, mesh)
    for (std::size_t i = 0; i < meshes.size(); ++i) {
        if (meshes[i].alphaMode != AlphaMode::Blend) continue;
        order.emplace_back(glm::length(0.5 * (meshes[i].boundsMin + meshes[i].boundsMax) - cam.eye), i);
    }
    // Back to front; equal distances keep the scene order.
    std::stable_sort(order.begin(), order.end(),
                     [](const auto& a, const auto& b) { return a.first > b.first; });
    // Volumes and emitters per object from the CPU (the global fog is per
    // vertex on the GPU and composited first, as fog_query.hpp's contract).
    beginComposite(gpu, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glUseProgram(gpu.shaders.program(Pass::Transparent));
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glEnable(GL_CULL_FACE);
    for (const auto& entry : order) {
        const GpuMesh& m = meshes[entry.second];
        ObjectBlock block = m.block;
        for (int k = 0; k < 8; ++k) {
            const glm::dvec3 corner((k & 1) ? m.boundsMax.x : m.boundsMin.x,
                                    (k & 2) ? m.boundsMax.y : m.boundsMin.y,
                                    (k & 4) ? m.boundsMax.z : m.boundsMin.z);
            const FogQueryResult q = fog.query(cam.eye, corner);
            block.cornerFog[k] = toVec4(colourOf(q.inScatter), std::clamp(q.transmittance.x, 0.0, 1.0));
        }
        glNamedBufferSubData(gpu.objectBuffer, 0, sizeof block, &block);
        glBindTextureUnit(kBaseColourUnit, m.texture != 0 ? m.texture : gpu.whiteTexture);
        glBindVertexArray(m.vertexArray);
        // Back faces first, then front faces: a closed convex mesh blends in
        // the right order without sorting its triangles.
        glCullFace(GL_FRONT);
        glDrawElements(GL_TRIANGLES, m.indexCount, GL_UNSIGNED_INT, nullptr);
        glCullFace(GL_BACK);
        glDrawElements(GL_TRIANGLES, m.indexCount, GL_UNSIGNED_INT, nullptr);
        ++f.stats.transparentDrawn;
    }
    glDisable(GL_CULL_FACE);
    glDisable(GL_DEPTH_TEST);
    endComposite(gpu);
}

}  // namespace

const RenderPass kTransparentPass{&PassTimes::transparent, runs, draw};

}  // namespace aerial::renderer::detail
