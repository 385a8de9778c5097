// cli_common.hpp — what every `aerial` subcommand shares: the command
// registry, exit codes and errors, parsing of times, vectors and sizes,
// loading presets, and turning an evaluated state into JSON (driven by the
// parameter table, so no parameter is listed by hand).
#pragma once

#include <aerial/evaluate.hpp>
#include <aerial/fog_query.hpp>
#include <aerial/param_table.hpp>
#include <aerial/photometry.hpp>
#include <aerial/preset.hpp>
#include <aerial/sky.hpp>
#include <aerial/sky_spectral.hpp>
#include <aerial/weather.hpp>

#include <CLI/CLI.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>

namespace aerial::cli {

/// JSON with keys in insertion order (the parameter table's order).
using Json = nlohmann::ordered_json;

/// Exit codes of every command (documented in each --help footer).
enum ExitCode : int {
    kExitOk = 0,          ///< success
    kExitDataError = 1,   ///< bad input or data: missing file, invalid preset, I/O error
    kExitUsageError = 2,  ///< bad command line: unknown flag, bad value
};

/// An error a command reports: one line on stderr, then `exitCode`.
class CommandError : public std::runtime_error {
public:
    CommandError(int exitCode, const std::string& message)
        : std::runtime_error(message), exitCode_(exitCode) {}
    int exitCode() const { return exitCode_; }

private:
    int exitCode_;
};

/// Throws a CommandError with kExitUsageError (bad command line).
[[noreturn]] void usageError(const std::string& message);
/// Throws a CommandError with kExitDataError (bad input data or I/O).
[[noreturn]] void dataError(const std::string& message);

/// A subcommand: CLI11 parses into options the command owns, run() acts.
struct Command {
    CLI::App* app = nullptr;
    std::function<int()> run;
};

// One per file (command_*.cpp).
Command addValidateCommand(CLI::App& parent);
Command addEvalCommand(CLI::App& parent);
Command addSkyCommand(CLI::App& parent);
Command addFogCommand(CLI::App& parent);
Command addCloudsCommand(CLI::App& parent);
Command addBakeCommand(CLI::App& parent);
Command addDayCommand(CLI::App& parent);
/// Only in a build with the renderer (AERIAL_HAVE_RENDERER).
Command addRenderCommand(CLI::App& parent);

/// The --help footer: the examples, then the exit codes.
std::string helpFooter(const std::string& examples);

/// A CLI11 check that rejects NaN and infinities (CLI::Range lets NaN through).
const CLI::Validator& finiteNumber();

/// The `--time` option (text; parsed by parseTimeOfDay), default "12:00".
CLI::Option* addTimeOption(CLI::App& app, std::string& text);

// ---------------------------------------------------------------------------
// Parsing command-line values. Each throws usageError naming `option`.

/// "HH:MM" (HH 0..23, MM 0..59), "HH:MM:SS", or decimal hours in [0, 24)
/// with an optional "h" suffix ("6.5", "6.5h"). Returns hours.
double parseTimeOfDay(const std::string& text, const std::string& option);
/// A duration: hours ("0.5", "0.5h") or minutes ("30m", "30min"), between
/// one minute and 24 h. Returns hours.
double parseStepHours(const std::string& text, const std::string& option);
/// "x,y,z": three finite numbers, each within +-1e7.
glm::dvec3 parseVec3(const std::string& text, const std::string& option);
/// parseVec3 and a non-zero length; returns the unit vector.
glm::dvec3 parseDirection(const std::string& text, const std::string& option);
/// "WxH": table columns (azimuth, 4..4096) by rows (elevation, 2..2048).
void parseTableSize(const std::string& text, const std::string& option, int& azimuthCount,
                    int& elevationCount);
/// "WxH": an image size in pixels, each side 1..maxSide.
void parseImageSize(const std::string& text, const std::string& option, int maxSide, int& width, int& height);
/// A finite number, whole text.
bool parseNumber(const std::string& text, double& out);

// ---------------------------------------------------------------------------
// Presets

/// The PRESET argument that names the built-in default preset
/// (aerial::defaultPreset()) in every command; a file literally named
/// "default" is ./default.
inline constexpr std::string_view kDefaultPresetName = "default";

/// Loads a preset (`default`: the built-in one); its warnings go to stderr
/// ("aerial <command>: warning: ..."). On failure throws dataError with the
/// first error (and how many more there are).
Preset loadPresetOrFail(const std::string& path, const std::string& command);

/// An issue in the validate format: "file:line:col: /pointer: reason"
/// (warnings "file:line:col: warning: /pointer: reason"); the position is
/// left out when unknown, the pointer when it names the whole document.
std::string formatIssue(const PresetIssue& issue);

// ---------------------------------------------------------------------------
// Files

/// The text of an errno value ("No such file or directory").
std::string errnoText(int error);

/// fsync a file (or a directory) by path; false on failure.
bool syncPath(const std::filesystem::path& path, bool directory);

/// Writes `path` through a hidden temporary beside it
/// (".NAME.tmp-PID-XXXXXX", aerial/detail/file_system.hpp): write(temp),
/// fsync, rename over `path`; the temporary is removed when anything fails
/// or throws, so `path` is either its old self or complete. Failures throw
/// dataError naming the file and the reason.
void writeAtomically(const std::filesystem::path& path,
                     const std::function<void(const std::filesystem::path& temp)>& write);
/// The same for bytes in memory (every byte through the writer's seam).
void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes);

