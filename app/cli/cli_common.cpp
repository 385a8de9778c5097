// cli_common.cpp — see cli_common.hpp.
#include "cli_common.hpp"

#include <aerial/weather.hpp>
#include <aerial/clock.hpp>
#include <aerial/detail/file_system.hpp>
#include <aerial/limits.hpp>

#include <aerial/atmosphere.hpp>

#include <fcntl.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <system_error>
#include <vector>

namespace aerial::cli {

void usageError(const std::string& message) { throw CommandError(kExitUsageError, message); }
void dataError(const std::string& message) { throw CommandError(kExitDataError, message); }

std::string helpFooter(const std::string& examples) {
    return "\nExample" + std::string(examples.find('\n') != std::string::npos ? "s" : "") + ":\n" + examples +
           "\n\nExit codes: 0 success; 1 bad input or data (missing file, invalid preset, I/O error);\n"
           "2 bad command line (unknown flag, bad value). Errors print one line on stderr.";
}

const CLI::Validator& finiteNumber() {
    static const CLI::Validator check(
        [](std::string& text) {
            double value = 0.0;
            return parseNumber(text, value) ? std::string() : "\"" + text + "\" is not a finite number";
        },
        "FINITE");
    return check;
}

CLI::Option* addTimeOption(CLI::App& app, std::string& text) {
    text = "12:00";
    return app.add_option("--time,-t", text, "Local solar time: HH:MM (00:00..23:59) or hours in [0, 24)")
        ->type_name("TIME")
        ->capture_default_str();
}

// ---------------------------------------------------------------------------
// Parsing

namespace {

std::string trim(const std::string& text) {
    std::size_t begin = 0, end = text.size();
    while (begin < end && std::isspace(static_cast<unsigned char>(text[begin]))) ++begin;
    while (end > begin && std::isspace(static_cast<unsigned char>(text[end - 1]))) --end;
    return text.substr(begin, end - begin);
}

std::vector<std::string> split(const std::string& text, char separator) {
    std::vector<std::string> parts;
    std::size_t start = 0;
    for (;;) {
        const std::size_t at = text.find(separator, start);
        parts.push_back(text.substr(start, at == std::string::npos ? std::string::npos : at - start));
        if (at == std::string::npos) return parts;
        start = at + 1;
    }
}

bool parseDigits(const std::string& text, int maxDigits, int& out) {
    if (text.empty() || int(text.size()) > maxDigits) return false;
    out = 0;
    for (char c : text) {
        if (c < '0' || c > '9') return false;
        out = out * 10 + (c - '0');
    }
    return true;
}

/// Strips a unit suffix (case-insensitive) if present.
bool stripSuffix(std::string& text, const std::string& suffix) {
    if (text.size() <= suffix.size()) return false;
    const std::string tail = text.substr(text.size() - suffix.size());
    for (std::size_t i = 0; i < suffix.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(tail[i])) != suffix[i]) return false;
    text = trim(text.substr(0, text.size() - suffix.size()));
    return true;
}

std::string quoted(const std::string& text) { return "\"" + text + "\""; }

}  // namespace

bool parseNumber(const std::string& text, double& out) {
    const std::string t = trim(text);
    if (t.empty()) return false;
    // Only decimal numbers: no "nan", "inf" or hex floats.
    for (char c : t)
        if (!(std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '+' || c == 'e' ||
              c == 'E'))
            return false;
    char* end = nullptr;
    out = std::strtod(t.c_str(), &end);
    return end == t.c_str() + t.size() && std::isfinite(out);
}

double parseTimeOfDay(const std::string& text, const std::string& option) {
    double hours = 0.0;
    if (!parseClock(text, hours))
        usageError(option + ": " + quoted(text) +
                   " is not a time of day (HH:MM with HH 00..23 and MM 00..59, or hours in [0, 24))");
    return hours;
}

