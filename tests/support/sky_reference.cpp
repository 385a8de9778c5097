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

namespace {
/// The boost fraction of a light just set (skyCapBoostFraction), written
/// out again: 0 above a kink at kSkyCapBoostStartDeg, 1 below kSkyCapBoostFullDeg.
double boostFraction(double c) {
    return std::clamp((kSkyCapBoostStartDeg - c * 180.0 / kPi) / (kSkyCapBoostStartDeg - kSkyCapBoostFullDeg),
                      0.0, 1.0);
}
}  // namespace

double texelElevation(int j, const SkyTable& table) {
    const int h = table.elevationCount;
    if (h <= 1) return 0.0;
    const double target = double(j) / (h - 1);
    // The mapping of <aerial/sky.hpp>, written out again: v(el) in 0..1.
    const double a = table.bandElevation > 0.0 ? table.bandShare : 0.0;
    const double b = table.shadowWidth > 0.0 ? table.shadowShare : 0.0;
    const double d =
        skyTableColumnsWarped(table) ? skyCapRowShare(table.shadowElevation, table.capStrength) : 0.0;
    auto mapped = [&](double el) {
        double v = (1.0 - a - b - d) * std::sqrt(el / (0.5 * kPi));
        if (d > 0.0) {
            const double c = table.shadowElevation;
            const double u = std::min(std::abs(el - c), c) / c;
            // Below c: u^p blending into ln(1 + u / s) / ln(1 + 1 / s) as the boost comes in.
            const double m = boostFraction(c);
            const double s = std::min(kSkyCapLogScale, kSkyCapLogScalePerKink * c);
            const double below = (1.0 - m) * std::pow(u, kSkyCapBelowPower) +
                                 m * std::log(1.0 + u / s) / std::log(1.0 + 1.0 / s);
            v += 0.5 * d * (el < c ? 1.0 - below : 1.0 + std::pow(u, 1.0 / 3.0));
        }
        if (a > 0.0)
            v += a * std::atan(el / table.bandElevation) / std::atan(0.5 * kPi / table.bandElevation);
        if (b > 0.0) {
            const double c = table.shadowElevation, w = table.shadowWidth;
            v += b * (std::atan((el - c) / w) - std::atan(-c / w)) /
                 (std::atan((0.5 * kPi - c) / w) - std::atan(-c / w));
        }
        return v;
    };
    if (j == h - 1) return 0.5 * kPi;
    double lo = 0.0, hi = 0.5 * kPi;  // bisection: v is increasing
    for (int it = 0; it < 200 && hi - lo > 1e-15; ++it) {
        const double mid = 0.5 * (lo + hi);
        (mapped(mid) < target ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

double texelAzimuth(int i, double elevation, const SkyTable& table) {
    const double n = table.azimuthCount;
    if (!skyTableColumnsWarped(table)) return 2.0 * kPi * i / n;
    // The column mapping of <aerial/sky.hpp>, written out again: piecewise
    // linear in the azimuth psi from the anti-light point, in ln(1 + y / Y0),
    // y = psi^2 - P^2, between the second and the third knot, quadratic in
    // the columns after the third.
    const double k = table.capCurvature, g = std::min(table.capStrength, 1.0), c = table.shadowElevation;
    const double foot = std::min(std::sqrt(c / k), 0.25 * kPi);
    const double floorBand = kSkyCapMinBandDeg * kPi / 180.0;
    const double band = std::max(0.5 * foot, std::min(floorBand, kSkyCapBandPerKink * c));
    const double wide = std::max(0.5 * foot, floorBand);
    const double onset = std::min(std::sqrt(std::max(c - elevation, 0.0) / k), foot);
    // A light just set blends the shares and the band's knot towards the
    // *Set constants by the boost fraction m.
    const double boost = boostFraction(c);
    const double inside = kSkyCapInsideShare + boost * (kSkyCapInsideShareSet - kSkyCapInsideShare);
    const double onsetShare = kSkyCapOnsetShare + boost * (kSkyCapOnsetShareSet - kSkyCapOnsetShare);
    const double growth = kSkyCapOnsetGrowth + boost * (kSkyCapOnsetGrowthSet - kSkyCapOnsetGrowth);
    const double y0 = std::pow(kSkyCapBandScale * c, 2) + std::pow(kSkyCapBandOnsetScale * onset, 2);
    // The blended knots rounded to whole columns, each where that keeps it
    // above the knot before it.
    double xs[5] = {0.0, inside * n, (inside + onsetShare) * n, (inside + onsetShare + kSkyCapNearShare) * n,
                    0.5 * n};
    for (int m = 1; m <= 3; ++m)
        if (std::round(xs[m]) > xs[m - 1]) xs[m] = std::round(xs[m]);
    const double cap[5] = {0.0, onset, std::hypot(growth * onset, band),
                           std::min(2.0 * (foot + wide), 0.75 * kPi), kPi};
    const double x = std::abs(i - 0.5 * n);
    for (int m = 0; m < 4; ++m) {
        if (x <= xs[m + 1]) {
            const double p0 = m == 0 ? 0.0 : g * cap[m] + (1.0 - g) * 2.0 * kPi * xs[m] / n;
            const double p1 = m == 3 ? kPi : g * cap[m + 1] + (1.0 - g) * 2.0 * kPi * xs[m + 1] / n;
            const double t = (x - xs[m]) / (xs[m + 1] - xs[m]);
            // The last two segments: quadratic, slope a at their start (relative to their mean).
            const double a = 1.0 - g * (1.0 - (m == 3 ? kSkyCapFarSlope : kSkyCapNearSlope));
            const double u = m >= 2 ? a * t + (1.0 - a) * t * t : t;
            double psi = p0 + (p1 - p0) * u;
            if (m == 1) {  // ln(1 + y / Y0) = u ln(1 + y1 / Y0), y1 = p1^2 - p0^2
                const double y1 = p1 * p1 - p0 * p0;
                psi = std::sqrt(p0 * p0 + y0 * (std::exp(u * std::log(1.0 + y1 / y0)) - 1.0));
            }
            return i <= 0.5 * n ? kPi - psi : kPi + psi;
        }
    }
    return 0.0;
}

glm::dvec3 texelDirection(int i, int j, const SkyTable& table) {
    const double elevation = texelElevation(j, table);
    const double azimuth = table.lightAzimuth + texelAzimuth(i, elevation, table);
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
    setSkyTableMapping(table, air, light);  // the solver's row mapping for this light
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
