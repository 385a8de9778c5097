// editor/view_filter.hpp — solo and mute of fog volumes and emitters: what
// the viewport leaves out to show one object's part of the picture. View
// state only: never in the preset, the undo history or a save. No GUI.
//
//   ViewFilter filter;
//   filter.toggleMute(ParamScope::Volume, "lake_mist");
//   renderer.render(camera, filter.active() ? filter.applied(state) : state, frame);
#pragma once

#include <aerial/evaluate.hpp>
#include <aerial/param_table.hpp>

#include <set>
#include <string>

namespace aerial::editor {

class ViewFilter {
public:
    /// Mutes or unmutes one object (a volume or an emitter, by id).
    void toggleMute(ParamScope scope, const std::string& id);
    /// Solos one object (only it of all volumes and emitters shows), or ends
    /// the solo when it is the soloed one.
    void toggleSolo(ParamScope scope, const std::string& id);
    void clear();
    bool muted(ParamScope scope, const std::string& id) const;
    bool soloed(ParamScope scope, const std::string& id) const;
    /// Whether the viewport shows the object.
    bool shows(ParamScope scope, const std::string& id) const;
    /// Something is muted or soloed.
    bool active() const { return !muted_.empty() || !solo_.empty(); }
    /// The state without the objects the viewport does not show.
    PresetState applied(const PresetState& state) const;
    /// Bumped by every change (the viewport re-renders on it).
    unsigned long long revision() const { return revision_; }

private:
    unsigned long long revision_ = 0;
    static std::string key(ParamScope scope, const std::string& id);
    std::set<std::string> muted_;
    std::string solo_;
};

}  // namespace aerial::editor
