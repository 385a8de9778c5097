// common/frame.glsl — the per-frame uniform block shared by every pass, and
// world-position reconstruction from linear depth (Wenzel 2006, "Real-Time
// Atmospheric Effects in Games", section 6.3: one multiply-add per pixel).
//
// Inputs (std140, binding 0; mirrored by FrameBlock in
// renderer/src/gpu_types.hpp with static_asserted offsets, filled by
// makeFrameBlock in renderer/src/frame_block.cpp):
//   clipFromWorld       world [m] -> clip space
//   eye, farDistance    camera position [m], far distance [m]
//   forward, nearDistance  unit view direction, near distance [m]
//   farCornerRays[4]    xyz: eye -> far-plane corner [m], world space:
//                       bottom-left, bottom-right, top-left, top-right
//   viewportSize        width, height [px]; viewportTexel: 1 / viewportSize
//   sun / moon          <light>Direction (unit, towards the light),
//                       <light>DiscChord (the disc's chord 2 sin(r/2), 0 = no
//                       disc), <light>IlluminanceSpace (illuminance above the
//                       atmosphere E, rgb), <light>Illuminance (reaching the
//                       ground, rgb), <light>DiscInverseSolidAngle (1 / the
//                       disc's solid angle [1/sr]), <light>HorizonRayleigh /
//                       Mie / Multiple (horizon averages I_R, I_M, I_ms),
//                       <light>TableAzimuth (the table's light azimuth [rad])
//   mieAnisotropy       Cornette-Shanks g of the sky and fog colour
//   skyAmbient          cosine-weighted irradiance of the clear sky on an
//                       upward surface (E_sky, same unit as E): what lights
//                       the clouds from above
//   groundAmbient       the same below the cloud deck (the clear sky through
//                       its gaps and the deck's underside; OvercastLight in
//                       aerial/evaluate.hpp): what lights surfaces and fog
//                       particles; skyAmbient without clouds
//   overcastCover, overcastRadiance
//                       the deck in front of the horizon (CloudOvercast::
//                       horizonCover) and its underside's radiance: the sky's
//                       fog colour is mix(sky, overcastRadiance, overcastCover)
//   overcastSkyCover    the deck over the whole sky (CloudOvercast::skyCover):
//                       with overcastCover, what a mirror sees of the deck
//   fogDensity          global fog b [1/m]; fogFalloff c [1/m];
//   fogBaseHeight       h0 [m]; fogColourMode 0 sky, 1 tinted, 2 custom
//   fogColour           tint or radiance of the global fog
//   radianceCap         the cap of every pass output (3e4 for an RGBA16F
//                       target, so sky/scene plus emitters stay below the half
//                       maximum 65504 and no pixel becomes Inf; 1e30 for RGBA32F).
//                       The fog passes only interpolate between the target and
//                       capped colours, so they stay below the cap too.
//   sunTableColumns, sunTableRows, moonTableColumns, moonTableRows  table sizes
//   sunTableWarped, moonTableWarped  1 where the table's columns are warped
//                       (their azimuths are searched, common/sky_table.glsl)
//   emitterCount        emitters in the EmitterBlock (common/emitters.glsl)
//   subtractActive      1 when subtract volumes cut the fog this frame: the
//                       per-pixel intervals of common/subtract.glsl are valid
//   starAxisX, starAxisY, starPole   the celestial frame (world, unit)
//   starIlluminance     the brightest star's illuminance (0 = no stars)
//   starSigma           a star's Gaussian radius [rad]
//   starTransmittance   transmittance viewer -> space at the zenith (rgb)
//   starNitsPerUnit     cd/m^2 per radiance unit (aerial/exposure.hpp)
//   starDarkLimit       naked-eye limiting magnitude on a black sky
//                       (aerial::limitingMagnitude(0), aerial/stars.hpp)
//   fogSkyL0, fogSkyL1x/y/z  the light reaching the fog from the sky dome,
//                       the ground and the night sky: its spherical-harmonic
//                       bands a_0, a_1 (aerial/fog_light.hpp, fogSkyLight)
//   fogDirectVisibility the clouds' mean visibility of the sun and moon for
//                       the fog (fogDirectVisibility); the fog's direct light
//                       is <light>Illuminance times it
//   lightPollutionZenith, lightPollutionCity  a city's glow (night_sky.hpp)
//   lightPollutionUplightDepth  kLightPollutionUplightDepth (clouds lit from
//                       below by the city)
//   airglowZenithRadiance, airglowScatteredFill, airglowShell  the night
//                       sky's airglow (aerial/night_sky.hpp:
//                       kAirglowZenithRadiance, kAirglowScatteredFill, and
//                       Rg / (Rg + kAirglowHeight) for the van Rhijn factor)
//   fogHorizonDistance  D [m]: fog at distance s takes the horizon's colour
//                       with weight 1 - exp(-(s / D)^2)
//
// Linear depth (the frame's R32F texture): normalised linear eye depth,
// z_view / far, 0 at the camera and 1 at the far plane (sky pixels hold 1),
// as in CryEngine 2. The ray to the far plane through a pixel, interpolated
// bilinearly between the four corner rays, gives the world position with one
// multiply-add:  p = eye + depth01 * farRay.
#ifndef AERIAL_FRAME_GLSL
#define AERIAL_FRAME_GLSL

