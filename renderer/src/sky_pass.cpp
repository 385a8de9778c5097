// sky_pass.cpp — pass 2: the sky, sun and moon discs and stars where no
// geometry is (shaders/sky.glsl).
//
// Reads:  FrameBlock (lights, table mapping, star frame), the sky tables
//         (units 0..3), the depth buffer of the scene pass.
// Writes: sceneTarget's colour (attachment 0) only, at pixels whose depth is
//         still 1: a full-screen triangle at the far plane, depth-tested
//         with GL_LEQUAL, so only uncovered pixels run the sky shader.
// GL state: draws to attachment 0 alone, depth test on (GL_LEQUAL) without
//         depth writes; restores both draw buffers, depth writes on and the
//         depth test off on exit.
#include "render_pass.hpp"

namespace aerial::renderer::detail {
namespace {

bool runs(const FrameContext& f) { return f.desc.passes.sky; }

void draw(FrameContext& f) {
    const GLuint target = f.gpu.sceneTarget;
    const GLenum colourOnly[2] = {GL_COLOR_ATTACHMENT0, GL_NONE};
    glNamedFramebufferDrawBuffers(target, 2, colourOnly);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_FALSE);
    drawFullscreen(f.gpu, Pass::Sky);
    const GLenum both[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glNamedFramebufferDrawBuffers(target, 2, both);
    glDepthMask(GL_TRUE);
    glDisable(GL_DEPTH_TEST);
}

}  // namespace

const RenderPass kSkyPass{&PassTimes::sky, runs, draw};

}  // namespace aerial::renderer::detail
