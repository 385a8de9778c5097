// aerial/exposure.hpp — from scene-linear radiance to an exposure: the
// physical-camera formulas of Unreal's and HDRP's auto exposure, for a game
// that wants the EV the editor shows.
//
// Usage (a game, with the preset's exposure block, state.environment.exposure):
//   const aerial::ExposureParams& p = state.environment.exposure;
//   double average = aerial::meterAverageLuminance(pixels, 4);   // RGBA radiance, once a frame
//   double target = aerial::targetEv100(p, average);              // manual: p.ev100
//   ev = aerial::adaptEv100(ev, target, dt, p.adaptUpPerSecond, p.adaptDownPerSecond);
//   float scale = float(aerial::radianceScale(p, ev));            // radiance -> display-linear
//
// The parts, for a game with its own meter:
//   aerial::LuminanceHistogram histogram;                 // log2 L in [-16, 16]
//   for (const glm::dvec3& rgb : framePixels) histogram.add(aerial::luminance(rgb));
//   double target = aerial::ev100FromAverageLuminance(histogram.averageLuminance(0.10, 0.90));
//   ev = aerial::adaptEv100(ev, target, dtSeconds, 3.0, 1.0);  // eyes adapt over time
//   double scale = aerial::exposureScale(ev - compensationEv);  // multiplies radiance
//
// Formulas (Lagarde and de Rousiers 2014, "Moving Frostbite to Physically
// Based Rendering", section 4.6; ISO 2720 and ISO 12232):
//   * luminance of a linear Rec.709 colour Y = 0.2126 R + 0.7152 G + 0.0722 B;
//   * the EV100 that exposes an average luminance L to middle grey (reflected-
//     light meter, calibration K = 12.5, ISO S = 100): EV100 = log2(L S / K);
//   * the scale from EV100 to the display transform's scene-linear input:
//     kMiddleGrey S / (K 2^EV100), so a pixel at the metered luminance maps
//     to scene-linear middle grey, 0.18, and a sunny-16 noon (EV100 15)
//     renders a grey card in full sun (~5700 cd/m^2) at ~0.25. A camera's
//     picture shows the metered grey at 118/255 (ISO 12232's standard output
//     sensitivity); a filmic view shows 0.18 darker (ACES SDR video: 0.35),
//     so the display adds its view's calibration (Aerial's renderer:
//     DisplayTransform::middleGreyEv, +0.56 EV for ACES; a game with its own
//     tone curve adds the stops that show 0.18 at 118/255) and the key reads
//     as a camera's: the metered luminance shows at 118/255;
//   * adaptation: an exponential approach to the target at `speed` per
//     second, faster when the scene gets brighter (a pupil closes faster than
//     it opens), 1 - exp(-dt * speed) of the gap closed in dt seconds;
//   * the meter: a photographer's centre-weighted average meter, about a
//     point a little below the frame's centre (a pixel counts 1 within
//     ~kMeterCentreRadius frame heights of it, kMeterOutsideWeight at the
//     edges: the subject counts more than the sky at the top of a landscape
//     frame, but the sky still counts, as in a camera's meter cell); its
//     average is taken in log2 luminance over a histogram of half-stop bins,
//     between the 10 % and 90 % quantiles of the weight, so a small bright
//     sun, a campfire or a dark corner does not swing the exposure.
// Units: the physical formulas take luminance in cd/m^2. Aerial's radiance
// unit is kNitsPerRadianceUnit cd/m^2: the default sun intensity 20 lights
// the ground like the ~100 000 lx of a clear noon, so one unit of
// illuminance is ~5000 lx and one of radiance ~5000 cd/m^2; EV100 values
// then read as on a real camera (a sunny noon ~15, a lit street at night ~5).
// The functions on ExposureParams take radiance units; the others cd/m^2.
// A positive compensation
// brightens the picture (subtract it from EV100). Nothing here returns NaN or
// Inf: non-finite or non-positive luminances count as the darkest bin.
#pragma once

#include <glm/vec3.hpp>

#include <array>
#include <cstddef>
#include <span>

