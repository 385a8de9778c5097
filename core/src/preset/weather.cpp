// weather.cpp — weather categories, mixes, transitions and the blend of two
// presets' states (aerial/weather.hpp).
#include <aerial/weather.hpp>

#include <aerial/param_table.hpp>

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>

namespace aerial {
namespace {

bool startsWith(std::string_view text, std::string_view prefix) {
    return text.substr(0, prefix.size()) == prefix;
}

/// Index of a state by name; -1 for "none" (the keyed values); -2 when unknown.
int stateIndex(const std::vector<std::string>& names, std::string_view name) {
    if (name.empty() || name == "none") return -1;
    for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i] == name) return int(i);
    return -2;
}

std::vector<std::string> stateNames(const Preset& preset) {
    std::vector<std::string> names;
    names.reserve(preset.weather.size());
    for (const WeatherState& s : preset.weather) names.push_back(s.name);
    return names;
}

/// The mix of one state held fully (-1: none).
void setSettled(std::size_t count, int index, WeatherMix& mix) {
    mix.weights.assign(count, std::array<double, kWeatherCategoryCount>{});
    if (index >= 0) mix.weights[std::size_t(index)].fill(1.0);
}

/// mix <- (1 - w_c) mix + w_c e_to, per category, for a fraction of a transition.
void blendTowards(int to, double fraction, WeatherMix& mix) {
    for (int c = 0; c < kWeatherCategoryCount; ++c) {
        const double w = weatherTransitionWeight(WeatherCategory(c), fraction);
        for (std::size_t i = 0; i < mix.weights.size(); ++i)
            mix.weights[i][std::size_t(c)] =
                (1.0 - w) * mix.weights[i][std::size_t(c)] + (int(i) == to ? w : 0.0);
    }
}

double fractionOf(const WeatherChange& change, double nowSeconds) {
    if (!(change.durationSeconds > 0.0)) return nowSeconds >= change.startSeconds ? 1.0 : 0.0;
    return std::clamp((nowSeconds - change.startSeconds) / change.durationSeconds, 0.0, 1.0);
}

}  // namespace

glm::dvec3 weatherOverrideValue(const WeatherOverride& o, const glm::dvec3& keyed) {
    switch (o.mode) {
        case WeatherOverrideMode::Add: return keyed + o.value;
        case WeatherOverrideMode::Scale: return keyed * o.value;
        case WeatherOverrideMode::Set:
        default: return o.value;
    }
}

WeatherCategory weatherCategory(const TrackTarget& target) {
    switch (target.scope) {
        case ParamScope::Volume: return WeatherCategory::Fog;
        case ParamScope::Emitter: return WeatherCategory::Lightning;
        case ParamScope::CloudVolume: return WeatherCategory::Clouds;
        case ParamScope::Global: break;
    }
    const std::string_view p = target.param;
    if (p == "clouds.wind_m_per_s") return WeatherCategory::Wind;
    if (startsWith(p, "clouds.")) return WeatherCategory::Clouds;
    if (startsWith(p, "fog.")) return WeatherCategory::Fog;
    if (startsWith(p, "atmosphere.")) return WeatherCategory::Haze;
    if (startsWith(p, "exposure.") || startsWith(p, "sun.") || startsWith(p, "moon.") || startsWith(p, "night."))
        return WeatherCategory::Light;
    return WeatherCategory::Other;
}

const char* weatherCategoryName(WeatherCategory category) {
    switch (category) {
        case WeatherCategory::Clouds: return "clouds";
        case WeatherCategory::Fog: return "fog";
        case WeatherCategory::Wind: return "wind";
        case WeatherCategory::Haze: return "haze";
        case WeatherCategory::Light: return "light";
        case WeatherCategory::Lightning: return "lightning";
        case WeatherCategory::Other:
        default: return "other";
    }
}

double weatherTransitionWeight(WeatherCategory category, double fraction) {
    if (std::isnan(fraction)) return 0.0;
    const double share = kWeatherCategoryShare[std::clamp(int(category), 0, kWeatherCategoryCount - 1)];
    const double x = std::clamp(fraction / share, 0.0, 1.0);
    return x * x * (3.0 - 2.0 * x);
}

bool settledWeather(const Preset& preset, std::string_view name, WeatherMix& mix) {
    const int index = stateIndex(stateNames(preset), name);
    if (index < -1) {
        mix.weights.clear();
        return false;
    }
    setSettled(preset.weather.size(), index, mix);
    return true;
}

bool transitionWeather(const Preset& preset, std::string_view from, std::string_view to, double fraction,
                       WeatherMix& mix) {
    const std::vector<std::string> names = stateNames(preset);
    const int a = stateIndex(names, from), b = stateIndex(names, to);
    if (a < -1 || b < -1) {
        mix.weights.clear();
        return false;
    }
    setSettled(names.size(), a, mix);
    blendTowards(b, std::clamp(std::isnan(fraction) ? 0.0 : fraction, 0.0, 1.0), mix);
    return true;
}

Weather::Weather(const Preset& preset, std::string_view initial) : names_(stateNames(preset)) {
    initial_ = stateIndex(names_, initial) >= 0 ? std::string(initial) : std::string("none");
}

int Weather::indexOf(std::string_view name) const { return stateIndex(names_, name); }

