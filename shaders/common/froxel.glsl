// common/froxel.glsl — the volumetric fog's grid (FroxelBlock, std140,
// binding 6; renderer/src/gpu_types.hpp) and its mapping, shared by the
// inject, integrate and apply stages (froxel_*.glsl).
//
// The grid (Wronski 2014, Hillaire 2015): gridSize.x x gridSize.y froxels of
// pixelsPerFroxel^2 pixels each, gridSize.z slices in view depth z (along
// frame.forward) from the eye to farM, exponentially distributed as Unreal's:
//   z(s) = z0 (exp(s ln(1 + farM / z0)) - 1),  s = k / slices in [0, 1],
// so z(0) = 0, z(1) = farM and a slice is ~ln(1 + farM/z0)/slices of its
// distance thick (dense near the eye, where shafts are seen).
// Froxel (i, j) takes the ray through pixel ((i + 0.5) pixelsPerFroxel,
// (j + 0.5) pixelsPerFroxel); slice k its segment z in [z(k/N), z((k+1)/N)].
// The integrated textures hold slices + 1 layers: layer k the light
// in-scattered and the transmittance from the eye to z(k/N) (layer 0: none).
#ifndef AERIAL_FROXEL_GLSL
#define AERIAL_FROXEL_GLSL

layout(std140, binding = 6) uniform FroxelBlock {
    ivec3 gridSize;        // froxels x, y, slices
    int volumeCount;       // fog volumes in the Volumes buffer (binding 3)
    float pixelsPerFroxel;
    float z0;              // [m] the exponential distribution's scale
    float farM;            // [m] view depth where the grid ends
    float logScale;        // ln(1 + farM / z0)
    float castIsMoon;      // 1: the moon is the light the shadows dim (the brighter), 0: the sun
    float sceneShadows;    // 1: the shadow maps dim it (ShadowBlock.castingLight > 0)
    float cloudShadows;    // 1: the cloud shadow map dims it (CloudBlock.shadowActive)
    float jitter;          // 0..1: where in each slice the light is sampled (0.5: its middle)
    float globalFog;       // 1: the global height fog is part of it
    float historyWeight;   // temporal: weight of this frame's visibility (1: no history)
    float padFroxel0;
    float padFroxel1;
    mat4 previousClipFromWorld;  // the history's view
    vec3 previousEye;
    float padPreviousEye;
    vec3 previousForward;
    float padPreviousForward;
    float customPhase;     // 1: the fog's own anisotropy for the casting light's part
    float anisotropy;      // its Cornette-Shanks g
    float noiseAmount;     // detail noise: density x (1 + amount (2 n - 1))
    float noiseScaleM;     // [m]
    vec3 noiseOffset;      // [m] the noise's drift
    float padNoise;
} froxel;

/// View depth [m] of slice coordinate s (0..1).
float froxelDepthAt(float s) { return froxel.z0 * (exp(s * froxel.logScale) - 1.0); }

/// Slice coordinate (0..1) of view depth z [m] (> 1 beyond the grid).
float froxelSliceAt(float z) { return log(1.0 + max(z, 0.0) / froxel.z0) / froxel.logScale; }

/// Ray from the eye to the far plane through the centre of froxel column (i, j).
vec3 froxelFarRay(ivec2 ij) {
    vec2 pixel = (vec2(ij) + 0.5) * froxel.pixelsPerFroxel;
    return farRayAtNdc(pixel * frame.viewportTexel * 2.0 - 1.0);
}

