// sky_table.cpp — sampling the solved hemisphere table (mapping in
// <aerial/sky.hpp>) and applying the phase functions per direction.
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

SkySample sampleSkyTable(const SkyTable& table, const glm::dvec3& viewDirection) {
    SkySample out;
    const int w = table.azimuthCount;
    const int h = table.elevationCount;
    const std::size_t texels = std::size_t(std::max(w, 0)) * std::size_t(std::max(h, 0)) * 3;
    if (w < 1 || h < 1 || table.rayleigh.size() < texels || table.mie.size() < texels) return out;
    const glm::dvec3 v = normalizedOr(viewDirection, glm::dvec3(0.0, 1.0, 0.0));

    // Row: el = pi/2 (j / (H - 1))^2  =>  j = (H - 1) sqrt(el / (pi/2)).
    // Directions below the horizon use row 0.
    const double elevation = std::asin(std::clamp(v.y, 0.0, 1.0));
    double row = h > 1 ? (h - 1) * std::sqrt(std::clamp(elevation / (0.5 * kPi), 0.0, 1.0)) : 0.0;
    row = std::clamp(row, 0.0, double(h - 1));
    const int j0 = std::min(int(row), h - 1);
    const int j1 = std::min(j0 + 1, h - 1);
    const double fj = row - j0;

    // Column: azimuth relative to the light, wrapping.
    double relative = std::atan2(v.x, -v.z) - table.lightAzimuth;
    relative -= 2.0 * kPi * std::floor(relative / (2.0 * kPi));
    double col = relative / (2.0 * kPi) * w;
    if (!(col >= 0.0) || !(col < w)) col = 0.0;  // NaN or exactly 2 pi
    const int i0 = std::min(int(col), w - 1);
    const int i1 = (i0 + 1) % w;
    const double fi = col - i0;

    const double weight[4] = {(1 - fi) * (1 - fj), fi * (1 - fj), (1 - fi) * fj, fi * fj};
    const std::size_t at[4] = {(std::size_t(j0) * w + i0) * 3, (std::size_t(j0) * w + i1) * 3,
                               (std::size_t(j1) * w + i0) * 3, (std::size_t(j1) * w + i1) * 3};
    const bool multiple = table.multiple.size() >= texels;
    for (int k = 0; k < 4; ++k) {
        for (int c = 0; c < 3; ++c) {
            out.rayleigh[c] += weight[k] * table.rayleigh[at[k] + c];
            out.mie[c] += weight[k] * table.mie[at[k] + c];
            if (multiple) out.multiple[c] += weight[k] * table.multiple[at[k] + c];
        }
    }
    return out;
}

glm::dvec3 skyRadiance(const SkyTable& table, double mieAnisotropy, const glm::dvec3& viewDirection,
                       const glm::dvec3& illuminance) {
    const SkySample s = sampleSkyTable(table, viewDirection);
    const glm::dvec3 v = normalizedOr(viewDirection, glm::dvec3(0.0, 1.0, 0.0));
    const glm::dvec3 l = normalizedOr(table.lightDirection, glm::dvec3(0.0, 1.0, 0.0));
    const double mu = dot3(v, l);
    return illuminance * (rayleighPhase(mu) * s.rayleigh + miePhase(mu, mieAnisotropy) * s.mie + s.multiple);
}

glm::dvec3 horizonFogRadiance(const SkyTable& table, double mieAnisotropy, const glm::dvec3& viewDirection,
                              const glm::dvec3& illuminance) {
    const glm::dvec3 v = normalizedOr(viewDirection, glm::dvec3(0.0, 1.0, 0.0));
    const glm::dvec3 l = normalizedOr(table.lightDirection, glm::dvec3(0.0, 1.0, 0.0));
    const double mu = dot3(v, l);
    return illuminance * (rayleighPhase(mu) * table.horizonRayleigh +
                          miePhase(mu, mieAnisotropy) * table.horizonMie + table.horizonMultiple);
}

}  // namespace aerial