// ---------------------------------------------------------------------------
// Text and JSON

constexpr double kDegreesPerRadian = 180.0 / 3.14159265358979323846;

/// "HH:MM", or "HH:MM:SS" when the time is not on a whole minute.
std::string formatTime(double hours);

Json toJson(const glm::dvec3& v);

/// Every parameter of the object, as the preset file writes it: globals
/// nested by their dotted path ({"atmosphere": {"mie": {...}}}), volumes,
/// emitters and cloud volumes as flat objects keyed by the parameter key.
Json parametersToJson(const Environment& environment);
Json parametersToJson(const FogVolume& volume);
Json parametersToJson(const Emitter& emitter);
Json parametersToJson(const CloudVolume& volume);

/// One parameter's value for people: "0.004", "(1, 0.9, 0.8)", "ellipsoid".
std::string formatParam(const ParamDesc& param, const void* object);

/// A sun or moon: elevation/azimuth [deg], direction, illuminated fraction,
/// phase, illuminance above the atmosphere, transmittance, illuminance.
Json lightToJson(const LightState& light);

/// A LightReport (aerial/photometry.hpp) as `aerial eval --json` prints it:
/// {"horizontal_illuminance_lux": {"sun", "sky", "moon", "night", "total"},
///  "zenith_luminance_cd_m2"}.
Json lightReportToJson(const LightReport& light);

/// The whole evaluated state: time, sun, moon, parameters, volumes,
/// emitters (with their lightning flash multiplier), cloud volumes.
Json stateToJson(const PresetState& state);

/// JSON text with two-space indentation, arrays of numbers on one line.
std::string jsonText(const Json& json);

/// Prints jsonText and a newline on stdout.
void printJson(const Json& json);

// ---------------------------------------------------------------------------
// Sky and fog from an evaluated state

/// The sun's and the moon's sky tables, solved for a state (spectrally,
/// <aerial/sky_spectral.hpp>: the colours of twilight).
class SkyTables {
public:
    explicit SkyTables(const SkySolverDesc& desc = {});
    void solve(const PresetState& state);
    const SkyTable& sun() const { return sun_->table(); }
    const SkyTable& moon() const { return moon_->table(); }

private:
    std::unique_ptr<SpectralSkySolver> sun_;
    std::unique_ptr<SpectralSkySolver> moon_;
};

/// The sky as the renderer shows it: both tables with their per-pixel phase
/// functions and illuminances above the atmosphere.
glm::dvec3 tableSkyRadiance(const PresetState& state, const SkyTables& tables, const glm::dvec3& direction);

// ---------------------------------------------------------------------------
// Weather

/// `--weather STATE` (a state held fully) or `--transition FROM:TO:FRACTION`
/// (the weather that far through a change, aerial/weather.hpp) into `mix`;
/// neither leaves it empty. Returns what was applied for --json: the state's
/// name, {"from", "to", "fraction", "weights"}, or null. Usage errors name
/// the option (an unknown state lists the preset's).
Json weatherFromOptions(const Preset& preset, const std::string& weather, const std::string& transition,
                        WeatherMix& mix);

/// A mix as {state: {category: weight}} (every state of the preset; an
/// empty mix gives 0 everywhere: the keyed values).
Json weatherMixToJson(const Preset& preset, const WeatherMix& mix);

/// The preset's weather regions as the file spells them: [{"id", "name",
/// "shape", "position_m", "rotation_xyzw", "half_extents_m", "blend_m",
/// "priority", "state"}] (aerial/weather_state.hpp); with `camera`, each
/// also carries its "weight" there (aerial::weatherRegionWeight).
Json weatherRegionsToJson(const Preset& preset, const glm::dvec3* camera = nullptr);

}  // namespace aerial::cli
