// Mesh and subtract fog volumes (aerial/fog_mesh.hpp, aerial/fog_volume.hpp,
// FogScene in aerial/fog_query.hpp) against independent references:
//   - a cube mesh against the box volume of the same transform;
//   - a concave mesh (a torus) against its chords found by a brute-force
//     loop over every triangle in this file (no BVH, its own ray/triangle
//     test), through the hole, across the ring, a segment that ends inside,
//     a camera inside;
//   - the exponential gradient against 10 000-point midpoint quadrature of
//     the density along each chord;
//   - subtract volumes against closed forms of uniform fog over the
//     segment minus the union of the subtracted intervals;
//   - the checks that refuse bad meshes, and the glTF reader.
#include "quick_run.hpp"
#include "test_meshes.hpp"

#include <aerial/fog_mesh.hpp>
#include <aerial/fog_query.hpp>
#include <aerial/fog_volume.hpp>
#include <aerial/height_fog.hpp>
#include <aerial/limits.hpp>
#include <aerial/preset.hpp>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <utility>
#include <vector>

namespace aerial {
namespace {

std::shared_ptr<const FogMesh> build(const test::TriangleMesh& m) {
    std::string error;
    auto mesh = FogMesh::build(m.positions, m.indices, error);
    EXPECT_TRUE(mesh) << error;
    return mesh;
}

FogVolume meshVolume(std::shared_ptr<const FogMesh> mesh, const glm::dvec3& position,
                     const glm::dquat& rotation, const glm::dvec3& scale) {
    FogVolume v;
    v.id = "mesh";
    v.shape = FogVolumeShape::Mesh;
    v.mesh = "generated";
    v.meshData = std::move(mesh);
    v.position = position;
    v.rotation = rotation;
    v.halfExtents = scale;
    return v;
}

/// Brute-force chords of the world ray o + t d through the placed mesh:
/// every triangle in world space, the crossings sorted, entries and exits
/// told apart by the world normal, paired by the winding count.
std::vector<std::pair<double, double>> referenceChords(const test::TriangleMesh& m, const FogVolume& v,
                                                       const glm::dvec3& o, const glm::dvec3& d) {
    const glm::dmat3 r = glm::mat3_cast(glm::normalize(v.rotation));
    auto world = [&](std::uint32_t i) { return v.position + r * (v.halfExtents * m.positions[i]); };
    std::vector<std::pair<double, int>> hits;
    for (std::size_t k = 0; k < m.indices.size(); k += 3) {
        const glm::dvec3 a = world(m.indices[k]), b = world(m.indices[k + 1]), c = world(m.indices[k + 2]);
        const glm::dvec3 n = glm::cross(b - a, c - a);
        const double dn = glm::dot(d, n);
        if (dn == 0.0) continue;
        const double t = glm::dot(a - o, n) / dn;
        const glm::dvec3 p = o + t * d;
        // Inside the triangle: the same side of all three edges as n.
        const double s0 = glm::dot(glm::cross(b - a, p - a), n);
        const double s1 = glm::dot(glm::cross(c - b, p - b), n);
        const double s2 = glm::dot(glm::cross(a - c, p - c), n);
        if (s0 >= 0 && s1 >= 0 && s2 >= 0) hits.push_back({t, dn < 0 ? 1 : -1});
    }
    std::sort(hits.begin(), hits.end());
    std::vector<std::pair<double, double>> chords;
    int winding = 0;
    double start = 0;
    for (auto [t, s] : hits) {
        if (winding == 0 && s > 0) start = t;
        winding += s;
        if (winding == 0) chords.push_back({start, t});
    }
    return chords;
}

/// The reference chords clipped to [0, tMax].
std::vector<std::pair<double, double>> clip(std::vector<std::pair<double, double>> chords, double tMax) {
    std::vector<std::pair<double, double>> out;
    for (auto [a, b] : chords) {
        a = std::max(a, 0.0);
        b = std::min(b, tMax);
        if (a < b) out.push_back({a, b});
    }
    return out;
}

TEST(FogMesh, CubeMeshIsTheBoxVolume) {
    const auto cube = build(test::cubeMesh());
    ASSERT_TRUE(cube);
    EXPECT_NEAR(cube->enclosedVolume(), 8.0, 1e-12);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < 200; ++i) {
        const glm::dquat q = glm::normalize(glm::dquat(u(rng), u(rng), u(rng), u(rng)));
        FogVolume box;
        box.shape = FogVolumeShape::Box;
        box.position = {30 * u(rng), 5 * u(rng), 30 * u(rng)};
        box.rotation = q;
        box.halfExtents = {5 + 4 * u(rng), 3 + 2 * u(rng), 8 + 4 * u(rng)};
        box.density = 0.05;
        box.falloff = i % 2 ? 0.0 : 0.2;
        box.gradientDirection = glm::normalize(glm::dvec3(u(rng), 1.0, u(rng)));
        box.gradientOffset = 2 * u(rng);
        FogVolume mesh = box;
        mesh.shape = FogVolumeShape::Mesh;
        mesh.mesh = "cube";
        mesh.meshData = cube;
        const glm::dvec3 eye{60 * u(rng), 10 * u(rng), 60 * u(rng)};
        const glm::dvec3 target = box.position + glm::dvec3(4 * u(rng), 2 * u(rng), 4 * u(rng));
        const glm::dvec3 dir = target - eye;
        const double tMax = i % 3 == 0 ? 0.9 + 0.2 * u(rng) : 2.0;  // some segments end inside
        const VolumeSegment sb = intersectFogVolume(box, eye, dir, tMax);
        const VolumeSegment sm = intersectFogVolume(mesh, eye, dir, tMax);
        ASSERT_EQ(sb.hit, sm.hit) << i;
        if (!sb.hit) continue;
        EXPECT_NEAR(sm.tIn, sb.tIn, 1e-9) << i;
        EXPECT_NEAR(sm.tOut, sb.tOut, 1e-9) << i;
        const double tb = fogVolumeOpticalDepth(box, eye, dir, sb);
        const double tm = fogVolumeOpticalDepth(mesh, eye, dir, sm);
        EXPECT_NEAR(tm, tb, 1e-6 * std::max(tb, 1e-3)) << i;
        // Bounds and containment agree too.
        glm::dvec3 bl, bh, ml, mh;
        fogVolumeBounds(box, bl, bh);
        fogVolumeBounds(mesh, ml, mh);
        EXPECT_LT(glm::length(bl - ml) + glm::length(bh - mh), 1e-9);
        const glm::dvec3 probe = box.position + glm::dvec3(6 * u(rng), 4 * u(rng), 9 * u(rng));
        EXPECT_EQ(fogVolumeDensityAt(mesh, probe) > 0, fogVolumeDensityAt(box, probe) > 0) << i;
    }
}

class TorusTest : public ::testing::Test {
protected:
    // Ring radius 6, tube radius 2 (object units), scaled by 2 and turned.
    test::TriangleMesh torus = test::torusMesh(6.0, 2.0, 48, 24);
    std::shared_ptr<const FogMesh> mesh = build(torus);
    FogVolume v = meshVolume(mesh, {5, 3, -20}, glm::angleAxis(0.3, glm::normalize(glm::dvec3(1, 0.2, 0.1))),
                             glm::dvec3(2.0));

