// sky_reference.cpp — brute-force single scattering, see sky_reference.hpp.
// Everything is recomputed from first principles: sphere geometry, density
// profiles, the optical depth to the light and the view-ray integral.
#include "sky_reference.hpp"

#include <algorithm>
#include <cmath>

namespace aerial::reference {
namespace {

struct Densities {
    double rayleigh;
    double mie;
    double ozone;
};

Densities densitiesAt(const AtmosphereParams& air, double height) {
    const double h = std::max(height, 0.0);
    Densities d{};
    d.rayleigh = air.rayleighScaleHeight > 0.0 ? std::exp(-h / air.rayleighScaleHeight) : 0.0;
    d.mie = air.mieScaleHeight > 0.0 ? std::exp(-h / air.mieScaleHeight) : 0.0;
    if (air.ozoneWidth > 0.0) {
        const double lower = air.ozoneCenterHeight - 0.5 * air.ozoneWidth;
        const double upper = air.ozoneCenterHeight + 0.5 * air.ozoneWidth;
        if (h > lower && h <= air.ozoneCenterHeight)
            d.ozone = (h - lower) / (0.5 * air.ozoneWidth);
        else if (h > air.ozoneCenterHeight && h < upper)
            d.ozone = (upper - h) / (0.5 * air.ozoneWidth);
    }
    return d;
}

glm::dvec3 extinction(const AtmosphereParams& air, const Densities& d) {
    return air.rayleighScattering * d.rayleigh + air.mieExtinction * d.mie + air.ozoneAbsorption * d.ozone;
}

// Length of the ray from point p (planet-centred) along unit dir to the top.
double lengthToTop(const AtmosphereParams& air, const glm::dvec3& p, const glm::dvec3& dir) {
    const double b = p.x * dir.x + p.y * dir.y + p.z * dir.z;
    const double c = p.x * p.x + p.y * p.y + p.z * p.z - air.atmosphereRadius * air.atmosphereRadius;
    const double disc = b * b - c;
    if (disc <= 0.0) return 0.0;
    return std::max(-b + std::sqrt(disc), 0.0);
}

bool hitsGround(const AtmosphereParams& air, const glm::dvec3& p, const glm::dvec3& dir) {
    const double b = p.x * dir.x + p.y * dir.y + p.z * dir.z;
    if (b >= 0.0) return false;
    const double perp2 = (p.x * p.x + p.y * p.y + p.z * p.z) - b * b;
    return perp2 <= air.planetRadius * air.planetRadius;
}

double heightOf(const AtmosphereParams& air, const glm::dvec3& p) {
    return std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z) - air.planetRadius;
}

// Optical depth from planet-centred p along unit dir to the top; the ray is
// split at its perigee and each piece is marched with `steps` midpoint steps
// in t, s = length * t^2 measured from the dense end (the start or perigee).
glm::dvec3 opticalDepthFrom(const AtmosphereParams& air, const glm::dvec3& p, const glm::dvec3& dir,
                            int steps) {
    const double length = lengthToTop(air, p, dir);
    if (!(length > 0.0)) return glm::dvec3(0.0);
    const double perigee = -(p.x * dir.x + p.y * dir.y + p.z * dir.z);
    glm::dvec3 depth(0.0);
    auto march = [&](double denseEnd, double otherEnd) {
        const double span = otherEnd - denseEnd;  // signed
        for (int k = 0; k < steps; ++k) {
            const double t = (k + 0.5) / steps;
            const double s = denseEnd + span * t * t;
            const double ds = std::abs(span) * 2.0 * t / steps;
            depth += extinction(air, densitiesAt(air, heightOf(air, p + dir * s))) * ds;
        }
    };
    if (perigee > 0.0 && perigee < length) {
        march(perigee, 0.0);
        march(perigee, length);
    } else {
        march(0.0, length);
    }
    return depth;
}

glm::dvec3 expNeg(const glm::dvec3& x) { return glm::dvec3(std::exp(-x.x), std::exp(-x.y), std::exp(-x.z)); }

}  // namespace

