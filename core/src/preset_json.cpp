// preset_json.cpp — reading, validating and writing preset JSON
// (../shared/DESIGN.md, "Presets"), driven by the parameter table.
//
// Reading: nlohmann's SAX parser builds a small tree that keeps the byte
// offset of every value and member name (the offsets come from re-scanning
// the token sequence the SAX events describe), so every error can name its
// line and column. Then the table drives the conversion into a Preset, and
// validatePreset() checks the values; its JSON pointers are mapped back to
// positions in the file.
//
// Writing: our own emitter, stable key order (the table's), numbers in the
// shortest form that reads back bit-exact (std::to_chars).
#include <aerial/detail/file_system.hpp>
#include <aerial/limits.hpp>
#include <aerial/param_table.hpp>
#include <aerial/preset.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <string_view>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace aerial {
namespace {

using sv = std::string_view;

// ---------------------------------------------------------------------------
// Positions and pointers

std::string escapePointerToken(sv token) {
    std::string out;
    out.reserve(token.size());
    for (char c : token) {
        if (c == '~')
            out += "~0";
        else if (c == '/')
            out += "~1";
        else
            out += c;
    }
    return out;
}

std::string pointerJoin(const std::string& base, sv token) { return base + "/" + escapePointerToken(token); }
std::string pointerJoin(const std::string& base, std::size_t index) {
    return base + "/" + std::to_string(index);
}

// 1-based line and column (in UTF-8 code points) of a byte offset.
void lineColumn(sv text, std::size_t offset, int& line, int& column) {
    offset = std::min(offset, text.size());
    line = 1;
    column = 1;
    for (std::size_t i = 0; i < offset; ++i) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        if (c == '\n') {
            ++line;
            column = 1;
        } else if ((c & 0xC0) != 0x80) {
            ++column;
        }
    }
}

bool validUtf8(sv s) {
    std::size_t i = 0;
    while (i < s.size()) {
        const unsigned char c = static_cast<unsigned char>(s[i]);
        int extra;
        std::uint32_t cp;
        if (c < 0x80) {
            ++i;
            continue;
        } else if ((c & 0xE0) == 0xC0) {
            extra = 1, cp = c & 0x1F;
        } else if ((c & 0xF0) == 0xE0) {
            extra = 2, cp = c & 0x0F;
        } else if ((c & 0xF8) == 0xF0) {
            extra = 3, cp = c & 0x07;
        } else {
            return false;
        }
        if (i + std::size_t(extra) >= s.size()) return false;
        for (int k = 1; k <= extra; ++k) {
            const unsigned char cc = static_cast<unsigned char>(s[i + k]);
            if ((cc & 0xC0) != 0x80) return false;
            cp = (cp << 6) | (cc & 0x3F);
        }
        if ((extra == 1 && cp < 0x80) || (extra == 2 && cp < 0x800) || (extra == 3 && cp < 0x10000) ||
            cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF))
            return false;
        i += std::size_t(extra) + 1;
    }
    return true;
}

// `text` with every byte that is not part of valid UTF-8 written as \xNN,
// so messages quoting a broken file stay valid text.
std::string printable(sv text) {
    std::string out;
    out.reserve(text.size());
    std::size_t i = 0;
    while (i < text.size()) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        const std::size_t length = c < 0x80             ? 1
                                   : (c & 0xE0) == 0xC0 ? 2
                                   : (c & 0xF0) == 0xE0 ? 3
                                   : (c & 0xF8) == 0xF0 ? 4
                                                        : 0;
        if (length > 0 && i + length <= text.size() && validUtf8(text.substr(i, length))) {
            out.append(text.substr(i, length));
            i += length;
        } else {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\x%02X", c);
            out += buf;
            ++i;
        }
    }
    return out;
}

bool validId(sv id) {
    if (id.empty() || id.size() > 64) return false;
    for (char c : id) {
        const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                        c == '_' || c == '-' || c == '.';
        if (!ok) return false;
    }
    return true;
}

// ---------------------------------------------------------------------------
// Number formatting: shortest text that reads back to the same double.

std::string formatDouble(double v) {
    // Never written by savePreset (it validates first); in messages only.
    if (std::isnan(v)) return "nan";
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    std::string s(buf, r.ptr);
    // "-0" would read back as the integer 0 and lose its sign.
    if (s == "-0") s = "-0.0";
    return s;
}

std::string quoteString(sv s) {
    std::string out;
    out.reserve(s.size() + 2);
    out += '"';
    for (char ch : s) {
        const unsigned char c = static_cast<unsigned char>(ch);
        switch (c) {
            case '"':
                out += "\\\"";
                break;
            case '\\':
                out += "\\\\";
                break;
            case '\n':
                out += "\\n";
                break;
            case '\r':
                out += "\\r";
                break;
            case '\t':
                out += "\\t";
                break;
            case '\b':
                out += "\\b";
                break;
            case '\f':
                out += "\\f";
                break;
            default:
                if (c < 0x20) {
                    char buf[8];
                    std::snprintf(buf, sizeof buf, "\\u%04x", c);
                    out += buf;
                } else {
                    out += ch;
                }
        }
    }
    out += '"';
    return out;
}

// ---------------------------------------------------------------------------
// The positioned tree built from SAX events.

struct JNode {
    enum Kind : std::uint8_t { Null, Bool, Integer, Unsigned, Float, String, Array, Object };
    Kind kind = Null;
    bool boolean = false;
    std::int64_t integer = 0;
    std::uint64_t unsignedInteger = 0;
    double number = 0.0;
    std::string text;  // String value
    std::string key;   // member name when the parent is an object
    std::uint32_t offset = 0;
    std::uint32_t keyOffset = 0;
    std::int32_t parent = -1;
    std::int32_t firstChild = -1;
    std::int32_t lastChild = -1;
    std::int32_t nextSibling = -1;
    std::uint32_t childCount = 0;

    bool isNumber() const { return kind == Integer || kind == Unsigned || kind == Float; }
    double asDouble() const {
        return kind == Integer ? double(integer) : kind == Unsigned ? double(unsignedInteger) : number;
    }
};

const char* kindName(JNode::Kind k) {
    switch (k) {
        case JNode::Null:
            return "null";
        case JNode::Bool:
            return "a boolean";
        case JNode::Integer:
        case JNode::Unsigned:
        case JNode::Float:
            return "a number";
        case JNode::String:
            return "a string";
        case JNode::Array:
            return "an array";
        case JNode::Object:
            return "an object";
    }
    return "?";
}

struct SyntaxError {
    std::size_t offset = 0;
    std::string pointer;
    std::string message;
};

