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
// Table mapping (aerial/sky.hpp, inverted): row j holds elevation
// el = pi/2 (j / (rows - 1))^2, so j = (rows - 1) sqrt(el / (pi/2)); column i
// holds the azimuth relative to the light phi = 2 pi i / columns (wrapping);
// directions below the horizon use row 0. Texel centres sit at (i + 0.5,
// j + 0.5), so the hardware's bilinear filter equals sampleSkyTable().
#include "common/frame.glsl"

#ifdef AERIAL_VERTEX_SHADER
#include "common/fullscreen.glsl"
#else
#include "common/atmosphere.glsl"

layout(binding = 0) uniform sampler2D uSunRayleigh;
layout(binding = 1) uniform sampler2D uSunMie;
layout(binding = 2) uniform sampler2D uMoonRayleigh;
layout(binding = 3) uniform sampler2D uMoonMie;

in vec3 vFarRay;
layout(location = 0) out vec4 outColour;

/// Continuous texel coordinates (column, row) of direction v in a table
/// solved for a light at world azimuth `lightAzimuth` [rad].
vec2 skyTableTexel(vec3 v, float lightAzimuth, vec2 size) {
    float columns = size.x;
    float rows = size.y;
    float elevation = preciseAtan2(max(v.y, 0.0), length(v.xz));
    float row = clamp((rows - 1.0) * sqrt(clamp(elevation / (0.5 * kPi), 0.0, 1.0)), 0.0, rows - 1.0);
    // From north (-Z) towards east (+X); straight up (0, 0) gives 0.
    float azimuth = preciseAtan2(v.x, -v.z);
    float relative = azimuth - lightAzimuth;
    relative -= 2.0 * kPi * floor(relative / (2.0 * kPi));
    float column = relative / (2.0 * kPi) * columns;
    if (!(column >= 0.0) || !(column < columns)) column = 0.0;
    return vec2(column, row);
}

/// Bilinear lookup: the texture's GL_LINEAR filter at the texel centre
/// convention ((i + 0.5) / columns, (j + 0.5) / rows), with GL_REPEAT wrapping
/// the azimuth and GL_CLAMP_TO_EDGE the rows, which is sampleSkyTable().
vec3 sampleTable(sampler2D table, vec2 texel, vec2 size) { return texture(table, (texel + 0.5) / size).rgb; }

vec3 lightSky(sampler2D rayleigh, sampler2D mie, vec3 v, vec3 lightDirection, float lightAzimuth,
              vec2 size, vec3 illuminance) {
    if (all(equal(illuminance, vec3(0.0)))) return vec3(0.0);
    vec2 texel = skyTableTexel(v, lightAzimuth, size);
    float mu = dot(v, lightDirection);
    return illuminance * (rayleighPhase(mu) * sampleTable(rayleigh, texel, size) +
                          miePhase(mu, frame.sunHorizonRayleigh.w) * sampleTable(mie, texel, size));
}

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
    vec3 radiance = lightSky(uSunRayleigh, uSunMie, v, frame.sunDirection.xyz, frame.skyTableMapping.x,
                             frame.skyTableMapping.zw, frame.sunIlluminanceSpace.rgb) +
                    lightSky(uMoonRayleigh, uMoonMie, v, frame.moonDirection.xyz, frame.skyTableMapping.y,
                             vec2(frame.counts.yz), frame.moonIlluminanceSpace.rgb);
    radiance += lightDisc(v, frame.sunDirection, frame.sunIlluminance);
    radiance += lightDisc(v, frame.moonDirection, frame.moonIlluminance);
    outColour = vec4(min(radiance, vec3(frame.fogColour.w)), 1.0);
}
#endif
