// evaluate.cpp — a compiled preset: tracks bound once to the fields they
// animate, then the per-frame evaluation (see evaluate.hpp for the steps).
#include <aerial/evaluate.hpp>

#include <aerial/atmosphere.hpp>
#include <aerial/exposure.hpp>
#include <aerial/finite.hpp>
#include <aerial/fog_volume.hpp>
#include <aerial/param_table.hpp>
#include <aerial/weather.hpp>

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>

namespace aerial {
namespace {

// Transmittance to space as a function of the light's zenith cosine, for a
// fixed geometry (radii, viewer height, scale heights, ozone profile): the
// optical depths per unit coefficient of Rayleigh, Mie and ozone, sampled
// with transmittanceToSpace itself (one coefficient per RGB channel). The
// coefficients (the usual animated quantities) are applied per evaluation.
class OpticalDepthTable {
public:
    // 48 samples, cubic in u with mu = muHorizon + (1 - muHorizon) u^3 (dense
    // near the horizon): max |T_table - T_direct| ~1e-4 for Earth-like and
    // hazy atmospheres, viewer at 0 and 2000 m (build cost 48 quadratures).
    static constexpr int kSamples = 48;
    static constexpr double kProbe = 1e-7;  // [1/m]: keeps k * tau << 700

    void build(const AtmosphereParams& air) {
        const double r = air.planetRadius + std::max(air.viewerHeight, 0.0);
        const double ratio = air.planetRadius / r;
        muHorizon_ = -std::sqrt(std::max(0.0, 1.0 - ratio * ratio));
        AtmosphereParams probe = air;
        probe.rayleighScattering = glm::dvec3(kProbe, 0.0, 0.0);
        probe.mieExtinction = glm::dvec3(0.0, kProbe, 0.0);
        probe.ozoneAbsorption = glm::dvec3(0.0, 0.0, kProbe);
        for (int i = 0; i < kSamples; ++i) {
            const double u = double(i) / (kSamples - 1);
            // Exactly at the horizon a downward-grazing ray may count as
            // hitting the ground; start a hair above it.
            const double mu = muHorizon_ + (1.0 - muHorizon_) * std::max(u * u * u, 1e-9);
            const glm::dvec3 t = transmittanceToSpace(probe, air.viewerHeight, mu);
            for (int c = 0; c < 3; ++c) depth_[i + 1][c] = t[c] > 0.0 ? -std::log(t[c]) / kProbe : 0.0;
        }
        // Ghost samples, extrapolated linearly, for the end segments.
        depth_[0] = 2.0 * depth_[1] - depth_[2];
        depth_[kSamples + 1] = 2.0 * depth_[kSamples] - depth_[kSamples - 1];
    }

