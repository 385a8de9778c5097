// editor/pending_edits.cpp — auto-key and unkeyed edits (pending_edits.hpp).
#include "pending_edits.hpp"

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

void displayedValueAt(const Preset& preset, const PendingEdits& pending, const ParamRef& ref,
                      double timeHours, double out[4]) {
    if (const PendingEdit* e = pending.find(ref)) {
        // The held value as the keyed preset would show it (clamped, normalised).
        Preset scratch = preset;
        setValueAt(scratch, ref, e->value, e->timeHours);
        readValueAt(scratch, ref, e->timeHours, out);
        return;
    }
    readValueAt(preset, ref, timeHours, out);
}

}  // namespace aerial::editor
