// common/sky_table.glsl — the solver's hemisphere tables as textures and
// their lookup (DESIGN.md, "Sky"): per-pixel phase functions applied to the
// phase-less integrals I_R, I_M; used by the sky pass and by the scene's
// specular sky reflections.
//
// Table mapping (aerial/sky.hpp, skyTableRow): the row of elevation el is
// j = (rows - 1) v(el) with, in x = sqrt(el),
//   v = (1 - a - b) x / sqrt(pi/2) + a atan(el / E) / atan(pi/2 / E)
//       + b (atan((el - c) / w) - atan(-c / w)) / (atan((pi/2 - c) / w) - atan(-c / w)),
// (E, a, c) = <light>TableBand, w = <light>TableShadowWidth,
// b = <light>TableShadowShare; with a = b = 0 (a light above 1 deg) the
// quadratic j = (rows - 1) sqrt(el / (pi/2)). Column i holds the azimuth
// relative to the light phi = 2 pi i / columns (wrapping); directions below
// the horizon use row 0. Texel centres sit at (i + 0.5, j + 0.5), so the
// hardware's bilinear filter equals sampleSkyTable().
// Requires common/frame.glsl and common/atmosphere.glsl.
#ifndef AERIAL_SKY_TABLE_GLSL
#define AERIAL_SKY_TABLE_GLSL

layout(binding = 0) uniform sampler2D uSunRayleigh;
layout(binding = 1) uniform sampler2D uSunMie;
layout(binding = 2) uniform sampler2D uMoonRayleigh;
layout(binding = 3) uniform sampler2D uMoonMie;
layout(binding = 6) uniform sampler2D uSunMultiple;   // I_ms, isotropic (no phase)
layout(binding = 7) uniform sampler2D uMoonMultiple;

/// Elevation [rad, >= 0] and world azimuth [rad] (from north (-Z) towards
/// east (+X); straight up gives 0) of direction v. `accurate` uses
/// preciseAtan2 (the sky pass: table lookups to ~5e-6); otherwise GLSL's atan
/// (~1e-4 relative on Mesa: enough for reflections, and cheaper).
vec2 skyAngles(vec3 v, bool accurate) {
    vec2 a = vec2(max(v.y, 0.0), v.x);
    vec2 b = vec2(length(v.xz), -v.z);
    if (accurate) return vec2(preciseAtan2(a.x, b.x), preciseAtan2(a.y, b.y));
    return vec2(a.x == 0.0 && b.x == 0.0 ? 0.0 : atan(a.x, b.x), a.y == 0.0 && b.y == 0.0 ? 0.0 : atan(a.y, b.y));
}

/// The table's row mapping v(el) in 0..1 (see the file comment); band =
/// (E, a, c), w and b as there.
float skyTableMappedRow(float elevation, vec3 band, float w, float b) {
    float el = clamp(elevation, 0.0, 0.5 * kPi);
    float a = band.y;
    if (a <= 0.0 && b <= 0.0) return sqrt(el / (0.5 * kPi));
    float v = (1.0 - a - b) * sqrt(el / (0.5 * kPi));
    if (a > 0.0) v += a * preciseAtan2(el, band.x) / preciseAtan2(0.5 * kPi, band.x);
    if (b > 0.0) {
        float low = preciseAtan2(-band.z, w);
        v += b * (preciseAtan2(el - band.z, w) - low) / (preciseAtan2(0.5 * kPi - band.z, w) - low);
    }
    return v;
}

/// Continuous texel coordinates (column, row) of a direction with the given
/// skyAngles in a table solved for a light at world azimuth `lightAzimuth`
/// [rad], with the row mapping (band, shadowWidth, shadowShare).
vec2 skyTableTexelAt(vec2 angles, float lightAzimuth, vec2 size, vec3 band, float shadowWidth, float shadowShare) {
    float columns = size.x;
    float rows = size.y;
    float row = clamp((rows - 1.0) * skyTableMappedRow(angles.x, band, shadowWidth, shadowShare), 0.0, rows - 1.0);
    float relative = angles.y - lightAzimuth;
    relative -= 2.0 * kPi * floor(relative / (2.0 * kPi));
    float column = relative / (2.0 * kPi) * columns;
    if (!(column >= 0.0) || !(column < columns)) column = 0.0;
    return vec2(column, row);
}


/// Bilinear lookup: the texture's GL_LINEAR filter at the texel centre
/// convention ((i + 0.5) / columns, (j + 0.5) / rows), with GL_REPEAT wrapping
/// the azimuth and GL_CLAMP_TO_EDGE the rows, which is sampleSkyTable().
vec3 sampleTable(sampler2D table, vec2 texel, vec2 size) { return texture(table, (texel + 0.5) / size).rgb; }

vec3 lightSky(sampler2D rayleigh, sampler2D mie, sampler2D multiple, vec3 v, vec2 angles, vec3 lightDirection,
              float lightAzimuth, vec2 size, vec3 band, float shadowWidth, float shadowShare, vec3 illuminance) {
    if (all(equal(illuminance, vec3(0.0)))) return vec3(0.0);
    vec2 texel = skyTableTexelAt(angles, lightAzimuth, size, band, shadowWidth, shadowShare);
    float mu = dot(v, lightDirection);
    return illuminance * (rayleighPhase(mu) * sampleTable(rayleigh, texel, size) +
                          miePhase(mu, frame.mieAnisotropy) * sampleTable(mie, texel, size) +
                          sampleTable(multiple, texel, size));
}

/// Sky radiance in direction v (unit) from both tables, without the discs;
/// `accurate` as in skyAngles.
vec3 skyRadiance(vec3 v, bool accurate) {
    vec2 angles = skyAngles(v, accurate);
    return lightSky(uSunRayleigh, uSunMie, uSunMultiple, v, angles, frame.sunDirection, frame.sunTableAzimuth,
                    vec2(frame.sunTableColumns, frame.sunTableRows), frame.sunTableBand, frame.sunTableShadowWidth,
                    frame.sunTableShadowShare, frame.sunIlluminanceSpace) +
           lightSky(uMoonRayleigh, uMoonMie, uMoonMultiple, v, angles, frame.moonDirection, frame.moonTableAzimuth,
                    vec2(frame.moonTableColumns, frame.moonTableRows), frame.moonTableBand,
                    frame.moonTableShadowWidth, frame.moonTableShadowShare, frame.moonIlluminanceSpace);
}

#endif