double parseStepHours(const std::string& text, const std::string& option) {
    std::string t = trim(text);
    double scale = 1.0;  // to hours
    if (stripSuffix(t, "min") || stripSuffix(t, "m"))
        scale = 1.0 / 60.0;
    else
        stripSuffix(t, "h");
    double value = 0.0;
    if (!parseNumber(t, value))
        usageError(option + ": " + quoted(text) +
                   " is not a duration (hours like 0.5 or 0.5h, or minutes like 30m)");
    const double hours = value * scale;
    if (!(hours >= 1.0 / 60.0 - 1e-12) || hours > 24.0)
        usageError(option + ": " + quoted(text) + " is out of range (1 minute to 24 hours)");
    return hours;
}

glm::dvec3 parseVec3(const std::string& text, const std::string& option) {
    const std::vector<std::string> parts = split(text, ',');
    glm::dvec3 v(0.0);
    bool ok = parts.size() == 3;
    for (std::size_t i = 0; ok && i < 3; ++i) ok = parseNumber(parts[i], v[int(i)]);
    if (!ok) usageError(option + ": " + quoted(text) + " is not three finite numbers x,y,z");
    for (int i = 0; i < 3; ++i)
        if (std::abs(v[i]) > 1e7)
            usageError(option + ": " + quoted(text) + " is out of range (|x|, |y|, |z| <= 1e7)");
    return v;
}

glm::dvec3 parseDirection(const std::string& text, const std::string& option) {
    const glm::dvec3 v = parseVec3(text, option);
    const double length = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    if (!(length > 1e-12))
        usageError(option + ": " + quoted(text) + " has zero length; a direction is needed");
    return v / length;
}

void parseTableSize(const std::string& text, const std::string& option, int& azimuthCount,
                    int& elevationCount) {
    const std::string t = trim(text);
    const std::size_t x = t.find_first_of("xX");
    // The caps of aerial/limits.hpp (kMaxSkyAzimuthCount, kMaxSkyElevationCount).
    const std::string why = option + ": " + quoted(text) +
                            " is not a table size WxH (azimuth columns 4..4096 x elevation rows 2..2048)";
    static_assert(limits::kMaxSkyAzimuthCount == 4096 && limits::kMaxSkyElevationCount == 2048);
    if (x == std::string::npos) usageError(why);
    int w = 0, h = 0;
    if (!parseDigits(trim(t.substr(0, x)), 5, w) || !parseDigits(trim(t.substr(x + 1)), 5, h))
        usageError(why);
    if (w < 4 || w > limits::kMaxSkyAzimuthCount || h < 2 || h > limits::kMaxSkyElevationCount)
        usageError(why);
    azimuthCount = w;
    elevationCount = h;
}

void parseImageSize(const std::string& text, const std::string& option, int maxSide, int& width,
                    int& height) {
    const std::string t = trim(text);
    const std::size_t x = t.find_first_of("xX");
    const std::string why = option + ": " + quoted(text) + " is not an image size WxH (each side 1.." +
                            std::to_string(maxSide) + " pixels)";
    if (x == std::string::npos) usageError(why);
    int w = 0, h = 0;
    if (!parseDigits(trim(t.substr(0, x)), 5, w) || !parseDigits(trim(t.substr(x + 1)), 5, h))
        usageError(why);
    if (w < 1 || w > maxSide || h < 1 || h > maxSide) usageError(why);
    width = w;
    height = h;
}

// ---------------------------------------------------------------------------
// Files

std::string errnoText(int error) { return std::generic_category().message(error); }

bool syncPath(const std::filesystem::path& path, bool directory) {
    const int fd = ::open(path.c_str(), directory ? (O_RDONLY | O_DIRECTORY) : O_RDONLY);
    if (fd < 0) return false;
    const bool ok = ::fsync(fd) == 0;
    ::close(fd);
    return ok;
}

void writeAtomically(const std::filesystem::path& path,
                     const std::function<void(const std::filesystem::path& temp)>& write) {
    // Through core's atomic writer (and its fault-injection seam): the
    // temporary is ".NAME.tmp-PID-XXXXXX", fsync'ed, renamed over `path`,
    // and removed on any failure.
    std::exception_ptr thrown;
    const std::string why =
        detail::writeFileAtomicallyWith(path.string(), [&](const std::string& temp) -> std::string {
            try {
                write(temp);
                return {};
            } catch (...) {
                thrown = std::current_exception();
                return "failed";
            }
        });
    if (thrown) std::rethrow_exception(thrown);
    if (!why.empty()) dataError(why);
}

