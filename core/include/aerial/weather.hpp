// aerial/weather.hpp — weather at runtime: a preset's weather states
// (weather_state.hpp) layered on its time-of-day keys, transitions between
// them, and a blend between two whole presets.
//
// Usage (a game):
//   aerial::CompiledPreset compiled(preset);
//   aerial::Weather weather(compiled.preset(), "clear");
//   aerial::WeatherMix mix;                       // reused, no allocation per frame
//   ...
//   weather.change("storm", 600.0, gameSeconds);  // ten minutes from now on
//   weather.mix(gameSeconds, mix);
//   compiled.evaluate(timeOfDayHours, mix, state);
// The game's clock (`gameSeconds`, any origin) drives the transitions; the
// time of day drives the keys. Deterministic: the same constructor and the
// same change() calls give the same values bit for bit, so a save or a
// network peer rebuilds the weather from initial() and changes() (names and
// times, no raw values).
//
// Regional weather (the preset's weather regions, weather_state.hpp): the
// global weather, then each region the camera is in pulling it towards the
// region's state:
//   weather.mix(gameSeconds, global);                 // both mixes reused
//   aerial::regionalWeather(compiled.preset(), cameraPosition, global, mix);
//   compiled.evaluate(timeOfDayHours, mix, state);
// Outside every region `mix` is `global`, bit for bit; deep inside a region
// its state holds exactly (with the regions above it in priority on top).
//
// The blend. Every overridden parameter takes
//   v = k + sum_i W_i,c (o_i(k) - k),
// k the keyed value, o_i the state i's override of it (set, add or scale),
// W_i,c the weight of state i in the parameter's category c (the keyed
// values alone hold the rest, 1 - sum_i W_i,c); clamped to the parameter's
// range. A transition of duration D from the mix m0 it starts from to the
// state s gives, t seconds after it began,
//   W_c(t) = (1 - w_c) m0_c + w_c e_s,   w_c = smoothstep(clamp(t / (share_c D), 0, 1)),
// so each category moves at its own speed (as Ultra Dynamic Weather and
// Enviro's per-category transition speeds): the clouds take the whole
// duration, the fog 60 %, the wind 40 % (kWeatherCategoryShare). Every
// value is continuous in time (a change started during another begins from
// the mix of that moment) and moves at most 1.5 |o_i - k| / (share_c D) per
// second plus the keys' own rate.
#pragma once

