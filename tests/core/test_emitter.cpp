// Emitters: the closed-form in-scatter (DESIGN.md, "Emitters") against
// sinh-graded Gauss-Legendre quadrature of the field i / (1 + a |l - p|^2),
// the seeded lightning flash pattern, and the photometry (emitter.hpp): the
// blackbody colour against Planck's law through the CIE 1931 observer, the
// candela against the inverse-square law, the shipped campfire against the
// moonlit sky it stands under, and version 2's emitters migrated.
#include <aerial/atmosphere.hpp>
#include <aerial/emitter.hpp>
#include <aerial/evaluate.hpp>
#include <aerial/exposure.hpp>
#include <aerial/photometry.hpp>
#include <aerial/preset.hpp>
#include <aerial/sky_spectral.hpp>

#include <gtest/gtest.h>

#include "cie1931.hpp"
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

// ---- Photometry (emitter.hpp, "Photometry") ----

/// CIE 1931 xy of a blackbody at `kelvin`: Planck's law times the observer
/// (support/cie1931.hpp), summed at its 10 nm points.
glm::dvec2 planckXy(double kelvin) {
    constexpr double h = 6.62607015e-34, c = 2.99792458e8, k = 1.380649e-23;
    glm::dvec3 xyz(0.0);
    for (int i = 0; i < aerial::test::kCmfBands; ++i) {
        const double lambda = (aerial::test::kCmfFirstNm + 10.0 * i) * 1e-9;
        const double radiance = 1.0 / (std::pow(lambda, 5) * (std::exp(h * c / (lambda * k * kelvin)) - 1.0));
        for (int j = 0; j < 3; ++j) xyz[j] += aerial::test::kCmf[i][j] * radiance;
    }
    return glm::dvec2(xyz.x, xyz.y) / (xyz.x + xyz.y + xyz.z);
}

/// CIE 1931 xy of a linear Rec.709 colour (IEC 61966-2-1's matrix).
glm::dvec2 rec709Xy(const glm::dvec3& rgb) {
    const glm::dvec3 xyz{0.4124564 * rgb.r + 0.3575761 * rgb.g + 0.1804375 * rgb.b,
                         0.2126729 * rgb.r + 0.7151522 * rgb.g + 0.0721750 * rgb.b,
                         0.0193339 * rgb.r + 0.1191920 * rgb.g + 0.9503041 * rgb.b};
    return glm::dvec2(xyz.x, xyz.y) / (xyz.x + xyz.y + xyz.z);
}

TEST(EmitterPhotometry, BlackbodyColourFollowsPlancksLaw) {
    // Within Rec.709's gamut (above ~1 900 K): the chromaticity within 0.003
    // in xy of Planck's law (Kim et al.'s fit is ~1e-3, the 10 nm sum a
    // little more), and luminance 1.
    double worst = 0.0;
    for (double kelvin : {2000.0, 2700.0, 3500.0, 5000.0, 6500.0, 10000.0, 20000.0}) {
        const glm::dvec3 rgb = aerial::blackbodyColour(kelvin);
        EXPECT_NEAR(aerial::luminance(rgb), 1.0, 1e-12) << kelvin;
        const double d = glm::length(rec709Xy(rgb) - planckXy(kelvin));
        worst = std::max(worst, d);
        EXPECT_LE(d, 0.003) << kelvin << " K";
    }
    std::printf("[ measured ] blackbody colour vs Planck x CIE 1931: worst |dxy| %.5f\n", worst);
    // A campfire is orange-red, a hot star blue; out-of-range and non-finite
    // inputs clamp or give white, never NaN.
    const glm::dvec3 fire = aerial::blackbodyColour(1900.0);
    EXPECT_GT(fire.r, fire.g);
    EXPECT_GT(fire.g, fire.b);
    const glm::dvec3 star = aerial::blackbodyColour(20000.0);
    EXPECT_GT(star.b, star.r);
    for (double kelvin : {0.0, -5.0, 1e9, std::nan(""), std::numeric_limits<double>::infinity()}) {
        const glm::dvec3 rgb = aerial::blackbodyColour(kelvin);
        EXPECT_TRUE(std::isfinite(rgb.r + rgb.g + rgb.b)) << kelvin;
        EXPECT_NEAR(aerial::luminance(rgb), 1.0, 1e-12) << kelvin;
    }
}

