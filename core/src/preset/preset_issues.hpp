// preset_issues.hpp — private: making the issues the preset loader and
// saver report (PresetIssue, aerial/preset.hpp).
#pragma once

#include <aerial/preset.hpp>

#include <string>

namespace aerial::detail {

/// An error about the whole file (no pointer, no position).
PresetIssue makeIssue(std::string file, std::string message);

}  // namespace aerial::detail
