// Preset benchmarks: load (parse + validate), compile and per-frame evaluate
// of a generated preset with 100 volumes, 20 emitters and 200 tracks.
// Targets: load <= 5 ms, evaluate <= 20 us.
#include <aerial/evaluate.hpp>
#include <aerial/preset.hpp>
#include <aerial/weather.hpp>

#include <benchmark/benchmark.h>

#include <cstdio>
#include <string>

namespace {

aerial::Preset bigPreset() {
    aerial::Preset p = aerial::defaultPreset();
    p.volumes.clear();
    p.emitters.clear();
    p.tracks.clear();
    for (int i = 0; i < 100; ++i) {
        aerial::FogVolume v;
        v.id = "volume_";
        v.id += std::to_string(i);
        v.name = "Volume ";
        v.name += std::to_string(i);
        v.shape = i % 2 ? aerial::FogVolumeShape::Ellipsoid : aerial::FogVolumeShape::Box;
        v.position = glm::dvec3(i * 13.7, 2.0 + i % 7, -20.0 - i * 3.1);
        v.halfExtents = glm::dvec3(20.0 + i % 5, 4.0, 15.0);
        v.density = 0.001 * (1 + i % 9);
        v.falloff = 0.05;
        p.volumes.push_back(v);
    }
    for (int i = 0; i < 20; ++i) {
        aerial::Emitter e;
        e.id = "emitter_";
        e.id += std::to_string(i);
        e.kind = i % 4 == 0 ? aerial::EmitterKind::Lightning : aerial::EmitterKind::Point;
        e.position = glm::dvec3(i * 10.0, 5.0, -30.0);
        e.seed = std::uint32_t(i + 1);
        p.emitters.push_back(e);
    }
    auto keys6 = [](double scale, bool vec) {
        std::vector<aerial::TrackKey> keys;
        for (int k = 0; k < 6; ++k) {
            const double v = scale * (0.5 + 0.5 * ((k * 7) % 5) / 4.0);
            keys.push_back({k * 4.0 + 0.5, vec ? glm::dvec3(v, 0.9 * v, 0.8 * v) : glm::dvec3(v, 0, 0)});
        }
        return keys;
    };
    const auto interp = [](int i) { return aerial::Interpolation(i % 3); };
    int n = 0;
    for (int i = 0; i < 100; ++i, ++n)  // 100 volume densities
        p.tracks.push_back({aerial::TrackTarget::volume(p.volumes[std::size_t(i)].id, "density_per_m"),
                            interp(n), keys6(0.01, false)});
    for (int i = 0; i < 40; ++i, ++n)  // 40 volume colours
        p.tracks.push_back({aerial::TrackTarget::volume(p.volumes[std::size_t(i)].id, "colour_rgb"),
                            interp(n), keys6(1.0, true)});
    for (int i = 0; i < 20; ++i, ++n)  // 20 volume positions
        p.tracks.push_back({aerial::TrackTarget::volume(p.volumes[std::size_t(i)].id, "position_m"),
                            interp(n), keys6(10.0, true)});
    for (int i = 0; i < 20; ++i, ++n)  // 20 emitter intensities
        p.tracks.push_back({aerial::TrackTarget::emitter(p.emitters[std::size_t(i)].id, "intensity_cd"),
                            interp(n), keys6(2.0, false)});
    for (int i = 0; i < 10; ++i, ++n)  // 10 emitter colours
        p.tracks.push_back({aerial::TrackTarget::emitter(p.emitters[std::size_t(i)].id, "colour_rgb"),
                            interp(n), keys6(1.0, true)});
    const char* globals[] = {"fog.density_per_m",
                             "fog.falloff_per_m",
                             "fog.base_height_m",
                             "fog.colour_rgb",
                             "sun.intensity",
                             "sun.colour_rgb",
                             "moon.intensity",
                             "moon.colour_rgb",
                             "atmosphere.mie.anisotropy",
                             "atmosphere.ozone.absorption_per_m"};
    for (const char* g : globals) {  // 10 globals
        const bool vec = std::string(g).find("rgb") != std::string::npos ||
                         std::string(g).find("absorption") != std::string::npos;
        const double scale = std::string(g) == "atmosphere.ozone.absorption_per_m" ? 1e-6
                             : std::string(g) == "atmosphere.mie.anisotropy"       ? 0.8
                             : std::string(g) == "sun.intensity"                   ? 20.0
                                                                                   : 0.01;
        p.tracks.push_back({aerial::TrackTarget::global(g), interp(n++), keys6(scale, vec)});
    }
    return p;
}

void BM_PresetParse(benchmark::State& state) {
    const std::string text = aerial::presetToJson(bigPreset());
    for (auto _ : state) {
        aerial::PresetLoadResult r = aerial::parsePreset(text, "big.json");
        if (!r.ok()) {
            state.SkipWithError(r.errors.front().toString().c_str());
            break;
        }
        benchmark::DoNotOptimize(r);
    }
    state.counters["bytes"] = double(text.size());
}
BENCHMARK(BM_PresetParse)->Unit(benchmark::kMillisecond);

void BM_PresetLoadFile(benchmark::State& state) {
    const std::string path = "/tmp/aerial_bench_preset.json";
    if (!aerial::savePreset(bigPreset(), path).ok()) {
        state.SkipWithError("cannot save");
        return;
    }
    for (auto _ : state) {
        aerial::PresetLoadResult r = aerial::loadPreset(path);
        benchmark::DoNotOptimize(r);
    }
    std::remove(path.c_str());
}
BENCHMARK(BM_PresetLoadFile)->Unit(benchmark::kMillisecond);

void BM_PresetToJson(benchmark::State& state) {
    const aerial::Preset p = bigPreset();
    for (auto _ : state) benchmark::DoNotOptimize(aerial::presetToJson(p));
}
BENCHMARK(BM_PresetToJson)->Unit(benchmark::kMillisecond);

void BM_PresetCompile(benchmark::State& state) {
    const aerial::Preset p = bigPreset();
    for (auto _ : state) {
        aerial::CompiledPreset c(p);
        benchmark::DoNotOptimize(c);
    }
}
BENCHMARK(BM_PresetCompile)->Unit(benchmark::kMillisecond);

void BM_PresetEvaluate(benchmark::State& state) {
    const aerial::CompiledPreset c(bigPreset());
    aerial::PresetState s;
    c.evaluate(0.0, s);
    double t = 0.0;
    for (auto _ : state) {
        c.evaluate(t, s);
        benchmark::DoNotOptimize(s.sunLight.illuminance);
        t += 0.0137;  // a new time every frame
        if (t >= 24.0) t -= 24.0;
    }
}
BENCHMARK(BM_PresetEvaluate)->Unit(benchmark::kMicrosecond);

// The shipped clear_summer_day through a day, plain and with a
// clear -> storm change under way (aerial/weather.hpp): the target is a
// running transition at most 2x the plain evaluation. Arg 0 plain, 1 with
// the weather (the mix and the overrides every frame).
void BM_EvaluateWeather(benchmark::State& state) {
    const aerial::PresetLoadResult r = aerial::loadPreset(AERIAL_SOURCE_DIR "/presets/clear_summer_day.json");
    if (!r.ok()) {
        state.SkipWithError("cannot load clear_summer_day.json");
        return;
    }
    const aerial::CompiledPreset c(*r.preset);
    aerial::Weather weather(c.preset(), "clear");
    weather.change("overcast", 400.0, 0.0);
    weather.change("storm", 600.0, 200.0);  // a change during another: two states mixed
    aerial::WeatherMix mix;
    aerial::PresetState s;
    c.evaluate(0.0, s);
    double t = 0.0, clock = 0.0;
    for (auto _ : state) {
        if (state.range(0) == 1) {
            weather.mix(clock, mix);
            c.evaluate(t, mix, s);
        } else {
            c.evaluate(t, s);
        }
        benchmark::DoNotOptimize(s.sunLight.illuminance);
        t += 0.0137;
        if (t >= 24.0) t -= 24.0;
        clock += 1.0 / 60.0;
        if (clock >= 700.0) clock = 210.0;  // stay inside the transitions
    }
}
BENCHMARK(BM_EvaluateWeather)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

}  // namespace
