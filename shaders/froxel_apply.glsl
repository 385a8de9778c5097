// froxel_apply.glsl — volumetric fog, stage 3: every pixel looks up the
// integrated grid (froxel_integrate.glsl) at its own screen position and
// view depth, and applies it with the fog colours of its own direction:
//   S = LitSky x L_cast(v) + Sky x (L_fog(v) - L_cast(v)) + Own
// (L_fog: the sky's fog colour with the per-pixel phase functions; L_cast:
// its part from the casting light's single scattering, the part shadows
// dim; froxelFogColours). Beyond the grid's far depth the global height fog
// continues analytically to the scene point (unshadowed), behind the grid.
//
// Inputs: frame, froxel (common/froxel.glsl), uLinearDepth (unit 4), the
//   integrated grid on units 11-13 (trilinear, clamped).
// Output (location 0), blended with glBlendFunc(GL_ONE, GL_SRC_ALPHA):
//   rgb = S, a = T: L <- L T + S.
#include "common/frame.glsl"

#ifdef AERIAL_VERTEX_SHADER
#include "common/fullscreen.glsl"
#else
#include "common/atmosphere.glsl"
#include "common/froxel.glsl"

layout(binding = 4) uniform sampler2D uLinearDepth;
layout(binding = 11) uniform sampler3D uLitSky;  // (sum T f W_sky V, T)
layout(binding = 12) uniform sampler3D uSky;     // (sum T f W_sky, 0)
layout(binding = 13) uniform sampler3D uOwn;     // (sum T f W_own, 0)

in vec3 vFarRay;
layout(location = 0) out vec4 outColour;

void main() {
    float depth01 = texelFetch(uLinearDepth, ivec2(gl_FragCoord.xy), 0).r;
    float z = depth01 * frame.farDistance;
    vec3 v = normalize(vFarRay);
    float s = froxelSliceAt(z);
    float slices = float(froxel.gridSize.z);
    vec3 uvw = vec3(gl_FragCoord.xy / (froxel.pixelsPerFroxel * vec2(froxel.gridSize.xy)),
                    (min(s, 1.0) * slices + 0.5) / (slices + 1.0));
    vec4 litSky = texture(uLitSky, uvw);
    vec3 sky = texture(uSky, uvw).rgb;
    vec3 own = texture(uOwn, uvw).rgb;
    vec3 shadowable, all;
    froxelFogColours(v, shadowable, all);
    vec3 inScatter = litSky.rgb * shadowable + sky * max(all - shadowable, vec3(0.0)) + own;
    float transmittance = clamp(litSky.a, 0.0, 1.0);

    if (z > froxel.farM) {  // the global fog behind the grid, in closed form
        float start = froxel.farM / frame.farDistance;
        vec3 o = frame.eye + start * vFarRay;
        vec3 d = (depth01 - start) * vFarRay;
        float tau = exponentialOpticalDepth(froxel.globalFog * frame.fogDensity, frame.fogFalloff, o.y - frame.fogBaseHeight, d.y,
                                            length(d));
        vec4 rest = fogInScatterTransmittance(frame.fogColourMode, frame.fogColour, v, tau);
        inScatter += transmittance * rest.rgb;
        transmittance *= rest.a;
    }
    outColour = vec4(min(inScatter, vec3(frame.radianceCap)), transmittance);
}
#endif
