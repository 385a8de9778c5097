// aerial/height_fog.hpp — global height fog, integrated analytically.
//
// Usage:
//   aerial::HeightFogParams fog;
//   fog.density = 0.002; fog.falloff = 0.01; fog.baseHeight = 0.0;
//   double tau = aerial::heightFogOpticalDepth(fog, camera, object - camera);
//   double T = std::exp(-tau);          // L = L_scene T + L_fog (1 - T)
//   // L_fog: the light that reaches the fog (aerial/fog_light.hpp)
//
// Formula (../shared/DESIGN.md, "Global height fog"; Wenzel 2006, eq. for
// exponential height fog): density f(p) = b exp(-c (p.y - h0)); along the
// segment o -> o + d
//   integral f = b exp(-c (o.y - h0)) |d| (1 - exp(-c d.y)) / (c d.y)
// where (1 - e^-x)/x -> 1 as x = c d.y -> 0 is evaluated with expm1 so it is
// finite and accurate for horizontal rays and for c = 0.
//
// Evaluation: the identical form b |d| exp(-c min(y0, y1)) g(|c d.y|), with
// y0, y1 the heights of the two ends and g(x) = (1 - e^-x)/x in (0, 1], i.e.
// the density at the denser end times a factor <= 1, so nothing overflows on
// the way to a moderate result; a result beyond kMaxOpticalDepth saturates.
//
// Sanitising: non-finite inputs are treated as 0; a negative density,
// falloff or length as 0; magnitudes are clamped to 1e150. Every function
// here returns a finite number for every input.
#pragma once

#include <glm/vec3.hpp>

namespace aerial {

/// Global exponential height fog.
struct HeightFogParams {
    /// Density b at the base height [1/m], >= 0. Default 0 (no fog).
    double density = 0.0;
    /// Height falloff c [1/m], >= 0; 0 is a uniform fog. Default 0.
    double falloff = 0.0;
    /// Base height h0 [m] where the density equals b. Default 0.
    double baseHeight = 0.0;
};

/// (1 - exp(-x)) / x, accurate to a few ulp everywhere (-expm1(-x) / x) and
/// exactly 1 at x = 0, its limit. For very negative x it grows like
/// exp(-x)/|x|; the result saturates at the largest finite double instead of
/// becoming Inf. +Inf gives 0; NaN is treated as 0 (gives 1).
double oneMinusExpOverX(double x);

/// Optical depth (dimensionless) of an exponential density
/// b exp(-c (dot(p, axis) - h0)) along o -> o + d, with `heightAtOrigin` =
/// dot(o, axis) - h0 [m], `rise` = dot(d, axis) [m] and `length` = |d| [m]
/// (b = `density` [1/m], c = `falloff` [1/m]). Shared by the global fog
/// (axis = +Y) and fog volumes (axis = their gradient). In [0,
/// kMaxOpticalDepth]; 0 for a zero length or density.
double exponentialOpticalDepth(double density, double falloff, double heightAtOrigin, double rise,
                               double length);

/// The global fog's optical depth along origin -> origin + delta [m]. 0 when
/// any coordinate (or the base height) is not finite.
double heightFogOpticalDepth(const HeightFogParams& fog, const glm::dvec3& origin, const glm::dvec3& delta);

/// Optical depths are clamped to this (transmittance exp(-1e4) is 0 in float
/// and double alike), so no Inf ever leaves the fog math.
constexpr double kMaxOpticalDepth = 1.0e4;

}  // namespace aerial
