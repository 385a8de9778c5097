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
    return std::min(p.density * std::exp(exponent), std::numeric_limits<double>::max());
}

void fogVolumeBounds(const FogVolume& volume, glm::dvec3& boundsMin, glm::dvec3& boundsMax) {
    const PreparedFogVolume p = prepareFogVolume(volume);
    boundsMin = p.boundsMin;
    boundsMax = p.boundsMax;
}

}  // namespace aerial
