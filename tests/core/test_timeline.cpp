// Timeline interpolation: known values for step / linear / smooth, the
// wrap through midnight, and the no-overshoot property of the monotone
// cubic over random keys.
#include <aerial/timeline.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace {

using aerial::CompiledTrack;
using aerial::Interpolation;
using aerial::Track;
using aerial::TrackKey;

Track scalarTrack(Interpolation interp, std::vector<std::pair<double, double>> keys) {
    Track t;
    t.interpolation = interp;
    for (auto [time, value] : keys) t.keys.push_back({time, glm::dvec3(value, 0.0, 0.0)});
    return t;
}

double at(const Track& t, double hours) { return aerial::evaluateTrack(t, hours, 1).x; }

TEST(Timeline, WrapHours) {
    EXPECT_DOUBLE_EQ(aerial::wrapHours(-1.0), 23.0);
    EXPECT_DOUBLE_EQ(aerial::wrapHours(24.0), 0.0);
    EXPECT_DOUBLE_EQ(aerial::wrapHours(48.5), 0.5);
    EXPECT_DOUBLE_EQ(aerial::wrapHours(std::nan("")), 0.0);
    EXPECT_DOUBLE_EQ(aerial::wrapHours(INFINITY), 0.0);
    // A tiny negative time must not wrap to 24 (outside [0, 24)).
    EXPECT_LT(aerial::wrapHours(-1e-300), 24.0);
}

TEST(Timeline, SingleKeyIsConstant) {
    const Track t = scalarTrack(Interpolation::Smooth, {{7.0, 0.25}});
    for (double h : {0.0, 6.9, 7.0, 13.0, 23.99}) EXPECT_EQ(at(t, h), 0.25) << h;
}

TEST(Timeline, StepKnownValues) {
    const Track t = scalarTrack(Interpolation::Step, {{6.0, 1.0}, {12.0, 2.0}, {18.0, 3.0}});
    EXPECT_EQ(at(t, 6.0), 1.0);
    EXPECT_EQ(at(t, 11.999), 1.0);
    EXPECT_EQ(at(t, 12.0), 2.0);
    EXPECT_EQ(at(t, 17.5), 2.0);
    EXPECT_EQ(at(t, 23.0), 3.0);
    // Before the first key the day wraps: the last key still holds.
    EXPECT_EQ(at(t, 0.0), 3.0);
    EXPECT_EQ(at(t, 5.99), 3.0);
}

TEST(Timeline, LinearKnownValues) {
    const Track t = scalarTrack(Interpolation::Linear, {{6.0, 0.0}, {12.0, 6.0}, {18.0, 0.0}});
    EXPECT_NEAR(at(t, 9.0), 3.0, 1e-12);
    EXPECT_NEAR(at(t, 13.5), 4.5, 1e-12);
    // 18:00 -> 06:00 next day is flat at 0.
    EXPECT_NEAR(at(t, 23.0), 0.0, 1e-12);
    EXPECT_NEAR(at(t, 2.0), 0.0, 1e-12);
}

TEST(Timeline, LinearWrapsThroughMidnight) {
    // Keys at 02:00 (4) and 22:00 (0): the 4-hour segment crosses midnight.
    const Track t = scalarTrack(Interpolation::Linear, {{2.0, 4.0}, {22.0, 0.0}});
    EXPECT_NEAR(at(t, 23.0), 1.0, 1e-12);
    EXPECT_NEAR(at(t, 0.0), 2.0, 1e-12);
    EXPECT_NEAR(at(t, 1.0), 3.0, 1e-12);
    EXPECT_NEAR(at(t, 24.0 + 1.0), 3.0, 1e-12);  // t wraps
    // The long segment 02:00 -> 22:00 goes down linearly.
    EXPECT_NEAR(at(t, 12.0), 2.0, 1e-12);
}

TEST(Timeline, SmoothWrapsThroughMidnight) {
    // Symmetric about midnight: the value at 00:00 is the mean of the keys,
    // and the curve is continuous across 24 -> 0.
    const Track t = scalarTrack(Interpolation::Smooth, {{2.0, 4.0}, {12.0, 10.0}, {22.0, 0.0}});
    const double before = at(t, 24.0 - 1e-9);
    const double after = at(t, 0.0);
    EXPECT_NEAR(before, after, 1e-8);
    EXPECT_GT(at(t, 0.0), 0.0);
    EXPECT_LT(at(t, 0.0), 4.0);
}

