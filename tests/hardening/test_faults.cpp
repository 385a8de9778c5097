// test_faults.cpp — saving through the atomic writer's seam
// (aerial/detail/file_system.hpp) with the faults a real disk has: a missing
// directory, a directory that is not writable, a full disk, fsync and rename
// failures, and a process killed in the middle of a save. Every time the old
// file is intact, no temporary is left behind (but after the kill, where
// nothing could remove it; the next save does), and the error names the file
// and the reason.
#include "hardening_support.hpp"

#include <aerial/detail/file_system.hpp>
#include <aerial/preset.hpp>

#include <gtest/gtest.h>

#include <csignal>
#include <ostream>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

namespace aerial::hardening {
namespace {

using detail::FaultyFileSystem;
using detail::FileFault;
using detail::ScopedFileSystem;

const std::string kOld = "{\"old\": \"the previous save\"}\n";

struct Case {
    FileFault fault;
    const char* name;
    /// The error after "not saved: ", with DIR for the directory and TEMP for
    /// the temporary's path up to its random suffix.
    const char* expected;
};

// gtest names the case by this (instead of its bytes).
void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

class SaveFault : public ::testing::TestWithParam<Case> {};

TEST_P(SaveFault, OldFileIntactAndReasonNamed) {
    const Case& c = GetParam();
    TempDir dir;
    const fs::path file = dir.path() / "scene.json";
    writeFile(file, kOld);

    FaultyFileSystem faulty(c.fault);
    SaveResult r;
    {
        ScopedFileSystem use(faulty);
        r = savePreset(defaultPreset(), file.string());
    }
    EXPECT_EQ(faulty.fired(), 1);
    ASSERT_FALSE(r.ok());
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_EQ(r.errors[0].file, file.string());

    std::string expected = std::string("not saved: ") + c.expected;
    const std::string temp = (dir.path() / ".scene.json.tmp-").string() + std::to_string(::getpid()) + "-";
    for (const auto& [token, value] : {std::pair<std::string, std::string>{"DIR", dir.path().string()},
                                       std::pair<std::string, std::string>{"TEMP", temp}}) {
        const std::size_t at = expected.find(token);
        if (at != std::string::npos) expected.replace(at, token.size(), value);
    }
    // The temporary's name ends in six random characters: compare around them.
    const std::string& message = r.errors[0].message;
    const std::size_t at = expected.find(temp);
    if (at == std::string::npos) {
        EXPECT_EQ(message, expected);
    } else {
        ASSERT_GE(message.size(), at + temp.size() + 6) << message;
        EXPECT_EQ(message.substr(0, at + temp.size()), expected.substr(0, at + temp.size())) << message;
        EXPECT_EQ(message.substr(at + temp.size() + 6), expected.substr(at + temp.size())) << message;
    }
    EXPECT_EQ(readFile(file), kOld) << "the previous file is intact";
    EXPECT_EQ(listDir(dir.path()), std::vector<std::string>{"scene.json"}) << "no temporary left behind";

    // The same save without the fault succeeds.
    ASSERT_TRUE(savePreset(defaultPreset(), file.string()).ok());
    EXPECT_EQ(readFile(file), presetToJson(defaultPreset()));
}

INSTANTIATE_TEST_SUITE_P(
    Faults, SaveFault,
    ::testing::Values(Case{FileFault::MissingDirectory, "MissingDirectory",
                           "cannot create a temporary file in DIR: No such file or directory"},
                      Case{FileFault::NotWritable, "NotWritable",
                           "cannot create a temporary file in DIR: Permission denied"},
                      Case{FileFault::DiskFull, "DiskFull", "cannot write TEMP: No space left on device"},
                      Case{FileFault::SyncFails, "SyncFails",
                           "cannot flush TEMP to disk (fsync): Input/output error"},
                      Case{FileFault::RenameFails, "RenameFails",
                           "cannot rename TEMP over DIR/scene.json: Input/output error"}),
    [](const ::testing::TestParamInfo<Case>& p) { return std::string(p.param.name); });

TEST(SaveFault, RealMissingDirectory) {
    TempDir dir;
    const fs::path file = dir.path() / "no" / "such" / "scene.json";
    const SaveResult r = savePreset(defaultPreset(), file.string());
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.errors[0].toString(),
              file.string() + ": error: not saved: cannot create a temporary file in " +
                  (dir.path() / "no" / "such").string() + ": No such file or directory");
}

TEST(SaveFault, PathNamingNoFile) {
    TempDir dir;
    const SaveResult r = savePreset(defaultPreset(), dir.path().string() + "/");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.errors[0].message, "not saved: the path names no file");
}