bool Weather::change(std::string_view state, double durationSeconds, double nowSeconds) {
    if (indexOf(state) < -1 || !std::isfinite(durationSeconds) || durationSeconds < 0.0 ||
        !std::isfinite(nowSeconds))
        return false;
    if (!changes_.empty() && nowSeconds < changes_.back().startSeconds) return false;
    foldFinished(nowSeconds);
    changes_.push_back({std::string(state.empty() ? "none" : state), nowSeconds, durationSeconds});
    return true;
}

void Weather::foldFinished(double nowSeconds) {
    // A change that had ended by now leaves nothing of what came before it:
    // it and everything earlier fold into the initial state.
    // Only a change that had ended before the next one started: the next
    // began from its state alone.
    for (std::size_t k = changes_.size(); k-- > 0;) {
        const double until = k + 1 < changes_.size() ? changes_[k + 1].startSeconds : nowSeconds;
        if (fractionOf(changes_[k], until) >= 1.0) {
            initial_ = changes_[k].state;
            changes_.erase(changes_.begin(), changes_.begin() + std::ptrdiff_t(k + 1));
            return;
        }
    }
}

void Weather::mix(double nowSeconds, WeatherMix& mix) const {
    // m_k(t) = (1 - w_k(t)) m_{k-1}(start_k) + w_k(t) e_{state_k}: each change
    // starts from the mix of the moment it was called.
    setSettled(names_.size(), indexOf(initial_), mix);
    for (std::size_t k = 0; k < changes_.size(); ++k) {
        const WeatherChange& c = changes_[k];
        const double until = k + 1 < changes_.size() ? std::min(nowSeconds, changes_[k + 1].startSeconds) : nowSeconds;
        blendTowards(indexOf(c.state), fractionOf(c, until), mix);
    }
}

bool Weather::transitioning(double nowSeconds) const {
    return !changes_.empty() && fractionOf(changes_.back(), nowSeconds) < 1.0;
}

const std::string& Weather::target() const { return changes_.empty() ? initial_ : changes_.back().state; }

void blendPresetStates(const PresetState& a, const PresetState& b, double t, PresetState& out) {
    const double u = std::clamp(std::isnan(t) ? 0.0 : t, 0.0, 1.0);
    out = u < 1.0 ? a : b;
    out.timeHours = a.timeHours;
    // Every animatable global parameter, linearly.
    for (const ParamDesc& d : paramTable(ParamScope::Global)) {
        if (!d.animatable) continue;
        void* o = &out.environment;
        void* pa = const_cast<Environment*>(&a.environment);
        void* pb = const_cast<Environment*>(&b.environment);
        if (d.type == ParamType::Scalar)
            *d.scalar(o) = (1.0 - u) * *d.scalar(pa) + u * *d.scalar(pb);
        else if (d.type == ParamType::Vec2)
            *d.vec2(o) = (1.0 - u) * *d.vec2(pa) + u * *d.vec2(pb);
        else if (d.type == ParamType::Colour || d.type == ParamType::Vec3)
            *d.vec3(o) = (1.0 - u) * *d.vec3(pa) + u * *d.vec3(pb);
    }
    const auto lerpLight = [u](const LightState& x, const LightState& y, LightState& z) {
        z.illuminanceSpace = (1.0 - u) * x.illuminanceSpace + u * y.illuminanceSpace;
        z.transmittance = (1.0 - u) * x.transmittance + u * y.transmittance;
        z.illuminance = (1.0 - u) * x.illuminance + u * y.illuminance;
    };
    lerpLight(a.sunLight, b.sunLight, out.sunLight);
    lerpLight(a.moonLight, b.moonLight, out.moonLight);
    out.zenithTransmittance = (1.0 - u) * a.zenithTransmittance + u * b.zenithTransmittance;
    // Both sides' volumes and emitters, each faded by its side's weight.
    out.volumes.clear();
    for (const FogVolume& v : a.volumes) {
        out.volumes.push_back(v);
        out.volumes.back().density *= 1.0 - u;
    }
    for (const FogVolume& v : b.volumes) {
        out.volumes.push_back(v);
        out.volumes.back().density *= u;
    }
    out.emitters.clear();
    out.emitterFlash.clear();
    for (std::size_t i = 0; i < a.emitters.size(); ++i) {
        out.emitters.push_back(a.emitters[i]);
        out.emitters.back().intensityCd *= 1.0 - u;
        out.emitters.back().intensity *= 1.0 - u;
        out.emitterFlash.push_back(i < a.emitterFlash.size() ? a.emitterFlash[i] : 1.0);
    }
    for (std::size_t i = 0; i < b.emitters.size(); ++i) {
        out.emitters.push_back(b.emitters[i]);
        out.emitters.back().intensityCd *= u;
        out.emitters.back().intensity *= u;
        out.emitterFlash.push_back(i < b.emitterFlash.size() ? b.emitterFlash[i] : 1.0);
    }
    // Cloud volumes: each pulled towards the blended layer's coverage by
    // the other side's weight, so none appears or vanishes at once.
    out.cloudVolumes.clear();
    const double coverage = out.environment.clouds.coverage;
    for (const CloudVolume& v : a.cloudVolumes) {
        out.cloudVolumes.push_back(v);
        out.cloudVolumes.back().coverage = (1.0 - u) * v.coverage + u * coverage;
    }
    for (const CloudVolume& v : b.cloudVolumes) {
        out.cloudVolumes.push_back(v);
        out.cloudVolumes.back().coverage = u * v.coverage + (1.0 - u) * coverage;
    }
}

}  // namespace aerial