TEST(Timeline, SmoothZeroTangentsAtExtrema) {
    // Alternating keys: every key is an extremum, so every tangent is 0 and
    // each segment is the Hermite basis h01(s) = 3 s^2 - 2 s^3.
    const Track t = scalarTrack(Interpolation::Smooth, {{0.0, 0.0}, {6.0, 1.0}, {12.0, 0.0}, {18.0, 1.0}});
    EXPECT_NEAR(at(t, 3.0), 0.5, 1e-15);
    EXPECT_NEAR(at(t, 1.5), 5.0 / 32.0, 1e-15);
    EXPECT_NEAR(at(t, 22.5), 5.0 / 32.0, 1e-15);  // 18 -> 24 (= 0), s = 3/4: 1 - h01(3/4)
    for (double h : {0.0, 6.0, 12.0, 18.0}) EXPECT_EQ(at(t, h), std::fmod(h, 12.0) == 0.0 ? 0.0 : 1.0);
}

TEST(Timeline, SmoothDensityNeverNegative) {
    // The design's example: 0 -> 0.01 -> 0 must never dip below 0.
    const Track t = scalarTrack(Interpolation::Smooth, {{5.0, 0.0}, {7.0, 0.01}, {8.0, 0.002}, {12.0, 0.0}});
    for (int i = 0; i < 24 * 600; ++i) {
        const double v = at(t, i / 600.0);
        ASSERT_GE(v, 0.0) << "t = " << i / 600.0;
        ASSERT_LE(v, 0.01) << "t = " << i / 600.0;
    }
    // Flat between 12:00 and 05:00 (keys equal there).
    EXPECT_EQ(at(t, 15.0), 0.0);
    EXPECT_EQ(at(t, 2.0), 0.0);
}

TEST(Timeline, SmoothIsMonotoneOnMonotoneData) {
    // Steep then flat: a plain Catmull-Rom would overshoot past 1 after 6:00.
    const Track t = scalarTrack(Interpolation::Smooth, {{5.0, 0.0}, {6.0, 1.0}, {12.0, 1.02}, {20.0, 1.03}});
    double previous = at(t, 5.0);
    for (int i = 1; i <= 15 * 100; ++i) {
        const double v = at(t, 5.0 + i / 100.0);
        ASSERT_GE(v, previous - 1e-15) << 5.0 + i / 100.0;
        previous = v;
    }
}

TEST(Timeline, SmoothNeverOvershootsRandomKeys) {
    std::mt19937 rng(12345);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 500; ++trial) {
        const int n = 2 + int(unit(rng) * 9);
        std::vector<double> times;
        while (int(times.size()) < n) {
            const double t = std::floor(unit(rng) * 24.0 * 64.0) / 64.0;  // 1/64 h grid
            if (std::find(times.begin(), times.end(), t) == times.end()) times.push_back(t);
        }
        std::sort(times.begin(), times.end());
        Track track;
        track.interpolation = Interpolation::Smooth;
        for (double t : times) {
            // Mix of zeros (densities), repeated values and spread values.
            const double r = unit(rng);
            const double v = r < 0.25 ? 0.0 : r < 0.35 ? 1.0 : std::pow(10.0, -6.0 + 6.0 * unit(rng));
            track.keys.push_back({t, glm::dvec3(v, -v, 1.0 - v)});
        }
        const CompiledTrack c = aerial::compileTrack(track, 3);
        for (int k = 0; k < n; ++k) {
            const TrackKey& a = track.keys[std::size_t(k)];
            const TrackKey& b = track.keys[std::size_t((k + 1) % n)];
            const double t0 = a.timeHours;
            const double t1 = k + 1 < n ? b.timeHours : b.timeHours + 24.0;
            for (int s = 0; s <= 64; ++s) {
                const double t = t0 + (t1 - t0) * s / 64.0;
                const glm::dvec3 v = aerial::evaluateTrack(c, t);
                for (int ch = 0; ch < 3; ++ch) {
                    const double lo = std::min(a.value[ch], b.value[ch]);
                    const double hi = std::max(a.value[ch], b.value[ch]);
                    ASSERT_GE(v[ch], lo) << "trial " << trial << " segment " << k << " t " << t;
                    ASSERT_LE(v[ch], hi) << "trial " << trial << " segment " << k << " t " << t;
                }
            }
        }
    }
}