    /// The mesh's chords of a ray, via the public function.
    std::vector<VolumeSegment> chords(const glm::dvec3& o, const glm::dvec3& d, double tMax) const {
        std::vector<VolumeSegment> out;
        fogVolumeChords(prepareFogVolume(v), o, d, tMax, out);
        return out;
    }

    void expectChords(const glm::dvec3& o, const glm::dvec3& d, double tMax, std::size_t expected) const {
        const auto got = chords(o, d, tMax);
        const auto want = clip(referenceChords(torus, v, o, d), tMax);
        ASSERT_EQ(want.size(), expected);
        ASSERT_EQ(got.size(), want.size());
        for (std::size_t k = 0; k < got.size(); ++k) {
            EXPECT_NEAR(got[k].tIn, want[k].first, 1e-9);
            EXPECT_NEAR(got[k].tOut, want[k].second, 1e-9);
        }
        // Uniform density: the optical depth is the density times the chords' length.
        FogVolume uniform = v;
        uniform.density = 0.03;
        uniform.falloff = 0.0;
        const VolumeSegment whole = intersectFogVolume(uniform, o, d, tMax);
        double length = 0;
        for (auto [a, b] : want) length += (b - a) * glm::length(d);
        const double tau = whole.hit ? fogVolumeOpticalDepth(uniform, o, d, whole) : 0.0;
        EXPECT_NEAR(tau, 0.03 * length, 1e-9 * std::max(1.0, tau));
    }
};

TEST_F(TorusTest, ZeroThroughTheHole) {
    const glm::dmat3 r = glm::mat3_cast(v.rotation);
    const glm::dvec3 axis = r[1];
    // Along the torus axis through its centre: no fog at all.
    expectChords(v.position - 40.0 * axis, axis, 80.0, 0);
    FogVolume uniform = v;
    const VolumeSegment s = intersectFogVolume(uniform, v.position - 40.0 * axis, axis, 80.0);
    EXPECT_FALSE(s.hit);
}

TEST_F(TorusTest, TwoChordsAcrossTheRing) {
    const glm::dmat3 r = glm::mat3_cast(v.rotation);
    // In the ring's plane through the centre: in and out of the tube twice.
    const glm::dvec3 dir = glm::normalize(r[0] + 0.01 * r[2]);
    expectChords(v.position - 40.0 * dir + 0.3 * r[1], dir, 80.0, 2);
    // Random rays through the ring's plane.
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int twoChordRays = 0;
    for (int i = 0; i < 100; ++i) {
        const glm::dvec3 o = v.position + glm::dvec3(40 * u(rng), 30 * u(rng), 40 * u(rng));
        const glm::dvec3 target = v.position + r * glm::dvec3(14 * u(rng), 3 * u(rng), 14 * u(rng));
        const glm::dvec3 d = target - o;
        const auto got = chords(o, d, 3.0);
        const auto want = clip(referenceChords(torus, v, o, d), 3.0);
        ASSERT_EQ(got.size(), want.size()) << i;
        twoChordRays += want.size() == 2;
        for (std::size_t k = 0; k < got.size(); ++k) {
            EXPECT_NEAR(got[k].tIn, want[k].first, 1e-9) << i;
            EXPECT_NEAR(got[k].tOut, want[k].second, 1e-9) << i;
        }
    }
    EXPECT_GT(twoChordRays, 5);
}

TEST_F(TorusTest, SegmentEndingInsideAndCameraInside) {
    const glm::dmat3 r = glm::mat3_cast(v.rotation);
    const glm::dvec3 dir = glm::normalize(r[0] + 0.013 * r[2] + 0.02 * r[1]);
    const glm::dvec3 o = v.position - 40.0 * dir;
    const auto full = referenceChords(torus, v, o, dir);
    ASSERT_EQ(full.size(), 2u);
    // An object inside the far chord ends the fog there.
    const double tEnd = 0.5 * (full[1].first + full[1].second);
    expectChords(o, dir, tEnd, 2);
    EXPECT_NEAR(chords(o, dir, tEnd).back().tOut, tEnd, 0.0);
    // The camera inside the near chord: fog from the camera on.
    const glm::dvec3 inside = o + 0.5 * (full[0].first + full[0].second) * dir;
    EXPECT_TRUE(fogVolumeContains(prepareFogVolume(v), inside));
    expectChords(inside, dir, 100.0, 2);
    EXPECT_EQ(chords(inside, dir, 100.0).front().tIn, 0.0);
}

TEST_F(TorusTest, GradientAgainstQuadrature) {
    FogVolume g = v;
    g.density = 0.04;
    g.falloff = 0.15;
    g.gradientDirection = glm::normalize(glm::dvec3(0.3, 1.0, -0.2));
    g.gradientOffset = -1.5;
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const glm::dmat3 r = glm::mat3_cast(v.rotation);
    // Under sanitizers / AERIAL_TEST_QUICK every fourth ray (the same rays):
    // the quadrature is ~10x slower there and checks no other code.
    const bool quick = test::quickRun();
    int checked = 0;
    for (int i = 0; i < 40; ++i) {
        const glm::dvec3 o = v.position + glm::dvec3(40 * u(rng), 30 * u(rng), 40 * u(rng));
        const glm::dvec3 d = v.position + r * glm::dvec3(14 * u(rng), 3 * u(rng), 14 * u(rng)) - o;
        if (quick && i % 4 != 0) continue;
        const auto want = referenceChords(torus, v, o, d);
        if (want.empty()) continue;
        // 10 000 midpoints over each chord of the density at the point
        // (fogVolumeDensityAt: its own inside test and exp law).
        double reference = 0;
        for (auto [a, b] : want) {
            const int n = 10000;
            const double h = (b - a) / n;
            for (int k = 0; k < n; ++k) {
                // Stay a hair inside the chord's ends (the inside test is exact there).
                const double t = a + (k + 0.5) * h;
                reference += fogVolumeDensityAt(g, o + t * d) * h * glm::length(d);
            }
        }
        const VolumeSegment s = intersectFogVolume(g, o, d, 10.0);
        ASSERT_TRUE(s.hit);
        const double tau = fogVolumeOpticalDepth(g, o, d, s);
        EXPECT_NEAR(tau, reference, 1e-4 * reference) << i;
        ++checked;
    }
    std::printf("[ torus   ] %d rays against the quadrature\n", checked);
    EXPECT_GT(checked, quick ? 5 : 10);
}

// ---------------------------------------------------------------------------
// Subtract volumes (FogScene)

FogSceneDesc uniformFog(double density) {
    FogSceneDesc desc;
    desc.heightFog.density = density;
    desc.heightFog.falloff = 0.0;
    return desc;
}

FogVolume subtractBox(const glm::dvec3& position, const glm::dvec3& half) {
    FogVolume v;
    v.id = "room";
    v.shape = FogVolumeShape::Box;
    v.blend = FogVolumeBlend::Subtract;
    v.position = position;
    v.halfExtents = half;
    return v;
}

TEST(SubtractVolume, RoomRemovesExactlyTheFogOfThePathInside) {
    const double b = 0.01;
    FogSceneDesc desc = uniformFog(b);
    desc.volumes.push_back(subtractBox({0, 2, 0}, {4, 2.5, 5}));
    const FogScene scene(desc);
    // Through the room along x at y = 2: 8 m of 100 m are fog-free.
    const FogQueryResult r = scene.query({-50, 2, 0.5}, {50, 2, 0.5});
    EXPECT_NEAR(r.globalOpticalDepth, b * 92.0, 1e-12);
    EXPECT_NEAR(r.transmittance.x, std::exp(-b * 92.0), 1e-12);
    // From inside the room to a point inside: no fog at all.
    EXPECT_NEAR(scene.query({-3, 1, 0}, {3, 3, 4}).globalOpticalDepth, 0.0, 1e-15);
    // From inside to outside: only the part outside.
    EXPECT_NEAR(scene.query({0, 2, 0}, {0, 2, 25}).globalOpticalDepth, b * 20.0, 1e-12);
    // Missing the room: the whole path.
    EXPECT_NEAR(scene.query({-50, 9, 0}, {50, 9, 0}).globalOpticalDepth, b * 100.0, 1e-12);
}

TEST(SubtractVolume, OverlapsRemoveTheUnionOnce) {
    const double b = 0.02;
    FogSceneDesc desc = uniformFog(b);
    desc.volumes.push_back(subtractBox({0, 0, 0}, {5, 5, 5}));   // x in [-5, 5]
    desc.volumes.push_back(subtractBox({7, 0, 0}, {4, 5, 5}));   // x in [3, 11]
    desc.volumes.push_back(subtractBox({30, 0, 0}, {2, 5, 5}));  // x in [28, 32]
    const FogScene scene(desc);
    // Along x from -40 to 60: removed [-5, 11] and [28, 32] = 20 m of 100.
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < 50; ++i) {
        const double y = 4 * u(rng), z = 4 * u(rng);
        const FogQueryResult r = scene.query({-40, y, z}, {60, y, z});
        EXPECT_NEAR(r.globalOpticalDepth, b * 80.0, 1e-12) << i;
    }
    // An ellipsoid subtract overlapping a box one: the union of their
    // analytic intervals, computed here.
    FogSceneDesc mixed = uniformFog(b);
    mixed.volumes.push_back(subtractBox({0, 0, 0}, {5, 5, 5}));
    FogVolume ball = subtractBox({6, 0, 0}, {3, 3, 3});
    ball.shape = FogVolumeShape::Ellipsoid;
    mixed.volumes.push_back(ball);
    const FogScene mixedScene(mixed);
    for (int i = 0; i < 50; ++i) {
        const double y = 2.5 * u(rng), z = 2.5 * u(rng);
        // [-5, 5] u [6 - half, 6 + half] (the ball missed when y^2 + z^2 >= 9).
        const double r2 = y * y + z * z;
        const double half = r2 < 9.0 ? std::sqrt(9.0 - r2) : 0.0;
        const double union_ = half == 0.0 ? 10.0 : (6.0 - half <= 5.0 ? 6.0 + half + 5.0 : 10.0 + 2.0 * half);
        const FogQueryResult r = mixedScene.query({-40, y, z}, {60, y, z});
        EXPECT_NEAR(r.globalOpticalDepth, b * (100.0 - union_), 1e-11) << i;
    }
}

