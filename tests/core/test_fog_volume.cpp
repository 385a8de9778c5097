// Fog volumes: intersection and optical depth against an independent
// reference — boundaries found by golden-section search and bisection on an
// inside test built from a 4x4 glm::inverse of worldFromObject (not the
// library's object-space rows), the density integrated by composite
// Gauss-Legendre quadrature between them.
#include <aerial/atmosphere.hpp>
#include <aerial/fog_volume.hpp>
#include <aerial/height_fog.hpp>
#include <aerial/limits.hpp>

#include <gtest/gtest.h>

#include "quadrature.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

namespace {

using aerial::FogVolume;
using aerial::FogVolumeShape;
using aerial::kMaxOpticalDepth;

/// Independent geometry of a volume: world = T R S object.
struct ReferenceGeometry {
    glm::dmat4 worldFromObject;
    glm::dmat4 objectFromWorld;
    FogVolumeShape shape;

    explicit ReferenceGeometry(const FogVolume& v) : shape(v.shape) {
        worldFromObject = glm::translate(glm::dmat4(1.0), v.position) *
                          glm::mat4_cast(glm::normalize(v.rotation)) *
                          glm::scale(glm::dmat4(1.0), v.halfExtents);
        objectFromWorld = glm::inverse(worldFromObject);
    }
    glm::dvec3 toObject(const glm::dvec3& p) const {
        return glm::dvec3(objectFromWorld * glm::dvec4(p, 1.0));
    }
    glm::dvec3 toWorld(const glm::dvec3& q) const { return glm::dvec3(worldFromObject * glm::dvec4(q, 1.0)); }
    glm::dvec3 vectorToWorld(const glm::dvec3& q) const {
        return glm::dvec3(worldFromObject * glm::dvec4(q, 0.0));
    }
    /// <= 1 inside: max-norm (box) or Euclidean norm (ellipsoid) of the
    /// object point. Convex along any line.
    double insideMeasure(const glm::dvec3& p) const {
        const glm::dvec3 q = toObject(p);
        return shape == FogVolumeShape::Box ? std::max({std::fabs(q.x), std::fabs(q.y), std::fabs(q.z)})
                                            : std::sqrt(glm::dot(q, q));
    }
};

/// The reference density: b exp(-c (dot(p - centre, g) - offset)), written
/// out (no inside test).
double referenceDensity(const FogVolume& v, const glm::dvec3& p) {
    const glm::dvec3 g = glm::normalize(v.gradientDirection);
    return v.density * std::exp(-v.falloff * (glm::dot(p - v.position, g) - v.gradientOffset));
}

struct ReferenceChord {
    bool hit = false;
    double t0 = 0.0;
    double t1 = 0.0;
};

/// Entry and exit of origin + t direction, t in [0, tMax], found without the
/// library: minimise the convex inside measure, then bisect each side.
ReferenceChord referenceChord(const ReferenceGeometry& geo, const glm::dvec3& origin,
                              const glm::dvec3& direction, double tMax) {
    auto phi = [&](double t) { return geo.insideMeasure(origin + t * direction); };
    double best = aerial::test::goldenSectionMinimum(phi, 0.0, tMax);
    for (double t : {0.0, tMax}) {
        if (phi(t) < phi(best)) {
            best = t;
        }
    }
    ReferenceChord chord;
    if (!(phi(best) < 1.0)) {
        return chord;
    }
    auto inside = [&](double t) { return phi(t) <= 1.0; };
    chord.hit = true;
    chord.t0 = inside(0.0) ? 0.0 : aerial::test::bisectBoundary(inside, 0.0, best);
    chord.t1 = inside(tMax) ? tMax : aerial::test::bisectBoundary(inside, best, tMax);
    return chord;
}

/// Quadrature of fogVolumeDensityAt between the reference boundaries:
/// >= 2000 five-point sub-intervals (10 000 evaluations), more for steep
/// falloffs (at most half an e-fold per sub-interval).
double referenceOpticalDepth(const FogVolume& v, const glm::dvec3& origin, const glm::dvec3& direction,
                             const ReferenceChord& chord) {
    if (!chord.hit) {
        return 0.0;
    }
    const double length = glm::length(direction);
    const glm::dvec3 g = glm::normalize(v.gradientDirection);
    const double efolds = std::fabs(v.falloff * glm::dot(direction, g)) * (chord.t1 - chord.t0);
    const std::size_t intervals = std::max<std::size_t>(2000, static_cast<std::size_t>(2.0 * efolds) + 1);
    return aerial::test::gaussLegendre(
        [&](double t) { return aerial::fogVolumeDensityAt(v, origin + t * direction) * length; }, chord.t0,
        chord.t1, intervals);
}

class VolumeCases {
public:
    explicit VolumeCases(std::uint64_t seed) : rng_(seed) {}