// The JSON pointer of a node, from its parents.
std::string pointerOfNode(const std::vector<JNode>& nodes, std::int32_t node) {
    std::vector<std::string> parts;
    while (node > 0) {
        const JNode& n = nodes[std::size_t(node)];
        const JNode& parent = nodes[std::size_t(n.parent)];
        if (parent.kind == JNode::Object) {
            parts.push_back(escapePointerToken(n.key));
        } else {
            std::size_t index = 0;
            for (std::int32_t c = parent.firstChild; c != node; c = nodes[std::size_t(c)].nextSibling)
                ++index;
            parts.push_back(std::to_string(index));
        }
        node = n.parent;
    }
    std::string out;
    for (auto it = parts.rbegin(); it != parts.rend(); ++it) out += "/" + *it;
    return out;
}

class TreeBuilder final : public nlohmann::json_sax<nlohmann::json> {
public:
    TreeBuilder(sv text, std::size_t start, std::vector<JNode>& nodes)
        : text_(text), nodes_(nodes), cursor_(start) {}

    bool null() override { return room() && add(JNode::Null); }
    bool boolean(bool v) override {
        if (!room()) return false;
        JNode& n = nodes_[std::size_t(addIndex(JNode::Bool))];
        n.boolean = v;
        return true;
    }
    bool number_integer(number_integer_t v) override {
        if (!room()) return false;
        nodes_[std::size_t(addIndex(JNode::Integer))].integer = v;
        return true;
    }
    bool number_unsigned(number_unsigned_t v) override {
        if (!room()) return false;
        nodes_[std::size_t(addIndex(JNode::Unsigned))].unsignedInteger = v;
        return true;
    }
    bool number_float(number_float_t v, const string_t&) override {
        if (!room()) return false;
        nodes_[std::size_t(addIndex(JNode::Float))].number = v;
        return true;
    }
    bool string(string_t& v) override {
        if (!room()) return false;
        nodes_[std::size_t(addIndex(JNode::String))].text = std::move(v);
        return true;
    }
    bool binary(binary_t&) override { return false; }
    bool start_object(std::size_t) override {
        if (!enter()) return false;
        stack_.push_back(addIndex(JNode::Object));
        return true;
    }
    bool key(string_t& v) override {
        pendingKeyOffset_ = std::uint32_t(nextToken());
        pendingKey_ = std::move(v);
        return true;
    }
    bool end_object() override {
        nextToken();
        stack_.pop_back();
        return true;
    }
    bool start_array(std::size_t) override {
        if (!enter()) return false;
        stack_.push_back(addIndex(JNode::Array));
        return true;
    }
    bool end_array() override {
        nextToken();
        stack_.pop_back();
        return true;
    }
    bool parse_error(std::size_t position, const std::string&,
                     const nlohmann::detail::exception& ex) override {
        // nlohmann counts the character it stopped at; report the start of
        // the offending token (after the last good one) when that is earlier.
        const std::size_t stop = std::min(position > 0 ? position - 1 : 0, text_.size());
        std::size_t start = cursor_;
        while (start < stop && isSpace(text_[start])) ++start;
        if (start < stop && (text_[start] == ',' || text_[start] == ':')) {
            ++start;
            while (start < stop && isSpace(text_[start])) ++start;
        }
        error.offset = std::min(start, stop);
        std::string what = ex.what();
        // "[json.exception.parse_error.101] parse error at line 1, column 2: reason"
        if (const std::size_t bracket = what.find("] ");
            what.rfind("[json.exception", 0) == 0 && bracket != std::string::npos)
            what.erase(0, bracket + 2);
        if (what.rfind("parse error", 0) == 0) {
            const std::size_t colon = what.find(": ");
            if (colon != std::string::npos) what.erase(0, colon + 2);
        }
        error.message = printable(what);
        pointAtOpenContainer();
        failed = true;
        return false;
    }

    SyntaxError error;
    bool failed = false;

private:
    static bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

    // Refuses the value about to be added when it would nest deeper than
    // limits::kMaxJsonDepth or make more than limits::kMaxJsonValues values
    // (the caps that keep the tree small whatever the file holds).
    bool enter() {
        if (stack_.size() < limits::kMaxJsonDepth) return room();
        refuse("nested deeper than " + std::to_string(limits::kMaxJsonDepth) + " levels (the limit)");
        return false;
    }
    bool room() {
        if (nodes_.size() < limits::kMaxJsonValues) return true;
        refuse("more than " + std::to_string(limits::kMaxJsonValues) + " JSON values (the limit)");
        return false;
    }

    // Where in the document: the open container and the member being read
    // (error.pointer; left alone at the top level).
    void pointAtOpenContainer() {
        if (stack_.empty()) return;
        const std::int32_t top = stack_.back();
        const JNode& n = nodes_[std::size_t(top)];
        error.pointer = pointerOfNode(nodes_, top);
        if (n.kind == JNode::Object && !pendingKey_.empty())
            error.pointer = pointerJoin(error.pointer, pendingKey_);
        else if (n.kind == JNode::Array)
            error.pointer = pointerJoin(error.pointer, std::size_t(n.childCount));
    }

    void refuse(std::string why) {
        std::size_t i = cursor_;
        while (i < text_.size() && (isSpace(text_[i]) || text_[i] == ',' || text_[i] == ':')) ++i;
        error.offset = i;
        pointAtOpenContainer();
        error.message = std::move(why);
        failed = true;
    }

    // The start of the next token after the previous one (skipping white
    // space and the ',' and ':' separators, which raise no SAX event), and
    // moves past it.
    std::size_t nextToken() {
        std::size_t i = cursor_;
        while (i < text_.size() && (isSpace(text_[i]) || text_[i] == ',' || text_[i] == ':')) ++i;
        const std::size_t start = i;
        if (i < text_.size()) {
            const char c = text_[i];
            if (c == '{' || c == '}' || c == '[' || c == ']') {
                ++i;
            } else if (c == '"') {
                ++i;
                while (i < text_.size() && text_[i] != '"') i += text_[i] == '\\' ? 2 : 1;
                ++i;
            } else {
                while (i < text_.size() && !isSpace(text_[i]) && text_[i] != ',' && text_[i] != ']' &&
                       text_[i] != '}' && text_[i] != ':')
                    ++i;
            }
        }
        cursor_ = std::min(i, text_.size());
        return start;
    }

    bool add(JNode::Kind kind) {
        addIndex(kind);
        return true;
    }

