// mesh_volume_composite.glsl — a mesh add volume, step 2 of 2: full
// screen (scissored to the volume's screen bounds), the accumulated sums of
// mesh_volume_accumulate.glsl become the volume's optical depth
//   tau = R + G integral(0, tRef)   (common/mesh_volume.glsl)
// and the volume is composited as a box volume: L <- L T + C (1 - T).
//
// Inputs:
//   frame (common/frame.glsl), VolumeBlock (binding 1: density, gradient,
//     colour mode and colour), uAccumulation (unit 5: RG32F, R = sum s F,
//     G = sum s), SubtractIntervals (storage 4, when active)
// Output (location 0), blended with glBlendFunc(GL_ONE, GL_SRC_ALPHA):
//   fogInScatterTransmittance (common/atmosphere.glsl); pixels the mesh
//   does not cover are discarded (tau would be 0: no change).
#include "common/frame.glsl"

#ifdef AERIAL_VERTEX_SHADER
#include "common/fullscreen.glsl"
#else
#include "common/volume.glsl"
#include "common/atmosphere.glsl"
#include "common/subtract.glsl"
#include "common/mesh_volume.glsl"

layout(binding = 5) uniform sampler2D uAccumulation;

in vec3 vFarRay;
layout(location = 0) out vec4 outColour;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec2 sums = texelFetch(uAccumulation, pixel, 0).rg;
    if (sums.x == 0.0 && sums.y == 0.0) discard;
    vec3 farRay = farRayAtFragment(gl_FragCoord.xy);
    float tRef = meshVolumeReference(farRay);
    float tau = sums.x + sums.y * meshVolumeDepth(pixel, farRay, 0.0, tRef);
    tau = tau > 0.0 ? min(tau, kMaxOpticalDepth) : 0.0;  // rounding may leave a tiny negative; NaN -> 0
    // The fog colour of the pixel's whole sight line, to its scene point (fog_light.hpp).
    float sceneDistance = texelFetch(uLinearDepth, ivec2(gl_FragCoord.xy), 0).r * length(farRay);
    outColour = fogInScatterTransmittance(volume.colourMode, volume.colour, normalize(farRay), sceneDistance, tau);
}
#endif
