// preset_validate.cpp — validatePreset: checks a Preset against the
// parameter table and the caps of aerial/limits.hpp (ranges, finite numbers,
// unit vectors and quaternions, ids, counts, string lengths, tracks). The
// loader runs exactly these checks on what it read; savePreset runs them
// before writing.
#include "preset_validate.hpp"

#include "json_text.hpp"

#include <aerial/clock.hpp>
#include <aerial/limits.hpp>
#include <aerial/preset.hpp>
#include <aerial/sun.hpp>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <exception>
#include <optional>
#include <string>
#include <vector>

namespace aerial {

using namespace detail;
using sv = std::string_view;

bool detail::validId(sv id) {
    if (id.empty() || id.size() > 64) return false;
    for (char c : id) {
        const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                        c == '_' || c == '-' || c == '.';
        if (!ok) return false;
    }
    return true;
}

sv detail::trackObjectKey(ParamScope scope) { return scopeKey(scope); }

std::string detail::rangeText(const ParamDesc& p) {
    return formatDouble(p.minValue) + ".." + formatDouble(p.maxValue);
}

namespace {

/// A key's time in an issue: "19.5", or "19.8333 (sunset + 00:20)" for an
/// anchored key.
std::string describeKeyTime(const TrackKey& key) {
    std::string text = formatDouble(key.timeHours);
    if (key.anchor) {
        text += std::string(" (") + sunEventName(*key.anchor) + (key.offsetHours < 0.0 ? " - " : " + ") +
                formatClock(std::abs(key.offsetHours)) + ")";
    }
    return text;
}

struct Issues {
    std::vector<PresetIssue> list;
    void error(std::string pointer, std::string message) {
        PresetIssue i;
        i.severity = PresetIssue::Severity::Error;
        i.pointer = std::move(pointer);
        i.message = std::move(message);
        list.push_back(std::move(i));
    }
};

/// A key's own tangents (TrackKey::tangents): finite slopes within
/// limits::kMaxKeyTangent, equal ones for unified handles, and no "flat".
void checkKeyTangents(const TrackKey& key, const ParamDesc* p, const std::string& keyAt, Issues& issues) {
    const KeyTangents& tangents = *key.tangents;
    const int count = p ? p->components() : 3;
    bool valid = true;
    const std::pair<const glm::dvec3*, const char*> slopes[2] = {{&tangents.in, "tangent_in"},
                                                                 {&tangents.out, "tangent_out"}};
    for (const auto& [slope, name] : slopes) {
        for (int c = 0; c < count; ++c) {
            const double v = (*slope)[c];
            if (std::isfinite(v) && std::abs(v) <= limits::kMaxKeyTangent) continue;
            const std::string at =
                count == 1 ? pointerJoin(keyAt, name) : pointerJoin(pointerJoin(keyAt, name), std::size_t(c));
            issues.error(at, "a tangent must be a finite slope of at most " +
                                 formatDouble(limits::kMaxKeyTangent) + " per hour (got " + formatDouble(v) +
                                 ")");
            valid = false;
        }
    }
    if (int(tangents.mode) < 0 || int(tangents.mode) > 1)
        issues.error(pointerJoin(keyAt, "tangent_mode"), "unknown tangent mode");
    if (valid && tangents.mode == TangentMode::Unified) {
        for (int c = 0; c < count; ++c) {
            if (tangents.in[c] == tangents.out[c]) continue;
            issues.error(pointerJoin(keyAt, "tangent_out"),
                         "unified tangents have one slope: tangent_in " + formatDouble(tangents.in[c]) +
                             " and tangent_out " + formatDouble(tangents.out[c]) +
                             " differ (\"tangent_mode\": \"broken\" for two)");
            break;
        }
    }
    if (key.flat)
        issues.error(pointerJoin(keyAt, "flat"),
                     "a key is either flat (tangent 0) or has its own tangents, not both");
}

void checkNumber(const ParamDesc& p, double v, const std::string& pointer, Issues& issues) {
    if (!std::isfinite(v)) {
        issues.error(pointer, "must be a finite number (got " + formatDouble(v) + ")");
    } else if (v < p.minValue || v > p.maxValue) {
        // Appended piece by piece: GCC 12 warns (-Wrestrict) on " " + unit.
        std::string m = "out of range: ";
        m += formatDouble(v);
        m += " is not in ";
        m += rangeText(p);
        if (!p.unit.empty()) {
            m += ' ';
            m += p.unit;
        }
        issues.error(pointer, std::move(m));
    }
}

void checkText(const std::string& s, const std::string& pointer, Issues& issues) {
    if (s.size() > limits::kMaxStringBytes) {
        std::string m = "is ";
        m += std::to_string(s.size());
        m += " bytes long, over the limit of ";
        m += std::to_string(limits::kMaxStringBytes);
        issues.error(pointer, std::move(m));
    } else if (!validUtf8(s)) {
        issues.error(pointer, "must be valid UTF-8");
    }
}

void checkCount(std::size_t count, std::size_t limit, const char* pointer, const char* what, Issues& issues) {
    if (count <= limit) return;
    std::string m = std::to_string(count);
    m += " ";
    m += what;
    m += ", over the limit of ";
    m += std::to_string(limit);
    issues.error(pointer, std::move(m));
}

void checkParam(const ParamDesc& p, void* object, const std::string& pointer, Issues& issues) {
    switch (p.type) {
        case ParamType::Scalar:
            checkNumber(p, *p.scalar(object), pointer, issues);
            break;
        case ParamType::Colour:
        case ParamType::Vec3: {
            const glm::dvec3 v = *p.vec3(object);
            for (int c = 0; c < 3; ++c) checkNumber(p, v[c], pointerJoin(pointer, std::size_t(c)), issues);
            if (p.unitLength && std::isfinite(v.x + v.y + v.z)) {
                const double len = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
                if (!(std::abs(len - 1.0) <= 1e-6))
                    issues.error(pointer, "must be a unit vector (length " + formatDouble(len) + ")");
            }
            break;
        }
        case ParamType::Vec2: {
            const glm::dvec2 v = *p.vec2(object);
            for (int c = 0; c < 2; ++c) checkNumber(p, v[c], pointerJoin(pointer, std::size_t(c)), issues);
            break;
        }
        case ParamType::Quaternion: {
            const glm::dquat q = *p.quat(object);
            const double c[4] = {q.x, q.y, q.z, q.w};
            bool finite = true;
            for (int i = 0; i < 4; ++i) {
                if (!std::isfinite(c[i])) {
                    issues.error(pointerJoin(pointer, std::size_t(i)),
                                 "must be a finite number (got " + formatDouble(c[i]) + ")");
                    finite = false;
                }
            }
            if (finite) {
                const double len = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2] + c[3] * c[3]);
                if (!(std::abs(len - 1.0) <= 1e-6))
                    issues.error(pointer, "must be a unit quaternion (length " + formatDouble(len) + ")");
            }
            break;
        }
        case ParamType::Enum:
        case ParamType::Int: {
            const std::int64_t v = p.getInt(object);
            if (double(v) < p.minValue || double(v) > p.maxValue)
                issues.error(pointer, "out of range: " + std::to_string(v) + " is not in " + rangeText(p));
            break;
        }
        case ParamType::String: {
            const std::string& s = *p.string(object);
            if (p.path == "id") {
                if (!validId(s))
                    issues.error(pointer, "an id must be 1..64 characters of A-Z a-z 0-9 _ - . (got " +
                                              quoteString(validUtf8(s) ? s : std::string("?")) + ")");
            } else if (p.path == "location.date") {
                CalendarDate date;
                if (!s.empty() && !parseCalendarDate(s, date))
                    issues.error(pointer,
                                 "location.date must be a calendar date \"YYYY-MM-DD\" from 1800-01-01 "
                                 "to 2200-12-31, or \"\" for none (got " +
                                     quoteString(validUtf8(s) ? s : std::string("?")) + ")");
            } else {
                checkText(s, pointer, issues);
            }
            break;
        }
    }
}