layout(std140, binding = 0) uniform FrameBlock {
    mat4 clipFromWorld;
    vec3 eye;
    float farDistance;
    vec3 forward;
    float nearDistance;
    vec4 farCornerRays[4];
    vec2 viewportSize;
    vec2 viewportTexel;
    vec3 sunDirection;
    float sunDiscChord;
    vec3 sunIlluminanceSpace;
    float padSun;
    vec3 sunIlluminance;
    float sunDiscInverseSolidAngle;
    vec3 moonDirection;
    float moonDiscChord;
    vec3 moonIlluminanceSpace;
    float airglowScatteredFill;
    vec3 moonIlluminance;
    float moonDiscInverseSolidAngle;
    vec3 sunHorizonRayleigh;
    float mieAnisotropy;
    vec3 sunHorizonMie;
    float padSunMie;
    vec3 moonHorizonRayleigh;
    float padMoonRayleigh;
    vec3 moonHorizonMie;
    float padMoonMie;
    vec3 skyAmbient;
    float overcastCover;
    float fogDensity;
    float fogFalloff;
    float fogBaseHeight;
    float fogColourMode;
    vec3 fogColour;
    float radianceCap;
    float sunTableAzimuth;
    float moonTableAzimuth;
    float sunTableColumns;
    float sunTableRows;
    int emitterCount;
    int moonTableColumns;
    int moonTableRows;
    int subtractActive;
    vec3 starAxisX;
    float starIlluminance;
    vec3 starAxisY;
    float starSigma;
    vec3 starPole;
    float starNitsPerUnit;
    vec3 starTransmittance;
    float starDarkLimit;
    vec3 sunHorizonMultiple;
    float padSunMultiple;
    vec3 moonHorizonMultiple;
    float padMoonMultiple;
    vec3 sunDiscDirection;
    float moonLitFraction;
    vec3 moonDiscDirection;
    float padMoonDisc;
    vec3 moonBrightLimb;
    float padBrightLimb;
    float sunTableWarped;
    float moonTableWarped;
    float padTableWarped0;
    float padTableWarped1;
    vec3 groundAmbient;
    float padGroundAmbient;
    vec3 overcastRadiance;
    float overcastSkyCover;
    vec3 fogSkyL0;
    float fogHorizonDistance;
    vec3 fogSkyL1x;
    float fogDirectVisibility;
    vec3 fogSkyL1y;
    float padFogSkyL1y;
    vec3 fogSkyL1z;
    float padFogSkyL1z;
    vec3 airglowZenithRadiance;
    float airglowShell;
    vec3 lightPollutionZenith;
    float lightPollutionUplightDepth;
    vec3 lightPollutionCity;
    float padLightPollutionCity;
} frame;

// Ray from the eye to the far plane at normalised device coordinates ndc
// (-1..1): bilinear in the corner rays, hence affine in ndc.
vec3 farRayAtNdc(vec2 ndc) {
    vec2 f = ndc * 0.5 + 0.5;
    vec3 bottom = mix(frame.farCornerRays[0].xyz, frame.farCornerRays[1].xyz, f.x);
    vec3 top = mix(frame.farCornerRays[2].xyz, frame.farCornerRays[3].xyz, f.x);
    return mix(bottom, top, f.y);
}

// The same ray for a fragment (pixel centre) of the frame.
vec3 farRayAtFragment(vec2 fragCoord) { return farRayAtNdc(fragCoord * frame.viewportTexel * 2.0 - 1.0); }

// World position [m] of a pixel from its normalised linear depth.
vec3 worldFromDepth(float depth01, vec3 farRay) { return frame.eye + depth01 * farRay; }

#endif
