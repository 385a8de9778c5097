// subtract_crossings.glsl — the mesh subtract volumes' crossings per pixel
// (DESIGN.md "Mesh and subtract volumes"): every triangle of every mesh
// subtract volume is rasterised (culling off, depth test off, depth clamp
// on so faces beyond the far plane count, colour writes off); each fragment
// appends its ray parameter t = z/far and whether it enters (front face)
// or leaves (back face) to its pixel's list, unsorted. Faces behind the eye
// are clipped away: subtract_resolve.glsl recovers how many meshes hold the
// eye from the signs in front (a closed mesh's signs sum to 0).
//
// Inputs:
//   frame (common/frame.glsl): clipFromWorld, eye, forward, farDistance,
//     viewportSize
//   VolumeBlock (common/volume.glsl, binding 1): worldFromObject
//   aPosition (location 0): mesh vertex, object space
// Output (fragment stage, storage):
//   SubtractCounts (std430, binding 6): [2 + pixel] += 1 (atomic)
//   SubtractCrossings (std430, binding 7): [pixel * 16 + slot] = the bits
//     of t with the lowest bit replaced by 1 for an entry, 0 for an exit;
//     crossings beyond 16 a pixel are dropped (the resolve counts them).
#include "common/frame.glsl"
#include "common/volume.glsl"

#ifdef AERIAL_VERTEX_SHADER
out vec3 vRelative;  // vertex - eye [m], world

void main() { vRelative = transformMeshVertex(); }
#else
const uint kSubtractCrossings = 16u;  // kSubtractCrossings in gpu_types.hpp

layout(std430, binding = 6) buffer SubtractCounts { uint subtractCounts[]; };
layout(std430, binding = 7) writeonly buffer SubtractCrossings { uint subtractCrossings[]; };

in vec3 vRelative;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    uint index = uint(pixel.y * int(frame.viewportSize.x) + pixel.x);
    float t = max(dot(vRelative, frame.forward) / frame.farDistance, 0.0);
    uint slot = atomicAdd(subtractCounts[2u + index], 1u);
    if (slot < kSubtractCrossings) {
        subtractCrossings[index * kSubtractCrossings + slot] =
            (floatBitsToUint(t) & ~1u) | (gl_FrontFacing ? 1u : 0u);
    }
}
#endif
