// scene.glsl — the opaque scene pass: glTF metallic-roughness meshes (base
// colour factor and sRGB texture, metallic, roughness, alpha mask) lit by
// the sun and moon light that passes through the atmosphere, the sky and
// the emitters (common/shading.glsl); writes HDR colour and the normalised
// linear depth the fog passes read (Wenzel 2006, section 6.3). Meshes with
// alpha mode "blend" are drawn later by transparent.glsl.
//
// Inputs:
//   frame (common/frame.glsl): clipFromWorld, eye, forward, far; the lights'
//     direction and illuminance at the ground E_ground (rgb); groundAmbient
//     E_sky (rgb, cosine-weighted irradiance of the sky, under the cloud
//     deck, on an upward surface); the
//     sky tables (units 0..3) for specular sky reflections
//   ObjectBlock (common/object.glsl, binding 3): transform, material
//   uBaseColour (unit 5): base-colour texture (sRGB, mipmapped), when used
//   Emitters (std430 SSBO, binding 2): as in emitters.glsl
//   vertex attributes: position [m] (0), normal (1), object space;
//     TEXCOORD_0 (2)
// Outputs:
//   location 0: radiance = emission + the shading of common/shading.glsl
//     (exactly emission + base / pi (sum_lights E_ground max(n.l, 0) +
//     E_sky (0.5 + 0.5 n.y) + sum_emitters colour i max(n.l, 0) / (1 + a r^2))
//     for a non-metal with specular factor 0)
//   location 1: depth01 = dot(p - eye, forward) / far (linear eye depth
//     over the far distance)
//   Mask: fragments whose alpha (opacity x texture alpha) is below the
//   cutoff are discarded (colour and depth).
#include "common/frame.glsl"
#include "common/object.glsl"

#ifdef AERIAL_VERTEX_SHADER
void main() { transformObjectVertex(); }
#else
#include "common/atmosphere.glsl"
#include "common/sky_table.glsl"
#include "common/shading.glsl"

layout(location = 0) out vec4 outColour;
layout(location = 1) out float outDepth01;

void main() {
    Surface s = surfaceAt(vTexcoord);
    if (object.alphaMode > 0.5 && object.alphaMode < 1.5 && s.alpha < object.alphaCutoff) discard;
    vec3 diffuse, specular;
    shadeFragment(s, vWorld, vNormal, diffuse, specular);
    outColour = vec4(min(object.emission + diffuse + specular, vec3(frame.radianceCap)), 1.0);
    outDepth01 = dot(vWorld - frame.eye, frame.forward) / frame.farDistance;
}
#endif