TEST(EmitterPhotometry, CandelaLightFogByTheInverseSquareLaw) {
    // A point source of I cd seen past at distance b, in fog of scattering
    // sigma: the in-scatter per metre sigma I / (4 pi r^2) (isotropic),
    // integrated along the view, sigma I / (4 pi) * 2 atan(L / B) / B with
    // B = sqrt(b^2 + r0^2), r0 = 1 / sqrt(a) the core. Written out here from
    // the inverse-square law, in cd/m^2.
    const double sigma = 1e-4, cd = 80.0;  // a 1 000 lm campfire in a light haze
    Emitter fire;
    fire.position = {0.0, 1.0, 0.0};
    fire.intensityCd = cd;
    fire.temperatureK = 1900.0;
    fire.attenuation = 4.0;
    fire.intensity = aerial::emitterFogIntensity(fire.intensityCd, fire.attenuation, sigma);
    fire.colour = aerial::emitterColour(fire);
    for (double b : {2.0, 10.0, 50.0, 300.0}) {
        const double halfLength = 2000.0;
        const glm::dvec3 origin{-halfLength, 1.0, b};
        const glm::dvec3 delta{2.0 * halfLength, 0.0, 0.0};
        const double big = std::sqrt(b * b + 1.0 / fire.attenuation);
        const double expected = sigma * cd / (4.0 * aerial::kPi) * 2.0 * std::atan(halfLength / big) / big;
        const double got =
            aerial::luminance(aerial::emitterInScatter(fire, origin, delta, 1.0)) * aerial::kNitsPerRadianceUnit;
        EXPECT_NEAR(got, expected, 1e-9 * expected) << "b = " << b << " m";
    }
    // Extinction: the glow dimmed by exp(-sigma_t D) over the emitter's
    // distance D from the view's start.
    Emitter dimmed = fire;
    dimmed.extinction = sigma;
    const glm::dvec3 origin{-300.0, 1.0, 40.0}, delta{600.0, 0.0, 0.0};
    const double distance = glm::length(fire.position - origin);
    EXPECT_NEAR(aerial::luminance(aerial::emitterInScatter(dimmed, origin, delta, 1.0)),
                aerial::luminance(aerial::emitterInScatter(fire, origin, delta, 1.0)) * std::exp(-sigma * distance),
                1e-12);
    // The light on a surface r metres away: I / (r0^2 + r^2) lx.
    for (double r : {0.0, 1.0, 10.0, 100.0}) {
        const double e = aerial::emitterIlluminance(fire) / (1.0 + fire.attenuation * r * r);
        EXPECT_NEAR(e * aerial::kNitsPerRadianceUnit, cd / (1.0 / fire.attenuation + r * r), 1e-9 * cd) << r;
    }
    // Nothing negative or non-finite gets through.
    EXPECT_EQ(aerial::emitterFogIntensity(-1.0, 4.0, sigma), 0.0);
    EXPECT_EQ(aerial::emitterFogIntensity(cd, std::nan(""), sigma), 0.0);
    EXPECT_EQ(aerial::emitterFogIntensity(cd, 4.0, std::numeric_limits<double>::infinity()), 0.0);
    Emitter black;
    black.colour = {0.0, 0.0, 0.0};
    EXPECT_EQ(aerial::emitterColour(black), glm::dvec3(0.0));
}

aerial::Preset shippedPreset(const char* name) {
    aerial::PresetLoadResult r =
        aerial::loadPreset(std::string(AERIAL_SOURCE_DIR) + "/presets/" + name + ".json");
    EXPECT_TRUE(r.ok()) << name;
    return r.preset ? *r.preset : aerial::Preset{};
}

