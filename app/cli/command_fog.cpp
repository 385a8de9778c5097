// command_fog.cpp — `aerial fog PRESET --time T --from x,y,z --to x,y,z
// [--json]`: the CPU fog query a game makes for a transparent object
// (FogScene, fog_query.hpp) between a camera (--from) and the object (--to).
//
// The scene is built from the evaluated state (aerial::fogSceneDesc): global
// height fog, the fog volumes and the emitters (keyed values and lightning
// flashes applied), and the light that reaches the fog (aerial/fog_light.hpp):
// the sun and the moon, each with the illuminance that reaches the viewer,
// the sky tables' (SkySolver, 128 x 64) spherical-harmonic bands, and for
// far fog each light's horizon (its averages and row: horizonSkySample in
// <aerial/sky.hpp>).
//
// --json:
//   {"preset": {"file", "name"}, "time_h", "time", "from", "to", "length_m",
//    "transmittance_rgb", "in_scatter_rgb",        // L = L_object T + S
//    "global_fog": {"optical_depth", "transmittance", "fog_colour_rgb",
//                   "lit_fog_colour_rgb", "horizon_fog_colour_rgb", "horizon_weight"},
//                   // L_fog = (1 - w) lit + w horizon (aerial/fog_light.hpp)
//    "emitter_in_scatter_rgb",
//    "volumes": [{"index", "id", "name", "entry_m", "exit_m", "optical_depth",
//                 "transmittance", "colour_rgb"}],   // back to front
//    "lights": {"sun": {"direction", "illuminance_space_rgb",
//                       "horizon_rayleigh", "horizon_mie"}, "moon": {...}}}
#include "cli_common.hpp"

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace aerial::cli {
namespace {

struct FogOptions {
    std::string preset;
    std::string time;
    std::string from;
    std::string to;
    bool json = false;
};

Json fogLightToJson(const FogLight& light) {
    return {{"direction", toJson(light.direction)},
            {"illuminance_space_rgb", toJson(light.illuminance)},
            {"horizon_rayleigh", toJson(light.horizonRayleigh)},
            {"horizon_mie", toJson(light.horizonMie)},
            {"horizon_multiple", toJson(light.horizonMultiple)}};
}

int runFog(const FogOptions& options) {
    const double t = parseTimeOfDay(options.time, "--time");
    const glm::dvec3 from = parseVec3(options.from, "--from");
    const glm::dvec3 to = parseVec3(options.to, "--to");
    Preset preset = loadPresetOrFail(options.preset, "fog");
    const std::string name = preset.name;
    const CompiledPreset compiled(std::move(preset));
    const PresetState state = compiled.evaluate(t);

    SkyTables tables;
    tables.solve(state);
    const FogScene scene(aerial::fogSceneDesc(state, tables.sun(), tables.moon()));
    std::vector<VolumeContribution> crossed;
    const FogQueryResult r = scene.query(from, to, crossed);
    const glm::dvec3 delta = to - from;
    const double length = std::sqrt(delta.x * delta.x + delta.y * delta.y + delta.z * delta.z);
    const glm::dvec3 fogColour = scene.fogColour(delta, length);
    const glm::dvec3 litColour = scene.fogColour(delta, 0.0);
    const glm::dvec3 horizonColour = scene.fogColour(delta);
    const double horizonWeight = fogHorizonWeight(length, scene.desc().horizonDistance);

    if (options.json) {
        Json volumes = Json::array();
        for (const VolumeContribution& c : crossed) {
            const FogVolume& v = state.volumes.at(c.volumeIndex);
            volumes.push_back({{"index", c.volumeIndex},
                               {"id", v.id},
                               {"name", v.name},
                               {"entry_m", c.tIn},
                               {"exit_m", c.tOut},
                               {"optical_depth", c.opticalDepth},
                               {"transmittance", std::exp(-c.opticalDepth)},
                               {"colour_rgb", toJson(c.colour)}});
        }
        const FogSceneDesc& desc = scene.desc();
        printJson({{"preset", {{"file", options.preset}, {"name", name}}},
                   {"time_h", state.timeHours},
                   {"time", formatTime(state.timeHours)},
                   {"from", toJson(from)},
                   {"to", toJson(to)},
                   {"length_m", length},
                   {"transmittance_rgb", toJson(r.transmittance)},
                   {"in_scatter_rgb", toJson(r.inScatter)},
                   {"global_fog",
                    {{"optical_depth", r.globalOpticalDepth},
                     {"transmittance", std::exp(-r.globalOpticalDepth)},
                     {"fog_colour_rgb", toJson(fogColour)},
                     {"lit_fog_colour_rgb", toJson(litColour)},
                     {"horizon_fog_colour_rgb", toJson(horizonColour)},
                     {"horizon_weight", horizonWeight}}},
                   {"emitter_in_scatter_rgb", toJson(r.emitterInScatter)},
                   {"volumes", volumes},
                   {"lights",
                    {{"sun", fogLightToJson(desc.lights[0])}, {"moon", fogLightToJson(desc.lights[1])}}}});
        return kExitOk;
    }
    std::printf("%s at %s, from (%g, %g, %g) to (%g, %g, %g), %.6g m\n", name.c_str(),
                formatTime(state.timeHours).c_str(), from.x, from.y, from.z, to.x, to.y, to.z, length);
    std::printf("  %-24s %12.6g %12.6g %12.6g   (L = L_object T + S)\n", "transmittance T", r.transmittance.x,
                r.transmittance.y, r.transmittance.z);
    std::printf("  %-24s %12.6g %12.6g %12.6g\n", "in-scattered S", r.inScatter.x, r.inScatter.y,
                r.inScatter.z);
    std::printf("  %-24s %12.6g %12.6g %12.6g\n", "  of which emitters", r.emitterInScatter.x,
                r.emitterInScatter.y, r.emitterInScatter.z);
    std::printf("  %-24s optical depth %.6g, fog colour (%.6g, %.6g, %.6g)\n", "global fog",
                r.globalOpticalDepth, fogColour.x, fogColour.y, fogColour.z);
    std::printf("  %-24s lit (%.6g, %.6g, %.6g), horizon (%.6g, %.6g, %.6g), horizon weight %.4g\n",
                "  fog colour", litColour.x, litColour.y, litColour.z, horizonColour.x, horizonColour.y,
                horizonColour.z, horizonWeight);
    if (crossed.empty()) std::printf("  no fog volume crossed\n");
    for (const VolumeContribution& c : crossed) {
        const FogVolume& v = state.volumes.at(c.volumeIndex);
        std::printf("  volume %-17s %.6g..%.6g m, optical depth %.6g, colour (%.6g, %.6g, %.6g)\n",
                    v.id.c_str(), c.tIn, c.tOut, c.opticalDepth, c.colour.x, c.colour.y, c.colour.z);
    }
    return kExitOk;
}

}  // namespace

Command addFogCommand(CLI::App& parent) {
    auto options = std::make_shared<FogOptions>();
    CLI::App* app = parent.add_subcommand(
        "fog", "Fog between a camera and a transparent object: transmittance, in-scatter, crossed volumes");
    app->add_option("preset", options->preset, "Preset file (JSON), or `default` for the built-in preset")
        ->required()
        ->type_name("PRESET");
    addTimeOption(*app, options->time);
    app->add_option("--from", options->from, "Segment start (the camera) x,y,z [m]")
        ->required()
        ->type_name("X,Y,Z");
    app->add_option("--to", options->to, "Segment end (the object) x,y,z [m]")
        ->required()
        ->type_name("X,Y,Z");
    app->add_flag("--json", options->json, "Machine-readable output");
    app->footer(helpFooter(
        "  aerial fog presets/foggy_valley_morning.json --time 07:00 --from 0,2,0 --to 0,2,-500\n"
        "  aerial fog presets/foggy_valley_morning.json --time 7 --from=-50,5,0 --to 0,2,-300 --json"));
    return {app, [options] { return runFog(*options); }};
}

}  // namespace aerial::cli