namespace aerial {

/// Luminance Y of a scene-linear Rec.709 colour (the colour's own unit);
/// 0 for a colour with a NaN component, negative components count as 0.
double luminance(const glm::dvec3& linearRec709);

/// EV100 that exposes `averageLuminance` to middle grey: log2(L * 100 / 12.5);
/// luminances are clamped to [2^-40, 2^40] first (so 0 gives -37).
double ev100FromAverageLuminance(double averageLuminance);

/// Multiplier on radiance [cd/m^2] for an EV100: kMiddleGrey * 100 / (12.5 *
/// 2^ev100) = 1.44 / 2^ev100 (see "Formulas"); the EV100 is clamped to
/// [-60, 60] (NaN counts as 0).
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

/// cd/m^2 per unit of Aerial's radiance (see "Units" above).
inline constexpr double kNitsPerRadianceUnit = 5000.0;

/// Night vision, the Purkinje shift: the colour to show for a scene-linear
/// Rec.709 colour as an eye sees it at its luminance. Below a few cd/m^2
/// the rods take over from the cones (CIE 191:2010's mesopic range, 0.005
/// to 5 cd/m^2): colour fades, blue-green light looks brighter than red of
/// the same luminance, and painters and film show the result as a blue
/// night (Jensen et al. 2000, "Night rendering"). Per pixel:
///   L = luminance(c) * nitsPerUnit [cd/m^2]
///   m = the rods' share: 1 at or below 0.005 cd/m^2, 0 at or above 5,
///       smoothstep in log10(L) between
///   V = scotopic luminance (Larson, Rushmeier and Piatko 1997):
///       Y (1.33 (1 + (Y + Z) / X) - 1.68) over the same for D65 white (so
///       a white surface keeps its luminance; warm light is dimmer, blue
///       light brighter), at most 4 Y
///   out = (1 - m) c + m V kNightVisionWhite
/// kNightVisionWhite is the blue white xy (0.28, 0.29), luminance 1. A
/// moonless natural sky (2e-4 cd/m^2) becomes fully scotopic; a moonlit
/// landscape (~0.05 cd/m^2) two thirds; the blue hour (>= 5 cd/m^2) keeps
/// its colour. Negative or non-finite components count as 0; the result is
/// finite.
glm::dvec3 nightVision(const glm::dvec3& linearRec709, double nitsPerUnit);

/// The colour of fully scotopic vision: xy (0.28, 0.29), luminance 1,
/// linear Rec.709 (~0.85, 1.00, 1.42).
glm::dvec3 nightVisionWhite();

/// How a preset chooses its exposure.
enum class ExposureMode {
    Manual,     ///< ExposureParams::ev100, keyed over the day if wanted
    Automatic,  ///< metered from each frame, clamped, adapting over time
};

/// The preset's "exposure" block (parameter table: "exposure.*").
struct ExposureParams {
    ExposureMode mode = ExposureMode::Automatic;
    /// Manual EV100 [EV]; -10..25. Default 15 (a sunny noon).
    double ev100 = 15.0;
    /// Compensation [EV], -10..10, added to the exposure (positive is
    /// brighter) in both modes; key it to set how dusk and night read.
    double compensationEv = 0.0;
    /// Automatic range [EV100]: the meter's EV is clamped to it, so a
    /// starlit night does not become grey day. Default -12..17 (the light
    /// is physical: a full moon's landscape meters ~-3, a moonless one -11
    /// to -13).
    double minEv100 = -12.0;
    double maxEv100 = 17.0;
    /// Automatic adaptation speeds [1/s]: the fraction 1 - exp(-speed dt)
    /// of the gap closes in dt seconds; up when the scene gets brighter.
    double adaptUpPerSecond = 3.0;
    double adaptDownPerSecond = 1.0;
};

/// Where the metered luminance lands before the display transform: the
/// scene-linear middle grey, 18 % (the key). The display shows it as the
/// picture's middle grey (see "Formulas").
inline constexpr double kMiddleGrey = 0.18;
/// The centre weighting of meterAverageLuminance with a frame size: a
/// pixel's weight is kMeterOutsideWeight + exp(-r^2 / (2 R^2)), r its
/// distance in frame heights from the point at the frame's middle column
/// and kMeterCentreHeight of its height from the top, R kMeterCentreRadius.
inline constexpr double kMeterCentreRadius = 0.25;
inline constexpr double kMeterCentreHeight = 0.62;
inline constexpr double kMeterOutsideWeight = 0.1;

/// The band of the metering histogram that counts (quantiles of the weight).
inline constexpr double kMeterLowFraction = 0.10;
inline constexpr double kMeterHighFraction = 0.90;

/// The average luminance [radiance units] of a frame as the automatic
/// exposure meters it: luminance() of every `step`-th pixel (of `channels`
/// floats, RGB first) into a LuminanceHistogram of log2 cd/m^2 over
/// [-16, 16], averaged between kMeterLowFraction and kMeterHighFraction.
/// Non-finite pixels count as black; an empty frame gives 2^-16 cd/m^2.
double meterAverageLuminance(std::span<const float> pixels, int channels, std::size_t step = 1);

/// The same, centre-weighted as a camera meters (kMeterCentreRadius,
/// kMeterOutsideWeight, kMeterCentreHeight) over a frame of width x height
/// pixels stored row by row, the top row first; what the editor and
/// `aerial render` meter with. Falls back to the unweighted meter when the
/// size does not match the pixels.
double meterAverageLuminance(std::span<const float> pixels, int channels, int width, int height,
                             std::size_t step = 1);

/// The EV100 the exposure asks for, before adaptation and compensation:
/// Manual, p.ev100; Automatic, ev100FromAverageLuminance of the average
/// [radiance units] in cd/m^2, clamped to [minEv100, maxEv100].
double targetEv100(const ExposureParams& p, double averageLuminance);

/// What multiplies radiance [units] to give the display transform's
/// scene-linear input, at this EV100 with the preset's compensation:
/// kNitsPerRadianceUnit * exposureScale(ev100 - compensationEv). The
/// metered average lands on kMiddleGrey.
double radianceScale(const ExposureParams& p, double ev100);

}  // namespace aerial
