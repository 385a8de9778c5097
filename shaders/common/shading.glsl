// common/shading.glsl — surface shading of the scene and transparent passes:
// the glTF 2.0 metallic-roughness material (glTF 2.0 specification, appendix
// B): Lambert diffuse and a GGX / height-correlated Smith / Schlick specular
// lobe, lit by the sun and moon that pass through the atmosphere (E_ground),
// the sky (ambient irradiance plus the sky tables seen in the mirror
// direction) and the point emitters (DESIGN.md, "Emitters").
//
// Units: illuminance E in the lights' unit, radiance in that unit per sr.
//   f(l, v) = (1 - F) c_diff / pi + F D(h) Vis(l, v)
//   c_diff = base (1 - metallic), F0 = mix(0.04 s, base, metallic),
//   F90 = mix(s, 1, metallic), F = F0 + (F90 - F0) (1 - v.h)^5,
//   D = alpha^2 / (pi ((n.h)^2 (alpha^2 - 1) + 1)^2), alpha = roughness^2,
//   Vis = 0.5 / (n.l sqrt((n.v)^2 (1 - alpha^2) + alpha^2)
//              + n.v sqrt((n.l)^2 (1 - alpha^2) + alpha^2))
//   L = emission + sum_lights f E max(n.l, 0)
//       + c_diff / pi E_sky (0.5 + 0.5 n.y)                    (diffuse sky)
//       + (F0 A + F90 B) mix(L_sky(r), E_sky (0.5 + 0.5 r.y) / pi, roughness)
//   where r = reflect(-v, n) and (A, B) is Karis' analytic fit of the
//   split-sum environment BRDF (Karis 2014, "Physically based shading on
//   mobile"). The emitters light as points: E = colour e / (1 + a |l - p|^2)
//   with e = a I / kNitsPerRadianceUnit (aerial::emitterIlluminance).
// Roughness is clamped to >= 0.045 (a point light on a perfect mirror is a
// delta), so a sun highlight stays finite. With s = 0 and metallic = 0 the
// material is exactly Lambert: L = emission + base / pi E_total.
// Requires common/frame.glsl, common/atmosphere.glsl, common/sky_table.glsl,
// common/object.glsl.
// Clouds: the sun and moon are multiplied by the cloud shadow map's
// visibility at p (common/clouds.glsl) while a cloud layer is drawn; E_sky
// is then the ambient below the deck (groundAmbient), and L_sky(r) the clear
// sky blended towards the deck's underside by the cover in r
// (overcastCoverTowards, common/atmosphere.glsl).
// Shadows: the light that casts the cascaded shadow maps (the brighter of
// sun and moon) is multiplied by their visibility at p
// (common/shadows.glsl) while they are drawn; the other light is not.
#ifndef AERIAL_SHADING_GLSL
#define AERIAL_SHADING_GLSL

#include "common/emitters.glsl"
#include "common/clouds.glsl"
#include "common/shadows.glsl"
layout(binding = 5) uniform sampler2D uBaseColour;  // sRGB8_A8: decoded to linear by the sampler

struct Surface {
    vec3 base;        // linear base colour
    float alpha;      // coverage 0..1
    float metallic;   // 0..1
    float roughness;  // perceptual, 0.045..1
    float specular;   // s, 0..1
};

/// The material at texture coordinate uv (glTF TEXCOORD_0).
Surface surfaceAt(vec2 uv) {
    vec4 base = vec4(object.albedo, object.opacity);
    if (object.baseColourTextured > 0.5) base *= texture(uBaseColour, uv);
    Surface s;
    s.base = clamp(base.rgb, 0.0, 1.0);
    s.alpha = clamp(base.a, 0.0, 1.0);
    s.metallic = clamp(object.metallic, 0.0, 1.0);
    s.roughness = clamp(object.roughness, 0.045, 1.0);
    s.specular = clamp(object.specularFactor, 0.0, 1.0);
    return s;
}

/// A unit normal facing the viewer's side of the surface.
vec3 shadingNormal(vec3 interpolated, bool frontFacing, vec3 v) {
    float len = length(interpolated);
    vec3 n = len > 1e-20 ? interpolated / len : v;
    return frontFacing ? n : -n;
}

