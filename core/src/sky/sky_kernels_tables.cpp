// sky_kernels_tables.cpp — the kernels of the sky solver's atmosphere
// tables (sky_kernels.hpp): the optical depths of a row of the
// optical-depth table and its lookup pairs, and the multiple-scattering
// LUT's crossings, sources and segments (sky_multiple.cpp). Hot kernels like
// sky_kernels.cpp's (whose file comment says how they are written), with
// the same compile options (core/CMakeLists.txt).
#include "sky_kernels.hpp"
#include "sky_kernels_inline.hpp"
#include "sky_multiple.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace aerial::detail {
namespace {

/// Gauss-Legendre panels per monotonic piece of a ray to the light.
constexpr int kDepthPanels = 4;

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
