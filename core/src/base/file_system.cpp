// file_system.cpp — the atomic file writer and its fault-injection seam
// (aerial/detail/file_system.hpp).
#include <aerial/detail/file_system.hpp>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <system_error>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace aerial::detail {
namespace {

namespace fs = std::filesystem;

std::atomic<FileSystem*> gReplacement{nullptr};

std::string errnoText(int error) { return std::generic_category().message(error); }

std::string reason(const std::string& what, int error) {
    std::string r = what;
    r += ": ";
    r += errnoText(error);
    return r;
}

/// ".NAME.tmp-" — the prefix of NAME's temporaries.
std::string temporaryPrefix(const fs::path& target) {
    std::string p = ".";
    p += target.filename().string();
    p += ".tmp-";
    return p;
}

/// Removes temporaries of `target` left by processes that no longer exist
/// (killed mid-write). Best effort: errors are ignored.
void removeStaleTemporaries(const fs::path& dir, const fs::path& target) {
    const std::string prefix = temporaryPrefix(target);
    std::error_code ec;
    fs::directory_iterator it(dir, ec), end;
    for (; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0) continue;
        const std::size_t dash = name.find('-', prefix.size());
        if (dash == std::string::npos) continue;
        char* endPtr = nullptr;
        const std::string pidText = name.substr(prefix.size(), dash - prefix.size());
        const long pid = std::strtol(pidText.c_str(), &endPtr, 10);
        if (pidText.empty() || *endPtr != '\0' || pid <= 0 || pid == long(::getpid())) continue;
        if (::kill(pid_t(pid), 0) != 0 && errno == ESRCH) fileSystem().remove(it->path().string());
    }
}

struct Temporary {
    std::string path;
    int fd = -1;
};

/// Step 1: the temporary beside `path`, or the reason it cannot be made.
std::string createTemporary(const std::string& path, Temporary& temp, fs::path& dir) {
    const fs::path target(path);
    if (target.filename().empty()) return "the path names no file";
    dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
    removeStaleTemporaries(dir, target);
    std::string tmpl = (dir / temporaryPrefix(target)).string();
    tmpl += std::to_string(::getpid());
    tmpl += "-XXXXXX";
    FileSystem& fsys = fileSystem();
    temp.fd = fsys.createTemporary(tmpl);
    if (temp.fd < 0) return reason("cannot create a temporary file in " + dir.string(), errno);
    temp.path = tmpl;
    struct stat existing {};
    const mode_t mode = ::stat(path.c_str(), &existing) == 0 ? (existing.st_mode & 07777) : 0644;
    if (::fchmod(temp.fd, mode) != 0) return reason("cannot set the permissions of " + temp.path, errno);
    return {};
}

/// Steps 3 and 4 for a temporary whose bytes are written (fd open).
std::string commit(Temporary& temp, const std::string& path, const fs::path& dir) {
    FileSystem& fsys = fileSystem();
    if (fsys.sync(temp.fd) != 0) return reason("cannot flush " + temp.path + " to disk (fsync)", errno);
    const int fd = temp.fd;
    temp.fd = -1;
    if (fsys.close(fd) != 0) return reason("cannot close " + temp.path, errno);
    if (fsys.rename(temp.path, path) != 0)
        return reason("cannot rename " + temp.path + " over " + path, errno);
    temp.path.clear();                 // it is `path` now
    fsys.syncDirectory(dir.string());  // best effort
    return {};
}

/// Closes and removes what is left of a failed write (errno preserved).
void abandon(Temporary& temp) {
    const int saved = errno;
    FileSystem& fsys = fileSystem();
    if (temp.fd >= 0) fsys.close(temp.fd);
    if (!temp.path.empty()) fsys.remove(temp.path);
    temp = {};
    errno = saved;
}

}  // namespace

// ---------------------------------------------------------------------------
// The real file system.

int FileSystem::createTemporary(std::string& pathTemplate) { return ::mkstemp(pathTemplate.data()); }
long FileSystem::write(int fd, const void* data, std::size_t size) { return long(::write(fd, data, size)); }
int FileSystem::sync(int fd) { return ::fsync(fd); }
int FileSystem::close(int fd) { return ::close(fd); }
int FileSystem::rename(const std::string& from, const std::string& to) {
    return ::rename(from.c_str(), to.c_str());
}
int FileSystem::remove(const std::string& path) { return ::unlink(path.c_str()); }
int FileSystem::syncDirectory(const std::string& directory) {
    const int fd = ::open(directory.c_str(), O_RDONLY | O_DIRECTORY);
    if (fd < 0) return -1;
    const int r = ::fsync(fd);
    ::close(fd);
    return r;
}

