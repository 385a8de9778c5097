// Autosave and crash recovery: the timer, the files, recovery of a crashed
// session (a marker whose process is gone), a clean exit.
#include "autosave.hpp"
#include "preset_edit.hpp"
#include "editor_test_support.hpp"
#include "script.hpp"
#include "settings.hpp"

#include <aerial/fog_mesh.hpp>

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace aerial::editor {
namespace {

namespace fs = std::filesystem;
using test::join;

/// A pid that certainly belongs to no process: a child that has exited and been reaped.
int deadPid() {
    const pid_t child = ::fork();
    if (child == 0) ::_exit(0);
    int status = 0;
    ::waitpid(child, &status, 0);
    return int(child);
}

TEST(Autosave, StateDirectoryFromEnvironment) {
    ::setenv("AERIAL_STATE_DIR", "/tmp/aerial-x", 1);
    EXPECT_EQ(stateDirectory(), "/tmp/aerial-x");
    ::unsetenv("AERIAL_STATE_DIR");
    ::setenv("XDG_STATE_HOME", "/tmp/xdg", 1);
    EXPECT_EQ(stateDirectory(), "/tmp/xdg/aerial");
    ::unsetenv("XDG_STATE_HOME");
    ::setenv("HOME", "/home/someone", 1);
    EXPECT_EQ(stateDirectory(), "/home/someone/.local/state/aerial");
}

TEST(Autosave, WritesAfterTheIntervalOfUnsavedWork) {
    const fs::path dir = test::tempDir("autosave", "timer");
    Autosave a(dir.string(), 30.0);
    ASSERT_TRUE(a.start(""));
    EXPECT_TRUE(fs::exists(a.markerFile()));
    Preset p = defaultPreset();
    EXPECT_FALSE(a.update(0.0, false, 1, p, ""));   // clean: nothing
    EXPECT_FALSE(a.update(100.0, true, 2, p, ""));  // dirty from t = 100
    EXPECT_FALSE(a.update(129.0, true, 3, p, ""));
    EXPECT_FALSE(fs::exists(a.recoveryFile()));
    EXPECT_TRUE(a.update(130.5, true, 3, p, ""));
    EXPECT_TRUE(fs::exists(a.recoveryFile()));
    EXPECT_EQ(a.writes(), 1);
    EXPECT_FALSE(a.update(200.0, true, 3, p, "")) << "nothing new since the autosave";
    EXPECT_FALSE(a.update(201.0, true, 4, p, ""));  // new work: the timer restarts
    EXPECT_FALSE(a.update(230.0, true, 4, p, ""));
    EXPECT_TRUE(a.update(231.5, true, 4, p, ""));
    EXPECT_EQ(a.writes(), 2);
    EXPECT_FALSE(a.update(232.0, false, 5, p, "")) << "saved: the recovery file goes";
    EXPECT_FALSE(fs::exists(a.recoveryFile()));
    a.finish();
    EXPECT_FALSE(fs::exists(a.markerFile()));
    fs::remove_all(dir);
}

TEST(Autosave, CleanExitLeavesNothingToRecover) {
    const fs::path dir = test::tempDir("autosave", "clean");
    {
        Autosave a(dir.string(), 1.0);
        ASSERT_TRUE(a.start("/some/file.json"));
        a.update(0.0, true, 2, defaultPreset(), "/some/file.json");
        a.update(2.0, true, 2, defaultPreset(), "/some/file.json");
        EXPECT_TRUE(fs::exists(a.recoveryFile()));
        a.finish();
    }
    EXPECT_TRUE(fs::is_empty(dir));
    Autosave next(dir.string(), 1.0);
    EXPECT_FALSE(next.findRecovery());
    fs::remove_all(dir);
}

TEST(Autosave, RecoversACrashedSession) {
    const fs::path dir = test::tempDir("autosave", "crash");
    const int pid = deadPid();
    Preset work = defaultPreset();
    work.environment.fog.density = 0.0321;
    work.volumes[0].position = {1.5, 2.5, -3.5};
    ASSERT_TRUE(savePreset(work, (dir / join("recovery-", std::to_string(pid), ".json")).string()).ok());
    {
        std::ofstream marker(dir / join("session-", std::to_string(pid), ".json"));
        marker << "{\"pid\": " << pid << ", \"document\": \"/work/mine.json\", \"started\": 5}\n";
    }
    // A live session (this process) is never offered.
    Autosave self(dir.string(), 1.0);
    ASSERT_TRUE(self.start(""));
    std::optional<RecoveryCandidate> c = self.findRecovery();
    ASSERT_TRUE(c);
    EXPECT_EQ(c->pid, pid);
    EXPECT_EQ(c->documentPath, "/work/mine.json");
    EXPECT_TRUE(presetsIdentical(c->preset, work));
    Autosave::discard(*c);
    EXPECT_FALSE(self.findRecovery());
    self.finish();
    EXPECT_TRUE(fs::is_empty(dir));
    fs::remove_all(dir);
}

TEST(Autosave, MeshVolumesSurviveTheRecoveryFile) {
    // A preset beside its mesh (a relative path) autosaved into the state
    // folder: the recovery file names the mesh absolutely, so it loads.
    const fs::path dir = test::tempDir("autosave", "mesh");
    const fs::path project = dir / "project";
    fs::create_directories(project / "meshes");
    fs::copy_file(fs::path(AERIAL_SOURCE_DIR) / "tests/data/bad_inputs/meshes/cube.gltf",
                  project / "meshes" / "room.gltf");
    Preset work = defaultPreset();
    FogVolume room;
    room.id = "room";
    room.shape = FogVolumeShape::Mesh;
    room.blend = FogVolumeBlend::Subtract;
    room.mesh = "meshes/room.gltf";
    work.volumes.push_back(room);
    const fs::path state = dir / "state";
    Autosave autosave(state.string(), 1.0);
    ASSERT_TRUE(autosave.start((project / "scene.json").string()));
    EXPECT_FALSE(autosave.update(0.0, true, 2, work, (project / "scene.json").string()));
    EXPECT_TRUE(autosave.update(1.5, true, 2, work, (project / "scene.json").string()));
    const PresetLoadResult recovered = loadPreset(autosave.recoveryFile());
    ASSERT_TRUE(recovered.ok()) << recovered.errors[0].toString();
    const FogVolume& v = recovered.preset->volumes.back();
    EXPECT_TRUE(fs::path(v.mesh).is_absolute()) << v.mesh;
    ASSERT_TRUE(v.meshData);
    EXPECT_EQ(v.meshData->triangleCount(), 12u);
    // Back in the document's folder the path is relative again.
    Preset back = *recovered.preset;
    EXPECT_EQ(rebaseMeshPaths(back, "", project.string()), 1);
    EXPECT_EQ(back.volumes.back().mesh, "meshes/room.gltf");
    autosave.finish();
    fs::remove_all(dir);
}

TEST(Autosave, CrashWithoutUnsavedWorkIsCleanedUp) {
    const fs::path dir = test::tempDir("autosave", "nowork");
    const int pid = deadPid();
    {
        std::ofstream marker(dir / join("session-", std::to_string(pid), ".json"));
        marker << "{\"pid\": " << pid << "}\n";
    }
    {
        std::ofstream junk(dir / join("session-", std::to_string(deadPid()), ".json"));
        junk << "not json";
    }
    Autosave a(dir.string(), 1.0);
    EXPECT_FALSE(a.findRecovery());
    EXPECT_TRUE(fs::is_empty(dir));
    fs::remove_all(dir);
}

TEST(Autosave, UnreadableRecoveryIsNotOffered) {
    const fs::path dir = test::tempDir("autosave", "broken");
    const int pid = deadPid();
    { std::ofstream(dir / join("recovery-", std::to_string(pid), ".json")) << "{ broken"; }
    { std::ofstream(dir / join("session-", std::to_string(pid), ".json")) << "{}"; }
    Autosave a(dir.string(), 1.0);
    EXPECT_FALSE(a.findRecovery());
    fs::remove_all(dir);
}

TEST(Settings, RecentFiles) {
    const fs::path dir = test::tempDir("autosave", "recent");
    RecentFiles r((dir / "recent.json").string());
    r.load();
    EXPECT_TRUE(r.files().empty());
    for (int i = 0; i < 14; ++i) r.add((dir / join("f", std::to_string(i), ".json")).string());
    r.add((dir / "f3.json").string());
    EXPECT_EQ(r.files().size(), RecentFiles::kMaxRecentFiles);
    EXPECT_EQ(r.files().front(), (dir / "f3.json").string());
    RecentFiles again((dir / "recent.json").string());
    again.load();
    EXPECT_EQ(again.files(), r.files());
    fs::remove_all(dir);
}

TEST(Settings, SessionRoundTrip) {
    const fs::path dir = test::tempDir("autosave", "session");
    Session s;
    s.cameraJson = "{\"distance_m\":42}";
    s.view = "ACES 1.0 - SDR Video";
    s.exposureEv = 1.5;
    s.resolutionScale = 0.75;
    s.timeHours = 18.25;
    ASSERT_TRUE(s.save((dir / "session.json").string()));
    Session t;
    t.load((dir / "session.json").string());
    EXPECT_EQ(t.view, s.view);
    EXPECT_EQ(t.exposureEv, 1.5);
    EXPECT_EQ(t.resolutionScale, 0.75);
    EXPECT_EQ(t.timeHours, 18.25);
    EXPECT_NE(t.cameraJson.find("42"), std::string::npos);
    fs::remove_all(dir);
}

TEST(Script, Parse) {
    const ScriptParseResult r =
        parseScript("# comment\nnew\n\n  set fog.density_per_m 0.01  # trailing\nrename \"My volume\"\n");
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(r.commands.size(), 3u);
    EXPECT_EQ(r.commands[0].line, 2);
    EXPECT_EQ(r.commands[1].line, 4);
    EXPECT_EQ(r.commands[1].words, (std::vector<std::string>{"set", "fog.density_per_m", "0.01"}));
    EXPECT_EQ(r.commands[2].words[1], "My volume");
    EXPECT_FALSE(parseScript("a \"b\n", "s.txt").ok());
    EXPECT_EQ(parseScript("a \"b\n", "s.txt").error, "s.txt:1: unterminated quote");
}

}  // namespace
}  // namespace aerial::editor
