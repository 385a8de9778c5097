// hardening_support.hpp — small helpers shared by the hardening tests:
// scratch directories, whole-file reads and writes, the source tree.
#pragma once

// GCC 12 warns falsely (-Wrestrict) on std::string concatenations such as
// "x" + std::to_string(i) at -O3 (GCC bug 105329); the tests build strings
// that way throughout.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wrestrict"
#endif

#include <aerial/preset.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include <unistd.h>

namespace aerial::hardening {

namespace fs = std::filesystem;

inline const fs::path kSourceRoot = fs::path(__FILE__).parent_path().parent_path().parent_path();
inline const fs::path kBadInputs = kSourceRoot / "tests" / "data" / "bad_inputs";

inline std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

inline void writeFile(const fs::path& path, const std::string& bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << bytes;
}

/// The names in a directory, sorted.
inline std::vector<std::string> listDir(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

/// A scratch directory, removed afterwards.
class TempDir {
public:
    TempDir() {
        std::string tmpl = (fs::temp_directory_path() / "aerial_hardening_XXXXXX").string();
        path_ = ::mkdtemp(tmpl.data());
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path_, ec);
    }
    const fs::path& path() const { return path_; }

private:
    fs::path path_;
};

inline std::string joinIssues(const std::vector<PresetIssue>& issues) {
    std::string s;
    for (const PresetIssue& i : issues) {
        s += i.toString();
        s += '\n';
    }
    return s;
}

}  // namespace aerial::hardening
