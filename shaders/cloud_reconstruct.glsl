// cloud_reconstruct.glsl — the amortised cloud path's reconstruction
// (renderer/src/cloud_amortised.cpp documents the scheme): per
// full-resolution pixel, this frame's sample where the pixel was traced,
// else the previous frames' history reprojected and clamped to the new
// samples around it, else an estimate from the traced pixels around it;
// composited over the frame as the reference pass does.
//
// Inputs: frame (eye, corner rays, viewport), CloudBlock (the layer's
//   shell, for the reprojection distance), uLinearDepth (unit 4),
//   uCloudTrace (unit 11: (S, T) of each block's traced pixel),
//   uCloudHistory (unit 12: the previous frame's output 1),
//   uPreviousDepth (unit 13: the previous frame's linear depth),
//   uPreviousClipFromWorld (location 0), uTrace (location 1): xy the traced
//   pixel of every n x n block, z = n, w = the history's mode: 0 none
//   (reset), 1 reprojected and clamped, 2 still (exact: no clamp, and its
//   traced pixels feed the estimates), uWindStep (location 2): the layer's
//   drift [m] in x, z since the previous frame (wind x time step).
// Outputs: location 0, blended with glBlendFunc(GL_ONE, GL_SRC_ALPHA):
//   (S, T), so L <- L T + S as in clouds.glsl; location 1, unblended: the
//   new history, (S, T) for a traced or kept pixel, (S, T + 2) for an
//   estimate. Both sanitised: S finite in [0, radianceCap], T in [0, 1].
#include "common/frame.glsl"

#ifdef AERIAL_VERTEX_SHADER
#include "common/fullscreen.glsl"
#else
#include "common/clouds.glsl"

layout(binding = 4) uniform sampler2D uLinearDepth;
layout(binding = 11) uniform sampler2D uCloudTrace;
layout(binding = 12) uniform sampler2D uCloudHistory;
layout(binding = 13) uniform sampler2D uPreviousDepth;
layout(location = 0) uniform mat4 uPreviousClipFromWorld;
layout(location = 1) uniform ivec4 uTrace;
layout(location = 2) uniform vec2 uWindStep;

in vec3 vFarRay;
layout(location = 0) out vec4 outColour;
layout(location = 1) out vec4 outHistory;

/// Added to T in the history to mark an estimate (T <= 1 otherwise).
const float kEstimateMark = 2.0;

ivec2 viewport() { return ivec2(frame.viewportSize); }

/// The pixel traced this frame in the block of pixel p.
ivec2 tracedPixel(ivec2 p) { return min((p / uTrace.z) * uTrace.z + uTrace.xy, viewport() - 1); }

/// The new sample of the block of pixel p.
vec4 sampleOfBlock(ivec2 p) { return texelFetch(uCloudTrace, p / uTrace.z, 0); }

/// Scene depths that belong to the same surface (or both sky).
bool depthsAgree(float a, float b) { return abs(a - b) <= 0.1 * max(max(a, b), 1e-6); }

/// The previous frame's pixel that saw this pixel's cloud, or false: the
/// point where the ray enters the layer (or the scene point if nearer),
/// moved back by the wind's drift, through the previous clipFromWorld; rays that miss the layer reproject
/// by direction (a point at infinity).
bool reproject(float depth01, out ivec2 previous) {
    float farLength = length(vFarRay);
    vec3 v = vFarRay / farLength;
    float tScene = depth01 >= 1.0 ? 1.0e30 : depth01 * farLength;
    vec2 segment0, segment1;
    int count = cloudLayerSegments(frame.eye, v, tScene, segment0, segment1);
    vec4 clip;
    if (count > 0) {
        float t = max(segment0.x, 1.0);
        // The cloud there drifted with the wind since the previous frame.
        vec3 point = frame.eye + v * t;
        clip = uPreviousClipFromWorld * vec4(point.x - uWindStep.x, point.y, point.z - uWindStep.y, 1.0);
    } else if (depth01 < 1.0) {
        clip = uPreviousClipFromWorld * vec4(frame.eye + v * tScene, 1.0);
    } else {
        clip = uPreviousClipFromWorld * vec4(v, 0.0);
    }
    previous = ivec2(0);
    if (!(clip.w > 0.0)) return false;
    vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
    if (!all(greaterThanEqual(uv, vec2(0.0))) || !all(lessThan(uv, vec2(1.0)))) return false;
    previous = clamp(ivec2(floor(uv * frame.viewportSize)), ivec2(0), viewport() - 1);
    return true;
}

