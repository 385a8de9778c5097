// planet_shadow.hpp — private: where a view ray crosses the planet's shadow
// (the cylinder of radius Rg around the light's axis, behind the planet),
// in a form that stays exact for rays within a hair of that axis.
//
// The sky solver (sky_solver.cpp) cuts every view ray at the shadow's edges
// and the table mapping (sky_table.cpp) finds the kink of the earth's shadow
// opposite a light just set from the same cylinder. Opposite such a light
// the view ray is within 1e-7 rad of the axis: 1 - mu^2 computed as written
// keeps no correct digit there (mu^2 rounds to 1 - 1e-16), and the textbook
// root (-b + sqrt(b^2 - a c)) / a cancels. Both are taken in forms without
// cancellation here.
#pragma once

#include <algorithm>
#include <cmath>

namespace aerial::detail {

/// A view ray whose 1 - mu^2 (mu: cosine to the light) is at most this,
/// within 1e-12 rad of the cylinder's axis, counts as running along it.
inline constexpr double kShadowAxisA2 = 1e-24;

/// 1 - cos(angle) between the directions at elevations a and b [rad] whose
/// azimuths differ by d [rad]: 2 sin^2((a - b) / 2) + 2 cos a cos b
/// sin^2(d / 2), without the cancellation of 1 - cos for small angles; from
/// its parts e = sin((a - b) / 2), cc = cos a cos b and f = sin(d / 2), for
/// a caller that keeps e and cc over many azimuths.
inline double oneMinusCosFromParts(double e, double cc, double f) { return 2.0 * (e * e + cc * f * f); }
inline double oneMinusCosBetween(double a, double b, double d) {
    return oneMinusCosFromParts(std::sin(0.5 * (a - b)), std::cos(a) * std::cos(b), std::sin(0.5 * d));
}

/// The roots lo <= hi of a s^2 + 2 b s + c = 0 (a > 0), without the
/// cancellation of (-b +- sqrt(b^2 - a c)) / a where a c << b^2; false (lo,
/// hi untouched) when there are none. Roots may be +-inf where a is tiny.
inline bool halfQuadraticRoots(double a, double b, double c, double& lo, double& hi) {
    const double disc = b * b - a * c;
    if (!(disc > 0.0) || !(a > 0.0)) return false;
    const double q = -(b + std::copysign(std::sqrt(disc), b));  // never 0: disc > 0
    const double r1 = q / a, r2 = c / q;
    lo = std::min(r1, r2);
    hi = std::max(r1, r2);
    return true;
}

}  // namespace aerial::detail
