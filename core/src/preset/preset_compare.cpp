// preset_compare.cpp — presetsIdentical: two presets compared value by
// value through the parameter table (bit for bit on every number), plus
// their tracks, weather states, weather regions and view.
#include <aerial/param_table.hpp>
#include <aerial/preset.hpp>

#include <cstring>

namespace aerial {

namespace {

/// Bit for bit, as the key's other numbers.
bool sameTangents(const std::optional<KeyTangents>& a, const std::optional<KeyTangents>& b) {
    if (!a || !b) return !a && !b;
    const double u[6] = {a->in.x, a->in.y, a->in.z, a->out.x, a->out.y, a->out.z};
    const double v[6] = {b->in.x, b->in.y, b->in.z, b->out.x, b->out.y, b->out.z};
    return std::memcmp(u, v, sizeof u) == 0 && a->mode == b->mode;
}

}  // namespace

bool presetsIdentical(const Preset& constA, const Preset& constB) {
    Preset& a = const_cast<Preset&>(constA);
    Preset& b = const_cast<Preset&>(constB);
    auto same = [](const ParamDesc& p, void* x, void* y) {
        if (p.type == ParamType::String) return *p.string(x) == *p.string(y);
        double u[4], v[4];
        switch (p.scope) {
            case ParamScope::Global:
                readParam(p, *static_cast<Environment*>(x), u);
                readParam(p, *static_cast<Environment*>(y), v);
                break;
            case ParamScope::Volume:
                readParam(p, *static_cast<FogVolume*>(x), u);
                readParam(p, *static_cast<FogVolume*>(y), v);
                break;
            case ParamScope::Emitter:
                readParam(p, *static_cast<Emitter*>(x), u);
                readParam(p, *static_cast<Emitter*>(y), v);
                break;
            case ParamScope::CloudVolume:
                readParam(p, *static_cast<CloudVolume*>(x), u);
                readParam(p, *static_cast<CloudVolume*>(y), v);
                break;
        }
        return std::memcmp(u, v, sizeof u) == 0;
    };
    if (a.name != b.name || a.description != b.description) return false;
    for (const ParamDesc& p : paramTable(ParamScope::Global))
        if (!same(p, &a.environment, &b.environment)) return false;
    if (a.volumes.size() != b.volumes.size() || a.emitters.size() != b.emitters.size() ||
        a.cloudVolumes.size() != b.cloudVolumes.size() || a.tracks.size() != b.tracks.size())
        return false;
    for (std::size_t i = 0; i < a.volumes.size(); ++i)
        for (const ParamDesc& p : paramTable(ParamScope::Volume))
            if (!same(p, &a.volumes[i], &b.volumes[i])) return false;
    for (std::size_t i = 0; i < a.emitters.size(); ++i)
        for (const ParamDesc& p : paramTable(ParamScope::Emitter))
            if (!same(p, &a.emitters[i], &b.emitters[i])) return false;
    for (std::size_t i = 0; i < a.cloudVolumes.size(); ++i)
        for (const ParamDesc& p : paramTable(ParamScope::CloudVolume))
            if (!same(p, &a.cloudVolumes[i], &b.cloudVolumes[i])) return false;
    for (std::size_t i = 0; i < a.tracks.size(); ++i) {
        const Track& s = a.tracks[i];
        const Track& t = b.tracks[i];
        if (!(s.target == t.target) || s.interpolation != t.interpolation || s.wrap != t.wrap ||
            s.keys.size() != t.keys.size())
            return false;
        for (std::size_t k = 0; k < s.keys.size(); ++k) {
            const double u[5] = {s.keys[k].timeHours, s.keys[k].value.x, s.keys[k].value.y, s.keys[k].value.z,
                                 s.keys[k].offsetHours};
            const double v[5] = {t.keys[k].timeHours, t.keys[k].value.x, t.keys[k].value.y, t.keys[k].value.z,
                                 t.keys[k].offsetHours};
            if (std::memcmp(u, v, sizeof u) != 0 || s.keys[k].flat != t.keys[k].flat ||
                s.keys[k].anchor != t.keys[k].anchor || s.keys[k].interpolation != t.keys[k].interpolation ||
                !sameTangents(s.keys[k].tangents, t.keys[k].tangents))
                return false;
        }
    }
    if (a.weather.size() != b.weather.size()) return false;
    for (std::size_t i = 0; i < a.weather.size(); ++i) {
        const WeatherState& s = a.weather[i];
        const WeatherState& t = b.weather[i];
        if (s.name != t.name || s.overrides.size() != t.overrides.size()) return false;
        for (std::size_t k = 0; k < s.overrides.size(); ++k) {
            const WeatherOverride& o = s.overrides[k];
            const WeatherOverride& q = t.overrides[k];
            const double u[3] = {o.value.x, o.value.y, o.value.z}, v[3] = {q.value.x, q.value.y, q.value.z};
            if (!(o.target == q.target) || o.mode != q.mode || std::memcmp(u, v, sizeof u) != 0) return false;
        }
    }
    if (a.weatherRegions.size() != b.weatherRegions.size()) return false;
    for (std::size_t i = 0; i < a.weatherRegions.size(); ++i) {
        const WeatherRegion& r = a.weatherRegions[i];
        const WeatherRegion& s = b.weatherRegions[i];
        const double u[12] = {r.position.x,    r.position.y,    r.position.z, r.rotation.x,
                              r.rotation.y,    r.rotation.z,    r.rotation.w, r.halfExtents.x,
                              r.halfExtents.y, r.halfExtents.z, r.blend,      double(r.priority)};
        const double v[12] = {s.position.x,    s.position.y,    s.position.z, s.rotation.x,
                              s.rotation.y,    s.rotation.z,    s.rotation.w, s.halfExtents.x,
                              s.halfExtents.y, s.halfExtents.z, s.blend,      double(s.priority)};
        if (r.id != s.id || r.name != s.name || r.shape != s.shape || r.state != s.state ||
            std::memcmp(u, v, sizeof u) != 0)
            return false;
    }
    if (a.view.has_value() != b.view.has_value()) return false;
    if (a.view) {
        const PresetView& v = *a.view;
        const PresetView& w = *b.view;
        const double u[7] = {v.eye.x, v.eye.y, v.eye.z, v.target.x, v.target.y, v.target.z, v.verticalFovDeg};
        const double x[7] = {w.eye.x, w.eye.y, w.eye.z, w.target.x, w.target.y, w.target.z, w.verticalFovDeg};
        if (std::memcmp(u, x, sizeof u) != 0) return false;
    }
    return true;
}

}  // namespace aerial
