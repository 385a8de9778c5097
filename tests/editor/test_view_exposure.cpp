// test_view_exposure.cpp — the viewport's exposure against aerial/exposure.hpp's
// closed forms: the first frame and manual mode jump, automatic mode follows
// the exact exponential at the preset's speeds, and the display gets
// log2(radianceScale) plus the viewer's offset.
#include "view_exposure.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace aerial::editor {
namespace {

ExposureParams automatic() {
    ExposureParams p;
    p.mode = ExposureMode::Automatic;
    p.minEv100 = -4.0;
    p.maxEv100 = 17.0;
    p.adaptUpPerSecond = 3.0;
    p.adaptDownPerSecond = 1.0;
    return p;
}

/// The average luminance [radiance units] that meters to `ev100`.
double luminanceForEv(double ev100) { return std::exp2(ev100) * 12.5 / 100.0 / kNitsPerRadianceUnit; }

TEST(ViewExposure, FirstFrameJumpsThenAdaptsExponentially) {
    const ExposureParams p = automatic();
    ViewExposure e;
    EXPECT_FALSE(e.adapt(p, 0.1));  // nothing metered yet
    e.meter(p, luminanceForEv(12.0));
    EXPECT_TRUE(e.adapt(p, 0.0));
    EXPECT_NEAR(e.ev100(), 12.0, 1e-9);
    // Brighter: speed up = 3 / s; 0.2 s closes 1 - exp(-0.6) of 2 EV.
    e.meter(p, luminanceForEv(14.0));
    EXPECT_TRUE(e.adapt(p, 0.2));
    EXPECT_NEAR(e.ev100(), 14.0 - 2.0 * std::exp(-0.6), 1e-9);
    // Darker: speed down = 1 / s, steps capped at 0.25 s.
    e.meter(p, luminanceForEv(10.0));
    const double from = e.ev100();
    EXPECT_TRUE(e.adapt(p, 5.0));
    EXPECT_NEAR(e.ev100(), 10.0 + (from - 10.0) * std::exp(-0.25), 1e-9);
    // Converges and then stops asking for redraws.
    for (int i = 0; i < 200; ++i) e.adapt(p, 0.25);
    EXPECT_EQ(e.ev100(), 10.0);
    EXPECT_FALSE(e.adapt(p, 0.25));
}

TEST(ViewExposure, AutomaticClampsAndManualIgnoresTheFrame) {
    ExposureParams p = automatic();
    ViewExposure e;
    e.meter(p, luminanceForEv(-9.0));  // a starlit night: clamped to min
    e.settle();
    EXPECT_NEAR(e.ev100(), -4.0, 1e-12);
    e.meter(p, luminanceForEv(21.0));
    e.settle();
    EXPECT_NEAR(e.ev100(), 17.0, 1e-12);
    p.mode = ExposureMode::Manual;
    p.ev100 = 9.5;
    e.meter(p, luminanceForEv(3.0));
    EXPECT_TRUE(e.adapt(p, 0.01));  // manual: at once
    EXPECT_EQ(e.ev100(), 9.5);
}

TEST(ViewExposure, DisplayStopsAreTheRadianceScaleAndTheOffset) {
    ExposureParams p = automatic();
    p.compensationEv = 1.5;
    ViewExposure e;
    e.meter(p, luminanceForEv(15.0));
    e.settle();
    const double expected = std::log2(kNitsPerRadianceUnit * 1.44 / std::exp2(15.0 - 1.5)) - 0.5;
    EXPECT_NEAR(e.displayEv(p, -0.5), expected, 1e-12);
    // The metered average lands on middle grey (0.18) x 2^compensation after the scale.
    EXPECT_NEAR(luminanceForEv(15.0) * std::exp2(e.displayEv(p, 0.0)), 0.18 * std::exp2(1.5), 1e-12);
    EXPECT_TRUE(std::isfinite(e.displayEv(p, std::nan(""))));
}

}  // namespace
}  // namespace aerial::editor
