// weather_region.cpp — regional weather: a region's depth and weight at a
// point, and the camera's mix with the preset's regions applied
// (aerial/weather.hpp).
#include <aerial/weather.hpp>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace aerial {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
/// Half extents outside [kMinHalf, kMaxHalf] make a region invalid (as fog
/// volumes: aerial/limits.hpp, "Geometry").
constexpr double kMinHalf = 1e-6;
constexpr double kMaxHalf = 1e30;

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

/// The point in the region's object frame (unscaled: metres along the
/// object axes); false for an invalid region or point.
bool objectPoint(const WeatherRegion& region, const glm::dvec3& point, glm::dvec3& local) {
    const glm::dvec3& h = region.halfExtents;
    if (!(h.x >= kMinHalf && h.y >= kMinHalf && h.z >= kMinHalf && h.x <= kMaxHalf && h.y <= kMaxHalf &&
          h.z <= kMaxHalf))
        return false;
    if (!finite(region.position) || !finite(point)) return false;
    const glm::dquat& q = region.rotation;
    const double length = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
    if (!(length > 1e-150) || !std::isfinite(length)) return false;
    const glm::dquat unit(q.w / length, q.x / length, q.y / length, q.z / length);
    local = glm::conjugate(unit) * (point - region.position);  // object from world: R^T
    return finite(local);
}

double boxDepth(const glm::dvec3& p, const glm::dvec3& h) {
    const glm::dvec3 d = glm::abs(p) - h;  // > 0 beyond a face
    const double inside = std::min(-d.x, std::min(-d.y, -d.z));
    if (inside >= 0.0) return inside;
    return -glm::length(glm::max(d, glm::dvec3(0.0)));
}

/// Sum of (p_i / h_i)^2: <= 1 inside the ellipsoid.
double ellipsoidLevel(const glm::dvec3& p, const glm::dvec3& h) {
    const glm::dvec3 q = p / h;
    return glm::dot(q, q);
}

/// The exact distance from p to the ellipsoid's surface, signed (> 0
/// inside): Eberly, "Distance from a Point to an Ellipse, an Ellipsoid, or a
/// Hyperellipsoid" (2013). In units of the largest half extent, with e the
/// half extents and y = |p|, the closest surface point is x_i = e_i^2 y_i /
/// (t + e_i^2), t the root of F(t) = sum_i (e_i y_i / (t + e_i^2))^2 - 1 on
/// t > -e_min^2, where F falls from +inf to below 0 at |e y|. Solved for
/// s = t + e_min^2 > 0 (no cancellation near the pole) by bisection down to
/// adjacent doubles: deterministic, at most 256 steps. Each y_i is raised to
/// at least 1e-12 e_min so that F has its pole (a point in a plane of
/// symmetry, the centre included, moves by at most 2e-12 e_min).
double ellipsoidDepth(const glm::dvec3& p, const glm::dvec3& h) {
    const double scale = std::max(h.x, std::max(h.y, h.z));
    const double e[3] = {h.x / scale, h.y / scale, h.z / scale};
    const double eMin = std::min(e[0], std::min(e[1], e[2]));
    double y[3], gap[3], ey = 0.0;
    for (int i = 0; i < 3; ++i) {
        y[i] = std::max(std::abs(p[i]) / scale, 1e-12 * eMin);
        gap[i] = e[i] == eMin ? 0.0 : e[i] * e[i] - eMin * eMin;  // e_i^2 - e_min^2 >= 0
        ey += (e[i] * y[i]) * (e[i] * y[i]);
    }
    double lo = 0.0, hi = std::sqrt(ey) + eMin * eMin;
    for (int step = 0; step < 256; ++step) {
        const double mid = 0.5 * (lo + hi);
        if (!(mid > lo && mid < hi)) break;
        double f = -1.0;
        for (int i = 0; i < 3; ++i) {
            const double r = e[i] * y[i] / (mid + gap[i]);
            f += r * r;
        }
        (f > 0.0 ? lo : hi) = mid;
    }
    const double s = 0.5 * (lo + hi);
    double squared = 0.0;
    for (int i = 0; i < 3; ++i) {
        const double d = e[i] * e[i] * y[i] / (s + gap[i]) - y[i];
        squared += d * d;
    }
    const double distance = std::sqrt(squared) * scale;
    return ellipsoidLevel(p, h) <= 1.0 ? distance : -distance;
}

