// photometry.cpp — the light of a moment in lux and cd/m^2
// (aerial/photometry.hpp).
#include <aerial/photometry.hpp>

#include <aerial/exposure.hpp>
#include <aerial/night_sky.hpp>

#include <algorithm>
#include <cmath>

namespace aerial {
namespace {

double finiteOrZero(double x) { return std::isfinite(x) && x > 0.0 ? x : 0.0; }

/// Lux of an illuminance in Aerial's unit, or cd/m^2 of a radiance in its unit.
double photometric(const glm::dvec3& c) { return finiteOrZero(luminance(c) * kNitsPerRadianceUnit); }

double beamLux(const LightState& light, double clearShare) {
    const double sine = std::clamp(light.body.direction.y, 0.0, 1.0);
    return photometric(light.illuminance) * sine * clearShare;
}

}  // namespace

LightReport lightReport(const PresetState& state, const SkyTable& sunSky, const SkyTable& moonSky) {
    return lightReport(state, sunSky, moonSky, overcastLight(state, sunSky, moonSky));
}

LightReport lightReport(const PresetState& state, const SkyTable& sunSky, const SkyTable& moonSky,
                        const OvercastLight& overcast) {
    LightReport out;
    const double cover =
        std::isfinite(overcast.overcast.skyCover) ? std::clamp(overcast.overcast.skyCover, 0.0, 1.0) : 0.0;
    const double clear = 1.0 - cover;
    HorizontalIlluminance& e = out.horizontalIlluminanceLux;
    e.sun = beamLux(state.sunLight, clear);
    e.moon = beamLux(state.moonLight, clear);
    e.sky = photometric(overcast.groundIrradiance);
    const LightPollution& glow = state.environment.lightPollution;
    e.night = photometric(airglowIrradiance(state.zenithTransmittance) + lightPollutionIrradiance(glow)) * clear;
    e.total = e.sun + e.sky + e.moon + e.night;

    const glm::dvec3 up(0.0, 1.0, 0.0);
    const double g = state.environment.atmosphere.mieAnisotropy;
    const glm::dvec3 zenith = skyRadiance(sunSky, g, up, state.sunLight.illuminanceSpace) +
                              skyRadiance(moonSky, g, up, state.moonLight.illuminanceSpace) +
                              airglowRadiance(up, state.zenithTransmittance) +
                              lightPollutionRadiance(glow, up, state.environment.location.northOffsetDeg);
    out.zenithLuminance = photometric(zenith);
    return out;
}

}  // namespace aerial
