// common/clouds.glsl — the cloud layer's density, its shell segments and
// the midpoint march: the SAME arithmetic as core/src/clouds/clouds.cpp
// (aerial/clouds.hpp documents the model) in float, and the cloud shadow
// map lookup of the scene lighting. tests/renderer/test_renderer_clouds.cpp
// compares the march with aerial::cloudTransmittance and the shadow map with
// aerial::cloudSunVisibility.
//
// Inputs (std140, binding 4; mirrored by CloudBlock in
// renderer/src/gpu_types.hpp with static_asserted offsets, filled by
// makeCloudBlock in renderer/src/cloud_pass.cpp):
//   shapeOffset, detailOffset  wind x seconds since 00:00 [m], [x, z],
//                       reduced modulo each tile in double on the CPU
//   planetRadius        Rg [m]; the shell's centre is (0, -Rg, 0)
//   bottomM, thicknessM the layer [m] above the ground
//   coverage, densityPerM, type, shapeScaleM, detailScaleM, erosion:
//                       CloudParams (sanitised by prepareClouds)
//   anisotropy          forward Henyey-Greenstein g; albedo (rgb)
//   steps, lightSteps   samples along the view ray / towards the light
//   volumeCount, volumeData  the cloud volumes (at most 64, limits.hpp's
//                       kMaxCloudVolumes), prepared by core (prepareClouds):
//                       per volume 4 vec4: objectFromWorld rows 0..2 with
//                       w = shape (0 box, 1 ellipsoid), coverage, edge
//                       softness; then the centre [m]
//   groundAlbedo        the atmosphere's ground albedo (light bounced into
//                       the cloud bases)
//   rayleighScattering, rayleighScaleHeight, mieExtinction, mieScaleHeight:
//                       the air for the clouds' aerial perspective
//   shadowOrigin, shadowExtentM, shadowToLight, shadowSteps, shadowActive,
//   shadowSize [texels]:
//                       the cloud shadow map (cloud_shadow.glsl)
//   outputMode          0 lit, 1 transmittance only
// Textures: uCloudShape (unit 8, 128^3), uCloudDetail (unit 9, 32^3), both
//   RG32F with mipmaps, GL_LINEAR_MIPMAP_LINEAR + GL_REPEAT: level 0 holds
//   the exact texels of CloudNoise x in r (so textureLod(.., 0) is
//   sampleTileable) and x^2 in g; the mip levels their box means, E[x] and
//   E[x^2] over the level's footprint (variance mapping: the noise's spread
//   within a texel is E[x^2] - E[x]^2). uCloudShadow (unit 10, R32F optical
//   depth).
//
// Far clouds (cloudDensityFiltered): a pixel far away covers many noise
// texels, and point samples of the thresholded noise alias into pixel
// noise at the horizon. There the noise is read at the mip level of the
// pixel's footprint w (lod = log2(w / texel)), mean m and variance s^2,
// and the coverage threshold is applied to its distribution, not to m:
// the mean of clamp((x - lo) / c, 0, 1) over x uniform in [m - a, m + a],
// a = sqrt(3) s (the uniform law of that variance), in closed form. Near
// (w below a texel) it is the exact point sample; far, the clouds turn
// smoothly into the mean density the coverage gives, without aliasing and
// without thinning out. The erosion takes its mean the same way.
//
// Float precision: the sphere roots never form |o - centre|^2 (~4e13 m^2):
// b = o.d + Rg d.y and c = (|o|^2 + 2 y Rg) - h_s (2 Rg + h_s), as core does
// in double; heights use the cancellation-free quotient. The view ray's
// samples stay within ~1e-7 relative of core's.
#ifndef AERIAL_CLOUDS_GLSL
#define AERIAL_CLOUDS_GLSL

layout(std140, binding = 4) uniform CloudBlock {
    vec2 shapeOffset;
    vec2 detailOffset;
    float planetRadius;
    float bottomM;
    float thicknessM;
    float coverage;
    float densityPerM;
    float type;
    float shapeScaleM;
    float detailScaleM;
    float erosion;
    float anisotropy;
    int steps;
    int lightSteps;
    vec3 albedo;
    int volumeCount;
    vec3 rayleighScattering;
    float rayleighScaleHeight;
    vec3 mieExtinction;
    float mieScaleHeight;
    vec2 shadowOrigin;
    float shadowExtentM;
    float shadowActive;
    vec3 shadowToLight;
    int shadowSteps;
    int outputMode;
    float shadowSize;
    float padShadow0;
    float padShadow1;
    vec3 groundAlbedo;
    float padGround;
    vec4 volumeData[256];  // 4 per volume, 64 volumes
} clouds;

layout(binding = 8) uniform sampler3D uCloudShape;
layout(binding = 9) uniform sampler3D uCloudDetail;
layout(binding = 10) uniform sampler2D uCloudShadow;

/// Optical depths saturate here (kMaxOpticalDepth of height_fog.hpp).
const float kCloudMaxOpticalDepth = 1.0e4;
/// |coordinate| beyond which a point or ray is outside the layer
/// (finite.hpp's kMaxCoordinate role; rays from the camera never get there).
const float kCloudMaxCoordinate = 1.0e15;

