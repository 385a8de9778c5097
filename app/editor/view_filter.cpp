// editor/view_filter.cpp — solo and mute (view_filter.hpp).
#include "view_filter.hpp"

#include <algorithm>

namespace aerial::editor {

std::string ViewFilter::key(ParamScope scope, const std::string& id) {
    return std::string(scopeKey(scope)) + ":" + id;
}

void ViewFilter::toggleMute(ParamScope scope, const std::string& id) {
    const std::string k = key(scope, id);
    if (!muted_.erase(k)) muted_.insert(k);
    ++revision_;
}

void ViewFilter::toggleSolo(ParamScope scope, const std::string& id) {
    const std::string k = key(scope, id);
    solo_ = solo_ == k ? std::string() : k;
    ++revision_;
}

void ViewFilter::clear() {
    muted_.clear();
    solo_.clear();
    ++revision_;
}

bool ViewFilter::muted(ParamScope scope, const std::string& id) const {
    return muted_.count(key(scope, id)) > 0;
}

bool ViewFilter::soloed(ParamScope scope, const std::string& id) const { return solo_ == key(scope, id); }

bool ViewFilter::shows(ParamScope scope, const std::string& id) const {
    if (!solo_.empty()) return soloed(scope, id);
    return !muted(scope, id);
}

PresetState ViewFilter::applied(const PresetState& state) const {
    PresetState shown = state;
    std::erase_if(shown.volumes, [&](const FogVolume& v) { return !shows(ParamScope::Volume, v.id); });
    std::erase_if(shown.emitters, [&](const Emitter& e) { return !shows(ParamScope::Emitter, e.id); });
    return shown;
}

}  // namespace aerial::editor
