// editor/game_export.hpp — File > Export for game: exactly what `aerial
// bake` does (it runs that command, the same code, in a child process),
// with its progress read back for a progress bar. The preset being edited is
// first saved into the export directory as preset.json, so the bake holds
// the preset it came from, with the mesh of every mesh volume written beside
// it as meshes/<id>.gltf (self-contained), so the export travels whole. No
// GUI.
//
// Usage:
//   GameExport job;
//   if (!job.start(doc.preset(), "/tmp/bake", 0.5, error)) show(error);
//   every frame: job.poll(); bar(job.progress());
//   if (job.done()) { job.succeeded() ? ok(job.summary()) : fail(job.summary()); }
#pragma once

#include <aerial/preset.hpp>

#include <string>

namespace aerial::editor {

/// The `aerial` CLI beside this executable (the build's app/ directory or
/// the install's bin/), else "aerial" from PATH.
std::string aerialCliPath();

/// What File > Export for game asks for (aerial bake's --step and --size).
struct ExportOptions {
    double stepHours = 0.5;   ///< 1/60..24
    int azimuthCount = 128;   ///< sky table columns
    int elevationCount = 64;  ///< sky table rows
};

/// Whether `directory` may receive an export: missing, empty, or an earlier
/// export (it holds an aerial-bake manifest.json). False with the reason
/// otherwise ("... holds other files and no earlier export: choose an empty
/// folder"), so an export never mixes its files into someone else's.
bool exportDirectoryUsable(const std::string& directory, std::string& error);

/// A line the bake printed, as the editor shows it: the bake runs inside
/// the export folder (--out .), so its "into ." names `directory` instead.
std::string exportSummaryLine(const std::string& line, const std::string& directory);

class GameExport {
public:
    GameExport() = default;
    ~GameExport();
    GameExport(const GameExport&) = delete;
    GameExport& operator=(const GameExport&) = delete;

    /// Checks the directory (exportDirectoryUsable), creates it, saves
    /// `preset` as directory/preset.json and starts `aerial bake preset.json
    /// --out . --step <step>h --size WxH` inside it (so the manifest's paths
    /// are relative to the export). False with `error` when any of that fails.
    bool start(const Preset& preset, const std::string& directory, const ExportOptions& options,
               std::string& error);
    /// Reads the child's output and reaps it when it has ended.
    void poll();
    /// Blocks until the child has ended (scripts, quitting).
    void wait();
    /// Stops a running bake (the directory then has no manifest.json).
    void cancel();

    bool running() const { return pid_ > 0; }
    /// True once after start() when the child has ended (until the next start).
    bool done() const { return done_; }
    bool succeeded() const { return done_ && exitCode_ == 0; }
    /// 0..1 from the "k/N" progress lines.
    double progress() const { return total_ > 0 ? double(steps_) / double(total_) : 0.0; }
    /// The last line the bake printed (its summary or error).
    const std::string& summary() const { return lastLine_; }
    const std::string& directory() const { return directory_; }
    void acknowledge() { done_ = false; }

private:
    void consume(const char* data, long size);
    int pid_ = -1;
    int fd_ = -1;
    bool done_ = false;
    int exitCode_ = -1;
    int steps_ = 0, total_ = 0;
    std::string buffer_, lastLine_, directory_;
};

}  // namespace aerial::editor
