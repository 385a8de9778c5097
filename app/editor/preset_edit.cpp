// editor/preset_edit.cpp — see preset_edit.hpp.
#include "preset_edit.hpp"

#include "document.hpp"
#include "weather_edit.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>

namespace aerial::editor {
namespace {

/// Numbers in a track key of an animatable parameter: 1 (Scalar), 2 (Vec2,
/// in value.x, .y) or 3 (Colour, Vec3).
int trackComponents(const ParamDesc& desc) { return desc.components(); }

/// Concatenation by appends (GCC 12 warns falsely on `"x" + std::string`).
template <class... Parts>
std::string cat(const Parts&... parts) {
    std::string out;
    (out.append(std::string_view(parts)), ...);
    return out;
}

bool parseIndex(std::string_view text, int& out) {
    if (text.empty() || text.size() > 9) return false;
    int v = 0;
    for (char c : text) {
        if (c < '0' || c > '9') return false;
        v = v * 10 + (c - '0');
    }
    out = v;
    return true;
}

const std::string* objectId(const Preset& preset, const ParamRef& ref) {
    if (ref.object < 0 || std::size_t(ref.object) >= objectCount(preset, ref.scope())) return nullptr;
    const std::size_t i = std::size_t(ref.object);
    switch (ref.scope()) {
        case ParamScope::Volume:
            return &preset.volumes[i].id;
        case ParamScope::Emitter:
            return &preset.emitters[i].id;
        case ParamScope::CloudVolume:
            return &preset.cloudVolumes[i].id;
        case ParamScope::Global:
            return nullptr;
    }
    return nullptr;
}

}  // namespace

std::size_t objectCount(const Preset& preset, ParamScope scope) {
    switch (scope) {
        case ParamScope::Volume:
            return preset.volumes.size();
        case ParamScope::Emitter:
            return preset.emitters.size();
        case ParamScope::CloudVolume:
            return preset.cloudVolumes.size();
        case ParamScope::Global:
            return 0;
    }
    return 0;
}

std::string_view addressPrefix(ParamScope scope) { return scopeKey(scope); }

std::optional<ParamRef> parseParamAddress(const Preset& preset, std::string_view address,
                                          std::string* error) {
    auto fail = [&](std::string why) -> std::optional<ParamRef> {
        if (error) *error = std::move(why);
        return std::nullopt;
    };
    ParamScope scope = ParamScope::Global;
    std::string_view key = address;
    int index = -1;
    for (ParamScope s : {ParamScope::Volume, ParamScope::Emitter, ParamScope::CloudVolume}) {
        const std::string prefix = cat(addressPrefix(s), "[");
        if (address.substr(0, prefix.size()) != prefix) continue;
        const std::size_t close = address.find("].", prefix.size());
        if (close == std::string_view::npos ||
            !parseIndex(address.substr(prefix.size(), close - prefix.size()), index))
            return fail(cat("\"", address, "\": expected ", prefix, "N].KEY"));
        const std::size_t count = objectCount(preset, s);
        if (std::size_t(index) >= count)
            return fail(cat("\"", address, "\": there are ", std::to_string(count), " ", scopeName(s), "s"));
        scope = s;
        key = address.substr(close + 2);
    }
    const ParamDesc* desc = findParam(scope, key);
    if (!desc)
        return fail(cat("\"", address, "\": no ", scopeName(scope), " parameter \"", key,
                        "\" in the parameter table"));
    return ParamRef{desc, index};
}

std::string paramAddress(const ParamRef& ref) {
    if (!ref.desc) return {};
    std::string out;
    if (ref.scope() != ParamScope::Global) {
        out = addressPrefix(ref.scope());
        out += '[';
        out += std::to_string(ref.object);
        out += "].";
    }
    out += ref.desc->path;
    return out;
}

void* paramObjectOf(Preset& preset, const ParamRef& ref) {
    switch (ref.scope()) {
        case ParamScope::Global:
            return &preset.environment;
        case ParamScope::Volume:
            return ref.object >= 0 && ref.object < int(preset.volumes.size())
                       ? &preset.volumes[std::size_t(ref.object)]
                       : nullptr;
        case ParamScope::Emitter:
            return ref.object >= 0 && ref.object < int(preset.emitters.size())
                       ? &preset.emitters[std::size_t(ref.object)]
                       : nullptr;
        case ParamScope::CloudVolume:
            return ref.object >= 0 && ref.object < int(preset.cloudVolumes.size())
                       ? &preset.cloudVolumes[std::size_t(ref.object)]
                       : nullptr;
    }
    return nullptr;
}

const void* paramObjectOf(const Preset& preset, const ParamRef& ref) {
    return paramObjectOf(const_cast<Preset&>(preset), ref);
}

TrackTarget trackTargetOf(const Preset& preset, const ParamRef& ref) {
    TrackTarget target;
    target.scope = ref.scope();
    target.param = ref.desc ? std::string(ref.desc->path) : std::string();
    if (const std::string* id = objectId(preset, ref)) target.objectId = *id;
    return target;
}

const Track* trackOf(const Preset& preset, const ParamRef& ref) {
    if (!ref.desc || !ref.desc->animatable) return nullptr;
    return findTrack(preset, trackTargetOf(preset, ref));
}

Track* trackOf(Preset& preset, const ParamRef& ref) {
    if (!ref.desc || !ref.desc->animatable) return nullptr;
    return findTrack(preset, trackTargetOf(preset, ref));
}

void readBaseValue(const Preset& preset, const ParamRef& ref, double out[4]) {
    out[0] = out[1] = out[2] = out[3] = 0.0;
    void* object = const_cast<void*>(paramObjectOf(preset, ref));
    if (!object || !ref.desc) return;
    const ParamDesc& p = *ref.desc;
    switch (p.type) {
        case ParamType::Scalar:
            out[0] = *p.scalar(object);
            break;
        case ParamType::Colour:
        case ParamType::Vec3: {
            const glm::dvec3& v = *p.vec3(object);
            out[0] = v.x, out[1] = v.y, out[2] = v.z;
            break;
        }
        case ParamType::Vec2: {
            const glm::dvec2& v = *p.vec2(object);
            out[0] = v.x, out[1] = v.y;
            break;
        }
        case ParamType::Quaternion: {
            const glm::dquat& q = *p.quat(object);
            out[0] = q.x, out[1] = q.y, out[2] = q.z, out[3] = q.w;
            break;
        }
        case ParamType::Enum:
        case ParamType::Int:
            out[0] = double(p.getInt(object));
            break;
        case ParamType::String:
            break;
    }
}

void readValueAt(const Preset& preset, const ParamRef& ref, double timeHours, double out[4]) {
    readBaseValue(preset, ref, out);
    if (const Track* track = trackOf(preset, ref); track && !track->keys.empty()) {
        const int components = trackComponents(*ref.desc);
        const glm::dvec3 v = evaluateTrack(*track, timeHours, components);
        for (int c = 0; c < components; ++c) out[c] = v[c];
    }
}

// The value of a track key (Scalar, Colour, Vec3, Vec2) as setValueAt
// writes it: non-finite components 0, clamped into the valid range, unit
// vectors normalised; false for a unit vector of no length.
static bool animatedValueOf(const ParamDesc& p, const double value[4], glm::dvec3& out) {
    const auto clampValue = [&](double v) {
        return std::clamp(std::isfinite(v) ? v : 0.0, p.minValue, p.maxValue);
    };
    switch (p.type) {
        case ParamType::Scalar:
            out = glm::dvec3(clampValue(value[0]), 0.0, 0.0);
            return true;
        case ParamType::Colour:
        case ParamType::Vec3: {
            out = glm::dvec3(clampValue(value[0]), clampValue(value[1]), clampValue(value[2]));
            if (!p.unitLength) return true;
            const double length = glm::length(out);
            if (!(length > 1e-9)) return false;
            out /= length;
            return true;
        }
        case ParamType::Vec2:
            out = glm::dvec3(clampValue(value[0]), clampValue(value[1]), 0.0);
            return true;
        default:
            return false;
    }
}

bool setTrackValueAt(Track& track, const ParamDesc& desc, const double value[4], double timeHours) {
    glm::dvec3 v;
    if (!animatedValueOf(desc, value, v)) return false;
    // An edit at a key (within kKeyTimeTolerance, where the inspector shows
    // "keyed here") changes that key at its own time, never a second key
    // beside it.
    const int k = keyIndexAt(track, timeHours);
    setKey(track, k >= 0 ? track.keys[std::size_t(k)].timeHours : timeHours, v);
    return true;
}

void setValueAt(Preset& preset, const ParamRef& ref, const double value[4], double timeHours) {
    void* object = paramObjectOf(preset, ref);
    if (!object || !ref.desc) return;
    const ParamDesc& p = *ref.desc;
    auto clampValue = [&](double v) {
        if (!std::isfinite(v)) v = 0.0;
        return std::clamp(v, p.minValue, p.maxValue);
    };
    switch (p.type) {
        case ParamType::Scalar:
        case ParamType::Colour:
        case ParamType::Vec3:
        case ParamType::Vec2: {
            if (Track* track = trackOf(preset, ref)) {
                setTrackValueAt(*track, p, value, timeHours);
                break;
            }
            glm::dvec3 v;
            if (!animatedValueOf(p, value, v)) return;
            if (p.type == ParamType::Scalar)
                *p.scalar(object) = v.x;
            else if (p.type == ParamType::Vec2)
                *p.vec2(object) = glm::dvec2(v.x, v.y);
            else
                *p.vec3(object) = v;
            break;
        }
        case ParamType::Quaternion: {
            glm::dquat q(value[3], value[0], value[1], value[2]);
            const double length = glm::length(q);
            if (!(length > 1e-9) || !std::isfinite(length)) return;
            *p.quat(object) = q / length;
            break;
        }
        case ParamType::Enum:
        case ParamType::Int: {
            double v = std::round(value[0]);
            if (p.type == ParamType::Enum)
                v = std::clamp(v, 0.0, double(std::max<std::size_t>(p.enumNames.size(), 1) - 1));
            else
                v = clampValue(v);
            p.setInt(object, std::int64_t(v));
            break;
        }
        case ParamType::String:
            break;
    }
}

int keyIndexAt(const Track& track, double timeHours) {
    const double t = wrapHours(timeHours);
    for (std::size_t i = 0; i < track.keys.size(); ++i) {
        double d = std::abs(track.keys[i].timeHours - t);
        d = std::min(d, 24.0 - d);
        if (d <= kKeyTimeTolerance) return int(i);
    }
    return -1;
}

bool keyParam(Preset& preset, const ParamRef& ref, double timeHours) {
    if (!ref.desc || !ref.desc->animatable || !paramObjectOf(preset, ref)) return false;
    double value[4];
    readValueAt(preset, ref, timeHours, value);
    Track* track = trackOf(preset, ref);
    if (!track) {
        Track fresh;
        fresh.target = trackTargetOf(preset, ref);
        fresh.interpolation = Interpolation::Smooth;
        preset.tracks.push_back(std::move(fresh));
        track = &preset.tracks.back();
    }
    const int existing = keyIndexAt(*track, timeHours);
    const double t = existing >= 0 ? track->keys[std::size_t(existing)].timeHours : wrapHours(timeHours);
    glm::dvec3 key(value[0], value[1], value[2]);
    for (int c = trackComponents(*ref.desc); c < 3; ++c) key[c] = 0.0;
    setKey(*track, t, key);
    return true;
}

bool removeKey(Preset& preset, const TrackTarget& target, int index) {
    for (auto it = preset.tracks.begin(); it != preset.tracks.end(); ++it) {
        if (!(it->target == target)) continue;
        if (index < 0 || index >= int(it->keys.size())) return false;
        it->keys.erase(it->keys.begin() + index);
        if (it->keys.empty()) preset.tracks.erase(it);
        return true;
    }
    return false;
}

double moveKey(Track& track, int index, double timeHours) {
    if (index < 0 || index >= int(track.keys.size())) return 0.0;
    const std::size_t i = std::size_t(index);
    double lo = 0.0, hi = 24.0 - kMinKeyGap;
    if (i > 0) lo = track.keys[i - 1].timeHours + kMinKeyGap;
    if (i + 1 < track.keys.size()) hi = track.keys[i + 1].timeHours - kMinKeyGap;
    double t = std::isfinite(timeHours) ? timeHours : track.keys[i].timeHours;
    if (lo <= hi)
        t = std::clamp(t, lo, hi);
    else
        t = track.keys[i].timeHours;
    setKeyTime(track.keys[i], t);  // an anchored key keeps its anchor, its offset moves
    return t;
}

int keyAllChanged(Preset& preset, const Preset& baseline, double timeHours) {
    int count = 0;
    auto keyIfChanged = [&](const ParamRef& ref, const ParamRef& baseRef) {
        if (!ref.desc->animatable) return;
        double now[4], before[4];
        readValueAt(preset, ref, timeHours, now);
        readValueAt(baseline, baseRef, timeHours, before);
        bool same = true;
        for (int c = 0; c < 3; ++c) same = same && now[c] == before[c];
        if (same) return;
        if (const Track* track = trackOf(preset, ref); track && keyIndexAt(*track, timeHours) >= 0) {
            // Already keyed here with this value: nothing to add.
            double keyed[4];
            readValueAt(preset, ref, track->keys[std::size_t(keyIndexAt(*track, timeHours))].timeHours,
                        keyed);
            if (keyed[0] == now[0] && keyed[1] == now[1] && keyed[2] == now[2]) return;
        }
        if (keyParam(preset, ref, timeHours)) ++count;
    };
    for (const ParamDesc& p : paramTable(ParamScope::Global)) keyIfChanged({&p, -1}, {&p, -1});
    for (std::size_t i = 0; i < preset.volumes.size(); ++i)
        for (std::size_t b = 0; b < baseline.volumes.size(); ++b)
            if (baseline.volumes[b].id == preset.volumes[i].id)
                for (const ParamDesc& p : paramTable(ParamScope::Volume))
                    keyIfChanged({&p, int(i)}, {&p, int(b)});
    for (std::size_t i = 0; i < preset.emitters.size(); ++i)
        for (std::size_t b = 0; b < baseline.emitters.size(); ++b)
            if (baseline.emitters[b].id == preset.emitters[i].id)
                for (const ParamDesc& p : paramTable(ParamScope::Emitter))
                    keyIfChanged({&p, int(i)}, {&p, int(b)});
    for (std::size_t i = 0; i < preset.cloudVolumes.size(); ++i)
        for (std::size_t b = 0; b < baseline.cloudVolumes.size(); ++b)
            if (baseline.cloudVolumes[b].id == preset.cloudVolumes[i].id)
                for (const ParamDesc& p : paramTable(ParamScope::CloudVolume))
                    keyIfChanged({&p, int(i)}, {&p, int(b)});
    return count;
}

bool pasteKey(Preset& preset, const ParamRef& ref, const KeyClipboard& clip, double timeHours) {
    if (!clip.valid || !ref.desc || !ref.desc->animatable || !paramObjectOf(preset, ref)) return false;
    // A key fits a parameter with as many numbers (a colour's key fits a
    // Vec3, a Vec2's only a Vec2).
    if (ParamDesc::componentCount(clip.type) != trackComponents(*ref.desc)) return false;
    if (!keyParam(preset, ref, timeHours)) return false;
    const double value[4] = {clip.value.x, clip.value.y, clip.value.z, 0.0};
    setValueAt(preset, ref, value, timeHours);  // the track exists now: sets the key
    return true;
}

/// A unique id from `base` (uniqueObjectId) and the name shown for it:
/// `label`, followed by the id's number when `base` itself was taken.
static void nameNewObject(const Preset& preset, ParamScope scope, const std::string& base, const char* label,
                          std::string& id, std::string& name) {
    id = uniqueObjectId(preset, scope, base);
    name = label;
    if (id != base) {
        name += ' ';
        name += id.substr(id.rfind('_') + 1);
    }
}

int addVolume(Preset& preset, FogVolumeShape shape, const glm::dvec3& position) {
    FogVolume v;
    const bool box = shape == FogVolumeShape::Box;
    nameNewObject(preset, ParamScope::Volume, box ? "box_volume" : "ellipsoid_volume",
                  box ? "Box volume" : "Ellipsoid volume", v.id, v.name);
    v.shape = shape;
    v.position = position;
    preset.volumes.push_back(v);
    return int(preset.volumes.size()) - 1;
}

int addMeshVolume(Preset& preset, const std::string& meshPath, std::shared_ptr<const FogMesh> mesh,
                  const glm::dvec3& ground, const std::string& label) {
    FogVolume v;
    nameNewObject(preset, ParamScope::Volume, "mesh_volume", "Mesh volume", v.id, v.name);
    if (!label.empty() && v.id == "mesh_volume") v.name = label;  // the file's stem reads better
    v.shape = FogVolumeShape::Mesh;
    v.halfExtents = glm::dvec3(1.0);
    v.position = ground;
    if (mesh) v.position.y -= mesh->boundsMin().y;  // resting on the surface
    v.mesh = meshPath;
    v.meshData = std::move(mesh);
    preset.volumes.push_back(v);
    return int(preset.volumes.size()) - 1;
}

std::string meshPathFor(const std::string& meshFile, const std::string& presetPath) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path absolute = fs::absolute(meshFile, ec).lexically_normal();
    if (ec) return meshFile;
    if (presetPath.empty()) return absolute.generic_string();
    const fs::path folder = fs::absolute(presetPath, ec).parent_path();
    const fs::path relative = absolute.lexically_relative(folder);
    return ec || relative.empty() ? absolute.generic_string() : relative.generic_string();
}

