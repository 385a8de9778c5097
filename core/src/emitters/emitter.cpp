// emitter.cpp — point emitters lighting the fog, and the seeded lightning
// flash pattern (../shared/DESIGN.md, "Emitters"; Wenzel 2006, section
// 6.9.2, volumetric lightning).
//
// In-scatter. With f(p) = i / (1 + a |l - p|^2) along o + s n, s in [0, L]
// (n = d / |d|, L = |d|, c = l - o, e = l - o - d the emitter seen from the
// end), the paper's
//   2 i L (atan((v + 2w)/k) - atan(v/k)) / k
// is rewritten with atan(A) - atan(B) = atan2(A - B, 1 + A B) (exact for
// A > B, as (sin, cos) of the difference are proportional to those two
// terms with a positive factor) into
//   integral f = (i / K) atan2(L K, X),
//   K = sqrt(a) sqrt(1 + a |c x n|^2)     ( = k / (2 |d|) ),
//   X = 1 + a (c . e)                     ( = (2u + v) / 2 ).
// K comes from a cross product and X from a dot product of the two end
// vectors, so neither 4uw - v^2 nor the difference of two nearly equal
// arctangents is ever formed: no cancellation for long segments or far
// emitters. For L K < X it is evaluated as i L atanc(L K / X) / X with
// atanc(z) = atan(z)/z, which is exact at a = 0 (K = 0): i L; otherwise as
// (i / K) (pi/2 - atan(X / (L K))).
#include "base/sanitise.hpp"

#include <aerial/atmosphere.hpp>
#include <aerial/emitter.hpp>
#include <aerial/exposure.hpp>
#include <aerial/finite.hpp>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace aerial {
namespace {

/// Emitter attenuation and intensity are clamped to this.
constexpr double kMaxEmitterParameter = 1.0e30;

/// atan(z) / z for z >= 0, 1 at z = 0 (the limit; atan keeps the leading z
/// exactly, so the ratio is accurate to an ulp or two right down to z = 0).
double atanOverX(double z) { return z != 0.0 ? std::atan(z) / z : 1.0; }

/// Not finite or negative -> 0, else at most `bound`.
double clampedNonNegative(double x, double bound) {
    return (std::isfinite(x) && x > 0.0) ? std::min(x, bound) : 0.0;
}

}  // namespace

glm::dvec3 blackbodyColour(double kelvin) {
    if (!std::isfinite(kelvin)) return glm::dvec3(1.0);
    const double t = std::clamp(kelvin, 1667.0, 25000.0);
    // Kim, Kim, Lee, Park and Choi 2002, the Planckian locus as cubics in 1/T
    // and x.
    const double t1 = 1.0e3 / t, t2 = t1 * t1, t3 = t2 * t1;
    const double x = t <= 4000.0 ? -0.2661239 * t3 - 0.2343589 * t2 + 0.8776956 * t1 + 0.179910
                                 : -3.0258469 * t3 + 2.1070379 * t2 + 0.2226347 * t1 + 0.240390;
    const double x2 = x * x, x3 = x2 * x;
    const double y = t <= 2222.0   ? -1.1063814 * x3 - 1.34811020 * x2 + 2.18555832 * x - 0.20219683
                     : t <= 4000.0 ? -0.9549476 * x3 - 1.37418593 * x2 + 2.09137015 * x - 0.16748867
                                   : 3.0817580 * x3 - 5.87338670 * x2 + 3.75112997 * x - 0.37001483;
    // XYZ with Y = 1, then linear Rec.709 (D65).
    const double bigX = x / y, bigZ = (1.0 - x - y) / y;
    glm::dvec3 rgb{3.2404542 * bigX - 1.5371385 - 0.4985314 * bigZ,
                   -0.9692660 * bigX + 1.8760108 + 0.0415560 * bigZ,
                   0.0556434 * bigX - 0.2040259 + 1.0572252 * bigZ};
    rgb = glm::max(rgb, glm::dvec3(0.0));
    const double y709 = luminance(rgb);
    return y709 > 0.0 ? rgb / y709 : glm::dvec3(1.0);
}

glm::dvec3 emitterColour(const Emitter& emitter) {
    if (std::isfinite(emitter.temperatureK) && emitter.temperatureK > 0.0)
        return blackbodyColour(emitter.temperatureK);
    const glm::dvec3 c{clampedNonNegative(emitter.colour.x, kMaxEmitterParameter),
                       clampedNonNegative(emitter.colour.y, kMaxEmitterParameter),
                       clampedNonNegative(emitter.colour.z, kMaxEmitterParameter)};
    const double y = luminance(c);
    return y > 0.0 ? c / y : glm::dvec3(0.0);
}

double emitterFogIntensity(double intensityCd, double attenuation, double scatteringPerM) {
    const double i = clampedNonNegative(attenuation, kMaxEmitterParameter) *
                     clampedNonNegative(scatteringPerM, kMaxEmitterParameter) *
                     clampedNonNegative(intensityCd, kMaxEmitterParameter) / (4.0 * kPi * kNitsPerRadianceUnit);
    return std::min(i, kMaxEmitterParameter);
}