    std::int32_t addIndex(JNode::Kind kind) {
        const std::int32_t index = std::int32_t(nodes_.size());
        nodes_.emplace_back();
        JNode& n = nodes_.back();
        n.kind = kind;
        n.offset = std::uint32_t(nextToken());
        if (!stack_.empty()) {
            const std::int32_t parentIndex = stack_.back();
            JNode& parent = nodes_[std::size_t(parentIndex)];
            n.parent = parentIndex;
            if (parent.kind == JNode::Object) {
                n.key = std::move(pendingKey_);
                pendingKey_.clear();
                n.keyOffset = pendingKeyOffset_;
            }
            if (parent.lastChild >= 0)
                nodes_[std::size_t(parent.lastChild)].nextSibling = index;
            else
                parent.firstChild = index;
            parent.lastChild = index;
            ++parent.childCount;
        }
        return index;
    }

    sv text_;
    std::vector<JNode>& nodes_;
    std::vector<std::int32_t> stack_;
    std::size_t cursor_ = 0;
    std::string pendingKey_;
    std::uint32_t pendingKeyOffset_ = 0;
};

// ---------------------------------------------------------------------------
// Validation (shared by the loader and validatePreset).

struct Issues {
    std::vector<PresetIssue> list;
    void error(std::string pointer, std::string message) {
        PresetIssue i;
        i.severity = PresetIssue::Severity::Error;
        i.pointer = std::move(pointer);
        i.message = std::move(message);
        list.push_back(std::move(i));
    }
};

std::string rangeText(const ParamDesc& p) {
    return formatDouble(p.minValue) + ".." + formatDouble(p.maxValue);
}

void checkNumber(const ParamDesc& p, double v, const std::string& pointer, Issues& issues) {
    if (!std::isfinite(v)) {
        issues.error(pointer, "must be a finite number (got " + formatDouble(v) + ")");
    } else if (v < p.minValue || v > p.maxValue) {
        issues.error(pointer, "out of range: " + formatDouble(v) + " is not in " + rangeText(p) +
                                  (p.unit.empty() ? "" : " " + std::string(p.unit)));
    }
}

void checkText(const std::string& s, const std::string& pointer, Issues& issues) {
    if (s.size() > limits::kMaxStringBytes) {
        std::string m = "is ";
        m += std::to_string(s.size());
        m += " bytes long, over the limit of ";
        m += std::to_string(limits::kMaxStringBytes);
        issues.error(pointer, std::move(m));
    } else if (!validUtf8(s)) {
        issues.error(pointer, "must be valid UTF-8");
    }
}

void checkCount(std::size_t count, std::size_t limit, const char* pointer, const char* what, Issues& issues) {
    if (count <= limit) return;
    std::string m = std::to_string(count);
    m += " ";
    m += what;
    m += ", over the limit of ";
    m += std::to_string(limit);
    issues.error(pointer, std::move(m));
}

void checkParam(const ParamDesc& p, void* object, const std::string& pointer, Issues& issues) {
    switch (p.type) {
        case ParamType::Scalar:
            checkNumber(p, *p.scalar(object), pointer, issues);
            break;
        case ParamType::Colour:
        case ParamType::Vec3: {
            const glm::dvec3 v = *p.vec3(object);
            for (int c = 0; c < 3; ++c) checkNumber(p, v[c], pointerJoin(pointer, std::size_t(c)), issues);
            if (p.unitLength && std::isfinite(v.x + v.y + v.z)) {
                const double len = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
                if (!(std::abs(len - 1.0) <= 1e-6))
                    issues.error(pointer, "must be a unit vector (length " + formatDouble(len) + ")");
            }
            break;
        }
        case ParamType::Quaternion: {
            const glm::dquat q = *p.quat(object);
            const double c[4] = {q.x, q.y, q.z, q.w};
            bool finite = true;
            for (int i = 0; i < 4; ++i) {
                if (!std::isfinite(c[i])) {
                    issues.error(pointerJoin(pointer, std::size_t(i)),
                                 "must be a finite number (got " + formatDouble(c[i]) + ")");
                    finite = false;
                }
            }
            if (finite) {
                const double len = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2] + c[3] * c[3]);
                if (!(std::abs(len - 1.0) <= 1e-6))
                    issues.error(pointer, "must be a unit quaternion (length " + formatDouble(len) + ")");
            }
            break;
        }
        case ParamType::Enum:
        case ParamType::Int: {
            const std::int64_t v = p.getInt(object);
            if (double(v) < p.minValue || double(v) > p.maxValue)
                issues.error(pointer, "out of range: " + std::to_string(v) + " is not in " + rangeText(p));
            break;
        }
        case ParamType::String: {
            const std::string& s = *p.string(object);
            if (p.path == "id") {
                if (!validId(s))
                    issues.error(pointer, "an id must be 1..64 characters of A-Z a-z 0-9 _ - . (got " +
                                              quoteString(validUtf8(s) ? s : std::string("?")) + ")");
            } else {
                checkText(s, pointer, issues);
            }
            break;
        }
    }
}

template <class Object>
void checkObjects(std::vector<Object>& objects, ParamScope scope, const char* arrayKey, Issues& issues) {
    const std::string base = std::string("/") + arrayKey;
    for (std::size_t i = 0; i < objects.size(); ++i) {
        const std::string at = pointerJoin(base, i);
        for (const ParamDesc& p : paramTable(scope))
            checkParam(p, &objects[i], pointerJoin(at, p.path), issues);
        for (std::size_t j = 0; j < i; ++j) {
            if (objects[j].id == objects[i].id && !objects[i].id.empty()) {
                issues.error(pointerJoin(at, "id"), "duplicate id " + quoteString(objects[i].id) + " (also " +
                                                        pointerJoin(base, j) + ")");
                break;
            }
        }
    }
}

std::string globalPointer(sv path) {
    std::string out;
    std::size_t start = 0;
    while (true) {
        const std::size_t dot = path.find('.', start);
        out += "/";
        out += path.substr(start, dot == sv::npos ? sv::npos : dot - start);
        if (dot == sv::npos) break;
        start = dot + 1;
    }
    return out;
}