void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes) {
    const std::string why = detail::writeFileAtomically(path.string(), bytes);
    if (!why.empty()) dataError(why);
}

// ---------------------------------------------------------------------------
// Presets

std::string formatIssue(const PresetIssue& issue) {
    std::string s = issue.file.empty() ? std::string("<preset>") : issue.file;
    if (issue.line > 0) s += ":" + std::to_string(issue.line) + ":" + std::to_string(issue.column);
    s += ": ";
    if (issue.severity == PresetIssue::Severity::Warning) s += "warning: ";
    if (!issue.pointer.empty()) s += issue.pointer + ": ";
    s += issue.message;
    return s;
}

Preset loadPresetOrFail(const std::string& path, const std::string& command) {
    if (path == kDefaultPresetName) return defaultPreset();
    PresetLoadResult result = loadPreset(path);
    for (const PresetIssue& w : result.warnings)
        std::cerr << "aerial " << command << ": " << formatIssue(w) << "\n";
    if (!result.ok()) {
        std::string message =
            result.errors.empty() ? path + ": cannot load preset" : formatIssue(result.errors[0]);
        if (result.errors.size() > 1)
            message += " (and " + std::to_string(result.errors.size() - 1) + " more; see aerial validate " +
                       path + ")";
        dataError(message);
    }
    return std::move(*result.preset);
}

// ---------------------------------------------------------------------------
// Text and JSON

std::string formatTime(double hours) { return formatClock(hours); }

Json toJson(const glm::dvec3& v) { return Json::array({v.x, v.y, v.z}); }

namespace {

/// A parameter's value as JSON, as the preset file spells it.
Json paramValueToJson(const ParamDesc& p, void* object) {
    switch (p.type) {
        case ParamType::Scalar:
            return *p.scalar(object);
        case ParamType::Colour:
        case ParamType::Vec3:
            return toJson(*p.vec3(object));
        case ParamType::Vec2: {
            const glm::dvec2& v = *p.vec2(object);
            return Json::array({v.x, v.y});
        }
        case ParamType::Quaternion: {
            const glm::dquat& q = *p.quat(object);
            return Json::array({q.x, q.y, q.z, q.w});
        }
        case ParamType::Enum: {
            const std::int64_t v = p.getInt(object);
            if (v >= 0 && std::size_t(v) < p.enumNames.size())
                return std::string(p.enumNames[std::size_t(v)]);
            return v;
        }
        case ParamType::Int:
            return p.getInt(object);
        case ParamType::String:
            return *p.string(object);
    }
    return nullptr;
}

template <class Object>
Json flatParametersToJson(ParamScope scope, const Object& object) {
    Json out = Json::object();
    for (const ParamDesc& p : paramTable(scope))
        out[std::string(p.path)] = paramValueToJson(p, paramObject(p, const_cast<Object&>(object)));
    return out;
}

std::string formatNumber(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", v);
    return text;
}

}  // namespace

Json parametersToJson(const Environment& environment) {
    Json out = Json::object();
    for (const ParamDesc& p : paramTable(ParamScope::Global)) {
        std::string pointer = "/" + std::string(p.path);
        for (char& c : pointer)
            if (c == '.') c = '/';
        out[Json::json_pointer(pointer)] =
            paramValueToJson(p, paramObject(p, const_cast<Environment&>(environment)));
    }
    return out;
}

Json parametersToJson(const FogVolume& volume) { return flatParametersToJson(ParamScope::Volume, volume); }

Json parametersToJson(const Emitter& emitter) { return flatParametersToJson(ParamScope::Emitter, emitter); }

Json parametersToJson(const CloudVolume& volume) {
    return flatParametersToJson(ParamScope::CloudVolume, volume);
}

std::string formatParam(const ParamDesc& p, const void* object) {
    const Json v = paramValueToJson(p, const_cast<void*>(object));
    if (v.is_string()) return v.get<std::string>();
    if (v.is_number_integer()) return std::to_string(v.get<std::int64_t>());
    if (v.is_number()) return formatNumber(v.get<double>());
    if (v.is_array()) {
        std::string s = "(";
        for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + formatNumber(v[i].get<double>());
        return s + ")";
    }
    return v.dump();
}

