// editor/weather_edit.cpp — the Weather panel's model (see weather_edit.hpp).
#include "weather_edit.hpp"

#include "action_args.hpp"
#include "curve_view.hpp"

#include <aerial/param_table.hpp>
#include <aerial/weather.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

namespace aerial::editor {
namespace {

constexpr std::string_view kStatesPointer = "/weather/states";

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
/// in the weather states that it did not find before; otherwise restores
/// the states and sets `error` to the first new one. (A duplicate name or
/// target is reported at the later of the two, so the whole of the states
/// is compared, not only the one edited.)
template <class Edit>
bool checkedEdit(Preset& preset, std::string& error, Edit&& edit) {
    const std::string at(kStatesPointer);
    const std::vector<PresetIssue> before = issuesAt(preset, at);
    std::vector<WeatherState> saved = preset.weather;
    edit(preset);
    const std::string message = newIssue(before, issuesAt(preset, at));
    if (!message.empty()) {
        preset.weather = std::move(saved);
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
    return checkedEdit(preset, error, [&](Preset& p) { p.weather[std::size_t(state)].name = name; });
}

bool removeWeatherState(Preset& preset, int state) {
    if (!validState(preset, state)) return false;
    preset.weather.erase(preset.weather.begin() + state);
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
