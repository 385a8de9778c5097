// emitters.glsl — lit fog: every point emitter's closed-form in-scatter along
// the eye -> scene segment, added on top (DESIGN.md, "Emitters"; Wenzel 2006,
// section 6.9.2).
//
// Inputs:
//   frame (common/frame.glsl): eye, far-plane corner rays, emitter count
//   Emitters (common/emitters.glsl; std430 SSBO, binding 2): per emitter
//     position [m], intensity i [1/m] (flash applied), colour (rgb) and
//     attenuation a [1/m^2]
//   uLinearDepth (unit 4): normalised linear eye depth
// Output (location 0), blended with glBlendFunc(GL_ONE, GL_ONE):
//   rgb = sum colour * integral f, f(p) = i / (1 + a |l - p|^2), in the
//   cancellation-free form of core/src/emitters/emitter.cpp:
//   integral f = (i / K) atan2(L K, X), K = sqrt(a) sqrt(1 + a |c x n|^2),
//   X = 1 + a c.(c - d), c = l - o, n = d / L.
#include "common/frame.glsl"

#ifdef AERIAL_VERTEX_SHADER
#include "common/fullscreen.glsl"
#else
#include "common/atmosphere.glsl"

#include "common/emitters.glsl"
layout(binding = 4) uniform sampler2D uLinearDepth;

in vec3 vFarRay;
layout(location = 0) out vec4 outColour;

void main() {
    float depth01 = texelFetch(uLinearDepth, ivec2(gl_FragCoord.xy), 0).r;
    vec3 o = frame.eye;
    vec3 d = depth01 * vFarRay;
    vec3 sum = vec3(0.0);
    for (int k = 0; k < frame.emitterCount; ++k) {
        EmitterGpu em = emitters[k];
        sum += em.colour * emitterIntegral(em.position, em.intensity, em.attenuation, o, d) *
               emitterDimming(k, o);
    }
    outColour = vec4(min(sum, vec3(frame.radianceCap)), 1.0);
}
#endif
