// sky_solver_atmosphere.cpp — the sky solver's work when the atmosphere
// changes (sky_solver.cpp describes the whole solve): the parameters as it
// uses them, its layers and optical-depth table (1. and 2.), the amortised
// rebuild's steps, the tables shared between solvers, and the
// multiple-scattering LUT kept while a keyed atmosphere drifts little.
#include "sky_solver_impl.hpp"

#include <aerial/sky.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <mutex>

namespace aerial {

using namespace detail;

namespace {

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

}  // namespace

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

}  // namespace aerial
