// test_renderer_mesh_volumes.cpp — mesh fog volumes and subtract volumes on
// the GPU (subtract_pass.cpp, mesh_volume_pass.cpp, common/subtract.glsl)
// against the CPU reference (FogScene, the contract of fog_query.hpp) on the
// same inputs, every pixel, as test_renderer_fog.cpp: a cube mesh against
// the box of the same transform, a torus (concave: several chords) with the
// camera outside and inside its tube and scene geometry inside it, a mesh
// subtract volume, room-sized subtract boxes in uniform fog (one, two
// overlapping, one cutting an add volume), and that nothing changes
// without them.
//
// Tolerance: 1e-3 relative to the unfogged value (compareWithCpu), as the
// box and ellipsoid tests.
#include "gl_fixture.hpp"

#include "test_meshes.hpp"

#include <aerial/fog_mesh.hpp>
#include <aerial/renderer/scene.hpp>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <cstdio>

namespace aerial::test {
namespace {

using renderer::Camera;
using renderer::FogMode;
using renderer::FrameDesc;

constexpr double kTolerance = 1e-3;

std::shared_ptr<const FogMesh> buildMesh(const TriangleMesh& m) {
    std::string error;
    std::shared_ptr<const FogMesh> mesh = FogMesh::build(m.positions, m.indices, error);
    EXPECT_TRUE(mesh) << error;
    return mesh;
}

class MeshVolumesVsCpu : public FogVsCpuTest {
protected:
    /// Renders the fog passes off and on; the fogged frame stays in the
    /// renderer (readColour) for the caller.
    FogComparison run(const char* name, const Camera& camera, const PresetState& air,
                      double wallDepth = 400.0) {
        const FogComparison c = renderAndCompare(camera, air, wallDepth);
        const renderer::RenderStats& s = renderer_->stats();
        std::printf(
            "[ measured ] %-36s max error %.3g (pixel %d,%d), mean T %.3f, mean S %.3g, mesh volumes %d, "
            "subtract volumes %d, overflow %d/%d\n",
            name, c.maxError, c.worstX, c.worstY, c.meanTransmittance, c.meanInScatter, s.meshVolumesDrawn,
            s.subtractVolumes, s.subtractCrossingOverflowPixels, s.subtractIntervalOverflowPixels);
        EXPECT_TRUE(log.errors.empty()) << log.errors.front();
        EXPECT_EQ(s.glErrors, 0);
        return c;
    }
};

/// A torus of ring radius 20 m and tube radius 6 m around +Y at (0, 4,
/// -60): the ground (y = 0) and the scene's box at (15, 6, -70) lie partly
/// inside its tube.
FogVolume torusVolume(const std::shared_ptr<const FogMesh>& mesh) {
    FogVolume v;
    v.shape = FogVolumeShape::Mesh;
    v.mesh = "torus.gltf";
    v.meshData = mesh;
    v.position = {0.0, 4.0, -60.0};
    v.rotation = glm::angleAxis(0.25, glm::normalize(glm::dvec3(1.0, 0.0, 0.3)));
    v.halfExtents = {1.0, 1.0, 1.0};
    v.density = 0.04;
    v.falloff = 0.05;
    v.gradientDirection = {0.0, 1.0, 0.0};
    v.colourMode = FogColourMode::Tinted;
    v.colour = {0.6, 0.8, 1.0};
    return v;
}

/// Largest per-channel difference of two frames, relative to the larger
/// value (floor 1e-3).
double relativeDifference(const renderer::Image& a, const renderer::Image& b) {
    double worst = 0.0;
    for (std::size_t i = 0; i < a.pixels.size() && i < b.pixels.size(); ++i) {
        const double x = a.pixels[i], y = b.pixels[i];
        const double e =
            std::isfinite(x) ? std::fabs(x - y) / std::max({std::fabs(x), std::fabs(y), 1e-3}) : 1e30;
        worst = std::max(worst, e);
    }
    return worst;
}

FogVolume subtractBox(const glm::dvec3& position, const glm::dvec3& halfExtents, double angle) {
    FogVolume v;
    v.shape = FogVolumeShape::Box;
    v.blend = FogVolumeBlend::Subtract;
    v.position = position;
    v.halfExtents = halfExtents;
    v.rotation = glm::angleAxis(angle, glm::dvec3(0.0, 1.0, 0.0));
    return v;
}

TEST_F(MeshVolumesVsCpu, CubeMeshIsTheBox) {
    PresetState air = baseFrame();
    air.environment.fog = {0.001, 0.02, 0.0};
    air.volumes.push_back(testVolume(FogVolumeShape::Box));
    const Camera camera = fogCamera({0, 15, 10}, {0, 8, -60});
    const FogComparison box = run("box", camera, air);
    EXPECT_LT(box.maxError, kTolerance);
    const renderer::Image boxImage = renderer_->readColour();

    FogVolume cube = testVolume(FogVolumeShape::Mesh);
    cube.mesh = "cube.gltf";
    cube.meshData = buildMesh(cubeMesh());
    air.volumes = {cube};
    const FogComparison mesh = run("cube mesh", camera, air);
    EXPECT_LT(mesh.maxError, kTolerance);
    EXPECT_EQ(renderer_->stats().meshVolumesDrawn, 1);
    EXPECT_EQ(renderer_->stats().volumesDrawn, 1);
    // The GPU's cube mesh against the GPU's box, pixel for pixel.
    const renderer::Image meshImage = renderer_->readColour();
    const double worst = relativeDifference(meshImage, boxImage);
    std::printf("[ measured ] cube mesh vs box (GPU) max relative difference %.3g\n", worst);
    EXPECT_LT(worst, kTolerance);
}

TEST_F(MeshVolumesVsCpu, CubeMeshIsTheBoxFromInsideAndSubtracting) {
    const std::shared_ptr<const FogMesh> cubeData = buildMesh(cubeMesh());
    for (bool subtract : {false, true}) {
        PresetState air = baseFrame();
        air.environment.fog = {0.003, 0.01, 0.0};
        FogVolume box = testVolume(FogVolumeShape::Box);
        if (subtract) box.blend = FogVolumeBlend::Subtract;
        FogVolume cube = box;
        cube.shape = FogVolumeShape::Mesh;
        cube.mesh = "cube.gltf";
        cube.meshData = cubeData;
        // Eye inside, looking out through a side: the near plane inside.
        const Camera camera = fogCamera(box.position, box.position + glm::dvec3(30.0, -4.0, -40.0));
        air.volumes = {box};
        EXPECT_LT(run(subtract ? "subtract box, inside" : "box, inside", camera, air).maxError, kTolerance);
        const renderer::Image boxImage = renderer_->readColour();
        air.volumes = {cube};
        EXPECT_LT(run(subtract ? "subtract cube mesh, inside" : "cube mesh, inside", camera, air).maxError,
                  kTolerance);
        const double worst = relativeDifference(renderer_->readColour(), boxImage);
        std::printf("[ measured ] %s vs box (GPU) max relative difference %.3g\n",
                    subtract ? "subtract cube mesh" : "cube mesh", worst);
        EXPECT_LT(worst, kTolerance);
    }
}

TEST_F(MeshVolumesVsCpu, TorusCameraOutsideWithGeometryInside) {
    PresetState air = baseFrame();
    air.environment.fog = {0.001, 0.02, 0.0};
    air.volumes.push_back(torusVolume(buildMesh(torusMesh(20.0, 6.0))));
    // From above and in front: the hole, both sides of the ring, the ground
    // and the scene's box inside the tube.
    const FogComparison c = run("torus, outside", fogCamera({0, 30, 5}, {0, 0, -60}), air);
    EXPECT_LT(c.maxError, kTolerance);
    EXPECT_LT(c.meanTransmittance, 0.97);  // the torus is not trivial
    EXPECT_EQ(renderer_->stats().meshVolumesDrawn, 1);
}

TEST_F(MeshVolumesVsCpu, TorusCameraInsideTheTube) {
    PresetState air = baseFrame();
    FogVolume torus = torusVolume(buildMesh(torusMesh(20.0, 6.0)));
    torus.rotation = glm::dquat(1.0, 0.0, 0.0, 0.0);
    air.volumes.push_back(torus);
    // On the tube's centre line at +X, looking along the tube and across
    // the hole: the far side of the ring is a second chord.
    const glm::dvec3 eye(20.0, 4.0, -60.0);
    const FogComparison c = run("torus, inside the tube", fogCamera(eye, {-5.0, 3.0, -85.0}), air);
    EXPECT_LT(c.maxError, kTolerance);
}

TEST_F(MeshVolumesVsCpu, MeshSubtractVolume) {
    PresetState air = baseFrame();
    air.environment.fog = {0.004, 0.0, 0.0};
    FogVolume torus = torusVolume(buildMesh(torusMesh(20.0, 6.0)));
    torus.blend = FogVolumeBlend::Subtract;
    air.volumes.push_back(torus);
    const FogComparison c = run("torus subtract in uniform fog", fogCamera({0, 30, 5}, {0, 0, -60}), air);
    EXPECT_LT(c.maxError, kTolerance);
    EXPECT_EQ(renderer_->stats().subtractVolumes, 1);
    EXPECT_EQ(renderer_->stats().subtractCrossingOverflowPixels, 0);
}

TEST_F(MeshVolumesVsCpu, SubtractRoomInUniformFog) {
    PresetState air = baseFrame();
    air.environment.fog = {0.004, 0.0, 0.0};
    air.volumes.push_back(subtractBox({0.0, 6.0, -60.0}, {14.0, 6.0, 18.0}, 0.4));
    FogComparison c = run("subtract room, outside", fogCamera({0, 15, 10}, {0, 6, -60}), air);
    EXPECT_LT(c.maxError, kTolerance);
    EXPECT_EQ(renderer_->stats().subtractVolumes, 1);
    c = run("subtract room, inside", fogCamera({2, 5, -55}, {10, 4, -100}), air);
    EXPECT_LT(c.maxError, kTolerance);
    EXPECT_EQ(renderer_->stats().subtractIntervalOverflowPixels, 0);
}

TEST_F(MeshVolumesVsCpu, OverlappingSubtractVolumesRemoveOnce) {
    PresetState air = baseFrame();
    air.environment.fog = {0.004, 0.01, 0.0};
    air.volumes.push_back(subtractBox({0.0, 6.0, -60.0}, {14.0, 6.0, 18.0}, 0.4));
    FogVolume second = subtractBox({10.0, 8.0, -75.0}, {12.0, 8.0, 10.0}, -0.3);
    second.shape = FogVolumeShape::Ellipsoid;
    air.volumes.push_back(second);
    const FogComparison c = run("two overlapping subtract volumes", fogCamera({0, 15, 10}, {5, 6, -70}), air);
    EXPECT_LT(c.maxError, kTolerance);
    EXPECT_EQ(renderer_->stats().subtractVolumes, 2);
}

TEST_F(MeshVolumesVsCpu, SubtractBoxCutsAddVolumes) {
    PresetState air = baseFrame();
    air.environment.fog = {0.002, 0.02, 0.0};
    air.volumes.push_back(testVolume(FogVolumeShape::Box));
    FogVolume torus = torusVolume(buildMesh(torusMesh(20.0, 6.0)));
    torus.position = {0.0, 4.0, -140.0};
    air.volumes.push_back(torus);
    air.volumes.push_back(subtractBox({0.0, 8.0, -70.0}, {10.0, 12.0, 80.0}, 0.2));
    const FogComparison c =
        run("subtract box through a box and a torus", fogCamera({0, 26, 10}, {0, 5, -100}), air);
    EXPECT_LT(c.maxError, kTolerance);
    EXPECT_EQ(renderer_->stats().volumesDrawn, 2);
}

TEST_F(MeshVolumesVsCpu, SubtractBoxCutsSoftEdgedVolumes) {
    // fog_volume.glsl's masked soft integral (maskedSoftDepth): the soft
    // profile's pieces between the subtract union's gaps, against the CPU.
    for (FogVolumeShape shape : {FogVolumeShape::Box, FogVolumeShape::Ellipsoid}) {
        PresetState air = baseFrame();
        air.environment.fog = {0.002, 0.02, 0.0};
        FogVolume v = testVolume(shape);
        v.edgeSoftness = 0.6;
        air.volumes.push_back(v);
        air.volumes.push_back(subtractBox({0.0, 8.0, -70.0}, {10.0, 12.0, 80.0}, 0.2));
        const FogComparison c = run(shape == FogVolumeShape::Box ? "subtract box through a soft box"
                                                                 : "subtract box through a soft ellipsoid",
                                    fogCamera({0, 26, 10}, {0, 5, -100}), air);
        EXPECT_LT(c.maxError, kTolerance);
    }
}

TEST_F(MeshVolumesVsCpu, SubtractVolumeAroundTheViewRemovesAllFogInBothModes) {
    // Known answer: uniform fog, a subtract box (or cube mesh) holding the
    // whole frustum up to the far plane: the fogged frame is the unfogged
    // one, in the analytic and in the volumetric fog.
    const Camera camera = fogCamera({0, 15, 10}, {0, 8, -60});
    renderer_->setScene(emissiveTestScene(camera, 400.0));
    for (bool mesh : {false, true}) {
        PresetState air = baseFrame();
        air.environment.fog = {0.004, 0.0, 0.0};
        FogVolume room = subtractBox({0.0, 15.0, 10.0}, {3000.0, 3000.0, 3000.0}, 0.3);
        if (mesh) {
            room.shape = FogVolumeShape::Mesh;
            room.mesh = "cube.gltf";
            room.meshData = buildMesh(cubeMesh());
        }
        air.volumes.push_back(room);
        FrameDesc frame = floatFrame();
        frame.passes.sky = false;
        frame.passes.globalFog = frame.passes.volumes = frame.passes.emitters = false;
        renderer_->render(camera, air, frame);
        const renderer::Image unfogged = renderer_->readColour();
        frame.passes.globalFog = frame.passes.volumes = frame.passes.emitters = true;
        for (FogMode mode : {FogMode::Analytic, FogMode::Volumetric}) {
            frame.fogMode = mode;
            renderer_->render(camera, air, frame);
            const double worst = relativeDifference(renderer_->readColour(), unfogged);
            std::printf("[ measured ] subtract %s around the view, %s fog: max relative change %.3g\n",
                        mesh ? "cube mesh" : "box", mode == FogMode::Analytic ? "analytic" : "volumetric",
                        worst);
            EXPECT_LT(worst, 1e-5);
            EXPECT_EQ(renderer_->stats().glErrors, 0);
        }
        // Without the subtract volume the same frames are fogged.
        air.volumes.clear();
        frame.fogMode = FogMode::Analytic;
        renderer_->render(camera, air, frame);
        EXPECT_GT(relativeDifference(renderer_->readColour(), unfogged), 0.1);
    }
}

TEST_F(MeshVolumesVsCpu, BeyondTheLimitsCountedAndFinite) {
    // Six disjoint subtract slabs across the view (more than 4 stretches a
    // pixel) and nine cube meshes in a row (18 crossings, more than 16):
    // the renderer counts the pixels beyond its limits and stays finite.
    PresetState air = baseFrame();
    air.environment.fog = {0.004, 0.0, 0.0};
    for (int k = 0; k < 6; ++k)
        air.volumes.push_back(subtractBox({0.0, 8.0, -30.0 - 20.0 * k}, {200.0, 200.0, 4.0}, 0.0));
    const Camera camera = fogCamera({0, 8, 10}, {0, 8, -100});
    renderer_->setScene(emissiveTestScene(camera, 400.0));
    FrameDesc frame = floatFrame();
    frame.passes.sky = false;
    renderer_->render(camera, air, frame);
    EXPECT_EQ(renderer_->stats().subtractVolumes, 6);
    EXPECT_GT(renderer_->stats().subtractIntervalOverflowPixels,
              kWidth * kHeight / 2);  // the ground ends some rays sooner
    const std::shared_ptr<const FogMesh> cube = buildMesh(cubeMesh());
    air.volumes.clear();
    for (int k = 0; k < 9; ++k) {
        FogVolume v = subtractBox({0.0, 8.0, -30.0 - 12.0 * k}, {100.0, 100.0, 3.0}, 0.0);
        v.shape = FogVolumeShape::Mesh;
        v.mesh = "cube.gltf";
        v.meshData = cube;
        air.volumes.push_back(v);
    }
    renderer_->render(camera, air, frame);
    EXPECT_GT(renderer_->stats().subtractCrossingOverflowPixels, kWidth * kHeight / 2);
    EXPECT_EQ(renderer_->stats().glErrors, 0);
    const renderer::Image image = renderer_->readColour();
    for (float x : image.pixels) ASSERT_TRUE(std::isfinite(x));
}

TEST_F(MeshVolumesVsCpu, NothingRunsWithoutThem) {
    PresetState air = baseFrame();
    air.environment.fog = {0.002, 0.02, 0.0};
    air.volumes.push_back(testVolume(FogVolumeShape::Box));
    const FogComparison c = run("box only", fogCamera({0, 15, 10}, {0, 8, -60}), air);
    EXPECT_LT(c.maxError, kTolerance);
    EXPECT_EQ(renderer_->stats().subtractVolumes, 0);
    EXPECT_EQ(renderer_->stats().meshVolumesDrawn, 0);
}

}  // namespace
}  // namespace aerial::test
