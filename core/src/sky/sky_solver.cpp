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
//     set sun (sky_layers.hpp).
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
//     curvatureFactor), for the layers the planet's shadow cylinder (solved
//     exactly per texel) does not touch. A layer that an edge of the shadow
//     cuts (sun below the horizon) adds its lit part only (shadowEdgeLayers):
//     the optical depth at the edge is that of the ray grazing the ground,
//     at the piece's middle interpolated between the two shells' rows at
//     the point's own margin above its horizon, at the lit shell the
//     table's; the view's weight falls exponentially along the layer; the
//     product integrated in closed form.
//  Rows are at the elevations of the table's row mapping for this light
//  (setSkyTableMapping, <aerial/sky.hpp>): for a low or set sun they crowd
//  towards the horizon and the edge of the earth's shadow opposite the sun.
//
// Threads: a persistent pool made in the constructor (worker_pool.hpp); one
// dispatch per solve (table rows first, then sky rows, pulled from an atomic
// counter). Every row is computed by the same code from the same inputs
// whichever thread runs it, so single-threaded, multi-threaded and amortised
// solves are bit-identical. No allocation happens after construction but
// the snapshot of a rebuilt atmosphere's tables (below). The
// hot loops work on contiguous float arrays (sky_kernels.hpp) and are
// compiled for x86-64-v4, x86-64-v3 and the baseline (target_clones, chosen
// at load time): no global -march needed.
//
// Files: this one the solver's set-up, its dispatch, the light, the rows
// that take their multiple scattering from their neighbours, publishing and
// the public calls; sky_solver_atmosphere.cpp a change of atmosphere (its
// layers and optical-depth table, the amortised rebuild's steps, the
// tables shared between solvers and the multiple-scattering LUT kept for
// a drifting atmosphere); sky_solver_row.cpp one elevation row (3. and
// 4. above); sky_solver_shadow.cpp the layers that an edge of the earth's
// shadow cuts. The state they share: sky_solver_impl.hpp.
#include "sky_solver_impl.hpp"

#include <aerial/limits.hpp>
#include <aerial/sky.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>
#include <thread>

namespace aerial {

using namespace detail;

namespace {

constexpr int kDefaultOpticalDepthAngles = 128;

}  // namespace

// ---------------------------------------------------------------------------

// SkySolver::Impl: sky_solver_impl.hpp.

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
    desc.multipleScatteringTolerance =
        desc.multipleScatteringTolerance > 0.0 ? std::min(desc.multipleScatteringTolerance, 0.05) : 0.0;

    azimuthCount = desc.azimuthCount;
    elevationCount = desc.elevationCount;
    layers = desc.layerCount;
    angles = desc.opticalDepthAngles;
    columns = azimuthCount / 2 + 1;
    // At least the multiple scattering's azimuths, which the kernels keep in
    // the same per-column records (a warped row's stride is at least that
    // many: rowColumns): narrower tables (azimuthCount < 30) overran the
    // scratch records for a light 0-1 deg down.
    paddedColumns = (std::max(columns, kMsSkyColumns) + 7) / 8 * 8;

