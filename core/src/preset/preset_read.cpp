// preset_read.cpp — reading: the positioned JSON tree of a preset file into
// a Preset, driven by the parameter table (preset_read.hpp). Type errors,
// missing fields and values over a cap are errors at the field's
// line:column; unknown fields are warnings; non-unit directions are
// normalised with a warning (aerial/preset.hpp, "Numbers"). Validation
// issues are mapped back to positions in the file.
#include "preset_read.hpp"

#include "json_text.hpp"
#include "preset_validate.hpp"

#include <aerial/atmosphere.hpp>
#include <aerial/clock.hpp>
#include <aerial/evaluate.hpp>
#include <aerial/exposure.hpp>
#include <aerial/limits.hpp>
#include <aerial/param_table.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iterator>
#include <set>

namespace aerial {

using namespace detail;
using sv = std::string_view;

namespace {

class Reader {
public:
    Reader(sv text, std::string file, const std::vector<JNode>& nodes)
        : text_(text), file_(std::move(file)), nodes_(nodes) {}

    std::vector<PresetIssue> errors;
    std::vector<PresetIssue> warnings;

    void issue(PresetIssue::Severity severity, std::int32_t node, bool atKey, std::string pointer,
               std::string message) {
        const bool isError = severity == PresetIssue::Severity::Error;
        std::vector<PresetIssue>& list = isError ? errors : warnings;
        if (list.size() >= limits::kMaxPresetIssues) {
            ++(isError ? suppressedErrors_ : suppressedWarnings_);
            return;
        }
        PresetIssue i;
        i.severity = severity;
        i.file = file_;
        i.pointer = std::move(pointer);
        i.message = std::move(message);
        if (node >= 0) {
            const JNode& n = nodes_[std::size_t(node)];
            positions_.push_back({isError, list.size(), atKey ? n.keyOffset : n.offset});
        }
        list.push_back(std::move(i));
    }

    // Fills in line:column of every issue (one pass over the text, however
    // many issues) and sums up the issues over limits::kMaxPresetIssues.
    void finish() {
        std::sort(positions_.begin(), positions_.end(),
                  [](const Position& a, const Position& b) { return a.offset < b.offset; });
        int line = 1, column = 1;
        std::size_t at = 0;
        for (const Position& p : positions_) {
            const std::size_t end = std::min<std::size_t>(p.offset, text_.size());
            for (; at < end; ++at) {
                const unsigned char c = static_cast<unsigned char>(text_[at]);
                if (c == '\n') {
                    ++line;
                    column = 1;
                } else if ((c & 0xC0) != 0x80) {
                    ++column;
                }
            }
            PresetIssue& i = (p.error ? errors : warnings)[p.index];
            i.line = line;
            i.column = column;
        }
        positions_.clear();
        auto summary = [&](std::vector<PresetIssue>& list, std::size_t more, PresetIssue::Severity severity,
                           const char* what) {
            if (more == 0) return;
            PresetIssue i;
            i.severity = severity;
            i.file = file_;
            i.message = std::to_string(more) + " more " + what + " not listed (at most " +
                        std::to_string(limits::kMaxPresetIssues) + " are)";
            list.push_back(std::move(i));
        };
        summary(errors, suppressedErrors_, PresetIssue::Severity::Error, "errors");
        summary(warnings, suppressedWarnings_, PresetIssue::Severity::Warning, "warnings");
    }
    void error(std::int32_t node, std::string pointer, std::string message) {
        issue(PresetIssue::Severity::Error, node, false, std::move(pointer), std::move(message));
    }

    std::int32_t member(std::int32_t object, sv key) const {
        for (std::int32_t c = nodes_[std::size_t(object)].firstChild; c >= 0;
             c = nodes_[std::size_t(c)].nextSibling)
            if (nodes_[std::size_t(c)].key == key) return c;
        return -1;
    }