    double unit() { return std::uniform_real_distribution<double>(0.0, 1.0)(rng_); }
    double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }
    double logUniform(double lo, double hi) {
        return std::exp(std::log(lo) + unit() * (std::log(hi) - std::log(lo)));
    }
    glm::dvec3 randomDirection() {
        std::normal_distribution<double> n(0.0, 1.0);
        for (;;) {
            const glm::dvec3 v{n(rng_), n(rng_), n(rng_)};
            const double l = glm::length(v);
            if (l > 1e-3) {
                return v / l;
            }
        }
    }
    glm::dquat randomRotation() {
        std::normal_distribution<double> n(0.0, 1.0);
        return glm::normalize(glm::dquat(n(rng_), n(rng_), n(rng_), n(rng_)));
    }
    /// A uniformly random point of the unit shape (object space).
    glm::dvec3 objectPointInside(FogVolumeShape shape, double margin = 0.98) {
        if (shape == FogVolumeShape::Box) {
            return margin * glm::dvec3(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
        }
        return randomDirection() * margin * std::cbrt(unit());
    }

    FogVolume volume(int i) {
        FogVolume v;
        v.shape = (i % 2 == 0) ? FogVolumeShape::Box : FogVolumeShape::Ellipsoid;
        v.position = {uniform(-300, 300), uniform(-50, 300), uniform(-300, 300)};
        v.halfExtents = {logUniform(0.5, 200), logUniform(0.5, 200), logUniform(0.5, 200)};
        switch (i % 5) {
            case 0:
                v.rotation = glm::dquat(1, 0, 0, 0);
                break;
            case 1:
                v.rotation = glm::angleAxis(aerial::kPi / 2, randomDirection());
                break;
            default:
                v.rotation = randomRotation();
                break;
        }
        v.density = logUniform(1e-5, 0.2);
        switch ((i / 2) % 5) {
            case 0:
                v.falloff = 0.0;
                break;
            case 1:
                v.falloff = logUniform(1e-13, 1e-8);
                break;
            case 2:
                v.falloff = logUniform(1e-4, 1e-2);
                break;
            case 3:
                v.falloff = logUniform(1e-2, 0.3);
                break;
            default:
                v.falloff = logUniform(0.3, 3.0);
                break;
        }
        switch ((i / 3) % 6) {
            case 0:
                v.gradientDirection = {0, 1, 0};
                break;
            case 1:
                v.gradientDirection = {-1, 0, 0};
                break;
            case 2:
                v.gradientDirection = randomDirection() * logUniform(1e-3, 1e3);
                break;
            default:
                v.gradientDirection = randomDirection();
                break;
        }
        const double size = glm::length(v.halfExtents);
        v.gradientOffset = uniform(-1, 1) * size;
        // Keep the densest point of the volume within double range for the
        // reference (the library itself saturates; tested elsewhere).
        v.falloff = std::min(v.falloff, 600.0 / (std::fabs(v.gradientOffset) + size));
        return v;
    }

private:
    std::mt19937_64 rng_;
};

struct Segment {
    glm::dvec3 origin;
    glm::dvec3 direction;  // to - from; t in [0, 1]
    const char* kind;
};

Segment makeSegment(VolumeCases& r, FogVolume& v, const ReferenceGeometry& geo, int i) {
    const double size = glm::length(v.halfExtents);
    auto outside = [&]() { return v.position + r.randomDirection() * (2.0 * size + r.uniform(1, 500)); };
    auto inside = [&]() { return geo.toWorld(r.objectPointInside(v.shape)); };
    switch (i % 7) {
        case 0: {  // from outside, through, beyond
            const glm::dvec3 from = outside();
            return {from, 2.0 * (inside() - from), "through"};
        }
        case 1: {  // camera inside
            const glm::dvec3 from = inside();
            return {from, outside() - from, "camera inside"};
        }
        case 2: {  // scene geometry inside
            const glm::dvec3 from = outside();
            return {from, inside() - from, "ends inside"};
        }
        case 3: {  // grazing: tangent to the surface, 1e-6 inside it
            glm::dvec3 o;
            glm::dvec3 d;
            if (v.shape == FogVolumeShape::Ellipsoid) {
                const glm::dvec3 n = r.randomDirection();
                glm::dvec3 t = glm::cross(n, r.randomDirection());
                t = glm::normalize(t);
                o = n * (1.0 - 1e-6) - 3.0 * t;
                d = 6.0 * t;
            } else {
                const int axis = static_cast<int>(r.unit() * 3.0) % 3;
                const int along = (axis + 1 + static_cast<int>(r.unit() * 2.0) % 2) % 3;
                o = glm::dvec3(r.uniform(-0.9, 0.9), r.uniform(-0.9, 0.9), r.uniform(-0.9, 0.9));
                o[axis] = (r.unit() < 0.5 ? -1.0 : 1.0) * (1.0 - 1e-6);
                o[along] = -3.0;
                d = glm::dvec3(0.0);
                d[along] = 6.0;
            }
            return {geo.toWorld(o), geo.vectorToWorld(d), "grazing"};
        }
        case 4: {  // exactly horizontal, gradient +Y: c d.y == 0 exactly
            v.gradientDirection = {0, 1, 0};
            glm::dvec3 from = inside();
            const double azimuth = r.uniform(0, 2 * aerial::kPi);
            const glm::dvec3 dir{std::cos(azimuth), 0.0, std::sin(azimuth)};
            from -= dir * (2.0 * size);
            return {from, dir * (4.0 * size), "horizontal"};
        }
        case 5: {  // both ends inside
            const glm::dvec3 from = inside();
            return {from, inside() - from, "inside"};
        }
        default: {  // arbitrary
            const glm::dvec3 from = outside();
            return {from, outside() - from, "arbitrary"};
        }
    }
}

TEST(FogVolume, KnownAnswers) {
    FogVolume box;
    box.position = {10, 20, 30};
    box.halfExtents = {5, 2, 3};
    box.density = 0.1;
    // Along +X through the centre: chord 2 s_x = 10 m.
    auto seg = aerial::intersectFogVolume(box, {-100, 20, 30}, {1, 0, 0}, 1000.0);
    ASSERT_TRUE(seg.hit);
    EXPECT_NEAR(seg.tIn, 105.0, 1e-12);
    EXPECT_NEAR(seg.tOut, 115.0, 1e-12);
    EXPECT_NEAR(aerial::fogVolumeOpticalDepth(box, {-100, 20, 30}, {1, 0, 0}, seg), 1.0, 1e-12);
    // Non-unit direction: t in units of |d|, distances in metres.
    seg = aerial::intersectFogVolume(box, {-100, 20, 30}, {10, 0, 0}, 100.0);
    EXPECT_NEAR(seg.tIn, 10.5, 1e-12);
    EXPECT_NEAR(aerial::fogVolumeOpticalDepth(box, {-100, 20, 30}, {10, 0, 0}, seg), 1.0, 1e-12);
    // Camera inside: clipped at 0. Scene geometry inside: clipped at tMax.
    seg = aerial::intersectFogVolume(box, {10, 20, 30}, {0, 1, 0}, 1.5);
    EXPECT_TRUE(seg.hit);
    EXPECT_EQ(seg.tIn, 0.0);
    EXPECT_EQ(seg.tOut, 1.5);
    EXPECT_NEAR(aerial::fogVolumeOpticalDepth(box, {10, 20, 30}, {0, 1, 0}, seg), 0.15, 1e-14);
    // Behind the camera, or beyond the scene: no hit.
    EXPECT_FALSE(aerial::intersectFogVolume(box, {-100, 20, 30}, {-1, 0, 0}, 1e9).hit);
    EXPECT_FALSE(aerial::intersectFogVolume(box, {-100, 20, 30}, {1, 0, 0}, 100.0).hit);

    // A cube rotated 45 degrees about Y: the diagonal chord 2 sqrt(2) s.
    FogVolume cube;
    cube.halfExtents = {4, 4, 4};
    cube.rotation = glm::angleAxis(aerial::kPi / 4, glm::dvec3(0, 1, 0));
    seg = aerial::intersectFogVolume(cube, {-50, 1, 0}, {1, 0, 0}, 100.0);
    ASSERT_TRUE(seg.hit);
    EXPECT_NEAR(seg.tOut - seg.tIn, 2.0 * std::sqrt(2.0) * 4.0, 1e-12);

    // Ellipsoid: through the centre along each axis, 2 s_i; off-centre chord
    // of the sphere 2 sqrt(R^2 - p^2).
    FogVolume ell;
    ell.shape = FogVolumeShape::Ellipsoid;
    ell.halfExtents = {7, 3, 5};
    ell.density = 0.5;
    seg = aerial::intersectFogVolume(ell, {0, -40, 0}, {0, 1, 0}, 100.0);
    EXPECT_NEAR(seg.tOut - seg.tIn, 6.0, 1e-12);
    ell.halfExtents = {5, 5, 5};
    seg = aerial::intersectFogVolume(ell, {-40, 3, 0}, {1, 0, 0}, 100.0);
    EXPECT_NEAR(seg.tOut - seg.tIn, 8.0, 1e-12);
    EXPECT_NEAR(aerial::fogVolumeOpticalDepth(ell, {-40, 3, 0}, {1, 0, 0}, seg), 4.0, 1e-12);

    // Gradient along +X with falloff c: integral b/c (e^{c s} - e^{-c s}).
    FogVolume slab = box;
    slab.position = {0, 0, 0};
    slab.gradientDirection = {2, 0, 0};  // not unit: normalised
    slab.falloff = 0.3;
    seg = aerial::intersectFogVolume(slab, {-10, 0, 0}, {1, 0, 0}, 100.0);
    const double expected = 0.1 / 0.3 * (std::exp(0.3 * 5) - std::exp(-0.3 * 5));
    EXPECT_NEAR(aerial::fogVolumeOpticalDepth(slab, {-10, 0, 0}, {1, 0, 0}, seg), expected, 1e-13 * expected);
    // A zero gradient falls back to +Y: a horizontal ray sees the density at
    // its height.
    slab.gradientDirection = {0, 0, 0};
    seg = aerial::intersectFogVolume(slab, {-10, 1, 0}, {1, 0, 0}, 100.0);
    EXPECT_NEAR(aerial::fogVolumeOpticalDepth(slab, {-10, 1, 0}, {1, 0, 0}, seg), 0.1 * std::exp(-0.3) * 10.0,
                1e-13);
}

TEST(FogVolume, MatchesQuadratureOverRandomisedVolumesAndRays) {
    // Tolerance: 1e-4 relative, absolute floor 1e-12 (for chords too short
    // to matter); saturated references compare against kMaxOpticalDepth.
    VolumeCases r(424242);
    double worst = 0.0;
    int hits = 0;
    int cases = 0;
    for (int i = 0; i < 700; ++i) {
        FogVolume v = r.volume(i);
        ReferenceGeometry geo(v);
        const Segment s = makeSegment(r, v, geo, i);
        const ReferenceChord chord = referenceChord(geo, s.origin, s.direction, 1.0);
        const double reference = referenceOpticalDepth(v, s.origin, s.direction, chord);
        const auto seg = aerial::intersectFogVolume(v, s.origin, s.direction, 1.0);
        const double got = aerial::fogVolumeOpticalDepth(v, s.origin, s.direction, seg);
        ++cases;
        hits += chord.hit ? 1 : 0;
        const char* shape = v.shape == FogVolumeShape::Box ? "box" : "ellipsoid";
        if (chord.hit && chord.t1 - chord.t0 > 1e-9) {
            EXPECT_TRUE(seg.hit) << "case " << i << " " << shape << " " << s.kind;
            // Boundaries: 1e-9 of the segment (the reference bisects the
            // independent inside test to the last bit).
            EXPECT_NEAR(seg.tIn, chord.t0, 1e-9) << "case " << i << " " << s.kind;
            EXPECT_NEAR(seg.tOut, chord.t1, 1e-9) << "case " << i << " " << s.kind;
        }
        if (reference >= kMaxOpticalDepth) {
            EXPECT_EQ(got, kMaxOpticalDepth) << "case " << i;
            continue;
        }
        const double error = std::fabs(got - reference);
        EXPECT_LE(error, 1e-4 * reference + 1e-12)
            << "case " << i << " " << shape << " " << s.kind << " c=" << v.falloff << " ref=" << reference
            << " got=" << got;
        if (reference > 1e-9) {
            worst = std::max(worst, error / reference);
        }
    }
    EXPECT_GE(hits, 450);  // most cases cross the volume
    std::printf("[          ] fog volumes: %d cases (%d hits), worst relative error %.3g\n", cases, hits,
                worst);
}

TEST(FogVolume, DensityAtMatchesIndependentFormula) {
    // Inside/outside by the reference geometry, density by the written-out
    // formula; points within 1e-9 of the surface are skipped (rounding
    // decides there). Tolerance 1e-12 relative.
    VolumeCases r(777);
    int insideCount = 0;
    for (int i = 0; i < 300; ++i) {
        const FogVolume v = r.volume(i);
        const ReferenceGeometry geo(v);
        for (int k = 0; k < 40; ++k) {
            const glm::dvec3 q = r.randomDirection() * r.uniform(0.0, 1.6);
            const glm::dvec3 p = geo.toWorld(q);
            const double measure = geo.insideMeasure(p);
            if (std::fabs(measure - 1.0) < 1e-9) {
                continue;
            }
            const double expected = measure <= 1.0 ? referenceDensity(v, p) : 0.0;
            insideCount += measure <= 1.0 ? 1 : 0;
            EXPECT_NEAR(aerial::fogVolumeDensityAt(v, p), expected, 1e-12 * expected) << "volume " << i;
        }
    }
    EXPECT_GT(insideCount, 3000);
}

TEST(FogVolume, BoundsContainTheShapeAndAreTight) {
    // Every surface point lies within the bounds (1e-9 relative slack); the
    // bounds are reached by the shape (within 2e-2 of the extent, from 20 000
    // samples for ellipsoids; exactly at a corner for boxes).
    VolumeCases r(99);
    for (int i = 0; i < 100; ++i) {
        const FogVolume v = r.volume(i);
        const ReferenceGeometry geo(v);
        glm::dvec3 lo;
        glm::dvec3 hi;
        aerial::fogVolumeBounds(v, lo, hi);
        glm::dvec3 seenLo(std::numeric_limits<double>::max());
        glm::dvec3 seenHi(-std::numeric_limits<double>::max());
        auto see = [&](const glm::dvec3& q) {
            const glm::dvec3 p = geo.toWorld(q);
            seenLo = glm::min(seenLo, p);
            seenHi = glm::max(seenHi, p);
        };
        if (v.shape == FogVolumeShape::Box) {
            for (int c = 0; c < 8; ++c) {
                see({c & 1 ? 1.0 : -1.0, c & 2 ? 1.0 : -1.0, c & 4 ? 1.0 : -1.0});
            }
        } else {
            for (int k = 0; k < 20000; ++k) {
                see(r.randomDirection());
            }
        }
        const glm::dvec3 extent = hi - lo;
        for (int a = 0; a < 3; ++a) {
            const double slack = 1e-9 * (extent[a] + std::fabs(v.position[a]));
            EXPECT_LE(lo[a], seenLo[a] + slack) << "volume " << i;
            EXPECT_GE(hi[a], seenHi[a] - slack) << "volume " << i;
            const double tight = (v.shape == FogVolumeShape::Box ? 1e-9 : 2e-2) * extent[a] + slack;
            EXPECT_NEAR(lo[a], seenLo[a], tight) << "volume " << i;
            EXPECT_NEAR(hi[a], seenHi[a], tight) << "volume " << i;
        }
    }
}

TEST(FogVolume, PreparedVolumeIsTheReferenceGeometry) {
    // prepareFogVolume is the one geometry the BVH, the renderer's packing
    // and the editor's picking share: its transforms against an independent
    // glm::translate * mat4_cast * scale (1e-12 of the size), its ray tests
    // against the single-volume API (bit for bit: the same code) and against
    // the reference inside measure at the hit points (1e-9).
    VolumeCases r(1234);
    for (int i = 0; i < 200; ++i) {
        FogVolume v = r.volume(i);
        const Segment seg = makeSegment(r, v, ReferenceGeometry(v), i);
        const ReferenceGeometry geo(v);
        const aerial::PreparedFogVolume p = aerial::prepareFogVolume(v);
        ASSERT_TRUE(p.valid) << "volume " << i;
        const double size = glm::length(v.halfExtents) + glm::length(v.position);
        for (int k = 0; k < 8; ++k) {
            const glm::dvec3 q = r.objectPointInside(v.shape, 1.5);
            const glm::dvec3 world = p.position + p.worldFromObject * q;
            EXPECT_LE(glm::length(world - geo.toWorld(q)), 1e-12 * size) << "volume " << i;
            EXPECT_LE(glm::length(p.toObject(world - p.position) - q), 1e-9) << "volume " << i;
            EXPECT_EQ(aerial::fogVolumeContains(p, world), geo.insideMeasure(world) <= 1.0)
                << "volume " << i << " point measure " << geo.insideMeasure(world);
        }
        const aerial::VolumeSegment a = aerial::intersectFogVolume(v, seg.origin, seg.direction, 1.0);
        const aerial::VolumeSegment b = aerial::intersectFogVolume(p, seg.origin, seg.direction, 1.0);
        EXPECT_EQ(a.hit, b.hit) << seg.kind << " volume " << i;
        EXPECT_EQ(a.tIn, b.tIn) << seg.kind << " volume " << i;
        EXPECT_EQ(a.tOut, b.tOut) << seg.kind << " volume " << i;
        EXPECT_EQ(aerial::fogVolumeOpticalDepth(v, seg.origin, seg.direction, a),
                  aerial::fogVolumeOpticalDepth(p, seg.origin, seg.direction, b))
            << seg.kind << " volume " << i;
        const aerial::VolumeInterval line = aerial::intersectFogVolumeLine(p, seg.origin, seg.direction);
        if (line.hit) {
            EXPECT_NEAR(geo.insideMeasure(seg.origin + line.tNear * seg.direction), 1.0, 1e-9)
                << seg.kind << " volume " << i;
            EXPECT_NEAR(geo.insideMeasure(seg.origin + line.tFar * seg.direction), 1.0, 1e-9)
                << seg.kind << " volume " << i;
            EXPECT_EQ(b.hit, std::max(line.tNear, 0.0) < std::min(line.tFar, 1.0))
                << seg.kind << " volume " << i;
        } else {
            EXPECT_FALSE(b.hit) << seg.kind << " volume " << i;
        }
    }
    // Degenerate by limits.hpp's numbers: just under the smallest half extent.
    FogVolume thin;
    thin.halfExtents = {1.0, 0.5 * aerial::limits::kMinHalfExtent, 1.0};
    EXPECT_FALSE(aerial::prepareFogVolume(thin).valid);
    thin.halfExtents.y = aerial::limits::kMinHalfExtent;
    EXPECT_TRUE(aerial::prepareFogVolume(thin).valid);
    thin.position.x = 2.0 * aerial::limits::kMaxCoordinate;
    EXPECT_FALSE(aerial::prepareFogVolume(thin).valid);
    EXPECT_FALSE(aerial::fogVolumeContains(aerial::prepareFogVolume(thin), thin.position));
}

TEST(FogVolume, DegenerateVolumesAreNeverHit) {
    const double nan = std::nan("");
    const double inf = std::numeric_limits<double>::infinity();
    for (FogVolumeShape shape : {FogVolumeShape::Box, FogVolumeShape::Ellipsoid}) {
        for (const glm::dvec3& s : {glm::dvec3(0, 1, 1), glm::dvec3(1, -1, 1), glm::dvec3(1, 1, nan),
                                    glm::dvec3(inf, 1, 1), glm::dvec3(1e-300, 1, 1), glm::dvec3(0, 0, 0)}) {
            FogVolume v;
            v.shape = shape;
            v.halfExtents = s;
            const auto seg = aerial::intersectFogVolume(v, {-100, 0, 0}, {1, 0, 0}, 1000.0);
            EXPECT_FALSE(seg.hit);
            EXPECT_EQ(aerial::fogVolumeDensityAt(v, {0, 0, 0}), 0.0);
            glm::dvec3 lo;
            glm::dvec3 hi;
            aerial::fogVolumeBounds(v, lo, hi);
            EXPECT_TRUE(std::isfinite(lo.x + lo.y + lo.z + hi.x + hi.y + hi.z));
            // Even a hand-made segment gives no optical depth.
            aerial::VolumeSegment forced{true, 0.0, 200.0};
            EXPECT_EQ(aerial::fogVolumeOpticalDepth(v, {-100, 0, 0}, {1, 0, 0}, forced), 0.0);
        }
        // A zero or NaN rotation, a NaN position: never hit either.
        FogVolume v;
        v.shape = shape;
        v.rotation = glm::dquat(0, 0, 0, 0);
        EXPECT_FALSE(aerial::intersectFogVolume(v, {-100, 0, 0}, {1, 0, 0}, 1000.0).hit);
        v.rotation = glm::dquat(nan, 0, 0, 0);
        EXPECT_FALSE(aerial::intersectFogVolume(v, {-100, 0, 0}, {1, 0, 0}, 1000.0).hit);
        v.rotation = glm::dquat(1, 0, 0, 0);
        v.position = {nan, 0, 0};
        EXPECT_FALSE(aerial::intersectFogVolume(v, {-100, 0, 0}, {1, 0, 0}, 1000.0).hit);
    }
}

TEST(FogVolume, NonFiniteInputsGiveFiniteAnswers) {
    const double nan = std::nan("");
    const double inf = std::numeric_limits<double>::infinity();
    const double values[] = {nan, inf, -inf, 0.0, -0.0, 1e308, -1e308, 1e-310, 1.0, -3.0, 1e30};
    std::mt19937_64 rng(5);
    auto pick = [&]() { return values[rng() % std::size(values)]; };
    auto pickVec = [&]() {
        // Mostly ordinary numbers, so that hits happen, some edge values.
        auto one = [&]() {
            return rng() % 3 == 0 ? pick() : std::uniform_real_distribution<double>(-20, 20)(rng);
        };
        return glm::dvec3(one(), one(), one());
    };
    for (int i = 0; i < 20000; ++i) {
        FogVolume v;
        v.shape = (i % 2) ? FogVolumeShape::Box : FogVolumeShape::Ellipsoid;
        v.position = pickVec();
        v.halfExtents = glm::abs(pickVec());
        v.rotation = glm::dquat(pick(), pick(), pick(), pick());
        if (i % 3 == 0) {
            v.rotation = glm::dquat(1, 0, 0, 0);
        }
        v.density = rng() % 2 ? pick() : 0.05;
        v.falloff = rng() % 2 ? pick() : 0.1;
        v.gradientDirection = pickVec();
        v.gradientOffset = rng() % 2 ? pick() : 1.0;
        const glm::dvec3 o = pickVec();
        const glm::dvec3 d = pickVec();
        const double tMax = rng() % 2 ? pick() : 10.0;
        const auto seg = aerial::intersectFogVolume(v, o, d, tMax);
        ASSERT_TRUE(std::isfinite(seg.tIn) && std::isfinite(seg.tOut)) << i;
        const double tau = aerial::fogVolumeOpticalDepth(v, o, d, seg);
        ASSERT_TRUE(std::isfinite(tau) && tau >= 0.0 && tau <= kMaxOpticalDepth) << i;
        const double rho = aerial::fogVolumeDensityAt(v, o);
        ASSERT_TRUE(std::isfinite(rho) && rho >= 0.0) << i;
        glm::dvec3 lo;
        glm::dvec3 hi;
        aerial::fogVolumeBounds(v, lo, hi);
        ASSERT_TRUE(std::isfinite(lo.x + lo.y + lo.z + hi.x + hi.y + hi.z)) << i;
    }
}

}  // namespace

