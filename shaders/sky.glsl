// sky.glsl — the sky pass: Nishita 1993 single scattering from the CPU
// solver's hemisphere tables, with both phase functions applied per pixel
// (DESIGN.md, "Sky"), for the sun and the moon, plus their discs.
//
// Inputs:
//   frame (common/frame.glsl): light directions, illuminance above the
//     atmosphere E (rgb), the illuminance reaching the viewer (for the disc),
//     Mie anisotropy g, each table's light azimuth and size
//   uSunRayleigh, uSunMie, uMoonRayleigh, uMoonMie (units 0..3): the
//     phase-less integrals I_R, I_M (RGB32F in rgb; dimensionless), one texel
//     per table entry, GL_LINEAR, GL_REPEAT on s (azimuth wraps), clamp on t
// Output: scene-linear radiance [unit of E / sr] in location 0 (alpha 1),
//   L = E (P_R(mu) I_R(v) + P_M(mu, g) I_M(v)) per light,
//   plus, inside a disc of angular radius r, E_ground / (2 pi (1 - cos r)).
//   Directions to table coordinates use preciseAtan2 (common/atmosphere.glsl):
//   with GLSL's own asin/atan (polynomials in Mesa) the lookup was off by up
//   to 4e-4 relative; now it matches sampleSkyTable to ~5e-6 on llvmpipe,
//   whose float filtering weights are exact (GPUs quantise them to ~8 bits:
//   invisible, but expect ~1e-3 there).
//
// Table mapping and lookup: common/sky_table.glsl.
#include "common/frame.glsl"

#ifdef AERIAL_VERTEX_SHADER
#include "common/fullscreen.glsl"
#else
#include "common/atmosphere.glsl"
#include "common/sky_table.glsl"

in vec3 vFarRay;
layout(location = 0) out vec4 outColour;

/// Radiance of a light's disc: the illuminance that reaches the viewer spread
/// over the disc's solid angle 2 pi (1 - cos r) = 4 pi sin^2(r / 2). In the
/// disc when |v - l| <= 2 sin(r / 2) (the chord: no float cancellation, unlike
/// comparing cosines near 1); direction.w holds the chord, illuminance.w the
/// reciprocal solid angle (both from double precision, 0 = no disc).
vec3 lightDisc(vec3 v, vec4 direction, vec4 illuminanceGround) {
    if (!(direction.w > 0.0) || length(v - direction.xyz) > direction.w) return vec3(0.0);
    return illuminanceGround.rgb * illuminanceGround.w;
}

void main() {
    vec3 v = normalize(vFarRay);
    vec3 radiance = skyRadiance(v, true);
    radiance += lightDisc(v, frame.sunDirection, frame.sunIlluminance);
    radiance += lightDisc(v, frame.moonDirection, frame.moonIlluminance);
    outColour = vec4(min(radiance, vec3(frame.fogColour.w)), 1.0);
}
#endif
