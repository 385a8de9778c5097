// fog_volume.cpp — box and ellipsoid fog volumes (../shared/DESIGN.md, "Fog
// volumes"; Wenzel 2006, section 6.6: rays traced in object space against
// the unit cube / unit sphere, results used in world space).
//
// The geometry lives in bvh.hpp (prepareVolume, intersectPrepared,
// opticalDepthPrepared) so that FogScene and these single-volume functions
// share one implementation.
#include "bvh.hpp"

#include <aerial/fog_volume.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace aerial {

VolumeSegment intersectFogVolume(const FogVolume& volume, const glm::dvec3& origin,
                                 const glm::dvec3& direction, double tMax) {
    if (!detail::withinCoordinateRange(origin) || !detail::withinCoordinateRange(direction) ||
        !(tMax > 0.0)) {
        return {};
    }
    const double tLimit = std::min(tMax, std::numeric_limits<double>::max());  // +Inf allowed
    return detail::intersectPrepared(detail::prepareVolume(volume), origin, direction, tLimit);
}

double fogVolumeOpticalDepth(const FogVolume& volume, const glm::dvec3& origin, const glm::dvec3& direction,
                             const VolumeSegment& segment) {
    if (!segment.hit || !detail::withinCoordinateRange(origin) || !detail::withinCoordinateRange(direction) ||
        !std::isfinite(segment.tIn) || !std::isfinite(segment.tOut) || !(segment.tOut > segment.tIn)) {
        return 0.0;
    }
    return detail::opticalDepthPrepared(detail::prepareVolume(volume), origin, direction, segment);
}

double fogVolumeDensityAt(const FogVolume& volume, const glm::dvec3& point) {
    const detail::PreparedVolume p = detail::prepareVolume(volume);
    if (!p.valid || !detail::withinCoordinateRange(point)) {
        return 0.0;
    }
    const glm::dvec3 q = p.toObject(point - p.position);
    const bool inside = (p.shape == FogVolumeShape::Box)
                            ? std::max({std::fabs(q.x), std::fabs(q.y), std::fabs(q.z)}) <= 1.0
                            : glm::dot(q, q) <= 1.0;
    if (!inside) {
        return 0.0;
    }
    const double height = glm::dot(point - p.position, p.gradient) - p.gradientOffset;
    // Exponent capped so the density stays finite (saturates at DBL_MAX).
    const double exponent = std::min(-p.falloff * height, 700.0);
    return std::min(p.density * std::exp(exponent), std::numeric_limits<double>::max());
}

void fogVolumeBounds(const FogVolume& volume, glm::dvec3& boundsMin, glm::dvec3& boundsMax) {
    const detail::PreparedVolume p = detail::prepareVolume(volume);
    boundsMin = p.boundsMin;
    boundsMax = p.boundsMax;
}

}  // namespace aerial
