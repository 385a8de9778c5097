// sky_solver_shadow.cpp — the sky solver's layers that an edge of the
// earth's shadow cuts (sky_solver.cpp describes the whole solve, 4.): the
// lit piece of each, for a light below the horizon.
#include "sky_solver_impl.hpp"

#include <aerial/sky.hpp>

#include <algorithm>
#include <cmath>

namespace aerial {

using namespace detail;

// The layers that an edge of the earth's shadow cuts, which skyKernel leaves
// out (a layer the shadow overlaps adds nothing there): for each column, the
// lit part of such a layer only, [s0, sIn] or [sOut, s1], added here. Near
// the horizon of a light just set this piece carries most of the texel (85%
// of the blue 30 deg from the anti-light point, a sun 0.01 deg down: the
// edge lies in the first layer there, 10 km out along a 40 km layer), and
// the light reaches it through an optical depth of ~10, so 0.5% in tau is 5%
// in the texel. Both factors of the integrand are modelled, not taken from
// the whole layer's straight lines:
//  * The view's weight beta_X T(viewer -> s) falls about exponentially along
//    the layer, e^(-kappa t) with kappa the layer's optical depth plus the
//    density's fall across it (from its first and last Gauss nodes), scaled
//    so that the whole layer integrates to its weight W = p + q/2. The
//    layer's linear p + q t (matched mean and centroid) put ~3% too much of
//    W into the far two thirds of the horizon's first layer (blue depth 1.5).
//  * The optical depth to the light at the edge is that of the ray grazing
//    the ground from the edge's height, at the lit shell the table's, and in
//    between (at the piece's middle) the table's rows of the layer's two
//    shells at the point's own margin above its horizon, interpolated
//    linearly in the tangent length sqrt(r^2 - Rg^2) (at the edge, margin 0,
//    that is the grazing value). tau is linear in each half (edgePieceKernel).
//    Along a ray looking away from the light the optical depth rises and
//    bulges above its chord (by 0.03 at the middle of the piece above,
//    where tau = 10..11): taken log-linear through the ends, as before, it
//    sagged below it instead.
// A sun 0.01 deg down, the horizon texels 26-30 deg from the anti-light
// point: 5.2 -> 0.9% (Rayleigh, blue), 4.4 -> 0.7% (Mie). Multiplying the
// whole layer's integral by its lit fraction, with the shadowed shell's
// lookup clamped to its grazing ray, put up to 17% too much Mie into the
// horizon towards a sun 0.5 deg below it.
void SkySolver::Impl::shadowEdgeLayers(Scratch& s, double r0, double sinEl, bool straightOn) {
    const double rg = air.planetRadius;
    const double cosEl = std::sqrt(std::max(1.0 - sinEl * sinEl, 0.0));
    const std::size_t rows = std::size_t(layers) + 1;
    const int cap = 2 * paddedColumns;
    float* crossing = s.edgeCrossing.data();
    for (int k = 0; k <= layers; ++k) crossing[k] = float(s.crossing[std::size_t(k)]);
    const double r0Tangent2 = (r0 - rg) * (r0 + rg);
    // Of layer l, the same in every column: the view's weight's fall kappa
    // and its weights A = W kappa / (1 - e^-kappa) (the single scattering's,
    // then the straight-on share's); its shells' tangent lengths (below).
    std::fill(s.edgeLayerReady.begin(), s.edgeLayerReady.end(), 0);
    auto layerWeights = [&](int l) {
        if (s.edgeLayerReady[std::size_t(l)]) return;
        s.edgeLayerReady[std::size_t(l)] = 1;
        const LayerConstants& lc = s.layer[std::size_t(l)];
        const float* profile[2] = {&s.nodeR[std::size_t(4 * l)], &s.nodeM[std::size_t(4 * l)]};
        for (int x = 0; x < 2; ++x) {
            const double first = profile[x][0], last = profile[x][3];
            const double fall =
                first > 0.0 && last > 0.0 ? std::log(first / last) / (kGaussT[3] - kGaussT[0]) : 0.0;
            for (int c = 0; c < 3; ++c) {
                // >= 0: the rows rise, so density and transmittance fall.
                const double kappa = std::max(double(s.layerDepth[std::size_t(3 * l + c)]) + fall, 0.0);
                const int k = 3 * x + c;
                // kappa / (1 - e^-kappa): 1 / layerShape (its series where
                // the quotient cancels; std::exp, a third of the std::expm1
                // this took, which was 2% of a solve for a light just set).
                const double norm = 1.0 / layerShape(kappa, std::exp(-kappa));
                s.edgeLayerKappa[std::size_t(6 * l + k)] = float(kappa);
                s.edgeLayerWeight[std::size_t(12 * l + k)] = float((lc.p[k] + 0.5 * double(lc.q[k])) * norm);
                s.edgeLayerWeight[std::size_t(12 * l + 6 + k)] =
                    float((lc.straightP[k] + 0.5 * double(lc.straightQ[k])) * norm);
            }
        }
        // The shells' tangent lengths z = sqrt(r^2 - Rg^2) (c_h = -z / r at
        // their horizon): the optical depth at the edge and the middle is
        // linear in z, the grazing ray's path down to the ground, which its
        // optical depth grows with (linear in height put it 4% low 22 m above
        // the ground, and the sky above the earth's shadow of a sun 0.07 deg
        // down 7% too bright).
        const double za = -horizonCosD[std::size_t(l)] * (rg + shellHeight[std::size_t(l)]);
        const double zb = -horizonCosD[std::size_t(l) + 1] * (rg + shellHeight[std::size_t(l) + 1]);
        s.edgeLayerTangent[std::size_t(2 * l)] = za;
        s.edgeLayerTangent[std::size_t(2 * l + 1)] = zb > za ? 1.0 / (zb - za) : 0.0;
        // Its extent along the view ray.
        const double s0 = crossing[l];
        s.edgeLayerExtent[std::size_t(2 * l)] = s0;
        s.edgeLayerExtent[std::size_t(2 * l + 1)] = 1.0 / (double(crossing[l + 1]) - s0);
    };
    int n = 0;
    // One lit piece of layer l, from s = from to s = to, in column i whose
    // light cosine along the view is mu and at the lit shell `litQ` (its
    // margin mapped, q); `edgeAtStart`: the start is the shadow's edge (else
    // the end is). edgePieceKernel takes it from here.
    auto piece = [&](int i, double mu, double litQ, int l, float from, float to, bool edgeAtStart) {
        if (!(double(crossing[l + 1]) - crossing[l] > 0.0)) return;
        layerWeights(l);
        const std::size_t m = std::size_t(n++);
        s.pieceFrom[m] = from;
        s.pieceTo[m] = to;
        s.pieceMu[m] = mu;
        s.pieceLitQ[m] = litQ;
        s.edgeColumn[m] = i;
        s.edgeLayer[m] = l;
        s.pieceAtStart[m] = edgeAtStart ? 1 : 0;
    };
    // The layer whose inside (start, end) holds s, or -1.
    auto layerOf = [&](float sv) {
        const float* it = std::upper_bound(crossing, crossing + layers + 1, sv);
        const int l = int(it - crossing) - 1;
        return l >= 0 && l < layers && crossing[l] < sv && sv < crossing[l + 1] ? l : -1;
    };
    // The light's margin above shell k's horizon in column i, mapped (the
    // optical-depth table's x / (x + knee), opticalDepthRow).
    auto litQ = [&](int k, int i) {
        const double alpha = k == 0 ? sinLight : double(s.layer[std::size_t(k) - 1].alpha);
        const double beta = k == 0 ? 0.0 : double(s.layer[std::size_t(k) - 1].beta);
        const double x = std::max(alpha + beta * s.cosPhi[i] - horizonCos[std::size_t(k)], 0.0);
        return x / (x + kAngleKnee);
    };
    for (int i = 0; i < s.rowColumnCount; ++i) {
        const float sIn = s.shadowIn[std::size_t(i)], sOut = s.shadowOut[std::size_t(i)];
        if (!(sOut > sIn)) continue;  // no shadow in this column
        const int lIn = layerOf(sIn), lOut = layerOf(sOut);
        const double mu = sinEl * sinLight + cosEl * cosLight * s.cosPhi[i];
        // The lit shell: the lower one (l) for a piece that ends at the edge.
        if (lIn >= 0) piece(i, mu, litQ(lIn, i), lIn, crossing[lIn], sIn, false);
        if (lOut >= 0) piece(i, mu, litQ(lOut + 1, i), lOut, sOut, crossing[lOut + 1], true);
    }
    if (n == 0) return;
    EdgePieceArgs p{};
    p.count = n;
    p.stride = cap;
    p.from = s.pieceFrom.data();
    p.to = s.pieceTo.data();
    p.mu = s.pieceMu.data();
    p.litQ = s.pieceLitQ.data();
    p.layer = s.edgeLayer.data();
    p.edgeAtStart = s.pieceAtStart.data();
    p.tangent2 = r0Tangent2;
    p.viewTwice = 2.0 * r0 * sinEl;
    p.planetRadius2 = rg * rg;
    p.lightAtViewer = r0 * sinLight;
    p.knee = kAngleKnee;
    p.maxU = double(angles - 1) - 1e-3;
    p.angles = angles;
    p.angleScale = angleScale.data();
    p.depthPairs = depthPairs.data();
    p.plane = rows * std::size_t(angles);
    p.layerKappa = s.edgeLayerKappa.data();
    p.layerTangent = s.edgeLayerTangent.data();
    p.layerExtent = s.edgeLayerExtent.data();
    p.tauStart = s.edgeTauStart.data();
    p.tauMid = s.edgeTauMid.data();
    p.tauEnd = s.edgeTauEnd.data();
    p.t0 = s.edgeT0.data();
    p.dt = s.edgeDt.data();
    p.kappa = s.edgeKappa.data();
    p.out = s.edgeOut.data();
    edgePieceKernel(p);
    // Into the row's accumulators: R rgb, M rgb, and with the straight-on
    // share (skyKernel's acc 9..14) the same integrals with its weights.
    const std::size_t stride = std::size_t(s.rowStride), outStride = std::size_t(cap);
    for (int m = 0; m < n; ++m) {
        float* acc = s.acc.data() + s.edgeColumn[std::size_t(m)];
        const float* out = s.edgeOut.data() + m;
        const float* weight = s.edgeLayerWeight.data() + 12 * s.edgeLayer[std::size_t(m)];
        for (std::size_t k = 0; k < 6; ++k) acc[k * stride] += weight[k] * out[k * outStride];
        if (straightOn)
            for (std::size_t k = 0; k < 6; ++k) acc[(9 + k) * stride] += weight[6 + k] * out[k * outStride];
    }
}

}  // namespace aerial
