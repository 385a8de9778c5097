// sky_solver_row.cpp — one elevation row of the sky solver (sky_solver.cpp
// describes the whole solve, 3. and 4.): its columns' azimuths, the view
// ray's layers, the kernels' inputs, and the spread of the multiple
// scattering from its integrated azimuths into the row's columns.
#include "sky_solver_impl.hpp"

#include <aerial/sky.hpp>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstdint>
#include <thread>

namespace aerial {

using namespace detail;

namespace {

/// A row sums the straight-on share of Mie's forward peak (solveRow) where
/// it reaches this fraction of the row's single scattering (fading in from
/// half of it).
constexpr double kStraightOnFloor = 5e-3;

/// v > 0 ? v : 0 (so never NaN, nor below 0) on the bit pattern: the same
/// value for every input, in integer operations that GCC vectorises (a float
/// compare blocks it under -ftrapping-math).
inline float positiveOrZero(float v) {
    const std::int32_t b = std::bit_cast<std::int32_t>(v);
    return std::bit_cast<float>(b > 0 && b <= 0x7f800000 ? b : 0);  // above +inf: NaN
}

/// Distance along a ray from radius r0 with zenith cosine mu >= 0 to the
/// sphere of radius r >= r0, given dr2 = r^2 - r0^2 >= 0 (no cancellation).
double upwardCrossing(double r0, double mu, double dr2) {
    if (!(dr2 > 0.0)) return 0.0;
    const double b = r0 * mu;
    return dr2 / (b + std::sqrt(b * b + dr2));
}

/// The curvature stencil of layer l (LayerConstants::stencil): the cubic
/// through tau at the four shells nearest the layer (l-1 .. l+2, shifted to
/// stay within 0 .. layers; a parabola through three where there are only
/// three) taken at the layer's middle, minus the chord, times -2/3, as
/// weights of tau at the layer's shells a = l and b = l + 1 and at the other
/// two, C and D. Shells at the same distance (a viewer at the top) give no
/// correction. Called for every layer of every row: it stays in this file,
/// where GCC inlines it into solveRow (in its own file it costs 0.5%).
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
        double num = 1.0, den = 1.0;
        for (int m = 0; m < n; ++m) {
            if (m == j) continue;
            const double gap = crossing[shellIndex] - crossing[first + m];
            if (!(std::abs(gap) > 0.0)) distinct = false;
            num *= mid - crossing[first + m];
            den *= gap;
        }
        const double lagrange = distinct ? num / den : 0.0;
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

// The azimuths of a row's columns 0..azimuthCount/2 (SkyTable::columnAzimuth): the
// uniform ones, or where the column mapping warps the row (around the cap
// of the earth's shadow opposite a light just set) the row's own, with their
// cosines and spreadMultiple's stencil. A warped row's azimuths reach pi
// before its last column in most rows of a light 0-0.5 deg down (the
// columns crowd into the cap; 2-3 at pi in 44-51 of the 64 rows): the row
// is solved for its distinct columns only, the first at pi standing for
// the rest (solveRow copies it), which brings its 65 columns to 64 lanes
// instead of 72 (every column's integral is its own, so the table is the
// same to the bit). The lanes past a row's distinct columns hold what an
// earlier row left there (finite azimuths, shadow spans and stencils); the
// kernels compute them like padding and nothing reads them back.
void SkySolver::Impl::rowColumns(int row, Scratch& s) const {
    const SkyTable& back = tables[1 - front];
    const bool uniform = !skyTableColumnsWarped(back);
    s.rowColumnCount = columns;
    s.rowStride = paddedColumns;
    if (uniform) {
        s.phi = phi.data();
        s.cosPhi = cosPhi.data();
        s.cosHalfPhi = cosHalfPhi.data();
        s.sinHalfPhi = sinHalfPhi.data();
        s.cosPhiF = cosPhiF.data();
        s.spreadIndex = spreadIndex.data();
        s.spreadWeight = spreadWeight.data();
        return;
    }
    const double* azimuth = back.columnAzimuth.data() + std::size_t(row) * std::size_t(azimuthCount);
    for (int i = 0; i < columns; ++i) {
        s.rowPhi[std::size_t(i)] = std::min(azimuth[i], kPi);
        if (s.rowPhi[std::size_t(i)] == kPi) {
            s.rowColumnCount = i + 1;
            break;
        }
    }
    // (Never under the multiple scattering's azimuths, which the kernel
    // keeps in the same records.)
    s.rowStride = (std::max(s.rowColumnCount, kMsSkyColumns) + 7) / 8 * 8;
    spreadStencilKernel(s.rowColumnCount, s.rowPhi.data(), s.rowStride, s.rowSpreadIndex.data(),
                        s.rowSpreadWeight.data());
    halfAngleKernel(s.rowColumnCount, s.rowPhi.data(), s.rowCosHalfPhi.data(), s.rowSinHalfPhi.data(),
                    s.rowCosPhi.data(), s.rowCosPhiF.data());
    s.phi = s.rowPhi.data();
    s.cosPhi = s.rowCosPhi.data();
    s.cosHalfPhi = s.rowCosHalfPhi.data();
    s.sinHalfPhi = s.rowSinHalfPhi.data();
    s.cosPhiF = s.rowCosPhiF.data();
    s.spreadIndex = s.rowSpreadIndex.data();
    s.spreadWeight = s.rowSpreadWeight.data();
}

// One elevation row: columns 0..azimuthCount/2, mirrored into the back table.
void SkySolver::Impl::solveRow(int row, Scratch& s) {
    const double rg = air.planetRadius;
    const double h0 = shellHeight[0];
    const double r0 = rg + h0;
    const double elevation = rowElevation[std::size_t(row)];
    rowColumns(row, s);
    const double sinEl = row == elevationCount - 1 ? 1.0 : std::sin(elevation);
    const double cosEl = row == elevationCount - 1 ? 0.0 : std::cos(elevation);

    // Shell crossings along the (rising) view ray.
    for (int k = 0; k <= layers; ++k) {
        const double hk = shellHeight[std::size_t(k)];
        s.crossing[std::size_t(k)] = upwardCrossing(r0, sinEl, (hk - h0) * (rg + hk + r0));
    }
    const double viewLength = s.crossing[std::size_t(layers)];

    // Densities at 4 Gauss-Legendre nodes per layer.
    segmentNodeDensities(s.crossing.data(), layers, h0, r0, sinEl, density, s.nodeS.data(), s.nodeR.data(),
                         s.nodeM.data(), s.nodeO.data());

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
        const MeanDensity m = segmentMeanDensity(s.nodeR.data(), s.nodeM.data(), s.nodeO.data(), l);
        const double mR = m.rayleigh, mM = m.mie, mO = m.ozone;
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
    // The straight-on share of Mie's forward peak (sky_multiple.hpp, "Mie's
    // truncation"): light scattered once and then on by less than the cone
    // keeps going towards the viewer, so beside the single scattering's
    // weight beta_X T(viewer -> s) the layer carries beta_X T (e^(f tau_M) - 1),
    // tau_M Mie's scattering depth from the viewer to s. Over the layer that
    // is T'(viewer -> a) beta_X m_X (1 - e^-tau') / tau' with tau' = tau - f
    // tau_M(layer) >= 0 (the extinction's depth is at least Mie's scattering
    // depth; clamped for air that says otherwise) and T' = T e^(f tau_M) the
    // product of the layers' e^-tau' before it, less the layer's own weight.
    // T' never rises along the ray, so a haze of any thickness neither
    // overflows nor turns 0 * inf into NaN; e^-tau' = e^-tau e^(f tau_M(layer))
    // costs one exp per layer (per channel only where Mie's scattering is
    // coloured), the solve's only transcendental per layer but layerExpKernel's.
    const double straight = multiple ? ms.mieStraightOn() : 0.0;
    double mieDepth[3] = {0.0, 0.0, 0.0};
    double straightView[3] = {1.0, 1.0, 1.0};  // T'(viewer -> a)
    const bool greyMie =
        air.mieScattering[0] == air.mieScattering[1] && air.mieScattering[1] == air.mieScattering[2];
    const double sinL = sinLight, cosL = cosLight;
    for (int l = 0; l < layers; ++l) {
        const double a = s.crossing[std::size_t(l)], b = s.crossing[std::size_t(l) + 1];
        LayerConstants& lc = s.layer[std::size_t(l)];
        const double mass[2] = {s.mass[std::size_t(3 * l)], s.mass[std::size_t(3 * l + 1)]};
        const float* profile[2] = {&s.nodeR[std::size_t(4 * l)], &s.nodeM[std::size_t(4 * l)]};
        double straightGain = 1.0;  // e^(f tau_M(layer)), grey Mie: the same in every channel
        for (int c = 0; c < 3; ++c) {
            const std::size_t at = std::size_t(3 * l + c);
            const double tau = s.layerDepth[at];
            const double layerT = s.layerT[at];
            // (1 - e^-tau) / tau, by its series where it would cancel.
            const double g = layerShape(tau, layerT);
            // e^(-tau t_g); the nodes are symmetric (t_3 = 1 - t_0, t_2 = 1 - t_1).
            const double e0 = s.nodeT0[at], e1 = s.nodeT1[at];
            const double e[4] = {e0, e1, e1 > 0.0 ? layerT / e1 : 0.0, e0 > 0.0 ? layerT / e0 : 0.0};
            const double beta[2] = {air.rayleighScattering[c], air.mieScattering[c]};
            const double mieLayer = air.mieScattering[c] * mass[1];
            double straightExtra = 0.0;
            if (straight > 0.0) {
                const double x = straight * mieLayer;
                if (c == 0 || !greyMie) straightGain = std::exp(std::min(x, 80.0));
                const double tauS = std::max(tau - x, 0.0);
                // e^-tau' (from e^-tau where layerExpKernel does not clamp it)
                const double layerS = tau < 80.0 ? std::min(layerT * straightGain, 1.0) : std::exp(-tauS);
                straightExtra = std::max(straightView[c] * layerShape(tauS, layerS) - viewT[c] * g, 0.0);
                straightView[c] *= layerS;
            }
            mieDepth[c] += mieLayer;
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
                // The straight-on share with the same shape (its centroid
                // lies a little deeper; the layers are thin where it matters).
                const double extra = beta[p] * mass[p] * straightExtra;
                const double sA = extra * (1.0 - centroid), sB = extra * centroid;
                lc.straightP[3 * p + c] = float(4.0 * sA - 2.0 * sB);
                lc.straightQ[3 * p + c] = float(6.0 * (sB - sA));
                // Multiple scattering: sigma_X T weights at a and b, with its
                // own straight-on share (the multiple scattering along the
                // view ray scattered on: e^(f tau_M) in all).
                lc.msA[3 * p + c] = float(wA + sA);
                lc.msB[3 * p + c] = float(wB + sB);
            }
            viewT[c] *= layerT;
        }
        lc.curvature = layerCurvature[std::size_t(l)];
        layerStencil(s.crossing.data(), layers, l, lc);
        lc.start = float(a);
        lc.end = float(b);
        // Light zenith cosine at the upper shell: (r0 sinL + s_b mu) / r_b
        // with mu = sinEl sinL + cosEl cosL cos(phi), i.e. alpha + beta cos(phi).
        const double rb = rg + shellHeight[std::size_t(l) + 1];
        lc.alpha = float((r0 * sinL + b * sinEl * sinL) / rb);
        lc.beta = float(b * cosEl * cosL / rb);
        lc.viewUp = float((r0 * sinEl + b) / rb);
        lc.horizonCos = horizonCos[std::size_t(l) + 1];
        lc.angleScale = angleScale[std::size_t(l) + 1];
    }

