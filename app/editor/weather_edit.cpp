// editor/weather_edit.cpp — the Weather panel's model (see weather_edit.hpp).
#include "weather_edit.hpp"

#include "action_args.hpp"
#include "curve_view.hpp"

#include <aerial/param_table.hpp>
#include <aerial/weather.hpp>

#include <glm/common.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

namespace aerial::editor {
namespace {

constexpr std::string_view kWeatherPointer = "/weather";

/// validatePreset's errors at `pointer` or below it.
std::vector<PresetIssue> issuesAt(const Preset& preset, const std::string& pointer) {
    std::vector<PresetIssue> out;
    for (PresetIssue& issue : validatePreset(preset)) {
        if (issue.severity != PresetIssue::Severity::Error) continue;
        const bool at = issue.pointer == pointer ||
                        (issue.pointer.size() > pointer.size() && issue.pointer.starts_with(pointer) &&
                         issue.pointer[pointer.size()] == '/');
        if (at) out.push_back(std::move(issue));
    }
    return out;
}

/// The first error of `after` that `before` did not have (an edit is not
/// blamed for what was wrong already), or "".
std::string newIssue(const std::vector<PresetIssue>& before, const std::vector<PresetIssue>& after) {
    for (const PresetIssue& a : after) {
        const bool old = std::any_of(before.begin(), before.end(), [&](const PresetIssue& b) {
            return b.pointer == a.pointer && b.message == a.message;
        });
        if (!old) return a.message;
    }
    return {};
}

/// Runs `edit` on `preset` and keeps it when validatePreset finds no error
/// in the weather (states and regions) that it did not find before;
/// otherwise restores them and sets `error` to the first new one. (A
/// duplicate name, target or id is reported at the later of the two, so the
/// whole of the weather is compared, not only what was edited.)
template <class Edit>
bool checkedEdit(Preset& preset, std::string& error, Edit&& edit) {
    const std::string at(kWeatherPointer);
    const std::vector<PresetIssue> before = issuesAt(preset, at);
    std::vector<WeatherState> saved = preset.weather;
    std::vector<WeatherRegion> savedRegions = preset.weatherRegions;
    edit(preset);
    const std::string message = newIssue(before, issuesAt(preset, at));
    if (!message.empty()) {
        preset.weather = std::move(saved);
        preset.weatherRegions = std::move(savedRegions);
        error = message;
        return false;
    }
    error.clear();
    return true;
}

bool validState(const Preset& preset, int state) {
    return state >= 0 && std::size_t(state) < preset.weather.size();
}

int componentCount(const ParamDesc& desc) { return desc.type == ParamType::Scalar ? 1 : desc.components(); }

std::string valuesText(const ParamDesc& desc, const double v[4], bool unit) {
    const int n = componentCount(desc);
    std::string text = n > 1 ? "[" : "";
    for (int c = 0; c < n; ++c) {
        if (c) text += ", ";
        text += valueWithUnit(v[c], "", 4);
    }
    if (n > 1) text += "]";
    if (unit && !desc.unit.empty()) text += " " + std::string(desc.unit);
    return text;
}

}  // namespace

const char* weatherModeName(WeatherOverrideMode mode) {
    switch (mode) {
        case WeatherOverrideMode::Add:
            return "add";
        case WeatherOverrideMode::Scale:
            return "scale";
        case WeatherOverrideMode::Set:
            break;
    }
    return "set";
}

bool weatherModeFromName(std::string_view name, WeatherOverrideMode& mode) {
    for (WeatherOverrideMode m :
         {WeatherOverrideMode::Set, WeatherOverrideMode::Add, WeatherOverrideMode::Scale})
        if (name == weatherModeName(m)) {
            mode = m;
            return true;
        }
    return false;
}

int weatherStateIndex(const Preset& preset, std::string_view name) {
    for (std::size_t i = 0; i < preset.weather.size(); ++i)
        if (preset.weather[i].name == name) return int(i);
    return -1;
}

int weatherOverrideIndex(const WeatherState& state, const TrackTarget& target) {
    for (std::size_t i = 0; i < state.overrides.size(); ++i)
        if (state.overrides[i].target == target) return int(i);
    return -1;
}

std::string uniqueWeatherStateName(const Preset& preset, std::string_view base) {
    std::string name(base);
    for (int n = 2; weatherStateIndex(preset, name) >= 0 || name == "none"; ++n)
        name = std::string(base) + "_" + std::to_string(n);
    return name;
}

bool addWeatherState(Preset& preset, const std::string& name, std::string& error) {
    return checkedEdit(preset, error, [&](Preset& p) { p.weather.push_back({name, {}}); });
}

bool renameWeatherState(Preset& preset, int state, const std::string& name, std::string& error) {
    if (!validState(preset, state)) {
        error = "no weather state " + std::to_string(state);
        return false;
    }
    return checkedEdit(preset, error, [&](Preset& p) {
        std::string& old = p.weather[std::size_t(state)].name;
        for (WeatherRegion& r : p.weatherRegions)  // the regions that hold it follow
            if (r.state == old) r.state = name;
        old = name;
    });
}

bool removeWeatherState(Preset& preset, int state) {
    if (!validState(preset, state)) return false;
    const std::string name = preset.weather[std::size_t(state)].name;
    preset.weather.erase(preset.weather.begin() + state);
    std::erase_if(preset.weatherRegions, [&](const WeatherRegion& r) { return r.state == name; });
    return true;
}

bool addWeatherOverride(Preset& preset, int state, const WeatherOverride& o, std::string& error) {
    if (!validState(preset, state)) {
        error = "no weather state " + std::to_string(state);
        return false;
    }
    return checkedEdit(preset, error,
                       [&](Preset& p) { p.weather[std::size_t(state)].overrides.push_back(o); });
}

bool setWeatherOverride(Preset& preset, int state, int index, WeatherOverrideMode mode,
                        const glm::dvec3& value, std::string& error) {
    if (!validState(preset, state) || index < 0 ||
        std::size_t(index) >= preset.weather[std::size_t(state)].overrides.size()) {
        error = "no such weather override";
        return false;
    }
    return checkedEdit(preset, error, [&](Preset& p) {
        WeatherOverride& o = p.weather[std::size_t(state)].overrides[std::size_t(index)];
        o.mode = mode;
        o.value = value;
    });
}

bool removeWeatherOverride(Preset& preset, int state, int index) {
    if (!validState(preset, state)) return false;
    std::vector<WeatherOverride>& list = preset.weather[std::size_t(state)].overrides;
    if (index < 0 || std::size_t(index) >= list.size()) return false;
    list.erase(list.begin() + index);
    return true;
}

WeatherOverride newWeatherOverride(const Preset& preset, const ParamRef& ref, double timeHours) {
    WeatherOverride o;
    o.target = trackTargetOf(preset, ref);
    o.mode = WeatherOverrideMode::Set;
    double v[4];
    readValueAt(preset, ref, timeHours, v);
    o.value = glm::dvec3(v[0], v[1], v[2]);
    if (ref.desc && ref.desc->type == ParamType::Scalar) o.value.y = o.value.z = 0.0;
    if (ref.desc && ref.desc->type == ParamType::Vec2) o.value.z = 0.0;
    return o;
}

void overriddenValue(const ParamDesc& desc, const double keyed[4], const WeatherOverride& o, double out[4]) {
    out[0] = out[1] = out[2] = out[3] = 0.0;
    const glm::dvec3 v = weatherOverrideValue(o, glm::dvec3(keyed[0], keyed[1], keyed[2]));  // as core blends it
    for (int c = 0; c < std::min(componentCount(desc), 3); ++c) out[c] = std::clamp(v[c], desc.minValue, desc.maxValue);
}

glm::dvec3 valueForMode(const ParamDesc& desc, const double keyed[4], const WeatherOverride& o,
                        WeatherOverrideMode mode) {
    double result[4];
    overriddenValue(desc, keyed, o, result);
    glm::dvec3 value(0.0);
    for (int c = 0; c < componentCount(desc); ++c) {
        if (mode == WeatherOverrideMode::Set) {
            value[c] = result[c];
        } else if (mode == WeatherOverrideMode::Add) {
            value[c] = result[c] - keyed[c];
        } else {
            const double ratio = keyed[c] != 0.0 ? result[c] / keyed[c] : 1.0;
            value[c] = std::isfinite(ratio) && ratio >= 0.0 ? ratio : 1.0;
        }
    }
    return value;
}

std::string weatherOverrideText(const Preset& preset, const WeatherOverride& o, const std::string& stateName,
                                const double keyed[4]) {
    const ParamDesc* desc = findParam(o.target.scope, o.target.param);
    if (!desc) return curveKey(o.target) + ": unknown parameter";
    double result[4];
    overriddenValue(*desc, keyed, o, result);
    const double given[4] = {o.value.x, o.value.y, o.value.z, 0.0};
    return curveLabel(preset, o.target) + ": " + weatherModeName(o.mode) + " " +
           valuesText(*desc, given, o.mode != WeatherOverrideMode::Scale) + " (keyed " +
           valuesText(*desc, keyed, false) + " -> " + valuesText(*desc, result, true) + " " + stateName + ")";
}

namespace {

/// Runs `edit` in doc.apply; false with `error` when it refused (its own
/// error) or changed nothing.
template <class Edit>
bool applyWeatherEdit(Document& doc, const std::string& label, const std::string& mergeKey,
                      std::string& error, Edit&& edit) {
    bool ok = false;
    std::string why;
    const bool changed = doc.apply(label, mergeKey, [&](Preset& p) { ok = edit(p, why); });
    if (!ok) {
        error = why.empty() ? label + ": nothing to change" : why;
        return false;
    }
    if (!changed && mergeKey.empty()) {
        error = label + ": nothing changed";
        return false;
    }
    error.clear();
    return true;
}

std::string stateName(const Document& doc, int state) {
    return validState(doc.preset(), state) ? doc.preset().weather[std::size_t(state)].name : std::string("?");
}

}  // namespace

bool applyAddWeatherState(Document& doc, const std::string& name, std::string& error) {
    return applyWeatherEdit(doc, "Add weather state " + name, "", error,
                            [&](Preset& p, std::string& e) { return addWeatherState(p, name, e); });
}

bool applyRenameWeatherState(Document& doc, int state, const std::string& name, std::string& error) {
    return applyWeatherEdit(doc, "Rename weather state " + stateName(doc, state) + " to " + name, "", error,
                            [&](Preset& p, std::string& e) { return renameWeatherState(p, state, name, e); });
}

bool applyRemoveWeatherState(Document& doc, int state, std::string& error) {
    return applyWeatherEdit(doc, "Remove weather state " + stateName(doc, state), "", error,
                            [&](Preset& p, std::string& e) {
                                if (removeWeatherState(p, state)) return true;
                                e = "no weather state " + std::to_string(state);
                                return false;
                            });
}

bool applyAddWeatherOverride(Document& doc, int state, const WeatherOverride& o, std::string& error) {
    return applyWeatherEdit(
        doc, "Add " + curveLabel(doc.preset(), o.target) + " to weather " + stateName(doc, state), "", error,
        [&](Preset& p, std::string& e) { return addWeatherOverride(p, state, o, e); });
}

bool applySetWeatherOverride(Document& doc, int state, int index, WeatherOverrideMode mode,
                             const glm::dvec3& value, bool continuous, std::string& error) {
    const std::string merge =
        continuous ? "weather:" + std::to_string(state) + ":" + std::to_string(index) : std::string();
    return applyWeatherEdit(
        doc, "Weather " + stateName(doc, state) + " override", merge, error,
        [&](Preset& p, std::string& e) { return setWeatherOverride(p, state, index, mode, value, e); });
}

bool applyRemoveWeatherOverride(Document& doc, int state, int index, std::string& error) {
    return applyWeatherEdit(doc, "Remove override from weather " + stateName(doc, state), "", error,
                            [&](Preset& p, std::string& e) {
                                if (removeWeatherOverride(p, state, index)) return true;
                                e = "no such weather override";
                                return false;
                            });
}

int weatherRegionIndex(const Preset& preset, std::string_view id) {
    for (std::size_t i = 0; i < preset.weatherRegions.size(); ++i)
        if (preset.weatherRegions[i].id == id) return int(i);
    return -1;
}

std::string uniqueWeatherRegionId(const Preset& preset, std::string_view base) {
    std::string id(base);
    for (int n = 2; weatherRegionIndex(preset, id) >= 0; ++n)
        id = std::string(base) + "_" + std::to_string(n);
    return id;
}

WeatherRegion newWeatherRegion(const Preset& preset, WeatherRegionShape shape, const std::string& state,
                               const glm::dvec3& centre) {
    WeatherRegion r;
    r.id = uniqueWeatherRegionId(preset, "region");
    r.shape = shape;
    r.position =
        glm::clamp(centre, glm::dvec3(-kWeatherRegionMaxCoordinate), glm::dvec3(kWeatherRegionMaxCoordinate));
    if (!std::isfinite(r.position.x + r.position.y + r.position.z)) r.position = glm::dvec3(0.0);
    r.halfExtents = glm::dvec3(1000.0, 500.0, 1000.0);
    r.blend = 200.0;
    r.state = state;
    return r;
}

const char* weatherRegionShapeName(WeatherRegionShape shape) {
    return shape == WeatherRegionShape::Ellipsoid ? "ellipsoid" : "box";
}

bool weatherRegionShapeFromName(std::string_view name, WeatherRegionShape& shape) {
    if (name == "box")
        shape = WeatherRegionShape::Box;
    else if (name == "ellipsoid")
        shape = WeatherRegionShape::Ellipsoid;
    else
        return false;
    return true;
}

double weatherRegionYawDeg(const WeatherRegion& region) {
    // Where the rotation takes +X, seen from above: atan2(-z, x) is the turn about +Y.
    const glm::dvec3 x = glm::normalize(region.rotation) * glm::dvec3(1.0, 0.0, 0.0);
    const double yaw = std::atan2(-x.z, x.x) * 180.0 / 3.14159265358979323846;
    return yaw <= -180.0 ? yaw + 360.0 : yaw;
}

void setWeatherRegionYawDeg(WeatherRegion& region, double degrees) {
    const double half = 0.5 * degrees * 3.14159265358979323846 / 180.0;
    region.rotation = glm::dquat(std::cos(half), 0.0, std::sin(half), 0.0);
}

bool setWeatherRegionField(WeatherRegion& region, std::string_view key,
                           const std::vector<std::string>& values, std::string& error) {
    const std::string k(key);
    auto count = [&](std::size_t n) {
        if (values.size() == n) return true;
        error = k + " takes " + std::to_string(n) + " value(s)";
        return false;
    };
    auto numbers = [&](double* out, std::size_t n) {
        if (!count(n)) return false;
        for (std::size_t i = 0; i < n; ++i)
            if (!toNumber(values[i], out[i])) {
                error = k + ": \"" + values[i] + "\" is not a number";
                return false;
            }
        return true;
    };
    double v[3] = {0.0, 0.0, 0.0};
    if (key == "name") {  // the words joined by spaces
        region.name.clear();
        for (const std::string& word : values) region.name += (region.name.empty() ? "" : " ") + word;
    } else if (key == "id" || key == "state") {
        if (!count(1)) return false;
        (key == "id" ? region.id : region.state) = values[0];
    } else if (key == "shape") {
        if (!count(1)) return false;
        if (!weatherRegionShapeFromName(values[0], region.shape)) {
            error = "shape \"" + values[0] + "\" is not one of box, ellipsoid";
            return false;
        }
    } else if (key == "position_m" || key == "half_extents_m") {
        if (!numbers(v, 3)) return false;
        (key == "position_m" ? region.position : region.halfExtents) = glm::dvec3(v[0], v[1], v[2]);
    } else if (key == "blend_m" || key == "yaw_deg" || key == "priority") {
        if (!numbers(v, 1)) return false;
        if (key == "blend_m") region.blend = v[0];
        if (key == "yaw_deg") setWeatherRegionYawDeg(region, v[0]);
        if (key == "priority") {
            if (!(std::trunc(v[0]) == v[0] && std::abs(v[0]) <= kWeatherRegionMaxPriority)) {
                error = "priority \"" + values[0] + "\" is not an integer in -1000..1000";
                return false;
            }
            region.priority = int(v[0]);
        }
    } else {
        error = "unknown region field \"" + k +
                "\" (id, name, shape, position_m, half_extents_m, yaw_deg, blend_m, priority, state)";
        return false;
    }
    return true;
}

bool addWeatherRegion(Preset& preset, const WeatherRegion& region, std::string& error) {
    return checkedEdit(preset, error, [&](Preset& p) { p.weatherRegions.push_back(region); });
}

bool setWeatherRegion(Preset& preset, int index, const WeatherRegion& region, std::string& error) {
    if (index < 0 || std::size_t(index) >= preset.weatherRegions.size()) {
        error = "no weather region " + std::to_string(index);
        return false;
    }
    return checkedEdit(preset, error, [&](Preset& p) { p.weatherRegions[std::size_t(index)] = region; });
}

bool removeWeatherRegion(Preset& preset, int index) {
    if (index < 0 || std::size_t(index) >= preset.weatherRegions.size()) return false;
    preset.weatherRegions.erase(preset.weatherRegions.begin() + index);
    return true;
}

bool applyAddWeatherRegion(Document& doc, const WeatherRegion& region, std::string& error) {
    return applyWeatherEdit(doc, "Add weather region " + region.id, "", error,
                            [&](Preset& p, std::string& e) { return addWeatherRegion(p, region, e); });
}

bool applySetWeatherRegion(Document& doc, int index, const WeatherRegion& region, bool continuous,
                           std::string& error) {
    const std::string merge = continuous ? "weather_region:" + std::to_string(index) : std::string();
    return applyWeatherEdit(doc, "Weather region " + region.id, merge, error,
                            [&](Preset& p, std::string& e) { return setWeatherRegion(p, index, region, e); });
}

bool applyRemoveWeatherRegion(Document& doc, int index, std::string& error) {
    const std::string id = index >= 0 && std::size_t(index) < doc.preset().weatherRegions.size()
                               ? doc.preset().weatherRegions[std::size_t(index)].id
                               : std::string("?");
    return applyWeatherEdit(doc, "Remove weather region " + id, "", error, [&](Preset& p, std::string& e) {
        if (removeWeatherRegion(p, index)) return true;
        e = "no weather region " + std::to_string(index);
        return false;
    });
}

std::vector<ParamRef> animatableParams(const Preset& preset) {
    std::vector<ParamRef> out;
    for (ParamScope scope :
         {ParamScope::Global, ParamScope::Volume, ParamScope::Emitter, ParamScope::CloudVolume}) {
        const int objects = scope == ParamScope::Global ? 1 : int(objectCount(preset, scope));
        for (int i = 0; i < objects; ++i)
            for (const ParamDesc& desc : paramTable(scope))
                if (desc.animatable) out.push_back({&desc, scope == ParamScope::Global ? -1 : i});
    }
    return out;
}

}  // namespace aerial::editor
