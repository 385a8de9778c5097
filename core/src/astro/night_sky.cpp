// night_sky.cpp — airglow (aerial/night_sky.hpp).
#include <aerial/night_sky.hpp>

#include <aerial/emitter.hpp>
#include <aerial/exposure.hpp>

#include <algorithm>
#include <cmath>

namespace aerial {
namespace {

constexpr double kPi = 3.14159265358979323846;

double unitOrZero(double x) { return std::isfinite(x) ? std::clamp(x, 0.0, 1.0) : 0.0; }

}  // namespace

double relativeAirMass(double mu) {
    const double m = unitOrZero(mu);
    const double zenithDeg = std::acos(m) * (180.0 / kPi);
    return 1.0 / (m + 0.50572 * std::pow(96.07995 - zenithDeg, -1.6364));
}

double airglowVanRhijn(double mu) {
    const double m = unitOrZero(mu);
    const double r = kAirglowShellRatio;
    return 1.0 / std::sqrt(1.0 - r * r * (1.0 - m * m));
}

glm::dvec3 airglowRadiance(const glm::dvec3& v, const glm::dvec3& zenithTransmittance) {
    if (!(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z))) return glm::dvec3(0.0);
    const double length = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    if (!(length > 0.0) || !(v.y > 0.0)) return glm::dvec3(0.0);
    const double mu = v.y / length;
    const double x = relativeAirMass(mu);
    glm::dvec3 t;
    for (int c = 0; c < 3; ++c) {
        const double direct = std::pow(unitOrZero(zenithTransmittance[c]), x);
        t[c] = direct + kAirglowScatteredFill * (1.0 - direct);
    }
    return kAirglowZenithRadiance * airglowVanRhijn(mu) * t;
}

glm::dvec3 airglowIrradiance(const glm::dvec3& zenithTransmittance) {
    // E = 2 pi integral_0^1 L(mu) mu dmu, midpoint rule in mu.
    constexpr int kRings = 256;
    glm::dvec3 sum(0.0);
    for (int i = 0; i < kRings; ++i) {
        const double mu = (i + 0.5) / kRings;
        sum += airglowRadiance({std::sqrt(1.0 - mu * mu), mu, 0.0}, zenithTransmittance) * mu;
    }
    return sum * (2.0 * kPi / kRings);
}

glm::dvec3 lightPollutionCityDirection(const LightPollution& glow, double northOffsetDeg) {
    const double deg = (std::isfinite(glow.azimuthDeg) ? glow.azimuthDeg : 0.0) +
                       (std::isfinite(northOffsetDeg) ? northOffsetDeg : 0.0);
    const double az = deg * (kPi / 180.0);
    return {std::sin(az), 0.0, -std::cos(az)};
}

glm::dvec3 lightPollutionColour(LightPollutionLamps lamps) {
    return blackbodyColour(lamps == LightPollutionLamps::Led ? 4000.0 : 2100.0);
}

namespace {

constexpr double kDomeGain = 20.0;                   // K
constexpr double kDomeWidth = 30.0 * kPi / 180.0;    // sigma

double dome(double theta) { return kDomeGain * std::exp(-theta * theta / (2.0 * kDomeWidth * kDomeWidth)); }

/// s(v) for a unit v above the horizon and the city's unit horizon direction c.
double glowShape(const glm::dvec3& v, const glm::dvec3& c) {
    const double cosTheta = std::clamp(v.x * c.x + v.y * c.y + v.z * c.z, -1.0, 1.0);
    return (std::sqrt(relativeAirMass(v.y)) + dome(std::acos(cosTheta))) / (1.0 + dome(0.5 * kPi));
}

double glowLuminance(const LightPollution& glow) {
    const double l = glow.zenithLuminance;
    return std::isfinite(l) && l > 0.0 ? std::min(l, 1.0e6) : 0.0;
}

}  // namespace

glm::dvec3 lightPollutionRadiance(const LightPollution& glow, const glm::dvec3& v, double northOffsetDeg) {
    const double lz = glowLuminance(glow);
    if (!(lz > 0.0) || !(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z))) return glm::dvec3(0.0);
    const double length = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    if (!(length > 0.0) || !(v.y > 0.0)) return glm::dvec3(0.0);
    const double shape = glowShape(v / length, lightPollutionCityDirection(glow, northOffsetDeg));
    return lightPollutionColour(glow.lamps) * (lz * shape / kNitsPerRadianceUnit);
}

glm::dvec3 lightPollutionIrradiance(const LightPollution& glow) {
    if (!(glowLuminance(glow) > 0.0)) return glm::dvec3(0.0);
    constexpr int kRings = 64, kAzimuths = 128;
    const double cell = 2.0 * kPi / (double(kAzimuths) * kRings);
    glm::dvec3 e(0.0);
    for (int j = 0; j < kRings; ++j) {
        const double mu = (j + 0.5) / kRings;
        const double r = std::sqrt(1.0 - mu * mu);
        for (int i = 0; i < kAzimuths; ++i) {
            const double az = (i + 0.5) / kAzimuths * 2.0 * kPi;
            e += lightPollutionRadiance(glow, glm::dvec3(r * std::sin(az), mu, -r * std::cos(az)), 0.0) * (mu * cell);
        }
    }
    return e;
}

glm::dvec3 lightPollutionUplight(const LightPollution& glow, const glm::dvec3& viewDirection,
                                 double northOffsetDeg) {
    return kPi / kLightPollutionUplightDepth * lightPollutionRadiance(glow, viewDirection, northOffsetDeg);
}

}  // namespace aerial
