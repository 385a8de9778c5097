// test_exposure.cpp — physical-camera exposure (aerial/exposure.hpp) against
// closed forms: the meter equation, the saturation scale, the exact
// exponential adaptation, and histogram averages against the sorted pixels.
#include <aerial/evaluate.hpp>
#include <aerial/exposure.hpp>
#include <aerial/preset.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace {

TEST(Exposure, MeterAndScaleAreTheClosedForms) {
    EXPECT_DOUBLE_EQ(aerial::luminance({1.0, 1.0, 1.0}), 1.0);
    EXPECT_DOUBLE_EQ(aerial::luminance({0.0, 1.0, 0.0}), 0.7152);
    EXPECT_DOUBLE_EQ(aerial::luminance({-1.0, 0.0, 2.0}), 0.1444);
    EXPECT_EQ(aerial::luminance({std::nan(""), 1.0, 1.0}), 0.0);
    // 1 / 8 cd/m^2 is EV100 0; each doubling one stop.
    EXPECT_NEAR(aerial::ev100FromAverageLuminance(0.125), 0.0, 1e-12);
    EXPECT_NEAR(aerial::ev100FromAverageLuminance(4000.0), std::log2(4000.0 * 8.0), 1e-12);
    EXPECT_NEAR(aerial::ev100FromAverageLuminance(0.0), -37.0, 1e-12);
    EXPECT_NEAR(aerial::ev100FromAverageLuminance(std::nan("")), -37.0, 1e-12);
    for (double l : {1e-6, 0.01, 1.0, 37.0, 1e5}) {
        // The metered luminance lands on middle grey whatever the scene.
        const double exposed = l * aerial::exposureScale(aerial::ev100FromAverageLuminance(l));
        EXPECT_NEAR(exposed, 0.18, 1e-12) << l;
    }
    EXPECT_DOUBLE_EQ(aerial::exposureScale(0.0), 0.18 * 100.0 / 12.5);
    // Sunny 16 (EV100 15): a grey card (18 %) in 100 000 lx, L = E 0.18 / pi,
    // renders within a third of a stop of middle grey.
    const double card = 100000.0 * 0.18 / 3.14159265358979323846;
    EXPECT_NEAR(std::log2(card * aerial::exposureScale(15.0) / 0.18), 0.0, 0.5);
    EXPECT_TRUE(std::isfinite(aerial::exposureScale(std::numeric_limits<double>::infinity())));
    EXPECT_GT(aerial::exposureScale(-std::numeric_limits<double>::infinity()), 0.0);
}

TEST(Exposure, AdaptationIsTheExactExponentialAndComposes) {
    // Closed form of dE/dt = k (T - E).
    const double e = aerial::adaptEv100(0.0, 10.0, 0.5, 3.0, 1.0);
    EXPECT_NEAR(e, 10.0 - 10.0 * std::exp(-1.5), 1e-12);
    const double down = aerial::adaptEv100(10.0, 0.0, 0.5, 3.0, 1.0);
    EXPECT_NEAR(down, 10.0 * std::exp(-0.5), 1e-12);
    // Ten steps of 0.1 s equal one step of 1 s (frame-rate independent).
    double stepped = 2.0;
    for (int i = 0; i < 10; ++i) stepped = aerial::adaptEv100(stepped, 12.0, 0.1, 2.0, 1.0);
    EXPECT_NEAR(stepped, aerial::adaptEv100(2.0, 12.0, 1.0, 2.0, 1.0), 1e-12);
    EXPECT_EQ(aerial::adaptEv100(3.0, 9.0, 0.0, 1.0, 1.0), 3.0);
    EXPECT_EQ(aerial::adaptEv100(std::nan(""), 9.0, 0.1, 1.0, 1.0), 9.0);
    EXPECT_EQ(aerial::adaptEv100(3.0, 9.0, 0.1, 0.0, 1.0), 9.0);
    EXPECT_EQ(aerial::adaptEv100(3.0, std::nan(""), 0.1, 1.0, 1.0), 3.0);
}

