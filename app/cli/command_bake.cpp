// command_bake.cpp — `aerial bake PRESET --out DIR [--step 0.5h] [--size
// 128x64]`: everything a game that does not link aerial_core needs to show
// the preset's sky and fog over the day.
//
// Layout of DIR:
//   sky_<NNN>_<HHMM>_sun.exr, sky_<NNN>_<HHMM>_moon.exr
//       one file per time step per light: the light's hemisphere sky table
//       (sky.hpp), W x H pixels, ZIP compressed (--compression), eleven
//       channels
//         rayleigh.R rayleigh.G rayleigh.B   phase-less Rayleigh integral I_R (half)
//         mie.R mie.G mie.B                  phase-less Mie integral I_M (half)
//         multiple.R multiple.G multiple.B   isotropic higher orders I_ms [1/sr] (half)
//         elevation azimuth                  where the texel lies (float, rad:
//                                            SkyTable::rowElevation, columnAzimuth)
//       pixel (x, y) = table texel (column i = x, row j = y): the first line
//       (y = 0) is the horizon, the last the zenith. Header attributes:
//       aerialLight ("sun"/"moon"), aerialTimeHours, aerialLightAzimuthRad,
//       aerialLightDirection (V3d), aerialSampling (how to sample the table
//       through its coordinates, in words), aerialMieAnisotropy,
//       aerialLightIlluminance (V3d, above the atmosphere) and aerialRadiance
//       (how to turn a texel into radiance).
//   sky_<NNN>_<HHMM>_skyview.exr, sky_<NNN>_<HHMM>_farfog.exr
//       the sky of both lights and the night sky as plain RGB radiance
//       (channels R, G, B, 32-bit float) over the upper hemisphere, lines
//       packed towards the horizon (--sky-view-size, default 512x320), and
//       the sky behind far fog over the whole sphere (--far-fog-size,
//       default 256x128): aerial/sky_maps.hpp, bake_maps.cpp. Header: the
//       mapping in words, the time, the units.
//   layout.gltf
//       the preset's fog volumes, cloud volumes and emitters at the first
//       step's time as a glTF 2.0 scene (layout_gltf.cpp): one node per
//       object named by its id, its position, rotation and half extents as
//       the node's translation, rotation and scale over a unit cube, unit
//       sphere or the volume's mesh, emitters as KHR_lights_punctual point
//       lights, every parameter in the node's extras; for Blender, Godot,
//       Unity or Unreal.
//   meshes/<id>.gltf
//       each mesh volume's closed mesh as a self-contained glTF
//       (aerial::fogMeshToGltf; object space, placed by the volume's
//       position, rotation and half extents), so that the bake carries the
//       meshes the preset's "mesh" paths name outside it.
//   manifest.json
//       format (format_version 3; the changes in the README), preset, steps
//       and how to sample a table, and for every step: the time, the full
//       evaluated state (sun, moon, every parameter, volumes, emitters, cloud
//       volumes: as `aerial eval --json`), per light its EXR file name, light
//       direction and azimuth, and horizon averages; the
//       sky-view and far fog files, the environment's irradiance as nine
//       spherical-harmonic coefficients (sky_irradiance_sh9) and the global
//       fog's light in the form of the manifest's fog formula ("fog");
//       how to expose a frame as the preset says ("exposure"); the clouds'
//       noise seed and, when the preset has clouds, the FNV-1a fingerprint
//       of the texels aerial::cloudNoise(seed) gives ("clouds"); the
//       layout's file name ("layout").
//
// Radiance in a world direction v (unit): for each light, the table sampled
// through its coordinates (kTableSampling; sampleSkyTable in aerial/sky.hpp),
//   L += E (3/(16 pi) (1 + mu^2) I_R + P_CS(mu, g) I_M + I_ms),  mu = dot(v, light),
// E = illuminance_space_rgb of that light, g = parameters.atmosphere.mie.
// anisotropy. Far fog seen along v: the same with H = (1 - s) horizon_x + s
// (row 0 at v's azimuth), s = |v.xz| = cos(elevation), for each of rayleigh
// / mie / multiple (the sky behind the fog; horizonSkySample).
//
// Writing is atomic: every file is written to a hidden temporary beside
// it, fsync'ed and renamed into place, and manifest.json is removed first and
// written last, so a directory with a manifest always holds a complete bake.
#include "bake_maps.hpp"
#include "cli_common.hpp"
#include "layout_gltf.hpp"

