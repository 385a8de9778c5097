// test_exposure.cpp — physical-camera exposure (aerial/exposure.hpp) against
// closed forms: the meter equation, the saturation scale, the exact
// exponential adaptation, and histogram averages against the sorted pixels.
#include <aerial/exposure.hpp>

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
        // The average luminance lands on K / (1.2 S) whatever the scene.
        const double exposed = l * aerial::exposureScale(aerial::ev100FromAverageLuminance(l));
        EXPECT_NEAR(exposed, 12.5 / 120.0, 1e-12) << l;
    }
    EXPECT_DOUBLE_EQ(aerial::exposureScale(0.0), 1.0 / 1.2);
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

}  // namespace
