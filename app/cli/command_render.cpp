// command_render.cpp — `aerial render PRESET --out FILE.exr|png [--time T]
// [--eye x,y,z --target x,y,z --fov deg] [--size WxH] [--exposure EV]
// [--display NAME] [--view NAME] [--half] [--shadows on|off] [--fog preset|analytic|volumetric]
// [--froxel-slices N] [--json]`: one frame of the built-in scene
// (renderer/scene.hpp: terrain with a valley, a lake, rocks, buildings, glass, a fence, steam) under the
// preset at one time of day, rendered headless (EGL on Mesa's surfaceless platform, no window) by the same
// renderer the editor uses.
//
// PRESET is a preset file, or the word `default` for the built-in default
// preset (aerial::defaultPreset(); a file literally named "default" is
// ./default).
//
// Weather: --weather STATE or --transition A:B:F as `aerial eval`; the
// preset's weather regions (aerial/weather.hpp, regionalWeather) then apply
// at the camera (--eye), as they do at the editor's camera.
//
// Output by extension (case-insensitive):
//   .exr  scene-linear Rec.709 radiance, RGBA half float, ZIP compressed;
//         values beyond the half range clamp to 65504. --exposure does not
//         apply (a usage error): the file holds the unscaled radiance.
//   .png  8-bit display-referred, through the OpenColorIO display transform
//         (renderer/display.hpp): radiance times the preset's exposure
//         (aerial/exposure.hpp: its manual EV100, or automatic — metered
//         from this frame, clamped to its range, fully adapted — and its
//         compensation at this time), times the view's middle-grey
//         calibration (DisplayTransform::middleGreyEv: the metered
//         luminance shows as 118/255, as in a camera's picture), times 2^EV
//         (--exposure, default 0: added to the preset's), then the view
//         (--view, default the
//         config's default: "ACES 1.0 - SDR Video" in Aerial's built-in
//         config, a filmic tone map; "Un-tone-mapped" clamps to [0, 1] and
//         sRGB-encodes) of the display (--display, default "sRGB - Display").
//         The config is $OCIO when set (a broken one falls back to the
//         built-in config with a warning), else the built-in one. An unknown
//         display or view is a usage error that lists the known ones.
// The frame renders into RGBA32F (the physical night is below the half
// range: renderer.hpp, ColourPrecision), or RGBA16F with --half (every pass
// capped at 3e4; a night sky then quantises into bands). A frame with any non-finite value is an error and
// nothing is written; the file is written to a hidden temporary beside it, fsync'ed and renamed, so FILE is
// either untouched or complete.
//
// --shadows on|off (default on): the sun's (or, at night, the moon's)
// cascaded shadow maps on the scene (RenderPasses::shadows, the renderer's
// default ShadowMapSettings); off renders exactly as without them.
//
// --fog preset|analytic|volumetric (default preset: the preset's
// fog.render_mode): analytic is the exact closed forms; volumetric draws the
// global fog, the volumes and the emitters' lit fog through the renderer's
// froxel grid, where the shadows (scene and clouds) cut light shafts
// (FogMode::Volumetric);
// --froxel-slices N (16..256, default 128) its depth slices.
//
// --scene FILE.gltf|.glb renders a glTF 2.0 scene (renderer/gltf.hpp)
// instead of the built-in one; a bad or unsupported file is exit 1 with the
// loader's one-line message, the loader's warnings go to stderr.
//
// Camera: Y up, metres. Each of --eye, --target and --fov that is not given
// comes from the preset's "view" (aerial/preset.hpp, PresetView: the camera
// that frames what the preset is about), or, for a preset without one, from
// the built-in default: north (-Z) up the valley from 30 m above the terrain
// at z = 120 towards a point 10 m above it at z = -200, so both the valley
// floor and the horizon are in view, with a 60 deg vertical field of view.
//
// Prints one line: the file, its size, the time and how long the sky solve
// and the render took. --json:
//   {"file", "format" ("exr"/"png"), "width", "height",
//    "preset": {"file", "name"}, "time_h", "time",
//    "camera": {"eye", "target", "fov_deg", "preset_view" (true when the
//    preset's view gave any of them)}, "precision" ("half"/"float"),
//    "night_vision" (PNG shown with aerial::nightVision; false for EXR and --photopic),
//    "shadows" (true/false), "fog" ("analytic"/"volumetric": the mode drawn),
//    "exposure": {"mode", "average_luminance" (metered, radiance units),
//    "ev100" (what the preset's exposure chose), "compensation_ev",
//    "exposure_ev" (--exposure), "view_grey_ev" (the view's middle-grey
//    calibration, DisplayTransform::middleGreyEv), "display_ev" (the stops
//    the display multiplied by: log2 radianceScale + view_grey_ev +
//    exposure_ev; both null for EXR)},
//    "display", "view", "ocio_config" (null for EXR),
//    "renderer" (GL_RENDERER and version),
//    "setup_ms" (context, shaders, scene), "solve_ms" (sun and moon tables),
//    "render_ms" (render and read-back), "write_ms"}
#include "cli_common.hpp"

