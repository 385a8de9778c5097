// common/soft_volume.glsl — the optical depth of a box or ellipsoid fog
// volume with a soft edge (fog_volume.hpp, "Soft edges"; the float twin of
// core/src/fog/fog_volume.cpp, softStretchOpticalDepth): the density
// b exp(-c h) times the profile w, 1 deep inside and 0 at the surface —
//   ellipsoid: w = clamp((1 - |q|^2) / (1 - (1 - sigma)^2), 0, 1),
//   box:       w = prod_i clamp((1 - |q_i|) / sigma, 0, 1),
// q the object-space point. Along a ray w is a polynomial (degree 2, 3)
// between breakpoints; on each piece int_0^1 P(s) e^(x s) ds =
// sum_n p_n J_n(x), J_n(x) = int_0^1 s^n e^(xs) ds (series for |x| < 2,
// recurrence beyond; x <= 0, each piece taken from its denser end).
// Inputs: the ray o + t d in object space (o, d) and in world terms
// (heightAt0 = height above the b plane at t = 0 [m], rate = height change
// per unit t [m], lengthPerT = world length per unit t [m]), the piece
// [t0, t1] inside the shape. Output: optical depth, <= kMaxOpticalDepth.
// Requires common/atmosphere.glsl.
#ifndef AERIAL_SOFT_VOLUME_GLSL
#define AERIAL_SOFT_VOLUME_GLSL

/// J_0..J_3 at x <= 0.
vec4 softExpMoments(float x) {
    if (x > -2.0) {
        vec4 j = vec4(0.0);
        float term = 1.0;
        for (int m = 0; m < 24; ++m) {
            j += term / (vec4(1.0, 2.0, 3.0, 4.0) + float(m));
            term *= x / float(m + 1);
            if (abs(term) < 1e-9) break;
        }
        return j;
    }
    float ex = exp(max(x, -80.0));
    vec4 j;
    j.x = (ex - 1.0) / x;
    j.y = (ex - j.x) / x;
    j.z = (ex - 2.0 * j.y) / x;
    j.w = (ex - 3.0 * j.z) / x;
    return j;
}

float softBoxRamp(float q, float sigma) { return clamp((1.0 - abs(q)) / sigma, 0.0, 1.0); }

float softVolumeDepth(float shape, float sigma, vec3 o, vec3 d, float b, float c, float heightAt0, float rate,
                      float lengthPerT, float t0, float t1) {
    if (!(b > 0.0) || !(t1 > t0)) return 0.0;
    c = max(c, 0.0);
    float inner = 1.0 - sigma;
    bool box = shape < 0.5;
    float cuts[11];
    int count = 0;
    cuts[count++] = t0;
    if (box) {
        for (int i = 0; i < 3; ++i) {
            if (d[i] == 0.0) continue;
            float k[3] = float[3]((inner - o[i]) / d[i], (-inner - o[i]) / d[i], -o[i] / d[i]);
            for (int n = 0; n < 3; ++n)
                if (k[n] > t0 && k[n] < t1) cuts[count++] = k[n];
        }
    } else {
        float a = dot(d, d);
        if (a > 0.0) {
            float tMid = -dot(o, d) / a;
            vec3 perp = o + tMid * d;
            float h = inner * inner - dot(perp, perp);
            if (h > 0.0) {
                float half_ = sqrt(h / a);
                if (tMid - half_ > t0 && tMid - half_ < t1) cuts[count++] = tMid - half_;
                if (tMid + half_ > t0 && tMid + half_ < t1) cuts[count++] = tMid + half_;
            }
        }
    }
    cuts[count++] = t1;
    for (int i = 1; i < count; ++i) {  // insertion sort
        float v = cuts[i];
        int k = i - 1;
        while (k >= 0 && cuts[k] > v) {
            cuts[k + 1] = cuts[k];
            --k;
        }
        cuts[k + 1] = v;
    }
    float tau = 0.0;
    for (int k = 0; k + 1 < count; ++k) {
        float ta = cuts[k];
        float span = cuts[k + 1] - ta;
        if (!(span > 0.0)) continue;
        vec4 poly = vec4(0.0);  // the profile in s in [0, 1]
        vec3 q0 = o + ta * d;
        vec3 dq = span * d;
        if (box) {
            poly = vec4(1.0, 0.0, 0.0, 0.0);
            for (int i = 0; i < 3; ++i) {
                float w0 = softBoxRamp(q0[i], sigma);
                float slope = softBoxRamp(q0[i] + dq[i], sigma) - w0;
                poly = vec4(poly.x * w0, poly.y * w0 + poly.x * slope, poly.z * w0 + poly.y * slope,
                            poly.w * w0 + poly.z * slope);
            }
        } else {
            vec3 mid = q0 + 0.5 * dq;
            if (dot(mid, mid) <= inner * inner) {
                poly = vec4(1.0, 0.0, 0.0, 0.0);
            } else {
                float scale = 1.0 / (1.0 - inner * inner);
                poly = vec4(1.0 - dot(q0, q0), -2.0 * dot(q0, dq), -dot(dq, dq), 0.0) * scale;
            }
        }
        float y0 = c * (heightAt0 + ta * rate);
        float x = -c * rate * span;
        if (x > 0.0) {  // denser at s = 1: s -> 1 - s
            y0 -= x;
            x = -x;
            poly = vec4(poly.x + poly.y + poly.z + poly.w, -(poly.y + 2.0 * poly.z + 3.0 * poly.w),
                        poly.z + 3.0 * poly.w, -poly.w);
        }
        float m = b * span * lengthPerT * max(dot(poly, softExpMoments(x)), 0.0);
        // As exponentialOpticalDepth: exp(80) ~ 5.5e34 saturates anyway.
        tau += m * exp(min(-y0, 80.0));
    }
    return min(tau, kMaxOpticalDepth);
}

#endif