void validateInto(const Preset& constPreset, Issues& issues) {
    // The accessors take non-const objects; validation only reads.
    Preset& preset = const_cast<Preset&>(constPreset);
    checkText(preset.name, "/name", issues);
    checkText(preset.description, "/description", issues);
    checkCount(preset.volumes.size(), limits::kMaxVolumes, "/volumes", "volumes", issues);
    checkCount(preset.emitters.size(), limits::kMaxEmitters, "/emitters", "emitters", issues);
    checkCount(preset.tracks.size(), limits::kMaxTracks, "/tracks", "tracks", issues);
    for (const ParamDesc& p : paramTable(ParamScope::Global))
        checkParam(p, &preset.environment, globalPointer(p.path), issues);
    const AtmosphereParams& air = preset.environment.atmosphere;
    for (int c = 0; c < 3; ++c) {
        if (air.mieExtinction[c] < air.mieScattering[c])
            issues.error("/atmosphere/mie/extinction_per_m/" + std::to_string(c),
                         "Mie extinction " + formatDouble(air.mieExtinction[c]) +
                             " must be >= Mie scattering " + formatDouble(air.mieScattering[c]));
    }
    checkObjects(preset.volumes, ParamScope::Volume, "volumes", issues);
    checkObjects(preset.emitters, ParamScope::Emitter, "emitters", issues);

    for (std::size_t i = 0; i < preset.tracks.size(); ++i) {
        const Track& track = preset.tracks[i];
        const std::string at = pointerJoin("/tracks", i);
        const TrackTarget& target = track.target;
        const ParamDesc* p = findParam(target.scope, target.param);
        const char* objectKey = target.scope == ParamScope::Volume ? "volume" : "emitter";
        if (!p) {
            issues.error(pointerJoin(at, "param"), "unknown " + std::string(scopeName(target.scope)) +
                                                       " parameter " + quoteString(target.param));
        } else if (!p->animatable) {
            issues.error(pointerJoin(at, "param"),
                         "parameter " + quoteString(target.param) + " cannot be animated");
        }
        if (target.scope == ParamScope::Volume) {
            const bool found = std::any_of(preset.volumes.begin(), preset.volumes.end(),
                                           [&](const FogVolume& v) { return v.id == target.objectId; });
            if (!found)
                issues.error(pointerJoin(at, objectKey), "no volume with id " + quoteString(target.objectId));
        } else if (target.scope == ParamScope::Emitter) {
            const bool found = std::any_of(preset.emitters.begin(), preset.emitters.end(),
                                           [&](const Emitter& e) { return e.id == target.objectId; });
            if (!found)
                issues.error(pointerJoin(at, objectKey),
                             "no emitter with id " + quoteString(target.objectId));
        } else if (!target.objectId.empty()) {
            issues.error(at, "a global parameter's track has no object id");
        }
        for (std::size_t j = 0; j < i; ++j) {
            if (preset.tracks[j].target == target) {
                issues.error(pointerJoin(at, "param"),
                             "a second track for the same target (also " + pointerJoin("/tracks", j) + ")");
                break;
            }
        }
        if (int(track.interpolation) < 0 || int(track.interpolation) > 2)
            issues.error(pointerJoin(at, "interpolation"), "unknown interpolation");
        const std::string keysAt = pointerJoin(at, "keys");
        if (track.keys.empty()) issues.error(keysAt, "a track needs at least one key");
        checkCount(track.keys.size(), limits::kMaxKeysPerTrack, keysAt.c_str(), "keys", issues);
        for (std::size_t k = 0; k < track.keys.size(); ++k) {
            const TrackKey& key = track.keys[k];
            const std::string keyAt = pointerJoin(keysAt, k);
            const double t = key.timeHours;
            if (!std::isfinite(t) || t < 0.0 || t >= 24.0) {
                issues.error(pointerJoin(keyAt, "time_h"),
                             "a key's time must be in [0, 24) h (got " + formatDouble(t) + ")");
            } else if (k > 0 && !(t > track.keys[k - 1].timeHours)) {
                issues.error(pointerJoin(keyAt, "time_h"),
                             "key times must increase strictly (" + formatDouble(t) + " after " +
                                 formatDouble(track.keys[k - 1].timeHours) + ")");
            }
            if (!p || !p->animatable) continue;
            const std::string valueAt = pointerJoin(keyAt, "value");
            if (p->type == ParamType::Scalar) {
                checkNumber(*p, key.value.x, valueAt, issues);
            } else {
                for (int c = 0; c < 3; ++c)
                    checkNumber(*p, key.value[c], pointerJoin(valueAt, std::size_t(c)), issues);
            }
        }
    }
}

// ---------------------------------------------------------------------------
// Reader: tree -> Preset, driven by the table.

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
            if (!findParam(scope, nodes_[std::size_t(c)].key))
                warnUnknown(c, pointerJoin(pointer, nodes_[std::size_t(c)].key));
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
        out.reserve(nodes_[std::size_t(node)].childCount);
        std::size_t i = 0;
        for (std::int32_t c = nodes_[std::size_t(node)].firstChild; c >= 0;
             c = nodes_[std::size_t(c)].nextSibling, ++i) {
            const std::string at = pointerJoin(pointer, i);
            out.emplace_back();
            if (expectKind(c, at, JNode::Object)) readObject(scope, &out.back(), c, at);
        }
    }

    void readTrack(std::int32_t node, const std::string& pointer, Track& track) {
        if (!expectKind(node, pointer, JNode::Object)) return;
        const std::int32_t volume = member(node, "volume");
        const std::int32_t emitter = member(node, "emitter");
        const std::int32_t param = member(node, "param");
        if (volume >= 0 && emitter >= 0)
            error(emitter, pointerJoin(pointer, "emitter"),
                  "a track targets a volume or an emitter, not both");
        if (volume >= 0) {
            track.target.scope = ParamScope::Volume;
            if (expectKind(volume, pointerJoin(pointer, "volume"), JNode::String))
                track.target.objectId = nodes_[std::size_t(volume)].text;
        } else if (emitter >= 0) {
            track.target.scope = ParamScope::Emitter;
            if (expectKind(emitter, pointerJoin(pointer, "emitter"), JNode::String))
                track.target.objectId = nodes_[std::size_t(emitter)].text;
        }
        if (param < 0)
            error(node, pointerJoin(pointer, "param"), "missing required field \"param\"");
        else if (expectKind(param, pointerJoin(pointer, "param"), JNode::String))
            track.target.param = nodes_[std::size_t(param)].text;
        if (const std::int32_t interp = member(node, "interpolation"); interp >= 0) {
            const std::string at = pointerJoin(pointer, "interpolation");
            if (expectKind(interp, at, JNode::String) &&
                !parseInterpolation(nodes_[std::size_t(interp)].text, track.interpolation))
                error(interp, at,
                      "unknown interpolation " + quoteString(nodes_[std::size_t(interp)].text) +
                          "; expected one of step, linear, smooth");
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
                    if (time < 0)
                        error(c, pointerJoin(at, "time_h"), "missing required field \"time_h\"");
                    else
                        readNumber(time, pointerJoin(at, "time_h"), key.timeHours);
                    if (value < 0) {
                        error(c, pointerJoin(at, "value"), "missing required field \"value\"");
                    } else if (p && p->type == ParamType::Scalar) {
                        readNumber(value, pointerJoin(at, "value"), key.value.x);
                    } else if (p) {
                        double v[3];
                        if (readNumbers(value, pointerJoin(at, "value"), v, 3))
                            key.value = glm::dvec3(v[0], v[1], v[2]);
                    }
                    for (std::int32_t m = nodes_[std::size_t(c)].firstChild; m >= 0;
                         m = nodes_[std::size_t(m)].nextSibling) {
                        const std::string& name = nodes_[std::size_t(m)].key;
                        if (name != "time_h" && name != "value") warnUnknown(m, pointerJoin(at, name));
                    }
                }
                track.keys.push_back(key);
            }
        }
        for (std::int32_t m = nodes_[std::size_t(node)].firstChild; m >= 0;
             m = nodes_[std::size_t(m)].nextSibling) {
            const std::string& name = nodes_[std::size_t(m)].key;
            if (name != "volume" && name != "emitter" && name != "param" && name != "interpolation" &&
                name != "keys")
                warnUnknown(m, pointerJoin(pointer, name));
        }
    }

    void readPreset(Preset& preset) {
        const std::int32_t root = 0;
        if (!expectKind(root, "", JNode::Object)) return;
        const std::int32_t version = member(root, "version");
        if (version < 0) {
            error(root, "/version", "missing \"version\" (this library reads version 1)");
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
            } else if (n.key == "tracks") {
                if (!expectKind(c, at, JNode::Array) || !withinLimit(c, at, limits::kMaxTracks, "tracks"))
                    continue;
                preset.tracks.reserve(n.childCount);
                std::size_t i = 0;
                for (std::int32_t t = n.firstChild; t >= 0; t = nodes_[std::size_t(t)].nextSibling, ++i) {
                    preset.tracks.emplace_back();
                    readTrack(t, pointerJoin(at, i), preset.tracks.back());
                }
            } else if (isGlobalGroup(n.key)) {
                readGlobalGroup(preset.environment, c, n.key + ".", at);
            } else {
                warnUnknown(c, at);
            }
        }
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
};

