// viewport/picking.hpp — rays through viewport pixels and click selection
// against the real shapes of fog volumes and emitter icons.
//
// Usage:
//   renderer::CameraFrame f = controller.cameraFrame(aspect);
//   Ray ray = rayThroughPixel(f, mouseInViewport, viewportSize);
//   double iconRadius = angularRadiusOfPixels(f, viewportSize.y, 10.0);
//   PickHit hit = pick(ray, preset.volumes, preset.emitters, iconRadius, true);
//   if (hit.kind == PickHit::Kind::Volume) select(preset.volumes[hit.index]);
//   glm::dvec3 where = placeInFront(f, 60.0).value_or(f.eye);   // "Add volume"
//   BoundingSphere b = boundingSphereOf(volume); controller.frame(b.centre, b.radius, aspect);  // F
//
// Geometry (DESIGN.md "Fog volumes", core/include/aerial/fog_volume.hpp): a
// box is the unit cube [-1,1]^3, an ellipsoid the unit sphere, world =
// position + rotation * (halfExtents * object). The ray is taken into object
// space and intersected there by core's intersectFogVolumeLine (slabs; the
// unit sphere's roots around the closest approach, free of cancellation) —
// the geometry the BVH and the renderer use; since the map is affine the ray
// parameter t is the same in both spaces, and with a unit world direction t
// is the world distance [m]. Degenerate volumes follow core's rules
// (fog_volume.hpp, "Sanitising") and are never hit.
//
// Cloud volumes are picked by the same geometry (shapeOf: a FogVolume with
// the cloud volume's shape, position, rotation and half extents). They are
// kilometres across and hold the camera and every other object, so they
// come last: a cloud volume is picked only where the ray hits no fog volume
// and no emitter icon.
//
// Emitters are picked as screen-constant icons: a ray hits an emitter when
// the angle between the ray and the direction to it is at most
// `iconAngularRadius` — exactly the sphere of radius D sin(alpha) around it
// (D its distance from the ray origin), so the radius grows in proportion
// to the distance and the icon's size on screen stays constant; the hit
// distance is where the ray enters that sphere.
#pragma once

#include <aerial/clouds.hpp>
#include <aerial/emitter.hpp>
#include <aerial/fog_volume.hpp>
#include <aerial/renderer/camera.hpp>

#include <glm/gtc/quaternion.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <functional>
#include <optional>
#include <vector>

