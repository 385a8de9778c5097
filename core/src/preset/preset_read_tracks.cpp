// preset_read_tracks.cpp — reading a preset's tracks (preset_read.cpp,
// preset_reader.hpp): each track's target, keys and interpolation, and the
// warning for two keys less than a minute apart.
#include "json_text.hpp"
#include "preset_reader.hpp"
#include "preset_validate.hpp"

#include <aerial/clock.hpp>
#include <aerial/limits.hpp>
#include <aerial/param_table.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>

namespace aerial {

using namespace detail;
using sv = std::string_view;

void Reader::readTrack(std::int32_t node, const std::string& pointer, Track& track) {
    if (!expectKind(node, pointer, JNode::Object)) return;
    readTarget(node, pointer, "a track", track.target);
    if (isLegacyEmitterIntensity(track.target.scope, track.target.param)) {
        track.target.param = "intensity_cd";
        legacyTrack_ = true;
    }
    if (const std::int32_t interp = member(node, "interpolation"); interp >= 0) {
        const std::string at = pointerJoin(pointer, "interpolation");
        if (expectKind(interp, at, JNode::String) &&
            !parseInterpolation(nodes_[std::size_t(interp)].text, track.interpolation))
            error(interp, at,
                  "unknown interpolation " + quoteString(nodes_[std::size_t(interp)].text) +
                      "; expected one of step, linear, smooth");
    }
    if (const std::int32_t wrap = member(node, "wrap"); wrap >= 0) {
        const std::string at = pointerJoin(pointer, "wrap");
        if (nodes_[std::size_t(wrap)].kind == JNode::Bool)
            track.wrap = nodes_[std::size_t(wrap)].boolean;
        else
            error(wrap, at, "wrap must be true (the day is cyclic) or false (hold the first and last keys)");
    }
    const ParamDesc* p = findParam(track.target.scope, track.target.param);
    const std::int32_t keys = member(node, "keys");
    const std::string keysAt = pointerJoin(pointer, "keys");
    if (keys < 0) {
        error(node, keysAt, "missing required field \"keys\"");
    } else if (expectKind(keys, keysAt, JNode::Array) &&
               withinLimit(keys, keysAt, limits::kMaxKeysPerTrack, "keys")) {
        track.keys.reserve(nodes_[std::size_t(keys)].childCount);
        std::size_t k = 0;
        for (std::int32_t c = nodes_[std::size_t(keys)].firstChild; c >= 0;
             c = nodes_[std::size_t(c)].nextSibling, ++k) {
            const std::string at = pointerJoin(keysAt, k);
            TrackKey key;
            if (expectKind(c, at, JNode::Object)) {
                const std::int32_t time = member(c, "time_h");
                const std::int32_t value = member(c, "value");
                const std::int32_t anchor = member(c, "anchor");
                const std::int32_t offset = member(c, "offset_h");
                if (time >= 0 && anchor >= 0)
                    error(anchor, pointerJoin(at, "anchor"),
                          "a key has either \"time_h\" (a fixed time) or \"anchor\" (a sun event), not both");
                else if (time >= 0)
                    readNumber(time, pointerJoin(at, "time_h"), key.timeHours);
                else if (anchor < 0)
                    error(c, pointerJoin(at, "time_h"),
                          "missing required field \"time_h\" (or \"anchor\", a sun event)");
                if (anchor >= 0 && expectKind(anchor, pointerJoin(at, "anchor"), JNode::String)) {
                    SunEvent event{};
                    if (parseSunEvent(nodes_[std::size_t(anchor)].text, event))
                        key.anchor = event;
                    else
                        error(anchor, pointerJoin(at, "anchor"),
                              "unknown sun event " + quoteString(nodes_[std::size_t(anchor)].text) +
                                  "; expected one of sunrise, noon, sunset, civil_dawn, civil_dusk, "
                                  "nautical_dawn, nautical_dusk");
                }
                if (const std::int32_t mode = member(c, "interpolation"); mode >= 0) {
                    const std::string modeAt = pointerJoin(at, "interpolation");
                    Interpolation parsed = Interpolation::Smooth;
                    if (expectKind(mode, modeAt, JNode::String)) {
                        if (parseInterpolation(nodes_[std::size_t(mode)].text, parsed))
                            key.interpolation = parsed;
                        else
                            error(mode, modeAt,
                                  "unknown interpolation " + quoteString(nodes_[std::size_t(mode)].text) +
                                      "; expected one of step, linear, smooth");
                    }
                }
                if (offset >= 0) {
                    if (anchor < 0)
                        error(offset, pointerJoin(at, "offset_h"),
                              "\"offset_h\" is the offset from a sun event; this key has no \"anchor\"");
                    else
                        readNumber(offset, pointerJoin(at, "offset_h"), key.offsetHours);
                }
                if (value < 0) {
                    error(c, pointerJoin(at, "value"), "missing required field \"value\"");
                } else if (p && p->type == ParamType::Scalar) {
                    readNumber(value, pointerJoin(at, "value"), key.value.x);
                } else if (p) {
                    // Vectors: components() numbers into x, y(, z); a
                    // Vec2's [x, z] lands in x, y with z = 0.
                    const int count = p->components() == 2 ? 2 : 3;
                    double v[3] = {0.0, 0.0, 0.0};
                    if (readNumbers(value, pointerJoin(at, "value"), v, count))
                        key.value = glm::dvec3(v[0], v[1], v[2]);
                }
                readKeyTangents(c, at, p, key);
                if (const std::int32_t flat = member(c, "flat"); flat >= 0) {
                    if (nodes_[std::size_t(flat)].kind == JNode::Bool)
                        key.flat = nodes_[std::size_t(flat)].boolean;
                    else
                        error(flat, pointerJoin(at, "flat"),
                              "flat must be true (a level tangent at the key) or false");
                }
                for (std::int32_t m = nodes_[std::size_t(c)].firstChild; m >= 0;
                     m = nodes_[std::size_t(m)].nextSibling) {
                    const std::string& name = nodes_[std::size_t(m)].key;
                    if (name != "time_h" && name != "value" && name != "flat" && name != "anchor" &&
                        name != "offset_h" && name != "interpolation" && name != "tangent_in" &&
                        name != "tangent_out" && name != "tangent_mode")
                        warnUnknown(m, pointerJoin(at, name));
                }
            }
            track.keys.push_back(key);
        }
    }
    for (std::int32_t m = nodes_[std::size_t(node)].firstChild; m >= 0;
         m = nodes_[std::size_t(m)].nextSibling) {
        const std::string& name = nodes_[std::size_t(m)].key;
        const bool objectKey = std::any_of(std::begin(kObjectScopes), std::end(kObjectScopes),
                                           [&](ParamScope s) { return trackObjectKey(s) == name; });
        if (!objectKey && name != "param" && name != "interpolation" && name != "wrap" && name != "keys")
            warnUnknown(m, pointerJoin(pointer, name));
    }
}

void Reader::readKeyTangents(std::int32_t node, const std::string& at, const ParamDesc* p, TrackKey& key) {
    const std::int32_t in = member(node, "tangent_in");
    const std::int32_t out = member(node, "tangent_out");
    const std::int32_t mode = member(node, "tangent_mode");
    if (in < 0 && out < 0) {
        if (mode >= 0)
            error(mode, pointerJoin(at, "tangent_mode"),
                  "\"tangent_mode\" goes with \"tangent_in\" and \"tangent_out\"; this key has neither");
        return;
    }
    if (in < 0 || out < 0) {
        const char* missing = in < 0 ? "tangent_in" : "tangent_out";
        error(in < 0 ? out : in, pointerJoin(at, missing),
              std::string("missing field \"") + missing +
                  "\": a key's own tangents give both slopes (equal ones for unified handles)");
        return;
    }
    KeyTangents tangents;
    if (mode >= 0) {
        const std::string modeAt = pointerJoin(at, "tangent_mode");
        if (!expectKind(mode, modeAt, JNode::String)) return;
        const std::string& text = nodes_[std::size_t(mode)].text;
        if (text == "unified")
            tangents.mode = TangentMode::Unified;
        else if (text == "broken")
            tangents.mode = TangentMode::Broken;
        else {
            error(mode, modeAt,
                  "unknown tangent mode " + quoteString(text) + "; expected one of unified, broken");
            return;
        }
    }
    if (!p) return;  // the target is reported elsewhere; the value's shape is unknown
    // Slopes take the value's shape: a number for scalars, components()
    // numbers for vectors and colours.
    auto slope = [&](std::int32_t n, const char* name, glm::dvec3& outSlope) {
        const std::string slopeAt = pointerJoin(at, name);
        if (p->type == ParamType::Scalar) return readNumber(n, slopeAt, outSlope.x);
        const int count = p->components() == 2 ? 2 : 3;
        double v[3] = {0.0, 0.0, 0.0};
        if (!readNumbers(n, slopeAt, v, count)) return false;
        outSlope = glm::dvec3(v[0], v[1], v[2]);
        return true;
    };
    const bool inRead = slope(in, "tangent_in", tangents.in);
    const bool outRead = slope(out, "tangent_out", tangents.out);
    if (inRead && outRead) key.tangents = tangents;
}

void Reader::warnCloseKeys(const Preset& preset) {
    constexpr double kMinute = 1.0 / 60.0;
    for (std::size_t i = 0; i < preset.tracks.size(); ++i) {
        const Track& track = preset.tracks[i];
        const std::size_t n = track.keys.size();
        for (std::size_t k = 0; k < n && n > 1; ++k) {
            if (k == 0 && !track.wrap) continue;
            const TrackKey& before = track.keys[k == 0 ? n - 1 : k - 1];
            const TrackKey& key = track.keys[k];
            const double gap = key.timeHours - before.timeHours + (k == 0 ? 24.0 : 0.0);
            if (!(gap < kMinute - 1e-9)) continue;  // a minute to the microsecond is enough
            const std::string at = pointerJoin(pointerJoin(pointerJoin("/tracks", i), "keys"), k) +
                                   (key.anchor ? "/anchor" : "/time_h");
            issue(PresetIssue::Severity::Warning, nodeAt(at), false, at,
                  "keys at " + formatClock(before.timeHours) + " and " + formatClock(key.timeHours) +
                      " are " + formatDouble(std::round(gap * 3600.0)) +
                      " s apart (under a minute): one key meant, two written? Remove one or move it");
        }
    }
}

}  // namespace aerial