    glm::dvec3 transmittance(const AtmosphereParams& air, double muZenith) const {
        if (!(muZenith > muHorizon_)) return glm::dvec3(0.0);
        const double u = std::cbrt(std::clamp((muZenith - muHorizon_) / (1.0 - muHorizon_), 0.0, 1.0));
        const double x = u * (kSamples - 1);
        const int i = std::min(int(x), kSamples - 2);
        const double f = x - i;
        // Catmull-Rom through samples i-1 .. i+2 (stored at +1).
        const glm::dvec3& p0 = depth_[i];
        const glm::dvec3& p1 = depth_[i + 1];
        const glm::dvec3& p2 = depth_[i + 2];
        const glm::dvec3& p3 = depth_[i + 3];
        const glm::dvec3 d =
            p1 +
            0.5 * f * (p2 - p0 + f * (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3 + f * (3.0 * (p1 - p2) + p3 - p0)));
        const glm::dvec3 tau =
            glm::max(air.rayleighScattering * d.x + air.mieExtinction * d.y + air.ozoneAbsorption * d.z,
                     glm::dvec3(0.0));
        return glm::dvec3(std::exp(-tau.x), std::exp(-tau.y), std::exp(-tau.z));
    }

private:
    double muHorizon_ = 0.0;
    glm::dvec3 depth_[kSamples + 2] = {};
};

struct Binding {
    const ParamDesc* desc = nullptr;
    ParamScope scope = ParamScope::Global;
    std::size_t object = 0;  // index into volumes / emitters / cloud volumes
    CompiledTrack track;
};

/// One override of one weather state, bound to its field.
struct WeatherBinding {
    const ParamDesc* desc = nullptr;
    ParamScope scope = ParamScope::Global;
    std::size_t object = 0;  // index into volumes / emitters / cloud volumes
    std::size_t state = 0;   // index into Preset::weather
    int category = 0;        // WeatherCategory
    WeatherOverride override_;
};

/// Same field: the same accessor on the same object.
bool sameField(const WeatherBinding& a, const WeatherBinding& b) {
    return a.desc == b.desc && a.scope == b.scope && a.object == b.object;
}

bool tableDependsOn(const ParamDesc& p) {
    return p.scope == ParamScope::Global &&
           (p.path == "atmosphere.viewer_height_m" || p.path == "atmosphere.rayleigh.scale_height_m" ||
            p.path == "atmosphere.mie.scale_height_m" || p.path == "atmosphere.ozone.peak_height_m" ||
            p.path == "atmosphere.ozone.width_m");
}

template <class Object>
std::size_t indexOf(const std::vector<Object>& objects, const std::string& id) {
    for (std::size_t i = 0; i < objects.size(); ++i)
        if (objects[i].id == id) return i;
    return objects.size();
}

}  // namespace

struct CompiledPreset::Impl {
    Preset preset;
    std::vector<PresetIssue> issues;
    std::vector<Binding> bindings;
    /// Grouped by field (sameField bindings adjacent), states in order.
    std::vector<WeatherBinding> weather;
    bool useTable = true;
    OpticalDepthTable table;

    explicit Impl(Preset p) : preset(std::move(p)) {
        resolveKeyAnchors(preset);  // keys that follow the sun, at this location and date
        issues = validatePreset(preset);
        for (std::size_t i = 0; i < preset.tracks.size(); ++i) {
            const Track& track = preset.tracks[i];
            const std::string prefix = "/tracks/" + std::to_string(i);
            const bool broken = std::any_of(issues.begin(), issues.end(), [&](const PresetIssue& e) {
                return e.pointer.compare(0, prefix.size(), prefix) == 0 &&
                       (e.pointer.size() == prefix.size() || e.pointer[prefix.size()] == '/');
            });
            const ParamDesc* desc = findParam(track.target.scope, track.target.param);
            if (broken || !desc || !desc->animatable || track.keys.empty()) continue;
            Binding b;
            b.desc = desc;
            b.scope = track.target.scope;
            if (b.scope == ParamScope::Volume) {
                b.object = indexOf(preset.volumes, track.target.objectId);
                if (b.object >= preset.volumes.size()) continue;
            } else if (b.scope == ParamScope::Emitter) {
                b.object = indexOf(preset.emitters, track.target.objectId);
                if (b.object >= preset.emitters.size()) continue;
            } else if (b.scope == ParamScope::CloudVolume) {
                b.object = indexOf(preset.cloudVolumes, track.target.objectId);
                if (b.object >= preset.cloudVolumes.size()) continue;
            }
            b.track = compileTrack(track, desc->components());
            if (tableDependsOn(*desc)) useTable = false;
            bindings.push_back(std::move(b));
        }
        bindWeather();
        if (useTable) table.build(preset.environment.atmosphere);
    }

