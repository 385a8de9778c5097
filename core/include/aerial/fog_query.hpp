// aerial/fog_query.hpp — fog along a segment, on the CPU, for transparent
// objects (which cannot read the fogged depth buffer; Wenzel 2006).
//
// Usage:
//   aerial::FogSceneDesc desc;
//   desc.heightFog = fog;  desc.volumes = volumes;  desc.emitters = emitters;
//   desc.lights[0] = {sunDir, sunIlluminance, sky.horizonRayleigh, sky.horizonMie, sky.horizonMultiple,
//                     skyHorizonRow(sky), sunIlluminanceReachingTheViewer};
//   desc.skyLight = ...;                             // fog_light.hpp
//   aerial::FogScene scene(desc);                    // builds the BVH once
//   // (aerial::fogSceneDesc in evaluate.hpp fills all of it from a preset's state)
//   aerial::FogQueryResult r = scene.query(camera, glassPane);
//   // shade the pane: L = L_pane * r.transmittance + r.inScatter
//
// Compositing (the contract the renderer follows too):
//   0. subtract volumes (FogVolumeBlend::Subtract) remove, along the
//      segment, the global fog and every add volume inside the union of
//      their chords (overlaps removed once); they add nothing themselves;
//   1. global fog over the whole segment (less the subtracted parts):
//        L <- L T_g + L_fog(v, s) (1 - T_g)
//      with L_fog the light that reaches the fog blended into the sky's
//      horizon with the segment's length s (fog_light.hpp, the model);
//   2. every add volume the segment crosses (a concave mesh volume once,
//      its chords' optical depths summed), back to front (by the entry
//      distance of its clipped segment, farthest first; equal entries by
//      ascending index, i.e. the lower index is composited first, behind):
//        L <- L T_v + C_v(v) (1 - T_v)
//      where C_v is the volume's colour (see FogColourMode; colour mode
//      "sky" is L_fog(v, s) of the same segment);
//   3. every emitter adds its closed-form in-scatter (additive, on top).
//   The result is affine in the scene radiance: L = L_scene T + S.
//   T_g, T_v = exp(-optical depth) are grey (the densities are scalar), so
//   transmittance has three equal components.
// Volumes are found through a bounding-volume hierarchy over their world
// bounds, so a query costs O(log n + crossed volumes). The BVH only prunes
// (conservatively), and each candidate is tested exactly as
// intersectFogVolume(volume, from, to - from, 1.0) and
// fogVolumeOpticalDepth(...) would: a query equals that brute-force loop over
// all volumes, composited as above.
//
// Queries are const and thread-safe on a shared FogScene; they allocate only
// while a thread's chord buffers grow to the most chords a segment has met,
// or when a segment crosses more than 64 volumes (the hit list spills to the
// heap). Inputs are sanitised as in height_fog.hpp, fog_volume.hpp and
// emitter.hpp: a segment with a non-finite end gives T = 1, S = 0, and no
// query returns NaN or Inf.
#pragma once

#include <aerial/emitter.hpp>
#include <aerial/fog_light.hpp>
#include <aerial/fog_volume.hpp>
#include <aerial/height_fog.hpp>
#include <aerial/sky.hpp>

#include <glm/vec3.hpp>

#include <cstddef>
#include <limits>
#include <memory>
#include <vector>

