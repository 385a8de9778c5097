// aerial/param_table.hpp — the one table of every editable parameter
// (../shared/STYLE.md, point 3). The JSON reader and writer, validation, the
// JSON Schema, the timeline and the editor's inspector all iterate it; no
// range or default is written down anywhere else.
//
// Usage (an inspector, generically):
//   for (const aerial::ParamDesc& p : aerial::paramTable(aerial::ParamScope::Volume)) {
//       switch (p.type) {
//       case aerial::ParamType::Scalar:
//           slider(p.label, *p.scalar(&volume), p.uiMin, p.uiMax, p.logScale); break;
//       case aerial::ParamType::Colour: colourPicker(p.label, *p.vec3(&volume)); break;
//       case aerial::ParamType::Enum: {
//           int v = int(p.getInt(&volume));
//           if (combo(p.label, v, p.enumNames)) p.setInt(&volume, v);
//           break;
//       }
//       ...
//       }
//       tooltip(p.doc);
//   }
//   const aerial::ParamDesc* d = aerial::findParam(aerial::ParamScope::Global, "fog.density_per_m");
//
// The object an accessor takes is, by scope: Global -> Environment,
// Volume -> FogVolume, Emitter -> Emitter, CloudVolume -> CloudVolume
// (passed as void*; the typed helpers below check the scope).
#pragma once

#include <aerial/clouds.hpp>
#include <aerial/emitter.hpp>
#include <aerial/fog_volume.hpp>
#include <aerial/preset.hpp>
#include <aerial/timeline.hpp>

#include <glm/gtc/quaternion.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cassert>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace aerial {

enum class ParamType {
    Scalar,      ///< double
    Colour,      ///< glm::dvec3, scene-linear Rec.709 RGB
    Vec3,        ///< glm::dvec3 (positions, extents, per-channel coefficients)
    Vec2,        ///< glm::dvec2, horizontal [x, z] (x = world X, y = world Z); JSON [x, z]
    Quaternion,  ///< glm::dquat, unit; JSON [x, y, z, w]
    Enum,        ///< an enum class; JSON string from enumNames
    Int,         ///< integer (e.g. a seed); JSON integer
    String,      ///< std::string; JSON string
};

/// One editable parameter.
struct ParamDesc {
    ParamScope scope = ParamScope::Global;
    ParamType type = ParamType::Scalar;
    /// Global: dotted path whose parts are the JSON object keys
    /// ("atmosphere.mie.scale_height_m"); the last part is the JSON key.
    /// Volume/emitter/cloud volume: the JSON key in the object
    /// ("density_per_m").
    /// Also the track target's `param`.
    std::string_view path;
    /// Short name for the inspector ("Scale height").
    std::string_view label;
    /// Display unit ("m", "1/m", "1/m^2", "deg", "day", "h", "s", "" if none).
    std::string_view unit;
    /// Tooltip / documentation: meaning, unit, range.
    std::string_view doc;
    /// Valid range, inclusive, for Scalar/Int and every component of
    /// Colour/Vec3/Vec2 (Quaternion: unit length instead). Values outside are
    /// errors in validation and in the loader.
    double minValue = 0.0;
    double maxValue = 0.0;
    /// Suggested slider range (inside the valid range; a log slider starts
    /// at uiMin > 0).
    double uiMin = 0.0;
    double uiMax = 0.0;
    /// Default value: x for Scalar/Int/Enum (enum index), xyz for
    /// Colour/Vec3, xz as [0], [1] for Vec2, xyzw for Quaternion (w = real
    /// part). Equals the
    /// struct's default member initialiser (a test checks).
    double defaultValue[4] = {0.0, 0.0, 0.0, 0.0};
    /// String default.
    std::string_view defaultText;
    /// Show the slider logarithmically.
    bool logScale = false;
    /// May carry a timeline track (Scalar, Colour, Vec3, Vec2 only). A
    /// track's keys hold components() numbers (TrackKey::value's x, y, z;
    /// a Vec2's [x, z] as value.x, value.y, with value.z = 0).
    bool animatable = false;
    /// Vec3 that must have unit length (|v| within 1e-6 of 1).
    bool unitLength = false;
    /// Required in a file (ids); the others take their default when absent.
    bool required = false;
    /// Left out of a saved file while it has its default (an Enum at
    /// defaultValue[0], an empty String, a Scalar bit-identical to
    /// defaultValue[0]): fields most objects never use ("mesh", "blend",
    /// "edge_softness") do not clutter every volume.
    bool omitWhenDefault = false;
    /// Enum: JSON spelling of each value, index = the enum's integer value.
    std::span<const std::string_view> enumNames;