int rebaseMeshPaths(Preset& preset, const std::string& fromFolder, const std::string& toFolder) {
    namespace fs = std::filesystem;
    int changed = 0;
    std::error_code ec;
    const fs::path from = fs::absolute(fromFolder.empty() ? fs::path(".") : fs::path(fromFolder), ec);
    const fs::path to = toFolder.empty() ? fs::path() : fs::absolute(toFolder, ec);
    for (FogVolume& v : preset.volumes) {
        if (v.mesh.empty() || (to.empty() && fs::path(v.mesh).is_absolute())) continue;
        const fs::path absolute = fs::path(v.mesh).is_absolute() ? fs::path(v.mesh).lexically_normal()
                                                                 : (from / v.mesh).lexically_normal();
        const fs::path relative = to.empty() ? fs::path() : absolute.lexically_relative(to);
        const std::string rebased = relative.empty() ? absolute.generic_string() : relative.generic_string();
        if (rebased != v.mesh) {
            v.mesh = rebased;
            ++changed;
        }
    }
    return changed;
}

int addEmitter(Preset& preset, EmitterKind kind, const glm::dvec3& position) {
    Emitter e;
    const bool lightning = kind == EmitterKind::Lightning;
    nameNewObject(preset, ParamScope::Emitter, lightning ? "lightning" : "emitter",
                  lightning ? "Lightning" : "Emitter", e.id, e.name);
    e.kind = kind;
    e.position = position;
    if (lightning) {
        e.colour = {0.8, 0.85, 1.0};
        e.intensityCd = kNewLightningIntensityCd;
        e.attenuation = kNewLightningAttenuationPerM2;
    } else {
        e.intensityCd = kNewEmitterIntensityCd;
        e.temperatureK = kNewEmitterTemperatureK;
        e.attenuation = kNewEmitterAttenuationPerM2;
    }
    preset.emitters.push_back(e);
    return int(preset.emitters.size()) - 1;
}