    shellHeight.assign(std::size_t(layers) + 1, 0.0);
    horizonCos.assign(std::size_t(layers) + 1, 0.0f);
    horizonCosD.assign(std::size_t(layers) + 1, 0.0);
    layerCurvature.assign(std::size_t(layers), 0.0f);
    angleScale.assign(std::size_t(layers) + 1, 0.0f);
    depthPairs.assign(std::size_t(3) * (layers + 1) * angles, 0);
    cosPhi.assign(std::size_t(columns), 1.0);
    cosHalfPhi.assign(std::size_t(columns), 1.0);
    sinHalfPhi.assign(std::size_t(columns), 0.0);
    rowElevation.assign(std::size_t(elevationCount), 0.0);
    rowOrder.assign(std::size_t(elevationCount), 0);
    for (int j = 0; j < elevationCount; ++j) rowOrder[std::size_t(j)] = j;
    msRowSolved.assign(std::size_t(elevationCount), 1);
    msRowNode.assign(std::size_t(4) * elevationCount, 0);
    msRowWeight.assign(std::size_t(4) * elevationCount, 0.0f);
    msRowValue.assign(std::size_t(3) * kMsSkyColumns * elevationCount, 0.0f);
    msRowDone = std::make_unique<std::atomic<int>[]>(std::size_t(elevationCount));
    cosPhiF.assign(std::size_t(paddedColumns), 1.0f);  // padding: a harmless direction
    msCosPhiF.assign(std::size_t(kMsSkyColumns), 1.0f);
    for (int k = 0; k < kMsSkyColumns; ++k)
        msCosPhiF[std::size_t(k)] = float(std::cos(kPi * k / (kMsSkyColumns - 1)));
    // spreadMultiple's stencil: column i at azimuth 2 pi i / azimuthCount is
    // u = 2 i (K - 1) / azimuthCount in units of the K azimuths; Catmull-Rom
    // through the azimuths k - 1 .. k + 2 around it, mirrored at 0 and K - 1
    // (padding: weight 0).
    spreadIndex.assign(std::size_t(4) * paddedColumns, 0);
    spreadWeight.assign(std::size_t(4) * paddedColumns, 0.0f);
    phi.assign(std::size_t(columns), 0.0);
    for (int i = 0; i < columns; ++i) {
        phi[std::size_t(i)] = 2.0 * kPi * i / azimuthCount;
        cosPhi[std::size_t(i)] = std::cos(phi[std::size_t(i)]);
        cosHalfPhi[std::size_t(i)] = std::cos(0.5 * phi[std::size_t(i)]);
        sinHalfPhi[std::size_t(i)] = std::sin(0.5 * phi[std::size_t(i)]);
        cosPhiF[std::size_t(i)] = float(cosPhi[std::size_t(i)]);
    }
    spreadStencilKernel(columns, phi.data(), paddedColumns, spreadIndex.data(), spreadWeight.data());
    for (SkyTable& t : tables) {
        t.azimuthCount = azimuthCount;
        t.elevationCount = elevationCount;
        t.rayleigh.assign(std::size_t(azimuthCount) * elevationCount * 3, 0.0f);
        t.mie.assign(std::size_t(azimuthCount) * elevationCount * 3, 0.0f);
        t.multiple.assign(std::size_t(azimuthCount) * elevationCount * 3, 0.0f);
    }
    multiple = !desc.singleScatteringOnly;
    psiShell.assign(std::size_t(3) * (layers + 1) * kMsCosines, 0.0f);
    psiPairs.assign(psiShell.size(), 0);
    anisoShell.assign(std::size_t(kMsAniso) * 3 * (layers + 1) * kMsCosines, 0.0f);
    viewShell.assign(std::size_t(kMsViews) * 3 * (layers + 1) * kMsCosines, 0.0f);
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
        s.acc.assign(std::size_t(15) * paddedColumns, 0.0f);
        s.anisoPoly.assign(std::size_t(9) * kMsCosines, 0.0f);
        s.msWeights.assign(std::size_t(layers + 1) * kMsShellWeights, 0.0f);
        s.layerLit.assign(std::size_t(layers), 1);
        s.layerShadow.assign(std::size_t(layers), 0);
        s.shellShadow.assign(std::size_t(layers) + 1, 0);
        s.shellRoots.assign(std::size_t(layers) + 1, 0);
        s.msWeightScratch.assign(std::size_t(layers + 1) * 6, 0.0f);
        const std::size_t pieces = std::size_t(2) * paddedColumns;
        s.edgeCrossing.assign(std::size_t(layers) + 1, 0.0f);
        s.edgeTauStart.assign(3 * pieces, 0.0f);
        s.edgeTauMid.assign(3 * pieces, 0.0f);
        s.edgeTauEnd.assign(3 * pieces, 0.0f);
        s.edgeT0.assign(pieces, 0.0f);
        s.edgeDt.assign(pieces, 0.0f);
        s.edgeKappa.assign(6 * pieces, 0.0f);
        s.edgeOut.assign(6 * pieces, 0.0f);
        s.edgeLayerKappa.assign(std::size_t(6) * layers, 0.0f);
        s.edgeLayerWeight.assign(std::size_t(12) * layers, 0.0f);
        s.edgeLayerTangent.assign(std::size_t(2) * layers, 0.0);
        s.edgeLayerExtent.assign(std::size_t(2) * layers, 0.0);
        s.edgeLayerReady.assign(std::size_t(layers), 0);
        s.edgeColumn.assign(pieces, 0);
        s.edgeLayer.assign(pieces, 0);
        s.pieceAtStart.assign(pieces, 0);
        for (auto* v : {&s.pieceFrom, &s.pieceTo, &s.pieceMu, &s.pieceLitQ}) v->assign(pieces, 0.0);
        s.depthRow.resize(angles);
        s.depthOut.assign(std::size_t(3) * angles, 0.0f);
        s.rowPhi.assign(std::size_t(columns), 0.0);
        s.rowCosPhi.assign(std::size_t(columns), 1.0);
        s.rowCosHalfPhi.assign(std::size_t(columns), 1.0);
        s.rowSinHalfPhi.assign(std::size_t(columns), 0.0);
        s.rowCosPhiF.assign(std::size_t(paddedColumns), 1.0f);
        s.rowSpreadIndex.assign(std::size_t(4) * paddedColumns, 0);
        s.rowSpreadWeight.assign(std::size_t(4) * paddedColumns, 0.0f);
    }
    msScratch.resize(std::size_t(desc.threadCount));
    pool.emplace(desc.threadCount);
}

