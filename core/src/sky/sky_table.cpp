// sky_table.cpp — sampling the solved hemisphere table through the
// coordinates it carries (<aerial/sky.hpp>, "Table coordinates") and
// applying the phase functions per direction.
#include <aerial/sky.hpp>

#include <algorithm>
#include <cmath>

namespace aerial {
namespace {

double dot3(const glm::dvec3& a, const glm::dvec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

glm::dvec3 normalizedOr(const glm::dvec3& v, const glm::dvec3& fallback) {
    const double len = std::sqrt(dot3(v, v));
    return len > 0.0 && std::isfinite(len) ? v / len : fallback;
}

}  // namespace

namespace {

/// The Hermite cubic from 0 to 1 over x = 0..1 with slopes m0 and m1 at its
/// ends (each at most 2: monotone, Fritsch and Carlson 1980).
double monotoneCubic(double x, double m0, double m1) {
    const double x2 = x * x, x3 = x2 * x;
    return (x3 - 2.0 * x2 + x) * m0 + (3.0 * x2 - 2.0 * x3) + (x3 - x2) * m1;
}

/// The upper row's weight at the fraction x of the way from row upper - 1
/// to row upper by elevation (rowsAround): the monotone cubic with the
/// rows' slopes m = 2 span / (span + the neighbouring span), below 2 (1 at
/// the first and the last row).
double rowWeight(double x, const double* e, int h, int upper) {
    const double span = e[upper] - e[upper - 1];
    const double m0 = upper >= 2 ? 2.0 * span / (e[upper] - e[upper - 2]) : 1.0;
    const double m1 = upper + 1 < h ? 2.0 * span / (e[upper + 1] - e[upper - 1]) : 1.0;
    return monotoneCubic(x, m0, m1);
}

/// Two neighbouring rows or columns and the second one's weight.
struct Neighbours {
    int first = 0, second = 0;
    double weight = 0.0;
};

/// The rows around elevation `el` [rad] and the upper one's weight: the
/// fractional row as the monotone cubic (Fritsch and Carlson 1980) through
/// the rows' (elevation, index), its slope at a row the harmonic mean of the
/// secants beside it (sky.hpp, "Table coordinates"). Where the rows crowd
/// (towards the horizon and the earth's shadow) the cubic follows how their
/// spacing changes, as the mapping that placed them does; between evenly
/// spaced rows it is linear in el.
Neighbours rowsAround(const SkyTable& table, double el) {
    const int h = table.elevationCount;
    const double* e = table.rowElevation.data();
    if (h <= 1 || !(el > e[0])) return {0, 0, 0.0};
    if (!(el < e[h - 1])) return {h - 1, h - 1, 0.0};
    const int upper = int(std::upper_bound(e, e + h, el) - e);  // 1..h-1: e[upper - 1] <= el < e[upper]
    const double span = e[upper] - e[upper - 1];
    if (!(span > 0.0)) return {upper - 1, upper, 0.0};
    const double t = std::clamp((el - e[upper - 1]) / span, 0.0, 1.0);
    return {upper - 1, upper, std::clamp(rowWeight(t, e, h, upper), 0.0, 1.0)};
}

/// The columns around the azimuth `phi` [rad, 0..2 pi) from the light at
/// the elevation between `rows` (sky.hpp, "Table coordinates"): each
/// column's azimuth blended between the two rows with the rows' weight, the
/// two columns around phi, and the second one's weight as rows have it
/// (rowWeight: the monotone cubic through the columns' azimuths, linear
/// between uniform columns). A column warped around the earth's shadow
/// keeps its place relative to the shadow's edge from row to row, so the
/// same column in both rows follows the edge.
Neighbours columnsAround(const SkyTable& table, const Neighbours& rows, double phi) {
    const int w = table.azimuthCount;
    const double* a0 = table.columnAzimuth.data() + std::size_t(rows.first) * std::size_t(w);
    const double* a1 = table.columnAzimuth.data() + std::size_t(rows.second) * std::size_t(w);
    const double t = rows.weight;
    auto blended = [&](int i) { return a0[i] + t * (a1[i] - a0[i]); };
    // Column i's blended azimuth for i = -1..w + 1, wrapping (column w is
    // column 0 at 2 pi; a table of one column wraps onto it twice).
    auto azimuth = [&](int i) {
        const int k = (i % w + w) % w;
        return blended(k) + 2.0 * kPi * double((i - k) / w);
    };
    int lo = 0, hi = w;  // azimuth(lo) <= phi < azimuth(hi): non-decreasing, azimuth(0) = 0
    while (hi - lo > 1) {
        const int mid = (lo + hi) / 2;
        (azimuth(mid) <= phi ? lo : hi) = mid;
    }
    const double low = azimuth(lo), span = azimuth(hi) - low;
    if (!(span > 0.0)) return {lo, hi % w, 0.0};
    const double x = std::clamp((phi - low) / span, 0.0, 1.0);
    const double m0 = 2.0 * span / (azimuth(hi) - azimuth(lo - 1));
    const double m1 = 2.0 * span / (azimuth(hi + 1) - low);
    return {lo, hi % w, std::clamp(monotoneCubic(x, m0, m1), 0.0, 1.0)};
}

/// The azimuth of v from the light's, wrapped into [0, 2 pi).
double azimuthFromLight(const SkyTable& table, const glm::dvec3& v) {
    const double relative = std::atan2(v.x, -v.z) - table.lightAzimuth;
    const double phi = relative - 2.0 * kPi * std::floor(relative / (2.0 * kPi));
    return phi >= 0.0 && phi < 2.0 * kPi ? phi : 0.0;  // NaN, or 2 pi by rounding
}

bool hasCoordinates(const SkyTable& table) {
    return table.azimuthCount >= 1 && table.elevationCount >= 1 &&
           table.rowElevation.size() == std::size_t(table.elevationCount) &&
           table.columnAzimuth.size() == std::size_t(table.azimuthCount) * std::size_t(table.elevationCount);
}

/// The bilinear sample at the given rows and columns.
SkySample bilinear(const SkyTable& table, const Neighbours& rows, const Neighbours& columns, bool multiple) {
    SkySample out;
    const std::size_t w = std::size_t(table.azimuthCount);
    const std::size_t at[4] = {std::size_t(rows.first) * w + std::size_t(columns.first),
                               std::size_t(rows.first) * w + std::size_t(columns.second),
                               std::size_t(rows.second) * w + std::size_t(columns.first),
                               std::size_t(rows.second) * w + std::size_t(columns.second)};
    const double weight[4] = {(1.0 - rows.weight) * (1.0 - columns.weight),
                              (1.0 - rows.weight) * columns.weight, rows.weight * (1.0 - columns.weight),
                              rows.weight * columns.weight};
    for (int n = 0; n < 4; ++n) {
        if (!(weight[n] > 0.0)) continue;
        for (int k = 0; k < 3; ++k) {
            out.rayleigh[k] += weight[n] * table.rayleigh[at[n] * 3 + std::size_t(k)];
            out.mie[k] += weight[n] * table.mie[at[n] * 3 + std::size_t(k)];
            if (multiple) out.multiple[k] += weight[n] * table.multiple[at[n] * 3 + std::size_t(k)];
        }
    }
    return out;
}

}  // namespace

SkySample sampleSkyTable(const SkyTable& table, const glm::dvec3& viewDirection) {
    const std::size_t texels =
        std::size_t(std::max(table.azimuthCount, 0)) * std::size_t(std::max(table.elevationCount, 0)) * 3;
    if (!hasCoordinates(table) || table.rayleigh.size() < texels || table.mie.size() < texels) return {};
    const glm::dvec3 v = normalizedOr(viewDirection, glm::dvec3(0.0, 1.0, 0.0));
    // Directions below the horizon use row 0.
    const Neighbours rows = rowsAround(table, std::asin(std::clamp(v.y, 0.0, 1.0)));
    const double phi = azimuthFromLight(table, v);
    return bilinear(table, rows, columnsAround(table, rows, phi), table.multiple.size() >= texels);
}

glm::dvec3 skyRadiance(const SkyTable& table, double mieAnisotropy, const glm::dvec3& viewDirection,
                       const glm::dvec3& illuminance) {
    const SkySample s = sampleSkyTable(table, viewDirection);
    const glm::dvec3 v = normalizedOr(viewDirection, glm::dvec3(0.0, 1.0, 0.0));
    const glm::dvec3 l = normalizedOr(table.lightDirection, glm::dvec3(0.0, 1.0, 0.0));
    const double mu = dot3(v, l);
    return illuminance * (rayleighPhase(mu) * s.rayleigh + miePhase(mu, mieAnisotropy) * s.mie + s.multiple);
}

SkyCosineMoments skyCosineMoments(const SkyTable& table, double mieAnisotropy,
                                  const glm::dvec3& illuminance) {
    SkyCosineMoments m;
    if (table.azimuthCount < 1 || table.elevationCount < 1) return m;
    constexpr int kAzimuths = 64;
    constexpr int kElevations = 16;
    for (int j = 0; j < kElevations; ++j) {
        // Midpoint in elevation; d omega = cos(el) d(el) d(az).
        const double el = (j + 0.5) / kElevations * 0.5 * kPi;
        const double mu = std::sin(el);
        const double weight = mu * std::cos(el) * (0.5 * kPi / kElevations) * (2.0 * kPi / kAzimuths);
        glm::dvec3 ring(0.0);
        for (int i = 0; i < kAzimuths; ++i) {
            const double az = (i + 0.5) / kAzimuths * 2.0 * kPi;
            const glm::dvec3 v(std::cos(el) * std::sin(az), mu, -std::cos(el) * std::cos(az));
            ring += skyRadiance(table, mieAnisotropy, v, illuminance);
        }
        m.first += ring * weight;
        m.second += ring * (weight * mu);
    }
    return m;
}

glm::dvec3 skyIrradiance(const SkyTable& table, double mieAnisotropy, const glm::dvec3& illuminance) {
    return skyCosineMoments(table, mieAnisotropy, illuminance).first;
}

glm::dvec3 skyIrradiance(const SkyTable& table, double mieAnisotropy, const glm::dvec3& illuminance, double a,
                         double b) {
    const SkyCosineMoments m = skyCosineMoments(table, mieAnisotropy, illuminance);
    return a * m.first + b * m.second;
}

SkySample horizonSkySample(const SkyTable& table, const glm::dvec3& viewDirection) {
    SkySample mean;
    mean.rayleigh = table.horizonRayleigh;
    mean.mie = table.horizonMie;
    mean.multiple = table.horizonMultiple;
    const glm::dvec3 v = normalizedOr(viewDirection, glm::dvec3(0.0, 1.0, 0.0));
    const double s = std::sqrt(v.x * v.x + v.z * v.z);
    const std::size_t texels = std::size_t(std::max(table.azimuthCount, 0)) * 3;
    if (!(s > 0.0) || table.azimuthCount < 1 || table.elevationCount < 1 || table.rayleigh.size() < texels ||
        table.mie.size() < texels)
        return mean;
    // Row 0 at v's azimuth, linear between its columns as sampleSkyTable.
    if (!hasCoordinates(table)) return mean;
    const Neighbours row0{0, 0, 0.0};
    const SkySample ring = bilinear(table, row0, columnsAround(table, row0, azimuthFromLight(table, v)),
                                    table.multiple.size() >= texels);
    const double w = std::min(s, 1.0);
    SkySample out;
    out.rayleigh = (1.0 - w) * mean.rayleigh + w * ring.rayleigh;
    out.mie = (1.0 - w) * mean.mie + w * ring.mie;
    out.multiple = (1.0 - w) * mean.multiple + w * ring.multiple;
    return out;
}

SkyTable skyHorizonRow(const SkyTable& table) {
    SkyTable row;
    row.azimuthCount = table.azimuthCount;
    row.elevationCount = 1;
    row.lightDirection = table.lightDirection;
    row.lightAzimuth = table.lightAzimuth;
    row.shadowElevation = table.shadowElevation;  // row 0's column mapping
    row.shadowWidth = table.shadowWidth;
    row.capCurvature = table.capCurvature;
    row.capStrength = table.capStrength;
    row.horizonRayleigh = table.horizonRayleigh;
    row.horizonMie = table.horizonMie;
    row.horizonMultiple = table.horizonMultiple;
    row.generation = table.generation;
    const std::size_t n = std::size_t(std::max(table.azimuthCount, 0)) * 3;
    auto first = [&](const std::vector<float>& v) {
        return v.size() >= n ? std::vector<float>(v.begin(), v.begin() + std::ptrdiff_t(n))
                             : std::vector<float>();
    };
    if (hasCoordinates(table)) {
        row.rowElevation.assign(1, table.rowElevation[0]);
        row.columnAzimuth.assign(table.columnAzimuth.begin(),
                                 table.columnAzimuth.begin() + table.azimuthCount);
    }
    row.rayleigh = first(table.rayleigh);
    row.mie = first(table.mie);
    row.multiple = first(table.multiple);
    if (row.rayleigh.empty() || row.mie.empty()) row.elevationCount = 0;
    return row;
}

glm::dvec3 horizonFogRadiance(const SkyTable& table, double mieAnisotropy, const glm::dvec3& viewDirection,
                              const glm::dvec3& illuminance) {
    const glm::dvec3 v = normalizedOr(viewDirection, glm::dvec3(0.0, 1.0, 0.0));
    const glm::dvec3 l = normalizedOr(table.lightDirection, glm::dvec3(0.0, 1.0, 0.0));
    const double mu = dot3(v, l);
    const SkySample h = horizonSkySample(table, v);
    return illuminance * (rayleighPhase(mu) * h.rayleigh + miePhase(mu, mieAnisotropy) * h.mie + h.multiple);
}

}  // namespace aerial