TEST(Exposure, HistogramAverageMatchesTheSortedPixels) {
    // Pixels drawn log-uniformly; the histogram's band average against the
    // geometric mean of the sorted pixels between the same quantiles. Bins
    // are 0.5 stops wide, so the two agree within a quarter stop.
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> stops(-10.0, 6.0);
    aerial::LuminanceHistogram histogram;
    std::vector<double> logs;
    for (int i = 0; i < 20000; ++i) {
        const double s = stops(rng) + (i % 10 == 0 ? 8.0 : 0.0);  // a few very bright pixels
        histogram.add(std::exp2(s));
        logs.push_back(s);
    }
    std::sort(logs.begin(), logs.end());
    for (const auto& [low, high] : {std::pair{0.0, 1.0}, std::pair{0.1, 0.9}, std::pair{0.5, 0.95}}) {
        const auto a = logs.begin() + std::ptrdiff_t(low * logs.size());
        const auto b = logs.begin() + std::ptrdiff_t(high * logs.size());
        double sum = 0.0;
        for (auto it = a; it != b; ++it) sum += *it;
        const double expected = sum / double(b - a);
        EXPECT_NEAR(std::log2(histogram.averageLuminance(low, high)), expected, 0.25) << low << ".." << high;
    }
    // Weighted: one pixel at 2^4 with weight 3 and one at 2^-4 with weight 1.
    aerial::LuminanceHistogram two;
    two.add(16.0, 3.0);
    two.add(1.0 / 16.0, 1.0);
    EXPECT_NEAR(std::log2(two.averageLuminance(0.0, 1.0)), (3.0 * 4.25 + 1.0 * -3.75) / 4.0, 1e-12);
    EXPECT_NEAR(std::log2(two.averageLuminance(0.5, 1.0)), 4.25, 1e-12);  // bin centres
    // Empty, junk and out-of-range input stay finite.
    aerial::LuminanceHistogram junk;
    EXPECT_EQ(junk.averageLuminance(0.1, 0.9), std::exp2(-16.0));
    junk.add(std::nan(""));
    junk.add(-1.0);
    junk.add(std::numeric_limits<double>::infinity());
    junk.add(1.0, std::nan(""));
    EXPECT_EQ(junk.totalWeight(), 3.0);
    EXPECT_TRUE(std::isfinite(junk.averageLuminance(std::nan(""), 2.0)));
    EXPECT_TRUE(std::isfinite(junk.averageLuminance(0.7, 0.2)));
}

TEST(Exposure, PresetExposureMetersTheFrameInCandelas) {
    // A frame of two luminances [radiance units]: 50 % at 0.2, 50 % at 4
    // (a bright sky). The 10-90 % band holds 0.2 with weight 0.4 and 4 with
    // weight 0.4; bins are half a stop, so within a quarter stop of the
    // geometric mean of the band. (The histogram ends at 2^16 cd/m^2 = 13 units.)
    std::vector<float> rgba;
    for (int i = 0; i < 1000; ++i) {
        const float v = i % 2 == 0 ? 4.0f : 0.2f;
        rgba.insert(rgba.end(), {v, v, v, 1.0f});
    }
    const double band = (0.4 * std::log2(0.2 * 5000.0) + 0.4 * std::log2(4.0 * 5000.0)) / 0.8;
    const double average = aerial::meterAverageLuminance(rgba, 4);
    EXPECT_NEAR(std::log2(average * aerial::kNitsPerRadianceUnit), band, 0.25);
    // Every 2nd pixel sees only the sky: step samples whole pixels.
    EXPECT_NEAR(std::log2(aerial::meterAverageLuminance(rgba, 4, 2)), 2.0, 0.25);
    EXPECT_TRUE(std::isfinite(aerial::meterAverageLuminance({}, 4)));
    EXPECT_TRUE(std::isfinite(aerial::meterAverageLuminance(rgba, 2)));  // not RGB: empty

    aerial::ExposureParams p;  // automatic, -12..17
    const double metered = std::log2(average * 5000.0 * 100.0 / 12.5);
    EXPECT_NEAR(aerial::targetEv100(p, average), metered, 1e-12);
    EXPECT_EQ(aerial::targetEv100(p, 1e-12), -12.0);  // night stays night
    EXPECT_EQ(aerial::targetEv100(p, 1e6), 17.0);
    p.mode = aerial::ExposureMode::Manual;
    p.ev100 = 11.0;
    EXPECT_EQ(aerial::targetEv100(p, average), 11.0);
    // The scale: 5000 cd/m^2 per unit times 0.18 S / (K 2^(EV - compensation)).
    p.compensationEv = 2.0;
    EXPECT_NEAR(aerial::radianceScale(p, 11.0), 5000.0 * 1.44 / std::exp2(9.0), 1e-12);
}