FileSystem& fileSystem() {
    static FileSystem real;
    FileSystem* replacement = gReplacement.load();
    return replacement ? *replacement : real;
}

ScopedFileSystem::ScopedFileSystem(FileSystem& replacement)
    : previous_(gReplacement.exchange(&replacement)) {}
ScopedFileSystem::~ScopedFileSystem() { gReplacement.store(previous_); }

// ---------------------------------------------------------------------------
// Faults.

bool parseFileFault(std::string_view name, FileFault& fault) {
    static constexpr std::pair<std::string_view, FileFault> kNames[] = {
        {"none", FileFault::None},
        {"missing-directory", FileFault::MissingDirectory},
        {"not-writable", FileFault::NotWritable},
        {"disk-full", FileFault::DiskFull},
        {"sync", FileFault::SyncFails},
        {"rename", FileFault::RenameFails},
        {"crash", FileFault::CrashDuringWrite},
    };
    for (const auto& [n, f] : kNames) {
        if (n == name) {
            fault = f;
            return true;
        }
    }
    return false;
}

int FaultyFileSystem::createTemporary(std::string& pathTemplate) {
    if (fault_ == FileFault::MissingDirectory || fault_ == FileFault::NotWritable) {
        ++fired_;
        errno = fault_ == FileFault::MissingDirectory ? ENOENT : EACCES;
        return -1;
    }
    return FileSystem::createTemporary(pathTemplate);
}

long FaultyFileSystem::write(int fd, const void* data, std::size_t size) {
    if (fault_ != FileFault::DiskFull && fault_ != FileFault::CrashDuringWrite)
        return FileSystem::write(fd, data, size);
    ++fired_;
    // Part of the data reaches the file first, as on a real disk.
    const std::size_t part = size / 2;
    if (part > 0 && FileSystem::write(fd, data, part) < 0) return -1;
    if (fault_ == FileFault::CrashDuringWrite) {
        ::kill(::getpid(), SIGKILL);
        ::pause();
    }
    errno = ENOSPC;
    return -1;
}

int FaultyFileSystem::sync(int fd) {
    if (fault_ == FileFault::SyncFails) {
        ++fired_;
        errno = EIO;
        return -1;
    }
    if (fault_ == FileFault::CrashDuringWrite) {  // writers that write by name crash here
        ++fired_;
        ::kill(::getpid(), SIGKILL);
        ::pause();
    }
    return FileSystem::sync(fd);
}

int FaultyFileSystem::rename(const std::string& from, const std::string& to) {
    if (fault_ == FileFault::RenameFails) {
        ++fired_;
        errno = EIO;
        return -1;
    }
    return FileSystem::rename(from, to);
}

// ---------------------------------------------------------------------------
// The writer.

namespace {

// Makes the temporary beside `path`, lets `fill` write it (returning why it
// could not, or ""), and commits it over `path`; the temporary is abandoned
// on any failure, exceptions included.
template <class Fill>
std::string writeThroughTemporary(const std::string& path, const Fill& fill) {
    Temporary temp;
    try {
        fs::path dir;
        std::string why = createTemporary(path, temp, dir);
        if (why.empty()) why = fill(temp);
        if (why.empty()) why = commit(temp, path, dir);
        if (!why.empty()) abandon(temp);
        return why;
    } catch (const std::exception& e) {
        abandon(temp);
        return std::string("cannot write ") + path + ": " + e.what();
    }
}

}  // namespace

std::string writeFileAtomically(const std::string& path, std::string_view bytes) {
    return writeThroughTemporary(path, [&](const Temporary& temp) {
        FileSystem& fsys = fileSystem();
        std::string why;
        std::size_t written = 0;
        while (why.empty() && written < bytes.size()) {
            const long n = fsys.write(temp.fd, bytes.data() + written, bytes.size() - written);
            if (n < 0) {
                if (errno == EINTR) continue;
                why = reason("cannot write " + temp.path, errno);
            } else if (n == 0) {
                errno = EIO;
                why = reason("cannot write " + temp.path, errno);
            } else {
                written += std::size_t(n);
            }
        }
        return why;
    });
}

std::string writeFileAtomicallyWith(
    const std::string& path, const std::function<std::string(const std::string& temporaryPath)>& write) {
    return writeThroughTemporary(path, [&](const Temporary& temp) {
        // The writer opens the file by name; keep our descriptor for fsync.
        std::string why = write(temp.path);
        if (!why.empty()) why = "cannot write " + temp.path + ": " + why;
        return why;
    });
}

}  // namespace aerial::detail