double smoothstep01(double x) {
    x = std::clamp(x, 0.0, 1.0);
    return x * x * (3.0 - 2.0 * x);
}

/// The index of a region's state in preset.weather; -1 for "none"; -2 when
/// the preset has no such state.
int regionStateIndex(const Preset& preset, const WeatherRegion& region) {
    if (region.state == "none") return -1;
    for (std::size_t i = 0; i < preset.weather.size(); ++i)
        if (preset.weather[i].name == region.state) return int(i);
    return -2;
}

}  // namespace

double weatherRegionDepth(const WeatherRegion& region, const glm::dvec3& point) {
    glm::dvec3 p;
    if (!objectPoint(region, point, p)) return -kInfinity;
    return region.shape == WeatherRegionShape::Ellipsoid ? ellipsoidDepth(p, region.halfExtents)
                                                         : boxDepth(p, region.halfExtents);
}

double weatherRegionWeight(const WeatherRegion& region, const glm::dvec3& point) {
    glm::dvec3 p;
    if (!objectPoint(region, point, p)) return 0.0;
    const double blend = std::isfinite(region.blend) ? std::max(region.blend, 0.0) : 0.0;
    const glm::dvec3& h = region.halfExtents;
    double depth = 0.0;
    if (region.shape == WeatherRegionShape::Ellipsoid) {
        // Outside, or deeper than the blend by the bound (1 - sqrt(level))
        // e_min <= depth: no root to find.
        const double level = ellipsoidLevel(p, h);
        if (!(level <= 1.0)) return 0.0;
        const double bound = (1.0 - std::sqrt(level)) * std::min(h.x, std::min(h.y, h.z));
        if (bound >= blend) return 1.0;
        depth = std::max(ellipsoidDepth(p, h), 0.0);
    } else {
        depth = boxDepth(p, h);
        if (!(depth >= 0.0)) return 0.0;
    }
    if (!(blend > 0.0)) return 1.0;
    return smoothstep01(depth / blend);
}

void regionalWeather(const Preset& preset, const glm::dvec3& camera, const WeatherMix& global,
                     WeatherMix& out) {
    if (&out != &global) out.weights = global.weights;  // reuses out's storage
    const std::size_t count = preset.weather.size();
    const std::vector<WeatherRegion>& regions = preset.weatherRegions;
    if (regions.empty()) return;
    // Priorities in ascending order without sorting (no allocation): each
    // pass takes the lowest priority above the previous pass's, and its
    // regions in file order.
    bool applied = false;
    long long previous = std::numeric_limits<long long>::min();
    while (true) {
        long long priority = std::numeric_limits<long long>::max();
        bool found = false;
        for (const WeatherRegion& r : regions)
            if (r.priority > previous && r.priority < priority) {
                priority = r.priority;
                found = true;
            }
        if (!found) break;
        for (const WeatherRegion& r : regions) {
            if (r.priority != priority) continue;
            const int state = regionStateIndex(preset, r);
            if (state == -2) continue;
            const double w = weatherRegionWeight(r, camera);
            if (!(w > 0.0)) continue;
            if (out.weights.size() != count) out.weights.resize(count);  // new rows: weight 0
            for (std::size_t i = 0; i < count; ++i)
                for (double& v : out.weights[i]) v = (1.0 - w) * v + (int(i) == state ? w : 0.0);
            applied = true;
        }
        previous = priority;
    }
    if (!applied) return;
    for (const auto& row : out.weights)
        for (double v : row)
            if (v != 0.0) return;
    out.weights.clear();  // a "none" region holds fully: the keyed values
}

}  // namespace aerial
