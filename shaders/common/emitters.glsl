// common/emitters.glsl — the point emitters of the frame (EmitterGpu in
// renderer/src/gpu_types.hpp, std430, binding 2; uploaded by
// renderer/src/emitter_pass.cpp, frame.emitterCount of them), read by the
// emitter pass, the scene and transparent shading and the particles.
#ifndef AERIAL_EMITTERS_GLSL
#define AERIAL_EMITTERS_GLSL

struct EmitterGpu {
    vec3 position;      // [m]
    float intensity;    // i [radiance unit/m]: the fog's in-scatter next to it, flash applied
    vec3 colour;        // rgb, unit luminance
    float attenuation;  // a [1/m^2]
    vec4 light;         // x: e = a I / kNitsPerRadianceUnit, E(r) = e / (1 + a r^2) on surfaces and clouds;
                        // y: extinction sigma_t [1/m], the light dimmed by exp(-sigma_t distance)
};
layout(std430, binding = 2) readonly buffer EmitterBlock { EmitterGpu emitters[]; };

/// atan(z) / z for z >= 0, 1 at 0.
float atanOverX(float z) { return z > 1e-4 ? atan(z) / z : 1.0 - z * z / 3.0; }

/// Integral of i / (1 + a |l - p|^2) along o -> o + d, in the
/// cancellation-free form of core/src/emitters/emitter.cpp (emitters.glsl, and the
/// volumetric fog's slices in froxel_inject.glsl).
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

/// exp(-sigma_t |l - p|): the air's extinction between emitter k and p
/// (core's emitterInScatter with p the segment's start; surfaces, clouds).
float emitterDimming(int k, vec3 p) {
    float sigma = emitters[k].light.y;
    return sigma > 0.0 ? exp(-sigma * length(emitters[k].position - p)) : 1.0;
}

#endif
