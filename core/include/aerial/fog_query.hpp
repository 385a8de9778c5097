// aerial/fog_query.hpp — fog along a segment, on the CPU, for transparent
// objects (which cannot read the fogged depth buffer; Wenzel 2006).
//
// Usage:
//   aerial::FogSceneDesc desc;
//   desc.heightFog = fog;  desc.volumes = volumes;  desc.emitters = emitters;
//   desc.lights[0] = {sunDir, sunIlluminance, sky.horizonRayleigh, sky.horizonMie, sky.horizonMultiple};
//   aerial::FogScene scene(desc);                    // builds the BVH once
//   aerial::FogQueryResult r = scene.query(camera, glassPane);
//   // shade the pane: L = L_pane * r.transmittance + r.inScatter
//
// Compositing (the contract the renderer follows too):
//   0. subtract volumes (FogVolumeBlend::Subtract) remove, along the
//      segment, the global fog and every add volume inside the union of
//      their chords (overlaps removed once); they add nothing themselves;
//   1. global fog over the whole segment (less the subtracted parts):
//        L <- L T_g + L_fog(v) (1 - T_g)
//   2. every add volume the segment crosses (a concave mesh volume once,
//      its chords' optical depths summed), back to front (by the entry
//      distance of its clipped segment, farthest first; equal entries by
//      ascending index, i.e. the lower index is composited first, behind):
//        L <- L T_v + C_v(v) (1 - T_v)
//      where C_v is the volume's colour (see FogColourMode);
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
#include <aerial/fog_volume.hpp>
#include <aerial/height_fog.hpp>
#include <aerial/sky.hpp>

#include <glm/vec3.hpp>

#include <cstddef>
#include <memory>
#include <vector>

namespace aerial {

/// A light that colours fog through the sky's horizon: the averages, and
/// (when given) the horizon row, so that the fog takes the sky behind it
/// (horizonSkySample in <aerial/sky.hpp>).
struct FogLight {
    glm::dvec3 direction{0.0, 1.0, 0.0};  ///< unit, from the scene to the light
    glm::dvec3 illuminance{0.0};          ///< E, RGB (0 turns the light off)
    glm::dvec3 horizonRayleigh{0.0};      ///< SkyTable::horizonRayleigh for this light
    glm::dvec3 horizonMie{0.0};           ///< SkyTable::horizonMie for this light
    glm::dvec3 horizonMultiple{0.0};      ///< SkyTable::horizonMultiple for this light (isotropic)
    /// skyHorizonRow of this light's table; empty (the default): the
    /// averages alone colour the fog in every direction.
    SkyTable horizonRow{};
};

struct FogSceneDesc {
    HeightFogParams heightFog;
    std::vector<FogVolume> volumes;
    /// Emitters with their intensity for this moment (lightning flashes and
    /// keyed values already applied: FogScene does not call lightningFlash).
    std::vector<Emitter> emitters;
    /// Sun and moon; a light with zero illuminance contributes nothing.
    FogLight lights[2];
    /// Anisotropy g of the Mie phase used for the fog colour, clamped to
    /// [-0.999, 0.999]. Default 0.8.
    double mieAnisotropy = 0.8;
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

    /// The fog colour of the sky in a view direction (global fog's L_fog):
    /// sum over the lights of E (P_R(mu) horizonRayleigh + P_M(mu, g)
    /// horizonMie + horizonMultiple), mu = dot(v, light direction), blended
    /// with the overcast: (1 - overcastCover) that + overcastCover
    /// overcastRadiance. The direction need not be unit (zero or non-finite
    /// means +Y).
    glm::dvec3 fogColour(const glm::dvec3& viewDirection) const;

    const FogSceneDesc& desc() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace aerial
