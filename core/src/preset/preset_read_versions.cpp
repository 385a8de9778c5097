// preset_read_versions.cpp — reading older preset versions
// (preset_read.cpp, preset_reader.hpp; aerial/preset.hpp, kPresetVersion): the
// fields they named otherwise, and their migration to the current one.
#include "json_text.hpp"
#include "preset_reader.hpp"

#include <aerial/atmosphere.hpp>
#include <aerial/evaluate.hpp>
#include <aerial/exposure.hpp>
#include <aerial/param_table.hpp>

#include <algorithm>
#include <cstdint>

namespace aerial {

using namespace detail;
using sv = std::string_view;

bool Reader::isLegacyEmitterIntensity(ParamScope scope, sv key) const {
    return fileVersion_ < 3 && scope == ParamScope::Emitter && key == "intensity_per_m";
}

void Reader::readLegacyEmitter(std::int32_t node, const std::string& pointer) {
    LegacyEmitter legacy;
    if (const std::int32_t m = member(node, "intensity_per_m"); m >= 0)
        readNumber(m, pointerJoin(pointer, "intensity_per_m"), legacy.intensityPerM);
    legacy.attenuationGiven = member(node, "attenuation_per_m2") >= 0;
    legacyEmitters_.push_back(legacy);
}

void Reader::migrateVersion2(Preset& preset) const {
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

void Reader::readGlobalGroup(Environment& env, std::int32_t node, const std::string& prefix,
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

void Reader::migrateVersion1(Preset& preset, std::int32_t root) const {
    const std::int32_t moon = member(root, "moon");
    if (moon >= 0 && nodes_[std::size_t(moon)].kind == JNode::Object && member(moon, "intensity") >= 0)
        preset.environment.moon.intensity /= kVersion1MoonScale;
    for (Track& track : preset.tracks) {
        if (track.target.scope != ParamScope::Global || track.target.param != "moon.intensity") continue;
        for (TrackKey& key : track.keys) key.value /= kVersion1MoonScale;
    }
}

bool Reader::isGlobalGroup(sv path) {
    for (const ParamDesc& p : paramTable(ParamScope::Global))
        if (p.path.size() > path.size() && p.path.substr(0, path.size()) == path &&
            p.path[path.size()] == '.')
            return true;
    return false;
}

}  // namespace aerial