namespace {

/// Brute-force reference of a soft volume's optical depth: fogVolumeDensityAt
/// (the profile evaluated point by point) summed by composite 5-point
/// Gauss-Legendre over 20 000 sub-intervals of the reference chord. The
/// profile is only continuous (its slope jumps at the breakpoints), so a
/// sub-interval holding a kink converges as h^2 (about 1e-9 of the chord per
/// kink at this h) rather than to the rounding level.
double softReferenceOpticalDepth(const FogVolume& v, const glm::dvec3& origin, const glm::dvec3& direction,
                                 const ReferenceChord& chord) {
    if (!chord.hit) {
        return 0.0;
    }
    const double length = glm::length(direction);
    return aerial::test::gaussLegendre(
        [&](double t) { return aerial::fogVolumeDensityAt(v, origin + t * direction) * length; }, chord.t0,
        chord.t1, 20000);
}

}  // namespace

TEST(FogVolumeSoftEdge, KnownAnswersThroughTheCentre) {
    // Uniform density 1 [1/m], unit shapes, the ray along x through the
    // centre: the sphere with sigma = 1 has w = 1 - t^2, int_-1^1 = 4/3; the
    // box has w = 1 - |t| (the other two ramps are 1 at 0), int = 1; with
    // sigma = 0.5 the box ramp is 1 on [-0.5, 0.5] and linear outside: 1.5;
    // the sphere with sigma = 0.5: 1 inside radius 0.5, (1 - t^2) / 0.75
    // outside: 1 + 2 (2/3 - 0.5 + 0.125/3) / 0.75 = 14/9.
    FogVolume v;
    v.halfExtents = {1.0, 1.0, 1.0};
    v.density = 1.0;
    const glm::dvec3 from{-3.0, 0.0, 0.0};
    const glm::dvec3 delta{6.0, 0.0, 0.0};
    const struct {
        FogVolumeShape shape;
        double sigma;
        double expected;
    } cases[] = {{FogVolumeShape::Ellipsoid, 1.0, 4.0 / 3.0},
                 {FogVolumeShape::Box, 1.0, 1.0},
                 {FogVolumeShape::Box, 0.5, 1.5},
                 {FogVolumeShape::Ellipsoid, 0.5, 14.0 / 9.0}};
    for (const auto& c : cases) {
        v.shape = c.shape;
        v.edgeSoftness = c.sigma;
        const auto seg = aerial::intersectFogVolume(v, from, delta, 1.0);
        // 4 ulps: a handful of roundings in the moments and coefficients.
        EXPECT_NEAR(aerial::fogVolumeOpticalDepth(v, from, delta, seg), c.expected, 4e-16 * 4.0)
            << int(c.shape) << " sigma " << c.sigma;
    }
}

