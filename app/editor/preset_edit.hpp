// editor/preset_edit.hpp — the edits the editor makes to a Preset, as plain
// functions (no GUI, unit-tested): addressing a parameter of the parameter
// table ("fog.density_per_m", "volume[0].density_per_m"), reading the value
// shown at a time of day, setting it (auto-key: a parameter that has a track
// gets a key at the current time, one without changes its constant value),
// keys (add, remove, move in time, interpolation, copy/paste, "key all
// changed") and objects (add, duplicate, delete, rename).
#pragma once

#include <aerial/clouds.hpp>
#include <aerial/fog_mesh.hpp>
#include <aerial/param_table.hpp>
#include <aerial/preset.hpp>

#include <glm/vec3.hpp>

#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace aerial::editor {

/// One parameter of one object of a preset.
struct ParamRef {
    const ParamDesc* desc = nullptr;
    /// Index into preset.volumes / preset.emitters / preset.cloudVolumes;
    /// -1 for globals.
    int object = -1;

    ParamScope scope() const { return desc ? desc->scope : ParamScope::Global; }
    bool operator==(const ParamRef&) const = default;
};

/// "fog.density_per_m" (global), "volume[2].density_per_m",
/// "emitter[0].intensity_cd", "cloud_volume[1].coverage". nullopt with `error` set when the address
/// or the object index is unknown.
std::optional<ParamRef> parseParamAddress(const Preset& preset, std::string_view address, std::string* error);
/// The inverse of parseParamAddress.
std::string paramAddress(const ParamRef& ref);

/// How many objects of a scope the preset holds (0 for Global).
std::size_t objectCount(const Preset& preset, ParamScope scope);
/// The address prefix of a scope: "volume", "emitter", "cloud_volume"; ""
/// for Global.
std::string_view addressPrefix(ParamScope scope);

/// The object a parameter lives in (Environment, FogVolume, Emitter or
/// CloudVolume);
/// null when the index is out of range.
void* paramObjectOf(Preset& preset, const ParamRef& ref);
const void* paramObjectOf(const Preset& preset, const ParamRef& ref);

/// The track target of an animatable parameter (uses the object's id).
TrackTarget trackTargetOf(const Preset& preset, const ParamRef& ref);
/// Its track, or null.
const Track* trackOf(const Preset& preset, const ParamRef& ref);
Track* trackOf(Preset& preset, const ParamRef& ref);

/// The stored (constant) value as up to four doubles (readParam's layout).
void readBaseValue(const Preset& preset, const ParamRef& ref, double out[4]);
/// The value at `timeHours`: the track's when there is one, else the base
/// value. Components as readParam.
void readValueAt(const Preset& preset, const ParamRef& ref, double timeHours, double out[4]);

/// Sets the parameter as the inspector does: values are clamped into the
/// table's valid range; an animatable parameter with a track gets a key at
/// `timeHours` (replacing one there), any other one its constant value.
/// Enum and Int values are rounded. Strings are not handled here.
void setValueAt(Preset& preset, const ParamRef& ref, const double value[4], double timeHours);
/// What setValueAt does to the track of an animatable parameter (Scalar,
/// Colour, Vec3, Vec2): the value, clamped (and normalised for a unit
/// vector), keyed at `timeHours` or on the key within kKeyTimeTolerance of
/// it. False (the track unchanged) for a unit vector of no length.
bool setTrackValueAt(Track& track, const ParamDesc& desc, const double value[4], double timeHours);

/// Tolerance for "a key at this time" [h]: half a minute.
inline constexpr double kKeyTimeTolerance = 0.5 / 60.0;
/// Smallest gap between two keys [h] when dragging: one minute.
inline constexpr double kMinKeyGap = 1.0 / 60.0;

/// Index of the key within kKeyTimeTolerance of `timeHours` (wrapping), or -1.
int keyIndexAt(const Track& track, double timeHours);

/// Keys an animatable parameter at `timeHours` with its value shown there;
/// creates the track (Smooth) when it has none. False for parameters that
/// are not animatable.
bool keyParam(Preset& preset, const ParamRef& ref, double timeHours);

/// Removes key `index` of the track for `target`; the track goes when its
/// last key does. False when there is no such key.
bool removeKey(Preset& preset, const TrackTarget& target, int index);

/// Moves key `index` to `timeHours`, clamped between its neighbours (at least
/// kMinKeyGap away) and into [0, 24 - kMinKeyGap]. Returns the key's time.
double moveKey(Track& track, int index, double timeHours);

/// The step a dragged key snaps to by default [h]: the quarter hour.
inline constexpr double kDefaultSnapHours = 0.25;

/// Where a key dragged to `timeHours` lands: on another key of any track
/// (the dragged key itself excluded: `track`, `index`) within
/// `snapHours` [h] (the drag's few pixels), else on the nearest multiple
/// of `stepHours` [h] (the timeline's Snap: 1, 5, 15 or 60 min). A key
/// that follows the sun snaps its offset from its event instead ("sunset
/// + 0:15", not 19:15). The timeline snaps unless Shift is held.
double snapKeyTime(const Preset& preset, const TrackTarget& track, int index, double timeHours,
                   double snapHours, double stepHours = kDefaultSnapHours);

