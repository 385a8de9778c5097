// preset_write.cpp — writing: presetToJson, the canonical JSON text of a
// Preset (the parameter table's key order, two-space indent, every
// parameter written, numbers in the shortest form that reads back
// bit-exact), and savePreset, which validates first and then writes through
// the atomic writer (aerial/detail/file_system.hpp).
#include "json_text.hpp"
#include "preset_issues.hpp"
#include "preset_validate.hpp"

#include <aerial/detail/file_system.hpp>
#include <aerial/param_table.hpp>
#include <aerial/preset.hpp>

#include <cmath>
#include <cstdint>
#include <exception>
#include <string>
#include <string_view>
#include <vector>

namespace aerial {

using namespace detail;
using sv = std::string_view;

namespace {

class Writer {
public:
    std::string out;

    void newline(int depth) {
        out += '\n';
        out.append(std::size_t(depth) * 2, ' ');
    }
    void key(sv k) {
        out += quoteString(k);
        out += ": ";
    }
    void numbers(const double* v, int count) {
        out += '[';
        for (int i = 0; i < count; ++i) {
            if (i) out += ", ";
            out += formatDouble(v[i]);
        }
        out += ']';
    }
    void value(const ParamDesc& p, void* object) {
        switch (p.type) {
            case ParamType::Scalar:
                out += formatDouble(*p.scalar(object));
                break;
            case ParamType::Colour:
            case ParamType::Vec3: {
                const glm::dvec3 v = *p.vec3(object);
                const double c[3] = {v.x, v.y, v.z};
                numbers(c, 3);
                break;
            }
            case ParamType::Vec2: {
                const glm::dvec2 v = *p.vec2(object);
                const double c[2] = {v.x, v.y};
                numbers(c, 2);
                break;
            }
            case ParamType::Quaternion: {
                const glm::dquat q = *p.quat(object);
                const double c[4] = {q.x, q.y, q.z, q.w};
                numbers(c, 4);
                break;
            }
            case ParamType::Enum: {
                const std::int64_t v = p.getInt(object);
                out += v >= 0 && std::size_t(v) < p.enumNames.size()
                           ? quoteString(p.enumNames[std::size_t(v)])
                           : std::string("null");
                break;
            }
            case ParamType::Int:
                out += std::to_string(p.getInt(object));
                break;
            case ParamType::String:
                out += quoteString(*p.string(object));
                break;
        }
    }

    // Members of a scope's object, one per line, at `depth`.
    void objectMembers(ParamScope scope, void* object, int depth) {
        bool first = true;
        for (const ParamDesc& p : paramTable(scope)) {
            if (p.omitWhenDefault &&
                ((p.type == ParamType::String && p.string(object)->empty()) ||
                 (p.type == ParamType::Enum && double(p.getInt(object)) == p.defaultValue[0]) ||
                 (p.type == ParamType::Scalar && *p.scalar(object) == p.defaultValue[0] &&
                  std::signbit(*p.scalar(object)) == std::signbit(p.defaultValue[0])))) {
                continue;
            }
            if (!first) out += ',';
            first = false;
            newline(depth);
            key(p.path);
            value(p, object);
        }
    }

    // The global table as nested groups, in table order.
    void globals(Environment& env) {
        std::vector<sv> open;  // currently open group names
        bool firstAtLevel = false;
        for (const ParamDesc& p : paramTable(ParamScope::Global)) {
            std::vector<sv> parts;
            std::size_t start = 0;
            while (true) {
                const std::size_t dot = p.path.find('.', start);
                parts.push_back(p.path.substr(start, dot == sv::npos ? sv::npos : dot - start));
                if (dot == sv::npos) break;
                start = dot + 1;
            }
            const std::size_t groups = parts.size() - 1;
            std::size_t common = 0;
            while (common < open.size() && common < groups && open[common] == parts[common]) ++common;
            while (open.size() > common) {
                open.pop_back();
                newline(int(open.size()) + 1);
                out += '}';
                firstAtLevel = false;
            }
            while (open.size() < groups) {
                if (!firstAtLevel) out += ',';
                newline(int(open.size()) + 1);
                key(parts[open.size()]);
                out += '{';
                open.push_back(parts[open.size()]);
                firstAtLevel = true;
            }
            if (!firstAtLevel) out += ',';
            firstAtLevel = false;
            newline(int(open.size()) + 1);
            key(parts.back());
            value(p, &env);
        }
        while (!open.empty()) {
            open.pop_back();
            newline(int(open.size()) + 1);
            out += '}';
        }
    }

    template <class Object>
    void objectArray(sv name, std::vector<Object>& objects, ParamScope scope) {
        out += ',';
        newline(1);
        key(name);
        if (objects.empty()) {
            out += "[]";
            return;
        }
        out += '[';
        for (std::size_t i = 0; i < objects.size(); ++i) {
            if (i) out += ',';
            newline(2);
            out += '{';
            objectMembers(scope, &objects[i], 3);
            newline(2);
            out += '}';
        }
        newline(1);
        out += ']';
    }

