// cloud_shadow_pass.cpp — pass 0: the cloud shadow map
// (shaders/cloud_shadow.glsl). A kCloudShadowSize^2 R32F texture over a
// kCloudShadowExtentM square of ground around the eye (placement in
// makeCloudBlock); each texel holds the optical depth from its ground point
// (height 0) towards the light through the cloud layer, core's
// cloudSunVisibility march (kCloudSunVisibilitySteps samples). The shading
// of the scene, transparent meshes and particles projects a point along the
// light onto the map's plane and multiplies the sun and moon by
// exp(-optical depth) (common/clouds.glsl, cloudShadowVisibility).
//
// Reads:  CloudBlock (binding 4), the noise (units 8, 9).
// Writes: gpu.cloudShadowMap through gpu.cloudShadowTarget.
// GL state: binds the shadow target and a kCloudShadowSize viewport; on exit
//         the sceneTarget and the frame's viewport again (the baseline).
#include "render_pass.hpp"

namespace aerial::renderer::detail {
namespace {

bool runs(const FrameContext& f) { return f.cloudsDrawn() && f.gpu.cloudShadowTarget != 0; }

void draw(FrameContext& f) {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, f.gpu.cloudShadowTarget);
    glViewport(0, 0, kCloudShadowSize, kCloudShadowSize);
    drawFullscreen(f.gpu, Pass::CloudShadow);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, f.gpu.sceneTarget);
    glViewport(0, 0, static_cast<GLsizei>(f.block.viewportSize[0]),
               static_cast<GLsizei>(f.block.viewportSize[1]));
}

}  // namespace

const RenderPass kCloudShadowPass{&PassTimes::cloudShadow, runs, draw};

}  // namespace aerial::renderer::detail
