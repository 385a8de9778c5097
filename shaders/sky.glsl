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
// Stars: a procedural field fixed to the celestial sphere (frame.starAxisX,
//   starAxisY, starPole from core's celestialFrame), so it turns about the
//   pole with sidereal time. The sphere is cut into kStarColumns x kStarRows
//   equal-area cells in (right ascension, sin declination); a cell holds a
//   star with probability kStarProbability, at a hashed place in the middle
//   70 % of the cell (~8400 stars, half above the horizon), with a hashed
//   tint and the V magnitude m = max(-1.5, 6.5 + 2 log10(1 - u)) of a uniform
//   hash u, so the counts follow the real sky's (aerial/stars.hpp,
//   starFieldMagnitude: ~15 stars brighter than 1, ~4700 than 6). Its flux is
//   frame.starIlluminance (the -1.5 star's illuminance) x 10^(-0.4 (m + 1.5)).
//   Each star is a Gaussian of radius sigma (0.6 pixel, at most 0.0015 rad:
//   frame_block.hpp) normalised to its flux, E_star / (2 pi sigma^2) at the
//   centre, summed over the pixel's cell and its 8 neighbours (stars within a
//   few cells of the pole, where cells are narrow, can be cut off), and
//   dimmed by T_zenith^X(z) with the Kasten-Young air mass X (within 2 % of
//   the exact slant transmittance above 10 deg elevation); none below the
//   horizon. A star shows as a person would see it: its magnitude after the
//   extinction, m - 2.5 X log10(T_zenith.g) (V ~ green), against the
//   naked-eye limiting magnitude of the pixel's sky (the sun's and moon's
//   sky and the airglow, luminance x frame.starNitsPerUnit cd/m^2; Hecht's
//   law with Schaefer 1990's night constants, aerial/stars.hpp,
//   limitingMagnitude: frame.starDarkLimit - 5 log10(1 + sqrt(K B))), faded
//   over 0.5 mag across the limit (starThresholdFade). Clouds are drawn over
//   the sky later and pass it (stars included) on through their
//   transmittance. tests/renderer/test_renderer_stars.cpp holds a CPU copy
//   of this function and compares every pixel.
//
// The tables' coordinates and lookup: common/sky_table.glsl.
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
/// comparing cosines near 1); the chord and the reciprocal solid angle come
/// from double precision (frame.<light>DiscChord, <light>DiscInverseSolidAngle;
/// 0 = no disc).
vec3 lightDisc(vec3 v, vec3 direction, float chord, vec3 illuminanceGround, float inverseSolidAngle) {
    if (!(chord > 0.0) || length(v - direction) > chord) return vec3(0.0);
    return illuminanceGround * inverseSolidAngle;
}

/// The moon's disc with its phase: a point at disc coordinates (u along the
/// bright limb, w across, radius 1) is lit when u > (1 - 2k) sqrt(1 - w^2)
/// (the terminator, an ellipse; k the illuminated fraction), and the lit part
/// carries the whole illuminance (already times the phase law): radiance
/// E / (k x solid angle).
vec3 moonDisc(vec3 v) {
    vec3 m = frame.moonDiscDirection;
    float chord = frame.moonDiscChord;
    vec3 d = v - m;
    if (!(chord > 0.0) || length(d) > chord) return vec3(0.0);
    float k = clamp(frame.moonLitFraction, 0.0, 1.0);
    if (k <= 1e-4) return vec3(0.0);
    vec3 tangent = d - m * dot(d, m);
    float u = dot(tangent, frame.moonBrightLimb) / chord;
    float w = length(tangent - frame.moonBrightLimb * dot(tangent, frame.moonBrightLimb)) / chord;
    if (u < (1.0 - 2.0 * k) * sqrt(max(1.0 - w * w, 0.0))) return vec3(0.0);
    return frame.moonIlluminance * frame.moonDiscInverseSolidAngle / k;
}

const uint kStarColumns = 1024u;
const uint kStarRows = 512u;
const float kStarProbability = 0.016;
const float kStarFluxExponent = 6.0;
const float kTwoPi = 6.28318530718;

uint starHash(uint x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}
float starUnit(uint h) { return float(h >> 8) * (1.0 / 16777216.0); }


// Hecht's law (aerial/stars.hpp): K = 10^-1.9 per nanolambert, 1 nL =
// 1e-5 / pi cd/m^2; the field's brightest and faintest magnitudes.
const float kHechtK = 0.0125892541;
const float kNitsPerNanolambert = 3.18309886e-6;
const float kStarBrightest = -1.5;
const float kStarFaintest = 6.5;
const float kStarFade = 0.5;
const float kLog10Of2 = 0.30102999566;

