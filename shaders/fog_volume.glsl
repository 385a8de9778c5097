// fog_volume.glsl — one box or ellipsoid fog volume (DESIGN.md, "Fog
// volumes"; Wenzel 2006, section 6.6): the bounding hull (the unit cube in
// object space, for both shapes) is rasterised, each fragment traces the
// pixel's ray in object space and integrates the volume's exponential density
// analytically over the clipped segment.
//
// Inputs:
//   frame (common/frame.glsl): eye [m], far-plane corner rays, lights
//   VolumeBlock (common/volume.glsl; std140, binding 1; VolumeBlock in
//     renderer/src/gpu_types.hpp): worldFromObject (hull transform:
//     position + rotation * halfExtents), objectFromWorldRow0..2 (the rows of
//     S^-1 R^T), shape (0 box, 1 ellipsoid), density b_v [1/m], falloff c_v
//     [1/m], position [m], gradientOffset [m], gradientDirection g (unit),
//     colourMode (0 sky, 1 tinted, 2 custom), colour (rgb)
//   uLinearDepth (unit 4): normalised linear eye depth z/far
// Output (location 0), blended with glBlendFunc(GL_ONE, GL_SRC_ALPHA):
//   rgb = C_v (1 - T_v), a = T_v: L <- L T_v + C_v (1 - T_v)
//   (fogInScatterTransmittance, common/atmosphere.glsl).
//
// The ray is eye + t farRay, t in [0, 1] to the far plane; the scene point is
// at t = depth01. The segment is [max(t_in, 0), min(t_out, depth01)] (the
// viewer may stand inside; geometry inside the volume ends it). Its optical
// depth is the global-fog formula with o.y - h0 -> dot(o - centre, g) - offset
// and d.y -> dot(d, g) (core/src/fog/bvh.hpp, opticalDepthPrepared). With
// subtract volumes (frame.subtractActive) the segment minus the pixel's
// subtract union (common/subtract.glsl). A soft edge (edgeSoftness > 0)
// multiplies the density by the profile of common/soft_volume.glsl.
#include "common/frame.glsl"
#include "common/volume.glsl"

#ifdef AERIAL_VERTEX_SHADER
void main() { transformHullVertex(); }
#else
#include "common/atmosphere.glsl"
#include "common/soft_volume.glsl"
#include "common/subtract.glsl"

/// Optical depth over [t0, t1] of a soft-edged volume (volume.edgeSoftness
/// > 0), the pixel's subtract union cut out as maskedExponentialDepth does.
float maskedSoftDepth(ivec2 pixel, vec3 o, vec3 d, float heightAt0, float rate, float lengthPerT, float t0,
                      float t1) {
    float sigma = volume.edgeSoftness;
    float b = volume.density;
    float c = volume.falloff;
    if (frame.subtractActive == 0)
        return softVolumeDepth(volume.shape, sigma, o, d, b, c, heightAt0, rate, lengthPerT, t0, t1);
    vec2 gaps[5];
    int n = subtractGaps(pixel, t0, t1, gaps);
    float tau = 0.0;
    for (int i = 0; i < n; ++i)
        tau += softVolumeDepth(volume.shape, sigma, o, d, b, c, heightAt0, rate, lengthPerT, gaps[i].x, gaps[i].y);
    return min(tau, kMaxOpticalDepth);
}

layout(location = 0) out vec4 outColour;

void main() {
    vec3 eye, farRay;
    float tIn, tOut;
    if (!clipFragmentRay(eye, farRay, tIn, tOut)) discard;

    vec3 centre = volume.position;
    vec3 g = volume.gradientDirection;
    float span = tOut - tIn;
    float rate = dot(farRay, g);  // height change per unit t
    float height = dot(eye - centre, g) + tIn * rate - volume.gradientOffset;
    float tau = exponentialOpticalDepth(volume.density, volume.falloff, height,
                                        span * rate, span * length(farRay));
    if (volume.edgeSoftness > 0.0) {
        tau = maskedSoftDepth(ivec2(gl_FragCoord.xy), toObject(eye - centre), toObject(farRay), height - tIn * rate,
                              rate, length(farRay), tIn, tOut);
    } else if (frame.subtractActive != 0) {
        tau = maskedExponentialDepth(ivec2(gl_FragCoord.xy), volume.density, volume.falloff, height - tIn * rate,
                                     rate, length(farRay), tIn, tOut);
    }
    // The fog colour of the pixel's whole sight line, to its scene point (fog_light.hpp).
    float sceneDistance = texelFetch(uLinearDepth, ivec2(gl_FragCoord.xy), 0).r * length(farRay);
    outColour = fogInScatterTransmittance(volume.colourMode, volume.colour, normalize(farRay), sceneDistance, tau);
}
#endif
