// sky_kernels_columns.cpp — the sky solver's per-column kernels around a
// row (sky_kernels.hpp): its columns' half-angles and multiple-scattering
// stencils and spread, the earth's shadow along their rays and the pieces of
// the layers its edge cuts, the straight-on share's phases. Hot kernels like
// sky_kernels.cpp's (whose file comment says how they are written), with
// the same compile options (core/CMakeLists.txt).
#include "phase.hpp"
#include "planet_shadow.hpp"
#include "sky_kernels.hpp"
#include "sky_kernels_inline.hpp"
#include "sky_multiple.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace aerial::detail {

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

/// spreadKernel's loop (restrict parameters: see crossingRecords,
/// sky_kernels_tables.cpp).
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

}  // namespace aerial::detail
