// Preset edits the editor makes: parameter addresses, values shown at a time
// (tracks), auto-key, key editing (add, remove, move, paste, key all
// changed) and objects (add, duplicate, delete, rename).
#include "preset_edit.hpp"

#include <gtest/gtest.h>

namespace aerial::editor {
namespace {

ParamRef ref(const Preset& p, const char* address) {
    std::string error;
    std::optional<ParamRef> r = parseParamAddress(p, address, &error);
    EXPECT_TRUE(r.has_value()) << error;
    return r.value_or(ParamRef{});
}

TEST(PresetEdit, Addresses) {
    const Preset p = defaultPreset();
    std::string error;
    const auto g = parseParamAddress(p, "fog.density_per_m", &error);
    ASSERT_TRUE(g);
    EXPECT_EQ(g->scope(), ParamScope::Global);
    EXPECT_EQ(paramAddress(*g), "fog.density_per_m");
    const auto v = parseParamAddress(p, "volume[0].density_per_m", &error);
    ASSERT_TRUE(v);
    EXPECT_EQ(v->object, 0);
    EXPECT_EQ(paramAddress(*v), "volume[0].density_per_m");
    EXPECT_TRUE(parseParamAddress(p, "emitter[0].intensity_cd", &error));
    EXPECT_FALSE(parseParamAddress(p, "volume[5].density_per_m", &error));
    EXPECT_NE(error.find("there are 1 volumes"), std::string::npos) << error;
    EXPECT_FALSE(parseParamAddress(p, "fog.nope", &error));
    EXPECT_FALSE(parseParamAddress(p, "volume[x].density_per_m", &error));
    EXPECT_FALSE(parseParamAddress(p, "volume[0]density_per_m", &error));
}

TEST(PresetEdit, ValueAtTimeFollowsTheTrack) {
    const Preset p = defaultPreset();
    double v[4];
    readValueAt(p, ref(p, "fog.density_per_m"), 6.0, v);
    EXPECT_DOUBLE_EQ(v[0], 0.0012);  // a key of the default preset
    readBaseValue(p, ref(p, "fog.density_per_m"), v);
    EXPECT_DOUBLE_EQ(v[0], 0.0004);
    readValueAt(p, ref(p, "fog.falloff_per_m"), 6.0, v);  // no track: constant
    EXPECT_DOUBLE_EQ(v[0], 0.02);
}

TEST(PresetEdit, SetValueAutoKeysAnimatedParameters) {
    Preset p = defaultPreset();
    const double value[4] = {0.005, 0, 0, 0};
    setValueAt(p, ref(p, "fog.density_per_m"), value, 9.0);  // animated: key at 09:00
    const Track* track = findTrack(p, TrackTarget::global("fog.density_per_m"));
    ASSERT_TRUE(track);
    EXPECT_EQ(track->keys.size(), 5u);
    EXPECT_GE(keyIndexAt(*track, 9.0), 0);
    EXPECT_DOUBLE_EQ(p.environment.fog.density, 0.0004) << "the constant stays";
    setValueAt(p, ref(p, "fog.falloff_per_m"), value, 9.0);  // constant
    EXPECT_DOUBLE_EQ(p.environment.fog.falloff, 0.005);
    EXPECT_FALSE(findTrack(p, TrackTarget::global("fog.falloff_per_m")));
}

TEST(PresetEdit, AnEditAtAKeyChangesThatKeyNotANeighbour) {
    // Issue 50: the playhead at 06:00:20 is "at" the 06:00 key (the
    // inspector shows it keyed there): the edit changes that key, at its own
    // time, and leaves no second key 20 s beside it.
    Preset p = defaultPreset();
    const Track* track = findTrack(p, TrackTarget::global("fog.density_per_m"));
    ASSERT_TRUE(track);
    const std::size_t before = track->keys.size();
    ASSERT_GE(keyIndexAt(*track, 6.0), 0);
    const double value[4] = {0.003, 0, 0, 0};
    setValueAt(p, ref(p, "fog.density_per_m"), value, 6.0 + 20.0 / 3600.0);
    track = findTrack(p, TrackTarget::global("fog.density_per_m"));
    ASSERT_EQ(track->keys.size(), before);
    const TrackKey& key = track->keys[std::size_t(keyIndexAt(*track, 6.0))];
    EXPECT_EQ(key.timeHours, 6.0);
    EXPECT_EQ(key.value.x, 0.003);
    for (std::size_t k = 1; k < track->keys.size(); ++k)
        EXPECT_GE(track->keys[k].timeHours - track->keys[k - 1].timeHours, 1.0 / 60.0);
    // Away from every key (beyond the tolerance) the edit adds a key there.
    setValueAt(p, ref(p, "fog.density_per_m"), value, 6.0 + 2.0 / 60.0);
    EXPECT_EQ(findTrack(p, TrackTarget::global("fog.density_per_m"))->keys.size(), before + 1);
}

TEST(PresetEdit, SetValueClampsAndNormalises) {
    Preset p = defaultPreset();
    const double huge[4] = {1e9, 0, 0, 0};
    setValueAt(p, ref(p, "fog.falloff_per_m"), huge, 0.0);
    EXPECT_DOUBLE_EQ(p.environment.fog.falloff, 10.0);
    const double dir[4] = {0, 2, 0, 0};
    setValueAt(p, ref(p, "volume[0].gradient_direction"), dir, 0.0);
    EXPECT_DOUBLE_EQ(p.volumes[0].gradientDirection.y, 1.0);
    const double zero[4] = {0, 0, 0, 0};
    setValueAt(p, ref(p, "volume[0].gradient_direction"), zero, 0.0);  // ignored
    EXPECT_DOUBLE_EQ(p.volumes[0].gradientDirection.y, 1.0);
    const double shape[4] = {1, 0, 0, 0};
    setValueAt(p, ref(p, "volume[0].shape"), shape, 0.0);
    EXPECT_EQ(p.volumes[0].shape, FogVolumeShape::Ellipsoid);
    EXPECT_TRUE(validatePreset(p).empty());
}

TEST(PresetEdit, KeyCreatesTrackWithTheShownValue) {
    Preset p = defaultPreset();
    ASSERT_TRUE(keyParam(p, ref(p, "fog.falloff_per_m"), 6.0));
    const Track* t = findTrack(p, TrackTarget::global("fog.falloff_per_m"));
    ASSERT_TRUE(t);
    ASSERT_EQ(t->keys.size(), 1u);
    EXPECT_DOUBLE_EQ(t->keys[0].timeHours, 6.0);
    EXPECT_DOUBLE_EQ(t->keys[0].value.x, 0.02);
    const double v[4] = {0.1, 0, 0, 0};
    setValueAt(p, ref(p, "fog.falloff_per_m"), v, 12.0);
    ASSERT_EQ(t->keys.size(), 2u);
    double shown[4];
    readValueAt(p, ref(p, "fog.falloff_per_m"), 6.0, shown);
    EXPECT_DOUBLE_EQ(shown[0], 0.02);
    readValueAt(p, ref(p, "fog.falloff_per_m"), 12.0, shown);
    EXPECT_DOUBLE_EQ(shown[0], 0.1);
    EXPECT_FALSE(keyParam(p, ref(p, "location.latitude_deg"), 6.0)) << "not animatable";
    EXPECT_TRUE(validatePreset(p).empty());
}

TEST(PresetEdit, KeyingTwiceAtTheSameTimeReplaces) {
    Preset p = defaultPreset();
    keyParam(p, ref(p, "fog.falloff_per_m"), 6.0);
    keyParam(p, ref(p, "fog.falloff_per_m"), 6.0 + 0.2 / 60.0);  // within half a minute
    EXPECT_EQ(findTrack(p, TrackTarget::global("fog.falloff_per_m"))->keys.size(), 1u);
}

TEST(PresetEdit, RemoveKeyRemovesEmptyTracks) {
    Preset p = defaultPreset();
    keyParam(p, ref(p, "fog.falloff_per_m"), 6.0);
    const TrackTarget target = TrackTarget::global("fog.falloff_per_m");
    EXPECT_FALSE(removeKey(p, target, 3));
    EXPECT_TRUE(removeKey(p, target, 0));
    EXPECT_FALSE(findTrack(p, target));
}

TEST(PresetEdit, MoveKeyStaysBetweenNeighbours) {
    Preset p = defaultPreset();
    Track& t = *findTrack(p, TrackTarget::global("fog.density_per_m"));  // keys 0, 6, 14, 20
    EXPECT_DOUBLE_EQ(moveKey(t, 1, 8.0), 8.0);
    EXPECT_NEAR(moveKey(t, 1, 30.0), 14.0 - kMinKeyGap, 1e-12);
    EXPECT_NEAR(moveKey(t, 1, -5.0), 0.0 + kMinKeyGap, 1e-12);
    EXPECT_NEAR(moveKey(t, 3, 25.0), 24.0 - kMinKeyGap, 1e-12);
    EXPECT_DOUBLE_EQ(moveKey(t, 0, -1.0), 0.0);
    EXPECT_TRUE(validatePreset(p).empty());
}

TEST(PresetEdit, KeyAllChanged) {
    const Preset baseline = defaultPreset();
    Preset p = baseline;
    EXPECT_EQ(keyAllChanged(p, baseline, 10.0), 0);
    p.environment.fog.falloff = 0.05;         // constant changed
    p.volumes[0].position.x = 12.0;           // volume param changed
    p.emitters[0].colour = {1, 0, 0};         // emitter param changed
    p.environment.location.latitudeDeg = 10;  // not animatable: ignored
    EXPECT_EQ(keyAllChanged(p, baseline, 10.0), 3);
    EXPECT_TRUE(findTrack(p, TrackTarget::global("fog.falloff_per_m")));
    EXPECT_TRUE(findTrack(p, TrackTarget::volume("ground_fog", "position_m")));
    EXPECT_TRUE(findTrack(p, TrackTarget::emitter("lamp", "colour_rgb")));
    EXPECT_EQ(keyAllChanged(p, baseline, 10.0), 0) << "already keyed with these values";
    EXPECT_TRUE(validatePreset(p).empty());
}

TEST(PresetEdit, CopyPasteKeys) {
    Preset p = defaultPreset();
    KeyClipboard clip{true, ParamType::Scalar, glm::dvec3(0.003, 0, 0)};
    EXPECT_TRUE(pasteKey(p, ref(p, "fog.falloff_per_m"), clip, 15.0));
    double v[4];
    readValueAt(p, ref(p, "fog.falloff_per_m"), 15.0, v);
    EXPECT_DOUBLE_EQ(v[0], 0.003);
    EXPECT_FALSE(pasteKey(p, ref(p, "fog.colour_rgb"), clip, 15.0)) << "scalar onto a colour";
    KeyClipboard colour{true, ParamType::Colour, glm::dvec3(0.1, 0.2, 0.3)};
    EXPECT_TRUE(pasteKey(p, ref(p, "fog.colour_rgb"), colour, 3.0));
    EXPECT_TRUE(validatePreset(p).empty());
}

TEST(PresetEdit, Vec2ValuesKeysAndPaste) {
    // No table entry is a Vec2 yet: a hand-made, animatable one (its field
    // lives outside Environment) drives the generic editing paths.
    static glm::dvec2 wind(0.0, 0.0);
    ParamDesc d;
    d.scope = ParamScope::Global;
    d.type = ParamType::Vec2;
    d.path = "test.wind_m_per_s";
    d.label = "Wind";
    d.minValue = -100.0;
    d.maxValue = 100.0;
    d.uiMin = -30.0;
    d.uiMax = 30.0;
    d.animatable = true;
    d.vec2 = [](void*) { return &wind; };
    const ParamRef r{&d, -1};
    Preset p = defaultPreset();

    // Constant value: set (clamped per component) and read back as [x, z].
    const double set[4] = {4.0, -250.0, 7.0, 0.0};
    setValueAt(p, r, set, 12.0);
    EXPECT_EQ(wind, glm::dvec2(4.0, -100.0));
    double v[4];
    readValueAt(p, r, 12.0, v);
    EXPECT_EQ(v[0], 4.0);
    EXPECT_EQ(v[1], -100.0);
    EXPECT_EQ(v[2], 0.0);

    // Keying makes a track whose keys hold x, z in value.x, .y and z = 0.
    ASSERT_TRUE(keyParam(p, r, 6.0));
    const Track* track = trackOf(p, r);
    ASSERT_NE(track, nullptr);
    ASSERT_EQ(track->keys.size(), 1u);
    EXPECT_EQ(track->keys[0].value, glm::dvec3(4.0, -100.0, 0.0));
    const double later[4] = {-2.0, 10.0, 5.0, 0.0};
    setValueAt(p, r, later, 18.0);  // auto-key
    track = trackOf(p, r);
    ASSERT_EQ(track->keys.size(), 2u);
    EXPECT_EQ(track->keys[1].value, glm::dvec3(-2.0, 10.0, 0.0));
    EXPECT_EQ(wind, glm::dvec2(4.0, -100.0)) << "a keyed parameter keeps its base value";
    readValueAt(p, r, 18.0, v);
    EXPECT_EQ(v[0], -2.0);
    EXPECT_EQ(v[1], 10.0);
    EXPECT_EQ(v[2], 0.0);

    // A Vec2 key pastes onto a Vec2 only.
    KeyClipboard clip{true, ParamType::Vec2, glm::dvec3(1.5, 2.5, 0.0)};
    EXPECT_TRUE(pasteKey(p, r, clip, 9.0));
    readValueAt(p, r, 9.0, v);
    EXPECT_EQ(v[0], 1.5);
    EXPECT_EQ(v[1], 2.5);
    EXPECT_FALSE(pasteKey(p, ref(p, "fog.colour_rgb"), clip, 9.0)) << "a 2-vector onto a colour";
    EXPECT_FALSE(pasteKey(p, ref(p, "fog.falloff_per_m"), clip, 9.0)) << "a 2-vector onto a scalar";
    KeyClipboard colour{true, ParamType::Colour, glm::dvec3(0.1, 0.2, 0.3)};
    EXPECT_FALSE(pasteKey(p, r, colour, 9.0)) << "a colour onto a 2-vector";
}

TEST(PresetEdit, Objects) {
    Preset p = defaultPreset();
    const int v = addVolume(p, FogVolumeShape::Ellipsoid, {1, 2, 3});
    EXPECT_EQ(v, 1);
    EXPECT_EQ(p.volumes[1].id, "ellipsoid_volume");
    EXPECT_EQ(p.volumes[1].position, glm::dvec3(1, 2, 3));
    EXPECT_EQ(addVolume(p, FogVolumeShape::Ellipsoid, {}), 2);
    EXPECT_EQ(p.volumes[2].id, "ellipsoid_volume_2");
    EXPECT_EQ(p.volumes[2].name, "Ellipsoid volume 2");
    const int e = addEmitter(p, EmitterKind::Point, {0, 3, 0});
    EXPECT_DOUBLE_EQ(p.emitters[std::size_t(e)].intensityCd, kNewEmitterIntensityCd);
    EXPECT_DOUBLE_EQ(p.emitters[std::size_t(e)].attenuation, kNewEmitterAttenuationPerM2);
    EXPECT_LT(p.emitters[std::size_t(e)].intensity, 0.01) << "artist-sane next to a sky of radiance ~1";

    // Duplicate copies the tracks under the new id.
    const int d = duplicateObject(p, ParamScope::Volume, 0, {5, 0, 0});
    ASSERT_GE(d, 0);
    EXPECT_EQ(p.volumes[std::size_t(d)].id, "ground_fog_2");
    EXPECT_EQ(p.volumes[std::size_t(d)].name, "Ground fog copy");
    EXPECT_TRUE(findTrack(p, TrackTarget::volume("ground_fog_2", "density_per_m")));
    EXPECT_TRUE(renameObject(p, ParamScope::Volume, d, "Mist"));
    EXPECT_EQ(p.volumes[std::size_t(d)].name, "Mist");
    EXPECT_TRUE(validatePreset(p).empty());

    EXPECT_TRUE(deleteObject(p, ParamScope::Volume, 0));
    EXPECT_FALSE(findTrack(p, TrackTarget::volume("ground_fog", "density_per_m")));
    EXPECT_TRUE(findTrack(p, TrackTarget::volume("ground_fog_2", "density_per_m")));
    EXPECT_FALSE(deleteObject(p, ParamScope::Volume, 99));
    EXPECT_TRUE(validatePreset(p).empty());
}

TEST(PresetEdit, CloudVolumesAreObjectsToo) {
    // The model addresses, keys, duplicates, renames and deletes them like volumes.
    Preset p;
    CloudVolume storm;
    storm.id = "storm";
    p.cloudVolumes.push_back(storm);
    const ParamRef coverage = ref(p, "cloud_volume[0].coverage");
    EXPECT_EQ(coverage.scope(), ParamScope::CloudVolume);
    EXPECT_EQ(paramAddress(coverage), "cloud_volume[0].coverage");
    EXPECT_EQ(objectCount(p, ParamScope::CloudVolume), 1u);
    std::string error;
    EXPECT_FALSE(parseParamAddress(p, "cloud_volume[1].coverage", &error));
    EXPECT_NE(error.find("there are 1 cloud volumes"), std::string::npos) << error;
    ASSERT_TRUE(keyParam(p, coverage, 9.0));
    EXPECT_EQ(trackTargetOf(p, coverage), TrackTarget::cloudVolume("storm", "coverage"));
    const double half[4] = {0.5, 0, 0, 0};
    setValueAt(p, coverage, half, 9.0);
    double v[4];
    readValueAt(p, coverage, 9.0, v);
    EXPECT_EQ(v[0], 0.5);
    EXPECT_EQ(duplicateObject(p, ParamScope::CloudVolume, 0, {1000, 0, 0}), 1);
    EXPECT_EQ(p.cloudVolumes[1].id, "storm_2");
    EXPECT_EQ(p.tracks.size(), 2u);
    EXPECT_TRUE(renameObject(p, ParamScope::CloudVolume, 1, "Second cell"));
    EXPECT_TRUE(validatePreset(p).empty());
    EXPECT_TRUE(deleteObject(p, ParamScope::CloudVolume, 0));
    EXPECT_EQ(p.cloudVolumes.size(), 1u);
    EXPECT_EQ(p.tracks.size(), 1u);
    EXPECT_EQ(p.tracks[0].target.objectId, "storm_2");
}

TEST(PresetEdit, NewCloudVolumeSitsInTheLayerAboveTheLookAtPoint) {
    CloudParams layer;
    layer.bottomM = 1400.0;
    layer.thicknessM = 1800.0;
    const CloudVolume v = newCloudVolumeAt(layer, {120.0, 3.0, -450.0});
    EXPECT_EQ(v.position, glm::dvec3(120.0, 1400.0 + 900.0, -450.0));
    EXPECT_EQ(v.halfExtents, glm::dvec3(kNewCloudVolumeHalfWidthM, 900.0, kNewCloudVolumeHalfWidthM));
    EXPECT_EQ(v.coverage, 1.0);
    EXPECT_EQ(v.edgeSoftness, 0.5);
    // Not finite where it looks: above the origin.
    EXPECT_EQ(newCloudVolumeAt(layer, {NAN, 0.0, INFINITY}).position, glm::dvec3(0.0, 2300.0, 0.0));

    Preset p;
    EXPECT_EQ(addCloudVolume(p, FogVolumeShape::Ellipsoid, v), 0);
    EXPECT_EQ(addCloudVolume(p, FogVolumeShape::Ellipsoid, v), 1);
    EXPECT_EQ(addCloudVolume(p, FogVolumeShape::Box, v), 2);
    EXPECT_EQ(p.cloudVolumes[0].id, "cloud_ellipsoid");
    EXPECT_EQ(p.cloudVolumes[0].name, "Cloud ellipsoid");
    EXPECT_EQ(p.cloudVolumes[1].id, "cloud_ellipsoid_2");
    EXPECT_EQ(p.cloudVolumes[1].name, "Cloud ellipsoid 2");
    EXPECT_EQ(p.cloudVolumes[2].id, "cloud_box");
    EXPECT_EQ(p.cloudVolumes[2].shape, FogVolumeShape::Box);
    EXPECT_EQ(p.cloudVolumes[2].position, v.position);
    EXPECT_TRUE(validatePreset(p).empty());
    // Duplicate and delete like any object.
    EXPECT_EQ(duplicateObject(p, ParamScope::CloudVolume, 2, {1000, 0, 0}), 3);
    EXPECT_EQ(p.cloudVolumes[3].id, "cloud_box_2");
    EXPECT_EQ(p.cloudVolumes[3].position, v.position + glm::dvec3(1000, 0, 0));
    EXPECT_TRUE(deleteObject(p, ParamScope::CloudVolume, 0));
    EXPECT_EQ(objectCount(p, ParamScope::CloudVolume), 3u);
    EXPECT_EQ(p.cloudVolumes[0].id, "cloud_ellipsoid_2");
}

TEST(PresetEdit, ObjectIdsAreEditedWithTheirTracks) {
    Preset p;
    addVolume(p, FogVolumeShape::Box, glm::dvec3(0.0));
    addVolume(p, FogVolumeShape::Ellipsoid, glm::dvec3(0.0));
    const ParamRef density{findParam(ParamScope::Volume, "density_per_m"), 1};
    ASSERT_TRUE(keyParam(p, density, 6.0));
    const std::string first = p.volumes[0].id;
    std::string error;
    EXPECT_TRUE(setObjectId(p, ParamScope::Volume, 1, "lake_mist", error)) << error;
    EXPECT_EQ(p.volumes[1].id, "lake_mist");
    ASSERT_NE(trackOf(p, density), nullptr);  // the track follows the id
    EXPECT_EQ(trackOf(p, density)->target.objectId, "lake_mist");
    // Refused, unchanged: a duplicate, an empty id, a bad character, too long.
    const Preset before = p;
    EXPECT_FALSE(setObjectId(p, ParamScope::Volume, 1, first, error));
    EXPECT_EQ(error, "another volume already has the id \"" + first + "\"");
    EXPECT_FALSE(setObjectId(p, ParamScope::Volume, 1, "", error));
    EXPECT_FALSE(setObjectId(p, ParamScope::Volume, 1, "lake mist", error));
    EXPECT_NE(error.find("A-Z a-z 0-9 _ - ."), std::string::npos);
    EXPECT_FALSE(setObjectId(p, ParamScope::Volume, 1, std::string(65, 'a'), error));
    EXPECT_FALSE(setObjectId(p, ParamScope::Volume, 7, "x", error));
    EXPECT_TRUE(presetsIdentical(p, before));
    // The same id as before is fine (unchanged).
    EXPECT_TRUE(setObjectId(p, ParamScope::Volume, 1, "lake_mist", error));
}

TEST(PresetEdit, SaveAsOffersTheNewFilesNameToAnUnnamedPreset) {
    EXPECT_EQ(presetNameFromFile("/a/b/misty_autumn-dawn.json"), "Misty autumn dawn");
    // Opened from foggy_valley_morning.json, never renamed: follows the file.
    EXPECT_EQ(
        nameAfterSaveAs("Foggy valley morning", "presets/foggy_valley_morning.json", "/tmp/misty_dawn.json"),
        "Misty dawn");
    // The built-in default (no file yet) too.
    EXPECT_EQ(nameAfterSaveAs(defaultPreset().name, "", "/tmp/lake.json"), "Lake");
    // A name the artist chose stays.
    EXPECT_EQ(nameAfterSaveAs("Lake at dawn, v2", "presets/foggy_valley_morning.json", "/tmp/lake.json"), "");
    EXPECT_EQ(nameAfterSaveAs("Lake", "/tmp/old.json", "/tmp/lake.json"), "");  // already it
}

TEST(PresetEdit, DraggedKeysSnapToOtherKeysElseToTheSnapStep) {
    Preset p;
    Track fog;
    fog.target = TrackTarget::global("fog.density_per_m");
    fog.keys = {{8.0, glm::dvec3(0.01)}, {12.0, glm::dvec3(0.0)}};
    Track mist;
    mist.target = TrackTarget::global("fog.falloff_per_m");
    mist.keys = {{9.6, glm::dvec3(0.02)}};
    p.tracks = {fog, mist};
    const double near = 0.05;  // [h], a few pixels
    // Dragging fog's 08:00 key: 08:28 lands on 08:30, 09:57 on the other track's 09:36 when within reach.
    EXPECT_DOUBLE_EQ(snapKeyTime(p, fog.target, 0, 8.0 + 28.0 / 60.0, near), 8.5);
    EXPECT_DOUBLE_EQ(snapKeyTime(p, fog.target, 0, 9.62, near), 9.6);
    EXPECT_DOUBLE_EQ(snapKeyTime(p, fog.target, 0, 11.97, near), 12.0);  // its own track's other key
    EXPECT_DOUBLE_EQ(snapKeyTime(p, fog.target, 0, 8.02, near), 8.0);    // itself excluded: the grid
    EXPECT_DOUBLE_EQ(snapKeyTime(p, fog.target, 0, 23.9, near), 0.0);    // the quarter hour wraps
    // The Snap step: 5 min and the hour.
    EXPECT_NEAR(snapKeyTime(p, fog.target, 0, 8.0 + 28.0 / 60.0, near, 5.0 / 60.0), 8.0 + 30.0 / 60.0, 1e-12);
    EXPECT_NEAR(snapKeyTime(p, fog.target, 0, 8.0 + 22.0 / 60.0, near, 5.0 / 60.0), 8.0 + 20.0 / 60.0, 1e-12);
    EXPECT_DOUBLE_EQ(snapKeyTime(p, fog.target, 0, 8.0 + 28.0 / 60.0, near, 1.0), 8.0);
    // A key that follows the sun snaps its offset from the event: sunset at 19:07 + 0:14 lands
    // on sunset + 0:15, not on 19:15.
    TrackKey& anchored = p.tracks[0].keys[1];
    anchored.anchor = SunEvent::Sunset;
    anchored.timeHours = 19.0 + 7.0 / 60.0 + 0.5;  // sunset + 0:30
    anchored.offsetHours = 0.5;
    EXPECT_NEAR(snapKeyTime(p, fog.target, 1, 19.0 + 21.0 / 60.0, near), 19.0 + 22.0 / 60.0, 1e-12);
    EXPECT_NEAR(snapKeyTime(p, fog.target, 1, 19.0 + 21.0 / 60.0, near, 1.0 / 60.0), 19.0 + 21.0 / 60.0,
                1e-12);
}

TEST(PresetEdit, MeshPathsFollowThePreset) {
    EXPECT_EQ(meshPathFor("/data/meshes/room.gltf", "/data/presets/a.json"), "../meshes/room.gltf");
    EXPECT_EQ(meshPathFor("/data/presets/room.gltf", "/data/presets/a.json"), "room.gltf");
    EXPECT_EQ(meshPathFor("/data/meshes/room.gltf", ""), "/data/meshes/room.gltf");  // untitled: absolute
    Preset p;
    FogVolume v;
    v.id = "room";
    v.shape = FogVolumeShape::Mesh;
    v.mesh = "../meshes/room.gltf";
    p.volumes.push_back(v);
    FogVolume box;
    box.id = "box";
    p.volumes.push_back(box);
    // Save As from /data/presets into /data/presets/dusk: one more level up.
    EXPECT_EQ(rebaseMeshPaths(p, "/data/presets", "/data/presets/dusk"), 1);
    EXPECT_EQ(p.volumes[0].mesh, "../../meshes/room.gltf");
    EXPECT_EQ(p.volumes[1].mesh, "");
    // To absolute (a recovery file) and back.
    EXPECT_EQ(rebaseMeshPaths(p, "/data/presets/dusk", ""), 1);
    EXPECT_EQ(p.volumes[0].mesh, "/data/meshes/room.gltf");
    EXPECT_EQ(rebaseMeshPaths(p, "", "/data"), 1);
    EXPECT_EQ(p.volumes[0].mesh, "meshes/room.gltf");
    EXPECT_EQ(rebaseMeshPaths(p, "/data", "/data"), 0);
}

TEST(PresetEdit, AddMeshVolumeRestsOnTheGround) {
    std::string error;
    // A cube [-1, 1]^3 (8 vertices, 12 triangles).
    std::vector<glm::dvec3> positions;
    for (int i = 0; i < 8; ++i) positions.push_back({(i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 1.0 : -1.0});
    const std::vector<std::uint32_t> indices = {1, 3, 7, 1, 7, 5, 0, 4, 6, 0, 6, 2, 2, 6, 7, 2, 7, 3,
                                                0, 1, 5, 0, 5, 4, 4, 5, 7, 4, 7, 6, 0, 2, 3, 0, 3, 1};
    const auto mesh = FogMesh::build(positions, indices, error);
    ASSERT_TRUE(mesh) << error;
    Preset p = defaultPreset();
    const int i = addMeshVolume(p, "meshes/room.gltf", mesh, {5, 2, -7}, "room");
    const FogVolume& v = p.volumes[std::size_t(i)];
    EXPECT_EQ(v.shape, FogVolumeShape::Mesh);
    EXPECT_EQ(v.name, "room");
    EXPECT_EQ(v.id, "mesh_volume");
    EXPECT_EQ(v.position, glm::dvec3(5, 3, -7));  // bottom at y = 2
    EXPECT_TRUE(validatePreset(p).empty());
}

}  // namespace
}  // namespace aerial::editor
