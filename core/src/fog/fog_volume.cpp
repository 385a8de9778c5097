// fog_volume.cpp — box, ellipsoid and mesh fog volumes (../shared/DESIGN.md,
// "Fog volumes", "Mesh and subtract volumes"; Wenzel 2006, section 6.6: rays
// traced in object space against the unit cube / unit sphere / the mesh,
// results used in world space).
//
// The one geometry of a volume: FogScene (fog_query.cpp, through its BVH),
// the renderer's packing and the editor's picking all call prepareFogVolume
// and the intersections here.
#include "base/sanitise.hpp"
#include "volume_geometry.hpp"

#include <aerial/finite.hpp>
#include <aerial/fog_mesh.hpp>
#include <aerial/fog_volume.hpp>
#include <aerial/height_fog.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace aerial {

namespace detail {
namespace {

/// J_n(x) = int_0^1 s^n e^(x s) ds for n = 0..3 and x <= 0 (finite or
/// -Inf): the series sum_m x^m / (m! (n + m + 1)) for |x| < 2 (its terms
/// fall by |x| / m; the alternating sum loses at most e^2 ~ 7.4 in relative
/// accuracy), the recurrence J_n = (e^x - n J_(n-1)) / x from J_0 =
/// expm1(x) / x beyond (each step multiplies earlier errors by n / |x| <= 1.5,
/// 0.75 over all three).
void expMoments(double x, double j[4]) {
    if (x > -2.0) {
        double term = 1.0;  // x^m / m!
        for (int n = 0; n < 4; ++n) j[n] = 0.0;
        for (int m = 0; m < 40; ++m) {
            for (int n = 0; n < 4; ++n) j[n] += term / double(n + m + 1);
            term *= x / double(m + 1);
            if (std::fabs(term) < 1e-18) break;
        }
        return;
    }
    if (x == -std::numeric_limits<double>::infinity()) {
        j[0] = j[1] = j[2] = j[3] = 0.0;
        return;
    }
    const double ex = std::exp(x);
    j[0] = std::expm1(x) / x;
    for (int n = 1; n < 4; ++n) j[n] = (ex - double(n) * j[n - 1]) / x;
}

/// Clamped per-axis box profile clamp((1 - |q|) / sigma, 0, 1).
double boxRamp(double q, double softness) { return std::clamp((1.0 - std::fabs(q)) / softness, 0.0, 1.0); }

}  // namespace

double softStretchOpticalDepth(const PreparedFogVolume& p, const glm::dvec3& origin,
                               const glm::dvec3& direction, const VolumeSegment& seg) {
    const double sigma = p.edgeSoftness;
    const double b = p.density;
    const double lengthPerT = glm::length(direction);
    if (!(b > 0.0) || !(seg.tOut > seg.tIn) || !(lengthPerT > 0.0)) {
        return 0.0;
    }
    const glm::dvec3 o = p.toObject(origin - p.position);
    const glm::dvec3 d = p.toObject(direction);
    const double rate = glm::dot(direction, p.gradient);  // height change per unit t
    const double height0 = glm::dot(origin - p.position, p.gradient) - p.gradientOffset;
    const double inner = 1.0 - sigma;

    // Breakpoints of the profile inside the stretch.
    double cuts[11];
    int count = 0;
    cuts[count++] = seg.tIn;
    const auto addCut = [&](double t) {
        if (t > seg.tIn && t < seg.tOut) cuts[count++] = t;
    };
    const bool box = p.shape == FogVolumeShape::Box;
    if (box) {
        for (int i = 0; i < 3; ++i) {
            if (d[i] != 0.0) {
                addCut((inner - o[i]) / d[i]);
                addCut((-inner - o[i]) / d[i]);
                addCut(-o[i] / d[i]);
            }
        }
    } else {
        // |o + t d| = 1 - sigma, from the closest approach (as lineInterval).
        const double a = glm::dot(d, d);
        if (a > 0.0) {
            const double tMid = -glm::dot(o, d) / a;
            const glm::dvec3 perp = o + tMid * d;
            const double h = inner * inner - glm::dot(perp, perp);
            if (h > 0.0) {
                const double half = std::sqrt(h / a);
                addCut(tMid - half);
                addCut(tMid + half);
            }
        }
    }
    cuts[count++] = seg.tOut;
    for (int i = 1; i < count; ++i) {  // insertion sort (at most 11; as the shader)
        const double v = cuts[i];
        int k = i - 1;
        for (; k >= 0 && cuts[k] > v; --k) cuts[k + 1] = cuts[k];
        cuts[k + 1] = v;
    }

    double tau = 0.0;
    for (int k = 0; k + 1 < count; ++k) {
        const double t0 = cuts[k];
        const double span = cuts[k + 1] - t0;
        if (!(span > 0.0)) continue;
        // The profile on the piece as a polynomial in s in [0, 1], t = t0 + s span.
        double poly[4] = {0.0, 0.0, 0.0, 0.0};
        const glm::dvec3 q0 = o + t0 * d;
        const glm::dvec3 dq = span * d;
        if (box) {
            poly[0] = 1.0;
            for (int i = 0; i < 3; ++i) {
                const double w0 = boxRamp(q0[i], sigma);
                const double w1 = boxRamp(q0[i] + dq[i], sigma);
                const double slope = w1 - w0;
                // poly *= (w0 + slope s)
                for (int n = 3; n >= 1; --n) poly[n] = poly[n] * w0 + poly[n - 1] * slope;
                poly[0] *= w0;
            }
        } else {
            const glm::dvec3 mid = q0 + 0.5 * dq;
            if (glm::dot(mid, mid) <= inner * inner) {
                poly[0] = 1.0;
            } else {
                const double scale = 1.0 / (1.0 - inner * inner);
                poly[0] = (1.0 - glm::dot(q0, q0)) * scale;
                poly[1] = -2.0 * glm::dot(q0, dq) * scale;
                poly[2] = -glm::dot(dq, dq) * scale;
            }
        }
        // Exponent -c h(t) = -y0 + x s; integrate from the denser end.
        double y0 = p.falloff * (height0 + t0 * rate);
        double x = -p.falloff * rate * span;
        if (x > 0.0) {  // denser at s = 1: reflect s -> 1 - s
            y0 -= x;
            x = -x;
            const double r[4] = {poly[0] + poly[1] + poly[2] + poly[3],
                                 -(poly[1] + 2.0 * poly[2] + 3.0 * poly[3]), poly[2] + 3.0 * poly[3],
                                 -poly[3]};
            for (int n = 0; n < 4; ++n) poly[n] = r[n];
        }
        double j[4];
        expMoments(x, j);
        const double integral = poly[0] * j[0] + poly[1] * j[1] + poly[2] * j[2] + poly[3] * j[3];
        const double m = b * span * lengthPerT * std::max(integral, 0.0);
        if (!(m > 0.0)) continue;
        if (y0 > -700.0) {
            tau += m * std::exp(-y0);
        } else {
            const double logTau = std::log(m) - y0;
            tau += logTau < std::log(kMaxOpticalDepth) ? std::exp(logTau) : kMaxOpticalDepth;
        }
    }
    return std::min(tau, kMaxOpticalDepth);
}

}  // namespace detail