TEST(SubtractVolume, CutsAddVolumesAndExponentialFog) {
    FogSceneDesc desc;
    desc.heightFog.density = 0.01;
    desc.heightFog.falloff = 0.05;
    desc.heightFog.baseHeight = 0.0;
    FogVolume add;
    add.id = "bank";
    add.shape = FogVolumeShape::Box;
    add.position = {0, 0, 0};
    add.halfExtents = {20, 10, 20};
    add.density = 0.04;
    desc.volumes.push_back(add);
    desc.volumes.push_back(subtractBox({5, 0, 0}, {3, 3, 3}));
    const FogScene scene(desc);
    const glm::dvec3 from{-50, 1, 0.5}, to{50, 2, 0.5};
    std::vector<VolumeContribution> parts;
    const FogQueryResult r = scene.query(from, to, parts);
    // Reference: the same integrals over the pieces outside x in [2, 8].
    const glm::dvec3 delta = to - from;
    const double t0 = (2.0 - from.x) / delta.x, t1 = (8.0 - from.x) / delta.x;
    const double globalRef = heightFogOpticalDepth(desc.heightFog, from, t0 * delta) +
                             heightFogOpticalDepth(desc.heightFog, from + t1 * delta, (1.0 - t1) * delta);
    EXPECT_NEAR(r.globalOpticalDepth, globalRef, 1e-12);
    ASSERT_EQ(parts.size(), 1u);
    const double a0 = (-20.0 - from.x) / delta.x, a1 = (20.0 - from.x) / delta.x;
    const double addRef = 0.04 * glm::length(delta) * ((t0 - a0) + (a1 - t1));
    EXPECT_NEAR(parts[0].opticalDepth, addRef, 1e-12);
}

