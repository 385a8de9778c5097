// aerial/emitter.hpp — light emitters that light the fog (and the scene):
// lamps, fires, and lightning.
//
// Usage:
//   aerial::Emitter lamp;
//   lamp.position = {3, 4, -10}; lamp.intensityCd = 1500; lamp.temperatureK = 2100;
//   lamp.attenuation = 10;                       // a glowing core ~0.3 m across
//   lamp.intensity = aerial::emitterFogIntensity(lamp.intensityCd, lamp.attenuation, fogSigma);
//   glm::dvec3 added = aerial::emitterInScatter(lamp, camera, object - camera, 1.0);
//   double flash = aerial::lightningFlash(bolt, timeHours);   // 0..1
// aerial::evaluate does the middle line for every emitter of a preset, with
// the fog's scattering where the emitter is (aerial::fogScatteringAt).
//
// Photometry (../shared/DESIGN.md, "Emitters": the strength is photometric).
// An emitter is a source of luminous intensity I [cd] whose colour has unit
// luminance (emitterColour: a blackbody of temperatureK, or colour_rgb
// divided by its luminance), softened over a core of radius r0 = 1/sqrt(a):
//   illuminance at distance r     E(r) = I / (r0^2 + r^2)            [lx]
//   in-scatter per metre of fog   f(r) = sigma_s E(r) / (4 pi)        [cd/m^2 per m]
// (isotropic scattering; sigma_s the fog's scattering coefficient at the
// emitter, held along the segment). In the renderer's radiance unit
// (kNitsPerRadianceUnit cd/m^2) that is f = i / (1 + a r^2) with
//   i = a sigma_s I / (4 pi kNitsPerRadianceUnit)     (emitterFogIntensity)
// and the light on surfaces and clouds is E = e / (1 + a r^2) with
//   e = a I / kNitsPerRadianceUnit                      (emitterIlluminance).
// So a 1 000 lm campfire (I = 80 cd) in a light haze (sigma_s = 1e-4 /m)
// adds ~2e-4 cd/m^2 to a view passing 10 m from it, the brightness of a
// moonless sky: the fog glows near the fire and the sky stays dark.
// Extinction: the light is dimmed by exp(-sigma_t D), sigma_t the air's
// extinction at the emitter (`extinction`, the fog's scattering: fog does
// not absorb) and D the distance from the emitter to the start of the
// segment (emitterInScatter; for the eye's view that is the path the glow
// travels to the eye, exact for a glow seen far from its source and within
// 2 sigma_t r0 of it when seen close) or to the lit surface or cloud. A
// sodium lamp in a thick fog (sigma 0.004 /m) lights the fog 100 m away
// a third less than without it.
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

#include <vector>

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
    /// Luminous intensity I [cd], >= 0: the artist's strength (preset key
    /// intensity_cd). A 1 000 lm campfire is ~80 cd, a 60 W bulb ~65 cd, a
    /// sodium street lamp 1 000-3 000 cd, a lightning channel 1e9-1e11 cd.
    /// Default 100.
    double intensityCd = 100.0;
    /// Colour temperature [K] of a blackbody of that colour, 1 667..25 000
    /// (a campfire ~1 900, a sodium lamp ~2 100, an LED 3 000-5 000); 0 (the
    /// default) takes `colour` instead.
    double temperatureK = 0.0;
    /// In-scatter coefficient i [radiance unit / m] of the fog next to the
    /// emitter, times the colour: derived, not stored in presets.
    /// aerial::evaluate sets it from intensityCd and the fog's scattering at
    /// the emitter (emitterFogIntensity); set it yourself for an emitter
    /// built by hand. >= 0.
    double intensity = 0.0;
    /// Extinction sigma_t [1/m] of the air at the emitter, >= 0: derived
    /// like `intensity` (aerial::evaluate: fogScatteringAt); the light is
    /// dimmed by exp(-extinction D) over the distance D it travels (see
    /// "Extinction"). Default 0 (no dimming).
    double extinction = 0.0;
    /// Attenuation a [1/m^2], >= 0: the glowing core's radius is 1/sqrt(a)
    /// (the field falls to half there). Default 1 (a 1 m core).
    double attenuation = 1.0;
    /// Colour, scene-linear Rec.709 (used when temperatureK is 0). Its
    /// luminance is divided out, so it sets the hue and not the strength;
    /// aerial::evaluate replaces it by emitterColour(). Default white.
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

/// Linear Rec.709 colour of a blackbody at `kelvin` (clamped to the fit's
/// 1 667..25 000 K), luminance 1: the Planckian locus in CIE 1931 xy (Kim et
/// al. 2002's cubic fit, within 1e-3 of Planck's law) converted through XYZ,
/// negative components (below ~1 900 K red is out of gamut) clipped to 0 and
/// the result renormalised. A non-finite kelvin gives white.
glm::dvec3 blackbodyColour(double kelvin);

/// The emitter's colour with unit luminance: blackbodyColour(temperatureK)
/// when temperatureK > 0, else colour divided by its luminance (black when
/// the colour's luminance is 0 or the colour not finite).
glm::dvec3 emitterColour(const Emitter& emitter);

/// i = a sigma_s I / (4 pi kNitsPerRadianceUnit) [radiance unit / m], the
/// in-scatter coefficient of fog with scattering coefficient
/// `scatteringPerM` [1/m] next to a source of `intensityCd` [cd] with
/// attenuation a [1/m^2]. Negative or non-finite inputs count as 0.
double emitterFogIntensity(double intensityCd, double attenuation, double scatteringPerM);

/// e = a I / kNitsPerRadianceUnit [illuminance unit]: the illuminance
/// e / (1 + a r^2) the emitter gives a surface or a cloud at distance r
/// (flash applied to intensityCd by evaluate). Finite, >= 0.
double emitterIlluminance(const Emitter& emitter);

/// Closed-form in-scattered light along origin -> origin + delta, RGB:
/// colour * scale * integral f * exp(-extinction |position - origin|).
/// `scale` multiplies the intensity (e.g. a lightning flash).
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

/// Start times [h] of a lightning emitter's flashes in (fromHours, toHours]
/// of one day (0 <= from <= to <= 24), in order, as lightningFlash draws
/// them (each flash's first stroke); appended to `out`. Nothing for other
/// emitters or invalid parameters. (events.hpp reports them to a game.)
void lightningStrikeHours(const Emitter& emitter, double fromHours, double toHours, std::vector<double>& out);

}  // namespace aerial
