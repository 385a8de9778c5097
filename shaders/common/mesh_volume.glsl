// common/mesh_volume.glsl — a mesh fog volume's density integral along a
// pixel's ray (DESIGN.md "Mesh and subtract volumes"; seed 001, polygonal
// fog volumes: back-face minus front-face sums), shared by its
// accumulation (mesh_volume_accumulate.glsl) and its composite
// (mesh_volume_composite.glsl).
//
// Along the ray eye + t farRay (t = z/far), the volume's fog is
//   tau = sum over exits F(t) - sum over entries F(t),
// t clamped to [0, depth01], F an antiderivative of the density (the box
// formula of fog_volume.glsl, extended beyond the mesh) with the pixel's
// subtract union cut out (common/subtract.glsl). F is taken from a
// reference tRef on the ray near the volume (its closest approach to the
// centre, in [0, 1]), F(t) = signed integral from tRef to t, so that no
// term holds the fog of far-away stretches of the ray (the density
// extended beyond the mesh may be huge there). Faces behind the eye are not
// rasterised; their share, F(0) times minus the sum of the signs in front
// (closed mesh: every sign sums to 0), is added by the composite from the
// accumulated sign sum: tau = R - G F(0) = R + G integral(0, tRef).
// Requires common/frame.glsl, common/atmosphere.glsl, common/volume.glsl
// (fragment stage) and common/subtract.glsl.
#ifndef AERIAL_MESH_VOLUME_GLSL
#define AERIAL_MESH_VOLUME_GLSL

/// The reference parameter tRef of the pixel's ray for this volume.
float meshVolumeReference(vec3 farRay) {
    return clamp(dot(volume.position - frame.eye, farRay) / max(dot(farRay, farRay), 1e-30), 0.0, 1.0);
}

/// The volume's optical depth over [t0, t1] of the pixel's ray (t0 <= t1),
/// minus the subtract union.
float meshVolumeDepth(ivec2 pixel, vec3 farRay, float t0, float t1) {
    vec3 g = volume.gradientDirection;
    float heightAt0 = dot(frame.eye - volume.position, g) - volume.gradientOffset;
    return maskedExponentialDepth(pixel, volume.density, volume.falloff, heightAt0, dot(farRay, g),
                                  length(farRay), t0, t1);
}

/// F(t): the signed optical depth from tRef to t.
float meshVolumeAntiderivative(ivec2 pixel, vec3 farRay, float tRef, float t) {
    return t >= tRef ? meshVolumeDepth(pixel, farRay, tRef, t) : -meshVolumeDepth(pixel, farRay, t, tRef);
}

#endif