#include <aerial/fog_mesh.hpp>

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfDoubleAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStdIO.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfVecAttribute.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <system_error>
#include <vector>

#ifndef AERIAL_VERSION
#define AERIAL_VERSION "unknown"
#endif

namespace aerial::cli {
namespace {

namespace fs = std::filesystem;

constexpr const char* kManifestName = "manifest.json";

/// How a game gets the clouds' noise: regenerate it from the seed through
/// the library and check the fingerprint (only computed when some step has
/// clouds; generating the noise costs ~0.4 s).
Json cloudsToJson(std::int64_t seed, bool cloudy) {
    Json clouds = {
        {"seed", seed},
        {"shape_size", CloudNoise::kShapeSize},
        {"detail_size", CloudNoise::kDetailSize},
        {"how",
         "per step, parameters.clouds; the noise is aerial::cloudNoise(seed) (aerial/clouds.hpp): "
         "shape and detail R32F 3D textures, texel (i, j, k) at (k * size + j) * size + i, sampled "
         "with GL_LINEAR + GL_REPEAT; the layer's density and its offset by the wind as "
         "aerial::cloudDensityAt"}};
    if (cloudy) {
        char hex[19];
        std::snprintf(hex, sizeof hex, "0x%016llx",
                      static_cast<unsigned long long>(cloudNoiseFingerprint(*cloudNoise(seed))));
        clouds["noise_fnv1a64"] = hex;
    }
    return clouds;
}
constexpr int kManifestFormatVersion = 3;
constexpr int kChannelCount = 9;  // half; then the two float coordinates
constexpr const char* kChannelNames[kChannelCount] = {"rayleigh.R", "rayleigh.G", "rayleigh.B",
                                                      "mie.R",      "mie.G",      "mie.B",
                                                      "multiple.R", "multiple.G", "multiple.B"};
constexpr const char* kCoordinateNames[2] = {"elevation", "azimuth"};

/// How to sample a table through the coordinates its texels carry (the
/// manifest's table.sampling and every table file's aerialSampling).
constexpr const char* kTableSampling =
    "each texel carries where it lies: channel elevation [rad] (the same along a line, rising from 0 on "
    "line y = 0 to pi/2 on the last) and channel azimuth [rad, 0..2 pi) from the light's azimuth towards "
    "east (non-decreasing along a line from 0 at x = 0; columns i and W - i mirror each other). A "
    "direction at elevation el = asin(max(v.y, 0)) (below the horizon: line 0) and azimuth phi = "
    "(atan2(v.x, -v.z) - light_azimuth_rad) mod 2 pi: the lines j, j + 1 with elevation_j <= el < "
    "elevation_j+1 (at or above the last line: j = j + 1 = the last line), x = (el - elevation_j) / "
    "(elevation_j+1 - elevation_j), t = (x^3 - 2 x^2 + x) m_j + (3 x^2 - 2 x^3) + (x^3 - x^2) m_j+1 "
    "(the monotone cubic through the lines), m_j = 2 (elevation_j+1 - elevation_j) / (elevation_j+1 - "
    "elevation_j-1) and m_j+1 = 2 (elevation_j+1 - elevation_j) / (elevation_j+2 - elevation_j), 1 "
    "where the line before or after does not exist; each column's azimuth between them b_i = (1 - t) "
    "azimuth(i, j) + t azimuth(i, j + 1), wrapping (b_-1 = b_W-1 - 2 pi, b_W = 2 pi, b_W+1 = b_1 + 2 pi); "
    "the columns i, i + 1 with b_i <= phi < b_i+1, y = (phi - b_i) / (b_i+1 - b_i), s = (y^3 - 2 y^2 + y) "
    "m_i + (3 y^2 - 2 y^3) + (y^3 - y^2) m_i+1 with m_i = 2 (b_i+1 - b_i) / (b_i+1 - b_i-1) and m_i+1 = 2 "
    "(b_i+1 - b_i) / (b_i+2 - b_i) (s = y between evenly spaced columns; 0 where b_i = b_i+1); the "
    "table's value is the bilinear blend of texels (i, j), (i + 1, j), (i, j + 1), (i + 1, j + 1) with "
    "weights s and t";

struct BakeOptions {
    std::string preset;
    std::string out;
    std::string step = "0.5h";
    std::string size = "128x64";
    std::string skyViewSize = std::to_string(kSkyViewMapWidth) + "x" + std::to_string(kSkyViewMapHeight);
    std::string farFogSize = std::to_string(kFarFogMapWidth) + "x" + std::to_string(kFarFogMapHeight);
    std::string compression = "zip";
    bool quiet = false;
};

/// The --compression choices: all lossless.
Imf::Compression exrCompression(const std::string& name) {
    if (name == "none") return Imf::NO_COMPRESSION;
    if (name == "zip") return Imf::ZIP_COMPRESSION;
    if (name == "piz") return Imf::PIZ_COMPRESSION;
    usageError("--compression: \"" + name + "\" is not one of none, zip, piz");
}

/// The table files' channels: the nine halves, then the two coordinates.
Json tableChannels() {
    std::vector<std::string> names(std::begin(kChannelNames), std::end(kChannelNames));
    names.insert(names.end(), std::begin(kCoordinateNames), std::end(kCoordinateNames));
    return Json(names);
}

Imath::half toHalf(float value) {
    // No NaN or Inf reaches a file; half's largest finite value is 65504.
    if (!std::isfinite(value) || value < 0.0f) return Imath::half(0.0f);
    return Imath::half(std::min(value, 65504.0f));
}

void writeSkyExr(const fs::path& path, const SkyTable& table, const char* light, double timeHours,
                 double mieAnisotropy, const glm::dvec3& illuminanceSpace, Imf::Compression compression) {
    const int w = table.azimuthCount, h = table.elevationCount;
    constexpr std::size_t n = kChannelCount;
    std::vector<Imath::half> pixels(std::size_t(w) * std::size_t(h) * n);
    std::vector<float> elevation(std::size_t(w) * std::size_t(h)), azimuth(elevation.size());
    for (std::size_t texel = 0; texel < std::size_t(w) * std::size_t(h); ++texel) {
        for (int c = 0; c < 3; ++c) {
            pixels[texel * n + std::size_t(c)] = toHalf(table.rayleigh[texel * 3 + std::size_t(c)]);
            pixels[texel * n + 3 + std::size_t(c)] = toHalf(table.mie[texel * 3 + std::size_t(c)]);
            pixels[texel * n + 6 + std::size_t(c)] = toHalf(table.multiple[texel * 3 + std::size_t(c)]);
        }
        elevation[texel] = float(table.rowElevation[texel / std::size_t(w)]);
        azimuth[texel] = float(table.columnAzimuth[texel]);
    }
    // Encoded in memory, then written atomically (every byte through the
    // writer's fault-injection seam, aerial/detail/file_system.hpp).
    Imf::StdOSStream encoded;
    {
        try {
            Imf::Header header(w, h);
            header.compression() = compression;
            for (const char* name : kChannelNames) header.channels().insert(name, Imf::Channel(Imf::HALF));
            for (const char* name : kCoordinateNames)
                header.channels().insert(name, Imf::Channel(Imf::FLOAT));
            header.insert("aerialLight", Imf::StringAttribute(light));
            header.insert("aerialTimeHours", Imf::DoubleAttribute(timeHours));
            header.insert("aerialLightAzimuthRad", Imf::DoubleAttribute(table.lightAzimuth));
            header.insert("aerialLightDirection",
                          Imf::V3dAttribute(Imath::V3d(table.lightDirection.x, table.lightDirection.y,
                                                       table.lightDirection.z)));
            header.insert("aerialSampling", Imf::StringAttribute(kTableSampling));
            header.insert("aerialMieAnisotropy", Imf::DoubleAttribute(mieAnisotropy));
            header.insert(
                "aerialLightIlluminance",
                Imf::V3dAttribute(Imath::V3d(illuminanceSpace.x, illuminanceSpace.y, illuminanceSpace.z)));
            header.insert("aerialRadiance",
                          Imf::StringAttribute("L = illuminance (3/(16 pi) (1 + mu^2) rayleigh + "
                                               "cornette_shanks(mu, mie_anisotropy) mie + multiple), mu = "
                                               "dot(view, light direction)"));
            Imf::FrameBuffer frame;
            const std::size_t xStride = sizeof(Imath::half) * n, yStride = xStride * std::size_t(w);
            for (int k = 0; k < kChannelCount; ++k)
                frame.insert(
                    kChannelNames[k],
                    Imf::Slice(Imf::HALF, reinterpret_cast<char*>(pixels.data() + k), xStride, yStride));
            std::vector<float>* coordinates[2] = {&elevation, &azimuth};
            for (int k = 0; k < 2; ++k)
                frame.insert(kCoordinateNames[k],
                             Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(coordinates[k]->data()),
                                        sizeof(float), sizeof(float) * std::size_t(w)));
            Imf::OutputFile file(encoded, header);
            file.setFrameBuffer(frame);
            file.writePixels(h);
        } catch (const std::exception& e) {
            dataError("cannot encode " + path.string() + ": " + e.what());
        }
    }
    writeFileAtomically(path, encoded.str());
}

void writeText(const fs::path& path, const std::string& text) { writeFileAtomically(path, text); }

/// A progress bar on a terminal, plain lines otherwise (or nothing, --quiet).
class Progress {
public:
    Progress(int total, bool quiet) : total_(total), quiet_(quiet), tty_(::isatty(STDERR_FILENO) == 1) {}

