// editor/document.hpp — the preset being edited: the Preset, its file, the
// dirty flag and the undo/redo history. No GUI, no GL: every change the
// editor makes (inspector, timeline keys, gizmo drags, add/delete/rename/
// duplicate, scripts) goes through Document::apply, so each is undoable and
// marks the document dirty.
//
// Usage:
//   aerial::editor::Document doc;                          // built-in default preset
//   doc.apply("Fog density", "global:fog.density_per_m",   // merge key: one step per drag
//             [](aerial::Preset& p) { p.environment.fog.density = 0.01; });
//   if (ImGui::IsItemDeactivated()) doc.closeMerge();      // the drag ended
//   doc.undo(); doc.redo();
//   doc.save("mine.json");                                 // atomic, clears dirty
//   std::string t = doc.title();                           // "mine.json* - Aerial"
//
// Undo model: snapshots. Each step stores the whole Preset before the change
// (a preset is a few kB; the history is capped at kMaxUndoSteps). A change
// with a non-empty merge key that follows a change with the same key, with
// no closeMerge() in between, extends that step instead of making a new one
// (a continuous slider or gizmo drag is one step). A change that leaves the
// preset identical (presetsIdentical) records nothing.
//
// Dirty flag: every state of the preset gets a revision number; the document
// is dirty when the current revision differs from the one last saved or
// opened, so undoing back to the saved state makes it clean again.
#pragma once

#include <aerial/preset.hpp>

#include <cstdint>
#include <deque>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace aerial::editor {

/// Largest number of undo steps kept (older ones are dropped).
inline constexpr std::size_t kMaxUndoSteps = 256;

class Document {
public:
    /// A new, unsaved document on aerial::defaultPreset(); clean.
    Document();

    /// Replaces everything: a new document on `preset` (clean, no history),
    /// backed by `path` ("" = untitled).
    void reset(Preset preset, std::string path = {});

    /// Loads a preset file. On failure returns the loader's result (with its
    /// errors) and changes nothing; on success the document is that file,
    /// clean, with an empty history.
    PresetLoadResult open(const std::string& path);

    /// Saves atomically to `path` (core's savePreset) and, on success, makes
    /// it the document's path and marks the current state saved.
    SaveResult save(const std::string& path);

    const Preset& preset() const { return preset_; }
    /// "" while untitled.
    const std::string& path() const { return path_; }
    bool dirty() const { return revision_ != savedRevision_; }
    /// Marks the current state as unsaved work (e.g. a recovered preset).
    void markDirty();
    /// "NAME.json* - Aerial" (the file name, "Untitled" without one, `*`
    /// when dirty).
    std::string title() const;

    /// Changes on every change of the preset, undo and redo included
    /// (what a view compares to know it must re-evaluate).
    std::uint64_t revision() const { return revision_; }

    /// Applies `change` to the preset as one undoable step named `label`.
    /// With a merge key equal to the previous change's (and no closeMerge()
    /// since), the change joins that step. Returns false (and records
    /// nothing) when the preset did not change.
    bool apply(std::string_view label, std::string_view mergeKey, const std::function<void(Preset&)>& change);
    /// Ends the current merge: the next change starts a new step.
    void closeMerge() { mergeKey_.clear(); }

    bool canUndo() const { return !undo_.empty(); }
    bool canRedo() const { return !redo_.empty(); }
    /// The label of the step undo() / redo() would revert or reapply.
    std::string undoLabel() const;
    std::string redoLabel() const;
    bool undo();
    bool redo();
    std::size_t undoCount() const { return undo_.size(); }
    std::size_t redoCount() const { return redo_.size(); }

    /// The preset as it was last opened or saved (for "key all changed").
    const Preset& baseline() const { return baseline_; }

private:
    struct Step {
        std::string label;
        Preset preset;           // the state this step restores
        std::uint64_t revision;  // that state's revision
    };
    void clearHistory();

    Preset preset_;
    Preset baseline_;
    std::string path_;
    std::uint64_t revision_ = 1;
    std::uint64_t nextRevision_ = 2;
    std::uint64_t savedRevision_ = 1;
    std::deque<Step> undo_;
    std::vector<Step> redo_;
    std::string mergeKey_;
};

/// A volume or emitter id not used yet in `preset` for that scope:
/// `base`, or `base_2`, `base_3`, ...
std::string uniqueObjectId(const Preset& preset, bool volume, std::string_view base);
/// The same for any object scope (Volume, Emitter, CloudVolume; Global
/// returns `base`).
std::string uniqueObjectId(const Preset& preset, ParamScope scope, std::string_view base);

}  // namespace aerial::editor
