// gl_fixture.hpp — shared helpers of test_renderer: one headless EGL context
// per process (the tests FAIL, not skip, when it cannot be created: CI has
// Mesa), a logger that records what the renderer reports, small sky tables,
// and the per-pixel comparison against the CPU fog queries.
#pragma once

#include <aerial/evaluate.hpp>
#include <aerial/fog_query.hpp>
#include <aerial/renderer/egl_context.hpp>
#include <aerial/renderer/renderer.hpp>
#include <aerial/sky.hpp>

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

namespace aerial::test {

/// The size of the test frames [px].
constexpr int kWidth = 160;
constexpr int kHeight = 90;

/// A camera from `eye` towards `target` for a kWidth x kHeight frame, near
/// plane 0.1 m.
renderer::Camera makeCamera(const glm::dvec3& eye, const glm::dvec3& target, double farDistance,
                            double verticalFov = 1.0);

/// A kWidth x kHeight frame in float precision, every pass on, no stars
/// (the tests' states are built by hand: their sun's elevation would not
/// match its direction).
renderer::FrameDesc floatFrame();

/// The sun or moon of a state built by hand: what the renderer reads
/// (direction, illuminance above the atmosphere and reaching the ground),
/// the elevation from the direction.
LightState light(const glm::dvec3& direction, const glm::dvec3& illuminanceSpace,
                 const glm::dvec3& illuminance);

/// The process-wide headless context, created on first use and made
/// current; null (with `error` set) when EGL cannot give one.
renderer::HeadlessContext* glContext(std::string& error);

/// Records every message the renderer logs.
struct LogCapture {
    std::vector<std::string> errors;
    std::vector<std::string> warnings;
    renderer::Logger logger();
};

/// Test fixture: makes the context current, or fails the test.
class GlTest : public ::testing::Test {
protected:
    void SetUp() override;
    renderer::RendererDesc rendererDesc() {
        renderer::RendererDesc d;
        d.logger = log.logger();
        return d;
    }
    LogCapture log;
};

/// A solved pair of tables (sun, moon) for the given light directions, small
/// enough to solve quickly (64 x 32, 16 layers).
struct SkyPair {
    SkyTable sun;
    SkyTable moon;
};
SkyPair solveSky(const AtmosphereParams& air, const glm::dvec3& sunDirection, const glm::dvec3& moonDirection,
                 int columns = 64, int rows = 32);

/// Test fixture with a renderer that has the sky of the given light
/// directions (solveSky, default size, solved once per process and pair of
/// directions).
class SkyRendererTest : public GlTest {
protected:
    SkyRendererTest(const glm::dvec3& sunDirection, const glm::dvec3& moonDirection)
        : sunDirection_(sunDirection), moonDirection_(moonDirection) {}
    void SetUp() override;

    const SkyPair* sky_ = nullptr;
    std::unique_ptr<renderer::Renderer> renderer_;

private:
    glm::dvec3 sunDirection_;
    glm::dvec3 moonDirection_;
};

/// The fog tests' camera: 1500 m far plane, 1.1 rad vertical field of view.
renderer::Camera fogCamera(const glm::dvec3& eye, const glm::dvec3& target);

/// The fog tests' volume of `shape` (a mesh volume still needs its meshData):
/// rotated, non-uniformly scaled, a density gradient in an arbitrary direction.
FogVolume testVolume(FogVolumeShape shape);

/// The tests' cloud deck over `air`: coverage 0.8 from 1500 m up, 2000 m
/// thick (an overcast that hides most of the sky, OvercastLight).
void addTestCloudDeck(PresetState& air);

/// Test geometry with known radiance (emission only, albedo 0): a wall
/// perpendicular to the view at `wallDepth` [m], the ground y = 0 and a
/// rotated box (the fog tests' scene).
renderer::SceneDesc emissiveTestScene(const renderer::Camera& camera, double wallDepth);

/// Largest per-pixel error of a fogged GPU frame against the CPU query on
/// the same inputs: for every pixel, the scene point is reconstructed from
/// the GPU's linear depth (in double), FogScene::query(eye, point) gives
/// T and S, and the error is max_c |L_gpu - (L_scene T + S)| divided by
/// max(max_c L_scene, max_c L_cpu, floor) ("relative to the unfogged value").
struct FogComparison {
    double maxError = 0.0;
    int worstX = 0, worstY = 0;
    double meanTransmittance = 0.0;  ///< of the CPU answers: shows the fog is not trivial
    double meanInScatter = 0.0;      ///< mean of max_c S
};
FogComparison compareWithCpu(const renderer::Image& fogged, const renderer::Image& unfogged,
                             const renderer::Image& depth01, const renderer::Camera& camera,
                             const FogScene& scene, double floor = 1e-3);

/// The fog-against-CPU fixture (test_renderer_fog.cpp, test_renderer_mesh_volumes.cpp):
/// a fixed sun and moon, the emissive test scene, and one comparison of a
/// fogged frame (global fog, volumes, emitters) with FogScene per pixel.
class FogVsCpuTest : public SkyRendererTest {
protected:
    FogVsCpuTest() : FogVsCpuTest(sunDirection(), moonDirection()) {}
    /// Lights in other directions (the tables are solved for them).
    FogVsCpuTest(const glm::dvec3& sun, const glm::dvec3& moon)
        : SkyRendererTest(sun, moon), sun_(sun), moon_(moon) {}
    static glm::dvec3 sunDirection();
    static glm::dvec3 moonDirection();

    /// The lights above the atmosphere and the Mie anisotropy; no fog yet.
    PresetState baseFrame() const;

    /// Renders the emissive test scene (its wall at `wallDepth`) with the fog
    /// passes off, then on, and compares every pixel with the CPU query; the
    /// fogged frame stays in the renderer (readColour) for the caller.
    FogComparison renderAndCompare(const renderer::Camera& camera, const PresetState& air,
                                   double wallDepth = 400.0);

private:
    glm::dvec3 sun_, moon_;
};

}  // namespace aerial::test
