// minimal_game — what a game does with aerial_core, start to finish:
//
//   1. load the artist's preset (errors name file, line, column and field);
//   2. compile it once; every frame evaluate it at the game's time of day;
//   3. re-solve the sky tables of the sun and the moon when the light moved
//      (here: every step; a game spreads beginSolve/continueSolve over frames);
//   4. build the fog scene for the frame and query the fog between the camera
//      and each transparent object (they cannot read the fogged depth buffer);
//   5. expose the frame as the artist's preset says (manual, or metered from
//      the frame's average luminance, plus the compensation keyed at this hour);
//   6. ask the clouds whether the player stands in their shadow (the noise is
//      generated once from the preset's seed, the same texels the editor and
//      the bake's manifest fingerprint describe).
//
// Usage: minimal_game PRESET.json [STEP_HOURS]
// Prints, per step: the time, the sun direction, the fog colour seen looking
// at the glass pane, the fog transmittance and in-scatter in front of it, and
// the EV100 and radiance scale of the preset's exposure (metered here on the
// zenith sky, where a game meters its rendered frame), and the sunlight the
// clouds let through to the camera (1 = clear).
// Exit code 0, or 1 when the preset does not load or a result is not finite.
#include <aerial/clouds.hpp>
#include <aerial/evaluate.hpp>
#include <aerial/exposure.hpp>
#include <aerial/fog_query.hpp>
#include <aerial/preset.hpp>
#include <aerial/sky.hpp>
#include <aerial/sky_spectral.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <utility>

namespace {

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: minimal_game PRESET.json [STEP_HOURS]\n");
        return 2;
    }
    const double stepHours = argc > 2 ? std::atof(argv[2]) : 1.0;
    if (!(stepHours > 0.0 && stepHours <= 24.0)) {
        std::fprintf(stderr, "minimal_game: STEP_HOURS must be in (0, 24]\n");
        return 2;
    }

    // 1. Load.
    aerial::PresetLoadResult loaded = aerial::loadPreset(argv[1]);
    for (const aerial::PresetIssue& warning : loaded.warnings)
        std::fprintf(stderr, "%s\n", warning.toString().c_str());
    if (!loaded.ok()) {
        for (const aerial::PresetIssue& error : loaded.errors)
            std::fprintf(stderr, "%s\n", error.toString().c_str());
        return 1;
    }

    // 2. Compile once; the state is reused every frame (no allocation).
    const aerial::CompiledPreset preset(std::move(*loaded.preset));
    aerial::PresetState state;
    aerial::SpectralSkySolver sunSky, moonSky;  // six wavelengths: the colours of twilight

    // The camera and a transparent object: a glass pane 150 m away, north-east.
    const glm::dvec3 camera(0.0, 2.0, 0.0);
    const glm::dvec3 glassPane(40.0, 3.0, -145.0);

    std::printf("%s\n%5s  %-26s  %-26s  %-8s  %s\n", preset.preset().name.c_str(), "time", "sun direction",
                "fog colour at the pane", "T_pane",
                "in-scatter at the pane                EV100  scale     sun_through_clouds");
    for (int step = 0; step * stepHours < 24.0 - 1e-9; ++step) {
        const double t = step * stepHours;
        preset.evaluate(t, state);

        // 3. Sky tables for this light position.
        const aerial::AtmosphereParams& air = state.environment.atmosphere;
        sunSky.solve(air, state.sunLight.body.direction);
        moonSky.solve(air, state.moonLight.body.direction);

        // 4. The fog scene of this frame, lit through the sky's horizon colour.
        // keyed intensities, lightning flashes and the preset's fog colour applied
        const aerial::FogScene fog(aerial::fogSceneDesc(state, sunSky.table(), moonSky.table()));
        const aerial::FogQueryResult pane = fog.query(camera, glassPane);
        const glm::dvec3 fogColour = fog.fogColour(glassPane - camera);
        // The pane would be shaded: L = L_pane * pane.transmittance + pane.inScatter.

        // 5. Exposure: a game meters its frame (aerial::meterAverageLuminance
        // of its pixels) and adapts over time (aerial::adaptEv100); the zenith
        // sky stands in for the frame here.
        const glm::dvec3 up(0.0, 1.0, 0.0);
        const double g = air.mieAnisotropy;
        const double average =
            aerial::luminance(aerial::skyRadiance(sunSky.table(), g, up, state.sunLight.illuminanceSpace) +
                              aerial::skyRadiance(moonSky.table(), g, up, state.moonLight.illuminanceSpace));
        const aerial::ExposureParams& exposure = state.environment.exposure;
        const double ev100 = aerial::targetEv100(exposure, average);
        const double scale =
            aerial::radianceScale(exposure, ev100);  // multiplies radiance before tone mapping

        // 6. Cloud shadow: the sun's transmittance through the clouds at the player.
        const glm::dvec3& sun = state.sunLight.body.direction;
        const aerial::CloudField clouds = aerial::prepareClouds(state);
        const double sunThroughClouds = aerial::cloudSunVisibility(clouds, camera, sun);

        std::printf(
            "%02d:%02d  (%7.4f, %7.4f, %7.4f)  (%7.4f, %7.4f, %7.4f)  %8.5f  (%.4f, %.4f, %.4f)  %6.2f  "
            "%-8.4g  %.4f\n",
            int(t), int(std::lround((t - int(t)) * 60.0)) % 60, sun.x, sun.y, sun.z, fogColour.r, fogColour.g,
            fogColour.b, pane.transmittance.g, pane.inScatter.r, pane.inScatter.g, pane.inScatter.b, ev100,
            scale, sunThroughClouds);
        if (!finite(sun) || !finite(fogColour) || !finite(pane.inScatter) || !(pane.transmittance.g >= 0.0) ||
            !(pane.transmittance.g <= 1.0) || !std::isfinite(ev100) ||
            !(scale > 0.0 && std::isfinite(scale)) || !(sunThroughClouds >= 0.0 && sunThroughClouds <= 1.0)) {
            std::fprintf(stderr, "minimal_game: a result at %.2f h is not finite or out of range\n", t);
            return 1;
        }
    }
    return 0;
}
