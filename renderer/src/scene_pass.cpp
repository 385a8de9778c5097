// scene_pass.cpp — pass 1: opaque and alpha-masked meshes (shaders/scene.glsl).
//
// Reads:  the scene's meshes (alpha mode opaque or mask) and their
//         base-colour textures, FrameBlock, the emitters, the sky tables.
// Writes: sceneTarget: HDR colour (attachment 0), normalised linear depth
//         (attachment 1) and the depth buffer; the ObjectBlock per mesh.
// GL state: enables the depth test (GL_LESS) with depth writes for its
//         draws, binds each mesh's vertex array and base-colour texture
//         (unit 5); disables the depth test again on exit.
#include "render_pass.hpp"

namespace aerial::renderer::detail {
namespace {

bool runs(const FrameContext& f) { return f.desc.passes.scene && !f.gpu.meshes.empty(); }

void draw(FrameContext& f) {
    RendererResources& gpu = f.gpu;
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glUseProgram(gpu.shaders.program(Pass::Scene));
    for (const GpuMesh& m : gpu.meshes) {
        if (m.alphaMode == AlphaMode::Blend) continue;
        glNamedBufferSubData(gpu.objectBuffer, 0, sizeof m.block, &m.block);
        glBindTextureUnit(kBaseColourUnit, m.texture != 0 ? m.texture : gpu.whiteTexture);
        glBindVertexArray(m.vertexArray);
        glDrawElements(GL_TRIANGLES, m.indexCount, GL_UNSIGNED_INT, nullptr);
    }
    glDisable(GL_DEPTH_TEST);
}

}  // namespace

const RenderPass kScenePass{&PassTimes::scene, runs, draw};

}  // namespace aerial::renderer::detail
