// froxel_inject.glsl — volumetric fog, stage 1 (compute): inject the
// medium and light every froxel (common/froxel.glsl for the grid).
//
// Per froxel, along the ray through its centre over its slice's segment
// o -> o + d (view depth z(k/N) .. z((k+1)/N)), everything in closed form so
// that the slice count only decides where the light is sampled:
//   tau          optical depth of the global height fog and every add
//                volume over the segment (the analytic integrals of
//                DESIGN.md "Global height fog" / "Fog volumes"; a mesh one
//                over the segment's parts of its chords)
//   W_sky (rgb)  sum of tau_i x tint_i over the media coloured by the sky
//                (colour mode sky: tint 1; tinted: the tint)
//   W_own (rgb)  sum of tau_i x colour_i over the media of a custom colour,
//                plus every emitter's exact in-scatter integral over the
//                segment (emitters.glsl's closed form)
//   V            visibility of the casting light (sun, or the moon when
//                brighter) at the sample point z(k + jitter)/N: the cascaded
//                shadow maps (one filtered comparison) x the cloud shadow
//                map (1 where they are off)
// Temporal (FroxelSettings::temporal): the sample point moves through the
// slice from frame to frame (froxel.jitter) and V is blended with the
// previous frame's V at the same world point (reprojected into the previous
// grid: its clip transform, eye and forward axis), V = mix(V_prev, V,
// historyWeight); the renderer sets the weight to 1 (no history) when the
// time, the camera or the grid jumps (froxel_pass.cpp), so nothing ghosts.
// Subtract volumes: a froxel whose sample point p lies inside one holds
// neither the global fog nor any added volume (the whole slice segment, a
// froxel's resolution of the cut). Box and ellipsoid ones (blend 1 in the
// volume array) test p itself; mesh ones (frame.subtractActive) through
// the subtract union of the pixel at the froxel's centre
// (common/subtract.glsl, written by subtract_pass.cpp; they end at that
// pixel's scene depth, and a sample beyond it takes the scene point's
// answer). Mesh add volumes are not in the volumetric fog (the
// renderer does not pass them).
// Output: image 0 = (W_sky, tau), image 1 = (W_own, V), RGBA32F, one texel
// per froxel (x, y, slice); image 2 = V (R32F), the next frame's history.
#include "common/frame.glsl"
#include "common/atmosphere.glsl"
#include "common/froxel.glsl"
#include "common/emitters.glsl"
#include "common/shadows.glsl"
#include "common/clouds.glsl"
#include "common/soft_volume.glsl"
#include "common/unit_shape.glsl"
#include "common/subtract.glsl"
#include "common/froxel_volumes.glsl"

layout(std430, binding = 1) readonly buffer MeshChords { vec2 meshChords[]; };

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(rgba32f, binding = 0) uniform writeonly image3D uMedium;  // (W_sky, tau)
layout(rgba32f, binding = 1) uniform writeonly image3D uLight;   // (W_own, V)
layout(r32f, binding = 2) uniform writeonly image3D uHistoryOut;  // V for the next frame
layout(binding = 15) uniform sampler3D uHistory;                  // the previous frame's V
layout(binding = 4) uniform sampler2D uLinearDepth;               // normalised linear depth z/far



/// Adds a medium of optical depth tau and colour mode/colour to the sums.
void addMedium(float tau, float mode, vec3 colour, inout vec3 wSky, inout vec3 wOwn) {
    if (mode > 1.5) {
        wOwn += tau * colour;
    } else {
        wSky += tau * (mode > 0.5 ? colour : vec3(1.0));
    }
}

/// Visibility of the casting light at p from the shadow maps: one
/// hardware-filtered comparison (2 x 2 texels) in the cascade of p's view
/// depth, none beyond the last (a froxel is wider than the 3 x 3 PCF kernel
/// of sceneShadowVisibility, which costs nine).
float froxelShadowVisibility(vec3 p) {
    float depth = dot(p - frame.eye, frame.forward);
    int last = shadow.cascadeCount - 1;
    if (!(depth < shadow.splitM[last])) return 1.0;
    int k = 0;
    while (k < last && depth > shadow.splitM[k]) ++k;
    vec3 s = (shadow.shadowFromWorld[k] * vec4(p, 1.0)).xyz;
    return texture(uShadowMap, vec4(s.xy, float(k), clamp(s.z, 0.0, 1.0)));
}

