// preset_schema.cpp — presetJsonSchema: the JSON Schema (draft 2020-12) of
// the preset format, generated from the parameter table, with the caps of
// aerial/limits.hpp as maxItems (volumes, emitters, cloud volumes, tracks,
// keys per track)
// and maxLength (ids, names, descriptions). presets/aerial-preset.schema.json
// is its output: scripts/update_schema.sh rewrites it, test_preset checks
// that they agree.
#include <aerial/limits.hpp>
#include <aerial/param_table.hpp>
#include <aerial/preset.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdint>
#include <string>
#include <string_view>

namespace aerial {

using sv = std::string_view;

namespace {

using ojson = nlohmann::ordered_json;

// The caps of aerial/limits.hpp a schema can state. JSON Schema counts a
// string's length in characters, the loader in bytes of UTF-8: maxLength is
// the same number, so it is a necessary condition, not a sufficient one.

std::string idPattern() { return "^[A-Za-z0-9_.-]{1," + std::to_string(limits::kMaxIdBytes) + "}$"; }

ojson idSchema() {
    return {{"type", "string"}, {"pattern", idPattern()}, {"maxLength", limits::kMaxIdBytes}};
}

ojson textSchema() { return {{"type", "string"}, {"maxLength", limits::kMaxStringBytes}}; }

ojson arraySchema(const char* itemRef, std::size_t maxItems) {
    return {{"type", "array"}, {"items", {{"$ref", itemRef}}}, {"maxItems", maxItems}};
}

ojson schemaFor(const ParamDesc& p) {
    ojson s;
    std::string description(p.label);
    if (!p.unit.empty()) description += " [" + std::string(p.unit) + "]";
    description += ". " + std::string(p.doc);
    s["description"] = description;
    switch (p.type) {
        case ParamType::Scalar:
            s["type"] = "number";
            s["minimum"] = p.minValue;
            s["maximum"] = p.maxValue;
            s["default"] = p.defaultValue[0];
            break;
        case ParamType::Colour:
        case ParamType::Vec3:
            s["type"] = "array";
            s["items"] = {{"type", "number"}, {"minimum", p.minValue}, {"maximum", p.maxValue}};
            s["minItems"] = 3;
            s["maxItems"] = 3;
            s["default"] = {p.defaultValue[0], p.defaultValue[1], p.defaultValue[2]};
            break;
        case ParamType::Vec2:
            s["type"] = "array";
            s["items"] = {{"type", "number"}, {"minimum", p.minValue}, {"maximum", p.maxValue}};
            s["minItems"] = 2;
            s["maxItems"] = 2;
            s["default"] = {p.defaultValue[0], p.defaultValue[1]};
            break;
        case ParamType::Quaternion:
            s["type"] = "array";
            s["items"] = {{"type", "number"}, {"minimum", -1.000001}, {"maximum", 1.000001}};
            s["minItems"] = 4;
            s["maxItems"] = 4;
            s["default"] = {p.defaultValue[0], p.defaultValue[1], p.defaultValue[2], p.defaultValue[3]};
            break;
        case ParamType::Enum: {
            ojson names = ojson::array();
            for (sv n : p.enumNames) names.push_back(std::string(n));
            s["type"] = "string";
            s["enum"] = names;
            s["default"] = std::string(p.enumNames[std::size_t(p.defaultValue[0])]);
            break;
        }
        case ParamType::Int:
            s["type"] = "integer";
            s["minimum"] = std::int64_t(p.minValue);
            s["maximum"] = std::int64_t(p.maxValue);
            s["default"] = std::int64_t(p.defaultValue[0]);
            break;
        case ParamType::String:
            s["type"] = "string";
            if (p.path == "id") {
                s["pattern"] = idPattern();
                s["maxLength"] = limits::kMaxIdBytes;
            } else if (p.path == "location.date") {
                // The calendar check itself (month lengths, 1800..2200) is the validator's.
                s["pattern"] = "^([0-9]{4}-[0-9]{2}-[0-9]{2})?$";
                s["default"] = std::string(p.defaultText);
            } else {
                s["maxLength"] = limits::kMaxStringBytes;
                s["default"] = std::string(p.defaultText);
            }
            break;
    }
    return s;
}

ojson objectSchema(ParamScope scope) {
    ojson s;
    s["type"] = "object";
    ojson props = ojson::object();
    ojson required = ojson::array();
    for (const ParamDesc& p : paramTable(scope)) {
        props[std::string(p.path)] = schemaFor(p);
        if (p.required) required.push_back(std::string(p.path));
    }
    s["properties"] = props;
    if (!required.empty()) s["required"] = required;
    s["additionalProperties"] = false;
    return s;
}

// The fewest and most numbers a key value array holds: 3 (Colour/Vec3),
// widened to 2 once an animatable Vec2 exists.
void keyArrayLengths(int& fewest, int& most) {
    fewest = most = 3;
    for (ParamScope scope :
         {ParamScope::Global, ParamScope::Volume, ParamScope::Emitter, ParamScope::CloudVolume}) {
        for (const ParamDesc& p : paramTable(scope)) {
            if (!p.animatable || p.type == ParamType::Scalar) continue;
            fewest = std::min(fewest, p.components());
            most = std::max(most, p.components());
        }
    }
}

ojson animatableNames(ParamScope scope) {
    ojson names = ojson::array();
    for (const ParamDesc& p : paramTable(scope))
        if (p.animatable) names.push_back(std::string(p.path));
    return names;
}

}  // namespace

std::string presetJsonSchema() {
    ojson root;
    root["$schema"] = "https://json-schema.org/draft/2020-12/schema";
    root["$id"] = "https://aerial.example/aerial-preset.schema.json";
    root["title"] = "Aerial time-of-day preset";
    root["description"] =
        "Generated from the parameter table (aerial::presetJsonSchema(); core/src/preset/param_table.cpp). "
        "Do not edit by hand.";
    root["type"] = "object";
    ojson props = ojson::object();
    props["version"] = {{"description", "File format version."}, {"const", kPresetVersion}};
    props["name"] = textSchema();
    props["description"] = textSchema();
    // Global groups, nested as in the file.
    for (const ParamDesc& p : paramTable(ParamScope::Global)) {
        ojson* node = &props;
        std::size_t start = 0;
        while (true) {
            const std::size_t dot = p.path.find('.', start);
            const std::string part(p.path.substr(start, dot == sv::npos ? sv::npos : dot - start));
            if (dot == sv::npos) {
                (*node)[part] = schemaFor(p);
                break;
            }
            ojson& group = (*node)[part];
            if (group.is_null()) {
                group["type"] = "object";
                group["properties"] = ojson::object();
                group["additionalProperties"] = false;
            }
            node = &group["properties"];
            start = dot + 1;
        }
    }
    props["volumes"] = arraySchema("#/$defs/volume", limits::kMaxVolumes);
    props["emitters"] = arraySchema("#/$defs/emitter", limits::kMaxEmitters);
    props["cloud_volumes"] = arraySchema("#/$defs/cloud_volume", limits::kMaxCloudVolumes);
    props["tracks"] = arraySchema("#/$defs/track", limits::kMaxTracks);
    props["weather"] = {{"type", "object"},
                        {"description",
                         "named weather states layered on the keys, and the regions where one holds "
                         "(aerial/weather_state.hpp)"},
                        {"properties",
                         {{"states", arraySchema("#/$defs/weather_state", limits::kMaxWeatherStates)},
                          {"regions", arraySchema("#/$defs/weather_region", limits::kMaxWeatherRegions)}}},
                        {"required", {"states"}},
                        {"additionalProperties", false}};
    const PresetView view;  // its defaults
    auto point = [](const glm::dvec3& fill, const char* description) {
        return ojson{
            {"type", "array"},
            {"items",
             {{"type", "number"}, {"minimum", -kViewMaxCoordinate}, {"maximum", kViewMaxCoordinate}}},
            {"minItems", 3},
            {"maxItems", 3},
            {"default", {fill.x, fill.y, fill.z}},
            {"description", description}};
    };
    props["view"] = {
        {"type", "object"},
        {"description",
         "the camera that frames the preset: aerial render's and the contact sheet's camera when none is "
         "given, the editor's on opening it (aerial/preset.hpp, PresetView); the eye and target at least "
         "0.01 m apart, up is +Y"},
        {"properties",
         {{"eye_m", point(view.eye, "Eye position [m], world (+Y up, -Z north, +X east)")},
          {"target_m", point(view.target, "A point the camera looks at [m], world")},
          {"fov_deg",
           {{"type", "number"},
            {"minimum", kViewMinFovDeg},
            {"maximum", kViewMaxFovDeg},
            {"default", view.verticalFovDeg},
            {"description", "Vertical field of view [deg]"}}}}},
        {"required", {"eye_m", "target_m"}},
        {"additionalProperties", false}};
    root["properties"] = props;
    root["required"] = {"version"};
    root["additionalProperties"] = false;

    ojson defs = ojson::object();
    defs["volume"] = objectSchema(ParamScope::Volume);
    defs["emitter"] = objectSchema(ParamScope::Emitter);
    defs["cloud_volume"] = objectSchema(ParamScope::CloudVolume);
    int fewest = 3, most = 3;
    keyArrayLengths(fewest, most);
    auto tangentSchema = [&](const char* what) {
        return ojson{{"oneOf",
                      {{{"type", "number"}},
                       {{"type", "array"},
                        {"items", {{"type", "number"}}},
                        {"minItems", fewest},
                        {"maxItems", most}}}},
                     {"description",
                      std::string(what) + " [value unit per h] in the value's shape (smooth segments)"}};
    };
    ojson key;
    key["type"] = "object";
    key["properties"] = {
        {"time_h", {{"type", "number"}, {"minimum", 0}, {"exclusiveMaximum", 24}}},
        {"value",
         {{"oneOf",
           {{{"type", "number"}},
            {{"type", "array"},
             {"items", {{"type", "number"}}},
             {"minItems", fewest},
             {"maxItems", most}}}}}},
        {"flat",
         {{"type", "boolean"},
          {"default", false},
          {"description",
           "smooth tracks: the curve is level at this key (tangent 0) instead of "
           "following its neighbours"}}},
        {"anchor",
         {{"enum", ojson::array()},
          {"description",
           "a key that follows the sun: its time is this event's at the preset's location "
           "and date plus offset_h (sunrise and sunset at -0.833 deg, civil -6, nautical -12)"}}},
        {"interpolation",
         {{"enum", {"step", "linear", "smooth"}},
          {"description",
           "the segment from this key to the next: this interpolation instead of the track's"}}},
        {"tangent_in", tangentSchema("the slope arriving at the key")},
        {"tangent_out", tangentSchema("the slope leaving the key")},
        {"tangent_mode",
         {{"enum", {"unified", "broken"}},
          {"default", "unified"},
          {"description",
           "unified: one slope through the key (tangent_in equals tangent_out); broken: two"}}},
        {"offset_h",
         {{"type", "number"},
          {"minimum", -12},
          {"maximum", 12},
          {"default", 0},
          {"description", "the anchored key's offset from its event [h]; negative is before it"}}}};
    for (SunEvent event : kSunEvents) key["properties"]["anchor"]["enum"].push_back(sunEventName(event));
    key["required"] = {"value"};
    // A key's own tangents give both slopes; tangent_mode only with them.
    key["dependentRequired"] = {{"tangent_in", {"tangent_out"}},
                                {"tangent_out", {"tangent_in"}},
                                {"tangent_mode", {"tangent_in", "tangent_out"}}};
    // A fixed time or a sun event, never both (offset_h only with an anchor).
    key["oneOf"] = {{{"required", {"time_h"}},
                     {"not", {{"anyOf", {{{"required", {"anchor"}}}, {{"required", {"offset_h"}}}}}}}},
                    {{"required", {"anchor"}}, {"not", {{"required", {"time_h"}}}}}};
    key["additionalProperties"] = false;
    defs["key"] = key;
    auto trackVariant = [&](const char* objectKey, ParamScope scope) {
        ojson t;
        t["type"] = "object";
        ojson tp = ojson::object();
        if (objectKey) tp[objectKey] = idSchema();
        tp["param"] = {{"enum", animatableNames(scope)}};
        tp["interpolation"] = {{"enum", {"step", "linear", "smooth"}}, {"default", "smooth"}};
        tp["wrap"] = {{"type", "boolean"},
                      {"default", true},
                      {"description",
                       "true: the day is cyclic (the last key runs into the next day's first); "
                       "false: hold the first key's value before it and the last key's after it"}};
        tp["keys"] = {{"type", "array"},
                      {"minItems", 1},
                      {"maxItems", limits::kMaxKeysPerTrack},
                      {"items", {{"$ref", "#/$defs/key"}}}};
        t["properties"] = tp;
        ojson req = ojson::array();
        if (objectKey) req.push_back(objectKey);
        req.push_back("param");
        req.push_back("keys");
        t["required"] = req;
        t["additionalProperties"] = false;
        return t;
    };
    defs["track"] = {{"oneOf",
                      {trackVariant(nullptr, ParamScope::Global), trackVariant("volume", ParamScope::Volume),
                       trackVariant("emitter", ParamScope::Emitter),
                       trackVariant("cloud_volume", ParamScope::CloudVolume)}}};
    // A weather override: a track's target and one of set / add / scale.
    auto overrideVariant = [&](const char* objectKey, const char* mode) {
        ojson o;
        o["type"] = "object";
        ojson op = ojson::object();
        if (objectKey) op[objectKey] = idSchema();
        op["param"] = {{"$ref", std::string("#/$defs/animatable_") + (objectKey ? objectKey : "global")}};
        op[mode] = {
            {"oneOf",
             {{{"type", "number"}},
              {{"type", "array"}, {"items", {{"type", "number"}}}, {"minItems", 2}, {"maxItems", 3}}}}};
        o["properties"] = op;
        ojson req = ojson::array();
        if (objectKey) req.push_back(objectKey);
        req.push_back("param");
        req.push_back(mode);
        o["required"] = req;
        o["additionalProperties"] = false;
        return o;
    };
    defs["animatable_global"] = {{"enum", animatableNames(ParamScope::Global)}};
    defs["animatable_volume"] = {{"enum", animatableNames(ParamScope::Volume)}};
    defs["animatable_emitter"] = {{"enum", animatableNames(ParamScope::Emitter)}};
    defs["animatable_cloud_volume"] = {{"enum", animatableNames(ParamScope::CloudVolume)}};
    ojson overrideVariants = ojson::array();
    for (const char* mode : {"set", "add", "scale"}) {
        for (const char* objectKey : {static_cast<const char*>(nullptr), "volume", "emitter", "cloud_volume"})
            overrideVariants.push_back(overrideVariant(objectKey, mode));
    }
    defs["weather_override"] = {{"oneOf", overrideVariants}};
    defs["weather_state"] = {
        {"type", "object"},
        {"properties",
         {{"name", {{"allOf", {idSchema(), {{"not", {{"const", "none"}}}}}}}},
          {"overrides", arraySchema("#/$defs/weather_override", limits::kMaxWeatherOverrides)}}},
        {"required", {"name", "overrides"}},
        {"additionalProperties", false}};
    auto numbers = [](int count, double lo, double hi, double fill, const char* description) {
        ojson def = ojson::array();
        for (int i = 0; i < count; ++i) def.push_back(fill);
        return ojson{{"type", "array"},   {"items", {{"type", "number"}, {"minimum", lo}, {"maximum", hi}}},
                     {"minItems", count}, {"maxItems", count},
                     {"default", def},    {"description", description}};
    };
    const WeatherRegion region;  // its defaults
    ojson rotation =
        numbers(4, -1.000001, 1.000001, 0.0, "Rotation, world from object, unit quaternion [x, y, z, w]");
    rotation["default"] = {0, 0, 0, 1};
    ojson state = idSchema();
    state["description"] = "the state that holds inside: one of weather.states' names, or \"none\"";
    defs["weather_region"] = {
        {"type", "object"},
        {"description",
         "a box or ellipsoid where a weather state holds, blended over blend_m inwards from its surface "
         "(aerial/weather_state.hpp)"},
        {"properties",
         {{"id", idSchema()},
          {"name", textSchema()},
          {"shape", {{"enum", {"box", "ellipsoid"}}, {"default", "box"}}},
          {"position_m", numbers(3, -kWeatherRegionMaxCoordinate, kWeatherRegionMaxCoordinate, 0.0,
                                 "Centre [m], world (+Y up, -Z north, +X east)")},
          {"rotation_xyzw", rotation},
          {"half_extents_m", numbers(3, kWeatherRegionMinHalfExtent, kWeatherRegionMaxHalfExtent,
                                     region.halfExtents.x, "Half extents along the object axes [m]")},
          {"blend_m",
           {{"type", "number"},
            {"minimum", 0},
            {"maximum", kWeatherRegionMaxBlend},
            {"default", region.blend},
            {"description", "Width of the soft edge [m], inwards from the surface; 0 a hard edge"}}},
          {"priority",
           {{"type", "integer"},
            {"minimum", -kWeatherRegionMaxPriority},
            {"maximum", kWeatherRegionMaxPriority},
            {"default", 0},
            {"description", "Higher over lower; equal ones in file order, the later over the earlier"}}},
          {"state", state}}},
        {"required", {"id", "state"}},
        {"additionalProperties", false}};
    root["$defs"] = defs;
    return root.dump(2) + "\n";
}

}  // namespace aerial