/// Every animatable parameter (globals, volumes, emitters, cloud volumes) whose value
/// shown at `timeHours` differs from `baseline`'s (matched by object id) gets
/// a key there. Returns how many keys were set.
int keyAllChanged(Preset& preset, const Preset& baseline, double timeHours);

/// A copied key: its value and the kind of parameter it came from.
struct KeyClipboard {
    bool valid = false;
    ParamType type = ParamType::Scalar;
    glm::dvec3 value{0.0};
};

/// Pastes `clip` as a key at `timeHours` on the parameter (creating its
/// track); false when the parameter is not animatable or its keys hold
/// another count of numbers (scalar 1, Vec2 2, Colour/Vec3 3).
bool pasteKey(Preset& preset, const ParamRef& ref, const KeyClipboard& clip, double timeHours);

// ---------------------------------------------------------------------------
// Objects

/// A new point emitter is a warm lamp: 200 cd (~2 500 lm, a bright
/// incandescent bulb), 2 700 K, a glowing core 0.5 m across (a = 4 /m^2).
inline constexpr double kNewEmitterIntensityCd = 200.0;
inline constexpr double kNewEmitterTemperatureK = 2700.0;
inline constexpr double kNewEmitterAttenuationPerM2 = 4.0;
/// A new lightning emitter: a channel of 1e10 cd seen through the cloud as
/// a glow ~100 m across (a = 1e-4 /m^2).
inline constexpr double kNewLightningIntensityCd = 1.0e10;
inline constexpr double kNewLightningAttenuationPerM2 = 1.0e-4;

/// Adds a volume (shape, centre) with a fresh id and name; returns its index.
int addVolume(Preset& preset, FogVolumeShape shape, const glm::dvec3& position);
/// Adds a mesh volume: `meshPath` as the preset stores it (meshPathFor), the
/// mesh loaded from it, scale 1 (the mesh's own metres), its lowest vertex
/// resting on `ground`; named after `label` (the file's stem). Returns its
/// index.
int addMeshVolume(Preset& preset, const std::string& meshPath, std::shared_ptr<const FogMesh> mesh,
                  const glm::dvec3& ground, const std::string& label);
/// What a preset saved at `presetPath` stores for the mesh file `meshFile`:
/// the path relative to the preset's folder, or the absolute path while the
/// preset is untitled ("").
std::string meshPathFor(const std::string& meshFile, const std::string& presetPath);
/// Rewrites the "mesh" paths of the mesh volumes, relative ones read from
/// `fromFolder` ("" = the working directory), so that they name the same
/// files relative to `toFolder`, or as absolute paths when `toFolder` is
/// "". Returns how many changed.
int rebaseMeshPaths(Preset& preset, const std::string& fromFolder, const std::string& toFolder);
/// Adds an emitter (point or lightning) with artist-sane values; returns its index.
int addEmitter(Preset& preset, EmitterKind kind, const glm::dvec3& position);
/// Half width [m] (x and z) of a new cloud volume: a cell 6 km across.
inline constexpr double kNewCloudVolumeHalfWidthM = 3000.0;

/// A new cloud volume for the layer `layer` (the clouds at the current time)
/// above `lookAt` (the point the camera looks at): centred in the layer
/// (height bottom + thickness / 2), kNewCloudVolumeHalfWidthM across x and z
/// and half the thickness tall, coverage 1 (a storm cell), edge softness 0.5.
/// Id, name and shape are set by addCloudVolume.
CloudVolume newCloudVolumeAt(const CloudParams& layer, const glm::dvec3& lookAt);
/// Adds `placed` (newCloudVolumeAt) as a box or an ellipsoid with a fresh id
/// and name ("Cloud box", "Cloud ellipsoid 2"); returns its index.
int addCloudVolume(Preset& preset, FogVolumeShape shape, const CloudVolume& placed);
/// Duplicates a volume, emitter or cloud volume (new id, " copy" name, tracks copied,
/// offset by `offset`); returns the new index or -1.
int duplicateObject(Preset& preset, ParamScope scope, int index, const glm::dvec3& offset);
/// Removes a volume, emitter or cloud volume, its tracks and the weather
/// overrides of it.
bool deleteObject(Preset& preset, ParamScope scope, int index);
/// Renames (the shown name, not the id).
bool renameObject(Preset& preset, ParamScope scope, int index, const std::string& name);
/// The preset name a file suggests: its stem with '_' and '-' as spaces and
/// the first letter capitalised ("misty_dawn.json" -> "Misty dawn").
std::string presetNameFromFile(const std::string& path);
/// Save As to `newPath`: the name to give the preset, or "" to keep its
/// own. It follows the new file when it was the one the old file suggests
/// (or the built-in default's), i.e. the artist never named it.
std::string nameAfterSaveAs(const std::string& currentName, const std::string& oldPath,
                            const std::string& newPath);

/// Changes an object's id (what tracks and games refer to): 1..64
/// characters of A-Z a-z 0-9 _ - . and unique among the objects of its
/// kind; every track and weather override of the object follows it. False with `error` (the
/// reason) otherwise, the preset unchanged.
bool setObjectId(Preset& preset, ParamScope scope, int index, const std::string& id, std::string& error);

}  // namespace aerial::editor
