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

/// The key a track names its object by in a file: "volume", "emitter",
/// "cloud_volume"; "" for globals.
std::string_view trackObjectKey(ParamScope scope);

/// The scopes of placed objects (those a track names by id), in file order.
inline constexpr ParamScope kObjectScopes[] = {ParamScope::Volume, ParamScope::Emitter,
                                               ParamScope::CloudVolume};

/// A parameter's valid range as text, "min..max".
std::string rangeText(const ParamDesc& p);

}  // namespace aerial::detail
