// editor/editor_parts.cpp — the parts' few calls (see editor_parts.hpp).
#include "editor_parts.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace aerial::editor {

ParamScope Selection::scopeOf(Kind kind) {
    switch (kind) {
        case Kind::Volume:
            return ParamScope::Volume;
        case Kind::Emitter:
            return ParamScope::Emitter;
        case Kind::CloudVolume:
            return ParamScope::CloudVolume;
        default:
            return ParamScope::Global;
    }
}

Selection::Kind Selection::kindOf(ParamScope scope) {
    switch (scope) {
        case ParamScope::Volume:
            return Kind::Volume;
        case ParamScope::Emitter:
            return Kind::Emitter;
        case ParamScope::CloudVolume:
            return Kind::CloudVolume;
        default:
            return Kind::None;
    }
}

void EditState::validate(const Preset& p) {
    pending.validate(p);
    curves.validate(p);
    // An object past the end (deleted, undone): the last one of its kind, else the group above it.
    if (const ParamScope scope = selection.scope(); scope != ParamScope::Global) {
        const int count = int(objectCount(p, scope));
        if (selection.index >= count)
            selection = count == 0 ? Selection{scope == ParamScope::CloudVolume ? Selection::Kind::Clouds
                                                                                : Selection::Kind::Fog,
                                               -1}
                                   : Selection{selection.kind, count - 1};
    }
    if (weather.selectedState >= int(p.weather.size())) weather.selectedState = int(p.weather.size()) - 1;
    if (selectedParam && selectedParam->object >= 0) {
        if (std::size_t(selectedParam->object) >= objectCount(p, selectedParam->scope()))
            selectedParam.reset();
    }
    if (selectedParam) {
        const Track* track = trackOf(p, *selectedParam);
        if (!track || selectedKey >= int(track->keys.size())) selectedKey = -1;
    } else {
        selectedKey = -1;
    }
}

void EditState::selectTrackKey(const Preset& p, int key) {
    selectedKey = key;
    curves.selected.clear();
    if (key >= 0 && selectedParam && trackOf(p, *selectedParam))
        curves.selected.push_back({trackTargetOf(p, *selectedParam), key, 0});
}

void EditState::followCurveSelection(const Preset& p) {
    if (curves.selected.empty()) return;
    selectedKey = -1;
    if (!selectedParam || !trackOf(p, *selectedParam)) return;
    const TrackTarget target = trackTargetOf(p, *selectedParam);
    for (const CurvePoint& point : curves.selected)
        if (point.target == target) {
            selectedKey = point.key;
            return;
        }
}

void Playback::advance(double dt) {
    if (!playing || !(dt > 0.0)) return;
    double t = timeHours + speed * std::min(dt, 0.25);
    if (t >= 24.0) {
        if (loop) {
            t = std::fmod(t, 24.0);
        } else {
            t = 24.0 - 1.0 / 3600.0;
            playing = false;
        }
    }
    timeHours = t;
}

bool SkyService::evaluate(const Document& doc, const PendingEdits& pending, double timeHours, bool dragging,
                          const WeatherMix& weather) {
    bool changed = false;
    if (pending.empty() || dragging) {
        // The document's own preset, and the changes being dragged written over it.
        if (!compiled || compiledRevision != doc.revision()) {
            compiled = std::make_unique<CompiledPreset>(doc.preset());
            compiledRevision = doc.revision();
            ++compiles;
            changed = true;
        }
        compiled->evaluate(timeHours, weather, state);
        if (pending.empty()) return changed;
        if (!overlayBound || overlayRevision != doc.revision() ||
            overlayPendingRevision != pending.revision()) {
            overlay.bind(doc.preset(), pending);  // a copy of each changed track only
            overlayRevision = doc.revision();
            overlayPendingRevision = pending.revision();
            overlayBound = changed = true;
        }
        overlay.apply(state);
        return changed;
    }
    // At rest: the preset with the changes keyed, exact (what evaluate
    // derives from them too), compiled once per change.
    if (!shown || shownRevision != doc.revision() || shownPendingRevision != pending.revision()) {
        shown = std::make_unique<CompiledPreset>(pending.applied(doc.preset()));
        shownRevision = doc.revision();
        shownPendingRevision = pending.revision();
        ++compiles;
        changed = true;
    }
    shown->evaluate(timeHours, weather, state);
    return changed;
}

bool SkyService::solve() {
    const AtmosphereParams& air = state.environment.atmosphere;
    const glm::dvec3 sun = state.sunLight.body.direction, moon = state.moonLight.body.direction;
    if (valid && std::memcmp(&air, &solvedAir, sizeof air) == 0 && sun == solvedSun && moon == solvedMoon)
        return false;
    const auto start = std::chrono::steady_clock::now();
    sunSolver->solve(air, sun);
    moonSolver->solve(air, moon);
    solveMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    light = lightReport(state, sunSolver->table(), moonSolver->table());
    solvedAir = air;
    solvedSun = sun;
    solvedMoon = moon;
    valid = true;
    ++generation;
    return true;
}

}  // namespace aerial::editor