    // The node a pointer names, or its deepest existing ancestor.
    std::int32_t nodeAt(sv pointer) const {
        std::int32_t node = 0;
        std::size_t start = 1;
        while (start <= pointer.size() && !pointer.empty()) {
            const std::size_t slash = pointer.find('/', start);
            std::string token(pointer.substr(start, slash == sv::npos ? sv::npos : slash - start));
            std::string unescaped;
            for (std::size_t i = 0; i < token.size(); ++i) {
                if (token[i] == '~' && i + 1 < token.size()) {
                    unescaped += token[i + 1] == '1' ? '/' : '~';
                    ++i;
                } else {
                    unescaped += token[i];
                }
            }
            const JNode& n = nodes_[std::size_t(node)];
            std::int32_t next = -1;
            if (n.kind == JNode::Object) {
                next = member(node, unescaped);
            } else if (n.kind == JNode::Array) {
                std::size_t index = 0;
                const auto r = std::from_chars(unescaped.data(), unescaped.data() + unescaped.size(), index);
                if (r.ec == std::errc() && r.ptr == unescaped.data() + unescaped.size()) {
                    std::int32_t c = n.firstChild;
                    for (std::size_t k = 0; c >= 0 && k < index; ++k) c = nodes_[std::size_t(c)].nextSibling;
                    next = c;
                }
            }
            if (next < 0) return node;
            node = next;
            if (slash == sv::npos) break;
            start = slash + 1;
        }
        return node;
    }

    bool expectKind(std::int32_t node, const std::string& pointer, JNode::Kind kind) {
        const JNode& n = nodes_[std::size_t(node)];
        if (n.kind == kind) return true;
        error(node, pointer, std::string("expected ") + kindName(kind) + ", got " + kindName(n.kind));
        return false;
    }

    bool readNumber(std::int32_t node, const std::string& pointer, double& out) {
        const JNode& n = nodes_[std::size_t(node)];
        if (!n.isNumber()) {
            error(node, pointer, std::string("expected a number, got ") + kindName(n.kind));
            return false;
        }
        out = n.asDouble();
        return true;
    }

    bool readNumbers(std::int32_t node, const std::string& pointer, double* out, int count) {
        const JNode& n = nodes_[std::size_t(node)];
        if (n.kind != JNode::Array || n.childCount != std::uint32_t(count)) {
            error(node, pointer,
                  "expected an array of " + std::to_string(count) + " numbers, got " +
                      (n.kind == JNode::Array ? "an array of " + std::to_string(n.childCount)
                                              : std::string(kindName(n.kind))));
            return false;
        }
        bool ok = true;
        int i = 0;
        for (std::int32_t c = n.firstChild; c >= 0; c = nodes_[std::size_t(c)].nextSibling, ++i)
            ok = readNumber(c, pointerJoin(pointer, std::size_t(i)), out[i]) && ok;
        return ok;
    }

