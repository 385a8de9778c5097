// Regional weather (aerial/weather.hpp, regionalWeather): inside a region
// its state holds exactly, outside the global mix comes back bit for bit,
// the weight is continuous across the blend band (1 cm steps against the
// smoothstep's slope), priorities order the regions, boxes and ellipsoids
// measure their depth exactly, and the same inputs give the same bits.
#include <aerial/evaluate.hpp>
#include <aerial/param_table.hpp>
#include <aerial/preset.hpp>
#include <aerial/weather.hpp>

#include <gtest/gtest.h>

#include <glm/gtc/quaternion.hpp>
#include "shipped_preset.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace aerial {
namespace {

WeatherRegion region(const char* id, WeatherRegionShape shape, glm::dvec3 position, glm::dvec3 half,
                     double blend, const char* state, int priority = 0) {
    WeatherRegion r;
    r.id = id;
    r.shape = shape;
    r.position = position;
    r.halfExtents = half;
    r.blend = blend;
    r.state = state;
    r.priority = priority;
    return r;
}

/// clear_summer_day (states clear, overcast, storm) with its own regions
/// replaced by `regions`.
Preset withRegions(std::vector<WeatherRegion> regions) {
    Preset p = test::loadShippedPreset("clear_summer_day.json");
    p.weatherRegions = std::move(regions);
    EXPECT_TRUE(validatePreset(p).empty());
    return p;
}

bool sameBits(const WeatherMix& a, const WeatherMix& b) {
    return a.weights.size() == b.weights.size() &&
           (a.weights.empty() ||
            std::memcmp(a.weights.data(), b.weights.data(), a.weights.size() * sizeof a.weights[0]) == 0);
}

/// Every animatable global parameter's components and each volume's density.
std::vector<double> values(const PresetState& state) {
    std::vector<double> out;
    Environment env = state.environment;
    for (const ParamDesc& d : paramTable(ParamScope::Global)) {
        if (!d.animatable) continue;
        double v[4];
        readParam(d, env, v);
        out.insert(out.end(), v, v + d.components());
    }
    for (const FogVolume& v : state.volumes) out.push_back(v.density);
    return out;
}

/// The exact distance from p to the ellipsoid with half extents h, brute
/// force: the closest of 720 x 360 surface points, then refined around it.
double bruteEllipsoidDistance(const glm::dvec3& p, const glm::dvec3& h) {
    double bestTheta = 0.0, bestPhi = 0.0, best = std::numeric_limits<double>::infinity();
    auto at = [&](double theta, double phi) {
        const glm::dvec3 s(h.x * std::sin(theta) * std::cos(phi), h.y * std::cos(theta),
                           h.z * std::sin(theta) * std::sin(phi));
        return glm::length(s - p);
    };
    const double pi = 3.14159265358979323846;
    for (int i = 0; i <= 360; ++i)
        for (int j = 0; j < 720; ++j) {
            const double theta = pi * i / 360.0, phi = 2.0 * pi * j / 720.0, d = at(theta, phi);
            if (d < best) best = d, bestTheta = theta, bestPhi = phi;
        }
    for (double step = pi / 360.0; step > 1e-12; step *= 0.5)
        for (int k = 0; k < 8; ++k)
            for (const auto& [dt, dp] : {std::pair{step, 0.0}, {-step, 0.0}, {0.0, step}, {0.0, -step}}) {
                const double d = at(bestTheta + dt, bestPhi + dp);
                if (d < best) best = d, bestTheta += dt, bestPhi += dp;
            }
    return best;
}

TEST(WeatherRegions, InsideTheRegionItsStateHoldsExactly) {
    const CompiledPreset compiled(withRegions({region("ridge_storm", WeatherRegionShape::Ellipsoid,
                                                      {2000, 500, -3000}, {1500, 800, 2000}, 300, "storm")}));
    WeatherMix global, mix, storm;
    ASSERT_TRUE(transitionWeather(compiled.preset(), "clear", "overcast", 0.4, global));
    ASSERT_TRUE(settledWeather(compiled.preset(), "storm", storm));
    // The centre and a point 301 m inside the surface along +X: deeper than the blend.
    for (const glm::dvec3 camera :
         {glm::dvec3(2000, 500, -3000), glm::dvec3(2000 + 1500 - 301, 500, -3000)}) {
        regionalWeather(compiled.preset(), camera, global, mix);
        EXPECT_TRUE(sameBits(mix, storm)) << camera.x;
        PresetState a, b;
        compiled.evaluate(14.0, mix, a);
        compiled.evaluate(14.0, storm, b);
        EXPECT_EQ(values(a), values(b));  // bit for bit
    }
}

TEST(WeatherRegions, OutsideEveryRegionTheGlobalMixComesBackBitForBit) {
    const Preset preset =
        withRegions({region("a", WeatherRegionShape::Box, {0, 0, 0}, {100, 100, 100}, 50, "storm"),
                     region("b", WeatherRegionShape::Ellipsoid, {0, 0, 0}, {100, 100, 100}, 50, "none", 3)});
    WeatherMix global, mix;
    ASSERT_TRUE(transitionWeather(preset, "clear", "overcast", 0.37, global));
    // On the surface (weight 0), just outside, far away, and at a box corner
    // outside the ellipsoid but on the box's surface.
    for (const glm::dvec3 camera : {glm::dvec3(100, 0, 0), glm::dvec3(100.01, 0, 0), glm::dvec3(1e6, 5, -3),
                                    glm::dvec3(100, 100, 100)}) {
        mix.weights.assign(1, {});  // stale content is replaced
        regionalWeather(preset, camera, global, mix);
        EXPECT_TRUE(sameBits(mix, global)) << camera.x;
    }
    // The keyed values (an empty global mix) stay empty.
    regionalWeather(preset, glm::dvec3(500, 0, 0), WeatherMix{}, mix);
    EXPECT_TRUE(mix.weights.empty());
    // A camera that is not finite changes nothing either.
    regionalWeather(preset, glm::dvec3(std::nan(""), 0, 0), global, mix);
    EXPECT_TRUE(sameBits(mix, global));
}

// The weight along a line through the blend band, in 1 cm steps: from 0 at
// the surface to 1 at `blend` inside, never stepping more than the
// smoothstep's slope allows (1.5 / blend per metre, the depth being a
// distance) plus 1e-9 for rounding.
TEST(WeatherRegions, TheWeightIsContinuousAcrossTheBlendBand) {
    const double blend = 200.0, step = 0.01;
    const glm::dquat yaw = glm::angleAxis(0.6, glm::dvec3(0, 1, 0));
    for (WeatherRegionShape shape : {WeatherRegionShape::Box, WeatherRegionShape::Ellipsoid}) {
        WeatherRegion r = region("r", shape, {300, 40, -700}, {1200, 600, 2000}, blend, "storm");
        r.rotation = yaw;
        // A slanted line from outside to the centre.
        const glm::dvec3 from = r.position + yaw * glm::dvec3(1500, 300, 900);
        const glm::dvec3 dir = glm::normalize(r.position - from);
        double last = weatherRegionWeight(r, from), largest = 0.0;
        bool reachedOne = false, leftZero = false;
        const int steps = int(glm::length(r.position - from) / step);
        for (int i = 1; i <= steps; ++i) {
            const double w = weatherRegionWeight(r, from + dir * (i * step));
            ASSERT_TRUE(w >= 0.0 && w <= 1.0);
            largest = std::max(largest, std::abs(w - last));
            leftZero = leftZero || w > 0.0;
            reachedOne = reachedOne || w == 1.0;
            last = w;
        }
        EXPECT_TRUE(leftZero && reachedOne) << int(shape);
        EXPECT_LE(largest, 1.5 * step / blend + 1e-9) << int(shape);
    }
    // The mix moves as the weight does: in each category the storm's weight
    // is the region's weight.
    const Preset preset =
        withRegions({region("r", WeatherRegionShape::Ellipsoid, {0, 0, 0}, {800, 800, 800}, blend, "storm")});
    WeatherMix mix;
    for (double x = 560.0; x <= 800.0; x += 7.3) {
        regionalWeather(preset, glm::dvec3(x, 0, 0), WeatherMix{}, mix);
        const double w = weatherRegionWeight(preset.weatherRegions[0], glm::dvec3(x, 0, 0));
        if (w == 0.0) {
            EXPECT_TRUE(mix.weights.empty());
            continue;
        }
        ASSERT_EQ(mix.weights.size(), 3u);
        for (double v : mix.weights[2]) EXPECT_EQ(v, w);
        const double x01 = std::clamp((800.0 - x) / blend, 0.0, 1.0);
        EXPECT_NEAR(w, x01 * x01 * (3.0 - 2.0 * x01), 1e-12);  // a sphere: depth 800 - x exactly
    }
}

TEST(WeatherRegions, HigherPriorityIsAppliedOverLowerAndEqualOnesInFileOrder) {
    const glm::dvec3 camera(0, 0, 0);
    WeatherMix mix, storm, overcast;
    // "storm" at priority 5 listed first, "overcast" at 0 after it: the storm wins.
    const Preset a = withRegions(
        {region("storm_high", WeatherRegionShape::Box, {0, 0, 0}, {500, 500, 500}, 100, "storm", 5),
         region("overcast_low", WeatherRegionShape::Box, {0, 0, 0}, {500, 500, 500}, 100, "overcast", 0)});
    settledWeather(a, "storm", storm);
    settledWeather(a, "overcast", overcast);
    regionalWeather(a, camera, WeatherMix{}, mix);
    EXPECT_TRUE(sameBits(mix, storm));
    // Equal priorities: the later in the file is applied over the earlier.
    Preset b = a;
    b.weatherRegions[0].priority = 0;
    regionalWeather(b, camera, WeatherMix{}, mix);
    EXPECT_TRUE(sameBits(mix, overcast));
    // Half-way through the upper region's band the lower one's state keeps
    // the other half: out = 0.5 overcast + 0.5 storm, in every category.
    Preset c = a;
    c.weatherRegions[0].halfExtents = glm::dvec3(2000);
    c.weatherRegions[0].blend = 4000;  // wider than the region: the centre is at depth 2000, x = 0.5
    regionalWeather(c, camera, WeatherMix{}, mix);
    ASSERT_EQ(mix.weights.size(), 3u);
    for (int k = 0; k < kWeatherCategoryCount; ++k) {
        EXPECT_DOUBLE_EQ(mix.weights[2][std::size_t(k)], 0.5);  // storm
        EXPECT_DOUBLE_EQ(mix.weights[1][std::size_t(k)], 0.5);  // overcast
        EXPECT_EQ(mix.weights[0][std::size_t(k)], 0.0);         // clear
    }
}

TEST(WeatherRegions, ANoneRegionGivesTheKeyedValues) {
    const CompiledPreset compiled(withRegions(
        {region("clear_valley", WeatherRegionShape::Box, {0, 0, 0}, {3000, 400, 1000}, 100, "none")}));
    WeatherMix global, mix;
    settledWeather(compiled.preset(), "storm", global);
    regionalWeather(compiled.preset(), glm::dvec3(10, 20, 30), global, mix);
    EXPECT_TRUE(mix.weights.empty());
    PresetState a;
    compiled.evaluate(9.0, mix, a);
    EXPECT_EQ(values(a), values(compiled.evaluate(9.0)));
}

TEST(WeatherRegions, BoxAndEllipsoidDepthsAreDistances) {
    const glm::dvec3 h(1500, 1200, 2500);
    WeatherRegion box = region("b", WeatherRegionShape::Box, {100, 200, 300}, h, 100, "storm");
    WeatherRegion ell = box;
    ell.shape = WeatherRegionShape::Ellipsoid;
    const glm::dvec3 c = box.position;
    // On the axes both shapes measure h_i - |p_i|.
    EXPECT_NEAR(weatherRegionDepth(box, c + glm::dvec3(1000, 0, 0)), 500.0, 1e-9);
    EXPECT_NEAR(weatherRegionDepth(ell, c + glm::dvec3(1000, 0, 0)), 500.0, 1e-6);
    EXPECT_NEAR(weatherRegionDepth(ell, c + glm::dvec3(0, 0, -2400)), 100.0, 1e-6);
    EXPECT_NEAR(weatherRegionDepth(ell, c + glm::dvec3(0, 1300, 0)), -100.0, 1e-6);
    EXPECT_NEAR(weatherRegionDepth(ell, c), 1200.0, 1e-6);  // the centre: the smallest half extent
    // Near a corner: inside the box, outside the ellipsoid.
    const glm::dvec3 corner = c + 0.9 * h;
    EXPECT_NEAR(weatherRegionDepth(box, corner), 120.0, 1e-9);
    EXPECT_LT(weatherRegionDepth(ell, corner), 0.0);
    EXPECT_EQ(weatherRegionWeight(box, corner), 1.0);
    EXPECT_EQ(weatherRegionWeight(ell, corner), 0.0);
    // Off the axes, against a brute-force search of the surface (to 1 mm).
    for (const glm::dvec3 p :
         {glm::dvec3(700, 500, 900), glm::dvec3(-1300, 100, 400), glm::dvec3(200, -900, -1500),
          glm::dvec3(10, 3, 5), glm::dvec3(1400, 700, 2100)}) {
        const double brute = bruteEllipsoidDistance(p, h);
        const double level = glm::dot(p / h, p / h);
        EXPECT_NEAR(weatherRegionDepth(ell, c + p), level <= 1.0 ? brute : -brute, 1e-3) << p.x;
    }
    // A rotated box: 90 degrees about +Y swaps its X and Z extents.
    WeatherRegion turned = box;
    turned.rotation = glm::angleAxis(1.5707963267948966, glm::dvec3(0, 1, 0));
    EXPECT_NEAR(weatherRegionDepth(turned, c + glm::dvec3(2000, 0, 0)), 500.0, 1e-6);
    // Invalid regions and points: no weight, no NaN.
    WeatherRegion bad = box;
    bad.halfExtents.y = 0.0;
    EXPECT_EQ(weatherRegionWeight(bad, c), 0.0);
    bad = box;
    bad.rotation = glm::dquat(0, 0, 0, 0);
    EXPECT_EQ(weatherRegionWeight(bad, c), 0.0);
    EXPECT_EQ(weatherRegionWeight(box, glm::dvec3(INFINITY, 0, 0)), 0.0);
    bad = box;
    bad.blend = std::nan("");
    EXPECT_EQ(weatherRegionWeight(bad, c), 1.0);  // a hard edge
}

TEST(WeatherRegions, TheSameInputsGiveTheSameBitsWithoutReallocating) {
    const Preset preset = test::loadShippedPreset("clear_summer_day.json");  // its shipped region
    ASSERT_FALSE(preset.weatherRegions.empty());
    const WeatherRegion& r = preset.weatherRegions[0];
    Weather weather(preset, "clear");
    weather.change("overcast", 600.0, 0.0);
    WeatherMix global, a, b;
    std::vector<WeatherMix> first;
    for (int run = 0; run < 2; ++run) {
        const void* storage = nullptr;
        for (int frame = 0; frame <= 600; ++frame) {
            // A camera flying through the region and out again.
            const double f = frame / 600.0;
            const glm::dvec3 camera = r.position + (f * 2.0 - 1.0) * 1.3 * (r.rotation * r.halfExtents);
            weather.mix(frame * 1.0, global);
            regionalWeather(preset, camera, global, run == 0 ? a : b);
            WeatherMix& out = run == 0 ? a : b;
            if (run == 0) {
                first.push_back(out);
            } else {
                EXPECT_TRUE(sameBits(out, first[std::size_t(frame)])) << frame;
            }
            if (!storage && !out.weights.empty()) storage = out.weights.data();
            if (storage && !out.weights.empty()) {
                EXPECT_EQ(out.weights.data(), storage) << frame;  // reused
            }
        }
    }
    // `out` may be `global` itself.
    weather.mix(300.0, global);
    regionalWeather(preset, r.position, global, a);
    regionalWeather(preset, r.position, global, global);
    EXPECT_TRUE(sameBits(a, global));
}

// ---------------------------------------------------------------------------
// In a file: read, written back bit for bit, validated with the field named.

TEST(WeatherRegions, RoundTripBitExactAndCompared) {
    Preset p = withRegions(
        {region("ridge", WeatherRegionShape::Ellipsoid, {2500.125, 600, -6000.3}, {3000, 2000, 1800.7}, 800.1,
                "storm", 7),
         region("valley", WeatherRegionShape::Box, {0.1, 0.2, 0.3}, {1, 1e7, 5}, 0.0, "none", -1000)});
    p.weatherRegions[0].rotation = glm::normalize(glm::dquat(0.9, 0.1, 0.3, -0.2));
    p.weatherRegions[0].name = "Storm \"over\" the ridge";
    p.weatherRegions[1].rotation = glm::normalize(glm::dquat(0.3, 0.0, -0.7, 0.0));
    ASSERT_TRUE(validatePreset(p).empty());
    const std::string text = presetToJson(p);
    const PresetLoadResult r = parsePreset(text);
    ASSERT_TRUE(r.ok()) << (r.errors.empty() ? "" : r.errors[0].toString());
    EXPECT_TRUE(r.warnings.empty());
    EXPECT_TRUE(presetsIdentical(p, *r.preset));
    EXPECT_EQ(presetToJson(*r.preset), text);
    // One bit of one field, and the other fields, are seen.
    Preset q = *r.preset;
    q.weatherRegions[0].blend = std::nextafter(q.weatherRegions[0].blend, 1e9);
    EXPECT_FALSE(presetsIdentical(*r.preset, q));
    for (auto change :
         {+[](WeatherRegion& w) { w.priority += 1; }, +[](WeatherRegion& w) { w.state = "clear"; },
          +[](WeatherRegion& w) { w.shape = WeatherRegionShape::Box; },
          +[](WeatherRegion& w) { w.id = "other"; }}) {
        Preset changed = *r.preset;
        change(changed.weatherRegions[0]);
        EXPECT_FALSE(presetsIdentical(p, changed));
    }
    // A preset without regions writes no "regions" (files stay as they were).
    p.weatherRegions.clear();
    EXPECT_EQ(presetToJson(p).find("\"regions\""), std::string::npos);
}

TEST(WeatherRegions, MissingFieldsTakeTheDefaults) {
    const PresetLoadResult r = parsePreset(
        R"({"version": 5, "weather": {"states": [], "regions": [{"id": "a", "state": "none", "colour": 1}]}})");
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_EQ(r.warnings[0].pointer, "/weather/regions/0/colour");
    const WeatherRegion& got = r.preset->weatherRegions.at(0);
    const WeatherRegion defaults;
    EXPECT_EQ(got.shape, defaults.shape);
    EXPECT_EQ(got.halfExtents, defaults.halfExtents);
    EXPECT_EQ(got.blend, defaults.blend);
    EXPECT_EQ(got.priority, 0);
    EXPECT_EQ(got.rotation, defaults.rotation);
}

TEST(WeatherRegions, ValidationNamesTheFieldAndTheReason) {
    Preset p = test::loadShippedPreset("clear_summer_day.json");
    p.weatherRegions = {region("ridge", WeatherRegionShape::Box, {0, 0, 0}, {100, 100, 100}, 10, "storm"),
                        region("ridge", WeatherRegionShape::Box, {0, 0, 0}, {100, 100, 100}, 10, "storm")};
    p.weatherRegions[0].position.y = std::nan("");
    p.weatherRegions[0].halfExtents.z = 0.0;
    p.weatherRegions[0].blend = -1.0;
    p.weatherRegions[0].state = "hail";
    p.weatherRegions[0].rotation = glm::dquat(2, 0, 0, 0);
    p.weatherRegions[0].priority = 1001;
    p.weatherRegions[1].shape = WeatherRegionShape(7);
    p.weatherRegions[1].halfExtents.x = INFINITY;
    std::vector<std::string> got;
    for (const PresetIssue& i : validatePreset(p)) got.push_back(i.pointer + ": " + i.message);
    const std::vector<std::string> expected = {
        "/weather/regions/0/position_m/1: must be a finite number (got nan)",
        "/weather/regions/0/half_extents_m/2: out of range: 0 is not in 1..1e+07 m",
        "/weather/regions/0/rotation_xyzw: must be a unit quaternion (length 2)",
        "/weather/regions/0/blend_m: out of range: -1 is not in 0..1e+07 m",
        "/weather/regions/0/priority: out of range: 1001 is not in -1000..1000",
        "/weather/regions/0/state: no weather state \"hail\" (the preset has none, clear, overcast, storm)",
        "/weather/regions/1/id: duplicate id \"ridge\" (also /weather/regions/0)",
        "/weather/regions/1/shape: unknown shape; expected one of box, ellipsoid",
        "/weather/regions/1/half_extents_m/0: must be a finite number (got inf)",
    };
    EXPECT_EQ(got, expected);
    // savePreset refuses it: nothing non-finite reaches a file.
    EXPECT_FALSE(savePreset(p, ::testing::TempDir() + "/regions_refused.json").ok());
}

}  // namespace
}  // namespace aerial
