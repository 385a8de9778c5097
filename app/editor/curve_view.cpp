// editor/curve_view.cpp — see curve_view.hpp.
#include "curve_view.hpp"

#include <aerial/clock.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <set>
#include <utility>

namespace aerial::editor {
namespace {

constexpr double kViewLo = -kViewMarginHours, kViewHi = 24.0 + kViewMarginHours;

TimeView keptInside(double start, double span) {
    span = std::clamp(span, kMinViewSpanHours, kMaxViewSpanHours);
    start = std::clamp(start, kViewLo, kViewHi - span);
    return {start, start + span};
}

}  // namespace

TimeView zoomView(const TimeView& view, double anchorHours, double factor) {
    if (!(factor > 0.0) || !std::isfinite(factor) || !std::isfinite(anchorHours)) return view;
    const double span = std::clamp(view.span() / factor, kMinViewSpanHours, kMaxViewSpanHours);
    // The anchor keeps its place: its fraction of the span is the same before and after.
    const double f = (anchorHours - view.startHours) / view.span();
    return keptInside(anchorHours - f * span, span);
}

TimeView panView(const TimeView& view, double deltaHours) {
    if (!std::isfinite(deltaHours)) return view;
    return keptInside(view.startHours + deltaHours, view.span());
}

double tickStepHours(const TimeView& view, double widthPx, double minSpacingPx) {
    constexpr double kSteps[] = {5.0 / 60.0, 0.25, 0.5, 1.0, 3.0, 6.0};
    const double pxPerHour = widthPx / view.span();
    for (double step : kSteps)
        if (step * pxPerHour >= minSpacingPx) return step;
    return kSteps[std::size(kSteps) - 1];
}

CurveRange paddedRange(double lo, double hi, const ParamDesc& desc) {
    if (!(hi > lo)) {
        const double pad = std::max({std::abs(hi) * 0.1, (desc.uiMax - desc.uiMin) * 0.05, 1e-6});
        return {lo - pad, hi + pad};
    }
    const double pad = (hi - lo) * kCurveRangePad;
    return {lo - pad, hi + pad};
}

namespace {

/// The smallest and largest value of a track's keys over the parameter's
/// components (0, 0 without keys).
void keyValueSpan(const Track& track, const ParamDesc& desc, double& lo, double& hi) {
    const int components = std::clamp(desc.components(), 1, 3);
    lo = 1e300, hi = -1e300;
    for (const TrackKey& k : track.keys)
        for (int c = 0; c < components; ++c) {
            lo = std::min(lo, k.value[c]);
            hi = std::max(hi, k.value[c]);
        }
    if (track.keys.empty()) lo = hi = 0.0;
}

}  // namespace

CurveRange curveRangeOf(const Track& track, const ParamDesc& desc) {
    double lo, hi;
    keyValueSpan(track, desc, lo, hi);
    return paddedRange(lo, hi, desc);
}

std::optional<ParamRef> paramRefOf(const Preset& preset, const TrackTarget& target) {
    const ParamDesc* desc = findParam(target.scope, target.param);
    if (!desc) return std::nullopt;
    if (target.scope == ParamScope::Global) return ParamRef{desc, -1};
    for (std::size_t i = 0; i < objectCount(preset, target.scope); ++i) {
        const ParamRef ref{desc, int(i)};
        if (trackTargetOf(preset, ref) == target) return ref;
    }
    return std::nullopt;
}

std::string curveKey(const TrackTarget& target) {
    if (target.scope == ParamScope::Global) return target.param;
    return std::string(scopeKey(target.scope)) + ":" + target.objectId + ":" + target.param;
}

std::optional<TrackTarget> curveTargetOf(std::string_view key) {
    const std::size_t first = key.find(':');
    if (first == std::string_view::npos) {
        if (!findParam(ParamScope::Global, key)) return std::nullopt;
        return TrackTarget::global(std::string(key));
    }
    const std::size_t second = key.find(':', first + 1);
    if (second == std::string_view::npos) return std::nullopt;
    const std::string_view scope = key.substr(0, first), id = key.substr(first + 1, second - first - 1),
                           param = key.substr(second + 1);
    for (ParamScope s : {ParamScope::Volume, ParamScope::Emitter, ParamScope::CloudVolume})
        if (scopeKey(s) == scope && !id.empty() && findParam(s, param))
            return TrackTarget{s, std::string(id), std::string(param)};
    return std::nullopt;
}

std::string curveLabel(const Preset& preset, const TrackTarget& target) {
    const std::optional<ParamRef> ref = paramRefOf(preset, target);
    if (!ref) return curveKey(target);
    std::string label(ref->desc->label);
    if (target.scope == ParamScope::Global) return label;
    const std::size_t i = std::size_t(ref->object);
    std::string name;
    switch (target.scope) {
        case ParamScope::Volume:
            name = preset.volumes[i].name;
            break;
        case ParamScope::Emitter:
            name = preset.emitters[i].name;
            break;
        case ParamScope::CloudVolume:
            name = preset.cloudVolumes[i].name;
            break;
        case ParamScope::Global:
            break;
    }
    if (name.empty()) name = target.objectId;
    // "Density" after a name reads "Haze bank density"; an acronym ("RGB") keeps its capitals.
    if (label.size() >= 2 && std::isupper(static_cast<unsigned char>(label[0])) &&
        std::islower(static_cast<unsigned char>(label[1])))
        label[0] = char(std::tolower(static_cast<unsigned char>(label[0])));
    return name + " " + label;
}

int curvePaletteIndex(const TrackTarget& target, int paletteSize) {
    if (paletteSize <= 1) return 0;
    std::uint32_t hash = 2166136261u;  // FNV-1a, 32 bits: the same on every machine
    for (const char c : curveKey(target)) {
        hash ^= std::uint32_t(static_cast<unsigned char>(c));
        hash *= 16777619u;
    }
    return int(hash % std::uint32_t(paletteSize));
}

std::vector<int> curvePaletteIndices(const std::vector<TrackTarget>& curves, int paletteSize) {
    std::vector<int> indices;
    indices.reserve(curves.size());
    std::vector<bool> used(std::size_t(std::max(paletteSize, 1)), false);
    int free = int(used.size());
    for (const TrackTarget& target : curves) {
        int index = curvePaletteIndex(target, paletteSize);
        if (free > 0) {  // probe to the next free entry; past a full palette, the curve's own
            while (used[std::size_t(index)]) index = (index + 1) % int(used.size());
            used[std::size_t(index)] = true;
            --free;
        }
        indices.push_back(index);
    }
    return indices;
}

std::vector<double> valueTicks(const CurveRange& range, int maxTicks) {
    std::vector<double> ticks;
    const double span = range.hi - range.lo;
    if (maxTicks < 1 || !std::isfinite(range.lo) || !std::isfinite(range.hi) || !(span > 0.0)) return ticks;
    const double decade = std::pow(10.0, std::floor(std::log10(span / maxTicks)));
    for (const double multiple : {1.0, 2.0, 5.0, 10.0, 20.0}) {
        const double step = multiple * decade;
        const double first = std::ceil(range.lo / step), last = std::floor(range.hi / step);
        if (last - first + 1.0 > maxTicks) continue;
        for (double n = first; n <= last; n += 1.0) ticks.push_back(std::abs(n) < 0.5 ? 0.0 : n * step);
        break;
    }
    return ticks;
}

std::string valueWithUnit(double value, std::string_view unit, int digits) {
    if (value == 0.0) value = 0.0;  // no "-0"
    char text[48];
    std::snprintf(text, sizeof text, "%.*g", std::clamp(digits, 1, 17), value);
    std::string out = text;
    if (!unit.empty()) out.append(" ").append(unit);
    return out;
}

int hitTestPoints(const std::vector<glm::dvec2>& points, glm::dvec2 mouse, double radiusPx) {
    return pickCurvePoint(points, {}, mouse, radiusPx, std::nullopt);  // no curve preferred
}

int pickCurvePoint(const std::vector<glm::dvec2>& points, const std::vector<CurvePoint>& ids,
                   glm::dvec2 mouse, double radiusPx, const std::optional<TrackTarget>& preferred) {
    int best = -1, bestPreferred = -1;
    double bestD2 = radiusPx * radiusPx, bestPreferredD2 = radiusPx * radiusPx;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const glm::dvec2 d = points[i] - mouse;
        const double d2 = d.x * d.x + d.y * d.y;
        if (d2 <= bestD2) {
            bestD2 = d2;
            best = int(i);
        }
        if (preferred && i < ids.size() && ids[i].target == *preferred && d2 <= bestPreferredD2) {
            bestPreferredD2 = d2;
            bestPreferred = int(i);
        }
    }
    return bestPreferred >= 0 ? bestPreferred : best;
}