template <class Object>
void checkObjects(std::vector<Object>& objects, ParamScope scope, const char* arrayKey, Issues& issues) {
    const std::string base = std::string("/") + arrayKey;
    for (std::size_t i = 0; i < objects.size(); ++i) {
        const std::string at = pointerJoin(base, i);
        for (const ParamDesc& p : paramTable(scope))
            checkParam(p, &objects[i], pointerJoin(at, p.path), issues);
        for (std::size_t j = 0; j < i; ++j) {
            if (objects[j].id == objects[i].id && !objects[i].id.empty()) {
                issues.error(pointerJoin(at, "id"), "duplicate id " + quoteString(objects[i].id) + " (also " +
                                                        pointerJoin(base, j) + ")");
                break;
            }
        }
    }
}

std::string globalPointer(sv path) {
    std::string out;
    std::size_t start = 0;
    while (true) {
        const std::size_t dot = path.find('.', start);
        out += "/";
        out += path.substr(start, dot == sv::npos ? sv::npos : dot - start);
        if (dot == sv::npos) break;
        start = dot + 1;
    }
    return out;
}

/// A track's or a weather override's target: a known, animatable parameter
/// of an object that exists.
void checkTarget(const Preset& preset, const TrackTarget& target, const std::string& at, const char* what,
                 Issues& issues) {
    const ParamDesc* p = findParam(target.scope, target.param);
    const sv objectKey = trackObjectKey(target.scope);
    if (!p) {
        issues.error(pointerJoin(at, "param"), "unknown " + std::string(scopeName(target.scope)) +
                                                   " parameter " + quoteString(target.param));
    } else if (!p->animatable) {
        issues.error(pointerJoin(at, "param"),
                     "parameter " + quoteString(target.param) +
                         (std::string(what) == "override"
                              ? " does not change with the weather (only a parameter a track may key does)"
                              : " cannot be animated"));
    }
    if (target.scope == ParamScope::Volume) {
        const bool found = std::any_of(preset.volumes.begin(), preset.volumes.end(),
                                       [&](const FogVolume& v) { return v.id == target.objectId; });
        if (!found)
            issues.error(pointerJoin(at, objectKey), "no volume with id " + quoteString(target.objectId));
    } else if (target.scope == ParamScope::Emitter) {
        const bool found = std::any_of(preset.emitters.begin(), preset.emitters.end(),
                                       [&](const Emitter& e) { return e.id == target.objectId; });
        if (!found)
            issues.error(pointerJoin(at, objectKey), "no emitter with id " + quoteString(target.objectId));
    } else if (target.scope == ParamScope::CloudVolume) {
        const bool found = std::any_of(preset.cloudVolumes.begin(), preset.cloudVolumes.end(),
                                       [&](const CloudVolume& v) { return v.id == target.objectId; });
        if (!found)
            issues.error(pointerJoin(at, objectKey),
                         "no cloud volume with id " + quoteString(target.objectId));
    } else if (!target.objectId.empty()) {
        issues.error(at, "a global parameter's " + std::string(what) + " has no object id");
    }
}