double emitterIlluminance(const Emitter& emitter) {
    const double e = clampedNonNegative(emitter.attenuation, kMaxEmitterParameter) *
                     clampedNonNegative(emitter.intensityCd, kMaxEmitterParameter) / kNitsPerRadianceUnit;
    return std::min(e, kMaxEmitterParameter);
}

double emitterFieldAt(const Emitter& emitter, const glm::dvec3& point) {
    if (!withinCoordinateRange(point) || !withinCoordinateRange(emitter.position)) {
        return 0.0;
    }
    const double i = clampedNonNegative(emitter.intensity, kMaxEmitterParameter);
    const double a = clampedNonNegative(emitter.attenuation, kMaxEmitterParameter);
    const glm::dvec3 c = emitter.position - point;
    return i / (1.0 + a * glm::dot(c, c));
}

double emitterIntegral(const Emitter& emitter, const glm::dvec3& origin, const glm::dvec3& delta) {
    if (!withinCoordinateRange(origin) || !withinCoordinateRange(delta) ||
        !withinCoordinateRange(emitter.position)) {
        return 0.0;
    }
    const double i = clampedNonNegative(emitter.intensity, kMaxEmitterParameter);
    const double a = clampedNonNegative(emitter.attenuation, kMaxEmitterParameter);
    const double length = glm::length(delta);
    if (!(i > 0.0) || !(length > 0.0)) {
        return 0.0;
    }
    const glm::dvec3 n = delta / length;
    const glm::dvec3 c = emitter.position - origin;  // emitter seen from the start
    const glm::dvec3 e = c - delta;                  // emitter seen from the end
    const glm::dvec3 cross = glm::cross(c, n);
    const double k = std::sqrt(a) * std::sqrt(1.0 + a * glm::dot(cross, cross));
    const double x = 1.0 + a * glm::dot(c, e);
    const double y = length * k;
    // y < X (so X > 0): i L atanc(y / X) / X, exact down to a = 0 (k = 0)
    // where it is i L. Otherwise y >= X and y > 0: X <= 0 needs the emitter
    // between the ends and a L^2 / 4 >= a |c.e| >= 1, hence y >= 2; and
    // y >= X > 0 gives k > 0. Then (i / k) atan2(y, X), the angle in
    // [pi/4, pi), evaluated as pi/2 - atan(X / y) (X / y <= 1, no
    // cancellation; cheaper than atan2). Both forms agree at y = X.
    constexpr double kHalfPi = 1.57079632679489661923;
    const double integral =
        (y < x) ? i * length * atanOverX(y / x) / x : i * (kHalfPi - std::atan(x / y)) / k;
    return std::min(integral, std::numeric_limits<double>::max());
}

glm::dvec3 emitterInScatter(const Emitter& emitter, const glm::dvec3& origin, const glm::dvec3& delta,
                            double scale) {
    const double s = clampedNonNegative(scale, kMaxEmitterParameter);
    const glm::dvec3 colour = detail::sanitiseColour(emitter.colour);
    const double integral = emitterIntegral(emitter, origin, delta);
    const double sigma = clampedNonNegative(emitter.extinction, kMaxEmitterParameter);
    const double dimming = sigma > 0.0 && integral > 0.0 ? std::exp(-sigma * glm::length(emitter.position - origin)) : 1.0;
    // integral <= i |d| <= 1e30 * 3.5e30, s <= 1e30, colour <= 1e30: the
    // product stays far below the double range.
    return colour * (integral * s * dimming);
}

// ---------------------------------------------------------------------------
// Lightning.
//
// The flash clock runs at flashSeconds = (timeHours mod 24) * 3600 /
// timeScale; one day of it, D = 86400 / timeScale seconds, is cut into an
// integer number of equal slots (so the pattern wraps seamlessly at 24 h).
// The slot length is about two flash durations (at least one), and each slot
// independently holds one flash with probability p = rate * slot / 60, so
// flashes arrive at the mean rate `flashesPerMinute` and never overlap. A
// counter-based hash of (seed, slot index) decides everything about a slot:
// whether it flashes, when inside the slot the flash starts, and its strokes.
// No state, no dependence on call order or platform RNGs.
//
// A flash is a multi-stroke flicker (return strokes of a cloud-to-ground
// discharge): 2..4 strokes, the first at the flash start with brightness 1,
// the others at hashed times in the first 70 % of the flash with brightness
// 0.45..1; each stroke decays exponentially, and a dim glow that fades
// linearly to the end keeps the flash > 0 over its whole duration.