/// Adds one light of irradiance E (perpendicular to l) from unit direction l.
void addLight(Surface s, vec3 n, vec3 v, vec3 l, vec3 E, inout vec3 diffuse, inout vec3 specular) {
    float nl = dot(n, l);
    if (!(nl > 0.0) || all(equal(E, vec3(0.0)))) return;
    float nv = clamp(dot(n, v), 1e-4, 1.0);
    vec3 hv = l + v;
    float hl = length(hv);
    vec3 h = hl > 1e-6 ? hv / hl : n;
    float vh = clamp(dot(v, h), 0.0, 1.0);
    float nh = clamp(dot(n, h), 0.0, 1.0);
    float alpha = s.roughness * s.roughness;
    float a2 = alpha * alpha;
    vec3 f0 = mix(vec3(0.04 * s.specular), s.base, s.metallic);
    vec3 f90 = vec3(mix(s.specular, 1.0, s.metallic));
    float m = 1.0 - vh;
    float m2 = m * m;
    vec3 F = f0 + (f90 - f0) * (m2 * m2 * m);  // Schlick, (1 - v.h)^5
    float dd = nh * nh * (a2 - 1.0) + 1.0;
    float D = a2 / (kPi * dd * dd);
    float vis = 0.5 / (nl * sqrt(nv * nv * (1.0 - a2) + a2) + nv * sqrt(nl * nl * (1.0 - a2) + a2));
    vec3 cdiff = s.base * (1.0 - s.metallic);
    diffuse += (1.0 - F) * cdiff / kPi * E * nl;
    specular += F * (D * vis) * E * nl;
}

/// Karis' fit of the split-sum environment BRDF: (scale of F0, scale of F90).
vec2 environmentBrdf(float roughness, float nv) {
    const vec4 c0 = vec4(-1.0, -0.0275, -0.572, 0.022);
    const vec4 c1 = vec4(1.0, 0.0425, 1.04, -0.04);
    vec4 r = roughness * c0 + c1;
    float a004 = min(r.x * r.x, exp2(-9.28 * nv)) * r.x + r.y;
    return vec2(-1.04, 1.04) * a004 + r.zw;
}

/// Light reflected towards v (unit, surface -> eye) at world point p with
/// unit normal n, split into the diffuse part (scaled by coverage in the
/// transparent pass) and the specular part.
void shadeSurface(Surface s, vec3 p, vec3 n, vec3 v, out vec3 diffuse, out vec3 specular) {
    diffuse = vec3(0.0);
    specular = vec3(0.0);
    vec3 sunE = frame.sunIlluminance;
    vec3 moonE = frame.moonIlluminance;
    if (clouds.shadowActive > 0.5) {  // the cloud shadow (common/clouds.glsl); off: exactly as without clouds
        float visibility = cloudShadowVisibility(p);
        sunE *= visibility;
        moonE *= visibility;
    }
    if (shadow.castingLight > 0.5) {  // the scene's shadow maps (common/shadows.glsl); off: exactly as without
        float visibility = sceneShadowVisibility(p, n);
        if (shadow.castingLight < 1.5) {
            sunE *= visibility;
        } else {
            moonE *= visibility;
        }
    }
    addLight(s, n, v, frame.sunDirection, sunE, diffuse, specular);
    addLight(s, n, v, frame.moonDirection, moonE, diffuse, specular);
    for (int k = 0; k < frame.emitterCount; ++k) {
        vec3 toLight = emitters[k].position - p;
        float r2 = dot(toLight, toLight);
        if (!(r2 > 1e-12)) continue;
        float falloff = emitters[k].light.x * emitterDimming(k, p) / (1.0 + max(emitters[k].attenuation, 0.0) * r2);
        addLight(s, n, v, toLight * inversesqrt(r2), emitters[k].colour * falloff, diffuse,
                 specular);
    }
    vec3 cdiff = s.base * (1.0 - s.metallic);
    diffuse += cdiff / kPi * frame.groundAmbient * (0.5 + 0.5 * n.y);
    float nv = clamp(dot(n, v), 1e-4, 1.0);
    vec3 f0 = mix(vec3(0.04 * s.specular), s.base, s.metallic);
    float f90 = mix(s.specular, 1.0, s.metallic);
    if (any(greaterThan(f0, vec3(0.0))) || f90 > 0.0) {
        vec3 r = reflect(-v, n);
        vec3 diffuseSky = frame.groundAmbient * (0.5 + 0.5 * r.y) / kPi;
        // Roughness is uniform per draw, so this branch is too (the table
        // lookups need no derivatives anyway).
        vec3 sky = diffuseSky;
        if (s.roughness < 1.0) {
            // The mirrored sky: the clear sky's, under the deck where it hides it.
            vec3 mirrored = skyRadiance(r, false);
            if (frame.overcastCover > 0.0 || frame.overcastSkyCover > 0.0)
                mirrored = mix(mirrored, frame.overcastRadiance, overcastCoverTowards(r));
            sky = mix(mirrored, diffuseSky, s.roughness);
        }
        vec2 ab = environmentBrdf(s.roughness, nv);
        specular += (f0 * ab.x + f90 * ab.y) * sky;
    }
}

/// shadeSurface for this fragment at world point p, seen from the eye, with
/// the interpolated vertex normal (shadingNormal).
void shadeFragment(Surface s, vec3 p, vec3 interpolatedNormal, out vec3 diffuse, out vec3 specular) {
    vec3 v = normalize(frame.eye - p);
    vec3 n = shadingNormal(interpolatedNormal, gl_FrontFacing, v);
    shadeSurface(s, p, n, v, diffuse, specular);
}

#endif