    void readParam(const ParamDesc& p, void* object, std::int32_t node, const std::string& pointer) {
        const JNode& n = nodes_[std::size_t(node)];
        switch (p.type) {
            case ParamType::Scalar:
                readNumber(node, pointer, *p.scalar(object));
                break;
            case ParamType::Colour:
            case ParamType::Vec3: {
                double v[3];
                if (!readNumbers(node, pointer, v, 3)) break;
                if (p.unitLength && !normaliseOrRefuse(node, pointer, v, 3, "a unit vector")) break;
                *p.vec3(object) = glm::dvec3(v[0], v[1], v[2]);
                break;
            }
            case ParamType::Vec2: {
                double v[2];
                if (readNumbers(node, pointer, v, 2)) *p.vec2(object) = glm::dvec2(v[0], v[1]);
                break;
            }
            case ParamType::Quaternion: {
                double v[4];
                if (readNumbers(node, pointer, v, 4) &&
                    normaliseOrRefuse(node, pointer, v, 4, "a unit quaternion"))
                    *p.quat(object) = glm::dquat(v[3], v[0], v[1], v[2]);
                break;
            }
            case ParamType::Enum: {
                if (!expectKind(node, pointer, JNode::String)) break;
                bool found = false;
                for (std::size_t i = 0; i < p.enumNames.size(); ++i) {
                    if (p.enumNames[i] == n.text) {
                        p.setInt(object, std::int64_t(i));
                        found = true;
                    }
                }
                if (!found) {
                    std::string names;
                    for (sv name : p.enumNames) names += (names.empty() ? "" : ", ") + std::string(name);
                    error(node, pointer,
                          "unknown value " + quoteString(n.text) + "; expected one of " + names);
                }
                break;
            }
            case ParamType::Int: {
                double v = 0.0;
                bool integral = false;
                if (n.kind == JNode::Integer || n.kind == JNode::Unsigned) {
                    v = n.asDouble();
                    integral = true;
                } else if (n.kind == JNode::Float) {
                    v = n.number;
                    integral = std::isfinite(v) && std::trunc(v) == v;
                }
                if (!integral) {
                    error(node, pointer, std::string("expected an integer, got ") + kindName(n.kind));
                } else if (v < p.minValue || v > p.maxValue) {
                    error(node, pointer, "out of range: " + formatDouble(v) + " is not in " + rangeText(p));
                } else {
                    p.setInt(object, std::int64_t(v));
                }
                break;
            }
            case ParamType::String:
                if (expectKind(node, pointer, JNode::String)) *p.string(object) = n.text;
                break;
        }
    }

    // Unit vectors and quaternions in a file (docs: preset.hpp, "Numbers"):
    // finite, non-zero and off unit length by more than 1e-6 -> normalised,
    // with a warning; zero (or too small to have a direction) -> an error.
    // Non-finite components are left for validation to report.
    bool normaliseOrRefuse(std::int32_t node, const std::string& pointer, double* v, int n,
                           const char* what) {
        double largest = 0.0;
        for (int i = 0; i < n; ++i) {
            if (!std::isfinite(v[i])) return true;
            largest = std::max(largest, std::abs(v[i]));
        }
        if (!(largest > 1e-150)) {
            error(node, pointer, std::string("must be ") + what + "; a zero vector has no direction");
            return false;
        }
        double scaled = 0.0;
        for (int i = 0; i < n; ++i) scaled += (v[i] / largest) * (v[i] / largest);
        const double length = std::sqrt(scaled) * largest;
        if (std::abs(length - 1.0) <= 1e-6) return true;
        const double norm = std::sqrt(scaled);
        for (int i = 0; i < n; ++i) v[i] = (v[i] / largest) / norm;
        issue(PresetIssue::Severity::Warning, node, false, pointer,
              std::string("not ") + what + " (length " + formatDouble(length) + "); normalised");
        return true;
    }

    void warnUnknown(std::int32_t node, const std::string& pointer) {
        issue(PresetIssue::Severity::Warning, node, true, pointer,
              "unknown field " + quoteString(nodes_[std::size_t(node)].key) + " (ignored)");
    }

    // Reads the members of an object node that belong to a scope's table.
    void readObject(ParamScope scope, void* object, std::int32_t node, const std::string& pointer) {
        for (const ParamDesc& p : paramTable(scope)) {
            const std::int32_t m = member(node, p.path);
            if (m >= 0)
                readParam(p, object, m, pointerJoin(pointer, p.path));
            else if (p.required)
                error(node, pointerJoin(pointer, p.path), "missing required field " + quoteString(p.path));
        }
        for (std::int32_t c = nodes_[std::size_t(node)].firstChild; c >= 0;
             c = nodes_[std::size_t(c)].nextSibling) {
            const std::string& key = nodes_[std::size_t(c)].key;
            if (isLegacyEmitterIntensity(scope, key)) continue;
            if (!findParam(scope, key)) warnUnknown(c, pointerJoin(pointer, key));
        }
    }

