// Auto-key and unkeyed changes (pending_edits.hpp): which edits are held,
// what the viewport is shown, what keying and validation do; the change's
// own track and the overlay on an evaluated state show what the whole
// preset with the change keyed shows.
#include "pending_edits.hpp"

#include <aerial/evaluate.hpp>

#include <gtest/gtest.h>

namespace aerial::editor {
namespace {

ParamRef fogDensity() { return {findParam(ParamScope::Global, "fog.density_per_m"), -1}; }

/// A preset whose fog density has keys at 06:00 (0.01) and 12:00 (0.002).
Preset animated() {
    Preset p;
    const double a[4] = {0.01, 0, 0, 0}, b[4] = {0.002, 0, 0, 0};
    keyParam(p, fogDensity(), 6.0);
    setValueAt(p, fogDensity(), a, 6.0);
    keyParam(p, fogDensity(), 12.0);
    setValueAt(p, fogDensity(), b, 12.0);
    return p;
}

TEST(PendingEdits, HeldOnlyForAnAnimatedParameterAwayFromItsKeysWithAutoKeyOff) {
    const Preset p = animated();
    PendingEdits pending;
    EXPECT_FALSE(pending.autoKey);  // the default
    EXPECT_TRUE(pending.holds(p, fogDensity(), 9.0));
    EXPECT_FALSE(pending.holds(p, fogDensity(), 12.0));             // at a key: the key changes
    EXPECT_FALSE(pending.holds(p, fogDensity(), 12.0 + 0.2 / 60));  // within the key tolerance
    const ParamRef falloff{findParam(ParamScope::Global, "fog.falloff_per_m"), -1};
    EXPECT_FALSE(pending.holds(p, falloff, 9.0));  // not animated: its constant value changes
    const ParamRef date{findParam(ParamScope::Global, "location.latitude_deg"), -1};
    EXPECT_FALSE(pending.holds(p, date, 9.0));  // not animatable
    pending.autoKey = true;
    EXPECT_FALSE(pending.holds(p, fogDensity(), 9.0));
}

TEST(PendingEdits, ShownWhereMadeNotSavedUntilKeyed) {
    const Preset p = animated();
    PendingEdits pending;
    const double v[4] = {0.05, 0, 0, 0};
    const std::uint64_t before = pending.revision();
    pending.set(fogDensity(), v, 9.0);
    EXPECT_GT(pending.revision(), before);
    double shown[4], stored[4];
    displayedValueAt(p, pending, fogDensity(), 9.0, shown);
    readValueAt(p, fogDensity(), 9.0, stored);
    EXPECT_EQ(shown[0], 0.05);
    EXPECT_NE(stored[0], 0.05);  // the document is untouched
    // The viewport's preset has it keyed at 09:00, the other keys kept.
    const Preset viewed = pending.applied(p);
    ASSERT_NE(trackOf(viewed, fogDensity()), nullptr);
    EXPECT_EQ(trackOf(viewed, fogDensity())->keys.size(), 3u);
    readValueAt(viewed, fogDensity(), 9.0, shown);
    EXPECT_EQ(shown[0], 0.05);
    readValueAt(viewed, fogDensity(), 12.0, shown);
    EXPECT_EQ(shown[0], 0.002);
    // Out of range: shown clamped, as it would be keyed.
    const double huge[4] = {50.0, 0, 0, 0};
    pending.set(fogDensity(), huge, 9.0);
    EXPECT_EQ(pending.size(), 1u);  // replaced, not added
    displayedValueAt(p, pending, fogDensity(), 9.0, shown);
    EXPECT_EQ(shown[0], fogDensity().desc->maxValue);
    EXPECT_TRUE(pending.erase(fogDensity()));
    EXPECT_FALSE(pending.erase(fogDensity()));
    EXPECT_TRUE(pending.empty());
}

TEST(PendingEdits, ValidateDropsWhatNoLongerApplies) {
    Preset p = animated();
    PendingEdits pending;
    const double v[4] = {0.05, 0, 0, 0};
    pending.set(fogDensity(), v, 9.0);
    pending.validate(p);
    EXPECT_EQ(pending.size(), 1u);
    p.tracks.clear();  // e.g. the keys were undone
    pending.validate(p);
    EXPECT_TRUE(pending.empty());
}

/// A volume whose colour is animated, beside the fog density of animated().
Preset animatedWithVolume(ParamRef& colour) {
    Preset p = animated();
    addVolume(p, FogVolumeShape::Box, glm::dvec3(0.0, 10.0, 0.0));
    colour = {findParam(ParamScope::Volume, "colour_rgb"), 0};
    const double warm[4] = {1.0, 0.5, 0.25, 0}, cold[4] = {0.2, 0.4, 1.0, 0};
    keyParam(p, colour, 7.0);
    setValueAt(p, colour, warm, 7.0);
    keyParam(p, colour, 19.0);
    setValueAt(p, colour, cold, 19.0);
    return p;
}

TEST(PendingEdits, ShownValueIsTheKeyedPresetsWithoutCopyingIt) {
    ParamRef colour;
    const Preset p = animatedWithVolume(colour);
    PendingEdits pending;
    const double density[4] = {0.07, 0, 0, 0}, rgb[4] = {3.0, -1.0, 0.5, 0};  // -1: clamped to 0
    pending.set(fogDensity(), density, 9.0);
    pending.set(colour, rgb, 10.5);
    const Preset keyed = pending.applied(p);  // what the inspector showed before: the whole preset keyed
    for (const ParamRef& ref : {fogDensity(), colour}) {
        const PendingEdit& e = *pending.find(ref);
        for (double t : {0.0, 9.0, 13.25}) {
            double shown[4], want[4];
            displayedValueAt(p, pending, ref, t, shown);
            readValueAt(keyed, ref, e.timeHours, want);  // shown where it was made
            for (int c = 0; c < 4; ++c) EXPECT_EQ(shown[c], want[c]) << paramAddress(ref) << " " << c;
        }
        const std::optional<Track> track = shownTrack(p, e);
        ASSERT_TRUE(track.has_value());
        EXPECT_EQ(track->keys.size(), trackOf(keyed, ref)->keys.size());
    }
}

TEST(PendingEdits, OverlayOnTheDocumentsStateIsTheKeyedPresetsState) {
    ParamRef colour;
    const Preset p = animatedWithVolume(colour);
    PendingEdits pending;
    const double density[4] = {0.07, 0, 0, 0}, rgb[4] = {3.0, 0.1, 0.5, 0};
    pending.set(fogDensity(), density, 9.0);
    pending.set(colour, rgb, 10.5);
    const CompiledPreset document(p), keyed(pending.applied(p));
    PendingOverlay overlay;
    overlay.bind(p, pending);
    EXPECT_EQ(overlay.size(), 2u);
    PresetState drawn, want;
    for (double t : {0.0, 6.0, 8.5, 9.0, 10.5, 11.0, 18.0, 23.9}) {
        document.evaluate(t, drawn);
        overlay.apply(drawn);
        keyed.evaluate(t, want);
        EXPECT_EQ(drawn.environment.fog.density, want.environment.fog.density) << t;
        EXPECT_EQ(drawn.volumes[0].colour, want.volumes[0].colour) << t;
    }
}

}  // namespace
}  // namespace aerial::editor
