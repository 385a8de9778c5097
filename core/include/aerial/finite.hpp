// aerial/finite.hpp — finiteness and range checks for the vectors Aerial
// passes around (positions, directions, colours, rotations).
//
// Usage:
//   if (!aerial::isFinite(cameraPosition)) return;            // NaN or Inf
//   if (!aerial::withinCoordinateRange(point)) return {};     // |x| > 1e30 m
//
// The range is limits::kMaxCoordinate: beyond it a coordinate is not
// meaningful and Aerial treats the point or ray as absent (never as NaN).
#pragma once

#include <aerial/limits.hpp>

#include <glm/gtc/quaternion.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cmath>

namespace aerial {

inline bool isFinite(double x) { return std::isfinite(x); }
inline bool isFinite(const glm::dvec2& v) { return std::isfinite(v.x) && std::isfinite(v.y); }
inline bool isFinite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
inline bool isFinite(const glm::dvec4& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}
inline bool isFinite(const glm::dquat& q) {
    return std::isfinite(q.w) && std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z);
}

/// Every component within [-kMaxCoordinate, kMaxCoordinate] (false for NaN).
inline bool withinCoordinateRange(const glm::dvec3& v) {
    return std::fabs(v.x) <= limits::kMaxCoordinate && std::fabs(v.y) <= limits::kMaxCoordinate &&
           std::fabs(v.z) <= limits::kMaxCoordinate;
}

}  // namespace aerial
