// editor/weather_edit.hpp — the edits of the Weather panel (no GUI,
// unit-tested): a preset's weather states (aerial/weather_state.hpp) added,
// renamed and removed, their overrides added, changed and removed, the
// panel's line for an override ("Cloud coverage: set 0.97 (keyed 0.3 ->
// 0.97 storm)"), and the weather regions added, changed and removed (a
// state's rename carries the regions that hold it; removing a state removes
// them too). The viewport's preview of the weather is weather_preview.hpp.
//
// Each edit checks its result with core's validatePreset, so a refused name
// or value says exactly what the loader would ("\"none\" is taken: it names
// the keyed values without weather"): the rules live in core only. The
// apply* forms run an edit through Document::apply, as one undo step that
// marks the document dirty (the panel's buttons and the script's weather_*
// commands call them):
//   std::string error;
//   if (!applyAddWeatherState(doc, "storm", error)) status = error;  // nothing recorded
//   applyAddWeatherOverride(doc, 0, newWeatherOverride(doc.preset(), ref, t), error);
//   doc.undo();
#pragma once

#include "document.hpp"
#include "preset_edit.hpp"

#include <aerial/weather_state.hpp>

#include <glm/vec3.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace aerial::editor {

/// "set", "add", "scale" (the JSON keys).
const char* weatherModeName(WeatherOverrideMode mode);
/// The inverse; false (mode unchanged) for any other word.
bool weatherModeFromName(std::string_view name, WeatherOverrideMode& mode);

/// The index of the state called `name` in preset.weather, or -1.
int weatherStateIndex(const Preset& preset, std::string_view name);
/// The index of the override of `target` in `state`, or -1.
int weatherOverrideIndex(const WeatherState& state, const TrackTarget& target);
/// A state name the preset does not use yet: `base`, else `base_2`, `base_3`, ...
std::string uniqueWeatherStateName(const Preset& preset, std::string_view base);

// ---------------------------------------------------------------------------
// Edits. Each changes `preset` only when what it touches passes
// validatePreset afterwards; otherwise it returns false, leaves the preset
// as it was and sets `error` to validatePreset's message.

/// Appends an empty state called `name`.
bool addWeatherState(Preset& preset, const std::string& name, std::string& error);
/// Renames state `state` (an index into preset.weather).
bool renameWeatherState(Preset& preset, int state, const std::string& name, std::string& error);
/// Removes state `state`; false when there is none.
bool removeWeatherState(Preset& preset, int state);
/// Appends `o` to state `state`; refused when the state already overrides
/// its target (validatePreset: one override per target and state).
bool addWeatherOverride(Preset& preset, int state, const WeatherOverride& o, std::string& error);
/// Gives override `index` of state `state` a mode and a value (the target stays).
bool setWeatherOverride(Preset& preset, int state, int index, WeatherOverrideMode mode,
                        const glm::dvec3& value, std::string& error);
/// Removes override `index` of state `state`; false when there is none.
bool removeWeatherOverride(Preset& preset, int state, int index);

// ---------------------------------------------------------------------------
// Values

/// A new override of `ref`: Set, to the value the parameter has at
/// `timeHours` in `preset` (so adding one changes nothing until it is edited).
WeatherOverride newWeatherOverride(const Preset& preset, const ParamRef& ref, double timeHours);
/// The value an override gives where the keyed value is `keyed`
/// (readParam's layout): the value (set), keyed + value (add) or keyed *
/// value per component (scale), clamped to the parameter's valid range: what
/// CompiledPreset::evaluate writes when the state holds fully.
void overriddenValue(const ParamDesc& desc, const double keyed[4], const WeatherOverride& o, double out[4]);
/// The value for `mode` that gives, at the keyed value `keyed`, what `o`
/// gives there now (changing the mode keeps the picture): the result (set),
/// result - keyed (add) or result / keyed (scale; 1 where keyed is 0 or the
/// ratio would be negative).
glm::dvec3 valueForMode(const ParamDesc& desc, const double keyed[4], const WeatherOverride& o,
                        WeatherOverrideMode mode);