TEST(Timeline, SmoothInterpolatesKeysAndIsContinuous) {
    const Track t =
        scalarTrack(Interpolation::Smooth, {{1.0, 0.3}, {4.5, 0.9}, {9.0, 0.1}, {13.0, 0.4}, {20.0, 0.35}});
    for (const TrackKey& k : t.keys) EXPECT_EQ(at(t, k.timeHours), k.value.x);
    // C1: left and right difference quotients agree at every key.
    const double h = 1e-6;
    for (const TrackKey& k : t.keys) {
        const double left = (at(t, k.timeHours) - at(t, k.timeHours - h)) / h;
        const double right = (at(t, k.timeHours + h) - at(t, k.timeHours)) / h;
        EXPECT_NEAR(left, right, 1e-4) << k.timeHours;
    }
}

TEST(Timeline, ColoursInterpolatePerChannelInLinearRgb) {
    Track t;
    t.interpolation = Interpolation::Linear;
    t.keys = {{6.0, glm::dvec3(1.0, 0.5, 0.0)}, {8.0, glm::dvec3(0.0, 0.5, 1.0)}};
    const glm::dvec3 mid = aerial::evaluateTrack(t, 7.0);
    // Linear RGB average, not an sRGB-encoded or hue interpolation.
    EXPECT_NEAR(mid.x, 0.5, 1e-15);
    EXPECT_NEAR(mid.y, 0.5, 1e-15);
    EXPECT_NEAR(mid.z, 0.5, 1e-15);
}

TEST(Timeline, ScalarTracksIgnoreUnusedComponents) {
    Track t;
    t.interpolation = Interpolation::Linear;
    t.keys = {{6.0, glm::dvec3(1.0, 5.0, 5.0)}, {8.0, glm::dvec3(3.0, 5.0, 5.0)}};
    const glm::dvec3 v = aerial::evaluateTrack(t, 7.0, 1);
    EXPECT_NEAR(v.x, 2.0, 1e-15);
    EXPECT_EQ(v.y, 0.0);
    EXPECT_EQ(v.z, 0.0);
}

TEST(Timeline, Vec2TracksInterpolatePerComponentAndZeroZ) {
    // A horizontal 2-vector [x, z] (ParamType::Vec2) keyed in value.x, .y;
    // a stray .z in the keys must not leak through.
    Track t;
    t.interpolation = Interpolation::Linear;
    t.keys = {{6.0, glm::dvec3(2.0, -4.0, 9.0)}, {8.0, glm::dvec3(4.0, 0.0, 9.0)}};
    const CompiledTrack c = aerial::compileTrack(t, 2);
    EXPECT_EQ(c.components, 2);
    for (const glm::dvec3& v : c.values) EXPECT_EQ(v.z, 0.0);
    const glm::dvec3 mid = aerial::evaluateTrack(c, 7.0);
    EXPECT_NEAR(mid.x, 3.0, 1e-15);
    EXPECT_NEAR(mid.y, -2.0, 1e-15);
    EXPECT_EQ(mid.z, 0.0);

    // Smooth: each component hits its keys, stays within each segment's
    // keys (monotone), and z stays 0 everywhere.
    t.interpolation = Interpolation::Smooth;
    t.keys = {{3.0, glm::dvec3(1.0, 5.0, 0.0)},
              {9.0, glm::dvec3(6.0, -5.0, 0.0)},
              {15.0, glm::dvec3(2.0, 0.5, 0.0)},
              {21.0, glm::dvec3(-3.0, 1.0, 0.0)}};
    const CompiledTrack s = aerial::compileTrack(t, 2);
    EXPECT_EQ(s.components, 2);
    ASSERT_EQ(s.tangents.size(), 4u);
    for (const glm::dvec3& m : s.tangents) EXPECT_EQ(m.z, 0.0);
    for (const TrackKey& k : t.keys) {
        const glm::dvec3 v = aerial::evaluateTrack(s, k.timeHours);
        EXPECT_EQ(v.x, k.value.x) << k.timeHours;
        EXPECT_EQ(v.y, k.value.y) << k.timeHours;
    }
    for (int i = 0; i < 4; ++i) {
        const TrackKey& a = t.keys[std::size_t(i)];
        const TrackKey& b = t.keys[std::size_t((i + 1) % 4)];
        for (int step = 0; step <= 24; ++step) {
            const double time = a.timeHours + 6.0 * step / 24.0;
            const glm::dvec3 v = aerial::evaluateTrack(s, time);
            for (int ch = 0; ch < 2; ++ch) {
                EXPECT_GE(v[ch], std::min(a.value[ch], b.value[ch])) << time;
                EXPECT_LE(v[ch], std::max(a.value[ch], b.value[ch])) << time;
            }
            EXPECT_EQ(v.z, 0.0) << time;
        }
    }
    // The same keys as a 3-component track give the same x and y.
    const CompiledTrack three = aerial::compileTrack(t, 3);
    for (double time : {0.5, 4.0, 11.25, 17.0, 23.5}) {
        const glm::dvec3 v2 = aerial::evaluateTrack(s, time);
        const glm::dvec3 v3 = aerial::evaluateTrack(three, time);
        EXPECT_EQ(v2.x, v3.x) << time;
        EXPECT_EQ(v2.y, v3.y) << time;
    }
}

