// command_eval.cpp — `aerial eval PRESET --time T [--json]`: the preset's
// complete state at one time of day (CompiledPreset::evaluate). PRESET may be
// `default` (aerial::defaultPreset()).
//
// --json prints stateToJson (cli_common.hpp) plus the preset's file and name:
//   {"preset": {"file", "name"}, "time_h", "time",
//    "julian_day_ut" (the instant of a dated preset, aerial/sun.hpp; null
//    when undated),
//    "sun": {"elevation_deg" (geometric, topocentric),
//            "apparent_elevation_deg" (with standard refraction: Saemundsson,
//            Meeus 16.4), "azimuth_deg" (from north through east, north
//            offset included), "direction", "apparent_direction",
//            "illuminated_fraction", "bright_limb_angle_deg" (moon: from the
//            zenith through east), "phase_irradiance", "illuminance_space_rgb",
//            "transmittance_rgb", "illuminance_rgb"},
//    "moon": {...},
//    "light": {"horizontal_illuminance_lux": {"sun", "sky", "moon", "night",
//              "total"}, "zenith_luminance_cd_m2"} (aerial/photometry.hpp: the
//              sky tables solved for this moment, 128 x 64; left out with
//              --no-light),
//    "parameters": {every global parameter, nested as in the preset file},
//    "volumes": [{every volume parameter}], "emitters": [{every emitter
//    parameter, "flash"}], "cloud_volumes": [{every cloud volume parameter}],
//    "sun_events": {"sunrise", "noon", ...: {"time_h", "time"}} (that day,
//    aerial/sun.hpp sunEventHours), "anchored_keys": [{"track", "key",
//    "anchor", "offset_h", "time_h", "time"}] (the keys that follow the sun,
//    where they fall that day),
//    "weather": {"states": [{"name", "overrides": [{"target", "mode",
//    "value", "category"}]}], "applied": "STATE" or {"from", "to",
//    "fraction", "weights": {state: {category: weight}}},
//    "regions": [{"id", "name", "shape", "position_m", "rotation_xyzw",
//    "half_extents_m", "blend_m", "priority", "state", "weight" (with
//    --camera: the region's weight there)}],
//    "camera": {"position_m", "weights": {state: {category: weight}}} (with
//    --camera: the mix evaluated, the regions applied)}}
// --weather STATE applies a weather state fully (aerial/weather.hpp);
// --transition A:B:F the weather a fraction F (0..1) of the way through a
// change from A to B, each category at its own speed ("none" names the keyed
// values alone in both). --camera X,Y,Z [m] applies the preset's weather
// regions at that point on top of that global weather (regionalWeather).
// Keyed values are applied; emitter intensities include the lightning flash.
// Without --json: a readable summary, one parameter per line with its unit.
#include "cli_common.hpp"

#include <aerial/clock.hpp>
#include <aerial/photometry.hpp>
#include <aerial/weather.hpp>

#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

