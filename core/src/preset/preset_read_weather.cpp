// preset_read_weather.cpp — the reader's targets, weather states and weather
// regions (preset_reader.hpp): "weather": {"states": [{"name", "overrides":
// [{target, "set" | "add" | "scale": value}]}], "regions": [{"id", "name",
// "shape", "position_m", "rotation_xyzw", "half_extents_m", "blend_m",
// "priority", "state"}]} (aerial/weather_state.hpp); and the preset's
// "view": {"eye_m", "target_m", "fov_deg"} (aerial/preset.hpp, PresetView).
#include "json_text.hpp"
#include "preset_reader.hpp"
#include "preset_validate.hpp"

#include <aerial/limits.hpp>
#include <aerial/param_table.hpp>

#include <algorithm>
#include <cmath>
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

void Reader::readWeather(std::int32_t node, const std::string& pointer, std::vector<WeatherState>& states,
                         std::vector<WeatherRegion>& regions) {
    if (!expectKind(node, pointer, JNode::Object)) return;
    warnUnknownMembers(node, pointer, {"states", "regions"});
    if (const std::int32_t list = member(node, "regions"); list >= 0) {
        const std::string at = pointerJoin(pointer, "regions");
        if (expectKind(list, at, JNode::Array) &&
            withinLimit(list, at, limits::kMaxWeatherRegions, "weather regions")) {
            std::size_t i = 0;
            for (std::int32_t c = nodes_[std::size_t(list)].firstChild; c >= 0;
                 c = nodes_[std::size_t(c)].nextSibling, ++i)
                readRegion(c, pointerJoin(at, i), regions.emplace_back());
        }
    }
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

void Reader::readRegion(std::int32_t node, const std::string& pointer, WeatherRegion& region) {
    if (!expectKind(node, pointer, JNode::Object)) return;
    warnUnknownMembers(node, pointer,
                       {"id", "name", "shape", "position_m", "rotation_xyzw", "half_extents_m", "blend_m",
                        "priority", "state"});
    auto text = [&](sv key, bool required, std::string& out) {
        const std::int32_t m = member(node, key);
        const std::string at = pointerJoin(pointer, key);
        if (m < 0) {
            if (required) error(node, at, "missing required field " + quoteString(key));
        } else if (expectKind(m, at, JNode::String)) {
            out = nodes_[std::size_t(m)].text;
        }
    };
    text("id", true, region.id);
    text("name", false, region.name);
    text("state", true, region.state);
    if (const std::int32_t m = member(node, "shape"); m >= 0) {
        const std::string at = pointerJoin(pointer, "shape");
        if (expectKind(m, at, JNode::String)) {
            const std::string& shape = nodes_[std::size_t(m)].text;
            if (shape == "box")
                region.shape = WeatherRegionShape::Box;
            else if (shape == "ellipsoid")
                region.shape = WeatherRegionShape::Ellipsoid;
            else
                error(m, at, "unknown value " + quoteString(shape) + "; expected one of box, ellipsoid");
        }
    }
    auto vector3 = [&](sv key, glm::dvec3& out) {
        const std::int32_t m = member(node, key);
        double v[3];
        if (m >= 0 && readNumbers(m, pointerJoin(pointer, key), v, 3)) out = glm::dvec3(v[0], v[1], v[2]);
    };
    vector3("position_m", region.position);
    vector3("half_extents_m", region.halfExtents);
    if (const std::int32_t m = member(node, "rotation_xyzw"); m >= 0) {
        const std::string at = pointerJoin(pointer, "rotation_xyzw");
        double v[4];
        if (readNumbers(m, at, v, 4) && normaliseOrRefuse(m, at, v, 4, "a unit quaternion"))
            region.rotation = glm::dquat(v[3], v[0], v[1], v[2]);
    }
    if (const std::int32_t m = member(node, "blend_m"); m >= 0)
        readNumber(m, pointerJoin(pointer, "blend_m"), region.blend);
    if (const std::int32_t m = member(node, "priority"); m >= 0) {
        const JNode& n = nodes_[std::size_t(m)];
        const double v = n.isNumber() ? n.asDouble() : 0.0;
        const bool integral = n.kind == JNode::Integer || n.kind == JNode::Unsigned ||
                              (n.kind == JNode::Float && std::isfinite(v) && std::trunc(v) == v);
        const std::string at = pointerJoin(pointer, "priority");
        if (!integral)
            error(m, at, std::string("expected an integer, got ") + kindName(n.kind));
        else if (std::abs(v) > kWeatherRegionMaxPriority)
            error(m, at, "out of range: " + formatDouble(v) + " is not in " +
                             std::to_string(-kWeatherRegionMaxPriority) + ".." +
                             std::to_string(kWeatherRegionMaxPriority));
        else
            region.priority = int(v);
    }
}

void Reader::readView(std::int32_t node, const std::string& pointer, std::optional<PresetView>& view) {
    if (!expectKind(node, pointer, JNode::Object)) return;
    warnUnknownMembers(node, pointer, {"eye_m", "target_m", "fov_deg"});
    PresetView v;
    bool complete = true;
    auto point = [&](sv key, glm::dvec3& out) {
        const std::int32_t m = member(node, key);
        const std::string at = pointerJoin(pointer, key);
        double xyz[3];
        if (m < 0) {
            error(node, at, "missing required field " + quoteString(key));
            complete = false;
        } else if (readNumbers(m, at, xyz, 3)) {
            out = glm::dvec3(xyz[0], xyz[1], xyz[2]);
        } else {
            complete = false;
        }
    };
    point("eye_m", v.eye);
    point("target_m", v.target);
    if (const std::int32_t m = member(node, "fov_deg"); m >= 0)
        complete = readNumber(m, pointerJoin(pointer, "fov_deg"), v.verticalFovDeg) && complete;
    if (complete) view = v;
}

void Reader::warnUnknownMembers(std::int32_t node, const std::string& pointer, std::initializer_list<sv> known) {
    for (std::int32_t m = nodes_[std::size_t(node)].firstChild; m >= 0; m = nodes_[std::size_t(m)].nextSibling) {
        const std::string& name = nodes_[std::size_t(m)].key;
        if (std::find(known.begin(), known.end(), sv(name)) == known.end()) warnUnknown(m, pointerJoin(pointer, name));
    }
}

}  // namespace aerial
