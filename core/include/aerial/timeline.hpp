// aerial/timeline.hpp — keyframe tracks over the 24-hour day.
//
// Usage:
//   aerial::Track t;
//   t.target = aerial::TrackTarget::volume("valley_fog", "density_per_m");
//   t.interpolation = aerial::Interpolation::Smooth;
//   t.keys = {{5.0, glm::dvec3(0.0)}, {7.0, glm::dvec3(0.03)}, {12.0, glm::dvec3(0.0)}};
//   aerial::CompiledTrack c = aerial::compileTrack(t, 1);   // tangents, once
//   double d = aerial::evaluateTrack(c, 6.5).x;
//
// Model (../shared/DESIGN.md, "Timeline"):
//   * Time t is local solar time [h], 0 <= t < 24, and the day wraps: the
//     segment after the last key runs to the first key + 24 h, so a key at
//     22:00 and one at 02:00 interpolate through midnight. A track with one
//     key is constant.
//   * Step: the value of the last key at or before t (wrapping).
//     A key may set its own interpolation for the segment after it
//     (TrackKey::interpolation); the others follow the track's.
//   * Linear: per component, along the (wrapping) segment.
//   * Smooth: periodic monotone cubic Hermite per component, tangents by
//     Fritsch & Carlson (1980): secants d_k, initial tangents their mean,
//     0 where the secants change sign or vanish, then (alpha, beta) =
//     (m_k, m_k+1) / d_k scaled onto the circle of radius 3 where they leave
//     it. Each segment is then monotone, so the curve never leaves the range
//     of its two keys (a density keyed 0 -> 0.01 -> 0 never goes negative);
//     evaluation also clamps to that range against rounding. A key marked
//     flat (TrackKey::flat, "flat": true in a preset) has tangent 0 in every
//     component whatever its neighbours: the curve levels out there (an
//     ease in and out), and stays monotone, since step 4 only shrinks.
//   * Tangent handles: a key may carry its own slopes (TrackKey::tangents;
//     "tangent_in", "tangent_out" [unit per h] and "tangent_mode" in a
//     preset). The smooth segment ending at the key uses its in-slope, the
//     one starting there its out-slope, in the same cubic Hermite basis;
//     the other keys' tangents are the automatic ones above, computed as if
//     no key had its own. A segment with a given slope at either end may
//     leave the range of its two keys (the artist's overshoot; a preset's
//     evaluation, evaluate.hpp, still clamps every parameter to its valid
//     range); the others are clamped to it as before.
//   * Colours interpolate per channel in scene-linear RGB; vectors (3 or
//     2 components) per component.
//   * Targets are stable: a global parameter by its path
//     ("fog.density_per_m"), a volume's, emitter's or cloud volume's
//     parameter by the object's id and the parameter key (in a file:
//     "volume", "emitter" or "cloud_volume": id, and "param"), so renaming
//     or reordering objects never breaks a track.
//   * A key can follow the sun (TrackKey::anchor): "sunset + 0:20" is
//     stored as the event and the offset ({"anchor": "sunset", "offset_h":
//     0.333, "value": ...} in a preset), and its time is derived from the
//     preset's location and date (sunEventHours, sun.hpp) whenever the
//     preset is loaded or compiled (resolveKeyAnchors, preset.hpp). Change
//     the date or the place and the key moves with the sun; the curve
//     itself is evaluated from the resolved times like any other.
#pragma once

#include <aerial/sun.hpp>

#include <glm/vec3.hpp>

#include <optional>
#include <string>
#include <vector>

namespace aerial {

/// Which struct a parameter lives in.
enum class ParamScope {
    Global,       ///< Environment (location, atmosphere, sun, moon, fog)
    Volume,       ///< FogVolume
    Emitter,      ///< Emitter
    CloudVolume,  ///< CloudVolume (clouds.hpp)
};

enum class Interpolation { Step, Linear, Smooth };

/// How a key's two tangent handles move together in the editor: unified
/// (one slope through the key, in == out) or broken (two independent
/// slopes, a corner).
enum class TangentMode { Unified, Broken };

/// A key's own slopes, per component [value unit per h]: `in` is the slope
/// of the segment arriving at the key, `out` of the one leaving it. Scalars
/// use .x only, 2-vectors .x and .y, as TrackKey::value does. Unified
/// tangents have in == out (validatePreset checks it).
struct KeyTangents {
    glm::dvec3 in{0.0};
    glm::dvec3 out{0.0};
    TangentMode mode = TangentMode::Unified;
    bool operator==(const KeyTangents&) const = default;
};

/// What a track animates.
struct TrackTarget {
    ParamScope scope = ParamScope::Global;
    /// The volume's, emitter's or cloud volume's id; empty for globals.
    std::string objectId;
    /// Global: the parameter path ("fog.density_per_m",
    /// "atmosphere.mie.scattering_per_m"); volume/emitter/cloud volume: the
    /// parameter key ("density_per_m").
    std::string param;