namespace aerial {

/// A light of the fog: what of it reaches the fog (`reaching`, lit by it
/// through the fog's phase) and, for far fog, its sky's horizon: the
/// averages and (when given) the horizon row, so that far fog takes the sky
/// behind it (horizonSkySample in <aerial/sky.hpp>; fog_light.hpp).
struct FogLight {
    glm::dvec3 direction{0.0, 1.0, 0.0};  ///< unit, from the scene to the light
    glm::dvec3 illuminance{0.0};          ///< E, RGB (0 turns the light off)
    glm::dvec3 horizonRayleigh{0.0};      ///< SkyTable::horizonRayleigh for this light
    glm::dvec3 horizonMie{0.0};           ///< SkyTable::horizonMie for this light
    glm::dvec3 horizonMultiple{0.0};      ///< SkyTable::horizonMultiple for this light (isotropic)
    /// skyHorizonRow of this light's table; empty (the default): the
    /// averages alone colour the fog in every direction.
    SkyTable horizonRow{};
    /// The illuminance that reaches the fog, RGB: E T(viewer -> light)
    /// (LightState::illuminance; zero below the horizon). Default 0: the
    /// light colours only far fog, through its horizon.
    glm::dvec3 reaching{0.0};
};

struct FogSceneDesc {
    HeightFogParams heightFog;
    std::vector<FogVolume> volumes;
    /// Emitters with their intensity for this moment (lightning flashes and
    /// keyed values already applied: FogScene does not call lightningFlash).
    std::vector<Emitter> emitters;
    /// Sun and moon; a light with zero illuminance contributes nothing.
    FogLight lights[2];
    /// Anisotropy g of the Mie phase used for the fog colour (the horizon's
    /// phase and the fog's own, fog_light.hpp), clamped to [-0.999, 0.999].
    /// Default 0.8.
    double mieAnisotropy = 0.8;
    /// The sky dome's, the ground's and the night sky's light at the fog:
    /// its first two spherical-harmonic bands (fog_light.hpp). Default: none.
    FogSkyLight skyLight{};
    /// The clouds' visibility V of the lights' `reaching` illuminance, 0..1
    /// (1 - CloudOvercast::skyCover). Default 1.
    double directVisibility = 1.0;
    /// D of the blend into the horizon [m] (fog_light.hpp); <= 0 or NaN:
    /// kFogHorizonDistance.
    double horizonDistance = kFogHorizonDistance;
    /// Where the global fog's colour L_fog comes from, as for volumes: the
    /// sky's fog colour, that times heightFogColour, or heightFogColour as
    /// radiance (Environment::fogColourMode / fogColour of a preset).
    FogColourMode heightFogColourMode = FogColourMode::Sky;
    glm::dvec3 heightFogColour{1.0, 1.0, 1.0};
    /// The cloud deck in front of the horizon (OvercastLight, evaluate.hpp):
    /// the sky's fog colour becomes (1 - cover) sky + cover radiance, in the
    /// colour modes that use it (Sky, Tinted). Default 0: the clear sky.
    double overcastCover = 0.0;
    glm::dvec3 overcastRadiance{0.0};  ///< the deck's underside [illuminance unit / sr]
};

/// One volume's share of a query.
struct VolumeContribution {
    std::size_t volumeIndex = 0;  ///< index into FogSceneDesc::volumes
    double tIn = 0.0;             ///< clipped entry distance [m] from the segment start
    double tOut = 0.0;            ///< clipped exit distance [m]
    double opticalDepth = 0.0;
    glm::dvec3 colour{0.0};  ///< C_v for this segment's direction
};

struct FogQueryResult {
    glm::dvec3 transmittance{1.0};  ///< T, RGB, 0..1
    glm::dvec3 inScatter{0.0};      ///< S, RGB radiance added in front of the object
    double globalOpticalDepth = 0.0;
    glm::dvec3 emitterInScatter{0.0};  ///< the emitters' share of inScatter
};

struct FogSegment {
    glm::dvec3 from{0.0};
    glm::dvec3 to{0.0};
};

class FogScene {
public:
    /// Copies the description, prepares every volume (object-from-world
    /// transform, normalised gradient, bounds) and builds the BVH.
    explicit FogScene(const FogSceneDesc& desc);
    ~FogScene();
    /// Movable (a moved-from scene may only be assigned to or destroyed).
    FogScene(FogScene&&) noexcept;
    FogScene& operator=(FogScene&&) noexcept;

    /// Fog between `from` (the camera) and `to` (the object).
    FogQueryResult query(const glm::dvec3& from, const glm::dvec3& to) const;
    /// The same, listing each crossed volume (back to front, the order it was
    /// composited in) in `volumes` (cleared first; reuse the vector to avoid
    /// allocations).
    FogQueryResult query(const glm::dvec3& from, const glm::dvec3& to,
                         std::vector<VolumeContribution>& volumes) const;
    /// Many segments at once; `results` must hold `count` entries.
    void queryBatch(const FogSegment* segments, FogQueryResult* results, std::size_t count) const;

    /// The fog colour L_fog(v, s) of colour mode "sky" for a sight line of
    /// length `distance` s [m] (fog_light.hpp):
    ///   (1 - w(s)) L_lit(v) + w(s) L_horizon(v),  w(s) = 1 - exp(-(s / D)^2),
    ///   L_lit(v) = V sum over the lights of reaching P_M(mu, g)
    ///            + max(a_0 + k_1(g) a_1 . v, 0)          (skyLight),
    ///   L_horizon(v) = sum over the lights of E (P_R(mu) H_R(v) + P_M(mu, g)
    ///            H_M(v) + H_ms(v)) (horizonSkySample), blended with the
    ///            overcast: (1 - overcastCover) that + overcastCover
    ///            overcastRadiance,
    /// mu = dot(v, light direction). The default distance (+inf) gives the
    /// horizon alone, 0 the lit fog alone. The direction need not be unit
    /// (zero or non-finite means +Y); a NaN distance counts as 0.
    glm::dvec3 fogColour(const glm::dvec3& viewDirection,
                         double distance = std::numeric_limits<double>::infinity()) const;

    const FogSceneDesc& desc() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace aerial
