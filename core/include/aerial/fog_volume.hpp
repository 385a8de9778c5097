// aerial/fog_volume.hpp — box, ellipsoid and mesh fog volumes placed in the
// world, adding fog or (blend subtract) removing it.
//
// Usage:
//   aerial::FogVolume v;
//   v.shape = aerial::FogVolumeShape::Ellipsoid;
//   v.position = {0, 5, -40}; v.halfExtents = {30, 5, 20};
//   v.density = 0.05; v.falloff = 0.2;          // thins out upwards
//   aerial::VolumeSegment s = aerial::intersectFogVolume(v, camera, dir, sceneDistance);
//   double tau = s.hit ? aerial::fogVolumeOpticalDepth(v, camera, dir, s) : 0.0;
//
//   // Many rays against one volume (a renderer packing it, an editor
//   // picking it): prepare once, intersect often.
//   aerial::PreparedFogVolume p = aerial::prepareFogVolume(v);
//   aerial::VolumeInterval line = aerial::intersectFogVolumeLine(p, eye, dir);  // unclipped
//
// Geometry (../shared/DESIGN.md, "Fog volumes", "Mesh and subtract volumes"):
// a box is the unit cube [-1,1]^3 in object space, an ellipsoid the unit
// sphere, a mesh volume its closed triangle mesh (aerial/fog_mesh.hpp) in
// its own coordinates; world = position + rotation * (halfExtents * object)
// (for a mesh the half extents are its scale: a mesh of the cube [-1,1]^3 is
// the box). A mesh may be concave: the ray meets it in several chords, and
// its fog is the sum over them (the sum over the exits minus the sum over
// the entries of the density's antiderivative along the ray). Rays are intersected in object space and
// the hit distances used in world space; the segment is clipped to
// [max(t_in, 0), min(t_out, t_scene)], so a viewer may stand inside and
// scene geometry inside the volume ends it.
//
// Density inside: b_v exp(-c_v (dot(p - position, g) - offset)), g a
// world-space unit gradient direction, offset [m] along it. Its integral is
// the global-fog formula with o.y - h0 -> dot(o - position, g) - offset and
// d.y -> dot(d, g) (see height_fog.hpp).
//
// Soft edges (`edge_softness` sigma in [0, 1], default 0 = a hard shape, its
// integrals evaluated exactly as without the field): the density is
// multiplied by a profile w that is 1 deep inside and falls to 0 at the
// surface over the outer sigma of the shape, chosen so that along any ray it
// is a polynomial between a few breakpoints and the optical depth stays a
// closed form:
//   - ellipsoid: w = clamp((1 - |q|^2) / (1 - (1 - sigma)^2), 0, 1), q the
//     object-space point — linear in |q|^2, so quadratic in t along a ray
//     (breakpoints where |q| = 1 - sigma);
//   - box: w = prod_i clamp((1 - |q_i|) / sigma, 0, 1) — per axis linear in
//     t between the breakpoints q_i = 0, +-(1 - sigma), so cubic in t.
// On each piece the integral of P(s) exp(x s) (P the cubic or quadratic,
// s in [0, 1]) is sum_n p_n J_n(x), J_n(x) = int_0^1 s^n e^(xs) ds, from its
// series for |x| < 2 and the recurrence J_n = (e^x - n J_(n-1)) / x beyond
// (x <= 0 always: each piece is integrated from its denser end), both to a
// few ulps (known answers within 4 ulps; within 1e-7 relative of a
// 20 000-interval Gauss-Legendre quadrature, that quadrature's own error, in
// test_fog_volume.cpp).
// A subtract volume's softness is unused (it removes fog with a hard edge).
//
// This header is the one place that says what a volume's shape is: core's
// BVH (FogScene), the renderer's packing of volumes for the GPU and the
// editor's picking all go through prepareFogVolume and the intersections
// below, so a new shape is added here once.
//
// Sanitising (no function here returns NaN or Inf; the numbers are in
// limits.hpp, "Geometry"):
//   - a volume is degenerate, never hit and of density 0 everywhere, when a
//     half extent is not in [kMinHalfExtent, kMaxCoordinate] = [1e-6, 1e30] m
//     (zero, negative, NaN, Inf), its rotation is zero or not finite, or its
//     position is beyond kMaxCoordinate;
//   - the rotation need not be unit (it is normalised); the gradient need not
//     be unit either, and a zero or non-finite gradient means +Y;
//   - a negative or non-finite density or falloff counts as 0, a non-finite
//     offset as 0, and all three are clamped to kMaxFogParameter (1e150);
//   - a colour component that is negative or not finite counts as 0;
//   - a ray whose origin or direction is not finite (or beyond 1e30 m), or
//     whose tMax is NaN or <= 0, hits nothing.
#pragma once

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace aerial {

class FogMesh;

enum class FogVolumeShape { Box, Ellipsoid, Mesh };

/// What a volume does to the fog around it. A subtract volume removes,
/// inside it, the global fog and the fog of every volume that adds (all of
/// them, whatever their order in the preset): a fog-free interior. Where
/// subtract volumes overlap, the fog is removed once. Emitters (light
/// glows, not fog) are not removed. A subtract volume's density, gradient
/// and colour are unused.
enum class FogVolumeBlend { Add, Subtract };

/// Where a fog volume's in-scattered colour comes from.
enum class FogColourMode {
    Sky,     ///< the light that reaches the fog, the horizon far away (fog_light.hpp; as global fog)
    Tinted,  ///< that fog colour multiplied by `colour`
    Custom,  ///< `colour` as in-scattered radiance, scene-linear Rec.709
};

/// How the preset's fog was authored to be drawn (the renderer's
/// FogMode): the closed-form integrals, exact and cheap, or a froxel grid
/// that the shadows cut into light shafts. The runtime library's fog
/// queries are the analytic answer either way; games read the choice from
/// the bake manifest.
enum class FogRenderMode { Analytic, Volumetric };

/// The phase of the volumetric fog's lit in-scattering (fog_light.hpp):
/// the sky's (Cornette-Shanks with the atmosphere's Mie anisotropy, as the
/// analytic fog: the two converge) or Cornette-Shanks with the fog's own
/// anisotropy (denser forward glow around the sun, or none). The analytic
/// fog ignores it.
enum class FogPhaseMode { Sky, Custom };

/// What only the volumetric fog draws (the analytic mode ignores it; the
/// CPU fog queries are analytic).
struct VolumetricFogParams {
    FogPhaseMode phase = FogPhaseMode::Sky;
    /// Cornette-Shanks g of the fog with FogPhaseMode::Custom, -0.95..0.95. Default 0.6.
    double anisotropy = 0.6;
    /// Detail noise: the global fog's density times 1 + amount (2 n - 1),
    /// n in 0..1 a smooth 3D noise of the world point (drifting with the
    /// clouds' wind), 0..1. 0 (default) is the exact height fog.
    double noiseAmount = 0.0;
    /// Size of the noise's features [m], 1..1000. Default 25.
    double noiseScaleM = 25.0;
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
    FogVolumeBlend blend = FogVolumeBlend::Add;
    /// Edge softness sigma (box and ellipsoid volumes that add fog): the
    /// outer fraction of the shape over which the density falls to 0 (see
    /// "Soft edges" above), 0..1, unitless. Default 0 (hard edge). Not finite
    /// counts as 0.
    double edgeSoftness = 0.0;
    /// Shape Mesh: the glTF file as written in the preset (relative to the
    /// preset's folder), and the mesh loaded from it (loadPreset and
    /// resolveFogMeshes fill it; a mesh volume without one is degenerate).
    std::string mesh;
    std::shared_ptr<const FogMesh> meshData;
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

/// A fog volume reduced to what a ray needs, with every number sanitised
/// (see "Sanitising" above): the object-from-world transform, the unit
/// gradient, the world bounds. Built by prepareFogVolume.
struct PreparedFogVolume {
    bool valid = false;  ///< false: degenerate, never hit, density 0 everywhere
    FogVolumeShape shape = FogVolumeShape::Box;
    glm::dvec3 position{0.0};  ///< centre [m], world (the origin when invalid)
    /// Rows of objectFromWorld (3x3): object = M (world - position), with
    /// M = S^-1 R^T (S the half extents, R the unit rotation).
    glm::dvec3 row0{1.0, 0.0, 0.0};
    glm::dvec3 row1{0.0, 1.0, 0.0};
    glm::dvec3 row2{0.0, 0.0, 1.0};
    /// worldFromObject (3x3) = R S: its columns are the object axes in world
    /// space scaled by the half extents (identity when invalid).
    glm::dmat3 worldFromObject{1.0};
    glm::dvec3 gradient{0.0, 1.0, 0.0};  ///< unit, world
    double gradientOffset = 0.0;         ///< [m]
    double density = 0.0;                ///< [1/m]
    double falloff = 0.0;                ///< [1/m]
    glm::dvec3 boundsMin{0.0};           ///< world AABB (exact, unpadded)
    glm::dvec3 boundsMax{0.0};
    FogColourMode colourMode = FogColourMode::Sky;
    glm::dvec3 colour{1.0};
    FogVolumeBlend blend = FogVolumeBlend::Add;
    /// Edge softness in [0, 1]; 0 for meshes and subtract volumes.
    double edgeSoftness = 0.0;
    /// Shape Mesh: the mesh (object space), non-null when valid.
    std::shared_ptr<const FogMesh> mesh;

    /// A world vector (a difference of points, a direction) in object space.
    glm::dvec3 toObject(const glm::dvec3& worldVector) const {
        return {glm::dot(row0, worldVector), glm::dot(row1, worldVector), glm::dot(row2, worldVector)};
    }
};

PreparedFogVolume prepareFogVolume(const FogVolume& volume);

/// The unclipped interval of the line origin + t * direction inside a shape;
/// t (in units of |direction|) may be negative (behind the origin) or, for a
/// direction of zero length inside the shape, infinite.
struct VolumeInterval {
    bool hit = false;
    double tNear = 0.0;
    double tFar = 0.0;
};

/// The line against the prepared volume's shape in object space (slabs for
/// the box; for the ellipsoid the roots around the closest approach, free of
/// cancellation for far or grazing rays; for a mesh its first entry and last
/// exit — the hull of its chords, what picking needs; fogVolumeChords gives
/// the chords themselves). No hit for an invalid volume or an
/// origin or direction that is not finite or beyond kMaxCoordinate.
VolumeInterval intersectFogVolumeLine(const PreparedFogVolume& volume, const glm::dvec3& origin,
                                      const glm::dvec3& direction);

/// The chords of the line origin + t * direction inside the volume, clipped
/// to [0, tMax] (tMax >= 0, may be +Inf), sorted and disjoint, appended to
/// `chords` (cleared first): one for a box or ellipsoid, any number for a
/// concave mesh. Returns how many.
std::size_t fogVolumeChords(const PreparedFogVolume& volume, const glm::dvec3& origin,
                            const glm::dvec3& direction, double tMax, std::vector<VolumeSegment>& chords);

/// intersectFogVolume for a prepared volume: the line clipped to
/// [max(tNear, 0), min(tFar, tMax)]; tMax must be >= 0 and may be +Inf.
VolumeSegment intersectFogVolume(const PreparedFogVolume& volume, const glm::dvec3& origin,
                                 const glm::dvec3& direction, double tMax);

/// fogVolumeOpticalDepth for a prepared volume (origin and direction within
/// kMaxCoordinate, the segment from intersectFogVolume). For a mesh, the
/// optical depth of its chords inside the segment.
double fogVolumeOpticalDepth(const PreparedFogVolume& volume, const glm::dvec3& origin,
                             const glm::dvec3& direction, const VolumeSegment& segment);

/// Whether a world point lies inside the prepared volume's shape (its
/// boundary included); false for an invalid volume.
bool fogVolumeContains(const PreparedFogVolume& volume, const glm::dvec3& point);

/// World-space axis-aligned bounds of the volume (tight: the rotated box's
/// corners, the rotated ellipsoid's extremes). A degenerate volume gives
/// boundsMin = boundsMax = its position (the origin when that is invalid).
void fogVolumeBounds(const FogVolume& volume, glm::dvec3& boundsMin, glm::dvec3& boundsMax);

}  // namespace aerial