    void tracks(const std::vector<Track>& list) {
        out += ',';
        newline(1);
        key("tracks");
        if (list.empty()) {
            out += "[]";
            return;
        }
        out += '[';
        for (std::size_t i = 0; i < list.size(); ++i) {
            const Track& t = list[i];
            const ParamDesc* p = findParam(t.target.scope, t.target.param);
            // Numbers per key value: 1 (scalar; also an unknown target's
            // keys, as read), 2 (Vec2 [x, z] from value.x, .y) or 3.
            const int valueCount = !p || p->type == ParamType::Scalar ? 1 : p->components() == 2 ? 2 : 3;
            if (i) out += ',';
            newline(2);
            out += '{';
            if (t.target.scope != ParamScope::Global) {
                newline(3);
                key(trackObjectKey(t.target.scope));
                out += quoteString(t.target.objectId);
                out += ',';
            }
            newline(3);
            key("param");
            out += quoteString(t.target.param);
            out += ',';
            newline(3);
            key("interpolation");
            out += quoteString(int(t.interpolation) >= 0 && int(t.interpolation) <= 2
                                   ? interpolationName(t.interpolation)
                                   : sv("smooth"));
            out += ',';
            if (!t.wrap) {  // written only when it differs from the cyclic default
                newline(3);
                key("wrap");
                out += "false,";
            }
            newline(3);
            key("keys");
            out += '[';
            for (std::size_t k = 0; k < t.keys.size(); ++k) {
                if (k) out += ',';
                newline(4);
                if (t.keys[k].anchor)  // the event and the offset; the time follows from them
                    out += std::string("{\"anchor\": ") + quoteString(sunEventName(*t.keys[k].anchor)) +
                           ", \"offset_h\": " + formatDouble(t.keys[k].offsetHours) + ", \"value\": ";
                else
                    out += "{\"time_h\": " + formatDouble(t.keys[k].timeHours) + ", \"value\": ";
                if (valueCount == 1) {
                    out += formatDouble(t.keys[k].value.x);
                } else {
                    const double c[3] = {t.keys[k].value.x, t.keys[k].value.y, t.keys[k].value.z};
                    numbers(c, valueCount);
                }
                if (t.keys[k].flat) out += ", \"flat\": true";  // only when set: old files stay as they were
                if (const auto& mode = t.keys[k].interpolation;
                    mode && int(*mode) >= 0 && int(*mode) <= 2)  // only when the key has its own
                    out += std::string(", \"interpolation\": ") + quoteString(interpolationName(*mode));
                if (const auto& tangents = t.keys[k].tangents) {  // only when the key has its own
                    const glm::dvec3* slopes[2] = {&tangents->in, &tangents->out};
                    const char* names[2] = {", \"tangent_in\": ", ", \"tangent_out\": "};
                    for (int s = 0; s < 2; ++s) {
                        out += names[s];
                        if (valueCount == 1) {
                            out += formatDouble(slopes[s]->x);
                        } else {
                            const double c[3] = {slopes[s]->x, slopes[s]->y, slopes[s]->z};
                            numbers(c, valueCount);
                        }
                    }
                    out += tangents->mode == TangentMode::Broken ? ", \"tangent_mode\": \"broken\""
                                                                 : ", \"tangent_mode\": \"unified\"";
                }
                out += '}';
            }
            if (!t.keys.empty()) newline(3);
            out += ']';
            newline(2);
            out += '}';
        }
        newline(1);
        out += ']';
    }
    /// "weather": {"states": [{"name", "overrides": [{target, "set"|"add"|"scale": value}]}],
    /// "regions": [{...}] (only when there are regions)}
    void weather(const std::vector<WeatherState>& states, const std::vector<WeatherRegion>& regions) {
        out += ',';
        newline(1);
        key("weather");
        out += '{';
        newline(2);
        key("states");
        out += '[';
        for (std::size_t i = 0; i < states.size(); ++i) {
            if (i) out += ',';
            newline(3);
            out += "{\"name\": " + quoteString(states[i].name) + ", \"overrides\": [";
            const std::vector<WeatherOverride>& list = states[i].overrides;
            for (std::size_t k = 0; k < list.size(); ++k) {
                const WeatherOverride& o = list[k];
                const ParamDesc* p = findParam(o.target.scope, o.target.param);
                const int count = !p || p->type == ParamType::Scalar ? 1 : p->components() == 2 ? 2 : 3;
                if (k) out += ',';
                newline(4);
                out += '{';
                if (o.target.scope != ParamScope::Global)
                    out += quoteString(trackObjectKey(o.target.scope)) + ": " +
                           quoteString(o.target.objectId) + ", ";
                out += "\"param\": " + quoteString(o.target.param) + ", ";
                out += o.mode == WeatherOverrideMode::Add     ? "\"add\": "
                       : o.mode == WeatherOverrideMode::Scale ? "\"scale\": "
                                                              : "\"set\": ";
                if (count == 1) {
                    out += formatDouble(o.value.x);
                } else {
                    const double c[3] = {o.value.x, o.value.y, o.value.z};
                    numbers(c, count);
                }
                out += '}';
            }
            if (!list.empty()) newline(3);
            out += "]}";
        }
        if (!states.empty()) newline(2);
        out += ']';
        if (!regions.empty()) {  // files without regions stay as they were
            out += ',';
            newline(2);
            key("regions");
            out += '[';
            for (std::size_t i = 0; i < regions.size(); ++i) {
                if (i) out += ',';
                newline(3);
                out += '{';
                region(regions[i]);
                newline(3);
                out += '}';
            }
            newline(2);
            out += ']';
        }
        newline(1);
        out += '}';
    }
    /// "view": {"eye_m", "target_m", "fov_deg"} (preset.hpp, PresetView).
    void view(const PresetView& v) {
        out += ',';
        newline(1);
        key("view");
        out += '{';
        newline(2);
        const double eye[3] = {v.eye.x, v.eye.y, v.eye.z};
        key("eye_m");
        numbers(eye, 3);
        out += ',';
        newline(2);
        const double target[3] = {v.target.x, v.target.y, v.target.z};
        key("target_m");
        numbers(target, 3);
        out += ',';
        newline(2);
        key("fov_deg");
        out += formatDouble(v.verticalFovDeg);
        newline(1);
        out += '}';
    }
    /// A region's members, one per line (weather_state.hpp).
    void region(const WeatherRegion& r) {
        auto member = [&](sv k) {
            newline(4);
            key(k);
        };
        member("id");
        out += quoteString(r.id) + ",";
        member("name");
        out += quoteString(r.name) + ",";
        member("shape");
        out += r.shape == WeatherRegionShape::Ellipsoid ? "\"ellipsoid\"," : "\"box\",";
        const double position[3] = {r.position.x, r.position.y, r.position.z};
        member("position_m");
        numbers(position, 3);
        out += ',';
        const double rotation[4] = {r.rotation.x, r.rotation.y, r.rotation.z, r.rotation.w};
        member("rotation_xyzw");
        numbers(rotation, 4);
        out += ',';
        const double half[3] = {r.halfExtents.x, r.halfExtents.y, r.halfExtents.z};
        member("half_extents_m");
        numbers(half, 3);
        out += ',';
        member("blend_m");
        out += formatDouble(r.blend) + ",";
        member("priority");
        out += std::to_string(r.priority) + ",";
        member("state");
        out += quoteString(r.state);
    }
};

}  // namespace

std::string presetToJson(const Preset& constPreset) {
    Preset& preset = const_cast<Preset&>(constPreset);  // accessors are non-const; we only read
    Writer w;
    w.out.reserve(4096 + preset.volumes.size() * 600 + preset.tracks.size() * 400);
    w.out += '{';
    w.newline(1);
    w.key("version");
    w.out += std::to_string(kPresetVersion) + ",";
    w.newline(1);
    w.key("name");
    w.out += quoteString(preset.name) + ",";
    w.newline(1);
    w.key("description");
    w.out += quoteString(preset.description);  // globals() writes the separator
    w.globals(preset.environment);
    w.objectArray("volumes", preset.volumes, ParamScope::Volume);
    w.objectArray("emitters", preset.emitters, ParamScope::Emitter);
    w.objectArray("cloud_volumes", preset.cloudVolumes, ParamScope::CloudVolume);
    w.tracks(preset.tracks);
    if (!preset.weather.empty() || !preset.weatherRegions.empty())  // files without weather stay as they were
        w.weather(preset.weather, preset.weatherRegions);
    if (preset.view) w.view(*preset.view);  // files without a view stay as they were
    w.out += "\n}\n";
    return std::move(w.out);
}

SaveResult savePreset(const Preset& preset, const std::string& path) {
    SaveResult result;
    auto fail = [&](std::string message) {
        result.errors.push_back(makeIssue(path, std::move(message)));
        return result;
    };
    try {
        result.errors = validatePreset(preset);
        if (!result.errors.empty()) {
            for (PresetIssue& i : result.errors) {
                i.file = path;
                i.message = "not saved: " + i.message;
            }
            return result;
        }
        const std::string text = presetToJson(preset);
        const std::string why = detail::writeFileAtomically(path, text);
        if (!why.empty()) return fail("not saved: " + why);
    } catch (const std::exception& e) {
        return fail(std::string("not saved: ") + e.what());
    }
    return result;
}

}  // namespace aerial