TEST(EmitterPhotometry, TheDesertCampfireLightsTheAirNearItNotTheSky) {
    // desert_dusk at 02:00: the moon (87 % lit) is up, the campfire burns in
    // the desert's dusty air (visibility ~5 km). Outdoors a campfire does not
    // out-light the moon on air hundreds of metres away: there its
    // illuminance is a small fraction of the moon's, and seen from the
    // default camera's distance (~150 m) the sky above 20 deg keeps its own
    // light; a view passing a few metres from the fire shows its glow.
    const aerial::CompiledPreset preset(shippedPreset("desert_dusk"));
    const aerial::PresetState state = preset.evaluate(2.0);
    ASSERT_EQ(state.emitters.size(), 1u);
    const Emitter& fire = state.emitters[0];
    ASSERT_GT(fire.intensityCd, 50.0);
    ASSERT_LT(fire.intensityCd, 500.0);
    ASSERT_GT(state.moonLight.body.direction.y, 0.2);
    const double moonLux =
        aerial::luminance(state.moonLight.illuminance) * state.moonLight.body.direction.y * aerial::kNitsPerRadianceUnit;
    for (double r : {100.0, 300.0}) {
        const double fireLux =
            aerial::emitterIlluminance(fire) / (1.0 + fire.attenuation * r * r) * aerial::kNitsPerRadianceUnit;
        EXPECT_LT(fireLux, 0.1 * moonLux) << r << " m";
    }
    aerial::SpectralSkySolver sun, moon;
    sun.solve(state.environment.atmosphere, state.sunLight.body.direction);
    moon.solve(state.environment.atmosphere, state.moonLight.body.direction);
    const double zenith = aerial::lightReport(state, sun.table(), moon.table()).zenithLuminance;
    ASSERT_GT(zenith, 1e-3);  // a moonlit sky, cd/m^2
    const glm::dvec3 eye = fire.position + glm::dvec3(0.0, 1.0, 150.0);
    double worst = 0.0;
    for (double elevationDeg : {20.0, 45.0, 90.0}) {
        for (double azimuthDeg = 0.0; azimuthDeg < 360.0; azimuthDeg += 15.0) {
            const double el = elevationDeg * aerial::kPi / 180.0, az = azimuthDeg * aerial::kPi / 180.0;
            const glm::dvec3 dir{std::cos(el) * std::sin(az), std::sin(el), -std::cos(el) * std::cos(az)};
            const double glow = aerial::luminance(aerial::emitterInScatter(fire, eye, 20000.0 * dir, 1.0)) *
                                aerial::kNitsPerRadianceUnit;
            worst = std::max(worst, glow / zenith);
        }
    }
    const double near = aerial::luminance(aerial::emitterInScatter(fire, fire.position + glm::dvec3(-50, 0, 3),
                                                                   glm::dvec3(100, 0, 0), 1.0)) *
                        aerial::kNitsPerRadianceUnit;
    std::printf("[ measured ] desert_dusk 02:00: campfire %.0f cd, moon %.3g lx, sky zenith %.3g cd/m^2; the "
                "fire's glow above 20 deg from 150 m at most %.3g of the zenith, 3 m past it %.3g\n",
                fire.intensityCd, moonLux, zenith, worst, near / zenith);
    EXPECT_LT(worst, 0.15);
    EXPECT_GT(near, 0.1 * zenith);
}

TEST(EmitterPhotometry, Version2EmittersLoadLightingTheirFogTheSame) {
    // A version-2 emitter's intensity_per_m i was the fog's in-scatter next to
    // it (colour x i); version 3 derives that from candela and the fog. The
    // migrated file lights the same fog the same, keys included.
    const char* text = R"({
      "version": 2, "name": "old",
      "fog": {"density_per_m": 0.004, "falloff_per_m": 0.02},
      "emitters": [
        {"id": "lamp", "position_m": [3, 4, -10], "intensity_per_m": 0.005, "attenuation_per_m2": 0.5,
         "colour_rgb": [1, 0.7, 0.38]},
        {"id": "glow", "position_m": [0, 1, 0], "colour_rgb": [0.5, 0.5, 0.5]}
      ],
      "tracks": [
        {"emitter": "lamp", "param": "intensity_per_m", "interpolation": "linear",
         "keys": [{"time_h": 6, "value": 0}, {"time_h": 18, "value": 0.01}]}
      ]
    })";
    const aerial::PresetLoadResult r = aerial::parsePreset(text, "old.json");
    ASSERT_TRUE(r.ok()) << (r.errors.empty() ? "" : r.errors[0].toString());
    EXPECT_TRUE(r.warnings.empty()) << r.warnings[0].toString();
    const aerial::Preset& p = *r.preset;
    ASSERT_EQ(p.emitters.size(), 2u);
    EXPECT_EQ(p.tracks[0].target.param, "intensity_cd");
    EXPECT_DOUBLE_EQ(p.emitters[1].attenuation, 0.01);  // version 2's default
    const aerial::CompiledPreset compiled(p);
    for (double t : {12.0, 18.0}) {
        const aerial::PresetState s = compiled.evaluate(t);
        const double oldLamp = t == 12.0 ? 0.005 : 0.01;
        const glm::dvec3 oldFog = glm::dvec3(1, 0.7, 0.38) * oldLamp;
        const glm::dvec3 newFog = s.emitters[0].colour * s.emitters[0].intensity;
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(newFog[c], oldFog[c], 1e-9 * oldFog[c]) << t << " h";
        const glm::dvec3 oldGlow = glm::dvec3(0.5) * 1.0;  // version 2's default intensity 1 /m
        const glm::dvec3 newGlow = s.emitters[1].colour * s.emitters[1].intensity;
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(newGlow[c], oldGlow[c], 1e-9) << t << " h";
    }
}

}  // namespace

