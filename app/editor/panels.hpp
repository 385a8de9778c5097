// editor/panels.hpp — the panels around the viewport. Each draws one
// window's contents with Dear ImGui and edits, in place, the parts it is
// given (editor_parts.hpp) and nothing else; a user action it offers runs
// the action table's declaration (actions.hpp). What a panel has to say
// goes to `status` (the status bar).
//
//   editor_outliner.cpp   drawOutliner, drawSkyPreview
//   editor_inspector.cpp  drawInspector, keyAllChangedAt
//   editor_param_edits.cpp editParam, editTextParam, keyParamNow
//   editor_timeline.cpp   drawTimeline
//   editor_curves.cpp     drawCurveView, curveColour, drawSunKeyRays (the
//                         timeline's curve area)
//   editor_key_menu.cpp   keyShapeMenu, followTheSunMenu (the key menu's
//                         parts the curve view and the track row share)
//   editor_weather.cpp    drawWeatherPanel
#pragma once

#include "actions.hpp"
#include "editor_parts.hpp"

#include <functional>
#include <string>

namespace aerial::editor {

/// The outliner: the atmosphere, lights, global fog, every volume and
/// emitter (select, rename inline, duplicate, delete). `select` selects as
/// a click in the viewport does.
void drawOutliner(Document& doc, EditState& edit, const ActionTable& actions,
                  const std::function<void(Selection)>& select);

/// The sky preview below the outliner: the solved sky as a fisheye through
/// the viewport's display transform, made again when the sky or the
/// display changed.
void drawSkyPreview(SkyPreview& preview, const SkyService& sky, const ViewportState& view, int frameIndex);

/// The inspector of the selection, generated from the parameter table;
/// `state` is the preset evaluated at `timeHours`.
void drawInspector(Document& doc, EditState& edit, double timeHours, const PresetState& state,
                   const LightReport& light, const ActionTable& actions, std::string& status);

/// The timeline: playback controls, ruler, keys and the selected parameter's curve.
void drawTimeline(Document& doc, EditState& edit, Playback& playback, const ActionTable& actions,
                  std::string& status);

/// The Weather panel (View > Weather): the preset's weather states; the
/// selected state's overrides, each with the value keyed at `timeHours` and
/// the one the state gives; adding, renaming and removing states, adding,
/// changing and removing overrides (weather_edit.hpp, one undo step each);
/// and the viewport's preview (edit.weather.preview: none, a state, a
/// transition at a fraction, Play transition from the clock `nowSeconds`
/// [s]), which never edits the document; the weather regions, each with its
/// weight at `camera`'s eye, added (around its target), edited and removed.
void drawWeatherPanel(Document& doc, EditState& edit, double timeHours, double nowSeconds,
                      const CameraController& camera, std::string& status);

/// The timeline's key operations (the action table's timeline_delete_keys,
/// timeline_copy_key and timeline_paste_key, and the timeline's buttons).
/// Deletes the keys selected on the curves, else the selected key of the
/// inspector's parameter (one undo step); false when there is none.
bool deleteTimelineKeys(Document& doc, EditState& edit);
/// Copies the selected key of the inspector's parameter; false when none.
bool copyTimelineKey(const Document& doc, EditState& edit);
/// Pastes the copied key on the inspector's parameter at `timeHours` (one
/// undo step); false when nothing is copied or the key does not fit it.
bool pasteTimelineKey(Document& doc, EditState& edit, double timeHours);

/// The timeline's curve area (editor_curves.cpp): the curves shown
/// (edit.curves.shown and the inspector's parameter) between `top` and
/// `bottom` [px], from x0 to x1 [px] in edit.curves.time, a legend from
/// `labelX` to x0; picks, drags and box-selects keys, sets the time on a click.
void drawCurveView(Document& doc, EditState& edit, Playback& playback, float labelX, float x0, float x1,
                   float top, float bottom);
/// The key menu's "Follow the sun" submenu (the curve view's and the track
/// row's): anchors the keys of `picked` to a sun event where they stand, or
/// gives them a fixed time again, one undo step; `suffix` follows the
/// menu's name (" (3 keys)").
void followTheSunMenu(Document& doc, const std::vector<CurvePoint>& picked, const std::string& suffix);
/// The key menu's shape items for the keys of `picked` (editor_key_menu.cpp):
/// flat or automatic tangents, unified or broken handles, the interpolation
/// of the segment after each key; each choice one undo step.
void keyShapeMenu(Document& doc, const std::vector<CurvePoint>& picked, const std::string& suffix);
/// The curves the timeline's curve view shows, in order: those toggled on
/// (edit.curves.shown), then the inspector's parameter when it is not among them.
std::vector<TrackTarget> shownCurveTargets(const Preset& preset, const EditState& edit);
/// The colour (ImU32) a curve is drawn in: its palette entry among the
/// curves shown (curvePaletteIndices over shownCurveTargets), its own entry
/// when it is not shown.
unsigned curveColour(const Preset& preset, const EditState& edit, const TrackTarget& target);
/// The mark of a key that follows the sun (TrackKey::anchor): eight short
/// rays around its point at (x, y) [px] of `radius` [px], in the current
/// window (the curve view and the timeline's track row draw it).
void drawSunKeyRays(float x, float y, float radius);

/// Sets a parameter at `timeHours` as the inspector does: with auto-key off
/// an animated parameter away from its keys gets an unkeyed change
/// (edit.pending); otherwise a key when it is animated, else its constant
/// value, as one undo step (with `continuous` part of the step of a drag,
/// until Document::closeMerge). Returns "" or, when a value lies outside
/// the parameter's valid range, what it was clamped to:
/// "<label> clamped to <value> (valid <lo>..<hi> <unit>)", and for a
/// colour or vector every value clamped, "<label>: 2 values clamped: r 1.5
/// to 1, b -0.2 to 0 (valid <lo>..<hi> <unit>)".
std::string editParam(Document& doc, EditState& edit, const ParamRef& ref, const double value[4],
                      bool continuous, double timeHours);
/// Keys `ref` at `timeHours` (the key diamond, the script's key): its
/// unkeyed change at the time it was made when it has one, else the value
/// shown there. One undo step.
void keyParamNow(Document& doc, EditState& edit, const ParamRef& ref, double timeHours);
/// Sets a text parameter of the environment (location.date) as one undo
/// step when the preset still validates; otherwise changes nothing and
/// returns false with the loader's reason in `error`.
bool editTextParam(Document& doc, const ParamRef& ref, const std::string& text, std::string& error);

/// Keys every animatable parameter whose value at `timeHours` differs from
/// the saved preset (one undo step); returns how many.
int keyAllChangedAt(Document& doc, double timeHours);

}  // namespace aerial::editor
