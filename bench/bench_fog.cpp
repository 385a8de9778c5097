// bench_fog.cpp — CPU fog queries (FogScene) for transparent objects.
//
// A plausible outdoor layout: global height fog, a sun and a moon, two
// emitters, and N fog volumes (boxes and ellipsoids, randomly rotated, 10-80
// m wide and 4-30 m tall) scattered over a 2 km x 2 km area. Each query runs
// from a camera near the centre to a random object in the area (up to ~1.4
// km away). Reports queries per second per thread (items_per_second) and the
// mean number of volumes a query crosses (crossed/query).
// BM_FogQueryMeshSubtract: the same layout with a quarter of the volumes
// mesh volumes (a torus of 2304 triangles, 10-60 m across) and a quarter
// subtract volumes, against BM_FogQuery/256 in the same run.
// BM_FogQueryHorizonRow: BM_FogQuery/256 with the lights' horizon rows (the
// fog colour from the sky behind it, a solved 128-column table of a sun 3
// deg below the horizon) in place of the averages alone.
//
//   build/fog/bench/aerial_bench --benchmark_filter=Fog
#include "test_meshes.hpp"

#include <aerial/fog_mesh.hpp>
#include <aerial/fog_query.hpp>
#include <aerial/sky.hpp>

#include <benchmark/benchmark.h>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cstddef>
#include <memory>
#include <random>
#include <vector>

namespace {

constexpr std::size_t kSegments = 4096;

struct BenchScene {
    aerial::FogSceneDesc desc;
    std::vector<aerial::FogSegment> segments;
};

/// The horizon row of a sun 3 deg below the horizon (solved once).
const aerial::SkyTable& twilightRow() {
    static const aerial::SkyTable row = [] {
        aerial::SkySolver solver;
        solver.solve(aerial::AtmosphereParams{}, glm::normalize(glm::dvec3(0.4, -0.05, -0.8)));
        return aerial::skyHorizonRow(solver.table());
    }();
    return row;
}

BenchScene makeScene(std::size_t volumeCount, bool meshAndSubtract = false, bool horizonRows = false) {
    std::mt19937_64 rng(0xF06 + volumeCount);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::normal_distribution<double> normal(0.0, 1.0);
    auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * unit(rng); };

    BenchScene s;
    s.desc.heightFog = {0.0005, 0.002, 0.0};
    s.desc.lights[0] = {
        glm::normalize(glm::dvec3(0.4, 0.3, -0.8)), {3.0, 2.9, 2.6}, {0.02, 0.05, 0.12}, {0.04, 0.04, 0.04}};
    s.desc.lights[1] = {glm::normalize(glm::dvec3(-0.3, 0.6, 0.7)),
                        {0.01, 0.01, 0.015},
                        {0.02, 0.05, 0.12},
                        {0.04, 0.04, 0.04}};
    if (horizonRows) {
        for (aerial::FogLight& light : s.desc.lights) light.horizonRow = twilightRow();
    }
    for (std::size_t i = 0; i < volumeCount; ++i) {
        aerial::FogVolume v;
        v.shape = (i % 2 == 0) ? aerial::FogVolumeShape::Box : aerial::FogVolumeShape::Ellipsoid;
        v.position = {uniform(-1000, 1000), uniform(0, 40), uniform(-1000, 1000)};
        v.halfExtents = {uniform(5, 40), uniform(2, 15), uniform(5, 40)};
        // Mostly upright (rotated about +Y), some tilted.
        v.rotation = (i % 4 == 0)
                         ? glm::normalize(glm::dquat(normal(rng), normal(rng), normal(rng), normal(rng)))
                         : glm::angleAxis(uniform(0, 6.283185307179586), glm::dvec3(0, 1, 0));
        v.density = uniform(0.002, 0.05);
        v.falloff = uniform(0.0, 0.1);
        v.colourMode = static_cast<aerial::FogColourMode>(i % 3);
        v.colour = {uniform(0.5, 1), uniform(0.5, 1), uniform(0.5, 1)};
        if (meshAndSubtract && i % 4 == 1) {
            static const std::shared_ptr<const aerial::FogMesh> torus = [] {
                const aerial::test::TriangleMesh m = aerial::test::torusMesh(6.0, 2.0, 48, 24);
                std::string error;
                return aerial::FogMesh::build(m.positions, m.indices, error);
            }();
            v.shape = aerial::FogVolumeShape::Mesh;
            v.meshData = torus;
            const double scale = uniform(1.0, 4.0);
            v.halfExtents = {scale, scale * uniform(0.5, 1.5), scale};
        }
        if (meshAndSubtract && i % 4 == 3) v.blend = aerial::FogVolumeBlend::Subtract;
        s.desc.volumes.push_back(v);
    }
    for (int i = 0; i < 2; ++i) {
        aerial::Emitter e;
        e.position = {uniform(-500, 500), uniform(2, 10), uniform(-500, 500)};
        e.intensity = 0.2;
        e.attenuation = 0.01;
        e.colour = {1.0, 0.6, 0.3};
        s.desc.emitters.push_back(e);
    }
    const glm::dvec3 camera{12.0, 1.8, -7.0};
    for (std::size_t k = 0; k < kSegments; ++k) {
        s.segments.push_back({camera, {uniform(-1000, 1000), uniform(0, 60), uniform(-1000, 1000)}});
    }
    return s;
}