TEST(Timeline, SetKeyKeepsKeysOrdered) {
    Track t;
    aerial::setKey(t, 12.0, glm::dvec3(1.0));
    aerial::setKey(t, 6.0, glm::dvec3(2.0));
    aerial::setKey(t, 25.0, glm::dvec3(3.0));  // wraps to 01:00
    aerial::setKey(t, 12.0, glm::dvec3(4.0));  // replaces
    ASSERT_EQ(t.keys.size(), 3u);
    EXPECT_EQ(t.keys[0].timeHours, 1.0);
    EXPECT_EQ(t.keys[1].timeHours, 6.0);
    EXPECT_EQ(t.keys[2].timeHours, 12.0);
    EXPECT_EQ(t.keys[2].value, glm::dvec3(4.0));
}

TEST(Timeline, HeldTracksKeepTheirEndValuesInsteadOfWrapping) {
    // A morning mist keyed 06 / 08 / 10 h: cyclic, the night runs from the
    // 10 h value back to the 06 h one (the mist returns before dawn); held,
    // it is the 06 h value until 06 h and the 10 h value after 10 h.
    Track t;
    aerial::setKey(t, 6.0, glm::dvec3(0.02));
    aerial::setKey(t, 8.0, glm::dvec3(0.01));
    aerial::setKey(t, 10.0, glm::dvec3(0.0));
    for (Interpolation interpolation : {Interpolation::Step, Interpolation::Linear, Interpolation::Smooth}) {
        t.interpolation = interpolation;
        t.wrap = true;
        const CompiledTrack cyclic = aerial::compileTrack(t, 1);
        if (interpolation != Interpolation::Step) {  // wraps back up towards the 06 h value
            EXPECT_GT(aerial::evaluateTrack(cyclic, 4.0).x, 0.0) << int(interpolation);
        }
        t.wrap = false;
        const CompiledTrack held = aerial::compileTrack(t, 1);
        for (double time : {0.0, 3.0, 5.99})
            EXPECT_EQ(aerial::evaluateTrack(held, time).x, 0.02) << time << " " << int(interpolation);
        for (double time : {10.0, 15.0, 23.99})
            EXPECT_EQ(aerial::evaluateTrack(held, time).x, 0.0) << time << " " << int(interpolation);
        // Between the keys: exactly the keys at the keys, monotone between them.
        EXPECT_EQ(aerial::evaluateTrack(held, 8.0).x, 0.01);
        double previous = 1.0;
        for (double time = 6.0; time <= 10.0; time += 0.05) {
            const double v = aerial::evaluateTrack(held, time).x;
            EXPECT_LE(v, previous + 1e-15) << time;
            EXPECT_GE(v, 0.0);
            previous = v;
        }
    }
    // Smooth and held: flat where it meets the held values (zero end tangents).
    t.interpolation = Interpolation::Smooth;
    const CompiledTrack held = aerial::compileTrack(t, 1);
    const double e = 1e-4;
    EXPECT_NEAR((aerial::evaluateTrack(held, 6.0 + e).x - 0.02) / e, 0.0, 1e-3);
    EXPECT_NEAR((aerial::evaluateTrack(held, 10.0 - e).x - 0.0) / e, 0.0, 1e-3);
}