void checkWeather(const Preset& preset, Issues& issues) {
    checkCount(preset.weather.size(), limits::kMaxWeatherStates, "/weather/states", "weather states", issues);
    for (std::size_t i = 0; i < preset.weather.size(); ++i) {
        const WeatherState& state = preset.weather[i];
        const std::string at = pointerJoin("/weather/states", i);
        const bool nameOk = detail::validId(state.name);  // named as objects are
        if (!nameOk)
            issues.error(pointerJoin(at, "name"),
                         "a weather state's name is 1 to " + std::to_string(limits::kMaxIdBytes) +
                             " of A-Z a-z 0-9 _ - . (got " + quoteString(state.name) + ")");
        else if (state.name == "none")
            issues.error(pointerJoin(at, "name"),
                         "\"none\" is taken: it names the keyed values without weather");
        for (std::size_t j = 0; j < i; ++j)
            if (preset.weather[j].name == state.name && nameOk) {
                issues.error(pointerJoin(at, "name"), "a second weather state named " +
                                                          quoteString(state.name) + " (also " +
                                                          pointerJoin("/weather/states", j) + ")");
                break;
            }
        const std::string overridesAt = pointerJoin(at, "overrides");
        checkCount(state.overrides.size(), limits::kMaxWeatherOverrides, overridesAt.c_str(), "overrides",
                   issues);
        for (std::size_t k = 0; k < state.overrides.size(); ++k) {
            const WeatherOverride& o = state.overrides[k];
            const std::string oAt = pointerJoin(overridesAt, k);
            checkTarget(preset, o.target, oAt, "override", issues);
            for (std::size_t j = 0; j < k; ++j)
                if (state.overrides[j].target == o.target) {
                    issues.error(pointerJoin(oAt, "param"),
                                 "a second override of the same target in this state (also " +
                                     pointerJoin(overridesAt, j) + ")");
                    break;
                }
            const ParamDesc* p = findParam(o.target.scope, o.target.param);
            if (!p || !p->animatable) continue;
            const char* key = o.mode == WeatherOverrideMode::Add     ? "add"
                              : o.mode == WeatherOverrideMode::Scale ? "scale"
                                                                     : "set";
            const std::string valueAt = pointerJoin(oAt, key);
            const int count = p->type == ParamType::Scalar ? 1 : p->components();
            for (int c = 0; c < count; ++c) {
                const double v = o.value[c];
                const std::string vAt = count == 1 ? valueAt : pointerJoin(valueAt, std::size_t(c));
                if (o.mode == WeatherOverrideMode::Set)
                    checkNumber(*p, v, vAt, issues);
                else if (!std::isfinite(v))
                    issues.error(vAt, "must be a finite number (got " + formatDouble(v) + ")");
                else if (o.mode == WeatherOverrideMode::Scale && v < 0.0)
                    issues.error(vAt, "a scale must be >= 0 (got " + formatDouble(v) + ")");
            }
        }
    }
}

