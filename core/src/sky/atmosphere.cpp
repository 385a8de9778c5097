// atmosphere.cpp — phase functions, density profiles, ray geometry against
// the two spheres and the double-precision transmittance to space.
// Model: ../shared/DESIGN.md, "Sky" (Nishita et al. 1993; Bruneton 2017
// defaults and ozone tent).
#include <aerial/atmosphere.hpp>

#include "phase.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace aerial {
namespace {

double clampUnit(double x) {
    // NaN compares false and falls through to 0: a NaN cosine never escapes.
    if (!(x > -1.0)) return x != x ? 0.0 : -1.0;
    return x < 1.0 ? x : 1.0;
}

double safeSqrt(double x) { return x > 0.0 ? std::sqrt(x) : 0.0; }

/// A coefficient [1/m] as the model uses it: negative and NaN -> 0, capped at
/// 1e10 (far beyond any atmosphere) so that sums stay finite.
double coefficient(double x) { return x > 0.0 ? std::min(x, 1e10) : 0.0; }
glm::dvec3 coefficient(const glm::dvec3& v) { return {coefficient(v.x), coefficient(v.y), coefficient(v.z)}; }

// 8-point Gauss-Legendre nodes and weights on [-1, 1] (symmetric halves).
constexpr std::array<double, 4> kGaussNode = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                              0.9602898564975363};
constexpr std::array<double, 4> kGaussWeight = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                                0.1012285362903763};

}  // namespace

double rayleighPhase(double mu) { return detail::rayleighPhaseOf(clampUnit(mu)); }

double miePhase(double mu, double g) {
    return detail::miePhaseOf(clampUnit(mu), std::isfinite(g) ? std::clamp(g, -0.999, 0.999) : 0.0);
}

double rayleighDensity(const AtmosphereParams& air, double height) {
    if (!(air.rayleighScaleHeight > 0.0)) return 0.0;
    return std::exp(-std::max(height, 0.0) / air.rayleighScaleHeight);
}

double mieDensity(const AtmosphereParams& air, double height) {
    if (!(air.mieScaleHeight > 0.0)) return 0.0;
    return std::exp(-std::max(height, 0.0) / air.mieScaleHeight);
}

double ozoneDensity(const AtmosphereParams& air, double height) {
    if (!(air.ozoneWidth > 0.0)) return 0.0;
    const double halfWidth = 0.5 * air.ozoneWidth;
    return std::max(0.0, 1.0 - std::abs(height - air.ozoneCenterHeight) / halfWidth);
}

glm::dvec3 extinctionAt(const AtmosphereParams& air, double height) {
    if (height != height) height = 0.0;
    return coefficient(air.rayleighScattering) * rayleighDensity(air, height) +
           coefficient(air.mieExtinction) * mieDensity(air, height) +
           coefficient(air.ozoneAbsorption) * ozoneDensity(air, height);
}

double distanceToTop(const AtmosphereParams& air, double r, double muZenith) {
    const double mu = clampUnit(muZenith);
    const double rt = air.atmosphereRadius;
    // Roots of s^2 + 2 r mu s + r^2 - Rt^2 = 0; the far one is wanted.
    const double disc = safeSqrt(r * r * (mu * mu - 1.0) + rt * rt);
    const double b = r * mu;
    if (b > 0.0) {
        // -b + disc cancels when the point is near the top and looks up.
        const double num = rt * rt - r * r;
        return num > 0.0 ? num / (b + disc) : 0.0;
    }
    return std::max(disc - b, 0.0);
}

bool rayHitsGround(const AtmosphereParams& air, double r, double muZenith) {
    const double mu = clampUnit(muZenith);
    const double rg = air.planetRadius;
    return mu < 0.0 && r * r * (mu * mu - 1.0) + rg * rg >= 0.0;
}

glm::dvec3 transmittanceToSpace(const AtmosphereParams& air, double height, double muZenith) {
    const double rg = air.planetRadius;
    const double rt = air.atmosphereRadius;
    if (!(rg > 0.0) || !std::isfinite(rg) || !std::isfinite(rt)) return glm::dvec3(1.0);
    if (height != height) height = 0.0;
    const double r = std::clamp(rg + std::max(height, 0.0), rg, std::max(rt, rg));
    const double mu = clampUnit(muZenith);
    if (rayHitsGround(air, r, mu)) return glm::dvec3(0.0);
    const double length = distanceToTop(air, r, mu);
    if (!(length > 0.0)) return glm::dvec3(1.0);

    // Break the path where the integrand has a kink or a turning point: the
    // perigee of a downward ray and the three corners of the ozone tent.
    std::array<double, 12> breaks{};
    int breakCount = 0;
    breaks[breakCount++] = 0.0;
    breaks[breakCount++] = length;
    const double perigee = -r * mu;
    if (perigee > 0.0 && perigee < length) breaks[breakCount++] = perigee;
    if (air.ozoneWidth > 0.0) {
        const double corners[3] = {air.ozoneCenterHeight - 0.5 * air.ozoneWidth, air.ozoneCenterHeight,
                                   air.ozoneCenterHeight + 0.5 * air.ozoneWidth};
        for (double hk : corners) {
            // Distances where |x(s)| = Rg + hk: s^2 + 2 r mu s + r^2 - rk^2 = 0.
            const double rk = rg + hk;
            const double disc = r * r * (mu * mu - 1.0) + rk * rk;
            if (!(disc > 0.0)) continue;
            const double root = std::sqrt(disc);
            for (double s : {-r * mu - root, -r * mu + root})
                if (s > 0.0 && s < length) breaks[breakCount++] = s;
        }
    }
    std::sort(breaks.begin(), breaks.begin() + breakCount);

    // Composite 8-point Gauss-Legendre on each piece: the integrand is smooth
    // (exponentials and linear pieces) between the breaks.
    constexpr int kSubintervals = 96;
    glm::dvec3 depth(0.0);
    for (int piece = 0; piece + 1 < breakCount; ++piece) {
        const double a = breaks[piece];
        const double b = breaks[piece + 1];
        if (!(b > a)) continue;
        const double step = (b - a) / kSubintervals;
        for (int k = 0; k < kSubintervals; ++k) {
            const double mid = a + (k + 0.5) * step;
            const double half = 0.5 * step;
            for (int n = 0; n < 4; ++n) {
                for (double sign : {-1.0, 1.0}) {
                    const double s = mid + sign * half * kGaussNode[n];
                    const double rs = std::sqrt(std::max(r * r + 2.0 * r * mu * s + s * s, 0.0));
                    depth += extinctionAt(air, rs - rg) * (half * kGaussWeight[n]);
                }
            }
        }
    }
    return glm::dvec3(std::exp(-depth.x), std::exp(-depth.y), std::exp(-depth.z));
}

}  // namespace aerial
