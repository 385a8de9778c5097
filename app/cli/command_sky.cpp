// command_sky.cpp — `aerial sky PRESET --time T --dir x,y,z [--json]`: the
// sky radiance in one direction as the renderer shows it (the sun's and the
// moon's hemisphere tables, bilinear, with the phase functions applied per
// pixel), next to the exact single-scattering integral (sky_reference.hpp:
// brute force, double precision; at the spectral solver's wavelengths,
// combined as its table is, spectralReferenceSkyIntegrals in
// sky_spectral.hpp), and their relative difference.
//
// --json:
//   {"preset": {"file", "name"}, "time_h", "time", "direction" (unit),
//    "elevation_deg", "azimuth_deg", "below_horizon",
//    "sky_rgb": the clear sky as the sky pass draws it behind the stars
//        (aerial::clearSkyRadiance: the table's radiance, the airglow, a
//        city's glow), what a bake's sky-view map holds,
//    "table": {"size": [W, H], "radiance_rgb",
//              "sun": {"radiance_rgb", "rayleigh", "mie"}, "moon": {...}},
//    "reference": {"radiance_rgb", "sun": {...}, "moon": {...}},
//    "relative_difference_rgb": table / reference - 1 per channel (null
//        where the reference is 0), "max_abs_relative_difference",
//    "stars": {"background_cd_m2", "background_mag_arcsec2",
//              "limiting_magnitude", "limiting_magnitude_at_eye",
//              "extinction_mag"}}
// "stars" (aerial/stars.hpp): the clear sky behind the stars (the table's
// radiance plus airglowRadiance and a city's glow, as the sky pass draws them) as a luminance
// and a V surface brightness; the naked-eye limiting magnitude against it
// at the eye, and for a star's magnitude above the atmosphere (the first
// plus the extinction T_zenith^X in V towards the direction): a star of
// the field shows there when brighter than "limiting_magnitude". Null
// below the horizon.
// "rayleigh" and "mie" are the phase-less integrals I_R, I_M; radiance =
// E (P_R I_R + P_M I_M) with E the light's illuminance above the atmosphere.
// Below the horizon the table repeats its horizon row while the reference
// integrates down to the ground, so they differ by design.
#include "cli_common.hpp"

#include <aerial/atmosphere.hpp>
#include <aerial/exposure.hpp>
#include <aerial/night_sky.hpp>
#include <aerial/sky_maps.hpp>
#include <aerial/sky_reference.hpp>
#include <aerial/stars.hpp>
#include <aerial/sky_spectral.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