    static TrackTarget global(std::string path) { return {ParamScope::Global, {}, std::move(path)}; }
    static TrackTarget volume(std::string id, std::string key) {
        return {ParamScope::Volume, std::move(id), std::move(key)};
    }
    static TrackTarget emitter(std::string id, std::string key) {
        return {ParamScope::Emitter, std::move(id), std::move(key)};
    }
    static TrackTarget cloudVolume(std::string id, std::string key) {
        return {ParamScope::CloudVolume, std::move(id), std::move(key)};
    }
    bool operator==(const TrackTarget&) const = default;
};

struct TrackKey {
    /// Time of day [h], 0 <= t < 24.
    double timeHours = 0.0;
    /// The value in the parameter's unit; scalars use .x only (y, z are 0),
    /// horizontal 2-vectors [x, z] use .x and .y (z is 0).
    glm::dvec3 value{0.0};
    /// Smooth tracks: the curve is level at this key (tangent 0) instead of
    /// following its neighbours. Ignored by step and linear. Default false;
    /// written to a preset only when true ("flat": true).
    bool flat = false;
    /// A key that follows the sun: its time is
    /// anchoredKeyHours(*this, location), the event's time plus
    /// `offsetHours`, and `timeHours` holds that resolved time (set by
    /// resolveKeyAnchors). Empty (default): a fixed time of day.
    std::optional<SunEvent> anchor;
    /// The anchored key's offset from its event [h], -12..12 (negative:
    /// before it). Unused without an anchor.
    double offsetHours = 0.0;
    /// The interpolation of the segment from this key to the next, in place
    /// of the track's ("interpolation" on the key in a preset): a jump at a
    /// lightning strike in a smooth track, a linear ramp in a stepped one.
    /// Empty (default): the track's. Smooth tangents are computed over the
    /// whole track as before, so a smooth segment beside a linear one keeps
    /// its shape.
    std::optional<Interpolation> interpolation;
    /// Smooth segments: the key's own slopes ("tangent_in", "tangent_out",
    /// "tangent_mode" in a preset; written only when set). Empty (default):
    /// automatic tangents (Fritsch-Carlson, or 0 when `flat`). Each slope is
    /// finite, at most limits::kMaxKeyTangent in magnitude. A key has
    /// either `flat` or its own tangents, not both.
    std::optional<KeyTangents> tangents;
};

struct Track {
    TrackTarget target;
    Interpolation interpolation = Interpolation::Smooth;
    /// At least one key; strictly increasing times in [0, 24).
    std::vector<TrackKey> keys;
    /// True (default): the day is cyclic, the curve runs on from the last
    /// key to the first key of the next day. False ("wrap": false in a
    /// preset): before the first key the track holds its value, after the
    /// last key its value (a morning mist keyed 06-10 h stays gone at night).
    bool wrap = true;
};

/// A track ready to evaluate: keys sorted (as validated) plus the smooth
/// tangents, computed once.
struct CompiledTrack {
    Interpolation interpolation = Interpolation::Smooth;
    bool wrap = true;           ///< Track::wrap
    int components = 1;         ///< 1 (scalar), 2 (vec2 in x, y) or 3 (vec3 / colour)
    std::vector<double> times;  ///< [h], strictly increasing in [0, 24)
    std::vector<glm::dvec3> values;
    /// d value / d t leaving each key [unit per h] (when some segment is Smooth).
    std::vector<glm::dvec3> tangents;
    /// d value / d t arriving at each key [unit per h]; equal to `tangents`
    /// except at keys with broken tangent handles.
    std::vector<glm::dvec3> tangentsIn;
    /// Per key: true where the key has its own tangents (TrackKey::tangents);
    /// the segments touching it are not clamped to their keys' range.
    std::vector<bool> givenTangents;
    /// The interpolation of each segment, key k to k + 1 (TrackKey::interpolation or the track's).
    std::vector<Interpolation> segments;
};

/// Prepares a track; keys must be valid (validatePreset checks them). An
/// empty key list gives a track that evaluates to 0. `components` is 1, 2 or
/// 3 (ParamDesc::components() of the target; other values read as 3): the
/// keys' components past it are taken as 0.
CompiledTrack compileTrack(const Track& track, int components);

/// The track's value at time t [h] (wrapped into [0, 24); a non-finite t
/// reads as 0). Unused components are 0.
glm::dvec3 evaluateTrack(const CompiledTrack& track, double timeHours);

/// Convenience: compile and evaluate once (slow path, for tools and tests).
glm::dvec3 evaluateTrack(const Track& track, double timeHours, int components = 3);

/// Editing helper: sets the key at `timeHours` (wrapped into [0, 24)),
/// replacing a key at exactly that time or inserting one in order.
void setKey(Track& track, double timeHours, const glm::dvec3& value);

/// The automatic tangents of a key, as compileTrack computes them when the
/// key has none of its own (d value / d t [unit per h]; 0 for a flat key,
/// and when no segment of the track is smooth). The editor's handles start
/// there.
glm::dvec3 automaticTangent(const Track& track, std::size_t key, int components);

/// t wrapped into [0, 24) [h]; non-finite values give 0.
double wrapHours(double timeHours);

/// The time of day [h], 0 <= t < 24, of an anchored key at `where`:
/// wrapHours(sunEventHours(where, *key.anchor) + key.offsetHours);
/// key.timeHours for a key without an anchor.
double anchoredKeyHours(const TrackKey& key, const Location& where);

/// Editing helper: moves a key to `timeHours`. An anchored key keeps its
/// anchor and its offset changes by the same amount (dragging "sunset +
/// 0:20" by ten minutes gives "sunset + 0:30"), wrapped into -12..12 h.
void setKeyTime(TrackKey& key, double timeHours);

/// Editing helper: anchors a key to `event` where it stands: the offset is
/// the key's time minus the event's at `where` (wrapped into -12..12 h), so
/// the curve does not change until the date or the place does. An empty
/// `event` makes it a fixed key again at its current time.
void anchorKey(TrackKey& key, std::optional<SunEvent> event, const Location& where);

}  // namespace aerial