namespace aerial::cli {
namespace {

struct EvalOptions {
    std::string preset;
    std::string time;
    bool json = false;
    bool light = true;
    std::string weather;
    std::string transition;
    std::string camera;  ///< "x,y,z" [m]; empty: no regions applied
};

void printLight(const char* name, const LightState& light) {
    const CelestialBody& b = light.body;
    std::printf("%-6s elevation %7.3f deg   azimuth %7.3f deg   direction (%.4f, %.4f, %.4f)\n", name,
                b.elevation * kDegreesPerRadian, b.azimuth * kDegreesPerRadian, b.direction.x, b.direction.y,
                b.direction.z);
    std::printf(
        "%-6s illuminance (%.6g, %.6g, %.6g) = above the atmosphere (%.6g, %.6g, %.6g) x "
        "transmittance (%.4f, %.4f, %.4f)",
        "", light.illuminance.x, light.illuminance.y, light.illuminance.z, light.illuminanceSpace.x,
        light.illuminanceSpace.y, light.illuminanceSpace.z, light.transmittance.x, light.transmittance.y,
        light.transmittance.z);
    if (b.illuminatedFraction < 1.0) std::printf("; %.0f %% lit", b.illuminatedFraction * 100.0);
    std::printf("\n");
}

template <class Object>
void printParameters(ParamScope scope, const Object& object, const char* indent) {
    for (const ParamDesc& p : paramTable(scope)) {
        if (p.path == "id" || p.path == "name") continue;  // ids and names are in the heading
        const std::string value = formatParam(p, &object);
        std::printf("%s%-40s %-36s %s\n", indent, std::string(p.path).c_str(), value.c_str(),
                    std::string(p.unit).c_str());
    }
}

/// "fog.density_per_m", or "volume valley_fog density_per_m".
std::string describeTarget(const TrackTarget& target) {
    switch (target.scope) {
        case ParamScope::Volume: return "volume " + target.objectId + " " + target.param;
        case ParamScope::Emitter: return "emitter " + target.objectId + " " + target.param;
        case ParamScope::CloudVolume: return "cloud_volume " + target.objectId + " " + target.param;
        case ParamScope::Global: break;
    }
    return target.param;
}

/// The day's sun events and the keys that follow them, resolved at the
/// preset's location and date: {"sun_events": {event: {"time_h", "time"}},
/// "anchored_keys": [{"track", "key", "anchor", "offset_h", "time_h",
/// "time"}]}.
Json anchorsToJson(const Preset& preset) {
    Json events = Json::object();
    for (SunEvent e : kSunEvents) {
        const double t = sunEventHours(preset.environment.location, e);
        events[sunEventName(e)] = {{"time_h", t}, {"time", formatTime(t)}};
    }
    Json keys = Json::array();
    for (const Track& track : preset.tracks) {
        for (std::size_t k = 0; k < track.keys.size(); ++k) {
            const TrackKey& key = track.keys[k];
            if (!key.anchor) continue;
            keys.push_back({{"track", describeTarget(track.target)},
                            {"key", k},
                            {"anchor", sunEventName(*key.anchor)},
                            {"offset_h", key.offsetHours},
                            {"time_h", key.timeHours},
                            {"time", formatTime(key.timeHours)}});
        }
    }
    return {{"sun_events", events}, {"anchored_keys", keys}};
}

void printAnchors(const Preset& preset) {
    std::printf("sun    ");
    for (SunEvent e : kSunEvents)
        std::printf(" %s %s", sunEventName(e), formatTime(sunEventHours(preset.environment.location, e)).c_str());
    std::printf("\n");
    for (const Track& track : preset.tracks) {
        for (const TrackKey& key : track.keys) {
            if (!key.anchor) continue;
            std::printf("key    %s at %s = %s %c %s\n", describeTarget(track.target).c_str(),
                        formatTime(key.timeHours).c_str(), sunEventName(*key.anchor),
                        key.offsetHours < 0.0 ? '-' : '+', formatClock(std::abs(key.offsetHours)).c_str());
        }
    }
}

/// The preset's weather states and regions, what --weather / --transition
/// applied and, with --camera, the mix there.
Json weatherToJson(const Preset& preset, const Json& applied, const glm::dvec3* camera,
                   const WeatherMix& mix) {
    Json states = Json::array();
    for (const WeatherState& s : preset.weather) {
        Json overrides = Json::array();
        for (const WeatherOverride& o : s.overrides) {
            const ParamDesc* p = findParam(o.target.scope, o.target.param);
            const int count = !p || p->components() == 1 ? 1 : p->components();
            Json value = count == 1 ? Json(o.value.x) : Json::array();
            for (int c = 0; c < count && count > 1; ++c) value.push_back(o.value[c]);
            overrides.push_back({{"target", describeTarget(o.target)},
                                 {"mode", o.mode == WeatherOverrideMode::Add     ? "add"
                                          : o.mode == WeatherOverrideMode::Scale ? "scale"
                                                                                 : "set"},
                                 {"value", value},
                                 {"category", weatherCategoryName(weatherCategory(o.target))}});
        }
        states.push_back({{"name", s.name}, {"overrides", overrides}});
    }
    Json out = {{"states", states}, {"applied", applied}, {"regions", weatherRegionsToJson(preset, camera)}};
    if (camera) out["camera"] = {{"position_m", toJson(*camera)}, {"weights", weatherMixToJson(preset, mix)}};
    return out;
}

int runEval(const EvalOptions& options) {
    const double t = parseTimeOfDay(options.time, "--time");
    Preset preset = loadPresetOrFail(options.preset, "eval");
    const std::string name = preset.name;
    const CompiledPreset compiled(std::move(preset));
    WeatherMix mix;
    const Json applied = weatherFromOptions(compiled.preset(), options.weather, options.transition, mix);
    std::optional<glm::dvec3> camera;
    if (!options.camera.empty()) {
        camera = parseVec3(options.camera, "--camera");
        regionalWeather(compiled.preset(), *camera, mix, mix);  // the global weather, then the regions there
    }
    PresetState state;
    compiled.evaluate(t, mix, state);
    // The light report needs both sky tables (a solve of ~1 ms, and the
    // atmosphere's tables the first time, ~20 ms): --no-light skips it for
    // scripts that only read positions and parameters.
    std::optional<LightReport> light;
    if (options.light) {
        SkyTables tables;
        tables.solve(state);
        light = lightReport(state, tables.sun(), tables.moon());
    }

    if (options.json) {
        Json out = {{"preset", {{"file", options.preset}, {"name", name}}}};
        out.update(stateToJson(state));
        if (light) out["light"] = lightReportToJson(*light);
        out.update(anchorsToJson(compiled.preset()));
        out["weather"] = weatherToJson(compiled.preset(), applied, camera ? &*camera : nullptr, mix);
        printJson(out);
        return kExitOk;
    }
    std::printf("%s (%s) at %s\n\n", name.c_str(), options.preset.c_str(),
                formatTime(state.timeHours).c_str());
    printLight("sun", state.sunLight);
    printLight("moon", state.moonLight);
    if (light) {
        const HorizontalIlluminance& lux = light->horizontalIlluminanceLux;
        std::printf("light  on the ground %.4g lx (sun %.4g, sky %.4g, moon %.4g, night sky %.4g); "
                    "zenith %.4g cd/m^2\n",
                    lux.total, lux.sun, lux.sky, lux.moon, lux.night, light->zenithLuminance);
    }
    printAnchors(compiled.preset());
    if (!compiled.preset().weather.empty()) {
        std::printf("weather");
        for (const WeatherState& s : compiled.preset().weather) std::printf(" %s", s.name.c_str());
        std::printf(applied.is_null() ? " (none applied)\n" : " (applied: %s)\n",
                    applied.is_string() ? applied.get<std::string>().c_str() : options.transition.c_str());
    }
    for (const WeatherRegion& r : compiled.preset().weatherRegions) {
        std::printf(
            "region %s \"%s\": %s at (%g, %g, %g) m, half extents (%g, %g, %g) m, blend %g m, priority %d, "
            "state %s",
            r.id.c_str(), r.name.c_str(), r.shape == WeatherRegionShape::Ellipsoid ? "ellipsoid" : "box",
            r.position.x, r.position.y, r.position.z, r.halfExtents.x, r.halfExtents.y, r.halfExtents.z,
            r.blend, r.priority, r.state.c_str());
        if (camera) std::printf("; weight %.4g at the camera", weatherRegionWeight(r, *camera));
        std::printf("\n");
    }
    if (camera && !compiled.preset().weather.empty()) {
        std::printf("camera (%g, %g, %g) m: weather", camera->x, camera->y, camera->z);
        for (std::size_t i = 0; i < compiled.preset().weather.size(); ++i) {
            // The clouds' weight stands for the state's (categories differ only within a transition).
            const double w =
                i < mix.weights.size() ? mix.weights[i][std::size_t(WeatherCategory::Clouds)] : 0.0;
            std::printf(" %s %.4g", compiled.preset().weather[i].name.c_str(), w);
        }
        std::printf(" (clouds' weights; --json has every category)\n");
    }
    std::printf("\nparameters\n");
    printParameters(ParamScope::Global, state.environment, "  ");
    for (const FogVolume& v : state.volumes) {
        std::printf("\nvolume %s \"%s\"\n", v.id.c_str(), v.name.c_str());
        printParameters(ParamScope::Volume, v, "  ");
    }
    for (std::size_t i = 0; i < state.emitters.size(); ++i) {
        const Emitter& e = state.emitters[i];
        const double flash = i < state.emitterFlash.size() ? state.emitterFlash[i] : 1.0;
        std::printf("\nemitter %s \"%s\" (flash x%.3g applied to the intensity; colour of unit luminance)\n", e.id.c_str(),
                    e.name.c_str(), flash);
        printParameters(ParamScope::Emitter, e, "  ");
    }
    for (const CloudVolume& v : state.cloudVolumes) {
        std::printf("\ncloud volume %s \"%s\"\n", v.id.c_str(), v.name.c_str());
        printParameters(ParamScope::CloudVolume, v, "  ");
    }
    return kExitOk;
}

}  // namespace

Command addEvalCommand(CLI::App& parent) {
    auto options = std::make_shared<EvalOptions>();
    CLI::App* app = parent.add_subcommand(
        "eval",
        "The preset at a time of day: sun, moon, every parameter, volumes, emitters and cloud volumes");
    app->add_option("preset", options->preset, "Preset file (JSON), or `default` for the built-in preset")
        ->required()
        ->type_name("PRESET");
    addTimeOption(*app, options->time);
    app->add_flag("--json", options->json, "Machine-readable output");
    app->add_flag("--light,!--no-light", options->light,
                  "Report the light in lux and cd/m^2 (default; solves both sky tables). --no-light skips "
                  "it: positions and parameters only, ~10x quicker");
    app->add_option("--weather", options->weather, "Apply one of the preset's weather states fully")
        ->type_name("STATE");
    app->add_option("--transition", options->transition,
                    "The weather a fraction of the way through a change: FROM:TO:FRACTION, FRACTION in 0..1")
        ->type_name("A:B:F");
    app->add_option(
           "--camera", options->camera,
           "Apply the preset's weather regions at this point [m] (x,y,z; Y up, north -Z, east +X) on top "
           "of the global weather (--weather, --transition, else the keyed values)")
        ->type_name("X,Y,Z");
    app->footer(helpFooter(
        "  aerial eval presets/hazy_sunset.json --time 18:30\n"
        "  aerial eval presets/hazy_sunset.json --time 18.5 --json\n"
        "  aerial eval presets/clear_summer_day.json --time 14:00 --transition clear:storm:0.5\n"
        "  aerial eval presets/clear_summer_day.json --time 14:00 --weather clear --camera=2500,600,-6000"));
    return {app, [options] { return runEval(*options); }};
}

}  // namespace aerial::cli
