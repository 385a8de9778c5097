// exposure.cpp — physical-camera exposure (aerial/exposure.hpp).
#include <aerial/exposure.hpp>

#include <algorithm>
#include <cmath>

namespace aerial {
namespace {

constexpr double kMeterCalibration = 12.5;  // K, reflected-light meter (ISO 2720)
constexpr double kIsoSpeed = 100.0;         // S, EV100

double positiveOrZero(double x) { return (std::isfinite(x) && x > 0.0) ? x : 0.0; }

}  // namespace

namespace {

/// CIE 1931 XYZ of a linear Rec.709 colour (IEC 61966-2-1).
glm::dvec3 xyzOf(const glm::dvec3& c) {
    return {0.4124564 * c.x + 0.3575761 * c.y + 0.1804375 * c.z,
            0.2126729 * c.x + 0.7151522 * c.y + 0.0721750 * c.z,
            0.0193339 * c.x + 0.1191920 * c.y + 0.9503041 * c.z};
}

/// Larson, Rushmeier and Piatko 1997's scotopic luminance of XYZ.
double scotopic(const glm::dvec3& xyz) {
    if (!(xyz.x > 1e-30 * (xyz.y + xyz.z)) || !(xyz.y > 0.0)) return 0.0;
    return xyz.y * (1.33 * (1.0 + (xyz.y + xyz.z) / xyz.x) - 1.68);
}

}  // namespace

glm::dvec3 nightVisionWhite() {
    constexpr double x = 0.28, y = 0.29;
    const double bigX = x / y, bigZ = (1.0 - x - y) / y;
    const glm::dvec3 rgb{3.2404542 * bigX - 1.5371385 - 0.4985314 * bigZ,
                         -0.9692660 * bigX + 1.8760108 + 0.0415560 * bigZ,
                         0.0556434 * bigX - 0.2040259 + 1.0572252 * bigZ};
    return rgb / luminance(rgb);  // exactly 1 with luminance()'s coefficients
}

glm::dvec3 nightVision(const glm::dvec3& linearRec709, double nitsPerUnit) {
    glm::dvec3 c;
    for (int i = 0; i < 3; ++i) {
        const double v = linearRec709[i];
        c[i] = std::isfinite(v) && v > 0.0 ? std::min(v, 1.0e30) : 0.0;
    }
    const double y = luminance(c);
    const double nits = std::isfinite(nitsPerUnit) && nitsPerUnit > 0.0 ? nitsPerUnit : kNitsPerRadianceUnit;
    const double l = y * nits;
    constexpr double kScotopicNits = 0.005, kPhotopicNits = 5.0;  // CIE 191:2010
    if (!(l < kPhotopicNits)) return c;
    double t = l > kScotopicNits ? std::log10(l / kScotopicNits) / std::log10(kPhotopicNits / kScotopicNits) : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    const double m = 1.0 - t * t * (3.0 - 2.0 * t);
    static const double kD65 = scotopic(xyzOf(glm::dvec3(1.0)));
    const double v = std::min(scotopic(xyzOf(c)) / kD65, 4.0 * y);
    static const glm::dvec3 kWhite = nightVisionWhite();
    return (1.0 - m) * c + m * v * kWhite;
}

double luminance(const glm::dvec3& c) {
    if (std::isnan(c.x) || std::isnan(c.y) || std::isnan(c.z)) return 0.0;
    const auto channel = [](double x) { return x > 0.0 ? std::min(x, 1.0e30) : 0.0; };
    return 0.2126 * channel(c.x) + 0.7152 * channel(c.y) + 0.0722 * channel(c.z);
}

double ev100FromAverageLuminance(double averageLuminance) {
    const double l = std::isnan(averageLuminance) ? 0.0 : averageLuminance;
    const double clamped = std::clamp(l, std::ldexp(1.0, -40), std::ldexp(1.0, 40));
    return std::log2(clamped * kIsoSpeed / kMeterCalibration);
}

double exposureScale(double ev100) {
    const double ev = std::isnan(ev100) ? 0.0 : std::clamp(ev100, -60.0, 60.0);
    // The luminance the meter reads at this EV, L = K 2^EV / S, lands on kMiddleGrey.
    return kMiddleGrey * kIsoSpeed / (kMeterCalibration * std::exp2(ev));
}

double adaptEv100(double currentEv100, double targetEv100, double dt, double speedUp, double speedDown) {
    if (!std::isfinite(targetEv100)) return std::isfinite(currentEv100) ? currentEv100 : 0.0;
    if (!std::isfinite(currentEv100)) return targetEv100;
    if (!(dt > 0.0)) return currentEv100;
    const double speed = targetEv100 > currentEv100 ? speedUp : speedDown;
    if (!(std::isfinite(speed) && speed > 0.0) || !std::isfinite(dt)) return targetEv100;
    // Closed form of d(ev)/dt = speed (target - ev): exact for any dt.
    return targetEv100 + (currentEv100 - targetEv100) * std::exp(-dt * speed);
}

LuminanceHistogram::LuminanceHistogram(double minLog2, double maxLog2) {
    const bool ok = std::isfinite(minLog2) && std::isfinite(maxLog2) && maxLog2 > minLog2;
    minLog2_ = ok ? minLog2 : -16.0;
    maxLog2_ = ok ? maxLog2 : 16.0;
}

void LuminanceHistogram::add(double luminance, double weight) {
    const double w = positiveOrZero(weight);
    if (w == 0.0) return;
    const double l = positiveOrZero(luminance);
    double bin = 0.0;
    if (l > 0.0) {
        const double x = (std::log2(l) - minLog2_) / (maxLog2_ - minLog2_) * double(kBins);
        bin = std::clamp(std::floor(x), 0.0, double(kBins - 1));
    }
    bins_[std::size_t(bin)] += w;
    total_ += w;
}

void LuminanceHistogram::clear() {
    bins_.fill(0.0);
    total_ = 0.0;
}

double LuminanceHistogram::averageLuminance(double lowFraction, double highFraction) const {
    const double width = (maxLog2_ - minLog2_) / double(kBins);
    if (!(total_ > 0.0)) return std::exp2(minLog2_);
    double low = std::isfinite(lowFraction) ? std::clamp(lowFraction, 0.0, 1.0) : 0.0;
    double high = std::isfinite(highFraction) ? std::clamp(highFraction, 0.0, 1.0) : 1.0;
    if (!(high > low)) {
        // An empty band: the quantile at its position.
        high = std::min(low + 1e-9, 1.0);
        low = high - 1e-9;
    }
    const double from = low * total_;
    const double to = high * total_;
    double before = 0.0;  // weight in the bins below this one
    double sumLog = 0.0;
    double sumWeight = 0.0;
    for (std::size_t i = 0; i < kBins; ++i) {
        const double b = bins_[i];
        // The part of this bin's weight inside [from, to].
        const double inside = std::max(0.0, std::min(before + b, to) - std::max(before, from));
        if (inside > 0.0) {
            sumLog += inside * (minLog2_ + (double(i) + 0.5) * width);
            sumWeight += inside;
        }
        before += b;
    }
    return sumWeight > 0.0 ? std::exp2(sumLog / sumWeight) : std::exp2(minLog2_);
}

double meterAverageLuminance(std::span<const float> pixels, int channels, std::size_t step) {
    LuminanceHistogram histogram;
    if (channels >= 3) {
        const std::size_t stride = std::size_t(channels) * std::max<std::size_t>(step, 1);
        for (std::size_t i = 0; i + 2 < pixels.size(); i += stride) {
            histogram.add(luminance({pixels[i], pixels[i + 1], pixels[i + 2]}) * kNitsPerRadianceUnit);
        }
    }
    return histogram.averageLuminance(kMeterLowFraction, kMeterHighFraction) / kNitsPerRadianceUnit;
}

double meterAverageLuminance(std::span<const float> pixels, int channels, int width, int height,
                             std::size_t step) {
    LuminanceHistogram histogram;
    const std::size_t w = width > 0 ? std::size_t(width) : 0;
    const std::size_t h = height > 0 ? std::size_t(height) : 0;
    if (channels < 3 || w == 0 || h == 0 || pixels.size() < w * h * std::size_t(channels))
        return meterAverageLuminance(pixels, channels, step);
    const std::size_t s = std::max<std::size_t>(step, 1);
    const double scale = 1.0 / double(h);  // distances in frame heights, so any aspect meters alike
    const double spread = 2.0 * kMeterCentreRadius * kMeterCentreRadius;
    for (std::size_t y = 0; y < h; y += s) {
        const double dy = (double(y) + 0.5 - kMeterCentreHeight * double(h)) * scale;
        for (std::size_t x = 0; x < w; x += s) {
            const double dx = (double(x) + 0.5 - 0.5 * double(w)) * scale;
            const double weight = kMeterOutsideWeight + std::exp(-(dx * dx + dy * dy) / spread);
            const float* p = pixels.data() + (y * w + x) * std::size_t(channels);
            histogram.add(luminance({p[0], p[1], p[2]}) * kNitsPerRadianceUnit, weight);
        }
    }
    return histogram.averageLuminance(kMeterLowFraction, kMeterHighFraction) / kNitsPerRadianceUnit;
}

double targetEv100(const ExposureParams& p, double averageLuminance) {
    if (p.mode == ExposureMode::Manual) return std::isfinite(p.ev100) ? p.ev100 : 0.0;
    const double metered = ev100FromAverageLuminance(averageLuminance * kNitsPerRadianceUnit);
    double lo = std::isfinite(p.minEv100) ? p.minEv100 : -60.0;
    double hi = std::isfinite(p.maxEv100) ? p.maxEv100 : 60.0;
    if (lo > hi) std::swap(lo, hi);
    return std::clamp(metered, lo, hi);
}

double radianceScale(const ExposureParams& p, double ev100) {
    const double compensation = std::isfinite(p.compensationEv) ? p.compensationEv : 0.0;
    return kNitsPerRadianceUnit * exposureScale(ev100 - compensation);
}

}  // namespace aerial
