// test_renderer_sky.cpp — the sky pass against the CPU (sampleSkyTable /
// skyRadiance, aerial/sky.hpp) per pixel: the table mapping inverted in GLSL,
// bilinear RGBA32F texture filtering with the azimuth wrapping, both phase
// functions per pixel for the sun and the moon; and the sun disc.
#include "gl_fixture.hpp"

#include <aerial/night_sky.hpp>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace aerial::test {
namespace {

using renderer::Camera;
using renderer::FrameDesc;
using renderer::Renderer;
using Image = renderer::Image;

constexpr int kWidth = 160;
constexpr int kHeight = 90;

struct SkyCase {
    const char* name;
    glm::dvec3 eye;
    glm::dvec3 target;
    double fov;
};

class SkyVsCpu : public GlTest {
protected:
    static glm::dvec3 sunDirection() { return glm::normalize(glm::dvec3(0.3, 0.12, -0.9)); }
    static glm::dvec3 moonDirection() { return glm::normalize(glm::dvec3(-0.7, 0.4, 0.3)); }

    PresetState frame() const {
        PresetState air;
        air.sunLight = light(sunDirection(), glm::dvec3(20.0, 19.0, 18.0), glm::dvec3(10.0, 8.0, 6.0));
        air.moonLight = light(moonDirection(), glm::dvec3(0.5, 0.55, 0.6), glm::dvec3(0.3));
        air.environment.atmosphere.mieAnisotropy = 0.76;
        return air;
    }

    /// No stars, no moon disc, the sun disc of the given radius [rad].
    Image renderSky(Renderer& r, const Camera& camera, const PresetState& air, double sunDiscRadius = 0.0) {
        FrameDesc f;
        f.stars = false;
        f.sunDiscRadius = sunDiscRadius;
        f.moonDiscRadius = 0.0;
        f.width = kWidth;
        f.height = kHeight;
        f.precision = renderer::ColourPrecision::Float;
        f.passes.scene = f.passes.globalFog = f.passes.volumes = f.passes.emitters = false;
        r.render(camera, air, f);
        return r.readColour();
    }