std::vector<int> pointsInBox(const std::vector<glm::dvec2>& points, glm::dvec2 a, glm::dvec2 b) {
    const glm::dvec2 lo(std::min(a.x, b.x), std::min(a.y, b.y)), hi(std::max(a.x, b.x), std::max(a.y, b.y));
    std::vector<int> inside;
    for (std::size_t i = 0; i < points.size(); ++i)
        if (points[i].x >= lo.x && points[i].x <= hi.x && points[i].y >= lo.y && points[i].y <= hi.y)
            inside.push_back(int(i));
    return inside;
}

namespace {

/// keyPointsOf with each curve's range from `rangeOf(target, track, desc)`.
template <class RangeOf>
CurveKeyPoints keyPointsIn(const Preset& preset, const std::vector<TrackTarget>& targets, RangeOf rangeOf) {
    CurveKeyPoints out;
    for (const TrackTarget& target : targets) {
        const Track* track = findTrack(preset, target);
        const ParamDesc* desc = findParam(target.scope, target.param);
        if (!track || !desc) continue;
        const CurveRange range = rangeOf(target, *track, *desc);
        for (std::size_t k = 0; k < track->keys.size(); ++k)
            for (int c = 0; c < std::clamp(desc->components(), 1, 3); ++c) {
                out.timeValue.push_back(
                    {track->keys[k].timeHours, range.normalised(track->keys[k].value[c])});
                out.ids.push_back({target, int(k), c});
            }
    }
    return out;
}

}  // namespace