    /// The overrides of every weather state, bound like the tracks (an
    /// override validatePreset refused is skipped).
    void bindWeather() {
        for (std::size_t s = 0; s < preset.weather.size(); ++s) {
            for (const WeatherOverride& o : preset.weather[s].overrides) {
                const ParamDesc* desc = findParam(o.target.scope, o.target.param);
                if (!desc || !desc->animatable) continue;
                WeatherBinding b;
                b.desc = desc;
                b.scope = o.target.scope;
                if (b.scope == ParamScope::Volume) b.object = indexOf(preset.volumes, o.target.objectId);
                if (b.scope == ParamScope::Emitter) b.object = indexOf(preset.emitters, o.target.objectId);
                if (b.scope == ParamScope::CloudVolume) b.object = indexOf(preset.cloudVolumes, o.target.objectId);
                if ((b.scope == ParamScope::Volume && b.object >= preset.volumes.size()) ||
                    (b.scope == ParamScope::Emitter && b.object >= preset.emitters.size()) ||
                    (b.scope == ParamScope::CloudVolume && b.object >= preset.cloudVolumes.size()))
                    continue;
                if (!isFinite(o.value)) continue;
                b.state = s;
                b.category = int(weatherCategory(o.target));
                b.override_ = o;
                if (tableDependsOn(*desc)) useTable = false;
                weather.push_back(b);
            }
        }
        std::stable_sort(weather.begin(), weather.end(), [](const WeatherBinding& a, const WeatherBinding& b) {
            if (a.desc != b.desc) return a.desc < b.desc;
            if (a.scope != b.scope) return a.scope < b.scope;
            return a.object < b.object;
        });
    }

