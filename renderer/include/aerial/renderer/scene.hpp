// aerial/renderer/scene.hpp — opaque scene geometry as plain data: triangle
// meshes with a transform and a simple material, the built-in scene (terrain
// with a valley and a few boxes) and test geometry at known depths.
//
// Usage:
//   aerial::renderer::SceneDesc scene = aerial::renderer::makeBuiltinScene();
//   scene.meshes.push_back(aerial::renderer::makeBoxMesh({0, 1, 0}, {1, 1, 1}));
//   renderer.setScene(scene);
#pragma once

#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <memory>
#include <vector>

namespace aerial::renderer {

/// How a material's alpha is used (glTF alphaMode).
enum class AlphaMode { Opaque, Mask, Blend };

/// An 8-bit RGBA image, sRGB-encoded colour and linear alpha, rows top first
/// (width * height * 4 bytes).
struct SceneTexture {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;
};

/// One triangle mesh: positions [m] and unit normals in object space,
/// counter-clockwise front faces.
///
/// The material fields after `emission` come from glTF files
/// (renderer/gltf.hpp). The scene pass draws with `albedo` and `emission`
/// only for now (Lambert, opaque): metal/roughness, the base-colour texture
/// and the alpha mode are carried for the passes to come.
struct SceneMesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<std::uint32_t> indices;  ///< three per triangle
    glm::dmat4 worldFromObject{1.0};
    /// Diffuse reflectance, 0..1 per channel (Lambert). Default 0.5.
    glm::dvec3 albedo{0.5};
    /// Emitted radiance, scene-linear Rec.709 (unlit test surfaces use albedo 0).
    glm::dvec3 emission{0.0};
    /// TEXCOORD_0 per vertex (empty when the mesh has none).
    std::vector<glm::vec2> texcoords;
    /// Base-colour alpha factor, 0..1 (glTF baseColorFactor[3]).
    double opacity{1.0};
    double metallic{0.0};   ///< 0..1
    double roughness{1.0};  ///< 0..1
    AlphaMode alphaMode{AlphaMode::Opaque};
    double alphaCutoff{0.5};  ///< for AlphaMode::Mask
    /// Base-colour texture (multiplies albedo/opacity), shared between meshes; may be null.
    std::shared_ptr<const SceneTexture> baseColorTexture;
};

struct SceneDesc {
    std::vector<SceneMesh> meshes;
};

/// A box (24 vertices, flat normals) of the given centre [m], half extents
/// [m] and rotation (world from object).
SceneMesh makeBoxMesh(const glm::dvec3& centre, const glm::dvec3& halfExtents,
                      const glm::dquat& rotation = glm::dquat(1.0, 0.0, 0.0, 0.0),
                      const glm::dvec3& albedo = glm::dvec3(0.5));

/// A parallelogram corner, corner + edgeU, corner + edgeU + edgeV,
/// corner + edgeV [m]; its front face (normal) is along cross(edgeU, edgeV).
/// Two-sided in the scene pass.
SceneMesh makeQuadMesh(const glm::dvec3& corner, const glm::dvec3& edgeU, const glm::dvec3& edgeV,
                       const glm::dvec3& albedo = glm::dvec3(0.5));

/// Height [m] of the built-in terrain at (x, z): rolling hills around a
/// valley that runs north-south through x = 0 (floor near 0 m, ridges up to
/// about 60 m).
double builtinTerrainHeight(double x, double z);

/// A heightfield of (cells + 1)^2 vertices over [-halfSize, halfSize]^2 [m]
/// sampling builtinTerrainHeight, with smooth normals.
SceneMesh makeTerrainMesh(double halfSize, int cells);

/// The built-in scene: terrain (800 m across) with its valley and a few
/// boxes on the valley floor and the slopes.
SceneDesc makeBuiltinScene();

}  // namespace aerial::renderer