// ---------------------------------------------------------------------------
// Writer.

class Writer {
public:
    std::string out;

    void newline(int depth) {
        out += '\n';
        out.append(std::size_t(depth) * 2, ' ');
    }
    void key(sv k) {
        out += quoteString(k);
        out += ": ";
    }
    void numbers(const double* v, int count) {
        out += '[';
        for (int i = 0; i < count; ++i) {
            if (i) out += ", ";
            out += formatDouble(v[i]);
        }
        out += ']';
    }
    void value(const ParamDesc& p, void* object) {
        switch (p.type) {
            case ParamType::Scalar:
                out += formatDouble(*p.scalar(object));
                break;
            case ParamType::Colour:
            case ParamType::Vec3: {
                const glm::dvec3 v = *p.vec3(object);
                const double c[3] = {v.x, v.y, v.z};
                numbers(c, 3);
                break;
            }
            case ParamType::Quaternion: {
                const glm::dquat q = *p.quat(object);
                const double c[4] = {q.x, q.y, q.z, q.w};
                numbers(c, 4);
                break;
            }
            case ParamType::Enum: {
                const std::int64_t v = p.getInt(object);
                out += v >= 0 && std::size_t(v) < p.enumNames.size()
                           ? quoteString(p.enumNames[std::size_t(v)])
                           : std::string("null");
                break;
            }
            case ParamType::Int:
                out += std::to_string(p.getInt(object));
                break;
            case ParamType::String:
                out += quoteString(*p.string(object));
                break;
        }
    }

    // Members of a scope's object, one per line, at `depth`.
    void objectMembers(ParamScope scope, void* object, int depth) {
        bool first = true;
        for (const ParamDesc& p : paramTable(scope)) {
            if (!first) out += ',';
            first = false;
            newline(depth);
            key(p.path);
            value(p, object);
        }
    }

    // The global table as nested groups, in table order.
    void globals(Environment& env) {
        std::vector<sv> open;  // currently open group names
        bool firstAtLevel = false;
        for (const ParamDesc& p : paramTable(ParamScope::Global)) {
            std::vector<sv> parts;
            std::size_t start = 0;
            while (true) {
                const std::size_t dot = p.path.find('.', start);
                parts.push_back(p.path.substr(start, dot == sv::npos ? sv::npos : dot - start));
                if (dot == sv::npos) break;
                start = dot + 1;
            }
            const std::size_t groups = parts.size() - 1;
            std::size_t common = 0;
            while (common < open.size() && common < groups && open[common] == parts[common]) ++common;
            while (open.size() > common) {
                open.pop_back();
                newline(int(open.size()) + 1);
                out += '}';
                firstAtLevel = false;
            }
            while (open.size() < groups) {
                if (!firstAtLevel) out += ',';
                newline(int(open.size()) + 1);
                key(parts[open.size()]);
                out += '{';
                open.push_back(parts[open.size()]);
                firstAtLevel = true;
            }
            if (!firstAtLevel) out += ',';
            firstAtLevel = false;
            newline(int(open.size()) + 1);
            key(parts.back());
            value(p, &env);
        }
        while (!open.empty()) {
            open.pop_back();
            newline(int(open.size()) + 1);
            out += '}';
        }
    }

    template <class Object>
    void objectArray(sv name, std::vector<Object>& objects, ParamScope scope) {
        out += ',';
        newline(1);
        key(name);
        if (objects.empty()) {
            out += "[]";
            return;
        }
        out += '[';
        for (std::size_t i = 0; i < objects.size(); ++i) {
            if (i) out += ',';
            newline(2);
            out += '{';
            objectMembers(scope, &objects[i], 3);
            newline(2);
            out += '}';
        }
        newline(1);
        out += ']';
    }

    void tracks(const std::vector<Track>& list) {
        out += ',';
        newline(1);
        key("tracks");
        if (list.empty()) {
            out += "[]";
            return;
        }
        out += '[';
        for (std::size_t i = 0; i < list.size(); ++i) {
            const Track& t = list[i];
            const ParamDesc* p = findParam(t.target.scope, t.target.param);
            const bool scalarValues = !p || p->type == ParamType::Scalar;
            if (i) out += ',';
            newline(2);
            out += '{';
            if (t.target.scope != ParamScope::Global) {
                newline(3);
                key(t.target.scope == ParamScope::Volume ? "volume" : "emitter");
                out += quoteString(t.target.objectId);
                out += ',';
            }
            newline(3);
            key("param");
            out += quoteString(t.target.param);
            out += ',';
            newline(3);
            key("interpolation");
            out += quoteString(int(t.interpolation) >= 0 && int(t.interpolation) <= 2
                                   ? interpolationName(t.interpolation)
                                   : sv("smooth"));
            out += ',';
            newline(3);
            key("keys");
            out += '[';
            for (std::size_t k = 0; k < t.keys.size(); ++k) {
                if (k) out += ',';
                newline(4);
                out += "{\"time_h\": " + formatDouble(t.keys[k].timeHours) + ", \"value\": ";
                if (scalarValues) {
                    out += formatDouble(t.keys[k].value.x);
                } else {
                    const double c[3] = {t.keys[k].value.x, t.keys[k].value.y, t.keys[k].value.z};
                    numbers(c, 3);
                }
                out += '}';
            }
            if (!t.keys.empty()) newline(3);
            out += ']';
            newline(2);
            out += '}';
        }
        newline(1);
        out += ']';
    }
};

