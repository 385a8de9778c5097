// aerial/detail/file_system.hpp — the atomic file writer every saved file
// goes through (savePreset, and the `aerial` CLI's bakes and renders), and
// its seam: the few file-system calls it makes sit behind an interface that
// tests replace to inject the faults a real disk has.
//
// Not part of the stable API (namespace detail): for Aerial's own tools and
// tests.
//
// Usage (tests):
//   aerial::detail::FaultyFileSystem full(aerial::detail::FileFault::DiskFull);
//   aerial::detail::ScopedFileSystem use(full);
//   aerial::SaveResult r = aerial::savePreset(preset, "out/mine.json");
//   // r.errors[0].message == "not saved: cannot write out/.mine.json.tmp-...: No space left on device"
//
// The write (writeFileAtomically):
//   1. create ".NAME.tmp-PID-XXXXXX" beside NAME (mkstemp: O_EXCL, mode 0600,
//      then the old file's permissions or 0644);
//   2. write every byte, retrying short writes and EINTR;
//   3. fsync the temporary, close it;
//   4. rename it over NAME (atomic on POSIX), then fsync the directory
//      (best effort: some file systems refuse).
// Any failure removes the temporary and leaves NAME as it was; the reason
// names the file and the errno text. A process killed between 1 and 4
// leaves its temporary behind (nothing can remove it then); the next write
// to the same NAME removes temporaries whose process is gone.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>

namespace aerial::detail {

/// The calls an atomic write makes. Each returns like its POSIX namesake:
/// -1 (write: -1) with errno set on failure.
class FileSystem {
public:
    virtual ~FileSystem() = default;
    /// mkstemp(3): creates and opens a new file from `pathTemplate` (ending
    /// in XXXXXX, replaced in place). Returns the descriptor.
    virtual int createTemporary(std::string& pathTemplate);
    /// write(2).
    virtual long write(int fd, const void* data, std::size_t size);
    /// fsync(2).
    virtual int sync(int fd);
    /// close(2).
    virtual int close(int fd);
    /// rename(2).
    virtual int rename(const std::string& from, const std::string& to);
    /// unlink(2).
    virtual int remove(const std::string& path);
    /// fsync(2) of a directory, by path.
    virtual int syncDirectory(const std::string& directory);
};

/// The file system writes go through: the real one unless replaced.
FileSystem& fileSystem();

/// Replaces the file system for the lifetime of this object (tests; not
/// thread-safe against writes in flight on other threads).
class ScopedFileSystem {
public:
    explicit ScopedFileSystem(FileSystem& replacement);
    ~ScopedFileSystem();
    ScopedFileSystem(const ScopedFileSystem&) = delete;
    ScopedFileSystem& operator=(const ScopedFileSystem&) = delete;

private:
    FileSystem* previous_;
};

/// The faults FaultyFileSystem injects, each where a real one happens.
enum class FileFault {
    None,
    MissingDirectory,  ///< createTemporary fails: ENOENT
    NotWritable,       ///< createTemporary fails: EACCES (root ignores chmod; this does not)
    DiskFull,          ///< write stores part of the data, then fails: ENOSPC
    SyncFails,         ///< sync (fsync) fails: EIO
    RenameFails,       ///< rename fails: EIO
    CrashDuringWrite,  ///< write stores part of the data, then the process is SIGKILLed
};

/// "missing-directory", "not-writable", "disk-full", "sync", "rename",
/// "crash" (the spellings of AERIAL_TEST_FILE_FAULT); false if unknown.
bool parseFileFault(std::string_view name, FileFault& fault);

/// The real file system with one fault.
class FaultyFileSystem : public FileSystem {
public:
    explicit FaultyFileSystem(FileFault fault) : fault_(fault) {}
    int createTemporary(std::string& pathTemplate) override;
    long write(int fd, const void* data, std::size_t size) override;
    int sync(int fd) override;
    int rename(const std::string& from, const std::string& to) override;
    /// How many times the fault fired.
    int fired() const { return fired_; }

private:
    FileFault fault_;
    int fired_ = 0;
};

/// Writes `bytes` to `path` atomically (steps above). Returns "" on
/// success, else the reason, e.g. "cannot write dir/.x.json.tmp-42-Ab12Cd:
/// No space left on device". Never throws.
std::string writeFileAtomically(const std::string& path, std::string_view bytes);

/// The same for writers that must write the file themselves by name (image
/// libraries): `write(temporaryPath)` fills the temporary and returns "" or
/// the reason it failed; it may also throw. Then the temporary is synced
/// and renamed as above. Returns "" or the reason; never throws.
std::string writeFileAtomicallyWith(
    const std::string& path, const std::function<std::string(const std::string& temporaryPath)>& write);

}  // namespace aerial::detail