Json lightToJson(const LightState& light) {
    return {{"elevation_deg", light.body.elevation * kDegreesPerRadian},
            {"apparent_elevation_deg", light.body.apparentElevation * kDegreesPerRadian},
            {"azimuth_deg", light.body.azimuth * kDegreesPerRadian},
            {"direction", toJson(light.body.direction)},
            {"apparent_direction", toJson(light.body.apparentDirection)},
            {"illuminated_fraction", light.body.illuminatedFraction},
            {"bright_limb_angle_deg", light.body.brightLimbAngle * kDegreesPerRadian},
            {"phase_irradiance", light.body.phaseIrradiance},
            {"illuminance_space_rgb", toJson(light.illuminanceSpace)},
            {"transmittance_rgb", toJson(light.transmittance)},
            {"illuminance_rgb", toJson(light.illuminance)}};
}

Json lightReportToJson(const LightReport& light) {
    const HorizontalIlluminance& e = light.horizontalIlluminanceLux;
    return {{"horizontal_illuminance_lux",
             {{"sun", e.sun}, {"sky", e.sky}, {"moon", e.moon}, {"night", e.night}, {"total", e.total}}},
            {"zenith_luminance_cd_m2", light.zenithLuminance}};
}

Json stateToJson(const PresetState& state) {
    Json volumes = Json::array();
    for (const FogVolume& v : state.volumes) volumes.push_back(parametersToJson(v));
    Json emitters = Json::array();
    for (std::size_t i = 0; i < state.emitters.size(); ++i) {
        Json e = parametersToJson(state.emitters[i]);
        e["flash"] = i < state.emitterFlash.size() ? state.emitterFlash[i] : 1.0;
        emitters.push_back(std::move(e));
    }
    Json cloudVolumes = Json::array();
    for (const CloudVolume& v : state.cloudVolumes) cloudVolumes.push_back(parametersToJson(v));
    const double julianDayUt = julianDayAt(state.environment.location, state.timeHours);
    return {{"time_h", state.timeHours},
            {"time", formatTime(state.timeHours)},
            {"julian_day_ut", std::isfinite(julianDayUt) ? Json(julianDayUt) : Json(nullptr)},
            {"sun", lightToJson(state.sunLight)},
            {"moon", lightToJson(state.moonLight)},
            {"parameters", parametersToJson(state.environment)},
            {"volumes", std::move(volumes)},
            {"emitters", std::move(emitters)},
            {"cloud_volumes", std::move(cloudVolumes)}};
}

namespace {

bool isFlatArray(const Json& json) {
    if (!json.is_array() || json.empty()) return false;
    for (const Json& element : json)
        if (element.is_structured()) return false;
    return true;
}

void appendJson(std::string& out, const Json& json, int indent) {
    const std::string pad(std::size_t(indent + 2), ' ');
    if (json.is_object() && !json.empty()) {
        out += "{\n";
        std::size_t i = 0;
        for (auto it = json.begin(); it != json.end(); ++it, ++i) {
            out += pad + Json(it.key()).dump() + ": ";
            appendJson(out, it.value(), indent + 2);
            out += i + 1 < json.size() ? ",\n" : "\n";
        }
        out += std::string(std::size_t(indent), ' ') + "}";
    } else if (json.is_array() && !json.empty() && !isFlatArray(json)) {
        out += "[\n";
        for (std::size_t i = 0; i < json.size(); ++i) {
            out += pad;
            appendJson(out, json[i], indent + 2);
            out += i + 1 < json.size() ? ",\n" : "\n";
        }
        out += std::string(std::size_t(indent), ' ') + "]";
    } else if (isFlatArray(json)) {
        out += "[";
        for (std::size_t i = 0; i < json.size(); ++i) out += (i ? ", " : "") + json[i].dump();
        out += "]";
    } else {
        out += json.dump();
    }
}

}  // namespace

std::string jsonText(const Json& json) {
    std::string out;
    appendJson(out, json, 0);
    return out;
}