std::string tooLargeMessage(std::size_t bytes, bool atLeast = false) {
    std::string m = atLeast ? "the file is at least " : "the file is ";
    m += std::to_string(bytes);
    m += " bytes, over the limit of ";
    m += std::to_string(limits::kMaxPresetFileBytes);
    m += " bytes (16 MiB) for a preset";
    return m;
}

PresetIssue makeIssue(std::string file, std::string message) {
    PresetIssue i;
    i.file = std::move(file);
    i.message = std::move(message);
    return i;
}

}  // namespace

// ---------------------------------------------------------------------------

std::string PresetIssue::toString() const {
    std::string s = file.empty() ? std::string("<preset>") : file;
    if (line > 0) s += ":" + std::to_string(line) + ":" + std::to_string(column);
    s += severity == Severity::Error ? ": error: " : ": warning: ";
    if (!pointer.empty()) s += pointer + ": ";
    s += message;
    return s;
}

std::vector<PresetIssue> validatePreset(const Preset& preset) {
    Issues issues;
    try {
        validateInto(preset, issues);
    } catch (const std::exception& e) {
        issues.error("", std::string("validation failed: ") + e.what());
    }
    return std::move(issues.list);
}

PresetLoadResult parsePreset(std::string_view jsonText, std::string_view fileName) {
    PresetLoadResult result;
    const std::string file(fileName);
    try {
        if (jsonText.size() > limits::kMaxPresetFileBytes) {
            result.errors.push_back(makeIssue(file, tooLargeMessage(jsonText.size())));
            return result;
        }
        const sv body = jsonText;
        // Text that is not UTF-8 JSON at all: say what it is.
        if (body.substr(0, 2) == "\xFF\xFE" || body.substr(0, 2) == "\xFE\xFF") {
            PresetIssue i = makeIssue(file, "UTF-16 text (byte order mark); a preset is UTF-8 JSON");
            i.line = i.column = 1;
            result.errors.push_back(std::move(i));
            return result;
        }
        if (const std::size_t nul = body.find('\0'); nul != sv::npos) {
            PresetIssue i = makeIssue(file, "a NUL byte: a preset is UTF-8 JSON text, not binary data");
            lineColumn(body, nul, i.line, i.column);
            result.errors.push_back(std::move(i));
            return result;
        }
        // nlohmann skips a UTF-8 byte order mark; so does the token re-scan.
        const std::size_t bom = body.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0;
        std::vector<JNode> nodes;
        nodes.reserve(std::min(jsonText.size() / 16 + 16, limits::kMaxJsonValues));
        TreeBuilder builder(body, bom, nodes);
        const bool parsed = nlohmann::json::sax_parse(body.begin(), body.end(), &builder,
                                                      nlohmann::json::input_format_t::json, true);
        if (!parsed || builder.failed) {
            PresetIssue i = makeIssue(file, builder.failed ? builder.error.message : "syntax error");
            i.pointer = builder.error.pointer;
            lineColumn(body, builder.error.offset, i.line, i.column);
            result.errors.push_back(std::move(i));
            return result;
        }
        Reader reader(body, file, nodes);
        reader.checkDuplicateKeys();
        Preset preset;
        reader.readPreset(preset);
        const bool versionRefused = !reader.errors.empty() && reader.errors.front().pointer == "/version";
        if (!versionRefused && nodes[0].kind == JNode::Object) reader.addValidation(validatePreset(preset));
        reader.finish();
        result.warnings = std::move(reader.warnings);
        result.errors = std::move(reader.errors);
        if (result.errors.empty()) result.preset = std::move(preset);
    } catch (const std::exception& e) {
        result.preset.reset();
        result.errors.push_back(makeIssue(file, std::string("could not load: ") + e.what()));
    } catch (...) {
        result.preset.reset();
        result.errors.push_back(makeIssue(file, "could not load: unknown failure"));
    }
    return result;
}

PresetLoadResult loadPreset(const std::string& path) {
    try {
        auto failed = [&](std::string message) {
            PresetLoadResult r;
            r.errors.push_back(makeIssue(path, std::move(message)));
            return r;
        };
        std::ifstream in(path, std::ios::binary);
        if (!in) return failed(std::string("cannot open: ") + std::strerror(errno));
        std::error_code ec;
        if (std::filesystem::is_directory(path, ec)) return failed("cannot open: Is a directory");
        // Never read more than the limit (plus one byte to tell it is over),
        // whatever the file (or a pipe, or /dev/zero) holds.
        std::string text;
        char chunk[65536];
        while (in && text.size() <= limits::kMaxPresetFileBytes) {
            in.read(chunk, sizeof chunk);
            text.append(chunk, std::size_t(in.gcount()));
        }
        if (in.bad()) return failed("read error");
        if (text.size() > limits::kMaxPresetFileBytes) {
            // The size on disk when there is one (a pipe or a device has none).
            const std::uintmax_t size = std::filesystem::file_size(path, ec);
            return failed(!ec && size >= text.size() ? tooLargeMessage(std::size_t(size))
                                                     : tooLargeMessage(text.size(), true));
        }
        return parsePreset(text, path);
    } catch (const std::exception& e) {
        PresetLoadResult r;
        r.errors.push_back(makeIssue(path, std::string("could not load: ") + e.what()));
        return r;
    }
}

std::string presetToJson(const Preset& constPreset) {
    Preset& preset = const_cast<Preset&>(constPreset);  // accessors are non-const; we only read
    Writer w;
    w.out.reserve(4096 + preset.volumes.size() * 600 + preset.tracks.size() * 400);
    w.out += '{';
    w.newline(1);
    w.key("version");
    w.out += std::to_string(kPresetVersion) + ",";
    w.newline(1);
    w.key("name");
    w.out += quoteString(preset.name) + ",";
    w.newline(1);
    w.key("description");
    w.out += quoteString(preset.description);  // globals() writes the separator
    w.globals(preset.environment);
    w.objectArray("volumes", preset.volumes, ParamScope::Volume);
    w.objectArray("emitters", preset.emitters, ParamScope::Emitter);
    w.tracks(preset.tracks);
    w.out += "\n}\n";
    return std::move(w.out);
}

