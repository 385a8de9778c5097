// command_day.cpp — `aerial day [PRESET] [--step 1] [--json]`: a preset
// through a whole day, one row per step (the built-in default preset,
// aerial::defaultPreset(), when no file is given; scripts/run.sh runs this).
//
// Each row: time; sun elevation and azimuth [deg]; the sun colour that
// lights the scene (illuminance after the atmosphere); moon elevation and
// illuminated fraction; the sky at the zenith (sun + moon tables with
// their phase functions); the horizon fog colour looking north; the
// transmittance and in-scatter from a camera at (0, 2, 0) to an object 1 km
// north (0, 2, -1000) through the preset's fog, volumes and emitters; and
// how long the two sky solves took. --json prints the same as
// {"preset", "location", "steps": [...]}.
#include "cli_common.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>

namespace aerial::cli {
namespace {

struct DayOptions {
    std::string preset;  // empty: the built-in default
    double stepHours = 1.0;
    double latitudeDeg = std::numeric_limits<double>::quiet_NaN();
    double dayOfYear = std::numeric_limits<double>::quiet_NaN();
    double northOffsetDeg = std::numeric_limits<double>::quiet_NaN();
    bool json = false;
};

int runDay(const DayOptions& options) {
    Preset preset = options.preset.empty() ? defaultPreset() : loadPresetOrFail(options.preset, "day");
    Location& where = preset.environment.location;
    if (!std::isnan(options.latitudeDeg)) where.latitudeDeg = options.latitudeDeg;
    if (!std::isnan(options.dayOfYear)) where.dayOfYear = options.dayOfYear;
    if (!std::isnan(options.northOffsetDeg)) where.northOffsetDeg = options.northOffsetDeg;
    const std::string name = preset.name;
    const CompiledPreset compiled(std::move(preset));
    const Location location = compiled.preset().environment.location;

    SkyTables tables;
    PresetState state;
    const glm::dvec3 camera(0.0, 2.0, 0.0), object(0.0, 2.0, -1000.0);
    const glm::dvec3 up(0.0, 1.0, 0.0), north(0.0, 0.0, -1.0);
    Json rows = Json::array();
    if (!options.json) {
        std::printf("%s%s%s, latitude %.2f deg, day %g\n", name.c_str(), options.preset.empty() ? "" : " — ",
                    options.preset.c_str(), location.latitudeDeg, location.dayOfYear);
        std::printf("%5s %7s %7s %20s %7s %5s %20s %20s %7s %8s\n", "time", "sun_el", "sun_az",
                    "sun_colour (lights)", "moon_el", "lit", "zenith_sky", "horizon_fog_north", "T_1km",
                    "solve_ms");
    }
    for (int k = 0; k * options.stepHours < 24.0 - 1e-9; ++k) {
        const double t = k * options.stepHours;
        compiled.evaluate(t, state);
        const auto start = std::chrono::steady_clock::now();
        tables.solve(state);
        const double solveMs =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        const FogScene scene(aerial::fogSceneDesc(state, tables.sun(), tables.moon()));
        const FogQueryResult fogged = scene.query(camera, object);
        const glm::dvec3 zenith = tableSkyRadiance(state, tables, up);
        const glm::dvec3 fogColour = scene.fogColour(north);
        const LightState& sun = state.sunLight;
        const LightState& moon = state.moonLight;

        if (options.json) {
            rows.push_back({{"time_h", t},
                            {"time", formatTime(t)},
                            {"sun", lightToJson(sun)},
                            {"moon", lightToJson(moon)},
                            {"zenith_sky_radiance_rgb", toJson(zenith)},
                            {"horizon_fog_radiance_north_rgb", toJson(fogColour)},
                            {"fog_1km_north",
                             {{"transmittance_rgb", toJson(fogged.transmittance)},
                              {"in_scatter_rgb", toJson(fogged.inScatter)}}},
                            {"sky_solve_ms", solveMs}});
            continue;
        }
        std::printf(
            "%5s %7.2f %7.2f %6.3f %6.3f %6.3f %7.2f %5.2f %6.4f %6.4f %6.4f %6.4f %6.4f %6.4f %7.4f %8.3f\n",
            formatTime(t).c_str(), sun.body.elevation * kDegreesPerRadian,
            sun.body.azimuth * kDegreesPerRadian, sun.illuminance.r, sun.illuminance.g, sun.illuminance.b,
            moon.body.elevation * kDegreesPerRadian, moon.body.illuminatedFraction, zenith.r, zenith.g,
            zenith.b, fogColour.r, fogColour.g, fogColour.b, fogged.transmittance.g, solveMs);
    }
    if (options.json)
        printJson(
            {{"preset",
              {{"file", options.preset.empty() ? "<built-in default>" : options.preset}, {"name", name}}},
             {"location",
              {{"latitude_deg", location.latitudeDeg},
               {"day_of_year", location.dayOfYear},
               {"north_offset_deg", location.northOffsetDeg}}},
             {"steps", rows}});
    return kExitOk;
}

}  // namespace

Command addDayCommand(CLI::App& parent) {
    auto options = std::make_shared<DayOptions>();
    CLI::App* app = parent.add_subcommand(
        "day",
        "A preset (default: the built-in one) through a whole day: sun, moon, sky, fog, one row per step");
    app->add_option("preset", options->preset, "Preset file (JSON); the built-in default preset when omitted")
        ->type_name("PRESET");
    app->add_option("--latitude", options->latitudeDeg, "Override the latitude [deg], north positive")
        ->check(finiteNumber())
        ->check(CLI::Range(-90.0, 90.0));
    app->add_option("--day-of-year", options->dayOfYear, "Override the day of the year, 1..365")
        ->check(finiteNumber())
        ->check(CLI::Range(1.0, 365.0));
    app->add_option("--north-offset", options->northOffsetDeg, "Override the sky rotation about +Y [deg]")
        ->check(finiteNumber())
        ->check(CLI::Range(-360.0, 360.0));
    app->add_option("--step", options->stepHours, "Hours between rows, 0.01..24")
        ->check(finiteNumber())
        ->check(CLI::Range(0.01, 24.0))
        ->capture_default_str();
    app->add_flag("--json", options->json, "Machine-readable output");
    app->footer(
        helpFooter("  aerial day\n"
                   "  aerial day presets/hazy_sunset.json --step 0.5\n"
                   "  aerial day --latitude 60 --day-of-year 172 --json"));
    return {app, [options] { return runDay(*options); }};
}

}  // namespace aerial::cli