TEST(FogVolumeSoftEdge, ZeroSoftnessIsTheHardIntegralBitForBit) {
    // sigma = 0 (and a subtract volume's sigma) takes the hard formula:
    // the same double as exponentialOpticalDepth over the chord.
    VolumeCases r(5050);
    for (int i = 0; i < 200; ++i) {
        FogVolume v = r.volume(i);
        ReferenceGeometry geo(v);
        const Segment s = makeSegment(r, v, geo, i);
        const auto seg = aerial::intersectFogVolume(v, s.origin, s.direction, 1.0);
        if (!seg.hit) continue;
        // The hard formula from the prepared (sanitised) numbers, as the
        // library computed it before soft edges.
        const aerial::PreparedFogVolume p = aerial::prepareFogVolume(v);
        const double span = seg.tOut - seg.tIn;
        const double rate = glm::dot(s.direction, p.gradient);
        const double height = glm::dot(s.origin - p.position, p.gradient) + seg.tIn * rate - p.gradientOffset;
        const double hard = aerial::exponentialOpticalDepth(p.density, p.falloff, height, span * rate,
                                                            span * glm::length(s.direction));
        v.edgeSoftness = 0.0;
        EXPECT_EQ(aerial::fogVolumeOpticalDepth(v, s.origin, s.direction, seg), hard) << "case " << i;
        v.edgeSoftness = std::numeric_limits<double>::quiet_NaN();  // sanitised to 0
        EXPECT_EQ(aerial::fogVolumeOpticalDepth(v, s.origin, s.direction, seg), hard) << "case " << i;
    }
}