// One dispatch. With `rebuild`, the first items build the optical-depth rows
// (the solver's, then the multiple-scattering LUT's), then the LUT's rows of
// each scattering order, then Psi_ms at each shell (the thread that
// resamples the last frees what only the build needed); the rest solve sky
// rows, which wait (briefly, yielding) until all of that is done.
void SkySolver::Impl::run(bool rebuild, int rowBegin, int rowEnd) {
    const int depthRows = rebuild ? layers + 1 : 0;
    const int msRows = rebuild && msPending ? kMsRows : 0;
    const int orderItems = msRows * (kMsLastOrder - 1);  // orders 2..kMsLastOrder
    const int resampleItems = msRows > 0 ? layers + 1 : 0;
    depthRowsDone.store(0);  // published to the workers by the pool's dispatch
    msDepthRowsDone.store(0);
    psiRowsDone.store(0);
    resampleDone.store(0);
    psiReady.store(msRows == 0);
    auto item = [&](int index, int worker) {
        if (index < depthRows) {
            buildDepthRow(index, scratch[std::size_t(worker)]);
            depthRowsDone.fetch_add(1, std::memory_order_release);
            return;
        }
        index -= depthRows;
        if (index < msRows) {
            ms.buildDepthRow(index, msScratch[std::size_t(worker)]);
            msDepthRowsDone.fetch_add(1, std::memory_order_release);
            return;
        }
        index -= msRows;
        if (index < orderItems) {
            // Order n's rows wait for the LUT's optical depths (n = 2) or for every row of order n - 1.
            const int order = 2 + index / msRows;
            const std::atomic<int>& ready = order == 2 ? msDepthRowsDone : psiRowsDone;
            while (ready.load(std::memory_order_acquire) < std::max(order - 2, 1) * msRows)
                std::this_thread::yield();
            ms.buildOrderRow(index % msRows, order, msScratch[std::size_t(worker)]);
            psiRowsDone.fetch_add(1, std::memory_order_acq_rel);
            return;
        }
        index -= orderItems;
        if (index < resampleItems) {
            // Psi_ms at the shells, a shell per item, once the last order is done.
            while (psiRowsDone.load(std::memory_order_acquire) < orderItems) std::this_thread::yield();
            resampleShell(index);
            if (resampleDone.fetch_add(1, std::memory_order_acq_rel) + 1 == resampleItems) {
                ms.releaseViews();
                psiReady.store(true, std::memory_order_release);
            }
            return;
        }
        index -= resampleItems;
        while (depthRowsDone.load(std::memory_order_acquire) < depthRows ||
               !psiReady.load(std::memory_order_acquire))
            std::this_thread::yield();
        solveRow(rowOrder[std::size_t(rowBegin + index)], scratch[std::size_t(worker)]);
    };
    pool->run(depthRows + msRows + orderItems + resampleItems + (rowEnd - rowBegin), item);
}

void SkySolver::Impl::setLight(const glm::dvec3& direction) {
    const double len =
        std::sqrt(direction.x * direction.x + direction.y * direction.y + direction.z * direction.z);
    light = len > 0.0 && std::isfinite(len) ? direction / len : glm::dvec3(0.0, 1.0, 0.0);
    lightAzimuth = std::atan2(light.x, -light.z);
    sinLight = std::clamp(light.y, -1.0, 1.0);
    cosLight = std::sqrt(light.x * light.x + light.z * light.z);
    SkyTable& back = tables[1 - front];
    back.lightDirection = light;
    back.lightAzimuth = lightAzimuth;
    setSkyTableMapping(back, air, light);  // the texels' coordinates
    std::copy(back.rowElevation.begin(), back.rowElevation.end(), rowElevation.begin());
    planMultipleRows();
}

