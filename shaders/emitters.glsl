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
//   cancellation-free form of core/src/emitter.cpp:
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

/// atan(z) / z for z >= 0, 1 at 0.
float atanOverX(float z) { return z > 1e-4 ? atan(z) / z : 1.0 - z * z / 3.0; }

/// Integral of i / (1 + a |l - p|^2) along o -> o + d (emitterIntegral).
float emitterIntegral(vec3 l, float i, float a, vec3 o, vec3 d) {
    float len = length(d);
    if (!(i > 0.0) || !(len > 0.0)) return 0.0;
    a = max(a, 0.0);
    vec3 n = d / len;
    vec3 c = l - o;  // the emitter seen from the start
    vec3 e = c - d;  // ... from the end
    vec3 cr = cross(c, n);
    float k = sqrt(a) * sqrt(1.0 + a * dot(cr, cr));
    float x = 1.0 + a * dot(c, e);
    float y = len * k;
    const float kHalfPi = 1.57079632679490;
    return (y < x) ? i * len * atanOverX(y / x) / x : i * (kHalfPi - atan(x / y)) / k;
}

void main() {
    float depth01 = texelFetch(uLinearDepth, ivec2(gl_FragCoord.xy), 0).r;
    vec3 o = frame.eye;
    vec3 d = depth01 * vFarRay;
    vec3 sum = vec3(0.0);
    for (int k = 0; k < frame.emitterCount; ++k) {
        EmitterGpu em = emitters[k];
        sum += em.colour *
               emitterIntegral(em.position, em.intensity, em.attenuation, o, d);
    }
    outColour = vec4(min(sum, vec3(frame.radianceCap)), 1.0);
}
#endif