CurveKeyPoints keyPointsOf(const Preset& preset, const std::vector<TrackTarget>& targets) {
    return keyPointsIn(preset, targets, [](const TrackTarget&, const Track& track, const ParamDesc& desc) {
        return curveRangeOf(track, desc);
    });
}

CurveKeyPoints keyPointsOf(const Preset& preset, const std::vector<TrackTarget>& targets,
                           const CurveViewState& view) {
    return keyPointsIn(preset, targets, [&](const TrackTarget& target, const Track&, const ParamDesc&) {
        return view.rangeOf(preset, target);
    });
}

std::vector<CurveDragItem> dragItemsOf(const Preset& preset, const std::vector<CurvePoint>& points) {
    std::vector<CurveDragItem> items;
    for (const CurvePoint& p : points) {
        const Track* track = findTrack(preset, p.target);
        const ParamDesc* desc = findParam(p.target.scope, p.target.param);
        if (!track || !desc || p.key < 0 || p.key >= int(track->keys.size()) || p.component < 0 ||
            p.component >= std::clamp(desc->components(), 1, 3))
            continue;
        const TrackKey& k = track->keys[std::size_t(p.key)];
        items.push_back({p, k.timeHours, k.value[p.component], curveRangeOf(*track, *desc)});
    }
    return items;
}

