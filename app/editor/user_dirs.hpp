// editor/user_dirs.hpp — where the editor keeps files per user, after the
// XDG Base Directory specification: an Aerial override variable first, then
// the XDG variable, then the XDG default under $HOME, then /tmp.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <string>

namespace aerial::editor {

struct UserDirectoryRule {
    const char* overrideVariable;  ///< e.g. "AERIAL_STATE_DIR": used as is
    const char* xdgVariable;       ///< e.g. "XDG_STATE_HOME": $XDG.../aerial
    const char* underHome;         ///< e.g. ".local/state": $HOME/<this>/aerial
    const char* lastResort;        ///< e.g. "/tmp/aerial-state"
};

inline std::string userDirectory(const UserDirectoryRule& rule) {
    namespace fs = std::filesystem;
    if (const char* dir = std::getenv(rule.overrideVariable); dir && *dir) return dir;
    if (const char* xdg = std::getenv(rule.xdgVariable); xdg && *xdg)
        return (fs::path(xdg) / "aerial").string();
    if (const char* home = std::getenv("HOME"); home && *home)
        return (fs::path(home) / rule.underHome / "aerial").string();
    return rule.lastResort;
}

}  // namespace aerial::editor
