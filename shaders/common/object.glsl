// common/object.glsl — the per-mesh uniform block of the scene and
// transparent passes (ObjectBlock in renderer/src/gpu_types.hpp, std140,
// binding 3), and the vertex attributes of a scene mesh. Requires
// common/frame.glsl.
//
//   worldFromObject     object -> world [m]
//   normalFromObject    columns xyz: inverse transpose of the 3x3 part
//   albedo              rgb: base-colour factor (linear, 0..1; glTF
//                       baseColorFactor), a: opacity (baseColorFactor[3])
//   emission            rgb: emitted radiance; w: specular factor s (0..1,
//                       KHR_materials_specular: F0 = 0.04 s for non-metals)
//   material            x: metallic, y: perceptual roughness (0..1), z: alpha
//                       cutoff, w: alpha mode (0 opaque, 1 mask, 2 blend)
//   flags               x: 1 when the base-colour texture (unit 5) is used
//   boundsMin/Max       xyz: the mesh's world bounds [m] (transparent pass)
//   cornerFog[8]        transparent pass: fog of the volumes and emitters
//                       from the eye to each corner of the world bounds
//                       (rgb: in-scatter S, a: transmittance T; corner k at
//                       x = bit 0, y = bit 1, z = bit 2 of k; 0 = min, 1 = max)
#ifndef AERIAL_OBJECT_GLSL
#define AERIAL_OBJECT_GLSL

layout(std140, binding = 3) uniform ObjectBlock {
    mat4 worldFromObject;
    mat4 normalFromObject;
    vec4 albedo;
    vec4 emission;
    vec4 material;
    vec4 flags;
    vec4 boundsMin;
    vec4 boundsMax;
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