#include <aerial/exposure.hpp>
#include <aerial/limits.hpp>
#include <aerial/renderer/camera.hpp>
#include <aerial/renderer/display.hpp>
#include <aerial/renderer/egl_context.hpp>
#include <aerial/renderer/gltf.hpp>
#include <aerial/renderer/image.hpp>
#include <aerial/renderer/renderer.hpp>
#include <aerial/renderer/scene.hpp>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <system_error>
#include <vector>

namespace aerial::cli {
namespace {

namespace fs = std::filesystem;

constexpr int kMaxImageSide = limits::kMaxImageSide;
constexpr double kMaxExposureEv = 30.0;

struct RenderOptions {
    std::string preset;
    std::string time;
    std::string eye;
    std::string target;
    double fovDeg = 60.0;
    bool fovGiven = false;  ///< --fov was given (else the preset's view, else fovDeg)
    std::string size = "320x180";
    std::string out;
    std::string scene;     // "" = the built-in scene
    std::string exposure;  // "" = not given (0 EV for PNG)
    std::string display;   // "" = the OCIO config's default display
    std::string view;      // "" = the display's default view
    bool halfTarget = false;
    bool photopic = false;
    bool floatTarget = false;    ///< --float: the default, kept for scripts
    std::string shadows = "on";  // on | off
    std::string fog = "preset";  // preset | analytic | volumetric
    int froxelSlices = 128;
    bool json = false;
    std::string weather;     // --weather STATE
    std::string transition;  // --transition A:B:F
};

enum class Format { Exr, Png };

/// The format from the file name's extension; a usage error otherwise.
Format formatOf(const std::string& out) {
    std::string extension = fs::path(out).extension().string();
    for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (extension == ".exr") return Format::Exr;
    if (extension == ".png") return Format::Png;
    usageError("--out: \"" + out + "\" must end in .exr (scene-linear half float) or .png (8-bit sRGB)" +
               (extension.empty() ? std::string() : "; \"" + extension + "\" is neither"));
}

/// The default camera of a preset without a view: above the valley floor,
/// looking north up the valley.
void defaultView(glm::dvec3& eye, glm::dvec3& target) {
    eye = {0.0, renderer::builtinTerrainHeight(0.0, 120.0) + 30.0, 120.0};
    target = {0.0, renderer::builtinTerrainHeight(0.0, -200.0) + 10.0, -200.0};
}

/// The renderer's messages: warnings go to stderr at once, errors are kept
/// (the first one fails the command).
struct RenderLog {
    std::vector<std::string> errors;

