// sky_kernels.cpp — the sky solver's hot loops (sky_kernels.hpp): optical
// depths to the light for a row of the optical-depth table, densities at
// the view-ray nodes, layer transmittances, the per-texel integral of a
// sky row (the light at each shell, then each layer in closed form), and
// the per-column parts of a row around it: its columns' half-angles and
// multiple-scattering stencils, the earth's shadow along their rays, the
// straight-on share's phases.
//
// Everything here is plain arithmetic over contiguous float arrays, written
// so that GCC vectorises it: no calls (helpers are forced inline, so they
// are compiled for the calling kernel's target clone), no float compares in
// loop bodies (clamps on the bit patterns; the file is also compiled with
// -fno-trapping-math, core/CMakeLists.txt, so that the double loop of
// edgePieceKernel vectorises with its compares), no std::exp (its errno path
// blocks the vectoriser; std::sqrt has none here, the file being compiled
// with -fno-math-errno). The kernels are compiled for
// x86-64-v4, x86-64-v3 and the baseline (target_clones, chosen at load
// time): the levels rather than "avx512f" and "avx2", which leave out FMA
// (the polynomials, exp's and the moments', then take a multiply and an
// add each: ~10% of the whole solve on an AVX2 machine).
#include "sky_kernels.hpp"
#include "phase.hpp"
#include "planet_shadow.hpp"
#include "sky_multiple.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

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
namespace {

/// Gauss-Legendre panels per monotonic piece of a ray to the light.
constexpr int kDepthPanels = 4;

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

/// One quadrature node of depthKernel for every ray: the falling piece
/// (d = len1 t^2 from the perigee) and the rising piece (d = start2 + len2 t^2).
AERIAL_INLINE void depthNode(int n, float t2, float w, float rg, float rg2, const DensityConstants& k,
                             const float* __restrict q, const float* __restrict len1,
                             const float* __restrict start2, const float* __restrict len2,
                             float* __restrict outR, float* __restrict outM, float* __restrict outO) {
    const float invR = k.invRayleighH, onR = k.rayleighOn, invM = k.invMieH, onM = k.mieOn;
    const float oc = k.ozoneCenter, oi = k.ozoneInvHalfWidth, onO = k.ozoneOn;
    for (int m = 0; m < n; ++m) {
        const float d1 = len1[m] * t2;
        const float d2 = start2[m] + len2[m] * t2;
        const float num1 = q[m] + d1 * d1;  // r^2 - Rg^2
        const float num2 = q[m] + d2 * d2;
        const float h1 = maxZero(num1 / (vecSqrt(rg2 + num1) + rg));
        const float h2 = maxZero(num2 / (vecSqrt(rg2 + num2) + rg));
        const float ds1 = len1[m] * w, ds2 = len2[m] * w;
        outR[m] += onR * (ds1 * expNeg(h1 * invR) + ds2 * expNeg(h2 * invR));
        outM[m] += onM * (ds1 * expNeg(h1 * invM) + ds2 * expNeg(h2 * invM));
        const float tent1 = maxZero(1.0f - std::abs(h1 - oc) * oi);
        const float tent2 = maxZero(1.0f - std::abs(h2 - oc) * oi);
        outO[m] += onO * (ds1 * tent1 + ds2 * tent2);
    }
}

/// The light at one shell for every column: its zenith cosine
/// alpha + beta cos(phi) -> mapped column of that table row -> the record
/// tau rgb, T = e^-tau rgb, sqrt(tau) rgb and the margin above the shell's
/// horizon cosine (negative: the light is below it, the lookup clamped).
/// Without kRoots (no layer next to the shell has a shell with the light
/// below its horizon in its stencil, SkyKernelArgs::shellRoots) the roots
/// are not needed (curvatureFactor's first case) and not written; without
/// kMargins (none in the whole row, SkyKernelArgs::shadow) neither are the
/// margins.
template <bool kRoots, bool kMargins>
AERIAL_INLINE void skyShell(int nc, float alpha, float beta, float ch, float scale, float knee, float maxU,
                            const std::uint64_t* __restrict t0, const std::uint64_t* __restrict t1,
                            const std::uint64_t* __restrict t2, const float* __restrict cosPhi,
                            float* __restrict tau0, float* __restrict tau1, float* __restrict tau2,
                            float* __restrict tr0, float* __restrict tr1, float* __restrict tr2,
                            float* __restrict root0, float* __restrict root1, float* __restrict root2,
                            float* __restrict margins) {
    for (int i = 0; i < nc; ++i) {
        const float margin = alpha + beta * cosPhi[i] - ch;
        const float x = maxZero(margin);
        const float u = minNonNegative(x / (x + knee) * scale, maxU);
        const int iu = static_cast<int>(u);
        const float f = u - float(iu);
        const float d0 = pairAt(t0[iu], f);
        const float d1 = pairAt(t1[iu], f);
        const float d2 = pairAt(t2[iu], f);
        tau0[i] = d0;
        tau1[i] = d1;
        tau2[i] = d2;
        tr0[i] = expNeg(d0);
        tr1[i] = expNeg(d1);
        tr2[i] = expNeg(d2);
        if constexpr (kRoots) {
            root0[i] = vecSqrt(d0);
            root1[i] = vecSqrt(d1);
            root2[i] = vecSqrt(d2);
        }
        if constexpr (kMargins) margins[i] = margin;
    }
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

/// e^x, x the correction of the layer's mean transmittance to the light for
/// the curvature of tau along the layer: 2/3 of the gap at mid-layer between
/// the straight line from tau_a to tau_b and tau itself (2/3: the mean of a
/// parabolic gap), positive where tau sags below the line (convex), negative
/// where it bulges above it (concave).
///  * Where the light is above the geometric horizon at every shell of the
///    layer's stencil, tau is smooth and the gap is `cubic`: the cubic through
///    tau at four shells around the layer at its middle, minus the chord,
///    times -2/3 (LayerConstants::stencil).
///  * Otherwise (a shell in the earth shadow, where the table lookup clamps to
///    the grazing ray) tau falling along the layer is taken to fall like the
///    density, tau_b + (tau_a - tau_b) (e^(-lambda t) - e^-lambda) / (1 - e^-lambda)
///    with lambda = (h_b - h_a) / H_R, which lies below the straight line by
///    curv (tau_a - tau_b), curv = tanh(lambda / 4) / 3 with the 2/3, capped by
///    the exponential through both ends, (sqrt tau_a - sqrt tau_b)^2 / 3;
///    0 where tau rises.
/// `shadowed` is negative (sign bit set) where the second case applies.
/// x is clamped to [-1/2, 1]: a quartic, error < 0.4% at 1 and < 0.05% at -1/2.
AERIAL_INLINE float curvatureFactor(float cubic, int shadowed, float tauA, float tauB, float rootA,
                                    float rootB, float curv) {
    const float rootGap = rootA - rootB;
    const float bump =
        minNonNegative(curv * maxZero(tauA - tauB), maxZero(rootGap) * rootGap * (1.0f / 3.0f));
    const int mask = shadowed >> 31;  // all ones where shadowed
    float x = std::bit_cast<float>((std::bit_cast<int>(bump) & mask) | (std::bit_cast<int>(cubic) & ~mask));
    x = minNonNegative(x, 1.0f);
    x = x + maxZero(-0.5f - x);  // max(x, -1/2)
    return 1.0f + x * (1.0f + x * (0.5f + x * (1.0f / 6.0f + x * (1.0f / 24.0f))));
}

/// One layer for every column. Along the layer (t = 0..1) the optical depth
/// to the light is linear between the two shells, so the transmittance is
/// T_a e^(-d t) (exact where it changes by orders of magnitude, as near the
/// earth shadow), and the weight beta_X T(viewer -> s) is p + q t. The layer
/// adds lit * e^x * (p F1 + q F2), e^x the correction for the curvature of
/// tau along the layer (curvatureFactor): a second-order term that removes
/// most of the bias of the straight line, which matters where a thick layer
/// is seen at a grazing angle. For a low sun near the horizon tau first rises
/// along the view ray (the light crosses the dense air below the point) and
/// bulges above the line: without the term the first layer of a horizon row
/// is 3% too bright in blue there, and the texel 2%.
/// With kStraight the same integrals are also summed with the straight-on
/// weights (LayerConstants::straightP, straightQ) into so0..so5: the single
/// scattering that Mie's narrow forward peak scatters on along the view ray
/// towards the viewer (sky_multiple.hpp, "Mie's truncation").
template <bool kStraight, bool kShadow>
AERIAL_INLINE void skyLayer(
    int nc, const LayerConstants& k, const float* __restrict sIn, const float* __restrict sOut,
    const float* __restrict tauA0, const float* __restrict tauA1, const float* __restrict tauA2,
    const float* __restrict tA0, const float* __restrict tA1, const float* __restrict tA2,
    const float* __restrict rA0, const float* __restrict rA1, const float* __restrict rA2,
    const float* __restrict tauB0, const float* __restrict tauB1, const float* __restrict tauB2,
    const float* __restrict tB0, const float* __restrict tB1, const float* __restrict tB2,
    const float* __restrict rB0, const float* __restrict rB1, const float* __restrict rB2,
    const float* __restrict tauC0, const float* __restrict tauC1, const float* __restrict tauC2,
    const float* __restrict tauD0, const float* __restrict tauD1, const float* __restrict tauD2,
    const float* __restrict mA, const float* __restrict mB, const float* __restrict mC,
    const float* __restrict mD, float* __restrict acc0, float* __restrict acc1, float* __restrict acc2,
    float* __restrict acc3, float* __restrict acc4, float* __restrict acc5, float* __restrict so0,
    float* __restrict so1, float* __restrict so2, float* __restrict so3, float* __restrict so4,
    float* __restrict so5) {
    const float s0 = k.start, s1 = k.end;
    const float p0 = k.p[0], p1 = k.p[1], p2 = k.p[2], p3 = k.p[3], p4 = k.p[4], p5 = k.p[5];
    const float q0 = k.q[0], q1 = k.q[1], q2 = k.q[2], q3 = k.q[3], q4 = k.q[4], q5 = k.q[5];
    const float sp0 = k.straightP[0], sp1 = k.straightP[1], sp2 = k.straightP[2], sp3 = k.straightP[3],
                sp4 = k.straightP[4], sp5 = k.straightP[5];
    const float sq0 = k.straightQ[0], sq1 = k.straightQ[1], sq2 = k.straightQ[2], sq3 = k.straightQ[3],
                sq4 = k.straightQ[4], sq5 = k.straightQ[5];
    const float curv = k.curvature;
    const float wA = k.stencil[0], wB = k.stencil[1], wC = k.stencil[2], wD = k.stencil[3];
    for (int i = 0; i < nc; ++i) {
        // Lit: 1 where the layer [s0, s1] and the shadow [sIn, sOut] do not
        // overlap, else 0. A layer that the shadow's edge cuts is added by
        // the solver afterwards, its lit part only (shadowEdgeLayers).
        const float lo = maxNonNegative(sIn[i], s0);
        const float hi = minNonNegative(sOut[i], s1);
        const int overlap = std::bit_cast<int>(maxZero(hi - lo));  // > 0 where they overlap
        const float lit = std::bit_cast<float>(overlap > 0 ? 0 : 0x3f800000);
        const float x0 = wA * tauA0[i] + wB * tauB0[i] + wC * tauC0[i] + wD * tauD0[i];
        const float x1 = wA * tauA1[i] + wB * tauB1[i] + wC * tauC1[i] + wD * tauD1[i];
        const float x2 = wA * tauA2[i] + wB * tauB2[i] + wC * tauC2[i] + wD * tauD2[i];
        float a1, a2, b1, b2, c1, c2;
        exponentialMoments(tA0[i], tB0[i], tauB0[i] - tauA0[i], a1, a2);
        exponentialMoments(tA1[i], tB1[i], tauB1[i] - tauA1[i], b1, b2);
        exponentialMoments(tA2[i], tB2[i], tauB2[i] - tauA2[i], c1, c2);
        float g0, g1, g2;
        if constexpr (kShadow) {
            // Sign bit set where a stencil shell has the light below its horizon.
            // (Loaded into locals first: a bit_cast of the array element itself
            // makes GCC lose the restrict information and the loop stays scalar.)
            const float marginA = mA[i], marginB = mB[i], marginC = mC[i], marginD = mD[i];
            const int shadowed = std::bit_cast<int>(marginA) | std::bit_cast<int>(marginB) |
                                 std::bit_cast<int>(marginC) | std::bit_cast<int>(marginD);
            g0 = lit * curvatureFactor(x0, shadowed, tauA0[i], tauB0[i], rA0[i], rB0[i], curv);
            g1 = lit * curvatureFactor(x1, shadowed, tauA1[i], tauB1[i], rA1[i], rB1[i], curv);
            g2 = lit * curvatureFactor(x2, shadowed, tauA2[i], tauB2[i], rA2[i], rB2[i], curv);
        } else {
            g0 = lit * curvatureFactor(x0, 0, 0.0f, 0.0f, 0.0f, 0.0f, curv);
            g1 = lit * curvatureFactor(x1, 0, 0.0f, 0.0f, 0.0f, 0.0f, curv);
            g2 = lit * curvatureFactor(x2, 0, 0.0f, 0.0f, 0.0f, 0.0f, curv);
        }
        a1 *= g0;
        a2 *= g0;
        b1 *= g1;
        b2 *= g1;
        c1 *= g2;
        c2 *= g2;
        acc0[i] += p0 * a1 + q0 * a2;
        acc1[i] += p1 * b1 + q1 * b2;
        acc2[i] += p2 * c1 + q2 * c2;
        acc3[i] += p3 * a1 + q3 * a2;
        acc4[i] += p4 * b1 + q4 * b2;
        acc5[i] += p5 * c1 + q5 * c2;
        if constexpr (kStraight) {
            so0[i] += sp0 * a1 + sq0 * a2;
            so1[i] += sp1 * b1 + sq1 * b2;
            so2[i] += sp2 * c1 + sq2 * c2;
            so3[i] += sp3 * a1 + sq3 * a2;
            so4[i] += sp4 * b1 + sq4 * b2;
            so5[i] += sp5 * c1 + sq5 * c2;
        }
    }
}

/// Psi_ms at one shell for every column: the light's zenith cosine
/// alpha + beta cos(phi) -> LUT column x = sign(mu) sqrt|mu|,
/// u = (x + 1) / 2 (n - 1) (sky_multiple.hpp) -> interpolation of -ln Psi
/// (MultipleScatteringLut::resample: geometric in Psi); the column u of
/// each sky column into `column` (shellAniso's lookups).
AERIAL_INLINE void shellPsi(int nc, float alpha, float beta, int n, const std::uint64_t* __restrict psi0,
                            const std::uint64_t* __restrict psi1, const std::uint64_t* __restrict psi2,
                            const float* __restrict cosPhi, float* __restrict out0, float* __restrict out1,
                            float* __restrict out2, float* __restrict column) {
    const float scale = 0.5f * float(n - 1);
    const float maxU = float(n - 1) - 1e-3f;
    for (int i = 0; i < nc; ++i) {
        const float mu = alpha + beta * cosPhi[i];
        const float root = vecSqrt(minNonNegative(std::abs(mu), 1.0f));
        const float x = std::bit_cast<float>(std::bit_cast<int>(root) |
                                             (std::bit_cast<int>(mu) & static_cast<int>(0x80000000u)));
        const float u = minNonNegative(maxZero((x + 1.0f) * scale), maxU);
        column[i] = u;
        const int iu = static_cast<int>(u);
        const float f = u - float(iu);
        out0[i] = expNeg(pairAt(psi0[iu], f));
        out1[i] = expNeg(pairAt(psi1[iu], f));
        out2[i] = expNeg(pairAt(psi2[iu], f));
    }
}

/// The second order's view-dependent remainder at one shell for every
/// column (sky_multiple.hpp, "The phases"), added to the multiple
/// scattering's accumulators: the layers on both sides of the shell weight
/// the shell's A_R and A_M by W_R and W_M (msB of the layer below, msA of
/// the one above: Psi and A_X are linear along a layer), so the shell adds
///   W_R A_R + W_M A_M = Psi (K_q Q + K_d D),  K_q = W_R r2 + W_M m2, K_d = W_M m1,
/// with Q = B_0 + B_u v_u^2 + B_s v_s^2 + B_us v_u v_s, D = D_u v_u + D_s v_s
/// (the B and D relative to Psi, resample), v_u the view's zenith cosine at
/// the shell (the same for every column of a row) and
/// v_s = (v.l - v_u mu) / sqrt(1 - mu^2) its component along the light's
/// horizontal. Per LUT column that is a polynomial p0 + p1 v_s + p2 v_s^2
/// (`poly`: [3 channels][3][n] scratch), interpolated at each column's light
/// cosine at shellPsi's LUT column (`column`, [count]); `psi` is shellPsi's
/// output ([3][nc]: channels nc apart, as acc's), `across` [count] scratch,
/// `aniso` the shell's first plane, planes `stride` apart. The first `count`
/// columns only (the multiple scattering's azimuths, kMsSkyColumns).
AERIAL_INLINE void shellAniso(int count, int nc, float alpha, float beta, int n,
                              const float* __restrict aniso, std::size_t stride, float viewUp, float nuA,
                              float nuB, const float kq[3], const float kd[3], const float* __restrict cosPhi,
                              const float* __restrict psi, float* __restrict poly,
                              const float* __restrict column, float* __restrict across,
                              float* __restrict acc) {
    const float vu = viewUp, vu2 = viewUp * viewUp;
    for (int c = 0; c < 3; ++c) {
        const float* __restrict du = aniso + std::size_t(c) * stride;
        const float* __restrict ds = aniso + std::size_t(3 + c) * stride;
        const float* __restrict b0 = aniso + std::size_t(6 + c) * stride;
        const float* __restrict bu = aniso + std::size_t(9 + c) * stride;
        const float* __restrict bs = aniso + std::size_t(12 + c) * stride;
        const float* __restrict bus = aniso + std::size_t(15 + c) * stride;
        float* __restrict p0 = poly + std::size_t(3 * c) * n;
        float* __restrict p1 = p0 + n;
        float* __restrict p2 = p1 + n;
        for (int j = 0; j < n; ++j) {
            p0[j] = kq[c] * (b0[j] + bu[j] * vu2) + kd[c] * du[j] * vu;
            p1[j] = kq[c] * bus[j] * vu + kd[c] * ds[j];
            p2[j] = kq[c] * bs[j];
        }
    }
    const float vsMax = vecSqrt(maxZero(1.0f - vu2) + 1e-30f);
    for (int i = 0; i < count; ++i) {
        const float mu = alpha + beta * cosPhi[i];
        const float sinS = vecSqrt(maxZero(1.0f - mu * mu) + 1e-8f);
        const float vs = (nuA + nuB * cosPhi[i] - vu * mu) / sinS;
        across[i] = vs < -vsMax ? -vsMax : (vs > vsMax ? vsMax : vs);
    }
    for (int c = 0; c < 3; ++c) {
        const float* __restrict p0 = poly + std::size_t(3 * c) * n;
        const float* __restrict p1 = p0 + n;
        const float* __restrict p2 = p1 + n;
        const float* __restrict psiC = psi + std::size_t(c) * nc;
        float* __restrict out = acc + std::size_t(c) * nc;
        for (int i = 0; i < count; ++i) {
            const float u = column[i], vs = across[i];
            const int iu = static_cast<int>(u);
            const float f = u - float(iu);
            const float a0 = p0[iu] + f * (p0[iu + 1] - p0[iu]);
            const float a1 = p1[iu] + f * (p1[iu + 1] - p1[iu]);
            const float a2 = p2[iu] + f * (p2[iu + 1] - p2[iu]);
            out[i] += psiC[i] * (a0 + vs * (a1 + vs * a2));
        }
    }
}

/// Node interval of position t in [0, nodes] among the view nodes 0, 0.5,
/// 1.5, .., nodes - 0.5, nodes (sky_multiple.hpp, kMsViewZeniths): the
/// lower node's index and the fraction towards the next.
AERIAL_INLINE void viewInterval(float t, int nodes, int& index, float& fraction) {
    const float last = float(nodes) - 0.5f;
    if (!(t > 0.5f)) {
        index = 0;
        fraction = maxZero(t) * 2.0f;
    } else if (t >= last) {
        index = nodes;
        fraction = std::min((t - last) * 2.0f, 1.0f);
    } else {
        const float k = std::floor(t - 0.5f);
        index = static_cast<int>(k) + 1;
        fraction = t - 0.5f - k;
    }
}

/// Cosines of the view nodes' azimuths from the light (1, the azimuth
/// nodes', -1), falling.
struct ViewAzimuths {
    float cosine[kMsViewAzimuths];
    ViewAzimuths() {
        cosine[0] = 1.0f;
        for (int a = 0; a < kMsAzimuths; ++a) cosine[a + 1] = float(std::cos(msAzimuthNode(a).angle));
        cosine[kMsViewAzimuths - 1] = -1.0f;
    }
};

/// Mie's last scattering of the second and third orders' fields where their
/// l <= 2 series misses it (sky_multiple.hpp, "Mie's last scattering"):
/// adds W_M Psi C(v) per column, C / Psi (`views`, the shell's first plane,
/// planes `stride` apart) bilinear between the view nodes, in the zenith
/// position of the view at the shell (`viewUp`, the same for every column)
/// and in the cosine of its azimuth from the light's horizontal (per
/// column, from shellAniso's `across`), and linear between the LUT columns
/// (`column`).
AERIAL_INLINE void shellViews(int count, int nc, const float* __restrict views, std::size_t stride,
                              float viewUp, const float wm[3], const float* __restrict across,
                              const float* __restrict column, const float* __restrict psi,
                              float* __restrict acc) {
    static const ViewAzimuths nodes;
    // cos theta = -sign(x) x^2, t = (x + 1) kMsZeniths / 2 (msZenithNode).
    static_assert(kMsZenithPower == 2.0, "the view's zenith position inverts x^2 by a square root");
    const float root = vecSqrt(minNonNegative(std::abs(viewUp), 1.0f));
    const float x = viewUp > 0.0f ? -root : root;
    int iz = 0;
    float fz = 0.0f;
    viewInterval((x + 1.0f) * 0.5f * float(kMsZeniths), kMsZeniths, iz, fz);
    const float sinV = vecSqrt(maxZero(1.0f - viewUp * viewUp));
    const float invSinV = sinV > 1e-6f ? 1.0f / sinV : 0.0f;
    const std::size_t lower = std::size_t(iz) * kMsViewAzimuths * 3, upper = lower + kMsViewAzimuths * 3;
    for (int i = 0; i < count; ++i) {
        const float cosPhi = sinV > 1e-6f ? std::clamp(across[i] * invSinV, -1.0f, 1.0f) : 1.0f;
        int ia = 0;
        for (int a = 1; a < kMsViewAzimuths - 1; ++a) ia += cosPhi < nodes.cosine[a] ? 1 : 0;
        const float fa = (nodes.cosine[ia] - cosPhi) / (nodes.cosine[ia] - nodes.cosine[ia + 1]);
        const float col = column[i];
        const int ic = static_cast<int>(col);
        const float fc = col - float(ic);
        // The four nodes' planes (channel 0) and their bilinear weights.
        const float* p00 = views + (lower + std::size_t(ia) * 3) * stride + std::size_t(ic);
        const float* p01 = p00 + 3 * stride;
        const float* p10 = views + (upper + std::size_t(ia) * 3) * stride + std::size_t(ic);
        const float* p11 = p10 + 3 * stride;
        const float w00 = (1.0f - fz) * (1.0f - fa), w01 = (1.0f - fz) * fa, w10 = fz * (1.0f - fa),
                    w11 = fz * fa;
        for (int c = 0; c < 3; ++c) {
            const std::size_t o = std::size_t(c) * stride;
            const float lo = w00 * p00[o] + w01 * p01[o] + w10 * p10[o] + w11 * p11[o];
            const float hi = w00 * p00[o + 1] + w01 * p01[o + 1] + w10 * p10[o + 1] + w11 * p11[o + 1];
            acc[std::size_t(c) * nc + std::size_t(i)] +=
                wm[c] * psi[std::size_t(c) * nc + std::size_t(i)] * (lo + fc * (hi - lo));
        }
    }
}

/// Shell j's multiple-scattering weights (sum[0..2] Rayleigh rgb, 3..5
/// Mie's) from the per-shell weights `w` ([layers + 1][6]: msB of the layer
/// below plus msA of the one above), each with its share of the skipped
/// shells' between its evaluated neighbours `stride` apart (linear between
/// them).
void stridedShellWeights(const float* w, int layers, int j, int stride, float sum[6]) {
    const int before = j == layers ? (j - 1) / stride * stride : j - stride;  // evaluated neighbours
    const int after = std::min(j + stride, layers);
    for (int x = 0; x < 6; ++x) sum[x] = w[6 * j + x];
    for (int i = std::max(before + 1, 1); i < after; ++i) {
        if (i == j) continue;
        const float share =
            i < j ? float(i - before) / float(j - before) : float(after - i) / float(after - j);
        for (int x = 0; x < 6; ++x) sum[x] += share * w[6 * i + x];
    }
}

/// A layer's multiple scattering for every column: msA Psi(a) + msB Psi(b)
/// (Psi linear along the layer, weighted by the layer's sigma_s T shape,
/// Mie's weights times its isotropic share `mieShare`; the anisotropy is
/// added per shell, shellAniso).
AERIAL_INLINE void msLayer(int nc, const LayerConstants& k, const float* __restrict lo,
                           const float* __restrict up, float mieShare, float* __restrict acc) {
    constexpr int count = kMsSkyColumns;  // of the nc-strided records
    for (int c = 0; c < 3; ++c) {
        const float wa = k.msA[c] + mieShare * k.msA[3 + c], wb = k.msB[c] + mieShare * k.msB[3 + c];
        const float* __restrict pa = lo + std::size_t(10 + c) * nc;
        const float* __restrict pb = up + std::size_t(10 + c) * nc;
        float* __restrict out = acc + std::size_t(c) * nc;
        for (int i = 0; i < count; ++i) out[i] += wa * pa[i] + wb * pb[i];
    }
}

/// One channel and scatterer of edgePieceKernel's integrals (a helper, as skyLayer, so that
/// GCC vectorises it): two halves per piece, tau linear in each through its
/// value at the middle; half k covers t = t0 + h (k .. k + 1), h = dt / 2,
/// where e^(-kappa t - tau) = E_k e^(-(kappa h + tau_(k+1) - tau_k) u),
/// u = 0..1, and adds h F1 (exponentialMoments).
AERIAL_INLINE void edgeChannel(int n, const float* __restrict tauS, const float* __restrict tauM,
                               const float* __restrict tauE, const float* __restrict start,
                               const float* __restrict length, const float* __restrict kappa,
                               float* __restrict out) {
    for (int i = 0; i < n; ++i) {
        const float ts = tauS[i], tm = tauM[i], te = tauE[i], k = kappa[i];
        const float h = 0.5f * length[i];
        const float ka = k * start[i], kh = k * h;
        const float e0 = expNeg(ka + ts), e1 = expNeg(ka + kh + tm), e2 = expNeg(ka + 2.0f * kh + te);
        float f1a, f2a, f1b, f2b;
        exponentialMoments(e0, e1, kh + tm - ts, f1a, f2a);
        exponentialMoments(e1, e2, kh + te - tm, f1b, f2b);
        out[i] = h * (f1a + f1b);
    }
}

/// edgePieceKernel's loop (restrict parameters, as skyShell).
AERIAL_INLINE void edgePieces(int n, std::size_t stride, const double* __restrict from,
                              const double* __restrict to, const double* __restrict mu,
                              const double* __restrict litQ, const double* __restrict layerTangent,
                              const double* __restrict layerExtent, const int* __restrict layer,
                              const int* __restrict edgeAtStart, double tangent2, double viewTwice,
                              double rg2, double lightAtViewer, double knee, double maxU, int angles,
                              const float* __restrict angleScale, const std::uint64_t* __restrict depth,
                              std::size_t plane, float* __restrict tauStart, float* __restrict tauMid,
                              float* __restrict tauEnd, float* __restrict t0, float* __restrict dt) {
    for (int m = 0; m < n; ++m) {
        const double a = from[m], b = to[m];
        const bool atStart = edgeAtStart[m] != 0;
        const double edge = atStart ? a : b, middle = 0.5 * (a + b);
        // r^2 - Rg^2 along the view ray; the tangent lengths.
        const double zMid2 = std::max(tangent2 + middle * (viewTwice + middle), 0.0);
        const double zMid = std::sqrt(zMid2), rMid = std::sqrt(zMid2 + rg2);
        const double zEdge = std::sqrt(std::max(tangent2 + edge * (viewTwice + edge), 0.0));
        const int l = layer[m];
        const double za = layerTangent[2 * l], zInv = layerTangent[2 * l + 1];
        const double fEdge = std::min(std::max((zEdge - za) * zInv, 0.0), 1.0);
        const double fMid = std::min(std::max((zMid - za) * zInv, 0.0), 1.0);
        // The light's zenith cosine at the middle, (r0 sinL + s mu) / r, above
        // the horizon's there, -z / r; mapped.
        const double midMargin = std::max((lightAtViewer + middle * mu[m] + zMid) / rMid, 0.0);
        const double midQ = midMargin / (midMargin + knee);
        const int lit = atStart ? l + 1 : l;
        const double uLit = std::min(litQ[m] * double(angleScale[lit]), maxU);
        const double uA = std::min(midQ * double(angleScale[l]), maxU);
        const double uB = std::min(midQ * double(angleScale[l + 1]), maxU);
        const int iLit = int(uLit), iA = int(uA), iB = int(uB);
        const double fLit = uLit - iLit, fA = uA - iA, fB = uB - iB;
        const int rowA = l * angles, rowB = rowA + angles;
        const int atLit = lit * angles + iLit, atA = rowA + iA, atB = rowB + iB;
        // Linear in a lookup pair (tablePairs), in double.
        auto at = [](std::uint64_t pair, double f) {
            const double lo = pairLow(pair), hi = pairHigh(pair);
            return lo + f * (hi - lo);
        };
        for (int c = 0; c < 3; ++c) {
            const std::uint64_t* ch = depth + std::size_t(c) * plane;
            const double ga = pairLow(ch[rowA]), gb = pairLow(ch[rowB]);
            const double tauEdge = ga + fEdge * (gb - ga);
            const double tauLit = at(ch[atLit], fLit);
            const double ma = at(ch[atA], fA);
            const double mb = at(ch[atB], fB);
            const std::size_t out = std::size_t(c) * stride + std::size_t(m);
            tauStart[out] = float(atStart ? tauEdge : tauLit);
            tauEnd[out] = float(atStart ? tauLit : tauEdge);
            tauMid[out] = float(ma + fMid * (mb - ma));
        }
        t0[m] = float((a - layerExtent[2 * l]) * layerExtent[2 * l + 1]);
        dt[m] = float((b - a) * layerExtent[2 * l + 1]);
    }
}

/// The light at shell j (0: the viewer's, j > 0: the upper shell of layer
/// j - 1) into its record slot.
template <bool kShadowRow>
AERIAL_INLINE void lightAtShell(const SkyKernelArgs& a, int j, float maxU) {
    const int nc = a.columns;
    const int na = a.angles;
    const std::size_t rows = std::size_t(a.layers) + 1;
    const float alpha = j == 0 ? a.alpha0 : a.layer[j - 1].alpha;
    const float beta = j == 0 ? a.beta0 : a.layer[j - 1].beta;
    const float ch = j == 0 ? a.horizonCos0 : a.layer[j - 1].horizonCos;
    const float scale = j == 0 ? a.angleScale0 : a.layer[j - 1].angleScale;
    const std::uint64_t* t0 = a.depthPairs + std::size_t(j) * na;
    const std::uint64_t* t1 = a.depthPairs + (rows + std::size_t(j)) * na;
    const std::uint64_t* t2 = a.depthPairs + (2 * rows + std::size_t(j)) * na;
    float* r = a.shells + std::size_t(j % kShellSlots) * kShellRecord * nc;
    auto record = [&]<bool kRoots, bool kMargins>() AERIAL_LAMBDA_INLINE {
        skyShell<kRoots, kMargins>(a.litColumns, alpha, beta, ch, scale, a.knee, maxU, t0, t1, t2, a.cosPhi,
                                   r, r + nc, r + 2 * nc, r + 3 * nc, r + 4 * nc, r + 5 * nc, r + 6 * nc,
                                   r + 7 * nc, r + 8 * nc, r + 9 * nc);
    };
    if (!kShadowRow)
        record.template operator()<false, false>();
    else if (a.shellRoots[j])
        record.template operator()<true, true>();
    else
        record.template operator()<false, true>();
    if (a.psi != nullptr) {
        const int n = a.psiCosines;
        const std::uint64_t* p0 = a.psi + std::size_t(j) * n;
        const std::uint64_t* p1 = a.psi + (rows + std::size_t(j)) * n;
        const std::uint64_t* p2 = a.psi + (2 * rows + std::size_t(j)) * n;
        shellPsi(kMsSkyColumns, alpha, beta, n, p0, p1, p2, a.msCosPhi, r + 10 * nc, r + 11 * nc, r + 12 * nc,
                 r + 13 * nc);
        // The anisotropy at every kAnisoShellStride-th shell (and the last)
        // only, each also with its share of the skipped shells' weights
        // (linear between the evaluated ones): A_X, a correction of a few tens
        // of percent, is smooth along the ray, and this divides its cost.
        const float* w = a.msWeights + std::size_t(j) * kMsShellWeights;
        if (a.aniso != nullptr && w[9] != 0.0f) {
            shellAniso(kMsSkyColumns, nc, alpha, beta, n, a.aniso + std::size_t(j) * n, rows * n,
                       j == 0 ? a.viewUp0 : a.layer[j - 1].viewUp, a.nuA, a.nuB, w, w + 3, a.msCosPhi,
                       r + 10 * nc, a.anisoPoly, r + 13 * nc, r + 14 * nc, a.acc + 6 * nc);
            if (a.views != nullptr && w[9] > 1.0f) {
                const float viewUp = j == 0 ? a.viewUp0 : a.layer[j - 1].viewUp;
                shellViews(kMsSkyColumns, nc, a.views + std::size_t(j) * kMsViews * 3 * n, std::size_t(n),
                           viewUp, w + 6, r + 14 * nc, r + 13 * nc, r + 10 * nc, a.acc + 6 * nc);
            }
        }
    }
}

}  // namespace

/// Optical depths (column masses) of Rayleigh, Mie and ozone density along
/// `count` rays from one table row: each piece is mapped d = dense + len t^2
/// (dense end: the perigee or the start) and integrated with kDepthPanels
/// 4-point Gauss-Legendre panels in t.
AERIAL_HOT_KERNEL void depthKernel(const DepthKernelArgs& a) {
    const int n = a.count;
    const DensityConstants k = a.density;
    const float* __restrict q = a.q;
    const float* __restrict len1 = a.len1;
    const float* __restrict start2 = a.start2;
    const float* __restrict len2 = a.len2;
    float* __restrict outR = a.depthR;
    float* __restrict outM = a.depthM;
    float* __restrict outO = a.depthO;
    for (int m = 0; m < n; ++m) {
        outR[m] = 0.0f;
        outM[m] = 0.0f;
        outO[m] = 0.0f;
    }
    for (int panel = 0; panel < kDepthPanels; ++panel) {
        for (int g = 0; g < 4; ++g) {
            const float t = float((panel + kGaussT[g]) / kDepthPanels);
            const float w = float(kGaussW[g] / kDepthPanels) * 2.0f * t;
            depthNode(n, t * t, w, a.planetRadius, a.planetRadius2, k, q, len1, start2, len2, outR, outM,
                      outO);
        }
    }
}

void tablePairs(const float* table, int count, std::uint64_t* pairs) {
    for (int a = 0; a < count; ++a) {
        const float next = table[std::min(a + 1, count - 1)];
        pairs[a] = std::uint64_t(std::bit_cast<std::uint32_t>(table[a])) |
                   (std::uint64_t(std::bit_cast<std::uint32_t>(next)) << 32);
    }
}

/// Densities at the view-ray quadrature nodes of one row.
AERIAL_HOT_KERNEL void nodeKernel(const NodeKernelArgs& a) {
    const DensityConstants k = a.density;
    const float* __restrict s = a.s;
    float* __restrict outR = a.rayleigh;
    float* __restrict outM = a.mie;
    float* __restrict outO = a.ozone;
    for (int n = 0; n < a.count; ++n) {
        const float dr2 = s[n] * (a.twoR0Mu + s[n]);  // r^2 - r0^2
        const float h = maxZero(a.viewerHeight + dr2 / (vecSqrt(a.r0 * a.r0 + dr2) + a.r0));
        outR[n] = k.rayleighOn * expNeg(h * k.invRayleighH);
        outM[n] = k.mieOn * expNeg(h * k.invMieH);
        outO[n] = k.ozoneOn * maxZero(1.0f - std::abs(h - k.ozoneCenter) * k.ozoneInvHalfWidth);
    }
}

AERIAL_HOT_KERNEL void halfAngleKernel(int n, const double* __restrict phi, double* __restrict cosHalf,
                                       double* __restrict sinHalf, double* __restrict cosPhi,
                                       float* __restrict cosPhiF) {
    // pi / 2 as the sum of two doubles: pi / 2 - h is then exact to an ulp
    // of the result even where h is within an ulp of pi / 2 (the
    // anti-light point, where cos(phi / 2) is all the precision there is).
    constexpr double kHalfPiHi = 1.5707963267948966, kHalfPiLo = 6.123233995736766e-17;
    // (-1)^t / (2t + 1)! and (-1)^t / (2t)!.
    constexpr double kSinTaylor[8] = {1.0,
                                      -1.0 / 6.0,
                                      1.0 / 120.0,
                                      -1.0 / 5040.0,
                                      1.0 / 362880.0,
                                      -1.0 / 39916800.0,
                                      1.0 / 6227020800.0,
                                      -1.0 / 1307674368000.0};
    constexpr double kCosTaylor[9] = {1.0,
                                      -0.5,
                                      1.0 / 24.0,
                                      -1.0 / 720.0,
                                      1.0 / 40320.0,
                                      -1.0 / 3628800.0,
                                      1.0 / 479001600.0,
                                      -1.0 / 87178291200.0,
                                      1.0 / 20922789888000.0};
    for (int i = 0; i < n; ++i) {
        const double h = 0.5 * std::min(std::max(phi[i], 0.0), 2.0 * kHalfPiHi);
        const bool upper = h > 0.5 * kHalfPiHi;
        const double a = upper ? (kHalfPiHi - h) + kHalfPiLo : h;  // in [0, pi / 4]
        const double z = a * a;
        // Taylor to a^15 and a^16 (Horner in a^2): the first terms left out
        // are below 4e-17 of the result at a = pi / 4 (test_sky_kernels.cpp:
        // within 2 ulp; with a term fewer 10 ulp in cos, 184 in sin).
        double ps = kSinTaylor[7], pc = kCosTaylor[8];
        for (int t = 6; t >= 0; --t) ps = ps * z + kSinTaylor[t];
        for (int t = 7; t >= 0; --t) pc = pc * z + kCosTaylor[t];
        const double sa = a * ps, ca = pc;
        const double c = upper ? sa : ca, s = upper ? ca : sa;
        cosHalf[i] = c;
        sinHalf[i] = s;
        cosPhi[i] = (c - s) * (c + s);
        cosPhiF[i] = float(cosPhi[i]);
    }
}

namespace {

/// straightOnKernel's loop (restrict parameters, as skyShell); `so` the
/// straight-on share's first plane, `out` the multiple scattering's.
AERIAL_INLINE void straightOnColumns(int n, const double* __restrict cosPhi, const float* __restrict so,
                                     float* __restrict out, std::size_t stride, const StraightOnArgs& a) {
    const double g = a.g, nuA = a.nuA, nuB = a.nuB, fade = a.fade;
    for (int i = 0; i < n; ++i) {
        const double mu = std::min(std::max(nuA + nuB * cosPhi[i], -1.0), 1.0);
        const double pr = rayleighPhaseOf(mu), pm = miePhaseOf(mu, g);
        for (std::size_t c = 0; c < 3; ++c)
            out[c * stride + std::size_t(i)] += float(
                fade * (pr * so[c * stride + std::size_t(i)] + pm * so[(3 + c) * stride + std::size_t(i)]));
    }
}

/// shadowSpanKernel's loop (restrict parameters, as skyShell): the
/// interval of the cylinder's quadratic (halfQuadraticRoots' roots where
/// the ray is not along the axis), cut to x . l < 0 (behind the planet:
/// r0 sinL + s mu < 0) and to the ray. Branch-free (selects), so that it
/// vectorises.
AERIAL_INLINE void shadowSpans(int n, const double* __restrict cosPhi, const double* __restrict cosHalfPhi,
                               const double* __restrict sinHalfPhi, const ShadowSpanArgs& a,
                               float* __restrict in, float* __restrict out) {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    const double sinEl = a.sinEl, sinL = a.sinL, r0 = a.r0, c2 = a.c2, length = a.viewLength;
    const double nuA = a.sinEl * a.sinL, nuB = a.cosEl * a.cosL;
    const double ta = a.towardsAnti, tl = a.towardsLight;
    const double cc = a.cosCos, lightAtViewer = r0 * sinL;
    // x . l is linear in s: a light above the horizon and lit at the ray's
    // end means no shadow (-inf: never, for a light below it).
    const double litEnd = sinL >= 0.0 ? 0.0 : kInf;
    const double muZero = sinL < 0.0 ? 1.0 : 0.0;  // mu = 0: in the shadow's half-space if the light is down
    const double axisHi = c2 > a.parallelLit ? -kInf : kInf;  // along the axis: lit, or all in it
    for (int i = 0; i < n; ++i) {
        const double mu = nuA + nuB * cosPhi[i];
        const bool litBoth = lightAtViewer + length * mu >= litEnd;
        const double ch = cosHalfPhi[i], sh = sinHalfPhi[i];
        const double a2 = oneMinusCosFromParts(ta, cc, ch) * oneMinusCosFromParts(tl, cc, sh);
        const double b2 = r0 * (sinEl - sinL * mu);
        const double disc = b2 * b2 - a2 * c2;
        const bool roots = disc > 0.0 && a2 > 0.0;
        const double q = -(b2 + std::copysign(std::sqrt(std::max(disc, 0.0)), b2));
        const double r1 = q / a2, r2 = c2 / q;
        const bool axis = !(a2 > kShadowAxisA2);
        double lo = axis || !roots ? -kInf : std::min(r1, r2);
        double hi = axis ? axisHi : (roots ? std::max(r1, r2) : -kInf);
        const double bound = -lightAtViewer / mu;
        hi = mu > 0.0 ? std::min(hi, bound) : hi;
        lo = mu < 0.0 ? std::max(lo, bound) : lo;
        hi = mu == 0.0 && muZero == 0.0 ? lo : hi;
        lo = std::max(lo, 0.0);
        hi = std::min(hi, length);
        const bool shadow = hi > lo && !litBoth;
        in[i] = float(shadow ? lo : -1.0);   // selected in double: GCC does not vectorise a
        out[i] = float(shadow ? hi : -1.0);  // double compare's mask on floats
    }
}

/// spreadStencilKernel's stencil for a block of positions.
AERIAL_INLINE void spreadStencilBlock(int n, const float* __restrict position, int padded,
                                      int* __restrict index, float* __restrict weight) {
    constexpr int kK = kMsSkyColumns;
    for (int i = 0; i < n; ++i) {
        const float u = position[i];
        const int k = std::min(int(u), kK - 2);
        const float f = u - float(k);
        // Written out (an inner loop over the four keeps GCC from vectorising).
        const int first = k - 1, last = k + 2;  // only these two can leave 0..K-1
        index[i] = first < 0 ? -first : first;
        index[padded + i] = k;
        index[2 * padded + i] = k + 1;
        index[3 * padded + i] = last > kK - 1 ? 2 * (kK - 1) - last : last;
        weight[i] = 0.5f * f * (-1.0f + f * (2.0f - f));
        weight[padded + i] = 1.0f + 0.5f * f * f * (-5.0f + 3.0f * f);
        weight[2 * padded + i] = 0.5f * f * (1.0f + f * (4.0f - 3.0f * f));
        weight[3 * padded + i] = 0.5f * f * f * (f - 1.0f);
    }
}

}  // namespace

AERIAL_HOT_KERNEL void straightOnKernel(const StraightOnArgs& a) {
    straightOnColumns(a.count, a.cosPhi, a.acc + 9 * std::size_t(a.stride), a.acc + 6 * std::size_t(a.stride),
                      std::size_t(a.stride), a);
}

AERIAL_HOT_KERNEL void shadowSpanKernel(const ShadowSpanArgs& a) {
    // A light above the horizon that lights the end of every column's ray
    // (mu >= nuA - |nuB|): no shadow in the row.
    if (a.sinL >= 0.0 &&
        a.r0 * a.sinL + a.viewLength * (a.sinEl * a.sinL - std::abs(a.cosEl * a.cosL)) >= 0.0) {
        std::fill(a.in, a.in + a.count, -1.0f);
        std::fill(a.out, a.out + a.count, -1.0f);
        return;
    }
    shadowSpans(a.count, a.cosPhi, a.cosHalfPhi, a.sinHalfPhi, a, a.in, a.out);
}

AERIAL_HOT_KERNEL void spreadStencilKernel(int n, const double* __restrict phi, int padded,
                                           int* __restrict index, float* __restrict weight) {
    constexpr int kK = kMsSkyColumns;  // positions 0 .. kK - 1
    constexpr double kPiD = 3.141592653589793;
    // The positions in double, the stencil in float (what it is stored as):
    // one type per loop, which GCC vectorises; in blocks of kBlock.
    constexpr int kBlock = 64;
    float position[kBlock];
    for (int b = 0; b < n; b += kBlock) {
        const int m = std::min(n - b, kBlock);
        for (int i = 0; i < m; ++i)
            position[i] = float(std::min(std::max(phi[b + i] / kPiD, 0.0), 1.0) * (kK - 1));
        spreadStencilBlock(m, position, padded, index + b, weight + b);
    }
}

/// Per-row transmittances of the layers: e^-tau, e^(-tau t_0), e^(-tau t_1).
AERIAL_HOT_KERNEL void layerExpKernel(int n, const float* __restrict tau, float* __restrict layerT,
                                      float* __restrict nodeT0, float* __restrict nodeT1) {
    const float t0 = float(kGaussT[0]), t1 = float(kGaussT[1]);
    for (int i = 0; i < n; ++i) {
        layerT[i] = expNeg(tau[i]);
        nodeT0[i] = expNeg(tau[i] * t0);
        nodeT1[i] = expNeg(tau[i] * t1);
    }
}

/// The inner loop of a sky row over contiguous float arrays, no branch.
/// Shell records are made just ahead of the layers that use them, into
/// kShellSlots slots (shell j in slot j % kShellSlots): layer l's stencil
/// spans shells l-1 .. l+2 (0 .. 3 for the first layer, see layerStencil),
/// so shell l + 2 replaces shell l - 2 before layer l >= 2.
template <bool kShadowRow>
AERIAL_INLINE void skyRow(const SkyKernelArgs& a) {
    const int nc = a.columns;
    const int nl = a.layers;
    const float maxU = float(a.angles - 1) - 1e-3f;
    float* acc = a.acc;
    auto shell = [&](int j) { return a.shells + std::size_t(j % kShellSlots) * kShellRecord * nc; };
    const bool straight = a.straightOn;
    for (int i = 0; i < (straight ? 15 : 9) * nc; ++i)
        acc[i] = 0.0f;  // before the shells: shellAniso adds to it
    for (int j = 0; j <= std::min(nl, kShellSlots - 1); ++j) lightAtShell<kShadowRow>(a, j, maxU);
    for (int l = 0; l < nl; ++l) {
        if (l >= 2 && l + 2 <= nl) lightAtShell<kShadowRow>(a, l + 2, maxU);
        const LayerConstants& k = a.layer[l];
        const float* lo = shell(l);
        const float* up = shell(l + 1);
        const float* c = shell(k.stencilC);
        const float* d = shell(k.stencilD);
        float* so = acc + 9 * nc;  // the straight-on share (with a.straightOn only)
        // The layer's integral, in the variant it needs (skyLayer): with the
        // straight-on share or not, with shells in the earth's shadow in its
        // stencil or not.
        auto layer = [&]<bool kStraight, bool kShadow>() AERIAL_LAMBDA_INLINE {
            skyLayer<kStraight, kShadow>(
                a.litColumns, k, a.shadowIn, a.shadowOut, lo, lo + nc, lo + 2 * nc, lo + 3 * nc, lo + 4 * nc,
                lo + 5 * nc, lo + 6 * nc, lo + 7 * nc, lo + 8 * nc, up, up + nc, up + 2 * nc, up + 3 * nc,
                up + 4 * nc, up + 5 * nc, up + 6 * nc, up + 7 * nc, up + 8 * nc, c, c + nc, c + 2 * nc, d,
                d + nc, d + 2 * nc, lo + 9 * nc, up + 9 * nc, c + 9 * nc, d + 9 * nc, acc, acc + nc,
                acc + 2 * nc, acc + 3 * nc, acc + 4 * nc, acc + 5 * nc, so, so + nc, so + 2 * nc, so + 3 * nc,
                so + 4 * nc, so + 5 * nc);
        };
        const bool shadowLayer = kShadowRow && a.layerShadow[l];
        if (!a.layerLit[l]) {
            // the earth's shadow overlaps the layer in every column: nothing to add
        } else if (straight) {
            if (shadowLayer)
                layer.template operator()<true, true>();
            else
                layer.template operator()<true, false>();
        } else {
            if (shadowLayer)
                layer.template operator()<false, true>();
            else
                layer.template operator()<false, false>();
        }
        if (a.psi != nullptr) msLayer(nc, k, lo, up, a.mieIsotropicShare, acc + 6 * nc);
    }
}

AERIAL_HOT_KERNEL void skyKernel(const SkyKernelArgs& a) {
    if (a.shadow)
        skyRow<true>(a);
    else
        skyRow<false>(a);
}

void msShellWeights(const LayerConstants* layer, int layers, float rayleighBand2, float mieBand1,
                    float mieBand2, float* scratch, float* out) {
    for (int i = 0; i <= layers; ++i)
        for (int x = 0; x < 6; ++x)
            scratch[6 * i + x] = (i > 0 ? layer[i - 1].msB[x] : 0.0f) + (i < layers ? layer[i].msA[x] : 0.0f);
    constexpr int stride = kAnisoShellStride, viewStride = 2 * kAnisoShellStride;
    for (int j = 0; j <= layers; ++j) {
        float* w = out + std::size_t(j) * kMsShellWeights;
        const bool evaluated = j % stride == 0 || j == layers;
        w[9] = 0.0f;
        if (!evaluated) continue;
        w[9] = 1.0f;
        float sum[6];
        stridedShellWeights(scratch, layers, j, stride, sum);
        for (int c = 0; c < 3; ++c) {
            w[c] = sum[c] * rayleighBand2 + sum[3 + c] * mieBand2;
            w[3 + c] = sum[3 + c] * mieBand1;
        }
        if (j % viewStride != 0 && j != layers) continue;
        stridedShellWeights(scratch, layers, j, viewStride, sum);
        bool mie = false;
        for (int c = 0; c < 3; ++c) {
            w[6 + c] = sum[3 + c];
            // Shells where Mie's weight is under kViewMieFloor of the
            // scattering's (high above a haze) leave it out.
            mie = mie || sum[3 + c] > kViewMieFloor * (sum[c] + sum[3 + c]);
        }
        if (mie) w[9] = 2.0f;
    }
}

AERIAL_HOT_KERNEL void edgePieceKernel(const EdgePieceArgs& a) {
    const std::size_t stride = std::size_t(a.stride);
    edgePieces(a.count, stride, a.from, a.to, a.mu, a.litQ, a.layerTangent, a.layerExtent, a.layer,
               a.edgeAtStart, a.tangent2, a.viewTwice, a.planetRadius2, a.lightAtViewer, a.knee, a.maxU,
               a.angles, a.angleScale, a.depthPairs, a.plane, a.tauStart, a.tauMid, a.tauEnd, a.t0, a.dt);
    for (std::size_t k = 0; k < 6; ++k)
        for (int m = 0; m < a.count; ++m)
            a.kappa[k * stride + std::size_t(m)] = a.layerKappa[6 * a.layer[m] + int(k)];
    // The integrals, channel by channel (edgeChannel).
    const int n = std::min((a.count + 7) / 8 * 8, a.stride);
    for (std::size_t x = 0; x < 6; ++x) {
        const std::size_t c = x % 3;
        edgeChannel(n, a.tauStart + c * stride, a.tauMid + c * stride, a.tauEnd + c * stride, a.t0, a.dt,
                    a.kappa + x * stride, a.out + x * stride);
    }
}

/// spreadKernel's loop (restrict parameters: see crossingRecords below).
AERIAL_INLINE void spreadColumns(int n, const int* __restrict i0, const int* __restrict i1,
                                 const int* __restrict i2, const int* __restrict i3,
                                 const float* __restrict w0, const float* __restrict w1,
                                 const float* __restrict w2, const float* __restrict w3,
                                 const float* __restrict v, float* __restrict out) {
    for (int i = 0; i < n; ++i) {
        const float x = w0[i] * v[i0[i]] + w1[i] * v[i1[i]] + w2[i] * v[i2[i]] + w3[i] * v[i3[i]];
        out[i] = expNeg(-x);
    }
}

/// exp of a 4-point weighted sum of logarithms per column (expNeg of its
/// negative: valid for sums in (-87, 87), which the callers' values are).
AERIAL_HOT_KERNEL void spreadKernel(const SpreadKernelArgs& a) {
    const int n = a.count;
    spreadColumns(n, a.index, a.index + n, a.index + 2 * n, a.index + 3 * n, a.weight, a.weight + n,
                  a.weight + 2 * n, a.weight + 3 * n, a.logValue, a.out);
}

// The loops of msCrossingKernel and msSourceKernel live in helpers whose
// arrays are __restrict parameters (as skyShell's): written inline in the
// kernels, with the pointers taken from the argument struct, GCC did not
// vectorise them.

/// msCrossingKernel's loop: as skyShell, without the roots.
AERIAL_INLINE void crossingRecords(int n, float alpha, float beta, float horizonCos, float knee,
                                   float angleScale, float maxU, const float* __restrict p,
                                   const float* __restrict q, const float* __restrict t0,
                                   const float* __restrict t1, const float* __restrict t2,
                                   float* __restrict tau0, float* __restrict tau1, float* __restrict tau2,
                                   float* __restrict tr0, float* __restrict tr1, float* __restrict tr2,
                                   float* __restrict margins) {
    for (int i = 0; i < n; ++i) {
        const float margin = alpha * p[i] + beta * q[i] - horizonCos;
        const float x = maxZero(margin);
        const float u = minNonNegative(x / (x + knee) * angleScale, maxU);
        const int iu = static_cast<int>(u);
        const float f = u - float(iu);
        const float d0 = t0[iu] + f * (t0[iu + 1] - t0[iu]);
        const float d1 = t1[iu] + f * (t1[iu + 1] - t1[iu]);
        const float d2 = t2[iu] + f * (t2[iu + 1] - t2[iu]);
        tau0[i] = d0;
        tau1[i] = d1;
        tau2[i] = d2;
        tr0[i] = expNeg(d0);
        tr1[i] = expNeg(d1);
        tr2[i] = expNeg(d2);
        margins[i] = margin;
    }
}

/// The sun seen from one crossing of a multiple-scattering ray, for every
/// combination of sun cosine and azimuth.
AERIAL_HOT_KERNEL void msCrossingKernel(const MsCrossingArgs& a) {
    const int n = a.count;
    float* r = a.record;
    crossingRecords(n, a.alpha, a.beta, a.horizonCos, a.knee, a.angleScale, a.maxU, a.p, a.q, a.depth0,
                    a.depth1, a.depth2, r, r + n, r + 2 * n, r + 3 * n, r + 4 * n, r + 5 * n, r + 6 * n);
}

/// msSourceKernel's loop. The LUT column: x = sign(mu) sqrt(min(|mu|, 1)),
/// on the bit patterns (sign and magnitude apart), so that it vectorises.
AERIAL_INLINE void sourceColumns(int n, float alpha, float beta, float scale, float maxU,
                                 const float* __restrict p, const float* __restrict q,
                                 const float* __restrict row, int* __restrict column,
                                 float* __restrict fraction, float* __restrict out0, float* __restrict out1,
                                 float* __restrict out2) {
    for (int i = 0; i < n; ++i) {
        const float mu = alpha * p[i] + beta * q[i];
        const int bits = std::bit_cast<int>(mu);
        const float magnitude = minNonNegative(std::bit_cast<float>(bits & 0x7fffffff), 1.0f);
        const float root = vecSqrt(magnitude);
        const float x = std::bit_cast<float>(std::bit_cast<int>(root) | (bits & int(0x80000000u)));
        const float u = minNonNegative(maxZero((x + 1.0f) * scale), maxU);
        const int iu = static_cast<int>(u);
        const float f = u - float(iu);
        const int at = 3 * iu;
        column[i] = iu;
        fraction[i] = f;
        out0[i] = row[at] + f * (row[at + 3] - row[at]);
        out1[i] = row[at + 1] + f * (row[at + 4] - row[at + 1]);
        out2[i] = row[at + 2] + f * (row[at + 5] - row[at + 2]);
    }
}

AERIAL_HOT_KERNEL void msSourceKernel(const MsSourceArgs& a) {
    const int n = a.count;
    const float scale = 0.5f * float(a.cosines - 1), maxU = float(a.cosines - 1) - 1e-3f;
    sourceColumns(n, a.alpha, a.beta, scale, maxU, a.p, a.q, a.row, a.column, a.fraction, a.out, a.out + n,
                  a.out + 2 * n);
}

/// msSegmentKernel's loop, one channel (restrict parameters, as above).
AERIAL_INLINE void segmentChannel(int n, float w, float wm, float tv, float eView,
                                  const float* __restrict tauA, const float* __restrict tauB,
                                  const float* __restrict trA, const float* __restrict trB,
                                  const float* __restrict mA, const float* __restrict mB,
                                  float* __restrict out, float* __restrict outMie) {
    for (int i = 0; i < n; ++i) {
        const float marginA = mA[i], marginB = mB[i];
        const float pos = maxZero(marginA) + maxZero(marginB);
        const float neg = maxZero(-marginA) + maxZero(-marginB);
        const float lit = pos / (pos + neg + 1e-30f);
        float f1, f2;
        exponentialMoments(trA[i], trB[i] * eView, tv + tauB[i] - tauA[i], f1, f2);
        const float share = lit * f1;
        out[i] += w * share;
        outMie[i] += wm * share;
    }
}

/// One segment of a multiple-scattering ray for every combination:
/// weight T_sun(a) E1(d) lit, d = tauView + tau_sun(b) - tau_sun(a)
/// (exponentialMoments), lit the fraction of the segment where the margin,
/// linear between its ends, is positive.
AERIAL_HOT_KERNEL void msSegmentKernel(const MsSegmentArgs& a) {
    const int n = a.count;
    const float* ra = a.a;
    const float* rb = a.b;
    for (int c = 0; c < 3; ++c) {
        const float w = a.weight[c], wm = a.weightMie[c], tv = a.tauView[c], eView = expNeg(tv);
        segmentChannel(n, w, wm, tv, eView, ra + c * n, rb + c * n, ra + (3 + c) * n, rb + (3 + c) * n,
                       ra + 6 * n, rb + 6 * n, a.acc + c * n, a.accMie + c * n);
    }
}

void segmentNodeDensities(const double* crossing, int segments, double h0, double r0, double mu,
                          const DensityConstants& density, float* s, float* rayleigh, float* mie,
                          float* ozone) {
    if (segments <= 0) return;
    for (int i = 0; i < segments; ++i) {
        const double a = crossing[i], b = crossing[i + 1];
        for (int g = 0; g < 4; ++g) s[4 * i + g] = float(a + (b - a) * kGaussT[g]);
    }
    NodeKernelArgs nodes{};
    nodes.count = 4 * segments;
    nodes.viewerHeight = float(h0);
    nodes.r0 = float(r0);
    nodes.twoR0Mu = float(2.0 * r0 * mu);
    nodes.density = density;
    nodes.s = s;
    nodes.rayleigh = rayleigh;
    nodes.mie = mie;
    nodes.ozone = ozone;
    nodeKernel(nodes);
}

}  // namespace aerial::detail
