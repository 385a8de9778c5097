// common/atmosphere.glsl — phase functions, the fog's colour (the light
// that reaches it blended into the sky's horizon far away, the model of
// core/include/aerial/fog_light.hpp) and the analytic exponential-fog
// integral, mirroring the CPU reference in core/ (core/src/sky/atmosphere.cpp,
// core/src/fog/height_fog.cpp, fog_light.cpp, fog_query.cpp).
//
// Papers: Nishita et al. 1993 (single scattering; Rayleigh and
// Cornette-Shanks phase functions), Wenzel 2006 section 6.4 (analytic
// exponential height fog). Units: lengths [m], coefficients [1/m], phase
// functions [1/sr], radiance in the unit of the lights' illuminance per sr.
// Requires common/frame.glsl; includes common/sky_table.glsl (the fog colour).
#ifndef AERIAL_ATMOSPHERE_GLSL
#define AERIAL_ATMOSPHERE_GLSL

const float kPi = 3.14159265358979;
/// Optical depths saturate here (as kMaxOpticalDepth in height_fog.hpp).
const float kMaxOpticalDepth = 1.0e4;

/// atan(y, x) to float precision. GLSL's atan/asin are often polynomial
/// approximations (Mesa's NIR lowering is good to ~1e-4 relative, enough for
/// 4e-4 errors in a sky lookup); one Newton step on
/// r sin(theta_true - theta) = y cos(theta) - x sin(theta) squares the error.
/// (0, 0) gives 0.
float preciseAtan2(float y, float x) {
    if (x == 0.0 && y == 0.0) return 0.0;
    float theta = atan(y, x);
    float c = cos(theta);
    float s = sin(theta);
    return theta + (y * c - x * s) / (x * c + y * s);
}

/// Rayleigh phase 3/(16 pi) (1 + mu^2) [1/sr], mu = cos(view, light).
float rayleighPhase(float mu) {
    mu = clamp(mu, -1.0, 1.0);
    return 3.0 / (16.0 * kPi) * (1.0 + mu * mu);
}

/// Cornette-Shanks 3/(8 pi) (1 - g^2)(1 + mu^2) / ((2 + g^2)(1 + g^2 - 2 g mu)^1.5) [1/sr].
float miePhase(float mu, float g) {
    mu = clamp(mu, -1.0, 1.0);
    g = clamp(g, -0.999, 0.999);
    float g2 = g * g;
    float denom = max(1.0 + g2 - 2.0 * g * mu, 1e-12);
    return 3.0 / (8.0 * kPi) * (1.0 - g2) * (1.0 + mu * mu) / ((2.0 + g2) * denom * sqrt(denom));
}

/// (1 - exp(-x)) / x for x >= 0, the factor of the fog integral that tends
/// to 1 as x -> 0. GLSL has no expm1: below 0.1 a Taylor series to x^4
/// (truncation < x^5/720 = 1.4e-8 at 0.1), above it the direct form
/// (cancellation error ~ 6e-8 / x <= 6e-7). Both agree to float precision at
/// the switch, so there is no visible jump as c d.y -> 0 (horizontal rays,
/// c = 0 gives exactly 1).
float oneMinusExpOverX(float x) {
    if (x < 0.1) {
        return 1.0 + x * (-0.5 + x * (1.0 / 6.0 + x * (-1.0 / 24.0 + x * (1.0 / 120.0))));
    }
    return (1.0 - exp(-x)) / x;
}

/// 1 - exp(-tau), tau >= 0, accurate near 0 (-expm1(-tau)).
float oneMinusExp(float tau) { return tau * oneMinusExpOverX(tau); }

/// Optical depth of b exp(-c (h - h0)) along a segment: `height` = height of
/// the start above the plane of density b [m], `rise` = height change over
/// the segment [m], `len` = its length [m]. The form of height_fog.cpp:
/// b L exp(-min(y0, y1)) g(|c rise|), the density at the denser end times a
/// factor <= 1, so nothing overflows; saturates at kMaxOpticalDepth.
float exponentialOpticalDepth(float b, float c, float height, float rise, float len) {
    if (!(b > 0.0) || !(len > 0.0)) return 0.0;
    c = max(c, 0.0);
    float x = c * rise;
    float y0 = c * height;
    float yDense = min(y0, y0 + x);
    float m = b * len * oneMinusExpOverX(abs(x));
    // exp(80) ~ 5.5e34: beyond it the result saturates anyway for any m that
    // matters (m e^80 > 1e4 needs m > 2e-31).
    return min(m * exp(min(-yDense, 80.0)), kMaxOpticalDepth);
}

