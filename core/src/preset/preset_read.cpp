// preset_read.cpp — reading: the positioned JSON tree of a preset file into
// a Preset, driven by the parameter table (preset_read.hpp). Type errors,
// missing fields and values over a cap are errors at the field's
// line:column; unknown fields are warnings; non-unit directions are
// normalised with a warning (aerial/preset.hpp, "Numbers"). Validation
// issues are mapped back to positions in the file.
// The reader (preset_reader.hpp): here its issues, the values, objects and
// the preset as a whole; the tracks in preset_read_tracks.cpp, the older
// versions' fields in preset_read_versions.cpp.
#include "preset_read.hpp"

#include "json_text.hpp"
#include "preset_reader.hpp"
#include "preset_validate.hpp"

#include <aerial/limits.hpp>
#include <aerial/param_table.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <set>

namespace aerial {

using namespace detail;
using sv = std::string_view;

void Reader::issue(PresetIssue::Severity severity, std::int32_t node, bool atKey, std::string pointer,
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

void Reader::finish() {
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

void Reader::error(std::int32_t node, std::string pointer, std::string message) {
    issue(PresetIssue::Severity::Error, node, false, std::move(pointer), std::move(message));
}

std::int32_t Reader::member(std::int32_t object, sv key) const {
    for (std::int32_t c = nodes_[std::size_t(object)].firstChild; c >= 0;
         c = nodes_[std::size_t(c)].nextSibling)
        if (nodes_[std::size_t(c)].key == key) return c;
    return -1;
}

std::int32_t Reader::nodeAt(sv pointer) const {
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

bool Reader::expectKind(std::int32_t node, const std::string& pointer, JNode::Kind kind) {
    const JNode& n = nodes_[std::size_t(node)];
    if (n.kind == kind) return true;
    error(node, pointer, std::string("expected ") + kindName(kind) + ", got " + kindName(n.kind));
    return false;
}

bool Reader::readNumber(std::int32_t node, const std::string& pointer, double& out) {
    const JNode& n = nodes_[std::size_t(node)];
    if (!n.isNumber()) {
        error(node, pointer, std::string("expected a number, got ") + kindName(n.kind));
        return false;
    }
    out = n.asDouble();
    return true;
}

bool Reader::readNumbers(std::int32_t node, const std::string& pointer, double* out, int count) {
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

void Reader::readParam(const ParamDesc& p, void* object, std::int32_t node, const std::string& pointer) {
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
                error(node, pointer, "unknown value " + quoteString(n.text) + "; expected one of " + names);
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

bool Reader::normaliseOrRefuse(std::int32_t node, const std::string& pointer, double* v, int n,
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

void Reader::warnUnknown(std::int32_t node, const std::string& pointer) {
    issue(PresetIssue::Severity::Warning, node, true, pointer,
          "unknown field " + quoteString(nodes_[std::size_t(node)].key) + " (ignored)");
}

void Reader::readObject(ParamScope scope, void* object, std::int32_t node, const std::string& pointer) {
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

bool Reader::withinLimit(std::int32_t node, const std::string& pointer, std::size_t limit, const char* what) {
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
void Reader::readObjectArray(std::int32_t node, ParamScope scope, const std::string& pointer,
                             std::vector<Object>& out) {
    if (!expectKind(node, pointer, JNode::Array)) return;
    if (scope == ParamScope::Volume && !withinLimit(node, pointer, limits::kMaxVolumes, "volumes")) return;
    if (scope == ParamScope::Emitter && !withinLimit(node, pointer, limits::kMaxEmitters, "emitters")) return;
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

void Reader::readPreset(Preset& preset) {
    const std::int32_t root = 0;
    if (!expectKind(root, "", JNode::Object)) return;
    const std::int32_t version = member(root, "version");
    if (version < 0) {
        error(
            root, "/version",
            "missing \"version\" (this library reads versions 1 to " + std::to_string(kPresetVersion) + ")");
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
        } else if (n.key == "weather") {
            readWeather(c, at, preset.weather, preset.weatherRegions);
        } else if (n.key == "view") {
            readView(c, at, preset.view);
        } else if (isGlobalGroup(n.key)) {
            readGlobalGroup(preset.environment, c, n.key + ".", at);
        } else {
            warnUnknown(c, at);
        }
    }
    if (fileVersion < 2) migrateVersion1(preset, root);
    if (fileVersion < 3) migrateVersion2(preset);
}

void Reader::checkDuplicateKeys() {
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

void Reader::addValidation(std::vector<PresetIssue> issues) {
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
            for (TrackKey& key : track.keys)
                key.timeHours = anchoredKeyHours(key, preset.environment.location);
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
