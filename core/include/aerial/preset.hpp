// aerial/preset.hpp — a time-of-day preset: every parameter of the sky, the
// fog, the clouds, the volumes, the emitters and the cloud volumes, plus the
// timeline that animates them.
// Loading, validating and saving presets (JSON, "version": 1).
//
// Usage:
//   aerial::PresetLoadResult r = aerial::loadPreset("presets/hazy_sunset.json");
//   if (!r.preset) { for (auto& e : r.errors) log(e.toString()); return; }
//   for (auto& w : r.warnings) log(w.toString());        // e.g. unknown fields
//   aerial::Preset preset = std::move(*r.preset);
//   preset.environment.fog.density = 0.003;
//   aerial::SaveResult s = aerial::savePreset(preset, "presets/mine.json");
//   if (!s.ok()) log(s.errors[0].toString());
//
// File format (../shared/DESIGN.md, "Presets"): a JSON object with
// "version": 1, "name", "description", the global parameters grouped as
// "location", "atmosphere" {"rayleigh", "mie", "ozone"}, "sun", "moon",
// "fog", "exposure", "clouds", then "volumes", "emitters" and "cloud_volumes"
// (arrays of objects with string "id"s), "tracks" (see timeline.hpp), and
// the optional "weather" (weather_state.hpp) and "view" (PresetView).
// Every key that carries a unit says it (`scale_height_m`, `density_per_m`). The keys, ranges and defaults
// come from the parameter table (param_table.hpp); the JSON Schema in presets/aerial-preset.schema.json is
// generated from the same table.
//
// Errors never escape as exceptions and never crash: loading returns either
// a complete preset or the list of errors, each naming the file, the JSON
// pointer of the field, its line:column in the file and the reason.
//
// Untrusted files: every size a file can ask for is capped (aerial/limits.hpp:
// 16 MiB per file, 64 levels of nesting, 1 Mi JSON values, 1024 volumes and
// emitters, 64 cloud volumes, 4096 tracks and keys per track, 4096-byte
// strings); over a cap is an error naming the field and the limit.
//
// Numbers (what the loader does with each kind of bad value):
//   * rejected, an error: NaN and infinities (JSON has no literal for them; a
//     number too large for a double is a "number overflow" error), any value
//     outside its parameter's range (param_table.hpp) — so negative
//     densities and zero or negative half-extents (fog volumes >= 0.001 m,
//     cloud volumes >= 1 m) are errors —,
//     a zero quaternion and a zero gradient direction (no direction to
//     normalise), Mie extinction below scattering;
//   * repaired, a warning: a rotation quaternion or gradient direction that
//     is finite, non-zero and off unit length by more than 1e-6 is
//     normalised ("not a unit quaternion (length 2); normalised").
// validatePreset (presets built in code) repairs nothing: it reports the
// same values as errors, and savePreset refuses to write them — no NaN, Inf
// or unnormalised rotation ever reaches a file.
#pragma once

#include <aerial/atmosphere.hpp>
#include <aerial/clouds.hpp>
#include <aerial/emitter.hpp>
#include <aerial/exposure.hpp>
#include <aerial/fog_volume.hpp>
#include <aerial/height_fog.hpp>
#include <aerial/night_sky.hpp>
#include <aerial/sun.hpp>
#include <aerial/timeline.hpp>
#include <aerial/weather_state.hpp>

#include <glm/vec3.hpp>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace aerial {

/// The preset file format this library writes and the newest it reads.
/// Version 2: the moon's intensity is physical (version 1's is converted
/// on load: divided by kVersion1MoonScale).
/// Version 3: an emitter's strength is its luminous intensity in candela
/// (intensity_cd, emitter.hpp "Photometry"); version 2's intensity_per_m i
/// loads as the candela that lights the preset's own fog the same:
/// I = 4 pi kNitsPerRadianceUnit i Y(colour) / (a sigma_s), sigma_s =
/// fogScatteringAt the emitter with the base (unkeyed) values, keys of its
/// track converted alike; an attenuation left out is version 2's 0.01.
/// Version 4: a key can follow the sun ("anchor" and "offset_h" in place of
/// "time_h", timeline.hpp); earlier versions load unchanged.
constexpr int kPresetVersion = 5;

/// Default sun intensity [illuminance unit = 5000 lx, aerial/exposure.hpp]:
/// 20, the ~100 000 lx of a clear noon above the atmosphere's losses.
constexpr double kDefaultSunIntensity = 20.0;
/// Ratio of the full moon's illuminance to the sun's, both above the
/// atmosphere: ~0.25 lx / ~100 000 lx = 2.5e-6 (the full moon is
/// magnitude -12.7 against the sun's -26.7; Krisciunas and Schaefer 1991).
constexpr double kPhysicalMoonToSunRatio = 2.5e-6;
/// Default moon intensity at full phase: the physical moon, 5e-5 of the
/// illuminance unit = 0.25 lx at the zenith above the atmosphere (a high
/// full moon gives 0.1-0.3 lx on the ground). How bright a moonlit night
/// reads is the exposure's job (a camera at EV100 -3 sees a moonlit
/// landscape), not the moon's.
constexpr double kDefaultMoonIntensity = kDefaultSunIntensity * kPhysicalMoonToSunRatio;
/// Version-1 presets kept the moon at 1000x the physical ratio (0.05 by
/// default); loading one divides its moon intensity and keys by this.
constexpr double kVersion1MoonScale = 1000.0;

