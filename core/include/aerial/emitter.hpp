// aerial/emitter.hpp — light emitters that light the fog (and the scene):
// lamps, fires, and lightning.
//
// Usage:
//   aerial::Emitter lamp;
//   lamp.position = {3, 4, -10}; lamp.intensity = 0.5; lamp.attenuation = 0.05;
//   glm::dvec3 added = aerial::emitterInScatter(lamp, camera, object - camera, 1.0);
//   double flash = aerial::lightningFlash(bolt, timeHours);   // 0..1
//
// In-scattering (../shared/DESIGN.md, "Emitters"; Wenzel 2006, lit fog): a
// point emitter at l with intensity i and attenuation a adds, along
// o -> o + d,
//   f(p) = i / (1 + a |l - p|^2),   c = l - o
//   u = 1 + a (c.c),  v = -2 a (c.d),  w = a (d.d),  k = sqrt(4 u w - v^2)
//   integral f = 2 i |d| (atan((v + 2w)/k) - atan(v/k)) / k
// (4uw - v^2 > 0 whenever a > 0 and d != 0). With a = 0 the integral is i |d|.
//
// Lightning: a flash pattern made from the emitter's parameters alone
// (seed, rate, duration), so every machine that loads the preset sees the
// same flashes at the same time of day.
#pragma once

#include <glm/vec3.hpp>

#include <cstdint>
#include <string>

namespace aerial {

enum class EmitterKind {
    Point,      ///< steady light (its intensity may still be keyed)
    Lightning,  ///< flashes following a seeded pattern
};

struct Emitter {
    /// Stable identifier: timeline tracks refer to it.
    std::string id;
    /// Name shown to the artist.
    std::string name;
    EmitterKind kind = EmitterKind::Point;
    /// Position [m], world space.
    glm::dvec3 position{0.0};
    /// In-scattered radiance per metre next to the emitter, i [1/m] times
    /// the colour. >= 0. Default 1.
    double intensity = 1.0;
    /// Attenuation a [1/m^2], >= 0: f falls to half at distance 1/sqrt(a).
    /// Default 0.01 (half at 10 m).
    double attenuation = 0.01;
    /// Colour, scene-linear Rec.709. Default white.
    glm::dvec3 colour{1.0, 1.0, 1.0};

    // Lightning only.
    /// Seed of the flash pattern.
    std::uint32_t seed = 1;
    /// Mean number of flashes per minute of the flash clock, >= 0. Default 6.
    double flashesPerMinute = 6.0;
    /// Length of one flash [s of the flash clock], > 0. Default 0.35.
    double flashDurationSeconds = 0.35;
    /// Game seconds per second of the flash clock, > 0: the pattern runs on
    /// flashSeconds = timeHours * 3600 / timeScale, so a game whose day runs
    /// at 60x sees flashes of flashDurationSeconds real seconds. Default 60.
    double timeScale = 60.0;
};

/// Closed-form in-scattered light along origin -> origin + delta, RGB:
/// colour * scale * integral f. `scale` multiplies the intensity (e.g. a
/// lightning flash).
glm::dvec3 emitterInScatter(const Emitter& emitter, const glm::dvec3& origin,
                            const glm::dvec3& delta, double scale);

/// The scalar integral of f (intensity included, colour not).
double emitterIntegral(const Emitter& emitter, const glm::dvec3& origin,
                       const glm::dvec3& delta);

/// f at a point (intensity included, colour not): the quadrature reference.
double emitterFieldAt(const Emitter& emitter, const glm::dvec3& point);

/// Brightness multiplier of a lightning emitter at a time of day [h], 0..1;
/// 1 for a point emitter. Deterministic: depends only on the emitter's
/// parameters and the time.
double lightningFlash(const Emitter& emitter, double timeHours);

}  // namespace aerial
