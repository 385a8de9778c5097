// gltf_model.hpp — private to the glTF loader: the error type, enum names,
// bounds-checked accessor view and node transform it shares with core
// (aerial/detail/gltf_model.hpp); gltf_scene_builder.cpp turns a parsed
// tinygltf::Model into a SceneDesc, gltf_loader.cpp reads the file
// (aerial/renderer/gltf.hpp).
#pragma once

#include <aerial/detail/gltf_model.hpp>
#include <aerial/renderer/gltf.hpp>

#include <string>

namespace aerial::renderer::gltf {

// The error type, enum names, accessor view and node transform shared with
// core's fog mesh reader.
using namespace aerial::detail::gltf;

/// The default scene of a parsed model as a SceneDesc in result.scene (every
/// node instanced, every accessor checked, the limits of `options` applied);
/// throws LoadError.
void buildScene(const tinygltf::Model& model, const GltfLoadOptions& options, GltfLoadResult& result);

}  // namespace aerial::renderer::gltf