glm::dvec3 opticalDepthToTop(const AtmosphereParams& air, double height, double muZenith, int steps) {
    const double mu = std::clamp(muZenith, -1.0, 1.0);
    const glm::dvec3 p(0.0, air.planetRadius + height, 0.0);
    const glm::dvec3 dir(std::sqrt(std::max(0.0, 1.0 - mu * mu)), mu, 0.0);
    if (hitsGround(air, p, dir)) return glm::dvec3(INFINITY);
    return opticalDepthFrom(air, p, dir, steps);
}

SkySample singleScattering(const AtmosphereParams& air, const glm::dvec3& view, const glm::dvec3& light,
                           const SkyReferenceOptions& options) {
    SkySample out;
    const glm::dvec3 origin(0.0, air.planetRadius + air.viewerHeight, 0.0);
    if (hitsGround(air, origin, view)) return out;
    const double length = lengthToTop(air, origin, view);
    if (!(length > 0.0)) return out;

    // March the view ray with s = length * t^2 (dense near the viewer, where
    // the horizon rays spend their optical depth). The viewer-to-sample
    // transmittance integrates the extinction up to the middle of the step.
    const int n = options.viewSteps;
    glm::dvec3 depthToViewer(0.0);
    double previousS = 0.0;
    glm::dvec3 previousExtinction = extinction(air, densitiesAt(air, air.viewerHeight));
    for (int k = 0; k < n; ++k) {
        const double t = (k + 0.5) / n;
        const double s = length * t * t;
        const double ds = length * 2.0 * t / n;
        const glm::dvec3 x = origin + view * s;
        const Densities d = densitiesAt(air, heightOf(air, x));
        const glm::dvec3 sigma = extinction(air, d);
        // Trapezoid from the previous node to this one.
        depthToViewer += 0.5 * (previousExtinction + sigma) * (s - previousS);
        previousS = s;
        previousExtinction = sigma;
        if (hitsGround(air, x, light)) continue;
        const glm::dvec3 depthToLight = opticalDepthFrom(air, x, light, options.lightSteps);
        const glm::dvec3 weight = expNeg(depthToViewer + depthToLight) * ds;
        out.rayleigh += air.rayleighScattering * d.rayleigh * weight;
        out.mie += air.mieScattering * d.mie * weight;
    }
    return out;
}

double azimuthOf(const glm::dvec3& direction) { return std::atan2(direction.x, -direction.z); }

double texelElevation(int j, const SkyTable& table) { return table.rowElevation.at(std::size_t(j)); }

double texelAzimuth(int i, int j, const SkyTable& table) {
    return table.columnAzimuth.at(std::size_t(j) * std::size_t(table.azimuthCount) + std::size_t(i));
}

glm::dvec3 texelDirection(int i, int j, const SkyTable& table) {
    const double elevation = texelElevation(j, table);
    const double azimuth = table.lightAzimuth + texelAzimuth(i, j, table);
    const double ce = std::cos(elevation);
    return glm::dvec3(std::sin(azimuth) * ce, std::sin(elevation), -std::cos(azimuth) * ce);
}

void solveTable(const AtmosphereParams& air, const glm::dvec3& light, int azimuthCount, int elevationCount,
                SkyTable& table, int rowBegin, int rowEnd, const SkyReferenceOptions& options) {
    const std::size_t texels = std::size_t(azimuthCount) * elevationCount * 3;
    table.azimuthCount = azimuthCount;
    table.elevationCount = elevationCount;
    table.rayleigh.assign(texels, 0.0f);
    table.mie.assign(texels, 0.0f);
    table.lightDirection = light;
    table.lightAzimuth = azimuthOf(light);
    setSkyTableMapping(table, air, light);  // the solver's coordinates for this light
    for (int j = std::max(rowBegin, 0); j < std::min(rowEnd, elevationCount); ++j) {
        for (int i = 0; i <= azimuthCount / 2; ++i) {
            const SkySample s = singleScattering(air, texelDirection(i, j, table), light, options);
            for (int mirror : {i, (azimuthCount - i) % azimuthCount}) {
                const std::size_t at = (std::size_t(j) * azimuthCount + mirror) * 3;
                for (int c = 0; c < 3; ++c) {
                    table.rayleigh[at + c] = float(s.rayleigh[c]);
                    table.mie[at + c] = float(s.mie[c]);
                }
            }
        }
    }
}

}  // namespace aerial::reference
