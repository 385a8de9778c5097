// bench_renderer.cpp — the OpenGL renderer, headless (EGL on whatever Mesa
// driver the machine has; llvmpipe on CI), at 1280 x 720. Reports, never
// fails.
//
//   DefaultScene720p: the built-in scene under the built-in default preset
//     at 12:00 with the whole pipeline; counters per pass [ms]: q_* the GL
//     timer queries (GL_TIME_ELAPSED), w_* the wall time between glFinish
//     calls around the pass (FrameDesc::gpuTimers), and the frame's wall
//     time with the read-back (frame_ms).
//   ShadowMaps/res/width: that frame with the cascaded shadow maps at `res`
//     texels per cascade (0: off), `width` pixels wide (16:9): the wall time
//     of the shadow-map pass, of the scene, transparent and particle passes
//     (whose shading reads it) and of the rest [ms].
//   Renderer/FogVolumesAnalyticVsMarched: the same frame with 8 fog volumes
//     (boxes and ellipsoids, rotated, non-uniformly scaled, tilted
//     gradients, two around the camera's path), rendered in one run with the
//     analytic volume pass and with the 64-step ray-marched reference
//     (fog_volume_marched.glsl), side by side. Counters: each volume pass's
//     timer query and its wall time between glFinish calls [ms] (llvmpipe
//     attributes queued work to whichever query is open when it flushes, so
//     the wall time is the steadier number on a CPU rasteriser), their
//     ratios (marched / analytic), and the largest
//     per-pixel difference between the two frames relative to the pixel
//     (max over channels |L_analytic - L_marched| / max(L_marched, 1e-3)).
//   FogAnalyticVsVolumetric/slices/width: the frame's fog drawn analytically
//     (global fog, volume and emitter passes) and volumetrically (the froxel
//     inject, integrate and apply passes; FogMode::Volumetric with `slices`
//     depth slices), shadows on, side by side in one run: each pass's wall
//     time [ms] and the ratio volumetric / analytic.
//   CloudsReferenceVsAmortised/W/H: the cloud layer's pass, the
//     full-resolution reference against CloudQuality::Amortised (4 x 4
//     blocks, still view, and its reset frame) side by side in one run, at
//     320 x 180 and 1280 x 720: each pass's wall time and the ratios.
//
//   build/release/bench/aerial_bench_renderer --benchmark_counters_tabular=true
#include <aerial/evaluate.hpp>
#include <aerial/preset.hpp>
#include <aerial/renderer/egl_context.hpp>
#include <aerial/renderer/renderer.hpp>
#include <aerial/renderer/scene.hpp>
#include <aerial/sky.hpp>

#include <benchmark/benchmark.h>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>

extern "C" __attribute__((used)) const char* __lsan_default_suppressions() {
    return aerial::renderer::kMesaLeakSuppressions;
}

