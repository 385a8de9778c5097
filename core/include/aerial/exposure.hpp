// aerial/exposure.hpp — from scene-linear radiance to an exposure: the
// physical-camera formulas of Unreal's and HDRP's auto exposure, for a game
// that wants the EV the editor shows.
//
// Usage:
//   aerial::LuminanceHistogram histogram;                 // log2 L in [-16, 16]
//   for (const glm::dvec3& rgb : framePixels) histogram.add(aerial::luminance(rgb));
//   double target = aerial::ev100FromAverageLuminance(histogram.averageLuminance(0.10, 0.90));
//   ev = aerial::adaptEv100(ev, target, dtSeconds, 3.0, 1.0);  // eyes adapt over time
//   double scale = aerial::exposureScale(ev - compensationEv);  // multiplies radiance
//
// Formulas (Lagarde and de Rousiers 2014, "Moving Frostbite to Physically
// Based Rendering", section 4.6; the same in Unreal's and HDRP's cameras):
//   * luminance of a linear Rec.709 colour Y = 0.2126 R + 0.7152 G + 0.0722 B;
//   * the EV100 that exposes an average luminance L to middle grey (reflected-
//     light meter, calibration K = 12.5, ISO S = 100): EV100 = log2(L S / K);
//   * the scale from EV100 to the value that saturates the sensor
//     (saturation-based speed, q = 0.65): H = 1 / (1.2 * 2^EV100), so that a
//     pixel at the average luminance maps to K / (1.2 S) = 0.104, a middle
//     grey before the display transform's curve;
//   * adaptation: an exponential approach to the target at `speed` per
//     second, faster when the scene gets brighter (a pupil closes faster than
//     it opens), 1 - exp(-dt * speed) of the gap closed in dt seconds;
//   * the average of a frame is taken in log2 luminance over a histogram,
//     between two percentiles (Unreal: 10 % and 90 %), so a small bright sun
//     or a dark corner does not swing the exposure.
// Luminance is in the scene's radiance unit; a positive compensation
// brightens the picture (subtract it from EV100). Nothing here returns NaN or
// Inf: non-finite or non-positive luminances count as the darkest bin.
#pragma once

#include <glm/vec3.hpp>

#include <array>
#include <cstddef>

namespace aerial {

/// Luminance Y of a scene-linear Rec.709 colour (the colour's own unit);
/// 0 for a colour with a NaN component, negative components count as 0.
double luminance(const glm::dvec3& linearRec709);

/// EV100 that exposes `averageLuminance` to middle grey: log2(L * 100 / 12.5);
/// luminances are clamped to [2^-40, 2^40] first (so 0 gives -37).
double ev100FromAverageLuminance(double averageLuminance);

/// Multiplier on radiance for an EV100: 1 / (1.2 * 2^ev100); the EV100 is
/// clamped to [-60, 60] (NaN counts as 0).
double exposureScale(double ev100);

/// One adaptation step from `currentEv100` towards `targetEv100` over `dt`
/// seconds: speedUp [1/s] when the target EV is higher (the scene brighter),
/// speedDown otherwise. dt <= 0 keeps the current EV; a non-finite current
/// EV jumps to the target; speeds <= 0 or non-finite jump at once.
double adaptEv100(double currentEv100, double targetEv100, double dt, double speedUp, double speedDown);

/// A histogram of log2 luminance: 64 bins over [minLog2, maxLog2]
/// (default [-16, 16]); values outside count in the first or last bin.
class LuminanceHistogram {
public:
    static constexpr std::size_t kBins = 64;

    explicit LuminanceHistogram(double minLog2 = -16.0, double maxLog2 = 16.0);

    /// Adds a pixel's luminance with a weight (>= 0; e.g. a centre weight).
    void add(double luminance, double weight = 1.0);
    void clear();

    /// Average luminance (2^mean log2 L) of the pixels between the
    /// lowFraction and highFraction quantiles of the weight (0 <= low < high
    /// <= 1; e.g. 0.1 and 0.9), each bin at its centre; the histogram's
    /// minimum when empty.
    double averageLuminance(double lowFraction, double highFraction) const;

    double totalWeight() const { return total_; }
    const std::array<double, kBins>& bins() const { return bins_; }

private:
    double minLog2_;
    double maxLog2_;
    std::array<double, kBins> bins_{};
    double total_ = 0.0;
};

}  // namespace aerial
