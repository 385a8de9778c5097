// height_fog.cpp — the analytic exponential-fog integral shared by the global
// height fog and the fog volumes (../shared/DESIGN.md, "Global height fog";
// Wenzel 2006, section 6.4).
//
// For a density b exp(-c (dot(p, axis) - h0)) along o -> o + d (length L,
// rise r = dot(d, axis), height y = dot(o, axis) - h0):
//
//   tau = b L exp(-c y) (1 - exp(-c r)) / (c r).
//
// Written as is, exp(-c y) overflows and the factor (1 - e^-x)/x overflows
// for a ray that climbs into thick fog from far below (x = c r << 0), even
// when the product is moderate. We therefore evaluate the identical
//
//   tau = b L exp(-min(y0, y0 + x)) g(|x|),   g(x) = (1 - e^-x) / x,
//
// with y0 = c y and x = c r (e^-y0 g(x) = e^-(y0 + x) g(-x)), i.e. the
// density at the denser end of the segment times g of a non-negative
// argument, 0 < g <= 1.
// Only the density at the denser end can overflow, and then tau saturates at
// kMaxOpticalDepth.
#include <aerial/height_fog.hpp>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace aerial {
namespace {

/// Magnitude bound applied to every input of the integral: keeps products of
/// two inputs finite (1e150 * 1e150 = 1e300) so no Inf - Inf can form. Far
/// beyond any meaningful scene (metres, 1/m).
constexpr double kInputBound = 1.0e150;

/// Not finite -> 0, otherwise clamped to [-kInputBound, kInputBound].
double sanitiseSigned(double x) { return std::isfinite(x) ? std::clamp(x, -kInputBound, kInputBound) : 0.0; }

/// Not finite or negative -> 0, otherwise clamped to [0, kInputBound].
double sanitiseNonNegative(double x) {
    return (std::isfinite(x) && x > 0.0) ? std::min(x, kInputBound) : 0.0;
}

}  // namespace

double oneMinusExpOverX(double x) {
    if (std::isnan(x)) {
        return 1.0;  // sanitised as x = 0
    }
    if (x == -std::numeric_limits<double>::infinity()) {
        return std::numeric_limits<double>::max();  // (-Inf) / (-Inf) below
    }
    // -expm1(-x) / x is accurate to about one ulp for every x != 0 (expm1
    // keeps the leading -x exactly); x == 0 selects the limit value 1, which
    // is also what the expression tends to, so there is no jump.
    const double e = std::expm1(-x);
    const double g = (x != 0.0) ? -e / x : 1.0;
    // x -> -inf: e^-x / |x| overflows; saturate. x -> +inf: 1/x -> 0.
    return std::min(g, std::numeric_limits<double>::max());
}

double exponentialOpticalDepth(double density, double falloff, double heightAtOrigin, double rise,
                               double length) {
    const double b = sanitiseNonNegative(density);
    const double c = sanitiseNonNegative(falloff);
    const double len = sanitiseNonNegative(length);
    if (!(b > 0.0) || !(len > 0.0)) {
        return 0.0;
    }
    const double y = sanitiseSigned(heightAtOrigin);
    const double r = sanitiseSigned(rise);

    // Exponents at both ends of the segment, all finite (|.| <= 2e300).
    const double x = c * r;    // c * rise: the change of the exponent
    const double y0 = c * y;   // c * height at the start
    const double y1 = y0 + x;  // c * height at the end
    const double yDense = std::min(y0, y1);

    // b L g(|x|) <= 1e300: finite and >= 0.
    const double m = b * len * oneMinusExpOverX(std::fabs(x));
    if (yDense > -700.0) {
        // exp(-yDense) <= e^700 ~ 1e304; the product may still overflow to
        // +Inf, which min() turns into the saturation value.
        return std::min(m * std::exp(-yDense), kMaxOpticalDepth);
    }
    // The denser end is beyond double range: go through logarithms.
    if (!(m > 0.0)) {
        return 0.0;
    }
    const double logTau = std::log(m) - yDense;
    return logTau < std::log(kMaxOpticalDepth) ? std::exp(logTau) : kMaxOpticalDepth;
}

double heightFogOpticalDepth(const HeightFogParams& fog, const glm::dvec3& origin, const glm::dvec3& delta) {
    const bool finite = std::isfinite(origin.x) && std::isfinite(origin.y) && std::isfinite(origin.z) &&
                        std::isfinite(delta.x) && std::isfinite(delta.y) && std::isfinite(delta.z) &&
                        std::isfinite(fog.baseHeight);
    if (!finite) {
        return 0.0;
    }
    // Scaled so that huge components do not overflow the length (the
    // sanitiser then clamps it to 1e150).
    const double scale = std::max({std::fabs(delta.x), std::fabs(delta.y), std::fabs(delta.z)});
    const double length = scale > 0.0 ? scale * glm::length(delta / scale) : 0.0;
    return exponentialOpticalDepth(fog.density, fog.falloff, origin.y - fog.baseHeight, delta.y, length);
}

}  // namespace aerial