PreparedFogVolume prepareFogVolume(const FogVolume& v) {
    using limits::kMaxCoordinate;
    using limits::kMinHalfExtent;
    PreparedFogVolume p;
    p.shape = v.shape;
    p.colourMode = v.colourMode;
    p.colour = detail::sanitiseColour(v.colour);
    p.density = detail::sanitiseNonNegative(v.density);
    p.falloff = detail::sanitiseNonNegative(v.falloff);
    p.gradient = detail::safeDirection(v.gradientDirection);
    p.gradientOffset = detail::sanitiseSigned(v.gradientOffset);
    p.blend = v.blend == FogVolumeBlend::Subtract ? FogVolumeBlend::Subtract : FogVolumeBlend::Add;
    if (v.shape == FogVolumeShape::Mesh) p.mesh = v.meshData;
    const bool softShape = v.shape != FogVolumeShape::Mesh && p.blend == FogVolumeBlend::Add;
    p.edgeSoftness = (softShape && v.edgeSoftness > 0.0) ? std::min(v.edgeSoftness, 1.0) : 0.0;  // NaN -> 0

    const glm::dvec3 s = v.halfExtents;
    const bool extentsOk = s.x >= kMinHalfExtent && s.y >= kMinHalfExtent && s.z >= kMinHalfExtent &&
                           s.x <= kMaxCoordinate && s.y <= kMaxCoordinate && s.z <= kMaxCoordinate;
    const glm::dquat q = v.rotation;
    const double qNorm2 = q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z;
    const bool rotationOk = std::isfinite(qNorm2) && qNorm2 > 1.0e-200;
    const bool positionOk = withinCoordinateRange(v.position);
    p.position = positionOk ? v.position : glm::dvec3(0.0);
    p.boundsMin = p.position;
    p.boundsMax = p.position;
    const bool shapeOk = v.shape != FogVolumeShape::Mesh || p.mesh != nullptr;
    if (!(extentsOk && rotationOk && positionOk && shapeOk)) {
        p.mesh.reset();
        return p;  // degenerate: never hit, density 0 everywhere
    }
    p.valid = true;

    // World from object rotation R (columns = object axes in world space).
    const glm::dmat3 r = glm::mat3_cast(q / std::sqrt(qNorm2));
    // objectFromWorld = S^-1 R^T: its rows are R's columns over the extents.
    p.row0 = r[0] / s.x;
    p.row1 = r[1] / s.y;
    p.row2 = r[2] / s.z;
    for (int c = 0; c < 3; ++c) {
        p.worldFromObject[c] = r[c] * s[c];
    }

    if (v.shape == FogVolumeShape::Mesh) {
        // World AABB of the placed vertices (tight).
        p.boundsMin = glm::dvec3(std::numeric_limits<double>::infinity());
        p.boundsMax = -p.boundsMin;
        for (const glm::dvec3& vertex : p.mesh->positions()) {
            const glm::dvec3 w = p.position + p.worldFromObject * vertex;
            p.boundsMin = glm::min(p.boundsMin, w);
            p.boundsMax = glm::max(p.boundsMax, w);
        }
        return p;
    }
    // World AABB: half width along world axis i of the image of the unit
    // cube is sum_j |R_ij| s_j; of the unit sphere sqrt(sum_j (R_ij s_j)^2).
    glm::dvec3 half;
    for (int i = 0; i < 3; ++i) {
        const double a = r[0][i] * s.x;
        const double b = r[1][i] * s.y;
        const double c = r[2][i] * s.z;
        half[i] = (v.shape == FogVolumeShape::Box) ? std::fabs(a) + std::fabs(b) + std::fabs(c)
                                                   : std::sqrt(a * a + b * b + c * c);
    }
    p.boundsMin = p.position - half;
    p.boundsMax = p.position + half;
    return p;
}