namespace aerial::cli {
namespace {

struct SkyOptions {
    std::string preset;
    std::string time;
    std::string direction;
    std::string size = "128x64";
    bool json = false;
};

struct LightSample {
    glm::dvec3 radiance{0.0};  ///< single + multiple
    glm::dvec3 single{0.0};    ///< E (P_R I_R + P_M I_M)
    glm::dvec3 multiple{0.0};  ///< E I_ms (0 for the exact single-scattering integral)
    SkySample integrals;
};

Json sampleToJson(const LightSample& s) {
    return {{"radiance_rgb", toJson(s.radiance)},
            {"rayleigh", toJson(s.integrals.rayleigh)},
            {"mie", toJson(s.integrals.mie)},
            {"multiple", toJson(s.integrals.multiple)}};
}

double phaseWeighted(double mu, double g, const SkySample& s, int c) {
    return rayleighPhase(mu) * s.rayleigh[c] + miePhase(mu, g) * s.mie[c];
}

LightSample tableSample(const SkyTable& table, double g, const glm::dvec3& v, const LightState& light) {
    LightSample out;
    out.integrals = sampleSkyTable(table, v);
    out.radiance = skyRadiance(table, g, v, light.illuminanceSpace);
    const double mu =
        v.x * table.lightDirection.x + v.y * table.lightDirection.y + v.z * table.lightDirection.z;
    for (int c = 0; c < 3; ++c) {
        out.single[c] = light.illuminanceSpace[c] * phaseWeighted(mu, g, out.integrals, c);
        out.multiple[c] = light.illuminanceSpace[c] * out.integrals.multiple[c];
    }
    return out;
}

LightSample referenceSample(const AtmosphereParams& air, const glm::dvec3& v, const LightState& light) {
    LightSample out;
    // A light with no illuminance (a new moon) contributes exactly nothing.
    if (light.illuminanceSpace == glm::dvec3(0.0)) return out;
    out.integrals = spectralReferenceSkyIntegrals(air, v, light.body.direction);
    const double mu =
        v.x * light.body.direction.x + v.y * light.body.direction.y + v.z * light.body.direction.z;
    for (int c = 0; c < 3; ++c)
        out.radiance[c] = light.illuminanceSpace[c] * phaseWeighted(mu, air.mieAnisotropy, out.integrals, c);
    out.single = out.radiance;
    return out;
}

/// The stars' view of the sky towards v (aerial/stars.hpp).
struct StarSample {
    double backgroundNits = 0.0;
    double limitAtEye = 0.0;
    double extinction = 0.0;  ///< [mag]
    bool aboveHorizon = false;
};

StarSample starSample(const PresetState& state, const glm::dvec3& v, const glm::dvec3& tableRadiance) {
    StarSample out;
    const glm::dvec3 background = tableRadiance + airglowRadiance(v, state.zenithTransmittance) +
                                  lightPollutionRadiance(state.environment.lightPollution, v,
                                                         state.environment.location.northOffsetDeg);
    out.backgroundNits = luminance(background) * kNitsPerRadianceUnit;
    out.limitAtEye = limitingMagnitude(out.backgroundNits);
    out.aboveHorizon = v.y > 0.0;
    out.extinction = extinctedMagnitude(0.0, state.zenithTransmittance.y, v.y);
    return out;
}

Json starsToJson(const StarSample& s) {
    const bool shown = s.aboveHorizon && s.extinction < kHiddenStarMagnitude;
    return {{"background_cd_m2", s.backgroundNits},
            {"background_mag_arcsec2", skyBrightnessFromLuminance(s.backgroundNits)},
            {"limiting_magnitude", shown ? Json(s.limitAtEye - s.extinction) : Json(nullptr)},
            {"limiting_magnitude_at_eye", s.aboveHorizon ? Json(s.limitAtEye) : Json(nullptr)},
            {"extinction_mag", shown ? Json(s.extinction) : Json(nullptr)}};
}

int runSky(const SkyOptions& options) {
    const double t = parseTimeOfDay(options.time, "--time");
    const glm::dvec3 v = parseDirection(options.direction, "--dir");
    SkySolverDesc desc;
    parseTableSize(options.size, "--size", desc.azimuthCount, desc.elevationCount);
    Preset preset = loadPresetOrFail(options.preset, "sky");
    const std::string name = preset.name;
    const CompiledPreset compiled(std::move(preset));
    const PresetState state = compiled.evaluate(t);
    const AtmosphereParams& air = state.environment.atmosphere;

    SkyTables tables(desc);
    tables.solve(state);
    const LightSample tableSun = tableSample(tables.sun(), air.mieAnisotropy, v, state.sunLight);
    const LightSample tableMoon = tableSample(tables.moon(), air.mieAnisotropy, v, state.moonLight);
    const LightSample exactSun = referenceSample(air, v, state.sunLight);
    const LightSample exactMoon = referenceSample(air, v, state.moonLight);
    const glm::dvec3 table = tableSun.radiance + tableMoon.radiance;
    const glm::dvec3 single = tableSun.single + tableMoon.single;
    const glm::dvec3 multiple = tableSun.multiple + tableMoon.multiple;
    const glm::dvec3 exact = exactSun.radiance + exactMoon.radiance;
    const StarSample stars = starSample(state, v, table);

    Json relative = Json::array();
    double maxRelative = 0.0;
    for (int c = 0; c < 3; ++c) {
        if (exact[c] > 0.0) {
            // Single scattering against its exact integral (the multiple
            // scattering has no exact counterpart here).
            const double r = single[c] / exact[c] - 1.0;
            relative.push_back(r);
            maxRelative = std::max(maxRelative, std::abs(r));
        } else {
            relative.push_back(nullptr);
        }
    }
    const double elevation = std::asin(std::clamp(v.y, -1.0, 1.0));
    // Azimuth from north (-Z) towards east (+X); 0 straight up or down.
    double azimuth = std::hypot(v.x, v.z) > 1e-12 ? std::atan2(v.x, -v.z) : 0.0;
    if (azimuth < 0.0) azimuth += 2.0 * kPi;

    if (options.json) {
        printJson({{"preset", {{"file", options.preset}, {"name", name}}},
                   {"time_h", state.timeHours},
                   {"time", formatTime(state.timeHours)},
                   {"direction", toJson(v)},
                   {"elevation_deg", elevation * kDegreesPerRadian},
                   {"azimuth_deg", azimuth * kDegreesPerRadian},
                   {"below_horizon", v.y < 0.0},
                   {"sky_rgb", toJson(clearSkyRadiance(state, tables.sun(), tables.moon(), v))},
                   {"table",
                    {{"size", {desc.azimuthCount, desc.elevationCount}},
                     {"radiance_rgb", toJson(table)},
                     {"single_scattering_rgb", toJson(single)},
                     {"multiple_scattering_rgb", toJson(multiple)},
                     {"sun", sampleToJson(tableSun)},
                     {"moon", sampleToJson(tableMoon)}}},
                   {"reference",
                    {{"radiance_rgb", toJson(exact)},
                     {"sun", sampleToJson(exactSun)},
                     {"moon", sampleToJson(exactMoon)}}},
                   {"relative_difference_rgb", relative},
                   {"max_abs_relative_difference", maxRelative},
                   {"stars", starsToJson(stars)}});
        return kExitOk;
    }
    std::printf("%s at %s, towards (%.4f, %.4f, %.4f): elevation %.3f deg, azimuth %.3f deg\n", name.c_str(),
                formatTime(state.timeHours).c_str(), v.x, v.y, v.z, elevation * kDegreesPerRadian,
                azimuth * kDegreesPerRadian);
    std::printf("  %-28s %12.6g %12.6g %12.6g\n", ("table " + options.size + " (sun + moon)").c_str(),
                table.x, table.y, table.z);
    std::printf("  %-28s %12.6g %12.6g %12.6g\n", "  single scattering", single.x, single.y, single.z);
    std::printf("  %-28s %12.6g %12.6g %12.6g\n", "  multiple scattering", multiple.x, multiple.y,
                multiple.z);
    std::printf("  %-28s %12.6g %12.6g %12.6g\n", "exact integral (single)", exact.x, exact.y, exact.z);
    std::printf("  %-28s", "relative difference (single)");
    for (int c = 0; c < 3; ++c) {
        if (relative[std::size_t(c)].is_null())
            std::printf(" %12s", "-");
        else
            std::printf(" %+11.3f%%", relative[std::size_t(c)].get<double>() * 100.0);
    }
    std::printf("\n");
    std::printf("  stars: sky behind %.3g cd/m^2 (%.2f mag/arcsec^2)", stars.backgroundNits,
                skyBrightnessFromLuminance(stars.backgroundNits));
    if (stars.aboveHorizon && stars.extinction < kHiddenStarMagnitude)
        std::printf(", limiting magnitude %.2f (%.2f at the eye, extinction %.2f mag)\n",
                    stars.limitAtEye - stars.extinction, stars.limitAtEye, stars.extinction);
    else
        std::printf(", no stars below the horizon\n");
    if (v.y < 0.0)
        std::printf(
            "  (below the horizon: the table repeats its horizon row, the exact integral runs to the "
            "ground)\n");
    return kExitOk;
}

}  // namespace

Command addSkyCommand(CLI::App& parent) {
    auto options = std::make_shared<SkyOptions>();
    CLI::App* app = parent.add_subcommand(
        "sky",
        "Sky radiance in a direction: the renderer's table next to the exact single-scattering integral");
    app->add_option("preset", options->preset, "Preset file (JSON), or `default` for the built-in preset")
        ->required()
        ->type_name("PRESET");
    addTimeOption(*app, options->time);
    app->add_option("--dir,-d", options->direction, "View direction x,y,z (world: Y up, north -Z, east +X)")
        ->required()
        ->type_name("X,Y,Z");
    app->add_option("--size", options->size, "Sky table size: azimuth columns x elevation rows")
        ->type_name("WxH")
        ->capture_default_str();
    app->add_flag("--json", options->json, "Machine-readable output");
    app->footer(
        helpFooter("  aerial sky presets/clear_summer_day.json --time 12:00 --dir 0,1,0\n"
                   "  aerial sky presets/hazy_sunset.json --time 18:30 --dir=-1,0.1,0 --json"));
    return {app, [options] { return runSky(*options); }};
}

}  // namespace aerial::cli
