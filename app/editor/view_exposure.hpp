// editor/view_exposure.hpp — the exposure the viewport shows: the preset's
// (aerial/exposure.hpp, "exposure" block) applied to the frames the
// viewport renders, adapting over real time in automatic mode as a game's
// camera would, plus the View menu's offset.
//
// Usage (once a frame):
//   if (renderedANewFrame) exposure.meter(params, meterAverageLuminance(pixels, 4, 4));
//   const bool moved = exposure.adapt(params, secondsSinceLastFrame);
//   if (renderedANewFrame || moved) display.setExposureEv(exposure.displayEv(params, offsetEv));
#pragma once

#include <aerial/exposure.hpp>

namespace aerial::editor {

class ViewExposure {
public:
    /// A frame was metered: its average luminance [radiance units]
    /// (ignored in manual mode, whose target is the preset's EV100).
    void meter(const ExposureParams& params, double averageLuminance);
    /// Advances the adaptation by `dt` real seconds (at most 0.25 s a call,
    /// so a stalled frame does not jump); manual mode and the first metered
    /// frame jump to the target. True when the EV moved by more than
    /// kVisibleStep, i.e. the picture must be shown again.
    bool adapt(const ExposureParams& params, double dt);
    /// Jumps to the target (a screenshot shows the settled picture).
    void settle();

    bool metered() const;
    /// The EV100 shown now; the target before the first frame.
    double ev100() const;
    double targetEv100() const;
    /// Stops the display transform multiplies by: log2 of
    /// radianceScale(params, ev100()) plus the viewer's offset.
    double displayEv(const ExposureParams& params, double offsetEv) const;

    /// Adaptation steps smaller than this [EV] are not shown (and end it).
    static constexpr double kVisibleStep = 0.002;

private:
    double ev100_ = 0.0;
    double target_ = 0.0;
    bool metered_ = false;
    bool shown_ = false;  ///< ev100_ has been set from a target
};

}  // namespace aerial::editor
