// aerial/photometry.hpp — the light of a moment in the units a lighting
// artist checks a scene with: the illuminance on a horizontal surface in lux
// and the zenith's luminance in cd/m^2, to hold against the outdoors.
//
// Usage (a state and its two sky tables, as for fogSceneDesc):
//   aerial::LightReport r = aerial::lightReport(state, sunSky.table(), moonSky.table());
//   r.horizontalIlluminanceLux.total;   // clear noon ~1e5, civil dusk ~3, full moon ~0.25
//   r.zenithLuminance;                  // moonless night ~2e-4 cd/m^2
//
// What it adds up (Aerial's illuminance unit is aerial::kNitsPerRadianceUnit
// = 5000 lx, its radiance unit 5000 cd/m^2; Y = luminance() of the linear
// Rec.709 colour):
//   * sun, moon: the direct beam, LightState::illuminance (above the
//     atmosphere x T(viewer -> light), 0 below the horizon) times the sine of
//     the light's elevation; under clouds times the share of the sky the deck
//     leaves clear (1 - CloudOvercast::skyCover, the mean a horizontal
//     surface sees, not the shadow at one point);
//   * sky: the sun's and the moon's scattered light over the upper
//     hemisphere, skyIrradiance of both tables (cosine-weighted, phases
//     applied per direction), or under clouds OvercastLight::groundIrradiance
//     (the clear sky through the gaps plus the deck's underside);
//   * night: the natural night sky (airglow, zodiacal light and unresolved
//     stars, aerial/night_sky.hpp: airglowIrradiance) and a city's glow
//     when the preset has one (lightPollutionIrradiance), through the gaps;
//   * zenithLuminance: the clear sky straight up, both tables, the airglow
//     and the city's glow (the clouds are not counted).
// Published clear-sky references (AMS Glossary of Meteorology, "twilight";
// USNO, "Illuminance": the horizontal illuminance by the sun's elevation):
// a high sun 90-130 klx, sun at the horizon 410-585 lx, civil twilight's
// end (-6 deg) 2-3.5 lx, nautical (-12 deg) ~0.008 lx; a full moon high up
// 0.1-0.3 lx; a moonless night 1-2 mlx, its zenith 1.7-2.5e-4 cd/m^2.
#pragma once

#include <aerial/evaluate.hpp>
#include <aerial/sky.hpp>

namespace aerial {

/// Illuminance on an upward horizontal surface at the viewer [lx], by source.
struct HorizontalIlluminance {
    double sun = 0.0;    ///< the sun's direct beam
    double sky = 0.0;    ///< the sunlit and moonlit sky (and under clouds the deck)
    double moon = 0.0;   ///< the moon's direct beam
    double night = 0.0;  ///< the natural night sky: airglow, zodiacal light, unresolved stars
    double total = 0.0;  ///< the sum
};

/// A moment's light as a meter reads it (see the header).
struct LightReport {
    HorizontalIlluminance horizontalIlluminanceLux;
    /// Luminance of the clear sky at the zenith [cd/m^2].
    double zenithLuminance = 0.0;
};

/// The light of `state` with the sky tables solved for its sun and moon
/// (any size; SkySolver's defaults are what the CLI and the editor use).
/// Finite and >= 0 for any input.
LightReport lightReport(const PresetState& state, const SkyTable& sunSky, const SkyTable& moonSky);

/// The same with the overcast already computed (overcastLight of the same
/// state and tables), for callers that have it.
LightReport lightReport(const PresetState& state, const SkyTable& sunSky, const SkyTable& moonSky,
                        const OvercastLight& overcast);

}  // namespace aerial
