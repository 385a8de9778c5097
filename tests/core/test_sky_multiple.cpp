// test_sky_multiple.cpp — the sky's multiple scattering (Hillaire 2020
// Psi_ms LUT, <aerial/sky.hpp>): the solver's total radiance against a Monte
// Carlo path tracer written apart from it (tests/support/ms_reference.hpp)
// plus the exact single-scattering integral, and the LUT's properties
// (finite, positive, zero without scattering, ground albedo ordering,
// bit-identical across thread counts and amortised solves).
//
// Error metric of the reference comparison: per direction and channel
// |L_solver - L_ref| / max(L_ref, 1% of the brightest reference radiance of
// that sun over the compared directions and channels); the worst per sun is
// printed. Under AddressSanitizer / UndefinedBehaviorSanitizer builds (or
// with AERIAL_TEST_QUICK set) the comparison runs 2 of the 7 sun elevations
// (+10 and +90 deg) with 4096 paths per direction: that pass checks memory,
// not convergence (0.015 and 0.022 against the 5% bound, as against 0.017
// and 0.016 with the release pass's 16384).
#include <aerial/atmosphere.hpp>
#include <aerial/sky.hpp>
#include <aerial/sky_reference.hpp>

#include "ms_reference.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <vector>

#include "quick_run.hpp"