/// A hash of an integer lattice point to 0..1 (PCG-style mixing; the
/// lattice repeats every 256 cells, so the drift is reduced modulo 256
/// cells on the CPU).
float latticeValue(ivec3 c) {
    uvec3 u = uvec3(c & 255);
    uint h = u.x * 0x8da6b343u ^ u.y * 0xd8163841u ^ u.z * 0xcb1ab31fu;
    h ^= h >> 16;
    h *= 0x7feb352du;
    h ^= h >> 15;
    h *= 0x846ca68bu;
    h ^= h >> 16;
    return float(h) * (1.0 / 4294967295.0);
}

/// Smooth 3D value noise in 0..1 (quintic interpolation of the lattice).
float detailNoise(vec3 x) {
    vec3 cell = floor(x);
    vec3 f = x - cell;
    vec3 w = f * f * f * (f * (f * 6.0 - 15.0) + 10.0);
    ivec3 c = ivec3(cell);
    float n000 = latticeValue(c), n100 = latticeValue(c + ivec3(1, 0, 0));
    float n010 = latticeValue(c + ivec3(0, 1, 0)), n110 = latticeValue(c + ivec3(1, 1, 0));
    float n001 = latticeValue(c + ivec3(0, 0, 1)), n101 = latticeValue(c + ivec3(1, 0, 1));
    float n011 = latticeValue(c + ivec3(0, 1, 1)), n111 = latticeValue(c + ivec3(1, 1, 1));
    return mix(mix(mix(n000, n100, w.x), mix(n010, n110, w.x), w.y),
               mix(mix(n001, n101, w.x), mix(n011, n111, w.x), w.y), w.z);
}

