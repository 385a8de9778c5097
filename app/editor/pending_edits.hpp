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
//   PendingEdits pending;
//   if (pending.holds(doc.preset(), ref, t)) pending.set(ref, value, t);
//   else doc.apply(... setValueAt(p, ref, value, t) ...);
//   CompiledPreset shown(pending.applied(doc.preset()));   // what the viewport draws
#pragma once

#include "preset_edit.hpp"

#include <cstdint>
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

    /// The preset as shown: every held change keyed at its time.
    Preset applied(const Preset& preset) const;
    /// Drops the changes whose parameter no longer exists or is no longer
    /// animated (after an undo, a delete, a load).
    void validate(const Preset& preset);

private:
    std::vector<PendingEdit> edits_;
    std::uint64_t revision_ = 0;
};

/// The value shown for `ref` at `timeHours`: the held change when there is
/// one, else readValueAt.
void displayedValueAt(const Preset& preset, const PendingEdits& pending, const ParamRef& ref,
                      double timeHours, double out[4]);

}  // namespace aerial::editor
