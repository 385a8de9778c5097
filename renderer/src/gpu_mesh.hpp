// gpu_mesh.hpp — private: a scene mesh and its base-colour texture on the
// GPU (vertex array, buffers, the mesh's ObjectBlock), shared by the scene
// and transparent passes and the fog-volume hull.
#pragma once

#include "gpu_types.hpp"

#include <aerial/renderer/scene.hpp>

#include <epoxy/gl.h>
#include <glm/vec3.hpp>

namespace aerial::renderer::detail {

struct GpuMesh {
    GLuint vertexArray = 0;
    GLuint vertexBuffer = 0;
    GLuint indexBuffer = 0;
    GLsizei indexCount = 0;
    GLuint texture = 0;  ///< base colour (owned by Impl::textures); 0 = none
    AlphaMode alphaMode = AlphaMode::Opaque;
    glm::dvec3 boundsMin{0.0}, boundsMax{0.0};  ///< world bounds [m]
    ObjectBlock block;
};

/// x when finite, clamped to [lo, hi]; `fallback` otherwise.
double clampOr(double x, double lo, double hi, double fallback);

/// Uploads a mesh (interleaved position, normal, TEXCOORD_0; the normal and
/// texcoord attributes only `withNormals`) and fills its ObjectBlock from the
/// material (sanitised) and its world bounds.
GpuMesh uploadMesh(const SceneMesh& mesh, bool withNormals);

/// An sRGB8_A8 texture with a full mipmap chain, repeat wrapping, trilinear
/// filtering (0 for a malformed image). Sets the unpack state it needs and
/// restores it.
GLuint uploadTexture(const SceneTexture& t);

/// Deletes the mesh's vertex array and buffers (not its texture).
void destroyMesh(GpuMesh& mesh);

}  // namespace aerial::renderer::detail
