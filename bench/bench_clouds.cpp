// bench_clouds.cpp — the cloud layer on the CPU (aerial/clouds.hpp): noise
// generation from a seed (issue 12 asks for "well under a second" here), the
// queries a game makes per frame (sun visibility at a point), and the
// reference march.
//
//   build/release/bench/aerial_bench --benchmark_filter=Cloud
#include <aerial/clouds.hpp>

#include <benchmark/benchmark.h>

#include <glm/geometric.hpp>

#include <random>
#include <vector>

namespace {

aerial::CloudField cumulus() {
    aerial::CloudParams p;
    p.coverage = 0.5;
    p.type = 0.8;
    return aerial::prepareClouds(p, {}, 14.0, 6360000.0);
}

/// Generating both textures (128^3 + 32^3) from a seed, 1 thread and all.
void BM_CloudNoiseGenerate(benchmark::State& state) {
    std::int64_t seed = 1;
    for (auto _ : state) benchmark::DoNotOptimize(aerial::generateCloudNoise(seed++, int(state.range(0))));
}
BENCHMARK(BM_CloudNoiseGenerate)
    ->ArgName("threads")
    ->Arg(1)
    ->Arg(0)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

/// Sun visibility (48 samples through the layer) at random ground points.
void BM_CloudSunVisibility(benchmark::State& state) {
    const aerial::CloudField f = cumulus();
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> xz(-20000.0, 20000.0);
    const glm::dvec3 sun = glm::normalize(glm::dvec3(0.4, 0.8, 0.2));
    for (auto _ : state)
        benchmark::DoNotOptimize(aerial::cloudSunVisibility(f, {xz(rng), 0.0, xz(rng)}, sun));
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_CloudSunVisibility)->Unit(benchmark::kMicrosecond);

/// The reference march (512 samples) along random upward rays.
void BM_CloudTransmittanceReference(benchmark::State& state) {
    const aerial::CloudField f = cumulus();
    std::mt19937_64 rng(2);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (auto _ : state) {
        const glm::dvec3 d = glm::normalize(glm::dvec3(u(rng), 0.3 + 0.7 * std::abs(u(rng)), u(rng)));
        benchmark::DoNotOptimize(aerial::cloudTransmittance(f, {0.0, 2.0, 0.0}, d));
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_CloudTransmittanceReference)->Unit(benchmark::kMicrosecond);

}  // namespace
