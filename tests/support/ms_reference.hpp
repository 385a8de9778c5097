// ms_reference.hpp — a brute-force reference for the sky's multiple
// scattering: a seeded Monte Carlo path tracer of the same atmosphere,
// written apart from the solver (no optical-depth table of the solver, no
// layers, no Psi_ms), for tests/core/test_sky_multiple.cpp.
//
// Model: spherical planet (AtmosphereParams radii), Rayleigh + Mie
// scattering with their phase functions (not isotropic), Rayleigh + Mie +
// ozone extinction, a Lambertian ground with AtmosphereParams::groundAlbedo,
// the sun a directional light of unit illuminance. It estimates the radiance
// that every order >= 2 adds in a view direction (everything but single
// scattering: ground bounces included), so that
//   total = referenceSkyIntegrals (single, exact) + multipleScattering().
//
// How: the view ray and every later ray are marched (kSteps midpoint steps,
// s = L u^2, transmittance by accumulated optical depth). Along a ray, the
// light scattered once (the sun, next-event estimation at every step, the
// sun's transmittance from a table of optical depths made here by Simpson
// quadrature) is summed deterministically; the higher orders and the
// ground's skylight follow one sampled path: a scattering point drawn along
// the ray in proportion to sigma_s T, a direction drawn from the phase
// functions (or cosine-weighted at the ground), Russian roulette after the
// second vertex. The first two random dimensions of each path (the point on
// the view ray and the new direction) come from a randomly shifted
// low-discrepancy sequence; the rest from a seeded std::mt19937_64, so the
// result is deterministic.
#pragma once

#include <aerial/atmosphere.hpp>

#include <glm/vec3.hpp>

#include <cstdint>
#include <memory>

namespace aerial::reference {

class MultipleScatteringTracer {
public:
    /// The phase functions at every scattering: the atmosphere's (Rayleigh
    /// and Cornette-Shanks Mie), or isotropic 1 / (4 pi) for both, the
    /// assumption of the solver's Psi_ms LUT (which that LUT's orders must
    /// then match closely, test_sky_multiple.cpp).
    enum class Phase { Physical, Isotropic };
    /// Builds the sun-transmittance table of this atmosphere.
    explicit MultipleScatteringTracer(const AtmosphereParams& air, Phase phase = Phase::Physical);
    ~MultipleScatteringTracer();

    /// Radiance per unit sun illuminance [1/sr], RGB, added by all orders
    /// >= 2 in the unit view direction `view` from the viewer (at
    /// air.viewerHeight), for a sun in the unit direction `sun`; `paths`
    /// paths, seeded with `seed`.
    glm::dvec3 multipleScattering(const glm::dvec3& view, const glm::dvec3& sun, int paths,
                                  std::uint64_t seed) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace aerial::reference
