// scene.glsl — the opaque scene pass: meshes lit by the sun and moon light
// that passes through the atmosphere, a sky ambient term and the emitters;
// writes HDR colour and the normalised linear depth the fog passes read
// (Wenzel 2006, section 6.3).
//
// Inputs:
//   frame (common/frame.glsl): clipFromWorld, eye, forward, far; the lights'
//     direction and illuminance at the ground E_ground (rgb); skyAmbient
//     E_sky (rgb, cosine-weighted sky irradiance on an upward surface)
//   ObjectBlock (std140, binding 3; ObjectBlock in renderer/src/gpu_types.hpp):
//     worldFromObject, normal matrix (columns xyz of normalFromObject),
//     albedo (rgb, 0..1), emission (rgb radiance)
//   Emitters (std430 SSBO, binding 2): as in emitters.glsl
//   vertex attributes: position [m] (0), normal (1), object space
// Outputs:
//   location 0: radiance = emission + albedo / pi * (sum_lights E_ground
//     max(n.l, 0) + E_sky (0.5 + 0.5 n.y) + sum_emitters colour i
//     max(n.l, 0) / (1 + a r^2) [emitters: i read as irradiance per 1/m])
//   location 1: depth01 = dot(p - eye, forward) / far (linear eye depth
//     over the far distance)
#include "common/frame.glsl"

layout(std140, binding = 3) uniform ObjectBlock {
    mat4 worldFromObject;
    mat4 normalFromObject;
    vec4 albedo;
    vec4 emission;
} object;

#ifdef AERIAL_VERTEX_SHADER
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
out vec3 vWorld;
out vec3 vNormal;

void main() {
    vec4 world = object.worldFromObject * vec4(aPosition, 1.0);
    vWorld = world.xyz;
    vNormal = mat3(object.normalFromObject) * aNormal;
    gl_Position = frame.clipFromWorld * world;
}
#else
#include "common/atmosphere.glsl"

struct EmitterGpu {
    vec4 positionIntensity;
    vec4 colourAttenuation;
};
layout(std430, binding = 2) readonly buffer EmitterBlock { EmitterGpu emitters[]; };

in vec3 vWorld;
in vec3 vNormal;
layout(location = 0) out vec4 outColour;
layout(location = 1) out float outDepth01;

void main() {
    vec3 n = normalize(vNormal);
    if (!gl_FrontFacing) n = -n;
    vec3 irradiance = frame.sunIlluminance.rgb * max(dot(n, frame.sunDirection.xyz), 0.0) +
                      frame.moonIlluminance.rgb * max(dot(n, frame.moonDirection.xyz), 0.0) +
                      frame.skyAmbient.rgb * (0.5 + 0.5 * n.y);
    for (int k = 0; k < frame.counts.x; ++k) {
        vec3 toLight = emitters[k].positionIntensity.xyz - vWorld;
        float r2 = dot(toLight, toLight);
        float falloff = emitters[k].positionIntensity.w / (1.0 + max(emitters[k].colourAttenuation.w, 0.0) * r2);
        irradiance += emitters[k].colourAttenuation.rgb * falloff * max(dot(n, toLight) * inversesqrt(max(r2, 1e-12)), 0.0);
    }
    outColour = vec4(min(object.emission.rgb + object.albedo.rgb / kPi * irradiance, vec3(frame.fogColour.w)), 1.0);
    outDepth01 = dot(vWorld - frame.eyeFar.xyz, frame.forwardNear.xyz) / frame.eyeFar.w;
}
#endif
