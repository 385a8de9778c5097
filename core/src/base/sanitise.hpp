// sanitise.hpp — private: how core turns the numbers a caller passes (fog
// densities, colours, directions) into numbers its formulas accept, without
// NaN or Inf (aerial/fog_volume.hpp, "Sanitising"; limits.hpp, "Geometry").
#pragma once

#include <aerial/limits.hpp>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>

namespace aerial::detail {

/// Not finite or negative -> 0, else clamped to [0, kMaxFogParameter].
inline double sanitiseNonNegative(double x) {
    return (std::isfinite(x) && x > 0.0) ? std::min(x, limits::kMaxFogParameter) : 0.0;
}

/// Not finite -> 0, else clamped to [-kMaxFogParameter, kMaxFogParameter].
inline double sanitiseSigned(double x) {
    return std::isfinite(x) ? std::clamp(x, -limits::kMaxFogParameter, limits::kMaxFogParameter) : 0.0;
}

/// Radiance and colour components: not finite or negative -> 0, at most 1e30.
inline glm::dvec3 sanitiseColour(const glm::dvec3& c) {
    auto one = [](double x) { return (std::isfinite(x) && x > 0.0) ? std::min(x, 1.0e30) : 0.0; };
    return {one(c.x), one(c.y), one(c.z)};
}

/// Normalised direction; +Y when zero or not finite.
inline glm::dvec3 safeDirection(const glm::dvec3& v) {
    if (!(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z))) {
        return {0.0, 1.0, 0.0};
    }
    // Rescale first so that tiny or huge vectors normalise without
    // underflow or overflow.
    const double m = std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
    if (!(m > 0.0)) {
        return {0.0, 1.0, 0.0};
    }
    const glm::dvec3 s = v / m;
    return s / std::sqrt(glm::dot(s, s));
}

}  // namespace aerial::detail
