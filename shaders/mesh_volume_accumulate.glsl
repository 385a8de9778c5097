// mesh_volume_accumulate.glsl — a mesh add volume, step 1 of 2: every
// triangle of its mesh (culling off, depth test off, depth clamp on so
// faces beyond the far plane still count) adds to an RG32F target, with
// additive blending, per fragment
//   R += s F(clamp(t, 0, depth01)),  G += s,
// s = +1 on a back face (the ray leaves the mesh) and -1 on a front face
// (it enters), t the fragment's ray parameter (z/far), F of
// common/mesh_volume.glsl (density, subtract union cut out). Faces behind
// the eye are clipped away; the composite accounts for them through G.
// DESIGN.md "Mesh and subtract volumes"; seed 001 (polygonal fog volumes).
//
// Inputs:
//   frame (common/frame.glsl): clipFromWorld, eye, forward, farDistance,
//     far-plane corner rays
//   VolumeBlock (common/volume.glsl, binding 1): worldFromObject (position
//     + rotation * halfExtents), density, falloff, gradient, position
//   aPosition (location 0): mesh vertex, object space (the FogMesh's)
//   uLinearDepth (unit 4), SubtractIntervals (storage 4, when active)
// Output (location 0): vec2(s F, s), blended GL_ONE, GL_ONE.
#include "common/frame.glsl"
#include "common/volume.glsl"

#ifdef AERIAL_VERTEX_SHADER
out vec3 vRelative;  // vertex - eye [m], world

void main() { vRelative = transformMeshVertex(); }
#else
#include "common/atmosphere.glsl"
#include "common/subtract.glsl"
#include "common/mesh_volume.glsl"

in vec3 vRelative;
layout(location = 0) out vec2 outAccumulation;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    float depth01 = texelFetch(uLinearDepth, pixel, 0).r;
    vec3 farRay = farRayAtFragment(gl_FragCoord.xy);
    float t = clamp(dot(vRelative, frame.forward) / frame.farDistance, 0.0, depth01);
    float s = gl_FrontFacing ? -1.0 : 1.0;
    float f = meshVolumeAntiderivative(pixel, farRay, meshVolumeReference(farRay), t);
    outAccumulation = vec2(s * f, s);
}
#endif