    /// What the GPU must show along v: the CPU's sun sky plus moon sky.
    static glm::dvec3 cpuSky(const SkyPair& sky, const PresetState& air, const glm::dvec3& v) {
        const double g = air.environment.atmosphere.mieAnisotropy;
        return skyRadiance(sky.sun, g, v, air.sunLight.illuminanceSpace) +
               skyRadiance(sky.moon, g, v, air.moonLight.illuminanceSpace);
    }
};

Camera skyCamera(const glm::dvec3& eye, const glm::dvec3& target, double fov) {
    Camera c;
    c.eye = eye;
    c.target = target;
    c.verticalFov = fov;
    c.aspect = double(kWidth) / kHeight;
    c.farDistance = 1000.0;
    return c;
}

TEST_F(SkyVsCpu, EveryPixelMatchesSkyRadiance) {
    const SkyPair sky = solveSky(AtmosphereParams{}, sunDirection(), moonDirection());
    Renderer r(rendererDesc());
    ASSERT_TRUE(r.valid()) << r.error();
    r.setSky(sky.sun, sky.moon);
    const PresetState air = frame();
    const SkyCase cases[] = {
        {"towards the sun (halo)", {0, 2, 0}, {0, 2, 0}, 1.2},
        {"away from the sun", {0, 2, 0}, {0, 2, 0}, 1.2},
        {"zenith", {0, 2, 0}, {0, 2, 0}, 1.4},
        {"horizon, wide", {0, 2, 0}, {0, 2, 0}, 2.2},
        {"north (azimuth wrap)", {0, 2, 0}, {0, 2, 0}, 1.0},
    };
    const glm::dvec3 targets[] = {sunDirection() * 10.0 + glm::dvec3(0, 2, 0),
                                  -sunDirection() * 10.0 + glm::dvec3(0, 6, 0), glm::dvec3(0.001, 12.0, 0.0),
                                  glm::dvec3(-10.0, 2.5, 3.0), glm::dvec3(0.0, 3.0, -10.0)};
    double worstAll = 0.0;
    for (int k = 0; k < 5; ++k) {
        Camera camera = skyCamera(cases[k].eye, targets[k], cases[k].fov);
        if (k == 2) camera.up = {0.0, 0.0, -1.0};
        const Image image = renderSky(r, camera, air);
        const renderer::CameraFrame f = renderer::cameraFrame(camera);
        double worst = 0.0;
        int wx = 0, wy = 0;
        for (int y = 0; y < kHeight; ++y) {
            for (int x = 0; x < kWidth; ++x) {
                const glm::dvec3 v = glm::normalize(renderer::farRayAtPixel(f, x, y, kWidth, kHeight));
                const glm::dvec3 cpu = cpuSky(sky, air, v);
                for (int c = 0; c < 3; ++c) {
                    const double gpu = image.at(x, y, c);
                    const double error = std::fabs(gpu - cpu[c]) / std::max(std::fabs(cpu[c]), 1e-6);
                    if (!(error <= worst)) {
                        worst = std::isfinite(error) ? error : 1e30;
                        wx = x;
                        wy = y;
                    }
                }
            }
        }
        std::printf("[ measured ] sky %-24s max relative error %.3g (pixel %d,%d)\n", cases[k].name, worst,
                    wx, wy);
        EXPECT_LT(worst, 1e-3) << cases[k].name;
        worstAll = std::max(worstAll, worst);
    }
    EXPECT_TRUE(log.errors.empty());
}

// The physical night is far below the half-float range: with the sun 16 deg
// down the sky is 1e-9..5e-7 of the radiance unit (the smallest half
// subnormal is 6e-8), which RGBA16F quantised into coloured rings. The
// default target keeps every pixel of it to 1e-3 of the brightest.
TEST_F(SkyVsCpu, DeepTwilightKeepsItsPrecisionInTheDefaultTarget) {
    const glm::dvec3 sun = glm::normalize(glm::dvec3(0.46, -0.28, -0.84));
    const glm::dvec3 moon = glm::normalize(glm::dvec3(-0.3, -0.5, 0.8));
    const SkyPair sky = solveSky(AtmosphereParams{}, sun, moon);
    Renderer r(rendererDesc());
    ASSERT_TRUE(r.valid()) << r.error();
    r.setSky(sky.sun, sky.moon);
    PresetState air;
    air.sunLight = light(sun, glm::dvec3(20.0), glm::dvec3(0.0));
    air.moonLight = light(moon, glm::dvec3(5e-5), glm::dvec3(0.0));
    FrameDesc f;  // the default precision
    f.stars = false;
    f.sunDiscRadius = f.moonDiscRadius = 0.0;
    f.width = kWidth;
    f.height = kHeight;
    f.passes.scene = f.passes.globalFog = f.passes.volumes = f.passes.emitters = false;
    const Camera camera =
        skyCamera({0, 2, 0}, glm::dvec3(0, 2, 0) + glm::dvec3(sun.x, 0.25, sun.z) * 10.0, 2.0);
    r.render(camera, air, f);
    const Image image = r.readColour();
    const renderer::CameraFrame cf = renderer::cameraFrame(camera);
    double brightest = 0.0, worst = 0.0;
    std::vector<glm::dvec3> cpu(std::size_t(kWidth) * kHeight);
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const glm::dvec3 v = glm::normalize(renderer::farRayAtPixel(cf, x, y, kWidth, kHeight));
            // The tables and the airglow, which is part of the sky with the stars off.
            cpu[std::size_t(y) * kWidth + x] =
                v.y > 0.0 ? cpuSky(sky, air, v) + airglowRadiance(v, air.zenithTransmittance)
                          : glm::dvec3(0.0);
            brightest = std::max(brightest, cpu[std::size_t(y) * kWidth + x].x);
        }
    ASSERT_GT(brightest, 0.0);
    ASSERT_LT(brightest, 1e-5);  // deep twilight: all of it below the half range's normals
    int wx = 0, wy = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const glm::dvec3 v = glm::normalize(renderer::farRayAtPixel(cf, x, y, kWidth, kHeight));
            if (v.y <= 0.0) continue;  // the ground, not the sky
            for (int c = 0; c < 3; ++c) {
                const double e =
                    std::fabs(image.at(x, y, c) - cpu[std::size_t(y) * kWidth + x][c]) / brightest;
                if (e > worst) worst = e, wx = x, wy = y;
            }
        }
    std::printf(
        "[ measured ] sky at sun -16 deg: brightest %.3g, worst error %.3g of it (pixel %d,%d: gpu "
        "%.3g cpu %.3g)\n",
        brightest, worst, wx, wy, image.at(wx, wy, 0), cpu[std::size_t(wy) * kWidth + wx].x);
    EXPECT_LT(worst, 1e-3);
}

