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
// quadratic j = (rows - 1) sqrt(el / (pi/2)); plus the cap's rows
// (skyTableMappedRow). Column i holds the azimuth relative to the light
// phi = 2 pi i / columns (wrapping), except around the cap of the earth's
// shadow opposite a light just set (skyTableColumnAt); directions below the
// horizon use row 0. Texel centres sit at (i + 0.5, j + 0.5), so the
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

// The mapping's constants (aerial/sky.hpp, kSkyCap*; kSkyCapMinBand in
// radians), written from the C++ by the renderer's include resolver.
#include "generated/core_constants.glsl"

/// Whether a table's columns are warped around the cap of the earth's shadow
/// (skyTableColumnsWarped): cap = (k, g) = (capCurvature, capStrength), c
/// the shadow's elevation.
bool skyTableCapActive(vec2 cap, float c) { return cap.x > 0.0 && cap.y > 0.0 && c > 0.0; }

/// 0..1, how far a light just set boosts the cap's rows and reshapes its
/// columns, for the kink's elevation c (skyCapBoostFraction).
float skyCapBoostFraction(float c) {
    return clamp((kSkyCapBoostStart - c) / (kSkyCapBoostStart - kSkyCapBoostFull), 0.0, 1.0);
}

/// The table's row mapping v(el) in 0..1 (see the file comment); band =
/// (E, a, c), w and b as there; cap as in skyTableCapActive (the cap's rows,
/// d = kSkyCapRowShare g times the boost of skyCapRowShare (aerial/sky.hpp),
/// uniform in (c - el)^kSkyCapBelowPower from 0 to c, blending into ln(1 + u
/// / s), s = min(kSkyCapLogScale, kSkyCapLogScalePerKink c), u = (c - el) / c,
/// with the boost (skyCapBelowRow), and
/// in cbrt(el - c) from c to 2c).
float skyTableMappedRow(float elevation, vec3 band, float w, float b, vec2 cap) {
    float el = clamp(elevation, 0.0, 0.5 * kPi);
    float a = band.y;
    float boostFraction = skyCapBoostFraction(band.z);
    float boost = 1.0 + (kSkyCapRowBoost - 1.0) * boostFraction;
    float d = skyTableCapActive(cap, band.z) ? kSkyCapRowShare * boost * clamp(cap.y, 0.0, 1.0) : 0.0;
    if (a <= 0.0 && b <= 0.0 && d <= 0.0) return sqrt(el / (0.5 * kPi));
    float v = (1.0 - a - b - d) * sqrt(el / (0.5 * kPi));
    if (a > 0.0) v += a * preciseAtan2(el, band.x) / preciseAtan2(0.5 * kPi, band.x);
    if (b > 0.0) {
        float low = preciseAtan2(-band.z, w);
        v += b * (preciseAtan2(el - band.z, w) - low) / (preciseAtan2(0.5 * kPi - band.z, w) - low);
    }
    if (d > 0.0) {
        float u = min(abs(el - band.z), band.z) / band.z;
        float logScale = clamp(kSkyCapLogScalePerKink * band.z, 0.0, kSkyCapLogScale);
        float below = mix(pow(u, kSkyCapBelowPower), log(1.0 + u / logScale) / log(1.0 + 1.0 / logScale),
                          boostFraction);
        v += d * 0.5 * (el < band.z ? 1.0 - below : 1.0 + pow(u, 1.0 / 3.0));
    }
    return v;
}

/// t of u = a t + (1 - a) t^2 (a quadratic segment of the column mapping,
/// slope a at its start relative to its mean), without cancellation.
float skyTableQuadraticStep(float u, float a) { return 2.0 * u / (a + sqrt(a * a + 4.0 * (1.0 - a) * u)); }

/// A column knot x on the nearest whole column where that keeps it above the
/// knot before it.
float skyTableWholeKnot(float x, float before) {
    float whole = floor(x + 0.5);
    return whole > before ? whole : x;
}

