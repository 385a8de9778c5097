// fog_volume_marched.glsl — the ray-marched reference of fog_volume.glsl
// (for the benchmark's side-by-side comparison, never in a normal frame):
// the same hull, intersection, clipping, colour and compositing, but the
// optical depth is a 64-step midpoint sum of the density
//   b_v exp(-c_v (dot(p - centre, g) - offset))
// along the clipped segment instead of the closed form.
//
// Inputs and output: as fog_volume.glsl.
#include "common/frame.glsl"
#include "common/volume.glsl"

#ifdef AERIAL_VERTEX_SHADER
void main() { transformHullVertex(); }
#else
#include "common/atmosphere.glsl"

layout(location = 0) out vec4 outColour;

const int kSteps = 64;

void main() {
    vec3 eye, farRay;
    float tIn, tOut;
    if (!clipFragmentRay(eye, farRay, tIn, tOut)) discard;

    vec3 centre = volume.positionOffset.xyz;
    vec3 g = volume.gradientMode.xyz;
    float b = volume.objectFromWorld1.w;
    float c = volume.objectFromWorld2.w;
    float dt = (tOut - tIn) / float(kSteps);
    float sum = 0.0;
    for (int i = 0; i < kSteps; ++i) {
        vec3 p = eye + (tIn + (float(i) + 0.5) * dt) * farRay;
        float height = dot(p - centre, g) - volume.positionOffset.w;
        sum += b * exp(min(-c * height, 80.0));
    }
    float tau = min(sum * dt * length(farRay), kMaxOpticalDepth);
    vec3 colour = min(fogColourFor(volume.gradientMode.w, volume.colour.rgb, normalize(farRay)), vec3(frame.fogColour.w));
    outColour = vec4(colour * oneMinusExp(tau), exp(-tau));
}
#endif
