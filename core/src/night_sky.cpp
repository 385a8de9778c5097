// night_sky.cpp — airglow (aerial/night_sky.hpp).
#include <aerial/night_sky.hpp>

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

}  // namespace aerial
