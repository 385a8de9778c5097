// aerial/clouds.hpp — the volumetric cloud layer: its parameters, the noise
// it is carved from, and the runtime answers a game asks (density at a
// point, transmittance along a ray, "is this point in cloud shadow").
//
// Usage (a game, once per frame or per query batch):
//   aerial::PresetState state = compiled.evaluate(hours);
//   aerial::CloudField clouds = aerial::prepareClouds(state);   // cheap after the first call
//   double v = aerial::cloudSunVisibility(clouds, playerPosition, state.sunLight.body.direction);
//   if (v < 0.3) { /* the player stands in cloud shadow */ }
//   double t = aerial::cloudTransmittance(clouds, eye, viewDirection);
//
// Geometry (../shared/DESIGN.md, "Clouds"): world space is metres, +Y up, the
// ground at y = 0 below the origin; the planet's centre is (0, -Rg, 0) with Rg
// the atmosphere's planet radius. The layer is the spherical shell of heights
// [bottom_m, bottom_m + thickness_m] above the ground, so it curves away and
// thins out towards the horizon as the real one does. Height above ground of
// a point p: h = |p - centre| - Rg, evaluated without cancellation as
// (x^2 + z^2 + y^2 + 2 y Rg) / (|p - centre| + Rg).
//
// Density [1/m] at p inside the shell (zero outside), with f = (h - bottom) /
// thickness the height fraction:
//   x     = shape(q / shape_scale) * profile(f, type)      (both in [0, 1])
//   d     = saturate((x - (1 - c)) / c)                      (c = coverage at p)
//   e     = erosion * detail(q / detail_scale)
//   rho   = density_per_m * saturate((d - e) / (1 - e))
// where q = (p.x - w.x, h, p.z - w.z), w = wind_m_per_s * seconds since 00:00
// (so a preset alone reproduces every frame), and shape and detail are the
// tileable noise textures of CloudNoise sampled trilinearly with wrapping,
// texel centres at (i + 0.5) / size — exactly what the GPU's GL_LINEAR +
// GL_REPEAT does with the same texels. d grows with c for every x (d/dc =
// (1 - x)/c^2 >= 0), so more coverage never gives less cloud, and c = 0 gives
// none. The height profile rises over the bottom 8 % of the layer and falls
// to zero at the type's top: top = mix(0.3, 1, type) of the layer, the fall
// starting at top * (1 - mix(0.5, 0.8, type)) — flat stratus at type 0,
// towering cumulus with rounded tops at type 1.
//
// Cloud volumes set the coverage inside them: c = mix(c, volume coverage, w),
// in order, with w = 1 inside and a smoothstep to 0 over the outer
// `edge_softness` of the shape (object-space radius 1 - softness .. 1).
//
// Transmittance: exp(-optical depth), the optical depth a midpoint march over
// the parts of the ray inside the shell (at most two: entering, and leaving
// again past the inner sphere), clipped to [0, tMax] and at the ground; the
// renderer's GPU march places its samples the same way (renderer/shaders/
// common/clouds.glsl) and is tested against this.
//
// Sanitising: every function returns a finite number; a point or ray that is
// not finite or beyond kMaxCoordinate is outside the layer (density 0,
// transmittance and visibility 1).
#pragma once

#include <aerial/fog_volume.hpp>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace aerial {

/// The cloud layer of a preset (the "clouds" block). Every number keyable.
struct CloudParams {
    /// Fraction of the sky covered, 0..1. Default 0: a preset without a
    /// "clouds" block has a clear sky.
    double coverage = 0.0;
    /// Height of the layer's base above the ground [m], 0..20000. Default 1500.
    double bottomM = 1500.0;
    /// Thickness of the layer [m], 10..20000 (> 0). Default 2000.
    double thicknessM = 2000.0;
    /// Extinction inside a full cloud [1/m], 0..1. Default 0.02 (a cumulus
    /// core; visibility ~200 m).
    double densityPerM = 0.02;
    /// Drift [m/s] along world X and Z. Default (10, 3).
    glm::dvec2 windMPerS{10.0, 3.0};
    /// Seed of the noise, 0..4294967295. Default 1.
    std::int64_t seed = 1;
    /// Cloud type, 0 flat stratus .. 1 towering cumulus. Default 0.6.
    double type = 0.6;
    /// Horizontal size of one tile of the shape noise [m], 500..200000.
    /// Default 12000 (cells of ~3 km).
    double shapeScaleM = 12000.0;
    /// Size of one tile of the erosion (detail) noise [m], 50..20000. Default 1200.
    double detailScaleM = 1200.0;
    /// How much the detail noise eats the edges, 0..0.9. Default 0.35.
    double erosion = 0.35;
    /// Forward scattering asymmetry g of the Henyey-Greenstein lobe,
    /// 0..0.95: the silver lining when a cloud covers the sun. Default 0.6.
    double anisotropy = 0.6;
    /// Single-scattering albedo per RGB channel, 0..1 (scattering =
    /// albedo x extinction). Default 0.98.
    glm::dvec3 albedo{0.98, 0.98, 0.98};
};

