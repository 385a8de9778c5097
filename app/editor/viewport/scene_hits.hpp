// viewport/scene_hits.hpp — rays against the scene's real geometry (no GL):
// where a new object lands (the surface under the viewport's centre) and
// Drop to ground (the surface under an object). Brute force over the world
// triangles of the opaque and masked meshes, built once per scene: a click,
// not a frame.
//
//   SceneHits hits(renderer::makeBuiltinScene());
//   if (auto t = hits.intersect(eye, forward, 500.0)) place(eye + *t * forward);
//   if (auto y = hits.surfaceBelow(volume.position)) volume.position.y = *y + halfHeight;
#pragma once

#include <aerial/renderer/scene.hpp>

#include <glm/vec3.hpp>

#include <optional>
#include <vector>

namespace aerial::editor {

class SceneHits {
public:
    SceneHits() = default;
    /// The world-space triangles of the scene's opaque and masked meshes
    /// (alpha-blended ones are glass, not ground).
    explicit SceneHits(const renderer::SceneDesc& scene);

    /// Distance t >= 0 along origin + t direction (direction unit) to the
    /// first triangle (either side) within maxDistance, or nullopt.
    std::optional<double> intersect(const glm::dvec3& origin, const glm::dvec3& direction,
                                    double maxDistance) const;
    /// Height of the surface under `point`: straight down from it, else
    /// (the point is under the ground) the topmost surface from 100 km
    /// above; nullopt where nothing is below or above.
    std::optional<double> surfaceBelow(const glm::dvec3& point) const;
    std::size_t triangleCount() const { return corners_.size() / 3; }

private:
    std::vector<glm::dvec3> corners_;  ///< three per triangle, world space
};

}  // namespace aerial::editor
