// editor/view_exposure.cpp — see view_exposure.hpp.
#include "view_exposure.hpp"

#include <algorithm>
#include <cmath>

namespace aerial::editor {

void ViewExposure::meter(const ExposureParams& params, double averageLuminance) {
    target_ = aerial::targetEv100(params, averageLuminance);
    metered_ = true;
}

bool ViewExposure::adapt(const ExposureParams& params, double dt) {
    if (!metered_) return false;
    const double before = ev100_;
    if (!shown_ || params.mode == ExposureMode::Manual) {
        ev100_ = target_;
        shown_ = true;
        return true;
    }
    const double step = std::isfinite(dt) ? std::clamp(dt, 0.0, 0.25) : 0.0;
    ev100_ = adaptEv100(ev100_, target_, step, params.adaptUpPerSecond, params.adaptDownPerSecond);
    if (std::fabs(ev100_ - target_) < kVisibleStep) ev100_ = target_;
    return std::fabs(ev100_ - before) >= kVisibleStep || (ev100_ == target_ && before != target_);
}

void ViewExposure::settle() {
    if (!metered_) return;
    ev100_ = target_;
    shown_ = true;
}

bool ViewExposure::metered() const { return metered_; }
double ViewExposure::ev100() const { return shown_ ? ev100_ : target_; }
double ViewExposure::targetEv100() const { return target_; }

double ViewExposure::displayEv(const ExposureParams& params, double offsetEv) const {
    const double offset = std::isfinite(offsetEv) ? offsetEv : 0.0;
    return std::log2(radianceScale(params, ev100())) + offset;
}

}  // namespace aerial::editor
