// aerial/fog_light.hpp — the light that reaches the fog: what the global
// height fog and every fog volume in colour mode "sky" (or "tinted")
// scatter towards the eye (../shared/DESIGN.md, "Global height fog").
//
// The model. Fog seen along a unit view direction v, over a segment whose
// far end (the object, the scene point) is a distance s from the eye, has
// the colour
//   L_fog(v, s) = (1 - w(s)) L_lit(v) + w(s) L_horizon(v),
//   w(s) = 1 - exp(-(s / D)^2),
// composited as L <- L T + L_fog (1 - T) (fog_query.hpp).
//  * L_lit(v), the fog lit by the light that reaches it (Hillaire 2020,
//    "A Scalable and Production Ready Sky and Atmosphere Rendering
//    Technique", its aerial-perspective volume: the in-scattering is the
//    sun's transmitted light times the phase, plus the multiply scattered
//    light; Unreal's exponential height fog likewise scatters the
//    directional light and the sky light):
//      L_lit(v) = V sum_{sun, moon} E T(viewer -> light) P(v.l, g)
//               + max(a_0 + k_1(g) a_1 . v, 0)
//    E the light's illuminance above the atmosphere, T(viewer -> light) its
//    transmittance to the viewer's height (zero in the earth's shadow, below
//    the horizon), P the Cornette-Shanks phase with the fog's anisotropy g
//    (a Mie-like droplet lobe), V the clouds' visibility of the light (the
//    mean 1 - skyCover of the cloud deck, CloudOvercast; the volumetric fog
//    instead dims the casting light per froxel with its shadow maps).
//    a_0, a_1 are the first two spherical-harmonic bands (Ramamoorthi and
//    Hanrahan 2001) of the radiance arriving from every direction w,
//      a_0 = 1/(4 pi) integral L(w) dw,   a_1 = 3/(4 pi) integral L(w) w dw,
//    L(w) the sky table's radiance (both lights, skyRadiance) under the
//    cloud deck ((1 - skyCover) sky + skyCover deck), plus the night sky's
//    airglow (night_sky.hpp), over the upper hemisphere, and the ground's
//    Lambertian reflection (albedo / pi times the irradiance of the direct
//    light and the sky) over the lower one. An isotropic scatterer returns
//    the mean a_0 (the fluence / 4 pi); a phase with first Legendre moment
//    k_1 = integral P(mu) mu dw adds k_1 a_1 . v, so the bright side of the
//    sky behind the fog tints it. For Cornette-Shanks
//      k_1(g) = 3 g (4 + g^2) / (5 (2 + g^2)).
//    That band is windowed per channel (Sloan 2008, "Stupid Spherical
//    Harmonics Tricks": a truncated band rings negative) so it swings at
//    most kFogSkyDipoleBound of the mean: valley fog is optically thick, and
//    its multiple scattering broadens a droplet's g = 0.8 lobe (after n
//    scatterings the mean cosine is g^n), so a twilight glow low in one
//    direction tints the fog towards it without making the fog opposite it
//    black (unwindowed, the two sides of 100 m of fog at sun -11 deg
//    differed 25x; outdoors they differ by a small factor).
//  * L_horizon(v), the sky behind far fog: the sky table's horizon row at
//    v's azimuth with the phases applied (horizonSkySample, sky.hpp), under
//    the cloud deck's horizon cover (CloudOvercast::horizonCover). Far away
//    the fog meets the sky's horizon without a seam (Wenzel 2006,
//    "Real-Time Atmospheric Effects in Games", CryEngine 2: distant
//    geometry fades into the sky behind it).
//  * D, kFogHorizonDistance = 5 km, the distance over which the fog's
//    colour goes over from the light at the viewer to the horizon's: the
//    height fog stands for the ground haze of a whole landscape, and beyond
//    a few km a sight line's light comes from air lit elsewhere (towards a
//    set sun, the sunlit air far away that makes the twilight glow; in a
//    valley, the next valley), which the sky's horizon holds and the light
//    at the viewer does not. 5 km is the renderer's default far plane and
//    the usual distance of a landscape's far side. The share grows as the
//    square of the distance near the viewer, so fog within a few hundred
//    metres is lit only where it is (at twilight the horizon towards a set
//    sun is 30-100x brighter than the light at the viewer, and even a 2%
//    share of it, a linear onset's at 100 m, painted the valley fog with the
//    glow): the horizon's share is 0.04% at 100 m, 4% at 1 km, 63% at 5 km
//    and 100% at 20 km (an object 20 km away sits in the sky's horizon
//    colour). Unreal's exponential height fog blends its sky-coloured
//    inscattering in by the pixel's distance the same way (its "fully
//    directional inscattering colour distance").
// The blend is taken at the end of each segment, as Unreal's distance
// blend: the same colour for every fog of one sight line, so the CPU
// queries (a segment), the analytic passes (the pixel's scene point), the
// froxels (the pixel's depth), transparent objects and particles (the
// fragment) agree. The price: dense fog close by in front of a far object
// takes some of the horizon's colour, though its light was scattered near
// the viewer (w weighs the sight line's length, not where along it the fog
// scattered; that integral has no closed form for the exponential fog).
#pragma once