// A camera's centre-weighted meter: in a landscape frame whose top 55 % is a
// sky 16x (4 stops) brighter than the ground, the sky counts, but less than
// the ground: the weighted meter reads between them, above the ground by
// less than the 2 stops of an even split and a quarter stop or more below
// the unweighted meter; a small bright light (a campfire: 2 % of the frame
// at 10 000x) does not move it (the 10-90 % band leaves it out).
TEST(Exposure, CentreWeightedMeterCountsTheSkyLessThanTheSubject) {
    const int w = 64, h = 36;
    const auto frame = [&](bool withFire) {
        std::vector<float> rgba;
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                const bool fire = withFire && std::abs(x - w / 2) < 3 && std::abs(y - 2 * h / 3) < 3;
                const float v = fire ? 1000.0f : y < h * 55 / 100 ? 1.6f : 0.1f;
                rgba.insert(rgba.end(), {v, v, v, 1.0f});
            }
        }
        return rgba;
    };
    const std::vector<float> rgba = frame(true);
    const double weighted = std::log2(aerial::meterAverageLuminance(rgba, 4, w, h) / 0.1);
    const double plain = std::log2(aerial::meterAverageLuminance(rgba, 4) / 0.1);
    const double noFire = std::log2(aerial::meterAverageLuminance(frame(false), 4, w, h) / 0.1);
    EXPECT_GT(weighted, 0.5) << weighted;
    EXPECT_LT(weighted, 2.0) << weighted;
    EXPECT_GT(plain, weighted + 0.25) << plain;
    EXPECT_NEAR(weighted, noFire, 0.25);
    // A size that does not match the pixels falls back to the plain meter.
    EXPECT_DOUBLE_EQ(aerial::meterAverageLuminance(rgba, 4, w + 1, h), aerial::meterAverageLuminance(rgba, 4));
}

TEST(Exposure, ThePresetBlockLoadsValidatesAndKeysTheCompensation) {
    const char* text = R"({"version": 1, "name": "x",
        "exposure": {"mode": "manual", "ev100": 12.5, "compensation_ev": -1, "min_ev100": -2, "max_ev100": 16},
        "tracks": [{"param": "exposure.compensation_ev", "interpolation": "linear",
                    "keys": [{"time_h": 6, "value": 0}, {"time_h": 18, "value": 2}]}]})";
    const aerial::PresetLoadResult r = aerial::parsePreset(text, "x.json");
    ASSERT_TRUE(r.ok()) << (r.errors.empty() ? "" : r.errors[0].toString());
    const aerial::ExposureParams& e = r.preset->environment.exposure;
    EXPECT_EQ(e.mode, aerial::ExposureMode::Manual);
    EXPECT_EQ(e.ev100, 12.5);
    EXPECT_EQ(e.minEv100, -2.0);
    EXPECT_EQ(e.adaptUpPerSecond, 3.0);  // the default
    // Keyed: linear between 06:00 (0) and 18:00 (2).
    const aerial::CompiledPreset compiled(*r.preset);
    EXPECT_NEAR(compiled.evaluate(9.0).environment.exposure.compensationEv, 0.5, 1e-12);
    // A file without the block gets the defaults; min above max is an error.
    EXPECT_EQ(aerial::parsePreset(R"({"version": 1, "name": "x"})").preset->environment.exposure.mode,
              aerial::ExposureMode::Automatic);
    const aerial::PresetLoadResult bad = aerial::parsePreset(
        R"({"version": 1, "name": "x", "exposure": {"min_ev100": 9, "max_ev100": 3}})", "b.json");
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(
        bad.errors[0].toString().find("/exposure/min_ev100: minimum EV100 9 must be <= maximum EV100 3"),
        std::string::npos)
        << bad.errors[0].toString();
    const aerial::PresetLoadResult mode =
        aerial::parsePreset(R"({"version": 1, "name": "x", "exposure": {"mode": "auto"}})", "m.json");
    ASSERT_FALSE(mode.ok());
    EXPECT_NE(mode.errors[0].toString().find("/exposure/mode"), std::string::npos)
        << mode.errors[0].toString();
}

}  // namespace