/// A sun or moon as the preset describes it, above the atmosphere.
/// Illuminance (RGB) = colour * intensity; the moon's is further scaled by
/// its phase (CelestialBody::phaseIrradiance).
struct LightParams {
    /// Colour, scene-linear Rec.709, each channel 0..100. Default white.
    glm::dvec3 colour{1.0, 1.0, 1.0};
    /// Intensity, dimensionless multiplier of the colour, 0..1e5. Default
    /// kDefaultSunIntensity (the moon's default is set in Environment).
    double intensity = kDefaultSunIntensity;

    glm::dvec3 illuminance() const { return colour * intensity; }
};

/// Every global (not per-object) parameter of a preset.
struct Environment {
    Location location;
    AtmosphereParams atmosphere;
    LightParams sun;
    /// The physical moon, slightly cool: kDefaultMoonIntensity.
    LightParams moon{glm::dvec3(0.85, 0.92, 1.0), kDefaultMoonIntensity};
    HeightFogParams fog;
    /// A city's glow on the night sky (night_sky.hpp), off by default.
    LightPollution lightPollution;
    /// Where the global fog's in-scattered colour comes from.
    FogColourMode fogColourMode = FogColourMode::Sky;
    /// Global fog tint or radiance (see fogColourMode), scene-linear Rec.709.
    glm::dvec3 fogColour{1.0, 1.0, 1.0};
    /// How the fog (global, volumes, emitters) is meant to be drawn.
    FogRenderMode fogRenderMode = FogRenderMode::Analytic;
    /// The volumetric mode's own settings (ignored by the analytic fog).
    VolumetricFogParams volumetricFog;
    /// How radiance becomes a picture: manual or automatic EV100 and a
    /// compensation keyed over the day (aerial/exposure.hpp).
    ExposureParams exposure;
    /// The volumetric cloud layer (aerial/clouds.hpp); coverage 0 by default.
    CloudParams clouds;
};

/// The valid ranges of a preset's view (validatePreset and the schema
/// enforce them): eye and target components in [-kViewMaxCoordinate,
/// kViewMaxCoordinate] m, at least kViewMinDistance apart; the vertical
/// field of view in [kViewMinFovDeg, kViewMaxFovDeg] deg.
inline constexpr double kViewMaxCoordinate = 1e7;
inline constexpr double kViewMinDistance = 0.01;
inline constexpr double kViewMinFovDeg = 1.0;
inline constexpr double kViewMaxFovDeg = 179.0;

/// The camera a preset is meant to be seen from, framing what it is about
/// (file: "view": {"eye_m", "target_m", "fov_deg"}). `aerial render` and
/// the contact sheet look from it when no camera is given; the editor
/// opens the preset with its viewport there. World space, Y up, metres
/// (DESIGN.md, "Units and axes"); the camera's up is +Y.
struct PresetView {
    /// Eye position [m], each component in [-1e7, 1e7].
    glm::dvec3 eye{0.0, 30.0, 120.0};
    /// A point the camera looks at [m], each component in [-1e7, 1e7], at
    /// least 0.01 m from the eye.
    glm::dvec3 target{0.0, 10.0, -200.0};
    /// Vertical field of view [deg], 1..179. Default 60 (the file may leave
    /// it out).
    double verticalFovDeg = 60.0;
};

/// A whole preset: what a file holds, what the editor edits.
struct Preset {
    /// Shown to the artist.
    std::string name;
    std::string description;
    Environment environment;
    /// Fog volumes; ids unique among volumes.
    std::vector<FogVolume> volumes;
    /// Emitters; ids unique among emitters.
    std::vector<Emitter> emitters;
    /// Cloud volumes (clouds.hpp): each sets the cloud coverage inside it,
    /// applied in order; ids unique among cloud volumes; at most
    /// limits::kMaxCloudVolumes.
    std::vector<CloudVolume> cloudVolumes;
    /// At most one track per target.
    std::vector<Track> tracks;
    /// Named weather states (weather_state.hpp), names unique; at most
    /// limits::kMaxWeatherStates, each with at most
    /// limits::kMaxWeatherOverrides overrides.
    std::vector<WeatherState> weather;
    /// Regions where a weather state holds (weather_state.hpp), ids unique,
    /// each naming a state of `weather` or "none"; at most
    /// limits::kMaxWeatherRegions. In a file: "weather": {"regions": [...]}.
    std::vector<WeatherRegion> weatherRegions;
    /// The camera that frames the preset (PresetView); none: the
    /// application's own default camera. Optional in a file, written only
    /// when set.
    std::optional<PresetView> view;
};

