// fog_volume_marched.glsl — the ray-marched reference of fog_volume.glsl
// (for the benchmark's side-by-side comparison, never in a normal frame):
// the same hull, intersection, clipping, colour and compositing, but the
// optical depth is a 64-step midpoint sum of the density
//   b_v exp(-c_v (dot(p - centre, g) - offset))
// along the clipped segment instead of the closed form.
//
// Inputs and output: as fog_volume.glsl.
// Subtract volumes are not cut out here (a benchmark reference of the
// plain integral; never in a normal frame).
#include "common/frame.glsl"
#include "common/volume.glsl"

#ifdef AERIAL_VERTEX_SHADER
void main() { transformHullVertex(); }
#else
#include "common/atmosphere.glsl"
#include "common/soft_volume.glsl"

layout(location = 0) out vec4 outColour;

const int kSteps = 64;

void main() {
    vec3 eye, farRay;
    float tIn, tOut;
    if (!clipFragmentRay(eye, farRay, tIn, tOut)) discard;

    vec3 centre = volume.position;
    vec3 g = volume.gradientDirection;
    float b = volume.density;
    float c = volume.falloff;
    float dt = (tOut - tIn) / float(kSteps);
    float sum = 0.0;
    for (int i = 0; i < kSteps; ++i) {
        vec3 p = eye + (tIn + (float(i) + 0.5) * dt) * farRay;
        float height = dot(p - centre, g) - volume.gradientOffset;
        float w = 1.0;  // the soft edge's profile (common/soft_volume.glsl)
        float sigma = volume.edgeSoftness;
        if (sigma > 0.0) {
            vec3 q = toObject(p - centre);
            w = volume.shape < 0.5 ? softBoxRamp(q.x, sigma) * softBoxRamp(q.y, sigma) * softBoxRamp(q.z, sigma)
                                   : clamp((1.0 - dot(q, q)) / (1.0 - (1.0 - sigma) * (1.0 - sigma)), 0.0, 1.0);
        }
        sum += w * b * exp(min(-c * height, 80.0));
    }
    float tau = min(sum * dt * length(farRay), kMaxOpticalDepth);
    // The fog colour of the pixel's whole sight line, to its scene point (fog_light.hpp).
    float sceneDistance = texelFetch(uLinearDepth, ivec2(gl_FragCoord.xy), 0).r * length(farRay);
    outColour = fogInScatterTransmittance(volume.colourMode, volume.colour, normalize(farRay), sceneDistance, tau);
}
#endif
