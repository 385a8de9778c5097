// transparent.glsl — alpha-blended meshes (glTF alpha mode "blend"), drawn
// after the fog passes, back to front, over the fogged frame (Wenzel 2006,
// section 6.7: transparent objects cannot read the fogged depth buffer).
//
// Fog, in the order of the compositing contract of fog_query.hpp:
//   1. global height fog per vertex: the same analytic integral as
//      global_fog.glsl from the eye to the vertex (optical depth tau_g,
//      interpolated across the triangle), T_g = exp(-tau_g) and
//      S_g = L_fog(v) (1 - T_g) per fragment with the per-pixel phase
//      functions of the fog colour (as global_fog.glsl); with subtract
//      volumes (frame.subtractActive) instead per fragment along the
//      pixel's ray without their union (common/subtract.glsl: exact, the
//      fragment lies in front of the opaque depth the union is known to);
//   2. fog volumes and emitters per object, from the CPU (FogScene without
//      the global fog): the renderer queries the fog from the eye to the 8
//      corners of the object's world bounds, and each fragment interpolates
//      (T', S') trilinearly at its position in the bounds (the corner
//      refinement Wenzel suggests).
//   Fogged: L' = (L T_g + S_g) T' + S'.
//   With the volumetric fog (froxelsActive()) both are replaced by the
//   froxel grid's answer at the fragment (froxelFog, common/froxel.glsl),
//   the same lookup as the opaque pixels: L' = L T + S.
// Shading as scene.glsl (common/shading.glsl). With coverage alpha (opacity
// x texture alpha) the diffuse and emitted light are scaled by alpha, the
// specular reflection is not (glass reflects where it is clear).
//
// Inputs: frame, ObjectBlock (with boundsMin/Max and cornerFog), uBaseColour
//   (unit 5), Emitters (binding 2), the sky tables (units 0..3); attributes
//   as scene.glsl.
// Output (location 0), premultiplied, blended with
//   glBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE):
//   rgb = ((alpha (emission + diffuse) + specular) T_g + alpha S_g) T'
//         + alpha S',  a = alpha.
//   For alpha = 1 this is the fog_query.hpp answer L T + S for the surface.
#include "common/frame.glsl"
#include "common/object.glsl"
#include "common/atmosphere.glsl"

#ifdef AERIAL_VERTEX_SHADER
out float vGlobalTau;  // optical depth of the global fog, eye -> vertex

void main() {
    vec4 world = transformObjectVertex();
    vGlobalTau = globalFogOpticalDepth(world.xyz - frame.eye);  // eye -> vertex [m]
}
#else
#include "common/sky_table.glsl"
#include "common/shading.glsl"
#include "common/froxel.glsl"
#include "common/subtract.glsl"

in float vGlobalTau;
layout(location = 0) out vec4 outColour;

/// Trilinear interpolation of the corner fog at world point p.
vec4 cornerFogAt(vec3 p) {
    vec3 lo = object.boundsMin;
    vec3 extent = object.boundsMax - lo;
    vec3 f = vec3(0.0);
    for (int i = 0; i < 3; ++i) f[i] = extent[i] > 1e-6 ? clamp((p[i] - lo[i]) / extent[i], 0.0, 1.0) : 0.0;
    vec4 x00 = mix(object.cornerFog[0], object.cornerFog[1], f.x);
    vec4 x10 = mix(object.cornerFog[2], object.cornerFog[3], f.x);
    vec4 x01 = mix(object.cornerFog[4], object.cornerFog[5], f.x);
    vec4 x11 = mix(object.cornerFog[6], object.cornerFog[7], f.x);
    return mix(mix(x00, x10, f.y), mix(x01, x11, f.y), f.z);
}

void main() {
    Surface s = surfaceAt(vTexcoord);
    vec3 diffuse, specular;
    shadeFragment(s, vWorld, vNormal, diffuse, specular);
    float alpha = s.alpha;
    vec3 surface = alpha * (object.emission + diffuse) + specular;
    // Global fog: the optical depth interpolated from the vertices, the
    // colour with the per-pixel phase functions (as global_fog.glsl).
    if (froxelsActive()) {
        vec4 fog = froxelFog(gl_FragCoord.xy, dot(vWorld - frame.eye, frame.forward),
                             farRayAtFragment(gl_FragCoord.xy));
        outColour = vec4(min(surface * fog.a + alpha * fog.rgb, vec3(frame.radianceCap)), alpha);
        return;
    }
    // With subtract volumes, per fragment along the pixel's ray without their union.
    float globalTau = frame.subtractActive != 0 ? maskedGlobalFogDepthTo(ivec2(gl_FragCoord.xy), vWorld) : vGlobalTau;
    vec4 globalFog = globalFogTowards(vWorld - frame.eye, globalTau);
    vec3 fogged = surface * globalFog.a + alpha * globalFog.rgb;
    vec4 local = cornerFogAt(vWorld);
    fogged = fogged * local.a + alpha * local.rgb;
    outColour = vec4(min(fogged, vec3(frame.radianceCap)), alpha);
}
#endif
