// aerial/fog_mesh.hpp — the closed triangle mesh of a mesh fog volume
// (aerial/fog_volume.hpp, shape Mesh; ../shared/DESIGN.md, "Mesh and
// subtract volumes"; Wenzel 2006 / seed 001, polygonal fog volumes).
//
// Usage:
//   aerial::FogMeshLoadResult r = aerial::loadFogMesh("meshes/cave.gltf");
//   if (!r.mesh) { log(r.error); return; }   // "cave.gltf: open edge ..."
//   volume.shape = aerial::FogVolumeShape::Mesh;
//   volume.mesh = "meshes/cave.gltf";  volume.meshData = r.mesh;
//
//   // The chords of a line inside the mesh (object space), e.g. a game's
//   // own queries; FogScene and the renderer use the same.
//   std::vector<aerial::VolumeSegment> chords;
//   r.mesh->lineChords(origin, direction, chords);
//
// What a fog mesh must be (anything else is refused, with the reason):
//   - triangles (glTF mode TRIANGLES, indexed or not), at most
//     limits::kMaxFogMeshTriangles of them in all the file's meshes;
//   - closed: every edge is shared by exactly two triangles ("open edge");
//     vertices at the same position are one vertex (glTF splits them for
//     normals and UVs), so edges are compared by position;
//   - manifold: no edge shared by three or more triangles ("non-manifold
//     edge");
//   - consistently oriented: the two triangles of an edge run along it in
//     opposite directions ("flipped triangle"), and the mesh faces outwards
//     (counter-clockwise seen from outside, as glTF: a positive enclosed
//     volume; a mesh turned inside out is refused, "faces inwards");
//   - no degenerate triangle (zero area), every position finite and within
//     limits::kMaxCoordinate.
// The glTF file: .gltf (with embedded or external buffers) or .glb, read
// through Debian's tinygltf under the size limits of aerial/limits.hpp; the
// triangles of every mesh primitive of the default scene's nodes, placed by
// the node transforms, are the object-space mesh (a file without scenes:
// every mesh, untransformed).
//
// Chords: a line meets the mesh in an even number of crossings (entries,
// where it goes in against the outward normal, and exits); sorted by
// distance, the stretches where more have been entered than left are the
// chords. Crossings are found through a BVH over the triangles with a
// double-precision ray/triangle test; a line through an edge or vertex may
// count it on both triangles, and crossings of equal sign closer than
// 1e-12 of the mesh's size are merged, so a chord is never lost or doubled.
#pragma once

#include <aerial/fog_volume.hpp>

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace aerial {

class FogMesh {
public:
    /// Checks and builds a mesh from object-space positions and triangle
    /// indices (3 per triangle, counter-clockwise seen from outside). On
    /// failure returns null and sets `error` to the reason (no file name).
    static std::shared_ptr<const FogMesh> build(const std::vector<glm::dvec3>& positions,
                                                const std::vector<std::uint32_t>& indices,
                                                std::string& error);

    ~FogMesh();
    FogMesh(const FogMesh&) = delete;
    FogMesh& operator=(const FogMesh&) = delete;

    /// Welded positions (one per distinct position), object space.
    const std::vector<glm::dvec3>& positions() const;
    /// Triangles into positions(), 3 per triangle, outward counter-clockwise.
    const std::vector<std::uint32_t>& indices() const;
    std::size_t triangleCount() const { return indices().size() / 3; }
    /// Object-space bounds.
    glm::dvec3 boundsMin() const;
    glm::dvec3 boundsMax() const;
    /// Enclosed volume [object units^3], > 0.
    double enclosedVolume() const;

    /// The chords of the line origin + t * direction (object space, t in
    /// units of |direction|, unclipped: t may be negative), sorted and
    /// disjoint, appended to `chords`. Returns how many were appended.
    std::size_t lineChords(const glm::dvec3& origin, const glm::dvec3& direction,
                           std::vector<VolumeSegment>& chords) const;

    /// Whether an object-space point is inside (a line through it has more
    /// entries than exits before it).
    bool contains(const glm::dvec3& point) const;

private:
    FogMesh();
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

struct FogMeshLoadResult {
    /// The mesh, null on failure.
    std::shared_ptr<const FogMesh> mesh;
    /// "<file>: <reason>" on failure ("cannot read", "not glTF", "open edge
    /// between (x, y, z) and (x, y, z)", ...).
    std::string error;
};

/// Reads and checks a glTF file (.gltf or .glb). Never throws.
FogMeshLoadResult loadFogMesh(const std::string& path);

/// The mesh as a self-contained glTF 2.0 text: one scene, one node and mesh
/// named `name`, its welded positions (float VEC3, with min/max) and
/// triangles (UNSIGNED_INT) in one embedded base64 buffer. What an export
/// writes beside a preset so that it travels with its meshes; loadFogMesh
/// reads it back to the same triangles (positions rounded to float).
std::string fogMeshToGltf(const FogMesh& mesh, const std::string& name);

}  // namespace aerial
