// common/shadows.glsl — the cascaded shadow maps of the sun or the moon
// (renderer/src/shadow_map_pass.cpp builds them; shadow_depth.glsl draws
// them): which cascade a point falls in, and the filtered visibility of the
// casting light there.
//
// Inputs (std140, binding 5; mirrored by ShadowBlock in
// renderer/src/gpu_types.hpp with static_asserted offsets, filled by
// makeShadowBlock):
//   shadowFromWorld[k]  world [m] -> (u, v, depth) in [0, 1]^3 of layer k
//                       (orthographic along the light, depth 0 nearest it)
//   splitM[k]           view depth (along frame.forward) where cascade k ends [m]
//   texelM[k]           world size of one texel of cascade k [m]
//   depthPerM[k]        depth units per metre along the light
//   toLight             unit direction towards the casting light
//   castingLight        0 no shadows, 1 the sun casts, 2 the moon casts
//   cascadeCount, resolution (texels per side), blendFraction (share of a
//                       cascade's depth range blended into the next one)
// Texture: uShadowMap (unit 14), GL_DEPTH_COMPONENT32F 2D array with
//   GL_COMPARE_REF_TO_TEXTURE / GL_LEQUAL and GL_LINEAR: each texture() is
//   a bilinear 2 x 2 percentage-closer lookup.
//
// Filter: 3 x 3 such lookups one texel apart, averaged: a tent-weighted PCF
// whose footprint is 4 texels wide (+-2 texels), so the penumbra is 4
// texels of the cascade (texelM[k]) wide on a surface facing the light.
// Acne: the receiver is moved along its normal by kShadowNormalOffsetTexels
// texels before the lookup (enough for the +-2 texel footprint at any
// slope: the plane's own depth over 2 texels rises by at most 2 texels x
// tan(theta), the offset buys offset / cos(theta)), and the casters carry
// a slope-scaled polygon offset.
// Cascade blend: over the last blendFraction of a cascade's depth range the
// visibility moves linearly to the next cascade's, and over the last
// cascade's to 1 (no shadow beyond splitM[cascadeCount - 1]). Written as
// v + (w - v) t, so a fully lit point gives exactly 1.
#ifndef AERIAL_SHADOWS_GLSL
#define AERIAL_SHADOWS_GLSL

layout(std140, binding = 5) uniform ShadowBlock {
    mat4 shadowFromWorld[4];
    vec4 splitM;
    vec4 texelM;
    vec4 depthPerM;
    vec3 toLight;
    float castingLight;
    int cascadeCount;
    float resolution;
    float blendFraction;
    float padShadow;
} shadow;

#ifndef AERIAL_VERTEX_SHADER
layout(binding = 14) uniform sampler2DArrayShadow uShadowMap;

const float kShadowNormalOffsetTexels = 2.5;

/// Visibility 0..1 of the light at world point p in cascade k (3 x 3 PCF).
float shadowCascadeVisibility(int k, vec3 p) {
    vec3 s = (shadow.shadowFromWorld[k] * vec4(p, 1.0)).xyz;
    float reference = clamp(s.z, 0.0, 1.0);
    float texel = 1.0 / shadow.resolution;
    float sum = 0.0;
    for (int y = -1; y <= 1; ++y) {
        for (int x = -1; x <= 1; ++x) {
            sum += texture(uShadowMap, vec4(s.xy + vec2(x, y) * texel, float(k), reference));
        }
    }
    return sum / 9.0;
}

/// Visibility 0..1 of the casting light at world point p with unit normal n
/// (facing the viewer; vec3(0) for a point without a surface, such as a
/// fog particle). 1 beyond the last cascade.
float sceneShadowVisibility(vec3 p, vec3 n) {
    float depth = dot(p - frame.eye, frame.forward);
    int last = shadow.cascadeCount - 1;
    if (!(depth < shadow.splitM[last])) return 1.0;
    int k = 0;
    while (k < last && depth > shadow.splitM[k]) ++k;
    float v = shadowCascadeVisibility(k, p + n * (kShadowNormalOffsetTexels * shadow.texelM[k]));
    float start = k > 0 ? shadow.splitM[k - 1] : frame.nearDistance;
    float band = shadow.blendFraction * (shadow.splitM[k] - start);
    float t = band > 0.0 ? clamp((depth - (shadow.splitM[k] - band)) / band, 0.0, 1.0) : 0.0;
    if (t > 0.0) {
        float w = 1.0;
        if (k < last) w = shadowCascadeVisibility(k + 1, p + n * (kShadowNormalOffsetTexels * shadow.texelM[k + 1]));
        v = v + (w - v) * t;
    }
    return v;
}
#endif

#endif
