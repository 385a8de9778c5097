// test_curve_view.cpp — the timeline's curve view without a window: zoom
// and pan of the time span, ruler ticks, normalisation of curves to their
// keys' range, hit-testing and box selection of key points, moving many
// keys in time and value at once, flat tangents and the undo step's name;
// typed shifts (limited as a drag) and keys that follow the sun (anchored
// where they stand, read as "sunset + 0:20 (19:52)"); the inspector's
// parameter winning where keys overlap, legend names, colours that follow
// the curve, the value axis and pinned ranges, and typed times and values
// (an anchored key's included).
#include "curve_view.hpp"
#include "document.hpp"

#include <aerial/clock.hpp>
#include <aerial/param_table.hpp>
#include <aerial/sun.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace aerial::editor {
namespace {

const ParamDesc& fogDensity() { return *findParam(ParamScope::Global, "fog.density_per_m"); }

Preset twoTracks() {
    Preset p;
    p.tracks.clear();
    Track fog;
    fog.target = TrackTarget::global("fog.density_per_m");
    fog.keys = {{6.0, glm::dvec3(0.01, 0, 0)}, {8.0, glm::dvec3(0.02, 0, 0)}, {10.0, glm::dvec3(0.0, 0, 0)}};
    Track haze;
    haze.target = TrackTarget::global("atmosphere.mie.scattering_per_m");
    haze.keys = {{12.0, glm::dvec3(1e-5)}, {18.0, glm::dvec3(2e-5)}};
    p.tracks = {fog, haze};
    return p;
}

/// Whether two tracks' keys are the same in time, value, flatness and anchor.
bool sameKeys(const Track& a, const Track& b) {
    if (a.keys.size() != b.keys.size()) return false;
    for (std::size_t k = 0; k < a.keys.size(); ++k)
        if (a.keys[k].timeHours != b.keys[k].timeHours || a.keys[k].value != b.keys[k].value ||
            a.keys[k].flat != b.keys[k].flat || a.keys[k].anchor != b.keys[k].anchor ||
            a.keys[k].offsetHours != b.keys[k].offsetHours)
            return false;
    return true;
}

TEST(CurveView, ZoomKeepsTheTimeUnderTheMouse) {
    const TimeView day = fitView();
    EXPECT_EQ(day.startHours, 0.0);
    EXPECT_EQ(day.endHours, 24.0);
    const TimeView in = zoomView(day, 6.0, 2.0);  // the mouse at 06:00, a quarter across
    EXPECT_DOUBLE_EQ(in.span(), 12.0);
    EXPECT_DOUBLE_EQ(in.startHours, 3.0);  // 06:00 is still a quarter across
    EXPECT_DOUBLE_EQ(in.xOf(6.0, 0.0, 1000.0), day.xOf(6.0, 0.0, 1000.0));
    EXPECT_DOUBLE_EQ(in.tOf(250.0, 0.0, 1000.0), 6.0);
    // Back out again: the same day.
    const TimeView out = zoomView(in, 6.0, 0.5);
    EXPECT_DOUBLE_EQ(out.startHours, 0.0);
    EXPECT_DOUBLE_EQ(out.endHours, 24.0);
    // Limits: never narrower than 15 min, never wider than two days or past the margins.
    EXPECT_DOUBLE_EQ(zoomView(day, 12.0, 1e6).span(), kMinViewSpanHours);
    const TimeView widest = zoomView(day, 12.0, 1e-6);
    EXPECT_DOUBLE_EQ(widest.span(), kMaxViewSpanHours);
    EXPECT_DOUBLE_EQ(widest.startHours, -kViewMarginHours);
    EXPECT_EQ(zoomView(day, 12.0, std::nan("")), day);
}

TEST(CurveView, PanStaysWithinTheDayAndItsMargins) {
    const TimeView half{6.0, 18.0};
    const TimeView later = panView(half, 3.0);
    EXPECT_DOUBLE_EQ(later.startHours, 9.0);
    EXPECT_DOUBLE_EQ(later.span(), 12.0);
    EXPECT_DOUBLE_EQ(panView(half, 100.0).endHours, 24.0 + kViewMarginHours);
    EXPECT_DOUBLE_EQ(panView(half, -100.0).startHours, -kViewMarginHours);
}

TEST(CurveView, TicksGetFinerAsTheViewZoomsIn) {
    EXPECT_DOUBLE_EQ(tickStepHours(fitView(), 1000.0, 30.0), 1.0);  // 41 px an hour
    EXPECT_DOUBLE_EQ(tickStepHours(fitView(), 300.0, 30.0), 3.0);   // 12.5 px an hour
    EXPECT_DOUBLE_EQ(tickStepHours({6.0, 7.0}, 1000.0, 30.0), 5.0 / 60.0);
    EXPECT_DOUBLE_EQ(tickStepHours({6.0, 10.0}, 1000.0, 30.0), 0.25);
}

TEST(CurveView, CurvesAreNormalisedToTheirKeysRange) {
    const Preset p = twoTracks();
    const CurveRange fog = curveRangeOf(p.tracks[0], fogDensity());
    // Keys 0 .. 0.02, padded by 10 % of the span at both ends.
    EXPECT_NEAR(fog.lo, -0.002, 1e-15);
    EXPECT_NEAR(fog.hi, 0.022, 1e-15);
    EXPECT_NEAR(fog.normalised(0.0), 1.0 / 12.0, 1e-12);
    EXPECT_NEAR(fog.normalised(0.02), 11.0 / 12.0, 1e-12);
    EXPECT_NEAR(fog.valueOf(fog.normalised(0.013)), 0.013, 1e-15);
    // A colour's range covers all three components.
    Track colour;
    colour.target = TrackTarget::global("sun.colour_rgb");
    colour.keys = {{6.0, glm::dvec3(0.2, 0.5, 1.0)}, {18.0, glm::dvec3(1.0, 0.8, 0.6)}};
    const ParamDesc* sunColour = findParam(ParamScope::Global, "sun.colour_rgb");
    ASSERT_NE(sunColour, nullptr);
    const CurveRange c = curveRangeOf(colour, *sunColour);
    EXPECT_NEAR(c.lo, 0.2 - 0.08, 1e-12);
    EXPECT_NEAR(c.hi, 1.0 + 0.08, 1e-12);
    // One value: centred, not a zero-height range.
    Track flat = p.tracks[0];
    flat.keys = {{6.0, glm::dvec3(0.01, 0, 0)}};
    const CurveRange one = curveRangeOf(flat, fogDensity());
    EXPECT_LT(one.lo, 0.01);
    EXPECT_GT(one.hi, 0.01);
    EXPECT_NEAR(one.normalised(0.01), 0.5, 1e-12);
}

TEST(CurveView, SessionKeysNameCurvesBothWays) {
    const TrackTarget targets[] = {
        TrackTarget::global("fog.density_per_m"), TrackTarget::volume("valley_fog", "density_per_m"),
        TrackTarget::emitter("lamp.2", "intensity_cd"), TrackTarget::cloudVolume("cell-1", "coverage")};
    EXPECT_EQ(curveKey(targets[0]), "fog.density_per_m");
    EXPECT_EQ(curveKey(targets[1]), "volume:valley_fog:density_per_m");
    for (const TrackTarget& t : targets) {
        const std::optional<TrackTarget> back = curveTargetOf(curveKey(t));
        ASSERT_TRUE(back) << curveKey(t);
        EXPECT_EQ(*back, t);
    }
    for (const char* bad : {"", "fog.nothing", "volume:x", "volume::density_per_m", "planet:x:density_per_m",
                            "volume:x:no_such_param"})
        EXPECT_FALSE(curveTargetOf(bad)) << bad;
}

TEST(CurveView, HitTestPicksTheNearestPointWithinReach) {
    const std::vector<glm::dvec2> points = {{10, 10}, {14, 10}, {100, 50}};
    EXPECT_EQ(hitTestPoints(points, {13, 11}, 6.0), 1);
    EXPECT_EQ(hitTestPoints(points, {10.5, 10}, 6.0), 0);
    EXPECT_EQ(hitTestPoints(points, {60, 30}, 6.0), -1);
    EXPECT_EQ(hitTestPoints({}, {0, 0}, 6.0), -1);
}

TEST(CurveView, BoxSelectionTakesAnyTwoCorners) {
    const std::vector<glm::dvec2> points = {{10, 10}, {20, 40}, {30, 20}, {50, 50}};
    EXPECT_EQ(pointsInBox(points, {5, 5}, {35, 25}), (std::vector<int>{0, 2}));
    EXPECT_EQ(pointsInBox(points, {35, 25}, {5, 5}), (std::vector<int>{0, 2}));  // dragged up-left
    EXPECT_EQ(pointsInBox(points, {15, 55}, {60, 0}), (std::vector<int>{1, 2, 3}));
    EXPECT_TRUE(pointsInBox(points, {0, 0}, {1, 1}).empty());
}

TEST(CurveView, TargetsFindTheirParameterByObjectId) {
    Preset p = defaultPreset();
    ASSERT_FALSE(p.volumes.empty());
    const ParamDesc* density = findParam(ParamScope::Volume, "density_per_m");
    ASSERT_NE(density, nullptr);
    const std::size_t last = p.volumes.size() - 1;
    const TrackTarget target = TrackTarget::volume(p.volumes[last].id, "density_per_m");
    const std::optional<ParamRef> ref = paramRefOf(p, target);
    ASSERT_TRUE(ref);
    EXPECT_EQ(ref->object, int(last));
    EXPECT_EQ(ref->desc, density);
    EXPECT_FALSE(paramRefOf(p, TrackTarget::volume("no such id", "density_per_m")));
    EXPECT_TRUE(paramRefOf(p, TrackTarget::global("fog.density_per_m")));
}

TEST(CurveView, MovingManyKeysShiftsTimesTogetherAndValuesByTheirRange) {
    Preset p = twoTracks();
    const CurvePoint fog6{p.tracks[0].target, 0, 0}, fog8{p.tracks[0].target, 1, 0},
        haze12{p.tracks[1].target, 0, 0};
    const std::vector<CurvePoint> picked = {fog6, fog8, haze12};
    const std::vector<CurveDragItem> items = dragItemsOf(p, picked);
    ASSERT_EQ(items.size(), 3u);
    EXPECT_EQ(moveLabel(picked), "Move 3 keys");
    EXPECT_EQ(moveLabel({fog6}), "Move key");
    EXPECT_EQ(moveLabel({fog6, CurvePoint{fog6.target, 0, 1}}), "Move key");  // two components, one key

    // +1 h and +1/12 of each curve's range up: fog's range is 0.024 wide, haze's 1.2e-5.
    const double dt = moveCurvePoints(p, items, 1.0, 1.0 / 12.0);
    EXPECT_DOUBLE_EQ(dt, 1.0);
    EXPECT_DOUBLE_EQ(p.tracks[0].keys[0].timeHours, 7.0);
    EXPECT_DOUBLE_EQ(p.tracks[0].keys[1].timeHours, 9.0);
    EXPECT_DOUBLE_EQ(p.tracks[0].keys[2].timeHours, 10.0);  // not selected: stays
    EXPECT_DOUBLE_EQ(p.tracks[1].keys[0].timeHours, 13.0);
    EXPECT_NEAR(p.tracks[0].keys[0].value.x, 0.012, 1e-15);
    EXPECT_NEAR(p.tracks[0].keys[1].value.x, 0.022, 1e-15);
    EXPECT_NEAR(p.tracks[1].keys[0].value.x, 1.1e-5, 1e-18);
    EXPECT_EQ(p.tracks[1].keys[0].value.y, 1e-5);  // other components untouched

    // Absolute: calling again with a smaller offset goes back towards the start, no drift.
    moveCurvePoints(p, items, 0.0, 0.0);
    EXPECT_EQ(p.tracks[0].keys[0].timeHours, 6.0);
    EXPECT_EQ(p.tracks[0].keys[1].value.x, 0.02);

    // Too far: the shift stops a minute before the first key that does not
    // move (fog's 10:00), for every key alike, so the keys keep their order.
    const double limited = moveCurvePoints(p, items, 5.0, 0.0);
    EXPECT_NEAR(limited, 2.0 - kMinKeyGap, 1e-12);
    EXPECT_NEAR(p.tracks[0].keys[1].timeHours, 10.0 - kMinKeyGap, 1e-12);
    EXPECT_NEAR(p.tracks[1].keys[0].timeHours, 12.0 + limited, 1e-12);
    // And before 00:00.
    EXPECT_NEAR(moveCurvePoints(p, items, -20.0, 0.0), -6.0, 1e-12);
    EXPECT_EQ(p.tracks[0].keys[0].timeHours, 0.0);

    // Values stay inside the parameter's valid range (a density is never negative).
    moveCurvePoints(p, items, 0.0, -10.0);
    EXPECT_EQ(p.tracks[0].keys[0].value.x, fogDensity().minValue);
}

TEST(CurveView, FlatTangentsAndSelectionFollowThePreset) {
    Preset p = twoTracks();
    const std::vector<CurvePoint> picked = {{p.tracks[0].target, 1, 0}, {p.tracks[1].target, 0, 0}};
    EXPECT_EQ(setFlatTangents(p, picked, true), 2);
    EXPECT_TRUE(p.tracks[0].keys[1].flat);
    EXPECT_TRUE(p.tracks[1].keys[0].flat);
    EXPECT_EQ(setFlatTangents(p, picked, true), 0);  // already flat
    EXPECT_EQ(setFlatTangents(p, picked, false), 2);

    CurveViewState view;
    view.setShown(p.tracks[0].target, true);
    view.setShown(p.tracks[0].target, true);
    EXPECT_EQ(view.shown.size(), 1u);
    EXPECT_TRUE(view.isShown(p.tracks[0].target));
    view.setShown(p.tracks[0].target, false);
    EXPECT_FALSE(view.isShown(p.tracks[0].target));
    view.selected = picked;
    EXPECT_TRUE(view.isSelected(picked[1]));
    p.tracks.pop_back();  // the haze track went (undo, delete)
    view.validate(p);
    EXPECT_EQ(view.selected, std::vector<CurvePoint>{picked[0]});
}

TEST(CurveView, DeletingPointsRemovesEachKeyOnce) {
    Preset p = twoTracks();
    const TrackTarget fog = p.tracks[0].target, haze = p.tracks[1].target;
    // Two components of one key count once; the haze track goes with its last keys.
    const std::vector<CurvePoint> picked = {
        {fog, 0, 0}, {fog, 2, 0}, {haze, 0, 0}, {haze, 0, 1}, {haze, 1, 2}};
    EXPECT_EQ(deleteLabel(picked), "Delete 4 keys");
    EXPECT_EQ(deleteLabel({picked[2], picked[3]}), "Delete key");
    EXPECT_EQ(removeCurvePoints(p, picked), 4);
    ASSERT_EQ(p.tracks.size(), 1u);
    ASSERT_EQ(p.tracks[0].keys.size(), 1u);
    EXPECT_EQ(p.tracks[0].keys[0].timeHours, 8.0);
}

TEST(CurveView, ADragThroughTheDocumentIsOneUndoStep) {
    Document doc;
    doc.reset(twoTracks());
    const std::vector<CurvePoint> picked = {{doc.preset().tracks[0].target, 0, 0},
                                            {doc.preset().tracks[0].target, 1, 0}};
    const std::vector<CurveDragItem> items = dragItemsOf(doc.preset(), picked);
    for (int frame = 1; frame <= 5; ++frame)
        doc.apply(moveLabel(picked), "curve-move",
                  [&](Preset& p) { moveCurvePoints(p, items, 0.2 * frame, 0.01 * frame); });
    doc.closeMerge();
    EXPECT_EQ(doc.undoCount(), 1u);
    EXPECT_EQ(doc.undoLabel(), "Move 2 keys");
    EXPECT_DOUBLE_EQ(doc.preset().tracks[0].keys[0].timeHours, 7.0);
    ASSERT_TRUE(doc.undo());
    EXPECT_EQ(doc.preset().tracks[0].keys[0].timeHours, 6.0);
    EXPECT_EQ(doc.preset().tracks[0].keys[1].value.x, 0.02);
}

TEST(CurveView, TypedShiftsAndOffsetsReadAsWritten) {
    double h = 99.0;
    EXPECT_TRUE(parseShiftHours("+0:20", h));
    EXPECT_DOUBLE_EQ(h, 20.0 / 60.0);
    EXPECT_TRUE(parseShiftHours("-1:00", h));
    EXPECT_DOUBLE_EQ(h, -1.0);
    EXPECT_TRUE(parseShiftHours("0:05", h));
    EXPECT_DOUBLE_EQ(h, 5.0 / 60.0);
    EXPECT_TRUE(parseShiftHours("-0.25", h));
    EXPECT_DOUBLE_EQ(h, -0.25);
    EXPECT_TRUE(parseShiftHours(" + 1.5h", h));
    EXPECT_DOUBLE_EQ(h, 1.5);
    h = 99.0;
    for (const char* bad : {"", "+", "--0:20", "+-1", "0:60", "abc", "-24", "1:2"})
        EXPECT_FALSE(parseShiftHours(bad, h)) << bad;
    EXPECT_EQ(h, 99.0);  // untouched on failure

    EXPECT_EQ(formatOffset(20.0 / 60.0), "+ 0:20");
    EXPECT_EQ(formatOffset(-(1.0 + 5.0 / 60.0)), "- 1:05");
    EXPECT_EQ(formatOffset(0.0), "+ 0:00");
    EXPECT_EQ(formatOffset(-1e-9), "+ 0:00");  // no "- 0:00"
    EXPECT_EQ(formatOffset(20.5 / 60.0), "+ 0:20:30");
    EXPECT_EQ(formatOffset(0.333), "+ 0:19:59");  // 1198.8 s, to the second

    EXPECT_EQ(sunEventLabel(SunEvent::CivilDusk), "civil dusk");
    TrackKey key{19.0 + 52.0 / 60.0, glm::dvec3(0.0)};
    EXPECT_EQ(keyTimeText(key), "19:52");
    key.anchor = SunEvent::Sunset;
    key.offsetHours = 20.0 / 60.0;
    EXPECT_EQ(keyTimeText(key), "sunset + 0:20 (19:52)");
    key.anchor = SunEvent::NauticalDawn;
    key.offsetHours = -(1.0 + 5.0 / 60.0);
    EXPECT_EQ(keyTimeText(key), "nautical dawn - 1:05 (19:52)");
}

// The key menu's Interpolation after: each selected key once (a colour's
// components are one key), back to the track's with nullopt.
TEST(CurveView, AKeysInterpolationIsSetOncePerKey) {
    Preset preset = twoTracks();
    const TrackTarget fog = preset.tracks[0].target, haze = preset.tracks[1].target;
    const std::vector<CurvePoint> picked = {{fog, 1, 0}, {haze, 1, 0}, {haze, 1, 2}};
    EXPECT_EQ(setKeyInterpolation(preset, picked, Interpolation::Step), 2);
    EXPECT_EQ(preset.tracks[0].keys[1].interpolation, Interpolation::Step);
    EXPECT_EQ(preset.tracks[1].keys[1].interpolation, Interpolation::Step);
    EXPECT_FALSE(preset.tracks[0].keys[0].interpolation.has_value());
    // The curve holds after the key.
    const CompiledTrack c = compileTrack(preset.tracks[0], 1);
    const double t0 = preset.tracks[0].keys[1].timeHours, t1 = preset.tracks[0].keys[2].timeHours;
    EXPECT_EQ(evaluateTrack(c, 0.5 * (t0 + t1)).x, preset.tracks[0].keys[1].value.x);
    EXPECT_EQ(setKeyInterpolation(preset, picked, Interpolation::Step), 0);
    EXPECT_EQ(setKeyInterpolation(preset, picked, std::nullopt), 2);
    EXPECT_FALSE(preset.tracks[1].keys[1].interpolation.has_value());
}

TEST(CurveView, AnchoringASelectionKeepsEveryKeysTimeAndValue) {
    Preset start = twoTracks();
    start.environment.location.latitudeDeg = 38.0;
    start.environment.location.dayOfYear = 225.0;
    Document doc;
    doc.reset(start);
    const TrackTarget fog = start.tracks[0].target, haze = start.tracks[1].target;
    // Both fog keys and the haze key at 18:00; its second component too (one key, counted once).
    const std::vector<CurvePoint> picked = {{fog, 1, 0}, {fog, 2, 0}, {haze, 1, 0}, {haze, 1, 2}};
    EXPECT_EQ(anchorLabel(picked, SunEvent::Sunset), "Anchor 3 keys to sunset");
    EXPECT_EQ(anchorLabel({picked[0]}, SunEvent::CivilDusk), "Anchor key to civil dusk");
    EXPECT_EQ(anchorLabel(picked, std::nullopt), "Fix 3 key times");
    EXPECT_FALSE(allAnchoredTo(doc.preset(), picked, SunEvent::Sunset));
    EXPECT_TRUE(allAnchoredTo(doc.preset(), picked, std::nullopt));

    int changed = 0;
    ASSERT_TRUE(doc.apply(anchorLabel(picked, SunEvent::Sunset), "",
                          [&](Preset& p) { changed = anchorCurvePoints(p, picked, SunEvent::Sunset); }));
    EXPECT_EQ(changed, 3);
    EXPECT_EQ(doc.undoCount(), 1u);
    EXPECT_EQ(doc.undoLabel(), "Anchor 3 keys to sunset");
    EXPECT_TRUE(allAnchoredTo(doc.preset(), picked, SunEvent::Sunset));
    // Every key where it was with the value it had (the document re-timed the anchored keys
    // from the location afterwards: resolveKeyAnchors); the offsets from today's sunset.
    const double sunset = sunEventHours(doc.preset().environment.location, SunEvent::Sunset);
    ASSERT_GT(sunset, 18.0);
    ASSERT_LT(sunset, 20.0);
    for (std::size_t t = 0; t < 2; ++t) {
        const Track& before = start.tracks[t];
        const Track& after = doc.preset().tracks[t];
        ASSERT_EQ(after.keys.size(), before.keys.size());
        for (std::size_t k = 0; k < before.keys.size(); ++k) {
            EXPECT_NEAR(after.keys[k].timeHours, before.keys[k].timeHours, 1e-9) << t << " " << k;
            EXPECT_EQ(after.keys[k].value, before.keys[k].value) << t << " " << k;
        }
        // The curve between and around the keys too.
        const int n = t == 0 ? 1 : 3;
        for (double hour = 0.0; hour < 24.0; hour += 0.37)
            for (int c = 0; c < n; ++c)
                EXPECT_NEAR(evaluateTrack(after, hour, n)[c], evaluateTrack(before, hour, n)[c],
                            1e-9 * std::abs(evaluateTrack(before, hour, n)[c]) + 1e-15);
    }
    const TrackKey& fog8 = doc.preset().tracks[0].keys[1];
    ASSERT_TRUE(fog8.anchor.has_value());
    EXPECT_EQ(*fog8.anchor, SunEvent::Sunset);
    EXPECT_NEAR(fog8.offsetHours, 8.0 - sunset, 1e-9);                // 08:00 is ~11 h before sunset
    EXPECT_FALSE(doc.preset().tracks[0].keys[0].anchor.has_value());  // not selected
    EXPECT_NEAR(doc.preset().tracks[1].keys[1].offsetHours, 18.0 - sunset, 1e-9);

    // Anchoring again to the same event changes nothing (no undo step); Fixed time
    // keeps the times too; undo brings back the fixed keys as they were.
    EXPECT_FALSE(doc.apply("again", "", [&](Preset& p) { anchorCurvePoints(p, picked, SunEvent::Sunset); }));
    ASSERT_TRUE(doc.apply(anchorLabel(picked, std::nullopt), "",
                          [&](Preset& p) { changed = anchorCurvePoints(p, picked, std::nullopt); }));
    EXPECT_EQ(changed, 3);
    EXPECT_TRUE(allAnchoredTo(doc.preset(), picked, std::nullopt));
    EXPECT_NEAR(doc.preset().tracks[0].keys[1].timeHours, 8.0, 1e-9);
    ASSERT_TRUE(doc.undo());
    ASSERT_TRUE(doc.undo());
    EXPECT_TRUE(presetsIdentical(doc.preset(), start));
}

TEST(CurveView, ATypedShiftIsLimitedAsADragAndKeepsTheAnchor) {
    Preset start = twoTracks();
    start.environment.location.latitudeDeg = 38.0;
    start.environment.location.dayOfYear = 225.0;
    const TrackTarget fog = start.tracks[0].target, haze = start.tracks[1].target;
    // The fog key at 08:00 follows sunrise (where it stands).
    anchorKey(start.tracks[0].keys[1], SunEvent::Sunrise, start.environment.location);
    const double offset = start.tracks[0].keys[1].offsetHours;
    const std::vector<CurvePoint> picked = {{fog, 0, 0}, {fog, 1, 0}, {haze, 0, 0}};
    EXPECT_EQ(shiftLabel(picked), "Shift 3 keys");
    EXPECT_EQ(shiftLabel({picked[1]}), "Shift key");

    // The same shift as a drag of the same keys by the same time: +5 h stops a minute
    // before fog's 10:00 (not selected), for every key alike.
    for (double dt : {0.25, 5.0, -20.0}) {
        Preset typed = start, dragged = start;
        const double applied = shiftCurvePoints(typed, picked, dt);
        const double draggedBy = moveCurvePoints(dragged, dragItemsOf(dragged, picked), dt, 0.0);
        EXPECT_EQ(applied, draggedBy) << dt;
        EXPECT_TRUE(presetsIdentical(typed, dragged)) << dt;
    }
    Preset p = start;
    const double limited = shiftCurvePoints(p, picked, 5.0);
    EXPECT_NEAR(limited, 2.0 - kMinKeyGap, 1e-12);
    EXPECT_NEAR(p.tracks[0].keys[1].timeHours, 10.0 - kMinKeyGap, 1e-12);
    EXPECT_NEAR(p.tracks[1].keys[0].timeHours, 12.0 + limited, 1e-12);
    EXPECT_EQ(p.tracks[0].keys[1].value, start.tracks[0].keys[1].value);  // values stay
    // The anchored key still follows sunrise, later by the shift.
    ASSERT_TRUE(p.tracks[0].keys[1].anchor.has_value());
    EXPECT_EQ(*p.tracks[0].keys[1].anchor, SunEvent::Sunrise);
    EXPECT_NEAR(p.tracks[0].keys[1].offsetHours, offset + limited, 1e-12);
    // Before 00:00: the 06:00 key stops at midnight.
    EXPECT_NEAR(shiftCurvePoints(p, picked, -20.0), -(6.0 + limited), 1e-12);

    // Through the document: one undo step, the key re-timed from its anchor where the shift put it.
    Document doc;
    doc.reset(start);
    ASSERT_TRUE(doc.apply(shiftLabel({picked[1]}), "",
                          [&](Preset& q) { shiftCurvePoints(q, {picked[1]}, 20.0 / 60.0); }));
    EXPECT_EQ(doc.undoCount(), 1u);
    EXPECT_EQ(doc.undoLabel(), "Shift key");
    const TrackKey& k = doc.preset().tracks[0].keys[1];
    EXPECT_NEAR(k.timeHours, 8.0 + 20.0 / 60.0, 1e-9);
    EXPECT_NEAR(k.offsetHours, offset + 20.0 / 60.0, 1e-12);
    EXPECT_NEAR(anchoredKeyHours(k, doc.preset().environment.location), 8.0 + 20.0 / 60.0, 1e-9);
    ASSERT_TRUE(doc.undo());
    EXPECT_TRUE(presetsIdentical(doc.preset(), start));
}

TEST(CurveView, TheInspectorsParameterWinsWhereKeysOverlap) {
    // Issue 50's repro: Valley fog's density key lies on the fog density key (the inspector's).
    const TrackTarget fog = TrackTarget::global("fog.density_per_m"),
                      valley = TrackTarget::volume("valley_fog", "density_per_m");
    const std::vector<CurvePoint> ids = {{fog, 0, 0}, {valley, 0, 0}, {valley, 1, 0}};
    const std::vector<glm::dvec2> points = {{100, 50}, {100, 50}, {200, 80}};
    EXPECT_EQ(pickCurvePoint(points, ids, {100, 50}, 6.0, fog), 0);
    // Even where the overlaid key is nearer the mouse, within the pick radius.
    const std::vector<glm::dvec2> near = {{104, 50}, {101, 50}, {200, 80}};
    EXPECT_EQ(pickCurvePoint(near, ids, {100, 50}, 6.0, fog), 0);
    EXPECT_EQ(hitTestPoints(near, {100, 50}, 6.0), 1);  // plain nearest: the overlaid one
    // Another curve's key where the inspector's has none in reach; nothing in reach.
    EXPECT_EQ(pickCurvePoint(near, ids, {198, 81}, 6.0, fog), 2);
    EXPECT_EQ(pickCurvePoint(near, ids, {150, 20}, 6.0, fog), -1);
    // The inspector showing Valley fog: its key wins instead; no inspector parameter: the nearest.
    EXPECT_EQ(pickCurvePoint(near, ids, {103, 50}, 6.0, valley), 1);
    EXPECT_EQ(pickCurvePoint(near, ids, {103.5, 50}, 6.0, std::nullopt), 0);
    EXPECT_EQ(pickCurvePoint(near, ids, {100, 50}, 6.0, std::nullopt), 1);
    // Among the inspector's own keys, the nearest.
    const std::vector<CurvePoint> own = {{fog, 0, 0}, {fog, 1, 0}, {valley, 0, 0}};
    EXPECT_EQ(pickCurvePoint({{100, 50}, {105, 50}, {104, 50}}, own, {104, 50}, 6.0, fog), 1);
}

TEST(CurveView, TheLegendNamesObjectsByTheirNames) {
    Preset p = defaultPreset();
    p.volumes.resize(2);
    p.volumes[0].id = "vol0";
    p.volumes[0].name = "Valley fog";
    p.volumes[1].id = "vol1";
    p.volumes[1].name = "";
    p.emitters.resize(1);
    p.emitters[0].id = "lamp";
    p.emitters[0].name = "Barn lamp";
    p.cloudVolumes.resize(1);
    p.cloudVolumes[0].id = "cell";
    p.cloudVolumes[0].name = "Storm cell";
    EXPECT_EQ(curveLabel(p, TrackTarget::global("fog.density_per_m")), "Fog density");
    EXPECT_EQ(curveLabel(p, TrackTarget::volume("vol0", "density_per_m")), "Valley fog density");
    EXPECT_EQ(curveLabel(p, TrackTarget::volume("vol1", "density_per_m")),
              "vol1 density");  // no name: the id
    EXPECT_EQ(curveLabel(p, TrackTarget::emitter("lamp", "intensity_cd")), "Barn lamp intensity");
    EXPECT_EQ(curveLabel(p, TrackTarget::cloudVolume("cell", "coverage")), "Storm cell coverage");
    // No such object: the curve key, as the session names it.
    EXPECT_EQ(curveLabel(p, TrackTarget::volume("gone", "density_per_m")), "volume:gone:density_per_m");
}

TEST(CurveView, ACurvesColourFollowsItsTargetNotItsPlace) {
    const TrackTarget fog = TrackTarget::global("fog.density_per_m");
    const int colour = curvePaletteIndex(fog, kCurvePaletteSize);
    EXPECT_GE(colour, 0);
    EXPECT_LT(colour, kCurvePaletteSize);
    // The same target, however it was made, and whatever else the view shows: the same colour.
    CurveViewState view;
    for (const char* other : {"fog.falloff_per_m", "sun.colour_rgb", "clouds.coverage"}) {
        view.setShown(TrackTarget::global(other), true);
        EXPECT_EQ(curvePaletteIndex(*curveTargetOf("fog.density_per_m"), kCurvePaletteSize), colour);
    }
    view.setShown(TrackTarget::global("fog.falloff_per_m"), false);
    EXPECT_EQ(curvePaletteIndex(fog, kCurvePaletteSize), colour);
    // A hash of scope, object id and parameter: the same parameter of two objects may differ,
    // and the global parameters spread over the palette.
    EXPECT_NE(curvePaletteIndex(TrackTarget::volume("haze_bank", "density_per_m"), kCurvePaletteSize),
              curvePaletteIndex(TrackTarget::volume("valley_fog", "density_per_m"), kCurvePaletteSize));
    std::set<int> used;
    for (const ParamDesc& d : paramTable(ParamScope::Global))
        if (d.animatable) {
            const int i = curvePaletteIndex(TrackTarget::global(std::string(d.path)), kCurvePaletteSize);
            EXPECT_GE(i, 0);
            EXPECT_LT(i, kCurvePaletteSize);
            used.insert(i);
        }
    EXPECT_GE(int(used.size()), kCurvePaletteSize / 2);
    EXPECT_EQ(curvePaletteIndex(fog, 1), 0);
}

TEST(CurveView, TheValueAxisHasRoundTicksInTheUnit) {
    EXPECT_EQ(valueTicks({-0.002, 0.022}, 5), (std::vector<double>{0.0, 0.005, 0.01, 0.015, 0.02}));
    const std::vector<double> fine = valueTicks({-0.002, 0.022}, 8);  // steps of 0.005 give 5
    ASSERT_EQ(fine.size(), 5u);
    const std::vector<double> negative = valueTicks({-3.5, 1.2}, 6);  // steps of 1
    EXPECT_EQ(negative, (std::vector<double>{-3.0, -2.0, -1.0, 0.0, 1.0}));
    EXPECT_FALSE(std::signbit(negative[3]));  // 0, not -0
    for (const CurveRange& r : {CurveRange{0.00046, 0.00194}, CurveRange{-1.5, 0.2}, CurveRange{1e3, 1e7}})
        for (int most : {2, 3, 5, 8}) {
            const std::vector<double> t = valueTicks(r, most);
            EXPECT_GE(t.size(), 1u) << r.lo << " " << most;
            EXPECT_LE(int(t.size()), most) << r.lo << " " << most;
            for (double v : t) {
                EXPECT_GE(v, r.lo);
                EXPECT_LE(v, r.hi);
            }
        }
    EXPECT_TRUE(valueTicks({1.0, 1.0}, 5).empty());
    EXPECT_TRUE(valueTicks({0.0, 1.0}, 0).empty());
    EXPECT_TRUE(valueTicks({0.0, std::nan("")}, 5).empty());

    EXPECT_EQ(valueWithUnit(0.0031, "1/m"), "0.0031 1/m");
    EXPECT_EQ(valueWithUnit(12.0, "deg"), "12 deg");
    EXPECT_EQ(valueWithUnit(0.5, ""), "0.5");
    EXPECT_EQ(valueWithUnit(-0.0, "m"), "0 m");
    EXPECT_EQ(valueWithUnit(0.00123456, "1/m", 6), "0.00123456 1/m");
}

TEST(CurveView, APinnedRangeKeepsTheDragSensitivityUntilTheViewIsFit) {
    Preset p = twoTracks();
    const TrackTarget fog = p.tracks[0].target;
    CurveViewState view;
    const CurveRange before = curveRangeOf(p.tracks[0], fogDensity());
    EXPECT_EQ(view.rangeOf(p, fog), before);  // not pinned: the keys' range
    view.pinRange(p, fog);
    // A drag lowers the 08:00 key (the top): the keys' range shrinks, the view's stays.
    p.tracks[0].keys[1].value.x = 0.015;
    EXPECT_NE(curveRangeOf(p.tracks[0], fogDensity()), before);
    EXPECT_EQ(view.rangeOf(p, fog), before);
    const std::vector<CurveDragItem> items = dragItemsOf(p, {{fog, 1, 0}}, view);
    ASSERT_EQ(items.size(), 1u);
    EXPECT_EQ(items[0].range, before);  // the next drag moves as much per pixel as the last
    // The same drag twice moves the key by the same value each time.
    moveCurvePoints(p, dragItemsOf(p, {{fog, 1, 0}}, view), 0.0, 0.1);
    const double first = p.tracks[0].keys[1].value.x - 0.015;
    const double was = p.tracks[0].keys[1].value.x;
    moveCurvePoints(p, dragItemsOf(p, {{fog, 1, 0}}, view), 0.0, 0.1);
    EXPECT_NEAR(p.tracks[0].keys[1].value.x - was, first, 1e-15);
    EXPECT_NEAR(first, 0.1 * (before.hi - before.lo), 1e-15);
    // A key outside the pinned range widens it to take the keys in.
    p.tracks[0].keys[1].value.x = 0.05;
    const CurveRange wide = view.rangeOf(p, fog);
    EXPECT_EQ(wide.lo, before.lo);
    EXPECT_GT(wide.hi, 0.05);
    EXPECT_EQ(wide.hi, curveRangeOf(p.tracks[0], fogDensity()).hi);
    // Script boxes read the same ranges as the view draws.
    const CurveKeyPoints points = keyPointsOf(p, {fog}, view);
    ASSERT_EQ(points.timeValue.size(), 3u);
    EXPECT_DOUBLE_EQ(points.timeValue[0].y, wide.normalised(0.01));
    // Fit (F): the ranges follow the keys again; another curve is not pinned by this one.
    EXPECT_EQ(view.rangeOf(p, p.tracks[1].target),
              curveRangeOf(p.tracks[1], *findParam(ParamScope::Global, "atmosphere.mie.scattering_per_m")));
    view.resetRanges();
    EXPECT_EQ(view.rangeOf(p, fog), curveRangeOf(p.tracks[0], fogDensity()));
    view.pinRange(p, TrackTarget::global("fog.falloff_per_m"));  // no track: nothing to pin
    EXPECT_TRUE(view.pinnedRanges.empty());
}

TEST(CurveView, TypedTimesAndValuesReadAsWritten) {
    EXPECT_EQ(keyClockText(19.0 + 52.0 / 60.0), "19:52:00");
    EXPECT_EQ(keyClockText(19.5 + 20.0 / 3600.0), "19:30:20");
    EXPECT_EQ(keyClockText(6.0), "06:00:00");
    double v = 99.0;
    EXPECT_TRUE(parseKeyValue("0.0031", "1/m", v));
    EXPECT_EQ(v, 0.0031);
    EXPECT_TRUE(parseKeyValue(" 0.0031 1/m ", "1/m", v));  // as the Value field shows it
    EXPECT_EQ(v, 0.0031);
    EXPECT_TRUE(parseKeyValue("3e-4", "1/m", v));
    EXPECT_EQ(v, 3e-4);
    EXPECT_TRUE(parseKeyValue("-2", "", v));
    EXPECT_EQ(v, -2.0);
    v = 99.0;
    for (const char* bad : {"", " ", "abc", "nan", "inf", "0x10", "1/m", "0.1 m", "1,5", "1e", "--1", "1 2"})
        EXPECT_FALSE(parseKeyValue(bad, "1/m", v)) << bad;
    EXPECT_EQ(v, 99.0);  // untouched on failure

    TrackKey key{19.0 + 52.0 / 60.0, glm::dvec3(0.0031, 0, 0)};
    EXPECT_EQ(keyReadout(key, 0, fogDensity()), "19:52:00  0.0031 1/m");
    key.anchor = SunEvent::Sunset;
    key.offsetHours = 22.0 / 60.0;
    EXPECT_EQ(keyReadout(key, 0, fogDensity()), "sunset + 0:22 (19:52:00)  0.0031 1/m");
    const ParamDesc& colour = *findParam(ParamScope::Global, "fog.colour_rgb");
    EXPECT_EQ(keyReadout({12.25, glm::dvec3(1.0, 0.8, 0.6)}, 2, colour), "12:15:00  0.6");
}

TEST(CurveView, ATypedTimeSetsTheKeyExactlyAndMovesTheOthersWithIt) {
    Preset start = twoTracks();
    start.environment.location.latitudeDeg = 38.0;
    start.environment.location.dayOfYear = 225.0;
    const TrackTarget fog = start.tracks[0].target, haze = start.tracks[1].target;
    Document doc;
    doc.reset(start);
    // One key: 08:00 typed as 08:52:10, exactly; one undo step; nothing else changes.
    double typed = 0.0;
    ASSERT_TRUE(parseClock("08:52:10", typed));
    const std::vector<CurvePoint> one = {{fog, 1, 0}};
    EXPECT_EQ(setTimeLabel(one), "Set key time");
    double now = 0.0;
    ASSERT_TRUE(
        doc.apply(setTimeLabel(one), "", [&](Preset& p) { now = setCurvePointsTime(p, one, typed); }));
    EXPECT_EQ(now, typed);
    EXPECT_EQ(doc.undoCount(), 1u);
    EXPECT_EQ(doc.undoLabel(), "Set key time");
    const Track& fogAfter = doc.preset().tracks[0];
    ASSERT_EQ(fogAfter.keys.size(), 3u);
    EXPECT_EQ(fogAfter.keys[1].timeHours, typed);
    EXPECT_EQ(keyClockText(fogAfter.keys[1].timeHours), "08:52:10");
    EXPECT_EQ(fogAfter.keys[1].value, start.tracks[0].keys[1].value);
    EXPECT_EQ(fogAfter.keys[0].timeHours, 6.0);
    EXPECT_EQ(fogAfter.keys[2].timeHours, 10.0);
    EXPECT_TRUE(sameKeys(doc.preset().tracks[1], start.tracks[1]));
    ASSERT_TRUE(doc.undo());
    EXPECT_TRUE(presetsIdentical(doc.preset(), start));

    // Several keys: the first selected goes to the time typed, the others by the same shift;
    // past a key that does not move, they stop a minute before it (as a drag, as a shift).
    Preset p = start;
    const std::vector<CurvePoint> two = {{fog, 0, 0}, {haze, 0, 0}};
    EXPECT_EQ(setTimeLabel(two), "Set 2 key times");
    EXPECT_EQ(setCurvePointsTime(p, two, 7.0), 7.0);
    EXPECT_EQ(p.tracks[0].keys[0].timeHours, 7.0);
    EXPECT_DOUBLE_EQ(p.tracks[1].keys[0].timeHours, 13.0);
    EXPECT_NEAR(setCurvePointsTime(p, two, 9.0), 8.0 - kMinKeyGap, 1e-12);  // fog's 08:00 stays
    EXPECT_NEAR(p.tracks[1].keys[0].timeHours, 14.0 - kMinKeyGap, 1e-12);
    EXPECT_TRUE(std::isnan(setCurvePointsTime(p, {}, 7.0)));
    EXPECT_TRUE(std::isnan(setCurvePointsTime(p, {{fog, 7, 0}}, 7.0)));

    // An anchored key keeps its anchor: its offset changes, and it resolves to the time typed.
    Preset anchored = start;
    anchorKey(anchored.tracks[0].keys[1], SunEvent::Sunrise, anchored.environment.location);
    const double offset = anchored.tracks[0].keys[1].offsetHours;
    doc.reset(anchored);
    ASSERT_TRUE(parseClock("08:30", typed));
    ASSERT_TRUE(doc.apply(setTimeLabel(one), "", [&](Preset& q) { setCurvePointsTime(q, one, typed); }));
    const TrackKey& k = doc.preset().tracks[0].keys[1];
    ASSERT_TRUE(k.anchor.has_value());
    EXPECT_EQ(*k.anchor, SunEvent::Sunrise);
    EXPECT_NEAR(k.offsetHours, offset + 0.5, 1e-12);
    EXPECT_NEAR(k.timeHours, 8.5, 1e-9);
    EXPECT_NEAR(anchoredKeyHours(k, doc.preset().environment.location), 8.5, 1e-9);
    EXPECT_EQ(keyClockText(k.timeHours), "08:30:00");
}

TEST(CurveView, ATypedValueSetsEveryKeyOfTheSameParameter) {
    Preset start = twoTracks();
    const TrackTarget fog = start.tracks[0].target, haze = start.tracks[1].target;
    // Fog's 08:00 and 10:00 keys and a haze key: the value is fog's (the first selected), in 1/m.
    const std::vector<CurvePoint> picked = {{fog, 1, 0}, {fog, 2, 0}, {haze, 0, 0}};
    ASSERT_TRUE(leadPointOf(start, picked));
    EXPECT_EQ(*leadPointOf(start, picked), picked[0]);
    EXPECT_FALSE(leadPointOf(start, {{fog, 9, 0}}));
    EXPECT_EQ(setValueLabel(start, picked), "Set 2 key values");
    Document doc;
    doc.reset(start);
    int changed = 0;
    ASSERT_TRUE(doc.apply(setValueLabel(doc.preset(), picked), "",
                          [&](Preset& p) { changed = setCurvePointsValue(p, picked, 0.0031); }));
    EXPECT_EQ(changed, 2);
    EXPECT_EQ(doc.undoCount(), 1u);
    EXPECT_EQ(doc.undoLabel(), "Set 2 key values");
    EXPECT_EQ(doc.preset().tracks[0].keys[1].value.x, 0.0031);
    EXPECT_EQ(doc.preset().tracks[0].keys[2].value.x, 0.0031);
    EXPECT_EQ(doc.preset().tracks[0].keys[0].value.x, 0.01);         // not selected
    EXPECT_TRUE(sameKeys(doc.preset().tracks[1], start.tracks[1]));  // another parameter
    for (std::size_t k = 0; k < 3; ++k)
        EXPECT_EQ(doc.preset().tracks[0].keys[k].timeHours, start.tracks[0].keys[k].timeHours);
    // The same value again changes nothing; a value below the valid range is clamped.
    Preset p = doc.preset();
    EXPECT_EQ(setCurvePointsValue(p, picked, 0.0031), 0);
    EXPECT_EQ(setCurvePointsValue(p, {picked[0]}, -1.0), 1);
    EXPECT_EQ(p.tracks[0].keys[1].value.x, fogDensity().minValue);
    EXPECT_EQ(setCurvePointsValue(p, picked, std::nan("")), 0);
    // A colour's component: only that one.
    const std::vector<CurvePoint> blue = {{haze, 1, 2}};
    EXPECT_EQ(setValueLabel(p, blue), "Set key value");
    EXPECT_EQ(setCurvePointsValue(p, blue, 3e-5), 1);
    EXPECT_EQ(p.tracks[1].keys[1].value, glm::dvec3(2e-5, 2e-5, 3e-5));
}

}  // namespace
}  // namespace aerial::editor

