// bench_sky.cpp — the Nishita sky solver (128 x 64 table).
//
//   BM_SkySolve/layers:L/threads:T/rebuild:R/multiple:M
//       one solve; threads 0 = all hardware threads; rebuild 1 forces the
//       optical-depth table (and the Psi_ms LUT) to be rebuilt every time (the
//       full cost), 0 reuses them (parameters unchanged, only the sun moves);
//       multiple 0 = single scattering only (SkySolverDesc::singleScatteringOnly).
//       Wall time.
//   BM_SkyPerSun/spectral:S/threads:T
//       the per-sun solve the renderer runs (multiple scattering on, the
//       atmosphere's tables kept, only the sun moves) on T threads: S = 0 the
//       RGB SkySolver, 1 SpectralSkySolver (<aerial/sky_spectral.hpp>: two
//       passes at three wavelengths and their combination). Wall time.
//   BM_SkyKeyedHaze/tolerance:T
//       one solve of a haze that thickens by 0.1% per solve (hazy_sunset's
//       afternoon haze evaluated once per minute of its day), with
//       SkySolverDesc::multipleScatteringTolerance T x 1e-4 (0: the LUT is
//       rebuilt at every solve; 25: the default, kept while the sky moves
//       by under 0.25%); all threads, wall time. The counter `builds` is
//       the share of solves that rebuilt the LUT.
//   BM_SkyAmortisedRebuild
//       an amortised solve after a change of the atmosphere that rebuilds
//       the LUT, continueSolve(1) until done; counters: the longest step
//       of the median solve and of all [ms], and the steps (the whole,
//       wall time, is their sum).
//   BM_SkyReferenceSolve
//       the brute-force double-precision reference (tests/support) on 4 of
//       the 64 rows (260 directions, 1000 x 200 steps each); the counters give
//       the whole-table estimate (x16) and the speed-up of the solver (32
//       layers, all threads, table rebuilt) over it.
//   BM_SkyAmortisedRow
//       continueSolve(1): one row of an amortised solve on the caller.
//   BM_SkyTableLookup/sun:S
//       aerial::skyRadiance (the table sampled through its coordinates,
//       sky.hpp "Table coordinates") at 4096 random directions of the upper
//       hemisphere, for a sun at S = 30 deg (plain rows and columns) and S =
//       -0.3 deg written as -3 (rows crowded at the earth's shadow, columns
//       warped around its cap: searched per lookup); time per lookup.
//
//   build/sky/bench/aerial_bench --benchmark_filter=Sky
#include <aerial/sky.hpp>
#include <aerial/sky_spectral.hpp>

#include "sky_reference.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <vector>

