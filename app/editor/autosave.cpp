// editor/autosave.cpp — see autosave.hpp.
#include "autosave.hpp"
#include "preset_edit.hpp"
#include "user_dirs.hpp"

#include <nlohmann/json.hpp>

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

namespace aerial::editor {
namespace fs = std::filesystem;

std::string stateDirectory() {
    return userDirectory({"AERIAL_STATE_DIR", "XDG_STATE_HOME", ".local/state", "/tmp/aerial-state"});
}

namespace {

bool processAlive(int pid) {
    if (pid <= 0) return false;
    if (::kill(pid, 0) == 0) return true;
    return errno == EPERM;  // exists, but not ours
}

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

}  // namespace

Autosave::Autosave(std::string directory, double intervalSeconds)
    : directory_(std::move(directory)), interval_(intervalSeconds > 0.0 ? intervalSeconds : 30.0) {
    const std::string pid = std::to_string(::getpid());
    recoveryFile_ = (fs::path(directory_) / ("recovery-" + pid + ".json")).string();
    markerFile_ = (fs::path(directory_) / ("session-" + pid + ".json")).string();
}

std::optional<RecoveryCandidate> Autosave::findRecovery() const {
    std::error_code ec;
    std::optional<RecoveryCandidate> best;
    long long bestTime = -1;
    for (const fs::directory_entry& entry : fs::directory_iterator(directory_, ec)) {
        const std::string name = entry.path().filename().string();
        if (name.rfind("session-", 0) != 0 || entry.path().extension() != ".json") continue;
        const std::string pidText = name.substr(8, name.size() - 8 - 5);
        char* end = nullptr;
        const long pid = std::strtol(pidText.c_str(), &end, 10);
        if (pidText.empty() || *end != '\0' || pid <= 0) continue;
        if (pid == ::getpid() || processAlive(int(pid))) continue;
        RecoveryCandidate candidate;
        candidate.pid = int(pid);
        candidate.markerFile = entry.path().string();
        candidate.recoveryFile = (fs::path(directory_) / ("recovery-" + pidText + ".json")).string();
        long long started = 0;
        const nlohmann::json marker = nlohmann::json::parse(readFile(entry.path()), nullptr, false);
        if (marker.is_object()) {
            if (marker.contains("document") && marker["document"].is_string())
                candidate.documentPath = marker["document"].get<std::string>();
            if (marker.contains("started") && marker["started"].is_number_integer())
                started = marker["started"].get<long long>();
        }
        if (!fs::exists(candidate.recoveryFile, ec)) {
            discard(candidate);  // crashed with nothing unsaved
            continue;
        }
        PresetLoadResult loaded = loadPreset(candidate.recoveryFile);
        if (!loaded.ok()) {
            discard(candidate);
            continue;
        }
        candidate.preset = std::move(*loaded.preset);
        if (started >= bestTime) {
            bestTime = started;
            best = std::move(candidate);
        }
    }
    return best;
}

void Autosave::discard(const RecoveryCandidate& candidate) {
    std::error_code ec;
    fs::remove(candidate.recoveryFile, ec);
    fs::remove(candidate.markerFile, ec);
}

bool Autosave::writeMarker(const std::string& documentPath) {
    nlohmann::json marker = {{"pid", ::getpid()},
                             {"document", documentPath},
                             {"started", static_cast<long long>(std::time(nullptr))}};
    const std::string temp = markerFile_ + ".tmp";
    {
        std::ofstream out(temp, std::ios::binary | std::ios::trunc);
        out << marker.dump() << "\n";
        out.flush();
        if (!out) return false;
    }
    std::error_code ec;
    fs::rename(temp, markerFile_, ec);
    if (ec) return false;
    markedDocument_ = documentPath;
    return true;
}

bool Autosave::start(const std::string& documentPath, std::string* error) {
    std::error_code ec;
    fs::create_directories(directory_, ec);
    if (!writeMarker(documentPath)) {
        lastError_ = "cannot write the session marker " + markerFile_;
        if (error) *error = lastError_;
        return false;
    }
    started_ = true;
    return true;
}

bool Autosave::update(double nowSeconds, bool dirty, std::uint64_t revision, const Preset& preset,
                      const std::string& documentPath) {
    if (!started_) return false;
    if (documentPath != markedDocument_) writeMarker(documentPath);
    if (!dirty) {
        pending_ = false;
        if (haveRecoveryFile_) {
            std::error_code ec;
            fs::remove(recoveryFile_, ec);
            haveRecoveryFile_ = false;
        }
        writtenRevision_ = 0;
        seenRevision_ = revision;
        return false;
    }
    if (revision != writtenRevision_ && !pending_) {
        pending_ = true;
        pendingSince_ = nowSeconds;
    }
    seenRevision_ = revision;
    if (!pending_ || nowSeconds - pendingSince_ < interval_) return false;
    pending_ = false;
    // Mesh paths absolute: the recovery file lives elsewhere than the preset.
    Preset aside = preset;
    rebaseMeshPaths(aside, documentPath.empty() ? std::string() : fs::path(documentPath).parent_path().string(), "");
    const SaveResult saved = savePreset(aside, recoveryFile_);
    if (!saved.ok()) {
        lastError_ = saved.errors.empty() ? std::string("cannot write the recovery file")
                                          : saved.errors.front().toString();
        return false;
    }
    lastError_.clear();
    haveRecoveryFile_ = true;
    writtenRevision_ = revision;
    ++writes_;
    return true;
}

void Autosave::finish() {
    if (!started_) return;
    std::error_code ec;
    fs::remove(recoveryFile_, ec);
    fs::remove(markerFile_, ec);
    started_ = false;
}

}  // namespace aerial::editor
