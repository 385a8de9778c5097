// fog_light.cpp — the light that reaches the fog (aerial/fog_light.hpp).
#include "base/sanitise.hpp"

#include <aerial/fog_light.hpp>
#include <aerial/night_sky.hpp>

#include <algorithm>
#include <cmath>

namespace aerial {
namespace {

constexpr int kAzimuths = 48;
constexpr int kRings = 16;

/// Midpoint rule over the upper hemisphere in equal solid angles (rings
/// uniform in the zenith cosine): calls f(v, d omega) per cell.
template <class F>
void forUpperHemisphere(F&& f) {
    const double cell = 2.0 * kPi / (double(kAzimuths) * kRings);
    for (int j = 0; j < kRings; ++j) {
        const double mu = (j + 0.5) / kRings;
        const double r = std::sqrt(1.0 - mu * mu);
        for (int i = 0; i < kAzimuths; ++i) {
            const double az = (i + 0.5) / kAzimuths * 2.0 * kPi;
            f(glm::dvec3(r * std::sin(az), mu, -r * std::cos(az)), cell);
        }
    }
}

/// Adds radiance L arriving from direction w over solid angle dw to the bands.
void accumulate(FogSkyLight& sky, const glm::dvec3& w, const glm::dvec3& L, double dw) {
    sky.l0 += L * (dw / (4.0 * kPi));
    for (int k = 0; k < 3; ++k) sky.l1[k] += L * (w[k] * 3.0 * dw / (4.0 * kPi));
}

}  // namespace

double miePhaseFirstMoment(double g) {
    const double x = std::isnan(g) ? 0.0 : std::clamp(g, -0.999, 0.999);
    return 3.0 * x * (4.0 + x * x) / (5.0 * (2.0 + x * x));
}

double fogHorizonWeight(double distance, double horizonDistance) {
    const double d =
        (std::isfinite(horizonDistance) && horizonDistance > 0.0) ? horizonDistance : kFogHorizonDistance;
    if (!(distance > 0.0)) return 0.0;
    const double x = distance / d;
    return -std::expm1(-x * x);
}

glm::dvec3 fogSkyInScatter(const FogSkyLight& sky, double firstMoment, const glm::dvec3& v) {
    glm::dvec3 l(0.0);
    for (int c = 0; c < 3; ++c) {
        // The band windowed so that it swings at most kFogSkyDipoleBound of the mean.
        const glm::dvec3 a1(sky.l1[0][c], sky.l1[1][c], sky.l1[2][c]);
        const double swing = std::fabs(firstMoment) * std::sqrt(glm::dot(a1, a1));
        const double bound = kFogSkyDipoleBound * std::max(sky.l0[c], 0.0);
        const double window = swing > bound ? bound / swing : 1.0;
        l[c] = sky.l0[c] + window * firstMoment * glm::dot(a1, v);
    }
    return glm::max(l, glm::dvec3(0.0));
}

glm::dvec3 addSkyTableLight(FogSkyLight& sky, const SkyTable& table, double mieAnisotropy,
                            const glm::dvec3& illuminance, double weight) {
    glm::dvec3 irradiance(0.0);
    const glm::dvec3 e = detail::sanitiseColour(illuminance) * weight;
    if (table.azimuthCount < 1 || table.elevationCount < 1 || !(weight > 0.0) ||
        !(e.x > 0.0 || e.y > 0.0 || e.z > 0.0))
        return irradiance;
    forUpperHemisphere([&](const glm::dvec3& w, double dw) {
        const glm::dvec3 L = detail::sanitiseColour(skyRadiance(table, mieAnisotropy, w, e));
        accumulate(sky, w, L, dw);
        irradiance += L * (w.y * dw);
    });
    return irradiance;
}

glm::dvec3 addUniformSkyLight(FogSkyLight& sky, const glm::dvec3& radiance) {
    const glm::dvec3 L = detail::sanitiseColour(radiance);
    // Over the upper hemisphere: integral dw = 2 pi, integral w dw = (0, pi, 0).
    sky.l0 += L * 0.5;
    sky.l1[1] += L * 0.75;
    return L * kPi;
}

glm::dvec3 addAirglowLight(FogSkyLight& sky, const glm::dvec3& zenithTransmittance) {
    // The airglow depends on the elevation alone: whole rings (a_1's x and z vanish).
    glm::dvec3 irradiance(0.0);
    constexpr int kAirglowRings = 64;
    for (int j = 0; j < kAirglowRings; ++j) {
        const double mu = (j + 0.5) / kAirglowRings;
        const double dw = 2.0 * kPi / kAirglowRings;
        const glm::dvec3 L =
            airglowRadiance(glm::dvec3(std::sqrt(1.0 - mu * mu), mu, 0.0), zenithTransmittance);
        sky.l0 += L * (dw / (4.0 * kPi));
        sky.l1[1] += L * (mu * 3.0 * dw / (4.0 * kPi));
        irradiance += L * (mu * dw);
    }
    return irradiance;
}

glm::dvec3 addLightPollutionLight(FogSkyLight& sky, const LightPollution& glow, double northOffsetDeg) {
    glm::dvec3 irradiance(0.0);
    if (!(glow.zenithLuminance > 0.0)) return irradiance;
    forUpperHemisphere([&](const glm::dvec3& w, double dw) {
        const glm::dvec3 L = lightPollutionRadiance(glow, w, northOffsetDeg);
        accumulate(sky, w, L, dw);
        irradiance += L * (w.y * dw);
    });
    return irradiance;
}

void addGroundLight(FogSkyLight& sky, const glm::dvec3& albedo, const glm::dvec3& groundIrradiance) {
    const glm::dvec3 a = glm::clamp(detail::sanitiseColour(albedo), 0.0, 1.0);
    const glm::dvec3 L = a * detail::sanitiseColour(groundIrradiance) / kPi;
    // Over the lower hemisphere: integral dw = 2 pi, integral w dw = (0, -pi, 0).
    sky.l0 += L * 0.5;
    sky.l1[1] -= L * 0.75;
}

}  // namespace aerial