float cloudSaturate(float v) { return clamp(v, 0.0, 1.0); }
float cloudSmooth01(float t) {
    t = cloudSaturate(t);
    return t * t * (3.0 - 2.0 * t);
}

/// Height above the ground [m]: (x^2 + z^2 + y^2 + 2 y Rg) / (|p - centre| + Rg).
float cloudHeightAboveGround(vec3 p) {
    float rg = clouds.planetRadius;
    float r2MinusRg2 = p.x * p.x + p.z * p.z + p.y * p.y + 2.0 * p.y * rg;
    vec3 oc = p + vec3(0.0, rg, 0.0);
    return r2MinusRg2 / (length(oc) + rg);
}

/// The height fraction where cloudHeightProfile ends: 0.3 (stratus) .. 1
/// (cumulus).
float cloudProfileTop(float type) { return 0.3 + 0.7 * cloudSaturate(type); }

/// cloudHeightProfile of clouds.cpp.
float cloudHeightProfile(float heightFraction, float type) {
    float f = heightFraction, k = cloudSaturate(type);
    if (!(f > 0.0) || !(f < 1.0)) return 0.0;
    float top = cloudProfileTop(type);
    float fall = top * (0.5 + 0.3 * k);
    return cloudSmooth01(f / 0.08) * cloudSmooth01((top - f) / fall);
}

/// The coverage at p (cloudCoverageAt of clouds.cpp): the layer's, set by
/// each cloud volume in order, c = mix(c, volume coverage, w), w = 1 inside
/// and a smoothstep to 0 over the outer edge_softness of the shape
/// (object-space radius: max |x_i| for a box, |x| for an ellipsoid).
float cloudCoverageAt(vec3 p) {
    float c = clouds.coverage;
    for (int k = 0; k < clouds.volumeCount; ++k) {
        vec4 r0 = clouds.volumeData[4 * k], r1 = clouds.volumeData[4 * k + 1];
        vec4 r2 = clouds.volumeData[4 * k + 2];
        vec3 rel = p - clouds.volumeData[4 * k + 3].xyz;
        vec3 q = vec3(dot(r0.xyz, rel), dot(r1.xyz, rel), dot(r2.xyz, rel));
        float r = r0.w > 0.5 ? length(q) : max(abs(q.x), max(abs(q.y), abs(q.z)));
        if (r >= 1.0) continue;
        float soft = cloudSaturate(r2.w);
        float w = soft <= 0.0 ? 1.0 : cloudSmooth01((1.0 - r) / soft);
        c += w * (r1.w - c);
    }
    return cloudSaturate(c);
}

/// Integral of clamp((u - lo) / c, 0, 1) du from -inf (taken as lo) to x.
float cloudRampIntegral(float x, float lo, float c) {
    float u = x - lo;
    return u <= 0.0 ? 0.0 : (u < c ? 0.5 * u * u / c : 0.5 * c + (u - c));
}

/// The mean of clamp((x - lo) / c, 0, 1) for x uniform in [m - a, m + a].
float cloudRampMean(float m, float a, float lo, float c) {
    if (a < 1e-4 * c) return cloudSaturate((m - lo) / c);
    return (cloudRampIntegral(m + a, lo, c) - cloudRampIntegral(m - a, lo, c)) / (2.0 * a);
}

/// cloudDensityAt for a sample that stands for a footprint `footprintM`
/// [m] across (the pixel's width at its distance): the noise read at that
/// footprint's mip level and the threshold applied to its spread (see the
/// top of this file). footprintM below a texel gives cloudDensityAt.
float cloudDensityFiltered(vec3 p, float footprintM, out float heightFraction) {
    float h = cloudHeightAboveGround(p);
    float f = (h - clouds.bottomM) / clouds.thicknessM;
    heightFraction = f;
    float profile = cloudHeightProfile(f, clouds.type);
    if (profile <= 0.0) return 0.0;
    float c = cloudCoverageAt(p);
    if (c <= 0.0) return 0.0;
    float shapeTexel = clouds.shapeScaleM / 128.0, detailTexel = clouds.detailScaleM / 32.0;
    float lodShape = max(log2(max(footprintM, 1e-3) / shapeTexel), 0.0);
    float lodDetail = max(log2(max(footprintM, 1e-3) / detailTexel), 0.0);
    vec3 qs = vec3(p.x - clouds.shapeOffset.x, h, p.z - clouds.shapeOffset.y);
    vec2 moments = textureLod(uCloudShape, qs / clouds.shapeScaleM, lodShape).rg;
    float m = moments.x * profile;
    float a = lodShape > 0.0 ? sqrt(3.0 * max(moments.y - moments.x * moments.x, 0.0)) * profile : 0.0;
    float d = cloudRampMean(m, a, 1.0 - c, c);
    if (d <= 0.0) return 0.0;
    vec3 qd = vec3(p.x - clouds.detailOffset.x, h, p.z - clouds.detailOffset.y);
    float e = clouds.erosion * textureLod(uCloudDetail, qd / clouds.detailScaleM, lodDetail).r;
    return clouds.densityPerM * cloudSaturate((d - e) / (1.0 - e));
}

