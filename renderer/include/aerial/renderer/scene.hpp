// aerial/renderer/scene.hpp — scene geometry as plain data: triangle meshes
// with a transform and a glTF metallic-roughness material (opaque, masked or
// alpha-blended), soft fog particles, the built-in scene (terrain with a
// valley, a lake, rocks, buildings, glass, a particle fog source) and test
// geometry at known depths.
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
/// (renderer/gltf.hpp). Shading (shaders/common/shading.glsl): the glTF 2.0
/// metallic-roughness BRDF, Lambert diffuse plus a GGX / Smith / Schlick
/// specular lobe, with base colour = albedo x texture (sRGB-decoded,
/// mipmapped, sampled at TEXCOORD_0), lit by the transmitted sun and moon,
/// the sky and the emitters. Opaque and Mask meshes are drawn in the scene
/// pass (Mask discards where alpha < alphaCutoff); Blend meshes after the fog
/// passes, back to front, fogged through the CPU fog query (renderer.hpp).
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
    /// Strength of the dielectric specular layer, 0..1 (KHR_materials_specular
    /// specularFactor): F0 = 0.04 x specularFactor for non-metals. 0 makes a
    /// non-metal a pure Lambert reflector. Default 1 (plain glTF).
    double specularFactor{1.0};
};

/// One camera-facing fog sprite of a particle fog source (soft particles):
/// a disc of radius `radius` in the view plane with coverage
/// opacity (1 - r^2)^2 (r = distance from the centre / radius), faded where it
/// nears scene geometry: fade = saturate((sceneDepth - spriteDepth) /
/// fadeDistance) (linear eye depths [m]), so it never shows a hard line.
/// Radiance: albedo (E_sun + E_moon + emitters) / (4 pi) + albedo E_sky /
/// (2 pi) + emission (an isotropic medium), fogged as a transparent object
/// (renderer.hpp; the volumes' and emitters' fog queried at its centre).
struct FogSprite {
    glm::dvec3 position{0.0};   ///< centre [m]
    double radius = 1.0;        ///< [m], > 0
    glm::dvec3 albedo{0.8};     ///< single-scattering albedo, 0..1
    double opacity = 0.5;       ///< peak coverage, 0..1
    glm::dvec3 emission{0.0};   ///< emitted radiance, scene-linear
    double fadeDistance = 2.0;  ///< [m], > 0
};

struct SceneDesc {
    std::vector<SceneMesh> meshes;
    /// Soft fog particles, drawn after the transparent meshes (sorted back to
    /// front each frame).
    std::vector<FogSprite> sprites;
};

/// A box (24 vertices, flat normals) of the given centre [m], half extents
/// [m] and rotation (world from object). Each face carries texture
/// coordinates 0..1 (the image upright on the side faces).
SceneMesh makeBoxMesh(const glm::dvec3& centre, const glm::dvec3& halfExtents,
                      const glm::dquat& rotation = glm::dquat(1.0, 0.0, 0.0, 0.0),
                      const glm::dvec3& albedo = glm::dvec3(0.5));

/// A parallelogram corner, corner + edgeU, corner + edgeU + edgeV,
/// corner + edgeV [m]; its front face (normal) is along cross(edgeU, edgeV).
/// Two-sided in the scene pass. Texture coordinates: u 0..1 along edgeU, the
/// image's top row at corner + edgeV (v = 0 there, glTF convention).
SceneMesh makeQuadMesh(const glm::dvec3& corner, const glm::dvec3& edgeU, const glm::dvec3& edgeV,
                       const glm::dvec3& albedo = glm::dvec3(0.5));

/// Height [m] of the built-in terrain at (x, z): rolling hills around a
/// valley that runs north-south through x = 0 (floor near 0 m, ridges up to
/// about 60 m), with the lake's basin (3 m deep at (0, 0)) on its floor.
double builtinTerrainHeight(double x, double z);

/// A heightfield of (cells + 1)^2 vertices over [-halfSize, halfSize]^2 [m]
/// sampling builtinTerrainHeight, with smooth normals.
SceneMesh makeTerrainMesh(double halfSize, int cells);

/// A particle fog source: `count` sprites in a plume rising from `base` [m]
/// up to `height` [m], spreading to `radius` [m] at the top, seeded so the
/// same arguments always give the same sprites.
std::vector<FogSprite> makeFogParticleSource(const glm::dvec3& base, double radius, double height, int count,
                                             std::uint32_t seed = 1);

/// The built-in scene, everything in code (no file): terrain (800 m across)
/// with its valley; a lake on the valley floor (flat, dark, slightly
/// specular water) at builtinLakeLevel(); rocks; a few buildings (walls with
/// an sRGB-textured facade, roofs, a metal mast); glass panes and other
/// alpha-blended objects; a masked (alpha-tested) fence; and a particle fog
/// source (steam rising from the lake shore).
SceneDesc makeBuiltinScene();

/// Water level of the built-in lake [m].
double builtinLakeLevel();

}  // namespace aerial::renderer