    // Version <= 2 gave an emitter's strength as intensity_per_m (the fog's
    // in-scatter next to it); version 3 as intensity_cd.
    bool isLegacyEmitterIntensity(ParamScope scope, sv key) const {
        return fileVersion_ < 3 && scope == ParamScope::Emitter && key == "intensity_per_m";
    }

    void readLegacyEmitter(std::int32_t node, const std::string& pointer) {
        LegacyEmitter legacy;
        if (const std::int32_t m = member(node, "intensity_per_m"); m >= 0)
            readNumber(m, pointerJoin(pointer, "intensity_per_m"), legacy.intensityPerM);
        legacy.attenuationGiven = member(node, "attenuation_per_m2") >= 0;
        legacyEmitters_.push_back(legacy);
    }

    // Version 2 -> 3 (preset.hpp, "Version 3"): each emitter's candela is
    // the one that scatters, in the fog its preset gives it (base values,
    // tracks not applied: fogScatteringAt), what intensity_per_m i did:
    //   I = 4 pi kNitsPerRadianceUnit i Y(colour) / (a sigma_s),
    // Y(colour) because version 3 divides the colour's luminance out. An
    // attenuation the file left out is version 2's default, 0.01; a = 0 (no
    // falloff, a field that never ended) becomes 1e-6. Keys of an
    // intensity_per_m track get the same factor.
    void migrateVersion2(Preset& preset) const {
        PresetState base;
        base.environment = preset.environment;
        base.volumes = preset.volumes;
        std::vector<double> factor(preset.emitters.size(), 0.0);
        for (std::size_t k = 0; k < preset.emitters.size() && k < legacyEmitters_.size(); ++k) {
            Emitter& e = preset.emitters[k];
            const LegacyEmitter& legacy = legacyEmitters_[k];
            if (!legacy.attenuationGiven) e.attenuation = 0.01;
            e.attenuation = std::max(e.attenuation, 1e-6);
            const double sigma = std::max(fogScatteringAt(base, e.position), 1e-9);
            factor[k] = 4.0 * kPi * kNitsPerRadianceUnit * luminance(glm::max(e.colour, glm::dvec3(0.0))) /
                        (e.attenuation * sigma);
            e.intensityCd = std::clamp(legacy.intensityPerM * factor[k], 0.0, 1e12);
        }
        for (const std::size_t t : legacyIntensityTracks_) {
            Track& track = preset.tracks[t];
            std::size_t k = preset.emitters.size();
            for (std::size_t j = 0; j < preset.emitters.size(); ++j)
                if (preset.emitters[j].id == track.target.objectId) k = j;
            if (k == preset.emitters.size()) continue;  // validation names the missing emitter
            for (TrackKey& key : track.keys) key.value.x = std::clamp(key.value.x * factor[k], 0.0, 1e12);
        }
    }

    // A group of global parameters ("atmosphere", "atmosphere.mie").
    void readGlobalGroup(Environment& env, std::int32_t node, const std::string& prefix,
                         const std::string& pointer) {
        if (!expectKind(node, pointer, JNode::Object)) return;
        for (std::int32_t c = nodes_[std::size_t(node)].firstChild; c >= 0;
             c = nodes_[std::size_t(c)].nextSibling) {
            const std::string& key = nodes_[std::size_t(c)].key;
            const std::string path = prefix + key;
            const std::string at = pointerJoin(pointer, key);
            if (const ParamDesc* p = findParam(ParamScope::Global, path)) {
                readParam(*p, &env, c, at);
            } else if (isGlobalGroup(path)) {
                readGlobalGroup(env, c, path + ".", at);
            } else {
                warnUnknown(c, at);
            }
        }
    }