TEST(Timeline, FlatKeysHaveLevelTangentsClosedForm) {
    // Keys 0 / 8 / 16 h at 0 / 1 / 2, cyclic. On the segment 0..8 h
    // (s = t / 8): the 0 h key is an extremum (secants -2/8 and 1/8), so its
    // tangent is 0; the 8 h key's is the mean of its secants, 1/8 per h. The
    // Hermite form with h = 8 is then v = h01(s) + h11(s) * 8 * (1/8)
    // = 3s^2 - 2s^3 + s^3 - s^2 = 2s^2 - s^3. Flat at 8 h, the tangent is 0
    // and the segment is the smoothstep 3s^2 - 2s^3.
    Track t = scalarTrack(Interpolation::Smooth, {{0.0, 0.0}, {8.0, 1.0}, {16.0, 2.0}});
    for (double s = 0.0; s <= 1.0; s += 1.0 / 64.0)
        EXPECT_NEAR(at(t, 8.0 * s), 2.0 * s * s - s * s * s, 1e-12) << s;
    t.keys[1].flat = true;
    for (double s = 0.0; s <= 1.0; s += 1.0 / 64.0) {
        EXPECT_NEAR(at(t, 8.0 * s), 3.0 * s * s - 2.0 * s * s * s, 1e-12) << s;
        // The next segment (8..16 h) starts level too: 1 + smoothstep.
        EXPECT_NEAR(at(t, 8.0 + 8.0 * s), 1.0 + 3.0 * s * s - 2.0 * s * s * s, 1e-12) << s;
    }
    const double e = 1e-6;
    EXPECT_NEAR((at(t, 8.0 + e) - at(t, 8.0 - e)) / (2.0 * e), 0.0, 1e-6);
    // Every component of a vector key levels out.
    Track v;
    v.interpolation = Interpolation::Smooth;
    v.keys = {{0.0, glm::dvec3(0.0, 0.0, 0.0)},
              {8.0, glm::dvec3(1.0, 2.0, 3.0), true},
              {16.0, glm::dvec3(2.0, 4.0, 6.0)}};
    const aerial::CompiledTrack cv = aerial::compileTrack(v, 3);
    EXPECT_EQ(cv.tangents[1], glm::dvec3(0.0));
    for (double s = 0.0; s <= 1.0; s += 1.0 / 16.0)
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(aerial::evaluateTrack(cv, 8.0 * s)[c], (c + 1.0) * (3.0 * s * s - 2.0 * s * s * s),
                        1e-12);
    // Step and linear ignore it.
    for (Interpolation interpolation : {Interpolation::Step, Interpolation::Linear}) {
        Track a = scalarTrack(interpolation, {{0.0, 0.0}, {8.0, 1.0}, {16.0, 2.0}});
        Track b = a;
        b.keys[1].flat = true;
        for (double time = 0.0; time < 24.0; time += 0.25) EXPECT_EQ(at(a, time), at(b, time)) << time;
    }
}

TEST(Timeline, FlatKeysOnHeldTracksClosedForm) {
    // Held keys 6 / 12 / 18 h at 0 / 1 / 2: the ends have tangent 0, the
    // 12 h key 1/6 per h, so on 6..12 h (s = (t - 6) / 6) v = 2s^2 - s^3;
    // flat at 12 h it is 3s^2 - 2s^3, and the held values do not change.
    Track t = scalarTrack(Interpolation::Smooth, {{6.0, 0.0}, {12.0, 1.0}, {18.0, 2.0}});
    t.wrap = false;
    for (double s = 0.0; s <= 1.0; s += 1.0 / 64.0)
        EXPECT_NEAR(at(t, 6.0 + 6.0 * s), 2.0 * s * s - s * s * s, 1e-12) << s;
    t.keys[1].flat = true;
    for (double s = 0.0; s <= 1.0; s += 1.0 / 64.0)
        EXPECT_NEAR(at(t, 6.0 + 6.0 * s), 3.0 * s * s - 2.0 * s * s * s, 1e-12) << s;
    EXPECT_EQ(at(t, 3.0), 0.0);
    EXPECT_EQ(at(t, 21.0), 2.0);
    // setKey keeps a key's flag when it replaces the value.
    aerial::setKey(t, 12.0, glm::dvec3(1.5));
    EXPECT_TRUE(t.keys[1].flat);
}

}  // namespace