namespace aerial::editor {

/// A ray origin + t * direction, t >= 0; direction unit.
struct Ray {
    glm::dvec3 origin{0.0};                ///< [m]
    glm::dvec3 direction{0.0, 0.0, -1.0};  ///< unit
};

/// The unclipped interval of a line origin + t * direction inside a shape;
/// t may be negative (behind the origin).
struct RayInterval {
    bool hit = false;
    double tIn = 0.0;   ///< entry [m along a unit direction]
    double tOut = 0.0;  ///< exit, >= tIn
};

/// The ray from the eye through a point of the viewport given in pixels from
/// its top-left corner (continuous: the centre of pixel (x, y) is
/// (x + 0.5, y + 0.5)), for a viewport of `viewportSize` pixels. Its direction
/// is normalize(farRayAtPixel(frame, x, y, w, h)) at pixel centres, and it
/// starts at the eye. Non-finite or non-positive sizes count as 1 px; a
/// non-finite pixel gives the centre ray (frame.forward).
Ray rayThroughPixel(const renderer::CameraFrame& frame, glm::dvec2 pixelFromTopLeft, glm::dvec2 viewportSize);

/// Angular radius [rad] of a disc of `pixels` radius at the centre of a
/// viewport `viewportHeight` pixels tall: atan(pixels * 2 tan(fov/2) / height).
/// Use it as pick()'s iconAngularRadius for icons drawn `pixels` wide.
double angularRadiusOfPixels(const renderer::CameraFrame& frame, double viewportHeight, double pixels);

/// Closed-form intersection of the line with an oriented box (centre,
/// rotation world-from-object, half extents [m]). `direction` need not be
/// unit (t is then in units of |direction|). No hit for degenerate boxes or
/// non-finite input.
RayInterval intersectOrientedBox(const Ray& ray, const glm::dvec3& centre, const glm::dquat& rotation,
                                 const glm::dvec3& halfExtents);

/// The same for an oriented ellipsoid (the unit sphere scaled by the half
/// extents, rotated, moved to centre). A tangent line (one touching point)
/// is a hit with tIn == tOut.
RayInterval intersectOrientedEllipsoid(const Ray& ray, const glm::dvec3& centre, const glm::dquat& rotation,
                                       const glm::dvec3& halfExtents);

/// The line against a volume's shape (box or ellipsoid), with core's
/// degenerate-volume rules.
RayInterval intersectVolumeShape(const Ray& ray, const FogVolume& volume);

/// Distance [m] along a unit ray to where it enters the icon sphere of a
/// point at `position` (see the header comment), or nullopt when the angle
/// to the point exceeds `angularRadius`, the point is behind the origin or
/// at it, or input is not finite.
std::optional<double> intersectIcon(const Ray& ray, const glm::dvec3& position, double angularRadius);

/// A cloud volume's shape as a FogVolume (shape, position, rotation, half
/// extents; the rest default): what core's fog-volume geometry, picking,
/// outlines and bounds take.
FogVolume shapeOf(const CloudVolume& cloudVolume);

/// What a click selected.
struct PickHit {
    enum class Kind { None, Volume, Emitter, CloudVolume };
    Kind kind = Kind::None;
    int index = -1;         ///< into the volumes, emitters or cloud volumes vector; -1 for None
    double distance = 0.0;  ///< along the ray [m]
};

/// Picks the nearest volume or emitter icon along a ray (direction is
/// normalised here). A volume in front of the origin is hit at its entry
/// distance; when the origin is inside a volume it is hit at its EXIT
/// distance, so anything inside or in front of it (still visible from
/// within) wins, and clicking anywhere while standing in an otherwise empty
/// volume selects it. Ties keep the lower index, volumes before emitters.
/// With `emittersFirst` any emitter hit beats every volume hit (icons are
/// drawn on top of the volumes; the editor should pass true so a lamp inside
/// a fog volume can be clicked); otherwise the nearest hit wins.
PickHit pick(const Ray& ray, const std::vector<FogVolume>& volumes, const std::vector<Emitter>& emitters,
             double iconAngularRadius, bool emittersFirst = false);

/// The same, then the cloud volumes where nothing else was hit: the nearest
/// by the volume rule above (entry, or exit from inside), ties to the lower
/// index.
PickHit pick(const Ray& ray, const std::vector<FogVolume>& volumes, const std::vector<Emitter>& emitters,
             const std::vector<CloudVolume>& cloudVolumes, double iconAngularRadius,
             bool emittersFirst = false);

/// A sphere [m]: what CameraController::frame() fits into the view.
struct BoundingSphere {
    glm::dvec3 centre{0.0};
    double radius = 1.0;
};

/// The smallest sphere about the volume's centre that holds its shape: the
/// box's half diagonal |halfExtents|, the ellipsoid's largest half extent.
/// A degenerate volume (see fog_volume.hpp) gives radius 1 m about its
/// position (the origin when that is not finite).
BoundingSphere boundingSphereOf(const FogVolume& volume);

/// A sphere to frame an emitter by: its position and the distance where its
/// glow falls to half, 1 / sqrt(attenuation), clamped to [1, 50] m (10 m when
/// the attenuation is not positive and finite).
BoundingSphere boundingSphereOf(const Emitter& emitter);

/// Height [m] of the ground at (x, z) [m], e.g. renderer::builtinTerrainHeight.
using GroundHeightFunction = std::function<double(double x, double z)>;

/// Where to put a new object "in front of the camera": where the view ray
/// (eye along forward) first meets the ground within `maxGroundDistance` [m]
/// — the plane y = 0, or the height field `groundHeight` when one is given
/// (found by marching in 1 m steps, at most 20000 steps, then bisection to
/// 1e-6 m) — else the point `distance` [m] along the forward direction.
/// nullopt only when the frame's eye or forward is not finite or `distance`
/// is not finite and positive.
std::optional<glm::dvec3> placeInFront(const renderer::CameraFrame& frame, double distance,
                                       double maxGroundDistance = 250.0,
                                       const GroundHeightFunction& groundHeight = {});

}  // namespace aerial::editor
