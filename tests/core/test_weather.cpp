// Weather states and transitions (aerial/weather.hpp) on the shipped
// presets that carry them: continuity frame by frame, the end state exactly,
// determinism bit for bit, the categories' speeds, and the blend of two
// presets.
#include <aerial/evaluate.hpp>
#include <aerial/param_table.hpp>
#include <aerial/preset.hpp>
#include <aerial/weather.hpp>

#include <gtest/gtest.h>

#include "shipped_preset.hpp"

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

namespace aerial {
namespace {

/// Every animatable global parameter's components, in table order.
std::vector<double> globals(const PresetState& state) {
    std::vector<double> out;
    Environment env = state.environment;
    for (const ParamDesc& d : paramTable(ParamScope::Global)) {
        if (!d.animatable) continue;
        if (d.type == ParamType::Scalar) out.push_back(*d.scalar(&env));
        if (d.type == ParamType::Vec2) out.insert(out.end(), {d.vec2(&env)->x, d.vec2(&env)->y});
        if (d.type == ParamType::Colour || d.type == ParamType::Vec3)
            out.insert(out.end(), {d.vec3(&env)->x, d.vec3(&env)->y, d.vec3(&env)->z});
    }
    for (const FogVolume& v : state.volumes) out.push_back(v.density);
    return out;
}

/// The category share of each entry of globals() (volumes: fog).
std::vector<double> shares(const PresetState& state) {
    std::vector<double> out;
    for (const ParamDesc& d : paramTable(ParamScope::Global)) {
        if (!d.animatable) continue;
        const double share =
            kWeatherCategoryShare[int(weatherCategory(TrackTarget::global(std::string(d.path))))];
        out.insert(out.end(), std::size_t(d.components()), share);
    }
    out.insert(out.end(), state.volumes.size(), kWeatherCategoryShare[int(WeatherCategory::Fog)]);
    return out;
}

PresetState settled(const CompiledPreset& compiled, const char* name, double hours) {
    WeatherMix mix;
    EXPECT_TRUE(settledWeather(compiled.preset(), name, mix)) << name;
    PresetState s;
    compiled.evaluate(hours, mix, s);
    return s;
}

TEST(Weather, StatesOverrideTheKeys) {
    const CompiledPreset compiled(test::loadShippedPreset("clear_summer_day.json"));
    const PresetState plain = compiled.evaluate(14.0);
    const PresetState none = settled(compiled, "none", 14.0);
    EXPECT_EQ(globals(plain), globals(none));
    const PresetState storm = settled(compiled, "storm", 14.0);
    EXPECT_EQ(storm.environment.clouds.coverage, 0.97);                                    // set
    EXPECT_DOUBLE_EQ(storm.environment.fog.density, 6.0 * plain.environment.fog.density);  // scale
    EXPECT_DOUBLE_EQ(storm.environment.exposure.compensationEv,
                     plain.environment.exposure.compensationEv - 1.0);
    // The seed never changes with the weather: the cloud noise keeps its phase.
    EXPECT_EQ(storm.environment.clouds.seed, plain.environment.clouds.seed);
    // Derived values follow: the hazier storm dims the sun that reaches the ground.
    EXPECT_LT(storm.sunLight.illuminance.y, plain.sunLight.illuminance.y);
}

// A game drives a ten-minute clear -> storm change at 60 frames a second
// with the time of day held: every parameter moves by at most the rate its
// category allows (the smoothstep's slope 1.5 over share x 600 s, times the
// difference between the states, per frame), and at 600 s the state is the
// storm's exactly.
TEST(Weather, TenMinutesClearToStormIsContinuousAndEndsAtTheStorm) {
    const CompiledPreset compiled(test::loadShippedPreset("clear_summer_day.json"));
    const double hours = 14.0, duration = 600.0, frame = 1.0 / 60.0;
    const std::vector<double> clear = globals(settled(compiled, "clear", hours));
    const std::vector<double> storm = globals(settled(compiled, "storm", hours));
    Weather weather(compiled.preset(), "clear");
    ASSERT_TRUE(weather.change("storm", duration, 0.0));
    WeatherMix mix;
    PresetState state;
    weather.mix(0.0, mix);
    compiled.evaluate(hours, mix, state);
    EXPECT_EQ(globals(state), clear);
    const std::vector<double> share = shares(state);
    std::vector<double> previous = clear;
    double worstRatio = 0.0;
    for (int f = 1; f <= int(duration / frame) + 60; ++f) {
        weather.mix(f * frame, mix);
        compiled.evaluate(hours, mix, state);
        const std::vector<double> now = globals(state);
        ASSERT_EQ(now.size(), previous.size());
        for (std::size_t i = 0; i < now.size(); ++i) {
            const double bound = 1.5 * std::abs(storm[i] - clear[i]) / (share[i] * duration) * frame;
            const double step = std::abs(now[i] - previous[i]);
            ASSERT_LE(step, bound * (1.0 + 1e-6) + 1e-12) << "component " << i << " at frame " << f;
            if (bound > 0.0) worstRatio = std::max(worstRatio, step / bound);
        }
        previous = now;
    }
    std::printf("[ weather ] largest frame step %.4f of its category's bound\n", worstRatio);
    EXPECT_GT(worstRatio, 0.9);  // the bound is tight: the test can fail
    EXPECT_EQ(previous, storm);  // exactly the storm, bit for bit
    EXPECT_FALSE(weather.transitioning(duration));
    EXPECT_EQ(weather.target(), "storm");
}

TEST(Weather, TheSameCallsGiveTheSameValuesBitForBit) {
    const CompiledPreset compiled(test::loadShippedPreset("clear_summer_day.json"));
    auto run = [&](Weather& w, double t) {
        WeatherMix mix;
        w.mix(t, mix);
        PresetState s;
        compiled.evaluate(9.25, mix, s);
        return globals(s);
    };
    Weather a(compiled.preset(), "clear"), b(compiled.preset(), "clear");
    for (Weather* w : {&a, &b}) {
        ASSERT_TRUE(w->change("overcast", 300.0, 10.0));
        ASSERT_TRUE(w->change("storm", 200.0, 160.0));  // during the first
    }
    for (double t : {0.0, 50.0, 160.0, 161.0, 250.0, 359.9, 400.0}) EXPECT_EQ(run(a, t), run(b, t)) << t;
    // A peer rebuilds it from the names and times alone.
    Weather c(compiled.preset(), a.initial());
    for (const WeatherChange& ch : a.changes())
        ASSERT_TRUE(c.change(ch.state, ch.durationSeconds, ch.startSeconds));
    for (double t : {170.0, 250.0, 400.0}) EXPECT_EQ(run(a, t), run(c, t)) << t;
    // A change started during another begins where the weather was.
    EXPECT_EQ(run(a, 160.0), [&] {
        Weather d(compiled.preset(), "clear");
        d.change("overcast", 300.0, 10.0);
        return run(d, 160.0);
    }());
    // Bad calls change nothing.
    EXPECT_FALSE(a.change("hail", 10.0, 500.0));
    EXPECT_FALSE(a.change("clear", -1.0, 500.0));
    EXPECT_FALSE(a.change("clear", 10.0, 100.0));  // before the last change
    EXPECT_EQ(a.target(), "storm");
}

TEST(Weather, CloudsChangeSlowerThanFog) {
    for (double f : {0.1, 0.3, 0.5}) {
        EXPECT_GT(weatherTransitionWeight(WeatherCategory::Fog, f),
                  weatherTransitionWeight(WeatherCategory::Clouds, f));
        EXPECT_GT(weatherTransitionWeight(WeatherCategory::Wind, f),
                  weatherTransitionWeight(WeatherCategory::Fog, f));
    }
    for (int c = 0; c < kWeatherCategoryCount; ++c) {
        EXPECT_EQ(weatherTransitionWeight(WeatherCategory(c), 0.0), 0.0);
        EXPECT_EQ(weatherTransitionWeight(WeatherCategory(c), 1.0), 1.0);
    }
    EXPECT_EQ(weatherCategory(TrackTarget::global("clouds.wind_m_per_s")), WeatherCategory::Wind);
    EXPECT_EQ(weatherCategory(TrackTarget::volume("mist", "density_per_m")), WeatherCategory::Fog);
}

// `--transition A:B:F`: 0 is A, 1 is B, 0.5 lies between for every
// parameter that differs (the valley clearing: its fog volumes too).
TEST(Weather, TransitionFractionsLieBetweenTheStates) {
    const CompiledPreset compiled(test::loadShippedPreset("foggy_valley_morning.json"));
    const double hours = 6.5;
    const std::vector<double> fog = globals(settled(compiled, "fog", hours));
    const std::vector<double> clearing = globals(settled(compiled, "clearing", hours));
    auto at = [&](double f) {
        WeatherMix mix;
        EXPECT_TRUE(transitionWeather(compiled.preset(), "fog", "clearing", f, mix));
        PresetState s;
        compiled.evaluate(hours, mix, s);
        return globals(s);
    };
    EXPECT_EQ(at(0.0), fog);
    EXPECT_EQ(at(1.0), clearing);
    const std::vector<double> half = at(0.5);
    int differing = 0;
    for (std::size_t i = 0; i < half.size(); ++i) {
        if (fog[i] == clearing[i]) continue;
        ++differing;
        EXPECT_GT(half[i], std::min(fog[i], clearing[i])) << i;
        EXPECT_LT(half[i], std::max(fog[i], clearing[i])) << i;
    }
    EXPECT_GE(differing, 5);  // global fog, coverage, three volumes
    WeatherMix mix;
    EXPECT_FALSE(transitionWeather(compiled.preset(), "fog", "hail", 0.5, mix));
}

// Renaming or removing an object carries the overrides that name it, as
// its tracks (core's editing helpers; the editor calls them).
TEST(Weather, OverridesFollowTheirObject) {
    Preset p = test::loadShippedPreset("foggy_valley_morning.json");
    const auto countTargets = [&](const std::string& id) {
        int n = 0;
        for (const WeatherState& s : p.weather)
            for (const WeatherOverride& o : s.overrides) n += o.target.objectId == id;
        return n;
    };
    ASSERT_EQ(countTargets("river_mist"), 1);
    ASSERT_TRUE(changeObjectId(p, ParamScope::Volume, "river_mist", "creek_mist"));
    EXPECT_EQ(countTargets("river_mist"), 0);
    EXPECT_EQ(countTargets("creek_mist"), 1);
    ASSERT_TRUE(removeObject(p, ParamScope::Volume, "creek_mist"));
    EXPECT_EQ(countTargets("creek_mist"), 0);
    EXPECT_TRUE(validatePreset(p).empty());  // nothing left dangling: the preset still saves
}

TEST(Weather, TwoPresetsBlendContinuously) {
    const PresetState a = CompiledPreset(test::loadShippedPreset("clear_summer_day.json")).evaluate(10.0);
    const PresetState b = CompiledPreset(test::loadShippedPreset("foggy_valley_morning.json")).evaluate(10.0);
    PresetState out;
    blendPresetStates(a, b, 0.0, out);
    EXPECT_EQ(out.environment.fog.density, a.environment.fog.density);
    blendPresetStates(a, b, 1.0, out);
    EXPECT_EQ(out.environment.fog.density, b.environment.fog.density);
    ASSERT_EQ(out.volumes.size(), a.volumes.size() + b.volumes.size());
    for (std::size_t i = 0; i < a.volumes.size(); ++i) EXPECT_EQ(out.volumes[i].density, 0.0);
    double previous = a.environment.clouds.coverage;
    for (int k = 1; k <= 100; ++k) {
        blendPresetStates(a, b, k / 100.0, out);
        EXPECT_LE(std::abs(out.environment.clouds.coverage - previous),
                  std::abs(b.environment.clouds.coverage - a.environment.clouds.coverage) / 100.0 + 1e-12);
        previous = out.environment.clouds.coverage;
    }
}

}  // namespace
}  // namespace aerial