    // The planet's shadow along each column's view ray: points x(s) whose
    // ray to the light hits the ground lie inside the cylinder of radius Rg
    // around the light axis and behind the planet (x . l < 0).
    //   |x|^2 - (x.l)^2 < Rg^2:  (1 - mu^2) s^2 + 2 r0 (sinEl - sinL mu) s + r0^2 cosL^2 - Rg^2 < 0
    //   x . l < 0:               r0 sinL + s mu < 0
    // Opposite a light just set the view ray runs within 1e-7 rad of the
    // cylinder's axis: 1 - mu^2 is formed from the angles and the roots
    // without cancellation (planet_shadow.hpp); as written (1 - mu * mu,
    // under 1e-12 taken as parallel) the rows just above the shadow's kink
    // came out dark straight opposite a light 0.01 deg down.
    const double c2 = (r0 * cosL - rg) * (r0 * cosL + rg);
    // 1 + mu and 1 - mu: the angle to the anti-light point (elevation -lambda,
    // azimuth pi - phi) and to the light; their elevation parts are the row's.
    const double lightElevation = std::atan2(sinL, cosL);
    const double towardsAnti = std::sin(0.5 * (elevation + lightElevation));
    const double towardsLight = std::sin(0.5 * (elevation - lightElevation));
    const double cosCos = std::cos(elevation) * cosL;
    ShadowSpanArgs span{};
    span.count = s.rowColumnCount;
    span.cosPhi = s.cosPhi;
    span.cosHalfPhi = s.cosHalfPhi;
    span.sinHalfPhi = s.sinHalfPhi;
    span.sinEl = sinEl;
    span.cosEl = cosEl;
    span.sinL = sinL;
    span.cosL = cosL;
    span.r0 = r0;
    span.viewLength = viewLength;
    span.towardsAnti = towardsAnti;
    span.towardsLight = towardsLight;
    span.cosCos = cosCos;
    span.c2 = c2;
    // Parallel to the axis, outside the cylinder or on its surface: a
    // viewer less than 1 nm inside it (c2 ~ -2 Rg depth) counts as on it,
    // and on it counts as lit, the limit of the neighbouring directions
    // (for a light exactly on the horizon, the anti-light horizon texel
    // would otherwise be dark by rounding alone: c2 ~ -0.01 m^2 there).
    // With 1 mm a light less than ~0.001 deg down (the viewer at the ground
    // ~Rg L^2 / 2 inside) lit the rows within ~1e-12 rad below the cap's
    // top straight opposite it, the full lit sky where the exact integral
    // is dark (the cap's logarithmic rows reach 1e-6 c there:
    // SkyShadowOnset, -0.00005 deg, 185%).
    span.parallelLit = -2.0e-9 * rg;
    span.in = s.shadowIn.data();
    span.out = s.shadowOut.data();
    shadowSpanKernel(span);