    /// `clock` shows on the bar, `detail` only on plain lines.
    void update(int done, const std::string& clock, const std::string& detail) {
        if (quiet_) return;
        if (!tty_) {
            std::fprintf(stderr, "aerial bake: %d/%d %s %s\n", done, total_, clock.c_str(), detail.c_str());
            return;
        }
        constexpr int kWidth = 32;
        const int filled = total_ > 0 ? done * kWidth / total_ : kWidth;
        std::string bar(std::size_t(filled), '#');
        bar.resize(kWidth, '.');
        std::fprintf(stderr, "\r[%s] %*d/%d  %s ", bar.c_str(), int(std::to_string(total_).size()), done,
                     total_, clock.c_str());
        std::fflush(stderr);
    }
    void finish() {
        if (!quiet_ && tty_) std::fprintf(stderr, "\n");
    }

private:
    int total_;
    bool quiet_;
    bool tty_;
};

Json lightBakeToJson(const SkyTable& table, const std::string& file) {
    return {{"table_file", file},
            {"light_direction", toJson(table.lightDirection)},
            {"light_azimuth_rad", table.lightAzimuth},
            {"horizon_rayleigh", toJson(table.horizonRayleigh)},
            {"horizon_mie", toJson(table.horizonMie)},
            {"horizon_multiple", toJson(table.horizonMultiple)}};
}

int runBake(const BakeOptions& options) {
    const double stepHours = parseStepHours(options.step, "--step");
    SkySolverDesc desc;
    parseTableSize(options.size, "--size", desc.azimuthCount, desc.elevationCount);
    const Imf::Compression compression = exrCompression(options.compression);
    int skyViewWidth = 0, skyViewHeight = 0, farFogWidth = 0, farFogHeight = 0;
    parseImageSize(options.skyViewSize, "--sky-view-size", 4096, skyViewWidth, skyViewHeight);
    if (skyViewHeight < 2) usageError("--sky-view-size: the height must be at least 2 (horizon and zenith)");
    parseImageSize(options.farFogSize, "--far-fog-size", 4096, farFogWidth, farFogHeight);
    Preset preset = loadPresetOrFail(options.preset, "bake");
    const Json presetInfo = {
        {"file", options.preset}, {"name", preset.name}, {"description", preset.description}};
    const std::string presetName = preset.name;
    const CompiledPreset compiled(std::move(preset));

    const fs::path dir(options.out);
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec || !fs::is_directory(dir))
        dataError("--out: cannot create directory " + dir.string() + ": " + ec.message());
    // An older manifest would vouch for files this bake is about to replace.
    fs::remove(dir / kManifestName, ec);
    if (ec) dataError("cannot remove the old " + (dir / kManifestName).string() + ": " + ec.message());