namespace {

glm::dvec3 sunAt(double elevationDegrees) {
    const double e = elevationDegrees * aerial::kPi / 180.0, a = 0.6;
    return {std::sin(a) * std::cos(e), std::sin(e), -std::cos(a) * std::cos(e)};
}

void BM_SkySolve(benchmark::State& state) {
    aerial::SkySolverDesc desc;
    desc.layerCount = int(state.range(0));
    desc.threadCount = int(state.range(1));
    const bool rebuild = state.range(2) != 0;
    desc.singleScatteringOnly = state.range(3) == 0;
    aerial::SkySolver solver(desc);
    const aerial::AtmosphereParams air;
    solver.solve(air, sunAt(10.0));
    int k = 0;
    for (auto _ : state) {
        if (rebuild) solver.invalidateCache();
        solver.solve(air, sunAt(5.0 + (k++ % 8)));
        benchmark::DoNotOptimize(solver.table().rayleigh.data());
    }
    state.counters["threads"] = double(solver.desc().threadCount);
    state.counters["texels"] = double(desc.azimuthCount * desc.elevationCount);
}
BENCHMARK(BM_SkySolve)
    ->ArgNames({"layers", "threads", "rebuild", "multiple"})
    ->ArgsProduct({{32}, {1, 0}, {1, 0}, {0, 1}})
    ->Unit(benchmark::kMicrosecond)
    ->UseRealTime();

template <class Solver>
void solvePerSun(benchmark::State& state, Solver& solver) {
    const aerial::AtmosphereParams air;
    solver.solve(air, sunAt(10.0));
    int k = 0;
    for (auto _ : state) {
        solver.solve(air, sunAt(5.0 + (k++ % 8)));
        benchmark::DoNotOptimize(solver.table().rayleigh.data());
    }
    state.counters["threads"] = double(solver.desc().threadCount);
}

void BM_SkyPerSun(benchmark::State& state) {
    aerial::SkySolverDesc desc;
    desc.threadCount = int(state.range(1));
    if (state.range(0) != 0) {
        aerial::SpectralSkySolver solver(desc);
        solvePerSun(state, solver);
    } else {
        aerial::SkySolver solver(desc);
        solvePerSun(state, solver);
    }
}
BENCHMARK(BM_SkyPerSun)
    ->ArgNames({"spectral", "threads"})
    ->ArgsProduct({{0, 1}, {1, 2}})
    ->Unit(benchmark::kMicrosecond)
    ->UseRealTime();

void BM_SkyKeyedHaze(benchmark::State& state) {
    aerial::SkySolverDesc desc;
    desc.multipleScatteringTolerance = double(state.range(0)) * 1e-4;
    aerial::SkySolver solver(desc);
    aerial::AtmosphereParams air;
    air.mieScattering = glm::dvec3(1.2e-5);
    air.mieExtinction = glm::dvec3(1.4e-5);
    air.mieScaleHeight = 1600.0;
    air.mieAnisotropy = 0.86;
    solver.solve(air, sunAt(10.0));
    std::vector<float> lut = solver.multipleScatteringTable().psi;
    double builds = 0.0, solves = 0.0;
    int k = 0;
    for (auto _ : state) {
        // Thickening from 1.2e-5 and starting again after 50% (as a day does).
        const double grow = std::pow(1.001, double(k++ % 400));
        aerial::AtmosphereParams now = air;
        now.mieScattering *= grow;
        now.mieExtinction *= grow;
        solver.solve(now, sunAt(20.0 - 0.05 * (k % 400)));
        benchmark::DoNotOptimize(solver.table().rayleigh.data());
        state.PauseTiming();
        if (solver.multipleScatteringTable().psi != lut) {
            builds += 1.0;
            lut = solver.multipleScatteringTable().psi;
        }
        solves += 1.0;
        state.ResumeTiming();
    }
    state.counters["builds"] = solves > 0.0 ? builds / solves : 0.0;
    state.counters["threads"] = double(solver.desc().threadCount);
}
BENCHMARK(BM_SkyKeyedHaze)
    ->ArgName("tolerance")
    ->Arg(0)
    ->Arg(25)
    ->Unit(benchmark::kMicrosecond)
    ->UseRealTime();

void BM_SkyAmortisedRebuild(benchmark::State& state) {
    aerial::SkySolver solver;
    aerial::AtmosphereParams air;
    solver.solve(air, sunAt(10.0));
    std::vector<double> longest;  // per solve [ms]
    double steps = 0.0;
    int k = 0;
    for (auto _ : state) {
        // 40 hazes 5% apart (the shared cache keeps 4): every one rebuilt.
        air.mieScattering = glm::dvec3(3.996e-6 * std::pow(1.05, double(k++ % 40 + 1)));
        air.mieExtinction = air.mieScattering / 0.9;
        solver.beginSolve(air, sunAt(5.0));
        double worst = 0.0;
        for (bool done = false; !done; steps += 1.0) {
            const auto t0 = std::chrono::steady_clock::now();
            done = solver.continueSolve(1);
            worst = std::max(
                worst,
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
        }
        longest.push_back(worst);
    }
    // The median solve's longest step, and the longest of all (a page fault
    // or another process on this VM's two cores shows there).
    std::sort(longest.begin(), longest.end());
    state.counters["longest_step_ms"] = longest.empty() ? 0.0 : longest[longest.size() / 2];
    state.counters["longest_step_max_ms"] = longest.empty() ? 0.0 : longest.back();
    state.counters["steps"] = steps / double(std::max<std::int64_t>(state.iterations(), 1));
}
BENCHMARK(BM_SkyAmortisedRebuild)->Unit(benchmark::kMillisecond)->UseRealTime();

// Best wall time [s] of a full solve (table rebuilt) over a few repeats.
double solverSeconds(int layers) {
    aerial::SkySolverDesc desc;
    desc.layerCount = layers;
    aerial::SkySolver solver(desc);
    const aerial::AtmosphereParams air;
    double best = 1e9;
    for (int k = 0; k < 50; ++k) {
        solver.invalidateCache();
        const auto t0 = std::chrono::steady_clock::now();
        solver.solve(air, sunAt(10.0));
        best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
    return best;
}

void BM_SkyReferenceSolve(benchmark::State& state) {
    const aerial::AtmosphereParams air;
    const glm::dvec3 sun = sunAt(10.0);
    aerial::SkyTable table;
    constexpr int kRows[] = {0, 21, 42, 63};
    double seconds = 0.0;
    for (auto _ : state) {
        const auto t0 = std::chrono::steady_clock::now();
        for (int j : kRows) aerial::reference::solveTable(air, sun, 128, 64, table, j, j + 1);
        seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        benchmark::DoNotOptimize(table.rayleigh.data());
    }
    const double fullTable = seconds * 64.0 / 4.0;
    const double solver = solverSeconds(32);
    state.counters["full_table_s"] = fullTable;
    state.counters["solver_32_all_threads_ms"] = solver * 1e3;
    state.counters["speedup"] = fullTable / solver;
    state.SetLabel("4 of 64 rows (260 directions), scaled x16 to the whole table");
}
BENCHMARK(BM_SkyReferenceSolve)->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();

void BM_SkyTableLookup(benchmark::State& state) {
    const double sun = state.range(0) >= 0 ? double(state.range(0)) : 0.1 * double(state.range(0));
    aerial::SkySolver solver;
    const aerial::AtmosphereParams air;
    solver.solve(air, sunAt(sun));
    std::vector<glm::dvec3> views(4096);
    std::uint32_t seed = 12345;
    auto next = [&] { return (seed = seed * 1664525u + 1013904223u) / 4294967296.0; };
    for (glm::dvec3& v : views) {
        const double z = next(), a = 2.0 * aerial::kPi * next(), r = std::sqrt(1.0 - z * z);
        v = {r * std::sin(a), z, -r * std::cos(a)};
    }
    for (auto _ : state)
        for (const glm::dvec3& v : views)
            benchmark::DoNotOptimize(aerial::skyRadiance(solver.table(), air.mieAnisotropy, v, glm::dvec3(1.0)));
    state.SetItemsProcessed(state.iterations() * std::int64_t(views.size()));
}
BENCHMARK(BM_SkyTableLookup)->ArgName("sun")->Arg(30)->Arg(-3)->Unit(benchmark::kMicrosecond);

void BM_SkyAmortisedRow(benchmark::State& state) {
    aerial::SkySolverDesc desc;
    desc.layerCount = int(state.range(0));
    aerial::SkySolver solver(desc);
    const aerial::AtmosphereParams air;
    solver.solve(air, sunAt(10.0));  // builds the optical-depth table once
    int k = 0;
    for (auto _ : state) {
        if (!solver.solving()) {
            state.PauseTiming();
            solver.beginSolve(air, sunAt(5.0 + (k++ % 8)));
            state.ResumeTiming();
        }
        solver.continueSolve(1);
    }
}
BENCHMARK(BM_SkyAmortisedRow)->ArgName("layers")->Arg(32)->Arg(40)->Unit(benchmark::kMicrosecond);

}  // namespace