namespace {

std::uint64_t splitMix64(std::uint64_t x) {
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
}

/// Uniform in [0, 1) from the top 53 bits.
double toUnit(std::uint64_t h) { return static_cast<double>(h >> 11) * (1.0 / 9007199254740992.0); }

/// The random stream of one slot: hashes of (seed, slot, counter).
class SlotHash {
public:
    SlotHash(std::uint32_t seed, std::uint64_t slot)
        : key_(splitMix64(splitMix64(static_cast<std::uint64_t>(seed) ^ 0xA511E9B3C0FFEE00ull) ^ slot)) {}
    double next() { return toUnit(splitMix64(key_ + 0x632BE59BD9B4E019ull * ++counter_)); }

private:
    std::uint64_t key_;
    std::uint64_t counter_ = 0;
};

/// The flash clock's slots of a lightning emitter (see above).
struct FlashSlots {
    bool valid = false;
    double slotCount = 1.0;
    double slotLength = 1.0;   ///< [s of the flash clock]
    double probability = 0.0;  ///< of a flash in a slot
    double flashLength = 1.0;  ///< [s of the flash clock]
};

FlashSlots flashSlots(const Emitter& emitter) {
    FlashSlots s;
    const double rate = emitter.flashesPerMinute;
    const double duration = emitter.flashDurationSeconds;
    const double timeScale = emitter.timeScale;
    // Invalid parameters mean no flashes (bounds keep the slot count in range).
    if (!(rate > 0.0) || !(rate < 1.0e9) || !(duration > 0.0) || !(duration < 1.0e9) || !(timeScale >= 1.0e-6) ||
        !(timeScale <= 1.0e9))
        return s;
    const double daySeconds = 86400.0 / timeScale;
    // Slots: target length two durations, shortened towards one duration
    // when the rate needs it, and an integer number per day.
    const double target = std::max(duration, std::min(2.0 * duration, 60.0 / rate));
    s.slotCount = std::clamp(std::floor(daySeconds / target), 1.0, 1.0e15);
    s.slotLength = daySeconds / s.slotCount;
    s.probability = std::min(1.0, rate * s.slotLength / 60.0);
    s.flashLength = std::min(duration, s.slotLength);  // a day shorter than a flash
    s.valid = true;
    return s;
}

}  // namespace

void lightningStrikeHours(const Emitter& emitter, double fromHours, double toHours, std::vector<double>& out) {
    if (emitter.kind != EmitterKind::Lightning) return;
    const FlashSlots slots = flashSlots(emitter);
    if (!slots.valid || !(fromHours < toHours)) return;
    const double from = std::max(fromHours, 0.0) * 3600.0 / emitter.timeScale;
    const double to = std::min(toHours, 24.0) * 3600.0 / emitter.timeScale;
    const double first = std::max(std::floor(from / slots.slotLength), 0.0);
    const double last = std::min(std::floor(to / slots.slotLength), slots.slotCount - 1.0);
    for (double slotReal = first; slotReal <= last; slotReal += 1.0) {
        SlotHash hash(emitter.seed, static_cast<std::uint64_t>(slotReal));
        if (!(hash.next() < slots.probability)) continue;
        const double start = slotReal * slots.slotLength + hash.next() * (slots.slotLength - slots.flashLength);
        if (start > from && start <= to) out.push_back(start * emitter.timeScale / 3600.0);
    }
}

double lightningFlash(const Emitter& emitter, double timeHours) {
    if (emitter.kind != EmitterKind::Lightning) {
        return 1.0;
    }
    const FlashSlots slots = flashSlots(emitter);
    if (!std::isfinite(timeHours) || !slots.valid) return 0.0;
    double hours = std::fmod(timeHours, 24.0);
    if (hours < 0.0) {
        hours += 24.0;
    }
    if (!(hours < 24.0)) {
        hours = 0.0;  // -tiny + 24 rounds to 24
    }
    const double seconds = hours * 3600.0 / emitter.timeScale;
    const double slotLength = slots.slotLength, slotCount = slots.slotCount, probability = slots.probability;
    const double duration = emitter.flashDurationSeconds;

    const double slotReal = std::min(std::floor(seconds / slotLength), slotCount - 1.0);
    const std::uint64_t slot = static_cast<std::uint64_t>(std::max(slotReal, 0.0));
    SlotHash hash(emitter.seed, slot);
    if (!(hash.next() < probability)) {
        return 0.0;
    }
    const double flashLength = std::min(duration, slotLength);  // a day shorter than a flash
    const double start = slotReal * slotLength + hash.next() * (slotLength - flashLength);
    const double tau = (seconds - start) / flashLength;  // 0..1 inside the flash
    if (!(tau >= 0.0 && tau < 1.0)) {
        return 0.0;
    }
    const int strokes = 2 + static_cast<int>(hash.next() * 3.0);  // 2..4
    const double decay = 0.07;                                    // of the flash length
    double value = 0.25 * (1.0 - tau);                            // glow
    for (int s = 0; s < strokes; ++s) {
        const double at = (s == 0) ? 0.0 : 0.7 * hash.next();
        const double peak = (s == 0) ? 1.0 : 0.45 + 0.55 * hash.next();
        if (tau >= at) {
            value = std::max(value, peak * std::exp(-(tau - at) / decay));
        }
    }
    return std::clamp(value, 0.0, 1.0);
}

}  // namespace aerial
