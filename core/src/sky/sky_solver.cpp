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
#include "sky_solver_impl.hpp"

#include <aerial/limits.hpp>
#include <aerial/sky.hpp>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

namespace aerial {

using namespace detail;

namespace {

constexpr int kDefaultOpticalDepthAngles = 128;
/// A row sums the straight-on share of Mie's forward peak (solveRow) where
/// it reaches this fraction of the row's single scattering (fading in from
/// half of it).
constexpr double kStraightOnFloor = 5e-3;

// Multiple scattering in a drifting atmosphere. A keyed atmosphere (a haze
// that thickens towards dusk) changes a little at every evaluation, and
// rebuilding the LUT each time is most of the solve (~9 ms on two threads
// against ~1 ms for a sun). The sky depends smoothly on the coefficients,
// so while the shells stay where they were (the same radii, viewer height,
// scale heights and ozone profile) and the coefficients drift so little
// from those the LUT was built for that the sky moves by at most
// desc.multipleScatteringTolerance of the pixel, the solve rebuilds the
// optical depths (the single scattering stays exact) and keeps the LUT.
// The drift is measured from the LUT's own atmosphere, so the error does
// not accumulate. The estimate is linear in each coefficient's relative
// change (g: absolute), with the largest change of the sky relative to the
// pixel (floored at 1% of the brightest sky) per unit change, measured over
// suns from -6 to 90 deg in the default air, hazy_sunset's and
// desert_dusk's (largest at -6 to 0 deg, where the sky is mostly multiple
// scattering; tests/core/test_sky_drift.cpp, KeptLutStaysWithinTheTolerance):
// Rayleigh 0.84, 1.05, 0.71; ozone 0.86, 0.95, 0.97; ground albedo 0.51,
// 0.70, 0.68. Mie's grow with its vertical optical depth tau_M (0.005,
// 0.042, 0.14 in those airs): its scattering and extinction together 0.12,
// 0.37, 0.89, as 0.15 + 6 tau_M; the extinction alone 0.14, 0.73, 1.44, as
// 0.3 + 12 tau_M (so that a haze's scattering and extinction moving
// together count once, Mie is its common change plus the extinction's
// change beyond it); g 0.58, 5.5 (g = 0.86), 3.6 (g = 0.7), as 0.6 + 3
// tau_M / (1 - g)^2. The constants keep ~5-10% above the measured.
constexpr double kMsDriftRayleigh = 1.1;
constexpr double kMsDriftOzone = 1.1;
constexpr double kMsDriftAlbedo = 0.75;

/// The largest relative change over the channels from `built` to `now`
/// (signed per channel in `out`); +inf from 0 to anything else.
double relativeDrift(const glm::dvec3& built, const glm::dvec3& now, glm::dvec3* out = nullptr) {
    double worst = 0.0;
    for (int c = 0; c < 3; ++c) {
        const double r = built[c] == now[c] ? 0.0
                         : built[c] > 0.0   ? (now[c] - built[c]) / built[c]
                                            : INFINITY;
        if (out) (*out)[c] = r;
        worst = std::max(worst, std::abs(r));
    }
    return worst;
}

/// The estimated change of the sky (relative to the pixel) if the LUT
/// built for `built` is kept for `now`; +inf where it cannot be kept.
double msDriftEstimate(const AtmosphereParams& built, const AtmosphereParams& now) {
    auto same = [](double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; };
    if (!same(built.planetRadius, now.planetRadius) || !same(built.atmosphereRadius, now.atmosphereRadius) ||
        !same(built.viewerHeight, now.viewerHeight) ||
        !same(built.rayleighScaleHeight, now.rayleighScaleHeight) ||
        !same(built.mieScaleHeight, now.mieScaleHeight) ||
        !same(built.ozoneCenterHeight, now.ozoneCenterHeight) || !same(built.ozoneWidth, now.ozoneWidth))
        return INFINITY;
    glm::dvec3 scatter(0.0), extinction(0.0);
    if (!std::isfinite(relativeDrift(built.mieScattering, now.mieScattering, &scatter) +
                       relativeDrift(built.mieExtinction, now.mieExtinction, &extinction)))
        return INFINITY;  // from 0 to anything else (and inf - inf below would be NaN)
    const double tauM = std::max({built.mieExtinction[0], built.mieExtinction[1], built.mieExtinction[2]}) *
                        built.mieScaleHeight;
    const double g = std::clamp(built.mieAnisotropy, -0.999, 0.999);
    double mie = 0.0;
    for (int c = 0; c < 3; ++c)
        mie = std::max(mie, (0.15 + 6.0 * tauM) * std::abs(scatter[c]) +
                                (0.3 + 12.0 * tauM) * std::abs(extinction[c] - scatter[c]));
    const double estimate =
        kMsDriftRayleigh * relativeDrift(built.rayleighScattering, now.rayleighScattering) +
        kMsDriftOzone * relativeDrift(built.ozoneAbsorption, now.ozoneAbsorption) +
        kMsDriftAlbedo * relativeDrift(built.groundAlbedo, now.groundAlbedo) + mie +
        (0.6 + 3.0 * tauM / ((1.0 - g) * (1.0 - g))) * std::abs(built.mieAnisotropy - now.mieAnisotropy);
    return std::isnan(estimate) ? INFINITY : estimate;
}

// Shared atmosphere tables. The optical-depth table and the multiple
// scattering's LUT depend only on the AtmosphereParams and on the solver's
// layers, angles and multiple-scattering settings, not on the light, and
// they are most of a solve's cost when the atmosphere changes (~50 ms on
// two threads against ~2 ms for the hemisphere). The sun's and the moon's
// solvers always see the same air, and so do the solvers of a bake's steps
// and of the editor's sky preview; so every rebuild leaves an immutable
// snapshot here (the last kSharedTables, keyed by the parameters' bytes and
// those settings), and a solver whose atmosphere changed adopts a matching
// snapshot instead of building it again (of several for the same key, the
// one whose LUT is nearest, within the solver's own tolerance). The snapshot
// holds exactly what a rebuild leaves for the solves after it (the tables as
// lookup pairs, not the floats they were paired from), so a solve that adopts
// it is bit-identical to one that builds
// (SkyMultiple.SharedAtmosphereTablesAreBitIdentical).
struct SharedTables {
    AtmosphereParams key;  // as given to solve(), compared bytewise
    int layers = 0, angles = 0;
    bool multiple = false, isotropic = false;
    std::vector<double> shellHeight, horizonCosD;
    std::vector<float> horizonCos, angleScale, layerCurvature, anisoShell, viewShell;
    std::vector<std::uint64_t> depthPairs, psiPairs;
    AtmosphereParams msAir;  // the atmosphere the LUT was built for (sanitized)
    DensityConstants density;
    MultipleScatteringLut ms;
};

constexpr std::size_t kSharedTables = 4;

/// The atmosphere's tables, from a solver to a snapshot or back (the one
/// list of what a rebuild writes; the same names on both sides).
template <class From, class To>
void copyAtmosphereTables(const From& from, To& to, bool multiple) {
    to.shellHeight = from.shellHeight;
    to.horizonCosD = from.horizonCosD;
    to.horizonCos = from.horizonCos;
    to.angleScale = from.angleScale;
    to.layerCurvature = from.layerCurvature;
    to.depthPairs = from.depthPairs;
    to.density = from.density;
    if (multiple) {
        to.ms = from.ms;
        to.psiPairs = from.psiPairs;
        to.anisoShell = from.anisoShell;
        to.viewShell = from.viewShell;
        to.msAir = from.msAir;
    }
}

class SharedTableCache {
public:
    /// Of the snapshots for these parameters and settings, the one whose
    /// LUT is nearest theirs (see msDriftEstimate), if within `tolerance`.
    std::shared_ptr<const SharedTables> find(const AtmosphereParams& key, const AtmosphereParams& air,
                                             int layers, int angles, bool multiple, bool isotropic,
                                             double tolerance) {
        const std::lock_guard<std::mutex> lock(mutex_);
        std::shared_ptr<const SharedTables> best;
        double nearest = INFINITY;
        for (const std::shared_ptr<const SharedTables>& e : entries_) {
            if (e->layers != layers || e->angles != angles || e->multiple != multiple ||
                e->isotropic != isotropic || std::memcmp(&e->key, &key, sizeof key) != 0)
                continue;
            const double drift = multiple ? msDriftEstimate(e->msAir, air) : 0.0;
            if (drift <= tolerance && (!best || drift < nearest)) best = e, nearest = drift;
        }
        return best;
    }
    void insert(std::shared_ptr<const SharedTables> tables) {
        const std::lock_guard<std::mutex> lock(mutex_);
        if (entries_.size() >= kSharedTables) entries_.erase(entries_.begin());
        entries_.push_back(std::move(tables));
    }

private:
    std::mutex mutex_;
    std::vector<std::shared_ptr<const SharedTables>> entries_;  // oldest first
};

SharedTableCache& sharedTableCache() {
    static SharedTableCache cache;
    return cache;
}

/// v > 0 ? v : 0 (so never NaN, nor below 0) on the bit pattern: the same
/// value for every input, in integer operations that GCC vectorises (a float
/// compare blocks it under -ftrapping-math).
inline float positiveOrZero(float v) {
    const std::int32_t b = std::bit_cast<std::int32_t>(v);
    return std::bit_cast<float>(b > 0 && b <= 0x7f800000 ? b : 0);  // above +inf: NaN
}

/// (1 - e^-tau) / tau, the mean transmittance across a layer of optical
/// depth tau >= 0 given its transmittance e^-tau, by its series where the
/// quotient would cancel.
double layerShape(double tau, double transmittance) {
    return tau < 1e-2 ? 1.0 - tau * (0.5 - tau * (1.0 / 6.0 - tau / 24.0)) : (1.0 - transmittance) / tau;
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
    publishAzimuths.assign(std::size_t(columns), 0.0);
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

// An amortised rebuild's steps (continueSolve): the same items as run()'s,
// in dependency order, each step one dispatch. With 5 of the LUT's 25 rows a
// step, on two threads (the whole rebuild in one solve ~9 ms): the depths
// 0.11 ms, each step of the LUT's orders 0.27-0.64 ms, its resampling 0.5
// ms, and continueSolve's last step, the snapshot for other solvers, 0.8.
constexpr int kMsStageRows = 5;
constexpr int kMsStageChunks = (kMsRows + kMsStageRows - 1) / kMsStageRows;

void SkySolver::Impl::resampleShell(int k) {
    ms.resample(shellHeight.data(), layers + 1, k, k + 1, psiShell.data(), anisoShell.data(),
                ms.anisotropic() ? viewShell.data() : nullptr);
    const std::size_t plane = std::size_t(layers + 1) * kMsCosines, at = std::size_t(k) * kMsCosines;
    for (std::size_t c = 0; c < 3; ++c)
        tablePairs(psiShell.data() + c * plane + at, kMsCosines, psiPairs.data() + c * plane + at);
}

int SkySolver::Impl::rebuildStages() const {
    return 1 + (msPending ? (kMsLastOrder - 1) * kMsStageChunks + 1 : 0);
}

void SkySolver::Impl::runStage(int stage) {
    if (stage == 0) {
        const int depthRows = layers + 1;
        auto item = [&](int index, int worker) {
            if (index < depthRows)
                buildDepthRow(index, scratch[std::size_t(worker)]);
            else
                ms.buildDepthRow(index - depthRows, msScratch[std::size_t(worker)]);
        };
        pool->run(depthRows + (msPending ? kMsRows : 0), item);
        return;
    }
    if (stage + 1 == rebuildStages()) {
        auto item = [&](int k, int) { resampleShell(k); };
        pool->run(layers + 1, item);
        ms.releaseViews();
        return;
    }
    const int order = 2 + (stage - 1) / kMsStageChunks;
    const int first = (stage - 1) % kMsStageChunks * kMsStageRows;
    const int count = std::min(kMsStageRows, kMsRows - first);
    auto item = [&](int index, int worker) {
        ms.buildOrderRow(first + index, order, msScratch[std::size_t(worker)]);
    };
    pool->run(count, item);
}

// Shells of equal mixed mass between the viewer and the top (see the file
// comment) and the per-row constants of the optical-depth table.
void SkySolver::Impl::buildLayers() {
    const double rg = air.planetRadius;
    const double top = std::max(air.atmosphereRadius - rg, 0.0);
    const double h0 = std::clamp(air.viewerHeight, 0.0, top);
    equalMassShells(air, h0, top, layers, shellHeight.data());
    for (int k = 0; k <= layers; ++k) {
        const double ch = horizonCosine(air, shellHeight[std::size_t(k)]);
        horizonCosD[std::size_t(k)] = ch;
        horizonCos[std::size_t(k)] = float(ch);
        angleScale[std::size_t(k)] = float(detail::angleScale(angles, ch));
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
    const std::size_t plane = std::size_t(layers + 1) * angles, n = std::size_t(angles);
    float* out = s.depthOut.data();
    opticalDepthRow(air, density, shellHeight[std::size_t(row)], horizonCosD[std::size_t(row)], angles,
                    s.depthRow, out, out + n, out + 2 * n);
    for (std::size_t c = 0; c < 3; ++c)
        tablePairs(out + c * n, angles, depthPairs.data() + std::size_t(row) * n + c * plane);
}

// The azimuths of a row's columns 0..azimuthCount/2 (skyTableAzimuth): the
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
void SkySolver::Impl::rowColumns(double elevation, Scratch& s) const {
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
    skyTableAzimuths(back, elevation, columns, s.rowPhi.data());
    for (int i = 0; i < columns; ++i) {
        s.rowPhi[std::size_t(i)] = std::min(s.rowPhi[std::size_t(i)], kPi);
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
    rowColumns(elevation, s);
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
    for (int c = 0; c < 3; ++c)
        a.groundAlbedo[c] =
            std::isfinite(in.groundAlbedo[c]) ? std::clamp(in.groundAlbedo[c], 0.0, 1.0) : 0.3;
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
    if (!forceRebuild && adoptSharedTables(params)) {
        cachedAir = params;
        cacheValid = true;
        depthPending = false;
        return;
    }
    buildLayers();
    msPending = multiple && (forceRebuild || !msValid ||
                             !(msDriftEstimate(msAir, air) <= desc.multipleScatteringTolerance));
    if (msPending) {
        msValid = false;
        ms.setAtmosphere(air, desc.isotropicMultipleScattering);
        msAir = air;
    }
    depthPending = true;
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
    setSkyTableMapping(back, air, light);
    skyTableElevations(back, elevationCount, rowElevation.data());
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
    double* az = publishAzimuths.data();
    if (!uniform) skyTableAzimuths(back, 0.0, columns, az);
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

bool SkySolver::Impl::adoptSharedTables(const AtmosphereParams& params) {
    // A snapshot whose LUT was kept from a drifted atmosphere only where
    // this solver would have kept it too (its tolerance may be 0).
    const std::shared_ptr<const SharedTables> t =
        sharedTableCache().find(params, air, layers, angles, multiple, desc.isotropicMultipleScattering,
                                desc.multipleScatteringTolerance);
    if (!t) return false;
    // Same sizes as this solver's (same layers and angles): the copies reuse
    // the vectors' storage.
    copyAtmosphereTables(*t, *this, multiple);
    msValid = multiple;
    return true;
}

void SkySolver::Impl::shareTables() const {
    auto t = std::make_shared<SharedTables>();
    t->key = cachedAir;
    t->layers = layers;
    t->angles = angles;
    t->multiple = multiple;
    t->isotropic = desc.isotropicMultipleScattering;
    copyAtmosphereTables(*this, *t, multiple);
    sharedTableCache().insert(std::move(t));
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