namespace {

// Night vision (aerial::nightVision). The references: CIE 191:2010's
// mesopic range (photopic from 5 cd/m^2, scotopic below 0.005) and the
// published scotopic-to-photopic (S/P) ratios of CIE illuminants A (1.41)
// and D65 (2.47) (Berman 1992; IES TM-24): relative to white, an
// incandescent light looks 1.41 / 2.47 as bright to the rods.

/// Linear Rec.709 of a chromaticity xy with luminance 1.
glm::dvec3 rec709OfXy(double x, double y) {
    const double bigX = x / y, bigZ = (1.0 - x - y) / y;
    return {3.2404542 * bigX - 1.5371385 - 0.4985314 * bigZ, -0.9692660 * bigX + 1.8760108 + 0.0415560 * bigZ,
            0.0556434 * bigX - 0.2040259 + 1.0572252 * bigZ};
}

constexpr double kNits = aerial::kNitsPerRadianceUnit;

TEST(NightVision, DaylightLevelsAreUntouched) {
    for (double nits : {5.0, 20.0, 1e4}) {
        const glm::dvec3 c = glm::dvec3(1.0, 0.6, 0.3) * (nits / kNits / aerial::luminance({1.0, 0.6, 0.3}));
        const glm::dvec3 out = aerial::nightVision(c, kNits);
        for (int i = 0; i < 3; ++i) EXPECT_EQ(out[i], c[i]) << nits;
    }
}

TEST(NightVision, TheMoonlessNightIsBlueAndIncandescentLightDimAsTheRodsSeeIt) {
    // Fully scotopic (2e-4 cd/m^2, the natural night sky): any colour comes
    // out in the night white, blue (B > R), at its scotopic luminance.
    const glm::dvec3 white = aerial::nightVisionWhite();
    EXPECT_NEAR(aerial::luminance(white), 1.0, 1e-6);
    EXPECT_GT(white.b, white.r);
    const glm::dvec3 warmSky = glm::dvec3(1.0, 0.85, 0.65) * (2e-4 / kNits);
    const glm::dvec3 seen = aerial::nightVision(warmSky, kNits);
    EXPECT_GT(seen.b, seen.r);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(seen[i] / aerial::luminance(seen), white[i], 1e-9);
    // S/P of illuminant A against D65, both at 1e-3 cd/m^2.
    const double level = 1e-3 / kNits;
    const glm::dvec3 d65 = rec709OfXy(0.31271, 0.32902) * level;
    const glm::dvec3 a = rec709OfXy(0.44757, 0.40745) * level;
    const double ratio = aerial::luminance(aerial::nightVision(a, kNits)) /
                         aerial::luminance(aerial::nightVision(d65, kNits));
    std::printf("[ measured ] scotopic A / D65 at equal luminance %.3f (published 1.41 / 2.47 = %.3f)\n", ratio,
                1.41 / 2.47);
    EXPECT_NEAR(ratio, 1.41 / 2.47, 0.15 * 1.41 / 2.47);
    EXPECT_NEAR(aerial::luminance(aerial::nightVision(d65, kNits)) / aerial::luminance(d65), 1.0, 0.02);
}

TEST(NightVision, ContinuousThroughTheMesopicRangeAndFinite) {
    // From 1e-4 to 10 cd/m^2 in steps of 0.1 %: no component jumps by more
    // than 1 % of the colour's luminance.
    const glm::dvec3 colour(1.0, 0.5, 0.2);
    glm::dvec3 previous = aerial::nightVision(colour * (1e-4 / kNits), kNits);
    double worst = 0.0;
    for (double nits = 1e-4 * 1.001; nits < 10.0; nits *= 1.001) {
        const glm::dvec3 c = colour * (nits / kNits);
        const glm::dvec3 out = aerial::nightVision(c, kNits);
        for (int i = 0; i < 3; ++i)
            worst = std::max(worst, std::fabs(out[i] / 1.001 - previous[i]) / aerial::luminance(c));
        previous = out;
    }
    EXPECT_LT(worst, 0.01);
    for (const glm::dvec3& bad : {glm::dvec3(std::nan(""), 1.0, 1.0), glm::dvec3(-1.0, 1e-8, 0.0),
                                  glm::dvec3(std::numeric_limits<double>::infinity(), 0.0, 1e-9),
                                  glm::dvec3(0.0), glm::dvec3(0.0, 0.0, 1e-9)}) {
        const glm::dvec3 out = aerial::nightVision(bad, kNits);
        EXPECT_TRUE(std::isfinite(out.x + out.y + out.z)) << bad.x << " " << bad.y << " " << bad.z;
    }
}

}  // namespace
