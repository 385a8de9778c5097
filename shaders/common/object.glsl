// common/object.glsl — the per-mesh uniform block of the scene and
// transparent passes (ObjectBlock in renderer/src/gpu_types.hpp, std140,
// binding 3), and the vertex attributes of a scene mesh. Requires
// common/frame.glsl.
//
//   worldFromObject     object -> world [m]
//   normalFromObject    columns xyz: inverse transpose of the 3x3 part
//   albedo              base-colour factor (linear, 0..1; glTF
//                       baseColorFactor); opacity: baseColorFactor[3]
//   emission            emitted radiance; specularFactor: s (0..1,
//                       KHR_materials_specular: F0 = 0.04 s for non-metals)
//   metallic, roughness (perceptual), 0..1; alphaCutoff; alphaMode (0
//                       opaque, 1 mask, 2 blend)
//   baseColourTextured  1 when the base-colour texture (unit 5) is used
//   boundsMin/Max       the mesh's world bounds [m] (transparent pass)
//   cornerFog[8]        transparent pass: fog of the volumes and emitters
//                       from the eye to each corner of the world bounds
//                       (rgb: in-scatter S, a: transmittance T; corner k at
//                       x = bit 0, y = bit 1, z = bit 2 of k; 0 = min, 1 = max)
#ifndef AERIAL_OBJECT_GLSL
#define AERIAL_OBJECT_GLSL

layout(std140, binding = 3) uniform ObjectBlock {
    mat4 worldFromObject;
    mat4 normalFromObject;
    vec3 albedo;
    float opacity;
    vec3 emission;
    float specularFactor;
    float metallic;
    float roughness;
    float alphaCutoff;
    float alphaMode;
    float baseColourTextured;
    float padFlags0;
    float padFlags1;
    float padFlags2;
    vec3 boundsMin;
    float padBoundsMin;
    vec3 boundsMax;
    float padBoundsMax;
    vec4 cornerFog[8];
} object;

// The vertex attributes of a scene mesh (position [m] and normal in object
// space, TEXCOORD_0) and what the vertex stage passes on (world space).
#ifdef AERIAL_VERTEX_SHADER
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aTexcoord;
out vec3 vWorld;
out vec3 vNormal;
out vec2 vTexcoord;

/// Writes vWorld, vNormal, vTexcoord and gl_Position of this vertex;
/// returns its world position.
vec4 transformObjectVertex() {
    vec4 world = object.worldFromObject * vec4(aPosition, 1.0);
    vWorld = world.xyz;
    vNormal = mat3(object.normalFromObject) * aNormal;
    vTexcoord = aTexcoord;
    gl_Position = frame.clipFromWorld * world;
    return world;
}
#else
in vec3 vWorld;
in vec3 vNormal;
in vec2 vTexcoord;
#endif

#endif