/// A region's or a view's number: finite and in [lo, hi] (metres in the message).
void checkRegionNumber(double v, double lo, double hi, const std::string& pointer, Issues& issues) {
    if (!std::isfinite(v)) {
        issues.error(pointer, "must be a finite number (got " + formatDouble(v) + ")");
    } else if (v < lo || v > hi) {
        std::string m = "out of range: ";
        m += formatDouble(v);
        m += " is not in ";
        m += formatDouble(lo);
        m += "..";
        m += formatDouble(hi);
        m += " m";
        issues.error(pointer, std::move(m));
    }
}

void checkWeatherRegions(const Preset& preset, Issues& issues) {
    checkCount(preset.weatherRegions.size(), limits::kMaxWeatherRegions, "/weather/regions",
               "weather regions", issues);
    for (std::size_t i = 0; i < preset.weatherRegions.size(); ++i) {
        const WeatherRegion& r = preset.weatherRegions[i];
        const std::string at = pointerJoin("/weather/regions", i);
        if (!validId(r.id)) {
            issues.error(pointerJoin(at, "id"), "an id must be 1..64 characters of A-Z a-z 0-9 _ - . (got " +
                                                    quoteString(validUtf8(r.id) ? r.id : std::string("?")) +
                                                    ")");
        } else {
            for (std::size_t j = 0; j < i; ++j)
                if (preset.weatherRegions[j].id == r.id) {
                    issues.error(pointerJoin(at, "id"), "duplicate id " + quoteString(r.id) + " (also " +
                                                            pointerJoin("/weather/regions", j) + ")");
                    break;
                }
        }
        checkText(r.name, pointerJoin(at, "name"), issues);
        if (r.shape != WeatherRegionShape::Box && r.shape != WeatherRegionShape::Ellipsoid)
            issues.error(pointerJoin(at, "shape"), "unknown shape; expected one of box, ellipsoid");
        for (int c = 0; c < 3; ++c) {
            checkRegionNumber(r.position[c], -kWeatherRegionMaxCoordinate, kWeatherRegionMaxCoordinate,
                              pointerJoin(pointerJoin(at, "position_m"), std::size_t(c)), issues);
            checkRegionNumber(r.halfExtents[c], kWeatherRegionMinHalfExtent, kWeatherRegionMaxHalfExtent,
                              pointerJoin(pointerJoin(at, "half_extents_m"), std::size_t(c)), issues);
        }
        const glm::dquat q = r.rotation;
        const double qc[4] = {q.x, q.y, q.z, q.w};
        bool finite = true;
        for (int c = 0; c < 4; ++c)
            if (!std::isfinite(qc[c])) {
                issues.error(pointerJoin(pointerJoin(at, "rotation_xyzw"), std::size_t(c)),
                             "must be a finite number (got " + formatDouble(qc[c]) + ")");
                finite = false;
            }
        if (finite) {
            const double len = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
            if (!(std::abs(len - 1.0) <= 1e-6))
                issues.error(pointerJoin(at, "rotation_xyzw"),
                             "must be a unit quaternion (length " + formatDouble(len) + ")");
        }
        checkRegionNumber(r.blend, 0.0, kWeatherRegionMaxBlend, pointerJoin(at, "blend_m"), issues);
        if (std::abs(r.priority) > kWeatherRegionMaxPriority)
            issues.error(pointerJoin(at, "priority"), "out of range: " + std::to_string(r.priority) +
                                                          " is not in " +
                                                          std::to_string(-kWeatherRegionMaxPriority) + ".." +
                                                          std::to_string(kWeatherRegionMaxPriority));
        const bool known =
            r.state == "none" || std::any_of(preset.weather.begin(), preset.weather.end(),
                                             [&](const WeatherState& s) { return s.name == r.state; });
        if (!known) {
            std::string names = "none";
            for (const WeatherState& s : preset.weather) names += ", " + s.name;
            issues.error(pointerJoin(at, "state"),
                         "no weather state " + quoteString(validUtf8(r.state) ? r.state : std::string("?")) +
                             " (the preset has " + names + ")");
        }
    }
}

