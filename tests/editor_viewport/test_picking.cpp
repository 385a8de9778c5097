// Picking: rays through pixels against the renderer's far rays; closed-form
// box / ellipsoid hits against hand-computed answers and against core's
// intersectFogVolume on random rays; icons; nearest-hit ordering; placement.
#include "test_meshes.hpp"
#include "viewport/overlay.hpp"
#include "viewport/picking.hpp"

#include <aerial/fog_mesh.hpp>
#include <aerial/fog_volume.hpp>
#include <aerial/renderer/camera.hpp>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

namespace aerial::editor {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

renderer::CameraFrame makeFrame(glm::dvec3 eye, glm::dvec3 target, double fovDeg = 60.0,
                                double aspect = 16.0 / 9.0) {
    renderer::Camera c;
    c.eye = eye;
    c.target = target;
    c.verticalFov = fovDeg * std::numbers::pi / 180.0;
    c.aspect = aspect;
    return renderer::cameraFrame(c);
}

FogVolume makeVolume(FogVolumeShape shape, glm::dvec3 position, glm::dquat rotation, glm::dvec3 halfExtents) {
    FogVolume v;
    v.shape = shape;
    v.position = position;
    v.rotation = rotation;
    v.halfExtents = halfExtents;
    return v;
}

TEST(RayThroughPixel, MatchesRendererFarRaysAtPixelCentres) {
    const renderer::CameraFrame f = makeFrame({3.0, 7.0, -2.0}, {-20.0, 1.0, -60.0}, 47.0, 1.3);
    const int w = 320;
    const int h = 246;
    for (int y : {0, 17, 123, 245}) {
        for (int x : {0, 1, 160, 319}) {
            const Ray r = rayThroughPixel(f, {x + 0.5, y + 0.5}, {w, h});
            const glm::dvec3 expected = glm::normalize(renderer::farRayAtPixel(f, x, y, w, h));
            EXPECT_EQ(r.origin, f.eye);
            EXPECT_NEAR(glm::length(r.direction - expected), 0.0, 1e-15) << x << "," << y;
            EXPECT_NEAR(glm::length(r.direction), 1.0, 1e-15);
        }
    }
    // The viewport centre is the forward direction; bad input gives it too.
    EXPECT_NEAR(glm::length(rayThroughPixel(f, {160.0, 123.0}, {w, h}).direction - f.forward), 0.0, 1e-15);
    EXPECT_EQ(rayThroughPixel(f, {std::nan(""), 3.0}, {w, h}).direction, f.forward);
    const Ray bad = rayThroughPixel(f, {10.0, 10.0}, {0.0, -kInf});
    EXPECT_TRUE(std::isfinite(bad.direction.x) && std::isfinite(bad.direction.y) &&
                std::isfinite(bad.direction.z));
}

TEST(RayThroughPixel, CornerRayHasTheFieldOfViewAngle) {
    // fov 90 deg, aspect 1: the ray at the top edge's middle is 45 deg up.
    const renderer::CameraFrame f = makeFrame({0, 0, 0}, {0, 0, -1}, 90.0, 1.0);
    const Ray r = rayThroughPixel(f, {50.0, 0.0}, {100.0, 100.0});
    EXPECT_NEAR(r.direction.x, 0.0, 1e-15);
    EXPECT_NEAR(r.direction.y, std::sqrt(0.5), 1e-15);
    EXPECT_NEAR(r.direction.z, -std::sqrt(0.5), 1e-15);
    EXPECT_NEAR(angularRadiusOfPixels(f, 100.0, 50.0), std::numbers::pi / 4.0, 1e-15);
}

TEST(IntersectBox, AxisAlignedAndRotatedKnownAnswers) {
    const glm::dquat identity(1, 0, 0, 0);
    // Unit direction from x = 10 towards -X through a box of half extents (2, 1, 3).
    RayInterval r = intersectOrientedBox({{10, 0, 0}, {-1, 0, 0}}, {0, 0, 0}, identity, {2, 1, 3});
    ASSERT_TRUE(r.hit);
    EXPECT_NEAR(r.tIn, 8.0, 1e-12);
    EXPECT_NEAR(r.tOut, 12.0, 1e-12);
    // Rotated 90 deg about Y: the world X extent is the object Z half extent, 3.
    const glm::dquat yaw90 = glm::angleAxis(std::numbers::pi / 2.0, glm::dvec3(0, 1, 0));
    r = intersectOrientedBox({{10, 0, 0}, {-1, 0, 0}}, {0, 0, 0}, yaw90, {2, 1, 3});
    ASSERT_TRUE(r.hit);
    EXPECT_NEAR(r.tIn, 7.0, 1e-12);
    EXPECT_NEAR(r.tOut, 13.0, 1e-12);
    // A unit cube rotated 45 deg about Z: its edge at x = sqrt(2) faces the ray.
    const glm::dquat roll45 = glm::angleAxis(std::numbers::pi / 4.0, glm::dvec3(0, 0, 1));
    r = intersectOrientedBox({{10, 0, 0.5}, {-1, 0, 0}}, {0, 0, 0}, roll45, {1, 1, 1});
    ASSERT_TRUE(r.hit);
    EXPECT_NEAR(r.tIn, 10.0 - std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(r.tOut, 10.0 + std::sqrt(2.0), 1e-12);
    // At height 0.5 above the centre the rotated square is narrower: x = sqrt(2) - 0.5.
    r = intersectOrientedBox({{10, 0.5, 0.0}, {-1, 0, 0}}, {0, 0, 0}, roll45, {1, 1, 1});
    ASSERT_TRUE(r.hit);
    EXPECT_NEAR(r.tIn, 10.0 - (std::sqrt(2.0) - 0.5), 1e-12);
    // Missing beside it; a moved centre; a non-unit direction counts in its units.
    EXPECT_FALSE(intersectOrientedBox({{10, 1.5, 0}, {-1, 0, 0}}, {0, 0, 0}, identity, {2, 1, 3}).hit);
    r = intersectOrientedBox({{10, 5, 5}, {-2, 0, 0}}, {1, 5, 5}, identity, {2, 1, 3});
    ASSERT_TRUE(r.hit);
    EXPECT_NEAR(r.tIn, 3.5, 1e-12);
    EXPECT_NEAR(r.tOut, 5.5, 1e-12);
    // Behind the origin: the unclipped interval is negative.
    r = intersectOrientedBox({{10, 0, 0}, {1, 0, 0}}, {0, 0, 0}, identity, {2, 1, 3});
    ASSERT_TRUE(r.hit);
    EXPECT_NEAR(r.tIn, -12.0, 1e-12);
    EXPECT_NEAR(r.tOut, -8.0, 1e-12);
}

TEST(IntersectEllipsoid, NonUniformAndRotatedKnownAnswers) {
    const glm::dquat identity(1, 0, 0, 0);
    RayInterval r = intersectOrientedEllipsoid({{11, 2, 3}, {-1, 0, 0}}, {1, 2, 3}, identity, {2, 1, 3});
    ASSERT_TRUE(r.hit);
    EXPECT_NEAR(r.tIn, 8.0, 1e-12);
    EXPECT_NEAR(r.tOut, 12.0, 1e-12);
    // Half a y-radius off the axis: x half chord 2 sqrt(1 - 0.25).
    r = intersectOrientedEllipsoid({{11, 2.5, 3}, {-1, 0, 0}}, {1, 2, 3}, identity, {2, 1, 3});
    ASSERT_TRUE(r.hit);
    EXPECT_NEAR(r.tIn, 10.0 - std::sqrt(3.0), 1e-12);
    EXPECT_NEAR(r.tOut, 10.0 + std::sqrt(3.0), 1e-12);
    // Rotated 90 deg about Z: object X -> world Y, so in world (x/1)^2 + (y/2)^2 = 1;
    // at y = 1 the chord is 2 sqrt(0.75).
    const glm::dquat roll90 = glm::angleAxis(std::numbers::pi / 2.0, glm::dvec3(0, 0, 1));
    r = intersectOrientedEllipsoid({{10, 1, 0}, {-1, 0, 0}}, {0, 0, 0}, roll90, {2, 1, 3});
    ASSERT_TRUE(r.hit);
    EXPECT_NEAR(r.tIn, 10.0 - std::sqrt(0.75), 1e-12);
    EXPECT_NEAR(r.tOut, 10.0 + std::sqrt(0.75), 1e-12);
    EXPECT_FALSE(intersectOrientedEllipsoid({{10, 2.01, 0}, {-1, 0, 0}}, {0, 0, 0}, roll90, {2, 1, 3}).hit);
    // A far ray (1e6 m) through a 1 m sphere keeps its precision (no b^2 - ac cancellation).
    r = intersectOrientedEllipsoid({{1e6, 0.6, 0}, {-1, 0, 0}}, {0, 0, 0}, identity, {1, 1, 1});
    ASSERT_TRUE(r.hit);
    EXPECT_NEAR(r.tOut - r.tIn, 1.6, 1e-9);
    // Degenerate shapes are never hit (core's rules).
    EXPECT_FALSE(intersectOrientedEllipsoid({{10, 0, 0}, {-1, 0, 0}}, {0, 0, 0}, identity, {1, 0, 1}).hit);
    EXPECT_FALSE(
        intersectOrientedEllipsoid({{10, 0, 0}, {-1, 0, 0}}, {0, 0, 0}, glm::dquat(0, 0, 0, 0), {1, 1, 1})
            .hit);
    EXPECT_FALSE(
        intersectOrientedBox({{10, 0, 0}, {-1, 0, 0}}, {0, 0, 0}, identity, {1, std::nan(""), 1}).hit);
    EXPECT_FALSE(intersectOrientedBox({{10, 0, 0}, {0, 0, 0}}, {0, 0, 0}, identity, {1, 1, 1}).hit);
}

// Does a shape scaled by (1 +- eps) give a different hit/miss answer? Then
// the ray grazes it and hit/miss is not well defined in floating point.
bool grazes(const Ray& ray, const FogVolume& v) {
    FogVolume grown = v;
    grown.halfExtents *= 1.0 + 1e-7;
    FogVolume shrunk = v;
    shrunk.halfExtents *= 1.0 - 1e-7;
    const auto clippedHit = [&ray](const FogVolume& s) {
        const RayInterval r = intersectVolumeShape(ray, s);
        return r.hit && r.tOut > 0.0;
    };
    return clippedHit(grown) != clippedHit(shrunk);
}

TEST(IntersectVolumeShape, AgreesWithCoreOnRandomRays) {
    std::mt19937_64 rng(20261121);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::uniform_real_distribution<double> extent(0.5, 20.0);
    int hits = 0;
    int misses = 0;
    int inside = 0;
    int skipped = 0;
    for (int i = 0; i < 10000; ++i) {
        const glm::dquat q = glm::normalize(glm::dquat(u(rng), u(rng), u(rng), u(rng)));
        const FogVolume v =
            makeVolume(i % 2 ? FogVolumeShape::Box : FogVolumeShape::Ellipsoid,
                       {50 * u(rng), 20 * u(rng), 50 * u(rng)}, q, {extent(rng), extent(rng), extent(rng)});
        Ray ray;
        // A quarter of the origins inside the volume's bounds, the rest around it.
        const double spread = (i % 4 == 0) ? 10.0 : 100.0;
        ray.origin = v.position + spread * glm::dvec3(u(rng), u(rng), u(rng));
        // Half the rays aimed near the volume, half anywhere.
        glm::dvec3 d = (i % 3 == 0) ? glm::dvec3(u(rng), u(rng), u(rng))
                                    : (v.position + 15.0 * glm::dvec3(u(rng), u(rng), u(rng))) - ray.origin;
        if (glm::length(d) < 1e-3) continue;
        ray.direction = glm::normalize(d);
        if (grazes(ray, v)) {
            ++skipped;
            continue;
        }
        const RayInterval mine = intersectVolumeShape(ray, v);
        const VolumeSegment core = intersectFogVolume(v, ray.origin, ray.direction, kInf);
        const bool mineHit = mine.hit && std::max(mine.tIn, 0.0) < mine.tOut;
        ASSERT_EQ(mineHit, core.hit) << "ray " << i;
        if (!core.hit) {
            ++misses;
            continue;
        }
        ++hits;
        if (mine.tIn < 0.0) ++inside;
        const double tIn = std::max(mine.tIn, 0.0);
        EXPECT_NEAR(tIn, core.tIn, 1e-9 * std::max(core.tIn, 1e-3)) << "ray " << i;
        EXPECT_NEAR(mine.tOut, core.tOut, 1e-9 * core.tOut) << "ray " << i;
    }
    // The sample exercises every case; grazing rays are rare.
    EXPECT_GT(hits, 3000);
    EXPECT_GT(misses, 2000);
    EXPECT_GT(inside, 500);
    EXPECT_LT(skipped, 20);
}

TEST(Pick, CameraInsideAVolumePicksItAtItsExit) {
    const std::vector<FogVolume> volumes{
        makeVolume(FogVolumeShape::Box, {0, 0, 0}, glm::dquat(1, 0, 0, 0), {5, 5, 5})};
    const Ray ray{{0, 0, 0}, {0, 0, -1}};
    PickHit hit = pick(ray, volumes, {}, 0.01);
    EXPECT_EQ(hit.kind, PickHit::Kind::Volume);
    EXPECT_EQ(hit.index, 0);
    EXPECT_NEAR(hit.distance, 5.0, 1e-12);
    // A volume inside it, in front, wins; one beyond the exit does not.
    std::vector<FogVolume> two = volumes;
    two.push_back(makeVolume(FogVolumeShape::Ellipsoid, {0, 0, -3}, glm::dquat(1, 0, 0, 0), {1, 1, 1}));
    hit = pick(ray, two, {}, 0.01);
    EXPECT_EQ(hit.index, 1);
    EXPECT_NEAR(hit.distance, 2.0, 1e-12);
    two[1].position = {0, 0, -7};
    hit = pick(ray, two, {}, 0.01);
    EXPECT_EQ(hit.index, 0);
    EXPECT_NEAR(hit.distance, 5.0, 1e-12);
    // Behind the camera: nothing.
    EXPECT_EQ(pick({{0, 0, 20}, {0, 0, 1}}, volumes, {}, 0.01).kind, PickHit::Kind::None);
}

TEST(Pick, NearestHitWinsWhateverTheOrder) {
    std::vector<FogVolume> volumes;
    for (double z : {-30.0, -10.0, -20.0}) {
        volumes.push_back(makeVolume(FogVolumeShape::Box, {0, 0, z}, glm::dquat(1, 0, 0, 0), {1, 1, 1}));
    }
    const Ray ray{{0, 0, 0}, {0, 0, -1}};
    PickHit hit = pick(ray, volumes, {}, 0.01);
    EXPECT_EQ(hit.kind, PickHit::Kind::Volume);
    EXPECT_EQ(hit.index, 1);
    EXPECT_NEAR(hit.distance, 9.0, 1e-12);
    // An emitter in front of the nearest box wins; one behind it loses unless emittersFirst.
    std::vector<Emitter> emitters(2);
    emitters[0].position = {0, 0, -25};
    emitters[1].position = {0, 0, -5};
    const double alpha = 0.02;
    hit = pick(ray, volumes, emitters, alpha);
    EXPECT_EQ(hit.kind, PickHit::Kind::Emitter);
    EXPECT_EQ(hit.index, 1);
    EXPECT_NEAR(hit.distance, 5.0 * (1.0 - std::sin(alpha)), 1e-12);
    emitters.pop_back();
    hit = pick(ray, volumes, emitters, alpha);
    EXPECT_EQ(hit.kind, PickHit::Kind::Volume);
    EXPECT_EQ(hit.index, 1);
    hit = pick(ray, volumes, emitters, alpha, /*emittersFirst=*/true);
    EXPECT_EQ(hit.kind, PickHit::Kind::Emitter);
    EXPECT_EQ(hit.index, 0);
    // A non-normalised ray direction gives the same distances.
    hit = pick({{0, 0, 0}, {0, 0, -7}}, volumes, {}, alpha);
    EXPECT_NEAR(hit.distance, 9.0, 1e-12);
    // Degenerate volumes are never picked.
    volumes[1].halfExtents = {0, 1, 1};
    hit = pick(ray, volumes, {}, alpha);
    EXPECT_EQ(hit.index, 2);
    EXPECT_EQ(pick({{0, 0, 0}, {0, 0, 0}}, volumes, emitters, alpha).kind, PickHit::Kind::None);
}

TEST(Pick, MeshVolumesByTheirRealTriangles) {
    // A torus (ring 6 m, tube 2 m) in front of the camera, its axis towards
    // it: a ray through the hole misses it and picks the box behind; a ray
    // through the tube picks the torus at the tube's surface.
    const test::TriangleMesh t = test::torusMesh(6.0, 2.0, 48, 24);
    std::string error;
    FogVolume torus = makeVolume(FogVolumeShape::Box, {0, 0, -20}, glm::angleAxis(std::numbers::pi / 2, glm::dvec3(1, 0, 0)),
                                 {1, 1, 1});
    torus.shape = FogVolumeShape::Mesh;
    torus.mesh = "torus";
    torus.meshData = FogMesh::build(t.positions, t.indices, error);
    ASSERT_TRUE(torus.meshData) << error;
    std::vector<FogVolume> volumes = {torus, makeVolume(FogVolumeShape::Box, {0, 0, -40}, glm::dquat(1, 0, 0, 0), {1, 1, 1})};
    PickHit hit = pick({{0, 0, 0}, {0, 0, -1}}, volumes, {}, 0.01);
    EXPECT_EQ(hit.index, 1);  // through the hole
    EXPECT_NEAR(hit.distance, 39.0, 1e-9);
    hit = pick({{6, 0.01, 0}, {0, 0, -1}}, volumes, {}, 0.01);
    EXPECT_EQ(hit.index, 0);  // the tube, entered about 2 m before its centre line
    EXPECT_NEAR(hit.distance, 18.0, 0.05);
    // Its outline is its edges (a small mesh: all of them), in world space.
    const std::vector<WorldSegment> outline = volumeOutlineSegments(torus);
    // Every edge but the diagonals of the quads (their two triangles are
    // coplanar): the closed torus has 3 edges per quad, 1 a diagonal.
    EXPECT_EQ(outline.size(), t.indices.size() / 2 - t.indices.size() / 6);
    for (const WorldSegment& s : outline) {
        EXPECT_NEAR(glm::length(glm::dvec2(s.first.x, s.first.y)), 6.0, 2.0 + 1e-9);
        EXPECT_NEAR(s.first.z, -20.0, 2.0 + 1e-9);
    }
    // The bounding sphere holds it.
    const BoundingSphere b = boundingSphereOf(torus);
    EXPECT_NEAR(b.centre.z, -20.0, 1e-9);
    EXPECT_GE(b.radius, 8.0);
}

TEST(Pick, CloudVolumesByTheirShapeWhereNothingElseIs) {
    // A storm cell kilometres across, seen from the ground 10 km away.
    CloudVolume cell;
    cell.shape = FogVolumeShape::Ellipsoid;
    cell.position = {0, 2500, -10000};
    cell.rotation = glm::angleAxis(0.3, glm::dvec3(0, 1, 0));
    cell.halfExtents = {3000, 900, 3000};
    const FogVolume shape = shapeOf(cell);
    EXPECT_EQ(shape.shape, cell.shape);
    EXPECT_EQ(shape.position, cell.position);
    EXPECT_EQ(shape.rotation, cell.rotation);
    EXPECT_EQ(shape.halfExtents, cell.halfExtents);
    const std::vector<CloudVolume> cells{cell};
    const glm::dvec3 eye(0, 2, 0);
    const Ray atCentre{eye, glm::normalize(cell.position - eye)};
    PickHit hit = pick(atCentre, {}, {}, cells, 0.01, true);
    EXPECT_EQ(hit.kind, PickHit::Kind::CloudVolume);
    EXPECT_EQ(hit.index, 0);
    EXPECT_NEAR(hit.distance, intersectVolumeShape(atCentre, shape).tIn, 1e-9);
    // Past the ellipsoid's rim but inside its bounding box: picked by the shape, not the bounds.
    const Ray corner{{2500, 3300, 0}, {0, 0, -1}};
    EXPECT_EQ(pick(corner, {}, {}, cells, 0.01, true).kind, PickHit::Kind::None);
    std::vector<CloudVolume> box = cells;
    box[0].shape = FogVolumeShape::Box;
    box[0].rotation = glm::dquat(1, 0, 0, 0);
    EXPECT_EQ(pick(corner, {}, {}, box, 0.01, true).kind, PickHit::Kind::CloudVolume);
    // A fog volume or an emitter on the ray wins, even behind the cell's entry.
    const std::vector<FogVolume> fog{makeVolume(FogVolumeShape::Box, eye + 20000.0 * atCentre.direction,
                                                glm::dquat(1, 0, 0, 0), {50, 50, 50})};
    hit = pick(atCentre, fog, {}, cells, 0.01, true);
    EXPECT_EQ(hit.kind, PickHit::Kind::Volume);
    std::vector<Emitter> lamps(1);
    lamps[0].position = eye + 30.0 * atCentre.direction;
    hit = pick(atCentre, {}, lamps, cells, 0.01, true);
    EXPECT_EQ(hit.kind, PickHit::Kind::Emitter);
    // From inside the cell: picked at its exit; the nearer of two overlapping cells.
    const Ray inside{cell.position, {0, 0, -1}};
    hit = pick(inside, {}, {}, cells, 0.01);
    EXPECT_EQ(hit.kind, PickHit::Kind::CloudVolume);
    EXPECT_NEAR(hit.distance, 3000.0, 1e-6);
    std::vector<CloudVolume> two = cells;
    two.push_back(cell);
    two[1].position.z -= 500.0;
    hit = pick(inside, {}, {}, two, 0.01);
    EXPECT_EQ(hit.index, 0);
}

TEST(Pick, IconsKeepTheirScreenSize) {
    // Camera at the origin looking -Z; an icon of 10 px radius at the centre
    // of a 720 px tall viewport. Rays 9 px off hit it at any distance, 11 px
    // off miss it.
    const renderer::CameraFrame f = makeFrame({0, 0, 0}, {0, 0, -1}, 60.0, 16.0 / 9.0);
    const glm::dvec2 size{1280, 720};
    const double alpha = angularRadiusOfPixels(f, size.y, 10.0);
    for (double distance : {2.0, 50.0, 3000.0}) {
        std::vector<Emitter> emitters(1);
        emitters[0].position = {0, 0, -distance};
        const Ray near = rayThroughPixel(f, {640.0 + 9.0, 360.0}, size);
        const Ray far = rayThroughPixel(f, {640.0, 360.0 - 11.0}, size);
        const PickHit hit = pick(near, {}, emitters, alpha);
        EXPECT_EQ(hit.kind, PickHit::Kind::Emitter) << distance;
        EXPECT_GT(hit.distance, 0.0);
        EXPECT_LT(hit.distance, distance);
        EXPECT_EQ(pick(far, {}, emitters, alpha).kind, PickHit::Kind::None) << distance;
    }
    // Exactly on the boundary angle (within rounding) and just outside.
    const glm::dvec3 p{0, 0, -10};
    const glm::dvec3 inside{std::sin(0.0199), 0, -std::cos(0.0199)};
    const glm::dvec3 outside{std::sin(0.0201), 0, -std::cos(0.0201)};
    EXPECT_TRUE(intersectIcon({{0, 0, 0}, inside}, p, 0.02).has_value());
    EXPECT_FALSE(intersectIcon({{0, 0, 0}, outside}, p, 0.02).has_value());
    EXPECT_FALSE(intersectIcon({{0, 0, 0}, {0, 0, 1}}, p, 0.02).has_value());     // behind
    EXPECT_FALSE(intersectIcon({{0, 0, -10}, {0, 0, -1}}, p, 0.02).has_value());  // at the origin
    EXPECT_FALSE(intersectIcon({{0, 0, 0}, {0, 0, -1}}, p, std::nan("")).has_value());
}

TEST(BoundingSphere, HoldsTheShape) {
    FogVolume v =
        makeVolume(FogVolumeShape::Box, {1, 2, 3}, glm::angleAxis(0.4, glm::dvec3(0, 1, 0)), {3, 4, 12});
    BoundingSphere b = boundingSphereOf(v);
    EXPECT_EQ(b.centre, v.position);
    EXPECT_NEAR(b.radius, 13.0, 1e-12);  // |(3, 4, 12)|
    v.shape = FogVolumeShape::Ellipsoid;
    EXPECT_NEAR(boundingSphereOf(v).radius, 12.0, 1e-12);
    v.halfExtents.x = -1.0;
    EXPECT_EQ(boundingSphereOf(v).radius, 1.0);
    Emitter e;
    e.position = {5, 6, 7};
    e.attenuation = 0.04;
    b = boundingSphereOf(e);
    EXPECT_EQ(b.centre, e.position);
    EXPECT_NEAR(b.radius, 5.0, 1e-12);
    e.attenuation = 1e-9;
    EXPECT_EQ(boundingSphereOf(e).radius, 50.0);
    e.attenuation = std::nan("");
    EXPECT_EQ(boundingSphereOf(e).radius, 10.0);
}

TEST(PlaceInFront, GroundPlaneHeightFieldOrForwardPoint) {
    // Looking 45 deg down from 10 m: the ground at 10 m ahead.
    const renderer::CameraFrame down = makeFrame({0, 10, 0}, {0, 0, -10});
    std::optional<glm::dvec3> p = placeInFront(down, 60.0);
    ASSERT_TRUE(p.has_value());
    EXPECT_NEAR(glm::length(*p - glm::dvec3(0, 0, -10)), 0.0, 1e-12);
    // Ground beyond maxGroundDistance: 60 m along the view.
    p = placeInFront(down, 60.0, 5.0);
    ASSERT_TRUE(p.has_value());
    EXPECT_NEAR(glm::length(*p - (down.eye + 60.0 * down.forward)), 0.0, 1e-12);
    // A flat height field at 2 m: hit at 8 m ahead, to the bisection's 1e-6 m.
    p = placeInFront(down, 60.0, 250.0, [](double, double) { return 2.0; });
    ASSERT_TRUE(p.has_value());
    EXPECT_NEAR(glm::length(*p - glm::dvec3(0, 2, -8)), 0.0, 2e-6);
    // A slope y = 0.5 (-z) - 20: along the ray y = 10 - s, z = -s: 10 - s = 0.5 s - 20 -> s = 20.
    p = placeInFront(down, 60.0, 250.0, [](double, double z) { return -0.5 * z - 20.0; });
    ASSERT_TRUE(p.has_value());
    EXPECT_NEAR(glm::length(*p - glm::dvec3(0, -10, -20)), 0.0, 3e-6);
    // Looking up: never the ground.
    const renderer::CameraFrame up = makeFrame({0, 10, 0}, {0, 20, -10});
    p = placeInFront(up, 60.0);
    ASSERT_TRUE(p.has_value());
    EXPECT_NEAR(glm::length(*p - (up.eye + 60.0 * up.forward)), 0.0, 1e-12);
    // Invalid input.
    EXPECT_FALSE(placeInFront(down, 0.0).has_value());
    EXPECT_FALSE(placeInFront(down, std::nan("")).has_value());
    renderer::CameraFrame broken = down;
    broken.eye.x = kInf;
    EXPECT_FALSE(placeInFront(broken, 10.0).has_value());
}

}  // namespace
}  // namespace aerial::editor