TEST_F(SkyVsCpu, SetSunRowMappingMatchesSkyRadiance) {
    // A sun 1.5 deg below the horizon: its table's rows crowd towards the
    // horizon and the earth's shadow (SkyTable::bandElevation .. shadowShare,
    // inverted in GLSL); and one 0.07 deg below it, whose columns are also
    // warped around the cap of the earth's shadow (capCurvature,
    // capStrength; skyTableColumnAt in GLSL), seen also straight along the
    // horizon. Error per pixel and channel relative to max(|cpu|, 1e-3 of
    // the brightest CPU value in the image): the shadow side is dark, and
    // there float rounding of the row alone is relative.
    // And one 0.002 deg below it, whose cap's rows below the kink are
    // logarithmic (skyCapBelowRow) and whose columns have the shares of a
    // light just set (SkyCapShape), seen also at the cap's top. And one
    // 0.007 deg below it, whose shares are blended halfway and rounded to
    // whole columns (the knots at x = 2.4, 19.2 and 32.2 otherwise).
    for (const double depression : {1.5, 0.07, 0.002, 0.007}) {
        const double t = std::tan(depression * kPi / 180.0);
        const glm::dvec3 sun = glm::normalize(glm::dvec3(0.3, -t * std::hypot(0.3, 0.9), -0.9));
        const SkyPair sky = solveSky(AtmosphereParams{}, sun, moonDirection());
        ASSERT_GT(sky.sun.shadowShare, 0.0);
        if (depression < 1.0) {
            ASSERT_TRUE(skyTableColumnsWarped(sky.sun));
        }
        Renderer r(rendererDesc());
        ASSERT_TRUE(r.valid()) << r.error();
        r.setSky(sky.sun, sky.moon);
        PresetState air = frame();
        air.sunLight = light(sun, glm::dvec3(20.0, 19.0, 18.0), glm::dvec3(0.0));
        const glm::dvec3 flat = glm::normalize(glm::dvec3(sun.x, 0.0, sun.z));
        const glm::dvec3 eye(0, 2, 0);
        struct View {
            glm::dvec3 target;
            double fov;  // [rad]
        };
        const View views[] = {
            {eye - flat * 10.0 + glm::dvec3(0, 0.3, 0), 0.3},    // the earth's shadow
            {eye + flat * 10.0 + glm::dvec3(0, 0.3, 0), 0.3},    // the afterglow
            {eye - flat * 10.0 + glm::dvec3(0, 0.005, 0), 0.3},  // along the horizon
            // the rows below the top of the cap of the earth's shadow,
            // where the lit sky beside the cap ramps up (0.17 x 0.3 deg,
            // 0.04 deg up, 3 deg from the anti-light point; under one
            // pixel row in the views above)
            {eye + 10.0 * glm::dvec3(-flat.x * std::cos(0.05236) + flat.z * std::sin(0.05236), 0.0007,
                                     -flat.z * std::cos(0.05236) - flat.x * std::sin(0.05236)),
             0.003},
            // the top of the cap of a light just set, where the lit sky
            // beside it ramps up (0.004 x 0.007 deg around 0.98 c up, 0.25
            // deg from the anti-light point)
            {eye + 10.0 * glm::dvec3(-flat.x * std::cos(4.4e-3) + flat.z * std::sin(4.4e-3),
                                     0.98 * sky.sun.shadowElevation,
                                     -flat.z * std::cos(4.4e-3) - flat.x * std::sin(4.4e-3)),
             1.2e-4}};
        for (const View& view : views) {
            const Camera camera = skyCamera(eye, view.target, view.fov);
            const Image image = renderSky(r, camera, air);
            const renderer::CameraFrame f = renderer::cameraFrame(camera);
            std::vector<glm::dvec3> cpu(std::size_t(kWidth) * kHeight);
            double brightest = 0.0;
            for (int y = 0; y < kHeight; ++y) {
                for (int x = 0; x < kWidth; ++x) {
                    const glm::dvec3 v = glm::normalize(renderer::farRayAtPixel(f, x, y, kWidth, kHeight));
                    const glm::dvec3 c = cpuSky(sky, air, v);
                    cpu[std::size_t(y) * kWidth + x] = c;
                    brightest = std::max({brightest, c.x, c.y, c.z});
                }
            }
            double worst = 0.0;
            for (int y = 0; y < kHeight; ++y)
                for (int x = 0; x < kWidth; ++x)
                    for (int c = 0; c < 3; ++c) {
                        const double want = cpu[std::size_t(y) * kWidth + x][c];
                        const double error =
                            std::fabs(image.at(x, y, c) - want) / std::max(std::fabs(want), 1e-3 * brightest);
                        worst = std::max(worst, std::isfinite(error) ? error : 1e30);
                    }
            std::printf("[ measured ] set sun (-%g deg): max error %.3g\n", depression, worst);
            EXPECT_LT(worst, 1e-3) << depression;
        }
    }
    EXPECT_TRUE(log.errors.empty());
}

