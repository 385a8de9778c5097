// layout_gltf.hpp — the layout of a preset's objects as a glTF 2.0 file
// (`aerial bake` writes it as layout.gltf): one node per fog volume, cloud
// volume and emitter, so a level designer sees where the fog is in Blender,
// Godot, Unity or Unreal. layout_gltf.cpp says what the file holds.
#pragma once

#include <aerial/evaluate.hpp>

#include <string>

namespace aerial::cli {

/// The file name `aerial bake` gives it, beside manifest.json.
inline constexpr const char* kLayoutName = "layout.gltf";

/// The glTF 2.0 document (JSON text, buffers embedded) of the volumes,
/// cloud volumes and emitters of an evaluated state, their transforms and
/// parameters as at state.timeHours. `presetName` names the scene. Never
/// writes NaN or Inf (non-finite values take their defaults).
std::string layoutGltf(const PresetState& state, const std::string& presetName);

}  // namespace aerial::cli
