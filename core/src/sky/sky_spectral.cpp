// sky_spectral.cpp — SpectralSkySolver (<aerial/sky_spectral.hpp>): two
// SkySolver passes at three wavelengths each, combined into linear Rec.709.
#include <aerial/sky_reference.hpp>
#include <aerial/sky_spectral.hpp>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstring>

#include "spectral_data.hpp"

namespace aerial {
namespace {

constexpr glm::dvec3 kDefaultOzone{0.650e-6, 1.881e-6, 0.085e-6};

/// Node index (into spectral::kNodeWavelengths) of pass k's channel c.
int nodeOf(int pass, int channel) {
    const double lambda = kSpectralSkyWavelengths[pass][channel];
    for (int i = 0; i < spectral::kNodeCount; ++i)
        if (spectral::kNodeWavelengths[i] == lambda) return i;
    assert(false && "every solved wavelength has fitted weights");
    return 0;
}

struct Matrices {
    std::array<glm::dmat3, kSpectralSkyPasses> m;
    Matrices() {
        glm::dvec3 rgb[spectral::kNodeCount];
        glm::dvec3 white(0.0);
        for (int i = 0; i < spectral::kNodeCount; ++i) {
            for (int r = 0; r < 3; ++r) {
                double s = 0.0;
                for (int c = 0; c < 3; ++c) s += spectral::kXyzToRec709[r][c] * spectral::kXyzWeights[i][c];
                rgb[i][r] = s;
            }
            white += rgb[i];
        }
        for (int k = 0; k < kSpectralSkyPasses; ++k)
            for (int c = 0; c < 3; ++c) m[std::size_t(k)][c] = rgb[nodeOf(k, c)] / white;
    }
};

const Matrices& matrices() {
    static const Matrices m;
    return m;
}

bool sameMapping(const SkyTable& a, const SkyTable& b) {
    auto same = [](double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; };
    return a.azimuthCount == b.azimuthCount && a.elevationCount == b.elevationCount &&
           same(a.bandElevation, b.bandElevation) && same(a.bandShare, b.bandShare) &&
           same(a.shadowElevation, b.shadowElevation) && same(a.shadowWidth, b.shadowWidth) &&
           same(a.shadowShare, b.shadowShare) && same(a.capCurvature, b.capCurvature) &&
           same(a.capStrength, b.capStrength) && a.rowElevation == b.rowElevation &&
           a.columnAzimuth == b.columnAzimuth && a.lightDirection == b.lightDirection &&
           same(a.lightAzimuth, b.lightAzimuth);
}

}  // namespace

double ozoneCrossSection(double wavelength) {
    if (!(wavelength > spectral::kOzoneFirstNm)) return spectral::kOzoneCrossSection[0];
    const double u = (wavelength - spectral::kOzoneFirstNm) / spectral::kOzoneStepNm;
    if (u >= spectral::kOzoneCount - 1) return spectral::kOzoneCrossSection[spectral::kOzoneCount - 1];
    const int i = int(u);
    const double t = u - i;
    return spectral::kOzoneCrossSection[i] * (1.0 - t) + spectral::kOzoneCrossSection[i + 1] * t;
}

double spectralSkyCoefficient(const glm::dvec3& rgb, double wavelength, int kind) {
    // Nominal wavelengths ascending: blue (440, channel 2), green (550, 1), red (680, 0).
    const double lam[3] = {kSpectralSkyNominal[2], kSpectralSkyNominal[1], kSpectralSkyNominal[0]};
    const double val[3] = {rgb[2], rgb[1], rgb[0]};
    if (kind == 1) {  // linear, the end values beyond
        if (!(wavelength > lam[0])) return std::clamp(val[0], 0.0, 1.0);
        if (wavelength >= lam[2]) return std::clamp(val[2], 0.0, 1.0);
        const int s = wavelength < lam[1] ? 0 : 1;
        const double t = (wavelength - lam[s]) / (lam[s + 1] - lam[s]);
        return std::clamp(val[s] + t * (val[s + 1] - val[s]), 0.0, 1.0);
    }
    // Power law through the neighbouring pair (the nearest pair beyond).
    const int s = wavelength < lam[1] ? 0 : 1;
    const double a = std::max(val[s], 0.0), b = std::max(val[s + 1], 0.0);
    if (a > 0.0 && b > 0.0) {
        const double t = std::log(wavelength / lam[s]) / std::log(lam[s + 1] / lam[s]);
        return a * std::exp(t * std::log(b / a));
    }
    const double t = (wavelength - lam[s]) / (lam[s + 1] - lam[s]);
    return std::max(a + t * (b - a), 0.0);
}

AtmosphereParams spectralSkyAtmosphere(const AtmosphereParams& air, int pass) {
    pass = std::clamp(pass, 0, kSpectralSkyPasses - 1);
    AtmosphereParams out = air;
    const double ozoneScale =
        std::max(glm::dot(air.ozoneAbsorption, kDefaultOzone) / glm::dot(kDefaultOzone, kDefaultOzone), 0.0);
    for (int c = 0; c < 3; ++c) {
        const double lambda = kSpectralSkyWavelengths[pass][c];
        out.rayleighScattering[c] = spectralSkyCoefficient(air.rayleighScattering, lambda, 0);
        out.mieScattering[c] = spectralSkyCoefficient(air.mieScattering, lambda, 0);
        out.mieExtinction[c] =
            std::max(spectralSkyCoefficient(air.mieExtinction, lambda, 0), out.mieScattering[c]);
        out.ozoneAbsorption[c] = ozoneScale * spectral::kOzonePeakDensity * ozoneCrossSection(lambda);
        out.groundAlbedo[c] = spectralSkyCoefficient(air.groundAlbedo, lambda, 1);
    }
    return out;
}

glm::dmat3 spectralSkyMatrix(int pass) {
    return matrices().m[std::size_t(std::clamp(pass, 0, kSpectralSkyPasses - 1))];
}

glm::dvec3 spectralSkyCombine(const std::array<glm::dvec3, kSpectralSkyPasses>& v) {
    glm::dvec3 out(0.0);
    for (int k = 0; k < kSpectralSkyPasses; ++k) out += matrices().m[std::size_t(k)] * v[std::size_t(k)];
    return out;
}

SkySample spectralReferenceSkyIntegrals(const AtmosphereParams& air, const glm::dvec3& viewDirection,
                                        const glm::dvec3& lightDirection) {
    std::array<glm::dvec3, kSpectralSkyPasses> r, m;
    for (int k = 0; k < kSpectralSkyPasses; ++k) {
        const SkySample s =
            referenceSkyIntegrals(spectralSkyAtmosphere(air, k), viewDirection, lightDirection);
        r[std::size_t(k)] = s.rayleigh;
        m[std::size_t(k)] = s.mie;
    }
    SkySample out;
    out.rayleigh = spectralSkyCombine(r);
    out.mie = spectralSkyCombine(m);
    return out;
}

struct SpectralSkySolver::Impl {
    std::array<std::unique_ptr<SkySolver>, kSpectralSkyPasses> passes;
    SkyTable table;  ///< published
    SkyTable back;   ///< the next one, combined here
    int nextPass = 0;
    bool amortised = false;

