// stars.cpp — naked-eye visibility of stars (aerial/stars.hpp).
#include <aerial/night_sky.hpp>
#include <aerial/stars.hpp>

#include <algorithm>
#include <cmath>

namespace aerial {
namespace {

constexpr double kNitsPerNanolambert = 1e-9 * 1e4 / 3.14159265358979323846;  // 1 L = 1/pi cd/cm^2
constexpr double kLuxPerFootCandle = 10.7639104;
// Schaefer (1990), eq. 2 with his night-vision constants; I in foot-candles.
constexpr double kHechtC = 1.5848931924611134e-10;  // 10^-9.8
constexpr double kHechtK = 1.2589254117941673e-2;   // 10^-1.9

/// Pogson's scale: the flux of a magnitude, zeroPoint 10^(-0.4 m); 0 for a
/// non-finite magnitude.
double fluxOfMagnitude(double magnitude, double zeroPoint) {
    if (!std::isfinite(magnitude)) return 0.0;
    return zeroPoint * std::pow(10.0, -0.4 * std::clamp(magnitude, -100.0, 100.0));
}

/// The magnitude of a flux, -2.5 log10(flux / zeroPoint), the flux floored
/// at `floor` (non-finite counts as the floor).
double magnitudeOfFlux(double flux, double zeroPoint, double floor) {
    const double f = std::isfinite(flux) ? std::max(flux, floor) : floor;
    return -2.5 * std::log10(f / zeroPoint);
}

}  // namespace

double luminanceFromSkyBrightness(double magPerSquareArcsec) {
    return fluxOfMagnitude(magPerSquareArcsec, kSkyBrightnessZeroPointNits);
}

double skyBrightnessFromLuminance(double nits) {
    return magnitudeOfFlux(nits, kSkyBrightnessZeroPointNits, 1e-12);
}

double starIlluminanceLux(double magnitude) {
    return fluxOfMagnitude(magnitude, kZeroMagnitudeIlluminanceLux);
}

double starMagnitudeFromIlluminance(double lux) {
    return magnitudeOfFlux(lux, kZeroMagnitudeIlluminanceLux, 1e-30);
}

double limitingMagnitude(double backgroundNits) {
    if (std::isnan(backgroundNits) || backgroundNits > 1e300) return kNoStarMagnitude;
    const double nanolamberts = std::max(backgroundNits, 0.0) / kNitsPerNanolambert;
    const double root = 1.0 + std::sqrt(kHechtK * nanolamberts);
    const double thresholdLux = kHechtC * root * root * kLuxPerFootCandle;
    return std::max(starMagnitudeFromIlluminance(thresholdLux), kNoStarMagnitude);
}

double extinctedMagnitude(double magnitude, double zenithTransmittanceV, double mu,
                          double cloudTransmittance) {
    if (!std::isfinite(magnitude) || !(mu > 0.0) || !(zenithTransmittanceV > 0.0) ||
        !(cloudTransmittance > 0.0))
        return kHiddenStarMagnitude;
    const double t = std::min(zenithTransmittanceV, 1.0);
    const double cloud = std::min(cloudTransmittance, 1.0);
    const double seen =
        magnitude - 2.5 * (relativeAirMass(std::min(mu, 1.0)) * std::log10(t) + std::log10(cloud));
    return std::isfinite(seen) ? std::min(seen, kHiddenStarMagnitude) : kHiddenStarMagnitude;
}

double starThresholdFade(double seenMagnitude, double limitMagnitude) {
    if (!std::isfinite(seenMagnitude) || !std::isfinite(limitMagnitude)) return 0.0;
    const double x = std::clamp((limitMagnitude - seenMagnitude) / kStarFadeMagnitudes + 0.5, 0.0, 1.0);
    return x * x * (3.0 - 2.0 * x);
}

double starFieldMagnitude(double u) {
    const double v = std::isfinite(u) ? std::clamp(u, 0.0, 1.0) : 0.0;
    if (!(v < 1.0)) return kStarFieldBrightest;
    return std::max(kStarFieldBrightest, kStarFieldFaintest + 2.0 * std::log10(1.0 - v));
}

double starFieldCount(double magnitude) {
    if (std::isnan(magnitude) || magnitude < kStarFieldBrightest) return 0.0;
    if (magnitude >= kStarFieldFaintest) return kStarFieldStars;
    return kStarFieldStars * std::pow(10.0, 0.5 * (magnitude - kStarFieldFaintest));
}

}  // namespace aerial
