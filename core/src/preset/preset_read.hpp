// preset_read.hpp — private: a parsed preset document (json_tree.hpp) into a
// Preset, driven by the parameter table (preset_read.cpp).
#pragma once

#include "json_tree.hpp"

#include <aerial/preset.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace aerial::detail {

/// Reads the tree `nodes` of `text` (named `file` in issues) into `preset`:
/// duplicate keys, the version, every known field (unknown ones are
/// warnings), then validatePreset on the result unless the version was
/// refused. Every issue carries the file, its JSON pointer and its
/// line:column; at most limits::kMaxPresetIssues of each severity are
/// listed, the rest summed up in one last issue. The preset is complete
/// only when `errors` is empty.
void readPresetTree(std::string_view text, const std::string& file, const std::vector<JNode>& nodes,
                    Preset& preset, std::vector<PresetIssue>& errors, std::vector<PresetIssue>& warnings);

}  // namespace aerial::detail
