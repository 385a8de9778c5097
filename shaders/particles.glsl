// particles.glsl — soft fog particles: camera-facing sprites (in the view
// plane) of a particle fog source, faded by the scene depth so they never
// show a hard line where they cut geometry (soft particles; Lorach 2007).
//
// Inputs:
//   frame (common/frame.glsl): far-plane corner rays (the camera's right and
//     up axes), eye, forward, near, far, lights, sky ambient, global fog
//   per instance (divisor 1): location 0: centre [m] (xyz), radius [m] (w);
//     location 1: single-scattering albedo (rgb), peak opacity (w);
//     location 2: emitted radiance (rgb), fade distance [m] (w);
//     location 3: the fog of the volumes and emitters from the eye to the
//     centre, from the CPU query (FogScene without the global fog): rgb S',
//     a T'
//   uLinearDepth (unit 4): normalised linear eye depth of the scene
//   Emitters (std430 SSBO, binding 2)
//   gl_VertexID 0..3: the corners of the sprite (triangle strip)
// Output (location 0), premultiplied, blended with
//   glBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE):
//   coverage alpha = opacity (1 - r^2)^2 (r = distance from the centre over
//     the radius, 0 outside) x fade x nearFade, with
//     fade = saturate((sceneDepth - spriteDepth) / fadeDistance),
//     nearFade = saturate((spriteDepth - near) / fadeDistance),
//     depths = linear eye depths [m] (the sprite's is constant: it lies in
//     the view plane);
//   radiance of the medium (isotropic phase 1/(4 pi)):
//     L = albedo (E_sun + E_moon + sum_emitters colour e / (1 + a r_e^2)) / (4 pi)
//         + albedo E_sky / (2 pi) + emission,
//   fogged as transparent.glsl: the global height fog (optical depth per
//   vertex, or per fragment without the subtract union when subtract volumes
//   are active; colour per fragment), then the volumes and emitters from the CPU
//   (one query per sprite, at its centre):
//   rgb = alpha ((L T_g + S_g) T' + S'), a = alpha.
#include "common/frame.glsl"
#include "common/atmosphere.glsl"

#ifdef AERIAL_VERTEX_SHADER
layout(location = 0) in vec4 aCentreRadius;
layout(location = 1) in vec4 aAlbedoOpacity;
layout(location = 2) in vec4 aEmissionFade;
layout(location = 3) in vec4 aLocalFog;
out vec2 vCorner;
out vec3 vWorld;
flat out float vSpriteDepth;
flat out vec4 vAlbedoOpacity;
flat out vec4 vEmissionFade;
flat out vec4 vLocalFog;
out float vGlobalTau;  // optical depth of the global fog, eye -> vertex

void main() {
    vec2 corner = vec2((gl_VertexID & 1) == 1 ? 1.0 : -1.0, (gl_VertexID & 2) == 2 ? 1.0 : -1.0);
    vec3 right = normalize(frame.farCornerRays[1].xyz - frame.farCornerRays[0].xyz);
    vec3 up = normalize(frame.farCornerRays[2].xyz - frame.farCornerRays[0].xyz);
    vec3 world = aCentreRadius.xyz + aCentreRadius.w * (corner.x * right + corner.y * up);
    vCorner = corner;
    vWorld = world;
    vSpriteDepth = dot(aCentreRadius.xyz - frame.eye, frame.forward);
    vAlbedoOpacity = aAlbedoOpacity;
    vEmissionFade = aEmissionFade;
    vLocalFog = aLocalFog;
    vGlobalTau = globalFogOpticalDepth(world - frame.eye);
    gl_Position = frame.clipFromWorld * vec4(world, 1.0);
}
#else
#include "common/emitters.glsl"
#include "common/clouds.glsl"
#include "common/shadows.glsl"
#include "common/froxel.glsl"
#include "common/subtract.glsl"
layout(binding = 4) uniform sampler2D uLinearDepth;

in vec2 vCorner;
in vec3 vWorld;
flat in float vSpriteDepth;
flat in vec4 vAlbedoOpacity;
flat in vec4 vEmissionFade;
flat in vec4 vLocalFog;
in float vGlobalTau;
layout(location = 0) out vec4 outColour;

void main() {
    float r2 = dot(vCorner, vCorner);
    if (!(r2 < 1.0)) discard;
    float profile = (1.0 - r2) * (1.0 - r2);
    float sceneDepth = texelFetch(uLinearDepth, ivec2(gl_FragCoord.xy), 0).r * frame.farDistance;
    float fadeDistance = max(vEmissionFade.w, 1e-4);
    float fade = clamp((sceneDepth - vSpriteDepth) / fadeDistance, 0.0, 1.0) *
                 clamp((vSpriteDepth - frame.nearDistance) / fadeDistance, 0.0, 1.0);
    float alpha = clamp(vAlbedoOpacity.w, 0.0, 1.0) * profile * fade;
    if (!(alpha > 0.0)) discard;
    vec3 sunE = frame.sunIlluminance;
    vec3 moonE = frame.moonIlluminance;
    if (shadow.castingLight > 0.5) {  // the scene's shadow maps at the sprite's point (no normal offset)
        float visibility = sceneShadowVisibility(vWorld, vec3(0.0));
        if (shadow.castingLight < 1.5) {
            sunE *= visibility;
        } else {
            moonE *= visibility;
        }
    }
    vec3 irradiance = sunE + moonE;
    if (clouds.shadowActive > 0.5) irradiance *= cloudShadowVisibility(vWorld);  // cloud shadow
    for (int k = 0; k < frame.emitterCount; ++k) {
        vec3 toLight = emitters[k].position - vWorld;
        irradiance += emitters[k].colour * emitters[k].light.x * emitterDimming(k, vWorld) /
                      (1.0 + max(emitters[k].attenuation, 0.0) * dot(toLight, toLight));
    }
    vec3 albedo = clamp(vAlbedoOpacity.rgb, 0.0, 1.0);
    vec3 radiance = albedo * irradiance / (4.0 * kPi) + albedo * frame.groundAmbient / (2.0 * kPi) +
                    max(vEmissionFade.rgb, vec3(0.0));
    vec3 fogged;
    if (froxelsActive()) {  // the volumetric fog's grid at the fragment (common/froxel.glsl)
        vec4 fog = froxelFog(gl_FragCoord.xy, vSpriteDepth, farRayAtFragment(gl_FragCoord.xy));
        fogged = radiance * fog.a + fog.rgb;
    } else {
        // With subtract volumes, per fragment along the pixel's ray without their union.
        float globalTau =
            frame.subtractActive != 0 ? maskedGlobalFogDepthTo(ivec2(gl_FragCoord.xy), vWorld) : vGlobalTau;
        vec4 globalFog = globalFogTowards(vWorld - frame.eye, globalTau);
        fogged = radiance * globalFog.a + globalFog.rgb;
        fogged = fogged * vLocalFog.a + vLocalFog.rgb;
    }
    outColour = vec4(min(alpha * fogged, vec3(frame.radianceCap)), alpha);
}
#endif