TEST(SubtractVolume, MeshSubtractVolumeRemovesItsChords) {
    const test::TriangleMesh torus = test::torusMesh(6.0, 2.0, 40, 20);
    FogSceneDesc desc = uniformFog(0.01);
    FogVolume v = meshVolume(build(torus), {0, 0, 0}, glm::dquat(1, 0, 0, 0), glm::dvec3(1.0));
    v.blend = FogVolumeBlend::Subtract;
    desc.volumes.push_back(v);
    const FogScene scene(desc);
    const glm::dvec3 from{-30, 0.4, 0.7}, to{30, 0.2, 0.9};
    double inside = 0;
    for (auto [a, b] : clip(referenceChords(torus, v, from, to - from), 1.0)) inside += b - a;
    ASSERT_GT(inside, 0.0);
    const double length = glm::length(to - from);
    EXPECT_NEAR(scene.query(from, to).globalOpticalDepth, 0.01 * length * (1.0 - inside), 1e-12);
}

// ---------------------------------------------------------------------------
// Refused meshes and the glTF reader

TEST(FogMesh, RefusesBadMeshesWithTheReason) {
    std::string error;
    test::TriangleMesh m = test::cubeMesh();
    test::TriangleMesh open = m;
    open.indices.resize(open.indices.size() - 3);
    EXPECT_FALSE(FogMesh::build(open.positions, open.indices, error));
    EXPECT_NE(error.find("open edge"), std::string::npos) << error;
    test::TriangleMesh flipped = m;
    std::swap(flipped.indices[3], flipped.indices[4]);
    EXPECT_FALSE(FogMesh::build(flipped.positions, flipped.indices, error));
    EXPECT_EQ(error.rfind("flipped triangle ", 0), 0u) << error;
    test::TriangleMesh inward = m;
    for (std::size_t k = 0; k < inward.indices.size(); k += 3)
        std::swap(inward.indices[k + 1], inward.indices[k + 2]);
    EXPECT_FALSE(FogMesh::build(inward.positions, inward.indices, error));
    EXPECT_NE(error.find("face inwards"), std::string::npos) << error;
    EXPECT_FALSE(FogMesh::build(m.positions, {0, 1}, error));
    EXPECT_NE(error.find("not a multiple of 3"), std::string::npos) << error;
    EXPECT_FALSE(FogMesh::build(m.positions, {0, 1, 99}, error));
    EXPECT_NE(error.find("refers to vertex 99"), std::string::npos) << error;
    test::TriangleMesh nan = m;
    nan.positions[2].y = std::nan("");
    EXPECT_FALSE(FogMesh::build(nan.positions, nan.indices, error));
    EXPECT_NE(error.find("not finite"), std::string::npos) << error;
    // Over the triangle limit: a fine torus of 2 x 256 x 129 > 65536 triangles.
    const test::TriangleMesh fine = test::torusMesh(6.0, 2.0, 256, 129);
    ASSERT_GT(fine.indices.size() / 3, limits::kMaxFogMeshTriangles);
    EXPECT_FALSE(FogMesh::build(fine.positions, fine.indices, error));
    EXPECT_EQ(error, "66048 triangles, over the limit of 65536 for a fog volume mesh");
    // Split vertices (as glTF exporters write them, one per face corner) weld.
    test::TriangleMesh split;
    for (std::uint32_t i : m.indices) {
        split.indices.push_back(std::uint32_t(split.positions.size()));
        split.positions.push_back(m.positions[i]);
    }
    const auto welded = FogMesh::build(split.positions, split.indices, error);
    ASSERT_TRUE(welded) << error;
    EXPECT_EQ(welded->positions().size(), 8u);
}

