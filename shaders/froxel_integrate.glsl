// froxel_integrate.glsl — volumetric fog, stage 2 (compute): integrate each
// froxel column front to back (Hillaire 2015, "Physically Based and Unified
// Volumetric Rendering in Frostbite", the energy-conserving slice).
//
// A slice of optical depth tau = sigma_t d whose in-scattered radiance per
// unit length is S = sigma_s L_in (constant over the slice) adds
//   integral_0^d S e^(-sigma_t s) ds = (S - S e^(-sigma_t d)) / sigma_t
//                                    = L_in (sigma_s / sigma_t) (1 - e^-tau)
// in front of what lies behind it, seen through the transmittance T of the
// slices before it. In DESIGN.md's terms, with sigma_s = sigma_t = the fog's
// density (fog scatters what it extinguishes) and L_in its colour: a slice
// adds T L_fog (1 - e^-tau), and the sum over slices is exactly the analytic
// L_fog (1 - T_total) of the composite "L T + L_fog (1 - T)" when nothing is
// shadowed, whatever the slice count (tau of a slice is its exact integral).
// Per medium i of the slice that becomes T (1 - e^-tau)/tau x tau_i x its
// colour: stage 1's W sums, weighted by f = (1 - e^-tau)/tau (the slice's
// mean transmittance; emitters' exact integrals take it too).
//
// Output, layer k = from the eye to z(k/N) (layer 0: nothing), RGBA32F:
//   image 0 = (sum T f W_sky V, T)   the sky-coloured fog lit by the casting
//                                    light's shadowable part, and T
//   image 1 = (sum T f W_sky, 0)     the same without the visibility
//   image 2 = (sum T f W_own, 0)     custom-coloured media and emitters (radiance)
// froxel_apply.glsl multiplies the first two by the per-pixel fog colours.
#include "common/frame.glsl"
#include "common/atmosphere.glsl"
#include "common/froxel.glsl"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(rgba32f, binding = 0) uniform readonly image3D uMedium;  // stage 1: (W_sky, tau)
layout(rgba32f, binding = 1) uniform readonly image3D uLight;   // stage 1: (W_own, V)
layout(rgba32f, binding = 2) uniform writeonly image3D uLitSky;
layout(rgba32f, binding = 3) uniform writeonly image3D uSky;
layout(rgba32f, binding = 4) uniform writeonly image3D uOwn;

void main() {
    ivec2 id = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(id, froxel.gridSize.xy))) return;
    float transmittance = 1.0;
    vec3 litSky = vec3(0.0), sky = vec3(0.0), own = vec3(0.0);
    imageStore(uLitSky, ivec3(id, 0), vec4(0.0, 0.0, 0.0, 1.0));
    imageStore(uSky, ivec3(id, 0), vec4(0.0));
    imageStore(uOwn, ivec3(id, 0), vec4(0.0));
    for (int k = 0; k < froxel.gridSize.z; ++k) {
        vec4 medium = imageLoad(uMedium, ivec3(id, k));
        vec4 light = imageLoad(uLight, ivec3(id, k));
        float tau = clamp(medium.a, 0.0, kMaxOpticalDepth);
        float weight = transmittance * oneMinusExpOverX(tau);
        vec3 w = max(medium.rgb, vec3(0.0)) * weight;
        sky += w;
        litSky += w * clamp(light.a, 0.0, 1.0);
        own += max(light.rgb, vec3(0.0)) * weight;
        transmittance *= exp(-tau);
        imageStore(uLitSky, ivec3(id, k + 1), vec4(litSky, transmittance));
        imageStore(uSky, ivec3(id, k + 1), vec4(sky, 0.0));
        imageStore(uOwn, ivec3(id, k + 1), vec4(min(own, vec3(frame.radianceCap)), 0.0));
    }
}
