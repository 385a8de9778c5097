// test_curve_view.cpp — the timeline's curve view without a window: zoom
// and pan of the time span, ruler ticks, normalisation of curves to their
// keys' range, hit-testing and box selection of key points, moving many
// keys in time and value at once, flat tangents and the undo step's name;
// typed shifts (limited as a drag) and keys that follow the sun (anchored
// where they stand, read as "sunset + 0:20 (19:52)").
#include "curve_view.hpp"
#include "document.hpp"

#include <aerial/clock.hpp>
#include <aerial/param_table.hpp>
#include <aerial/sun.hpp>

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace aerial::editor
