// solver_shim.cpp — one sky solver behind a C interface, built into a
// shared library against any revision's aerial_core, so that
// sky_against.cpp can load two revisions into one process and time them
// side by side (scripts/sky_cost_against.sh). Built outside CMake by that
// script; the old revision's headers may lack newer SkySolverDesc fields
// (AERIAL_SHIM_SINGLE says whether singleScatteringOnly exists).
#include <aerial/sky.hpp>

#include <chrono>
#include <cmath>

namespace {

glm::dvec3 sunAt(double elevationDegrees) {
    const double e = elevationDegrees * aerial::kPi / 180.0, a = 0.6;
    return {std::sin(a) * std::cos(e), std::sin(e), -std::cos(a) * std::cos(e)};
}

struct Shim {
    aerial::SkySolver solver;
    aerial::AtmosphereParams air;
    int solves = 0;
    explicit Shim(const aerial::SkySolverDesc& d) : solver(d) {}
};

}  // namespace

/// A solver on `threads` threads (0: all), single scattering only where
/// `single` (and the revision has the switch), its atmosphere built.
extern "C" void* aerialShimCreate(int threads, int single) {
    aerial::SkySolverDesc desc;
    desc.threadCount = threads;
#if AERIAL_SHIM_SINGLE
    desc.singleScatteringOnly = single != 0;
#else
    (void)single;
#endif
    auto* shim = new Shim(desc);
    shim->solver.solve(shim->air, sunAt(10.0));
    return shim;
}

/// Wall time [ms] of one solve for the sun `elevation` deg up, after a solve
/// for a sun 1e-4 deg away (so that the timed one is a new light).
extern "C" double aerialShimSolveMs(void* handle, double elevation) {
    auto* shim = static_cast<Shim*>(handle);
    shim->solver.solve(shim->air, sunAt(elevation + ((++shim->solves) % 2 == 0 ? 1e-4 : -1e-4)));
    const auto t0 = std::chrono::steady_clock::now();
    shim->solver.solve(shim->air, sunAt(elevation));
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

extern "C" void aerialShimDestroy(void* handle) { delete static_cast<Shim*>(handle); }