SaveResult savePreset(const Preset& preset, const std::string& path) {
    SaveResult result;
    auto fail = [&](std::string message) {
        result.errors.push_back(makeIssue(path, std::move(message)));
        return result;
    };
    try {
        result.errors = validatePreset(preset);
        if (!result.errors.empty()) {
            for (PresetIssue& i : result.errors) {
                i.file = path;
                i.message = "not saved: " + i.message;
            }
            return result;
        }
        const std::string text = presetToJson(preset);
        const std::string why = detail::writeFileAtomically(path, text);
        if (!why.empty()) return fail("not saved: " + why);
    } catch (const std::exception& e) {
        return fail(std::string("not saved: ") + e.what());
    }
    return result;
}

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
        }
        return std::memcmp(u, v, sizeof u) == 0;
    };
    if (a.name != b.name || a.description != b.description) return false;
    for (const ParamDesc& p : paramTable(ParamScope::Global))
        if (!same(p, &a.environment, &b.environment)) return false;
    if (a.volumes.size() != b.volumes.size() || a.emitters.size() != b.emitters.size() ||
        a.tracks.size() != b.tracks.size())
        return false;
    for (std::size_t i = 0; i < a.volumes.size(); ++i)
        for (const ParamDesc& p : paramTable(ParamScope::Volume))
            if (!same(p, &a.volumes[i], &b.volumes[i])) return false;
    for (std::size_t i = 0; i < a.emitters.size(); ++i)
        for (const ParamDesc& p : paramTable(ParamScope::Emitter))
            if (!same(p, &a.emitters[i], &b.emitters[i])) return false;
    for (std::size_t i = 0; i < a.tracks.size(); ++i) {
        const Track& s = a.tracks[i];
        const Track& t = b.tracks[i];
        if (!(s.target == t.target) || s.interpolation != t.interpolation || s.keys.size() != t.keys.size())
            return false;
        for (std::size_t k = 0; k < s.keys.size(); ++k) {
            const double u[4] = {s.keys[k].timeHours, s.keys[k].value.x, s.keys[k].value.y,
                                 s.keys[k].value.z};
            const double v[4] = {t.keys[k].timeHours, t.keys[k].value.x, t.keys[k].value.y,
                                 t.keys[k].value.z};
            if (std::memcmp(u, v, sizeof u) != 0) return false;
        }
    }
    return true;
}

// ---------------------------------------------------------------------------
// Editing helpers.

Track* findTrack(Preset& preset, const TrackTarget& target) {
    for (Track& t : preset.tracks)
        if (t.target == target) return &t;
    return nullptr;
}

const Track* findTrack(const Preset& preset, const TrackTarget& target) {
    return findTrack(const_cast<Preset&>(preset), target);
}

namespace {

template <class Object>
bool changeId(std::vector<Object>& objects, std::vector<Track>& tracks, ParamScope scope,
              const std::string& oldId, const std::string& newId) {
    if (!validId(newId)) return false;
    Object* found = nullptr;
    for (Object& o : objects) {
        if (o.id == newId && newId != oldId) return false;
        if (o.id == oldId && !found) found = &o;
    }
    if (!found) return false;
    found->id = newId;
    for (Track& t : tracks)
        if (t.target.scope == scope && t.target.objectId == oldId) t.target.objectId = newId;
    return true;
}

template <class Object>
bool removeById(std::vector<Object>& objects, std::vector<Track>& tracks, ParamScope scope,
                const std::string& id) {
    const auto it = std::find_if(objects.begin(), objects.end(), [&](const Object& o) { return o.id == id; });
    if (it == objects.end()) return false;
    objects.erase(it);
    std::erase_if(tracks, [&](const Track& t) { return t.target.scope == scope && t.target.objectId == id; });
    return true;
}

}  // namespace

bool changeObjectId(Preset& preset, ParamScope scope, const std::string& oldId, const std::string& newId) {
    switch (scope) {
        case ParamScope::Volume:
            return changeId(preset.volumes, preset.tracks, scope, oldId, newId);
        case ParamScope::Emitter:
            return changeId(preset.emitters, preset.tracks, scope, oldId, newId);
        case ParamScope::Global:
            return false;
    }
    return false;
}

bool removeObject(Preset& preset, ParamScope scope, const std::string& id) {
    switch (scope) {
        case ParamScope::Volume:
            return removeById(preset.volumes, preset.tracks, scope, id);
        case ParamScope::Emitter:
            return removeById(preset.emitters, preset.tracks, scope, id);
        case ParamScope::Global:
            return false;
    }
    return false;
}

// ---------------------------------------------------------------------------
// JSON Schema, generated from the table.

namespace {

using ojson = nlohmann::ordered_json;

ojson schemaFor(const ParamDesc& p) {
    ojson s;
    std::string description(p.label);
    if (!p.unit.empty()) description += " [" + std::string(p.unit) + "]";
    description += ". " + std::string(p.doc);
    s["description"] = description;
    switch (p.type) {
        case ParamType::Scalar:
            s["type"] = "number";
            s["minimum"] = p.minValue;
            s["maximum"] = p.maxValue;
            s["default"] = p.defaultValue[0];
            break;
        case ParamType::Colour:
        case ParamType::Vec3:
            s["type"] = "array";
            s["items"] = {{"type", "number"}, {"minimum", p.minValue}, {"maximum", p.maxValue}};
            s["minItems"] = 3;
            s["maxItems"] = 3;
            s["default"] = {p.defaultValue[0], p.defaultValue[1], p.defaultValue[2]};
            break;
        case ParamType::Quaternion:
            s["type"] = "array";
            s["items"] = {{"type", "number"}, {"minimum", -1.000001}, {"maximum", 1.000001}};
            s["minItems"] = 4;
            s["maxItems"] = 4;
            s["default"] = {p.defaultValue[0], p.defaultValue[1], p.defaultValue[2], p.defaultValue[3]};
            break;
        case ParamType::Enum: {
            ojson names = ojson::array();
            for (sv n : p.enumNames) names.push_back(std::string(n));
            s["type"] = "string";
            s["enum"] = names;
            s["default"] = std::string(p.enumNames[std::size_t(p.defaultValue[0])]);
            break;
        }
        case ParamType::Int:
            s["type"] = "integer";
            s["minimum"] = std::int64_t(p.minValue);
            s["maximum"] = std::int64_t(p.maxValue);
            s["default"] = std::int64_t(p.defaultValue[0]);
            break;
        case ParamType::String:
            s["type"] = "string";
            if (p.path == "id") {
                s["pattern"] = "^[A-Za-z0-9_.-]{1,64}$";
            } else {
                s["default"] = std::string(p.defaultText);
            }
            break;
    }
    return s;
}

ojson objectSchema(ParamScope scope) {
    ojson s;
    s["type"] = "object";
    ojson props = ojson::object();
    ojson required = ojson::array();
    for (const ParamDesc& p : paramTable(scope)) {
        props[std::string(p.path)] = schemaFor(p);
        if (p.required) required.push_back(std::string(p.path));
    }
    s["properties"] = props;
    if (!required.empty()) s["required"] = required;
    s["additionalProperties"] = false;
    return s;
}

ojson animatableNames(ParamScope scope) {
    ojson names = ojson::array();
    for (const ParamDesc& p : paramTable(scope))
        if (p.animatable) names.push_back(std::string(p.path));
    return names;
}

}  // namespace