    // The layers that the shadow overlaps in every column (as skyLayer tells
    // overlap, in float): skyKernel leaves their single scattering out.
    for (int l = 0; l < layers; ++l) {
        const float s0 = s.layer[std::size_t(l)].start, s1 = s.layer[std::size_t(l)].end;
        unsigned char lit = 0;
        for (int i = 0; i < s.rowColumnCount && !lit; ++i) {
            const float lo = std::max(s.shadowIn[std::size_t(i)], s0);
            const float hi = std::min(s.shadowOut[std::size_t(i)], s1);
            lit = !(hi - lo > 0.0f);
        }
        s.layerLit[std::size_t(l)] = lit;
    }

    // The columns after the last that is lit somewhere along its ray (the
    // shadow spans the whole ray, every layer overlapped, so that the
    // kernel would add +0 in each): in a row below the top of the earth's
    // shadow opposite a light set 1-6 deg, 10-28 of its 65 columns.
    int litColumns = s.rowColumnCount;
    const float rayStart = s.layer[0].start, rayEnd = s.layer[std::size_t(layers) - 1].end;
    bool layersOpen = true;  // every layer of positive length in float (none that the kernel counts lit)
    for (int l = 0; l < layers; ++l)
        layersOpen = layersOpen && s.layer[std::size_t(l)].end > s.layer[std::size_t(l)].start;
    while (layersOpen && litColumns > 0 && s.shadowIn[std::size_t(litColumns) - 1] <= rayStart &&
           s.shadowOut[std::size_t(litColumns) - 1] >= rayEnd)
        --litColumns;