    renderer::Logger logger() {
        renderer::Logger l;
        l.userData = this;
        l.function = [](renderer::LogLevel level, const char* message, void* user) {
            auto* self = static_cast<RenderLog*>(user);
            if (level == renderer::LogLevel::Error)
                self->errors.emplace_back(message);
            else if (level == renderer::LogLevel::Warning)
                std::fprintf(stderr, "aerial render: warning: %s\n", message);
        };
        return l;
    }
};

std::string formatNumber(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

/// The number of non-finite values in the colour channels (alpha included).
std::size_t nonFiniteCount(const renderer::Image& image) {
    return std::size_t(
        std::count_if(image.pixels.begin(), image.pixels.end(), [](float v) { return !std::isfinite(v); }));
}

/// writeExr / writePng name the temporary in their message; name the file.
std::string writerReason(const std::string& error, const fs::path& temp) {
    const std::string prefix = temp.string() + ": ";
    return error.compare(0, prefix.size(), prefix) == 0 ? error.substr(prefix.size()) : error;
}

void writeImage(const renderer::Image& image, const fs::path& path, Format format,
                const renderer::DisplayTransform* display) {
    writeAtomically(path, [&](const fs::path& temp) {
        std::string error;
        errno = 0;
        const bool ok = format == Format::Exr ? renderer::writeExr(image, temp.string(), error)
                                              : renderer::writePng(image, temp.string(), *display, error);
        if (!ok) {
            const int saved = errno;
            std::string reason = writerReason(error, temp);
            if (saved != 0) reason += " (" + errnoText(saved) + ")";
            dataError("cannot write " + path.string() + ": " + reason);
        }
    });
    syncPath(path.parent_path().empty() ? fs::path(".") : path.parent_path(), true);
}

int runRender(const RenderOptions& options) {
    // The command line first (exit 2), then the data (exit 1).
    const Format format = formatOf(options.out);
    const double t = parseTimeOfDay(options.time, "--time");
    int width = 0, height = 0;
    parseImageSize(options.size, "--size", kMaxImageSide, width, height);
    glm::dvec3 eye, target;
    defaultView(eye, target);
    if (!options.eye.empty()) eye = parseVec3(options.eye, "--eye");
    if (!options.target.empty()) target = parseVec3(options.target, "--target");
    if (!options.eye.empty() && !options.target.empty() && glm::dvec3(target - eye) == glm::dvec3(0.0))
        usageError("--eye and --target are the same point; the camera needs a direction");
    if (options.fovGiven && !(options.fovDeg > 1.0 && options.fovDeg < 179.0))
        usageError("--fov: " + formatNumber(options.fovDeg) + " is out of range (1 < fov < 179 degrees)");
    double exposureEv = 0.0;
    if (!options.exposure.empty()) {
        if (format == Format::Exr)
            usageError("--exposure applies to PNG only; an EXR holds the unscaled scene-linear radiance");
        if (!parseNumber(options.exposure, exposureEv) || std::abs(exposureEv) > kMaxExposureEv)
            usageError("--exposure: \"" + options.exposure + "\" is not a number of stops in [-30, 30]");
    }

    if (format == Format::Exr && (!options.display.empty() || !options.view.empty()))
        usageError(std::string(options.view.empty() ? "--display" : "--view") +
                   " applies to PNG only; an EXR holds the scene-linear radiance");
    RenderLog log;
    std::unique_ptr<renderer::DisplayTransform> display;
    if (format == Format::Png) {
        renderer::DisplayDesc displayDesc;
        displayDesc.display = options.display;
        displayDesc.view = options.view;
        displayDesc.exposureEv = exposureEv;
        displayDesc.nightVision = !options.photopic;
        displayDesc.logger = log.logger();  // a broken $OCIO: a warning on stderr
        display = std::make_unique<renderer::DisplayTransform>(displayDesc);
        if (!display->valid()) {
            auto contains = [](const std::vector<std::string>& names, const std::string& name) {
                return std::find(names.begin(), names.end(), name) != names.end();
            };
            const std::vector<std::string> displays = display->displays();
            if (!displays.empty() && !contains(displays, display->display()))
                usageError("--display: " + display->error());
            if (!displays.empty() && !contains(display->views(), display->view()))
                usageError("--view: " + display->error());
            dataError("cannot set up the display transform: " + display->error());
        }
    }

    const bool builtin = options.preset == kDefaultPresetName;
    Preset preset = loadPresetOrFail(options.preset, "render");
    const std::string name = preset.name;
    // What the options leave open comes from the preset's view (validated
    // on load: apart, in range), else the built-in default.
    double fovDeg = options.fovDeg;
    const bool presetView =
        preset.view && (options.eye.empty() || options.target.empty() || !options.fovGiven);
    if (preset.view) {
        if (options.eye.empty()) eye = preset.view->eye;
        if (options.target.empty()) target = preset.view->target;
        if (!options.fovGiven) fovDeg = preset.view->verticalFovDeg;
    }
    if (glm::dvec3(target - eye) == glm::dvec3(0.0))
        usageError(std::string(options.eye.empty() ? "--target" : "--eye") +
                   " is the preset view's other point; the camera needs a direction");
    const CompiledPreset compiled(std::move(preset));

    const fs::path out(options.out);
    const fs::path dir = out.parent_path().empty() ? fs::path(".") : out.parent_path();
    std::error_code ec;
    if (!fs::is_directory(dir, ec))
        dataError("--out: cannot write " + out.string() + ": the directory " + dir.string() +
                  " does not exist");
    if (fs::is_directory(out, ec)) dataError("--out: " + out.string() + " is a directory");
    renderer::SceneDesc scene;
    if (!options.scene.empty()) {
        renderer::GltfLoadResult loaded = renderer::loadGltfScene(options.scene);
        if (!loaded.ok()) dataError("--scene: " + loaded.error);
        for (const std::string& warning : loaded.warnings)
            std::fprintf(stderr, "aerial render: warning: %s\n", warning.c_str());
        scene = std::move(loaded.scene);
    }

    // GL: a headless context, then the renderer (destroyed first, while the
    // context is still current).
    const auto setupStart = std::chrono::steady_clock::now();
    // The context lives until the process exits: tearing it down
    // (eglTerminate) only unloads Mesa's driver moments before exit, after
    // which LeakSanitizer can no longer attribute Mesa's own allocations to
    // Mesa (see the suppressions in main.cpp).
    static renderer::HeadlessContext* processContext = nullptr;
    if (processContext == nullptr) {
        auto created = std::make_unique<renderer::HeadlessContext>();
        renderer::HeadlessContextDesc contextDesc;
        contextDesc.debug = true;  // GL errors reach the log
        if (!created->create(contextDesc))
            dataError("cannot create a headless OpenGL 4.5 context: " + created->error());
        processContext = created.release();
    }
    renderer::HeadlessContext& context = *processContext;
    if (!context.makeCurrent()) dataError("cannot make the OpenGL context current: " + context.error());
    renderer::RendererDesc rendererDesc;
    rendererDesc.logger = log.logger();
    renderer::Renderer renderer(rendererDesc);
    if (!renderer.valid()) dataError("cannot create the renderer: " + renderer.error());
    renderer.setScene(options.scene.empty() ? renderer::makeBuiltinScene() : scene);
    const double setupMs = millisecondsSince(setupStart);

    const auto solveStart = std::chrono::steady_clock::now();
    WeatherMix mix;
    weatherFromOptions(compiled.preset(), options.weather, options.transition, mix);
    regionalWeather(compiled.preset(), eye, mix, mix);  // the preset's weather regions at the camera
    PresetState state;
    compiled.evaluate(t, mix, state);
    SkyTables tables;
    tables.solve(state);
    const double solveMs = millisecondsSince(solveStart);

    const auto renderStart = std::chrono::steady_clock::now();
    renderer.setSky(tables.sun(), tables.moon());
    renderer::Camera camera;
    camera.eye = eye;
    camera.target = target;
    camera.verticalFov = fovDeg / kDegreesPerRadian;
    camera.aspect = double(width) / double(height);
    renderer::FrameDesc frame;
    frame.width = width;
    frame.height = height;
    frame.precision = options.halfTarget ? renderer::ColourPrecision::Half : renderer::ColourPrecision::Float;
    frame.passes.shadows = options.shadows == "on";
    const bool volumetric =
        options.fog == "volumetric" ||
        (options.fog == "preset" && state.environment.fogRenderMode == FogRenderMode::Volumetric);
    frame.fogMode = volumetric ? renderer::FogMode::Volumetric : renderer::FogMode::Analytic;
    frame.froxels.slices = options.froxelSlices;
    renderer.render(camera, state, frame);
    const renderer::Image image = renderer.readColour();
    const double renderMs = millisecondsSince(renderStart);

    if (!log.errors.empty())
        dataError("the renderer reported an error: " + log.errors.front() +
                  (log.errors.size() > 1 ? " (and " + std::to_string(log.errors.size() - 1) + " more)" : ""));
    if (image.width != width || image.height != height || image.channels < 3 ||
        image.pixels.size() != std::size_t(width) * std::size_t(height) * std::size_t(image.channels))
        dataError("the renderer returned a " + std::to_string(image.width) + "x" +
                  std::to_string(image.height) + " frame, not " + std::to_string(width) + "x" +
                  std::to_string(height) + "; nothing written");
    if (const std::size_t bad = nonFiniteCount(image); bad > 0)
        dataError("the rendered frame has " + std::to_string(bad) + " non-finite values (NaN or Inf); " +
                  out.string() + " not written");

    // The preset's exposure, fully adapted (one frame): manual EV100, or
    // metered from this frame and clamped; --exposure adds to it.
    const ExposureParams& exposure = state.environment.exposure;
    const double averageLuminance =
        meterAverageLuminance(image.pixels, image.channels, image.width, image.height);
    const double ev100 = targetEv100(exposure, averageLuminance);
    const double greyEv = display ? display->middleGreyEv() : 0.0;  // the view shows the metered grey as 0.46
    const double displayEv = std::log2(radianceScale(exposure, ev100)) + greyEv + exposureEv;
    if (display) display->setExposureEv(displayEv);

    const auto writeStart = std::chrono::steady_clock::now();
    writeImage(image, out, format, display.get());
    const double writeMs = millisecondsSince(writeStart);

    const char* formatName = format == Format::Exr ? "exr" : "png";
    if (options.json) {
        const Json cameraJson = {{"eye", toJson(eye)},
                                 {"target", toJson(target)},
                                 {"fov_deg", fovDeg},
                                 {"preset_view", presetView}};
        printJson({{"file", out.string()},
                   {"format", formatName},
                   {"width", width},
                   {"height", height},
                   {"preset", {{"file", builtin ? "<built-in default>" : options.preset}, {"name", name}}},
                   {"time_h", state.timeHours},
                   {"time", formatTime(state.timeHours)},
                   {"camera", cameraJson},
                   {"precision", options.halfTarget ? "half" : "float"},
                   {"night_vision", !options.photopic && format != Format::Exr},
                   {"shadows", options.shadows == "on"},
                   {"fog", frame.fogMode == renderer::FogMode::Volumetric ? "volumetric" : "analytic"},
                   {"exposure",
                    {{"mode", exposure.mode == ExposureMode::Manual ? "manual" : "automatic"},
                     {"average_luminance", averageLuminance},
                     {"ev100", ev100},
                     {"compensation_ev", exposure.compensationEv},
                     {"exposure_ev", format == Format::Png ? Json(exposureEv) : Json(nullptr)},
                     {"view_grey_ev", format == Format::Png ? Json(greyEv) : Json(nullptr)},
                     {"display_ev", format == Format::Png ? Json(displayEv) : Json(nullptr)}}},
                   {"display", display ? Json(display->display()) : Json(nullptr)},
                   {"view", display ? Json(display->view()) : Json(nullptr)},
                   {"ocio_config", display ? Json(display->configSource()) : Json(nullptr)},
                   {"renderer", context.rendererName()},
                   {"setup_ms", setupMs},
                   {"solve_ms", solveMs},
                   {"render_ms", renderMs},
                   {"write_ms", writeMs}});
        return kExitOk;
    }
    std::printf("wrote %s (%dx%d %s, %s at %s): sky solve %.1f ms, render %.1f ms\n", out.string().c_str(),
                width, height, format == Format::Exr ? "EXR" : "PNG", name.c_str(),
                formatTime(state.timeHours).c_str(), solveMs, renderMs);
    return kExitOk;
}

}  // namespace

Command addRenderCommand(CLI::App& parent) {
    auto options = std::make_shared<RenderOptions>();
    CLI::App* app = parent.add_subcommand(
        "render",
        "Render one frame of the built-in scene headless (no window): scene-linear EXR or sRGB PNG");
    app->add_option("preset", options->preset,
                    "Preset file (JSON), or the word `default` for the built-in default preset")
        ->required()
        ->type_name("PRESET");
    app->add_option("--out,-o", options->out, "Output image: .exr (scene-linear half float) or .png (sRGB)")
        ->required()
        ->type_name("FILE");
    addTimeOption(*app, options->time);
    app->add_option("--scene", options->scene, "glTF 2.0 scene (.gltf or .glb) instead of the built-in one")
        ->type_name("FILE");
    app->add_option("--eye", options->eye,
                    "Camera position x,y,z [m] (default: the preset's view, else 30 m above the valley floor "
                    "at z = 120)")
        ->type_name("X,Y,Z");
    app->add_option(
           "--target", options->target,
           "Point the camera looks at x,y,z [m] (default: the preset's view, else up the valley, 10 m "
           "above it at z = -200)")
        ->type_name("X,Y,Z");
    CLI::Option* fov =
        app->add_option(
               "--fov", options->fovDeg,
               "Vertical field of view [deg], between 1 and 179 (default: the preset's view, else 60)")
            ->type_name("DEG")
            ->check(finiteNumber());
    app->add_option("--size", options->size, "Image size in pixels, each side 1..8192 (limits.hpp)")
        ->type_name("WxH")
        ->capture_default_str();
    app->add_option("--weather", options->weather, "Apply one of the preset's weather states fully")
        ->type_name("STATE");
    app->add_option("--transition", options->transition,
                    "The weather a fraction of the way through a change: FROM:TO:FRACTION, FRACTION in 0..1")
        ->type_name("A:B:F");
    app->add_option("--exposure", options->exposure,
                    "PNG only: scale the radiance by 2^EV before the display transform (default 0)")
        ->type_name("EV");
    app->add_option("--display", options->display,
                    "PNG only: OpenColorIO display (default: the config's default, \"sRGB - Display\")")
        ->type_name("NAME");
    app->add_option("--view", options->view,
                    "PNG only: OpenColorIO view, e.g. \"ACES 1.0 - SDR Video\" (default, tone-mapped) or "
                    "\"Un-tone-mapped\"")
        ->type_name("NAME");
    CLI::Option* half =
        app->add_flag("--half", options->halfTarget,
                      "Render into RGBA16F instead of RGBA32F: half the memory, but a night sky (below the "
                      "half range) quantises into bands; the EXR is half float either way");
    app->add_flag("--float", options->floatTarget, "Render into RGBA32F (the default)")->excludes(half);
    app->add_flag("--photopic", options->photopic,
                  "PNG only: show the colours as measured, without night vision (the eye's blue, colourless "
                  "sight below 5 cd/m^2, aerial::nightVision)");
    app->add_option("--shadows", options->shadows,
                    "Sun and moon shadows of the scene (cascaded shadow maps): on or off")
        ->type_name("on|off")
        ->check(CLI::IsMember({"on", "off"}))
        ->capture_default_str();
    app->add_option("--fog", options->fog,
                    "Fog: preset (its fog.render_mode), analytic (exact closed forms) or volumetric (froxel "
                    "grid: light shafts through the shadows)")
        ->type_name("preset|analytic|volumetric")
        ->check(CLI::IsMember({"preset", "analytic", "volumetric"}))
        ->capture_default_str();
    app->add_option("--froxel-slices", options->froxelSlices, "Volumetric fog: depth slices of the grid")
        ->type_name("N")
        ->check(CLI::Range(16, 256))
        ->capture_default_str();
    app->add_flag("--json", options->json, "Machine-readable output");
    app->footer(
        helpFooter("  aerial render presets/clear_summer_day.json --time 12:00 --out noon.png\n"
                   "  aerial render default --time 18:30 --size 1280x720 --out dusk.exr --json\n"
                   "  aerial render presets/foggy_valley_morning.json --time 7 --eye 0,20,150 "
                   "--target=0,5,-100 --fov 45 --exposure 1 --out fog.png\n"
                   "  aerial render presets/hazy_sunset.json --time 19:00 --view \"ACES 1.0 - SDR Video\" "
                   "--out sunset.png"));
    return {app, [options, fov] {
                options->fovGiven = fov->count() > 0;
                return runRender(*options);
            }};
}

}  // namespace aerial::cli
