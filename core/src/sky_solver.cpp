// sky_solver.cpp — Nishita et al. 1993 single scattering on the CPU.
//
// Structure of one solve (../shared/DESIGN.md, "Sky"; <aerial/sky.hpp>):
//  1. Layers. layerCount + 1 spherical shells between the viewer height h0
//     and the top Ht split the air into layers of equal "mass" of the mixed
//     profile F = (F_R + F_M + 2 F_U) / 4: F_X the normalised cumulative
//     density of exp(-h/H_X) above h0, F_U uniform in height. A quarter of
//     the layers thus follows the 8 km Rayleigh profile, a quarter the 1.2 km
//     Mie profile (dense near the ground), and half are spread evenly, which
//     keeps the upper layers thin enough for the earth-shadow boundary of a
//     set sun.
//  2. Optical-depth table (Nishita's 2D table), one row per shell height
//     (no interpolation in height), opticalDepthAngles columns over the
//     light's zenith cosine c in [c_h(r), 1], c_h the cosine of the geometric
//     horizon at that radius, with the mapping u = x / (x + k), x = c - c_h,
//     which puts half of the columns within kAngleKnee of the horizon (where
//     the optical depth changes fastest). Each entry integrates the Rayleigh,
//     Mie and ozone densities to the top (Gauss-Legendre panels on each side
//     of the perigee) and stores tau = sum beta_X m_X per channel. Below c_h
//     the ray hits the ground (transmittance 0, the shadow, see 4.); lookups
//     there clamp to c_h, the grazing ray. Cached while the AtmosphereParams
//     are bitwise unchanged.
//  3. Per elevation row (independent of azimuth): where the view ray crosses
//     the shells, each layer's column masses (4-point Gauss-Legendre), the
//     transmittance from the viewer and the layer weights
//        W_X = T(viewer -> layer) * beta_X m_X * (1 - exp(-tau)) / tau,
//     the exact integral of beta_X T(viewer -> s) over a layer whose
//     scattering/extinction ratio is constant (this keeps the horizon rows,
//     where one layer can have an optical depth above 1, accurate), with
//     their shape p + q t along the layer; and per shell the coefficients of
//     the light's zenith cosine there, alpha + beta cos(phi) (phi: azimuth
//     from the light; cos = (r0 sinL + s mu) / r, mu = dot(view, light)).
//  4. Per texel (columns 0..azimuthCount/2, then mirrored): first tau to
//     the light at every shell (table lookup, linear in the mapped angle),
//     then for each layer the integral of (p + q t) T_a e^(-(tau_b - tau_a) t)
//     over it in closed form, times a curvature term (tau along the layer is
//     not a straight line: the cubic through four neighbouring shells, see
//     curvatureFactor), times the lit fraction of the layer: the part of it
//     outside the planet's shadow cylinder, which is solved exactly per
//     texel, so the earth-shadow boundary (sun below the horizon) falls
//     smoothly inside a layer.
//
// Threads: a persistent pool made in the constructor; one dispatch per solve
// (table rows first, then sky rows, pulled from an atomic counter). Every
// row is computed by the same code from the same inputs whichever thread
// runs it, so single-threaded, multi-threaded and amortised solves are
// bit-identical. No allocation happens after construction. The hot loops
// work on contiguous float arrays and are compiled for AVX-512, AVX2 and the
// baseline (target_clones, chosen at load time): no global -march needed.
#include <aerial/limits.hpp>
#include <aerial/sky.hpp>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <condition_variable>
#include <cstdint>
#include <cstring>
#include <mutex>
#include <thread>

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && !defined(__SANITIZE_ADDRESS__) && \
    !defined(__SANITIZE_THREAD__)  // sanitizers and ifunc resolvers do not mix
#define AERIAL_HOT_KERNEL __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define AERIAL_HOT_KERNEL
#endif
// Helpers of the hot kernels are forced inline so that they are compiled
// for the kernel's target clone (a call would run the baseline code).
#if defined(__GNUC__)
#define AERIAL_INLINE inline __attribute__((always_inline))
#else
#define AERIAL_INLINE inline
#endif

namespace aerial {
namespace {

constexpr int kDefaultOpticalDepthAngles = 128;
/// Knee of the angle mapping u = x / (x + k) (x = c - c_h): half the columns
/// lie within k of the horizon cosine.
constexpr double kAngleKnee = 0.05;
/// Gauss-Legendre panels per monotonic piece of a ray to the light.
constexpr int kDepthPanels = 4;

// 4-point Gauss-Legendre on [0, 1].
constexpr double kGaussT[4] = {0.0694318442029737, 0.3300094782075719, 0.6699905217924281,
                               0.9305681557970263};
constexpr double kGaussW[4] = {0.1739274225687269, 0.3260725774312731, 0.3260725774312731,
                               0.1739274225687269};

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

/// Weight of the uniform-in-height profile in the layer mix, relative to
/// the Rayleigh and Mie profiles (1 each): half of the shells are spread
/// evenly in height, which keeps the upper layers thin enough to follow the
/// earth-shadow boundary of a set sun (measured against the reference: with
/// 32 layers the worst texel at a -5 deg sun is 1.3% off with this mix,
/// 2.2% with a third, 3.9% with a quarter).
constexpr double kUniformShare = 2.0;

/// sqrt(x) for x > 0 (relative error < 1e-5) by Newton steps on the
/// reciprocal root: plain arithmetic, so that loops over it vectorise
/// (std::sqrt keeps an errno branch that blocks GCC's vectoriser).
AERIAL_INLINE float fastSqrt(float x) {
    float y = std::bit_cast<float>(0x5f375a86 - (std::bit_cast<int>(x) >> 1));
    const float half = 0.5f * x;
    y = y * (1.5f - half * y * y);
    y = y * (1.5f - half * y * y);
    y = y * (1.5f - half * y * y);
    return x * y;
}

double safeSqrt(double x) { return x > 0.0 ? std::sqrt(x) : 0.0; }

/// Distance along a ray from radius r0 with zenith cosine mu >= 0 to the
/// sphere of radius r >= r0, given dr2 = r^2 - r0^2 >= 0 (no cancellation).
double upwardCrossing(double r0, double mu, double dr2) {
    if (!(dr2 > 0.0)) return 0.0;
    const double b = r0 * mu;
    return dr2 / (b + std::sqrt(b * b + dr2));
}

/// Density constants in the form the kernels use (float, 1/H or 0).
struct DensityConstants {
    float invRayleighH = 0.0f, rayleighOn = 0.0f;
    float invMieH = 0.0f, mieOn = 0.0f;
    float ozoneCenter = 0.0f, ozoneInvHalfWidth = 0.0f, ozoneOn = 0.0f;
};

DensityConstants densityConstants(const AtmosphereParams& air) {
    DensityConstants k;
    if (air.rayleighScaleHeight > 0.0) {
        k.invRayleighH = float(1.0 / air.rayleighScaleHeight);
        k.rayleighOn = 1.0f;
    }
    if (air.mieScaleHeight > 0.0) {
        k.invMieH = float(1.0 / air.mieScaleHeight);
        k.mieOn = 1.0f;
    }
    if (air.ozoneWidth > 0.0) {
        k.ozoneCenter = float(air.ozoneCenterHeight);
        k.ozoneInvHalfWidth = float(2.0 / air.ozoneWidth);
        k.ozoneOn = 1.0f;
    }
    return k;
}

// ---------------------------------------------------------------------------
// Hot kernels: plain loops over contiguous float arrays.

struct DepthKernelArgs {
    int count;
    float planetRadius2;
    float planetRadius;
    DensityConstants density;
    const float* q;       // p^2 - Rg^2 per column (p: impact parameter)
    const float* len1;    // length of the descending piece (0 for rising rays)
    const float* start2;  // distance from the perigee where the rising piece starts
    const float* len2;    // length of the rising piece
    float* depthR;
    float* depthM;
    float* depthO;
};

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
        const float h1 = maxZero(num1 / (fastSqrt(rg2 + num1) + rg));
        const float h2 = maxZero(num2 / (fastSqrt(rg2 + num2) + rg));
        const float ds1 = len1[m] * w, ds2 = len2[m] * w;
        outR[m] += onR * (ds1 * expNeg(h1 * invR) + ds2 * expNeg(h2 * invR));
        outM[m] += onM * (ds1 * expNeg(h1 * invM) + ds2 * expNeg(h2 * invM));
        const float tent1 = maxZero(1.0f - std::abs(h1 - oc) * oi);
        const float tent2 = maxZero(1.0f - std::abs(h2 - oc) * oi);
        outO[m] += onO * (ds1 * tent1 + ds2 * tent2);
    }
}

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

