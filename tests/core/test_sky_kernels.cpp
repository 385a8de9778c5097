// test_sky_kernels.cpp — the sky solver's per-column kernels (private
// sky_kernels.hpp) against the standard library where they replace it.
#include "sky_kernels.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace aerial::detail {
namespace {

/// |a - b| in units of the last place of b (of the smallest normal double at b = 0).
double ulps(double a, double b) {
    const double m = std::abs(b);
    const double ulp = m > 0.0 ? std::nextafter(m, INFINITY) - m : 4.9e-324;
    return std::abs(a - b) / ulp;
}

// halfAngleKernel stands in for std::cos and std::sin of phi / 2 in the
// rows whose columns follow the earth's shadow. Near phi = pi (the
// anti-light point, where the shadow's cap is) cos(phi / 2) is tiny and all
// of its digits count: checked relative to itself there. With one Taylor
// term fewer the worst is 10 ulp (cosine) or 184 ulp (sine), tried.
TEST(SkyKernels, HalfAnglesWithinTwoUlpOfTheStandardLibrary) {
    constexpr double kPi = 3.141592653589793;
    std::vector<double> phi = {0.0, 1e-300, 1e-12, 0.5 * kPi, 0.5 * kPi + 1e-9, kPi, -1.0, 4.0};
    for (int i = 1; i <= 1000; ++i)
        phi.push_back(std::nextafter(kPi, 0.0) - 1e-15 * i);                       // at the anti-light point
    for (int i = 1; i <= 1000; ++i) phi.push_back(0.5 * kPi + 1e-13 * (i - 500));  // where the halves meet
    std::mt19937_64 rng(20261202);
    std::uniform_real_distribution<double> any(0.0, kPi);
    for (int i = 0; i < 200000; ++i) phi.push_back(any(rng));
    const int n = int(phi.size());
    std::vector<double> c(phi.size()), s(phi.size()), cp(phi.size());
    std::vector<float> cf(phi.size());
    halfAngleKernel(n, phi.data(), c.data(), s.data(), cp.data(), cf.data());
    double worstCos = 0.0, worstSin = 0.0, worstCosPhi = 0.0;
    for (int i = 0; i < n; ++i) {
        const double p = std::min(std::max(phi[std::size_t(i)], 0.0), kPi);  // the kernel clamps to [0, pi]
        const double rc = std::cos(0.5 * p), rs = std::sin(0.5 * p);
        worstCos = std::max(worstCos, ulps(c[std::size_t(i)], rc));
        worstSin = std::max(worstSin, ulps(s[std::size_t(i)], rs));
        // cos phi = (c - s)(c + s): within a few rounding errors of 1.
        worstCosPhi = std::max(worstCosPhi, std::abs(cp[std::size_t(i)] - (rc - rs) * (rc + rs)));
        ASSERT_EQ(cf[std::size_t(i)], float(cp[std::size_t(i)])) << "phi " << phi[std::size_t(i)];
    }
    std::printf("[ kernels ] half angles: cos %.1f ulp, sin %.1f ulp, cos phi %.2g\n", worstCos, worstSin,
                worstCosPhi);
    EXPECT_LE(worstCos, 2.0);
    EXPECT_LE(worstSin, 2.0);
    EXPECT_LE(worstCosPhi, 1e-15);
}

}  // namespace
}  // namespace aerial::detail
