// cloud_shadow.glsl — the cloud shadow map (renderer/src/cloud_shadow_pass.cpp):
// per texel, the optical depth from its ground point towards the light
// through the cloud layer, core's cloudSunVisibility march
// (kCloudSunVisibilitySteps midpoint samples over the shell segments).
//
// Inputs: CloudBlock (common/clouds.glsl: shadowOrigin, shadowExtentM,
//   shadowToLight, shadowSteps and the layer), the noise (units 8, 9).
// Output (location 0, R32F): tau >= 0 (dimensionless) for the ground point
//   (shadowOrigin + (texel + 0.5) shadowExtentM / size, height 0); the
//   lighting reads exp(-tau) (cloudShadowVisibility).
#include "common/frame.glsl"

#ifdef AERIAL_VERTEX_SHADER
#include "common/fullscreen.glsl"
#else
#include "common/clouds.glsl"

layout(location = 0) out vec4 outDepth;

void main() {
    vec2 xz = clouds.shadowOrigin + gl_FragCoord.xy / clouds.shadowSize * clouds.shadowExtentM;
    float tau = cloudOpticalDepth(vec3(xz.x, 0.0, xz.y), clouds.shadowToLight, 1.0e30, clouds.shadowSteps);
    outDepth = vec4(tau, 0.0, 0.0, 1.0);
}
#endif
