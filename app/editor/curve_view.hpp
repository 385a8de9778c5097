// editor/curve_view.hpp — the timeline's curve view without a window: the
// visible time span (zoom and pan around the mouse, fit to the day, ruler
// ticks), the curves shown (toggled from the inspector, view state only,
// never in the preset), each normalised to its keys' range, hit-testing and
// box selection of key points, and moving many keys at once in time and
// value as one edit. editor_curves.cpp draws it with Dear ImGui; scripts and
// tests call the same functions.
//
// Normalisation: a curve is drawn from its keys' smallest to largest value
// (over all its components) padded by kCurveRangePad of that span at both
// ends, so every curve uses the height of the view whatever its unit or
// slider range (a density of 1e-4..3e-3 /m and a colour of 0..1 overlay
// readably). The first drag or typed value of a curve pins its range
// (CurveViewState::pinRange) until the view is fit to the day again, so the
// drag sensitivity does not change after every drag; a key taken outside a
// pinned range widens it. The inspector's parameter gets a value axis in
// its unit (valueTicks).
//
// Picking prefers the inspector's parameter: where another curve's key lies
// on one of its keys, a click takes the inspector's (pickCurvePoint). The
// legend names a curve by its object's name and the parameter's label
// ("Haze bank density"); its colour is its target's own palette entry
// unless a curve shown before it has that one (curvePaletteIndices), so
// two curves shown never share a colour.
// The selected keys' time and value can be typed (setCurvePointsTime,
// setCurvePointsValue: one undo step each).
//
// A selected key's tangent handles (TrackKey::tangents) are drawn along its
// slopes and set them when dragged (tangentHandleOffset, slopeOfHandle,
// setKeyTangent; unified or broken, setTangentMode). Keys of several curves
// are copied with their relative times and pasted at another time, each
// onto its own curve, never beside an existing key (copyCurvePoints,
// pasteCurveKeys).
//
// Keys that follow the sun (TrackKey::anchor, timeline.hpp) are shown as
// "sunset + 0:20 (19:52)"; a selection is anchored to an event where it
// stands (the curve does not change), and shifted by a typed amount with
// the same limits as a drag, an anchored key keeping its anchor.
#pragma once

#include "preset_edit.hpp"

#include <aerial/preset.hpp>
#include <aerial/sun.hpp>