/// The column (0..columns) of an azimuth `relative` [0, 2 pi) from the light
/// at elevation el (skyTableColumn, core/src/sky/sky_table.cpp): uniform, or
/// piecewise linear in the azimuth psi from the anti-light point (in
/// ln(1 + (psi^2 - psiC^2) / Y0) between the second and third knot, Y0 =
/// (kSkyCapBandScale c)^2 + (kSkyCapBandOnsetScale psiC)^2) through the
/// knots x = (0, 3, 15, 28, 64) / 128 columns (blended with m towards (0,
/// 2, 22, 35, 64) / 128 for a light just set, as G towards
/// kSkyCapOnsetGrowthSet: skyCapShape, m the boost fraction; the blended
/// knots rounded to whole columns), psi = (0, psiC,
/// sqrt((G psiC)^2 + D^2), psiE, pi), psiC = sqrt(max(c - el, 0) / k) the
/// onset of the lit sky around the cap of the earth's shadow, D =
/// max(psiC(0) / 2, min(1 deg, kSkyCapBandPerKink c)), G =
/// kSkyCapOnsetGrowth, psiE = min(2 (psiC(0) + max(psiC(0) / 2, 1 deg)),
/// 3 pi / 4), the last two segments quadratic (psi = p + (q - p) (a t +
/// (1 - a) t^2) from p to q, a = 1 - g (1 - kSkyCapNearSlope) from the
/// band's outer knot to psiE, 1 - g (1 - kSkyCapFarSlope) beyond), each inner psi blended
/// with g towards 2 pi x / columns.
float skyTableColumnAt(float relative, float el, float columns, float c, vec2 cap) {
    if (!skyTableCapActive(cap, c) || !(columns >= 4.0)) return relative / (2.0 * kPi) * columns;
    float k = cap.x, g = min(cap.y, 1.0);
    float foot = min(sqrt(c / k), 0.25 * kPi);
    float band = max(0.5 * foot, min(kSkyCapMinBand, kSkyCapBandPerKink * c));
    float end = min(2.0 * (foot + max(0.5 * foot, kSkyCapMinBand)), 0.75 * kPi);
    float onset = min(sqrt(max(c - max(el, 0.0), 0.0) / k), foot);
    // The shares and the band's knot for a light just set (skyCapShape): m the boost fraction.
    float m = skyCapBoostFraction(c);
    float growth = mix(kSkyCapOnsetGrowth, kSkyCapOnsetGrowthSet, m);
    float bandScale = kSkyCapBandScale * c * kSkyCapBandScale * c +
                      kSkyCapBandOnsetScale * onset * kSkyCapBandOnsetScale * onset;
    // The knots on whole columns (a knot inside a texel put a kink in its
    // bilinear filter: skyTableColumn in sky_table.cpp).
    float inside = mix(kSkyCapInsideShare, kSkyCapInsideShareSet, m);
    float onsetEnd = inside + mix(kSkyCapOnsetShare, kSkyCapOnsetShareSet, m);
    // (where that keeps each above the one before it, as in sky_table.cpp)
    float x1 = skyTableWholeKnot(inside * columns, 0.0);
    float x2 = skyTableWholeKnot(onsetEnd * columns, x1);
    float x3 = skyTableWholeKnot((onsetEnd + kSkyCapNearShare) * columns, x2), x4 = 0.5 * columns;
    float p1 = g * onset + (1.0 - g) * 2.0 * kPi * x1 / columns;
    float p2 = g * length(vec2(growth * onset, band)) + (1.0 - g) * 2.0 * kPi * x2 / columns;
    float p3 = g * end + (1.0 - g) * 2.0 * kPi * x3 / columns;
    float psi = relative <= kPi ? kPi - relative : relative - kPi;
    float x;
    if (!(psi > 0.0))
        x = 0.0;  // the anti-light point
    else if (psi < p1)
        x = x1 * psi / p1;
    else if (psi < p2)
    {
        float y = psi * psi - p1 * p1, y2 = p2 * p2 - p1 * p1;
        x = x1 + (x2 - x1) * log(1.0 + y / bandScale) / log(1.0 + y2 / bandScale);
    }
    else if (psi < p3)
        x = x2 + (x3 - x2) * skyTableQuadraticStep((psi - p2) / (p3 - p2), 1.0 - g * (1.0 - kSkyCapNearSlope));
    else
        x = x3 + (x4 - x3) * skyTableQuadraticStep((min(psi, kPi) - p3) / (kPi - p3), 1.0 - g * (1.0 - kSkyCapFarSlope));
    return relative <= kPi ? x4 - x : x4 + x;
}

/// Continuous texel coordinates (column, row) of a direction with the given
/// skyAngles in a table solved for a light at world azimuth `lightAzimuth`
/// [rad], with the row mapping (band, shadowWidth, shadowShare) and the
/// column mapping (cap, band.z).
vec2 skyTableTexelAt(vec2 angles, float lightAzimuth, vec2 size, vec3 band, float shadowWidth, float shadowShare,
                     vec2 cap) {
    float columns = size.x;
    float rows = size.y;
    float row =
        clamp((rows - 1.0) * skyTableMappedRow(angles.x, band, shadowWidth, shadowShare, cap), 0.0, rows - 1.0);
    float relative = angles.y - lightAzimuth;
    relative -= 2.0 * kPi * floor(relative / (2.0 * kPi));
    float column = skyTableColumnAt(relative, angles.x, columns, band.z, cap);
    if (!(column >= 0.0) || !(column < columns)) column = 0.0;
    return vec2(column, row);
}


/// Bilinear lookup: the texture's GL_LINEAR filter at the texel centre
/// convention ((i + 0.5) / columns, (j + 0.5) / rows), with GL_REPEAT wrapping
/// the azimuth and GL_CLAMP_TO_EDGE the rows, which is sampleSkyTable().
vec3 sampleTable(sampler2D table, vec2 texel, vec2 size) { return texture(table, (texel + 0.5) / size).rgb; }

vec3 lightSky(sampler2D rayleigh, sampler2D mie, sampler2D multiple, vec3 v, vec2 angles, vec3 lightDirection,
              float lightAzimuth, vec2 size, vec3 band, float shadowWidth, float shadowShare, vec2 cap,
              vec3 illuminance) {
    if (all(equal(illuminance, vec3(0.0)))) return vec3(0.0);
    vec2 texel = skyTableTexelAt(angles, lightAzimuth, size, band, shadowWidth, shadowShare, cap);
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
                    frame.sunTableShadowShare, vec2(frame.sunTableCapCurvature, frame.sunTableCapStrength),
                    frame.sunIlluminanceSpace) +
           lightSky(uMoonRayleigh, uMoonMie, uMoonMultiple, v, angles, frame.moonDirection, frame.moonTableAzimuth,
                    vec2(frame.moonTableColumns, frame.moonTableRows), frame.moonTableBand,
                    frame.moonTableShadowWidth, frame.moonTableShadowShare,
                    vec2(frame.moonTableCapCurvature, frame.moonTableCapStrength), frame.moonIlluminanceSpace);
}

#endif
