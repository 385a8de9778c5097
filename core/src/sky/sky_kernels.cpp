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
//
// This file: the sky row (skyKernel and its per-shell and per-layer
// helpers), the view-ray densities and layer transmittances of a row;
// sky_kernels_columns.cpp the per-column parts around a row;
// sky_kernels_tables.cpp the optical-depth table's and the
// multiple-scattering LUT's kernels; sky_kernels_inline.hpp the macros and
// float helpers they share.
#include "sky_kernels.hpp"
#include "phase.hpp"
#include "planet_shadow.hpp"
#include "sky_kernels_inline.hpp"
#include "sky_multiple.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace aerial::detail {
namespace {

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

}  // namespace aerial::detail
