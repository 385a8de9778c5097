// aerial/weather_state.hpp — a preset's named weather states: overrides of
// its parameters layered on the time-of-day keys, and the regions of the
// world in which one of them holds (the runtime that blends them is
// aerial/weather.hpp).
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
//
// Regions (optional, beside "states"): a box or an ellipsoid of the world in
// which a state holds whatever the global weather, its edge blended over
// blend_m inwards from the surface — a storm over the ridge, a clear valley:
//   "regions": [
//     {"id": "ridge_storm", "name": "Storm over the ridge", "shape": "ellipsoid",
//      "position_m": [2500, 600, -4000], "rotation_xyzw": [0, 0, 0, 1],
//      "half_extents_m": [1500, 1200, 2500], "blend_m": 800, "priority": 0,
//      "state": "storm"}]
// Placed as fog volumes are (aerial/fog_volume.hpp): world = position +
// rotation * (half_extents * object), object the unit cube [-1,1]^3 or the
// unit sphere; metres, +Y up, -Z north, +X east. "state" is one of the
// preset's states or "none" (the keyed values: a clear valley in a stormy
// preset). Higher priorities are applied over lower ones; equal priorities
// in file order, the later over the earlier. regionalWeather (weather.hpp)
// gives the weather at a camera.
#pragma once

#include <aerial/timeline.hpp>

#include <glm/gtc/quaternion.hpp>
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

/// The valid ranges of a region's fields (validatePreset and the schema
/// enforce them): position components in [-kWeatherRegionMaxCoordinate,
/// kWeatherRegionMaxCoordinate] m, half extents in
/// [kWeatherRegionMinHalfExtent, kWeatherRegionMaxHalfExtent] m, blend in
/// [0, kWeatherRegionMaxBlend] m, priority in [-kWeatherRegionMaxPriority,
/// kWeatherRegionMaxPriority].
inline constexpr double kWeatherRegionMaxCoordinate = 1e7;
inline constexpr double kWeatherRegionMinHalfExtent = 1.0;
inline constexpr double kWeatherRegionMaxHalfExtent = 1e7;
inline constexpr double kWeatherRegionMaxBlend = 1e7;
inline constexpr int kWeatherRegionMaxPriority = 1000;

enum class WeatherRegionShape {
    Box,        ///< the unit cube [-1,1]^3 in object space
    Ellipsoid,  ///< the unit sphere in object space
};

/// A part of the world where another weather state holds
/// (weatherRegionWeight in weather.hpp gives how much at a point).
struct WeatherRegion {
    /// Stable identifier, as object ids (1..64 of A-Z a-z 0-9 _ - .), unique
    /// among the regions.
    std::string id;
    /// Name shown to the artist.
    std::string name;
    WeatherRegionShape shape = WeatherRegionShape::Box;
    /// Centre [m], world space, each component in [-1e7, 1e7]. Default 0.
    glm::dvec3 position{0.0};
    /// Orientation, world from object (unit quaternion, w first in glm).
    glm::dquat rotation{1.0, 0.0, 0.0, 0.0};
    /// Half extents along the object axes [m], each in [1, 1e7]. Default 1000.
    glm::dvec3 halfExtents{1000.0, 1000.0, 1000.0};
    /// Width of the soft edge [m], measured inwards from the surface, in
    /// [0, 1e7]: the state holds fully from this depth inside on. 0: a hard
    /// edge. Wider than the smallest half extent: nowhere at full weight.
    /// Default 200.
    double blend = 200.0;
    /// Order of application, an integer in [-1000, 1000]: higher over lower,
    /// equal ones in file order (the later over the earlier). Default 0.
    int priority = 0;
    /// The state that holds inside: a WeatherState's name, or "none" (the
    /// keyed values alone).
    std::string state = "none";
};

}  // namespace aerial