/// Extinction [1/m] at p (cloudDensityAt of clouds.cpp), with its height
/// fraction f for the lighting: the point sample, level 0 (the exact texels).
float cloudDensityAt(vec3 p, out float heightFraction) { return cloudDensityFiltered(p, 0.0, heightFraction); }

float cloudDensityAt(vec3 p) {
    float f;
    return cloudDensityAt(p, f);
}

/// Roots of |o + t d - centre|^2 = (Rg + shellHeight)^2, or false
/// (sphereRoots of clouds.cpp, with the numerically stable pair).
bool cloudSphereRoots(vec3 o, vec3 d, float shellHeight, out float t0, out float t1) {
    float rg = clouds.planetRadius;
    float a = dot(d, d);
    float b = dot(o, d) + rg * d.y;
    float c = (o.x * o.x + o.z * o.z + o.y * o.y + 2.0 * o.y * rg) - shellHeight * (2.0 * rg + shellHeight);
    float disc = b * b - a * c;
    t0 = 0.0;
    t1 = 0.0;
    if (!(disc >= 0.0) || !(a > 0.0)) return false;
    float q = -(b + (b >= 0.0 ? sqrt(disc) : -sqrt(disc)));
    float ra = q / a;
    float rb = q != 0.0 ? c / q : -b / a;
    t0 = min(ra, rb);
    t1 = max(ra, rb);
    return true;
}

/// Where o + t d runs inside the shell: up to two intervals, clipped to
/// [0, tMax] and at the ground (cloudLayerSegments of clouds.cpp).
int cloudLayerSegments(vec3 o, vec3 d, float tMax, out vec2 segment0, out vec2 segment1) {
    segment0 = vec2(0.0);
    segment1 = vec2(0.0);
    if (!(tMax > 0.0) || any(greaterThan(abs(o), vec3(kCloudMaxCoordinate)))) return 0;
    float bottom = clouds.bottomM, top = bottom + clouds.thicknessM;
    float o0, o1;
    if (!cloudSphereRoots(o, d, top, o0, o1)) return 0;
    float g0, g1;
    if (cloudSphereRoots(o, d, 0.0, g0, g1) && g0 > 0.0) tMax = min(tMax, g0);
    float i0, i1;
    bool inner = bottom > 0.0 && cloudSphereRoots(o, d, bottom, i0, i1);
    vec2 spans[2];
    int candidates = 1;
    if (!inner) {
        spans[0] = vec2(o0, o1);
    } else {
        spans[0] = vec2(o0, min(o1, i0));
        spans[1] = vec2(max(o0, i1), o1);
        candidates = 2;
    }
    int count = 0;
    for (int k = 0; k < candidates; ++k) {
        float a = max(spans[k].x, 0.0);
        float b = min(spans[k].y, tMax);
        if (b > a) {
            if (count == 0) {
                segment0 = vec2(a, b);
            } else {
                segment1 = vec2(a, b);
            }
            ++count;
        }
    }
    return count;
}

/// Samples of one segment of the midpoint march: max(1, round(steps x its
/// share of the total length)) (cloudOpticalDepth of clouds.cpp).
int cloudSegmentSamples(int steps, float span, float total) {
    return max(1, int(floor(float(steps) * span / total + 0.5)));
}

/// Optical depth along o + t d, t in [0, tMax] (cloudOpticalDepth).
float cloudOpticalDepth(vec3 o, vec3 d, float tMax, int steps) {
    vec2 segments[2];
    int count = cloudLayerSegments(o, d, tMax, segments[0], segments[1]);
    if (count == 0) return 0.0;
    steps = clamp(steps, 1, 65536);
    float total = (segments[0].y - segments[0].x) + (count > 1 ? segments[1].y - segments[1].x : 0.0);
    float len = length(d);
    float tau = 0.0;
    for (int k = 0; k < count; ++k) {
        float span = segments[k].y - segments[k].x;
        int n = cloudSegmentSamples(steps, span, total);
        float dt = span / float(n);
        float sum = 0.0;
        for (int i = 0; i < n; ++i) sum += cloudDensityAt(o + d * (segments[k].x + (float(i) + 0.5) * dt));
        tau += sum * dt * len;
    }
    return min(tau, kCloudMaxOpticalDepth);
}

/// Transmittance towards the shadow map's light at world point p, from the
/// cloud shadow map: p is moved along the light onto the map's plane
/// (height 0), where each texel holds the optical depth from the ground
/// towards the light; the same line above the ground, so exact for points
/// below the layer (bilinear between texel centres). 1 when the layer is off.
float cloudShadowVisibility(vec3 p) {
    if (!(clouds.shadowActive > 0.5)) return 1.0;
    vec3 l = clouds.shadowToLight;
    vec2 ground = p.xz - l.xz * (p.y / max(l.y, 0.05));
    vec2 uv = (ground - clouds.shadowOrigin) / clouds.shadowExtentM;
    float tau = texture(uCloudShadow, uv).r;
    return exp(-clamp(tau, 0.0, kCloudMaxOpticalDepth));
}

#endif