/// An estimate of pixel p: a Gaussian (sigma 0.7 px, so the nearest traced
/// pixels dominate) over the 5 x 5 pixels
/// around it that hold a traced value (this frame's samples; in a still
/// frame also the history's traced pixels), weighted down where the scene
/// depth disagrees with p's.
vec4 estimate(ivec2 p, float depth01, bool stillHistory) {
    vec4 sum = vec4(0.0);
    float weights = 0.0;
    for (int y = -2; y <= 2; ++y) {
        for (int x = -2; x <= 2; ++x) {
            ivec2 q = p + ivec2(x, y);
            if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, viewport()))) continue;
            vec4 value;
            if (all(equal(q, tracedPixel(q)))) {
                value = sampleOfBlock(q);
            } else if (stillHistory) {
                value = texelFetch(uCloudHistory, q, 0);
                if (value.a > 1.5) continue;  // an estimate itself
            } else {
                continue;
            }
            float w = exp(-float(x * x + y * y));
            if (!depthsAgree(depth01, texelFetch(uLinearDepth, q, 0).r)) w *= 1e-3;
            sum += w * value;
            weights += w;
        }
    }
    return weights > 0.0 ? sum / weights : sampleOfBlock(p);
}

/// The per-channel range of the new samples of the 3 x 3 blocks around p's.
void neighbourhood(ivec2 p, out vec4 low, out vec4 high) {
    ivec2 block = p / uTrace.z;
    ivec2 last = textureSize(uCloudTrace, 0) - 1;
    low = vec4(1e30);
    high = vec4(-1e30);
    for (int y = -1; y <= 1; ++y) {
        for (int x = -1; x <= 1; ++x) {
            vec4 s = texelFetch(uCloudTrace, clamp(block + ivec2(x, y), ivec2(0), last), 0);
            low = min(low, s);
            high = max(high, s);
        }
    }
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    float depth01 = texelFetch(uLinearDepth, p, 0).r;
    int mode = uTrace.w;
    vec4 result;
    bool traced = true;
    if (all(equal(p, tracedPixel(p)))) {
        result = sampleOfBlock(p);
    } else {
        bool kept = false;
        ivec2 previous;
        // A still frame sees exactly what the last one saw: the same pixel.
        if (mode == 2 || (mode == 1 && reproject(depth01, previous))) {
            if (mode == 2) previous = p;
            vec4 history = texelFetch(uCloudHistory, previous, 0);
            if (history.a <= 1.5 && depthsAgree(depth01, texelFetch(uPreviousDepth, previous, 0).r)) {
                if (mode == 1) {
                    vec4 low, high;
                    neighbourhood(p, low, high);
                    history = clamp(history, low, high);
                }
                result = history;
                kept = true;
            }
        }
        if (!kept) {
            result = estimate(p, depth01, mode == 2);
            traced = false;
        }
    }

    // Nothing non-finite or negative leaves the pass.
    vec3 S = result.rgb;
    bool finite = all(greaterThanEqual(S, vec3(0.0))) && all(lessThan(S, vec3(3.0e38)));
    S = finite ? min(S, vec3(frame.radianceCap)) : vec3(0.0);
    float T = result.a >= 0.0 && result.a <= 1.0 ? result.a : 1.0;
    outColour = vec4(S, T);
    outHistory = vec4(S, traced ? T : T + kEstimateMark);
}
#endif
