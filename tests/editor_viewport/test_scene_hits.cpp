// Rays against the scene's triangles (scene_hits.hpp): exact hits on a box
// and a quad, glass ignored, and the built-in terrain's surface against its
// height function (the mesh samples it, so they agree to the mesh's
// flattening between vertices).
#include "viewport/scene_hits.hpp"

#include <gtest/gtest.h>

#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <random>

namespace aerial::editor {
namespace {

TEST(SceneHits, ExactDistancesToABoxAndAQuad) {
    renderer::SceneDesc scene;
    scene.meshes.push_back(renderer::makeBoxMesh({0.0, 2.0, -10.0}, {1.0, 2.0, 1.5}));
    scene.meshes.push_back(renderer::makeQuadMesh({-50.0, 0.0, 50.0}, {100.0, 0.0, 0.0}, {0.0, 0.0, -100.0}));
    const SceneHits hits(scene);
    EXPECT_EQ(hits.triangleCount(), 12u + 2u);
    // Along -Z at y = 1: the box's front face at z = -8.5.
    auto t = hits.intersect({0.0, 1.0, 0.0}, {0.0, 0.0, -1.0}, 100.0);
    ASSERT_TRUE(t);
    EXPECT_NEAR(*t, 8.5, 1e-12);
    EXPECT_FALSE(hits.intersect({0.0, 1.0, 0.0}, {0.0, 0.0, -1.0}, 8.0));  // beyond the range
    // Down onto the box's top (y = 4) and onto the ground beside it.
    EXPECT_NEAR(*hits.surfaceBelow({0.2, 30.0, -10.3}), 4.0, 1e-12);
    EXPECT_NEAR(*hits.surfaceBelow({5.0, 30.0, -10.0}), 0.0, 1e-12);
    // Under the ground: the topmost surface above.
    EXPECT_NEAR(*hits.surfaceBelow({5.0, -20.0, -10.0}), 0.0, 1e-12);
    EXPECT_FALSE(hits.surfaceBelow({500.0, 3.0, 0.0}));  // nothing there
}

TEST(SceneHits, GlassIsNotGround) {
    renderer::SceneDesc scene;
    renderer::SceneMesh glass = renderer::makeQuadMesh({-5.0, 3.0, 5.0}, {10.0, 0.0, 0.0}, {0.0, 0.0, -10.0});
    glass.alphaMode = renderer::AlphaMode::Blend;
    scene.meshes.push_back(glass);
    scene.meshes.push_back(renderer::makeQuadMesh({-5.0, 0.0, 5.0}, {10.0, 0.0, 0.0}, {0.0, 0.0, -10.0}));
    EXPECT_NEAR(*SceneHits(scene).surfaceBelow({0.0, 10.0, 0.0}), 0.0, 1e-12);
}

TEST(SceneHits, TheBuiltInTerrainWhereItsHeightFunctionSaysItIs) {
    const SceneHits hits(renderer::makeBuiltinScene());
    std::mt19937 random(7);
    std::uniform_real_distribution<double> coordinate(-300.0, 300.0);
    double worst = 0.0;
    int measured = 0;
    for (int i = 0; i < 40; ++i) {
        const double x = coordinate(random), z = coordinate(random);
        const double ground = renderer::builtinTerrainHeight(x, z);
        const std::optional<double> y = hits.surfaceBelow({x, ground + 200.0, z});
        ASSERT_TRUE(y) << x << " " << z;
        if (*y > ground + 0.5) continue;  // a house, a rock or the mast stands there
        worst = std::max(worst, std::abs(*y - ground));
        ++measured;
    }
    std::printf("[ measured ] built-in terrain: %d points, surface vs height function at most %.3f m\n",
                measured, worst);
    EXPECT_GT(measured, 30);
    EXPECT_LT(worst, 0.5);
}

}  // namespace
}  // namespace aerial::editor
