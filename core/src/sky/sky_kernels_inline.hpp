// sky_kernels_inline.hpp — private to the sky solver's kernel files
// (sky_kernels*.cpp): the target-clone attribute of the hot kernels and the
// branch-free float helpers they share, forced inline so that each is
// compiled for the calling kernel's clone (sky_kernels.cpp explains why).
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && !defined(__SANITIZE_ADDRESS__) && \
    !defined(__SANITIZE_THREAD__)  // sanitizers and ifunc resolvers do not mix
#define AERIAL_HOT_KERNEL __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define AERIAL_HOT_KERNEL
#endif
// Helpers of the hot kernels are forced inline so that they are compiled
// for the kernel's target clone (a call would run the baseline code).
#if defined(__GNUC__)
#define AERIAL_INLINE inline __attribute__((always_inline))
#define AERIAL_LAMBDA_INLINE __attribute__((always_inline))
#else
#define AERIAL_INLINE inline
#define AERIAL_LAMBDA_INLINE
#endif

namespace aerial::detail {

// Branch-free float helpers. With GCC's default -ftrapping-math a float
// compare inside a loop body blocks if-conversion and thus vectorisation, so
// the clamps are done on the bit patterns (as integers, which order like the
// floats for non-negative values).

/// max(x, 0).
AERIAL_INLINE float maxZero(float x) {
    const int b = std::bit_cast<int>(x);
    return std::bit_cast<float>(b & ~(b >> 31));
}

/// min(a, b) for b >= 0 (a of any sign).
AERIAL_INLINE float minNonNegative(float a, float b) {
    const int ia = std::bit_cast<int>(a), ib = std::bit_cast<int>(b);
    return std::bit_cast<float>(ia < ib ? ia : ib);
}

/// max(a, b) for b >= 0 (a of any sign).
AERIAL_INLINE float maxNonNegative(float a, float b) {
    const int ia = std::bit_cast<int>(a), ib = std::bit_cast<int>(b);
    return std::bit_cast<float>(ia > ib ? ia : ib);
}

/// exp(-x) for x >= 0 (clamped to 87), relative error < 3e-7: Cody-Waite
/// reduction and a degree-6 polynomial, plain arithmetic that vectorises.
AERIAL_INLINE float expNeg(float x) {
    x = minNonNegative(x, 87.0f);          // also maps negative rounding noise through
    constexpr float kShift = 12582912.0f;  // 1.5 * 2^23: adding it rounds to an integer
    float k = -x * 1.44269504f + kShift;
    k -= kShift;
    float r = -x - k * 0.693359375f;  // ln 2 = 0.693359375 - 2.12194440e-4
    r += k * 2.12194440e-4f;
    const float p =
        1.0f + r * (1.0f + r * (0.5f + r * (0.166666672f + r * (0.0416666679f +
                                                                r * (0.00833333377f + r * 0.00138888892f)))));
    const int bits = (static_cast<int>(k) + 127) << 23;
    return p * std::bit_cast<float>(bits);
}

/// sqrt(x) for x >= 0 that vectorises (the packed square root): this file
/// is compiled with -fno-math-errno (core/CMakeLists.txt), so std::sqrt
/// has no errno branch to block GCC's vectoriser. (The Newton steps on the
/// reciprocal root it replaced took 12 instructions and 1e-7 of precision.)
AERIAL_INLINE float vecSqrt(float x) { return std::sqrt(x); }

/// The two entries of a lookup pair (tablePairs).
AERIAL_INLINE float pairLow(std::uint64_t pair) {
    return std::bit_cast<float>(static_cast<std::uint32_t>(pair));
}

AERIAL_INLINE float pairHigh(std::uint64_t pair) {
    return std::bit_cast<float>(static_cast<std::uint32_t>(pair >> 32));
}

/// Linear interpolation in a lookup pair: a + f (b - a), as from the table.
AERIAL_INLINE float pairAt(std::uint64_t pair, float f) {
    const float a = pairLow(pair), b = pairHigh(pair);
    return a + f * (b - a);
}

/// F1 = T_a E1(d) and F2 = T_a E2(d), E1 = int_0^1 e^(-d t) dt and
/// E2 = int_0^1 t e^(-d t) dt, given T_a and T_b = T_a e^-d: the closed forms
/// (T_a - T_b) / d and (T_a - (1 + d) T_b) / d^2, or their Taylor series
/// where those cancel (|d| < 0.05, truncation < 6e-8). Branch-free: an
/// integer mask blends the two (the division is kept finite in between).
AERIAL_INLINE void exponentialMoments(float ta, float tb, float d, float& f1, float& f2) {
    const float s1 = ta * (1.0f + d * (-0.5f + d * (1.0f / 6.0f - d * (1.0f / 24.0f))));
    const float s2 = ta * (0.5f + d * (-1.0f / 3.0f + d * (0.125f - d * (1.0f / 30.0f))));
    const int small = (std::bit_cast<int>(d) & 0x7fffffff) < 0x3d4ccccd ? -1 : 0;  // |d| < 0.05f
    const float safeD = std::bit_cast<float>((std::bit_cast<int>(d) & ~small) | (0x3f800000 & small));
    const float inv = 1.0f / safeD;
    const float c1 = (ta - tb) * inv;
    const float c2 = (ta - (1.0f + d) * tb) * inv * inv;
    f1 = std::bit_cast<float>((std::bit_cast<int>(s1) & small) | (std::bit_cast<int>(c1) & ~small));
    f2 = std::bit_cast<float>((std::bit_cast<int>(s2) & small) | (std::bit_cast<int>(c2) & ~small));
}

}  // namespace aerial::detail