CloudVolume newCloudVolumeAt(const CloudParams& layer, const glm::dvec3& lookAt) {
    CloudVolume v;
    const double thickness =
        std::isfinite(layer.thicknessM) && layer.thicknessM > 0.0 ? layer.thicknessM : 2000.0;
    const double bottom = std::isfinite(layer.bottomM) ? layer.bottomM : 1500.0;
    v.position = {std::isfinite(lookAt.x) ? lookAt.x : 0.0, bottom + 0.5 * thickness,
                  std::isfinite(lookAt.z) ? lookAt.z : 0.0};
    v.halfExtents = {kNewCloudVolumeHalfWidthM, std::max(0.5 * thickness, 1.0), kNewCloudVolumeHalfWidthM};
    v.coverage = 1.0;
    v.edgeSoftness = 0.5;
    return v;
}

int addCloudVolume(Preset& preset, FogVolumeShape shape, const CloudVolume& placed) {
    CloudVolume v = placed;
    const bool box = shape == FogVolumeShape::Box;
    nameNewObject(preset, ParamScope::CloudVolume, box ? "cloud_box" : "cloud_ellipsoid",
                  box ? "Cloud box" : "Cloud ellipsoid", v.id, v.name);
    v.shape = shape;
    preset.cloudVolumes.push_back(v);
    return int(preset.cloudVolumes.size()) - 1;
}