struct NodeKernelArgs {
    int count;
    float viewerHeight;
    float r0;
    float twoR0Mu;  // 2 r0 mu_view
    DensityConstants density;
    const float* s;  // node distances from the viewer
    float* rayleigh;
    float* mie;
    float* ozone;
};

/// Densities at the view-ray quadrature nodes of one row.
AERIAL_HOT_KERNEL void nodeKernel(const NodeKernelArgs& a) {
    const DensityConstants k = a.density;
    const float* __restrict s = a.s;
    float* __restrict outR = a.rayleigh;
    float* __restrict outM = a.mie;
    float* __restrict outO = a.ozone;
    for (int n = 0; n < a.count; ++n) {
        const float dr2 = s[n] * (a.twoR0Mu + s[n]);  // r^2 - r0^2
        const float h = maxZero(a.viewerHeight + dr2 / (fastSqrt(a.r0 * a.r0 + dr2) + a.r0));
        outR[n] = k.rayleighOn * expNeg(h * k.invRayleighH);
        outM[n] = k.mieOn * expNeg(h * k.invMieH);
        outO[n] = k.ozoneOn * maxZero(1.0f - std::abs(h - k.ozoneCenter) * k.ozoneInvHalfWidth);
    }
}

/// The light at one shell for every column: its zenith cosine
/// alpha + beta cos(phi) -> mapped column of that table row -> the record
/// tau rgb, T = e^-tau rgb, sqrt(tau) rgb and the margin above the shell's
/// horizon cosine (negative: the light is below it, the lookup clamped).
AERIAL_INLINE void skyShell(int nc, float alpha, float beta, float ch, float scale, float knee, float maxU,
                            const float* __restrict t0, const float* __restrict t1,
                            const float* __restrict t2, const float* __restrict cosPhi,
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
        const float d0 = t0[iu] + f * (t0[iu + 1] - t0[iu]);
        const float d1 = t1[iu] + f * (t1[iu + 1] - t1[iu]);
        const float d2 = t2[iu] + f * (t2[iu + 1] - t2[iu]);
        tau0[i] = d0;
        tau1[i] = d1;
        tau2[i] = d2;
        tr0[i] = expNeg(d0);
        tr1[i] = expNeg(d1);
        tr2[i] = expNeg(d2);
        root0[i] = fastSqrt(d0);
        root1[i] = fastSqrt(d1);
        root2[i] = fastSqrt(d2);
        margins[i] = margin;
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

/// Per-layer constants of a sky row.
struct LayerConstants {
    float alpha, beta, horizonCos, angleScale;  // upper shell: light cosine alpha + beta cos(phi), table row
    float start, end, invLength;                // layer extent along the view ray
    float p[6], q[6];                           // weight p + q t: R rgb, M rgb
    float curvature;                            // tanh(lambda / 4) / 3, see curvatureFactor
    int stencilC, stencilD;  // the stencil's two shells besides the layer's own (curvatureFactor)
    float stencil[4];        // -2/3 (cubic at mid-layer - chord): weights of tau at shells a, b, C, D
};

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
    float* __restrict acc3, float* __restrict acc4, float* __restrict acc5) {
    const float s0 = k.start, s1 = k.end, invLen = k.invLength;
    const float p0 = k.p[0], p1 = k.p[1], p2 = k.p[2], p3 = k.p[3], p4 = k.p[4], p5 = k.p[5];
    const float q0 = k.q[0], q1 = k.q[1], q2 = k.q[2], q3 = k.q[3], q4 = k.q[4], q5 = k.q[5];
    const float curv = k.curvature;
    const float wA = k.stencil[0], wB = k.stencil[1], wC = k.stencil[2], wD = k.stencil[3];
    for (int i = 0; i < nc; ++i) {
        // Lit fraction: the layer [s0, s1] minus the shadow [sIn, sOut].
        const float lo = maxNonNegative(sIn[i], s0);
        const float hi = minNonNegative(sOut[i], s1);
        const float lit = maxZero(1.0f - maxZero((hi - lo) * invLen));
        // Sign bit set where a stencil shell has the light below its horizon.
        // (Loaded into locals first: a bit_cast of the array element itself
        // makes GCC lose the restrict information and the loop stays scalar.)
        const float marginA = mA[i], marginB = mB[i], marginC = mC[i], marginD = mD[i];
        const int shadowed = std::bit_cast<int>(marginA) | std::bit_cast<int>(marginB) |
                             std::bit_cast<int>(marginC) | std::bit_cast<int>(marginD);
        const float x0 = wA * tauA0[i] + wB * tauB0[i] + wC * tauC0[i] + wD * tauD0[i];
        const float x1 = wA * tauA1[i] + wB * tauB1[i] + wC * tauC1[i] + wD * tauD1[i];
        const float x2 = wA * tauA2[i] + wB * tauB2[i] + wC * tauC2[i] + wD * tauD2[i];
        float a1, a2, b1, b2, c1, c2;
        exponentialMoments(tA0[i], tB0[i], tauB0[i] - tauA0[i], a1, a2);
        exponentialMoments(tA1[i], tB1[i], tauB1[i] - tauA1[i], b1, b2);
        exponentialMoments(tA2[i], tB2[i], tauB2[i] - tauA2[i], c1, c2);
        const float g0 = lit * curvatureFactor(x0, shadowed, tauA0[i], tauB0[i], rA0[i], rB0[i], curv);
        const float g1 = lit * curvatureFactor(x1, shadowed, tauA1[i], tauB1[i], rA1[i], rB1[i], curv);
        const float g2 = lit * curvatureFactor(x2, shadowed, tauA2[i], tauB2[i], rA2[i], rB2[i], curv);
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

struct SkyKernelArgs {
    int columns;
    int layers;
    int angles;
    float knee;
    float alpha0, beta0, horizonCos0, angleScale0;  // the viewer's shell
    const float* cosPhi;                            // [columns]
    const float* shadowIn;                          // [columns]
    const float* shadowOut;                         // [columns]
    const LayerConstants* layer;                    // [layers]
    const float* depth;                             // [3][layers + 1][angles] optical depth to the light
    float* shells;  // [kShellSlots][kShellRecord][columns] scratch: the light at the shells in use
    float* acc;     // [6][columns]
};

/// Floats per column of a shell record (skyShell).
constexpr int kShellRecord = 10;
/// Shell records kept at a time: a layer's stencil spans four shells.
constexpr int kShellSlots = 4;

/// The light at shell j (0: the viewer's, j > 0: the upper shell of layer
/// j - 1) into its record slot.
AERIAL_INLINE void lightAtShell(const SkyKernelArgs& a, int j, float maxU) {
    const int nc = a.columns;
    const int na = a.angles;
    const std::size_t rows = std::size_t(a.layers) + 1;
    const float alpha = j == 0 ? a.alpha0 : a.layer[j - 1].alpha;
    const float beta = j == 0 ? a.beta0 : a.layer[j - 1].beta;
    const float ch = j == 0 ? a.horizonCos0 : a.layer[j - 1].horizonCos;
    const float scale = j == 0 ? a.angleScale0 : a.layer[j - 1].angleScale;
    const float* t0 = a.depth + std::size_t(j) * na;
    const float* t1 = a.depth + (rows + std::size_t(j)) * na;
    const float* t2 = a.depth + (2 * rows + std::size_t(j)) * na;
    float* r = a.shells + std::size_t(j % kShellSlots) * kShellRecord * nc;
    skyShell(nc, alpha, beta, ch, scale, a.knee, maxU, t0, t1, t2, a.cosPhi, r, r + nc, r + 2 * nc,
             r + 3 * nc, r + 4 * nc, r + 5 * nc, r + 6 * nc, r + 7 * nc, r + 8 * nc, r + 9 * nc);
}

/// The inner loop of a sky row over contiguous float arrays, no branch.
/// Shell records are made just ahead of the layers that use them, into
/// kShellSlots slots (shell j in slot j % kShellSlots): layer l's stencil
/// spans shells l-1 .. l+2 (0 .. 3 for the first layer, see layerStencil),
/// so shell l + 2 replaces shell l - 2 before layer l >= 2.
AERIAL_HOT_KERNEL void skyKernel(const SkyKernelArgs& a) {
    const int nc = a.columns;
    const int nl = a.layers;
    const float maxU = float(a.angles - 1) - 1e-3f;
    float* acc = a.acc;
    auto shell = [&](int j) { return a.shells + std::size_t(j % kShellSlots) * kShellRecord * nc; };
    for (int j = 0; j <= std::min(nl, kShellSlots - 1); ++j) lightAtShell(a, j, maxU);
    for (int i = 0; i < 6 * nc; ++i) acc[i] = 0.0f;
    for (int l = 0; l < nl; ++l) {
        if (l >= 2 && l + 2 <= nl) lightAtShell(a, l + 2, maxU);
        const LayerConstants& k = a.layer[l];
        const float* lo = shell(l);
        const float* up = shell(l + 1);
        const float* c = shell(k.stencilC);
        const float* d = shell(k.stencilD);
        skyLayer(nc, k, a.shadowIn, a.shadowOut, lo, lo + nc, lo + 2 * nc, lo + 3 * nc, lo + 4 * nc,
                 lo + 5 * nc, lo + 6 * nc, lo + 7 * nc, lo + 8 * nc, up, up + nc, up + 2 * nc, up + 3 * nc,
                 up + 4 * nc, up + 5 * nc, up + 6 * nc, up + 7 * nc, up + 8 * nc, c, c + nc, c + 2 * nc, d,
                 d + nc, d + 2 * nc, lo + 9 * nc, up + 9 * nc, c + 9 * nc, d + 9 * nc, acc, acc + nc,
                 acc + 2 * nc, acc + 3 * nc, acc + 4 * nc, acc + 5 * nc);
    }
}

/// The curvature stencil of layer l (LayerConstants::stencil): the cubic
/// through tau at the four shells nearest the layer (l-1 .. l+2, shifted to
/// stay within 0 .. layers; a parabola through three where there are only
/// three) taken at the layer's middle, minus the chord, times -2/3, as
/// weights of tau at the layer's shells a = l and b = l + 1 and at the other
/// two, C and D. Shells at the same distance (a viewer at the top) give no
/// correction.
void layerStencil(const double* crossing, int layers, int l, LayerConstants& lc) {
    const int n = std::min(4, layers + 1);
    const int first = std::clamp(l - 1, 0, layers + 1 - n);
    const double mid = 0.5 * (crossing[l] + crossing[l + 1]);
    double weight[4] = {0.0, 0.0, 0.0, 0.0};  // a, b, C, D
    int other[2] = {l, l};                    // C and D (unused: a, weight 0)
    int others = 0;
    bool distinct = true;
    for (int j = 0; j < n; ++j) {
        const int shellIndex = first + j;
        double lagrange = 1.0;
        for (int m = 0; m < n; ++m) {
            if (m == j) continue;
            const double gap = crossing[shellIndex] - crossing[first + m];
            if (!(std::abs(gap) > 0.0)) distinct = false;
            lagrange *= (mid - crossing[first + m]) / gap;
        }
        if (shellIndex == l) {
            weight[0] = lagrange - 0.5;
        } else if (shellIndex == l + 1) {
            weight[1] = lagrange - 0.5;
        } else {
            other[others] = shellIndex;
            weight[2 + others] = lagrange;
            ++others;
        }
    }
    lc.stencilC = other[0];
    lc.stencilD = other[1];
    for (int j = 0; j < 4; ++j) lc.stencil[j] = distinct ? float(-2.0 / 3.0 * weight[j]) : 0.0f;
}

}  // namespace

// ---------------------------------------------------------------------------

struct SkySolver::Impl {
    struct Scratch {
        // view rows
        std::vector<double> crossing;                           // [layers + 1]
        std::vector<float> nodeS, nodeR, nodeM, nodeO;          // [4 layers]
        std::vector<LayerConstants> layer;                      // [layers]
        std::vector<double> mass;                               // [3 layers]: R, M, O column masses
        std::vector<float> layerDepth, layerT, nodeT0, nodeT1;  // [3 layers]
        std::vector<float> shells;                              // [kShellSlots][kShellRecord][padded columns]
        std::vector<float> shadowIn, shadowOut;                 // [padded columns]
        std::vector<float> acc;                                 // [6 padded columns]
        // optical-depth rows
        std::vector<float> q, len1, start2, len2, depthR, depthM, depthO;  // [angles]
    };

    SkySolverDesc desc;
    int azimuthCount = 0, elevationCount = 0, layers = 0, angles = 0, columns = 0;
    int paddedColumns = 0;  // columns rounded up to 16: the kernels run no scalar tail

    // Atmosphere-dependent state (the optical-depth table and the layers).
    bool cacheValid = false;
    AtmosphereParams cachedAir;
    AtmosphereParams rawAir;                    // parameters of the solve in progress, as given
    AtmosphereParams air;                       // the same, sanitized
    std::vector<double> shellHeight;            // [layers + 1], shellHeight[0] = viewer height
    std::vector<float> horizonCos, angleScale;  // [layers + 1]
    std::vector<double> horizonCosD;            // [layers + 1]
    std::vector<float> layerCurvature;          // [layers] tanh(lambda / 4) / 3, see curvatureFactor
    std::vector<float> depth;                   // [3][layers + 1][angles]
    DensityConstants density;

    // Light-dependent state.
    glm::dvec3 light{0.0, 1.0, 0.0};
    double lightAzimuth = 0.0, sinLight = 1.0, cosLight = 0.0;
    std::vector<double> cosPhi;  // [columns]
    std::vector<float> cosPhiF;  // [padded columns]

    // Double-buffered output: tables[front] is published.
    SkyTable tables[2];
    int front = 0;

    // Amortised solve.
    bool amortised = false;
    bool depthPending = false;
    int nextRow = 0;

    // Worker pool.
    std::vector<Scratch> scratch;  // [threads], 0 = the caller
    std::vector<std::thread> threads;
    std::mutex mutex;
    std::condition_variable wakeCv, doneCv;
    std::uint64_t epoch = 0;
    int active = 0;  // workers inside runItems (guarded by mutex)
    bool quit = false;
    struct Job {
        int depthRows = 0, rowBegin = 0, rowEnd = 0;
        int total() const { return depthRows + (rowEnd - rowBegin); }
    };
    Job job;  // guarded by mutex; workers take a copy when they wake
    std::atomic<int> nextItem{0};
    std::atomic<int> depthRowsDone{0};
    std::atomic<int> itemsDone{0};

    explicit Impl(const SkySolverDesc& d);
    ~Impl();

    void setAtmosphere(const AtmosphereParams& params);
    void setLight(const glm::dvec3& direction);
    void buildLayers();
    void buildDepthRow(int row, Scratch& s);
    void solveRow(int row, Scratch& s);
    void run(int depthRows, int rowBegin, int rowEnd);
    void runItems(const Job& j, Scratch& s);
    void workerMain(int index);
    void publish();
};

SkySolver::Impl::Impl(const SkySolverDesc& d) : desc(d) {
    // Sizes over the caps of aerial/limits.hpp are clamped (desc() reports them).
    desc.azimuthCount =
        desc.azimuthCount > 0 ? std::clamp(desc.azimuthCount, 4, limits::kMaxSkyAzimuthCount) : 128;
    desc.elevationCount =
        desc.elevationCount > 0 ? std::clamp(desc.elevationCount, 2, limits::kMaxSkyElevationCount) : 64;
    desc.layerCount = desc.layerCount > 0 ? std::clamp(desc.layerCount, 2, limits::kMaxSkyLayerCount)
                                          : SkySolverDesc{}.layerCount;
    desc.opticalDepthHeights = desc.layerCount + 1;  // one row per shell
    desc.opticalDepthAngles = desc.opticalDepthAngles > 0
                                  ? std::clamp(desc.opticalDepthAngles, 8, limits::kMaxOpticalDepthAngles)
                                  : kDefaultOpticalDepthAngles;
    if (desc.threadCount <= 0) desc.threadCount = int(std::max(1u, std::thread::hardware_concurrency()));
    desc.threadCount = std::min(desc.threadCount, 256);

    azimuthCount = desc.azimuthCount;
    elevationCount = desc.elevationCount;
    layers = desc.layerCount;
    angles = desc.opticalDepthAngles;
    columns = azimuthCount / 2 + 1;
    paddedColumns = (columns + 15) / 16 * 16;

    shellHeight.assign(std::size_t(layers) + 1, 0.0);
    horizonCos.assign(std::size_t(layers) + 1, 0.0f);
    horizonCosD.assign(std::size_t(layers) + 1, 0.0);
    layerCurvature.assign(std::size_t(layers), 0.0f);
    angleScale.assign(std::size_t(layers) + 1, 0.0f);
    depth.assign(std::size_t(3) * (layers + 1) * angles, 0.0f);
    cosPhi.assign(std::size_t(columns), 1.0);
    cosPhiF.assign(std::size_t(paddedColumns), 1.0f);  // padding: a harmless direction
    for (SkyTable& t : tables) {
        t.azimuthCount = azimuthCount;
        t.elevationCount = elevationCount;
        t.rayleigh.assign(std::size_t(azimuthCount) * elevationCount * 3, 0.0f);
        t.mie.assign(std::size_t(azimuthCount) * elevationCount * 3, 0.0f);
    }
    scratch.resize(std::size_t(desc.threadCount));
    for (Scratch& s : scratch) {
        s.crossing.assign(std::size_t(layers) + 1, 0.0);
        for (auto* v : {&s.nodeS, &s.nodeR, &s.nodeM, &s.nodeO}) v->assign(std::size_t(4) * layers, 0.0f);
        s.layer.assign(std::size_t(layers), LayerConstants{});
        s.mass.assign(std::size_t(3) * layers, 0.0);
        for (auto* v : {&s.layerDepth, &s.layerT, &s.nodeT0, &s.nodeT1})
            v->assign(std::size_t(3) * layers, 0.0f);
        s.shells.assign(std::size_t(kShellSlots) * kShellRecord * paddedColumns, 0.0f);
        s.shadowIn.assign(std::size_t(paddedColumns), -1.0f);  // padding stays unshadowed
        s.shadowOut.assign(std::size_t(paddedColumns), -1.0f);
        s.acc.assign(std::size_t(6) * paddedColumns, 0.0f);
        for (auto* v : {&s.q, &s.len1, &s.start2, &s.len2, &s.depthR, &s.depthM, &s.depthO})
            v->assign(std::size_t(angles), 0.0f);
    }
    for (int i = 1; i < desc.threadCount; ++i) threads.emplace_back([this, i] { workerMain(i); });
}

SkySolver::Impl::~Impl() {
    {
        std::lock_guard<std::mutex> lock(mutex);
        quit = true;
    }
    wakeCv.notify_all();
    for (std::thread& t : threads) t.join();
}

// Dispatch. The caller publishes a job under the mutex and bumps the epoch;
// workers wake, copy the job and pull items from an atomic counter, as does
// the caller. The caller then waits only for the items that were taken (a
// worker the OS has not scheduled yet costs nothing: it finds the counter
// exhausted when it wakes). Such a straggler may still be inside runItems
// when the next job starts, so run() first waits until no worker is active.
void SkySolver::Impl::workerMain(int index) {
    std::uint64_t seen = 0;
    std::unique_lock<std::mutex> lock(mutex);
    for (;;) {
        wakeCv.wait(lock, [&] { return quit || epoch != seen; });
        if (quit) return;
        seen = epoch;
        const Job j = job;
        ++active;
        lock.unlock();
        runItems(j, scratch[std::size_t(index)]);
        lock.lock();
        if (--active == 0) doneCv.notify_all();
    }
}

// Items [0, depthRows) build optical-depth rows; the rest solve sky rows,
// which wait (briefly, yielding) until every depth row is done.
void SkySolver::Impl::runItems(const Job& j, Scratch& s) {
    const int total = j.total();
    for (;;) {
        const int item = nextItem.fetch_add(1, std::memory_order_relaxed);
        if (item >= total) return;
        if (item < j.depthRows) {
            buildDepthRow(item, s);
            depthRowsDone.fetch_add(1, std::memory_order_release);
        } else {
            while (depthRowsDone.load(std::memory_order_acquire) < j.depthRows) std::this_thread::yield();
            solveRow(j.rowBegin + item - j.depthRows, s);
        }
        if (itemsDone.fetch_add(1, std::memory_order_acq_rel) + 1 == total) {
            std::lock_guard<std::mutex> lock(mutex);
            doneCv.notify_all();
        }
    }
}

void SkySolver::Impl::run(int depthRows, int rowBegin, int rowEnd) {
    Job j;
    j.depthRows = depthRows;
    j.rowBegin = rowBegin;
    j.rowEnd = rowEnd;
    const int total = j.total();
    if (total <= 0) return;
    if (threads.empty()) {
        nextItem.store(0);
        depthRowsDone.store(0);
        itemsDone.store(0);
        runItems(j, scratch[0]);
        return;
    }
    {
        std::unique_lock<std::mutex> lock(mutex);
        doneCv.wait(lock, [&] { return active == 0; });  // stragglers of the last job have left
        job = j;
        nextItem.store(0);
        depthRowsDone.store(0);
        itemsDone.store(0);
        if (total > 1) ++epoch;  // a single item runs on the caller alone
    }
    if (total > 1) wakeCv.notify_all();
    runItems(j, scratch[0]);
    if (itemsDone.load(std::memory_order_acquire) < total) {
        std::unique_lock<std::mutex> lock(mutex);
        doneCv.wait(lock, [&] { return itemsDone.load(std::memory_order_acquire) >= total; });
    }
}

// Shells of equal mixed mass between the viewer and the top (see the file
// comment) and the per-row constants of the optical-depth table.
void SkySolver::Impl::buildLayers() {
    const double rg = air.planetRadius;
    const double top = std::max(air.atmosphereRadius - rg, 0.0);
    const double h0 = std::clamp(air.viewerHeight, 0.0, top);
    const double span = top - h0;
    // Mixed profile: Rayleigh, Mie and a uniform share (which keeps the top
    // layers thin enough for the earth-shadow boundary of a set sun).
    const double scaleHeight[2] = {air.rayleighScaleHeight, air.mieScaleHeight};
    double norm[2] = {0.0, 0.0};
    double totalWeight = 0.0;
    for (int p = 0; p < 2; ++p) {
        if (scaleHeight[p] > 0.0 && span > 0.0) {
            norm[p] = -std::expm1(-span / scaleHeight[p]);
            if (norm[p] > 0.0) totalWeight += 1.0;
        }
    }
    const double uniformWeight = span > 0.0 ? (totalWeight > 0.0 ? kUniformShare : 1.0) : 0.0;
    totalWeight += uniformWeight;
    // F(h) and F'(h): the weighted mean of the normalised profiles.
    auto mass = [&](double h, double& slope) {
        double f = uniformWeight * (h - h0) / span;
        double df = uniformWeight / span;
        for (int p = 0; p < 2; ++p) {
            if (!(norm[p] > 0.0)) continue;
            const double e = std::exp(-(h - h0) / scaleHeight[p]);
            f += (1.0 - e) / norm[p];
            df += e / (scaleHeight[p] * norm[p]);
        }
        slope = df / totalWeight;
        return f / totalWeight;
    };
    // F is increasing and concave, so Newton from below converges monotonically.
    auto solveMass = [&](double target, double from) {
        double h = from;
        for (int it = 0; it < 100; ++it) {
            double slope = 0.0;
            const double f = mass(h, slope);
            if (!(slope > 0.0)) break;
            const double step = (target - f) / slope;
            h = std::min(h + std::max(step, 0.0), top);
            if (step < 1e-4) break;
        }
        return h;
    };
    double h = h0;
    for (int k = 0; k <= layers; ++k) {
        if (span <= 0.0) {
            shellHeight[std::size_t(k)] = h0;
        } else if (k == layers) {
            shellHeight[std::size_t(k)] = top;
        } else {
            h = solveMass(double(k) / layers, h);
            shellHeight[std::size_t(k)] = h;
        }
    }
    shellHeight[0] = h0;
    for (int k = 0; k <= layers; ++k) {
        const double r = rg + shellHeight[std::size_t(k)];
        const double ratio = rg / r;
        const double ch = -safeSqrt(1.0 - ratio * ratio);
        horizonCosD[std::size_t(k)] = ch;
        horizonCos[std::size_t(k)] = float(ch);
        const double range = 1.0 - ch;
        angleScale[std::size_t(k)] = float((angles - 1) * (range + kAngleKnee) / range);
    }
    for (int l = 0; l < layers; ++l) {
        const double dh = shellHeight[std::size_t(l) + 1] - shellHeight[std::size_t(l)];
        const double lambda = air.rayleighScaleHeight > 0.0 ? dh / air.rayleighScaleHeight : 0.0;
        layerCurvature[std::size_t(l)] = float(std::tanh(0.25 * lambda) / 3.0);
    }
    density = densityConstants(air);
}

// Row `row` of the optical-depth table: transmittance from shell `row`
// towards each tabulated light zenith cosine.
void SkySolver::Impl::buildDepthRow(int row, Scratch& s) {
    const double rg = air.planetRadius;
    const double rt = std::max(air.atmosphereRadius, rg);
    const double h = shellHeight[std::size_t(row)];
    const double r = rg + h;
    const double ch = horizonCosD[std::size_t(row)];
    const double range = 1.0 - ch;
    const double capacity = range / (range + kAngleKnee);  // a at u = 1
    const double r2MinusRg2 = h * (r + rg);
    const double rt2MinusRg2 = (rt - rg) * (rt + rg);
    for (int m = 0; m < angles; ++m) {
        const double a = capacity * m / (angles - 1);
        const double c = std::min(ch + a * kAngleKnee / (1.0 - a), 1.0);
        // p^2 - Rg^2 = (r^2 - Rg^2) - r^2 c^2; negative for rising rays whose
        // line passes below the ground, >= 0 for falling rays above the horizon.
        double q = r2MinusRg2 - r * r * c * c;
        if (c < 0.0) q = std::max(q, 0.0);
        const double dStart = r * c;  // signed distance of the start from the perigee
        const double dTop = safeSqrt(rt2MinusRg2 - q);
        s.q[std::size_t(m)] = float(q);
        s.len1[std::size_t(m)] = float(std::max(-dStart, 0.0));
        s.start2[std::size_t(m)] = float(std::max(dStart, 0.0));
        s.len2[std::size_t(m)] = float(std::max(dTop - std::max(dStart, 0.0), 0.0));
    }
    DepthKernelArgs args{};
    args.count = angles;
    args.planetRadius = float(rg);
    args.planetRadius2 = float(rg * rg);
    args.density = density;
    args.q = s.q.data();
    args.len1 = s.len1.data();
    args.start2 = s.start2.data();
    args.len2 = s.len2.data();
    args.depthR = s.depthR.data();
    args.depthM = s.depthM.data();
    args.depthO = s.depthO.data();
    depthKernel(args);
    for (int ch3 = 0; ch3 < 3; ++ch3) {
        const float br = float(air.rayleighScattering[ch3]);
        const float bm = float(air.mieExtinction[ch3]);
        const float bo = float(air.ozoneAbsorption[ch3]);
        float* out = depth.data() + (std::size_t(ch3) * (layers + 1) + row) * angles;
        for (int m = 0; m < angles; ++m)
            out[m] =
                br * s.depthR[std::size_t(m)] + bm * s.depthM[std::size_t(m)] + bo * s.depthO[std::size_t(m)];
    }
}

// One elevation row: columns 0..azimuthCount/2, mirrored into the back table.
void SkySolver::Impl::solveRow(int row, Scratch& s) {
    const double rg = air.planetRadius;
    const double h0 = shellHeight[0];
    const double r0 = rg + h0;
    const double v = elevationCount > 1 ? double(row) / (elevationCount - 1) : 0.0;
    const double elevation = 0.5 * kPi * v * v;
    const double sinEl = row == elevationCount - 1 ? 1.0 : std::sin(elevation);
    const double cosEl = row == elevationCount - 1 ? 0.0 : std::cos(elevation);

    // Shell crossings along the (rising) view ray.
    for (int k = 0; k <= layers; ++k) {
        const double hk = shellHeight[std::size_t(k)];
        s.crossing[std::size_t(k)] = upwardCrossing(r0, sinEl, (hk - h0) * (rg + hk + r0));
    }
    const double viewLength = s.crossing[std::size_t(layers)];

    // Densities at 4 Gauss-Legendre nodes per layer.
    for (int l = 0; l < layers; ++l) {
        const double a = s.crossing[std::size_t(l)], b = s.crossing[std::size_t(l) + 1];
        for (int g = 0; g < 4; ++g) s.nodeS[std::size_t(4 * l + g)] = float(a + (b - a) * kGaussT[g]);
    }
    NodeKernelArgs nodes{};
    nodes.count = 4 * layers;
    nodes.viewerHeight = float(h0);
    nodes.r0 = float(r0);
    nodes.twoR0Mu = float(2.0 * r0 * sinEl);
    nodes.density = density;
    nodes.s = s.nodeS.data();
    nodes.rayleigh = s.nodeR.data();
    nodes.mie = s.nodeM.data();
    nodes.ozone = s.nodeO.data();
    nodeKernel(nodes);

    // Layer weights and the transmittance from the viewer. A layer's weight
    // W_X = T(viewer -> a) beta_X m_X (1 - e^-tau) / tau is the exact integral
    // of beta_X T(viewer -> s) over it when scattering / extinction is
    // constant in the layer (m_X: column mass by 4-point Gauss-Legendre; this
    // keeps the horizon rows right, where a layer's optical depth exceeds 1).
    // Its shape is the linear p + q t with the centroid of the same nodes,
    // weighted by T(a -> node) = e^(-tau t_g): p = 4 wA - 2 wB, q = 6 (wB - wA)
    // with wA = W (1 - centroid), wB = W centroid.
    for (int l = 0; l < layers; ++l) {
        const double len = s.crossing[std::size_t(l) + 1] - s.crossing[std::size_t(l)];
        double mR = 0.0, mM = 0.0, mO = 0.0;
        for (int g = 0; g < 4; ++g) {
            mR += kGaussW[g] * s.nodeR[std::size_t(4 * l + g)];
            mM += kGaussW[g] * s.nodeM[std::size_t(4 * l + g)];
            mO += kGaussW[g] * s.nodeO[std::size_t(4 * l + g)];
        }
        s.mass[std::size_t(3 * l)] = mR * len;
        s.mass[std::size_t(3 * l + 1)] = mM * len;
        s.mass[std::size_t(3 * l + 2)] = mO * len;
        for (int c = 0; c < 3; ++c)
            s.layerDepth[std::size_t(3 * l + c)] =
                float(air.rayleighScattering[c] * mR * len + air.mieExtinction[c] * mM * len +
                      air.ozoneAbsorption[c] * mO * len);
    }
    layerExpKernel(3 * layers, s.layerDepth.data(), s.layerT.data(), s.nodeT0.data(), s.nodeT1.data());
    double viewT[3] = {1.0, 1.0, 1.0};
    const double sinL = sinLight, cosL = cosLight;
    for (int l = 0; l < layers; ++l) {
        const double a = s.crossing[std::size_t(l)], b = s.crossing[std::size_t(l) + 1];
        const double len = b - a;
        LayerConstants& lc = s.layer[std::size_t(l)];
        const double mass[2] = {s.mass[std::size_t(3 * l)], s.mass[std::size_t(3 * l + 1)]};
        const float* profile[2] = {&s.nodeR[std::size_t(4 * l)], &s.nodeM[std::size_t(4 * l)]};
        for (int c = 0; c < 3; ++c) {
            const std::size_t at = std::size_t(3 * l + c);
            const double tau = s.layerDepth[at];
            const double layerT = s.layerT[at];
            // (1 - e^-tau) / tau, by its series where it would cancel.
            const double g =
                tau < 1e-2 ? 1.0 - tau * (0.5 - tau * (1.0 / 6.0 - tau / 24.0)) : (1.0 - layerT) / tau;
            // e^(-tau t_g); the nodes are symmetric (t_3 = 1 - t_0, t_2 = 1 - t_1).
            const double e0 = s.nodeT0[at], e1 = s.nodeT1[at];
            const double e[4] = {e0, e1, e1 > 0.0 ? layerT / e1 : 0.0, e0 > 0.0 ? layerT / e0 : 0.0};
            const double beta[2] = {air.rayleighScattering[c], air.mieScattering[c]};
            for (int p = 0; p < 2; ++p) {
                double num = 0.0, den = 0.0;
                for (int n = 0; n < 4; ++n) {
                    const double wn = kGaussW[n] * profile[p][n] * e[n];
                    num += wn * kGaussT[n];
                    den += wn;
                }
                const double total = viewT[c] * beta[p] * mass[p] * g;
                const double centroid = den > 0.0 ? num / den : 0.5;
                const double wA = total * (1.0 - centroid), wB = total * centroid;
                lc.p[3 * p + c] = float(4.0 * wA - 2.0 * wB);
                lc.q[3 * p + c] = float(6.0 * (wB - wA));
            }
            viewT[c] *= layerT;
        }
        lc.curvature = layerCurvature[std::size_t(l)];
        layerStencil(s.crossing.data(), layers, l, lc);
        lc.start = float(a);
        lc.end = float(b);
        lc.invLength = len > 0.0 ? float(1.0 / len) : 0.0f;
        // Light zenith cosine at the upper shell: (r0 sinL + s_b mu) / r_b
        // with mu = sinEl sinL + cosEl cosL cos(phi), i.e. alpha + beta cos(phi).
        const double rb = rg + shellHeight[std::size_t(l) + 1];
        lc.alpha = float((r0 * sinL + b * sinEl * sinL) / rb);
        lc.beta = float(b * cosEl * cosL / rb);
        lc.horizonCos = horizonCos[std::size_t(l) + 1];
        lc.angleScale = angleScale[std::size_t(l) + 1];
    }

    // The planet's shadow along each column's view ray: points x(s) whose
    // ray to the light hits the ground lie inside the cylinder of radius Rg
    // around the light axis and behind the planet (x . l < 0).
    //   |x|^2 - (x.l)^2 < Rg^2:  (1 - mu^2) s^2 + 2 r0 (sinEl - sinL mu) s + r0^2 cosL^2 - Rg^2 < 0
    //   x . l < 0:               r0 sinL + s mu < 0
    const double c2 = (r0 * cosL - rg) * (r0 * cosL + rg);
    for (int i = 0; i < columns; ++i) {
        const double mu = sinEl * sinL + cosEl * cosL * cosPhi[std::size_t(i)];
        // x . l is linear in s: lit at both ends of the ray means no shadow.
        if (sinL >= 0.0 && r0 * sinL + viewLength * mu >= 0.0) {
            s.shadowIn[std::size_t(i)] = -1.0f;
            s.shadowOut[std::size_t(i)] = -1.0f;
            continue;
        }
        double lo = -INFINITY, hi = INFINITY;
        const double a2 = 1.0 - mu * mu;
        const double b2 = r0 * (sinEl - sinL * mu);
        if (a2 > 1e-12) {
            const double disc = b2 * b2 - a2 * c2;
            if (disc > 0.0) {
                const double root = std::sqrt(disc);
                lo = (-b2 - root) / a2;
                hi = (-b2 + root) / a2;
            } else {
                hi = lo;  // empty
            }
        } else if (c2 > 0.0) {
            hi = lo;  // parallel to the axis, outside the cylinder (on it counts as inside)
        }
        if (mu > 0.0)
            hi = std::min(hi, -r0 * sinL / mu);
        else if (mu < 0.0)
            lo = std::max(lo, -r0 * sinL / mu);
        else if (!(sinL < 0.0))
            hi = lo;
        lo = std::max(lo, 0.0);
        hi = std::min(hi, viewLength);
        if (hi > lo) {
            s.shadowIn[std::size_t(i)] = float(lo);
            s.shadowOut[std::size_t(i)] = float(hi);
        } else {
            s.shadowIn[std::size_t(i)] = -1.0f;
            s.shadowOut[std::size_t(i)] = -1.0f;
        }
    }

    SkyKernelArgs k{};
    k.columns = paddedColumns;
    k.layers = layers;
    k.angles = angles;
    k.knee = float(kAngleKnee);
    k.alpha0 = float(sinL);  // at the viewer: cos(light zenith) = sinL for every column
    k.beta0 = 0.0f;
    k.horizonCos0 = horizonCos[0];
    k.angleScale0 = angleScale[0];
    k.cosPhi = cosPhiF.data();
    k.shadowIn = s.shadowIn.data();
    k.shadowOut = s.shadowOut.data();
    k.layer = s.layer.data();
    k.depth = depth.data();
    k.shells = s.shells.data();
    k.acc = s.acc.data();
    skyKernel(k);
    SkyTable& out = tables[1 - front];
    for (int i = 0; i < columns; ++i) {
        const std::size_t at0 = (std::size_t(row) * azimuthCount + i) * 3;
        const std::size_t at1 = (std::size_t(row) * azimuthCount + (azimuthCount - i) % azimuthCount) * 3;
        for (int c = 0; c < 3; ++c) {
            // Never below 0 (rounding) and never NaN.
            const float r = s.acc[std::size_t(c * paddedColumns + i)];
            const float m = s.acc[std::size_t((3 + c) * paddedColumns + i)];
            const float vr = r > 0.0f ? r : 0.0f;
            const float vm = m > 0.0f ? m : 0.0f;
            out.rayleigh[at0 + c] = vr;
            out.rayleigh[at1 + c] = vr;
            out.mie[at0 + c] = vm;
            out.mie[at1 + c] = vm;
        }
    }
}

// The parameters as the solver uses them: non-finite values take the
// defaults, coefficients are clamped to [0, 1e10] 1/m, the top lies above
// the ground. Bad data gives a meaningful table, never NaN.
static AtmosphereParams sanitized(const AtmosphereParams& in) {
    const AtmosphereParams d;
    AtmosphereParams a = in;
    auto finiteOr = [](double x, double fallback) { return std::isfinite(x) ? x : fallback; };
    auto coefficient = [](const glm::dvec3& v) {
        glm::dvec3 out;
        for (int c = 0; c < 3; ++c) out[c] = v[c] > 0.0 ? std::min(v[c], 1e10) : 0.0;
        return out;
    };
    a.planetRadius =
        in.planetRadius > 0.0 && std::isfinite(in.planetRadius) ? in.planetRadius : d.planetRadius;
    a.atmosphereRadius = std::max(finiteOr(in.atmosphereRadius, d.atmosphereRadius), a.planetRadius);
    a.viewerHeight = finiteOr(in.viewerHeight, 0.0);
    a.rayleighScattering = coefficient(in.rayleighScattering);
    a.mieScattering = coefficient(in.mieScattering);
    a.mieExtinction = coefficient(in.mieExtinction);
    a.ozoneAbsorption = coefficient(in.ozoneAbsorption);
    a.rayleighScaleHeight = finiteOr(in.rayleighScaleHeight, 0.0);
    a.mieScaleHeight = finiteOr(in.mieScaleHeight, 0.0);
    a.ozoneCenterHeight = finiteOr(in.ozoneCenterHeight, d.ozoneCenterHeight);
    a.ozoneWidth = finiteOr(in.ozoneWidth, 0.0);
    return a;
}

void SkySolver::Impl::setAtmosphere(const AtmosphereParams& params) {
    rawAir = params;
    air = sanitized(params);
    if (cacheValid && std::memcmp(&cachedAir, &params, sizeof(AtmosphereParams)) == 0) {
        depthPending = false;
        return;
    }
    cacheValid = false;
    buildLayers();
    depthPending = true;
}

void SkySolver::Impl::setLight(const glm::dvec3& direction) {
    const double len =
        std::sqrt(direction.x * direction.x + direction.y * direction.y + direction.z * direction.z);
    light = len > 0.0 && std::isfinite(len) ? direction / len : glm::dvec3(0.0, 1.0, 0.0);
    lightAzimuth = std::atan2(light.x, -light.z);
    sinLight = std::clamp(light.y, -1.0, 1.0);
    cosLight = std::sqrt(light.x * light.x + light.z * light.z);
    for (int i = 0; i < columns; ++i) {
        const double phi = 2.0 * kPi * i / azimuthCount;
        cosPhi[std::size_t(i)] = std::cos(phi);
        cosPhiF[std::size_t(i)] = float(cosPhi[std::size_t(i)]);
    }
    SkyTable& back = tables[1 - front];
    back.lightDirection = light;
    back.lightAzimuth = lightAzimuth;
}

// Horizon averages (row 0, all columns, equal weights) and the swap.
void SkySolver::Impl::publish() {
    SkyTable& back = tables[1 - front];
    glm::dvec3 sumR(0.0), sumM(0.0);
    for (int i = 0; i < azimuthCount; ++i) {
        for (int c = 0; c < 3; ++c) {
            sumR[c] += back.rayleigh[std::size_t(i) * 3 + c];
            sumM[c] += back.mie[std::size_t(i) * 3 + c];
        }
    }
    back.horizonRayleigh = sumR / double(azimuthCount);
    back.horizonMie = sumM / double(azimuthCount);
    back.generation = tables[front].generation + 1;
    front = 1 - front;
}

SkySolver::SkySolver(const SkySolverDesc& desc) : impl_(std::make_unique<Impl>(desc)) {}
SkySolver::~SkySolver() = default;

void SkySolver::solve(const AtmosphereParams& air, const glm::dvec3& lightDirection) {
    Impl& m = *impl_;
    m.amortised = false;
    m.setAtmosphere(air);
    m.setLight(lightDirection);
    const int depthRows = m.depthPending ? m.layers + 1 : 0;
    m.run(depthRows, 0, m.elevationCount);
    if (m.depthPending) {
        m.cachedAir = m.rawAir;
        m.cacheValid = true;
        m.depthPending = false;
    }
    m.publish();
}

void SkySolver::beginSolve(const AtmosphereParams& air, const glm::dvec3& lightDirection) {
    Impl& m = *impl_;
    m.setAtmosphere(air);
    m.setLight(lightDirection);
    m.amortised = true;
    m.nextRow = 0;
}

bool SkySolver::continueSolve(int rows) {
    Impl& m = *impl_;
    if (!m.amortised) return true;
    rows = std::max(rows, 1);
    if (m.depthPending) {
        m.run(m.layers + 1, 0, 0);
        m.cachedAir = m.rawAir;
        m.cacheValid = true;
        m.depthPending = false;
        --rows;
    }
    const int end = std::min(m.nextRow + rows, m.elevationCount);
    m.run(0, m.nextRow, end);
    m.nextRow = end;
    if (m.nextRow < m.elevationCount) return false;
    m.amortised = false;
    m.publish();
    return true;
}

bool SkySolver::solving() const { return impl_->amortised; }

const SkyTable& SkySolver::table() const { return impl_->tables[impl_->front]; }

const SkySolverDesc& SkySolver::desc() const { return impl_->desc; }

void SkySolver::invalidateCache() { impl_->cacheValid = false; }

}  // namespace aerial
