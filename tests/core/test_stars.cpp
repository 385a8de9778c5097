// test_stars.cpp — naked-eye star visibility (aerial/stars.hpp): the
// surface-brightness conversion against Garstang's nanolambert formula, the
// limiting magnitude against the published sky-brightness form of Hecht's
// law and against what observers report, the field's star counts against
// the real sky's, and the limit over the shipped clear_summer_day sky in
// twilight, on a moonless night and under a full moon.
#include <aerial/evaluate.hpp>
#include <aerial/exposure.hpp>
#include <aerial/night_sky.hpp>
#include <aerial/preset.hpp>
#include <aerial/sky.hpp>
#include <aerial/stars.hpp>

#include "sun_times.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>

namespace {

constexpr double kPi = 3.14159265358979323846;

// Garstang (1986)'s conversion of a V surface brightness into nanolamberts,
// B = 34.08 exp(20.7233 - 0.92104 S), 1 nL = 1e-5 / pi cd/m^2: an
// independent statement of the same photometric zero point.
double garstangNits(double s) { return 34.08 * std::exp(20.7233 - 0.92104 * s) * 1e-5 / kPi; }

TEST(Stars, SurfaceBrightnessAgreesWithGarstang) {
    EXPECT_NEAR(aerial::luminanceFromSkyBrightness(22.0), 1.71e-4, 0.01e-4);
    for (double s = 8.0; s <= 24.0; s += 0.5) {
        const double l = aerial::luminanceFromSkyBrightness(s);
        EXPECT_NEAR(l / garstangNits(s), 1.0, 0.01) << s << " mag/arcsec^2";
        EXPECT_NEAR(aerial::skyBrightnessFromLuminance(l), s, 1e-12);
    }
    EXPECT_EQ(aerial::luminanceFromSkyBrightness(std::nan("")), 0.0);
    EXPECT_TRUE(std::isfinite(aerial::skyBrightnessFromLuminance(0.0)));
    EXPECT_TRUE(std::isfinite(aerial::skyBrightnessFromLuminance(std::nan(""))));
}

// The sky-brightness form of Hecht's law with Schaefer's night constants,
// NELM = 7.93 - 5 log10(10^(4.316 - S/5) + 1), written from the published
// formula (not from the library's foot-candles and nanolamberts): within
// 0.01 mag from daylight (S = 4) to a black sky (S = 26). Observed naked-eye
// limits: 6.4-6.7 under the natural sky (21.6-22 mag/arcsec^2; Schaefer
// 1990's and Crumey 2014's dark-site observers), 4-5 under a full moon
// (S ~ 18.5), nothing of the field (-1.5) in a 2 cd/m^2 twilight sky.
TEST(Stars, LimitingMagnitudeFollowsHechtsLaw) {
    for (double s = 4.0; s <= 26.0; s += 0.25) {
        const double reference = 7.93 - 5.0 * std::log10(std::pow(10.0, 4.316 - s / 5.0) + 1.0);
        EXPECT_NEAR(aerial::limitingMagnitude(aerial::luminanceFromSkyBrightness(s)), reference, 0.01) << s;
    }
    const double dark = aerial::limitingMagnitude(aerial::luminanceFromSkyBrightness(22.0));
    const double natural = aerial::limitingMagnitude(aerial::luminanceFromSkyBrightness(21.6));
    std::printf("limit: %.2f at 22, %.2f at 21.6 mag/arcsec^2\n", dark, natural);
    EXPECT_GE(natural, 6.3);
    EXPECT_LE(dark, 6.8);
    const double fullMoon = aerial::limitingMagnitude(aerial::luminanceFromSkyBrightness(18.5));
    EXPECT_GE(fullMoon, 4.0);
    EXPECT_LE(fullMoon, 5.0);
    EXPECT_LT(aerial::limitingMagnitude(2.0), aerial::kStarFieldBrightest - 0.25);
    // Monotonic, a black sky the dark limit, nothing through an infinite one.
    EXPECT_NEAR(aerial::limitingMagnitude(0.0), 7.93, 0.01);
    EXPECT_EQ(aerial::limitingMagnitude(-1.0), aerial::limitingMagnitude(0.0));
    double previous = aerial::limitingMagnitude(0.0);
    for (double l = 1e-6; l < 1e5; l *= 1.5) {
        const double m = aerial::limitingMagnitude(l);
        EXPECT_LT(m, previous) << l;
        previous = m;
    }
    EXPECT_EQ(aerial::limitingMagnitude(std::numeric_limits<double>::infinity()), aerial::kNoStarMagnitude);
    EXPECT_EQ(aerial::limitingMagnitude(std::nan("")), aerial::kNoStarMagnitude);
}

TEST(Stars, ExtinctionCloudsAndFade) {
    // -2.5 log10(T^X t), X the Kasten-Young air mass.
    EXPECT_NEAR(aerial::extinctedMagnitude(3.0, 0.8, 1.0), 3.0 - 2.5 * std::log10(0.8), 1e-3);
    const double mu30 = 0.5;
    EXPECT_NEAR(aerial::extinctedMagnitude(3.0, 0.8, mu30),
                3.0 - 2.5 * aerial::relativeAirMass(mu30) * std::log10(0.8), 1e-12);
    EXPECT_NEAR(aerial::extinctedMagnitude(3.0, 0.8, 1.0, 0.1) - aerial::extinctedMagnitude(3.0, 0.8, 1.0),
                2.5,
                1e-12);  // a cloud of optical depth ln 10
    EXPECT_EQ(aerial::extinctedMagnitude(3.0, 0.8, -0.1), aerial::kHiddenStarMagnitude);
    EXPECT_EQ(aerial::extinctedMagnitude(3.0, 0.8, 1.0, 0.0), aerial::kHiddenStarMagnitude);
    EXPECT_EQ(aerial::extinctedMagnitude(3.0, 0.0, 1.0), aerial::kHiddenStarMagnitude);
    EXPECT_EQ(aerial::starThresholdFade(4.0, 4.0), 0.5);
    EXPECT_EQ(aerial::starThresholdFade(3.75, 4.0), 1.0);
    EXPECT_EQ(aerial::starThresholdFade(4.25, 4.0), 0.0);
    EXPECT_EQ(aerial::starThresholdFade(std::nan(""), 4.0), 0.0);
}

// Cumulative star counts over the whole sky (Allen's Astrophysical
// Quantities, V): the field's N(m) within a factor 1.3 from magnitude 1 to 6.
TEST(Stars, FieldCountsFollowTheRealSky) {
    const struct {
        double magnitude, count;
    } allen[] = {{1.0, 15.0}, {2.0, 48.0}, {3.0, 171.0}, {4.0, 513.0}, {5.0, 1602.0}, {6.0, 4800.0}};
    for (const auto& row : allen) {
        const double n = aerial::starFieldCount(row.magnitude);
        std::printf("N(< %.0f): field %.0f, sky %.0f\n", row.magnitude, n, row.count);
        EXPECT_NEAR(std::log(n / row.count), 0.0, std::log(1.3)) << row.magnitude;
    }
    EXPECT_EQ(aerial::starFieldMagnitude(0.0), aerial::kStarFieldFaintest);
    EXPECT_EQ(aerial::starFieldMagnitude(1.0 - 1e-9), aerial::kStarFieldBrightest);
    // The fraction of hashes brighter than m is N(m) / N_total.
    for (double m : {0.0, 2.0, 4.5, 6.0}) {
        const double u = 1.0 - std::pow(10.0, 0.5 * (m - aerial::kStarFieldFaintest));
        EXPECT_NEAR(aerial::starFieldMagnitude(u), m, 1e-9);
        EXPECT_NEAR(aerial::starFieldCount(m), aerial::kStarFieldStars * (1.0 - u), 1e-6);
    }
}

// --- The shipped clear_summer_day sky (45 deg N), dated.

class StarsOverClearSummerDay : public ::testing::Test {
protected:
    static aerial::CompiledPreset dated(const char* date) {
        aerial::PresetLoadResult loaded =
            aerial::loadPreset(AERIAL_SOURCE_DIR "/presets/clear_summer_day.json");
        EXPECT_TRUE(loaded.ok());
        aerial::Preset preset = loaded.ok() ? *loaded.preset : aerial::Preset{};
        preset.environment.location.date = date;
        return aerial::CompiledPreset(std::move(preset));
    }
    /// The clear sky's luminance [cd/m^2] as the sky pass composes it: the
    /// sun's and the moon's tables and the airglow.
    struct Sky {
        aerial::PresetState state;
        aerial::SkySolver sun, moon;
        explicit Sky(const aerial::PresetState& s) : state(s) {
            sun.solve(state.environment.atmosphere, state.sunLight.body.direction);
            moon.solve(state.environment.atmosphere, state.moonLight.body.direction);
        }
        double nits(const glm::dvec3& v) const {
            const double g = state.environment.atmosphere.mieAnisotropy;
            const glm::dvec3 radiance =
                aerial::skyRadiance(sun.table(), g, v, state.sunLight.illuminanceSpace) +
                aerial::skyRadiance(moon.table(), g, v, state.moonLight.illuminanceSpace) +
                aerial::airglowRadiance(v, state.zenithTransmittance);
            return aerial::luminance(radiance) * aerial::kNitsPerRadianceUnit;
        }
        /// The faintest magnitude above the atmosphere seen towards v.
        double limit(const glm::dvec3& v) const {
            const double atEye = aerial::limitingMagnitude(nits(v));
            return atEye - (aerial::extinctedMagnitude(0.0, state.zenithTransmittance.y, v.y));
        }
    };
};

// Only the brightest stars at the end of civil twilight (sun -6 deg): the
// limit at the zenith <= 1.5; and no star of the field anywhere with the sun
// at -3 deg (a grid over the sky above 5 deg: the limit there is brighter
// than the field's -1.5 by more than half the fade).
TEST_F(StarsOverClearSummerDay, TwilightShowsOnlyTheBrightest) {
    const aerial::CompiledPreset preset = dated("2025-06-25");
    const Sky civil(preset.evaluate(aerial::test::eveningTimeOfSun(preset, -6.0)));
    const double zenith = civil.limit({0.0, 1.0, 0.0});
    std::printf("sun -6 deg: zenith %.3g cd/m^2 (%.2f mag/arcsec^2), limiting magnitude %.2f\n",
                civil.nits({0.0, 1.0, 0.0}), aerial::skyBrightnessFromLuminance(civil.nits({0.0, 1.0, 0.0})),
                zenith);
    EXPECT_LE(zenith, 1.5);

    const Sky early(preset.evaluate(aerial::test::eveningTimeOfSun(preset, -3.0)));
    double faintest = -100.0;
    for (int e = 5; e <= 90; e += 5) {
        for (int a = 0; a < 360; a += 15) {
            const double el = e * kPi / 180.0, az = a * kPi / 180.0;
            const glm::dvec3 v(std::cos(el) * std::sin(az), std::sin(el), -std::cos(el) * std::cos(az));
            faintest = std::max(faintest, early.limit(v));
        }
    }
    std::printf("sun -3 deg: faintest limit over the sky %.2f\n", faintest);
    EXPECT_LT(faintest, aerial::kStarFieldBrightest - 0.5 * aerial::kStarFadeMagnitudes);
}

// A moonless night (2025-06-25, new moon; the sun below -18 deg at
// midnight at 45 N): sixth-magnitude stars at the zenith (>= 5.5, the
// natural sky of 21.6-22 mag/arcsec^2 gives ~6.2-6.4 above the atmosphere).
// Under the full moon (2025-06-11, moon up at midnight) the limit is
// brighter and the sky holds fewer stars.
TEST_F(StarsOverClearSummerDay, MoonlessNightShowsSixthMagnitudeAndTheMoonFewer) {
    const aerial::CompiledPreset newMoon = dated("2025-06-25");
    const aerial::PresetState dark = newMoon.evaluate(0.0);
    ASSERT_LT(dark.sunLight.body.elevation, -18.0 * kPi / 180.0);
    const Sky moonless(dark);
    const double zenithDark = moonless.limit({0.0, 1.0, 0.0});
    std::printf("new moon: zenith %.3g cd/m^2 (%.2f mag/arcsec^2), limiting magnitude %.2f\n",
                moonless.nits({0.0, 1.0, 0.0}),
                aerial::skyBrightnessFromLuminance(moonless.nits({0.0, 1.0, 0.0})), zenithDark);
    EXPECT_GE(zenithDark, 5.5);

    const aerial::CompiledPreset fullMoon = dated("2025-06-11");
    const aerial::PresetState moonlit = fullMoon.evaluate(0.0);
    ASSERT_GT(moonlit.moonLight.body.elevation, 10.0 * kPi / 180.0);
    ASSERT_GT(moonlit.moonLight.body.illuminatedFraction, 0.95);
    const Sky bright(moonlit);
    const double zenithMoon = bright.limit({0.0, 1.0, 0.0});
    std::printf("full moon: zenith %.3g cd/m^2, limiting magnitude %.2f\n", bright.nits({0.0, 1.0, 0.0}),
                zenithMoon);
    EXPECT_LT(zenithMoon, zenithDark - 1.0);
    EXPECT_LT(aerial::starFieldCount(zenithMoon), 0.5 * aerial::starFieldCount(zenithDark));
}

}  // namespace