// A key's own interpolation (TrackKey::interpolation) governs the segment
// after it: in a smooth track, a key marked step holds its value to the next
// key and one marked linear ramps straight to it; the other segments are the
// track's smooth curve, with the tangents of the whole track as before.
TEST(Timeline, AKeysInterpolationGovernsTheSegmentAfterIt) {
    aerial::Track track;
    track.interpolation = aerial::Interpolation::Smooth;
    track.keys = {
        {2.0, glm::dvec3(0.0)}, {6.0, glm::dvec3(1.0)}, {10.0, glm::dvec3(3.0)}, {14.0, glm::dvec3(4.0)}};
    const aerial::CompiledTrack smooth = aerial::compileTrack(track, 1);
    track.keys[1].interpolation = aerial::Interpolation::Step;
    track.keys[2].interpolation = aerial::Interpolation::Linear;
    const aerial::CompiledTrack mixed = aerial::compileTrack(track, 1);
    for (double t = 6.0; t < 10.0; t += 0.25) EXPECT_EQ(aerial::evaluateTrack(mixed, t).x, 1.0) << t;
    for (double t = 10.0; t <= 14.0; t += 0.25)
        EXPECT_NEAR(aerial::evaluateTrack(mixed, t).x, 3.0 + (t - 10.0) / 4.0, 1e-12);
    // The segments without an override are unchanged, the wrap through midnight included.
    for (double t : {2.5, 4.0, 5.9, 15.0, 20.0, 1.0})
        EXPECT_EQ(aerial::evaluateTrack(mixed, t).x, aerial::evaluateTrack(smooth, t).x) << t;
    // A linear track with one smooth segment gets tangents for it.
    track.interpolation = aerial::Interpolation::Linear;
    track.keys[1].interpolation.reset();
    track.keys[2].interpolation.reset();
    track.keys[0].interpolation = aerial::Interpolation::Smooth;
    const aerial::CompiledTrack oneSmooth = aerial::compileTrack(track, 1);
    EXPECT_EQ(oneSmooth.tangents.size(), 4u);
    EXPECT_EQ(aerial::evaluateTrack(oneSmooth, 4.0).x, aerial::evaluateTrack(smooth, 4.0).x);
    EXPECT_NEAR(aerial::evaluateTrack(oneSmooth, 8.0).x, 2.0, 1e-12);  // linear 6 -> 10
}

