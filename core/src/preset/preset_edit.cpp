// preset_edit.cpp — editing helpers on a Preset (aerial/preset.hpp):
// finding a track, renaming and removing volumes, emitters and cloud volumes
// together with the tracks and weather overrides that target them.
#include "preset_validate.hpp"

#include <aerial/preset.hpp>

#include <algorithm>
#include <iterator>
#include <optional>
#include <vector>

namespace aerial {

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
bool changeId(std::vector<Object>& objects, Preset& preset, ParamScope scope, const std::string& oldId,
              const std::string& newId) {
    if (!detail::validId(newId)) return false;
    Object* found = nullptr;
    for (Object& o : objects) {
        if (o.id == newId && newId != oldId) return false;
        if (o.id == oldId && !found) found = &o;
    }
    if (!found) return false;
    found->id = newId;
    for (Track& t : preset.tracks)
        if (t.target.scope == scope && t.target.objectId == oldId) t.target.objectId = newId;
    for (WeatherState& state : preset.weather)
        for (WeatherOverride& o : state.overrides)
            if (o.target.scope == scope && o.target.objectId == oldId) o.target.objectId = newId;
    return true;
}

template <class Object>
bool removeById(std::vector<Object>& objects, Preset& preset, ParamScope scope, const std::string& id) {
    const auto it = std::find_if(objects.begin(), objects.end(), [&](const Object& o) { return o.id == id; });
    if (it == objects.end()) return false;
    objects.erase(it);
    std::erase_if(preset.tracks,
                  [&](const Track& t) { return t.target.scope == scope && t.target.objectId == id; });
    for (WeatherState& state : preset.weather)
        std::erase_if(state.overrides,
                      [&](const WeatherOverride& o) { return o.target.scope == scope && o.target.objectId == id; });
    return true;
}

}  // namespace

bool changeObjectId(Preset& preset, ParamScope scope, const std::string& oldId, const std::string& newId) {
    switch (scope) {
        case ParamScope::Volume:
            return changeId(preset.volumes, preset, scope, oldId, newId);
        case ParamScope::Emitter:
            return changeId(preset.emitters, preset, scope, oldId, newId);
        case ParamScope::CloudVolume:
            return changeId(preset.cloudVolumes, preset, scope, oldId, newId);
        case ParamScope::Global:
            return false;
    }
    return false;
}

std::size_t resolveKeyAnchors(Preset& preset) {
    std::size_t changed = 0;
    const Location& where = preset.environment.location;
    // Each event once (a scan of the day each): the editor calls this after
    // every edit, a drag included, and many keys may follow one sunset.
    std::optional<double> eventHours[std::size(kSunEvents)];
    for (Track& track : preset.tracks) {
        bool anchored = false;
        for (TrackKey& key : track.keys) {
            if (!key.anchor) continue;
            anchored = true;
            std::optional<double>& event = eventHours[std::size_t(*key.anchor)];
            if (!event) event = sunEventHours(where, *key.anchor);
            const double t = wrapHours(*event + key.offsetHours);  // anchoredKeyHours, its event cached
            if (t != key.timeHours) ++changed;
            key.timeHours = t;
        }
        if (anchored)
            std::stable_sort(track.keys.begin(), track.keys.end(),
                             [](const TrackKey& a, const TrackKey& b) { return a.timeHours < b.timeHours; });
    }
    return changed;
}

bool removeObject(Preset& preset, ParamScope scope, const std::string& id) {
    switch (scope) {
        case ParamScope::Volume:
            return removeById(preset.volumes, preset, scope, id);
        case ParamScope::Emitter:
            return removeById(preset.emitters, preset, scope, id);
        case ParamScope::CloudVolume:
            return removeById(preset.cloudVolumes, preset, scope, id);
        case ParamScope::Global:
            return false;
    }
    return false;
}

}  // namespace aerial
