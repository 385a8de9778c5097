// Global height fog: the analytic integral (DESIGN.md, "Global height fog")
// against composite Gauss-Legendre quadrature of the density itself, the
// (1 - e^-x)/x factor against its Taylor series, saturation and sanitising.
#include <aerial/atmosphere.hpp>
#include <aerial/height_fog.hpp>

#include <gtest/gtest.h>

#include "quadrature.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

namespace {

using aerial::HeightFogParams;
using aerial::kMaxOpticalDepth;

/// Taylor series of (1 - e^-x)/x = sum_n (-x)^n / (n + 1)!, summed until the
/// terms vanish (|x| << 1 here, so a few terms reach full precision).
double taylorOneMinusExpOverX(double x) {
    double sum = 0.0;
    double term = 1.0;  // (-x)^0 / 1!
    for (int n = 0; n < 30; ++n) {
        sum += term;
        term *= -x / static_cast<double>(n + 2);
    }
    return sum;
}

/// The fog density b exp(-c (y - h0)) at height y, written out.
double referenceDensity(const HeightFogParams& fog, double y) {
    return fog.density * std::exp(-fog.falloff * (y - fog.baseHeight));
}

/// Optical depth by quadrature along origin + t delta, t in [0, 1]:
/// 10 000 evaluations at least, more when the exponent changes by more than
/// half an e-fold per sub-interval.
double quadratureOpticalDepth(const HeightFogParams& fog, const glm::dvec3& origin, const glm::dvec3& delta) {
    const double length = glm::length(delta);
    const double efolds = std::fabs(fog.falloff * delta.y);
    const std::size_t intervals = std::max<std::size_t>(2000, static_cast<std::size_t>(2.0 * efolds) + 1);
    return aerial::test::gaussLegendre(
        [&](double t) { return referenceDensity(fog, origin.y + t * delta.y) * length; }, 0.0, 1.0,
        intervals);
}

TEST(HeightFog, OneMinusExpOverXMatchesTaylorSeriesNearZero) {
    // Tolerance: 1e-15 relative (a few ulp) for |x| <= 1e-4.
    for (double x : {1e-12, -1e-12, 1e-8, -1e-8, 1e-4, -1e-4, 1e-6, 3e-10}) {
        const double expected = taylorOneMinusExpOverX(x);
        const double got = aerial::oneMinusExpOverX(x);
        EXPECT_NEAR(got, expected, 1e-15 * std::fabs(expected)) << "x = " << x;
    }
    EXPECT_EQ(aerial::oneMinusExpOverX(0.0), 1.0);
    EXPECT_EQ(aerial::oneMinusExpOverX(-0.0), 1.0);
}

TEST(HeightFog, OneMinusExpOverXIsContinuousAndMatchesDirectFormAwayFromZero) {
    // Reference: the Taylor series up to |x| = 1 (30 terms converge), the
    // direct form beyond (no cancellation there). 1e-14 relative.
    for (double x : {0.01, -0.01, 0.5, -0.7, 1.0, -1.0, 1.5, 10.0, -10.0, 100.0, -300.0}) {
        const double expected = std::fabs(x) <= 1.0 ? taylorOneMinusExpOverX(x) : (1.0 - std::exp(-x)) / x;
        EXPECT_NEAR(aerial::oneMinusExpOverX(x), expected, 1e-14 * std::fabs(expected)) << "x = " << x;
    }
    // No jump anywhere near 0: neighbouring arguments give neighbouring
    // values (|g'| = 1/2 there), down to denormals.
    double previous = aerial::oneMinusExpOverX(-1e-3);
    for (double x = -1e-3; x <= 1e-3; x += 1e-6) {
        const double g = aerial::oneMinusExpOverX(x);
        EXPECT_NEAR(g, previous, 0.6e-6 + 1e-15);
        previous = g;
    }
    EXPECT_EQ(aerial::oneMinusExpOverX(std::numeric_limits<double>::denorm_min()), 1.0);
}

TEST(HeightFog, OneMinusExpOverXSaturates) {
    const double big = aerial::oneMinusExpOverX(-1000.0);
    EXPECT_TRUE(std::isfinite(big));
    EXPECT_EQ(big, std::numeric_limits<double>::max());
    EXPECT_EQ(aerial::oneMinusExpOverX(-std::numeric_limits<double>::infinity()),
              std::numeric_limits<double>::max());
    EXPECT_EQ(aerial::oneMinusExpOverX(std::numeric_limits<double>::infinity()), 0.0);
    EXPECT_EQ(aerial::oneMinusExpOverX(std::nan("")), 1.0);
}

TEST(HeightFog, KnownAnswers) {
    HeightFogParams fog;
    fog.density = 0.01;
    // Uniform fog: tau = b L for any direction, exactly.
    EXPECT_DOUBLE_EQ(aerial::heightFogOpticalDepth(fog, {1, 2, 3}, {300, -400, 0}), 0.01 * 500.0);
    // Vertical ray through an exponential fog: b/c (e^{-c y0} - e^{-c y1}).
    fog.falloff = 0.002;
    fog.baseHeight = 100.0;
    const double y0 = 50.0;
    const double y1 = 1050.0;
    const double expected = fog.density / fog.falloff *
                            (std::exp(-fog.falloff * (y0 - 100.0)) - std::exp(-fog.falloff * (y1 - 100.0)));
    EXPECT_NEAR(aerial::heightFogOpticalDepth(fog, {0, y0, 0}, {0, y1 - y0, 0}), expected, 1e-13 * expected);
    // The same ray backwards gives the same optical depth.
    EXPECT_NEAR(aerial::heightFogOpticalDepth(fog, {0, y1, 0}, {0, y0 - y1, 0}), expected, 1e-13 * expected);
    // Horizontal ray: density at that height times the length.
    const double horizontal = referenceDensity(fog, 300.0) * std::hypot(123.0, 45.0);
    EXPECT_NEAR(aerial::heightFogOpticalDepth(fog, {0, 300, 0}, {123, 0, -45}), horizontal,
                1e-14 * horizontal);
    // Zero-length segments give 0.
    EXPECT_EQ(aerial::heightFogOpticalDepth(fog, {0, 300, 0}, {0, 0, 0}), 0.0);
}

TEST(HeightFog, MatchesQuadratureOverRandomisedParameters) {
    // Tolerance: 1e-4 relative with an absolute floor of 1e-14 (optical
    // depths below it are "no fog"); saturated cases compare against
    // kMaxOpticalDepth. In practice the error is at the 1e-12 level.
    std::mt19937_64 rng(20061);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    auto logUniform = [&](double lo, double hi) {
        return std::exp(std::log(lo) + unit(rng) * (std::log(hi) - std::log(lo)));
    };
    double worst = 0.0;
    int cases = 0;
    for (int i = 0; i < 600; ++i) {
        HeightFogParams fog;
        fog.density = logUniform(1e-6, 1e-1);
        switch (i % 5) {
            case 0:
                fog.falloff = 0.0;
                break;
            case 1:
                fog.falloff = logUniform(1e-13, 1e-8);
                break;  // tiny
            case 2:
                fog.falloff = logUniform(1e-5, 1e-2);
                break;
            case 3:
                fog.falloff = logUniform(1e-2, 0.5);
                break;  // steep
            default:
                fog.falloff = logUniform(1e-4, 5.0);
                break;  // large
        }
        fog.baseHeight = -100.0 + 600.0 * unit(rng);
        const glm::dvec3 origin{-1000.0 + 2000.0 * unit(rng), -50.0 + 1500.0 * unit(rng),
                                -1000.0 + 2000.0 * unit(rng)};
        const double length = logUniform(1e-2, 2e4);
        const double azimuth = 2.0 * aerial::kPi * unit(rng);
        double elevation;
        switch (i % 4) {
            case 0:
                elevation = 0.0;
                break;  // exactly horizontal
            case 1:
                elevation = (unit(rng) - 0.5) * 1e-9;
                break;  // grazing
            case 2:
                elevation = (unit(rng) - 0.5) * 1e-3;
                break;  // nearly horizontal
            default:
                elevation = (unit(rng) - 0.5) * aerial::kPi;
                break;  // anything
        }
        glm::dvec3 delta{std::cos(elevation) * std::cos(azimuth), std::sin(elevation),
                         std::cos(elevation) * std::sin(azimuth)};
        delta *= length;
        if (i % 4 == 0) {
            delta.y = 0.0;
        }
        // Keep the densest point within double range for the reference.
        const double ySpan = std::max(origin.y, origin.y + delta.y) - fog.baseHeight;
        const double yLow = std::min(origin.y, origin.y + delta.y) - fog.baseHeight;
        if (fog.falloff * std::fabs(yLow) > 600.0 || fog.falloff * std::fabs(ySpan) > 600.0) {
            continue;
        }
        const double reference = quadratureOpticalDepth(fog, origin, delta);
        const double got = aerial::heightFogOpticalDepth(fog, origin, delta);
        ++cases;
        if (reference >= kMaxOpticalDepth) {
            EXPECT_EQ(got, kMaxOpticalDepth) << "case " << i;
            continue;
        }
        const double error = std::fabs(got - reference);
        EXPECT_LE(error, 1e-4 * reference + 1e-14)
            << "case " << i << " b=" << fog.density << " c=" << fog.falloff << " h0=" << fog.baseHeight
            << " o.y=" << origin.y << " d=(" << delta.x << "," << delta.y << "," << delta.z
            << ") ref=" << reference << " got=" << got;
        if (reference > 1e-14) {
            worst = std::max(worst, error / reference);
        }
    }
    EXPECT_GE(cases, 400);
    std::printf("[          ] height fog: %d cases, worst relative error %.3g\n", cases, worst);
}

TEST(HeightFog, HugeExponentsSaturateInsteadOfOverflowing) {
    // Looking up from 1 km below a fog with a 1/m falloff: e^1000 overflows
    // a double; the optical depth saturates.
    HeightFogParams fog{0.01, 1.0, 0.0};
    const double up = aerial::heightFogOpticalDepth(fog, {0, -1000, 0}, {0, 2000, 0});
    EXPECT_EQ(up, kMaxOpticalDepth);
    // The same segment walked backwards (x = c d.y << 0 at the start).
    EXPECT_EQ(aerial::heightFogOpticalDepth(fog, {0, 1000, 0}, {0, -2000, 0}), kMaxOpticalDepth);
    // Far above a thin fog, climbing: underflows gracefully to (near) 0.
    const double high = aerial::heightFogOpticalDepth(fog, {0, 5000, 0}, {0, 10, 0});
    EXPECT_GE(high, 0.0);
    EXPECT_LT(high, 1e-300);
    // Descending from far above into the fog: only the dense end matters,
    // e^-(c y_end) g(|x|), no Inf * 0 on the way.
    const double down = aerial::heightFogOpticalDepth(fog, {0, 1500, 0}, {0, -1490, 0});
    const double expected = 0.01 * (std::exp(-10.0) - std::exp(-1500.0));
    EXPECT_NEAR(down, expected, 1e-13 * expected);
    // A tiny density far below still gives a finite, accurate answer through
    // the logarithmic path: b L e^{-c y_dense} with e^702 beyond the direct
    // path's range, the product ~0.74.
    const double tiny = aerial::exponentialOpticalDepth(1e-305, 1.0, -702.0, 0.0, 1.0);
    const double tinyExpected = std::exp(std::log(1e-305) + 702.0);
    EXPECT_NEAR(tiny, tinyExpected, 1e-11 * tinyExpected);
}

TEST(HeightFog, SanitisesNonFiniteInputs) {
    const double nan = std::nan("");
    const double inf = std::numeric_limits<double>::infinity();
    for (double b : {nan, inf, -inf, -1.0, 0.0, 1e308, 0.01}) {
        for (double c : {nan, inf, -inf, -1.0, 0.0, 1e308, 0.01}) {
            for (double y : {nan, inf, -inf, 0.0, -1e308, 1e308, 5.0}) {
                for (double r : {nan, inf, -inf, 0.0, -1e308, 1e308, 3.0}) {
                    for (double len : {nan, inf, -inf, 0.0, 1e308, 4.0}) {
                        const double tau = aerial::exponentialOpticalDepth(b, c, y, r, len);
                        ASSERT_TRUE(std::isfinite(tau));
                        ASSERT_GE(tau, 0.0);
                        ASSERT_LE(tau, kMaxOpticalDepth);
                    }
                }
            }
        }
    }
    HeightFogParams fog{0.01, 0.001, 0.0};
    EXPECT_EQ(aerial::heightFogOpticalDepth(fog, {nan, 0, 0}, {1, 1, 1}), 0.0);
    EXPECT_EQ(aerial::heightFogOpticalDepth(fog, {0, 0, 0}, {inf, 1, 1}), 0.0);
    fog.baseHeight = nan;
    EXPECT_EQ(aerial::heightFogOpticalDepth(fog, {0, 0, 0}, {1, 1, 1}), 0.0);
}

}  // namespace