    explicit Impl(const SkySolverDesc& desc) {
        for (auto& p : passes) p = std::make_unique<SkySolver>(desc);
        table = passes[0]->table();  // zeros, generation 0
    }

    /// Combines the passes' tables texel by texel into `table` and publishes it.
    void combine() {
        const SkyTable& first = passes[0]->table();
        SkyTable& out = back;
        out.azimuthCount = first.azimuthCount;
        out.elevationCount = first.elevationCount;
        out.lightDirection = first.lightDirection;
        out.lightAzimuth = first.lightAzimuth;
        out.bandElevation = first.bandElevation;
        out.bandShare = first.bandShare;
        out.shadowElevation = first.shadowElevation;
        out.shadowWidth = first.shadowWidth;
        out.shadowShare = first.shadowShare;
        out.capCurvature = first.capCurvature;
        out.capStrength = first.capStrength;
        out.rowElevation = first.rowElevation;
        out.columnAzimuth = first.columnAzimuth;
        for (int k = 1; k < kSpectralSkyPasses; ++k) {
            [[maybe_unused]] const bool same = sameMapping(first, passes[std::size_t(k)]->table());
            assert(same && "the passes' tables share one mapping (geometry only)");
        }
        // m[k][r][c]: pass k's sample c into output channel r.
        double m[kSpectralSkyPasses][3][3];
        for (int k = 0; k < kSpectralSkyPasses; ++k)
            for (int r = 0; r < 3; ++r)
                for (int c = 0; c < 3; ++c) m[k][r][c] = matrices().m[std::size_t(k)][c][r];
        auto mix = [&](std::vector<float> SkyTable::*field) {
            const float* src[kSpectralSkyPasses];
            std::size_t n = (first.*field).size();
            for (int k = 0; k < kSpectralSkyPasses; ++k) {
                const std::vector<float>& v = passes[std::size_t(k)]->table().*field;
                n = std::min(n, v.size());
                src[k] = v.data();
            }
            std::vector<float>& dst = out.*field;
            dst.resize(n);
            float* d = dst.data();
            for (std::size_t t = 0; t + 2 < n; t += 3)
                for (int r = 0; r < 3; ++r) {
                    double sum = 0.0;
                    for (int k = 0; k < kSpectralSkyPasses; ++k)
                        sum +=
                            m[k][r][0] * src[k][t] + m[k][r][1] * src[k][t + 1] + m[k][r][2] * src[k][t + 2];
                    d[t + std::size_t(r)] = float(sum);
                }
        };
        mix(&SkyTable::rayleigh);
        mix(&SkyTable::mie);
        mix(&SkyTable::multiple);
        auto mixAverage = [&](glm::dvec3 SkyTable::*field) {
            std::array<glm::dvec3, kSpectralSkyPasses> v;
            for (int k = 0; k < kSpectralSkyPasses; ++k)
                v[std::size_t(k)] = passes[std::size_t(k)]->table().*field;
            out.*field = spectralSkyCombine(v);
        };
        mixAverage(&SkyTable::horizonRayleigh);
        mixAverage(&SkyTable::horizonMie);
        mixAverage(&SkyTable::horizonMultiple);
        out.generation = table.generation + 1;
        std::swap(table, back);  // the buffers are reused; table() stays the same object
    }
};

SpectralSkySolver::SpectralSkySolver(const SkySolverDesc& desc) : impl_(std::make_unique<Impl>(desc)) {}
SpectralSkySolver::~SpectralSkySolver() = default;

void SpectralSkySolver::solve(const AtmosphereParams& air, const glm::dvec3& lightDirection) {
    Impl& m = *impl_;
    m.amortised = false;
    for (int k = 0; k < kSpectralSkyPasses; ++k)
        m.passes[std::size_t(k)]->solve(spectralSkyAtmosphere(air, k), lightDirection);
    m.combine();
}

void SpectralSkySolver::beginSolve(const AtmosphereParams& air, const glm::dvec3& lightDirection) {
    Impl& m = *impl_;
    for (int k = 0; k < kSpectralSkyPasses; ++k)
        m.passes[std::size_t(k)]->beginSolve(spectralSkyAtmosphere(air, k), lightDirection);
    m.amortised = true;
    m.nextPass = 0;
}

bool SpectralSkySolver::continueSolve(int rows) {
    Impl& m = *impl_;
    if (!m.amortised) return true;
    if (!m.passes[std::size_t(m.nextPass)]->continueSolve(rows)) return false;
    if (++m.nextPass < kSpectralSkyPasses) return false;
    m.amortised = false;
    m.combine();
    return true;
}

bool SpectralSkySolver::solving() const { return impl_->amortised; }

void SpectralSkySolver::invalidateCache() {
    for (auto& p : impl_->passes) p->invalidateCache();
}

const SkyTable& SpectralSkySolver::table() const { return impl_->table; }

const SkySolverDesc& SpectralSkySolver::desc() const { return impl_->passes[0]->desc(); }

}  // namespace aerial
