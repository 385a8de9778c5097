// editor/curve_keys.cpp — the curve view's key tangents (the handles of a
// selected key: their place on screen, the slope a dragged handle sets,
// unified or broken, automatic again) and copy and paste of keys across
// curves and times. Declared in curve_view.hpp.
#include "curve_view.hpp"

#include <aerial/limits.hpp>

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

namespace aerial::editor {
namespace {

/// The key of `p` in `preset`, or null.
TrackKey* keyOf(Preset& preset, const CurvePoint& p, Track** trackOut = nullptr) {
    Track* track = findTrack(preset, p.target);
    if (!track || p.key < 0 || p.key >= int(track->keys.size())) return nullptr;
    if (trackOut) *trackOut = track;
    return &track->keys[std::size_t(p.key)];
}

int componentsOf(const TrackTarget& target) {
    const ParamDesc* desc = findParam(target.scope, target.param);
    return desc ? std::clamp(desc->components(), 1, 3) : 3;
}

/// The key's own tangents, taken from the automatic ones when it has none
/// (so a first drag of one handle leaves the other where it was drawn).
KeyTangents& ownTangents(const Track& track, TrackKey& key, std::size_t index, int components) {
    if (!key.tangents) {
        const glm::dvec3 automatic = automaticTangent(track, index, components);
        key.tangents = KeyTangents{automatic, automatic, TangentMode::Unified};
        key.flat = false;  // a key is flat or has its own tangents
    }
    return *key.tangents;
}

}  // namespace

glm::dvec2 tangentHandleOffset(double slope, const CurveRange& range, double pxPerHour, double heightPx,
                               TangentSide side) {
    const double span = range.hi - range.lo;
    // One hour along the slope, in pixels (y down), scaled to the handle's length.
    glm::dvec2 d(pxPerHour, span != 0.0 ? -slope / span * heightPx : 0.0);
    const double length = std::hypot(d.x, d.y);
    if (!(length > 0.0) || !std::isfinite(length))
        d = glm::dvec2(0.0, slope > 0.0 ? -1.0 : 1.0);
    else
        d /= length;
    return (side == TangentSide::Out ? 1.0 : -1.0) * kTangentHandlePx * d;
}

double slopeOfHandle(glm::dvec2 offsetPx, const CurveRange& range, double pxPerHour, double heightPx,
                     TangentSide side) {
    // A handle stays on its side of the key: at least a pixel before (in) or after (out) it.
    const double dx = side == TangentSide::Out ? std::max(offsetPx.x, 1.0) : std::min(offsetPx.x, -1.0);
    if (!(pxPerHour > 0.0) || !(heightPx > 0.0)) return 0.0;
    const double dValue = -offsetPx.y / heightPx * (range.hi - range.lo);
    const double dHours = dx / pxPerHour;
    return std::clamp(dValue / dHours, -limits::kMaxKeyTangent, limits::kMaxKeyTangent);
}

bool setKeyTangent(Preset& preset, const CurvePoint& point, TangentSide side, double slope) {
    Track* track = nullptr;
    TrackKey* key = keyOf(preset, point, &track);
    if (!key || point.component < 0 || point.component > 2 || !std::isfinite(slope)) return false;
    slope = std::clamp(slope, -limits::kMaxKeyTangent, limits::kMaxKeyTangent);
    KeyTangents& t = ownTangents(*track, *key, std::size_t(point.key), componentsOf(point.target));
    const int c = point.component;
    if (side == TangentSide::Out || t.mode == TangentMode::Unified) t.out[c] = slope;
    if (side == TangentSide::In || t.mode == TangentMode::Unified) t.in[c] = slope;
    return true;
}

int setTangentMode(Preset& preset, const std::vector<CurvePoint>& points, TangentMode mode) {
    int changed = 0;
    std::set<const TrackKey*> seen;  // a colour's three points are one key
    for (const CurvePoint& p : points) {
        Track* track = nullptr;
        TrackKey* key = keyOf(preset, p, &track);
        if (!key || !seen.insert(key).second) continue;
        const bool had = key->tangents.has_value();
        KeyTangents& t = ownTangents(*track, *key, std::size_t(p.key), componentsOf(p.target));
        if (had && t.mode == mode) continue;
        t.mode = mode;
        if (mode == TangentMode::Unified) t.in = t.out = 0.5 * (t.in + t.out);  // one slope: the mean
        ++changed;
    }
    return changed;
}

std::string tangentModeLabel(const std::vector<CurvePoint>& points, TangentMode mode) {
    // Appended piece by piece: GCC 12 warns (-Wrestrict) on " " + a temporary string.
    const int keys = keyCountOf(points);
    std::string label = mode == TangentMode::Unified ? "Unify " : "Break ";
    if (keys != 1) {
        label += std::to_string(keys);
        label += ' ';
    }
    label += keys == 1 ? "tangent" : "tangents";
    return label;
}

std::optional<TangentMode> tangentModeOf(const Preset& preset, const CurvePoint& point) {
    const Track* track = findTrack(preset, point.target);
    if (!track || point.key < 0 || point.key >= int(track->keys.size())) return std::nullopt;
    const std::optional<KeyTangents>& t = track->keys[std::size_t(point.key)].tangents;
    return t ? std::optional<TangentMode>(t->mode) : std::nullopt;
}

CurveClipboard copyCurvePoints(const Preset& preset, const std::vector<CurvePoint>& points) {
    CurveClipboard clipboard;
    std::set<std::pair<std::string, int>> seen;  // a colour's three points are one key
    for (const CurvePoint& p : points) {
        const Track* track = findTrack(preset, p.target);
        if (!track || p.key < 0 || p.key >= int(track->keys.size())) continue;
        if (!seen.insert({curveKey(p.target), p.key}).second) continue;
        CopiedKey copied{p.target, track->keys[std::size_t(p.key)].timeHours,
                         track->keys[std::size_t(p.key)]};
        clipboard.keys.push_back(std::move(copied));
    }
    if (clipboard.keys.empty()) return clipboard;
    // The first key after the longest gap between the copied times (round the day) is the earliest:
    // a selection from 23:30 to 00:30 starts at 23:30.
    std::vector<double> times;
    for (const CopiedKey& k : clipboard.keys) times.push_back(k.offsetHours);
    std::sort(times.begin(), times.end());
    double start = times.front(), longest = -1.0;
    for (std::size_t i = 0; i < times.size(); ++i) {
        const double before = i == 0 ? times.back() - 24.0 : times[i - 1];
        if (times[i] - before > longest) longest = times[i] - before, start = times[i];
    }
    for (CopiedKey& k : clipboard.keys) k.offsetHours = wrapHours(k.offsetHours - start);
    std::stable_sort(clipboard.keys.begin(), clipboard.keys.end(),
                     [](const CopiedKey& a, const CopiedKey& b) { return a.offsetHours < b.offsetHours; });
    return clipboard;
}

std::vector<CurvePoint> pasteCurveKeys(Preset& preset, const CurveClipboard& clipboard, double timeHours) {
    std::vector<std::pair<TrackTarget, double>> pasted;
    for (const CopiedKey& copied : clipboard.keys) {
        const std::optional<ParamRef> ref = paramRefOf(preset, copied.target);
        if (!ref || !ref->desc->animatable) continue;
        Track* track = findTrack(preset, copied.target);
        if (!track) {
            Track created;
            created.target = copied.target;
            preset.tracks.push_back(std::move(created));
            track = &preset.tracks.back();
        }
        TrackKey key = copied.key;
        key.anchor.reset();
        key.offsetHours = 0.0;
        key.timeHours = wrapHours(timeHours + copied.offsetHours);
        // On an existing key (within a minute, round midnight too): that key, at its own time.
        const auto near = std::find_if(track->keys.begin(), track->keys.end(), [&](const TrackKey& k) {
            const double gap = std::abs(k.timeHours - key.timeHours);
            return std::min(gap, 24.0 - gap) < kMinKeyGap;
        });
        if (near != track->keys.end()) {
            key.timeHours = near->timeHours;
            *near = key;
        } else {
            track->keys.insert(std::lower_bound(track->keys.begin(), track->keys.end(), key.timeHours,
                                                [](const TrackKey& k, double t) { return k.timeHours < t; }),
                               key);
        }
        pasted.emplace_back(copied.target, key.timeHours);
    }
    std::vector<CurvePoint> points;
    for (const auto& [target, time] : pasted) {
        const Track* track = findTrack(preset, target);
        for (std::size_t k = 0; track && k < track->keys.size(); ++k)
            if (track->keys[k].timeHours == time) points.push_back({target, int(k), 0});
    }
    return points;
}

std::string pasteLabel(const CurveClipboard& clipboard) {
    const std::size_t n = clipboard.keys.size();
    if (n == 1) return "Paste key";
    std::string label = "Paste ";
    label += std::to_string(n);
    label += " keys";
    return label;
}

}  // namespace aerial::editor