#include <glm/vec2.hpp>

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace aerial::editor {

/// The shortest and longest time span the view shows [h] (15 minutes, two days).
inline constexpr double kMinViewSpanHours = 0.25;
inline constexpr double kMaxViewSpanHours = 48.0;
/// How far the view may pan past the day [h]: the day is cyclic, so
/// yesterday evening and tomorrow morning show the wrap through midnight.
inline constexpr double kViewMarginHours = 12.0;

/// The timeline's visible time span [h].
struct TimeView {
    double startHours = 0.0;
    double endHours = 24.0;

    double span() const { return endHours - startHours; }
    /// x [px] of time `t` [h] on a strip from `x0` to `x1` [px].
    double xOf(double t, double x0, double x1) const { return x0 + (t - startHours) / span() * (x1 - x0); }
    /// Time [h] (not wrapped) at x [px] on that strip.
    double tOf(double x, double x0, double x1) const {
        return startHours + (x - x0) / (x1 - x0 > 0.0 ? x1 - x0 : 1.0) * span();
    }
    bool operator==(const TimeView&) const = default;
};

/// The view zoomed by `factor` (> 1 zooms in) keeping `anchorHours` (the
/// time under the mouse) where it is; the span stays within
/// [kMinViewSpanHours, kMaxViewSpanHours] and the view within the day plus
/// kViewMarginHours either side.
TimeView zoomView(const TimeView& view, double anchorHours, double factor);
/// The view moved by `deltaHours`, kept within the day plus the margins.
TimeView panView(const TimeView& view, double deltaHours);
/// The whole day, 00:00 to 24:00 (F, double-click on the ruler).
inline TimeView fitView() { return {}; }
/// The ruler's tick step [h]: the finest of 5 min, 15 min, 30 min, 1 h,
/// 3 h, 6 h whose ticks lie at least `minSpacingPx` apart on `widthPx`.
double tickStepHours(const TimeView& view, double widthPx, double minSpacingPx);

/// Padding of a curve's value range, as a fraction of its span.
inline constexpr double kCurveRangePad = 0.1;

/// The value range a curve is drawn in: lo at the bottom, hi at the top.
struct CurveRange {
    double lo = 0.0;
    double hi = 1.0;
    /// 0 at lo, 1 at hi.
    double normalised(double value) const { return (value - lo) / (hi - lo); }
    double valueOf(double normalised) const { return lo + normalised * (hi - lo); }
    bool operator==(const CurveRange&) const = default;
};
/// The range of values from `lo` to `hi` padded by kCurveRangePad; a single
/// value (lo == hi) gets +-10 % of its magnitude, at least 5 % of the
/// parameter's slider range (so a flat curve sits in the middle).
CurveRange paddedRange(double lo, double hi, const ParamDesc& desc);
/// The range of a track's keys over the components the parameter has.
CurveRange curveRangeOf(const Track& track, const ParamDesc& desc);

/// The parameter a track target names (its object found by id); nullopt
/// when the preset has no such parameter or object.
std::optional<ParamRef> paramRefOf(const Preset& preset, const TrackTarget& target);

/// A curve as the session remembers it: the global parameter's path
/// ("fog.density_per_m"), or scope, object id and parameter key
/// ("volume:valley_fog:density_per_m").
std::string curveKey(const TrackTarget& target);
/// The inverse; nullopt for text that names no parameter.
std::optional<TrackTarget> curveTargetOf(std::string_view key);

/// The legend's name of a curve: a global parameter's label ("Fog
/// density"); an object's name (its id when the name is empty) and the
/// parameter's label ("Haze bank density"); the curve key when the preset
/// has no such parameter or object.
std::string curveLabel(const Preset& preset, const TrackTarget& target);
/// How many colours the curve view's palette has (editor_curves.cpp).
inline constexpr int kCurvePaletteSize = 12;
/// A curve's own palette entry [0, paletteSize): a hash (FNV-1a) of its
/// curve key (scope, object id, parameter), the same in every session.
int curvePaletteIndex(const TrackTarget& target, int paletteSize);
/// The palette entries of the curves shown together, in the order shown
/// (CurveViewState::shown, then the inspector's parameter): each curve takes
/// its own entry (curvePaletteIndex) unless a curve before it has it, else
/// the next free entry after it (wrapping). So no two curves share a colour
/// while there are no more of them than colours (past that, the extra ones
/// take their own entries), a curve keeps its own colour wherever it does
/// not clash, and showing a curve recolours none shown before it.
std::vector<int> curvePaletteIndices(const std::vector<TrackTarget>& curves, int paletteSize);

/// The ticks of a value axis over `range`: the multiples inside it of the
/// finest step of 1, 2 or 5 x 10^n that gives at most `maxTicks` of them,
/// in increasing order (zero as 0, never -0); none for an empty range.
std::vector<double> valueTicks(const CurveRange& range, int maxTicks);
/// A value with its unit as the view shows it: "0.0031 1/m", "12 deg",
/// "0.5" (no unit); 4 significant digits (`digits` to change that).
std::string valueWithUnit(double value, std::string_view unit, int digits = 4);

/// One component of one key of one track: what the curve view selects and drags.
struct CurvePoint {
    TrackTarget target;
    int key = -1;
    int component = 0;
    bool operator==(const CurvePoint&) const = default;
};

/// Index of the point nearest `mouse` within `radiusPx`, or -1.
int hitTestPoints(const std::vector<glm::dvec2>& points, glm::dvec2 mouse, double radiusPx);
/// The point a click at `mouse` picks (ids[i] is points[i]'s): the nearest
/// within `radiusPx` of the curve `preferred` (the inspector's parameter)
/// when one is in reach, so that where a key of another curve lies on (or
/// near) one of its keys the inspector's wins; else the nearest of all; -1
/// when none is in reach.
int pickCurvePoint(const std::vector<glm::dvec2>& points, const std::vector<CurvePoint>& ids,
                   glm::dvec2 mouse, double radiusPx, const std::optional<TrackTarget>& preferred);
/// Indices of the points inside the box with corners `a` and `b` (any two
/// opposite corners), in order.
std::vector<int> pointsInBox(const std::vector<glm::dvec2>& points, glm::dvec2 a, glm::dvec2 b);

/// The key points of the curves of `targets` in time and value: x the
/// key's time [h], y its component normalised to the curve's range (0
/// bottom, 1 top); what a script's box selection tests.
struct CurveKeyPoints {
    std::vector<glm::dvec2> timeValue;
    std::vector<CurvePoint> ids;
};
CurveKeyPoints keyPointsOf(const Preset& preset, const std::vector<TrackTarget>& targets);

/// A point as a drag found it: where it started and the range it is drawn in.
struct CurveDragItem {
    CurvePoint point;
    double timeHours = 0.0;  ///< the key's time when the drag began [h]
    double value = 0.0;      ///< the component's value when the drag began
    CurveRange range;        ///< the curve's range when the drag began
};
/// The drag items of `points` (those the preset has; others are left out).
std::vector<CurveDragItem> dragItemsOf(const Preset& preset, const std::vector<CurvePoint>& points);

/// Moves the items' keys together: every key by the same time `dtHours`,
/// limited so that no moved key comes within kMinKeyGap of a key that does
/// not move or leaves [0, 24 - kMinKeyGap] (the keys keep their order, so
/// their indices stay valid); every component by `dNormalised` of its
/// curve's range, clamped into the parameter's valid range. Absolute: the
/// keys are set from the items' starting values, so a drag calls it every
/// frame with its whole offset. Returns the time shift applied [h].
double moveCurvePoints(Preset& preset, const std::vector<CurveDragItem>& items, double dtHours,
                       double dNormalised);
/// How many distinct keys the points belong to.
int keyCountOf(const std::vector<CurvePoint>& points);
/// The undo step's name for moving them: "Move key", "Move 3 keys".
std::string moveLabel(const std::vector<CurvePoint>& points);
/// Removes the points' keys (a track goes with its last key); returns how
/// many keys went.
int removeCurvePoints(Preset& preset, const std::vector<CurvePoint>& points);
/// The undo step's name for that: "Delete key", "Delete 3 keys".
std::string deleteLabel(const std::vector<CurvePoint>& points);
/// Sets (or clears) the flat tangent of the points' keys; either way their
/// own tangents (TrackKey::tangents) go: "Automatic tangent" resets a key's
/// handles. Returns how many keys changed.
int setFlatTangents(Preset& preset, const std::vector<CurvePoint>& points, bool flat);
/// Sets the interpolation of the segment after each of the points' keys
/// (TrackKey::interpolation; nullopt: the track's again); returns how many
/// keys changed.
int setKeyInterpolation(Preset& preset, const std::vector<CurvePoint>& points,
                        std::optional<Interpolation> interpolation);

// --- tangent handles (TrackKey::tangents; curve_keys.cpp) ---------------------------------------

/// The length of a selected key's tangent handles on screen [px].
inline constexpr double kTangentHandlePx = 40.0;
/// A key's two handles: the slope arriving at it (in, drawn before the key)
/// and the one leaving it (out, after it).
enum class TangentSide { In, Out };
/// Where a handle of slope `slope` [value unit per h] is drawn, relative to
/// its key [px, y down]: kTangentHandlePx along the slope as the curve is
/// drawn (`pxPerHour` across, `heightPx` for the whole of `range` up), on
/// the side's side of the key.
glm::dvec2 tangentHandleOffset(double slope, const CurveRange& range, double pxPerHour, double heightPx,
                               TangentSide side);
/// The slope [value unit per h] of a handle dragged to `offsetPx` from its
/// key (the inverse of tangentHandleOffset at any length); a handle dragged
/// past its key counts as a pixel on its own side (the slope of a vertical
/// line is out of reach), clamped to limits::kMaxKeyTangent.
double slopeOfHandle(glm::dvec2 offsetPx, const CurveRange& range, double pxPerHour, double heightPx,
                     TangentSide side);
/// Sets the point's component's slope on `side` (unified handles: both
/// sides). A key without its own tangents gets them from the automatic ones
/// first (unified, no longer flat), so the other handle stays where it was
/// drawn. False when the preset has no such key or the slope is not finite.
bool setKeyTangent(Preset& preset, const CurvePoint& point, TangentSide side, double slope);
/// Makes the points' keys' handles unified (both slopes become their mean)
/// or broken (independent from now on); keys without their own tangents
/// take the automatic ones first. Returns how many keys changed.
int setTangentMode(Preset& preset, const std::vector<CurvePoint>& points, TangentMode mode);
/// The undo step's name for that: "Unify tangent", "Break 3 tangents".
std::string tangentModeLabel(const std::vector<CurvePoint>& points, TangentMode mode);
/// The point's key's handle mode; nullopt when it has automatic tangents
/// (or the preset has no such key).
std::optional<TangentMode> tangentModeOf(const Preset& preset, const CurvePoint& point);

// --- copy and paste of keys across curves and times (curve_keys.cpp) ----------------------------

/// A copied key: its curve, its time after the earliest copied key [h] and
/// the key itself (value, flat, interpolation, tangents).
struct CopiedKey {
    TrackTarget target;
    double offsetHours = 0.0;
    TrackKey key;
};
/// The keys Ctrl+C took from the curves (several curves, their times kept
/// relative to each other).
struct CurveClipboard {
    std::vector<CopiedKey> keys;
    bool empty() const { return keys.empty(); }
};
/// Copies the points' keys (each key once, whatever its components), their
/// offsets from the earliest of them (a selection across midnight counts
/// from its first key after the longest gap, so 23:30 and 00:30 are an hour
/// apart).
CurveClipboard copyCurvePoints(const Preset& preset, const std::vector<CurvePoint>& points);
/// Pastes the clipboard with its earliest key at `timeHours` [h], each key
/// onto its own curve at `timeHours` + its offset (wrapped into the day),
/// as a key at a fixed time (a copied anchor is not kept). A key landing
/// within kMinKeyGap of an existing key replaces that key at its own time,
/// so the track never gets two keys closer than a minute; a curve whose
/// object is gone is left out; a track is created for a parameter that has
/// none. Returns the pasted keys' points (component 0), in the clipboard's
/// order.
std::vector<CurvePoint> pasteCurveKeys(Preset& preset, const CurveClipboard& clipboard, double timeHours);
/// The undo step's name for that: "Paste key", "Paste 3 keys".
std::string pasteLabel(const CurveClipboard& clipboard);

// --- typed shifts and keys that follow the sun (TrackKey::anchor) ------------------------------

/// The snap steps a key drag offers [min] (the timeline's Snap); the
/// default is kDefaultSnapHours, the quarter hour.
inline constexpr int kSnapStepsMinutes[] = {1, 5, 15, 60};

/// Reads a typed time shift [h]: an optional sign ('+' or '-', blanks
/// after it allowed), then a time aerial::parseClock reads ("+0:20",
/// "-1:00", "0:05", "-0.25", "+ 1.5h"). False on anything else.
bool parseShiftHours(std::string_view text, double& hours);
/// An offset [h] as "+ 0:20" or "- 1:05", rounded to the second; the
/// seconds only when it is off the minute ("+ 0:20:30").
std::string formatOffset(double hours);
/// An event as a menu names it: "sunrise", "civil dusk".
std::string sunEventLabel(SunEvent event);
/// A key's time as the view shows it: "19:52" for a key at a fixed time,
/// "sunset + 0:20 (19:52)" for one that follows the sun (its resolved time
/// as the minute that has begun, as the clock shows it).
std::string keyTimeText(const TrackKey& key);

/// Shifts the points' keys by `dtHours` exactly as a drag does
/// (moveCurvePoints: one shift for all, limited by the keys that do not
/// move and by the day; values unchanged). A key that follows the sun keeps
/// its anchor and its offset changes by the shift. Returns the shift
/// applied [h].
double shiftCurvePoints(Preset& preset, const std::vector<CurvePoint>& points, double dtHours);
/// The undo step's name for that: "Shift key", "Shift 3 keys".
std::string shiftLabel(const std::vector<CurvePoint>& points);

/// Makes the points' keys follow `event` where they stand (anchorKey at
/// the preset's location: neither time nor value changes, so the curve
/// stays as it is until the date or the place does); nullopt gives them a
/// fixed time again. Returns how many keys changed.
int anchorCurvePoints(Preset& preset, const std::vector<CurvePoint>& points, std::optional<SunEvent> event);
/// The undo step's name for that: "Anchor key to sunset", "Anchor 3 keys
/// to civil dusk", "Fix key time", "Fix 3 key times".
std::string anchorLabel(const std::vector<CurvePoint>& points, std::optional<SunEvent> event);
/// Whether every one of the points' keys follows `event` (nullopt: every
/// one has a fixed time); false for no keys. What the menu ticks.
bool allAnchoredTo(const Preset& preset, const std::vector<CurvePoint>& points,
                   std::optional<SunEvent> event);

// --- typed time and value of the selected keys; the drag's readout -----------------------------

/// A key's time as the Time field shows it: "19:52:00" (formatClock to the
/// second, always with the seconds).
std::string keyClockText(double hours);
/// Reads a typed value: a finite number ("0.0031", "-2", "3e-4"), blanks
/// around it allowed, optionally followed by `unit` ("0.0031 1/m", as the
/// Value field shows it). False on anything else.
bool parseKeyValue(std::string_view text, std::string_view unit, double& value);

/// The point the Time and Value fields show: the first of `points` the
/// preset has (its key's time and its component's value); nullopt for none.
std::optional<CurvePoint> leadPointOf(const Preset& preset, const std::vector<CurvePoint>& points);
/// Sets the lead point's key (leadPointOf) to `timeHours` [h] exactly and
/// shifts the other keys of the points by the same amount (one shift for
/// all, limited as a drag is: shiftCurvePoints). A key that follows the sun
/// keeps its anchor and its offset changes (setKeyTime). Returns the lead
/// key's time afterwards [h] (where the limits stopped it), NaN when none
/// of the points exists.
double setCurvePointsTime(Preset& preset, const std::vector<CurvePoint>& points, double timeHours);
/// The undo step's name for that: "Set key time", "Set 3 key times".
std::string setTimeLabel(const std::vector<CurvePoint>& points);
/// Sets the component of every point of the lead point's parameter (the
/// same scope and parameter: one unit) to `value`, clamped into the
/// parameter's valid range; points of other parameters are left alone.
/// Returns how many keys changed.
int setCurvePointsValue(Preset& preset, const std::vector<CurvePoint>& points, double value);
/// The undo step's name for that: "Set key value", "Set 3 key values".
std::string setValueLabel(const Preset& preset, const std::vector<CurvePoint>& points);
/// What a drag shows beside the cursor: the key's time and its
/// component's value with the unit, "19:52:00  0.0031 1/m"; a key that
/// follows the sun "sunset + 0:22 (19:52:00)  0.0031 1/m".
std::string keyReadout(const TrackKey& key, int component, const ParamDesc& desc);

/// A mouse drag on the timeline's canvas, from press to release.
struct CurveDrag {
    enum class Kind { None, Keys, Box, Pan, Handle } kind = Kind::None;
    glm::dvec2 from{0.0};  ///< where the button went down [px]
    /// Keys: the points dragged as they began, the one under the mouse
    /// (its time snaps), whether time and value have moved past the dead
    /// zone yet, and the offset applied last (time [h], normalised value).
    std::vector<CurveDragItem> items;
    int lead = -1;
    bool timeMoved = false, valueMoved = false;
    double appliedHours = 0.0, appliedNormalised = 0.0;
    /// Handle: the key point whose tangent handle is dragged, which one,
    /// and where the key is drawn [px].
    CurvePoint handlePoint;
    TangentSide handleSide = TangentSide::Out;
    glm::dvec2 handleKeyPx{0.0};
    bool additive = false;  ///< Box: Ctrl adds to the selection
    TimeView viewFrom;      ///< Pan: the view when it began
};

/// The curve view's state (view state: never saved in the preset; the
/// curves shown are remembered in the session, settings.hpp).
struct CurveViewState {
    TimeView time;
    CurveDrag drag;
    /// The curves overlaid besides the inspector's parameter, in the order shown.
    std::vector<TrackTarget> shown;
    /// The selected key points.
    std::vector<CurvePoint> selected;
    /// The step key drags snap to [h] (Snap: 1, 5, 15, 60 min; Shift: free).
    double snapHours = kDefaultSnapHours;
    /// The "Shift by" field's text ("+0:20"): what Enter shifts the selection by.
    std::string shiftText;
    /// The value ranges curves are drawn in, by curve key, pinned by their
    /// first drag or typed value and kept until the view is fit to the day
    /// (resetRanges): a drag's sensitivity stays the same from drag to drag.
    std::map<std::string, CurveRange> pinnedRanges;
    /// Where the curves were drawn last frame [px in the window]: x of
    /// time.startHours and time.endHours, y of the bottom (0) and top (1)
    /// of every curve's range (what a script's mouse drag aims at).
    double drawnX0 = 0.0, drawnX1 = 0.0, drawnBottom = 0.0, drawnTop = 0.0;

    bool isShown(const TrackTarget& target) const;
    /// Shows or hides a curve.
    void setShown(const TrackTarget& target, bool show);
    bool isSelected(const CurvePoint& point) const;
    /// Forgets selected points whose key the preset no longer has.
    void validate(const Preset& preset);

    /// The range `target`'s curve is drawn in: its pinned range when it has
    /// one (widened on the side where a key lies outside it, to the keys'
    /// padded range, curveRangeOf), else its keys' range.
    CurveRange rangeOf(const Preset& preset, const TrackTarget& target) const;
    /// Pins `target`'s range where it is drawn now (rangeOf), when the preset
    /// has its track.
    void pinRange(const Preset& preset, const TrackTarget& target);
    /// Unpins every range (the view fit to the day, another preset).
    void resetRanges() { pinnedRanges.clear(); }
};

/// The drag items of `points` with the ranges their curves are drawn in
/// (view.rangeOf): what a drag in the view moves.
std::vector<CurveDragItem> dragItemsOf(const Preset& preset, const std::vector<CurvePoint>& points,
                                       const CurveViewState& view);
/// keyPointsOf with the ranges the view draws the curves in.
CurveKeyPoints keyPointsOf(const Preset& preset, const std::vector<TrackTarget>& targets,
                           const CurveViewState& view);

}  // namespace aerial::editor