VolumeInterval intersectFogVolumeLine(const PreparedFogVolume& volume, const glm::dvec3& origin,
                                      const glm::dvec3& direction) {
    if (!withinCoordinateRange(origin) || !withinCoordinateRange(direction)) {
        return {};
    }
    return detail::lineInterval(volume, origin, direction);
}

VolumeSegment intersectFogVolume(const PreparedFogVolume& volume, const glm::dvec3& origin,
                                 const glm::dvec3& direction, double tMax) {
    if (!withinCoordinateRange(origin) || !withinCoordinateRange(direction) || !(tMax >= 0.0)) {
        return {};
    }
    return detail::clippedSegment(volume, origin, direction, tMax);
}

double fogVolumeOpticalDepth(const PreparedFogVolume& volume, const glm::dvec3& origin,
                             const glm::dvec3& direction, const VolumeSegment& segment) {
    if (!withinCoordinateRange(origin) || !withinCoordinateRange(direction)) {
        return 0.0;
    }
    return detail::segmentOpticalDepth(volume, origin, direction, segment);
}

std::size_t fogVolumeChords(const PreparedFogVolume& volume, const glm::dvec3& origin,
                            const glm::dvec3& direction, double tMax, std::vector<VolumeSegment>& chords) {
    chords.clear();
    if (!withinCoordinateRange(origin) || !withinCoordinateRange(direction) || !(tMax >= 0.0)) {
        return 0;
    }
    detail::clippedChords(volume, origin, direction, 0.0, tMax, chords);
    return chords.size();
}