    // Version 1 kept the moon 1000x brighter than the physical moon
    // (preset.hpp, kVersion1MoonScale); version 2 keeps it physical. A moon
    // intensity the file gives, and every key of its track, is converted;
    // one the file leaves out takes version 2's (physical) default.
    void migrateVersion1(Preset& preset, std::int32_t root) const {
        const std::int32_t moon = member(root, "moon");
        if (moon >= 0 && nodes_[std::size_t(moon)].kind == JNode::Object && member(moon, "intensity") >= 0)
            preset.environment.moon.intensity /= kVersion1MoonScale;
        for (Track& track : preset.tracks) {
            if (track.target.scope != ParamScope::Global || track.target.param != "moon.intensity") continue;
            for (TrackKey& key : track.keys) key.value /= kVersion1MoonScale;
        }
    }

    static bool isGlobalGroup(sv path) {
        for (const ParamDesc& p : paramTable(ParamScope::Global))
            if (p.path.size() > path.size() && p.path.substr(0, path.size()) == path &&
                p.path[path.size()] == '.')
                return true;
        return false;
    }

    // False (and an error) when an array holds more than `limit` elements.
    bool withinLimit(std::int32_t node, const std::string& pointer, std::size_t limit, const char* what) {
        const std::size_t count = nodes_[std::size_t(node)].childCount;
        if (count <= limit) return true;
        std::string m = std::to_string(count);
        m += " ";
        m += what;
        m += ", over the limit of ";
        m += std::to_string(limit);
        error(node, pointer, std::move(m));
        return false;
    }

    template <class Object>
    void readObjectArray(std::int32_t node, ParamScope scope, const std::string& pointer,
                         std::vector<Object>& out) {
        if (!expectKind(node, pointer, JNode::Array)) return;
        if (scope == ParamScope::Volume && !withinLimit(node, pointer, limits::kMaxVolumes, "volumes"))
            return;
        if (scope == ParamScope::Emitter && !withinLimit(node, pointer, limits::kMaxEmitters, "emitters"))
            return;
        if (scope == ParamScope::CloudVolume &&
            !withinLimit(node, pointer, limits::kMaxCloudVolumes, "cloud volumes"))
            return;
        out.reserve(nodes_[std::size_t(node)].childCount);
        std::size_t i = 0;
        for (std::int32_t c = nodes_[std::size_t(node)].firstChild; c >= 0;
             c = nodes_[std::size_t(c)].nextSibling, ++i) {
            const std::string at = pointerJoin(pointer, i);
            out.emplace_back();
            const bool object = expectKind(c, at, JNode::Object);
            if (object) readObject(scope, &out.back(), c, at);
            if (scope == ParamScope::Emitter && fileVersion_ < 3) {
                if (object)
                    readLegacyEmitter(c, at);
                else
                    legacyEmitters_.emplace_back();
            }
        }
    }

    void readTrack(std::int32_t node, const std::string& pointer, Track& track) {
        if (!expectKind(node, pointer, JNode::Object)) return;
        // The object key ("volume", "emitter", "cloud_volume") names the
        // scope; none is a global parameter's track.
        bool targeted = false;
        for (const ParamScope scope : kObjectScopes) {
            const sv key = trackObjectKey(scope);
            const std::int32_t object = member(node, key);
            if (object < 0) continue;
            const std::string at = pointerJoin(pointer, key);
            if (targeted) {
                error(object, at, "a track targets one volume, emitter or cloud volume, not several");
                continue;
            }
            targeted = true;
            track.target.scope = scope;
            if (expectKind(object, at, JNode::String))
                track.target.objectId = nodes_[std::size_t(object)].text;
        }
        const std::int32_t param = member(node, "param");
        if (param < 0)
            error(node, pointerJoin(pointer, "param"), "missing required field \"param\"");
        else if (expectKind(param, pointerJoin(pointer, "param"), JNode::String))
            track.target.param = nodes_[std::size_t(param)].text;
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
                error(wrap, at,
                      "wrap must be true (the day is cyclic) or false (hold the first and last keys)");
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
                            name != "offset_h" && name != "interpolation")
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