namespace aerial::editor {
namespace {

// A handle drawn for a slope reads back as that slope, on its own side of
// the key; one dragged past the key stays a pixel on its side.
TEST(CurveTangents, AHandlesPlaceAndSlopeAreInverse) {
    const CurveRange range{0.0, 0.04};
    const double pxPerHour = 50.0, heightPx = 200.0;
    for (double slope : {0.0, 0.01, -0.003, 0.2}) {
        for (TangentSide side : {TangentSide::In, TangentSide::Out}) {
            const glm::dvec2 offset = tangentHandleOffset(slope, range, pxPerHour, heightPx, side);
            EXPECT_NEAR(std::hypot(offset.x, offset.y), kTangentHandlePx, 1e-9);
            EXPECT_EQ(offset.x > 0.0, side == TangentSide::Out);
            EXPECT_NEAR(slopeOfHandle(offset, range, pxPerHour, heightPx, side), slope,
                        1e-12 + 1e-12 * std::abs(slope));
        }
    }
    // 10 px right and 20 px up of the key: 0.2 h and 0.004 (a tenth of the range): 0.02 per h.
    EXPECT_DOUBLE_EQ(slopeOfHandle({10.0, -20.0}, range, pxPerHour, heightPx, TangentSide::Out), 0.02);
    // The in handle 10 px left and 20 px up: the curve comes down into the key.
    EXPECT_DOUBLE_EQ(slopeOfHandle({-10.0, -20.0}, range, pxPerHour, heightPx, TangentSide::In), -0.02);
    // Past the key: a pixel on its side (50 px per h: 0.02 h).
    EXPECT_DOUBLE_EQ(slopeOfHandle({-5.0, -20.0}, range, pxPerHour, heightPx, TangentSide::Out),
                     0.004 / 0.02);
}

// Dragging one handle gives the key its own tangents, taken from the
// automatic ones: unified, the other side follows; broken, it stays. The
// key menu's Automatic tangent takes them away again. One undo step per
// drag.
TEST(CurveTangents, HandlesAreUnifiedOrBrokenAndOneUndoStepPerDrag) {
    Document doc;
    doc.reset(twoTracks());
    const TrackTarget fog = doc.preset().tracks[0].target;
    const CurvePoint point{fog, 1, 0};  // 08:00, a maximum: automatic tangent 0
    const double automatic = automaticTangent(doc.preset().tracks[0], 1, 1).x;
    EXPECT_EQ(automatic, 0.0);
    EXPECT_FALSE(tangentModeOf(doc.preset(), point).has_value());
    for (int frame = 1; frame <= 4; ++frame)
        doc.apply("Tangent", "curve-tangent",
                  [&](Preset& p) { setKeyTangent(p, point, TangentSide::Out, 0.001 * frame); });
    doc.closeMerge();
    EXPECT_EQ(doc.undoCount(), 1u);
    const TrackKey* key = &doc.preset().tracks[0].keys[1];
    ASSERT_TRUE(key->tangents.has_value());
    EXPECT_EQ(key->tangents->mode, TangentMode::Unified);
    EXPECT_EQ(key->tangents->out.x, 0.004);
    EXPECT_EQ(key->tangents->in.x, 0.004);  // unified: the in handle follows
    // The game evaluates the curve with it: past 08:00 it still rises.
    EXPECT_GT(evaluateTrack(doc.preset().tracks[0], 8.05, 1).x, 0.02);
    // Broken: the in side moves alone.
    doc.apply(tangentModeLabel({point}, TangentMode::Broken), "",
              [&](Preset& p) { setTangentMode(p, {point}, TangentMode::Broken); });
    EXPECT_EQ(doc.undoLabel(), "Break tangent");
    doc.apply("Tangent", "", [&](Preset& p) { setKeyTangent(p, point, TangentSide::In, -0.002); });
    key = &doc.preset().tracks[0].keys[1];
    EXPECT_EQ(key->tangents->in.x, -0.002);
    EXPECT_EQ(key->tangents->out.x, 0.004);
    // Unified again: the mean of the two.
    doc.apply("", "", [&](Preset& p) { setTangentMode(p, {point}, TangentMode::Unified); });
    key = &doc.preset().tracks[0].keys[1];
    EXPECT_EQ(key->tangents->in.x, 0.001);
    EXPECT_EQ(key->tangents->out.x, 0.001);
    // Automatic again; a flat key loses its flatness to its own tangents.
    doc.apply("", "", [&](Preset& p) { EXPECT_EQ(setFlatTangents(p, {point}, false), 1); });
    EXPECT_FALSE(doc.preset().tracks[0].keys[1].tangents.has_value());
    doc.apply("", "", [&](Preset& p) { setFlatTangents(p, {point}, true); });
    doc.apply("", "", [&](Preset& p) { setKeyTangent(p, point, TangentSide::Out, 0.003); });
    EXPECT_FALSE(doc.preset().tracks[0].keys[1].flat);
    EXPECT_TRUE(validatePreset(doc.preset()).empty());
    // The undo steps walk back to the automatic key.
    while (doc.undo()) {
    }
    EXPECT_FALSE(doc.preset().tracks[0].keys[1].tangents.has_value());
}

}  // namespace
}  // namespace aerial::editor

