// froxel_apply.glsl — volumetric fog, stage 3: every opaque pixel looks up
// the integrated grid (froxel_integrate.glsl) at its own screen position and
// view depth and applies it with the fog colours of its own direction
// (froxelFog, common/froxel.glsl):
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

in vec3 vFarRay;
layout(location = 0) out vec4 outColour;

void main() {
    float depth01 = texelFetch(uLinearDepth, ivec2(gl_FragCoord.xy), 0).r;
    outColour = froxelFog(gl_FragCoord.xy, depth01 * frame.farDistance, vFarRay);
}
#endif