    glm::dvec3 transmittance(const AtmosphereParams& air, const glm::dvec3& direction) const {
        return useTable ? table.transmittance(air, direction.y)
                        : transmittanceToSpace(air, air.viewerHeight, direction.y);
    }
};

CompiledPreset::CompiledPreset() : CompiledPreset(defaultPreset()) {}
CompiledPreset::CompiledPreset(Preset preset) : impl_(std::make_unique<Impl>(std::move(preset))) {}
CompiledPreset::~CompiledPreset() = default;
CompiledPreset::CompiledPreset(CompiledPreset&&) noexcept = default;
CompiledPreset& CompiledPreset::operator=(CompiledPreset&&) noexcept = default;

const Preset& CompiledPreset::preset() const { return impl_->preset; }
const std::vector<PresetIssue>& CompiledPreset::issues() const { return impl_->issues; }

void CompiledPreset::evaluate(double timeHours, PresetState& state) const {
    evaluate(timeHours, WeatherMix{}, state);
}

namespace {

void* objectOf(PresetState& state, ParamScope scope, std::size_t index) {
    switch (scope) {
        case ParamScope::Volume: return &state.volumes[index];
        case ParamScope::Emitter: return &state.emitters[index];
        case ParamScope::CloudVolume: return &state.cloudVolumes[index];
        case ParamScope::Global:
        default: return &state.environment;
    }
}

glm::dvec3 readField(const ParamDesc& d, void* object) {
    if (d.type == ParamType::Scalar) return glm::dvec3(*d.scalar(object), 0.0, 0.0);
    if (d.type == ParamType::Vec2) return glm::dvec3(d.vec2(object)->x, d.vec2(object)->y, 0.0);
    return *d.vec3(object);
}

void writeField(const ParamDesc& d, void* object, const glm::dvec3& v) {
    if (d.type == ParamType::Scalar)
        *d.scalar(object) = std::clamp(v.x, d.minValue, d.maxValue);
    else if (d.type == ParamType::Vec2)
        *d.vec2(object) = glm::clamp(glm::dvec2(v.x, v.y), glm::dvec2(d.minValue), glm::dvec2(d.maxValue));
    else
        *d.vec3(object) = glm::clamp(v, glm::dvec3(d.minValue), glm::dvec3(d.maxValue));
}

/// v = k + sum_i W_i,c (o_i(k) - k) for each overridden field (weather.hpp).
void applyWeather(const std::vector<WeatherBinding>& bindings, const WeatherMix& mix, PresetState& state) {
    for (std::size_t begin = 0; begin < bindings.size();) {
        std::size_t end = begin + 1;
        while (end < bindings.size() && sameField(bindings[begin], bindings[end])) ++end;
        const WeatherBinding& first = bindings[begin];
        void* object = objectOf(state, first.scope, first.object);
        const glm::dvec3 keyed = readField(*first.desc, object);
        glm::dvec3 value = keyed;
        bool touched = false;
        for (std::size_t k = begin; k < end; ++k) {
            const WeatherBinding& b = bindings[k];
            if (b.state >= mix.weights.size()) continue;
            const double w = mix.weights[b.state][std::size_t(b.category)];
            if (!(w > 0.0)) continue;
            glm::dvec3 target = weatherOverrideValue(b.override_, keyed);
            if (b.desc->type == ParamType::Scalar) target.y = target.z = 0.0;
            if (b.desc->type == ParamType::Vec2) target.z = 0.0;
            value += std::min(w, 1.0) * (target - keyed);
            touched = true;
        }
        if (touched) writeField(*first.desc, object, value);
        begin = end;
    }
}

}  // namespace

void CompiledPreset::evaluate(double timeHours, const WeatherMix& mix, PresetState& state) const {
    const Impl& impl = *impl_;
    const Preset& preset = impl.preset;
    const double t = wrapHours(timeHours);
    state.timeHours = t;

    // 1. Base values (element-wise copy: no allocation once the shapes match).
    state.environment = preset.environment;
    state.volumes = preset.volumes;
    state.emitters = preset.emitters;
    state.emitterFlash.resize(preset.emitters.size());
    state.cloudVolumes = preset.cloudVolumes;

    // 2. Tracks, written through their pre-bound accessors, clamped to range.
    for (const Binding& b : impl.bindings) {
        void* object = objectOf(state, b.scope, b.object);
        writeField(*b.desc, object, evaluateTrack(b.track, t));
    }
    // 2b. The weather's overrides on top of the keys (weather.hpp).
    if (!mix.weights.empty()) applyWeather(impl.weather, mix, state);
    AtmosphereParams& air = state.environment.atmosphere;
    air.mieExtinction = glm::max(air.mieExtinction, air.mieScattering);

    // 3. Sun and moon.
    const Environment& env = state.environment;
    LightState& sun = state.sunLight;
    sun.body = sunPosition(env.location, t);
    sun.illuminanceSpace = env.sun.illuminance();
    sun.transmittance = impl.transmittance(air, sun.body.direction);
    sun.illuminance = sun.illuminanceSpace * sun.transmittance;
    LightState& moon = state.moonLight;
    moon.body = moonPosition(env.location, t);
    moon.illuminanceSpace = env.moon.illuminance() * moon.body.phaseIrradiance;
    moon.transmittance = impl.transmittance(air, moon.body.direction);
    moon.illuminance = moon.illuminanceSpace * moon.transmittance;
    state.zenithTransmittance = impl.transmittance(air, glm::dvec3(0.0, 1.0, 0.0));

    // 4. Emitters: lightning, the unit-luminance colour, and what the fog
    // where each one stands scatters of it (emitter.hpp, "Photometry").
    for (std::size_t i = 0; i < state.emitters.size(); ++i) {
        Emitter& e = state.emitters[i];
        const double flash = e.kind == EmitterKind::Lightning ? lightningFlash(e, t) : 1.0;
        state.emitterFlash[i] = flash;
        e.intensityCd *= flash;
        e.colour = emitterColour(e);
        const double sigma = fogScatteringAt(state, e.position);
        e.intensity = emitterFogIntensity(e.intensityCd, e.attenuation, sigma);
        e.extinction = sigma;
    }
}

double fogScatteringAt(const PresetState& state, const glm::dvec3& point) {
    if (!withinCoordinateRange(point)) return 0.0;
    bool removed = false;
    double volumes = 0.0;
    for (const FogVolume& v : state.volumes) {
        const double density = fogVolumeDensityAt(v, point);
        if (v.blend == FogVolumeBlend::Subtract) {
            // A subtract volume's density is unused; containment is what counts.
            FogVolume probe = v;
            probe.density = 1.0;
            probe.falloff = 0.0;
            removed = removed || fogVolumeDensityAt(probe, point) > 0.0;
        } else {
            volumes += density;
        }
    }
    const Environment& env = state.environment;
    const HeightFogParams& fog = env.fog;
    double global = 0.0;
    if (std::isfinite(fog.density) && fog.density > 0.0 && std::isfinite(fog.baseHeight)) {
        const double falloff = std::isfinite(fog.falloff) ? std::max(fog.falloff, 0.0) : 0.0;
        global = fog.density * std::exp(std::min(-falloff * (point.y - fog.baseHeight), 700.0));
    }
    const AtmosphereParams& air = env.atmosphere;
    const double altitude = std::max(air.viewerHeight + point.y, 0.0);
    const double atmosphere = luminance(air.rayleighScattering * rayleighDensity(air, altitude) +
                                        air.mieScattering * mieDensity(air, altitude));
    const double fogs = removed ? 0.0 : global + volumes;
    return std::min(fogs + std::max(atmosphere, 0.0), 1.0e30);
}

PresetState CompiledPreset::evaluate(double timeHours) const {
    PresetState state;
    evaluate(timeHours, state);
    return state;
}

PresetState evaluate(const Preset& preset, double timeHours) {
    return CompiledPreset(preset).evaluate(timeHours);
}

CloudField prepareClouds(const PresetState& state) {
    return prepareClouds(state.environment.clouds, state.cloudVolumes, state.timeHours,
                         state.environment.atmosphere.planetRadius);
}

OvercastLight overcastLight(const PresetState& state, const SkyTable& sunSky, const SkyTable& moonSky) {
    OvercastLight out;
    const double g = state.environment.atmosphere.mieAnisotropy;
    // One pass over each table gives both the clear sky's irradiance and the
    // deck's weighting of it below.
    const SkyCosineMoments sunMoments = skyCosineMoments(sunSky, g, state.sunLight.illuminanceSpace);
    const SkyCosineMoments moonMoments = skyCosineMoments(moonSky, g, state.moonLight.illuminanceSpace);
    out.clearSkyIrradiance = sunMoments.first + moonMoments.first;
    out.groundIrradiance = out.clearSkyIrradiance;
    const CloudField clouds = prepareClouds(state);
    out.overcast = cloudOvercast(clouds);
    if (!(out.overcast.skyCover > 0.0) && !(out.overcast.horizonCover > 0.0)) return out;
    // What the deck passes on of each light: a beam at zenith cosine mu gets
    // through as (1/2 + 3/4 mu) times diffuse light does (Eddington; the
    // mean over a diffuse field is 1), so the glow low over a set sun's
    // horizon counts less than the sky overhead.
    auto direct = [](const LightState& l) {
        const double mu = std::clamp(l.body.direction.y, 0.0, 1.0);
        return l.illuminance * mu * (0.5 + 0.75 * mu);
    };
    const glm::dvec3 sky =
        0.5 * (sunMoments.first + moonMoments.first) + 0.75 * (sunMoments.second + moonMoments.second);
    out.radiance = overcastRadiance(out.overcast, clouds.params.albedo,
                                    direct(state.sunLight) + direct(state.moonLight) + sky);
    // A city's light from below, reflected by the deck: albedo (1 - T_d)
    // of lightPollutionUplight (night_sky.hpp).
    const glm::dvec3 uplight = lightPollutionUplight(state.environment.lightPollution, glm::dvec3(0.0, 1.0, 0.0),
                                                     state.environment.location.northOffsetDeg);
    const double reflected = 1.0 - std::clamp(out.overcast.diffuseTransmittance, 0.0, 1.0);
    if (std::isfinite(reflected))
        out.radiance += glm::clamp(clouds.params.albedo, 0.0, 1.0) * reflected * uplight / kPi;
    const double c = out.overcast.skyCover;
    out.groundIrradiance = (1.0 - c) * out.clearSkyIrradiance + c * kPi * out.radiance;
    return out;
}

double fogDirectVisibility(const OvercastLight& overcast) {
    const double c = overcast.overcast.skyCover;
    return std::isfinite(c) ? 1.0 - std::clamp(c, 0.0, 1.0) : 1.0;
}

FogSkyLight fogSkyLight(const PresetState& state, const SkyTable& sunSky, const SkyTable& moonSky,
                        const OvercastLight& overcast) {
    FogSkyLight sky;
    const double clear = fogDirectVisibility(overcast);
    const AtmosphereParams& air = state.environment.atmosphere;
    const double g = std::isnan(air.mieAnisotropy) ? 0.0 : std::clamp(air.mieAnisotropy, -0.999, 0.999);
    glm::dvec3 down = addSkyTableLight(sky, sunSky, g, state.sunLight.illuminanceSpace, clear);
    down += addSkyTableLight(sky, moonSky, g, state.moonLight.illuminanceSpace, clear);
    FogSkyLight night;
    down += clear * addAirglowLight(night, state.zenithTransmittance);
    down += clear * addLightPollutionLight(night, state.environment.lightPollution,
                                           state.environment.location.northOffsetDeg);
    sky.l0 += clear * night.l0;
    for (int k = 0; k < 3; ++k) sky.l1[k] += clear * night.l1[k];
    if (clear < 1.0) down += addUniformSkyLight(sky, (1.0 - clear) * overcast.radiance);
    for (const LightState* l : {&state.sunLight, &state.moonLight}) {
        const double mu = l->body.direction.y;
        if (mu > 0.0 && std::isfinite(mu)) down += clear * std::min(mu, 1.0) * l->illuminance;
    }
    addGroundLight(sky, air.groundAlbedo, down);
    return sky;
}

FogSceneDesc fogSceneDesc(const PresetState& state, const SkyTable& sunSky, const SkyTable& moonSky) {
    // Without clouds the overcast changes nothing (and its sky irradiance is not needed).
    const bool clouds = prepareClouds(state).active();
    return fogSceneDesc(state, sunSky, moonSky,
                        clouds ? overcastLight(state, sunSky, moonSky) : OvercastLight{});
}

FogSceneDesc fogSceneDesc(const PresetState& state, const SkyTable& sunSky, const SkyTable& moonSky,
                          const OvercastLight& overcast) {
    FogSceneDesc desc;
    desc.overcastCover = overcast.overcast.horizonCover;
    desc.overcastRadiance = overcast.radiance;
    desc.heightFog = state.environment.fog;
    desc.heightFogColourMode = state.environment.fogColourMode;
    desc.heightFogColour = state.environment.fogColour;
    desc.volumes = state.volumes;
    desc.emitters = state.emitters;
    desc.mieAnisotropy = state.environment.atmosphere.mieAnisotropy;
    desc.lights[0] = {state.sunLight.body.direction, state.sunLight.illuminanceSpace,
                      sunSky.horizonRayleigh,        sunSky.horizonMie,
                      sunSky.horizonMultiple,        skyHorizonRow(sunSky),
                      state.sunLight.illuminance};
    desc.lights[1] = {state.moonLight.body.direction, state.moonLight.illuminanceSpace,
                      moonSky.horizonRayleigh,        moonSky.horizonMie,
                      moonSky.horizonMultiple,        skyHorizonRow(moonSky),
                      state.moonLight.illuminance};
    desc.skyLight = fogSkyLight(state, sunSky, moonSky, overcast);
    desc.directVisibility = fogDirectVisibility(overcast);
    return desc;
}

}  // namespace aerial
