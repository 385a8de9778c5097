// editor_test_support.hpp — small helpers shared by the editor's unit tests.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <string>

namespace aerial::editor::test {

/// Concatenation by appends (GCC 12 warns falsely on `"x" + std::to_string(n)`).
template <class... Parts>
std::string join(const Parts&... parts) {
    std::string out;
    (out.append(parts), ...);
    return out;
}

/// A fresh, empty directory `<temp>/aerial_<suite>_test_<name>_<pid>`.
inline std::filesystem::path tempDir(const std::string& suite, const std::string& name) {
    std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                join("aerial_", suite, "_test_", name, "_", std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

}  // namespace aerial::editor::test