namespace {

using aerial::renderer::FrameDesc;

constexpr int kWidth = 1280;
constexpr int kHeight = 720;

/// The process's context, renderer and the default preset's noon, made once.
struct Setup {
    aerial::renderer::HeadlessContext context;
    std::unique_ptr<aerial::renderer::Renderer> renderer;
    aerial::PresetState state;
    aerial::renderer::Camera camera;
    std::string error;
};

Setup* setup() {
    static Setup* s = [] {
        auto* created = new Setup;  // never destroyed (Mesa tear-down at exit, see gl_fixture.cpp)
        if (!created->context.create()) {
            created->error = "no headless OpenGL 4.5 context: " + created->context.error();
            return created;
        }
        created->renderer = std::make_unique<aerial::renderer::Renderer>();
        if (!created->renderer->valid()) {
            created->error = created->renderer->error();
            return created;
        }
        created->renderer->setScene(aerial::renderer::makeBuiltinScene());
        const aerial::CompiledPreset preset;
        aerial::PresetState& state = created->state;
        preset.evaluate(12.0, state);
        aerial::SkySolver solver;
        solver.solve(state.environment.atmosphere, state.sunLight.body.direction);
        const aerial::SkyTable sun = solver.table();
        solver.solve(state.environment.atmosphere, state.moonLight.body.direction);
        created->renderer->setSky(sun, solver.table());
        // The default camera of `aerial render`.
        created->camera.eye = {0.0, aerial::renderer::builtinTerrainHeight(0.0, 120.0) + 30.0, 120.0};
        created->camera.target = {0.0, aerial::renderer::builtinTerrainHeight(0.0, -200.0) + 10.0, -200.0};
        created->camera.aspect = double(kWidth) / kHeight;
        std::printf("renderer: %s\n", created->context.rendererName().c_str());
        return created;
    }();
    return s;
}

double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

/// Renders and reads the colour back (the read-back waits for the GPU).
double timedFrame(Setup& s, const aerial::PresetState& state, const FrameDesc& frame,
                  aerial::renderer::Image* out = nullptr) {
    const auto start = std::chrono::steady_clock::now();
    s.renderer->render(s.camera, state, frame);
    aerial::renderer::Image image = s.renderer->readColour();
    const double ms = millisecondsSince(start);
    if (out) *out = std::move(image);
    return ms;
}

void DefaultScene720p(benchmark::State& state) {
    Setup& s = *setup();
    if (!s.error.empty()) {
        state.SkipWithError(s.error.c_str());
        return;
    }
    FrameDesc frame;
    frame.width = kWidth;
    frame.height = kHeight;
    frame.gpuTimers = true;
    aerial::renderer::PassTimes gpu, cpu;
    auto add = [](aerial::renderer::PassTimes& sum, const aerial::renderer::PassTimes& t) {
        sum.scene += t.scene;
        sum.sky += t.sky;
        sum.globalFog += t.globalFog;
        sum.subtract += t.subtract;
        sum.volumes += t.volumes;
        sum.emitters += t.emitters;
        sum.transparent += t.transparent;
        sum.particles += t.particles;
        sum.cloudShadow += t.cloudShadow;
        sum.clouds += t.clouds;
        sum.shadowMap += t.shadowMap;
        sum.froxelInject += t.froxelInject;
        sum.froxelIntegrate += t.froxelIntegrate;
        sum.froxelApply += t.froxelApply;
    };
    double wall = 0.0;
    for (auto _ : state) {
        wall += timedFrame(s, s.state, frame);
        add(gpu, s.renderer->stats().gpuMilliseconds);
        add(cpu, s.renderer->stats().wallMilliseconds);
    }
    const double n = double(state.iterations());
    auto report = [&](const char* prefix, const aerial::renderer::PassTimes& t) {
        const std::string p(prefix);
        state.counters[p + "scene"] = t.scene / n;
        state.counters[p + "sky"] = t.sky / n;
        state.counters[p + "fog"] = t.globalFog / n;
        state.counters[p + "subtract"] = t.subtract / n;
        state.counters[p + "volumes"] = t.volumes / n;
        state.counters[p + "emitters"] = t.emitters / n;
        state.counters[p + "transp"] = t.transparent / n;
        state.counters[p + "particles"] = t.particles / n;
        state.counters[p + "shadowMap"] = t.shadowMap / n;
        state.counters[p + "froxels"] = (t.froxelInject + t.froxelIntegrate + t.froxelApply) / n;
        state.counters[p + "total"] = t.total() / n;
    };
    report("q_", gpu);  // GL_TIME_ELAPSED queries [ms]
    report("w_", cpu);  // wall time between glFinish calls [ms]
    state.counters["frame_ms"] = wall / n;
}
BENCHMARK(DefaultScene720p)->Unit(benchmark::kMillisecond)->Iterations(8);

/// The same frame with the shadow maps at range(0) texels per cascade (0:
/// shadows off), range(1) pixels wide (16:9): the wall time of the shadow
/// pass and of the passes whose shading reads it [ms].
void ShadowMaps(benchmark::State& state) {
    Setup& s = *setup();
    if (!s.error.empty()) {
        state.SkipWithError(s.error.c_str());
        return;
    }
    FrameDesc frame;
    frame.width = int(state.range(1));
    frame.height = frame.width * 9 / 16;
    frame.gpuTimers = true;
    frame.passes.shadows = state.range(0) > 0;
    frame.shadowMap.resolution = int(std::max<std::int64_t>(state.range(0), 256));
    aerial::renderer::PassTimes sum;
    double wall = 0.0;
    for (auto _ : state) {
        wall += timedFrame(s, s.state, frame);
        const aerial::renderer::PassTimes& t = s.renderer->stats().wallMilliseconds;
        sum.shadowMap += t.shadowMap;
        sum.scene += t.scene;
        sum.transparent += t.transparent;
        sum.particles += t.particles;
        sum.sky += t.total() - t.shadowMap - t.scene - t.transparent - t.particles;  // the rest
    }
    const double n = double(state.iterations());
    state.counters["w_shadowMap"] = sum.shadowMap / n;
    state.counters["w_scene"] = sum.scene / n;
    state.counters["w_transp"] = sum.transparent / n;
    state.counters["w_particles"] = sum.particles / n;
    state.counters["w_others"] = sum.sky / n;
    state.counters["frame_ms"] = wall / n;
}
void FogAnalyticVsVolumetric(benchmark::State& state) {
    Setup& s = *setup();
    if (!s.error.empty()) {
        state.SkipWithError(s.error.c_str());
        return;
    }
    FrameDesc frame;
    frame.width = int(state.range(1));
    frame.height = frame.width * 9 / 16;
    frame.gpuTimers = true;
    frame.froxels.slices = int(state.range(0));
    double fog = 0.0, volumes = 0.0, emitters = 0.0, inject = 0.0, integrate = 0.0, apply = 0.0;
    for (auto _ : state) {
        frame.fogMode = aerial::renderer::FogMode::Analytic;
        timedFrame(s, s.state, frame);
        const aerial::renderer::PassTimes& a = s.renderer->stats().wallMilliseconds;
        fog += a.globalFog;
        volumes += a.volumes;
        emitters += a.emitters;
        frame.fogMode = aerial::renderer::FogMode::Volumetric;
        timedFrame(s, s.state, frame);
        const aerial::renderer::PassTimes& v = s.renderer->stats().wallMilliseconds;
        inject += v.froxelInject;
        integrate += v.froxelIntegrate;
        apply += v.froxelApply;
    }
    const double n = double(state.iterations());
    const double analytic = (fog + volumes + emitters) / n, volumetric = (inject + integrate + apply) / n;
    state.counters["w_fog"] = fog / n;
    state.counters["w_volumes"] = volumes / n;
    state.counters["w_emitters"] = emitters / n;
    state.counters["w_inject"] = inject / n;
    state.counters["w_integrate"] = integrate / n;
    state.counters["w_apply"] = apply / n;
    state.counters["analytic_ms"] = analytic;
    state.counters["volumetric_ms"] = volumetric;
    state.counters["ratio"] = analytic > 0.0 ? volumetric / analytic : 0.0;
    const aerial::renderer::FroxelStats& g = s.renderer->stats().froxels;
    state.counters["froxels"] = double(g.width) * g.height * g.slices;
}
BENCHMARK(FogAnalyticVsVolumetric)
    ->ArgNames({"slices", "width"})
    ->Args({64, 1280})
    ->Args({128, 1280})
    ->Args({64, 320})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(4);

BENCHMARK(ShadowMaps)
    ->ArgNames({"res", "width"})
    ->Args({0, 1280})
    ->Args({1024, 1280})
    ->Args({2048, 1280})
    ->Args({0, 320})
    ->Args({1024, 320})
    ->Args({2048, 320})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(4);

/// Eight volumes over the default view: boxes and ellipsoids along the
/// valley, rotated, non-uniformly scaled, with tilted gradients; the first
/// two are crossed by most of the frame's rays.
std::vector<aerial::FogVolume> benchVolumes() {
    std::vector<aerial::FogVolume> volumes;
    for (int k = 0; k < 8; ++k) {
        aerial::FogVolume v;
        v.shape = (k % 2 == 0) ? aerial::FogVolumeShape::Box : aerial::FogVolumeShape::Ellipsoid;
        const double z = 60.0 - 45.0 * k;
        const double x = (k % 3 - 1) * 25.0;
        v.position = {x, aerial::renderer::builtinTerrainHeight(x, z) + 6.0, z};
        v.halfExtents = {30.0 + 5.0 * k, 8.0 + k, 25.0};
        v.rotation = glm::angleAxis(0.3 * k, glm::normalize(glm::dvec3(0.1 * k, 1.0, 0.05)));
        v.density = 0.01 + 0.004 * k;
        v.falloff = 0.05 + 0.02 * (k % 4);
        v.gradientDirection = glm::normalize(glm::dvec3(0.2 * (k % 3) - 0.2, 1.0, 0.1 * k));
        v.gradientOffset = -2.0;
        v.colourMode = k % 2 == 0 ? aerial::FogColourMode::Sky : aerial::FogColourMode::Tinted;
        v.colour = {0.9, 0.95, 1.0};
        volumes.push_back(v);
    }
    return volumes;
}

void FogVolumesAnalyticVsMarched(benchmark::State& state) {
    Setup& s = *setup();
    if (!s.error.empty()) {
        state.SkipWithError(s.error.c_str());
        return;
    }
    aerial::PresetState foggy = s.state;
    foggy.volumes = benchVolumes();
    FrameDesc frame;
    frame.width = kWidth;
    frame.height = kHeight;
    frame.precision = aerial::renderer::ColourPrecision::Float;
    frame.gpuTimers = true;
    FrameDesc marched = frame;
    marched.volumeMethod = aerial::renderer::VolumeMethod::RayMarched64;
    double analyticGpu = 0.0, marchedGpu = 0.0, analyticWall = 0.0, marchedWall = 0.0;
    double maxError = 0.0;
    aerial::renderer::Image a, m;
    for (auto _ : state) {
        timedFrame(s, foggy, frame, &a);
        analyticGpu += s.renderer->stats().gpuMilliseconds.volumes;
        analyticWall += s.renderer->stats().wallMilliseconds.volumes;
        timedFrame(s, foggy, marched, &m);
        marchedGpu += s.renderer->stats().gpuMilliseconds.volumes;
        marchedWall += s.renderer->stats().wallMilliseconds.volumes;
    }
    for (std::size_t p = 0; p + 3 < a.pixels.size(); p += 4) {
        double difference = 0.0, scale = 1e-3;
        for (int c = 0; c < 3; ++c) {
            difference = std::max(difference, double(std::fabs(a.pixels[p + c] - m.pixels[p + c])));
            scale = std::max(scale, double(m.pixels[p + c]));
        }
        maxError = std::max(maxError, difference / scale);
    }
    const double n = double(state.iterations());
    state.counters["analytic_gpu_ms"] = analyticGpu / n;
    state.counters["marched_gpu_ms"] = marchedGpu / n;
    state.counters["gpu_ratio"] = analyticGpu > 0.0 ? marchedGpu / analyticGpu : 0.0;
    const double analyticCost = analyticWall / n;
    const double marchedCost = marchedWall / n;
    state.counters["analytic_wall_ms"] = analyticCost;
    state.counters["marched_wall_ms"] = marchedCost;
    state.counters["wall_ratio"] = analyticCost > 0.0 ? marchedCost / analyticCost : 0.0;
    state.counters["max_rel_error"] = maxError;
    state.counters["volumes_drawn"] = s.renderer->stats().volumesDrawn;
}
BENCHMARK(FogVolumesAnalyticVsMarched)->Unit(benchmark::kMillisecond)->Iterations(6);

/// The cloud pass, reference against amortised, at width x height
/// (range(0), range(1)) with a partly cloudy layer (coverage 0.6, type 0.7)
/// over the default view tilted up at the sky; both in one run. The
/// amortised path (4 x 4 blocks) is timed in three states: a reset frame
/// (the first after a jump: estimates everywhere), a still frame after 16
/// still ones (the steady state of a viewport at rest: every pixel traced
/// or kept), and a frame of a slow pan (history reprojected and clamped).
/// Counters [ms]: the cloud pass's wall time between glFinish calls (trace
/// and reconstruction together), and the ratios reference / amortised.
void CloudsReferenceVsAmortised(benchmark::State& state) {
    Setup& s = *setup();
    if (!s.error.empty()) {
        state.SkipWithError(s.error.c_str());
        return;
    }
    aerial::PresetState cloudy = s.state;
    cloudy.environment.clouds.coverage = 0.6;
    cloudy.environment.clouds.type = 0.7;
    const int w = int(state.range(0)), h = int(state.range(1));
    aerial::renderer::Camera camera = s.camera;
    camera.aspect = double(w) / h;
    camera.target = camera.eye + glm::dvec3(0.0, 130.0, -520.0);
    FrameDesc reference;
    reference.width = w;
    reference.height = h;
    reference.gpuTimers = true;
    FrameDesc amortised = reference;
    amortised.cloudQuality = aerial::renderer::CloudQuality::Amortised;
    FrameDesc reset = amortised;
    reset.cloudResetHistory = true;
    auto cloudMs = [&](const FrameDesc& frame, const aerial::renderer::Camera& view) {
        s.renderer->render(view, cloudy, frame);
        return s.renderer->stats().wallMilliseconds.clouds;
    };
    cloudMs(reference, camera);  // the noise upload, llvmpipe's shader compiles
    cloudMs(reset, camera);
    cloudMs(amortised, camera);
    double referenceMs = 0.0, stillMs = 0.0, resetMs = 0.0, panMs = 0.0;
    for (auto _ : state) {
        referenceMs += cloudMs(reference, camera);
        resetMs += cloudMs(reset, camera);
        for (int k = 0; k < 16; ++k) cloudMs(amortised, camera);  // every pixel traced once
        stillMs += cloudMs(amortised, camera);
        // Panning 0.2 deg per frame: the history reprojected and clamped.
        aerial::renderer::Camera pan = camera;
        for (int k = 1; k <= 4; ++k) {
            const double a = 0.0035 * k;
            const glm::dvec3 d = camera.target - camera.eye;
            pan.target = camera.eye + glm::dvec3(d.x * std::cos(a) - d.z * std::sin(a), d.y,
                                                 d.x * std::sin(a) + d.z * std::cos(a));
            const double ms = cloudMs(amortised, pan);
            if (k == 4) panMs += ms;
        }
    }
    const double n = double(state.iterations());
    state.counters["reference_ms"] = referenceMs / n;
    state.counters["still_ms"] = stillMs / n;
    state.counters["pan_ms"] = panMs / n;
    state.counters["reset_ms"] = resetMs / n;
    state.counters["still_ratio"] = stillMs > 0.0 ? referenceMs / stillMs : 0.0;
    state.counters["pan_ratio"] = panMs > 0.0 ? referenceMs / panMs : 0.0;
    state.counters["reset_ratio"] = resetMs > 0.0 ? referenceMs / resetMs : 0.0;
}
BENCHMARK(CloudsReferenceVsAmortised)
    ->Args({320, 180})
    ->Args({1280, 720})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);

}  // namespace