TEST(FogVolumeSoftEdge, MatchesBruteForceOverRandomisedVolumesAndRays) {
    // Softness 0, 0.3 and 1 on boxes and ellipsoids, the randomised volumes
    // and rays of the hard test. Tolerance 1e-7 relative (the reference's
    // h^2 kink error is <= ~1e-8, see softReferenceOpticalDepth; the closed
    // form is at the rounding level), absolute floor 1e-12.
    for (const double sigma : {0.0, 0.3, 1.0}) {
        VolumeCases r(777);
        double worst = 0.0;
        int hits = 0;
        for (int i = 0; i < 150; ++i) {
            FogVolume v = r.volume(i);
            v.edgeSoftness = sigma;
            ReferenceGeometry geo(v);
            const Segment s = makeSegment(r, v, geo, i);
            const ReferenceChord chord = referenceChord(geo, s.origin, s.direction, 1.0);
            const double reference = softReferenceOpticalDepth(v, s.origin, s.direction, chord);
            const auto seg = aerial::intersectFogVolume(v, s.origin, s.direction, 1.0);
            const double got = aerial::fogVolumeOpticalDepth(v, s.origin, s.direction, seg);
            hits += chord.hit ? 1 : 0;
            if (reference >= kMaxOpticalDepth) {
                EXPECT_EQ(got, kMaxOpticalDepth) << "case " << i;
                continue;
            }
            const double error = std::fabs(got - reference);
            EXPECT_LE(error, 1e-7 * reference + 1e-12)
                << "sigma " << sigma << " case " << i << " "
                << (v.shape == FogVolumeShape::Box ? "box" : "ellipsoid") << " " << s.kind
                << " c=" << v.falloff << " ref=" << reference << " got=" << got;
            if (reference > 1e-9) worst = std::max(worst, error / reference);
        }
        EXPECT_GE(hits, 100);
        std::printf(
            "[          ] soft fog volumes sigma %.1f: 150 cases (%d hits), worst relative error %.3g\n",
            sigma, hits, worst);
    }
}

