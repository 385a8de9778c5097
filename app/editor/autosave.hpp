// editor/autosave.hpp — crash safety: a recovery file written after a while
// of unsaved work, and a running-session marker so that the next start after
// a crash (kill -9, power loss) offers to recover it. No GUI.
//
// Files, in stateDirectory() (created when missing):
//   session-<pid>.json   the marker: {"pid": N, "document": "path or empty",
//                        "started": unix seconds}; written at start, updated
//                        when the document's path changes
//   recovery-<pid>.json  the preset (core's savePreset: validated, written
//                        aside, fsync'ed, renamed) after `intervalSeconds` of
//                        unsaved work
// A clean exit removes both. A marker whose process is gone (kill(pid, 0)
// fails with ESRCH) is a crashed session; if its recovery file loads it is
// offered; recovering or declining removes the crashed session's files.
//
// Usage:
//   Autosave autosave(stateDirectory(), 30.0);
//   std::optional<RecoveryCandidate> c = autosave.findRecovery();  // before start()
//   autosave.start(doc.path());
//   every frame: autosave.update(secondsNow, doc.dirty(), doc.revision(), doc.preset(), doc.path());
//   on clean exit: autosave.finish();
#pragma once

#include <aerial/preset.hpp>

#include <cstdint>
#include <optional>
#include <string>

namespace aerial::editor {

/// $AERIAL_STATE_DIR if set, else $XDG_STATE_HOME/aerial, else
/// $HOME/.local/state/aerial (else /tmp/aerial-state).
std::string stateDirectory();

/// A crashed session's work.
struct RecoveryCandidate {
    int pid = 0;
    std::string recoveryFile;
    std::string markerFile;
    /// The file the crashed session was editing ("" when untitled).
    std::string documentPath;
    Preset preset;
};

class Autosave {
public:
    Autosave(std::string directory, double intervalSeconds);
    ~Autosave() = default;
    Autosave(const Autosave&) = delete;
    Autosave& operator=(const Autosave&) = delete;

    const std::string& directory() const { return directory_; }
    double intervalSeconds() const { return interval_; }
    const std::string& recoveryFile() const { return recoveryFile_; }
    const std::string& markerFile() const { return markerFile_; }

    /// The newest crashed session with a loadable recovery file (markers of
    /// crashed sessions without one are removed).
    std::optional<RecoveryCandidate> findRecovery() const;
    /// Removes a crashed session's marker and recovery file.
    static void discard(const RecoveryCandidate& candidate);

    /// Writes this session's marker. False (with `error`) when the directory
    /// cannot be written; autosave then stays off.
    bool start(const std::string& documentPath, std::string* error = nullptr);

    /// Call every frame with a monotonic clock [s]. The timer starts when the
    /// document first has unsaved work (or changes after an autosave) and
    /// fires `intervalSeconds` later; returns true when it wrote the
    /// recovery file this call. A clean document removes the recovery file.
    bool update(double nowSeconds, bool dirty, std::uint64_t revision, const Preset& preset,
                const std::string& documentPath);

    /// How many recovery files this session wrote.
    int writes() const { return writes_; }
    /// Last write error ("" when fine).
    const std::string& lastError() const { return lastError_; }

    /// Clean exit: removes the marker and the recovery file.
    void finish();

private:
    bool writeMarker(const std::string& documentPath);

    std::string directory_;
    double interval_;
    std::string recoveryFile_;
    std::string markerFile_;
    std::string markedDocument_;
    bool started_ = false;
    bool pending_ = false;  // unsaved work not yet in the recovery file
    double pendingSince_ = 0.0;
    std::uint64_t writtenRevision_ = 0;
    std::uint64_t seenRevision_ = 0;
    bool haveRecoveryFile_ = false;
    int writes_ = 0;
    std::string lastError_;
};

}  // namespace aerial::editor