    const int stepCount = std::max(1, int(std::ceil(24.0 / stepHours - 1e-9)));
    const int indexWidth = std::max(3, int(std::to_string(stepCount - 1).size()));
    const auto start = std::chrono::steady_clock::now();
    SkyTables tables(desc);
    PresetState state;
    // Each weather state's own tables keep their atmosphere's cache warm.
    const std::vector<WeatherState>& weatherStates = compiled.preset().weather;
    std::vector<std::unique_ptr<SkyTables>> weatherTables;
    for (std::size_t w = 0; w < weatherStates.size(); ++w)
        weatherTables.push_back(std::make_unique<SkyTables>(desc));
    PresetState weatherState;
    WeatherMix weatherMix;
    Json steps = Json::array();
    std::string layout;   // layout.gltf
    bool cloudy = false;  // some step has clouds: the manifest fingerprints their noise
    Progress progress(stepCount, options.quiet);
    for (int k = 0; k < stepCount; ++k) {
        const double t = k * stepHours;
        compiled.evaluate(t, state);
        if (k == 0) layout = layoutGltf(state, presetName);  // the layout at the first step's time
        tables.solve(state);
        cloudy = cloudy || aerial::prepareClouds(state).active();
        std::string clock = formatTime(t);
        clock.erase(std::remove(clock.begin(), clock.end(), ':'), clock.end());
        std::string index = std::to_string(k);
        index.insert(0, std::size_t(std::max(0, indexWidth - int(index.size()))), '0');
        const std::string stem = "sky_" + index + "_" + clock;
        const std::string sunFile = stem + "_sun.exr", moonFile = stem + "_moon.exr";
        const double g = state.environment.atmosphere.mieAnisotropy;
        writeSkyExr(dir / sunFile, tables.sun(), "sun", t, g, state.sunLight.illuminanceSpace, compression);
        writeSkyExr(dir / moonFile, tables.moon(), "moon", t, g, state.moonLight.illuminanceSpace,
                    compression);
        const StepMaps maps = bakeStepMaps(state, tables.sun(), tables.moon(), skyViewWidth, skyViewHeight,
                                           farFogWidth, farFogHeight);
        const std::string skyViewFile = stem + "_skyview.exr", farFogFile = stem + "_farfog.exr";
        writeRgbExr(dir / skyViewFile, maps.skyView, t, kSkyViewMapping, compression);
        writeRgbExr(dir / farFogFile, maps.farFog, t, kFarFogMapping, compression);

        Json step = {{"index", k}};
        step.update(stateToJson(state));
        step["sun"].update(lightBakeToJson(tables.sun(), sunFile));
        step["moon"].update(lightBakeToJson(tables.moon(), moonFile));
        step["sky_view_file"] = skyViewFile;
        step["far_fog_file"] = farFogFile;
        step["sky_irradiance_sh9"] = irradianceToJson(maps.irradiance);
        step["fog"] = maps.fog;
        step["fog"]["far_fog_file"] = farFogFile;
        // Each weather state held fully at this step: what an engine
        // cross-fades by the weights of bake_weather's formula.
        Json weather = Json::object();
        for (std::size_t w = 0; w < weatherStates.size(); ++w) {
            const std::string& name = weatherStates[w].name;
            settledWeather(compiled.preset(), name, weatherMix);
            compiled.evaluate(t, weatherMix, weatherState);
            SkyTables& wt = *weatherTables[w];
            wt.solve(weatherState);
            const StepMaps wm = bakeStepMaps(weatherState, wt.sun(), wt.moon(), skyViewWidth, skyViewHeight,
                                             farFogWidth, farFogHeight);
            const std::string wSky = stem + "_skyview_" + name + ".exr",
                              wFog = stem + "_farfog_" + name + ".exr";
            writeRgbExr(dir / wSky, wm.skyView, t, kSkyViewMapping, compression);
            writeRgbExr(dir / wFog, wm.farFog, t, kFarFogMapping, compression);
            Json entry = {{"parameters", parametersToJson(weatherState.environment)},
                          {"sun_illuminance_rgb", toJson(weatherState.sunLight.illuminance)},
                          {"moon_illuminance_rgb", toJson(weatherState.moonLight.illuminance)},
                          {"sky_view_file", wSky},
                          {"far_fog_file", wFog},
                          {"sky_irradiance_sh9", irradianceToJson(wm.irradiance)},
                          {"fog", wm.fog}};
            entry["fog"]["far_fog_file"] = wFog;
            weather[name] = std::move(entry);
        }
        if (!weatherStates.empty()) step["weather"] = std::move(weather);
        steps.push_back(std::move(step));
        progress.update(k + 1, formatTime(t), sunFile + ", " + moonFile);
    }
    progress.finish();
    // Before the manifest that vouches for them: the meshes and the layout.
    Json meshes = Json::object();
    for (const FogVolume& v : compiled.preset().volumes) {
        if (v.shape != FogVolumeShape::Mesh || !v.meshData) continue;
        const std::string file = "meshes/" + v.id + ".gltf";
        std::error_code made;
        fs::create_directories(dir / "meshes", made);
        if (made) dataError("cannot create " + (dir / "meshes").string() + ": " + made.message());
        writeText(dir / file, fogMeshToGltf(*v.meshData, v.id));
        meshes[v.id] = {{"file", file}, {"preset_mesh", v.mesh}, {"triangles", v.meshData->triangleCount()}};
    }
    writeText(dir / kLayoutName, layout);

