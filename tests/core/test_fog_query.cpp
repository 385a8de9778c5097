// FogScene: the BVH-accelerated query against a brute-force reference (every
// volume through the public single-volume functions, sorted, composited as
// fog_query.hpp's contract says), known answers, and sanitising.
#include <aerial/atmosphere.hpp>
#include <aerial/emitter.hpp>
#include <aerial/fog_query.hpp>
#include <aerial/fog_volume.hpp>
#include <aerial/height_fog.hpp>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <new>
#include <random>
#include <vector>

// Counting global allocation functions (forwarding to malloc/free), so a
// test can assert that queries do not allocate. GCC cannot see that the
// replaced operator new pairs with free (-Wmismatched-new-delete).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif
namespace {
std::atomic<long> gAllocations{0};

void* countedAllocate(std::size_t size) noexcept {
    gAllocations.fetch_add(1, std::memory_order_relaxed);
    return std::malloc(size == 0 ? 1 : size);
}
void* countedAllocateOrThrow(std::size_t size) {
    if (void* p = countedAllocate(size)) {
        return p;
    }
    throw std::bad_alloc();
}
}  // namespace

// Every non-aligned form is replaced, so that no sanitizer runtime's own
// operator new ever pairs with this free (or the reverse).
void* operator new(std::size_t size) { return countedAllocateOrThrow(size); }
void* operator new[](std::size_t size) { return countedAllocateOrThrow(size); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept { return countedAllocate(size); }
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept { return countedAllocate(size); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

namespace {

using aerial::FogColourMode;
using aerial::FogQueryResult;
using aerial::FogScene;
using aerial::FogSceneDesc;
using aerial::FogVolume;
using aerial::FogVolumeShape;
using aerial::VolumeContribution;

// Phase functions written out from DESIGN.md ("Sky").
double referenceRayleighPhase(double mu) { return 3.0 / (16.0 * aerial::kPi) * (1.0 + mu * mu); }
double referenceMiePhase(double mu, double g) {
    return 3.0 / (8.0 * aerial::kPi) * (1.0 - g * g) * (1.0 + mu * mu) /
           ((2.0 + g * g) * std::pow(1.0 + g * g - 2.0 * g * mu, 1.5));
}

/// The far fog's colour: the lights' horizons (no horizon row here).
glm::dvec3 referenceHorizonColour(const FogSceneDesc& desc, const glm::dvec3& v) {
    glm::dvec3 colour(0.0);
    for (const aerial::FogLight& light : desc.lights) {
        const double mu = glm::dot(v, glm::normalize(light.direction));
        colour += light.illuminance * (referenceRayleighPhase(mu) * light.horizonRayleigh +
                                       referenceMiePhase(mu, desc.mieAnisotropy) * light.horizonMie);
    }
    return colour;
}

/// L_fog(v, s) of fog_light.hpp written out: the lit fog (the reaching
/// light through the phase, the sky's bands with the phase's mean cosine
/// 3 g (4 + g^2) / (5 (2 + g^2))) blended into the horizon by 1 - exp(-(s / D)^2).
glm::dvec3 referenceFogColour(const FogSceneDesc& desc, const glm::dvec3& v, double distance) {
    const double g = desc.mieAnisotropy;
    const double k1 = 3.0 * g * (4.0 + g * g) / (5.0 * (2.0 + g * g));
    glm::dvec3 lit(0.0);
    for (int c = 0; c < 3; ++c) {
        // The dipole, windowed to swing at most half the mean.
        const double ax = desc.skyLight.l1[0][c], ay = desc.skyLight.l1[1][c], az = desc.skyLight.l1[2][c];
        const double swing = std::abs(k1) * std::sqrt(ax * ax + ay * ay + az * az);
        const double bound = 0.5 * std::max(desc.skyLight.l0[c], 0.0);
        const double window = swing > bound ? bound / swing : 1.0;
        lit[c] = std::max(desc.skyLight.l0[c] + window * k1 * (ax * v.x + ay * v.y + az * v.z), 0.0);
    }
    for (const aerial::FogLight& light : desc.lights) {
        const double mu = glm::dot(v, glm::normalize(light.direction));
        lit += desc.directVisibility * light.reaching * referenceMiePhase(mu, g);
    }
    const double x = distance / desc.horizonDistance;
    const double w = 1.0 - std::exp(-x * x);
    return (1.0 - w) * lit + w * referenceHorizonColour(desc, v);
}

struct ReferenceResult {
    FogQueryResult result;
    std::vector<VolumeContribution> volumes;
};

/// The contract of fog_query.hpp, straightforwardly: no BVH, every volume
/// tested, hits sorted by entry distance (farthest first, ties by index),
/// composited L <- L T + C (1 - T); emitters added.
ReferenceResult referenceQuery(const FogSceneDesc& desc, const glm::dvec3& from, const glm::dvec3& to) {
    const glm::dvec3 delta = to - from;
    const double length = glm::length(delta);
    const glm::dvec3 view = length > 0.0 ? delta / length : glm::dvec3(0, 1, 0);
    const glm::dvec3 fogColour = referenceFogColour(desc, view, length);

    std::vector<VolumeContribution> hits;
    for (std::size_t i = 0; i < desc.volumes.size(); ++i) {
        const auto seg = aerial::intersectFogVolume(desc.volumes[i], from, delta, 1.0);
        if (seg.hit) {
            VolumeContribution c;
            c.volumeIndex = i;
            c.tIn = seg.tIn;
            c.tOut = seg.tOut;
            c.opticalDepth = aerial::fogVolumeOpticalDepth(desc.volumes[i], from, delta, seg);
            hits.push_back(c);
        }
    }
    std::stable_sort(hits.begin(), hits.end(), [](const auto& a, const auto& b) {
        return a.tIn > b.tIn;  // stable: equal entries keep ascending index
    });

    ReferenceResult ref;
    const double tauGlobal = aerial::heightFogOpticalDepth(desc.heightFog, from, delta);
    double transmittance = std::exp(-tauGlobal);
    glm::dvec3 inScatter = fogColour * (1.0 - std::exp(-tauGlobal));
    for (VolumeContribution& h : hits) {
        const FogVolume& v = desc.volumes[h.volumeIndex];
        glm::dvec3 colour = fogColour;
        if (v.colourMode == FogColourMode::Tinted) {
            colour = v.colour * fogColour;
        } else if (v.colourMode == FogColourMode::Custom) {
            colour = v.colour;
        }
        const double tv = std::exp(-h.opticalDepth);
        inScatter = inScatter * tv + colour * (1.0 - tv);
        transmittance *= tv;
        h.tIn *= length;
        h.tOut *= length;
        h.colour = colour;
    }
    glm::dvec3 emitted(0.0);
    for (const aerial::Emitter& e : desc.emitters) {
        emitted += aerial::emitterInScatter(e, from, delta, 1.0);
    }
    ref.result.transmittance = glm::dvec3(transmittance);
    ref.result.inScatter = inScatter + emitted;
    ref.result.globalOpticalDepth = tauGlobal;
    ref.result.emitterInScatter = emitted;
    ref.volumes = hits;
    return ref;
}

/// |a - b| <= tol max(1, |b|) per component.
::testing::AssertionResult near(const glm::dvec3& a, const glm::dvec3& b, double tol) {
    for (int i = 0; i < 3; ++i) {
        if (!(std::fabs(a[i] - b[i]) <= tol * std::max(1.0, std::fabs(b[i])))) {
            return ::testing::AssertionFailure() << "component " << i << ": " << a[i] << " vs " << b[i];
        }
    }
    return ::testing::AssertionSuccess();
}

class SceneMaker {
public:
    explicit SceneMaker(std::uint64_t seed) : rng_(seed) {}
    double unit() { return std::uniform_real_distribution<double>(0.0, 1.0)(rng_); }
    double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }
    double logUniform(double lo, double hi) {
        return std::exp(std::log(lo) + unit() * (std::log(hi) - std::log(lo)));
    }
    glm::dvec3 direction() {
        std::normal_distribution<double> n(0.0, 1.0);
        const glm::dvec3 v{n(rng_), n(rng_), n(rng_)};
        return v / glm::length(v);
    }

    /// Volumes scattered over a 2 km x 2 km area, with lights and emitters.
    FogSceneDesc scene(std::size_t volumeCount, std::size_t emitterCount) {
        FogSceneDesc desc;
        desc.heightFog = {logUniform(1e-5, 1e-3), logUniform(1e-4, 1e-2), uniform(-20, 50)};
        desc.mieAnisotropy = uniform(0.3, 0.9);
        desc.lights[0] = {glm::normalize(glm::dvec3(0.3, 0.5, -0.8)),
                          {3.0, 2.8, 2.5},
                          {0.02, 0.05, 0.12},
                          {0.04, 0.04, 0.04}};
        desc.lights[0].reaching = {2.0, 1.7, 1.2};
        desc.lights[1] = {glm::normalize(glm::dvec3(-0.5, 0.2, 0.6)),
                          {0.01, 0.01, 0.02},
                          {0.02, 0.05, 0.12},
                          {0.04, 0.04, 0.04}};
        desc.lights[1].reaching = {0.004, 0.004, 0.008};
        desc.skyLight.l0 = {0.03, 0.05, 0.09};
        desc.skyLight.l1[0] = {0.01, 0.012, 0.015};
        desc.skyLight.l1[1] = {0.02, 0.03, 0.06};
        desc.skyLight.l1[2] = {-0.01, -0.01, -0.02};
        desc.directVisibility = uniform(0.3, 1.0);
        desc.horizonDistance = uniform(500.0, 5000.0);
        std::normal_distribution<double> n(0.0, 1.0);
        for (std::size_t i = 0; i < volumeCount; ++i) {
            FogVolume v;
            v.shape = (unit() < 0.5) ? FogVolumeShape::Box : FogVolumeShape::Ellipsoid;
            v.position = {uniform(-1000, 1000), uniform(-10, 120), uniform(-1000, 1000)};
            v.halfExtents = {logUniform(10, 200), logUniform(3, 60), logUniform(10, 200)};
            v.rotation = glm::normalize(glm::dquat(n(rng_), n(rng_), n(rng_), n(rng_)));
            v.density = logUniform(1e-4, 5e-2);
            v.falloff = unit() < 0.3 ? 0.0 : logUniform(1e-4, 5e-2);
            v.gradientDirection = unit() < 0.5 ? glm::dvec3(0, 1, 0) : direction();
            v.gradientOffset = uniform(-10, 10);
            const double mode = unit();
            v.colourMode = mode < 0.4   ? FogColourMode::Sky
                           : mode < 0.7 ? FogColourMode::Tinted
                                        : FogColourMode::Custom;
            v.colour = {uniform(0, 2), uniform(0, 2), uniform(0, 2)};
            desc.volumes.push_back(v);
        }
        for (std::size_t i = 0; i < emitterCount; ++i) {
            aerial::Emitter e;
            e.position = {uniform(-1000, 1000), uniform(0, 50), uniform(-1000, 1000)};
            e.intensity = logUniform(1e-3, 1.0);
            e.attenuation = logUniform(1e-4, 1e-1);
            e.colour = {uniform(0, 1), uniform(0, 1), uniform(0, 1)};
            desc.emitters.push_back(e);
        }
        return desc;
    }

    /// A camera near the ground and an object somewhere in the area; some
    /// segments start inside a volume or end inside one.
    std::pair<glm::dvec3, glm::dvec3> segment(const FogSceneDesc& desc, int i) {
        glm::dvec3 from{uniform(-1000, 1000), uniform(0, 60), uniform(-1000, 1000)};
        glm::dvec3 to{uniform(-1000, 1000), uniform(0, 200), uniform(-1000, 1000)};
        if (!desc.volumes.empty() && i % 4 == 1) {
            from = desc.volumes[static_cast<std::size_t>(unit() * desc.volumes.size()) % desc.volumes.size()]
                       .position;
        }
        if (!desc.volumes.empty() && i % 4 == 2) {
            to = desc.volumes[static_cast<std::size_t>(unit() * desc.volumes.size()) % desc.volumes.size()]
                     .position;
        }
        return {from, to};
    }

private:
    std::mt19937_64 rng_;
};

void expectMatchesReference(const FogSceneDesc& desc, SceneMaker& maker, int queries, int* totalHits) {
    const FogScene scene(desc);
    std::vector<VolumeContribution> contributions;
    for (int q = 0; q < queries; ++q) {
        const auto [from, to] = maker.segment(desc, q);
        const ReferenceResult ref = referenceQuery(desc, from, to);
        const FogQueryResult got = scene.query(from, to);
        // Tolerance: 1e-12 relative (floor 1e-12 absolute); the arithmetic
        // is the same up to the order of independent operations.
        ASSERT_TRUE(near(got.transmittance, ref.result.transmittance, 1e-12)) << "query " << q;
        ASSERT_TRUE(near(got.inScatter, ref.result.inScatter, 1e-12)) << "query " << q;
        ASSERT_TRUE(near(got.emitterInScatter, ref.result.emitterInScatter, 1e-12)) << q;
        ASSERT_NEAR(got.globalOpticalDepth, ref.result.globalOpticalDepth, 1e-12) << q;

        const FogQueryResult listed = scene.query(from, to, contributions);
        ASSERT_EQ(listed.inScatter, got.inScatter);
        ASSERT_EQ(listed.transmittance, got.transmittance);
        ASSERT_EQ(contributions.size(), ref.volumes.size()) << "query " << q;
        for (std::size_t k = 0; k < contributions.size(); ++k) {
            const VolumeContribution& a = contributions[k];
            const VolumeContribution& b = ref.volumes[k];
            ASSERT_EQ(a.volumeIndex, b.volumeIndex) << "query " << q << " position " << k;
            ASSERT_NEAR(a.tIn, b.tIn, 1e-12 * std::max(1.0, b.tIn));
            ASSERT_NEAR(a.tOut, b.tOut, 1e-12 * std::max(1.0, b.tOut));
            ASSERT_NEAR(a.opticalDepth, b.opticalDepth, 1e-12 * std::max(1.0, b.opticalDepth));
            ASSERT_TRUE(near(a.colour, b.colour, 1e-12));
        }
        *totalHits += static_cast<int>(contributions.size());
    }
}

TEST(FogQuery, MatchesBruteForceReference1Volume) {
    SceneMaker maker(1);
    int hits = 0;
    for (int s = 0; s < 20; ++s) {
        expectMatchesReference(maker.scene(1, 1), maker, 200, &hits);
    }
    EXPECT_GT(hits, 200);
}

TEST(FogQuery, MatchesBruteForceReference16Volumes) {
    SceneMaker maker(16);
    int hits = 0;
    for (int s = 0; s < 10; ++s) {
        expectMatchesReference(maker.scene(16, 2), maker, 300, &hits);
    }
    EXPECT_GT(hits, 1000);
}

TEST(FogQuery, MatchesBruteForceReference256Volumes) {
    SceneMaker maker(256);
    int hits = 0;
    for (int s = 0; s < 3; ++s) {
        expectMatchesReference(maker.scene(256, 4), maker, 1000, &hits);
    }
    EXPECT_GT(hits, 3000);
}

TEST(FogQuery, ManyOverlappingVolumesSpillPastTheInlineBuffer) {
    // 150 nested volumes along one line: every query crosses all of them.
    SceneMaker maker(150);
    FogSceneDesc desc = maker.scene(0, 0);
    for (int i = 0; i < 150; ++i) {
        FogVolume v;
        v.shape = i % 2 ? FogVolumeShape::Box : FogVolumeShape::Ellipsoid;
        v.position = {maker.uniform(-5, 5), maker.uniform(-5, 5), maker.uniform(-5, 5)};
        v.halfExtents = {maker.uniform(20, 100), maker.uniform(20, 100), maker.uniform(20, 100)};
        v.density = 1e-3;
        v.colourMode = FogColourMode::Custom;
        v.colour = {maker.unit(), maker.unit(), maker.unit()};
        desc.volumes.push_back(v);
    }
    const FogScene scene(desc);
    std::vector<VolumeContribution> list;
    for (int q = 0; q < 50; ++q) {
        const glm::dvec3 from = maker.direction() * 300.0;
        const glm::dvec3 to = -from + maker.direction() * 3.0;
        const ReferenceResult ref = referenceQuery(desc, from, to);
        const FogQueryResult got = scene.query(from, to, list);
        EXPECT_EQ(list.size(), 150u);
        EXPECT_TRUE(near(got.inScatter, ref.result.inScatter, 1e-12));
        EXPECT_TRUE(near(got.transmittance, ref.result.transmittance, 1e-12));
        EXPECT_TRUE(near(scene.query(from, to).inScatter, ref.result.inScatter, 1e-12));
    }
}

TEST(FogQuery, BvhKeepsRaysThatRunAlongFacesAndEdges) {
    // Axis-aligned boxes on an integer grid, and axis-aligned segments that
    // lie exactly in their faces or along their edges (direction components
    // exactly 0, origins exactly on slab planes), some from far away: the
    // BVH must not prune what the exact object-space test accepts.
    FogSceneDesc desc;
    for (int i = 0; i < 64; ++i) {
        FogVolume v;
        v.position = {static_cast<double>((i % 8) * 10), static_cast<double>((i / 8) % 4) * 6.0,
                      static_cast<double>(i / 8) * 10.0};
        v.halfExtents = {2.0 + i % 3, 3.0, 2.0 + i % 2};
        v.shape = (i % 5 == 0) ? FogVolumeShape::Ellipsoid : FogVolumeShape::Box;
        v.density = 0.01;
        v.colourMode = FogColourMode::Custom;
        v.colour = {1.0, 0.5, 0.25};
        desc.volumes.push_back(v);
    }
    const FogScene scene(desc);
    std::vector<VolumeContribution> list;
    int hits = 0;
    for (int i = 0; i < 64; ++i) {
        const FogVolume& v = desc.volumes[static_cast<std::size_t>(i)];
        for (int axis = 0; axis < 3; ++axis) {
            for (double far : {50.0, 1e6}) {
                for (int corner = 0; corner < 4; ++corner) {
                    // A line along `axis` through a face (corner 0, 1) or an
                    // edge (corner 2, 3) of the box.
                    glm::dvec3 from = v.position;
                    const int a1 = (axis + 1) % 3;
                    const int a2 = (axis + 2) % 3;
                    from[a1] += (corner % 2 ? 1.0 : -1.0) * v.halfExtents[a1];
                    if (corner >= 2) {
                        from[a2] += v.halfExtents[a2];
                    }
                    glm::dvec3 to = from;
                    from[axis] -= far;
                    to[axis] += 7.0;
                    const ReferenceResult ref = referenceQuery(desc, from, to);
                    const FogQueryResult got = scene.query(from, to, list);
                    ASSERT_EQ(list.size(), ref.volumes.size()) << i << " " << axis << " " << corner;
                    for (std::size_t k = 0; k < list.size(); ++k) {
                        ASSERT_EQ(list[k].volumeIndex, ref.volumes[k].volumeIndex);
                    }
                    ASSERT_TRUE(near(got.inScatter, ref.result.inScatter, 1e-12));
                    hits += static_cast<int>(list.size());
                }
            }
        }
    }
    EXPECT_GT(hits, 200);  // face-lying rays do count as inside the slab
}

TEST(FogQuery, QueriesDoNotAllocate) {
    SceneMaker maker(31);
    const FogSceneDesc desc = maker.scene(256, 4);
    const FogScene scene(desc);
    std::vector<std::pair<glm::dvec3, glm::dvec3>> segments;
    for (int q = 0; q < 2000; ++q) {
        segments.push_back(maker.segment(desc, q));
    }
    std::vector<VolumeContribution> list;
    list.reserve(64);
    std::vector<aerial::FogSegment> batch(100);
    std::vector<FogQueryResult> results(100);
    double sink = 0.0;
    const long before = gAllocations.load();
    for (const auto& [from, to] : segments) {
        sink += scene.query(from, to).inScatter.x;
        sink += scene.query(from, to, list).inScatter.y;  // reuses the caller's capacity
    }
    scene.queryBatch(batch.data(), results.data(), batch.size());
    EXPECT_EQ(gAllocations.load() - before, 0);
    EXPECT_TRUE(std::isfinite(sink));
}

TEST(FogQuery, TiesCompositeByIndex) {
    // Two volumes the camera stands in: both enter at 0; the lower index is
    // composited first (behind).
    FogSceneDesc desc;
    FogVolume a;
    a.colourMode = FogColourMode::Custom;
    a.colour = {1, 0, 0};
    a.density = 0.1;
    FogVolume b = a;
    b.colour = {0, 0, 1};
    b.halfExtents = {5, 5, 5};
    desc.volumes = {a, b};
    const FogScene scene(desc);
    std::vector<VolumeContribution> list;
    const FogQueryResult r = scene.query({0, 0, 0}, {0, 0, 3}, list);
    ASSERT_EQ(list.size(), 2u);
    EXPECT_EQ(list[0].volumeIndex, 0u);
    EXPECT_EQ(list[1].volumeIndex, 1u);
    // Known answer: both have tau = 0.3; red first, then blue over it.
    const double t = std::exp(-0.3);
    EXPECT_NEAR(r.inScatter.x, (1 - t) * t, 1e-15);
    EXPECT_NEAR(r.inScatter.z, 1 - t, 1e-15);
    EXPECT_NEAR(r.transmittance.x, t * t, 1e-15);
}

TEST(FogQuery, WithoutVolumesEqualsGlobalFogAlone) {
    SceneMaker maker(7);
    FogSceneDesc desc = maker.scene(0, 0);
    desc.heightFog = {0.002, 0.003, 10.0};
    const FogScene scene(desc);
    for (int q = 0; q < 500; ++q) {
        const auto [from, to] = maker.segment(desc, q);
        const glm::dvec3 delta = to - from;
        const double tau = aerial::heightFogOpticalDepth(desc.heightFog, from, delta);
        const double t = std::exp(-tau);
        const glm::dvec3 colour = referenceFogColour(desc, glm::normalize(delta), glm::length(delta));
        const FogQueryResult r = scene.query(from, to);
        // 1e-12 relative: same formula, independent phase functions.
        EXPECT_TRUE(near(r.transmittance, glm::dvec3(t), 1e-12));
        EXPECT_TRUE(near(r.inScatter, colour * (1.0 - t), 1e-12));
        EXPECT_TRUE(near(scene.fogColour(delta, glm::length(delta)), colour, 1e-12));
        EXPECT_EQ(r.globalOpticalDepth, tau);
    }
}

TEST(FogQuery, GlobalFogColourModes) {
    SceneMaker maker(8);
    FogSceneDesc desc = maker.scene(0, 0);
    desc.heightFog = {0.002, 0.003, 10.0};
    const glm::dvec3 tint(0.9, 0.6, 0.3);
    for (FogColourMode mode : {FogColourMode::Sky, FogColourMode::Tinted, FogColourMode::Custom}) {
        desc.heightFogColourMode = mode;
        desc.heightFogColour = tint;
        const FogScene scene(desc);
        for (int q = 0; q < 100; ++q) {
            const auto [from, to] = maker.segment(desc, q);
            const glm::dvec3 delta = to - from;
            const double t = std::exp(-aerial::heightFogOpticalDepth(desc.heightFog, from, delta));
            const glm::dvec3 sky = referenceFogColour(desc, glm::normalize(delta), glm::length(delta));
            const glm::dvec3 colour = mode == FogColourMode::Sky      ? sky
                                      : mode == FogColourMode::Tinted ? tint * sky
                                                                      : tint;
            const FogQueryResult r = scene.query(from, to);
            EXPECT_TRUE(near(r.inScatter, colour * (1.0 - t), 1e-12)) << int(mode);
            EXPECT_TRUE(near(scene.fogColour(delta, glm::length(delta)), sky, 1e-12));  // always the sky's
            EXPECT_TRUE(
                near(scene.fogColour(delta), referenceHorizonColour(desc, glm::normalize(delta)), 1e-12));
        }
    }
}

TEST(FogQuery, ZeroDensityIsClearAir) {
    SceneMaker maker(8);
    FogSceneDesc desc = maker.scene(32, 0);
    desc.heightFog.density = 0.0;
    for (FogVolume& v : desc.volumes) {
        v.density = 0.0;
    }
    const FogScene scene(desc);
    for (int q = 0; q < 200; ++q) {
        const auto [from, to] = maker.segment(desc, q);
        const FogQueryResult r = scene.query(from, to);
        EXPECT_EQ(r.transmittance, glm::dvec3(1.0));
        EXPECT_EQ(r.inScatter, glm::dvec3(0.0));
    }
}

TEST(FogQuery, ZeroLengthSegmentAndEmittersAdd) {
    SceneMaker maker(9);
    const FogSceneDesc desc = maker.scene(16, 3);
    const FogScene scene(desc);
    const glm::dvec3 p = desc.volumes[0].position;
    const FogQueryResult r = scene.query(p, p);
    EXPECT_EQ(r.transmittance, glm::dvec3(1.0));
    EXPECT_EQ(r.inScatter, glm::dvec3(0.0));

    FogSceneDesc dark = desc;
    dark.emitters.clear();
    const FogScene withoutEmitters(dark);
    for (int q = 0; q < 100; ++q) {
        const auto [from, to] = maker.segment(desc, q);
        const FogQueryResult a = scene.query(from, to);
        const FogQueryResult b = withoutEmitters.query(from, to);
        glm::dvec3 emitted(0.0);
        for (const auto& e : desc.emitters) {
            emitted += aerial::emitterInScatter(e, from, to - from, 1.0);
        }
        EXPECT_TRUE(near(a.inScatter - b.inScatter, emitted, 1e-12));
        EXPECT_EQ(a.transmittance, b.transmittance);
    }
}

TEST(FogQuery, BatchEqualsSingleQueries) {
    SceneMaker maker(10);
    const FogSceneDesc desc = maker.scene(64, 2);
    FogScene scene(desc);
    std::vector<aerial::FogSegment> segments;
    for (int q = 0; q < 300; ++q) {
        const auto [from, to] = maker.segment(desc, q);
        segments.push_back({from, to});
    }
    std::vector<FogQueryResult> results(segments.size());
    scene.queryBatch(segments.data(), results.data(), segments.size());
    for (std::size_t q = 0; q < segments.size(); ++q) {
        const FogQueryResult single = scene.query(segments[q].from, segments[q].to);
        EXPECT_EQ(results[q].transmittance, single.transmittance);
        EXPECT_EQ(results[q].inScatter, single.inScatter);
        EXPECT_EQ(results[q].emitterInScatter, single.emitterInScatter);
    }
    // Moving the scene keeps it working.
    FogScene moved(std::move(scene));
    EXPECT_EQ(moved.query(segments[0].from, segments[0].to).inScatter, results[0].inScatter);
    EXPECT_EQ(moved.desc().volumes.size(), 64u);
}

TEST(FogQuery, NonFiniteAndDegenerateInputsGiveFiniteAnswers) {
    const double nan = std::nan("");
    const double inf = std::numeric_limits<double>::infinity();
    const double values[] = {nan, inf, -inf, 0.0, 1e308, -1e308, 1e-310, 1.0, -1.0, 1e30};
    std::mt19937_64 rng(12);
    auto pick = [&]() { return values[rng() % std::size(values)]; };
    auto maybe = [&](double ordinary) { return rng() % 4 == 0 ? pick() : ordinary; };
    auto vec = [&](double spread) {
        auto one = [&]() { return maybe(std::uniform_real_distribution<double>(-spread, spread)(rng)); };
        return glm::dvec3(one(), one(), one());
    };
    for (int s = 0; s < 40; ++s) {
        FogSceneDesc desc;
        desc.heightFog = {maybe(0.01), maybe(0.01), maybe(0.0)};
        desc.mieAnisotropy = maybe(0.8);
        for (auto& light : desc.lights) {
            light = {vec(1), glm::abs(vec(2)), glm::abs(vec(1)), glm::abs(vec(1))};
        }
        for (int i = 0; i < 40; ++i) {
            FogVolume v;
            v.shape = i % 2 ? FogVolumeShape::Box : FogVolumeShape::Ellipsoid;
            v.position = vec(50);
            v.halfExtents = glm::abs(vec(30));
            v.rotation =
                rng() % 3 ? glm::dquat(1, 0, 0, 0) : glm::dquat(maybe(1), maybe(0), maybe(0), maybe(0));
            v.density = maybe(0.05);
            v.falloff = maybe(0.01);
            v.gradientDirection = vec(1);
            v.gradientOffset = maybe(0.0);
            v.colourMode = static_cast<FogColourMode>(rng() % 3);
            v.colour = vec(2);
            desc.volumes.push_back(v);
        }
        for (int i = 0; i < 3; ++i) {
            aerial::Emitter e;
            e.position = vec(50);
            e.intensity = maybe(1.0);
            e.attenuation = maybe(0.01);
            e.colour = vec(1);
            desc.emitters.push_back(e);
        }
        const FogScene scene(desc);
        std::vector<VolumeContribution> list;
        for (int q = 0; q < 200; ++q) {
            const glm::dvec3 from = vec(80);
            const glm::dvec3 to = rng() % 5 == 0 ? from : vec(80);
            const FogQueryResult r = scene.query(from, to, list);
            for (int c = 0; c < 3; ++c) {
                ASSERT_TRUE(std::isfinite(r.transmittance[c]) && r.transmittance[c] >= 0.0 &&
                            r.transmittance[c] <= 1.0);
                ASSERT_TRUE(std::isfinite(r.inScatter[c]) && r.inScatter[c] >= 0.0);
                ASSERT_TRUE(std::isfinite(r.emitterInScatter[c]));
            }
            ASSERT_TRUE(std::isfinite(r.globalOpticalDepth));
            for (const auto& v : list) {
                ASSERT_TRUE(std::isfinite(v.tIn) && std::isfinite(v.tOut) && std::isfinite(v.opticalDepth));
            }
            const glm::dvec3 colour = scene.fogColour(vec(1));
            ASSERT_TRUE(std::isfinite(colour.x) && std::isfinite(colour.y) && std::isfinite(colour.z));
        }
    }
}

}  // namespace