TEST_F(SkyVsCpu, SunDiscHasTheTransmittedIlluminanceOverItsSolidAngle) {
    const SkyPair sky = solveSky(AtmosphereParams{}, sunDirection(), moonDirection());
    Renderer r(rendererDesc());
    ASSERT_TRUE(r.valid());
    r.setSky(sky.sun, sky.moon);
    const PresetState air = frame();
    const double fov = 0.05;  // ~5.6e-4 rad per pixel: the disc is ~17 px across
    const Camera camera = skyCamera({0, 2, 0}, glm::dvec3(0, 2, 0) + sunDirection(), fov);
    const Image withDisc = renderSky(r, camera, air, 0.004653);
    const Image without = renderSky(r, camera, air);
    const double discRadiance = air.sunLight.illuminance.x / (2.0 * kPi * (1.0 - std::cos(0.004653)));
    int discPixels = 0;
    double worst = 0.0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const double added = double(withDisc.at(x, y, 0)) - without.at(x, y, 0);
            if (added > 0.0) {
                ++discPixels;
                worst = std::max(worst, std::fabs(added - discRadiance) / discRadiance);
            }
        }
    }
    const double pixelAngle = fov / kHeight;
    const double expectedPixels = kPi * std::pow(0.004653 / pixelAngle, 2.0);
    std::printf("[ measured ] sun disc: %d pixels (expected %.0f), radiance error %.3g\n", discPixels,
                expectedPixels, worst);
    EXPECT_NEAR(discPixels, expectedPixels, 0.1 * expectedPixels);
    EXPECT_LT(worst, 1e-3);
}

TEST_F(SkyVsCpu, MoonDiscShowsItsPhaseTheRightWayRound) {
    // A half-lit moon due south (+Z) at 30 deg. Facing south, east is on the
    // left of the picture: a bright limb at position angle 90 deg (from the
    // zenith through east) lights the left half; at 0 deg the upper half.
    // The lit part carries the whole illuminance: the disc's flux is the
    // moon's illuminance whatever the phase.
    const glm::dvec3 m = glm::normalize(glm::dvec3(0.0, std::sin(kPi / 6.0), std::cos(kPi / 6.0)));
    const SkyPair sky = solveSky(AtmosphereParams{}, sunDirection(), m);
    Renderer r(rendererDesc());
    ASSERT_TRUE(r.valid());
    r.setSky(sky.sun, sky.moon);
    const double fov = 0.04, radius = 0.004517;
    const Camera camera = skyCamera({0, 2, 0}, glm::dvec3(0, 2, 0) + m, fov);
    auto render = [&](double limb, double discRadius) {
        PresetState air = frame();
        air.moonLight.body.direction = air.moonLight.body.apparentDirection = m;
        air.moonLight.body.illuminatedFraction = 0.5;
        air.moonLight.body.brightLimbAngle = limb;
        FrameDesc f;
        f.stars = false;
        f.sunDiscRadius = 0.0;
        f.moonDiscRadius = discRadius;
        f.width = kWidth;
        f.height = kHeight;
        f.precision = renderer::ColourPrecision::Float;
        f.passes.scene = f.passes.globalFog = f.passes.volumes = f.passes.emitters = false;
        f.passes.clouds = f.passes.shadows = false;
        r.render(camera, air, f);
        return r.readColour();
    };
    const Image without = render(0.0, 0.0);
    const double pixel = fov / kHeight;  // [rad]
    for (const double limb : {kPi / 2.0, 0.0}) {
        const Image with = render(limb, radius);
        double left = 0.0, right = 0.0, top = 0.0, bottom = 0.0, flux = 0.0;
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) {
                const double added = double(with.at(x, y, 0)) - without.at(x, y, 0);
                if (!(added > 0.0)) continue;
                (x < kWidth / 2 ? left : right) += added;
                (y < kHeight / 2 ? top : bottom) += added;  // row 0 at the top
                flux += added * pixel * pixel;
            }
        const double expected = frame().moonLight.illuminance.x;
        std::printf(
            "[ measured ] half moon, bright limb %.0f deg: left/right %.3g/%.3g, top/bottom %.3g/%.3g, "
            "flux %.4g (illuminance %.4g)\n",
            limb * 180.0 / kPi, left, right, top, bottom, flux, expected);
        if (limb > 1.0) {
            EXPECT_GT(left, 20.0 * right) << "lit on the east, the left when facing south";
        } else {
            EXPECT_GT(top, 20.0 * bottom) << "lit from above";
        }
        EXPECT_NEAR(flux, expected, 0.1 * expected);
    }
}

}  // namespace
}  // namespace aerial::test