std::vector<CurveDragItem> dragItemsOf(const Preset& preset, const std::vector<CurvePoint>& points,
                                       const CurveViewState& view) {
    std::vector<CurveDragItem> items = dragItemsOf(preset, points);
    for (CurveDragItem& item : items) item.range = view.rangeOf(preset, item.point.target);
    return items;
}

double moveCurvePoints(Preset& preset, const std::vector<CurveDragItem>& items, double dtHours,
                       double dNormalised) {
    if (!std::isfinite(dtHours)) dtHours = 0.0;
    if (!std::isfinite(dNormalised)) dNormalised = 0.0;
    // The keys that move, per track, with their starting times.
    std::map<std::size_t, std::map<int, double>> moving;  // track index -> key -> start time
    for (const CurveDragItem& item : items) {
        const Track* track = findTrack(preset, item.point.target);
        if (!track) continue;
        const std::size_t t = std::size_t(track - preset.tracks.data());
        if (item.point.key >= 0 && item.point.key < int(track->keys.size()))
            moving[t][item.point.key] = item.timeHours;
    }
    // One shift for all: each moving key stays a gap away from the nearest
    // key that does not move on either side, and inside the day.
    double lo = -1e300, hi = 1e300;
    for (const auto& [t, keys] : moving) {
        const Track& track = preset.tracks[t];
        for (const auto& [k, start] : keys) {
            int before = k - 1, after = k + 1;
            while (before >= 0 && keys.count(before)) --before;
            while (after < int(track.keys.size()) && keys.count(after)) ++after;
            const double floor = before >= 0 ? track.keys[std::size_t(before)].timeHours + kMinKeyGap : 0.0;
            const double ceiling = after < int(track.keys.size())
                                       ? track.keys[std::size_t(after)].timeHours - kMinKeyGap
                                       : 24.0 - kMinKeyGap;
            lo = std::max(lo, floor - start);
            hi = std::min(hi, ceiling - start);
        }
    }
    // Keys closer than the gap to start with: they may stay where they are.
    lo = std::min(lo, 0.0);
    hi = std::max(hi, 0.0);
    const double dt = moving.empty() ? 0.0 : std::clamp(dtHours, lo, hi);
    for (const auto& [t, keys] : moving)
        for (const auto& [k, start] : keys) setKeyTime(preset.tracks[t].keys[std::size_t(k)], start + dt);
    for (const CurveDragItem& item : items) {
        Track* track = findTrack(preset, item.point.target);
        const ParamDesc* desc = findParam(item.point.target.scope, item.point.target.param);
        if (!track || !desc || item.point.key < 0 || item.point.key >= int(track->keys.size())) continue;
        const double v = item.value + dNormalised * (item.range.hi - item.range.lo);
        track->keys[std::size_t(item.point.key)].value[item.point.component] =
            std::clamp(v, desc->minValue, desc->maxValue);
    }
    return dt;
}

int keyCountOf(const std::vector<CurvePoint>& points) {
    std::set<std::pair<std::string, int>> keys;
    for (const CurvePoint& p : points)
        keys.insert(
            {std::to_string(int(p.target.scope)) + ":" + p.target.objectId + ":" + p.target.param, p.key});
    return int(keys.size());
}

std::string moveLabel(const std::vector<CurvePoint>& points) {
    const int n = keyCountOf(points);
    return n == 1 ? std::string("Move key") : "Move " + std::to_string(n) + " keys";
}

int removeCurvePoints(Preset& preset, const std::vector<CurvePoint>& points) {
    // Highest index first within a track, so the indices still to go stay valid.
    std::vector<CurvePoint> order = points;
    std::sort(order.begin(), order.end(),
              [](const CurvePoint& a, const CurvePoint& b) { return a.key > b.key; });
    std::vector<std::pair<TrackTarget, int>> done;
    for (const CurvePoint& p : order) {
        if (std::find(done.begin(), done.end(), std::make_pair(p.target, p.key)) != done.end()) continue;
        done.emplace_back(p.target, p.key);
        removeKey(preset, p.target, p.key);
    }
    return int(done.size());
}