    SkyKernelArgs k{};
    k.columns = s.rowStride;
    k.litColumns = std::min((litColumns + 7) / 8 * 8, s.rowStride);
    k.layers = layers;
    k.angles = angles;
    k.knee = float(kAngleKnee);
    k.alpha0 = float(sinL);  // at the viewer: cos(light zenith) = sinL for every column
    k.beta0 = 0.0f;
    k.horizonCos0 = horizonCos[0];
    k.angleScale0 = angleScale[0];
    k.cosPhi = s.cosPhiF;
    k.msCosPhi = msCosPhiF.data();
    k.shadowIn = s.shadowIn.data();
    k.shadowOut = s.shadowOut.data();
    k.layer = s.layer.data();
    k.layerLit = s.layerLit.data();
    k.depthPairs = depthPairs.data();
    const bool msSolved = multiple && msRowSolved[std::size_t(row)] != 0;
    k.psi = msSolved ? psiPairs.data() : nullptr;
    k.psiCosines = kMsCosines;
    k.aniso = msSolved && ms.anisotropic() ? anisoShell.data() : nullptr;
    k.views = k.aniso != nullptr ? viewShell.data() : nullptr;
    k.anisoPoly = s.anisoPoly.data();
    k.viewUp0 = float(sinEl);
    k.nuA = float(sinEl * sinL);
    k.nuB = float(cosEl * cosL);
    k.rayleighBand2 = float(ms.rayleighBand2());
    k.mieBand1 = float(ms.mieBand1());
    k.mieBand2 = float(ms.mieBand2());
    k.mieIsotropicShare = float(1.0 - straight);
    if (k.aniso != nullptr)
        msShellWeights(s.layer.data(), layers, k.rayleighBand2, k.mieBand1, k.mieBand2,
                       s.msWeightScratch.data(), s.msWeights.data());
    k.msWeights = s.msWeights.data();
    // Rows whose straight-on share stays below kStraightOnFloor of their
    // single scattering (e^(f tau_M) - 1 at the far end: all but the rows
    // within a few degrees of the horizon) leave it out, the cost of
    // summing it; it fades in from half the floor to the floor, so that
    // the sky stays continuous in the air and the light (with a cut, a 0.5%
    // step as g crossed 0.8001 at sun -2 deg, 6.5 deg up).
    const double straightRatio = std::expm1(straight * std::max({mieDepth[0], mieDepth[1], mieDepth[2]}));
    k.straightOn = multiple && straightRatio > 0.5 * kStraightOnFloor;
    // The light below a shell's horizon in some column: alpha + beta cos(phi)
    // is at least alpha - |beta| (with a margin for the kernel's rounding).
    // A layer needs the shadowed case if a shell of its stencil may be
    // shadowed, and a shell its roots if a layer beside it does.
    unsigned char* shellShadow = s.shellShadow.data();
    shellShadow[0] = sinL - horizonCos[0] < 1e-6f;
    for (int l = 0; l < layers; ++l) {
        const LayerConstants& lc = s.layer[std::size_t(l)];
        shellShadow[l + 1] = lc.alpha - std::abs(lc.beta) - lc.horizonCos < 1e-6f;
    }
    k.shadow = false;
    for (int l = 0; l < layers; ++l) {
        const LayerConstants& lc = s.layer[std::size_t(l)];
        s.layerShadow[std::size_t(l)] =
            shellShadow[l] | shellShadow[l + 1] | shellShadow[lc.stencilC] | shellShadow[lc.stencilD];
        k.shadow = k.shadow || s.layerShadow[std::size_t(l)];
    }
    for (int j = 0; j <= layers; ++j)
        s.shellRoots[std::size_t(j)] =
            (j > 0 && s.layerShadow[std::size_t(j) - 1]) || (j < layers && s.layerShadow[std::size_t(j)]);
    k.layerShadow = s.layerShadow.data();
    k.shellRoots = s.shellRoots.data();
    const double straightFade = std::min(straightRatio / (0.5 * kStraightOnFloor) - 1.0, 1.0);
    k.shells = s.shells.data();
    k.acc = s.acc.data();
    skyKernel(k);
    shadowEdgeLayers(s, r0, sinEl, k.straightOn);
    if (multiple) {
        // The row's multiple scattering at the kMsSkyColumns azimuths: its
        // own, kept for the rows between, or theirs (planMultipleRows).
        float* value = &msRowValue[std::size_t(row) * 3 * kMsSkyColumns];
        const std::size_t n = std::size_t(s.rowStride);
        if (msSolved) {
            for (std::size_t c = 0; c < 3; ++c)
                std::copy_n(&s.acc[(6 + c) * n], kMsSkyColumns, value + c * kMsSkyColumns);
            msRowDone[std::size_t(row)].store(1, std::memory_order_release);
        } else {
            const int* node = &msRowNode[std::size_t(4 * row)];
            const float* weight = &msRowWeight[std::size_t(4 * row)];
            for (int q = 0; q < 4; ++q)
                while (msRowDone[std::size_t(node[q])].load(std::memory_order_acquire) == 0)
                    std::this_thread::yield();
            for (std::size_t c = 0; c < 3; ++c) {
                for (int a = 0; a < kMsSkyColumns; ++a) {
                    float v = 0.0f;
                    for (int q = 0; q < 4; ++q)
                        v += weight[q] *
                             msRowValue[(std::size_t(node[q]) * 3 + c) * kMsSkyColumns + std::size_t(a)];
                    s.acc[(6 + c) * n + std::size_t(a)] = std::max(v, 0.0f);  // a cubic may dip below
                }
            }
        }
        spreadMultiple(s);
    }
    if (k.straightOn) {
        // The straight-on share, phase-less as the single scattering, with
        // the phases of each column's angle to the light.
        // (rayleighPhase and miePhase, in a kernel that vectorises.)
        const double g = air.mieAnisotropy;
        StraightOnArgs so{};
        so.count = s.rowColumnCount;
        so.stride = s.rowStride;
        so.cosPhi = s.cosPhi;
        so.nuA = sinEl * sinL;
        so.nuB = cosEl * cosL;
        so.g = std::isfinite(g) ? std::clamp(g, -0.999, 0.999) : 0.0;
        so.fade = straightFade;
        so.acc = s.acc.data();
        straightOnKernel(so);
    }
    // Columns 0..columns-1 from the accumulators (never below 0, rounding,
    // and never NaN; those after the row's distinct ones copies of its last),
    // then their mirrors azimuthCount - i.
    SkyTable& out = tables[1 - front];
    const std::size_t rowAt = std::size_t(row) * azimuthCount * 3;
    float* planes[3] = {out.rayleigh.data() + rowAt, out.mie.data() + rowAt, out.multiple.data() + rowAt};
    for (std::size_t x = 0; x < 3; ++x) {
        float* __restrict texel = planes[x];
        const std::size_t n = std::size_t(s.rowStride);
        const float* __restrict from = s.acc.data() + 3 * x * n;
        const int distinct = s.rowColumnCount;
        for (std::size_t i = 0; i < std::size_t(distinct); ++i) {
            const float r = from[i], g = from[n + i], b = from[2 * n + i];
            texel[3 * i] = positiveOrZero(r);
            texel[3 * i + 1] = positiveOrZero(g);
            texel[3 * i + 2] = positiveOrZero(b);
        }
        // (Element by element: std::copy_n of 3 floats is a call to memmove,
        // 2% of a solve.)
        auto copyTexel = [texel](std::size_t source, std::size_t to) {
            for (std::size_t c = 0; c < 3; ++c) texel[3 * to + c] = texel[3 * source + c];
        };
        for (int i = distinct; i < columns; ++i) copyTexel(std::size_t(distinct - 1), std::size_t(i));
        for (int i = 1; 2 * i < azimuthCount; ++i) copyTexel(std::size_t(i), std::size_t(azimuthCount - i));
    }
}

// The multiple scattering of a row from its kMsSkyColumns azimuths
// phi_k = pi k / (K - 1) (skyKernel) into the table's columns: Catmull-Rom
// in ln(value), the azimuths mirrored about 0 and pi (the row is symmetric
// about the light's vertical plane); linear where a value is 0 (no
// atmosphere). In twilight the multiple scattering falls about
// exponentially away from the light; against integrating every column this
// changes the pixel by at most 0.12% (relative to the total radiance,
// floored at 1% of the brightest; 20000 random directions per sun from -6
// to 90 deg), where interpolating the value linearly cost ~1.6% at -6 deg.
void SkySolver::Impl::spreadMultiple(Scratch& s) const {
    constexpr int kK = kMsSkyColumns;
    for (int c = 0; c < 3; ++c) {
        float* x = &s.acc[std::size_t((6 + c) * s.rowStride)];
        float value[kK], logValue[kK];
        bool positive = true;
        for (int k = 0; k < kK; ++k) {
            value[k] = x[k] > 0.0f && std::isfinite(x[k]) ? x[k] : 0.0f;
            positive = positive && value[k] > 1e-30f;
            // ln in [-69, 60]: Catmull-Rom overshoots by at most 0.148 of the
            // range, so the sum stays inside spreadKernel's (-87, 87).
            logValue[k] = positive ? std::min(std::log(value[k]), 60.0f) : 0.0f;
        }
        if (positive) {
            SpreadKernelArgs a{};
            a.count = s.rowStride;
            a.index = s.spreadIndex;
            a.weight = s.spreadWeight;
            a.logValue = logValue;
            a.out = x;
            spreadKernel(a);
            continue;
        }
        for (int i = 0; i < s.rowColumnCount; ++i) {  // linear between the two nearest
            const double u = s.phi[i] / kPi * (kK - 1);
            const int k = std::min(int(u), kK - 2);
            const float f = float(u - k);
            x[i] = value[k] + f * (value[k + 1] - value[k]);
        }
    }
}

}  // namespace aerial