void main() {
    ivec3 id = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(id, froxel.gridSize))) return;
    vec3 farRay = froxelFarRay(id.xy);
    float za = froxelDepthAt(float(id.z) / float(froxel.gridSize.z));
    float zb = froxelDepthAt(float(id.z + 1) / float(froxel.gridSize.z));
    vec3 o = frame.eye + (za / frame.farDistance) * farRay;
    vec3 d = ((zb - za) / frame.farDistance) * farRay;
    float len = length(d);

    vec3 p = o + froxel.jitter * d;  // where this slice's light (and noise) is sampled
    vec3 wSky = vec3(0.0), wOwn = vec3(0.0);
    bool cut = false;  // p inside a subtract volume
    for (int v = 0; v < froxel.volumeCount && !cut; ++v) {
        PackedVolume fv = volumes[v];
        if (fv.blend < 0.5) continue;
        vec3 rel = p - fv.position;
        vec3 q = vec3(dot(fv.objectFromWorldRow0, rel), dot(fv.objectFromWorldRow1, rel),
                      dot(fv.objectFromWorldRow2, rel));
        cut = fv.shape < 0.5 ? all(lessThanEqual(abs(q), vec3(1.0))) : dot(q, q) <= 1.0;
    }
    if (frame.subtractActive != 0 && !cut) {  // the mesh subtract volumes, per pixel
        ivec2 pixel = min(ivec2((vec2(id.xy) + 0.5) * froxel.pixelsPerFroxel), ivec2(frame.viewportSize) - 1);
        vec4 first, second;
        pixelSubtractIntervals(pixel, first, second);
        // Beyond the pixel's scene point (the intervals end there) p counts
        // as inside when the scene point is: the slice the pixel's depth
        // falls in is interpolated from both sides of it.
        float depth01 = texelFetch(uLinearDepth, pixel, 0).r;
        float t = min(dot(p - frame.eye, frame.forward) / frame.farDistance, depth01);
        cut = (t >= first.x && t <= first.y) || (t >= first.z && t <= first.w) ||
              (t >= second.x && t <= second.y) || (t >= second.z && t <= second.w);
    }
    float tau = cut ? 0.0 : exponentialOpticalDepth(froxel.globalFog * frame.fogDensity, frame.fogFalloff,
                                        o.y - frame.fogBaseHeight, d.y, len);
    if (froxel.noiseAmount > 0.0) {  // the detail noise: the slice's density scaled at its sample point
        float n = detailNoise((p - froxel.noiseOffset) / froxel.noiseScaleM);
        tau *= max(1.0 + froxel.noiseAmount * (2.0 * n - 1.0), 0.0);
    }
    addMedium(tau, frame.fogColourMode, frame.fogColour, wSky, wOwn);

    int mesh = 0;  // mesh volumes met so far (their chords' order)
    for (int v = 0; v < froxel.volumeCount && !cut; ++v) {
        PackedVolume fv = volumes[v];
        if (fv.blend > 0.5) continue;  // subtract volumes add nothing
        if (fv.shape > 1.5) {  // a mesh: the slice's parts of its chords (mesh_volume_chords.glsl)
            float ta = za / frame.farDistance;
            float tb = zb / frame.farDistance;
            float rate = dot(farRay, fv.gradientDirection);
            float tv = 0.0;
            int base = meshChordBase(mesh++, id.xy);
            for (int k = 0; k < kMeshChords; ++k) {
                vec2 chord = meshChords[base + k];
                float a = max(chord.x, ta);
                float b = min(chord.y, tb);
                if (!(b > a)) continue;
                float height = dot(frame.eye + a * farRay - fv.position, fv.gradientDirection) - fv.gradientOffset;
                tv += exponentialOpticalDepth(fv.density, fv.falloff, height, (b - a) * rate,
                                              (b - a) * length(farRay));
            }
            addMedium(tv, fv.colourMode, fv.colour, wSky, wOwn);
            tau += tv;
            continue;
        }
        vec3 rel = o - fv.position;
        vec3 oo = vec3(dot(fv.objectFromWorldRow0, rel), dot(fv.objectFromWorldRow1, rel),
                       dot(fv.objectFromWorldRow2, rel));
        vec3 dd = vec3(dot(fv.objectFromWorldRow0, d), dot(fv.objectFromWorldRow1, d),
                       dot(fv.objectFromWorldRow2, d));
        vec2 hit = unitShapeHit(fv.shape, oo, dd);
        float tIn = max(hit.x, 0.0);
        float tOut = min(hit.y, 1.0);
        if (!(tIn < tOut)) continue;
        float rate = dot(d, fv.gradientDirection);
        float height = dot(rel, fv.gradientDirection) + tIn * rate - fv.gradientOffset;
        float span = tOut - tIn;
        float tv = fv.edgeSoftness > 0.0
                       ? softVolumeDepth(fv.shape, fv.edgeSoftness, oo, dd, fv.density, fv.falloff,
                                         height - tIn * rate, rate, len, tIn, tOut)
                       : exponentialOpticalDepth(fv.density, fv.falloff, height, span * rate, span * len);
        addMedium(tv, fv.colourMode, fv.colour, wSky, wOwn);
        tau += tv;
    }

    for (int k = 0; k < frame.emitterCount; ++k) {
        EmitterGpu em = emitters[k];
        wOwn += em.colour * emitterIntegral(em.position, em.intensity, em.attenuation, o, d) *
                emitterDimming(k, o);
    }

    float visibility = 1.0;
    if (froxel.sceneShadows > 0.5) visibility *= froxelShadowVisibility(p);
    if (froxel.cloudShadows > 0.5) visibility *= cloudShadowVisibility(p);

    if (froxel.historyWeight < 1.0) {  // the previous frame's V at this world point
        vec4 clip = froxel.previousClipFromWorld * vec4(p, 1.0);
        if (clip.w > 0.0) {
            vec2 pixel = (clip.xy / clip.w * 0.5 + 0.5) * frame.viewportSize;
            vec3 uvw = vec3(pixel / (froxel.pixelsPerFroxel * vec2(froxel.gridSize.xy)),
                            froxelSliceAt(dot(p - froxel.previousEye, froxel.previousForward)));
            if (all(greaterThanEqual(uvw, vec3(0.0))) && all(lessThanEqual(uvw, vec3(1.0)))) {
                float previous = texture(uHistory, uvw).r;
                if (previous >= 0.0 && previous <= 1.0) visibility = mix(previous, visibility, froxel.historyWeight);
            }
        }
    }
    imageStore(uHistoryOut, id, vec4(visibility));

    tau = min(tau, kMaxOpticalDepth);
    imageStore(uMedium, id, vec4(wSky, tau));
    imageStore(uLight, id, vec4(min(wOwn, vec3(frame.radianceCap)), visibility));
}
