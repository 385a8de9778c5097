// common/volume.glsl — one fog volume's uniform block (VolumeBlock in
// renderer/src/gpu_types.hpp, std140, binding 1) and the ray / unit-shape
// intersection in object space, shared by fog_volume.glsl (analytic) and
// fog_volume_marched.glsl (the ray-marched reference of the benchmark).
// Requires common/frame.glsl.
#ifndef AERIAL_VOLUME_GLSL
#define AERIAL_VOLUME_GLSL

layout(std140, binding = 1) uniform VolumeBlock {
    mat4 worldFromObject;
    vec4 objectFromWorld0;
    vec4 objectFromWorld1;
    vec4 objectFromWorld2;
    vec4 positionOffset;
    vec4 gradientMode;
    vec4 colour;
} volume;

#ifndef AERIAL_VERTEX_SHADER
vec3 toObject(vec3 w) {
    return vec3(dot(volume.objectFromWorld0.xyz, w), dot(volume.objectFromWorld1.xyz, w),
                dot(volume.objectFromWorld2.xyz, w));
}

/// Entry and exit parameters of o + t d against the unit cube or unit
/// sphere (object space); tNear > tFar when missed.
vec2 intersectUnitShape(vec3 o, vec3 d) {
    if (volume.objectFromWorld0.w < 0.5) {
        // Slabs |o_i + t d_i| <= 1.
        float tNear = -3.0e38;
        float tFar = 3.0e38;
        for (int i = 0; i < 3; ++i) {
            if (abs(d[i]) > 1e-30) {
                float t1 = (-1.0 - o[i]) / d[i];
                float t2 = (1.0 - o[i]) / d[i];
                tNear = max(tNear, min(t1, t2));
                tFar = min(tFar, max(t1, t2));
            } else if (abs(o[i]) > 1.0) {
                return vec2(1.0, 0.0);
            }
        }
        return vec2(tNear, tFar);
    }
    // Unit sphere from the closest approach (no B^2 - AC cancellation).
    float a = dot(d, d);
    if (!(a > 0.0)) return vec2(1.0, 0.0);
    float tMid = -dot(o, d) / a;
    vec3 perp = o + tMid * d;
    float h = 1.0 - dot(perp, perp);
    if (!(h > 0.0)) return vec2(1.0, 0.0);
    float halfChord = sqrt(h / a);
    return vec2(tMid - halfChord, tMid + halfChord);
}
#endif

#endif