/// One problem with a preset (an error or a warning).
struct PresetIssue {
    enum class Severity { Error, Warning };
    Severity severity = Severity::Error;
    /// The file it concerns ("" for presets built in code).
    std::string file;
    /// JSON pointer of the field (RFC 6901), e.g. "/volumes/2/half_extents_m/1";
    /// "" for the whole document.
    std::string pointer;
    /// 1-based position in the file of the value (or syntax error); 0 when
    /// unknown (presets built in code, or a missing field: its parent's).
    int line = 0;
    int column = 0;  ///< in UTF-8 code points
    /// Why, in words.
    std::string message;

    /// "file:line:column: error: /pointer: message".
    std::string toString() const;
};

struct PresetLoadResult {
    /// The preset, only when there are no errors (never half-loaded).
    std::optional<Preset> preset;
    std::vector<PresetIssue> errors;
    /// Unknown fields and other harmless oddities; the preset still loaded.
    std::vector<PresetIssue> warnings;

    bool ok() const { return preset.has_value(); }
};

struct SaveResult {
    /// Empty on success. On failure the old file (if any) is untouched.
    std::vector<PresetIssue> errors;
    bool ok() const { return errors.empty(); }
};

/// The track animating `target`, or null.
Track* findTrack(Preset& preset, const TrackTarget& target);
const Track* findTrack(const Preset& preset, const TrackTarget& target);

/// Editing helper: gives a volume (scope Volume), emitter (scope Emitter) or
/// cloud volume (scope CloudVolume) a new id and retargets its tracks and
/// weather overrides. Returns false and changes nothing when
/// `oldId` is unknown or `newId` is malformed or taken.
bool changeObjectId(Preset& preset, ParamScope scope, const std::string& oldId, const std::string& newId);

/// Keys that follow the sun (TrackKey::anchor): sets each anchored key's
/// time from the preset's location and date (anchoredKeyHours), then puts
/// every track's keys back in time order (stable), so a new date or place
/// moves those keys with the sun. Returns how many keys changed time.
/// loadPreset, parsePreset and CompiledPreset call it; so does an editor
/// after changing the location or anchoring a key. Two keys of a track
/// that land on the same time are left for validatePreset to report.
std::size_t resolveKeyAnchors(Preset& preset);

/// Editing helper: removes a volume, emitter or cloud volume and the tracks
/// and weather overrides that target it. Returns false when there is no
/// such object.
bool removeObject(Preset& preset, ParamScope scope, const std::string& id);

/// The built-in preset the editor opens on: Earth's atmosphere at 45 deg N
/// in June, a light global fog, a morning ground-fog volume that burns off
/// by noon and a lamp that is lit at night, keyed over the day.
Preset defaultPreset();

/// Reads the glTF mesh of every mesh fog volume (FogVolume::meshData) from
/// its "mesh" file, a relative path taken from `baseFolder` (the preset
/// file's folder; "" for the working directory); other volumes' meshData is
/// cleared. A file read before and unchanged since is shared, not read
/// again. Returns one error per volume that has no usable mesh (pointer
/// /volumes/<i>/mesh, the file and the reason: missing, not glTF, open or
/// non-manifold edge, flipped triangles, too many triangles); those
/// volumes are left without a mesh (drawn as nothing). loadPreset and
/// parsePreset call it; an editor calls it after changing a "mesh" field.
std::vector<PresetIssue> resolveFogMeshes(Preset& preset, const std::string& baseFolder);

/// Reads a preset file. Never throws.
PresetLoadResult loadPreset(const std::string& path);

/// Parses preset JSON text; `fileName` names the source in issues and its
/// folder is where mesh volumes' relative "mesh" paths start (the working
/// directory for "<memory>").
/// Never throws.
PresetLoadResult parsePreset(std::string_view jsonText, std::string_view fileName = "<memory>");

/// Checks a preset built in code against the parameter table: ranges,
/// finite numbers, unit vectors, unique and well-formed ids, Mie extinction
/// >= scattering, tracks (known animatable targets, keys in [0, 24) h,
/// strictly increasing, values in range). Issues carry JSON pointers but
/// no positions. The loader runs exactly these checks.
std::vector<PresetIssue> validatePreset(const Preset& preset);

/// The canonical JSON text of a preset: stable key order (the parameter
/// table's), every parameter written, numbers in the shortest form that
/// reads back bit-exact. Does not validate.
std::string presetToJson(const Preset& preset);

/// Validates (so nothing non-finite or out of range is written), then
/// writes atomically through aerial/detail/file_system.hpp: a temporary file
/// in the same directory, flushed and fsync'ed, then renamed over `path`. On
/// any failure (missing or read-only directory, full disk, fsync or rename
/// error) the old file survives, no temporary is left, and the reason names
/// the file ("not saved: cannot write dir/.x.json.tmp-...: No space left on
/// device"). Never throws.
SaveResult savePreset(const Preset& preset, const std::string& path);

/// True when both presets hold the same values, bit for bit on every
/// number (compared through the parameter table, plus tracks, weather
/// states and weather regions).
bool presetsIdentical(const Preset& a, const Preset& b);

/// The JSON Schema (draft 2020-12) of the preset format, generated from the
/// parameter table; presets/aerial-preset.schema.json is this text.
std::string presetJsonSchema();

}  // namespace aerial
