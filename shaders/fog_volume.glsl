// fog_volume.glsl — one box or ellipsoid fog volume (DESIGN.md, "Fog
// volumes"; Wenzel 2006, section 6.6): the bounding hull (the unit cube in
// object space, for both shapes) is rasterised, each fragment traces the
// pixel's ray in object space and integrates the volume's exponential density
// analytically over the clipped segment.
//
// Inputs:
//   frame (common/frame.glsl): eye [m], far-plane corner rays, lights
//   VolumeBlock (std140, binding 1; VolumeBlock in renderer/src/gpu_types.hpp):
//     worldFromObject (hull transform: position + rotation * halfExtents),
//     the rows of objectFromWorld (S^-1 R^T; w of row0: shape, 0 box,
//     1 ellipsoid; w of row1: density b_v [1/m]; w of row2: falloff c_v [1/m]),
//     position [m] (w: gradient offset [m]), unit gradient g (w: colour mode
//     0 sky, 1 tinted, 2 custom), colour (rgb)
//   uLinearDepth (unit 4): normalised linear eye depth z/far
// Output (location 0), blended with glBlendFunc(GL_ONE, GL_SRC_ALPHA):
//   rgb = C_v (1 - T_v), a = T_v: L <- L T_v + C_v (1 - T_v).
//
// The ray is eye + t farRay, t in [0, 1] to the far plane; the scene point is
// at t = depth01. The segment is [max(t_in, 0), min(t_out, depth01)] (the
// viewer may stand inside; geometry inside the volume ends it). Its optical
// depth is the global-fog formula with o.y - h0 -> dot(o - centre, g) - offset
// and d.y -> dot(d, g) (core/src/bvh.hpp, opticalDepthPrepared).
#include "common/frame.glsl"
#include "common/volume.glsl"

#ifdef AERIAL_VERTEX_SHADER
void main() { transformHullVertex(); }
#else
#include "common/atmosphere.glsl"

layout(location = 0) out vec4 outColour;

void main() {
    vec3 eye, farRay;
    float tIn, tOut;
    if (!clipFragmentRay(eye, farRay, tIn, tOut)) discard;

    vec3 centre = volume.positionOffset.xyz;
    vec3 g = volume.gradientMode.xyz;
    float span = tOut - tIn;
    float rate = dot(farRay, g);  // height change per unit t
    float height = dot(eye - centre, g) + tIn * rate - volume.positionOffset.w;
    float tau = exponentialOpticalDepth(volume.objectFromWorld1.w, volume.objectFromWorld2.w, height,
                                        span * rate, span * length(farRay));
    vec3 colour = min(fogColourFor(volume.gradientMode.w, volume.colour.rgb, normalize(farRay)), vec3(frame.fogColour.w));
    outColour = vec4(colour * oneMinusExp(tau), exp(-tau));
}
#endif