/// Appends a copy of (preset.*objects)[index] with a new unique id, " copy"
/// after its name and moved by `offset`; false for a bad index.
template <class Object>
static bool appendCopy(Preset& preset, std::vector<Object> Preset::*objects, ParamScope scope, int index,
                       const glm::dvec3& offset, std::string& oldId, std::string& newId) {
    std::vector<Object>& list = preset.*objects;
    if (index < 0 || index >= int(list.size())) return false;
    Object copy = list[std::size_t(index)];
    oldId = copy.id;
    copy.id = newId = uniqueObjectId(preset, scope, oldId);
    copy.name += " copy";
    copy.position += offset;
    list.push_back(std::move(copy));
    return true;
}

int duplicateObject(Preset& preset, ParamScope scope, int index, const glm::dvec3& offset) {
    std::string oldId, newId;
    bool copied = false;
    switch (scope) {
        case ParamScope::Volume:
            copied = appendCopy(preset, &Preset::volumes, scope, index, offset, oldId, newId);
            break;
        case ParamScope::Emitter:
            copied = appendCopy(preset, &Preset::emitters, scope, index, offset, oldId, newId);
            break;
        case ParamScope::CloudVolume:
            copied = appendCopy(preset, &Preset::cloudVolumes, scope, index, offset, oldId, newId);
            break;
        case ParamScope::Global:
            break;
    }
    if (!copied) return -1;
    const std::size_t trackCount = preset.tracks.size();
    for (std::size_t i = 0; i < trackCount; ++i) {
        if (preset.tracks[i].target.scope != scope || preset.tracks[i].target.objectId != oldId) continue;
        Track copy = preset.tracks[i];
        copy.target.objectId = newId;
        if (copy.target.param == "position_m")  // keep the offset on keyed positions too
            for (TrackKey& k : copy.keys) k.value += offset;
        preset.tracks.push_back(std::move(copy));
    }
    return int(objectCount(preset, scope)) - 1;
}

