// aerial/evaluate.hpp — a preset at a time of day: the one call a game
// makes per frame.
//
// Usage:
//   aerial::CompiledPreset compiled(preset);    // once: binds tracks to fields
//   aerial::PresetState state;                  // caller-owned, reused
//   compiled.evaluate(timeHours, state);        // per frame, no allocation
//                                               // once `state` has its shape
//   // sunSky, moonSky: aerial::SpectralSkySolver (sky_spectral.hpp)
//   sunSky.solve(state.environment.atmosphere, state.sunLight.body.direction);
//   moonSky.solve(state.environment.atmosphere, state.moonLight.body.direction);
//   aerial::FogScene fog(aerial::fogSceneDesc(state, sunSky.table(), moonSky.table()));
//
// What evaluate does, in order:
//   1. copies the preset's values, then writes every track's value at t
//      into its (pre-bound) field;
//   2. clamps animated values into their table range and keeps the Mie
//      extinction >= scattering per channel;
//   3. the sun and moon: aerial::sunPosition / moonPosition (sun.hpp); their
//      illuminance above the atmosphere = colour * intensity (the moon's
//      times its phaseIrradiance), and the light that reaches the viewer =
//      that times aerial::transmittanceToSpace(atmosphere, viewerHeight,
//      direction.y) (atmosphere.hpp);
//   4. emitters: intensityCd times aerial::lightningFlash(emitter, t)
//      (emitter.hpp; kept in emitterFlash), colour = emitterColour, and
//      intensity = emitterFogIntensity(intensityCd, attenuation, sigma) and
//      extinction = sigma, sigma = fogScatteringAt(state, position).
//
// Cost: transmittanceToSpace is a fine quadrature, so the compiled preset
// tabulates the three unit optical depths (Rayleigh, Mie, ozone) over the
// light's zenith cosine once (computed with transmittanceToSpace itself)
// and evaluate combines them with the animated coefficients; when a track
// animates a quantity the table depends on (scale heights, viewer height)
// evaluate calls transmittanceToSpace directly (slower).
#pragma once

#include <aerial/clouds.hpp>
#include <aerial/emitter.hpp>
#include <aerial/fog_query.hpp>
#include <aerial/fog_volume.hpp>
#include <aerial/preset.hpp>
#include <aerial/sky.hpp>
#include <aerial/sun.hpp>
#include <aerial/timeline.hpp>

#include <glm/vec3.hpp>

#include <memory>
#include <vector>

namespace aerial {

struct WeatherMix;  // weather.hpp

/// A sun or moon at one moment.
struct LightState {
    CelestialBody body;
    /// Illuminance above the atmosphere, RGB: colour * intensity (moon:
    /// times body.phaseIrradiance).
    glm::dvec3 illuminanceSpace{0.0};
    /// T(viewer -> light), RGB, 0..1; 0 below the horizon.
    glm::dvec3 transmittance{0.0};
    /// What lights the scene: illuminanceSpace * transmittance.
    glm::dvec3 illuminance{0.0};
};

/// The complete state of a preset at one time of day.
struct PresetState {
    double timeHours = 0.0;
    Environment environment;
    std::vector<FogVolume> volumes;
    /// Keyed values and lightning flashes applied (to intensityCd), colour
    /// replaced by emitterColour (unit luminance), the fog in-scatter
    /// coefficient `intensity` and the `extinction` derived from intensityCd
    /// and fogScatteringAt(state, position) (emitter.hpp, "Photometry").
    std::vector<Emitter> emitters;
    /// The flash multiplier applied to each emitter (1 for point emitters).
    std::vector<double> emitterFlash;
    /// Cloud volumes with keyed values applied (prepareClouds passes them on).
    std::vector<CloudVolume> cloudVolumes;
    LightState sunLight;
    LightState moonLight;
    /// T(viewer -> space) straight up, RGB, 0..1 (what dims the stars;
    /// from the same transmittance table as the lights).
    glm::dvec3 zenithTransmittance{1.0};
};

/// A preset with its tracks bound to the fields they animate.
class CompiledPreset {
public:
    /// Compiles defaultPreset().
    CompiledPreset();
    /// Binds every track once. Keys that follow the sun are placed at the
    /// preset's location and date first (resolveKeyAnchors): a game that
    /// changes the date or the place compiles the preset again. Tracks that
    /// do not validate (unknown target, bad keys) are skipped and listed in
    /// issues(); a preset that passed validatePreset has none.
    explicit CompiledPreset(Preset preset);
    ~CompiledPreset();
    CompiledPreset(CompiledPreset&&) noexcept;
    CompiledPreset& operator=(CompiledPreset&&) noexcept;
    CompiledPreset(const CompiledPreset&) = delete;
    CompiledPreset& operator=(const CompiledPreset&) = delete;

    const Preset& preset() const;
    const std::vector<PresetIssue>& issues() const;