std::string deleteLabel(const std::vector<CurvePoint>& points) {
    const int n = keyCountOf(points);
    return n == 1 ? std::string("Delete key") : "Delete " + std::to_string(n) + " keys";
}

int setFlatTangents(Preset& preset, const std::vector<CurvePoint>& points, bool flat) {
    int changed = 0;
    for (const CurvePoint& p : points) {
        Track* track = findTrack(preset, p.target);
        if (!track || p.key < 0 || p.key >= int(track->keys.size())) continue;
        TrackKey& k = track->keys[std::size_t(p.key)];
        if (k.flat != flat || k.tangents) {  // flat or automatic: the key's own tangents go
            k.flat = flat;
            k.tangents.reset();
            ++changed;
        }
    }
    return changed;
}

int setKeyInterpolation(Preset& preset, const std::vector<CurvePoint>& points,
                        std::optional<Interpolation> interpolation) {
    int changed = 0;
    std::set<const TrackKey*> seen;  // a colour's three points are one key
    for (const CurvePoint& p : points) {
        Track* track = findTrack(preset, p.target);
        if (!track || p.key < 0 || p.key >= int(track->keys.size())) continue;
        TrackKey& k = track->keys[std::size_t(p.key)];
        if (!seen.insert(&k).second) continue;
        if (k.interpolation != interpolation) {
            k.interpolation = interpolation;
            ++changed;
        }
    }
    return changed;
}

bool parseShiftHours(std::string_view text, double& hours) {
    while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
    double sign = 1.0;
    if (!text.empty() && (text.front() == '+' || text.front() == '-')) {
        sign = text.front() == '-' ? -1.0 : 1.0;
        text.remove_prefix(1);
        if (!text.empty() && (text.front() == '+' || text.front() == '-')) return false;  // "+-1"
    }
    double magnitude = 0.0;
    if (!parseClock(text, magnitude)) return false;
    hours = sign * magnitude;
    return true;
}

std::string formatOffset(double hours) {
    if (!std::isfinite(hours)) hours = 0.0;
    const long long seconds = std::llround(std::abs(hours) * 3600.0);
    const char sign = hours < 0.0 && seconds > 0 ? '-' : '+';
    char text[32];
    if (seconds % 60 == 0)
        std::snprintf(text, sizeof text, "%c %lld:%02lld", sign, seconds / 3600, seconds / 60 % 60);
    else
        std::snprintf(text, sizeof text, "%c %lld:%02lld:%02lld", sign, seconds / 3600, seconds / 60 % 60,
                      seconds % 60);
    return text;
}

std::string sunEventLabel(SunEvent event) {
    std::string label = sunEventName(event);
    std::replace(label.begin(), label.end(), '_', ' ');
    return label;
}

std::string keyTimeText(const TrackKey& key) {
    const std::string clock = formatClock(key.timeHours, ClockResolution::Minutes);
    if (!key.anchor) return clock;
    return sunEventLabel(*key.anchor) + " " + formatOffset(key.offsetHours) + " (" + clock + ")";
}

double shiftCurvePoints(Preset& preset, const std::vector<CurvePoint>& points, double dtHours) {
    return moveCurvePoints(preset, dragItemsOf(preset, points), dtHours, 0.0);
}

std::string shiftLabel(const std::vector<CurvePoint>& points) {
    const int n = keyCountOf(points);
    return n == 1 ? std::string("Shift key") : "Shift " + std::to_string(n) + " keys";
}