bool deleteObject(Preset& preset, ParamScope scope, int index) {
    // Copy the id: removeObject erases the object that holds it.
    std::string id;
    if (scope == ParamScope::Volume && index >= 0 && index < int(preset.volumes.size()))
        id = preset.volumes[std::size_t(index)].id;
    else if (scope == ParamScope::Emitter && index >= 0 && index < int(preset.emitters.size()))
        id = preset.emitters[std::size_t(index)].id;
    else if (scope == ParamScope::CloudVolume && index >= 0 && index < int(preset.cloudVolumes.size()))
        id = preset.cloudVolumes[std::size_t(index)].id;
    else
        return false;
    return removeObject(preset, scope, id);  // its tracks and weather overrides go with it
}

std::string presetNameFromFile(const std::string& path) {
    std::string name = std::filesystem::path(path).stem().string();
    for (char& c : name)
        if (c == '_' || c == '-') c = ' ';
    if (!name.empty()) name[0] = char(std::toupper(static_cast<unsigned char>(name[0])));
    return name;
}

std::string nameAfterSaveAs(const std::string& currentName, const std::string& oldPath,
                            const std::string& newPath) {
    const std::string suggested = presetNameFromFile(newPath);
    if (suggested.empty() || suggested == currentName) return {};
    const bool unnamed = currentName.empty() || currentName == defaultPreset().name ||
                         (!oldPath.empty() && currentName == presetNameFromFile(oldPath));
    return unnamed ? suggested : std::string();
}

