// mesh_volume_chords.glsl — the volumetric fog's mesh add volumes (compute,
// one invocation per froxel column; DESIGN.md "Mesh and subtract volumes"):
// the ray through the column's centre (froxelFarRay, as froxel_inject.glsl)
// against every triangle of one mesh volume in object space (Möller-Trumbore,
// brute force: meant for the meshes of fog volumes, a few thousand
// triangles), the crossings sorted and turned into chords by a running
// count (entries where the ray goes against the outward normal), the count
// at the eye from the crossings behind it. froxel_inject.glsl integrates the
// volume's density over each slice's part of the chords.
//
// Inputs:
//   frame (common/frame.glsl), FroxelBlock (common/froxel.glsl: gridSize,
//     pixelsPerFroxel)
//   Volumes (common/froxel_volumes.glsl, binding 3): the volume uVolume
//     (objectFromWorld rows, position)
//   uVolume (location 0), uMesh (location 1: its order among the mesh
//     volumes), uTriangleCount (location 2)
//   MeshPositions (std430, binding 6): the mesh's object-space positions,
//     3 floats each; MeshIndices (std430, binding 7): 3 per triangle
// Output: MeshChords (std430, binding 1), kMeshChords (8) per column from
//   meshChordBase(uMesh, column): (a, b) in t = z/far, clipped to [0, 1];
//   beyond 16 crossings in front of the eye the rest are dropped, beyond 8
//   chords the 8th is extended over the rest.
#include "common/frame.glsl"
#include "common/atmosphere.glsl"
#include "common/froxel.glsl"
#include "common/froxel_volumes.glsl"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(location = 0) uniform int uVolume;
layout(location = 1) uniform int uMesh;
layout(location = 2) uniform int uTriangleCount;

layout(std430, binding = 6) readonly buffer MeshPositions { float meshPositions[]; };
layout(std430, binding = 7) readonly buffer MeshIndices { uint meshIndices[]; };
layout(std430, binding = 1) writeonly buffer MeshChords { vec2 meshChords[]; };

const int kCrossings = 16;

vec3 meshVertex(uint index) {
    return vec3(meshPositions[3u * index], meshPositions[3u * index + 1u], meshPositions[3u * index + 2u]);
}

void main() {
    ivec2 ij = ivec2(gl_GlobalInvocationID.xy);
    if (ij.x >= froxel.gridSize.x || ij.y >= froxel.gridSize.y) return;
    PackedVolume fv = volumes[uVolume];
    vec3 farRay = froxelFarRay(ij);
    vec3 rel = frame.eye - fv.position;
    vec3 o = vec3(dot(fv.objectFromWorldRow0, rel), dot(fv.objectFromWorldRow1, rel),
                  dot(fv.objectFromWorldRow2, rel));
    vec3 d = vec3(dot(fv.objectFromWorldRow0, farRay), dot(fv.objectFromWorldRow1, farRay),
                  dot(fv.objectFromWorldRow2, farRay));

    float crossingT[kCrossings];
    int crossingStep[kCrossings];  // +1 entry, -1 exit
    int count = 0;
    int inside = 0;  // the count at the eye: the steps of the crossings behind it
    for (int k = 0; k < uTriangleCount; ++k) {
        vec3 a = meshVertex(meshIndices[3 * k]);
        vec3 e1 = meshVertex(meshIndices[3 * k + 1]) - a;
        vec3 e2 = meshVertex(meshIndices[3 * k + 2]) - a;
        vec3 p = cross(d, e2);
        float det = dot(e1, p);  // = -dot(d, outward normal): > 0 on an entry
        if (det == 0.0) continue;
        float inv = 1.0 / det;
        vec3 s = o - a;
        float u = dot(s, p) * inv;
        if (u < 0.0 || u > 1.0) continue;
        vec3 q = cross(s, e1);
        float v = dot(d, q) * inv;
        if (v < 0.0 || u + v > 1.0) continue;
        float t = dot(e2, q) * inv;
        int step = det > 0.0 ? 1 : -1;
        if (t <= 0.0) {
            inside += step;
        } else if (count < kCrossings) {
            crossingT[count] = t;
            crossingStep[count] = step;
            ++count;
        }
    }
    for (int i = 1; i < count; ++i) {  // insertion sort by t
        float t = crossingT[i];
        int step = crossingStep[i];
        int j = i - 1;
        while (j >= 0 && crossingT[j] > t) {
            crossingT[j + 1] = crossingT[j];
            crossingStep[j + 1] = crossingStep[j];
            --j;
        }
        crossingT[j + 1] = t;
        crossingStep[j + 1] = step;
    }
    vec2 chords[kMeshChords];
    for (int k = 0; k < kMeshChords; ++k) chords[k] = vec2(0.0);
    int chordCount = 0;
    int depth = max(inside, 0);
    float start = 0.0;
    for (int i = 0; i <= count; ++i) {
        bool end = i == count;
        float t = end ? 1.0 : min(crossingT[i], 1.0);
        int before = depth;
        depth = end ? 0 : max(depth + crossingStep[i], 0);
        if (before == 0 && depth > 0) {
            start = t;
        } else if (before > 0 && depth == 0 && t > start) {
            if (chordCount < kMeshChords) {
                chords[chordCount++] = vec2(start, t);
            } else {
                chords[kMeshChords - 1].y = t;  // merged into the last
            }
        }
    }
    int base = meshChordBase(uMesh, ij);
    for (int k = 0; k < kMeshChords; ++k) meshChords[base + k] = chords[k];
}