namespace aerial {
namespace {

constexpr double kDeg = kPi / 180.0;

glm::dvec3 direction(double elevationDeg, double azimuthDeg) {
    const double e = elevationDeg * kDeg, a = azimuthDeg * kDeg;
    return {std::sin(a) * std::cos(e), std::sin(e), -std::cos(a) * std::cos(e)};
}

bool quick() { return test::quickRun(); }

struct SunCase {
    double elevation;
    double tolerance;
    int paths;  // per direction: the twilight references need more to settle
};

// The goal is 5% at every sun, and that is the bound. Measured with these
// paths and seeds: -6: 0.045, -2: 0.032, 0: 0.024, +2: 0.023, +10: 0.017,
// +30: 0.012, +90: 0.017 (with Mie's straight-on cone at 6 deg instead of
// 4.5, sky_multiple.hpp: 0.045, 0.032, 0.026, 0.024, 0.021, 0.016, 0.016;
// without Mie's last scattering at the view nodes,
// sky_multiple.hpp, "Mie's last scattering": 0.129, 0.055, 0.041, 0.024,
// 0.014, 0.013, 0.013, so -6 and -2 deg fail); with 262144 paths and
// another seed (11): 0.042, 0.030, 0.027, 0.023, 0.019, 0.016, 0.014,
// against 0.122, 0.055, 0.042, 0.027, 0.013, 0.013, 0.013 before (at the 16384
// paths this test took before, the -6 deg references moved by up to 0.06
// between seeds and the -2 deg one read 0.046 where the converged figure
// was 0.055: twilight references below 131072 paths are not to be trusted
// to 1%). The worst was the sun's side of the horizon in blue, 0.88x.
// History (16384 paths): with five explicit orders and Mie's straight-on
// share -6: 0.123, -2: 0.046, 0: 0.035, +2: 0.024, +10: 0.014, +30: 0.013,
// +90: 0.013; three explicit orders and the delta through the Fejer window
// only: -6: 0.144, -2: 0.067, 0: 0.054, +2: 0.042, +10: 0.023, +30: 0.020,
// +90: 0.018; before delta-M -6: 0.36, -2: 0.114, 0: 0.047, +2: 0.038,
// +10: 0.014, +30: 0.011, +90: 0.018; with L_1's moments only (2048
// paths) -6: 0.39, -2: 0.135, 0: 0.069, +2: 0.065, +10: 0.032, +30: 0.019,
// +90: 0.021, and with the isotropic LUT they were bounded by 0.50, 0.30,
// 0.35, 0.14, 0.10, 0.07 and 0.06.
// At sun 0 the probe (0, 180) lies exactly on the earth's shadow (the light
// grazes the ground at the viewer), where the exact single scattering is a
// knife edge (0 just below, twice the probed value just above): left out
// there, as in test_sky's off-texel probes.
const SunCase kSuns[] = {{-6.0, 0.05, 262144}, {-2.0, 0.05, 131072}, {0.0, 0.05, 131072}, {2.0, 0.05, 16384},
                         {10.0, 0.05, 16384},  {30.0, 0.05, 16384},  {90.0, 0.05, 16384}};

/// The worst error of the solver's total radiance against the tracer's
/// multiple scattering plus the exact single scattering, over 13 directions
/// (the horizon included) for a sun `sunElevation` deg up, `paths` paths per
/// direction; prints its line of the report.
double worstAgainstTracer(const AtmosphereParams& air, const reference::MultipleScatteringTracer& tracer,
                          SkySolver& solver, double sunElevation, int paths) {
    SkyReferenceSettings single;
    single.viewSteps = 512;
    single.lightSteps = 128;
    const glm::dvec3 light = direction(sunElevation, 0.0);
    solver.solve(air, light);
    struct Probe {
        double el, az;
        glm::dvec3 solver, ref, ms;
    };
    std::vector<Probe> probes;
    double brightest = 0.0;
    for (double el : {0.0, 2.0, 10.0, 45.0, 90.0}) {
        for (double az : {0.0, 90.0, 180.0}) {
            if (el == 90.0 && az > 0.0) continue;
            if (sunElevation == 0.0 && el == 0.0 && az == 180.0) continue;  // the knife edge (above)
            const glm::dvec3 v = direction(el, az);
            Probe p{el, az, skyRadiance(solver.table(), air.mieAnisotropy, v, glm::dvec3(1.0)),
                    glm::dvec3(0.0), glm::dvec3(0.0)};
            p.ms = tracer.multipleScattering(v, light, paths, 1234 + probes.size());
            p.ref = referenceSkyRadiance(air, v, light, glm::dvec3(1.0), single) + p.ms;
            for (int c = 0; c < 3; ++c) brightest = std::max(brightest, p.ref[c]);
            probes.push_back(p);
        }
    }
    double worst = 0.0;
    const Probe* at = nullptr;
    int channel = 0;
    for (const Probe& p : probes) {
        for (int c = 0; c < 3; ++c) {
            const double err = std::abs(p.solver[c] - p.ref[c]) / std::max(p.ref[c], 0.01 * brightest);
            if (err > worst) {
                worst = err;
                at = &p;
                channel = c;
            }
        }
    }
    if (at == nullptr) {
        ADD_FAILURE() << "no probe compared at sun " << sunElevation;
        return INFINITY;
    }
    std::printf(
        "[ sky ms  ] %+6.1f   | %9.3f   | (%4.0f, %4.0f)                   | %c       | %.4g / %.4g | "
        "%.2f\n",
        sunElevation, worst, at->el, at->az, "RGB"[channel], at -> solver[channel], at -> ref[channel],
        at -> ms[channel] / at -> ref[channel]);
    return worst;
}

constexpr char kReportHeader[] =
    "[ sky ms  ] sun elev | worst error | at (elev, azimuth from the sun) | channel | "
    "solver / reference total | multiple / total (ref)\n";

TEST(SkyMultiple, TotalRadianceAgainstPathTracer) {
    const AtmosphereParams air;
    const reference::MultipleScatteringTracer tracer(air);
    // Fewer paths add Monte Carlo noise the tolerances were not measured
    // with; AERIAL_MS_PATHS sets another count (for every sun) for a report.
    const char* pathsEnv = std::getenv("AERIAL_MS_PATHS");
    SkySolver solver;
    std::printf("%s", kReportHeader);
    for (const SunCase& sun : kSuns) {
        // The sanitizer pass checks memory, not convergence: the two suns
        // with 16384 paths (the twilight ones take 8-16x longer), with a
        // quarter of them (the tracer under ASan is ~14x slower).
        if (quick() && sun.elevation != 10.0 && sun.elevation != 90.0) continue;
        const int paths = pathsEnv != nullptr ? std::clamp(std::atoi(pathsEnv), 256, 1 << 20)
                          : quick()           ? sun.paths / 4
                                              : sun.paths;
        EXPECT_LT(worstAgainstTracer(air, tracer, solver, sun.elevation, paths), sun.tolerance)
            << "sun " << sun.elevation;
    }
}

// hazy_sunset's air (Mie 2.2e-5 /m, extinction 2.6e-5 /m, scale height 1600
// m, g = 0.86): the 5% goal is not met in a haze this thick, so these are
// regression bounds a little above the measured worst (65536 paths, these
// seeds): -6: 0.135, -2: 0.091, +10: 0.045. With Mie's straight-on cone at
// 6 deg instead of 4.5 (sky_multiple.hpp, "Mie's last scattering") they
// were 0.151, 0.234, 0.049 (the sun's side of the horizon at -2 deg, red
// 1.23x), and before Mie's last scattering at the view nodes (131072
// paths, seed 11) 0.48, 0.23 and 0.099.
TEST(SkyMultiple, HazyAirAgainstPathTracer) {
    if (quick()) GTEST_SKIP() << "65536 paths per direction: release builds only";
    AtmosphereParams air;
    air.mieScattering = glm::dvec3(2.2e-5);
    air.mieExtinction = glm::dvec3(2.6e-5);
    air.mieScaleHeight = 1600.0;
    air.mieAnisotropy = 0.86;
    const reference::MultipleScatteringTracer tracer(air);
    SkySolver solver;
    std::printf("%s", kReportHeader);
    const SunCase hazy[] = {{-6.0, 0.15, 65536}, {-2.0, 0.10, 65536}, {10.0, 0.05, 65536}};
    for (const SunCase& sun : hazy)
        EXPECT_LT(worstAgainstTracer(air, tracer, solver, sun.elevation, sun.paths), sun.tolerance)
            << "sun " << sun.elevation;
}

// The LUT's own assumption made true: with isotropic phase functions at
// every scattering the in-scattered field is isotropic at each point, and
// the LUT's explicit orders (sky_multiple.hpp: J_2, then J_3 .. J_5 each from the one before along every
// direction, the ground's reflection of the skylight, a geometric tail) must
// match the path tracer's orders >= 2 direction by direction. Hillaire's
// local geometric series alone came out 0.67-0.93 at sun 0 (fails here) and
// 0.96-1.00 at the zenith sun (8192 paths); with the explicit orders the
// measured band is 0.92-1.07 over these suns. Within 10%: the quadrature
// (96 directions, 24 layers, 64 sun cosines) and 4096 paths' noise. The
// solver's LUT runs with Hillaire's isotropic phases here
// (SkySolverDesc::isotropicMultipleScattering), as the tracer; with the real
// phases its second order is view-dependent, up to 1.7x off this tracer.
TEST(SkyMultiple, IsotropicOrdersAgainstPathTracer) {
    const AtmosphereParams air;
    const reference::MultipleScatteringTracer tracer(air,
                                                     reference::MultipleScatteringTracer::Phase::Isotropic);
    SkySolverDesc isotropic;  // the LUT with Hillaire's isotropic phases, as the tracer
    isotropic.isotropicMultipleScattering = true;
    SkySolver solver(isotropic);
    for (double sunElevation : {-2.0, 0.0, 10.0, 90.0}) {
        if (quick() && sunElevation != 10.0) continue;
        const glm::dvec3 light = direction(sunElevation, 0.0);
        solver.solve(air, light);
        double lowest = 1e9, highest = 0.0;
        for (double el : {0.0, 2.0, 10.0, 45.0, 90.0}) {
            for (double az : {0.0, 90.0, 180.0}) {
                if (el == 90.0 && az > 0.0) continue;
                const glm::dvec3 v = direction(el, az);
                const glm::dvec3 got = sampleSkyTable(solver.table(), v).multiple;
                const glm::dvec3 ref = tracer.multipleScattering(v, light, 4096, 4321);
                for (int c = 0; c < 3; ++c) {
                    ASSERT_GT(ref[c], 0.0) << el << " " << az;
                    const double ratio = got[c] / ref[c];
                    lowest = std::min(lowest, ratio);
                    highest = std::max(highest, ratio);
                    EXPECT_NEAR(ratio, 1.0, 0.10)
                        << "sun " << sunElevation << " at " << el << ", " << az << " "
                        << "RGB"[c];
                }
            }
        }
        std::printf(
            "[ sky ms  ] sun %+5.1f, isotropic phases: multiple scattering solver / tracer %.3f .. %.3f\n",
            sunElevation, lowest, highest);
    }
}

// Deep twilight (nautical, sun 9-11 deg below the horizon): no air near the
// viewer is lit, the sky is light scattered twice or more from the sunlit
// upper atmosphere far towards the sun, and its zenith is blue (the light
// crossed the ozone layer edge-on). The Psi_ms quadrature must find that thin
// lit region from every height: with Hillaire's 64 uniform directions the
// solver's sky above 10 deg was 10-100x too dark and red (blue / red at the
// zenith 0.06 against the reference's 1.8 at -11 deg). The band is a factor
// 2.5 per channel (the isotropic, local approximation's limit there; the
// measured worst is printed), over directions from 10 deg up; 16384 paths,
// as fewer leave the reference itself too noisy at these depressions (at
// -14 deg even 16384 leave its zenith red or blue by the seed).
TEST(SkyMultiple, DeepTwilightAgainstPathTracer) {
    if (quick()) GTEST_SKIP() << "16384 paths per direction: release builds only";
    const AtmosphereParams air;
    const reference::MultipleScatteringTracer tracer(air);
    SkyReferenceSettings single;
    single.viewSteps = 512;
    single.lightSteps = 128;
    SkySolver solver;
    for (double sunElevation : {-9.0, -11.0}) {
        const glm::dvec3 light = direction(sunElevation, 0.0);
        solver.solve(air, light);
        double lowest = 1e9, highest = 0.0;
        for (double el : {10.0, 45.0, 90.0}) {
            for (double az : {0.0, 90.0, 180.0}) {
                if (el == 90.0 && az > 0.0) continue;
                const glm::dvec3 v = direction(el, az);
                const glm::dvec3 got = skyRadiance(solver.table(), air.mieAnisotropy, v, glm::dvec3(1.0));
                const glm::dvec3 ref = referenceSkyRadiance(air, v, light, glm::dvec3(1.0), single) +
                                       tracer.multipleScattering(v, light, 16384, 99);
                for (int c = 0; c < 3; ++c) {
                    ASSERT_GT(ref[c], 0.0) << el << " " << az;
                    const double ratio = got[c] / ref[c];
                    lowest = std::min(lowest, ratio);
                    highest = std::max(highest, ratio);
                    EXPECT_GT(ratio, 1.0 / 2.5) << "sun " << sunElevation << " at " << el << ", " << az << " "
                                                << "RGB"[c];
                    EXPECT_LT(ratio, 2.5) << "sun " << sunElevation << " at " << el << ", " << az << " "
                                          << "RGB"[c];
                }
                if (el == 90.0) {
                    // The zenith is blue in both.
                    EXPECT_GT(ref.b, ref.r) << "sun " << sunElevation;
                    EXPECT_GT(got.b, got.r) << "sun " << sunElevation;
                }
            }
        }
        std::printf(
            "[ sky ms  ] sun %+5.1f: solver / reference from %.2f to %.2f (10-90 deg, 3 azimuths, RGB)\n",
            sunElevation, lowest, highest);
    }
}

TEST(SkyMultiple, LutIsFiniteAndPositive) {
    AtmosphereParams air;
    SkySolver solver;
    solver.solve(air, direction(10.0, 0.0));
    const MultipleScatteringTable lut = solver.multipleScatteringTable();
    ASSERT_GT(lut.heightCount, 1);
    ASSERT_GT(lut.cosineCount, 1);
    ASSERT_EQ(lut.psi.size(), std::size_t(lut.heightCount) * lut.cosineCount * 3);
    for (float x : lut.psi) {
        ASSERT_TRUE(std::isfinite(x));
        ASSERT_GE(x, 0.0f);
    }
    // A sun above the horizon lights every height: strictly positive there.
    for (int row = 0; row < lut.heightCount; ++row) {
        for (int j = 0; j < lut.cosineCount; ++j) {
            if (!(lut.cosines[std::size_t(j)] > 0.05)) continue;
            for (int c = 0; c < 3; ++c) {
                EXPECT_GT(lut.psi[(std::size_t(row) * lut.cosineCount + j) * 3 + c], 0.0f) << row << " " << j;
            }
        }
    }
    EXPECT_DOUBLE_EQ(lut.heights.front(), 0.0);
    EXPECT_DOUBLE_EQ(lut.heights.back(), air.atmosphereRadius - air.planetRadius);
    EXPECT_DOUBLE_EQ(lut.cosines.front(), -1.0);
    EXPECT_DOUBLE_EQ(lut.cosines.back(), 1.0);
    for (float x : solver.table().multiple) ASSERT_TRUE(std::isfinite(x) && x >= 0.0f);
}

TEST(SkyMultiple, ZeroWithoutScattering) {
    AtmosphereParams air;
    air.rayleighScattering = glm::dvec3(0.0);
    air.mieScattering = glm::dvec3(0.0);
    SkySolver solver;
    solver.solve(air, direction(20.0, 0.0));
    for (float x : solver.table().multiple) ASSERT_EQ(x, 0.0f);
    EXPECT_EQ(solver.table().horizonMultiple, glm::dvec3(0.0));
}

// A fog-thick haze (Mie 0.2 /m: 20 m visibility): the straight-on share's
// e^(f tau_M) would overflow on its own (f tau_M ~ 1e4 along the horizon)
// where the view transmittance underflows; their product must stay finite
// and the horizon keep its multiple scattering (0 * inf gave NaN there,
// which the solver's guards turned into a horizon without any).
TEST(SkyMultiple, ThickHazeKeepsItsMultipleScattering) {
    AtmosphereParams air;
    air.mieScattering = glm::dvec3(0.2);
    air.mieExtinction = air.mieScattering / 0.9;
    SkySolver solver;
    const glm::dvec3 light = direction(10.0, 0.0);
    solver.solve(air, light);
    for (float x : solver.table().multiple) ASSERT_TRUE(std::isfinite(x) && x >= 0.0f);
    for (float x : solver.table().mie) ASSERT_TRUE(std::isfinite(x) && x >= 0.0f);
    for (int c = 0; c < 3; ++c) EXPECT_GT(solver.table().horizonMultiple[c], 0.0) << c;
    for (double azimuth : {0.0, 90.0, 180.0}) {
        for (double elevation : {0.0, 0.5, 3.0}) {
            const SkySample at = sampleSkyTable(solver.table(), direction(elevation, azimuth));
            for (int c = 0; c < 3; ++c) {
                EXPECT_TRUE(std::isfinite(at.multiple[c]));
                EXPECT_GT(at.multiple[c], 0.0) << elevation << " " << azimuth << " " << c;
            }
        }
    }
}

TEST(SkyMultiple, GroundAlbedoBrightensTheSky) {
    AtmosphereParams dark, bright;
    dark.groundAlbedo = glm::dvec3(0.0);
    bright.groundAlbedo = glm::dvec3(1.0);
    SkySolver a, b;
    a.solve(dark, direction(30.0, 0.0));
    b.solve(bright, direction(30.0, 0.0));
    const std::vector<float>& x = a.table().multiple;
    const std::vector<float>& y = b.table().multiple;
    ASSERT_EQ(x.size(), y.size());
    for (std::size_t i = 0; i < x.size(); ++i) ASSERT_LT(x[i], y[i]) << i;
    // Single scattering does not see the ground.
    EXPECT_EQ(a.table().rayleigh, b.table().rayleigh);
    EXPECT_EQ(a.table().mie, b.table().mie);
}

TEST(SkyMultiple, SingleScatteringChannelsUnchanged) {
    AtmosphereParams air;
    SkySolverDesc only;
    only.singleScatteringOnly = true;
    SkySolver a, b(only);
    a.solve(air, direction(3.0, 40.0));
    b.solve(air, direction(3.0, 40.0));
    EXPECT_EQ(a.table().rayleigh, b.table().rayleigh);
    EXPECT_EQ(a.table().mie, b.table().mie);
    for (float x : b.table().multiple) ASSERT_EQ(x, 0.0f);
    EXPECT_TRUE(b.multipleScatteringTable().psi.empty());
}

TEST(SkyMultiple, BitIdenticalAcrossThreadsAndAmortised) {
    AtmosphereParams air;
    air.mieScattering = glm::dvec3(12e-6);
    air.mieExtinction = air.mieScattering / 0.9;
    const glm::dvec3 light = direction(-3.0, 120.0);
    SkySolverDesc one;
    one.threadCount = 1;
    SkySolverDesc many;
    many.threadCount = 4;
    SkySolver a(one), b(many), c(many);
    // Each builds the atmosphere's tables itself (not adopting another's:
    // SharedAtmosphereTablesAreBitIdentical).
    for (SkySolver* s : {&a, &b, &c}) s->invalidateCache();
    a.solve(air, light);
    b.solve(air, light);
    c.beginSolve(air, light);
    while (!c.continueSolve(5)) {
    }
    EXPECT_EQ(a.table().multiple, b.table().multiple);
    EXPECT_EQ(a.table().multiple, c.table().multiple);
    EXPECT_EQ(a.table().horizonMultiple, b.table().horizonMultiple);
    EXPECT_EQ(a.multipleScatteringTable().psi, b.multipleScatteringTable().psi);
    // The cached LUT gives the same result as a rebuilt one.
    b.solve(air, light);
    EXPECT_EQ(a.table().multiple, b.table().multiple);
}

// Solvers share the atmosphere's tables (sky.hpp, SkySolver): one that
// adopts what another built (other thread count, other light, amortised or
// not) gives exactly the table of one that builds them itself, and a
// solver with other multiple-scattering settings or other air never adopts
// them.
TEST(SkyMultiple, SharedAtmosphereTablesAreBitIdentical) {
    AtmosphereParams air;
    air.mieScattering = glm::dvec3(17e-6);  // air no other test solves
    air.mieExtinction = air.mieScattering / 0.9;
    const glm::dvec3 sun = direction(-1.5, 30.0), moon = direction(25.0, 200.0);
    SkySolverDesc two;
    two.threadCount = 2;
    SkySolverDesc one;
    one.threadCount = 1;
    SkySolver builder(two);
    builder.invalidateCache();
    builder.solve(air, sun);
    auto expectSame = [](const SkySolver& x, const SkySolver& y, const char* what) {
        EXPECT_EQ(x.table().rayleigh, y.table().rayleigh) << what;
        EXPECT_EQ(x.table().mie, y.table().mie) << what;
        EXPECT_EQ(x.table().multiple, y.table().multiple) << what;
        EXPECT_EQ(x.table().horizonMultiple, y.table().horizonMultiple) << what;
        EXPECT_EQ(x.multipleScatteringTable().psi, y.multipleScatteringTable().psi) << what;
    };
    for (const glm::dvec3& light : {sun, moon}) {
        SkySolver adopter(one), amortised(one), fresh(one);
        adopter.solve(air, light);
        amortised.beginSolve(air, light);
        while (!amortised.continueSolve(7)) {
        }
        fresh.invalidateCache();
        fresh.solve(air, light);
        expectSame(adopter, fresh, "adopted");
        expectSame(amortised, fresh, "adopted, amortised");
    }
    // A solver that may adopt against one that builds, for the sun: the
    // first (returned) must come out as the second.
    auto againstFresh = [&](const SkySolverDesc& desc, const AtmosphereParams& a, const char* what) {
        auto solver = std::make_unique<SkySolver>(desc);
        SkySolver fresh(desc);
        solver->solve(a, sun);
        fresh.invalidateCache();
        fresh.solve(a, sun);
        expectSame(*solver, fresh, what);
        return solver;
    };
    // Isotropic multiple scattering has its own LUT: not the shared one.
    SkySolverDesc iso = one;
    iso.isotropicMultipleScattering = true;
    const auto isotropic = againstFresh(iso, air, "isotropic");
    EXPECT_NE(isotropic->multipleScatteringTable().psi, builder.multipleScatteringTable().psi);
    // Other air (one byte of it: the viewer's height) is built anew.
    AtmosphereParams higher = air;
    higher.viewerHeight = 1.0;
    const auto other = againstFresh(one, higher, "other air");
    EXPECT_NE(other->table().multiple, builder.table().multiple);
}

// The view-ray integral of the LUT, I_ms(v) = integral T(viewer -> x)
// sigma_s(h) Psi_ms(h, mu_s) ds (isotropic LUT: no A_X), by brute force
// along each ray (4000 steps crowded at the viewer; Psi linear in height
// between the LUT's rows and geometric between its sun cosines, as the
// solver reads it) against the table, at random directions between the
// texels and between the 16 azimuths the solver integrates before spreading
// them into its columns (sky.hpp). Error relative to the pixel's multiple
// scattering, floored at 1% of the brightest; measured worst 0.4-0.9% (the
// solver's layers, linear Psi along each), the bound 2%.
glm::dvec3 lutAlongRay(const AtmosphereParams& air, const MultipleScatteringTable& lut, const glm::dvec3& v,
                       const glm::dvec3& light) {
    const double rg = air.planetRadius, rt = air.atmosphereRadius, r0 = rg + air.viewerHeight;
    const double top = -r0 * v.y + std::sqrt(r0 * r0 * v.y * v.y - r0 * r0 + rt * rt);
    auto psiAt = [&](double h, double mu, int c) {
        const int rows = lut.heightCount, cols = lut.cosineCount;
        int i = 0;
        while (i + 2 < rows && lut.heights[std::size_t(i) + 1] < h) ++i;
        const double fh = std::clamp((h - lut.heights[std::size_t(i)]) /
                                         (lut.heights[std::size_t(i) + 1] - lut.heights[std::size_t(i)]),
                                     0.0, 1.0);
        int j = 0;
        while (j + 2 < cols && lut.cosines[std::size_t(j) + 1] < mu) ++j;
        const double fc = std::clamp((mu - lut.cosines[std::size_t(j)]) /
                                         (lut.cosines[std::size_t(j) + 1] - lut.cosines[std::size_t(j)]),
                                     0.0, 1.0);
        auto lnPsi = [&](int jj) {
            const auto at = [&](int ii) { return double(lut.psi[(std::size_t(ii) * cols + jj) * 3 + c]); };
            return std::log(std::max(at(i) + fh * (at(i + 1) - at(i)), 1e-30));
        };
        return std::exp(lnPsi(j) + fc * (lnPsi(j + 1) - lnPsi(j)));
    };
    constexpr int kSteps = 4000;
    glm::dvec3 tau(0.0), sum(0.0);
    for (int k = 0; k < kSteps; ++k) {
        const double t = (k + 0.5) / kSteps, s = top * t * t, ds = top * 2.0 * t / kSteps;
        const glm::dvec3 x = glm::dvec3(0.0, r0, 0.0) + s * v;
        const double r = std::sqrt(x.x * x.x + x.y * x.y + x.z * x.z), h = r - rg;
        const double mu = (x.x * light.x + x.y * light.y + x.z * light.z) / r;
        const glm::dvec3 ext = extinctionAt(air, h);
        const double rho[2] = {rayleighDensity(air, h), mieDensity(air, h)};
        for (int c = 0; c < 3; ++c) {
            const double sigma = air.rayleighScattering[c] * rho[0] + air.mieScattering[c] * rho[1];
            sum[c] += std::exp(-(tau[c] + 0.5 * ext[c] * ds)) * sigma * psiAt(h, mu, c) * ds;
            tau[c] += ext[c] * ds;
        }
    }
    return sum;
}

TEST(SkyMultiple, TableAgainstTheLutAlongTheViewRays) {
    const AtmosphereParams air;
    SkySolverDesc isotropic;
    isotropic.isotropicMultipleScattering = true;
    SkySolver solver(isotropic);
    unsigned seed = 2024u;
    auto uniform = [&] {
        seed = seed * 1664525u + 1013904223u;
        return double(seed >> 8) / 16777216.0;
    };
    for (double sun : {-4.0, -1.0, 0.5, 5.0, 30.0}) {
        if (quick() && sun != 5.0) continue;
        const glm::dvec3 light = direction(sun, 37.0);
        solver.solve(air, light);
        const MultipleScatteringTable lut = solver.multipleScatteringTable();
        std::vector<glm::dvec3> dirs, refs;
        double brightest = 0.0;
        for (int n = 0; n < 60; ++n) {
            const double el = (n % 3 == 0 ? 3.0 : 90.0) * uniform() * uniform();  // a third within 3 deg
            dirs.push_back(direction(el, 360.0 * uniform()));
            refs.push_back(lutAlongRay(air, lut, dirs.back(), light));
            for (int c = 0; c < 3; ++c) brightest = std::max(brightest, refs.back()[c]);
        }
        double worst = 0.0;
        for (std::size_t n = 0; n < dirs.size(); ++n) {
            const glm::dvec3 got = sampleSkyTable(solver.table(), dirs[n]).multiple;
            for (int c = 0; c < 3; ++c)
                worst =
                    std::max(worst, std::abs(got[c] - refs[n][c]) / std::max(refs[n][c], 0.01 * brightest));
        }
        std::printf("[ sky ms  ] sun %+5.1f: table against the LUT along 60 view rays, worst %.4f\n", sun,
                    worst);
        EXPECT_LT(worst, 0.02) << "sun " << sun;
    }
}

// The rows that take their multiple scattering from the rows around them
// (a cubic in elevation at the kMsSkyColumns azimuths, sky_solver.cpp,
// "Multiple scattering between rows") against a solver that integrates it
// along every row's view rays: the change of the total radiance relative to
// the pixel (floored at 1% of the brightest) over random directions, a third
// within 5 deg of the horizon. Measured worst: the default air 0.21%,
// hazy_sunset's 0.23% (both a light 0.005 deg down). Taken linear in
// elevation instead of cubic it was 0.93% (hazy, sun 0); with the rows that
// have a view node of Mie's last scattering between their neighbours taken
// too (the kink there), 0.80% (hazy, sun -0.05): both fail.
TEST(SkyMultiple, RowsBetweenMatchEveryRowIntegrated) {
    AtmosphereParams hazy;
    hazy.mieScattering = glm::dvec3(2.2e-5);
    hazy.mieExtinction = glm::dvec3(2.6e-5);
    hazy.mieScaleHeight = 1600.0;
    hazy.mieAnisotropy = 0.86;
    SkySolverDesc every;
    every.multipleScatteringEveryRow = true;
    SkySolver between, integrated(every);
    unsigned seed = 77u;
    auto uniform = [&] {
        seed = seed * 1664525u + 1013904223u;
        return double(seed >> 8) / 16777216.0;
    };
    double worst = 0.0;
    for (const AtmosphereParams& air : {AtmosphereParams{}, hazy}) {
        // Down to a light just set, where the cap's rows crowd at the horizon
        // (2.2% at -0.00002 deg with nodes crowded on one side).
        for (double sun :
             {-6.0, -2.0, -0.5, -0.2, -0.05, -0.005, -0.0005, -0.00002, 0.0, 2.0, 10.0, 45.0, 90.0}) {
            if (quick() && sun != -0.5 && sun != -0.00002 && sun != 10.0) continue;
            const glm::dvec3 light = direction(sun, 23.0);
            between.solve(air, light);
            integrated.solve(air, light);
            std::vector<glm::dvec3> dirs, refs;
            double brightest = 0.0;
            for (int n = 0; n < 3000; ++n) {
                const double el = n % 3 == 0 ? 5.0 * uniform() * uniform() : 90.0 * uniform();
                dirs.push_back(direction(el, 360.0 * uniform()));
                refs.push_back(
                    skyRadiance(integrated.table(), air.mieAnisotropy, dirs.back(), glm::dvec3(1.0)));
                for (int c = 0; c < 3; ++c) brightest = std::max(brightest, refs.back()[c]);
            }
            double here = 0.0;
            for (std::size_t n = 0; n < dirs.size(); ++n) {
                const glm::dvec3 got =
                    skyRadiance(between.table(), air.mieAnisotropy, dirs[n], glm::dvec3(1.0));
                for (int c = 0; c < 3; ++c)
                    here = std::max(here,
                                    std::abs(got[c] - refs[n][c]) / std::max(refs[n][c], 0.01 * brightest));
            }
            std::printf(
                "[ sky ms  ] %s air, sun %+9.5f: rows between against every row integrated, worst %.4f\n",
                air.mieAnisotropy == hazy.mieAnisotropy ? "hazy_sunset's" : "default", sun, here);
            worst = std::max(worst, here);
            EXPECT_LT(here, 0.004) << "sun " << sun;
        }
    }
    EXPECT_GT(worst, 0.0);  // the rows between are taken, not integrated
}

TEST(SkyMultiple, HorizonAverageAndFogColour) {
    AtmosphereParams air;
    SkySolver solver;
    solver.solve(air, direction(6.0, 0.0));
    const SkyTable& t = solver.table();
    glm::dvec3 sum(0.0);
    for (int i = 0; i < t.azimuthCount; ++i)
        for (int c = 0; c < 3; ++c) sum[c] += t.multiple[std::size_t(i) * 3 + c];
    for (int c = 0; c < 3; ++c) {
        EXPECT_GT(t.horizonMultiple[c], 0.0);
        EXPECT_NEAR(t.horizonMultiple[c], sum[c] / t.azimuthCount, 1e-12 * sum[c]);
    }
    // Far fog and the sky: the isotropic term is added as it is (towards the
    // horizon, the fog takes row 0 behind it: the sky's own sample there).
    const glm::dvec3 v = direction(0.0, 90.0), e(2.0);
    const SkySample s = sampleSkyTable(t, v);
    const glm::dvec3 withMs = skyRadiance(t, air.mieAnisotropy, v, e);
    SkyTable noMs = t;
    std::fill(noMs.multiple.begin(), noMs.multiple.end(), 0.0f);
    noMs.horizonMultiple = glm::dvec3(0.0);
    const glm::dvec3 without = skyRadiance(noMs, air.mieAnisotropy, v, e);
    const glm::dvec3 fogWith = horizonFogRadiance(t, air.mieAnisotropy, v, e);
    const glm::dvec3 fogWithout = horizonFogRadiance(noMs, air.mieAnisotropy, v, e);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(withMs[c] - without[c], e[c] * s.multiple[c], 1e-12);
        EXPECT_NEAR(fogWith[c] - fogWithout[c], e[c] * s.multiple[c], 1e-12);
    }
}

}  // namespace
}  // namespace aerial
