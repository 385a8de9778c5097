// editor/game_export.cpp — see game_export.hpp.
#include "game_export.hpp"

#include <aerial/detail/file_system.hpp>
#include <aerial/fog_mesh.hpp>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <system_error>
#include <vector>

extern char** environ;

namespace aerial::editor {
namespace fs = std::filesystem;

std::string aerialCliPath() {
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        const fs::path beside = self.parent_path() / "aerial";
        if (fs::exists(beside, ec)) return beside.string();
    }
    return "aerial";
}

GameExport::~GameExport() { cancel(); }

std::string exportSummaryLine(const std::string& line, const std::string& directory) {
    const std::string here = " into . ";
    std::string out = line;
    if (const std::size_t at = out.find(here); at != std::string::npos)
        out.replace(at, here.size(), " into " + directory + " ");
    return out;
}

bool exportDirectoryUsable(const std::string& directory, std::string& error) {
    std::error_code ec;
    if (!fs::exists(directory, ec)) return true;
    if (!fs::is_directory(directory, ec)) {
        error = directory + " is a file, not a folder";
        return false;
    }
    if (fs::is_empty(directory, ec)) return true;
    std::ifstream in(fs::path(directory) / "manifest.json");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (text.find("\"aerial-bake\"") != std::string::npos) return true;
    error = directory +
            " holds other files and no earlier export: choose an empty folder (or one exported before)";
    return false;
}

bool GameExport::start(const Preset& preset, const std::string& directory, const ExportOptions& options,
                       std::string& error) {
    if (running()) {
        error = "an export is already running";
        return false;
    }
    if (!exportDirectoryUsable(directory, error)) return false;
    std::error_code ec;
    fs::create_directories(directory, ec);
    if (!fs::is_directory(directory, ec)) {
        error = "cannot create the directory " + directory;
        return false;
    }
    // The export travels with its meshes: each mesh volume's mesh written
    // beside preset.json as meshes/<id>.gltf (self-contained), which the
    // exported preset names.
    Preset exported = preset;
    for (FogVolume& v : exported.volumes) {
        if (v.shape != FogVolumeShape::Mesh || !v.meshData) continue;
        fs::create_directories(fs::path(directory) / "meshes", ec);
        const std::string relative = "meshes/" + v.id + ".gltf";
        const std::string failure = detail::writeFileAtomically((fs::path(directory) / relative).string(),
                                                                fogMeshToGltf(*v.meshData, v.id));
        if (!failure.empty()) {
            error = "cannot write " + relative + ": " + failure;
            return false;
        }
        v.mesh = relative;
    }
    const std::string presetFile = (fs::path(directory) / "preset.json").string();
    const SaveResult saved = savePreset(exported, presetFile);
    if (!saved.ok()) {
        error = saved.errors.empty() ? "cannot write " + presetFile : saved.errors.front().toString();
        return false;
    }
    int fds[2];
    if (::pipe(fds) != 0) {
        error = std::string("pipe: ") + std::strerror(errno);
        return false;
    }
    char step[32], size[32];
    std::snprintf(step, sizeof step, "%.9gh", std::clamp(options.stepHours, 1.0 / 60.0, 24.0));
    std::snprintf(size, sizeof size, "%dx%d", options.azimuthCount, options.elevationCount);
    const std::string cli = aerialCliPath();
    // Run inside the export: the manifest then names preset.json, not an absolute path.
    std::vector<std::string> args = {cli,      "bake", "preset.json", "--out", ".",
                                     "--step", step,   "--size",      size};
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[1], STDOUT_FILENO);
    posix_spawn_file_actions_adddup2(&actions, fds[1], STDERR_FILENO);
    posix_spawn_file_actions_addclose(&actions, fds[0]);
    posix_spawn_file_actions_addclose(&actions, fds[1]);
    const std::string absolute = fs::absolute(directory, ec).string();
    posix_spawn_file_actions_addchdir_np(&actions, absolute.c_str());
    pid_t pid = -1;
    const int rc = posix_spawnp(&pid, cli.c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    ::close(fds[1]);
    if (rc != 0) {
        ::close(fds[0]);
        error = "cannot run " + cli + ": " + std::strerror(rc);
        return false;
    }
    ::fcntl(fds[0], F_SETFL, ::fcntl(fds[0], F_GETFL) | O_NONBLOCK);
    pid_ = pid;
    fd_ = fds[0];
    done_ = false;
    exitCode_ = -1;
    steps_ = total_ = 0;
    buffer_.clear();
    lastLine_.clear();
    directory_ = directory;
    return true;
}

void GameExport::consume(const char* data, long size) {
    buffer_.append(data, std::size_t(size));
    std::size_t newline;
    while ((newline = buffer_.find_first_of("\r\n")) != std::string::npos) {
        std::string line = buffer_.substr(0, newline);
        buffer_.erase(0, newline + 1);
        if (line.empty()) continue;
        int k = 0, n = 0;
        if (std::sscanf(line.c_str(), "aerial bake: %d/%d", &k, &n) == 2 && n > 0) {
            steps_ = k;
            total_ = n;
        } else {
            lastLine_ = exportSummaryLine(line, directory_);
        }
    }
}

void GameExport::poll() {
    if (fd_ >= 0) {
        char data[4096];
        for (;;) {
            const long got = long(::read(fd_, data, sizeof data));
            if (got > 0) {
                consume(data, got);
                continue;
            }
            if (got == 0) {  // end of output
                ::close(fd_);
                fd_ = -1;
            }
            break;
        }
    }
    if (pid_ > 0) {
        int status = 0;
        if (::waitpid(pid_, &status, WNOHANG) == pid_) {
            exitCode_ =
                WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
            pid_ = -1;
            if (fd_ >= 0) {  // the rest of the output
                char data[4096];
                long got;
                while ((got = long(::read(fd_, data, sizeof data))) > 0) consume(data, got);
                ::close(fd_);
                fd_ = -1;
            }
            if (!buffer_.empty()) consume("\n", 1);
            done_ = true;
        }
    }
}

void GameExport::wait() {
    while (running()) {
        poll();
        if (running()) ::usleep(2000);
    }
}

void GameExport::cancel() {
    if (pid_ > 0) {
        ::kill(pid_, SIGTERM);
        int status = 0;
        ::waitpid(pid_, &status, 0);
        pid_ = -1;
    }
    if (fd_ >= 0) {
        ::close(fd_);
        fd_ = -1;
    }
}

}  // namespace aerial::editor