/// "view": finite coordinates and a field of view in range, the target
/// apart from the eye (PresetView).
void checkView(const std::optional<PresetView>& view, Issues& issues) {
    if (!view) return;
    const PresetView& v = *view;
    for (int c = 0; c < 3; ++c) {
        checkRegionNumber(v.eye[c], -kViewMaxCoordinate, kViewMaxCoordinate,
                          pointerJoin("/view/eye_m", std::size_t(c)), issues);
        checkRegionNumber(v.target[c], -kViewMaxCoordinate, kViewMaxCoordinate,
                          pointerJoin("/view/target_m", std::size_t(c)), issues);
    }
    const double fov = v.verticalFovDeg;
    if (!std::isfinite(fov))
        issues.error("/view/fov_deg", "must be a finite number (got " + formatDouble(fov) + ")");
    else if (fov < kViewMinFovDeg || fov > kViewMaxFovDeg)
        issues.error("/view/fov_deg", "out of range: " + formatDouble(fov) + " is not in " +
                                          formatDouble(kViewMinFovDeg) + ".." + formatDouble(kViewMaxFovDeg) +
                                          " deg");
    const double distance = glm::length(v.target - v.eye);
    if (std::isfinite(distance) && distance < kViewMinDistance)
        issues.error("/view/target_m", "the target is " + formatDouble(distance) +
                                           " m from the eye; a view needs a direction (at least " +
                                           formatDouble(kViewMinDistance) + " m apart)");
}