/// A box or ellipsoid that sets the coverage inside it (a storm cell, a
/// clear hole), placed like a fog volume.
struct CloudVolume {
    std::string id;
    std::string name;
    FogVolumeShape shape = FogVolumeShape::Ellipsoid;
    /// Centre [m], world.
    glm::dvec3 position{0.0, 2500.0, 0.0};
    /// Orientation, world from object (unit quaternion).
    glm::dquat rotation{1.0, 0.0, 0.0, 0.0};
    /// Half extents [m] along the object axes, >= 1. Default 4000 x 2000 x 4000.
    glm::dvec3 halfExtents{4000.0, 2000.0, 4000.0};
    /// Coverage inside, 0..1. Default 1 (overcast).
    double coverage = 1.0;
    /// Outer fraction of the shape over which the coverage blends to the
    /// layer's, 0..1. Default 0.3.
    double edgeSoftness = 0.3;
};

/// The tileable noise the layer is carved from, generated from a seed.
/// Both textures tile with period 1 in every axis; values in [0, 1]; texel
/// (i, j, k) at index (k * size + j) * size + i. The renderer uploads these
/// exact floats (R32F, GL_LINEAR, GL_REPEAT).
struct CloudNoise {
    static constexpr int kShapeSize = 128;  ///< Perlin-Worley shape, 128^3
    static constexpr int kDetailSize = 32;  ///< Worley erosion, 32^3
    std::int64_t seed = 0;
    std::vector<float> shape;   ///< kShapeSize^3
    std::vector<float> detail;  ///< kDetailSize^3
};

/// Generates the noise of a seed (Schneider 2015/2017, Nubis: a Perlin-Worley
/// shape texture and a Worley-fBm erosion texture), deterministically: the
/// same texels whatever the thread count or run. `threadCount` 0 uses the
/// machine's threads (at most 8).
CloudNoise generateCloudNoise(std::int64_t seed, int threadCount = 0);

/// The noise of a seed, generated on first use and cached (the last few
/// seeds); thread-safe.
std::shared_ptr<const CloudNoise> cloudNoise(std::int64_t seed);

/// FNV-1a (64 bit) over the bytes of the shape then the detail texels
/// (little-endian IEEE floats): a game that regenerates the noise from the
/// seed checks it got the same texels, bit for bit, against the bake's
/// manifest.
std::uint64_t cloudNoiseFingerprint(const CloudNoise& noise);

/// Trilinear, wrapping sample of a tileable texture (size^3 floats) at uvw
/// (period 1), texel centres at (i + 0.5) / size.
double sampleTileable(const std::vector<float>& texels, int size, const glm::dvec3& uvw);

/// The layer's height profile, 0..1, at height fraction f (0 bottom, 1 top)
/// for a cloud type 0..1 (see the header comment).
double cloudHeightProfile(double heightFraction, double type);

/// The clouds at one time, ready for queries.
struct CloudField {
    CloudParams params;
    /// The planet's radius Rg [m] (the shell's centre is (0, -Rg, 0)).
    double planetRadius = 6360000.0;
    /// Wind offset w = wind x seconds since 00:00 [m], reduced modulo the
    /// shape and the detail tile (in double), as the GPU receives them.
    glm::dvec2 shapeOffset{0.0};
    glm::dvec2 detailOffset{0.0};
    /// The volumes, prepared (shape and transform as fog volumes).
    struct Volume {
        PreparedFogVolume geometry;
        double coverage = 1.0;
        double edgeSoftness = 0.3;
    };
    std::vector<Volume> volumes;
    std::shared_ptr<const CloudNoise> noise;

    /// True when the layer can hold any cloud (some coverage and density).
    bool active() const;
};

/// The clouds of explicit parameters at `timeHours` (sets the wind offset).
CloudField prepareClouds(const CloudParams& params, std::span<const CloudVolume> volumes, double timeHours,
                         double planetRadius);

/// Height above the ground [m] of a world point (see the header comment).
double cloudHeightAboveGround(const glm::dvec3& point, double planetRadius);

/// The coverage 0..1 at a world point: the layer's, set by the volumes.
double cloudCoverageAt(const CloudField& clouds, const glm::dvec3& point);

/// Extinction [1/m] at a world point.
double cloudDensityAt(const CloudField& clouds, const glm::dvec3& point);