bool fogVolumeContains(const PreparedFogVolume& p, const glm::dvec3& point) {
    if (!p.valid || !withinCoordinateRange(point)) {
        return false;
    }
    const glm::dvec3 q = p.toObject(point - p.position);
    if (p.shape == FogVolumeShape::Mesh) {
        return p.mesh->contains(q);
    }
    return (p.shape == FogVolumeShape::Box)
               ? std::max({std::fabs(q.x), std::fabs(q.y), std::fabs(q.z)}) <= 1.0
               : glm::dot(q, q) <= 1.0;
}

VolumeSegment intersectFogVolume(const FogVolume& volume, const glm::dvec3& origin,
                                 const glm::dvec3& direction, double tMax) {
    if (!withinCoordinateRange(origin) || !withinCoordinateRange(direction) || !(tMax > 0.0)) {
        return {};
    }
    const double tLimit = std::min(tMax, std::numeric_limits<double>::max());  // +Inf allowed
    return detail::clippedSegment(prepareFogVolume(volume), origin, direction, tLimit);
}

double fogVolumeOpticalDepth(const FogVolume& volume, const glm::dvec3& origin, const glm::dvec3& direction,
                             const VolumeSegment& segment) {
    if (!segment.hit || !withinCoordinateRange(origin) || !withinCoordinateRange(direction) ||
        !std::isfinite(segment.tIn) || !std::isfinite(segment.tOut) || !(segment.tOut > segment.tIn)) {
        return 0.0;
    }
    return detail::segmentOpticalDepth(prepareFogVolume(volume), origin, direction, segment);
}

double fogVolumeDensityAt(const FogVolume& volume, const glm::dvec3& point) {
    const PreparedFogVolume p = prepareFogVolume(volume);
    if (!fogVolumeContains(p, point)) {
        return 0.0;
    }
    const double height = glm::dot(point - p.position, p.gradient) - p.gradientOffset;
    // Exponent capped so the density stays finite (saturates at DBL_MAX).
    const double exponent = std::min(-p.falloff * height, 700.0);
    const double rho = std::min(p.density * std::exp(exponent), std::numeric_limits<double>::max());
    if (!(p.edgeSoftness > 0.0)) {
        return rho;
    }
    // The soft-edge profile (fog_volume.hpp, "Soft edges").
    const glm::dvec3 q = p.toObject(point - p.position);
    const double sigma = p.edgeSoftness;
    double w = 1.0;
    if (p.shape == FogVolumeShape::Box) {
        w = detail::boxRamp(q.x, sigma) * detail::boxRamp(q.y, sigma) * detail::boxRamp(q.z, sigma);
    } else {
        const double inner = 1.0 - sigma;
        w = std::clamp((1.0 - glm::dot(q, q)) / (1.0 - inner * inner), 0.0, 1.0);
    }
    return rho * w;
}

void fogVolumeBounds(const FogVolume& volume, glm::dvec3& boundsMin, glm::dvec3& boundsMax) {
    const PreparedFogVolume p = prepareFogVolume(volume);
    boundsMin = p.boundsMin;
    boundsMax = p.boundsMax;
}

}  // namespace aerial
