// aerial/sky_reference.hpp — ground truth for the sky: brute-force single
// scattering in double precision, with no optical-depth table and no layers.
//
// Usage:
//   aerial::AtmosphereParams air;
//   glm::dvec3 exact = aerial::referenceSkyRadiance(air, viewDir, sunDir, sunIlluminance);
//   glm::dvec3 fast  = aerial::skyRadiance(solver.table(), air.mieAnisotropy, viewDir,
//                                          sunIlluminance);     // sky.hpp
//   // `aerial sky PRESET --time T --dir x,y,z` prints both.
//
// What it computes (../shared/DESIGN.md, "Sky"; Nishita et al. 1993, eq. 3
// with single scattering only): for the viewer at AtmosphereParams::
// viewerHeight and a unit view direction v,
//   I_R(v) = integral beta_R(h(s)) T(viewer -> x(s)) T(x(s) -> light) ds
//   I_M(v) = integral beta_M(h(s)) T(viewer -> x(s)) T(x(s) -> light) ds
// from the viewer to the top of the atmosphere, or to the ground when the
// view ray hits it (unlike the hemisphere table, which repeats its horizon
// row below the horizon); T(x -> light) is 0 where the planet shadows x.
// Radiance L(v) = E (P_R(mu) I_R + P_M(mu, g) I_M), mu = dot(v, light).
//
// How (deliberately unlike SkySolver, so each checks the other):
//   * the view ray is cut where the integrand has a kink or a jump (the
//     perigee of a downward ray, the edges of the planet's shadow) and each
//     piece is integrated with composite Simpson in u, with s = a + (b - a)
//     u^2 (or its mirror) so the nodes crowd at the piece's lower, denser end;
//   * T(viewer -> x) accumulates the extinction along the same
//     nodes (Simpson per interval, with one extra midpoint);
//   * T(x -> light) is integrated afresh at every node, again split at the
//     light ray's perigee, with lightSteps Simpson intervals per piece;
//   * densities, extinction and geometry are recomputed here from
//     AtmosphereParams (Rayleigh + Mie extinction + the ozone tent).
// Cost: about viewSteps * 2 * lightSteps density evaluations per piece of the
// view ray (~10-20 ms with the defaults on one core). For tools and tests,
// never per frame.
#pragma once

#include <aerial/atmosphere.hpp>
#include <aerial/sky.hpp>

#include <glm/vec3.hpp>

namespace aerial {

/// Quadrature resolution of the reference integrator.
struct SkyReferenceSettings {
    /// Simpson intervals along the view ray (per piece), >= 16 (rounded up
    /// to even). Default 2048.
    int viewSteps = 2048;
    /// Simpson intervals along each piece of every ray towards the light,
    /// >= 16 (rounded up to even). Default 256.
    int lightSteps = 256;
};

/// Phase-less single-scattering integrals I_R and I_M (RGB, dimensionless)
/// seen from the viewer along `viewDirection`, lit from `lightDirection`
/// (world space, need not be unit; zero or non-finite reads as +Y).
SkySample referenceSkyIntegrals(const AtmosphereParams& air, const glm::dvec3& viewDirection,
                                const glm::dvec3& lightDirection, const SkyReferenceSettings& settings = {});

/// Radiance [illuminance unit / sr]: illuminance * (P_R(mu) I_R + P_M(mu, g) I_M)
/// with the phase functions of DESIGN.md evaluated here in double precision.
glm::dvec3 referenceSkyRadiance(const AtmosphereParams& air, const glm::dvec3& viewDirection,
                                const glm::dvec3& lightDirection, const glm::dvec3& illuminance,
                                const SkyReferenceSettings& settings = {});

}  // namespace aerial