TEST(FogVolumeSoftEdge, ProfileFallsToZeroAtTheSurface) {
    // Density at the surface is 0 with any softness > 0, full deeper than
    // 1 - sigma, and a subtract volume stays hard.
    FogVolume v;
    v.density = 0.5;
    v.halfExtents = {10.0, 4.0, 10.0};
    v.edgeSoftness = 0.25;
    for (const FogVolumeShape shape : {FogVolumeShape::Box, FogVolumeShape::Ellipsoid}) {
        v.shape = shape;
        v.blend = aerial::FogVolumeBlend::Add;
        EXPECT_EQ(aerial::fogVolumeDensityAt(v, {0.0, 4.0, 0.0}), 0.0);
        EXPECT_NEAR(aerial::fogVolumeDensityAt(v, {0.0, 3.5, 0.0}),
                    0.5 * (shape == FogVolumeShape::Box ? 0.5 : (1.0 - 0.875 * 0.875) / (1.0 - 0.75 * 0.75)),
                    1e-15);
        EXPECT_EQ(aerial::fogVolumeDensityAt(v, {0.0, 2.9, 0.0}), 0.5);
        v.blend = aerial::FogVolumeBlend::Subtract;
        EXPECT_EQ(aerial::fogVolumeDensityAt(v, {0.0, 3.99, 0.0}), 0.5);
    }
}
