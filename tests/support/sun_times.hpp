// sun_times.hpp — when the sun of an evaluated preset stands at an
// elevation, for tests that hold the sky to the outdoors at a given sun.
#pragma once

#include <aerial/evaluate.hpp>

namespace aerial::test {

/// The evening time [h] of `preset` at which the sun's geometric elevation
/// is `elevationDeg`: bisection between noon and midnight, where the sun
/// only sinks (50 halvings: far below a second). A sun that never reaches
/// the elevation gives noon or midnight.
inline double eveningTimeOfSun(const CompiledPreset& preset, double elevationDeg) {
    constexpr double kDegreesPerRadian = 57.29577951308232;
    double lo = 12.0, hi = 23.999;
    for (int i = 0; i < 50; ++i) {
        const double mid = 0.5 * (lo + hi);
        const double e = preset.evaluate(mid).sunLight.body.elevation * kDegreesPerRadian;
        (e > elevationDeg ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

}  // namespace aerial::test