#include <aerial/evaluate.hpp>
#include <aerial/preset.hpp>
#include <aerial/weather_state.hpp>

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace aerial {

/// What a parameter is, for the speed of its transitions.
enum class WeatherCategory {
    Clouds,     ///< clouds.* (but the wind), cloud volumes
    Fog,        ///< fog.*, fog volumes
    Wind,       ///< clouds.wind_m_per_s
    Haze,       ///< atmosphere.*
    Light,      ///< exposure.*, sun.*, moon.*, night.*
    Lightning,  ///< emitters (their flashes)
    Other,      ///< anything else (location)
};
inline constexpr int kWeatherCategoryCount = 7;

/// The share of a transition's duration each category takes to complete,
/// indexed by WeatherCategory: clouds build up or break over the whole
/// change, fog and wind faster.
inline constexpr double kWeatherCategoryShare[kWeatherCategoryCount] = {1.0, 0.6, 0.4, 0.8, 0.8, 0.3, 1.0};

/// o(k): what an override makes of the keyed value k (per component: set
/// -> value, add -> k + value, scale -> k value), before the parameter's
/// range clamps it.
glm::dvec3 weatherOverrideValue(const WeatherOverride& o, const glm::dvec3& keyed);

/// The category of a target (above).
WeatherCategory weatherCategory(const TrackTarget& target);
/// "clouds", "fog", "wind", "haze", "light", "lightning", "other".
const char* weatherCategoryName(WeatherCategory category);

/// The new state's weight in `category` after `fraction` (0..1) of a
/// transition: smoothstep(clamp(fraction / share, 0, 1)); 1 for fraction
/// >= 1 or NaN-free inputs beyond it.
double weatherTransitionWeight(WeatherCategory category, double fraction);

/// Weights of a preset's weather states per category: weights[i][c] for
/// the preset's state i (Preset::weather) and category c; the keyed values
/// alone hold 1 - sum_i weights[i][c]. Empty: the keyed values.
struct WeatherMix {
    std::vector<std::array<double, kWeatherCategoryCount>> weights;
};

/// The mix of a preset that holds state `name` fully ("none" or "": the
/// keyed values); false for an unknown name (mix then empty).
bool settledWeather(const Preset& preset, std::string_view name, WeatherMix& mix);

/// The mix `fraction` (0..1) of the way through a transition from state
/// `from` to state `to` (each a name or "none"), each category at its own
/// speed; false for an unknown name.
bool transitionWeather(const Preset& preset, std::string_view from, std::string_view to, double fraction,
                       WeatherMix& mix);

/// One call of Weather::change.
struct WeatherChange {
    std::string state;               ///< a state's name, or "none"
    double startSeconds = 0.0;       ///< the game clock when it was called
    double durationSeconds = 0.0;    ///< 0: at once
};

class Weather {
public:
    /// The weather of `preset` holding `initial` ("none": the keyed values;
    /// an unknown name counts as "none", initial() says which). Keeps the
    /// state names only: the preset may go away.
    explicit Weather(const Preset& preset, std::string_view initial = "none");

    /// Starts a change to `state` at the game clock `nowSeconds`, lasting
    /// `durationSeconds` (0: at once). Changes are taken in the order of
    /// their start; one that starts before the last is refused. Returns
    /// false and changes nothing for an unknown state, a non-finite or
    /// negative duration, or a start before the last change's.
    bool change(std::string_view state, double durationSeconds, double nowSeconds);

    /// The mix at the game clock `nowSeconds` (allocates only when `mix`
    /// does not yet have the preset's state count).
    void mix(double nowSeconds, WeatherMix& mix) const;

    /// Whether a change is still under way at `nowSeconds`.
    bool transitioning(double nowSeconds) const;
    /// The state the weather is going to (the last change's, else initial()).
    const std::string& target() const;

    /// What rebuilds this weather exactly: Weather(preset, initial()) and
    /// change() with each of changes() in order. Changes that had ended
    /// before a later one started are folded into initial() as they end.
    const std::string& initial() const { return initial_; }
    const std::vector<WeatherChange>& changes() const { return changes_; }

private:
    int indexOf(std::string_view name) const;
    void foldFinished(double nowSeconds);

    std::vector<std::string> names_;
    std::string initial_;
    std::vector<WeatherChange> changes_;
};

/// Signed depth [m] of a world point inside a region: > 0 inside, 0 on the
/// surface, < 0 outside; the exact distance to the surface, measured in the
/// region's object frame (position, rotation; half extents h, metres):
///   box:       inside min_i (h_i - |p_i|), outside minus the distance to the box;
///   ellipsoid: the distance to the closest surface point (Eberly 2013, the
///              root of a monotone function found by bisection, to ~1e-9
///              of the smallest half extent).
/// An invalid region (a half extent not in [1e-6, 1e30], a non-finite
/// position or rotation, a zero rotation) or a non-finite point gives -inf.
double weatherRegionDepth(const WeatherRegion& region, const glm::dvec3& point);

/// The region's weight at a world point, in [0, 1]: s(clamp(depth / blend,
/// 0, 1)), s(x) = x^2 (3 - 2 x) the smoothstep, depth weatherRegionDepth.
/// 0 on the surface and outside, 1 from `blend` metres inside on, continuous
/// (the depth is a distance, so the weight moves at most 1.5 / blend per
/// metre the point moves). A blend of 0 (or not finite, or negative): 1
/// inside and on the surface, 0 outside. Cheap where the answer is plain:
/// outside, or (ellipsoid) deeper than the blend by a lower bound, no root
/// is sought.
double weatherRegionWeight(const WeatherRegion& region, const glm::dvec3& point);

/// The weather at `camera` [m, world]: `global` (a mix of this preset's
/// states, e.g. Weather::mix or settledWeather; empty = the keyed values)
/// with the preset's weather regions applied in priority order (lower
/// first; equal priorities in file order), each pulling every category
/// towards its state by its weight r at the camera:
///   out = (1 - r) under + r settled(region.state).
/// A region with weight 0 (the camera outside it) changes nothing: outside
/// every region `out` equals `global` bit for bit. A region whose state the
/// preset does not have is skipped. When a region applied and left every
/// weight 0 (a "none" region), `out` is empty (the keyed values). `out` may
/// be `global` itself; reusing `out` makes it allocation-free once it has
/// held the preset's state count. Deterministic: the same inputs give the
/// same bits.
void regionalWeather(const Preset& preset, const glm::dvec3& camera, const WeatherMix& global, WeatherMix& out);

/// The blend of two whole presets' states for a game that moves between
/// regions: t = 0 is `a`, 1 is `b`, clamped. Every animatable global
/// parameter (param_table.hpp) blends linearly (enums, integers and
/// strings, like the clouds' seed, come from `a` while t < 1, from `b` at
/// 1), the lights' states linearly; the fog volumes and emitters of both
/// are kept, each faded by its side's weight (a's density and intensity
/// times 1 - t, b's times t), as are the cloud volumes (their coverage
/// pulled towards the blended layer's by the other side's weight). `out`
/// is reused (allocates only while it grows).
void blendPresetStates(const PresetState& a, const PresetState& b, double t, PresetState& out);

}  // namespace aerial
