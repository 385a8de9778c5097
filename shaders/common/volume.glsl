// common/volume.glsl — one fog volume's uniform block (VolumeBlock in
// renderer/src/gpu_types.hpp, std140, binding 1), its hull's vertex, the
// scene depth (uLinearDepth, unit 4) and the ray / unit-shape intersection
// in object space, shared by fog_volume.glsl (analytic) and
// fog_volume_marched.glsl (the ray-marched reference of the benchmark).
// Requires common/frame.glsl.
#ifndef AERIAL_VOLUME_GLSL
#define AERIAL_VOLUME_GLSL

#include "common/unit_shape.glsl"

layout(std140, binding = 1) uniform VolumeBlock {
    mat4 worldFromObject;      // the hull: position + rotation * halfExtents
    vec3 objectFromWorldRow0;  // rows of objectFromWorld = S^-1 R^T
    float shape;               // 0 box, 1 ellipsoid
    vec3 objectFromWorldRow1;
    float density;             // b_v [1/m]
    vec3 objectFromWorldRow2;
    float falloff;             // c_v [1/m]
    vec3 position;             // centre [m]
    float gradientOffset;      // [m]
    vec3 gradientDirection;    // unit g
    float colourMode;          // 0 sky, 1 tinted, 2 custom
    vec3 colour;
    float blend;                // 0 add, 1 subtract
    float edgeSoftness;         // sigma 0..1 (0 hard; common/soft_volume.glsl)
    float padSoftness0;
    float padSoftness1;
    float padSoftness2;
} volume;

#ifdef AERIAL_VERTEX_SHADER
layout(location = 0) in vec3 aPosition;  // unit cube corner, object space

/// Writes gl_Position of this corner of the hull.
void transformHullVertex() {
    gl_Position = frame.clipFromWorld * (volume.worldFromObject * vec4(aPosition, 1.0));
}

/// Writes gl_Position of this vertex of the volume's mesh (the hull's
/// transform) and returns the vertex relative to the eye [m], world.
vec3 transformMeshVertex() {
    vec4 world = volume.worldFromObject * vec4(aPosition, 1.0);
    gl_Position = frame.clipFromWorld * world;
    return world.xyz - frame.eye;
}
#else
layout(binding = 4) uniform sampler2D uLinearDepth;  // normalised linear eye depth z/far

vec3 toObject(vec3 w) {
    return vec3(dot(volume.objectFromWorldRow0, w), dot(volume.objectFromWorldRow1, w),
                dot(volume.objectFromWorldRow2, w));
}

/// Entry and exit parameters of o + t d against the unit cube or unit
/// sphere (object space) of this volume's shape; tNear > tFar when missed.
vec2 intersectUnitShape(vec3 o, vec3 d) { return unitShapeHit(volume.shape, o, d); }

/// The fragment's ray eye + t farRay (t in [0, 1] to the far plane) clipped
/// to the hull and to the scene point at t = depth01 (uLinearDepth; the
/// viewer may stand inside, geometry inside the volume ends it): the segment
/// [tIn, tOut]; false when it is empty.
bool clipFragmentRay(out vec3 eye, out vec3 farRay, out float tIn, out float tOut) {
    float depth01 = texelFetch(uLinearDepth, ivec2(gl_FragCoord.xy), 0).r;
    farRay = farRayAtFragment(gl_FragCoord.xy);
    eye = frame.eye;
    vec2 hit = intersectUnitShape(toObject(eye - volume.position), toObject(farRay));
    tIn = max(hit.x, 0.0);
    tOut = min(hit.y, depth01);
    return tIn < tOut;
}
#endif

#endif
