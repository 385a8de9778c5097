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
// It is evaluated in the equivalent, cancellation-free form
//   integral f = (i / K) atan2(|d| K, X),
//   K = sqrt(a) sqrt(1 + a |c x n|^2),  X = 1 + a c.(c - d),  n = d / |d|
// (the atan difference folded into one atan2; K = k / (2|d|), X = (2u + v)/2),
// accurate for long segments and far emitters and exactly i |d| at a = 0.
//
// Sanitising: a negative or non-finite intensity, attenuation or scale counts
// as 0, colours likewise per component; positions or segments that are not
// finite (or beyond 1e30 m) give 0. No function here returns NaN or Inf.
//
// Lightning: a flash pattern made from the emitter's parameters alone
// (seed, rate, duration, time scale), so every machine that loads the preset
// sees the same flashes at the same time of day. The flash clock
// flashSeconds = (timeHours mod 24) 3600 / timeScale is cut into equal slots
// (about two flash durations long, an integer number per day, so the pattern
// wraps seamlessly at 24 h); a counter-based hash (splitmix64) of (seed, slot)
// decides whether a slot flashes (probability rate x slot length, so the mean
// rate is flashesPerMinute while it stays below about 30 / duration), where in
// the slot the flash starts, and its 2-4 strokes (a flicker of exponentially
// decaying strokes over a fading glow, > 0 for the whole flash, peak 1). No
// state: any call order gives the same values.
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
glm::dvec3 emitterInScatter(const Emitter& emitter, const glm::dvec3& origin, const glm::dvec3& delta,
                            double scale);

/// The scalar integral of f (intensity included, colour not).
double emitterIntegral(const Emitter& emitter, const glm::dvec3& origin, const glm::dvec3& delta);

/// f at a point (intensity included, colour not): the quadrature reference.
double emitterFieldAt(const Emitter& emitter, const glm::dvec3& point);

/// Brightness multiplier of a lightning emitter at a time of day [h], 0..1;
/// 1 for a point emitter. Deterministic: depends only on the emitter's
/// parameters and the time. Invalid lightning parameters (rate or duration
/// not positive and finite, timeScale outside [1e-6, 1e9]) or a non-finite
/// time give 0: no flashes.
double lightningFlash(const Emitter& emitter, double timeHours);

}  // namespace aerial
