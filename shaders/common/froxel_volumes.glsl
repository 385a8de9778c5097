// common/froxel_volumes.glsl — the volumetric fog's fog volumes (std430,
// binding 3: VolumeBlock of renderer/src/gpu_types.hpp in an array, the
// layout of common/volume.glsl; froxel.volumeCount of them, uploaded by
// froxel_pass.cpp) and the per-column chords of its mesh add volumes
// (std430, binding 1: kMeshChords vec2 per mesh volume and froxel column,
// written by mesh_volume_chords.glsl). Compute stages.
#ifndef AERIAL_FROXEL_VOLUMES_GLSL
#define AERIAL_FROXEL_VOLUMES_GLSL

#include "common/packed_volume.glsl"
layout(std430, binding = 3) readonly buffer Volumes { PackedVolume volumes[]; };

/// Chords kept per mesh volume and froxel column (kFroxelMeshChords in
/// renderer/src/gpu_types.hpp): (a, b) in the ray parameter t of
/// eye + t froxelFarRay (t = z/far), sorted, disjoint, in [0, 1]; unused
/// ones (0, 0).
const int kMeshChords = 8;

/// Index of the first chord of mesh volume `mesh` (the order of the mesh
/// volumes in Volumes) in froxel column (i, j).
int meshChordBase(int mesh, ivec2 ij) {
    return ((mesh * froxel.gridSize.y + ij.y) * froxel.gridSize.x + ij.x) * kMeshChords;
}

#endif
