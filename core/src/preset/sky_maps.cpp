// sky_maps.cpp — the sky-view map, the far fog map and the environment's
// irradiance coefficients (aerial/sky_maps.hpp).
#include "base/sanitise.hpp"
#include "base/worker_pool.hpp"

#include <aerial/night_sky.hpp>
#include <aerial/sky_maps.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <thread>

namespace aerial {
namespace {

constexpr int kShAzimuths = 128;
constexpr int kShRings = 64;  // per hemisphere, uniform in the zenith cosine (equal solid angles)

/// A world direction from an azimuth (from north, -Z, towards east, +X) and an elevation [rad].
glm::dvec3 worldDirection(double azimuth, double elevation) {
    const double c = std::cos(elevation);
    return {c * std::sin(azimuth), std::sin(elevation), -c * std::cos(azimuth)};
}

void store(RgbImage& image, int x, int y, const glm::dvec3& value) {
    const glm::dvec3 v = detail::sanitiseColour(value);
    const std::size_t at = (std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 3;
    for (int c = 0; c < 3; ++c) image.rgb[at + std::size_t(c)] = float(std::max(v[c], 0.0));
}

RgbImage blankImage(int width, int height) {
    RgbImage image;
    image.width = std::max(width, 1);
    image.height = std::max(height, 1);
    image.rgb.assign(std::size_t(image.width) * std::size_t(image.height) * 3, 0.0f);
    return image;
}

}  // namespace

double skyViewElevation(double line, int height) {
    const double last = std::max(height - 1, 1);
    const double t = std::clamp(std::isnan(line) ? 0.0 : line, 0.0, last) / last;
    return 0.5 * kPi * t * t;
}

double skyViewLine(double elevation, int height) {
    const double el = std::clamp(std::isnan(elevation) ? 0.0 : elevation, 0.0, 0.5 * kPi);
    return std::max(height - 1, 1) * std::sqrt(el / (0.5 * kPi));
}

glm::dvec3 skyViewDirection(int x, int y, int width, int height) {
    return worldDirection(2.0 * kPi * (x + 0.5) / std::max(width, 1), skyViewElevation(y, height));
}

namespace {
/// Line 0 holds the sky's limit from above the horizon: the night sky's
/// airglow and a city's glow end at the horizon (0 below it).
constexpr double kHorizonLineElevation = 1e-9;
}  // namespace

glm::dvec3 clearSkyRadiance(const PresetState& state, const SkyTable& sun, const SkyTable& moon,
                            const glm::dvec3& direction) {
    const double g = state.environment.atmosphere.mieAnisotropy;
    return skyRadiance(sun, g, direction, state.sunLight.illuminanceSpace) +
           skyRadiance(moon, g, direction, state.moonLight.illuminanceSpace) +
           airglowRadiance(direction, state.zenithTransmittance) +
           lightPollutionRadiance(state.environment.lightPollution, direction,
                                  state.environment.location.northOffsetDeg);
}

RgbImage skyViewMap(const PresetState& state, const SkyTable& sun, const SkyTable& moon, int width,
                    int height) {
    RgbImage image = blankImage(width, std::max(height, 2));
    // One line per item on every core: each texel depends on nothing else,
    // so the image is the same whatever the thread count.
    auto line = [&](int y, int) {
        const double el = std::max(skyViewElevation(y, image.height), kHorizonLineElevation);
        for (int x = 0; x < image.width; ++x)
            store(image, x, y,
                  clearSkyRadiance(state, sun, moon, worldDirection(2.0 * kPi * (x + 0.5) / image.width, el)));
    };
    detail::WorkerPool pool(int(std::max(1u, std::thread::hardware_concurrency())));
    pool.run(image.height, line);
    return image;
}

RgbImage farFogMap(const FogScene& fog, int width, int height) {
    RgbImage image = blankImage(width, height);
    for (int y = 0; y < image.height; ++y) {
        const double el = 0.5 * kPi - kPi * (y + 0.5) / image.height;
        for (int x = 0; x < image.width; ++x)
            store(image, x, y, fog.fogColour(worldDirection(2.0 * kPi * (x + 0.5) / image.width, el)));
    }
    return image;
}

double sh9Basis(int i, const glm::dvec3& d) {
    switch (i) {
        case 0: return 0.282095;
        case 1: return 0.488603 * d.y;
        case 2: return 0.488603 * d.z;
        case 3: return 0.488603 * d.x;
        case 4: return 1.092548 * d.x * d.y;
        case 5: return 1.092548 * d.y * d.z;
        case 6: return 0.315392 * (3.0 * d.z * d.z - 1.0);
        case 7: return 1.092548 * d.x * d.z;
        case 8: return 0.546274 * (d.x * d.x - d.y * d.y);
        default: return 0.0;
    }
}

IrradianceSH9 environmentIrradianceSH9(const PresetState& state, const SkyTable& sun, const SkyTable& moon,
                                       const OvercastLight& overcast) {
    const double clear = fogDirectVisibility(overcast);
    const glm::dvec3 deck = (1.0 - clear) * detail::sanitiseColour(overcast.radiance);
    glm::dvec3 radiance[9] = {};
    glm::dvec3 down(0.0);  // irradiance on the ground
    const double cell = 2.0 * kPi / (double(kShAzimuths) * kShRings);
    // Both hemispheres on the same grid: the sky above, then the ground's
    // uniform reflection of the sky's and the lights' irradiance below.
    for (int pass = 0; pass < 2; ++pass) {
        const glm::dvec3 ground = pass == 0 ? glm::dvec3(0.0)
                                            : glm::clamp(detail::sanitiseColour(state.environment.atmosphere.groundAlbedo), 0.0, 1.0) *
                                                  down / kPi;
        for (int j = 0; j < kShRings; ++j) {
            const double mu = (j + 0.5) / kShRings * (pass == 0 ? 1.0 : -1.0);
            const double r = std::sqrt(1.0 - mu * mu);
            for (int i = 0; i < kShAzimuths; ++i) {
                const double az = (i + 0.5) / kShAzimuths * 2.0 * kPi;
                const glm::dvec3 w(r * std::sin(az), mu, -r * std::cos(az));
                const glm::dvec3 L =
                    pass == 0 ? clear * detail::sanitiseColour(clearSkyRadiance(state, sun, moon, w)) + deck
                              : ground;
                for (int k = 0; k < 9; ++k) radiance[k] += L * (sh9Basis(k, w) * cell);
                if (pass == 0) down += L * (mu * cell);
            }
        }
        if (pass == 0)
            for (const LightState* l : {&state.sunLight, &state.moonLight}) {
                const double m = l->body.direction.y;
                if (m > 0.0 && std::isfinite(m))
                    down += clear * std::min(m, 1.0) * detail::sanitiseColour(l->illuminance);
            }
    }
    // Convolution with the clamped cosine (Ramamoorthi and Hanrahan 2001).
    constexpr double kBand[3] = {kPi, 2.0 * kPi / 3.0, kPi / 4.0};
    IrradianceSH9 sh;
    for (int k = 0; k < 9; ++k) sh.c[k] = radiance[k] * kBand[k == 0 ? 0 : (k < 4 ? 1 : 2)];
    return sh;
}

glm::dvec3 evaluateIrradianceSH9(const IrradianceSH9& sh, const glm::dvec3& normal) {
    glm::dvec3 e(0.0);
    for (int k = 0; k < 9; ++k) e += sh.c[k] * sh9Basis(k, normal);
    return glm::max(detail::sanitiseColour(e), glm::dvec3(0.0));
}

}  // namespace aerial