/// The fog colour L_fog(v, s) of a sight line of length s [m] in direction v
/// (aerial/fog_light.hpp; skyFogColour) split into the part the shadows dim
/// (the casting light's share of the lit fog, (1 - w) L_cast P(v.l, g)) and
/// the whole (capped as fogInScatterTransmittance). With the custom phase
/// the lit fog takes the fog's own anisotropy. With the cloud shadow in the
/// grid the casting light is dimmed per froxel (V) instead of by the clouds'
/// mean visibility.
void froxelFogColours(vec3 v, float s, out vec3 shadowable, out vec3 all) {
    float g = froxel.customPhase > 0.5 ? froxel.anisotropy : frame.mieAnisotropy;
    bool moon = froxel.castIsMoon > 0.5;
    float w = fogHorizonWeight(s);
    vec3 castLight = fogDirectLight(v, g, moon) * (froxel.cloudShadows > 0.5 ? 1.0 : frame.fogDirectVisibility);
    vec3 lit = castLight + frame.fogDirectVisibility * fogDirectLight(v, g, !moon) + fogSkyInScatter(v, g);
    vec3 sky = (1.0 - w) * lit;
    if (w > 0.0) sky += w * horizonFogColourFrom(horizonSkies(v), v);
    vec3 single = (1.0 - w) * castLight;
    vec3 capped = min(sky, vec3(frame.radianceCap));
    vec3 share = vec3(1.0);
    for (int c = 0; c < 3; ++c) share[c] = sky[c] > 0.0 ? capped[c] / sky[c] : 0.0;
    shadowable = single * share;
    all = capped;
}

#ifdef AERIAL_FRAGMENT_SHADER
layout(binding = 11) uniform sampler3D uFroxelLitSky;  // (sum T f W_sky V, T)
layout(binding = 12) uniform sampler3D uFroxelSky;     // (sum T f W_sky, 0)
layout(binding = 13) uniform sampler3D uFroxelOwn;     // (sum T f W_own, 0)

/// True when this frame's fog is volumetric (the FroxelBlock is zero otherwise).
bool froxelsActive() { return froxel.gridSize.x > 0; }

/// The volumetric fog between the eye and the point at view depth z [m] on
/// the ray eye + t farRay of the pixel at fragCoord, ready to composite as
/// fogInScatterTransmittance's answer (rgb = S, a = T: L <- L T + S): the
/// integrated grid at the pixel's screen position and depth (trilinear),
/// with the fog colours of the pixel's own direction and distance,
///   S = LitSky x L_cast(v) + Sky x (L_fog(v) - L_cast(v)) + Own,
/// and beyond the grid's far depth the global height fog in closed form
/// (unshadowed), behind the grid. The opaque pixels (froxel_apply.glsl),
/// transparent meshes and particles all fog through it.
vec4 froxelFog(vec2 fragCoord, float z, vec3 farRay) {
    vec3 v = normalize(farRay);
    float s = froxelSliceAt(z);
    float slices = float(froxel.gridSize.z);
    vec3 uvw = vec3(fragCoord / (froxel.pixelsPerFroxel * vec2(froxel.gridSize.xy)),
                    (min(s, 1.0) * slices + 0.5) / (slices + 1.0));
    vec4 litSky = texture(uFroxelLitSky, uvw);
    vec3 sky = texture(uFroxelSky, uvw).rgb;
    vec3 own = texture(uFroxelOwn, uvw).rgb;
    vec3 shadowable, all;
    float sightLength = z / frame.farDistance * length(farRay);  // to the point, for the horizon blend
    froxelFogColours(v, sightLength, shadowable, all);
    vec3 inScatter = litSky.rgb * shadowable + sky * max(all - shadowable, vec3(0.0)) + own;
    float transmittance = clamp(litSky.a, 0.0, 1.0);
    if (z > froxel.farM) {  // the global fog behind the grid, in closed form
        float start = froxel.farM / frame.farDistance;
        vec3 o = frame.eye + start * farRay;
        vec3 d = (z / frame.farDistance - start) * farRay;
        float tau = exponentialOpticalDepth(froxel.globalFog * frame.fogDensity, frame.fogFalloff,
                                            o.y - frame.fogBaseHeight, d.y, length(d));
        vec4 rest = fogInScatterTransmittance(frame.fogColourMode, frame.fogColour, v, sightLength, tau);
        inScatter += transmittance * rest.rgb;
        transmittance *= rest.a;
    }
    return vec4(min(inScatter, vec3(frame.radianceCap)), transmittance);
}
#endif

#endif