#include <aerial/night_sky.hpp>

#include <aerial/sky.hpp>

#include <glm/vec3.hpp>

namespace aerial {

/// The sky band's largest swing about its mean, a fraction of the mean (above).
inline constexpr double kFogSkyDipoleBound = 0.5;

/// D of the horizon blend [m] (above).
inline constexpr double kFogHorizonDistance = 5000.0;

/// The first two spherical-harmonic bands of the radiance arriving at the
/// fog (above): l0 = a_0, l1 = a_1 (x, y, z), RGB, [illuminance unit / sr].
struct FogSkyLight {
    glm::dvec3 l0{0.0};
    glm::dvec3 l1[3] = {glm::dvec3(0.0), glm::dvec3(0.0), glm::dvec3(0.0)};
};

/// First Legendre moment k_1 of the Cornette-Shanks phase (phase-weighted
/// mean cosine): 3 g (4 + g^2) / (5 (2 + g^2)); g clamped to [-0.999,
/// 0.999], NaN counts as 0.
double miePhaseFirstMoment(double g);

/// Weight w(s) = 1 - exp(-(s / D)^2) of the horizon in the fog's colour at
/// distance s [m] (0 for s <= 0 or NaN, 1 for s = +inf); D <= 0 or NaN
/// counts as kFogHorizonDistance.
double fogHorizonWeight(double distance, double horizonDistance);

/// The sky part of L_lit for a unit view direction v: a_0 + k_1 a_1 . v with
/// the band windowed to kFogSkyDipoleBound (above), at least 0.
glm::dvec3 fogSkyInScatter(const FogSkyLight& sky, double firstMoment, const glm::dvec3& v);

/// Adds to `sky` the bands of one sky table's radiance (skyRadiance with
/// this anisotropy and illuminance above the atmosphere) over the upper
/// hemisphere times `weight`: midpoint rule on 48 azimuths x 16 rings
/// uniform in the zenith cosine (equal solid angles). Also returns the
/// table's irradiance on an upward surface (times `weight`), for the
/// ground's reflection.
glm::dvec3 addSkyTableLight(FogSkyLight& sky, const SkyTable& table, double mieAnisotropy,
                            const glm::dvec3& illuminance, double weight);

/// Adds the bands of a radiance that is uniform over the upper hemisphere
/// (the cloud deck's underside) and returns its irradiance on an upward
/// surface (pi L).
glm::dvec3 addUniformSkyLight(FogSkyLight& sky, const glm::dvec3& radiance);

/// Adds the airglow's bands (airglowRadiance, night_sky.hpp, through the
/// zenith transmittance) and returns its irradiance on an upward surface.
glm::dvec3 addAirglowLight(FogSkyLight& sky, const glm::dvec3& zenithTransmittance);

/// Adds a city's glow (night_sky.hpp, lightPollutionRadiance) over the
/// upper hemisphere to the bands (its dome tilts a_1 towards the city);
/// returns its irradiance on an upward surface.
glm::dvec3 addLightPollutionLight(FogSkyLight& sky, const LightPollution& glow, double northOffsetDeg);

/// Adds the ground's Lambertian reflection, uniform radiance albedo / pi
/// times `groundIrradiance` over the lower hemisphere.
void addGroundLight(FogSkyLight& sky, const glm::dvec3& albedo, const glm::dvec3& groundIrradiance);

}  // namespace aerial
