// preset_validate.hpp — private: the pieces of preset validation
// (preset_validate.cpp) that the reader and the editing helpers reuse.
// validatePreset itself is public (aerial/preset.hpp).
#pragma once

#include <aerial/param_table.hpp>

#include <string>
#include <string_view>

namespace aerial::detail {

/// An object id: 1..limits::kMaxIdBytes characters of A-Z a-z 0-9 _ - .
bool validId(std::string_view id);

/// A parameter's valid range as text, "min..max".
std::string rangeText(const ParamDesc& p);

}  // namespace aerial::detail
