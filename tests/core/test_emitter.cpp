// Emitters: the closed-form in-scatter (DESIGN.md, "Emitters") against
// sinh-graded Gauss-Legendre quadrature of the field i / (1 + a |l - p|^2),
// and the seeded lightning flash pattern.
#include <aerial/atmosphere.hpp>
#include <aerial/emitter.hpp>

#include <gtest/gtest.h>

#include "quadrature.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

namespace {

using aerial::Emitter;
using aerial::EmitterKind;

/// The field written out (not the library's emitterFieldAt).
double referenceField(const Emitter& e, const glm::dvec3& p) {
    const glm::dvec3 c = e.position - p;
    return e.intensity / (1.0 + e.attenuation * glm::dot(c, c));
}

/// Quadrature of the field along origin + s n, s in [0, |delta|]: split at
/// the closest approach to the emitter, graded by the field's width there,
/// 2000 five-point sub-intervals per side (20 000 evaluations).
double referenceIntegral(const Emitter& e, const glm::dvec3& origin, const glm::dvec3& delta) {
    const double length = glm::length(delta);
    if (!(length > 0.0)) {
        return 0.0;
    }
    const glm::dvec3 n = delta / length;
    auto f = [&](double s) { return referenceField(e, origin + s * n); };
    if (e.attenuation == 0.0) {
        return aerial::test::gaussLegendre(f, 0.0, length, 2000);
    }
    const glm::dvec3 c = e.position - origin;
    const double closest = glm::dot(c, n);
    const glm::dvec3 perp = c - closest * n;
    const double width = std::sqrt((1.0 + e.attenuation * glm::dot(perp, perp)) / e.attenuation);
    return aerial::test::gaussLegendrePeaked(f, 0.0, length, closest, width, 2000);
}

TEST(Emitter, KnownAnswers) {
    Emitter e;
    e.position = {1, 2, 3};
    e.intensity = 2.5;
    e.attenuation = 0.0;
    // a = 0: a uniform field, exactly i |d|.
    EXPECT_DOUBLE_EQ(aerial::emitterIntegral(e, {0, 0, 0}, {3, 4, 0}), 2.5 * 5.0);
    // Symmetric segment through the emitter: 2 i atan(L sqrt(a)) / sqrt(a).
    e.attenuation = 0.04;
    const double expected = 2.0 * 2.5 * std::atan(30.0 * 0.2) / 0.2;
    EXPECT_NEAR(aerial::emitterIntegral(e, {-29, 2, 3}, {60, 0, 0}), expected, 1e-13 * expected);
    // Zero-length segments and zero intensity give 0.
    EXPECT_EQ(aerial::emitterIntegral(e, {5, 5, 5}, {0, 0, 0}), 0.0);
    Emitter dark = e;
    dark.intensity = 0.0;
    EXPECT_EQ(aerial::emitterIntegral(dark, {0, 0, 0}, {10, 0, 0}), 0.0);
    // In-scatter: colour * scale * integral.
    e.colour = {1.0, 0.5, 0.25};
    const glm::dvec3 in = aerial::emitterInScatter(e, {-29, 2, 3}, {60, 0, 0}, 0.5);
    EXPECT_NEAR(in.x, 0.5 * expected, 1e-13 * expected);
    EXPECT_NEAR(in.y, 0.25 * expected, 1e-13 * expected);
    EXPECT_NEAR(in.z, 0.125 * expected, 1e-13 * expected);
    // The field: i / (1 + a r^2).
    EXPECT_DOUBLE_EQ(aerial::emitterFieldAt(e, {1, 2, 8}), 2.5 / (1.0 + 0.04 * 25.0));
}

TEST(Emitter, MatchesQuadratureOverRandomisedParameters) {
    // Tolerance: 1e-4 relative (the integral is > 0 in every case; no
    // floor needed). Observed errors are ~1e-12.
    std::mt19937_64 rng(6292006);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::normal_distribution<double> normal(0.0, 1.0);
    auto logUniform = [&](double lo, double hi) {
        return std::exp(std::log(lo) + unit(rng) * (std::log(hi) - std::log(lo)));
    };
    auto direction = [&]() {
        glm::dvec3 v{normal(rng), normal(rng), normal(rng)};
        return v / glm::length(v);
    };
    double worst = 0.0;
    for (int i = 0; i < 500; ++i) {
        Emitter e;
        e.intensity = logUniform(1e-3, 1e3);
        e.attenuation = (i % 10 == 0) ? 0.0 : logUniform(1e-7, 1e2);
        const glm::dvec3 origin{unit(rng) * 2000 - 1000, unit(rng) * 200, unit(rng) * 2000 - 1000};
        const double length = logUniform(1e-2, 2e4);
        const glm::dvec3 delta = direction() * length;
        switch (i % 5) {
            case 0:  // on the segment (passes exactly through)
                e.position = origin + unit(rng) * delta;
                break;
            case 1:  // near the segment
                e.position = origin + unit(rng) * delta + direction() * logUniform(1e-3, 50);
                break;
            case 2:  // far away (1-100 km): the naive atan difference cancels
                e.position = origin + direction() * logUniform(1e3, 1e5);
                break;
            case 3:  // beyond an end, on the line
                e.position = origin + delta * (1.0 + logUniform(1e-3, 10));
                break;
            default:  // anywhere
                e.position = origin + direction() * logUniform(1e-1, 1e4);
                break;
        }
        const double reference = referenceIntegral(e, origin, delta);
        const double got = aerial::emitterIntegral(e, origin, delta);
        const double error = std::fabs(got - reference);
        EXPECT_LE(error, 1e-4 * reference) << "case " << i << " a=" << e.attenuation << " L=" << length
                                           << " ref=" << reference << " got=" << got;
        worst = std::max(worst, error / reference);
    }
    std::printf("[          ] emitters: 500 cases, worst relative error %.3g\n", worst);
}

TEST(Emitter, StableForFarEmittersAndLongSegments) {
    // Cases where atan((v+2w)/k) - atan(v/k) of the paper's form subtracts
    // two nearly equal angles; the library must stay at rounding level.
    // Tolerance 1e-10 relative.
    struct Case {
        glm::dvec3 emitter, origin, delta;
        double attenuation;
    };
    const Case cases[] = {
        {{1e5, 0, 0}, {0, 0, 0}, {0, 1, 0}, 1.0},        // far, short, sideways
        {{1e5, 0, 0}, {0, 0, 0}, {1, 0, 0}, 1.0},        // far, towards it
        {{0, 0, 0}, {5e4, 3, 0}, {1e5, 0, 0}, 0.5},      // long, away from it
        {{0, 1e-3, 0}, {-1e4, 0, 0}, {2e4, 0, 0}, 1e2},  // long, through it
        {{3, 0, 0}, {0, 0, 0}, {1e-4, 0, 0}, 1e-9},      // short, weak attenuation
    };
    for (const Case& c : cases) {
        Emitter e;
        e.position = c.emitter;
        e.attenuation = c.attenuation;
        const double reference = referenceIntegral(e, c.origin, c.delta);
        EXPECT_NEAR(aerial::emitterIntegral(e, c.origin, c.delta), reference, 1e-10 * reference);
    }
}

TEST(Emitter, NonFiniteInputsGiveFiniteAnswers) {
    const double nan = std::nan("");
    const double inf = std::numeric_limits<double>::infinity();
    const double values[] = {nan, inf, -inf, 0.0, 1e308, -1e308, 1e-310, 1.0, -2.0, 1e30, 1e-30};
    std::mt19937_64 rng(11);
    auto pick = [&]() { return values[rng() % std::size(values)]; };
    auto pickVec = [&]() {
        auto one = [&]() {
            return rng() % 3 == 0 ? pick() : std::uniform_real_distribution<double>(-50, 50)(rng);
        };
        return glm::dvec3(one(), one(), one());
    };
    for (int i = 0; i < 20000; ++i) {
        Emitter e;
        e.position = pickVec();
        e.intensity = rng() % 2 ? pick() : 1.0;
        e.attenuation = rng() % 2 ? pick() : 0.1;
        e.colour = pickVec();
        const glm::dvec3 o = pickVec();
        const glm::dvec3 d = pickVec();
        const double scale = rng() % 2 ? pick() : 1.0;
        const double integral = aerial::emitterIntegral(e, o, d);
        ASSERT_TRUE(std::isfinite(integral) && integral >= 0.0) << i;
        const glm::dvec3 in = aerial::emitterInScatter(e, o, d, scale);
        ASSERT_TRUE(std::isfinite(in.x) && std::isfinite(in.y) && std::isfinite(in.z)) << i;
        const double f = aerial::emitterFieldAt(e, o);
        ASSERT_TRUE(std::isfinite(f) && f >= 0.0) << i;
        e.kind = EmitterKind::Lightning;
        e.flashesPerMinute = rng() % 2 ? pick() : 30.0;
        e.flashDurationSeconds = rng() % 2 ? pick() : 0.3;
        e.timeScale = rng() % 2 ? pick() : 60.0;
        const double flash = aerial::lightningFlash(e, rng() % 2 ? pick() : 12.3);
        ASSERT_TRUE(flash >= 0.0 && flash <= 1.0) << i;
    }
}

// --- Lightning -------------------------------------------------------------

Emitter makeBolt(std::uint32_t seed, double perMinute, double duration, double timeScale) {
    Emitter e;
    e.kind = EmitterKind::Lightning;
    e.seed = seed;
    e.flashesPerMinute = perMinute;
    e.flashDurationSeconds = duration;
    e.timeScale = timeScale;
    return e;
}

TEST(Lightning, PointEmittersDoNotFlash) {
    Emitter lamp;
    for (double t : {0.0, 3.3, 12.0, 23.99}) {
        EXPECT_EQ(aerial::lightningFlash(lamp, t), 1.0);
    }
}

TEST(Lightning, ReproducibleFromParametersAloneAndOrderIndependent) {
    const Emitter a = makeBolt(1234, 20.0, 0.4, 60.0);
    const Emitter b = makeBolt(1234, 20.0, 0.4, 60.0);  // a separate object, same parameters
    std::vector<double> times;
    for (int k = 0; k < 200000; ++k) {
        times.push_back(24.0 * k / 200000.0);
    }
    std::vector<double> forward;
    for (double t : times) {
        forward.push_back(aerial::lightningFlash(a, t));
    }
    // Backwards, on the other object, interleaved with another emitter.
    const Emitter other = makeBolt(99, 50.0, 0.2, 1.0);
    int nonZero = 0;
    for (std::size_t k = times.size(); k-- > 0;) {
        (void)aerial::lightningFlash(other, times[k] * 0.37);
        const double v = aerial::lightningFlash(b, times[k]);
        ASSERT_EQ(v, forward[k]) << "t = " << times[k];
        nonZero += v > 0.0 ? 1 : 0;
    }
    EXPECT_GT(nonZero, 100);  // it does flash
}

TEST(Lightning, DifferentSeedsGiveDifferentPatterns) {
    int differing = 0;
    const Emitter a = makeBolt(1, 10.0, 0.35, 60.0);
    const Emitter b = makeBolt(2, 10.0, 0.35, 60.0);
    for (int k = 0; k < 100000; ++k) {
        const double t = 24.0 * k / 100000.0;
        differing += aerial::lightningFlash(a, t) != aerial::lightningFlash(b, t) ? 1 : 0;
    }
    EXPECT_GT(differing, 1000);
}

TEST(Lightning, ValuesInRangeWithFullBrightnessPeaks) {
    const Emitter e = makeBolt(7, 30.0, 0.5, 60.0);
    double peak = 0.0;
    for (int k = 0; k < 500000; ++k) {
        const double v = aerial::lightningFlash(e, 24.0 * k / 500000.0);
        ASSERT_GE(v, 0.0);
        ASSERT_LE(v, 1.0);
        peak = std::max(peak, v);
    }
    EXPECT_GT(peak, 0.9);  // sampled every 0.17 s of a 0.5 s flash with fast decay
}

TEST(Lightning, WrapsAtMidnight) {
    const Emitter e = makeBolt(42, 40.0, 0.3, 60.0);
    // Dyadic times so that t + 24 and t - 24 are exact.
    for (int k = 0; k < 24 * 4096; k += 3) {
        const double t = k / 4096.0;
        const double v = aerial::lightningFlash(e, t);
        ASSERT_EQ(aerial::lightningFlash(e, t + 24.0), v) << t;
        ASSERT_EQ(aerial::lightningFlash(e, t - 24.0), v) << t;
        ASSERT_EQ(aerial::lightningFlash(e, t + 48.0), v) << t;
    }
}

TEST(Lightning, DutyCycleAndRateMatchParametersOverADay) {
    // With the flash clock at game speed (timeScale 1) a day holds
    // thousands of flashes: the fraction of the day spent flashing should be
    // rate * duration / 60 and the number of flashes rate * 1440, each
    // within 6 % (statistical spread ~1-2 %, the pattern being Bernoulli per
    // slot).
    struct Params {
        std::uint32_t seed;
        double perMinute, duration;
    };
    for (const Params& p : {Params{3, 6.0, 0.35}, Params{17, 30.0, 0.2}, Params{5, 2.0, 1.0}}) {
        const Emitter e = makeBolt(p.seed, p.perMinute, p.duration, 1.0);
        const double step = p.duration / 10.0;  // seconds of the flash clock
        const std::size_t samples = static_cast<std::size_t>(86400.0 / step);
        std::size_t lit = 0;
        std::size_t flashes = 0;
        bool previous = false;
        for (std::size_t k = 0; k < samples; ++k) {
            const double hours = (static_cast<double>(k) + 0.5) * step / 3600.0;
            const bool on = aerial::lightningFlash(e, hours) > 0.0;
            lit += on ? 1 : 0;
            flashes += (on && !previous) ? 1 : 0;
            previous = on;
        }
        const double duty = static_cast<double>(lit) / static_cast<double>(samples);
        const double expectedDuty = p.perMinute * p.duration / 60.0;
        EXPECT_NEAR(duty, expectedDuty, 0.06 * expectedDuty) << "rate " << p.perMinute;
        const double expectedFlashes = p.perMinute * 1440.0;
        EXPECT_NEAR(static_cast<double>(flashes), expectedFlashes, 0.06 * expectedFlashes)
            << "rate " << p.perMinute;
    }
}

TEST(Lightning, InvalidParametersMeanNoFlashes) {
    for (const Emitter& e :
         {makeBolt(1, 0.0, 0.3, 60.0), makeBolt(1, -5.0, 0.3, 60.0), makeBolt(1, 10.0, 0.0, 60.0),
          makeBolt(1, 10.0, 0.3, 0.0), makeBolt(1, std::nan(""), 0.3, 60.0)}) {
        for (int k = 0; k < 10000; ++k) {
            ASSERT_EQ(aerial::lightningFlash(e, 24.0 * k / 10000.0), 0.0);
        }
    }
}

}  // namespace
