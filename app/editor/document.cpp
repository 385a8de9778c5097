// editor/document.cpp — see document.hpp.
#include "document.hpp"

#include <filesystem>
#include <utility>

namespace aerial::editor {

Document::Document() { reset(defaultPreset()); }

void Document::reset(Preset preset, std::string path) {
    preset_ = std::move(preset);
    baseline_ = preset_;
    path_ = std::move(path);
    revision_ = nextRevision_++;
    savedRevision_ = revision_;
    clearHistory();
}

void Document::clearHistory() {
    undo_.clear();
    redo_.clear();
    mergeKey_.clear();
}

PresetLoadResult Document::open(const std::string& path) {
    PresetLoadResult result = loadPreset(path);
    if (result.ok()) reset(*result.preset, path);
    return result;
}

SaveResult Document::save(const std::string& path) {
    SaveResult result = savePreset(preset_, path);
    if (result.ok()) {
        path_ = path;
        savedRevision_ = revision_;
        baseline_ = preset_;
        mergeKey_.clear();
    }
    return result;
}

void Document::markDirty() {
    if (savedRevision_ == revision_) savedRevision_ = 0;  // no state has revision 0
}

std::string Document::title() const {
    std::string name =
        path_.empty() ? std::string("Untitled") : std::filesystem::path(path_).filename().string();
    if (dirty()) name += '*';
    name += " - Aerial";
    return name;
}

bool Document::apply(std::string_view label, std::string_view mergeKey,
                     const std::function<void(Preset&)>& change) {
    Preset before = preset_;
    change(preset_);
    // Keys that follow the sun move with a new date or place, and a moved
    // or newly anchored key takes its place in its track's order.
    resolveKeyAnchors(preset_);
    if (presetsIdentical(before, preset_) && preset_.name == before.name &&
        preset_.description == before.description)
        return false;
    redo_.clear();
    const bool merge = !mergeKey.empty() && mergeKey == mergeKey_ && !undo_.empty();
    if (!merge) {
        undo_.push_back({std::string(label), std::move(before), revision_});
        if (undo_.size() > kMaxUndoSteps) undo_.pop_front();
    }
    mergeKey_ = std::string(mergeKey);
    revision_ = nextRevision_++;
    return true;
}

std::string Document::undoLabel() const { return undo_.empty() ? std::string() : undo_.back().label; }
std::string Document::redoLabel() const { return redo_.empty() ? std::string() : redo_.back().label; }

bool Document::undo() {
    if (undo_.empty()) return false;
    Step step = std::move(undo_.back());
    undo_.pop_back();
    redo_.push_back({step.label, std::move(preset_), revision_});
    preset_ = std::move(step.preset);
    revision_ = step.revision;
    mergeKey_.clear();
    return true;
}

bool Document::redo() {
    if (redo_.empty()) return false;
    Step step = std::move(redo_.back());
    redo_.pop_back();
    undo_.push_back({step.label, std::move(preset_), revision_});
    preset_ = std::move(step.preset);
    revision_ = step.revision;
    mergeKey_.clear();
    return true;
}

std::string uniqueObjectId(const Preset& preset, bool volume, std::string_view base) {
    return uniqueObjectId(preset, volume ? ParamScope::Volume : ParamScope::Emitter, base);
}

std::string uniqueObjectId(const Preset& preset, ParamScope scope, std::string_view base) {
    auto inList = [](const auto& objects, const std::string& id) {
        for (const auto& o : objects)
            if (o.id == id) return true;
        return false;
    };
    auto taken = [&](const std::string& id) {
        switch (scope) {
            case ParamScope::Volume:
                return inList(preset.volumes, id);
            case ParamScope::Emitter:
                return inList(preset.emitters, id);
            case ParamScope::CloudVolume:
                return inList(preset.cloudVolumes, id);
            case ParamScope::Global:
                return false;
        }
        return false;
    };
    std::string id(base);
    for (int n = 2; taken(id); ++n) {
        id = base;
        id += '_';
        id += std::to_string(n);
    }
    return id;
}

}  // namespace aerial::editor