    void readPreset(Preset& preset) {
        const std::int32_t root = 0;
        if (!expectKind(root, "", JNode::Object)) return;
        const std::int32_t version = member(root, "version");
        if (version < 0) {
            error(root, "/version",
                  "missing \"version\" (this library reads versions 1 to " + std::to_string(kPresetVersion) +
                      ")");
            return;
        }
        const JNode& v = nodes_[std::size_t(version)];
        const bool integral = v.kind == JNode::Integer || v.kind == JNode::Unsigned ||
                              (v.kind == JNode::Float && std::trunc(v.number) == v.number);
        if (!integral) {
            error(version, "/version", std::string("expected an integer, got ") + kindName(v.kind));
            return;
        }
        if (v.asDouble() > kPresetVersion) {
            error(version, "/version",
                  "preset version " + formatDouble(v.asDouble()) + " is newer than this library reads (" +
                      std::to_string(kPresetVersion) + "); update Aerial to load it");
            return;
        }
        if (v.asDouble() < 1) {
            error(version, "/version", "unsupported version " + formatDouble(v.asDouble()));
            return;
        }
        const int fileVersion = int(v.asDouble());
        fileVersion_ = fileVersion;
        for (std::int32_t c = nodes_[0].firstChild; c >= 0; c = nodes_[std::size_t(c)].nextSibling) {
            const JNode& n = nodes_[std::size_t(c)];
            const std::string at = pointerJoin("", n.key);
            if (n.key == "version") continue;
            if (n.key == "name") {
                if (expectKind(c, at, JNode::String)) preset.name = n.text;
            } else if (n.key == "description") {
                if (expectKind(c, at, JNode::String)) preset.description = n.text;
            } else if (n.key == "volumes") {
                readObjectArray(c, ParamScope::Volume, at, preset.volumes);
            } else if (n.key == "emitters") {
                readObjectArray(c, ParamScope::Emitter, at, preset.emitters);
            } else if (n.key == "cloud_volumes") {
                readObjectArray(c, ParamScope::CloudVolume, at, preset.cloudVolumes);
            } else if (n.key == "tracks") {
                if (!expectKind(c, at, JNode::Array) || !withinLimit(c, at, limits::kMaxTracks, "tracks"))
                    continue;
                preset.tracks.reserve(n.childCount);
                std::size_t i = 0;
                for (std::int32_t t = n.firstChild; t >= 0; t = nodes_[std::size_t(t)].nextSibling, ++i) {
                    preset.tracks.emplace_back();
                    legacyTrack_ = false;
                    readTrack(t, pointerJoin(at, i), preset.tracks.back());
                    if (legacyTrack_) legacyIntensityTracks_.push_back(preset.tracks.size() - 1);
                }
            } else if (isGlobalGroup(n.key)) {
                readGlobalGroup(preset.environment, c, n.key + ".", at);
            } else {
                warnUnknown(c, at);
            }
        }
        if (fileVersion < 2) migrateVersion1(preset, root);
        if (fileVersion < 3) migrateVersion2(preset);
    }

    void checkDuplicateKeys() {
        for (std::size_t i = 0; i < nodes_.size(); ++i) {
            const JNode& n = nodes_[i];
            if (n.kind != JNode::Object || n.childCount < 2) continue;
            std::set<sv> seen;
            for (std::int32_t c = n.firstChild; c >= 0; c = nodes_[std::size_t(c)].nextSibling) {
                if (seen.insert(nodes_[std::size_t(c)].key).second) continue;
                if (errors.size() >= limits::kMaxPresetIssues) {  // pointerOf is not free: count only
                    ++suppressedErrors_;
                    continue;
                }
                issue(PresetIssue::Severity::Error, c, true, pointerOf(c),
                      "duplicate key " + quoteString(nodes_[std::size_t(c)].key));
            }
        }
    }

    std::string pointerOf(std::int32_t node) const { return pointerOfNode(nodes_, node); }

