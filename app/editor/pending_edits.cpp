// editor/pending_edits.cpp — auto-key and unkeyed edits (pending_edits.hpp).
#include "pending_edits.hpp"

#include <glm/common.hpp>

#include <algorithm>

namespace aerial::editor {

bool PendingEdits::holds(const Preset& preset, const ParamRef& ref, double timeHours) const {
    if (autoKey || !ref.desc || !ref.desc->animatable) return false;
    const Track* track = trackOf(preset, ref);
    return track != nullptr && keyIndexAt(*track, timeHours) < 0;
}

void PendingEdits::set(const ParamRef& ref, const double value[4], double timeHours) {
    PendingEdit edit;
    edit.ref = ref;
    edit.timeHours = timeHours;
    std::copy(value, value + 4, edit.value);
    auto it = std::find_if(edits_.begin(), edits_.end(), [&](const PendingEdit& e) { return e.ref == ref; });
    if (it != edits_.end())
        *it = edit;
    else
        edits_.push_back(edit);
    ++revision_;
}

const PendingEdit* PendingEdits::find(const ParamRef& ref) const {
    auto it = std::find_if(edits_.begin(), edits_.end(), [&](const PendingEdit& e) { return e.ref == ref; });
    return it != edits_.end() ? &*it : nullptr;
}

bool PendingEdits::erase(const ParamRef& ref) {
    const std::size_t before = edits_.size();
    std::erase_if(edits_, [&](const PendingEdit& e) { return e.ref == ref; });
    if (edits_.size() == before) return false;
    ++revision_;
    return true;
}

void PendingEdits::clear() {
    if (edits_.empty()) return;
    edits_.clear();
    ++revision_;
}

Preset PendingEdits::applied(const Preset& preset) const {
    Preset shown = preset;
    for (const PendingEdit& e : edits_) setValueAt(shown, e.ref, e.value, e.timeHours);
    return shown;
}

void PendingEdits::validate(const Preset& preset) {
    const std::size_t before = edits_.size();
    std::erase_if(edits_, [&](const PendingEdit& e) {
        return !e.ref.desc || !paramObjectOf(preset, e.ref) || trackOf(preset, e.ref) == nullptr;
    });
    if (edits_.size() != before) ++revision_;
}

std::optional<Track> shownTrack(const Preset& preset, const PendingEdit& edit) {
    const Track* track = edit.ref.desc ? trackOf(preset, edit.ref) : nullptr;
    if (!track) return std::nullopt;
    Track shown = *track;
    setTrackValueAt(shown, *edit.ref.desc, edit.value, edit.timeHours);
    return shown;
}

void displayedValueAt(const Preset& preset, const PendingEdits& pending, const ParamRef& ref,
                      double timeHours, double out[4]) {
    const PendingEdit* e = pending.find(ref);
    const std::optional<Track> track = e ? shownTrack(preset, *e) : std::nullopt;
    if (!track) {
        readValueAt(preset, ref, timeHours, out);
        return;
    }
    // The held value as the keyed preset would show it (clamped, normalised), as readValueAt reads it.
    readBaseValue(preset, ref, out);
    const int components = ref.desc->components();
    const glm::dvec3 v = evaluateTrack(*track, e->timeHours, components);
    for (int c = 0; c < components; ++c) out[c] = v[c];
}

void PendingOverlay::bind(const Preset& preset, const PendingEdits& pending) {
    bindings_.clear();
    for (const PendingEdit& e : pending.all())
        if (std::optional<Track> track = shownTrack(preset, e); track && !track->keys.empty())
            bindings_.push_back({e.ref.desc, e.ref.object, compileTrack(*track, e.ref.desc->components())});
}

void PendingOverlay::apply(PresetState& state) const {
    for (const Binding& b : bindings_) {
        const ParamDesc& d = *b.desc;
        void* object = nullptr;
        const std::size_t i = std::size_t(b.object);
        switch (d.scope) {
            case ParamScope::Global:
                object = &state.environment;
                break;
            case ParamScope::Volume:
                object = i < state.volumes.size() ? &state.volumes[i] : nullptr;
                break;
            case ParamScope::Emitter:
                object = i < state.emitters.size() ? &state.emitters[i] : nullptr;
                break;
            case ParamScope::CloudVolume:
                object = i < state.cloudVolumes.size() ? &state.cloudVolumes[i] : nullptr;
                break;
        }
        if (!object) continue;
        const glm::dvec3 v = evaluateTrack(b.track, state.timeHours);
        if (d.type == ParamType::Scalar)
            *d.scalar(object) = std::clamp(v.x, d.minValue, d.maxValue);
        else if (d.type == ParamType::Vec2)
            *d.vec2(object) =
                glm::clamp(glm::dvec2(v.x, v.y), glm::dvec2(d.minValue), glm::dvec2(d.maxValue));
        else if (d.type == ParamType::Colour || d.type == ParamType::Vec3)
            *d.vec3(object) = glm::clamp(v, glm::dvec3(d.minValue), glm::dvec3(d.maxValue));
    }
}

}  // namespace aerial::editor
