// editor/pending_edits.hpp — auto-key and unkeyed edits (no GUI, unit-tested).
//
// With auto-key off (the default, as Unreal's Sequencer), editing an
// animated parameter at a time where it has no key does not write a key: the
// change is held here, shown in the viewport and the inspector (highlighted,
// with Key and Revert), until the artist keys it (a key at the time it was
// made) or reverts it. Editing at a key changes that key; a parameter
// without a track changes its constant value; with auto-key on every edit of
// an animated parameter keys it, as before. Unkeyed edits are view state:
// they are not in the undo history and are not saved.
//
// Showing them costs no copy of the preset per frame: the inspector reads a
// change's value from its own track (shownTrack: a copy of that one track
// with the change keyed), and while a field is dragged the viewport writes
// the changes over the document's evaluated state (PendingOverlay); the
// whole preset with the changes keyed (applied) is compiled once a change
// rests (SkyService, editor_parts.hpp).
//
//   PendingEdits pending;
//   if (pending.holds(doc.preset(), ref, t)) pending.set(ref, value, t);
//   else doc.apply(... setValueAt(p, ref, value, t) ...);
//   PendingOverlay overlay;
//   overlay.bind(doc.preset(), pending);      // when either changes
//   compiled.evaluate(t, state);              // the document's
//   overlay.apply(state);                     // per frame: what the viewport draws
#pragma once

#include "preset_edit.hpp"

#include <aerial/evaluate.hpp>
#include <aerial/timeline.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace aerial::editor {

/// One change not keyed yet.
struct PendingEdit {
    ParamRef ref;
    double value[4] = {0, 0, 0, 0};  ///< readParam's layout, sanitised
    double timeHours = 0.0;          ///< where it was made (and will be keyed)
};

class PendingEdits {
public:
    /// Auto-key: every edit of an animated parameter writes a key. Default off.
    bool autoKey = false;

    /// True when an edit of `ref` at `timeHours` is held here instead of
    /// written: auto-key off, the parameter animatable and animated, no key
    /// within kKeyTimeTolerance of the time.
    bool holds(const Preset& preset, const ParamRef& ref, double timeHours) const;

    /// Holds (or replaces) the change of `ref`, as given; it is sanitised
    /// where it is shown and keyed (setValueAt: clamped into the valid
    /// range, unit vectors normalised).
    void set(const ParamRef& ref, const double value[4], double timeHours);
    /// The held change of `ref`, or null.
    const PendingEdit* find(const ParamRef& ref) const;
    /// Forgets the change of `ref`; false when there was none.
    bool erase(const ParamRef& ref);
    void clear();
    bool empty() const { return edits_.empty(); }
    std::size_t size() const { return edits_.size(); }
    const std::vector<PendingEdit>& all() const { return edits_; }
    /// Bumped by every change (the viewport re-evaluates on it).
    std::uint64_t revision() const { return revision_; }

    /// The preset as shown: every held change keyed at its time (a copy
    /// of the whole preset: compiled once a change rests, not per frame).
    Preset applied(const Preset& preset) const;
    /// Drops the changes whose parameter no longer exists or is no longer
    /// animated (after an undo, a delete, a load).
    void validate(const Preset& preset);

private:
    std::vector<PendingEdit> edits_;
    std::uint64_t revision_ = 0;
};

/// The track of `edit`'s parameter as applied() would make it (a copy of
/// that one track with the change keyed); nullopt when the parameter has no
/// track in `preset`.
std::optional<Track> shownTrack(const Preset& preset, const PendingEdit& edit);

/// The value shown for `ref` at `timeHours`: the held change when there is
/// one (as the keyed preset would show it at the time it was made), else
/// readValueAt. Copies no preset.
void displayedValueAt(const Preset& preset, const PendingEdits& pending, const ParamRef& ref,
                      double timeHours, double out[4]);

/// The held changes bound to the fields they change in a state evaluated
/// from the document's preset: each change's track (shownTrack) compiled
/// once, then evaluated per frame and written, clamped into its range, as
/// CompiledPreset::evaluate writes a track. What evaluate derives from those
/// fields (the lights through the atmosphere, the emitters' glow in the
/// fog) stays the document's: the viewport draws this only while a change
/// is being dragged, and the applied preset, compiled, once it rests.
class PendingOverlay {
public:
    /// Binds every change of `pending` whose parameter has a track in `preset`.
    void bind(const Preset& preset, const PendingEdits& pending);
    /// Writes the bound changes into `state` at state.timeHours (`state`
    /// has `preset`'s objects, as CompiledPreset::evaluate makes it).
    void apply(PresetState& state) const;
    std::size_t size() const { return bindings_.size(); }

private:
    struct Binding {
        const ParamDesc* desc = nullptr;
        int object = -1;  ///< index into the state's volumes, emitters or cloud volumes; -1 global
        CompiledTrack track;
    };
    std::vector<Binding> bindings_;
};

}  // namespace aerial::editor