namespace aerial::editor {
namespace {

// Two curves shown together never share a colour: the later one probes to
// the next free entry; one that clashes with none keeps its own; showing a
// curve recolours none shown before it.
TEST(CurveColours, CurvesShownTogetherNeverShareAColour) {
    // Two global parameters whose own entries clash (12 entries: there are some).
    std::vector<TrackTarget> globals;
    for (const ParamDesc& d : paramTable(ParamScope::Global))
        if (d.animatable) globals.push_back(TrackTarget::global(std::string(d.path)));
    std::optional<std::pair<TrackTarget, TrackTarget>> clash;
    for (std::size_t i = 0; i < globals.size() && !clash; ++i)
        for (std::size_t j = i + 1; j < globals.size() && !clash; ++j)
            if (curvePaletteIndex(globals[i], kCurvePaletteSize) ==
                curvePaletteIndex(globals[j], kCurvePaletteSize))
                clash = std::make_pair(globals[i], globals[j]);
    ASSERT_TRUE(clash.has_value());
    const auto& [a, b] = *clash;
    const int own = curvePaletteIndex(a, kCurvePaletteSize);
    EXPECT_EQ(curvePaletteIndices({a, b}, kCurvePaletteSize),
              (std::vector<int>{own, (own + 1) % kCurvePaletteSize}));
    EXPECT_EQ(curvePaletteIndices({b, a}, kCurvePaletteSize),
              (std::vector<int>{own, (own + 1) % kCurvePaletteSize}));
    // Alone, each has its own colour again.
    EXPECT_EQ(curvePaletteIndices({b}, kCurvePaletteSize), std::vector<int>{own});
    // Every animatable global shown at once: the first 12 all differ, and
    // each prefix keeps the colours it had (showing more recolours none).
    const std::vector<int> all = curvePaletteIndices(globals, kCurvePaletteSize);
    ASSERT_EQ(all.size(), globals.size());
    ASSERT_GT(globals.size(), std::size_t(kCurvePaletteSize));
    const std::set<int> first(all.begin(), all.begin() + kCurvePaletteSize);
    EXPECT_EQ(int(first.size()), kCurvePaletteSize);
    for (std::size_t n = 1; n < globals.size(); ++n) {
        const std::vector<TrackTarget> prefix(globals.begin(), globals.begin() + long(n));
        const std::vector<int> colours = curvePaletteIndices(prefix, kCurvePaletteSize);
        EXPECT_TRUE(std::equal(colours.begin(), colours.end(), all.begin())) << n;
    }
    // Past a full palette, a curve takes its own entry.
    for (std::size_t i = kCurvePaletteSize; i < globals.size(); ++i)
        EXPECT_EQ(all[i], curvePaletteIndex(globals[i], kCurvePaletteSize));
}

}  // namespace
}  // namespace aerial::editor

