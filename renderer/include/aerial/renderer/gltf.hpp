// aerial/renderer/gltf.hpp — glTF 2.0 scenes (.gltf with embedded or
// external buffers, .glb) as a SceneDesc, through tinygltf.
//
// Usage:
//   aerial::renderer::GltfLoadResult r = aerial::renderer::loadGltfScene("valley.glb");
//   if (!r.ok()) { fprintf(stderr, "%s\n", r.error.c_str()); return 1; }
//   for (const std::string& w : r.warnings) fprintf(stderr, "warning: %s\n", w.c_str());
//   renderer.setScene(r.scene);
//
// What is read: the default scene (or scene 0) and its node hierarchy (TRS
// or matrix; world = parent x local), one SceneMesh per TRIANGLES primitive
// per node instance with positions, normals (given, else computed: flat by
// default, as glTF asks, or smooth), TEXCOORD_0, indices (uint8/16/32 or
// none), and the material: base colour factor (albedo, opacity), metallic
// and roughness factors, the base-colour texture (decoded to RGBA8) and the
// alpha mode. SceneMesh::worldFromObject holds the node's world matrix;
// positions stay in object space.
//
// Not read: cameras, lights, animations, skins, morph targets, texture
// samplers (wrap/filter) and texture transforms, emissive, normal, occlusion
// and metal/rough textures, TEXCOORD_1 and up, vertex colours (the renderer
// samples every texture with repeat wrapping and trilinear filtering). How
// the material is shaded: SceneMesh.
//
// Errors (one line: "FILE: ELEMENT: reason", e.g. "cube.gltf:
// meshes[0].primitives[0]: POSITION accessor (accessors[0]) has componentType
// 5121, expected FLOAT (5126)"): files that are not glTF 2.0, bad GLB
// headers, missing buffers or images (a missing texture image is an error,
// not a warning), accessors or buffer views reaching outside their buffer,
// indices out of range, sparse accessors, node cycles, extensions the file
// requires, and anything over the limits. Nothing is read out of bounds
// whatever the file claims. Warnings (the load goes on): primitives of
// another mode than TRIANGLES (skipped), unusable normals (recomputed).
#pragma once

#include <aerial/limits.hpp>
#include <aerial/renderer/scene.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace aerial::renderer {

enum class GltfNormals { Flat, Smooth };

struct GltfLoadOptions {
    /// How normals are made for primitives that have none.
    GltfNormals computedNormals = GltfNormals::Flat;
    // Caps (aerial/limits.hpp documents them all).
    /// The .gltf/.glb and each external buffer or image [bytes].
    std::uint64_t maxFileBytes = limits::kMaxGltfFileBytes;
    std::uint64_t maxVertices = limits::kMaxGltfVertices;    ///< over all meshes, after node instancing
    std::uint64_t maxTriangles = limits::kMaxGltfTriangles;  ///< over all meshes, after node instancing
    int maxNodeDepth = limits::kMaxGltfNodeDepth;
    /// Pixels of all images together, decoded (checked from each header first).
    std::uint64_t maxImagePixels = limits::kMaxTexturePixelsTotal;
};

struct GltfLoadResult {
    SceneDesc scene;
    std::string error;  ///< empty on success
    std::vector<std::string> warnings;
    bool ok() const { return error.empty(); }
};

/// Loads a .gltf or .glb file (chosen by the extension, case-insensitive).
GltfLoadResult loadGltfScene(const std::string& path, const GltfLoadOptions& options = {});

}  // namespace aerial::renderer