// Multiple scattering between rows. Like the azimuth (spreadMultiple), the
// elevation of a view changes the multiple scattering slowly, so where the
// rows are dense only every second one integrates it: an odd row whose
// neighbours lie less than kMsRowGap apart takes it, at each of the
// kMsSkyColumns azimuths, from four integrated rows around it (a cubic in
// elevation, Lagrange), and spreads it into its columns as those do. The
// view term of Mie's last scattering is linear between its zenith nodes
// (sky_multiple.hpp), which puts a kink into the multiple scattering at the
// nodes' elevations (0.4, 3.6, 10, 19.9, 34.2 and 57.1 deg): a row with a
// node between its neighbours integrates its own (across it the cubic was
// 0.68% off in hazy_sunset's air at sun -0.2 deg). Taking the rows from one
// side of a node instead of the two nearest on each side was worse, 1.4%.
// Nor does a row whose nodes crowd on one side: for a light less than
// ~0.001 deg down the rows of the cap lie within 1e-4 deg of the horizon and
// the band's begin at 0.08 deg, and the cubic through two nodes 5e-5 deg
// apart and two 0.2 deg beyond put 2.2% into the anti-light horizon of
// hazy_sunset's air (sun -0.00002 deg; 3.4% at -0.00001, 0.6% in the
// default air): each neighbour must lie at least kMsRowSpread of the gap
// between them from its own other neighbour (for a light 0.00002-0.002 deg
// down 3 rows integrate their own for it, 1-2 from there to 0.02 deg, none
// otherwise).
// Against integrating every row (SkySolverDesc::multipleScatteringEveryRow)
// this changes the pixel by at most 0.26% (relative to the total radiance,
// floored at 1% of the brightest; random directions, suns from -6 to 90
// deg, down to 0.00001 deg below the horizon, the default air and
// hazy_sunset's: SkyMultiple.RowsBetweenMatchEveryRowIntegrated), and 20 to
// 25 of the 64 rows take theirs from the others (at sun +10 deg 17.1 -> 15.3 M
// instructions per solve on one thread). The
// integrated rows are solved first (rowOrder), the others wait for the rows
// they take it from (msRowDone), so a full and an amortised solve, on any
// number of threads, give the same table.
constexpr double kMsRowGap = 6.0 * kPi / 180.0;
constexpr double kMsRowSpread = 0.1;

void SkySolver::Impl::planMultipleRows() {
    const int h = elevationCount;
    const double* el = rowElevation.data();
    // The view nodes' elevations above the horizon (zenith cosines > 0).
    static const std::vector<double> kinks = [] {
        std::vector<double> k;
        for (int z = 0; z < kMsZeniths; ++z)
            if (msZenithNode(z).angle > 0.0) k.push_back(std::asin(msZenithNode(z).angle));
        return k;
    }();
    auto kinkWithin = [&](double lo, double hi) {
        return std::any_of(kinks.begin(), kinks.end(), [&](double e) { return lo < e && e < hi; });
    };
    std::vector<int>& order = rowOrder;
    int solved = 0;
    for (int j = 0; j < h; ++j) {
        bool between = multiple && !desc.multipleScatteringEveryRow && j % 2 == 1 && j + 2 < h &&
                       el[j + 1] - el[j - 1] < kMsRowGap && !kinkWithin(el[j - 1], el[j + 1]);
        if (between) {
            // Nodes well apart: rows j - 1 and j + 1 each at least
            // kMsRowSpread of their gap from their other neighbour.
            const double inner = el[j + 1] - el[j - 1];
            const double below = j >= 2 ? el[j - 1] - el[j - 2] : inner, above = el[j + 2] - el[j + 1];
            between = std::min(below, above) >= kMsRowSpread * inner;
        }
        msRowSolved[std::size_t(j)] = between ? 0 : 1;
        if (!between) order[std::size_t(solved++)] = j;
        msRowDone[std::size_t(j)].store(0, std::memory_order_relaxed);
    }
    int next = solved;
    for (int j = 0, p = 0; j < h; ++j) {
        if (msRowSolved[std::size_t(j)]) {
            ++p;  // integrated rows at and below j; order[p - 1] = j - 1, order[p] = j + 1 below
            continue;
        }
        order[std::size_t(next++)] = j;
        // The four integrated rows nearest j, two on each side where there are.
        const int nodes = std::min(solved, 4);
        const int first = std::clamp(p - 2, 0, solved - nodes);
        for (int q = 0; q < 4; ++q) {
            const std::size_t at = std::size_t(4 * j + q);
            msRowNode[at] = order[std::size_t(first + std::min(q, nodes - 1))];
            msRowWeight[at] = 0.0f;
            if (q >= nodes) continue;
            double w = 1.0;
            for (int r = 0; r < nodes; ++r) {
                if (r == q) continue;
                const double er = el[order[std::size_t(first + r)]];
                w *= (el[j] - er) / (el[msRowNode[at]] - er);
            }
            msRowWeight[at] = float(w);
        }
    }
}