// A key's own tangents (TrackKey::tangents) are the slopes of the Hermite
// segments at the key: keys 0 / 8 / 16 h at 0 / 1 / 2, cyclic, smooth. The
// 0 h and 16 h keys are extrema (tangent 0). With broken slopes at 8 h,
// in 0.5 and out -0.25 per h, h = 8 and s the segment's fraction:
//   0..8 h:  v = h01(s) + h11(s) * 8 * 0.5 = 3s^2 - 2s^3 + 4(s^3 - s^2)
//              = 2s^3 - s^2 (below 0 near the start: the artist's overshoot)
//   8..16 h: v = h00(s) + h10(s) * 8 * (-0.25) + 2 h01(s)
//              = -4s^3 + 7s^2 - 2s + 1
// and the segment 16..24 h, which does not touch the key, is unchanged.
TEST(Timeline, KeyTangentsAreTheHermiteSlopesClosedForm) {
    using aerial::Interpolation;
    aerial::Track track;
    track.interpolation = Interpolation::Smooth;
    track.keys = {{0.0, glm::dvec3(0.0)}, {8.0, glm::dvec3(1.0)}, {16.0, glm::dvec3(2.0)}};
    const aerial::CompiledTrack automatic = aerial::compileTrack(track, 1);
    EXPECT_EQ(aerial::automaticTangent(track, 1, 1).x, 1.0 / 8.0);  // the mean of the secants 1/8, 1/8
    track.keys[1].tangents =
        aerial::KeyTangents{glm::dvec3(0.5), glm::dvec3(-0.25), aerial::TangentMode::Broken};
    const aerial::CompiledTrack given = aerial::compileTrack(track, 1);
    for (double s = 0.0; s <= 1.0; s += 1.0 / 64.0) {
        EXPECT_NEAR(aerial::evaluateTrack(given, 8.0 * s).x, 2.0 * s * s * s - s * s, 1e-12) << s;
        EXPECT_NEAR(aerial::evaluateTrack(given, 8.0 + 8.0 * s).x,
                    -4.0 * s * s * s + 7.0 * s * s - 2.0 * s + 1.0, 1e-12)
            << s;
    }
    EXPECT_LT(aerial::evaluateTrack(given, 2.0).x, 0.0);  // 2/64 - 1/16: not clamped to the keys' range
    for (double t = 16.0; t < 24.0; t += 0.25)
        EXPECT_EQ(aerial::evaluateTrack(given, t).x, aerial::evaluateTrack(automatic, t).x) << t;
    // The automatic tangent ignores the key's own.
    EXPECT_EQ(aerial::automaticTangent(track, 1, 1).x, 1.0 / 8.0);
    // Step and linear segments ignore tangents.
    for (Interpolation interpolation : {Interpolation::Step, Interpolation::Linear}) {
        aerial::Track a = track;
        a.interpolation = interpolation;
        aerial::Track b = a;
        b.keys[1].tangents.reset();
        for (double t = 0.0; t < 24.0; t += 0.25)
            EXPECT_EQ(aerial::evaluateTrack(a, t, 1).x, aerial::evaluateTrack(b, t, 1).x) << t;
    }
    // Unified slopes on a colour, per channel: (0.5, 0, -0.5) per h at 8 h,
    // every channel keyed 0, 1, 2; on 0..8 h channel 0 is
    // 3s^2 - 2s^3 + 4(s^3 - s^2), channel 1 the smoothstep 3s^2 - 2s^3,
    // channel 2 3s^2 - 2s^3 - 4(s^3 - s^2).
    aerial::Track colour;
    colour.interpolation = Interpolation::Smooth;
    colour.keys = {{0.0, glm::dvec3(0.0)}, {8.0, glm::dvec3(1.0)}, {16.0, glm::dvec3(2.0)}};
    colour.keys[1].tangents = aerial::KeyTangents{glm::dvec3(0.5, 0.0, -0.5), glm::dvec3(0.5, 0.0, -0.5)};
    const aerial::CompiledTrack cc = aerial::compileTrack(colour, 3);
    for (double s = 0.0; s <= 1.0; s += 1.0 / 16.0) {
        const glm::dvec3 v = aerial::evaluateTrack(cc, 8.0 * s);
        const double smoothstep = 3.0 * s * s - 2.0 * s * s * s, h11 = s * s * s - s * s;
        EXPECT_NEAR(v.x, smoothstep + 4.0 * h11, 1e-12) << s;
        EXPECT_NEAR(v.y, smoothstep, 1e-12) << s;
        EXPECT_NEAR(v.z, smoothstep - 4.0 * h11, 1e-12) << s;
    }
}

// Tracks without their own tangents evaluate exactly as the automatic ones.
TEST(Timeline, TracksWithoutKeyTangentsAreUnchanged) {
    aerial::Track track;
    track.interpolation = aerial::Interpolation::Smooth;
    track.keys = {
        {1.0, glm::dvec3(0.2)}, {7.0, glm::dvec3(0.9)}, {13.0, glm::dvec3(0.4)}, {20.0, glm::dvec3(0.6)}};
    const aerial::CompiledTrack c = aerial::compileTrack(track, 1);
    EXPECT_EQ(c.tangentsIn, c.tangents);
    for (std::size_t k = 0; k < track.keys.size(); ++k) {
        EXPECT_FALSE(c.givenTangents[k]);
        EXPECT_EQ(aerial::automaticTangent(track, k, 1), c.tangents[k]);
    }
}