/// The panel's line for override `o` of state `stateName` at `timeHours`:
/// "Cloud coverage: set 0.97 (keyed 0.3 -> 0.97 storm)"; values as the
/// curve view prints them (4 significant digits, with the unit). `keyed`
/// is the value shown there (the inspector's).
std::string weatherOverrideText(const Preset& preset, const WeatherOverride& o, const std::string& stateName,
                                const double keyed[4]);

// ---------------------------------------------------------------------------
// As one undo step of `doc` (Document::apply). False, with nothing recorded,
// when the edit is refused (`error` says why) or changes nothing. A value
// edit with `continuous` joins the previous one of the same override until
// Document::closeMerge (a drag is one step).

bool applyAddWeatherState(Document& doc, const std::string& name, std::string& error);
bool applyRenameWeatherState(Document& doc, int state, const std::string& name, std::string& error);
bool applyRemoveWeatherState(Document& doc, int state, std::string& error);
bool applyAddWeatherOverride(Document& doc, int state, const WeatherOverride& o, std::string& error);
bool applySetWeatherOverride(Document& doc, int state, int index, WeatherOverrideMode mode,
                             const glm::dvec3& value, bool continuous, std::string& error);
bool applyRemoveWeatherOverride(Document& doc, int state, int index, std::string& error);

// ---------------------------------------------------------------------------
// Weather regions (weather_state.hpp). The same rules: refused with
// validatePreset's message, applied as one undo step.

/// The index of the region with id `id` in preset.weatherRegions, or -1.
int weatherRegionIndex(const Preset& preset, std::string_view id);
/// A region id the preset does not use yet: `base`, else `base_2`, ...
std::string uniqueWeatherRegionId(const Preset& preset, std::string_view base);
/// A new region: a fresh id ("region"), `shape`, holding `state`, centred on
/// `centre` [m] (the camera's target), 2 km x 1 km x 2 km, a 200 m blend.
WeatherRegion newWeatherRegion(const Preset& preset, WeatherRegionShape shape, const std::string& state,
                               const glm::dvec3& centre);
/// "box", "ellipsoid"; and the inverse (false for another word).
const char* weatherRegionShapeName(WeatherRegionShape shape);
bool weatherRegionShapeFromName(std::string_view name, WeatherRegionShape& shape);
/// The region's heading [deg]: its rotation's turn about +Y (from +X towards
/// -Z, i.e. counter-clockwise seen from above), in (-180, 180]. Setting it
/// replaces the rotation by that turn alone (a region tilted in a file
/// loses its tilt).
double weatherRegionYawDeg(const WeatherRegion& region);
void setWeatherRegionYawDeg(WeatherRegion& region, double degrees);
/// Sets one field from the script's words, the keys as in a file ("id",
/// "name" (its words joined by spaces), "shape", "position_m" X Y Z, "half_extents_m" X Y Z, "blend_m",
/// "priority", "state") plus "yaw_deg"; false with `error` for an unknown
/// key or a value that is not one (ranges are validatePreset's).
bool setWeatherRegionField(WeatherRegion& region, std::string_view key,
                           const std::vector<std::string>& values, std::string& error);

bool addWeatherRegion(Preset& preset, const WeatherRegion& region, std::string& error);
/// Replaces region `index` by `region` (every field, the id included).
bool setWeatherRegion(Preset& preset, int index, const WeatherRegion& region, std::string& error);
bool removeWeatherRegion(Preset& preset, int index);

bool applyAddWeatherRegion(Document& doc, const WeatherRegion& region, std::string& error);
bool applySetWeatherRegion(Document& doc, int index, const WeatherRegion& region, bool continuous,
                           std::string& error);
bool applyRemoveWeatherRegion(Document& doc, int index, std::string& error);

/// Every animatable parameter of the preset, globals first, then each
/// volume's, emitter's and cloud volume's (what an override may target), in
/// the parameter table's order.
std::vector<ParamRef> animatableParams(const Preset& preset);

}  // namespace aerial::editor