// The sky tables (units 0-3, 6, 7, bound for the whole frame) give the fog
// the horizon behind it.
#include "common/sky_table.glsl"

/// The phase-less horizon behind far fog in direction v (unit) for one light
/// (horizonSkySample in core/src/sky/sky_table.cpp): the table's row 0 at v's
/// world `azimuth` blended with the horizon averages by s = |v.xz|,
/// H = (1 - s) average + s row0(azimuth). Row 0 is the texel row's centre,
/// so only the columns are filtered, as in sampleSkyTable.
void horizonSky(sampler2D rayleighTable, sampler2D mieTable, sampler2D multipleTable, vec3 v, float azimuth,
                float lightAzimuth, vec2 size, bool warped, vec3 meanRayleigh, vec3 meanMie, vec3 meanMultiple,
                out vec3 rayleigh, out vec3 mie, out vec3 multiple) {
    rayleigh = meanRayleigh;
    mie = meanMie;
    multiple = meanMultiple;
    float s = min(length(v.xz), 1.0);
    if (!(s > 0.0) || !(size.x >= 1.0)) return;
    float column =
        skyTableColumnAt(rayleighTable, 0, 0, 0.0, skyTableAntiLightAzimuth(azimuth, lightAzimuth), int(size.x), warped);
    vec2 at = skyTableCoordinate(column, 0.0, size);
    rayleigh = mix(meanRayleigh, texture(rayleighTable, at).rgb, s);
    mie = mix(meanMie, texture(mieTable, at).rgb, s);
    multiple = mix(meanMultiple, texture(multipleTable, at).rgb, s);
}

/// Both lights' horizons behind direction v (the azimuth found once; a light
/// that is off keeps zeros and fetches nothing).
struct HorizonSkies {
    vec3 sunRayleigh, sunMie, sunMultiple;
    vec3 moonRayleigh, moonMie, moonMultiple;
};

HorizonSkies horizonSkies(vec3 v) {
    HorizonSkies h;
    h.sunRayleigh = h.sunMie = h.sunMultiple = vec3(0.0);
    h.moonRayleigh = h.moonMie = h.moonMultiple = vec3(0.0);
    float azimuth = skyAngles(v, false).y;
    if (any(greaterThan(frame.sunIlluminanceSpace, vec3(0.0))))
        horizonSky(uSunRayleigh, uSunMie, uSunMultiple, v, azimuth, frame.sunTableAzimuth,
                   vec2(frame.sunTableColumns, frame.sunTableRows),
                   frame.sunTableWarped != 0.0,
                   frame.sunHorizonRayleigh, frame.sunHorizonMie, frame.sunHorizonMultiple, h.sunRayleigh, h.sunMie,
                   h.sunMultiple);
    if (any(greaterThan(frame.moonIlluminanceSpace, vec3(0.0))))
        horizonSky(uMoonRayleigh, uMoonMie, uMoonMultiple, v, azimuth, frame.moonTableAzimuth,
                   vec2(frame.moonTableColumns, frame.moonTableRows),
                   frame.moonTableWarped != 0.0,
                   frame.moonHorizonRayleigh, frame.moonHorizonMie, frame.moonHorizonMultiple, h.moonRayleigh,
                   h.moonMie, h.moonMultiple);
    return h;
}