double meanCrossed(const aerial::FogScene& scene, const BenchScene& s) {
    std::vector<aerial::VolumeContribution> list;
    std::size_t total = 0;
    for (const auto& seg : s.segments) {
        scene.query(seg.from, seg.to, list);
        total += list.size();
    }
    return static_cast<double>(total) / static_cast<double>(s.segments.size());
}

/// Queries, one segment after another, of the scene of range(0) volumes.
void runQueries(benchmark::State& state, bool meshAndSubtract, bool horizonRows = false) {
    const BenchScene s = makeScene(static_cast<std::size_t>(state.range(0)), meshAndSubtract, horizonRows);
    const aerial::FogScene scene(s.desc);
    std::size_t k = 0;
    for (auto _ : state) {
        const aerial::FogSegment& seg = s.segments[k];
        k = (k + 1) % kSegments;
        benchmark::DoNotOptimize(scene.query(seg.from, seg.to));
    }
    state.SetItemsProcessed(state.iterations());
    state.counters["crossed/query"] = meanCrossed(scene, s);
}

void BM_FogQuery(benchmark::State& state) { runQueries(state, false); }
BENCHMARK(BM_FogQuery)->Arg(1)->Arg(16)->Arg(256);

void BM_FogQueryMeshSubtract(benchmark::State& state) { runQueries(state, true); }
BENCHMARK(BM_FogQueryMeshSubtract)->Arg(256);

void BM_FogQueryHorizonRow(benchmark::State& state) { runQueries(state, false, true); }
BENCHMARK(BM_FogQueryHorizonRow)->Arg(256);

void BM_FogQueryContributions(benchmark::State& state) {
    const BenchScene s = makeScene(static_cast<std::size_t>(state.range(0)));
    const aerial::FogScene scene(s.desc);
    std::vector<aerial::VolumeContribution> list;
    std::size_t k = 0;
    for (auto _ : state) {
        const aerial::FogSegment& seg = s.segments[k];
        k = (k + 1) % kSegments;
        benchmark::DoNotOptimize(scene.query(seg.from, seg.to, list));
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_FogQueryContributions)->Arg(256);

void BM_FogQueryBatch(benchmark::State& state) {
    const BenchScene s = makeScene(static_cast<std::size_t>(state.range(0)));
    const aerial::FogScene scene(s.desc);
    std::vector<aerial::FogQueryResult> results(kSegments);
    for (auto _ : state) {
        scene.queryBatch(s.segments.data(), results.data(), kSegments);
        benchmark::DoNotOptimize(results.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(kSegments));
}
BENCHMARK(BM_FogQueryBatch)->Arg(1)->Arg(16)->Arg(256);

void BM_FogSceneBuild(benchmark::State& state) {
    const BenchScene s = makeScene(static_cast<std::size_t>(state.range(0)));
    for (auto _ : state) {
        const aerial::FogScene scene(s.desc);
        benchmark::DoNotOptimize(&scene);
    }
}
BENCHMARK(BM_FogSceneBuild)->Arg(256);

}  // namespace
