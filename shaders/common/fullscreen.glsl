// common/fullscreen.glsl — vertex stage of the full-screen passes: one
// triangle covering the viewport, no vertex buffer (gl_VertexID 0..2).
//
// Outputs: vFarRay, the ray from the eye to the far plane [m] (world space),
// interpolated by the rasteriser from the frustum's far-plane corner rays
// (Wenzel 2006, section 6.3), so the fragment stage reconstructs the world
// position with worldFromDepth(depth01, vFarRay).
// Requires common/frame.glsl.
#ifndef AERIAL_FULLSCREEN_GLSL
#define AERIAL_FULLSCREEN_GLSL

out vec3 vFarRay;

void main() {
    // (-1,-1), (3,-1), (-1,3): the viewport is the lower-left quarter.
    vec2 ndc = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0);
    vFarRay = farRayAtNdc(ndc);  // affine in ndc: exact under linear interpolation
    gl_Position = vec4(ndc, 1.0, 1.0);
}

#endif