void printJson(const Json& json) { std::cout << jsonText(json) << "\n"; }

// ---------------------------------------------------------------------------
// Sky and fog

SkyTables::SkyTables(const SkySolverDesc& desc)
    : sun_(std::make_unique<SpectralSkySolver>(desc)), moon_(std::make_unique<SpectralSkySolver>(desc)) {}

void SkyTables::solve(const PresetState& state) {
    const AtmosphereParams& air = state.environment.atmosphere;
    sun_->solve(air, state.sunLight.body.direction);
    moon_->solve(air, state.moonLight.body.direction);
}

glm::dvec3 tableSkyRadiance(const PresetState& state, const SkyTables& tables, const glm::dvec3& direction) {
    const double g = state.environment.atmosphere.mieAnisotropy;
    return skyRadiance(tables.sun(), g, direction, state.sunLight.illuminanceSpace) +
           skyRadiance(tables.moon(), g, direction, state.moonLight.illuminanceSpace);
}

// ---------------------------------------------------------------------------
// Weather

Json weatherFromOptions(const Preset& preset, const std::string& weather, const std::string& transition,
                        WeatherMix& mix) {
    auto known = [&](const std::string& name, const char* option) {
        if (name == "none" || std::any_of(preset.weather.begin(), preset.weather.end(),
                                          [&](const WeatherState& s) { return s.name == name; }))
            return;
        std::string list = "none";
        for (const WeatherState& s : preset.weather) list += ", " + s.name;
        usageError(std::string(option) + ": the preset has no weather state \"" + name + "\" (it has " + list + ")");
    };
    if (!weather.empty() && !transition.empty())
        usageError("--weather and --transition: give one of them");
    if (!weather.empty()) {
        known(weather, "--weather");
        settledWeather(preset, weather, mix);
        return weather;
    }
    if (transition.empty()) return nullptr;
    const std::size_t a = transition.find(':'), b = transition.rfind(':');
    if (a == std::string::npos || a == b)
        usageError("--transition: expected FROM:TO:FRACTION (e.g. clear:storm:0.5), got \"" + transition + "\"");
    const std::string from = transition.substr(0, a), to = transition.substr(a + 1, b - a - 1);
    const std::string fraction = transition.substr(b + 1);
    char* end = nullptr;
    const double f = std::strtod(fraction.c_str(), &end);
    if (fraction.empty() || *end != '\0' || !(f >= 0.0 && f <= 1.0))
        usageError("--transition: the fraction \"" + fraction + "\" is not a number from 0 to 1");
    known(from, "--transition");
    known(to, "--transition");
    transitionWeather(preset, from, to, f, mix);
    return {{"from", from}, {"to", to}, {"fraction", f}, {"weights", weatherMixToJson(preset, mix)}};
}

Json weatherMixToJson(const Preset& preset, const WeatherMix& mix) {
    Json weights = Json::object();
    for (std::size_t i = 0; i < preset.weather.size(); ++i) {
        Json w = Json::object();
        for (int c = 0; c < kWeatherCategoryCount; ++c)
            w[weatherCategoryName(WeatherCategory(c))] =
                i < mix.weights.size() ? mix.weights[i][std::size_t(c)] : 0.0;
        weights[preset.weather[i].name] = w;
    }
    return weights;
}

Json weatherRegionsToJson(const Preset& preset, const glm::dvec3* camera) {
    Json regions = Json::array();
    for (const WeatherRegion& r : preset.weatherRegions) {
        Json j = {{"id", r.id},
                  {"name", r.name},
                  {"shape", r.shape == WeatherRegionShape::Ellipsoid ? "ellipsoid" : "box"},
                  {"position_m", toJson(r.position)},
                  {"rotation_xyzw", Json::array({r.rotation.x, r.rotation.y, r.rotation.z, r.rotation.w})},
                  {"half_extents_m", toJson(r.halfExtents)},
                  {"blend_m", r.blend},
                  {"priority", r.priority},
                  {"state", r.state}};
        if (camera) j["weight"] = weatherRegionWeight(r, *camera);
        regions.push_back(std::move(j));
    }
    return regions;
}

}  // namespace aerial::cli
