// shadow_depth.glsl — the cascaded shadow maps' depth pass
// (renderer/src/shadow_map_pass.cpp): the opaque and alpha-masked meshes
// seen along the sun or moon, one cascade per draw loop, depth only.
//
// Inputs:
//   ShadowBlock (common/shadows.glsl, binding 5): shadowFromWorld[uCascade]
//   uCascade (location 0): the cascade (layer) being drawn
//   ObjectBlock (common/object.glsl, binding 3): transform, opacity, alpha
//     mode and cutoff, baseColourTextured
//   uBaseColour (unit 5): the base-colour texture (its alpha, linear)
//   vertex attributes as scene.glsl
// Output: depth = the point's depth along the light, (u, v, depth) of
//   shadowFromWorld mapped to clip space (orthographic: w = 1); depth clamp
//   keeps casters nearer the light than the layer's range at depth 0.
//   Masked meshes discard where opacity x texture alpha < cutoff, exactly
//   as scene.glsl, so a fence casts the shadow of its boards.
#include "common/frame.glsl"
#include "common/object.glsl"
#include "common/shadows.glsl"

layout(location = 0) uniform int uCascade;

#ifdef AERIAL_VERTEX_SHADER
void main() {
    vec4 world = object.worldFromObject * vec4(aPosition, 1.0);
    vWorld = world.xyz;
    vNormal = vec3(0.0);
    vTexcoord = aTexcoord;
    vec3 s = (shadow.shadowFromWorld[uCascade] * world).xyz;
    gl_Position = vec4(s * 2.0 - 1.0, 1.0);
}
#else
layout(binding = 5) uniform sampler2D uBaseColour;

void main() {
    if (object.alphaMode > 0.5 && object.alphaMode < 1.5) {
        float alpha = object.opacity;
        if (object.baseColourTextured > 0.5) alpha *= texture(uBaseColour, vTexcoord).a;
        if (clamp(alpha, 0.0, 1.0) < object.alphaCutoff) discard;
    }
}
#endif