namespace aerial::editor {
namespace {

// Keys of two curves copied together paste at another time, each onto its
// own curve with their relative times; one landing within a minute of an
// existing key replaces it at that key's time (no near-duplicates).
TEST(CurveClipboard, KeysOfSeveralCurvesPasteAtTheirOffsets) {
    Preset preset = twoTracks();  // fog 6, 8, 10 h; haze 12, 18 h
    const TrackTarget fog = preset.tracks[0].target, haze = preset.tracks[1].target;
    preset.tracks[0].keys[1].tangents = KeyTangents{glm::dvec3(0.001), glm::dvec3(0.001)};
    // 08:00 fog (its value and tangents), 12:00 haze, and the fog key's second point counted once.
    const CurveClipboard clip = copyCurvePoints(preset, {{fog, 1, 0}, {haze, 0, 0}, {fog, 1, 0}});
    ASSERT_EQ(clip.keys.size(), 2u);
    EXPECT_EQ(clip.keys[0].offsetHours, 0.0);
    EXPECT_EQ(clip.keys[1].offsetHours, 4.0);
    EXPECT_EQ(pasteLabel(clip), "Paste 2 keys");
    // At 17:59:40: the fog key lands there and the haze key at 21:59:40, no key near either: both new.
    Preset a = preset;
    std::vector<CurvePoint> pasted = pasteCurveKeys(a, clip, 17.0 + 59.0 / 60.0 + 40.0 / 3600.0);
    ASSERT_EQ(pasted.size(), 2u);
    ASSERT_EQ(a.tracks[0].keys.size(), 4u);
    EXPECT_EQ(a.tracks[0].keys[3].timeHours, 17.0 + 59.0 / 60.0 + 40.0 / 3600.0);
    EXPECT_EQ(a.tracks[0].keys[3].value.x, 0.02);
    EXPECT_EQ(a.tracks[0].keys[3].tangents, preset.tracks[0].keys[1].tangents);
    EXPECT_EQ(pasted[0], (CurvePoint{fog, 3, 0}));
    EXPECT_EQ(a.tracks[1].keys.size(), 3u);
    EXPECT_NEAR(a.tracks[1].keys[2].timeHours, 21.0 + 59.0 / 60.0 + 40.0 / 3600.0, 1e-12);
    // At 13:59:40: the haze key lands 20 s before the 18:00 key and replaces it at 18:00 exactly;
    // the fog key is new at 13:59:40.
    Preset b = preset;
    pasted = pasteCurveKeys(b, clip, 13.0 + 59.0 / 60.0 + 40.0 / 3600.0);
    ASSERT_EQ(b.tracks[1].keys.size(), 2u);
    EXPECT_EQ(b.tracks[1].keys[1].timeHours, 18.0);
    EXPECT_EQ(b.tracks[1].keys[1].value.x, 1e-5);
    EXPECT_EQ(pasted[1], (CurvePoint{haze, 1, 0}));
    for (const Track& t : b.tracks)
        for (std::size_t k = 1; k < t.keys.size(); ++k)
            EXPECT_GE(t.keys[k].timeHours - t.keys[k - 1].timeHours, kMinKeyGap);
    // Across midnight: keys at 23:30 and 00:30 are an hour apart, the 23:30 one first.
    Preset night = preset;
    night.tracks[0].keys = {{0.5, glm::dvec3(0.01)}, {23.5, glm::dvec3(0.02)}};
    const CurveClipboard wrap = copyCurvePoints(night, {{fog, 0, 0}, {fog, 1, 0}});
    ASSERT_EQ(wrap.keys.size(), 2u);
    EXPECT_EQ(wrap.keys[0].key.value.x, 0.02);
    EXPECT_EQ(wrap.keys[1].offsetHours, 1.0);
    // A deleted track comes back with the pasted key; one undo step through the document.
    Document doc;
    doc.reset(preset);
    doc.apply(pasteLabel(clip), "", [&](Preset& p) {
        p.tracks.erase(p.tracks.begin() + 1);
        pasteCurveKeys(p, clip, 3.0);
    });
    ASSERT_NE(findTrack(doc.preset(), haze), nullptr);
    EXPECT_EQ(findTrack(doc.preset(), haze)->keys.size(), 1u);
    EXPECT_EQ(findTrack(doc.preset(), haze)->keys[0].timeHours, 7.0);
    EXPECT_EQ(doc.undoLabel(), "Paste 2 keys");
    EXPECT_EQ(doc.undoCount(), 1u);
}

}  // namespace
}  // namespace aerial::editor