std::string presetJsonSchema() {
    ojson root;
    root["$schema"] = "https://json-schema.org/draft/2020-12/schema";
    root["$id"] = "https://aerial.example/aerial-preset.schema.json";
    root["title"] = "Aerial time-of-day preset";
    root["description"] =
        "Generated from the parameter table (aerial::presetJsonSchema(); core/src/param_table.cpp). "
        "Do not edit by hand.";
    root["type"] = "object";
    ojson props = ojson::object();
    props["version"] = {{"description", "File format version."}, {"const", kPresetVersion}};
    props["name"] = {{"type", "string"}};
    props["description"] = {{"type", "string"}};
    // Global groups, nested as in the file.
    for (const ParamDesc& p : paramTable(ParamScope::Global)) {
        ojson* node = &props;
        std::size_t start = 0;
        while (true) {
            const std::size_t dot = p.path.find('.', start);
            const std::string part(p.path.substr(start, dot == sv::npos ? sv::npos : dot - start));
            if (dot == sv::npos) {
                (*node)[part] = schemaFor(p);
                break;
            }
            ojson& group = (*node)[part];
            if (group.is_null()) {
                group["type"] = "object";
                group["properties"] = ojson::object();
                group["additionalProperties"] = false;
            }
            node = &group["properties"];
            start = dot + 1;
        }
    }
    props["volumes"] = {{"type", "array"}, {"items", {{"$ref", "#/$defs/volume"}}}};
    props["emitters"] = {{"type", "array"}, {"items", {{"$ref", "#/$defs/emitter"}}}};
    props["tracks"] = {{"type", "array"}, {"items", {{"$ref", "#/$defs/track"}}}};
    root["properties"] = props;
    root["required"] = {"version"};
    root["additionalProperties"] = false;

    ojson defs = ojson::object();
    defs["volume"] = objectSchema(ParamScope::Volume);
    defs["emitter"] = objectSchema(ParamScope::Emitter);
    ojson key;
    key["type"] = "object";
    key["properties"] = {
        {"time_h", {{"type", "number"}, {"minimum", 0}, {"exclusiveMaximum", 24}}},
        {"value",
         {{"oneOf",
           {{{"type", "number"}},
            {{"type", "array"}, {"items", {{"type", "number"}}}, {"minItems", 3}, {"maxItems", 3}}}}}}};
    key["required"] = {"time_h", "value"};
    key["additionalProperties"] = false;
    defs["key"] = key;
    auto trackVariant = [&](const char* objectKey, ParamScope scope) {
        ojson t;
        t["type"] = "object";
        ojson tp = ojson::object();
        if (objectKey) tp[objectKey] = {{"type", "string"}, {"pattern", "^[A-Za-z0-9_.-]{1,64}$"}};
        tp["param"] = {{"enum", animatableNames(scope)}};
        tp["interpolation"] = {{"enum", {"step", "linear", "smooth"}}, {"default", "smooth"}};
        tp["keys"] = {{"type", "array"}, {"minItems", 1}, {"items", {{"$ref", "#/$defs/key"}}}};
        t["properties"] = tp;
        ojson req = ojson::array();
        if (objectKey) req.push_back(objectKey);
        req.push_back("param");
        req.push_back("keys");
        t["required"] = req;
        t["additionalProperties"] = false;
        return t;
    };
    defs["track"] = {{"oneOf",
                      {trackVariant(nullptr, ParamScope::Global), trackVariant("volume", ParamScope::Volume),
                       trackVariant("emitter", ParamScope::Emitter)}}};
    root["$defs"] = defs;
    return root.dump(2) + "\n";
}

// ---------------------------------------------------------------------------

Preset defaultPreset() {
    Preset p;
    p.name = "Default";
    p.description =
        "Earth's atmosphere at 45 deg N in June; a light haze, a morning ground fog that burns off "
        "by noon and a lamp lit at night.";
    Environment& env = p.environment;
    // A full moon on the default day (172): night reads as moonlit.
    env.location.moonPhaseOffsetDays = 20.0;
    env.fog.density = 0.0004;
    env.fog.falloff = 0.02;
    env.fog.baseHeight = 0.0;

    FogVolume ground;
    ground.id = "ground_fog";
    ground.name = "Ground fog";
    ground.shape = FogVolumeShape::Ellipsoid;
    ground.position = {0.0, 0.0, -60.0};
    ground.halfExtents = {80.0, 12.0, 60.0};
    ground.density = 0.03;
    ground.falloff = 0.15;
    p.volumes.push_back(ground);

    Emitter lamp;
    lamp.id = "lamp";
    lamp.name = "Lamp";
    lamp.position = {6.0, 4.0, -20.0};
    lamp.intensity = 0.0;
    lamp.attenuation = 0.5;  // a glow of ~1.4 m half radius
    lamp.colour = {1.0, 0.72, 0.4};
    p.emitters.push_back(lamp);

    auto track = [](TrackTarget target, Interpolation interp, std::vector<TrackKey> keys) {
        Track t;
        t.target = std::move(target);
        t.interpolation = interp;
        t.keys = std::move(keys);
        return t;
    };
    p.tracks.push_back(track(TrackTarget::global("fog.density_per_m"), Interpolation::Smooth,
                             {{0.0, glm::dvec3(0.0006, 0, 0)},
                              {6.0, glm::dvec3(0.0012, 0, 0)},
                              {14.0, glm::dvec3(0.0002, 0, 0)},
                              {20.0, glm::dvec3(0.0004, 0, 0)}}));
    p.tracks.push_back(track(TrackTarget::volume("ground_fog", "density_per_m"), Interpolation::Smooth,
                             {{4.0, glm::dvec3(0.0)},
                              {6.5, glm::dvec3(0.035, 0, 0)},
                              {9.0, glm::dvec3(0.01, 0, 0)},
                              {12.0, glm::dvec3(0.0)}}));
    p.tracks.push_back(track(TrackTarget::emitter("lamp", "intensity_per_m"), Interpolation::Linear,
                             {{5.5, glm::dvec3(0.005, 0, 0)},
                              {6.5, glm::dvec3(0.0)},
                              {19.5, glm::dvec3(0.0)},
                              {20.5, glm::dvec3(0.005, 0, 0)}}));
    return p;
}

}  // namespace aerial
