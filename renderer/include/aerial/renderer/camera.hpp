// aerial/renderer/camera.hpp — a pinhole camera and the quantities the
// passes derive from it: matrices, and the far-plane corner rays used to
// reconstruct world positions from linear depth (Wenzel 2006, section 6.3).
//
// Usage:
//   aerial::renderer::Camera camera;
//   camera.eye = {0, 2, 10}; camera.target = {0, 2, 0};
//   camera.aspect = 160.0 / 90.0;
//   aerial::renderer::CameraFrame f = aerial::renderer::cameraFrame(camera);
//   glm::dvec3 p = f.eye + depth01 * aerial::renderer::farRayAtPixel(f, x, y, 160, 90);
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <array>

namespace aerial::renderer {

/// Right-handed, Y up, metres (DESIGN.md). Zero values are not valid
/// defaults here; the defaults below are.
struct Camera {
    glm::dvec3 eye{0.0, 2.0, 10.0};     ///< position [m]
    glm::dvec3 target{0.0, 2.0, 0.0};   ///< a point it looks at [m], != eye
    glm::dvec3 up{0.0, 1.0, 0.0};       ///< approximate up, not parallel to the view
    double verticalFov = 1.0471975512;  ///< vertical field of view [rad], 0..pi. Default 60 deg
    double nearDistance = 0.1;          ///< near plane [m], > 0. Default 0.1
    double farDistance = 5000.0;        ///< far plane [m], > near. Default 5000
    double aspect = 16.0 / 9.0;         ///< width / height, > 0
};

/// Everything the passes derive from a camera (double precision).
struct CameraFrame {
    glm::dvec3 eye{0.0};
    glm::dvec3 forward{0.0, 0.0, -1.0};  ///< unit view direction
    glm::dvec3 right{1.0, 0.0, 0.0};     ///< unit
    glm::dvec3 up{0.0, 1.0, 0.0};        ///< unit, orthogonal to forward and right
    double nearDistance = 0.1;
    double farDistance = 5000.0;
    glm::dmat4 viewFromWorld{1.0};
    glm::dmat4 clipFromView{1.0};  ///< OpenGL perspective, z in [-1, 1]
    glm::dmat4 clipFromWorld{1.0};
    /// From the eye to the far plane's corners [m]: bottom-left,
    /// bottom-right, top-left, top-right (each has eye depth farDistance).
    std::array<glm::dvec3, 4> farCornerRays{};
};

/// Derives the frame of a camera; invalid values are sanitised (eye ==
/// target looks along -Z, an up parallel to the view is replaced, the fov is
/// clamped to [1e-4, pi - 1e-4], near/far/aspect to positive values).
CameraFrame cameraFrame(const Camera& camera);

/// The ray from the eye to the far plane at normalised device coordinates
/// (-1..1, y up), bilinear in the corner rays. A point at normalised linear
/// depth d01 = z_view / far lies at eye + d01 * ray.
glm::dvec3 farRayAtNdc(const CameraFrame& frame, double ndcX, double ndcY);

/// The same ray through the centre of pixel (x, y) of a width x height image,
/// y counted from the TOP row (as in Image).
glm::dvec3 farRayAtPixel(const CameraFrame& frame, int x, int y, int width, int height);

}  // namespace aerial::renderer