    // Accessors; the one matching `type` is set, the others are null.
    double* (*scalar)(void* object) = nullptr;             ///< Scalar
    glm::dvec3* (*vec3)(void* object) = nullptr;           ///< Colour, Vec3
    glm::dvec2* (*vec2)(void* object) = nullptr;           ///< Vec2
    glm::dquat* (*quat)(void* object) = nullptr;           ///< Quaternion
    std::string* (*string)(void* object) = nullptr;        ///< String
    std::int64_t (*getInt)(const void* object) = nullptr;  ///< Enum, Int
    void (*setInt)(void* object, std::int64_t value) = nullptr;

    /// The JSON key (last part of `path`).
    std::string_view key() const {
        const std::size_t dot = path.rfind('.');
        return dot == std::string_view::npos ? path : path.substr(dot + 1);
    }
    /// 1 for Scalar/Int/Enum, 2 for Vec2, 3 for Colour/Vec3, 4 for
    /// Quaternion, 0 for String.
    int components() const { return componentCount(type); }

    /// components() of a type.
    static int componentCount(ParamType type);
};

/// Every parameter of a scope, in canonical (file) order.
std::span<const ParamDesc> paramTable(ParamScope scope);

/// The parameter with this path in a scope, or null.
const ParamDesc* findParam(ParamScope scope, std::string_view path);

/// "global", "volume", "emitter", "cloud volume" (in messages: "unknown
/// cloud volume parameter \"x\"").
std::string_view scopeName(ParamScope scope);

/// The key a scope's objects go by in files and addresses: "volume",
/// "emitter", "cloud_volume" (a track's object key, the editor's address
/// prefix); "" for Global.
std::string_view scopeKey(ParamScope scope);

/// JSON spelling of enums (the same lists the table uses).
std::string_view interpolationName(Interpolation interpolation);
bool parseInterpolation(std::string_view name, Interpolation& out);

// Typed access, checking that the object matches the parameter's scope.
inline void* paramObject(const ParamDesc& p, Environment& env) {
    assert(p.scope == ParamScope::Global);
    (void)p;
    return &env;
}
inline void* paramObject(const ParamDesc& p, FogVolume& volume) {
    assert(p.scope == ParamScope::Volume);
    (void)p;
    return &volume;
}
inline void* paramObject(const ParamDesc& p, Emitter& emitter) {
    assert(p.scope == ParamScope::Emitter);
    (void)p;
    return &emitter;
}
inline void* paramObject(const ParamDesc& p, CloudVolume& volume) {
    assert(p.scope == ParamScope::CloudVolume);
    (void)p;
    return &volume;
}

/// A parameter's current value as up to four doubles (see defaultValue's
/// layout: a Vec2 fills out[0], out[1]); strings give zeros.
template <class Object>
void readParam(const ParamDesc& p, const Object& object, double out[4]) {
    void* o = paramObject(p, const_cast<Object&>(object));
    out[0] = out[1] = out[2] = out[3] = 0.0;
    switch (p.type) {
        case ParamType::Scalar:
            out[0] = *p.scalar(o);
            break;
        case ParamType::Colour:
        case ParamType::Vec3: {
            const glm::dvec3& v = *p.vec3(o);
            out[0] = v.x, out[1] = v.y, out[2] = v.z;
            break;
        }
        case ParamType::Vec2: {
            const glm::dvec2& v = *p.vec2(o);
            out[0] = v.x, out[1] = v.y;
            break;
        }
        case ParamType::Quaternion: {
            const glm::dquat& q = *p.quat(o);
            out[0] = q.x, out[1] = q.y, out[2] = q.z, out[3] = q.w;
            break;
        }
        case ParamType::Enum:
        case ParamType::Int:
            out[0] = double(p.getInt(o));
            break;
        case ParamType::String:
            break;
    }
}

}  // namespace aerial
