// test_renderer_fog.cpp — GPU fog against the CPU reference (FogScene, the
// contract of fog_query.hpp) on the same inputs, every pixel: global height
// fog, box and ellipsoid volumes (rotated, non-uniformly scaled, gradients in
// arbitrary directions, offsets, colour modes) with the camera outside,
// inside and straddling the hull (near-plane crossing), and emitters; the
// sky fog colour at twilight, where it takes the horizon row behind it, and
// under a cloud deck, where it takes the deck's underside.
//
// Method: render the scene pass alone (L_scene) and the full frame into
// RGBA32F targets, read back the linear depth, reconstruct each pixel's
// scene point in double (eye + depth01 * farRay), query the CPU and compare
// (gl_fixture.hpp, compareWithCpu). Tolerance: 1e-3 relative to the
// unfogged value.
#include "gl_fixture.hpp"

#include <aerial/fog_volume.hpp>
#include <aerial/renderer/scene.hpp>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <cstdio>

namespace aerial::test {
namespace {

using renderer::Camera;
using renderer::FrameDesc;

constexpr double kTolerance = 1e-3;

class FogVsCpu : public FogVsCpuTest {
protected:
    FogVsCpu() = default;
    FogVsCpu(const glm::dvec3& sun, const glm::dvec3& moon) : FogVsCpuTest(sun, moon) {}
    /// Renders with and without fog and compares every pixel with the CPU.
    FogComparison run(const char* name, const Camera& camera, const PresetState& air,
                      double wallDepth = 400.0) {
        const FogComparison c = renderAndCompare(camera, air, wallDepth);
        std::printf(
            "[ measured ] %-34s max error %.3g (pixel %d,%d), mean T %.3f, mean S %.3g, inside hulls %d\n",
            name, c.maxError, c.worstX, c.worstY, c.meanTransmittance, c.meanInScatter,
            renderer_->stats().volumesDrawnInside);
        EXPECT_TRUE(log.errors.empty()) << log.errors.front();
        return c;
    }
};

TEST_F(FogVsCpu, GlobalHeightFog) {
    PresetState air = baseFrame();
    air.environment.fog = {0.004, 0.02, 3.0};
    const FogComparison c = run("global fog", fogCamera({0, 25, 0}, {0, 18, -100}), air);
    EXPECT_LT(c.maxError, kTolerance);
    EXPECT_LT(c.meanTransmittance, 0.9);  // the fog is not trivial
}

// The sun 3 deg below the horizon: the horizon row behind the fog varies by
// orders of magnitude in azimuth (the glow towards the sun, the earth's
// shadow opposite); far fog takes the sky behind it (horizonSkySample),
// near fog the light that reaches it (aerial/fog_light.hpp). Looking
// towards the sun, across and away, the GPU matches the CPU.
class FogVsCpuAtTwilight : public FogVsCpu {
protected:
    FogVsCpuAtTwilight()
        : FogVsCpu(glm::normalize(glm::dvec3(0.6, -0.0524, -0.8)),
                   glm::normalize(glm::dvec3(-0.6, 0.2, 0.5))) {}
};

TEST_F(FogVsCpuAtTwilight, GlobalFogTakesTheSkyBehindIt) {
    PresetState air = baseFrame();
    air.environment.fog = {0.004, 0.02, 3.0};
    // A set sun's sky is dim: brighter light makes the in-scattering as large
    // as the scene behind it, so the tolerance (relative to the larger) bites.
    air.sunLight.illuminanceSpace *= 30.0;
    air.sunLight.illuminance = glm::dvec3(0.0);  // below the horizon nothing of it reaches the fog
    const double sunAzimuth = std::atan2(0.6, 0.8);
    const FogScene scene(aerial::fogSceneDesc(air, sky_->sun, sky_->moon));
    glm::dvec3 towards(0.0), away(0.0), nearTowards(0.0), nearAway(0.0);
    for (double turn : {0.0, 0.5 * kPi, kPi}) {
        const double az = sunAzimuth + turn;
        const glm::dvec3 target(100.0 * std::sin(az), 18.0, -100.0 * std::cos(az));
        char name[64];
        std::snprintf(name, sizeof name, "twilight fog, %.0f deg from the sun", turn * 180.0 / kPi);
        const FogComparison c = run(name, fogCamera({0, 25, 0}, target), air);
        EXPECT_LT(c.maxError, kTolerance) << name;
        const glm::dvec3 level(std::sin(az), 0.0, -std::cos(az));
        (turn == 0.0 ? towards : away) = scene.fogColour(level);
        (turn == 0.0 ? nearTowards : nearAway) = scene.fogColour(level, 100.0);
    }
    // The point of it: towards the glow far fog is far brighter than
    // opposite; fog 100 m away, lit by the sky dome (brighter on the sun's
    // side: its forward scattering), much less so.
    std::printf("[ measured ] twilight fog, red towards / away the sun: far %.3g, 100 m %.3g\n",
                towards.r / away.r, nearTowards.r / nearAway.r);
    EXPECT_GT(towards.r, 10.0 * away.r);
    EXPECT_LT(nearTowards.r / nearAway.r, 0.25 * towards.r / away.r);
}

TEST_F(FogVsCpu, GlobalFogHorizontalRaysAndUniformFog) {
    // A level camera: the centre rows have d.y -> 0 (c d.y -> 0 must not jump).
    PresetState air = baseFrame();
    air.environment.fog = {0.003, 0.05, 0.0};
    FogComparison c = run("global fog, level camera", fogCamera({0, 10, 0}, {0, 10, -100}), air);
    EXPECT_LT(c.maxError, kTolerance);
    air.environment.fog = {0.002, 0.0, 0.0};  // c = 0: uniform
    c = run("global fog, c = 0", fogCamera({0, 10, 0}, {0, 10, -100}), air);
    EXPECT_LT(c.maxError, kTolerance);
    air.environment.fog = {0.01, 0.2, -40.0};  // thin air far above the base: large c y
    c = run("global fog, far above the base", fogCamera({0, 30, 0}, {0, 5, -100}), air);
    EXPECT_LT(c.maxError, kTolerance);
}

TEST_F(FogVsCpu, BoxVolumeCameraOutside) {
    PresetState air = baseFrame();
    air.environment.fog = {0.001, 0.02, 0.0};
    air.volumes.push_back(testVolume(FogVolumeShape::Box));
    const FogComparison c = run("box, outside", fogCamera({0, 15, 10}, {0, 8, -60}), air);
    EXPECT_LT(c.maxError, kTolerance);
    EXPECT_EQ(renderer_->stats().volumesDrawn, 1);
    EXPECT_EQ(renderer_->stats().volumesDrawnInside, 0);
}

TEST_F(FogVsCpu, EllipsoidVolumeCameraOutside) {
    PresetState air = baseFrame();
    air.volumes.push_back(testVolume(FogVolumeShape::Ellipsoid));
    const FogComparison c = run("ellipsoid, outside", fogCamera({0, 15, 10}, {0, 8, -60}), air);
    EXPECT_LT(c.maxError, kTolerance);
    EXPECT_EQ(renderer_->stats().volumesDrawnInside, 0);
}

TEST_F(FogVsCpu, VolumesCameraInside) {
    for (FogVolumeShape shape : {FogVolumeShape::Box, FogVolumeShape::Ellipsoid}) {
        PresetState air = baseFrame();
        FogVolume v = testVolume(shape);
        air.volumes.push_back(v);
        // Eye at the centre, looking out through the side, the box in view.
        const FogComparison c = run(shape == FogVolumeShape::Box ? "box, inside" : "ellipsoid, inside",
                                    fogCamera(v.position, v.position + glm::dvec3(30.0, -4.0, -40.0)), air);
        EXPECT_LT(c.maxError, kTolerance);
        EXPECT_EQ(renderer_->stats().volumesDrawnInside, 1);
    }
}

TEST_F(FogVsCpu, SoftEdgedVolumes) {
    // Soft edges (fog_volume.hpp, "Soft edges"): the GPU's piecewise closed
    // form (common/soft_volume.glsl) against the CPU's, camera outside and
    // inside, softness 0.3 and 1, the rotated, graded test volumes. The soft
    // profile changes these pixels by far more than the tolerance (checked:
    // the CPU transmittance through the box's middle, hard against soft).
    for (FogVolumeShape shape : {FogVolumeShape::Box, FogVolumeShape::Ellipsoid}) {
        for (double sigma : {0.3, 1.0}) {
            PresetState air = baseFrame();
            FogVolume v = testVolume(shape);
            v.edgeSoftness = sigma;
            air.volumes.push_back(v);
            char name[64];
            std::snprintf(name, sizeof name, "%s soft %.1f, outside",
                          shape == FogVolumeShape::Box ? "box" : "ellipsoid", sigma);
            FogComparison c = run(name, fogCamera({0, 15, 10}, {0, 8, -60}), air);
            EXPECT_LT(c.maxError, kTolerance) << name;
            std::snprintf(name, sizeof name, "%s soft %.1f, inside",
                          shape == FogVolumeShape::Box ? "box" : "ellipsoid", sigma);
            c = run(name, fogCamera(v.position, v.position + glm::dvec3(30.0, -4.0, -40.0)), air);
            EXPECT_LT(c.maxError, kTolerance) << name;
            EXPECT_EQ(renderer_->stats().volumesDrawnInside, 1);

            // The profile matters here: optical depth across the volume,
            // soft against hard, differs by more than 10 %.
            const glm::dvec3 from = v.position + glm::dvec3(0.0, 0.0, 60.0);
            const glm::dvec3 delta(0.0, 0.0, -120.0);
            const auto seg = intersectFogVolume(v, from, delta, 1.0);
            FogVolume hard = v;
            hard.edgeSoftness = 0.0;
            EXPECT_LT(fogVolumeOpticalDepth(v, from, delta, seg),
                      0.9 * fogVolumeOpticalDepth(hard, from, delta, seg));
        }
    }
}

TEST_F(FogVsCpu, VolumesStraddlingTheNearPlane) {
    for (FogVolumeShape shape : {FogVolumeShape::Box, FogVolumeShape::Ellipsoid}) {
        PresetState air = baseFrame();
        FogVolume v;
        v.shape = shape;
        v.position = {0.0, 10.0, -30.0};
        v.halfExtents = {20.0, 10.0, 20.0};
        v.density = 0.05;
        v.gradientDirection = {1.0, 0.0, 0.0};
        v.falloff = 0.03;
        air.volumes.push_back(v);
        // The eye 5 cm outside the +Z face (box) / surface (ellipsoid), near
        // plane 10 cm: half of the view starts inside the volume.
        const glm::dvec3 eye(0.0, 10.0, -10.0 + 0.05);
        const FogComparison c = run(
            shape == FogVolumeShape::Box ? "box, straddling near plane" : "ellipsoid, straddling near plane",
            fogCamera(eye, eye + glm::dvec3(-0.3, -0.2, -1.0)), air);
        EXPECT_LT(c.maxError, kTolerance);
        EXPECT_EQ(renderer_->stats().volumesDrawnInside, 1);
    }
}

TEST_F(FogVsCpu, VolumeColourModesAndTwoDisjointVolumes) {
    PresetState air = baseFrame();
    air.environment.fog = {0.002, 0.03, 0.0};
    FogVolume a = testVolume(FogVolumeShape::Box);
    a.colourMode = FogColourMode::Tinted;
    a.colour = {1.0, 0.6, 0.3};
    FogVolume b = testVolume(FogVolumeShape::Ellipsoid);
    b.position = {30.0, 10.0, -160.0};
    b.colourMode = FogColourMode::Custom;
    b.colour = {0.2, 0.5, 1.5};
    b.density = 0.02;
    air.volumes = {b, a};  // the far one first in the list, the near one in front
    const FogComparison c = run("tinted box + custom ellipsoid", fogCamera({0, 15, 10}, {10, 8, -100}), air);
    EXPECT_LT(c.maxError, kTolerance);
    EXPECT_EQ(renderer_->stats().volumesDrawn, 2);
}

TEST_F(FogVsCpu, Emitters) {
    PresetState air = baseFrame();
    air.environment.fog = {0.002, 0.03, 0.0};
    Emitter lamp;
    lamp.position = {-6.0, 4.0, -40.0};
    lamp.intensity = 0.4;
    lamp.attenuation = 0.05;
    lamp.colour = {1.0, 0.7, 0.4};
    Emitter far;
    far.position = {40.0, 30.0, -300.0};
    far.intensity = 0.05;
    far.attenuation = 0.0004;
    far.colour = {0.3, 0.5, 1.0};
    Emitter hidden;  // behind the wall: contributes only along rays that pass near it
    hidden.position = {0.0, 10.0, -600.0};
    hidden.intensity = 2.0;
    hidden.attenuation = 0.01;
    air.emitters = {lamp, far, hidden};
    const FogComparison c = run("emitters + global fog", fogCamera({0, 12, 0}, {0, 8, -100}), air);
    EXPECT_LT(c.maxError, kTolerance);
    EXPECT_GT(c.meanInScatter, 0.0);
    EXPECT_EQ(renderer_->stats().emitters, 3);
}

TEST_F(FogVsCpu, GlobalFogTintedAndCustomColour) {
    for (FogColourMode mode : {FogColourMode::Tinted, FogColourMode::Custom}) {
        PresetState air = baseFrame();
        air.environment.fog = {0.004, 0.02, 3.0};
        air.environment.fogColourMode = mode;
        air.environment.fogColour = {0.9, 0.5, 0.25};
        const FogComparison c =
            run(mode == FogColourMode::Custom ? "global fog, custom colour" : "global fog, tinted colour",
                fogCamera({0, 25, 0}, {0, 18, -100}), air);
        EXPECT_LT(c.maxError, kTolerance);
    }
}

// Under a cloud deck the sky's fog colour is blended with the deck's
// underside (OvercastLight, FogScene::fogColour): the GPU's global fog and
// tinted volume take the same blend as the CPU.
TEST_F(FogVsCpu, GlobalFogAndVolumesUnderAnOvercast) {
    PresetState air = baseFrame();
    addTestCloudDeck(air);
    air.environment.fog = {0.004, 0.02, 3.0};
    FogVolume e = testVolume(FogVolumeShape::Ellipsoid);
    e.colourMode = FogColourMode::Tinted;
    e.colour = {0.5, 0.8, 1.0};
    air.volumes.push_back(e);
    const FogComparison c =
        run("global fog + volume under an overcast", fogCamera({0, 25, 0}, {0, 18, -100}), air);
    EXPECT_LT(c.maxError, kTolerance);
    // The deck is there: the fog's colour is not the clear sky's.
    const FogSceneDesc under = aerial::fogSceneDesc(air, sky_->sun, sky_->moon);
    FogSceneDesc clear = under;
    clear.overcastCover = 0.0;
    ASSERT_GT(under.overcastCover, 0.5);
    const glm::dvec3 v(0.0, 0.05, -1.0);
    const glm::dvec3 a = FogScene(clear).fogColour(v), b = FogScene(under).fogColour(v);
    EXPECT_GT(glm::length(b - a), 0.1 * glm::length(a));
}

TEST_F(FogVsCpu, TheComparisonSeesAMissingPass) {
    // Negative control: the same frame without the volume pass is far off.
    PresetState air = baseFrame();
    air.volumes.push_back(testVolume(FogVolumeShape::Box));
    const Camera camera = fogCamera({0, 15, 10}, {0, 8, -60});
    renderer_->setScene(emissiveTestScene(camera, 400.0));
    FrameDesc frame = floatFrame();
    frame.passes.sky = frame.passes.globalFog = frame.passes.volumes = frame.passes.emitters = false;
    renderer_->render(camera, air, frame);
    const renderer::Image unfogged = renderer_->readColour();
    frame.passes.globalFog = frame.passes.emitters = true;
    renderer_->render(camera, air, frame);
    const FogScene scene(aerial::fogSceneDesc(air, sky_->sun, sky_->moon));
    const FogComparison c =
        compareWithCpu(renderer_->readColour(), unfogged, renderer_->readLinearDepth(), camera, scene);
    EXPECT_GT(c.maxError, 0.05);
}

TEST_F(FogVsCpu, EverythingTogether) {
    PresetState air = baseFrame();
    air.environment.fog = {0.003, 0.04, 2.0};
    air.volumes.push_back(testVolume(FogVolumeShape::Box));
    FogVolume e = testVolume(FogVolumeShape::Ellipsoid);
    e.position = {40.0, 5.0, -200.0};
    e.colourMode = FogColourMode::Tinted;
    e.colour = {0.5, 0.8, 1.0};
    air.volumes.push_back(e);
    Emitter lamp;
    lamp.position = {-6.0, 4.0, -40.0};
    lamp.intensity = 0.4;
    lamp.attenuation = 0.05;
    air.emitters.push_back(lamp);
    const FogComparison c = run("global + 2 volumes + emitter", fogCamera({0, 15, 10}, {10, 8, -100}), air);
    EXPECT_LT(c.maxError, kTolerance);
}

}  // namespace
}  // namespace aerial::test
