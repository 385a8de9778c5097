// Document: undo/redo by snapshots, merge keys, the dirty flag, titles, and
// every kind of edit (parameters, keys, add/delete/rename/duplicate) round
// tripping through undo and redo.
#include "document.hpp"
#include "editor_test_support.hpp"
#include "preset_edit.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>

namespace aerial::editor {
namespace {

namespace fs = std::filesystem;

void setFog(Document& doc, double density, const std::string& merge = "") {
    doc.apply("Fog density", merge, [&](Preset& p) { p.environment.fog.density = density; });
}

TEST(Document, StartsCleanOnTheDefaultPreset) {
    Document doc;
    EXPECT_FALSE(doc.dirty());
    EXPECT_TRUE(presetsIdentical(doc.preset(), defaultPreset()));
    EXPECT_EQ(doc.title(), "Untitled - Aerial");
    EXPECT_FALSE(doc.canUndo());
    EXPECT_FALSE(doc.canRedo());
}

TEST(Document, ApplyMarksDirtyAndUndoRestoresBitForBit) {
    Document doc;
    const Preset before = doc.preset();
    setFog(doc, 0.0123);
    EXPECT_TRUE(doc.dirty());
    EXPECT_EQ(doc.title(), "Untitled* - Aerial");
    EXPECT_EQ(doc.preset().environment.fog.density, 0.0123);
    ASSERT_TRUE(doc.undo());
    EXPECT_TRUE(presetsIdentical(doc.preset(), before));
    EXPECT_FALSE(doc.dirty()) << "undoing back to the saved state is clean";
    ASSERT_TRUE(doc.redo());
    EXPECT_EQ(doc.preset().environment.fog.density, 0.0123);
    EXPECT_TRUE(doc.dirty());
}

TEST(Document, NoChangeRecordsNothing) {
    Document doc;
    EXPECT_FALSE(doc.apply("nothing", "", [](Preset&) {}));
    EXPECT_FALSE(doc.canUndo());
    EXPECT_FALSE(doc.dirty());
}

TEST(Document, MergeKeyMakesOneStepPerDrag) {
    Document doc;
    const double original = doc.preset().environment.fog.density;
    for (int i = 1; i <= 20; ++i) setFog(doc, 0.001 * i, "param:fog.density_per_m");
    EXPECT_EQ(doc.undoCount(), 1u);
    doc.closeMerge();
    for (int i = 1; i <= 5; ++i) setFog(doc, 0.1 * i, "param:fog.density_per_m");
    EXPECT_EQ(doc.undoCount(), 2u) << "a second drag of the same slider is a second step";
    setFog(doc, 0.7, "param:other");
    EXPECT_EQ(doc.undoCount(), 3u) << "another key starts a new step";
    doc.undo();
    EXPECT_EQ(doc.preset().environment.fog.density, 0.5);
    doc.undo();
    EXPECT_EQ(doc.preset().environment.fog.density, 0.02);
    doc.undo();
    EXPECT_EQ(doc.preset().environment.fog.density, original);
    EXPECT_FALSE(doc.dirty());
}

TEST(Document, EmptyMergeKeyNeverMerges) {
    Document doc;
    setFog(doc, 0.1);
    setFog(doc, 0.2);
    EXPECT_EQ(doc.undoCount(), 2u);
}

TEST(Document, NewChangeClearsRedo) {
    Document doc;
    setFog(doc, 0.1);
    doc.undo();
    EXPECT_TRUE(doc.canRedo());
    setFog(doc, 0.3);
    EXPECT_FALSE(doc.canRedo());
}

TEST(Document, HistoryIsCapped) {
    Document doc;
    for (std::size_t i = 0; i < kMaxUndoSteps + 20; ++i) setFog(doc, 1e-4 * double(i + 1));
    EXPECT_EQ(doc.undoCount(), kMaxUndoSteps);
}

TEST(Document, SaveOpenAndDirtyFlag) {
    const fs::path dir = test::tempDir("editor", "save");
    const std::string file = (dir / "mine.json").string();
    Document doc;
    setFog(doc, 0.004);
    ASSERT_TRUE(doc.save(file).ok());
    EXPECT_FALSE(doc.dirty());
    EXPECT_EQ(doc.title(), "mine.json - Aerial");
    EXPECT_EQ(doc.path(), file);
    doc.undo();  // back before the save: differs from the file
    EXPECT_TRUE(doc.dirty());
    doc.redo();
    EXPECT_FALSE(doc.dirty());

    Document other;
    ASSERT_TRUE(other.open(file).ok());
    EXPECT_TRUE(presetsIdentical(other.preset(), doc.preset()));
    EXPECT_FALSE(other.dirty());
    EXPECT_FALSE(other.canUndo());
    fs::remove_all(dir);
}

TEST(Document, FailedOpenChangesNothing) {
    const fs::path dir = test::tempDir("editor", "badopen");
    const std::string bad = (dir / "bad.json").string();
    {
        std::FILE* f = std::fopen(bad.c_str(), "w");
        std::fputs("{\"version\": 1, \"fog\": {\"density_per_m\": -1}}", f);
        std::fclose(f);
    }
    Document doc;
    setFog(doc, 0.009);
    const std::uint64_t revision = doc.revision();
    const PresetLoadResult r = doc.open(bad);
    EXPECT_FALSE(r.ok());
    ASSERT_FALSE(r.errors.empty());
    EXPECT_NE(r.errors.front().toString().find("bad.json"), std::string::npos);
    EXPECT_EQ(doc.revision(), revision);
    EXPECT_EQ(doc.preset().environment.fog.density, 0.009);
    EXPECT_TRUE(doc.dirty());
    EXPECT_TRUE(doc.canUndo());
    EXPECT_FALSE(doc.open((dir / "missing.json").string()).ok());
    fs::remove_all(dir);
}

TEST(Document, FailedSaveKeepsDirty) {
    Document doc;
    setFog(doc, 0.01);
    EXPECT_FALSE(doc.save("/nonexistent-dir/x/y.json").ok());
    EXPECT_TRUE(doc.dirty());
    EXPECT_TRUE(doc.path().empty());
}

TEST(Document, MarkDirty) {
    Document doc;
    doc.markDirty();
    EXPECT_TRUE(doc.dirty());
}

// Every kind of edit round-trips through undo and redo.
struct EditCase {
    const char* name;
    std::function<void(Preset&)> edit;
};

TEST(Document, EveryKindOfEditRoundTrips) {
    const std::vector<EditCase> edits = {
        {"global param", [](Preset& p) { p.environment.atmosphere.mieAnisotropy = 0.5; }},
        {"key", [](Preset& p) { keyParam(p, *parseParamAddress(p, "fog.falloff_per_m", nullptr), 7.0); }},
        {"remove key", [](Preset& p) { removeKey(p, TrackTarget::global("fog.density_per_m"), 1); }},
        {"move key",
         [](Preset& p) { moveKey(*findTrack(p, TrackTarget::global("fog.density_per_m")), 1, 7.5); }},
        {"interpolation",
         [](Preset& p) {
             findTrack(p, TrackTarget::global("fog.density_per_m"))->interpolation = Interpolation::Step;
         }},
        {"add volume",
         [](Preset& p) {
             addVolume(p, FogVolumeShape::Ellipsoid, {1, 2, 3});
         }},
        {"add emitter",
         [](Preset& p) {
             addEmitter(p, EmitterKind::Point, {1, 2, 3});
         }},
        {"delete volume", [](Preset& p) { deleteObject(p, ParamScope::Volume, 0); }},
        {"duplicate emitter",
         [](Preset& p) {
             duplicateObject(p, ParamScope::Emitter, 0, {1, 0, 0});
         }},
        {"rename", [](Preset& p) { renameObject(p, ParamScope::Volume, 0, "Renamed"); }},
        {"gizmo move", [](Preset& p) { p.volumes[0].position += glm::dvec3(3, 0, 0); }},
        {"gizmo rotate",
         [](Preset& p) { p.volumes[0].rotation = glm::dquat(0.7071067811865476, 0, 0.7071067811865476, 0); }},
        {"gizmo scale", [](Preset& p) { p.volumes[0].halfExtents *= 2.0; }},
        {"preset name", [](Preset& p) { p.name = "Other"; }},
        {"add cloud volume",
         [](Preset& p) {
             addCloudVolume(p, FogVolumeShape::Ellipsoid,
                            newCloudVolumeAt(p.environment.clouds, {10, 0, -20}));
         }},
    };
    for (const EditCase& e : edits) {
        SCOPED_TRACE(e.name);
        Document doc;
        const Preset before = doc.preset();
        ASSERT_TRUE(doc.apply(e.name, "", e.edit));
        const Preset after = doc.preset();
        EXPECT_FALSE(presetsIdentical(before, after) && before.name == after.name);
        ASSERT_TRUE(doc.undo());
        EXPECT_TRUE(presetsIdentical(doc.preset(), before));
        EXPECT_EQ(doc.preset().name, before.name);
        EXPECT_FALSE(doc.dirty());
        ASSERT_TRUE(doc.redo());
        EXPECT_TRUE(presetsIdentical(doc.preset(), after));
        EXPECT_TRUE(doc.dirty());
        EXPECT_EQ(doc.undoLabel(), e.name);
    }
}

// A cloud volume added, moved by the gizmo, duplicated and deleted: each
// step undoes and redoes to the same preset, bit for bit (presetsIdentical
// compares every parameter's bits).
TEST(Document, CloudVolumeEditsUndoBitForBit) {
    Document doc;
    std::vector<Preset> states{doc.preset()};
    const auto step = [&](const char* label, const std::function<void(Preset&)>& edit) {
        ASSERT_TRUE(doc.apply(label, "", edit));
        states.push_back(doc.preset());
    };
    step("Add cloud box", [](Preset& p) {
        addCloudVolume(p, FogVolumeShape::Box, newCloudVolumeAt(p.environment.clouds, {0.1, 5, 0.3}));
    });
    step("Move", [](Preset& p) {
        const double position[4] = {1234.5678, 2100.25, -987.125, 0};
        setValueAt(p, *parseParamAddress(p, "cloud_volume[0].position_m", nullptr), position, 9.0);
    });
    step("Key coverage",
         [](Preset& p) { keyParam(p, *parseParamAddress(p, "cloud_volume[0].coverage", nullptr), 9.0); });
    step("Duplicate", [](Preset& p) { duplicateObject(p, ParamScope::CloudVolume, 0, {1000, 0, 0}); });
    step("Delete", [](Preset& p) { deleteObject(p, ParamScope::CloudVolume, 0); });
    ASSERT_EQ(doc.preset().cloudVolumes.size(), 1u);
    EXPECT_EQ(doc.preset().cloudVolumes[0].id, "cloud_box_2");
    for (std::size_t i = states.size() - 1; i > 0; --i) {
        ASSERT_TRUE(doc.undo());
        EXPECT_TRUE(presetsIdentical(doc.preset(), states[i - 1])) << "undo to state " << i - 1;
    }
    EXPECT_FALSE(doc.dirty());
    for (std::size_t i = 1; i < states.size(); ++i) {
        ASSERT_TRUE(doc.redo());
        EXPECT_TRUE(presetsIdentical(doc.preset(), states[i])) << "redo to state " << i;
    }
}

TEST(Document, UniqueObjectIds) {
    Preset p = defaultPreset();
    EXPECT_EQ(uniqueObjectId(p, true, "fresh"), "fresh");
    EXPECT_EQ(uniqueObjectId(p, true, "ground_fog"), "ground_fog_2");
    EXPECT_EQ(uniqueObjectId(p, false, "lamp"), "lamp_2");
    EXPECT_EQ(uniqueObjectId(p, false, "ground_fog"), "ground_fog");
}

}  // namespace
}  // namespace aerial::editor
