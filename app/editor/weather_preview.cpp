// editor/weather_preview.cpp — the viewport's weather preview (see weather_preview.hpp).
#include "weather_preview.hpp"

#include "action_args.hpp"
#include "weather_edit.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace aerial::editor {

void WeatherPreview::showNone() {
    mode_ = Mode::None;
    playing_ = false;
    weather_.reset();
}

bool WeatherPreview::showState(const Preset& preset, const std::string& name, std::string& error) {
    if (name == "none" || name.empty()) {
        showNone();
        return true;
    }
    if (weatherStateIndex(preset, name) < 0) {
        error = "no weather state \"" + name + "\"";
        return false;
    }
    showNone();
    mode_ = Mode::State;
    state_ = name;
    return true;
}

bool WeatherPreview::showTransition(const Preset& preset, const std::string& from, const std::string& to,
                                    double fraction, std::string& error) {
    for (const std::string& name : {from, to})
        if (name != "none" && weatherStateIndex(preset, name) < 0) {
            error = "no weather state \"" + name + "\"";
            return false;
        }
    if (!std::isfinite(fraction)) {
        error = "the fraction must be a number from 0 to 1";
        return false;
    }
    showNone();
    mode_ = Mode::Transition;
    from_ = from;
    to_ = to;
    fraction_ = std::clamp(fraction, 0.0, 1.0);
    return true;
}

bool WeatherPreview::play(const Preset& preset, const std::string& from, const std::string& to,
                          double seconds, double nowSeconds, std::string& error) {
    if (!(seconds > 0.0) || !std::isfinite(seconds)) {
        error = "a transition lasts more than 0 seconds";
        return false;
    }
    if (!showTransition(preset, from, to, 0.0, error)) return false;
    weather_.emplace(preset, from);
    playNames_.clear();
    for (const WeatherState& state : preset.weather) playNames_.push_back(state.name);
    weather_->change(to, seconds, nowSeconds);
    playStart_ = nowSeconds;
    playSeconds_ = seconds;
    playing_ = true;
    return true;
}

void WeatherPreview::stop() {
    playing_ = false;
    weather_.reset();
}

bool WeatherPreview::update(const Preset& preset, double nowSeconds, const glm::dvec3* camera) {
    // A state the preview names went (removed, renamed): the keyed values.
    const auto known = [&](const std::string& name) {
        return name == "none" || weatherStateIndex(preset, name) >= 0;
    };
    if ((mode_ == Mode::State && !known(state_)) ||
        (mode_ == Mode::Transition && (!known(from_) || !known(to_))))
        showNone();
    WeatherMix next;
    if (playing_) {
        fraction_ = std::clamp((nowSeconds - playStart_) / playSeconds_, 0.0, 1.0);
        // Weather keeps the state names it was made with: while they are the preset's, its mix is exact.
        const bool sameNames =
            weather_ &&
            std::equal(playNames_.begin(), playNames_.end(), preset.weather.begin(), preset.weather.end(),
                       [](const std::string& n, const WeatherState& s) { return n == s.name; });
        if (sameNames)
            weather_->mix(nowSeconds, next);
        else
            transitionWeather(preset, from_, to_, fraction_, next);
        if (fraction_ >= 1.0) stop();
    } else if (mode_ == Mode::State) {
        settledWeather(preset, state_, next);
    } else if (mode_ == Mode::Transition) {
        transitionWeather(preset, from_, to_, fraction_, next);
    }
    regionsShown_.clear();
    if (regionsAtCamera_ && camera) {
        regionalWeather(preset, *camera, next, next);
        for (const WeatherRegion& r : preset.weatherRegions) {
            const double w = weatherRegionWeight(r, *camera);
            if (!(w > 0.0)) continue;
            char weight[32];
            std::snprintf(weight, sizeof weight, " %.2f", w);
            regionsShown_ += (regionsShown_.empty() ? "" : ", ") + r.id + weight;
        }
    }
    if (next.weights == mix_.weights) return false;
    mix_ = std::move(next);
    ++revision_;
    return true;
}

std::string WeatherPreview::describe() const {
    std::string text = "none";
    if (mode_ == Mode::State) text = state_;
    if (mode_ == Mode::Transition) {
        char fraction[32];
        std::snprintf(fraction, sizeof fraction, "%.2f", fraction_);
        text = from_ + " -> " + to_ + " " + fraction + (playing_ ? " (playing)" : "");
    }
    return regionsShown_.empty() ? text : text + " + regions " + regionsShown_;
}

bool parseWeatherPreview(const Preset& preset, const std::string& text, WeatherPreview& preview,
                         std::string& error) {
    const std::size_t first = text.find(':');
    if (first == std::string::npos) return preview.showState(preset, text, error);
    const std::size_t second = text.find(':', first + 1);
    double fraction = 0.0;
    if (second == std::string::npos || !toNumber(text.substr(second + 1), fraction)) {
        error = "\"" + text + "\" is not none, a state or FROM:TO:FRACTION";
        return false;
    }
    return preview.showTransition(preset, text.substr(0, first), text.substr(first + 1, second - first - 1),
                                  fraction, error);
}

}  // namespace aerial::editor
