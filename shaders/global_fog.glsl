// global_fog.glsl — the global height-fog pass (DESIGN.md, "Global height
// fog"; Wenzel 2006, section 6.4): full screen, analytic integral of
// f(p) = b exp(-c (p.y - h0)) from the eye to the pixel's scene point.
//
// Inputs:
//   frame (common/frame.glsl): eye [m], far-plane corner rays, fog b [1/m],
//     c [1/m], h0 [m], colour mode and colour, lights for the sky's fog colour
//   uLinearDepth (unit 4): normalised linear eye depth z/far (sky = 1: the
//     sky is fogged up to the far plane)
// Output (location 0), blended with glBlendFunc(GL_ONE, GL_SRC_ALPHA):
//   rgb = L_fog(v) (1 - T), a = T, T = exp(-integral f), so the target becomes
//   L = L_scene T + L_fog (1 - T); L_fog(v, s) is the light that reaches
//   the fog blended into the horizon with the scene point's distance s
//   (FogScene::fogColour, aerial/fog_light.hpp) in colour mode "sky".
// Subtract volumes (frame.subtractActive): the integral runs over the
// segment minus the pixel's subtract union (common/subtract.glsl), the sum
// over the gaps; without them the plain integral, bit for bit as before.
#include "common/frame.glsl"

#ifdef AERIAL_VERTEX_SHADER
#include "common/fullscreen.glsl"
#else
#include "common/atmosphere.glsl"
#include "common/subtract.glsl"

layout(binding = 4) uniform sampler2D uLinearDepth;

in vec3 vFarRay;
layout(location = 0) out vec4 outColour;

void main() {
    float depth01 = texelFetch(uLinearDepth, ivec2(gl_FragCoord.xy), 0).r;
    vec3 d = depth01 * vFarRay;  // eye -> scene point [m]
    float tau = globalFogOpticalDepth(d);
    if (frame.subtractActive != 0) {
        tau = maskedExponentialDepth(ivec2(gl_FragCoord.xy), frame.fogDensity, frame.fogFalloff,
                                     frame.eye.y - frame.fogBaseHeight, vFarRay.y, length(vFarRay), 0.0,
                                     depth01);
    }
    outColour = fogInScatterTransmittance(frame.fogColourMode, frame.fogColour, normalize(vFarRay),
                                          depth01 * length(vFarRay), tau);
}
#endif
