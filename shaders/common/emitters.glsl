// common/emitters.glsl — the point emitters of the frame (EmitterGpu in
// renderer/src/gpu_types.hpp, std430, binding 2; uploaded by
// renderer/src/emitter_pass.cpp, frame.emitterCount of them), read by the
// emitter pass, the scene and transparent shading and the particles.
#ifndef AERIAL_EMITTERS_GLSL
#define AERIAL_EMITTERS_GLSL

struct EmitterGpu {
    vec3 position;      // [m]
    float intensity;    // i [1/m], lightning flash applied
    vec3 colour;        // rgb
    float attenuation;  // a [1/m^2]
};
layout(std430, binding = 2) readonly buffer EmitterBlock { EmitterGpu emitters[]; };

#endif