    const Json manifest = {
        {"format", "aerial-bake"},
        {"format_version", kManifestFormatVersion},
        {"generator", "aerial bake " AERIAL_VERSION},
        {"preset", presetInfo},
        {"step_h", stepHours},
        {"step_count", stepCount},
        {"table",
         {{"azimuth_count", desc.azimuthCount},
          {"elevation_count", desc.elevationCount},
          {"file_pattern",
           "sky_<index>_<HHMM>_<light>.exr, light = sun | moon (HHMMSS when the step's time has seconds; "
           "per step and light: table_file)"},
          {"pixel_type", "half; the coordinates float"},
          {"compression", options.compression},
          {"channels", tableChannels()},
          {"pixel", "pixel (x, y) = texel (column i = x, row j = y); y = 0 is the first line in the file"},
          {"world_azimuth",
           "from north (-Z) towards east (+X): direction = (cos(el) sin(az), sin(el), -cos(el) cos(az)); "
           "light_azimuth_rad per step and light"},
          {"sampling", kTableSampling},
          {"radiance",
           "L(v) = sum over sun and moon of E * (P_R(mu) * rayleigh + P_M(mu, g) * mie + multiple), mu = "
           "dot(v, light_direction), E = illuminance_space_rgb, g = parameters.atmosphere.mie.anisotropy"},
          {"phase_rayleigh", "P_R(mu) = 3 / (16 pi) * (1 + mu^2)"},
          {"phase_mie",
           "P_M(mu, g) = 3 / (8 pi) * (1 - g^2) (1 + mu^2) / ((2 + g^2) (1 + g^2 - 2 g mu)^1.5)"},
          {"far_fog",
           "the sky behind far fog seen along v (what the far fog map holds, before the cloud deck's "
           "horizon cover): the radiance formula with H = (1 - s) * horizon_x + s * (row 0 at the azimuth "
           "of v) in place of the table sample, s = sqrt(v.x^2 + v.z^2), for x = rayleigh, mie, multiple"},
          {"values",
           "rayleigh, mie: phase-less single-scattering integrals (dimensionless); multiple: the isotropic "
           "higher orders (Hillaire 2020), per steradian, phase already applied; scene-linear"}}},
        {"exposure",
         {{"nits_per_radiance_unit", kNitsPerRadianceUnit},
          {"how",
           "per step, parameters.exposure: mode manual -> EV100 = ev100; automatic -> EV100 = "
           "clamp(log2(L_avg "
           "* nits_per_radiance_unit * 100 / 12.5), min_ev100, max_ev100), L_avg the frame's average "
           "luminance (10-90 % band of a log2 histogram), adapting at adapt_up_per_s / adapt_down_per_s; "
           "multiply radiance by nits_per_radiance_unit / (1.2 * 2^(EV100 - compensation_ev)) before tone "
           "mapping (aerial/exposure.hpp)"}}},
        {"sky_view", skyViewManifest(skyViewWidth, skyViewHeight)},
        {"far_fog", farFogManifest(farFogWidth, farFogHeight)},
        {"sky_irradiance_sh9", irradianceManifest()},
        {"clouds", cloudsToJson(compiled.preset().environment.clouds.seed, cloudy)},
        {"weather", bakeWeatherManifest(compiled.preset())},
        {"fog",
         {{"render_mode", compiled.preset().environment.fogRenderMode == FogRenderMode::Volumetric
                              ? "volumetric"
                              : "analytic"},
          {"how",
           "how the preset's fog was authored to be drawn: analytic (closed-form integrals per pixel, "
           "DESIGN.md) or volumetric (a froxel grid in which the sun's, moon's and clouds' shadows cut light "
           "shafts, converging to the analytic fog without them); aerial::FogScene queries return the "
           "analytic answer in both modes"},
          {"formula", fogFormulaManifest()}}},
        {"layout",
         {{"file", kLayoutName},
          {"time_h", 0.0},
          {"what",
           "glTF 2.0 (Y up, metres, as the manifest): one node per fog volume, cloud volume and emitter at "
           "the first step's time, named by its id; translation = position_m, rotation = rotation_xyzw, "
           "scale = half_extents_m over a unit cube (box), unit sphere (ellipsoid) or the volume's mesh; "
           "emitters as KHR_lights_punctual point lights; the parameters in each node's extras"}}},
        {"meshes",
         {{"what",
           "per mesh volume id: its closed mesh as a self-contained glTF beside this manifest (object space; "
           "the volume's position_m, rotation_xyzw and half_extents_m place it); the parameters' \"mesh\" "
           "names the preset's own file (preset_mesh)"},
          {"volumes", meshes}}},
        {"steps", steps}};
    writeText(dir / kManifestName, jsonText(manifest) + "\n");
    syncPath(dir, true);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf(
        "baked %d steps (%d EXR tables, %dx%d, %d sky-view maps, %dx%d, %d far fog maps, %dx%d), %s and %s "
        "into %s in %.2f s\n",
        stepCount, 2 * stepCount, desc.azimuthCount, desc.elevationCount, stepCount, skyViewWidth,
        skyViewHeight, stepCount, farFogWidth, farFogHeight, kLayoutName, kManifestName, dir.string().c_str(),
        seconds);
    return kExitOk;
}

}  // namespace

