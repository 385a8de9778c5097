// common/unit_shape.glsl — a ray against a fog volume's unit shape in
// object space (DESIGN.md "Fog volumes"; core's intersectFogVolumeLine):
// the unit cube [-1, 1]^3 (shape 0, box) or the unit sphere (shape 1,
// ellipsoid). Shared by the volume hulls (common/volume.glsl) and the
// volumetric fog's injection (froxel_inject.glsl).
#ifndef AERIAL_UNIT_SHAPE_GLSL
#define AERIAL_UNIT_SHAPE_GLSL

/// Entry and exit parameters of o + t d against the unit cube (shape < 0.5)
/// or the unit sphere; tNear > tFar when missed.
vec2 unitShapeHit(float shape, vec3 o, vec3 d) {
    if (shape < 0.5) {
        // Slabs |o_i + t d_i| <= 1.
        float tNear = -3.0e38;
        float tFar = 3.0e38;
        for (int i = 0; i < 3; ++i) {
            if (abs(d[i]) > 1e-30) {
                float t1 = (-1.0 - o[i]) / d[i];
                float t2 = (1.0 - o[i]) / d[i];
                tNear = max(tNear, min(t1, t2));
                tFar = min(tFar, max(t1, t2));
            } else if (abs(o[i]) > 1.0) {
                return vec2(1.0, 0.0);
            }
        }
        return vec2(tNear, tFar);
    }
    // Unit sphere from the closest approach (no B^2 - AC cancellation).
    float a = dot(d, d);
    if (!(a > 0.0)) return vec2(1.0, 0.0);
    float tMid = -dot(o, d) / a;
    vec3 perp = o + tMid * d;
    float h = 1.0 - dot(perp, perp);
    if (!(h > 0.0)) return vec2(1.0, 0.0);
    float halfChord = sqrt(h / a);
    return vec2(tMid - halfChord, tMid + halfChord);
}

#endif