    /// The state at time t [h] (wrapped into [0, 24)). Allocates only when
    /// `state` does not yet have this preset's shape (first call).
    void evaluate(double timeHours, PresetState& state) const;
    PresetState evaluate(double timeHours) const;
    /// The same with the weather (weather.hpp): the overrides of the
    /// preset's weather states, weighted per category by `mix`, on top of
    /// the keys and before the lights, the emitters and every value derived
    /// from them. An empty mix is the plain evaluate. Allocates nothing.
    void evaluate(double timeHours, const WeatherMix& mix, PresetState& state) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

/// The light under the cloud deck of a state (clouds.hpp, CloudOvercast),
/// with the sky tables solved for its sun and moon. The renderer and
/// fogSceneDesc take it from here, so the GPU's fog and ambient and a game's
/// CPU queries agree.
struct OvercastLight {
    CloudOvercast overcast;  ///< of prepareClouds(state); all zero without clouds
    /// The clear sky's irradiance on an upward surface (skyIrradiance of both
    /// tables with the lights' illuminance above the atmosphere).
    glm::dvec3 clearSkyIrradiance{0.0};
    /// The deck's underside (overcastRadiance): lit on top by the sun and
    /// moon as they reach the ground (LightState::illuminance times mu (1/2 +
    /// 3/4 mu), mu the zenith cosine, 0 below the horizon) and the clear sky
    /// (skyIrradiance with a = 1/2, b = 3/4): a thick deck passes a beam at
    /// zenith cosine mu on as (1/2 + 3/4 mu) times diffuse light (Eddington).
    /// Plus a city's light from below that the deck reflects: albedo (1 -
    /// T_d) lightPollutionUplight(zenith) / pi (night_sky.hpp).
    glm::dvec3 radiance{0.0};
    /// Ambient on an upward surface below the deck: the clear sky through
    /// the gaps plus the deck, (1 - skyCover) clearSkyIrradiance + skyCover
    /// pi radiance; clearSkyIrradiance exactly without clouds.
    glm::dvec3 groundIrradiance{0.0};
};
OvercastLight overcastLight(const PresetState& state, const SkyTable& sunSky, const SkyTable& moonSky);

/// The scattering coefficient [1/m] of what hangs in the air at a world
/// point, the luminance-weighted (Y) mean over the colour channels: the
/// global height fog (density b exp(-c (y - h0)), all of it scattering),
/// plus every adding fog volume that contains the point (a subtract volume
/// there removes the fog, global and volumes), plus the atmosphere's
/// Rayleigh and Mie scattering at the altitude viewerHeight + y. What an
/// emitter there lights (evaluate sets each emitter's `intensity` from it).
double fogScatteringAt(const PresetState& state, const glm::dvec3& point);

/// The light of the sky dome at the fog of a state (fog_light.hpp): the
/// bands of both sky tables (the lights' illuminance above the atmosphere,
/// the atmosphere's anisotropy), the airglow and a city's glow, times 1 - skyCover, plus
/// the deck's underside (overcast.radiance) times skyCover, plus the
/// ground's reflection (the atmosphere's groundAlbedo) of that sky's and
/// the lights' irradiance (LightState::illuminance times the zenith cosine,
/// times 1 - skyCover). The renderer's fog and FogScene both take it from here.
FogSkyLight fogSkyLight(const PresetState& state, const SkyTable& sunSky, const SkyTable& moonSky,
                        const OvercastLight& overcast);
/// The clouds' mean visibility of the sun and the moon for the fog: 1 -
/// overcast.overcast.skyCover (1 without clouds).
double fogDirectVisibility(const OvercastLight& overcast);

/// The fog of a state for CPU fog queries (FogScene): global fog with the
/// preset's fog colour mode, volumes, emitters (flashes applied), the two
/// fog lights — direction, illuminance above the atmosphere, the horizon
/// averages of the sky tables solved for this state's sun and moon and the
/// illuminance that reaches the fog — the sky's light (fogSkyLight,
/// fogDirectVisibility) and the overcast (overcastLight: horizonCover and
/// the deck's radiance).
FogSceneDesc fogSceneDesc(const PresetState& state, const SkyTable& sunSky, const SkyTable& moonSky);
/// The same with the overcast already computed (overcastLight of the same state and tables).
FogSceneDesc fogSceneDesc(const PresetState& state, const SkyTable& sunSky, const SkyTable& moonSky,
                          const OvercastLight& overcast);

/// The clouds of a state for CPU cloud queries (clouds.hpp): the evaluated
/// cloud layer at the state's time (wind offset), the evaluated cloud
/// volumes, the planet's radius.
/// Cheap once the seed's noise is cached.
CloudField prepareClouds(const PresetState& state);

/// Convenience: compile and evaluate once (slow path; a game keeps a
/// CompiledPreset).
PresetState evaluate(const Preset& preset, double timeHours);

}  // namespace aerial