Command addBakeCommand(CLI::App& parent) {
    auto options = std::make_shared<BakeOptions>();
    CLI::App* app = parent.add_subcommand(
        "bake",
        "Sky tables (EXR, per step and light) and every evaluated parameter (manifest.json) over the day, "
        "for games that do not link the library, and the fog volumes, cloud volumes and emitters as a glTF "
        "scene (layout.gltf) for level editors");
    app->add_option("preset", options->preset, "Preset file (JSON), or `default` for the built-in preset")
        ->required()
        ->type_name("PRESET");
    app->add_option("--out,-o", options->out, "Output directory (created if missing)")
        ->required()
        ->type_name("DIR");
    app->add_option("--step", options->step, "Time between steps: hours (0.5, 0.5h) or minutes (30m)")
        ->type_name("DURATION")
        ->capture_default_str();
    app->add_option("--size", options->size, "Sky table size: azimuth columns x elevation rows")
        ->type_name("WxH")
        ->capture_default_str();
    app->add_option("--sky-view-size", options->skyViewSize,
                    "Size of the per-step sky-view map (upper hemisphere, lines packed towards the horizon)")
        ->type_name("WxH")
        ->capture_default_str();
    app->add_option("--far-fog-size", options->farFogSize,
                    "Size of the per-step far fog map (whole sphere, equirectangular)")
        ->type_name("WxH")
        ->capture_default_str();
    app->add_option("--compression", options->compression, "EXR compression (lossless): zip, piz or none")
        ->type_name("KIND")
        ->capture_default_str();
    app->add_flag("--quiet,-q", options->quiet, "No progress output");
    app->footer(
        helpFooter("  aerial bake presets/hazy_sunset.json --out bake/hazy_sunset --step 0.5h\n"
                   "  aerial bake presets/stormy_night.json --out /tmp/storm --step 15m --size 256x128"));
    return {app, [options] { return runBake(*options); }};
}

}  // namespace aerial::cli