/// Where a ray runs inside the shell: up to two intervals [t0, t1] (units of
/// |direction|), clipped to [0, tMax] and to the ground.
struct CloudSegments {
    int count = 0;
    double t0[2] = {0.0, 0.0};
    double t1[2] = {0.0, 0.0};
};
CloudSegments cloudLayerSegments(const CloudField& clouds, const glm::dvec3& origin,
                                 const glm::dvec3& direction,
                                 double tMax = std::numeric_limits<double>::infinity());

/// Samples of the reference march (enough for 1e-3 on the shipped presets).
constexpr int kCloudReferenceSteps = 512;
/// Samples the sun-visibility march takes through the layer.
constexpr int kCloudSunVisibilitySteps = 48;

/// Optical depth through the clouds along origin + t direction, t in [0,
/// tMax]: a midpoint march over each segment with max(1, round(steps x
/// its share of the total length)) samples.
double cloudOpticalDepth(const CloudField& clouds, const glm::dvec3& origin, const glm::dvec3& direction,
                         double tMax = std::numeric_limits<double>::infinity(),
                         int steps = kCloudReferenceSteps);

/// exp(-cloudOpticalDepth): 1 = clear.
double cloudTransmittance(const CloudField& clouds, const glm::dvec3& origin, const glm::dvec3& direction,
                          double tMax = std::numeric_limits<double>::infinity(),
                          int steps = kCloudReferenceSteps);

/// Transmittance through the clouds from a point towards the sun (or moon):
/// 1 in full sun, towards 0 deep in a cloud's shadow. `toLight` need not be
/// unit; a light below the horizon still gives the clouds' transmittance
/// along it (the ground is not a cloud).
double cloudSunVisibility(const CloudField& clouds, const glm::dvec3& point, const glm::dvec3& toLight,
                          int steps = kCloudSunVisibilitySteps);

/// What the cloud deck does to the sky's light below it (an overcast greys
/// and dims the fog and the ambient light; Aerial's sky table is the clear
/// sky's). Seen from the world origin on the ground, so that every query of
/// a frame (renderer, FogScene, a game) agrees whatever its camera; the
/// layer's wind and volumes at that moment are in the field.
struct CloudOvercast {
    /// Fraction of the upper hemisphere's cosine-weighted light the clouds
    /// block, 0..1: 1 - mean transmittance over kCloudOvercastRays
    /// cosine-distributed directions.
    double skyCover = 0.0;
    /// The same for the band 1-11 deg above the horizon (what far fog shows
    /// behind it), 0..1: through the layer's long slant there, a broken
    /// deck covers more of it than of the zenith.
    double horizonCover = 0.0;
    /// Mean vertical optical depth of the clouds where they are (the covered
    /// directions' optical depth times their zenith cosine, weighted by
    /// their cover); 0 without clouds.
    double opticalDepth = 0.0;
    /// Diffuse transmittance of a slab of that optical depth, the two-stream
    /// (diffusion) T_d = 1 / (1 + 3/4 (1 - g) tau) with the droplets' g =
    /// 0.85 (Bohren 1987; the renderer's cloud shader uses the same for the
    /// light deep in a cloud); 1 without clouds.
    double diffuseTransmittance = 1.0;
};

/// Directions per band of cloudOvercast (the zenith band; the horizon band has as many).
constexpr int kCloudOvercastRays = 128;
/// Samples of each of cloudOvercast's marches.
constexpr int kCloudOvercastSteps = 32;

/// The overcast of a cloud field (above); all zero (and T_d = 1) when the
/// layer is inactive.
CloudOvercast cloudOvercast(const CloudField& clouds);

/// Radiance of the deck's underside [illuminance unit / sr], the same in
/// every direction: the light falling on its top (`irradianceOnTop`: the
/// direct sun and moon on a horizontal surface plus the clear sky's
/// irradiance), diffusely transmitted (T_d) times the clouds' albedo, spread
/// over the lower hemisphere: albedo T_d E / pi.
glm::dvec3 overcastRadiance(const CloudOvercast& overcast, const glm::dvec3& albedo,
                            const glm::dvec3& irradianceOnTop);

/// How much of the sky in direction `direction` (unit) the deck hides, for
/// what a mirror reflects: horizonCover for a direction level or below,
/// rising smoothly (smoothstep in its y from 0 to 0.5) to skyCover from 30
/// deg up. The renderer blends the sky seen in its reflections towards the
/// deck's underside by it (shading.glsl); a game can do the same:
/// mix(clear sky, overcast radiance, overcastCoverTowards(overcast, r)).
double overcastCoverTowards(const CloudOvercast& overcast, const glm::dvec3& direction);

}  // namespace aerial
