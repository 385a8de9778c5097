// viewport/scene_hits.cpp — rays against the scene's triangles (scene_hits.hpp).
#include "viewport/scene_hits.hpp"

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include <cmath>
#include <limits>

namespace aerial::editor {

SceneHits::SceneHits(const renderer::SceneDesc& scene) {
    for (const renderer::SceneMesh& m : scene.meshes) {
        if (m.alphaMode == renderer::AlphaMode::Blend) continue;
        for (std::size_t i = 0; i + 2 < m.indices.size(); i += 3) {
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t index = m.indices[i + std::size_t(k)];
                if (index >= m.positions.size()) break;
                const glm::dvec3 p(m.positions[index]);
                corners_.push_back(glm::dvec3(m.worldFromObject * glm::dvec4(p, 1.0)));
            }
            if (corners_.size() % 3 != 0) corners_.resize(corners_.size() - corners_.size() % 3);
        }
    }
}

std::optional<double> SceneHits::intersect(const glm::dvec3& origin, const glm::dvec3& direction,
                                           double maxDistance) const {
    // Moeller-Trumbore, both faces.
    double best = std::isfinite(maxDistance) ? maxDistance : std::numeric_limits<double>::max();
    bool hit = false;
    for (std::size_t i = 0; i < corners_.size(); i += 3) {
        const glm::dvec3 e1 = corners_[i + 1] - corners_[i], e2 = corners_[i + 2] - corners_[i];
        const glm::dvec3 p = glm::cross(direction, e2);
        const double det = glm::dot(e1, p);
        if (std::abs(det) < 1e-14) continue;
        const double inv = 1.0 / det;
        const glm::dvec3 s = origin - corners_[i];
        const double u = glm::dot(s, p) * inv;
        if (u < 0.0 || u > 1.0) continue;
        const glm::dvec3 q = glm::cross(s, e1);
        const double v = glm::dot(direction, q) * inv;
        if (v < 0.0 || u + v > 1.0) continue;
        const double t = glm::dot(e2, q) * inv;
        if (t >= 0.0 && t <= best) best = t, hit = true;
    }
    if (!hit) return std::nullopt;
    return best;
}

std::optional<double> SceneHits::surfaceBelow(const glm::dvec3& point) const {
    const glm::dvec3 down(0.0, -1.0, 0.0);
    if (auto t = intersect(point, down, 1e5)) return point.y - *t;
    constexpr double kAbove = 1e5;
    const glm::dvec3 top(point.x, point.y + kAbove, point.z);
    if (auto t = intersect(top, down, 2e5)) return top.y - *t;
    return std::nullopt;
}

}  // namespace aerial::editor