// Horizon averages (the azimuthal mean of row 0: its columns with equal
// weights, or where the column mapping warps row 0 the mean of its
// interpolant over the azimuth, from its columns' azimuths) and the swap.
void SkySolver::Impl::publish() {
    SkyTable& back = tables[1 - front];
    glm::dvec3 sumR(0.0), sumM(0.0), sumX(0.0);
    const bool uniform = !skyTableColumnsWarped(back);
    // Row 0's column azimuths 0..azimuthCount/2 (the rest mirror them).
    const double* az = back.columnAzimuth.data();
    // Table column m's azimuth, m in -2..azimuthCount + 1 (mirrored, wrapped).
    auto azimuthOf = [&](int m) {
        const double wrap = m < 0 ? -2.0 * kPi : (m > azimuthCount ? 2.0 * kPi : 0.0);
        m = m < 0 ? m + azimuthCount : (m > azimuthCount ? m - azimuthCount : m);
        return wrap + (2 * m <= azimuthCount ? az[m] : 2.0 * kPi - az[azimuthCount - m]);
    };
    // The integral of the azimuth over columns m..m+1 (the cubic through
    // m-1..m+2): the mean of the interpolant, linear in the column, over
    // the azimuth gives column m the weight span(m) - span(m - 1).
    auto span = [&](int m) {
        return (13.0 * (azimuthOf(m) + azimuthOf(m + 1)) - azimuthOf(m - 1) - azimuthOf(m + 2)) / 24.0;
    };
    for (int n = 0; n < azimuthCount; ++n) {
        double weight = 1.0 / azimuthCount;
        if (!uniform) weight = (span(n) - span(n - 1)) / (2.0 * kPi);
        for (int c = 0; c < 3; ++c) {
            sumR[c] += weight * back.rayleigh[std::size_t(n) * 3 + c];
            sumM[c] += weight * back.mie[std::size_t(n) * 3 + c];
            sumX[c] += weight * back.multiple[std::size_t(n) * 3 + c];
        }
    }
    back.horizonRayleigh = sumR;
    back.horizonMie = sumM;
    back.horizonMultiple = sumX;
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
    m.run(m.depthPending, 0, m.elevationCount);
    if (m.depthPending) {
        m.cachedAir = m.rawAir;
        m.cacheValid = true;
        m.depthPending = false;
        m.msValid = m.multiple;
        m.msPending = false;
        m.forceRebuild = false;
        m.shareTables();
    }
    m.publish();
}

void SkySolver::beginSolve(const AtmosphereParams& air, const glm::dvec3& lightDirection) {
    Impl& m = *impl_;
    m.setAtmosphere(air);
    m.setLight(lightDirection);
    m.amortised = true;
    m.nextRow = 0;
    m.nextStage = 0;
}

bool SkySolver::continueSolve(int rows) {
    Impl& m = *impl_;
    if (!m.amortised) return true;
    rows = std::max(rows, 1);
    // The rebuild, a step per row of the budget; offering the snapshot to
    // other solvers (a copy of ~2 MB) is its last.
    for (; m.depthPending && rows > 0; --rows) {
        if (m.nextStage < m.rebuildStages()) {
            m.runStage(m.nextStage++);
            continue;
        }
        m.cachedAir = m.rawAir;
        m.cacheValid = true;
        m.depthPending = false;
        m.msValid = m.multiple;
        m.msPending = false;
        m.forceRebuild = false;
        m.shareTables();
    }
    if (m.depthPending) return false;
    const int end = std::min(m.nextRow + rows, m.elevationCount);
    m.run(false, m.nextRow, end);
    m.nextRow = end;
    if (m.nextRow < m.elevationCount) return false;
    m.amortised = false;
    m.publish();
    return true;
}

bool SkySolver::solving() const { return impl_->amortised; }

const SkyTable& SkySolver::table() const { return impl_->tables[impl_->front]; }

const SkySolverDesc& SkySolver::desc() const { return impl_->desc; }

void SkySolver::invalidateCache() {
    impl_->cacheValid = false;
    impl_->forceRebuild = true;
}

}  // namespace aerial
