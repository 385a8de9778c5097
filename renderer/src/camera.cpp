// camera.cpp — camera matrices and far-plane corner rays (Wenzel 2006,
// section 6.3: the rays from the eye to the far plane's corners,
// interpolated across the screen, turn linear depth into world positions
// with one multiply-add).
#include <aerial/finite.hpp>
#include <aerial/renderer/camera.hpp>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace aerial::renderer {
namespace {

glm::dvec3 normalisedOr(const glm::dvec3& v, const glm::dvec3& fallback) {
    const double len = glm::length(v);
    return (len > 1e-300 && std::isfinite(len)) ? v / len : fallback;
}

}  // namespace

CameraFrame cameraFrame(const Camera& camera) {
    CameraFrame f;
    f.eye = isFinite(camera.eye) ? camera.eye : glm::dvec3(0.0);
    const glm::dvec3 target = isFinite(camera.target) ? camera.target : f.eye + glm::dvec3(0.0, 0.0, -1.0);
    f.forward = normalisedOr(target - f.eye, glm::dvec3(0.0, 0.0, -1.0));
    glm::dvec3 up = isFinite(camera.up) ? camera.up : glm::dvec3(0.0, 1.0, 0.0);
    glm::dvec3 right = glm::cross(f.forward, up);
    if (glm::length(right) < 1e-9 * std::max(glm::length(up), 1e-300)) {
        // Up parallel to the view: any perpendicular will do.
        right =
            glm::cross(f.forward, std::fabs(f.forward.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0));
    }
    f.right = glm::normalize(right);
    f.up = glm::cross(f.right, f.forward);

    const double fov =
        std::isfinite(camera.verticalFov) ? std::clamp(camera.verticalFov, 1e-4, 3.14149) : 1.0472;
    const double aspect = (std::isfinite(camera.aspect) && camera.aspect > 0.0) ? camera.aspect : 1.0;
    f.nearDistance =
        (std::isfinite(camera.nearDistance) && camera.nearDistance > 0.0) ? camera.nearDistance : 0.1;
    f.farDistance = (std::isfinite(camera.farDistance) && camera.farDistance > f.nearDistance)
                        ? camera.farDistance
                        : f.nearDistance * 1.0e4;

    // viewFromWorld: rows right, up, -forward (OpenGL looks down -Z).
    glm::dmat4 view(1.0);
    for (int i = 0; i < 3; ++i) {
        view[i][0] = f.right[i];
        view[i][1] = f.up[i];
        view[i][2] = -f.forward[i];
    }
    view[3][0] = -glm::dot(f.right, f.eye);
    view[3][1] = -glm::dot(f.up, f.eye);
    view[3][2] = glm::dot(f.forward, f.eye);
    f.viewFromWorld = view;

    const double tanHalf = std::tan(0.5 * fov);
    const double n = f.nearDistance;
    const double fa = f.farDistance;
    glm::dmat4 proj(0.0);
    proj[0][0] = 1.0 / (aspect * tanHalf);
    proj[1][1] = 1.0 / tanHalf;
    proj[2][2] = -(fa + n) / (fa - n);
    proj[2][3] = -1.0;
    proj[3][2] = -2.0 * fa * n / (fa - n);
    f.clipFromView = proj;
    f.clipFromWorld = proj * view;

    const glm::dvec3 centre = f.forward * fa;
    const glm::dvec3 halfRight = f.right * (fa * tanHalf * aspect);
    const glm::dvec3 halfUp = f.up * (fa * tanHalf);
    f.farCornerRays = {centre - halfRight - halfUp, centre + halfRight - halfUp, centre - halfRight + halfUp,
                       centre + halfRight + halfUp};
    return f;
}

glm::dvec3 farRayAtNdc(const CameraFrame& frame, double ndcX, double ndcY) {
    const double fx = 0.5 * ndcX + 0.5;
    const double fy = 0.5 * ndcY + 0.5;
    const glm::dvec3 bottom = frame.farCornerRays[0] + fx * (frame.farCornerRays[1] - frame.farCornerRays[0]);
    const glm::dvec3 top = frame.farCornerRays[2] + fx * (frame.farCornerRays[3] - frame.farCornerRays[2]);
    return bottom + fy * (top - bottom);
}

glm::dvec3 farRayAtPixel(const CameraFrame& frame, int x, int y, int width, int height) {
    const double ndcX = (x + 0.5) / width * 2.0 - 1.0;
    const double ndcY = 1.0 - (y + 0.5) / height * 2.0;  // y from the top row
    return farRayAtNdc(frame, ndcX, ndcY);
}

}  // namespace aerial::renderer
