// Small things the editor's study met (issue 50, point 4), in the model the
// panels draw: the timeline's one key selection (the track row and the curve
// view pick the same keys; Delete deletes the one picked last, as one undo
// step), clamp messages that name every clamped value, and the export's
// summary naming its folder.
#include "document.hpp"
#include "editor_parts.hpp"
#include "game_export.hpp"
#include "panels.hpp"

#include <gtest/gtest.h>

#include <string>

namespace aerial::editor {
namespace {

ParamRef global(const char* path) { return {findParam(ParamScope::Global, path), -1}; }

/// A preset whose fog density and base height each have keys at 06:00 and 12:00.
void twoTracks(Document& doc) {
    doc.reset(Preset{}, "");
    for (const char* path : {"fog.density_per_m", "fog.base_height_m"})
        doc.apply("Add keys", "", [&](Preset& p) {
            EXPECT_TRUE(keyParam(p, global(path), 6.0));
            EXPECT_TRUE(keyParam(p, global(path), 12.0));
        });
}

TEST(TimelineEdits, DeleteDeletesTheTrackKeyPickedAfterACurveSelection) {
    Document doc;
    twoTracks(doc);
    EditState edit;
    const ParamRef density = global("fog.density_per_m"), height = global("fog.base_height_m");
    // The curve view has the density's 06:00 key selected...
    edit.curves.selected = {{trackTargetOf(doc.preset(), density), 0, 0}};
    // ... then the artist picks the base height's 12:00 key on the track row.
    edit.selectedParam = height;
    edit.selectTrackKey(doc.preset(), 1);
    ASSERT_EQ(edit.curves.selected.size(), 1u);
    EXPECT_EQ(edit.curves.selected.front().target, trackTargetOf(doc.preset(), height));

    const std::size_t undoBefore = doc.undoCount();
    ASSERT_TRUE(deleteTimelineKeys(doc, edit));
    EXPECT_EQ(doc.undoCount(), undoBefore + 1);
    EXPECT_EQ(trackOf(doc.preset(), density)->keys.size(), 2u) << "the density's key was deleted";
    ASSERT_EQ(trackOf(doc.preset(), height)->keys.size(), 1u);
    EXPECT_EQ(trackOf(doc.preset(), height)->keys.front().timeHours, 6.0);
    EXPECT_EQ(edit.selectedKey, -1);
    EXPECT_TRUE(edit.curves.selected.empty());
}

TEST(TimelineEdits, TheTrackRowFollowsTheCurveSelection) {
    Document doc;
    twoTracks(doc);
    EditState edit;
    const ParamRef density = global("fog.density_per_m"), height = global("fog.base_height_m");
    edit.selectedParam = height;
    edit.selectedKey = 0;
    // A curve selection of the density's key only: no key of the track row is selected.
    edit.curves.selected = {{trackTargetOf(doc.preset(), density), 1, 0}};
    edit.followCurveSelection(doc.preset());
    EXPECT_EQ(edit.selectedKey, -1);
    // With the base height's 12:00 key among them, the track row shows that key.
    edit.curves.selected.push_back({trackTargetOf(doc.preset(), height), 1, 0});
    edit.followCurveSelection(doc.preset());
    EXPECT_EQ(edit.selectedKey, 1);
    // Picking nothing on the track row clears both.
    edit.selectTrackKey(doc.preset(), -1);
    EXPECT_EQ(edit.selectedKey, -1);
    EXPECT_TRUE(edit.curves.selected.empty());
}

TEST(TimelineEdits, AClampMessageNamesEveryClampedValue) {
    Document doc;
    doc.reset(Preset{}, "");
    EditState edit;
    const double albedo[4] = {1.5, 0.5, -0.25, 0.0};  // Ground albedo: valid 0..1
    const std::string message =
        editParam(doc, edit, global("atmosphere.ground_albedo_rgb"), albedo, false, 9.0);
    EXPECT_NE(message.find("2 values clamped"), std::string::npos) << message;
    EXPECT_NE(message.find("r 1.5 to 1"), std::string::npos) << message;
    EXPECT_NE(message.find("b -0.25 to 0"), std::string::npos) << message;
    EXPECT_EQ(message.find("g "), std::string::npos) << "g was in range: " << message;
    EXPECT_EQ(doc.preset().environment.atmosphere.groundAlbedo, glm::dvec3(1.0, 0.5, 0.0));

    const double falloff[4] = {-3.0, 0.0, 0.0, 0.0};
    EXPECT_EQ(editParam(doc, edit, global("fog.falloff_per_m"), falloff, false, 9.0),
              "Fog height falloff clamped to 0 (valid 0..10 1/m)");
    const double fine[4] = {0.5, 0.5, 0.5, 0.0};
    EXPECT_EQ(editParam(doc, edit, global("atmosphere.ground_albedo_rgb"), fine, false, 9.0), "");
}

TEST(TimelineEdits, TheExportSummaryNamesItsFolder) {
    const std::string line =
        "baked 48 steps (96 EXR tables, 128x64), layout.gltf and manifest.json into . in 2.10 s";
    const std::string shown = exportSummaryLine(line, "/home/artist/export");
    EXPECT_EQ(shown.find("into ."), std::string::npos) << shown;
    EXPECT_NE(shown.find(" into /home/artist/export in 2.10 s"), std::string::npos) << shown;
    EXPECT_EQ(exportSummaryLine("aerial bake: error: no preset", "out"), "aerial bake: error: no preset");
}

}  // namespace
}  // namespace aerial::editor