namespace {

/// The distinct keys of `points` that the preset has (TrackKey* or const TrackKey*).
template <class PresetT>
auto keysOf(PresetT& preset, const std::vector<CurvePoint>& points) {
    std::vector<decltype(&preset.tracks.front().keys.front())> keys;
    for (const CurvePoint& p : points) {
        auto* track = findTrack(preset, p.target);
        if (!track || p.key < 0 || p.key >= int(track->keys.size())) continue;
        auto* key = &track->keys[std::size_t(p.key)];
        if (std::find(keys.begin(), keys.end(), key) == keys.end()) keys.push_back(key);
    }
    return keys;
}

}  // namespace

int anchorCurvePoints(Preset& preset, const std::vector<CurvePoint>& points, std::optional<SunEvent> event) {
    int changed = 0;
    for (TrackKey* key : keysOf(preset, points)) {
        if (key->anchor == event) continue;
        anchorKey(*key, event, preset.environment.location);
        ++changed;
    }
    return changed;
}

std::string anchorLabel(const std::vector<CurvePoint>& points, std::optional<SunEvent> event) {
    const int n = keyCountOf(points);
    const std::string keys = n == 1 ? std::string("key") : std::to_string(n) + " keys";
    if (!event) return n == 1 ? std::string("Fix key time") : "Fix " + std::to_string(n) + " key times";
    return "Anchor " + keys + " to " + sunEventLabel(*event);
}

bool allAnchoredTo(const Preset& preset, const std::vector<CurvePoint>& points,
                   std::optional<SunEvent> event) {
    const std::vector<const TrackKey*> keys = keysOf(preset, points);
    return !keys.empty() &&
           std::all_of(keys.begin(), keys.end(), [&](const TrackKey* k) { return k->anchor == event; });
}

std::string keyClockText(double hours) {
    std::string text = formatClock(hours, ClockResolution::Seconds);
    if (text.size() == 5) text += ":00";  // "19:52" on the minute
    return text;
}

bool parseKeyValue(std::string_view text, std::string_view unit, double& value) {
    auto trim = [](std::string_view& t) {
        while (!t.empty() && t.front() == ' ') t.remove_prefix(1);
        while (!t.empty() && t.back() == ' ') t.remove_suffix(1);
    };
    trim(text);
    if (!unit.empty() && text.size() > unit.size() && text.substr(text.size() - unit.size()) == unit) {
        text.remove_suffix(unit.size());
        trim(text);
    }
    // Digits, a sign, a point and an exponent only: no "nan", "inf" or hex floats.
    if (text.empty() || text.find_first_not_of("0123456789+-.eE") != std::string_view::npos) return false;
    const std::string copy(text);
    char* end = nullptr;
    const double parsed = std::strtod(copy.c_str(), &end);
    if (end != copy.c_str() + copy.size() || !std::isfinite(parsed)) return false;
    value = parsed;
    return true;
}

std::optional<CurvePoint> leadPointOf(const Preset& preset, const std::vector<CurvePoint>& points) {
    const std::vector<CurveDragItem> items = dragItemsOf(preset, points);
    if (items.empty()) return std::nullopt;
    return items.front().point;
}

double setCurvePointsTime(Preset& preset, const std::vector<CurvePoint>& points, double timeHours) {
    const std::optional<CurvePoint> lead = leadPointOf(preset, points);
    if (!lead) return std::nan("");
    const std::size_t key = std::size_t(lead->key);
    const double start = findTrack(preset, lead->target)->keys[key].timeHours;
    if (!std::isfinite(timeHours)) return start;
    const double wanted = timeHours - start;
    const double applied = shiftCurvePoints(preset, points, wanted);
    // The keys keep their order, so the lead is still key `key`; set to the time typed, not
    // start + (typed - start), which may differ from it in the last bit.
    TrackKey& moved = findTrack(preset, lead->target)->keys[key];
    if (applied == wanted) setKeyTime(moved, timeHours);
    return moved.timeHours;
}

std::string setTimeLabel(const std::vector<CurvePoint>& points) {
    const int n = keyCountOf(points);
    return n == 1 ? std::string("Set key time") : "Set " + std::to_string(n) + " key times";
}

