// common/subtract.glsl — the subtract volumes' union along a pixel's ray
// (DESIGN.md "Mesh and subtract volumes"; fog_volume.hpp, FogVolumeBlend),
// and the exponential fog integrals with that union cut out. Fragment and
// compute stages only (vertex stages have no storage buffers to promise).
//
// Inputs:
//   frame.subtractActive (common/frame.glsl): 1 when the intervals below
//     were written this frame (subtract_pass.cpp), 0 when no subtract volume
//     cuts the fog (then nothing here reads the buffer)
//   SubtractIntervals (std430, binding 4): per pixel (row-major from the
//     bottom-left, index y * width + x) two vec4 = 4 pairs (a, b) in the
//     ray parameter t of eye + t farRay (t = normalised linear depth z/far),
//     sorted, disjoint, clipped to [0, depth01]; an empty pair has b <= a
//     (subtract_resolve.glsl writes them).
// Units: t in units of the far ray, optical depths dimensionless.
// Requires common/frame.glsl and common/atmosphere.glsl.
#ifndef AERIAL_SUBTRACT_GLSL
#define AERIAL_SUBTRACT_GLSL

layout(std430, binding = 4) readonly buffer SubtractIntervals { vec4 subtractIntervals[]; };

/// The 4 intervals of a pixel as 8 numbers (a0, b0, a1, b1, ...).
void pixelSubtractIntervals(ivec2 pixel, out vec4 first, out vec4 second) {
    int index = pixel.y * int(frame.viewportSize.x) + pixel.x;
    first = subtractIntervals[2 * index];
    second = subtractIntervals[2 * index + 1];
}

/// Optical depth of b exp(-c h) over the ray parameters [t0, t1] (0 when
/// empty), h = heightAt0 + t rate the height above the density-b plane,
/// lengthPerT = |farRay| [m]. The integral of common/atmosphere.glsl.
float exponentialDepthBetween(float b, float c, float heightAt0, float rate, float lengthPerT, float t0,
                              float t1) {
    if (!(t1 > t0)) return 0.0;
    float span = t1 - t0;
    return exponentialOpticalDepth(b, c, heightAt0 + t0 * rate, span * rate, span * lengthPerT);
}

/// The gaps of [t0, t1] outside the pixel's subtract union, in order, into
/// gaps[0..n-1] (the union is at most 4 intervals, so at most 5 gaps);
/// returns n. The masked integrals below sum their integral over these.
int subtractGaps(ivec2 pixel, float t0, float t1, out vec2 gaps[5]) {
    if (!(t1 > t0)) return 0;
    vec4 first, second;
    pixelSubtractIntervals(pixel, first, second);
    float cuts[8] = float[8](first.x, first.y, first.z, first.w, second.x, second.y, second.z, second.w);
    int n = 0;
    float start = t0;
    for (int i = 0; i < 4; ++i) {
        float lo = cuts[2 * i];
        float hi = cuts[2 * i + 1];
        if (!(hi > lo)) continue;  // empty
        if (lo > start) gaps[n++] = vec2(start, min(lo, t1));
        start = max(start, hi);
        if (start >= t1) break;
    }
    if (t1 > start) gaps[n++] = vec2(start, t1);
    return n;
}

/// The same over [t0, t1] minus the pixel's subtract union: the sum over
/// the gaps between the intervals (never a difference, so a fog-free
/// interior is exactly 0). Without subtract volumes the plain integral.
float maskedExponentialDepth(ivec2 pixel, float b, float c, float heightAt0, float rate, float lengthPerT,
                             float t0, float t1) {
    if (frame.subtractActive == 0) return exponentialDepthBetween(b, c, heightAt0, rate, lengthPerT, t0, t1);
    vec2 gaps[5];
    int n = subtractGaps(pixel, t0, t1, gaps);
    float tau = 0.0;
    for (int i = 0; i < n; ++i) tau += exponentialDepthBetween(b, c, heightAt0, rate, lengthPerT, gaps[i].x, gaps[i].y);
    return min(tau, kMaxOpticalDepth);
}

/// The global height fog's optical depth from the eye to the world point
/// p seen through this pixel, the subtract union cut out (p's parameter
/// t = z/far; the union is known up to the opaque scene's depth, which a
/// depth-tested transparent fragment does not pass). For the transparent
/// meshes and the particles, whose per-vertex global fog does not see the
/// subtract volumes.
float maskedGlobalFogDepthTo(ivec2 pixel, vec3 p) {
    vec3 farRay = farRayAtFragment(vec2(pixel) + 0.5);
    float t = max(dot(p - frame.eye, frame.forward) / frame.farDistance, 0.0);
    return maskedExponentialDepth(pixel, frame.fogDensity, frame.fogFalloff, frame.eye.y - frame.fogBaseHeight,
                                  farRay.y, length(farRay), 0.0, t);
}

#endif