TEST(FogMesh, WrittenAsGltfReadsBackToTheSameTriangles) {
    const test::TriangleMesh torus = test::torusMesh(6.0, 2.0, 24, 12);
    const auto mesh = build(torus);
    ASSERT_TRUE(mesh);
    const std::filesystem::path file =
        std::filesystem::temp_directory_path() / "aerial_fog_mesh_roundtrip.gltf";
    {
        std::ofstream out(file);
        out << fogMeshToGltf(*mesh, "torus");
    }
    const FogMeshLoadResult back = loadFogMesh(file.string());
    std::filesystem::remove(file);
    ASSERT_TRUE(back.mesh) << back.error;
    ASSERT_EQ(back.mesh->indices(), mesh->indices());
    ASSERT_EQ(back.mesh->positions().size(), mesh->positions().size());
    for (std::size_t i = 0; i < mesh->positions().size(); ++i)
        EXPECT_LT(glm::length(back.mesh->positions()[i] - mesh->positions()[i]), 1e-6);  // float rounding
    EXPECT_NEAR(back.mesh->enclosedVolume(), mesh->enclosedVolume(), 1e-5 * mesh->enclosedVolume());
}

TEST(FogMesh, ReadsGltfAndPresetsResolveRelativePaths) {
    const std::filesystem::path data = std::filesystem::path(AERIAL_SOURCE_DIR) / "tests/data/bad_inputs";
    const FogMeshLoadResult cube = loadFogMesh((data / "meshes/cube.gltf").string());
    ASSERT_TRUE(cube.mesh) << cube.error;
    EXPECT_EQ(cube.mesh->triangleCount(), 12u);
    EXPECT_NEAR(cube.mesh->enclosedVolume(), 8.0, 1e-9);
    const FogMeshLoadResult missing = loadFogMesh((data / "meshes/none.gltf").string());
    EXPECT_FALSE(missing.mesh);
    EXPECT_EQ(missing.error, (data / "meshes/none.gltf").string() + ": no such file");

    // A preset in memory: the path is relative to the named file's folder.
    const std::string text = R"({"version": 1, "volumes": [{"id": "room", "shape": "mesh",
        "mesh": "../meshes/cube.gltf", "blend": "subtract", "half_extents_m": [3, 2, 4]}]})";
    const PresetLoadResult r = parsePreset(text, (data / "presets" / "memory.json").string());
    ASSERT_TRUE(r.ok()) << r.errors[0].toString();
    const FogVolume& v = r.preset->volumes[0];
    EXPECT_EQ(v.blend, FogVolumeBlend::Subtract);
    ASSERT_TRUE(v.meshData);
    EXPECT_EQ(v.meshData->triangleCount(), 12u);
    // The same file, unchanged, is shared, not read again.
    const PresetLoadResult again = parsePreset(text, (data / "presets" / "other.json").string());
    ASSERT_TRUE(again.ok());
    EXPECT_EQ(again.preset->volumes[0].meshData.get(), v.meshData.get());
    // Saved, the volume keeps its path and blend; box volumes stay without them.
    const std::string saved = presetToJson(*r.preset);
    EXPECT_NE(saved.find("\"mesh\": \"../meshes/cube.gltf\""), std::string::npos) << saved;
    EXPECT_NE(saved.find("\"blend\": \"subtract\""), std::string::npos);
}

}  // namespace
}  // namespace aerial