namespace {

/// The points of the lead point's parameter (its scope and parameter), those the preset has.
std::vector<CurvePoint> pointsOfLeadParam(const Preset& preset, const std::vector<CurvePoint>& points) {
    std::vector<CurvePoint> same;
    const std::optional<CurvePoint> lead = leadPointOf(preset, points);
    if (!lead) return same;
    for (const CurveDragItem& item : dragItemsOf(preset, points))
        if (item.point.target.scope == lead->target.scope && item.point.target.param == lead->target.param)
            same.push_back(item.point);
    return same;
}

}  // namespace

int setCurvePointsValue(Preset& preset, const std::vector<CurvePoint>& points, double value) {
    if (!std::isfinite(value)) return 0;
    std::set<const TrackKey*> changed;
    for (const CurvePoint& p : pointsOfLeadParam(preset, points)) {
        const ParamDesc* desc = findParam(p.target.scope, p.target.param);
        TrackKey& key = findTrack(preset, p.target)->keys[std::size_t(p.key)];
        const double v = std::clamp(value, desc->minValue, desc->maxValue);
        if (key.value[p.component] != v) {
            key.value[p.component] = v;
            changed.insert(&key);
        }
    }
    return int(changed.size());
}

std::string setValueLabel(const Preset& preset, const std::vector<CurvePoint>& points) {
    const int n = keyCountOf(pointsOfLeadParam(preset, points));
    return n == 1 ? std::string("Set key value") : "Set " + std::to_string(n) + " key values";
}

std::string keyReadout(const TrackKey& key, int component, const ParamDesc& desc) {
    std::string when = keyClockText(key.timeHours);
    if (key.anchor)
        when = sunEventLabel(*key.anchor) + " " + formatOffset(key.offsetHours) + " (" + when + ")";
    return when + "  " + valueWithUnit(key.value[std::clamp(component, 0, 2)], desc.unit);
}

bool CurveViewState::isShown(const TrackTarget& target) const {
    return std::find(shown.begin(), shown.end(), target) != shown.end();
}

void CurveViewState::setShown(const TrackTarget& target, bool show) {
    const auto it = std::find(shown.begin(), shown.end(), target);
    if (show && it == shown.end()) shown.push_back(target);
    if (!show && it != shown.end()) shown.erase(it);
}

bool CurveViewState::isSelected(const CurvePoint& point) const {
    return std::find(selected.begin(), selected.end(), point) != selected.end();
}

void CurveViewState::validate(const Preset& preset) {
    std::erase_if(selected, [&](const CurvePoint& p) {
        const Track* track = findTrack(preset, p.target);
        return !track || p.key < 0 || p.key >= int(track->keys.size());
    });
}

CurveRange CurveViewState::rangeOf(const Preset& preset, const TrackTarget& target) const {
    const Track* track = findTrack(preset, target);
    const ParamDesc* desc = findParam(target.scope, target.param);
    if (!track || !desc) return {};
    const auto pinned = pinnedRanges.find(curveKey(target));
    if (pinned == pinnedRanges.end()) return curveRangeOf(*track, *desc);
    double lo, hi;
    keyValueSpan(*track, *desc, lo, hi);
    if (lo >= pinned->second.lo && hi <= pinned->second.hi) return pinned->second;
    // A key outside the pinned range: widened on that side to the keys' range (padded).
    const CurveRange keys = curveRangeOf(*track, *desc);
    return {lo < pinned->second.lo ? std::min(pinned->second.lo, keys.lo) : pinned->second.lo,
            hi > pinned->second.hi ? std::max(pinned->second.hi, keys.hi) : pinned->second.hi};
}

void CurveViewState::pinRange(const Preset& preset, const TrackTarget& target) {
    if (findTrack(preset, target)) pinnedRanges[curveKey(target)] = rangeOf(preset, target);
}

}  // namespace aerial::editor
