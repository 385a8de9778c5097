// command_clouds.cpp — `aerial clouds PRESET --time T --at X,Y,Z [--at ...]
// [--dir X,Y,Z] [--json]`: the cloud queries a game makes (clouds.hpp) at
// points of its world — is the player in cloud shadow, how much of the sky
// above is cloud.
//
// For each --at point, in the order given:
//   sun_visibility  transmittance through the clouds from the point towards
//                   the sun (1 = clear; aerial::cloudSunVisibility);
//   transmittance   through the layer along --dir (default straight up;
//                   aerial::cloudTransmittance, the reference march);
//   density_per_m, coverage, height_m   at the point itself.
// And once, the overcast seen from the world origin (aerial::cloudOvercast,
// what greys the fog and the ambient light under the deck): sky_cover,
// horizon_cover, optical_depth, diffuse_transmittance.
//
// --json:
//   {"preset": {"file", "name"}, "time_h", "time", "direction",
//    "sun_direction", "clouds_active",
//    "overcast": {"sky_cover", "horizon_cover", "optical_depth", "diffuse_transmittance"},
//    "points": [{"at", "sun_visibility", "transmittance", "density_per_m",
//                "coverage", "height_m"}]}
#include "cli_common.hpp"

#include <aerial/clouds.hpp>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace aerial::cli {
namespace {

struct CloudsOptions {
    std::string preset;
    std::string time;
    std::vector<std::string> at;
    std::string dir = "0,1,0";
    bool json = false;
};

int runClouds(const CloudsOptions& options) {
    const double t = parseTimeOfDay(options.time, "--time");
    std::vector<glm::dvec3> points;
    for (const std::string& text : options.at) points.push_back(parseVec3(text, "--at"));
    const glm::dvec3 direction = parseDirection(options.dir, "--dir");
    Preset preset = loadPresetOrFail(options.preset, "clouds");
    const std::string name = preset.name;
    const CompiledPreset compiled(std::move(preset));
    const PresetState state = compiled.evaluate(t);
    const CloudField clouds = aerial::prepareClouds(state);
    const glm::dvec3 sun = state.sunLight.body.direction;
    const CloudOvercast overcast = cloudOvercast(clouds);

    struct Answer {
        double sunVisibility, transmittance, density, coverage, height;
    };
    std::vector<Answer> answers;
    for (const glm::dvec3& p : points) {
        answers.push_back({cloudSunVisibility(clouds, p, sun), cloudTransmittance(clouds, p, direction),
                           cloudDensityAt(clouds, p), cloudCoverageAt(clouds, p),
                           cloudHeightAboveGround(p, clouds.planetRadius)});
    }
    if (options.json) {
        Json list = Json::array();
        for (std::size_t i = 0; i < points.size(); ++i) {
            list.push_back({{"at", toJson(points[i])},
                            {"sun_visibility", answers[i].sunVisibility},
                            {"transmittance", answers[i].transmittance},
                            {"density_per_m", answers[i].density},
                            {"coverage", answers[i].coverage},
                            {"height_m", answers[i].height}});
        }
        printJson({{"preset", {{"file", options.preset}, {"name", name}}},
                   {"time_h", state.timeHours},
                   {"time", formatTime(state.timeHours)},
                   {"direction", toJson(direction)},
                   {"sun_direction", toJson(sun)},
                   {"clouds_active", clouds.active()},
                   {"overcast",
                    {{"sky_cover", overcast.skyCover},
                     {"horizon_cover", overcast.horizonCover},
                     {"optical_depth", overcast.opticalDepth},
                     {"diffuse_transmittance", overcast.diffuseTransmittance}}},
                   {"points", list}});
        return kExitOk;
    }
    std::printf("%s at %s: cloud coverage %.3g, layer %.6g..%.6g m, sun (%.4f, %.4f, %.4f)%s\n", name.c_str(),
                formatTime(state.timeHours).c_str(), clouds.params.coverage, clouds.params.bottomM,
                clouds.params.bottomM + clouds.params.thicknessM, sun.x, sun.y, sun.z,
                clouds.active() ? "" : " (clear sky)");
    std::printf(
        "  overcast from the origin: sky cover %.4g, horizon cover %.4g, optical depth %.4g (diffuse "
        "transmittance %.4g)\n",
        overcast.skyCover, overcast.horizonCover, overcast.opticalDepth, overcast.diffuseTransmittance);
    for (std::size_t i = 0; i < points.size(); ++i) {
        const Answer& a = answers[i];
        std::printf(
            "  (%g, %g, %g): sun visibility %.6g, transmittance along (%.4g, %.4g, %.4g) %.6g, "
            "density %.6g 1/m, coverage %.4g, height %.6g m\n",
            points[i].x, points[i].y, points[i].z, a.sunVisibility, direction.x, direction.y, direction.z,
            a.transmittance, a.density, a.coverage, a.height);
    }
    return kExitOk;
}

}  // namespace

Command addCloudsCommand(CLI::App& parent) {
    auto options = std::make_shared<CloudsOptions>();
    CLI::App* app = parent.add_subcommand(
        "clouds", "Cloud queries at points: sun visibility (cloud shadow), transmittance through the layer");
    app->add_option("preset", options->preset, "Preset file (JSON), or `default` for the built-in preset")
        ->required()
        ->type_name("PRESET");
    addTimeOption(*app, options->time);
    app->add_option("--at", options->at, "A point x,y,z [m]; repeat for more (answered in order)")
        ->required()
        ->type_name("X,Y,Z")
        ->allow_extra_args(false)
        ->take_all();
    app->add_option("--dir", options->dir, "Direction of the transmittance ray (default 0,1,0: straight up)")
        ->type_name("X,Y,Z");
    app->add_flag("--json", options->json, "Machine-readable output");
    app->footer(helpFooter(
        "  aerial clouds presets/clear_summer_day.json --time 14:00 --at 0,0,0 --at 2000,0,-500\n"
        "  aerial clouds presets/stormy_night.json --time 01:00 --at=-300,2,40 --dir 0.3,1,0 --json"));
    return {app, [options] { return runClouds(*options); }};
}

}  // namespace aerial::cli
