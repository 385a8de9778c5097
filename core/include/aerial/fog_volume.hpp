// aerial/fog_volume.hpp — box and ellipsoid fog volumes placed in the world.
//
// Usage:
//   aerial::FogVolume v;
//   v.shape = aerial::FogVolumeShape::Ellipsoid;
//   v.position = {0, 5, -40}; v.halfExtents = {30, 5, 20};
//   v.density = 0.05; v.falloff = 0.2;          // thins out upwards
//   aerial::VolumeSegment s = aerial::intersectFogVolume(v, camera, dir, sceneDistance);
//   double tau = s.hit ? aerial::fogVolumeOpticalDepth(v, camera, dir, s) : 0.0;
//
// Geometry (../shared/DESIGN.md, "Fog volumes"): a box is the unit cube
// [-1,1]^3 in object space, an ellipsoid the unit sphere; world = position +
// rotation * (halfExtents * object). Rays are intersected in object space and
// the hit distances used in world space; the segment is clipped to
// [max(t_in, 0), min(t_out, t_scene)], so a viewer may stand inside and
// scene geometry inside the volume ends it.
//
// Density inside: b_v exp(-c_v (dot(p - position, g) - offset)), g a
// world-space unit gradient direction, offset [m] along it. Its integral is
// the global-fog formula with o.y - h0 -> dot(o - position, g) - offset and
// d.y -> dot(d, g) (see height_fog.hpp).
//
// Sanitising (no function here returns NaN or Inf):
//   - a volume is degenerate, never hit and of density 0 everywhere, when a
//     half extent is not in [1e-6, 1e30] m (zero, negative, NaN, Inf), its
//     rotation is zero or not finite, or its position is beyond 1e30 m;
//   - the rotation need not be unit (it is normalised); the gradient need not
//     be unit either, and a zero or non-finite gradient means +Y;
//   - a negative or non-finite density or falloff counts as 0, a non-finite
//     offset as 0;
//   - a ray whose origin or direction is not finite (or beyond 1e30 m), or
//     whose tMax is NaN or <= 0, hits nothing.
#pragma once

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <string>

namespace aerial {

enum class FogVolumeShape { Box, Ellipsoid };

/// Where a fog volume's in-scattered colour comes from.
enum class FogColourMode {
    Sky,     ///< the sky's horizon fog colour with per-pixel phase (as global fog)
    Tinted,  ///< the sky's fog colour multiplied by `colour`
    Custom,  ///< `colour` as in-scattered radiance, scene-linear Rec.709
};

struct FogVolume {
    /// Stable identifier: timeline tracks refer to it; never shown.
    std::string id;
    /// Name shown to the artist.
    std::string name;
    FogVolumeShape shape = FogVolumeShape::Box;
    /// Centre [m], world space.
    glm::dvec3 position{0.0};
    /// Orientation, world from object (unit quaternion, w first in glm).
    glm::dquat rotation{1.0, 0.0, 0.0, 0.0};
    /// Half extents along the object axes [m], > 0. Default 10.
    glm::dvec3 halfExtents{10.0, 10.0, 10.0};
    /// Density b_v at the offset plane [1/m], >= 0. Default 0.02.
    double density = 0.02;
    /// Falloff c_v along the gradient [1/m], >= 0. Default 0 (uniform).
    double falloff = 0.0;
    /// Gradient direction g, world space, unit. Default +Y.
    glm::dvec3 gradientDirection{0.0, 1.0, 0.0};
    /// Offset of the b_v plane from the centre along g [m]. Default 0.
    double gradientOffset = 0.0;
    FogColourMode colourMode = FogColourMode::Sky;
    /// Tint or radiance (see colourMode), scene-linear Rec.709. Default 1.
    glm::dvec3 colour{1.0, 1.0, 1.0};
};

/// The part of a ray o + t d (|d| = 1 not required) inside a volume, after
/// clipping; t in units of |d|.
struct VolumeSegment {
    bool hit = false;  ///< false when the clipped segment is empty
    double tIn = 0.0;
    double tOut = 0.0;
};

/// Intersects the ray origin + t * direction, t in [0, tMax], with the volume
/// in object space and clips it to [max(t_in, 0), min(t_out, tMax)]; tMax may
/// be +Inf. A clipped segment of zero length is no hit. Degenerate volumes
/// (see above) are never hit.
VolumeSegment intersectFogVolume(const FogVolume& volume, const glm::dvec3& origin,
                                 const glm::dvec3& direction, double tMax);

/// Optical depth of the volume's density over a clipped segment (world
/// distance (tOut - tIn) |direction|), in [0, kMaxOpticalDepth]; 0 when the
/// segment is no hit or the volume degenerate.
double fogVolumeOpticalDepth(const FogVolume& volume, const glm::dvec3& origin, const glm::dvec3& direction,
                             const VolumeSegment& segment);

/// Density [1/m] at a world point (0 outside the shape): the reference for
/// numeric quadrature.
double fogVolumeDensityAt(const FogVolume& volume, const glm::dvec3& point);

/// World-space axis-aligned bounds of the volume (tight: the rotated box's
/// corners, the rotated ellipsoid's extremes). A degenerate volume gives
/// boundsMin = boundsMax = its position (the origin when that is invalid).
void fogVolumeBounds(const FogVolume& volume, glm::dvec3& boundsMin, glm::dvec3& boundsMax);

}  // namespace aerial
