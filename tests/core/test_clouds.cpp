// test_clouds.cpp — the cloud layer of aerial/clouds.hpp against closed
// forms (the shell's geometry), an independent fine quadrature of the
// density (the reference march), and the properties the issue asks of the
// noise and the coverage (deterministic, tileable, monotonic, local).
#include <aerial/clouds.hpp>

#include "cloud_noise_fields.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

namespace {

constexpr double kRg = 6360000.0;

aerial::CloudParams overcastLayer() {
    aerial::CloudParams p;
    p.coverage = 0.6;
    p.bottomM = 1500.0;
    p.thicknessM = 2000.0;
    p.densityPerM = 0.02;
    p.type = 0.7;
    return p;
}

glm::dvec3 randomPointInLayer(std::mt19937_64& rng, const aerial::CloudParams& p) {
    std::uniform_real_distribution<double> xz(-30000.0, 30000.0), f(0.0, 1.0);
    const glm::dvec3 p0(xz(rng), 0.0, xz(rng));
    // Lift to the wanted height above the curved ground (height h at
    // horizontal position (x, z) is y = sqrt((Rg + h)^2 - x^2 - z^2) - Rg).
    const double h = p.bottomM + f(rng) * p.thicknessM;
    const double y = std::sqrt((kRg + h) * (kRg + h) - p0.x * p0.x - p0.z * p0.z) - kRg;
    return {p0.x, y, p0.z};
}

/// The optical depth by an independent fine trapezoid quadrature of the
/// density along [0, tEnd] (not the library's segments or step rule).
double fineOpticalDepth(const aerial::CloudField& f, const glm::dvec3& o, const glm::dvec3& d, double tEnd,
                        int n) {
    double sum = 0.0;
    const double dt = tEnd / n;
    for (int i = 0; i <= n; ++i) {
        const double w = (i == 0 || i == n) ? 0.5 : 1.0;
        sum += w * aerial::cloudDensityAt(f, o + d * (i * dt));
    }
    return sum * dt * glm::length(d);
}

TEST(CloudNoise, DeterministicWhateverTheThreadCountAndSeedDependent) {
    const aerial::CloudNoise one = aerial::generateCloudNoise(7, 1);
    const aerial::CloudNoise two = aerial::generateCloudNoise(7, 2);
    const aerial::CloudNoise five = aerial::generateCloudNoise(7, 5);
    ASSERT_EQ(one.shape.size(), std::size_t(128 * 128 * 128));
    ASSERT_EQ(one.detail.size(), std::size_t(32 * 32 * 32));
    EXPECT_EQ(0, std::memcmp(one.shape.data(), two.shape.data(), one.shape.size() * sizeof(float)));
    EXPECT_EQ(0, std::memcmp(one.shape.data(), five.shape.data(), one.shape.size() * sizeof(float)));
    EXPECT_EQ(0, std::memcmp(one.detail.data(), two.detail.data(), one.detail.size() * sizeof(float)));
    // The cached copy is the same noise.
    const auto cached = aerial::cloudNoise(7);
    EXPECT_EQ(0, std::memcmp(one.shape.data(), cached->shape.data(), one.shape.size() * sizeof(float)));
    EXPECT_EQ(cached.get(), aerial::cloudNoise(7).get());
    EXPECT_EQ(aerial::cloudNoiseFingerprint(one), aerial::cloudNoiseFingerprint(*cached));
    // Another seed is other noise: most texels differ.
    const auto other = aerial::cloudNoise(8);
    std::size_t same = 0;
    for (std::size_t i = 0; i < one.shape.size(); ++i) same += one.shape[i] == other->shape[i];
    EXPECT_LT(double(same) / double(one.shape.size()), 0.01);
    EXPECT_NE(aerial::cloudNoiseFingerprint(one), aerial::cloudNoiseFingerprint(*other));
    // The fingerprint sees a single flipped bit.
    aerial::CloudNoise flipped = one;
    flipped.detail[12345] = std::nextafter(flipped.detail[12345], 2.0f);
    EXPECT_NE(aerial::cloudNoiseFingerprint(one), aerial::cloudNoiseFingerprint(flipped));
}

TEST(CloudNoise, ValuesInUnitRangeAndShapeUniformSoCoverageMeansCoverage) {
    const auto noise = aerial::cloudNoise(1);
    for (float v : noise->shape) ASSERT_TRUE(v >= 0.0f && v <= 1.0f);
    for (float v : noise->detail) ASSERT_TRUE(v >= 0.0f && v <= 1.0f);
    // Equalised: the fraction of texels above 1 - c is c (to the histogram's
    // resolution), so coverage c covers a fraction c at the profile's peak.
    for (double c : {0.1, 0.3, 0.5, 0.8}) {
        std::size_t above = 0;
        for (float v : noise->shape) above += v > 1.0 - c;
        EXPECT_NEAR(double(above) / double(noise->shape.size()), c, 0.005) << "coverage " << c;
    }
}

TEST(CloudNoise, RowsAreTheFieldAtTheTexelCentres) {
    // generateCloudNoise fills the shape texture a row at a time
    // (shapeRow: each Worley octave's candidates set up once per run of
    // texels in a cell); every texel must be the field itself at the
    // texel's centre, shape() point by point, bit for bit, at any size, for
    // rows at the tile's borders and inside (runs cut at the cells and the
    // wrap).
    for (std::int64_t seed : {1LL, 11LL, -5LL}) {
        const aerial::detail::CloudNoiseFields fields(seed);
        for (int size : {128, 40, 7}) {
            std::vector<float> row(static_cast<std::size_t>(size));
            for (int j : {0, 1, size / 2, size - 1}) {
                for (int k : {0, size / 3, size - 1}) {
                    fields.shapeRow(j, k, size, row.data());
                    int differ = 0;
                    for (int i = 0; i < size; ++i) {
                        const float want = float(fields.shape((glm::dvec3(i, j, k) + 0.5) / double(size)));
                        differ += std::memcmp(&want, &row[std::size_t(i)], sizeof want) != 0;
                    }
                    EXPECT_EQ(differ, 0) << "seed " << seed << ", size " << size << ", row " << j << ", " << k;
                }
            }
        }
    }
}

TEST(CloudNoise, TilesSeamlesslyAtItsBorders) {
    // The fields the texels are sampled from have period 1 and are
    // continuous across the wrap: f(u + e_axis) = f(u), and f just below 1
    // meets f just above 0.
    const aerial::detail::CloudNoiseFields fields(1);
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    double worstPeriod = 0.0, worstSeam = 0.0, typicalStep = 0.0;
    for (int i = 0; i < 300; ++i) {
        const glm::dvec3 u(u01(rng), u01(rng), u01(rng));
        for (int axis = 0; axis < 3; ++axis) {
            glm::dvec3 e(0.0);
            e[axis] = 1.0;
            worstPeriod = std::max({worstPeriod, std::fabs(fields.shape(u + e) - fields.shape(u)),
                                    std::fabs(fields.detail(u - e) - fields.detail(u))});
            glm::dvec3 below = u, above = u;
            below[axis] = 1.0 - 1e-7;
            above[axis] = 1e-7;
            worstSeam = std::max({worstSeam, std::fabs(fields.shape(below) - fields.shape(above)),
                                  std::fabs(fields.detail(below) - fields.detail(above))});
            glm::dvec3 step = u;
            step[axis] += 1.0 / 128.0;
            typicalStep += std::fabs(fields.shape(step) - fields.shape(u)) / 900.0;
        }
    }
    EXPECT_LT(worstPeriod, 1e-9);
    EXPECT_LT(worstSeam, 1e-4);    // a step of 2e-7 of the tile
    EXPECT_GT(typicalStep, 1e-3);  // while one texel apart the field moves
    const auto noise = aerial::cloudNoise(1);
    constexpr int n = aerial::CloudNoise::kShapeSize;
    // Sampling wraps: uvw and uvw + integer give the same value.
    std::uniform_real_distribution<double> u(-2.0, 2.0);
    for (int i = 0; i < 200; ++i) {
        const glm::dvec3 p(u(rng), u(rng), u(rng));
        EXPECT_NEAR(aerial::sampleTileable(noise->shape, n, p),
                    aerial::sampleTileable(noise->shape, n, p + 3.0), 1e-6);
    }
}

TEST(CloudNoise, SampleIsTrilinearBetweenTexelCentres) {
    // A tiny 2^3 texture with known texels: the sample at a point between
    // centres is the trilinear blend, computed here by hand.
    const std::vector<float> t = {0, 1, 2, 3, 4, 5, 6, 7};  // value = i + 2j + 4k
    // Texel centres at 0.25 and 0.75; at (0.25 + 0.5 * 0.3, 0.25 + 0.5 * 0.6, 0.25) the blend is
    // 0.3 * 1 + 0.6 * 2 + 0 * 4 (the value is linear between centres).
    EXPECT_NEAR(aerial::sampleTileable(t, 2, {0.4, 0.55, 0.25}), 0.3 + 1.2, 1e-12);
    // Across the wrap: halfway between texel 1 (0.75) and texel 0 (1.25 = 0.25).
    EXPECT_NEAR(aerial::sampleTileable(t, 2, {1.0, 0.25, 0.25}), 0.5, 1e-12);
}

TEST(CloudProfile, ZeroAtTheLayersEdgesAndStratusStaysLow) {
    for (double type : {0.0, 0.5, 1.0}) {
        EXPECT_EQ(aerial::cloudHeightProfile(0.0, type), 0.0);
        EXPECT_EQ(aerial::cloudHeightProfile(1.0, type), 0.0);
        double peak = 0.0;
        for (int i = 1; i < 100; ++i) peak = std::max(peak, aerial::cloudHeightProfile(i / 100.0, type));
        EXPECT_NEAR(peak, 1.0, 0.05) << type;
    }
    EXPECT_EQ(aerial::cloudHeightProfile(0.35, 0.0), 0.0);  // stratus: top at 0.3 of the layer
    EXPECT_GT(aerial::cloudHeightProfile(0.8, 1.0), 0.1);   // cumulus towers
}

TEST(CloudLayer, SegmentsAreTheShellsClosedForms) {
    const aerial::CloudField f = aerial::prepareClouds(overcastLayer(), {}, 12.0, kRg);
    const double b = 1500.0, top = 3500.0;
    // Straight up from the ground: [bottom, top].
    aerial::CloudSegments s = aerial::cloudLayerSegments(f, {0, 0, 0}, {0, 1, 0});
    ASSERT_EQ(s.count, 1);
    EXPECT_NEAR(s.t0[0], b, 1e-6);
    EXPECT_NEAR(s.t1[0], top, 1e-6);
    // Horizontal from the ground: the chord to each sphere, sqrt((Rg+h)^2 - Rg^2).
    s = aerial::cloudLayerSegments(f, {0, 0, 0}, {1, 0, 0});
    ASSERT_EQ(s.count, 1);
    EXPECT_NEAR(s.t0[0], std::sqrt((kRg + b) * (kRg + b) - kRg * kRg), 1e-3);
    EXPECT_NEAR(s.t1[0], std::sqrt((kRg + top) * (kRg + top) - kRg * kRg), 1e-3);
    // From inside the layer, horizontally: out through the top.
    s = aerial::cloudLayerSegments(f, {0, 2000, 0}, {0, 0, 1});
    ASSERT_EQ(s.count, 1);
    EXPECT_NEAR(s.t0[0], 0.0, 0.0);
    EXPECT_NEAR(s.t1[0], std::sqrt((kRg + top) * (kRg + top) - (kRg + 2000) * (kRg + 2000)), 1e-3);
    // From above, straight down: through the layer to its base, the ground ends the rest.
    s = aerial::cloudLayerSegments(f, {0, 5000, 0}, {0, -1, 0});
    ASSERT_EQ(s.count, 1);
    EXPECT_NEAR(s.t0[0], 5000 - top, 1e-6);
    EXPECT_NEAR(s.t1[0], 5000 - b, 1e-6);
    // From above, grazing the inner sphere: in, out of the base, through the
    // hollow, in again and out: two segments.
    const glm::dvec3 graze = glm::normalize(glm::dvec3(1.0, -0.036, 0.0));
    s = aerial::cloudLayerSegments(f, {0, 5000, 0}, graze);
    ASSERT_EQ(s.count, 2);
    EXPECT_LT(s.t1[0], s.t0[1]);
    // tMax clips.
    s = aerial::cloudLayerSegments(f, {0, 0, 0}, {0, 1, 0}, 2000.0);
    ASSERT_EQ(s.count, 1);
    EXPECT_NEAR(s.t1[0], 2000.0, 1e-9);
    s = aerial::cloudLayerSegments(f, {0, 0, 0}, {0, 1, 0}, 1000.0);
    EXPECT_EQ(s.count, 0);
    // Down from the ground: nothing (the ground is not a cloud).
    EXPECT_EQ(aerial::cloudLayerSegments(f, {0, 10, 0}, {0, -1, 0}).count, 0);
}

TEST(CloudLayer, CoverageZeroGivesNoCloudAnywhere) {
    aerial::CloudParams p = overcastLayer();
    p.coverage = 0.0;
    const aerial::CloudField f = aerial::prepareClouds(p, {}, 9.0, kRg);
    EXPECT_FALSE(f.active());
    std::mt19937_64 rng(11);
    for (int i = 0; i < 2000; ++i) ASSERT_EQ(aerial::cloudDensityAt(f, randomPointInLayer(rng, p)), 0.0);
    EXPECT_EQ(aerial::cloudTransmittance(f, {0, 0, 0}, {0, 1, 0}), 1.0);
    // Even with the noise present (a volume elsewhere makes the field active).
    aerial::CloudVolume v;
    v.position = {1e6, 2500, 0};
    const aerial::CloudField g = aerial::prepareClouds(p, {&v, 1}, 9.0, kRg);
    ASSERT_TRUE(g.active());
    for (int i = 0; i < 2000; ++i) ASSERT_EQ(aerial::cloudDensityAt(g, randomPointInLayer(rng, p)), 0.0);
}

TEST(CloudLayer, MoreCoverageNeverGivesLessCloud) {
    std::mt19937_64 rng(5);
    aerial::CloudParams p = overcastLayer();
    std::vector<glm::dvec3> points;
    for (int i = 0; i < 3000; ++i) points.push_back(randomPointInLayer(rng, p));
    std::vector<double> previous(points.size(), 0.0);
    double previousMean = 0.0;
    for (double c = 0.05; c <= 1.0001; c += 0.05) {
        p.coverage = c;
        const aerial::CloudField f = aerial::prepareClouds(p, {}, 15.5, kRg);
        double mean = 0.0;
        for (std::size_t i = 0; i < points.size(); ++i) {
            const double d = aerial::cloudDensityAt(f, points[i]);
            ASSERT_GE(d, previous[i]) << "coverage " << c << " point " << i;
            previous[i] = d;
            mean += d;
        }
        EXPECT_GT(mean, previousMean) << c;
        previousMean = mean;
        EXPECT_LE(*std::max_element(previous.begin(), previous.end()), p.densityPerM);
    }
}

TEST(CloudLayer, WindDriftsTheNoise) {
    // At t the density at p equals the density at t = 0 at p - wind t.
    aerial::CloudParams p = overcastLayer();
    p.windMPerS = {12.0, -4.0};
    const aerial::CloudField f0 = aerial::prepareClouds(p, {}, 0.0, kRg);
    const aerial::CloudField f1 = aerial::prepareClouds(p, {}, 0.25, kRg);  // 900 s
    std::mt19937_64 rng(9);
    int nonZero = 0;
    for (int i = 0; i < 500; ++i) {
        const glm::dvec3 q = randomPointInLayer(rng, p);
        // Moving horizontally by (dx, dz) keeps the height only approximately on
        // the sphere; the noise uses h, so compare at the same h: the density at
        // (x + dx, h, z + dz) later equals the density at (x, h, z) now.
        const double h = aerial::cloudHeightAboveGround(q, kRg);
        const double x1 = q.x + 12.0 * 900.0, z1 = q.z - 4.0 * 900.0;
        const double y1 = std::sqrt((kRg + h) * (kRg + h) - x1 * x1 - z1 * z1) - kRg;
        const double now = aerial::cloudDensityAt(f0, q), later = aerial::cloudDensityAt(f1, {x1, y1, z1});
        EXPECT_NEAR(now, later, 1e-9 + 1e-6 * now);
        nonZero += now > 0.0;
    }
    EXPECT_GT(nonZero, 50);
}

TEST(CloudLayer, ReferenceMarchConvergesToAFineQuadrature) {
    const aerial::CloudField f = aerial::prepareClouds(overcastLayer(), {}, 14.0, kRg);
    std::mt19937_64 rng(21);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int cloudy = 0;
    for (int i = 0; i < 24; ++i) {
        // Steep rays up from the ground near the origin: one segment each.
        glm::dvec3 d = glm::normalize(glm::dvec3(0.4 * u(rng), 1.0, 0.4 * u(rng)));
        const glm::dvec3 o(3000.0 * u(rng), 0.0, 3000.0 * u(rng));
        const aerial::CloudSegments s = aerial::cloudLayerSegments(f, o, d);
        ASSERT_EQ(s.count, 1);
        const double ref = fineOpticalDepth(f, o, d, s.t1[0] + 10.0, 40000);
        const double march = aerial::cloudOpticalDepth(f, o, d);
        // Transmittance to 1e-3 (the GPU test's tolerance), optical depth to 1 %.
        EXPECT_NEAR(std::exp(-march), std::exp(-ref), 1e-3) << i;
        EXPECT_NEAR(march, ref, 0.01 * ref + 1e-6) << i;
        cloudy += ref > 0.1;
    }
    EXPECT_GT(cloudy, 4);  // the test saw clouds
}

TEST(CloudLayer, SunVisibilityIsTheTransmittanceTowardsTheSun) {
    aerial::CloudParams p = overcastLayer();
    p.coverage = 1.0;  // overcast: the sun is hidden everywhere
    const aerial::CloudField f = aerial::prepareClouds(p, {}, 10.0, kRg);
    const glm::dvec3 sun = glm::normalize(glm::dvec3(0.3, 0.8, 0.2));
    const double v = aerial::cloudSunVisibility(f, {100, 0, 200}, sun);
    const aerial::CloudSegments s = aerial::cloudLayerSegments(f, {100, 0, 200}, sun);
    const double ref = std::exp(-fineOpticalDepth(f, {100, 0, 200}, sun, s.t1[0] + 10.0, 40000));
    EXPECT_NEAR(v, ref, 2e-3);
    EXPECT_LT(v, 0.05);
    // Above the layer there is nothing between a point and the sun.
    EXPECT_EQ(aerial::cloudSunVisibility(f, {0, 4000, 0}, sun), 1.0);
    // Clear sky: full sun.
    p.coverage = 0.0;
    EXPECT_EQ(aerial::cloudSunVisibility(aerial::prepareClouds(p, {}, 10.0, kRg), {0, 0, 0}, sun), 1.0);
}

TEST(CloudVolumes, SetTheCoverageOnlyInsideTheirSoftBounds) {
    aerial::CloudParams p = overcastLayer();
    p.coverage = 0.2;
    aerial::CloudVolume storm;
    storm.shape = aerial::FogVolumeShape::Ellipsoid;
    storm.position = {5000, 2500, -3000};
    storm.rotation = glm::angleAxis(0.4, glm::dvec3(0, 1, 0));
    storm.halfExtents = {6000, 1500, 3000};
    storm.coverage = 1.0;
    storm.edgeSoftness = 0.4;
    aerial::CloudVolume hole;
    hole.shape = aerial::FogVolumeShape::Box;
    hole.position = {-8000, 2500, 4000};
    hole.halfExtents = {2000, 3000, 2000};
    hole.coverage = 0.0;
    hole.edgeSoftness = 0.0;
    const aerial::CloudVolume both[] = {storm, hole};
    const aerial::CloudField plain = aerial::prepareClouds(p, {}, 7.0, kRg);
    const aerial::CloudField shaped = aerial::prepareClouds(p, both, 7.0, kRg);
    std::mt19937_64 rng(17);
    int inside = 0, outside = 0;
    for (int i = 0; i < 20000; ++i) {
        const glm::dvec3 q = randomPointInLayer(rng, p);
        // The storm's object-space radius.
        const glm::dvec3 o = glm::inverse(storm.rotation) * (q - storm.position) / storm.halfExtents;
        const double r = glm::length(o);
        const bool inHole = std::fabs(q.x - hole.position.x) <= 2000 &&
                            std::fabs(q.z - hole.position.z) <= 2000 &&
                            std::fabs(q.y - hole.position.y) <= 3000;
        const double c = aerial::cloudCoverageAt(shaped, q);
        if (r >= 1.0 && !inHole) {
            ++outside;
            ASSERT_EQ(c, 0.2);
            ASSERT_EQ(aerial::cloudDensityAt(shaped, q), aerial::cloudDensityAt(plain, q));
        } else if (r <= 0.6) {
            ++inside;
            ASSERT_NEAR(c, 1.0, 1e-12);  // the core of the storm
        } else if (inHole) {
            ASSERT_EQ(c, 0.0);
            ASSERT_EQ(aerial::cloudDensityAt(shaped, q), 0.0);
        } else {
            ASSERT_GT(c, 0.2);  // the soft edge blends
            ASSERT_LT(c, 1.0);
        }
    }
    EXPECT_GT(inside, 40);
    EXPECT_GT(outside, 10000);
}

TEST(CloudLayer, BadInputGivesFiniteAnswers) {
    const aerial::CloudField f = aerial::prepareClouds(overcastLayer(), {}, 12.0, kRg);
    const double nan = std::numeric_limits<double>::quiet_NaN(),
                 inf = std::numeric_limits<double>::infinity();
    EXPECT_EQ(aerial::cloudDensityAt(f, {nan, 2000, 0}), 0.0);
    EXPECT_EQ(aerial::cloudTransmittance(f, {0, nan, 0}, {0, 1, 0}), 1.0);
    EXPECT_EQ(aerial::cloudTransmittance(f, {0, 0, 0}, {inf, 1, 0}), 1.0);
    EXPECT_EQ(aerial::cloudTransmittance(f, {0, 0, 0}, {0, 0, 0}), 1.0);
    EXPECT_EQ(aerial::cloudSunVisibility(f, {0, 0, 0}, {nan, nan, nan}), 1.0);
    aerial::CloudParams bad = overcastLayer();
    bad.coverage = nan;
    bad.thicknessM = -5.0;
    bad.shapeScaleM = inf;
    bad.windMPerS = {nan, 1.0};
    const aerial::CloudField g = aerial::prepareClouds(bad, {}, nan, nan);
    const double t = aerial::cloudTransmittance(g, {0, 0, 0}, {0.3, 1, 0});
    EXPECT_TRUE(std::isfinite(t));
    EXPECT_GE(t, 0.0);
    EXPECT_LE(t, 1.0);
}

}  // namespace
