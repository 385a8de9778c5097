// aerial/atmosphere.hpp — the planet's atmosphere: parameters, phase
// functions, density profiles and the transmittance along a ray.
//
// Usage:
//   aerial::AtmosphereParams air;                 // Earth defaults
//   air.mieScattering = glm::dvec3(20e-6);        // hazier
//   glm::dvec3 t = aerial::transmittanceToSpace(air, air.viewerHeight, sunDir.y);
//   double pr = aerial::rayleighPhase(mu), pm = aerial::miePhase(mu, air.mieAnisotropy);
//
// Model (../shared/DESIGN.md, "Sky"): Nishita et al. 1993 single scattering.
// Planet radius Rg, top of the atmosphere Rt, densities exp(-h/H) for
// Rayleigh and Mie and a tent profile for ozone. Heights h are above the
// ground [m]; coefficients are per RGB channel [1/m].
#pragma once

#include <glm/vec3.hpp>

namespace aerial {

/// Physical description of the atmosphere. Zero values are valid (an empty
/// atmosphere); the defaults are Earth's (Bruneton 2017).
struct AtmosphereParams {
    /// Planet radius Rg [m]. Default 6 360 000.
    double planetRadius = 6360000.0;
    /// Radius of the top of the atmosphere Rt [m], > planetRadius. Default 6 420 000.
    double atmosphereRadius = 6420000.0;
    /// Viewer height above the ground [m], 0..(Rt - Rg). Default 0.
    double viewerHeight = 0.0;

    /// Rayleigh scattering at sea level [1/m], RGB. Extinction equals scattering.
    glm::dvec3 rayleighScattering{5.802e-6, 13.558e-6, 33.1e-6};
    /// Rayleigh scale height H_R [m]. Default 8000.
    double rayleighScaleHeight = 8000.0;

    /// Mie scattering at sea level [1/m], RGB. Default 3.996e-6.
    glm::dvec3 mieScattering{3.996e-6, 3.996e-6, 3.996e-6};
    /// Mie extinction at sea level [1/m], RGB, >= scattering. Default scattering / 0.9.
    glm::dvec3 mieExtinction{3.996e-6 / 0.9, 3.996e-6 / 0.9, 3.996e-6 / 0.9};
    /// Mie scale height H_M [m]. Default 1200.
    double mieScaleHeight = 1200.0;
    /// Cornette-Shanks anisotropy g, -0.999..0.999. Default 0.8.
    double mieAnisotropy = 0.8;

    /// Ozone absorption at the peak of its tent profile [1/m], RGB; 0 turns it off.
    glm::dvec3 ozoneAbsorption{0.650e-6, 1.881e-6, 0.085e-6};
    /// Height of the ozone peak [m]. Default 25 000.
    double ozoneCenterHeight = 25000.0;
    /// Full width of the ozone tent [m] (density 0 at centre +- width/2). Default 30 000.
    double ozoneWidth = 30000.0;

    /// Lambertian albedo of the ground [0..1], RGB: the ground reflects the
    /// sun into the sky's higher scattering orders (the multiple-scattering
    /// LUT of <aerial/sky.hpp>). Default 0.3 grey.
    glm::dvec3 groundAlbedo{0.3, 0.3, 0.3};
};

constexpr double kPi = 3.14159265358979323846;

/// Rayleigh phase function 3/(16 pi) (1 + mu^2) [1/sr]; mu = cos(view, light).
double rayleighPhase(double mu);

/// Cornette-Shanks phase function
/// 3/(8 pi) (1 - g^2)(1 + mu^2) / ((2 + g^2)(1 + g^2 - 2 g mu)^1.5) [1/sr].
/// Finite for every |g| < 1 and mu in [-1, 1] (inputs are clamped).
double miePhase(double mu, double g);

/// Relative densities (0..1 at sea level) at height h [m] above the ground.
double rayleighDensity(const AtmosphereParams& air, double height);
double mieDensity(const AtmosphereParams& air, double height);
double ozoneDensity(const AtmosphereParams& air, double height);

/// Extinction coefficient [1/m], RGB, at height h [m]: Rayleigh + Mie + ozone.
glm::dvec3 extinctionAt(const AtmosphereParams& air, double height);

/// Distance [m] from a point at radius r along a ray whose cosine with the
/// local zenith is muZenith to the top of the atmosphere (>= 0).
double distanceToTop(const AtmosphereParams& air, double r, double muZenith);

/// True when a ray from radius r with zenith cosine muZenith hits the ground.
bool rayHitsGround(const AtmosphereParams& air, double r, double muZenith);

/// Transmittance [0..1], RGB, from a point at height h [m] towards a light
/// with zenith cosine muZenith, out to space; 0 when the ray hits the
/// ground. Numerical quadrature, double precision: used for the sun colour
/// that lights the scene (DESIGN.md: "dimmed by T(viewer -> sun)").
glm::dvec3 transmittanceToSpace(const AtmosphereParams& air, double height, double muZenith);

}  // namespace aerial
