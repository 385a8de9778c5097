// preset_reader.hpp — private to preset_read*.cpp: the reader of a
// preset's positioned JSON tree (preset_read.hpp), its issues with their
// line:column, and the file versions it migrates. preset_read.cpp holds the
// issues and the values, objects and the preset as a whole;
// preset_read_tracks.cpp the tracks; preset_read_versions.cpp the older
// versions' fields.
#pragma once

#include "json_tree.hpp"

#include <aerial/param_table.hpp>
#include <aerial/preset.hpp>

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace aerial::detail {

class Reader {
public:
    using sv = std::string_view;

    Reader(sv text, std::string file, const std::vector<JNode>& nodes)
        : text_(text), file_(std::move(file)), nodes_(nodes) {}

    std::vector<PresetIssue> errors;
    std::vector<PresetIssue> warnings;

    void issue(PresetIssue::Severity severity, std::int32_t node, bool atKey, std::string pointer,
               std::string message);

    // Fills in line:column of every issue (one pass over the text, however
    // many issues) and sums up the issues over limits::kMaxPresetIssues.
    void finish();

    void error(std::int32_t node, std::string pointer, std::string message);

    std::int32_t member(std::int32_t object, sv key) const;

    // The node a pointer names, or its deepest existing ancestor.
    std::int32_t nodeAt(sv pointer) const;

    bool expectKind(std::int32_t node, const std::string& pointer, JNode::Kind kind);

    bool readNumber(std::int32_t node, const std::string& pointer, double& out);

    bool readNumbers(std::int32_t node, const std::string& pointer, double* out, int count);

    void readParam(const ParamDesc& p, void* object, std::int32_t node, const std::string& pointer);

    // Unit vectors and quaternions in a file (docs: preset.hpp, "Numbers"):
    // finite, non-zero and off unit length by more than 1e-6 -> normalised,
    // with a warning; zero (or too small to have a direction) -> an error.
    // Non-finite components are left for validation to report.
    bool normaliseOrRefuse(std::int32_t node, const std::string& pointer, double* v, int n, const char* what);

    void warnUnknown(std::int32_t node, const std::string& pointer);

    // Reads the members of an object node that belong to a scope's table.
    void readObject(ParamScope scope, void* object, std::int32_t node, const std::string& pointer);

    // Version <= 2 gave an emitter's strength as intensity_per_m (the fog's
    // in-scatter next to it); version 3 as intensity_cd.
    bool isLegacyEmitterIntensity(ParamScope scope, sv key) const;

    void readLegacyEmitter(std::int32_t node, const std::string& pointer);

    // Version 2 -> 3 (preset.hpp, "Version 3"): each emitter's candela is
    // the one that scatters, in the fog its preset gives it (base values,
    // tracks not applied: fogScatteringAt), what intensity_per_m i did:
    //   I = 4 pi kNitsPerRadianceUnit i Y(colour) / (a sigma_s),
    // Y(colour) because version 3 divides the colour's luminance out. An
    // attenuation the file left out is version 2's default, 0.01; a = 0 (no
    // falloff, a field that never ended) becomes 1e-6. Keys of an
    // intensity_per_m track get the same factor.
    void migrateVersion2(Preset& preset) const;

    // A group of global parameters ("atmosphere", "atmosphere.mie").
    void readGlobalGroup(Environment& env, std::int32_t node, const std::string& prefix,
                         const std::string& pointer);

    // Version 1 kept the moon 1000x brighter than the physical moon
    // (preset.hpp, kVersion1MoonScale); version 2 keeps it physical. A moon
    // intensity the file gives, and every key of its track, is converted;
    // one the file leaves out takes version 2's (physical) default.
    void migrateVersion1(Preset& preset, std::int32_t root) const;

    static bool isGlobalGroup(sv path);

    // False (and an error) when an array holds more than `limit` elements.
    bool withinLimit(std::int32_t node, const std::string& pointer, std::size_t limit, const char* what);

    template <class Object>
    void readObjectArray(std::int32_t node, ParamScope scope, const std::string& pointer,
                         std::vector<Object>& out);

    void readTrack(std::int32_t node, const std::string& pointer, Track& track);
    /// A key's "tangent_in", "tangent_out" (both or neither; the value's
    /// shape) and "tangent_mode" into key.tangents (preset_read_tracks.cpp).
    void readKeyTangents(std::int32_t node, const std::string& at, const ParamDesc* p, TrackKey& key);

    /// A track's or a weather override's target: the object key ("volume",
    /// "emitter", "cloud_volume") names the scope (none: a global
    /// parameter), "param" the parameter (preset_read_weather.cpp).
    void readTarget(std::int32_t node, const std::string& pointer, const char* what, TrackTarget& target);

    /// "weather": {"states": [{"name", "overrides": [...]}], "regions":
    /// [...]} (weather_state.hpp); what names, targets and ranges mean is
    /// validatePreset's.
    void readWeather(std::int32_t node, const std::string& pointer, std::vector<WeatherState>& states,
                     std::vector<WeatherRegion>& regions);
    void readRegion(std::int32_t node, const std::string& pointer, WeatherRegion& region);
    void readOverride(std::int32_t node, const std::string& pointer, WeatherOverride& o);
    /// "view": {"eye_m", "target_m", "fov_deg"} (PresetView); eye_m and
    /// target_m are required, ranges are validatePreset's
    /// (preset_read_weather.cpp).
    void readView(std::int32_t node, const std::string& pointer, std::optional<PresetView>& view);
    void warnUnknownMembers(std::int32_t node, const std::string& pointer, std::initializer_list<sv> known);

    void readPreset(Preset& preset);

    void checkDuplicateKeys();

    std::string pointerOf(std::int32_t node) const { return pointerOfNode(nodes_, node); }

    /// Two keys of a track less than a minute apart (the wrap from the last
    /// key to the first included): valid, but almost always one edit that
    /// wrote a second key beside the one it meant to change.
    void warnCloseKeys(const Preset& preset);

    // Adds validation issues, located in the file, unless the reader already
    // reported a problem at (or above) the same field.
    void addValidation(std::vector<PresetIssue> issues);

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

}  // namespace aerial::detail