double snapKeyTime(const Preset& preset, const TrackTarget& track, int index, double timeHours,
                   double snapHours, double stepHours) {
    const double t = wrapHours(timeHours);
    double best = -1.0, bestGap = std::max(snapHours, 0.0);
    const TrackKey* dragged = nullptr;
    for (const Track& other : preset.tracks) {
        for (std::size_t k = 0; k < other.keys.size(); ++k) {
            if (other.target == track && int(k) == index) {
                dragged = &other.keys[k];
                continue;
            }
            double gap = std::abs(other.keys[k].timeHours - t);
            gap = std::min(gap, 24.0 - gap);
            if (gap <= bestGap) best = other.keys[k].timeHours, bestGap = gap;
        }
    }
    if (best >= 0.0) return best;
    const double step = std::isfinite(stepHours) && stepHours > 0.0 ? stepHours : kDefaultSnapHours;
    // The grid: whole steps of the day, or of the offset from the event a key follows.
    const double origin = dragged && dragged->anchor ? dragged->timeHours - dragged->offsetHours : 0.0;
    return wrapHours(origin + std::round((t - origin) / step) * step);
}

bool setObjectId(Preset& preset, ParamScope scope, int index, const std::string& id, std::string& error) {
    const std::string* current = nullptr;
    bool taken = false;
    auto look = [&](const auto& objects) {
        for (std::size_t i = 0; i < objects.size(); ++i) {
            if (int(i) == index)
                current = &objects[i].id;
            else
                taken = taken || objects[i].id == id;
        }
    };
    if (scope == ParamScope::Volume) look(preset.volumes);
    if (scope == ParamScope::Emitter) look(preset.emitters);
    if (scope == ParamScope::CloudVolume) look(preset.cloudVolumes);
    if (!current) {
        error = "no such object";
        return false;
    }
    if (*current == id) return true;
    if (taken) {
        error = "another " + std::string(addressPrefix(scope)) + " already has the id \"" + id + "\"";
        return false;
    }
    // core's changeObjectId checks the characters and retargets the tracks
    // and weather overrides.
    const std::string old = *current;  // a copy: the call changes the object's id first
    if (!changeObjectId(preset, scope, old, id)) {
        error = "an id must be 1..64 characters of A-Z a-z 0-9 _ - . (got \"" + id + "\")";
        return false;
    }
    return true;
}

bool renameObject(Preset& preset, ParamScope scope, int index, const std::string& name) {
    if (scope == ParamScope::Volume && index >= 0 && index < int(preset.volumes.size())) {
        preset.volumes[std::size_t(index)].name = name;
        return true;
    }
    if (scope == ParamScope::Emitter && index >= 0 && index < int(preset.emitters.size())) {
        preset.emitters[std::size_t(index)].name = name;
        return true;
    }
    if (scope == ParamScope::CloudVolume && index >= 0 && index < int(preset.cloudVolumes.size())) {
        preset.cloudVolumes[std::size_t(index)].name = name;
        return true;
    }
    return false;
}

}  // namespace aerial::editor
