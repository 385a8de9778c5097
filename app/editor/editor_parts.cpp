// editor/editor_parts.cpp — the parts' few calls (see editor_parts.hpp).
#include "editor_parts.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace aerial::editor {

void EditState::validate(const Preset& p) {
    if (selection.kind == Selection::Kind::Volume && selection.index >= int(p.volumes.size()))
        selection = p.volumes.empty() ? Selection{Selection::Kind::Fog, -1}
                                      : Selection{Selection::Kind::Volume, int(p.volumes.size()) - 1};
    if (selection.kind == Selection::Kind::Emitter && selection.index >= int(p.emitters.size()))
        selection = p.emitters.empty() ? Selection{Selection::Kind::Fog, -1}
                                       : Selection{Selection::Kind::Emitter, int(p.emitters.size()) - 1};
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

bool SkyService::evaluate(const Document& doc, double timeHours) {
    const bool recompile = !compiled || compiledRevision != doc.revision();
    if (recompile) {
        compiled = std::make_unique<CompiledPreset>(doc.preset());
        compiledRevision = doc.revision();
    }
    compiled->evaluate(timeHours, state);
    return recompile;
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
    solvedAir = air;
    solvedSun = sun;
    solvedMoon = moon;
    valid = true;
    ++generation;
    return true;
}

}  // namespace aerial::editor