/// Naked-eye limiting magnitude (V, at the eye) against a sky of radiance
/// `background` (stars.hpp, limitingMagnitude).
float starLimitingMagnitude(vec3 background) {
    float nits = max(dot(background, vec3(0.2126, 0.7152, 0.0722)), 0.0) * frame.starNitsPerUnit;
    return frame.starDarkLimit - 5.0 * kLog10Of2 * log2(1.0 + sqrt(kHechtK * nits / kNitsPerNanolambert));
}

/// The stars towards v seen against the sky radiance `background` there.
vec3 starRadiance(vec3 v, vec3 background) {
    float illuminance = frame.starIlluminance;
    if (!(illuminance > 0.0) || v.y <= 0.0 || !(frame.starTransmittance.g > 0.0)) return vec3(0.0);
    // Every star is at least kStarBrightest + the extinction: none shows
    // where the limit is brighter than that by half the fade.
    float mu = v.y;
    float x = airMass(mu);
    float extinction = -2.5 * x * kLog10Of2 * log2(min(frame.starTransmittance.g, 1.0));
    float limit = starLimitingMagnitude(background);
    if (!(limit - extinction > kStarBrightest - 0.5 * kStarFade)) return vec3(0.0);
    float sigma = frame.starSigma;
    vec3 c = vec3(dot(v, frame.starAxisX), dot(v, frame.starAxisY), dot(v, frame.starPole));
    float u = fract(atan(c.y, c.x) / kTwoPi + 1.0);
    float z = clamp(c.z, -1.0, 1.0);
    int column = int(min(u * float(kStarColumns), float(kStarColumns - 1u)));
    int row = int(min((z * 0.5 + 0.5) * float(kStarRows), float(kStarRows - 1u)));
    vec3 sum = vec3(0.0);
    for (int dj = -1; dj <= 1; ++dj) {
        int j = row + dj;
        if (j < 0 || j >= int(kStarRows)) continue;
        for (int di = -1; di <= 1; ++di) {
            uint i = uint(column + di + int(kStarColumns)) % kStarColumns;
            uint h = starHash(uint(j) * kStarColumns + i + 0x5bd1e995u);
            if (starUnit(h) >= kStarProbability) continue;
            uint h1 = starHash(h);
            uint h2 = starHash(h1);
            uint h3 = starHash(h2);
            uint h4 = starHash(h3);
            // 1 - u of a 24-bit hash is exact in float and > 0.
            float magnitude = max(kStarBrightest, kStarFaintest + 2.0 * kLog10Of2 * log2(1.0 - starUnit(h3)));
            float f = clamp((limit - magnitude - extinction) / kStarFade + 0.5, 0.0, 1.0);
            if (!(f > 0.0)) continue;
            float ra = kTwoPi * (float(i) + 0.15 + 0.7 * starUnit(h1)) / float(kStarColumns);
            float sinDec = (float(j) + 0.15 + 0.7 * starUnit(h2)) / float(kStarRows) * 2.0 - 1.0;
            float cosDec = sqrt(max(1.0 - sinDec * sinDec, 0.0));
            vec3 s = vec3(cosDec * cos(ra), cosDec * sin(ra), sinDec);
            vec3 d = c - s;
            float flux = exp2(-0.4 / kLog10Of2 * (magnitude - kStarBrightest)) * f * f * (3.0 - 2.0 * f);
            float weight = flux * exp(-dot(d, d) / (2.0 * sigma * sigma));
            vec3 tint = mix(vec3(1.0, 0.82, 0.64), vec3(0.72, 0.84, 1.0), starUnit(h4));
            sum += weight * tint;
        }
    }
    vec3 transmittance = pow(frame.starTransmittance, vec3(x));
    return sum * (illuminance / (kTwoPi * sigma * sigma)) * transmittance;
}

// Airglow (core's aerial/night_sky.hpp is the reference and documents the
// model): frame.airglowZenithRadiance times the van Rhijn factor of its
// shell (frame.airglowShell), dimmed like the stars, with frame.airglowScatteredFill of what
// the air scatters out of the line of sight scattered back in. Physical, so
// always on, as the sky tables are (by day it is 1e-9 of the sky).
vec3 airglowRadiance(vec3 v) {
    if (v.y <= 0.0) return vec3(0.0);
    float vanRhijn = inversesqrt(1.0 - frame.airglowShell * frame.airglowShell * (1.0 - v.y * v.y));
    vec3 direct = pow(frame.starTransmittance, vec3(airMass(v.y)));
    return frame.airglowZenithRadiance * vanRhijn * (direct + frame.airglowScatteredFill * (1.0 - direct));
}


void main() {
    vec3 v = normalize(vFarRay);
    vec3 radiance = skyRadiance(v, true) + airglowRadiance(v) + lightPollutionRadiance(v);
    radiance += starRadiance(v, radiance);
    radiance += lightDisc(v, frame.sunDiscDirection, frame.sunDiscChord, frame.sunIlluminance,
                          frame.sunDiscInverseSolidAngle);
    radiance += moonDisc(v);
    outColour = vec4(min(radiance, vec3(frame.radianceCap)), 1.0);
}
#endif
