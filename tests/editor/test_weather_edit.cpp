// The Weather panel's model: its edits of a preset's weather states (one
// undo step each, refused with validatePreset's own message), the value an
// override gives (checked against CompiledPreset::evaluate), and the
// viewport's preview, which never touches the document; the weather
// regions' edits and the preview's regions at the camera.
#include "document.hpp"
#include "editor_parts.hpp"
#include "weather_edit.hpp"
#include "weather_preview.hpp"

#include <gtest/gtest.h>

#include <string>

namespace aerial::editor {
namespace {

const std::string kPresets = std::string(AERIAL_SOURCE_DIR) + "/presets/";

Preset summerDay() {
    const PresetLoadResult loaded = loadPreset(kPresets + "clear_summer_day.json");
    EXPECT_TRUE(loaded.ok());
    return loaded.preset.value_or(Preset{});
}

ParamRef global(const char* path) { return {findParam(ParamScope::Global, path), -1}; }

WeatherOverride coverage(WeatherOverrideMode mode, double value) {
    return {TrackTarget::global("clouds.coverage"), mode, glm::dvec3(value, 0.0, 0.0)};
}

TEST(WeatherEdit, AddStateIsOneUndoStepThatMarksDirtyAndRedoes) {
    Document doc;
    doc.reset(summerDay(), "summer.json");
    ASSERT_FALSE(doc.dirty());
    const std::size_t before = doc.preset().weather.size();
    std::string error;
    ASSERT_TRUE(applyAddWeatherState(doc, "drizzle", error)) << error;
    EXPECT_TRUE(error.empty());
    EXPECT_TRUE(doc.dirty());
    EXPECT_EQ(doc.undoCount(), 1u);
    ASSERT_EQ(doc.preset().weather.size(), before + 1);
    EXPECT_EQ(doc.preset().weather.back().name, "drizzle");
    EXPECT_TRUE(doc.preset().weather.back().overrides.empty());
    EXPECT_EQ(doc.undoLabel(), "Add weather state drizzle");

    ASSERT_TRUE(doc.undo());
    EXPECT_EQ(doc.preset().weather.size(), before);
    EXPECT_FALSE(doc.dirty());
    ASSERT_TRUE(doc.redo());
    EXPECT_EQ(doc.preset().weather.back().name, "drizzle");
    EXPECT_TRUE(doc.dirty());
    EXPECT_TRUE(validatePreset(doc.preset()).empty());
}

TEST(WeatherEdit, RefusedNamesSayWhatValidatePresetSaysAndRecordNothing) {
    Document doc;
    doc.reset(summerDay());
    std::string error;
    EXPECT_FALSE(applyAddWeatherState(doc, "none", error));
    EXPECT_NE(error.find("\"none\" is taken"), std::string::npos) << error;
    EXPECT_FALSE(applyAddWeatherState(doc, "storm", error));
    EXPECT_NE(error.find("a second weather state named \"storm\""), std::string::npos) << error;
    EXPECT_FALSE(applyAddWeatherState(doc, "heavy rain", error));
    EXPECT_NE(error.find("1 to 64 of A-Z a-z 0-9 _ - . (got \"heavy rain\")"), std::string::npos) << error;
    EXPECT_FALSE(applyAddWeatherState(doc, "", error));
    // Renaming the first state to the last's name: core reports it at the later state.
    EXPECT_FALSE(applyRenameWeatherState(doc, 0, "storm", error));
    EXPECT_NE(error.find("a second weather state named \"storm\""), std::string::npos) << error;
    EXPECT_EQ(doc.undoCount(), 0u);
    EXPECT_FALSE(doc.dirty());
    EXPECT_EQ(doc.preset().weather.front().name, "clear");
    EXPECT_TRUE(presetsIdentical(doc.preset(), summerDay()));
}

TEST(WeatherEdit, RenameAndRemoveStateUndoAndRedo) {
    Document doc;
    doc.reset(summerDay());
    std::string error;
    ASSERT_TRUE(applyRenameWeatherState(doc, 1, "grey", error)) << error;
    EXPECT_EQ(doc.preset().weather[1].name, "grey");
    const std::size_t overrides = doc.preset().weather[2].overrides.size();
    ASSERT_TRUE(applyRemoveWeatherState(doc, 2, error)) << error;
    EXPECT_EQ(weatherStateIndex(doc.preset(), "storm"), -1);
    EXPECT_FALSE(applyRemoveWeatherState(doc, 7, error));
    EXPECT_EQ(doc.undoCount(), 2u);
    ASSERT_TRUE(doc.undo());
    ASSERT_EQ(weatherStateIndex(doc.preset(), "storm"), 2);
    EXPECT_EQ(doc.preset().weather[2].overrides.size(), overrides);
    ASSERT_TRUE(doc.undo());
    EXPECT_EQ(doc.preset().weather[1].name, "overcast");
    EXPECT_FALSE(doc.dirty());
    ASSERT_TRUE(doc.redo());
    ASSERT_TRUE(doc.redo());
    EXPECT_EQ(doc.preset().weather[1].name, "grey");
    EXPECT_EQ(doc.preset().weather.size(), 2u);
}

TEST(WeatherEdit, AddChangeAndRemoveAnOverrideEachUndoable) {
    Document doc;
    doc.reset(summerDay());
    std::string error;
    ASSERT_TRUE(applyAddWeatherState(doc, "haze", error)) << error;
    const int state = weatherStateIndex(doc.preset(), "haze");
    ASSERT_EQ(state, 3);
    const WeatherOverride fog = newWeatherOverride(doc.preset(), global("fog.density_per_m"), 9.0);
    EXPECT_EQ(fog.mode, WeatherOverrideMode::Set);
    double keyed[4];
    readValueAt(doc.preset(), global("fog.density_per_m"), 9.0, keyed);
    EXPECT_EQ(fog.value.x, keyed[0]);  // a new override changes nothing until it is edited
    ASSERT_TRUE(applyAddWeatherOverride(doc, state, fog, error)) << error;
    EXPECT_EQ(doc.undoCount(), 2u);
    // The same target twice: core's message, nothing recorded.
    EXPECT_FALSE(applyAddWeatherOverride(doc, state, fog, error));
    EXPECT_NE(error.find("a second override of the same target"), std::string::npos) << error;
    EXPECT_EQ(doc.undoCount(), 2u);

    // A drag of the value is one step; the mode is another.
    ASSERT_TRUE(applySetWeatherOverride(doc, state, 0, WeatherOverrideMode::Scale, glm::dvec3(2.0, 0, 0),
                                        true, error));
    ASSERT_TRUE(applySetWeatherOverride(doc, state, 0, WeatherOverrideMode::Scale, glm::dvec3(4.0, 0, 0),
                                        true, error));
    doc.closeMerge();
    EXPECT_EQ(doc.undoCount(), 3u);
    EXPECT_EQ(doc.preset().weather[3].overrides[0].value.x, 4.0);
    // A negative scale is refused with core's message.
    EXPECT_FALSE(applySetWeatherOverride(doc, state, 0, WeatherOverrideMode::Scale, glm::dvec3(-1.0, 0, 0),
                                         false, error));
    EXPECT_NE(error.find("a scale must be >= 0"), std::string::npos) << error;
    // A set value outside the parameter's range too.
    EXPECT_FALSE(applyAddWeatherOverride(doc, state, coverage(WeatherOverrideMode::Set, 1.5), error));
    EXPECT_FALSE(error.empty());
    EXPECT_EQ(doc.undoCount(), 3u);

    ASSERT_TRUE(applyRemoveWeatherOverride(doc, state, 0, error)) << error;
    EXPECT_TRUE(doc.preset().weather[3].overrides.empty());
    ASSERT_TRUE(doc.undo());
    ASSERT_EQ(doc.preset().weather[3].overrides.size(), 1u);
    EXPECT_EQ(doc.preset().weather[3].overrides[0].mode, WeatherOverrideMode::Scale);
    ASSERT_TRUE(doc.undo());  // the drag
    EXPECT_EQ(doc.preset().weather[3].overrides[0].mode, WeatherOverrideMode::Set);
    ASSERT_TRUE(doc.undo());  // the add
    EXPECT_TRUE(doc.preset().weather[3].overrides.empty());
    ASSERT_TRUE(doc.redo());
    ASSERT_TRUE(doc.redo());
    EXPECT_EQ(doc.preset().weather[3].overrides[0].value.x, 4.0);
    EXPECT_TRUE(validatePreset(doc.preset()).empty());
}

TEST(WeatherEdit, OnlyAnimatableParametersCanBeOverridden) {
    Preset p = summerDay();
    std::string error;
    WeatherOverride seed{TrackTarget::global("clouds.seed"), WeatherOverrideMode::Set, glm::dvec3(3.0)};
    if (const ParamDesc* d = findParam(ParamScope::Global, "clouds.seed"); d && !d->animatable) {
        EXPECT_FALSE(addWeatherOverride(p, 0, seed, error));
        EXPECT_NE(error.find("does not change with the weather"), std::string::npos) << error;
    }
    for (const ParamRef& ref : animatableParams(p)) EXPECT_TRUE(ref.desc->animatable);
    EXPECT_GT(animatableParams(p).size(), 10u);
}

TEST(WeatherEdit, OverriddenValueIsWhatEvaluateGivesWhenTheStateHolds) {
    const Preset p = summerDay();
    const CompiledPreset compiled(p);
    for (const WeatherState& state : p.weather) {
        WeatherMix mix;
        ASSERT_TRUE(settledWeather(p, state.name, mix));
        const PresetState keyed = compiled.evaluate(13.0);
        PresetState weathered;
        compiled.evaluate(13.0, mix, weathered);
        for (const WeatherOverride& o : state.overrides) {
            const std::optional<ParamRef> ref = paramRefOf(p, o.target);
            ASSERT_TRUE(ref);
            double k[4], want[4], have[4];
            readParam(*ref->desc, keyed.environment, k);
            readParam(*ref->desc, weathered.environment, want);
            overriddenValue(*ref->desc, k, o, have);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(have[c], want[c], 1e-12 * (1.0 + std::abs(want[c]))) << o.target.param;
            // Another mode for the same result keeps the picture.
            for (WeatherOverrideMode m :
                 {WeatherOverrideMode::Set, WeatherOverrideMode::Add, WeatherOverrideMode::Scale}) {
                WeatherOverride changed = o;
                changed.value = valueForMode(*ref->desc, k, o, m);
                changed.mode = m;
                double again[4];
                overriddenValue(*ref->desc, k, changed, again);
                bool zero = false;
                for (int c = 0; c < 3; ++c) zero = zero || k[c] == 0.0;
                if (m == WeatherOverrideMode::Scale && zero) continue;  // no ratio gives it
                for (int c = 0; c < 3; ++c) {
                    EXPECT_NEAR(again[c], have[c], 1e-9 * (1.0 + std::abs(have[c])));
                }
            }
        }
    }
}

TEST(WeatherEdit, TheLineSaysKeyedAndGiven) {
    const Preset p = summerDay();
    const WeatherOverride o = coverage(WeatherOverrideMode::Set, 0.97);
    const double keyed[4] = {0.3, 0, 0, 0};
    EXPECT_EQ(weatherOverrideText(p, o, "storm", keyed),
              "Cloud coverage: set 0.97 (keyed 0.3 -> 0.97 storm)");
}

TEST(WeatherEdit, DeletingOrRenamingAnObjectTakesItsOverridesAlong) {
    const PresetLoadResult loaded = loadPreset(kPresets + "foggy_valley_morning.json");
    ASSERT_TRUE(loaded.ok());
    Preset p = *loaded.preset;
    int valley = -1;
    for (std::size_t i = 0; i < p.volumes.size(); ++i)
        if (p.volumes[i].id == "valley_floor") valley = int(i);
    ASSERT_GE(valley, 0);
    std::string error;
    ASSERT_TRUE(setObjectId(p, ParamScope::Volume, valley, "valley_bottom", error)) << error;
    EXPECT_TRUE(validatePreset(p).empty());
    const int clearing = weatherStateIndex(p, "clearing");
    EXPECT_GE(weatherOverrideIndex(p.weather[std::size_t(clearing)],
                                   TrackTarget::volume("valley_bottom", "density_per_m")),
              0);
    ASSERT_TRUE(deleteObject(p, ParamScope::Volume, valley));
    EXPECT_TRUE(validatePreset(p).empty());  // no override of a missing volume left behind
}

TEST(WeatherPreview, ShowsStatesAndTransitionsWithoutTouchingTheDocument) {
    Document doc;
    doc.reset(summerDay());
    WeatherPreview preview;
    std::string error;
    EXPECT_FALSE(preview.update(doc.preset(), 0.0));
    EXPECT_TRUE(preview.mix().weights.empty());
    ASSERT_TRUE(parseWeatherPreview(doc.preset(), "storm", preview, error)) << error;
    EXPECT_TRUE(preview.update(doc.preset(), 0.0));
    EXPECT_EQ(preview.describe(), "storm");
    WeatherMix storm;
    settledWeather(doc.preset(), "storm", storm);
    EXPECT_EQ(preview.mix().weights, storm.weights);
    ASSERT_TRUE(parseWeatherPreview(doc.preset(), "clear:storm:0.25", preview, error)) << error;
    preview.update(doc.preset(), 0.0);
    EXPECT_EQ(preview.describe(), "clear -> storm 0.25");
    WeatherMix quarter;
    transitionWeather(doc.preset(), "clear", "storm", 0.25, quarter);
    EXPECT_EQ(preview.mix().weights, quarter.weights);
    EXPECT_FALSE(parseWeatherPreview(doc.preset(), "hail", preview, error));
    EXPECT_FALSE(parseWeatherPreview(doc.preset(), "clear:storm", preview, error));
    EXPECT_FALSE(doc.dirty());
    EXPECT_EQ(doc.undoCount(), 0u);

    // The viewport's evaluation with the mix: the storm's clouds.
    SkyService sky;
    PendingEdits pending;
    ASSERT_TRUE(preview.showState(doc.preset(), "storm", error));
    preview.update(doc.preset(), 0.0);
    sky.evaluate(doc, pending, 12.0, false, preview.mix());
    EXPECT_DOUBLE_EQ(sky.state.environment.clouds.coverage, 0.97);
    sky.evaluate(doc, pending, 12.0);
    EXPECT_LT(sky.state.environment.clouds.coverage, 0.9);
}

TEST(WeatherPreview, PlaysOnTheClockAndEndsAtTheTarget) {
    const Preset p = summerDay();
    WeatherPreview preview;
    std::string error;
    EXPECT_FALSE(preview.play(p, "clear", "storm", 0.0, 100.0, error));
    ASSERT_TRUE(preview.play(p, "clear", "storm", 10.0, 100.0, error)) << error;
    EXPECT_TRUE(preview.playing());
    preview.update(p, 105.0);
    EXPECT_NEAR(preview.fraction(), 0.5, 1e-12);
    // The mix is aerial::Weather's, each category at its own speed: the wind (40 %) has arrived.
    ASSERT_EQ(preview.mix().weights.size(), p.weather.size());
    EXPECT_DOUBLE_EQ(preview.mix().weights[2][std::size_t(WeatherCategory::Wind)], 1.0);
    EXPECT_LT(preview.mix().weights[2][std::size_t(WeatherCategory::Clouds)], 1.0);
    preview.update(p, 111.0);
    EXPECT_FALSE(preview.playing());
    EXPECT_EQ(preview.describe(), "clear -> storm 1.00");
    WeatherMix storm;
    settledWeather(p, "storm", storm);
    EXPECT_EQ(preview.mix().weights, storm.weights);
    // A state removed under the preview ends it.
    Preset fewer = p;
    ASSERT_TRUE(removeWeatherState(fewer, 2));
    EXPECT_TRUE(preview.update(fewer, 112.0));
    EXPECT_EQ(preview.mode(), WeatherPreview::Mode::None);
    EXPECT_TRUE(preview.mix().weights.empty());
}

// ---------------------------------------------------------------------------
// Weather regions

TEST(WeatherRegionEdit, AddChangeAndRemoveEachOneUndoStep) {
    Document doc;
    doc.reset(summerDay(), "summer.json");
    std::string error;
    const WeatherRegion r =
        newWeatherRegion(doc.preset(), WeatherRegionShape::Box, "overcast", glm::dvec3(100.0, 0.0, -200.0));
    EXPECT_EQ(r.id, "region");
    ASSERT_TRUE(applyAddWeatherRegion(doc, r, error)) << error;
    EXPECT_EQ(doc.undoLabel(), "Add weather region region");
    ASSERT_EQ(doc.preset().weatherRegions.size(), 2u);
    EXPECT_EQ(uniqueWeatherRegionId(doc.preset(), "region"), "region_2");
    // A drag: two continuous edits are one step until closeMerge.
    WeatherRegion moved = doc.preset().weatherRegions[1];
    ASSERT_TRUE(setWeatherRegionField(moved, "position_m", {"10", "20", "30"}, error)) << error;
    ASSERT_TRUE(applySetWeatherRegion(doc, 1, moved, true, error)) << error;
    ASSERT_TRUE(setWeatherRegionField(moved, "blend_m", {"350"}, error)) << error;
    ASSERT_TRUE(applySetWeatherRegion(doc, 1, moved, true, error)) << error;
    doc.closeMerge();
    EXPECT_EQ(doc.undoCount(), 2u);
    EXPECT_EQ(doc.preset().weatherRegions[1].position, glm::dvec3(10.0, 20.0, 30.0));
    EXPECT_EQ(doc.preset().weatherRegions[1].blend, 350.0);
    // Refused with validatePreset's words, nothing recorded.
    WeatherRegion bad = moved;
    bad.id = "ridge_storm";
    EXPECT_FALSE(applySetWeatherRegion(doc, 1, bad, false, error));
    EXPECT_EQ(error, "duplicate id \"ridge_storm\" (also /weather/regions/0)");
    bad = moved;
    bad.state = "hail";
    EXPECT_FALSE(applySetWeatherRegion(doc, 1, bad, false, error));
    EXPECT_EQ(error, "no weather state \"hail\" (the preset has none, clear, overcast, storm)");
    bad = moved;
    bad.halfExtents.y = 0.0;
    EXPECT_FALSE(applySetWeatherRegion(doc, 1, bad, false, error));
    EXPECT_EQ(error, "out of range: 0 is not in 1..1e+07 m");
    EXPECT_FALSE(setWeatherRegionField(bad, "shape", {"cone"}, error));
    EXPECT_EQ(error, "shape \"cone\" is not one of box, ellipsoid");
    EXPECT_FALSE(setWeatherRegionField(bad, "priority", {"1.5"}, error));
    EXPECT_FALSE(setWeatherRegionField(bad, "colour", {"1"}, error));
    EXPECT_EQ(doc.undoCount(), 2u);
    // Remove, undo, redo.
    ASSERT_TRUE(applyRemoveWeatherRegion(doc, 1, error)) << error;
    EXPECT_EQ(doc.preset().weatherRegions.size(), 1u);
    EXPECT_FALSE(applyRemoveWeatherRegion(doc, 5, error));
    ASSERT_TRUE(doc.undo());
    EXPECT_EQ(doc.preset().weatherRegions[1].blend, 350.0);
    ASSERT_TRUE(doc.undo());
    ASSERT_TRUE(doc.undo());
    EXPECT_EQ(doc.preset().weatherRegions.size(), 1u);
    EXPECT_FALSE(doc.dirty());
}

TEST(WeatherRegionEdit, RenamingAStateCarriesItsRegionsAndRemovingItTakesThem) {
    Document doc;
    doc.reset(summerDay());
    std::string error;
    ASSERT_EQ(doc.preset().weatherRegions.at(0).state, "storm");
    ASSERT_TRUE(applyRenameWeatherState(doc, 2, "thunder", error)) << error;
    EXPECT_EQ(doc.preset().weatherRegions[0].state, "thunder");
    ASSERT_TRUE(applyRemoveWeatherState(doc, 2, error)) << error;
    EXPECT_TRUE(doc.preset().weatherRegions.empty());
    EXPECT_TRUE(validatePreset(doc.preset()).empty());
    ASSERT_TRUE(doc.undo());
    ASSERT_EQ(doc.preset().weatherRegions.size(), 1u);
    EXPECT_EQ(doc.preset().weatherRegions[0].state, "thunder");
    ASSERT_TRUE(doc.undo());
    EXPECT_EQ(doc.preset().weatherRegions[0].state, "storm");
}

TEST(WeatherRegionEdit, YawIsTheTurnAboutUp) {
    const Preset preset = summerDay();
    EXPECT_NEAR(weatherRegionYawDeg(preset.weatherRegions.at(0)), 30.0, 1e-9);  // the shipped ridge
    WeatherRegion r;
    std::string error;
    for (double yaw : {-179.5, -90.0, 0.0, 45.0, 180.0}) {
        ASSERT_TRUE(setWeatherRegionField(r, "yaw_deg", {std::to_string(yaw)}, error)) << error;
        EXPECT_NEAR(weatherRegionYawDeg(r), yaw, 1e-9);
        EXPECT_NEAR(glm::length(r.rotation), 1.0, 1e-15);
    }
    // 90 degrees takes +X to -Z (north): counter-clockwise seen from above.
    setWeatherRegionYawDeg(r, 90.0);
    const glm::dvec3 x = r.rotation * glm::dvec3(1.0, 0.0, 0.0);
    EXPECT_NEAR(x.z, -1.0, 1e-12);
}

TEST(WeatherPreview, AppliesTheRegionsAtTheCamera) {
    const Preset preset = summerDay();
    const WeatherRegion& ridge = preset.weatherRegions.at(0);
    WeatherPreview preview;
    ASSERT_TRUE(preview.regionsAtCamera());
    WeatherMix storm;
    settledWeather(preset, "storm", storm);
    // In the storm's ellipsoid: the storm, and the words say so.
    EXPECT_TRUE(preview.update(preset, 0.0, &ridge.position));
    EXPECT_EQ(preview.mix().weights, storm.weights);
    EXPECT_EQ(preview.describe(), "none + regions ridge_storm 1.00");
    // Far away, or with the regions off: the preview's own mix.
    const glm::dvec3 far(0.0, 2.0, 0.0);
    EXPECT_TRUE(preview.update(preset, 0.0, &far));
    EXPECT_TRUE(preview.mix().weights.empty());
    EXPECT_EQ(preview.describe(), "none");
    preview.setRegionsAtCamera(false);
    EXPECT_FALSE(preview.update(preset, 0.0, &ridge.position));
    EXPECT_TRUE(preview.mix().weights.empty());
    // A state previewed under a region: the region is applied over it.
    preview.setRegionsAtCamera(true);
    std::string error;
    ASSERT_TRUE(preview.showState(preset, "clear", error));
    preview.update(preset, 0.0, &ridge.position);
    EXPECT_EQ(preview.mix().weights, storm.weights);
    EXPECT_EQ(preview.describe(), "clear + regions ridge_storm 1.00");
}

}  // namespace
}  // namespace aerial::editor