TEST(SaveFault, CrashMidSaveKeepsTheOldFile) {
    TempDir dir;
    const fs::path file = dir.path() / "scene.json";
    writeFile(file, kOld);

    // A child process saves and is SIGKILLed half-way through the write.
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        FaultyFileSystem crash(FileFault::CrashDuringWrite);
        ScopedFileSystem use(crash);
        savePreset(defaultPreset(), file.string());
        ::_exit(3);  // not reached: the write kills the process
    }
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFSIGNALED(status)) << "exit status " << status;
    EXPECT_EQ(WTERMSIG(status), SIGKILL);

    EXPECT_EQ(readFile(file), kOld) << "the previous file is intact";
    // What the killed process left: its temporary, with half the data.
    const std::vector<std::string> left = listDir(dir.path());
    ASSERT_EQ(left.size(), 2u);
    const std::string stalePrefix = ".scene.json.tmp-" + std::to_string(child) + "-";
    EXPECT_EQ(left[0].rfind(stalePrefix, 0), 0u) << left[0];
    const std::string partial = readFile(dir.path() / left[0]);
    EXPECT_EQ(partial.size(), presetToJson(defaultPreset()).size() / 2);

    // The next save replaces the file and removes the dead process's temporary.
    ASSERT_TRUE(savePreset(defaultPreset(), file.string()).ok());
    EXPECT_EQ(readFile(file), presetToJson(defaultPreset()));
    EXPECT_EQ(listDir(dir.path()), std::vector<std::string>{"scene.json"});
}

TEST(SaveFault, WriterWithCallbackRemovesTheTemporary) {
    TempDir dir;
    const fs::path file = dir.path() / "image.exr";
    writeFile(file, kOld);
    std::string seen;
    const std::string why = detail::writeFileAtomicallyWith(file.string(), [&](const std::string& temp) {
        seen = temp;
        writeFile(temp, "half an ima");
        return std::string("the encoder ran out of memory");
    });
    EXPECT_EQ(why, "cannot write " + seen + ": the encoder ran out of memory");
    EXPECT_EQ(readFile(file), kOld);
    EXPECT_EQ(listDir(dir.path()), std::vector<std::string>{"image.exr"});

    // A writer that throws: the same.
    const std::string thrown = detail::writeFileAtomicallyWith(
        file.string(), [&](const std::string&) -> std::string { throw std::runtime_error("boom"); });
    EXPECT_EQ(thrown, "cannot write " + file.string() + ": boom");
    EXPECT_EQ(listDir(dir.path()), std::vector<std::string>{"image.exr"});

    // And one that works: renamed into place.
    EXPECT_EQ(detail::writeFileAtomicallyWith(file.string(),
                                              [&](const std::string& temp) {
                                                  writeFile(temp, "new");
                                                  return std::string();
                                              }),
              "");
    EXPECT_EQ(readFile(file), "new");
    EXPECT_EQ(listDir(dir.path()), std::vector<std::string>{"image.exr"});
}

TEST(SaveFault, FaultNames) {
    FileFault f{};
    EXPECT_TRUE(detail::parseFileFault("disk-full", f));
    EXPECT_EQ(f, FileFault::DiskFull);
    EXPECT_TRUE(detail::parseFileFault("crash", f));
    EXPECT_EQ(f, FileFault::CrashDuringWrite);
    EXPECT_FALSE(detail::parseFileFault("meteor", f));
}

}  // namespace
}  // namespace aerial::hardening
