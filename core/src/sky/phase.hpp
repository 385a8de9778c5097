// phase.hpp — private: the phase functions' formulas for a cosine already
// in [-1, 1] and an anisotropy already in [-0.999, 0.999], the one place
// they are written. atmosphere.cpp's rayleighPhase and miePhase clamp their
// arguments and call these; the sky solver's straight-on kernel
// (sky_kernels*.cpp) calls them per column, inlined into its vector clones.
// Model: ../shared/DESIGN.md, "Sky" (Rayleigh; Cornette-Shanks for Mie).
#pragma once

#include <algorithm>
#include <cmath>

#if defined(__GNUC__)
#define AERIAL_PHASE_INLINE inline __attribute__((always_inline))
#else
#define AERIAL_PHASE_INLINE inline
#endif

namespace aerial::detail {

/// 3 / (16 pi) (1 + mu^2) [1/sr].
AERIAL_PHASE_INLINE double rayleighPhaseOf(double mu) {
    return 3.0 / (16.0 * 3.141592653589793) * (1.0 + mu * mu);
}

/// Cornette-Shanks: 3 / (8 pi) (1 - g^2) (1 + mu^2) / ((2 + g^2) (1 + g^2 - 2 g mu)^1.5) [1/sr].
AERIAL_PHASE_INLINE double miePhaseOf(double mu, double g) {
    const double g2 = g * g;
    // 1 + g^2 - 2 g mu >= (1 - |g|)^2 >= 1e-6: never zero for |g| <= 0.999.
    const double denom = std::max(1.0 + g2 - 2.0 * g * mu, 1e-12);
    return 3.0 / (8.0 * 3.141592653589793) * (1.0 - g2) * (1.0 + mu * mu) /
           ((2.0 + g2) * denom * std::sqrt(denom));
}

}  // namespace aerial::detail