/// The clear sky's fog colour in direction v (unit) from its horizons: sum
/// over sun and moon of E (P_R(mu) H_R(v) + P_M(mu, g) H_M(v) + H_ms(v)).
vec3 clearSkyFogColourFrom(HorizonSkies h, vec3 v) {
    float g = frame.mieAnisotropy;
    float muSun = dot(v, frame.sunDirection);
    float muMoon = dot(v, frame.moonDirection);
    return frame.sunIlluminanceSpace *
               (rayleighPhase(muSun) * h.sunRayleigh + miePhase(muSun, g) * h.sunMie + h.sunMultiple) +
           frame.moonIlluminanceSpace *
               (rayleighPhase(muMoon) * h.moonRayleigh + miePhase(muMoon, g) * h.moonMie + h.moonMultiple);
}

/// The cloud deck in front of the horizon (frame.overcastCover) over a clear
/// sky's fog colour: mix(clear, deck's underside, cover); the clear colour
/// itself without clouds.
vec3 underOvercast(vec3 clear) {
    return frame.overcastCover > 0.0 ? mix(clear, frame.overcastRadiance, frame.overcastCover) : clear;
}

/// How much of the sky in direction r (unit) the deck hides, for what a mirror
/// reflects (shading.glsl): the cover in front of the horizon (overcastCover,
/// 1-11 deg up) for r level or below, rising to the whole sky's cosine-weighted
/// cover (overcastSkyCover) from 30 deg up, smoothly (smoothstep in r.y from 0
/// to 0.5); overcastCoverTowards in aerial/clouds.hpp on the CPU.
float overcastCoverTowards(vec3 r) {
    return mix(frame.overcastCover, frame.overcastSkyCover, smoothstep(0.0, 0.5, r.y));
}

/// The horizon's colour behind far fog in direction v (unit): the clear
/// sky's under the overcast (L_horizon of aerial/fog_light.hpp).
vec3 horizonFogColourFrom(HorizonSkies h, vec3 v) { return underOvercast(clearSkyFogColourFrom(h, v)); }

/// k_1(g), the Cornette-Shanks phase's mean cosine (miePhaseFirstMoment).
float miePhaseFirstMoment(float g) {
    g = clamp(g, -0.999, 0.999);
    return 3.0 * g * (4.0 + g * g) / (5.0 * (2.0 + g * g));
}

/// The sky dome's light scattered by fog of anisotropy g towards -v:
/// max(a_0 + k_1(g) a_1 . v, 0) (fogSkyInScatter).
/// The band is windowed so that it swings at most kFogSkyDipoleBound of the
/// mean (fog_light.hpp).
const float kFogSkyDipoleBound = 0.5;
vec3 fogSkyInScatter(vec3 v, float g) {
    float k1 = miePhaseFirstMoment(g);
    vec3 l1 = frame.fogSkyL1x * v.x + frame.fogSkyL1y * v.y + frame.fogSkyL1z * v.z;
    vec3 magnitude = sqrt(frame.fogSkyL1x * frame.fogSkyL1x + frame.fogSkyL1y * frame.fogSkyL1y +
                          frame.fogSkyL1z * frame.fogSkyL1z);
    vec3 swing = abs(k1) * magnitude;
    vec3 bound = kFogSkyDipoleBound * max(frame.fogSkyL0, vec3(0.0));
    vec3 window = mix(vec3(1.0), bound / max(swing, vec3(1e-30)), greaterThan(swing, bound));
    return max(frame.fogSkyL0 + window * k1 * l1, vec3(0.0));
}

/// One light's illuminance that reaches the fog (its <light>Illuminance)
/// through the fog's phase, without the clouds' visibility.
vec3 fogDirectLight(vec3 v, float g, bool moon) {
    return moon ? frame.moonIlluminance * miePhase(dot(v, frame.moonDirection), g)
                : frame.sunIlluminance * miePhase(dot(v, frame.sunDirection), g);
}

/// L_lit(v) (fog_light.hpp): both lights through the phase, times the
/// clouds' mean visibility, plus the sky dome's light.
vec3 litFogColour(vec3 v, float g) {
    return frame.fogDirectVisibility * (fogDirectLight(v, g, false) + fogDirectLight(v, g, true)) +
           fogSkyInScatter(v, g);
}

/// w(s) = 1 - exp(-(s / D)^2), the horizon's share of the fog's colour at
/// distance s [m] (fogHorizonWeight).
float fogHorizonWeight(float s) {
    float x = s / max(frame.fogHorizonDistance, 1e-6);
    return s > 0.0 ? oneMinusExp(x * x) : 0.0;
}

