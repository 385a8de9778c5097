// preset_read_weather.cpp — the reader's targets and weather states
// (preset_reader.hpp): "weather": {"states": [{"name", "overrides":
// [{target, "set" | "add" | "scale": value}]}]} (aerial/weather_state.hpp).
#include "json_text.hpp"
#include "preset_reader.hpp"
#include "preset_validate.hpp"

#include <aerial/limits.hpp>
#include <aerial/param_table.hpp>

#include <algorithm>
#include <cstdint>
#include <utility>

namespace aerial {

using namespace detail;
using sv = std::string_view;

void Reader::readTarget(std::int32_t node, const std::string& pointer, const char* what, TrackTarget& target) {
    bool targeted = false;
    for (const ParamScope scope : kObjectScopes) {
        const sv key = trackObjectKey(scope);
        const std::int32_t object = member(node, key);
        if (object < 0) continue;
        const std::string at = pointerJoin(pointer, key);
        if (targeted) {
            error(object, at, std::string(what) + " targets one volume, emitter or cloud volume, not several");
            continue;
        }
        targeted = true;
        target.scope = scope;
        if (expectKind(object, at, JNode::String)) target.objectId = nodes_[std::size_t(object)].text;
    }
    const std::int32_t param = member(node, "param");
    if (param < 0)
        error(node, pointerJoin(pointer, "param"), "missing required field \"param\"");
    else if (expectKind(param, pointerJoin(pointer, "param"), JNode::String))
        target.param = nodes_[std::size_t(param)].text;
}

void Reader::readWeather(std::int32_t node, const std::string& pointer, std::vector<WeatherState>& states) {
    if (!expectKind(node, pointer, JNode::Object)) return;
    warnUnknownMembers(node, pointer, {"states"});
    const std::int32_t list = member(node, "states");
    const std::string at = pointerJoin(pointer, "states");
    if (list < 0) {
        error(node, at, "missing required field \"states\"");
        return;
    }
    if (!expectKind(list, at, JNode::Array) ||
        !withinLimit(list, at, limits::kMaxWeatherStates, "weather states"))
        return;
    std::size_t i = 0;
    for (std::int32_t c = nodes_[std::size_t(list)].firstChild; c >= 0;
         c = nodes_[std::size_t(c)].nextSibling, ++i) {
        const std::string stateAt = pointerJoin(at, i);
        WeatherState& state = states.emplace_back();
        if (!expectKind(c, stateAt, JNode::Object)) continue;
        warnUnknownMembers(c, stateAt, {"name", "overrides"});
        const std::int32_t name = member(c, "name");
        if (name < 0)
            error(c, pointerJoin(stateAt, "name"), "missing required field \"name\"");
        else if (expectKind(name, pointerJoin(stateAt, "name"), JNode::String))
            state.name = nodes_[std::size_t(name)].text;
        const std::int32_t overrides = member(c, "overrides");
        const std::string overridesAt = pointerJoin(stateAt, "overrides");
        if (overrides < 0) {
            error(c, overridesAt, "missing required field \"overrides\"");
            continue;
        }
        if (!expectKind(overrides, overridesAt, JNode::Array) ||
            !withinLimit(overrides, overridesAt, limits::kMaxWeatherOverrides, "overrides"))
            continue;
        std::size_t k = 0;
        for (std::int32_t o = nodes_[std::size_t(overrides)].firstChild; o >= 0;
             o = nodes_[std::size_t(o)].nextSibling, ++k)
            readOverride(o, pointerJoin(overridesAt, k), state.overrides.emplace_back());
    }
}

void Reader::readOverride(std::int32_t node, const std::string& pointer, WeatherOverride& o) {
    if (!expectKind(node, pointer, JNode::Object)) return;
    readTarget(node, pointer, "an override", o.target);
    warnUnknownMembers(node, pointer, {"param", "volume", "emitter", "cloud_volume", "set", "add", "scale"});
    constexpr std::pair<sv, WeatherOverrideMode> kModes[] = {
        {"set", WeatherOverrideMode::Set}, {"add", WeatherOverrideMode::Add}, {"scale", WeatherOverrideMode::Scale}};
    std::int32_t value = -1;
    for (const auto& [key, mode] : kModes) {
        const std::int32_t v = member(node, key);
        if (v < 0) continue;
        if (value >= 0) {
            error(v, pointerJoin(pointer, key), "an override has one of \"set\", \"add\", \"scale\", not several");
            continue;
        }
        value = v;
        o.mode = mode;
    }
    if (value < 0) {
        error(node, pointerJoin(pointer, "set"),
              "missing the override's value: one of \"set\", \"add\" (to the keyed value) or \"scale\" (times it)");
        return;
    }
    const std::string at = pointerJoin(pointer, nodes_[std::size_t(value)].key);
    const ParamDesc* p = findParam(o.target.scope, o.target.param);
    if (!p || p->components() == 1) {
        readNumber(value, at, o.value.x);
    } else {
        const int count = p->components() == 2 ? 2 : 3;
        double v[3] = {0.0, 0.0, 0.0};
        if (readNumbers(value, at, v, count)) o.value = glm::dvec3(v[0], v[1], v[2]);
    }
}

void Reader::warnUnknownMembers(std::int32_t node, const std::string& pointer, std::initializer_list<sv> known) {
    for (std::int32_t m = nodes_[std::size_t(node)].firstChild; m >= 0; m = nodes_[std::size_t(m)].nextSibling) {
        const std::string& name = nodes_[std::size_t(m)].key;
        if (std::find(known.begin(), known.end(), sv(name)) == known.end()) warnUnknown(m, pointerJoin(pointer, name));
    }
}

}  // namespace aerial
