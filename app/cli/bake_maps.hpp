// bake_maps.hpp — what `aerial bake` (format 2) writes per step for an
// engine that does not link the library: the sky-view map, the far fog
// map, the irradiance coefficients and the global fog's light
// (aerial/sky_maps.hpp, aerial/fog_light.hpp), and the words the manifest
// states them in.
#pragma once

#include "cli_common.hpp"

#include <aerial/sky_maps.hpp>

#include <OpenEXR/ImfCompression.h>

#include <filesystem>

namespace aerial::cli {

/// The manifest's "sky_view" section (mapping in words, size, channels).
Json skyViewManifest(int width, int height);
/// The manifest's "far_fog" section.
Json farFogManifest(int width, int height);
/// The manifest's "fog" formula and its per-step fields, in words.
Json fogFormulaManifest();
/// The manifest's "sky_irradiance_sh9" convention, in words.
Json irradianceManifest();

/// Writes an RGB image as a 32-bit float EXR (channels R, G, B), atomically,
/// with the step's time, the words of its mapping and the units in the header.
void writeRgbExr(const std::filesystem::path& path, const RgbImage& image, double timeHours,
                 const char* mapping, Imf::Compression compression);

/// The per-step maps and coefficients of a state with its solved tables.
struct StepMaps {
    RgbImage skyView;
    RgbImage farFog;
    IrradianceSH9 irradiance;
    Json fog;  ///< the step's "fog" object (fogFormulaManifest)
};
StepMaps bakeStepMaps(const PresetState& state, const SkyTable& sun, const SkyTable& moon, int skyViewWidth,
                      int skyViewHeight, int farFogWidth, int farFogHeight);

/// The manifest's "weather": the preset's states (their overrides as
/// `aerial eval --json` lists them), each category's share of a change and
/// how to blend the states' per-step data without the library.
Json bakeWeatherManifest(const Preset& preset);

/// Nine [r, g, b] triples.
Json irradianceToJson(const IrradianceSH9& sh);

extern const char* const kSkyViewMapping;
extern const char* const kFarFogMapping;

}  // namespace aerial::cli