void validateInto(const Preset& constPreset, Issues& issues) {
    // The accessors take non-const objects; validation only reads.
    Preset& preset = const_cast<Preset&>(constPreset);
    checkText(preset.name, "/name", issues);
    checkText(preset.description, "/description", issues);
    checkCount(preset.volumes.size(), limits::kMaxVolumes, "/volumes", "volumes", issues);
    checkCount(preset.emitters.size(), limits::kMaxEmitters, "/emitters", "emitters", issues);
    checkCount(preset.cloudVolumes.size(), limits::kMaxCloudVolumes, "/cloud_volumes", "cloud volumes",
               issues);
    checkCount(preset.tracks.size(), limits::kMaxTracks, "/tracks", "tracks", issues);
    for (const ParamDesc& p : paramTable(ParamScope::Global))
        checkParam(p, &preset.environment, globalPointer(p.path), issues);
    const AtmosphereParams& air = preset.environment.atmosphere;
    for (int c = 0; c < 3; ++c) {
        if (air.mieExtinction[c] < air.mieScattering[c])
            issues.error("/atmosphere/mie/extinction_per_m/" + std::to_string(c),
                         "Mie extinction " + formatDouble(air.mieExtinction[c]) +
                             " must be >= Mie scattering " + formatDouble(air.mieScattering[c]));
    }
    const ExposureParams& exposure = preset.environment.exposure;
    if (exposure.minEv100 > exposure.maxEv100)
        issues.error("/exposure/min_ev100", "minimum EV100 " + formatDouble(exposure.minEv100) +
                                                " must be <= maximum EV100 " +
                                                formatDouble(exposure.maxEv100));
    checkObjects(preset.volumes, ParamScope::Volume, "volumes", issues);
    for (std::size_t i = 0; i < preset.volumes.size(); ++i) {
        if (preset.volumes[i].shape == FogVolumeShape::Mesh && preset.volumes[i].mesh.empty())
            issues.error(pointerJoin("/volumes", i) + "/mesh",
                         "a mesh volume needs \"mesh\": the glTF file of its closed mesh");
    }
    checkObjects(preset.emitters, ParamScope::Emitter, "emitters", issues);
    checkObjects(preset.cloudVolumes, ParamScope::CloudVolume, "cloud_volumes", issues);

    for (std::size_t i = 0; i < preset.tracks.size(); ++i) {
        const Track& track = preset.tracks[i];
        const std::string at = pointerJoin("/tracks", i);
        const TrackTarget& target = track.target;
        const ParamDesc* p = findParam(target.scope, target.param);
        checkTarget(preset, target, at, "track", issues);
        for (std::size_t j = 0; j < i; ++j) {
            if (preset.tracks[j].target == target) {
                issues.error(pointerJoin(at, "param"),
                             "a second track for the same target (also " + pointerJoin("/tracks", j) + ")");
                break;
            }
        }
        if (int(track.interpolation) < 0 || int(track.interpolation) > 2)
            issues.error(pointerJoin(at, "interpolation"), "unknown interpolation");
        const std::string keysAt = pointerJoin(at, "keys");
        if (track.keys.empty()) issues.error(keysAt, "a track needs at least one key");
        checkCount(track.keys.size(), limits::kMaxKeysPerTrack, keysAt.c_str(), "keys", issues);
        for (std::size_t k = 0; k < track.keys.size(); ++k) {
            const TrackKey& key = track.keys[k];
            const std::string keyAt = pointerJoin(keysAt, k);
            const double t = key.timeHours;
            // An anchored key's time comes from its event: its issues name
            // the anchor (the file has no time_h there).
            const std::string timeAt = pointerJoin(keyAt, key.anchor ? "anchor" : "time_h");
            if (key.anchor && (!std::isfinite(key.offsetHours) || std::abs(key.offsetHours) > 12.0)) {
                issues.error(pointerJoin(keyAt, "offset_h"),
                             "an offset from a sun event must be in [-12, 12] h (got " +
                                 formatDouble(key.offsetHours) + ")");
            } else if (!std::isfinite(t) || t < 0.0 || t >= 24.0) {
                issues.error(timeAt, "a key's time must be in [0, 24) h (got " + formatDouble(t) + ")");
            } else if (k > 0 && !(t > track.keys[k - 1].timeHours)) {
                issues.error(timeAt, "key times must increase strictly (" + describeKeyTime(key) + " after " +
                                         describeKeyTime(track.keys[k - 1]) + ")");
            }
            if (key.interpolation && (int(*key.interpolation) < 0 || int(*key.interpolation) > 2))
                issues.error(pointerJoin(keyAt, "interpolation"), "unknown interpolation");
            if (key.tangents) checkKeyTangents(key, p, keyAt, issues);
            if (!p || !p->animatable) continue;
            const std::string valueAt = pointerJoin(keyAt, "value");
            if (p->type == ParamType::Scalar) {
                checkNumber(*p, key.value.x, valueAt, issues);
            } else {
                // Vec2 keys carry [x, z] in value.x, .y (.z unused).
                for (int c = 0; c < p->components(); ++c)
                    checkNumber(*p, key.value[c], pointerJoin(valueAt, std::size_t(c)), issues);
            }
        }
    }
    checkWeather(preset, issues);
    checkWeatherRegions(preset, issues);
    checkView(preset.view, issues);
}

}  // namespace

std::vector<PresetIssue> validatePreset(const Preset& preset) {
    Issues issues;
    try {
        validateInto(preset, issues);
    } catch (const std::exception& e) {
        issues.error("", std::string("validation failed: ") + e.what());
    }
    return std::move(issues.list);
}

}  // namespace aerial