/// The fog colour L_fog(v, s) of colour mode "sky" for a sight line of
/// length s [m] in direction v (unit) (FogScene::fogColour):
/// (1 - w) L_lit(v) + w L_horizon(v).
vec3 skyFogColour(vec3 v, float s) {
    float w = fogHorizonWeight(s);
    vec3 colour = vec3(0.0);
    if (w < 1.0) colour = (1.0 - w) * litFogColour(v, frame.mieAnisotropy);
    if (w > 0.0) colour += w * horizonFogColourFrom(horizonSkies(v), v);
    return colour;
}

/// Colour of fog in a colour mode (0 sky, 1 tinted, 2 custom; FogColourMode)
/// for a sight line of length s [m].
vec3 fogColourFor(float mode, vec3 colour, vec3 v, float s) {
    if (mode > 1.5) return colour;
    vec3 sky = skyFogColour(v, s);
    return mode > 0.5 ? colour * sky : sky;
}

/// The fog between the eye and a point at distance s [m], ready to composite
/// (the contract of fog_query.hpp): rgb = S = L_fog(v, s) (1 - T), with the
/// fog colour of `colourMode` (fogColourFor) capped at frame.radianceCap,
/// a = T = exp(-tau). Radiance L behind the fog becomes L T + S; a fog pass
/// outputs it as is, blended with glBlendFunc(GL_ONE, GL_SRC_ALPHA).
vec4 fogInScatterTransmittance(float colourMode, vec3 colour, vec3 v, float s, float tau) {
    vec3 fogColour = min(fogColourFor(colourMode, colour, v, s), vec3(frame.radianceCap));
    return vec4(fogColour * oneMinusExp(tau), exp(-tau));
}

/// Optical depth of the global height fog from the eye along d (eye ->
/// point [m]).
float globalFogOpticalDepth(vec3 d) {
    return exponentialOpticalDepth(frame.fogDensity, frame.fogFalloff, frame.eye.y - frame.fogBaseHeight, d.y,
                                   length(d));
}

/// The global fog (fogInScatterTransmittance) from the eye to a point,
/// `view` = point - eye, optical depth tau; at the eye itself the colour is
/// taken along the view direction.
vec4 globalFogTowards(vec3 view, float tau) {
    float s = length(view);
    return fogInScatterTransmittance(frame.fogColourMode, frame.fogColour, s > 0.0 ? normalize(view) : frame.forward,
                                     s, tau);
}

/// Kasten & Young (1989) relative air mass for a zenith cosine mu > 0.
float airMass(float mu) {
    float zenithDeg = degrees(acos(clamp(mu, 0.0, 1.0)));
    return 1.0 / (mu + 0.50572 * pow(96.07995 - zenithDeg, -1.6364));
}

// A city's glow (core's lightPollutionRadiance, aerial/night_sky.hpp):
// Lz (sqrt(X) + K exp(-theta^2 / 2 sigma^2)) / (1 + K exp(-(pi/2)^2 / 2 sigma^2)),
// K = 20, sigma = 30 deg, theta from the city's point on the horizon.
vec3 lightPollutionRadiance(vec3 v) {
    if (v.y <= 0.0 || !(dot(frame.lightPollutionZenith, vec3(1.0)) > 0.0)) return vec3(0.0);
    const float kGain = 20.0, kTwoSigma2 = 2.0 * 0.523598776 * 0.523598776;
    float theta = acos(clamp(dot(v, frame.lightPollutionCity), -1.0, 1.0));
    float shape = (sqrt(airMass(v.y)) + kGain * exp(-theta * theta / kTwoSigma2)) /
                  (1.0 + kGain * exp(-2.4674011 / kTwoSigma2));
    return frame.lightPollutionZenith * shape;
}

/// The city's light arriving from below at a cloud seen along v
/// (lightPollutionUplight of night_sky.hpp): pi L(v) / tau_up.
vec3 lightPollutionUplight(vec3 v) {
    return kPi / max(frame.lightPollutionUplightDepth, 1e-3) * lightPollutionRadiance(v);
}

#endif