    // Adds validation issues, located in the file, unless the reader already
    // reported a problem at (or above) the same field.
    /// Two keys of a track less than a minute apart (the wrap from the last
    /// key to the first included): valid, but almost always one edit that
    /// wrote a second key beside the one it meant to change.
    void warnCloseKeys(const Preset& preset) {
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
                const std::string at =
                    pointerJoin(pointerJoin(pointerJoin("/tracks", i), "keys"), k) + (key.anchor ? "/anchor" : "/time_h");
                issue(PresetIssue::Severity::Warning, nodeAt(at), false, at,
                      "keys at " + formatClock(before.timeHours) + " and " + formatClock(key.timeHours) + " are " +
                          formatDouble(std::round(gap * 3600.0)) +
                          " s apart (under a minute): one key meant, two written? Remove one or move it");
            }
        }
    }

    void addValidation(std::vector<PresetIssue> issues) {
        for (PresetIssue& i : issues) {
            const bool covered = std::any_of(errors.begin(), errors.end(), [&](const PresetIssue& e) {
                return i.pointer.compare(0, e.pointer.size(), e.pointer) == 0 &&
                       (i.pointer.size() == e.pointer.size() || i.pointer[e.pointer.size()] == '/') &&
                       !e.pointer.empty();
            });
            if (covered) continue;
            if (errors.size() >= limits::kMaxPresetIssues) {
                ++suppressedErrors_;
                continue;
            }
            i.file = file_;
            positions_.push_back({true, errors.size(), nodes_[std::size_t(nodeAt(i.pointer))].offset});
            errors.push_back(std::move(i));
        }
    }

private:
    struct Position {
        bool error;
        std::size_t index;  // in errors or warnings
        std::size_t offset;
    };
    sv text_;
    std::string file_;
    const std::vector<JNode>& nodes_;
    std::vector<Position> positions_;
    std::size_t suppressedErrors_ = 0;
    std::size_t suppressedWarnings_ = 0;
    int fileVersion_ = kPresetVersion;
    /// Version <= 2 emitters, by index: the file's intensity_per_m (1 when
    /// left out, that version's default) and whether it gave the attenuation.
    struct LegacyEmitter {
        double intensityPerM = 1.0;
        bool attenuationGiven = false;
    };
    std::vector<LegacyEmitter> legacyEmitters_;
    /// Indices of the tracks on a version <= 2 emitter's intensity_per_m.
    std::vector<std::size_t> legacyIntensityTracks_;
    bool legacyTrack_ = false;
};

}  // namespace

void detail::readPresetTree(sv text, const std::string& file, const std::vector<JNode>& nodes, Preset& preset,
                            std::vector<PresetIssue>& errors, std::vector<PresetIssue>& warnings) {
    Reader reader(text, file, nodes);
    reader.checkDuplicateKeys();
    reader.readPreset(preset);
    const bool versionRefused = !reader.errors.empty() && reader.errors.front().pointer == "/version";
    if (!versionRefused && nodes[0].kind == JNode::Object) {
        // Anchored keys take their times from the location before the
        // checks, in the file's order (so issues point at the file's keys);
        // a valid file's keys are then already in order.
        for (Track& track : preset.tracks)
            for (TrackKey& key : track.keys) key.timeHours = anchoredKeyHours(key, preset.environment.location);
        reader.addValidation(validatePreset(preset));
        if (reader.errors.empty()) reader.warnCloseKeys(preset);
        if (reader.errors.empty()) {
            // Mesh volumes: their files, relative to the preset's folder.
            const std::filesystem::path folder = std::filesystem::path(file).parent_path();
            reader.addValidation(
                resolveFogMeshes(preset, file.empty() || file[0] == '<' ? "" : folder.string()));
        }
    }
    reader.finish();
    warnings = std::move(reader.warnings);
    errors = std::move(reader.errors);
}

}  // namespace aerial
