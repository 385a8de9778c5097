// aerial/weather_state.hpp — a preset's named weather states: overrides of
// its parameters layered on the time-of-day keys (the runtime that blends
// them is aerial/weather.hpp).
//
// In a preset file (version 5):
//   "weather": {"states": [
//     {"name": "storm", "overrides": [
//       {"param": "clouds.coverage", "set": 0.95},
//       {"param": "fog.density_per_m", "scale": 3},
//       {"param": "exposure.compensation_ev", "add": -0.5},
//       {"emitter": "bolt_north", "param": "flash_rate_per_min", "set": 8}]}]}
// An override names its target as a track does ("param", plus "volume",
// "emitter" or "cloud_volume" and the object's id) and one of
//   set:   the value replaces the keyed one (a number, or [r, g, b] / [x, y,
//          z] / [x, z] as the parameter has components),
//   add:   added to the keyed value,
//   scale: multiplies the keyed value (per component).
// Only animatable parameters (those a track may key) can be overridden: a
// seed, a type of fog or an id never changes with the weather, so the cloud
// noise keeps its seed and phase through any change of weather.
#pragma once

#include <aerial/timeline.hpp>

#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace aerial {

enum class WeatherOverrideMode {
    Set,    ///< the value replaces the keyed value
    Add,    ///< the value is added to the keyed value
    Scale,  ///< the keyed value is multiplied by the value (per component)
};

/// One parameter of one weather state.
struct WeatherOverride {
    TrackTarget target;
    WeatherOverrideMode mode = WeatherOverrideMode::Set;
    /// components() numbers of the parameter: x; or x, y, z; a Vec2's [x, z]
    /// as x, y (as TrackKey::value).
    glm::dvec3 value{0.0};
};

/// A named weather: the overrides that hold while it does.
struct WeatherState {
    /// 1..64 of A-Z a-z 0-9 _ - . (as object ids), unique in the preset; "none" is taken
    /// (the keyed values alone).
    std::string name;
    std::vector<WeatherOverride> overrides;
};

}  // namespace aerial
