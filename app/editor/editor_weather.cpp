// editor/editor_weather.cpp — the Weather panel (View > Weather): the
// preset's weather states, the selected state's overrides (the parameter as
// the inspector names it, the mode, the value, and the keyed value at the
// current time next to the one the state gives: "keyed 0.3 -> 0.97 storm"),
// their edits (weather_edit.hpp, one undo step each) and the viewport's
// weather preview (weather_preview.hpp: none, a state, a transition A -> B at
// a fraction, Play transition on the editor's clock), and the weather
// regions (a list with each one's weight at the camera, Add box / Add
// ellipsoid around the camera's target, Remove, and the selected region's
// fields, one undo step per edit, a drag one step). The preview is view
// state: it never edits the document.
#include "panels.hpp"
#include "weather_edit.hpp"

#include <aerial/clock.hpp>

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace aerial::editor {
namespace {

const ImVec4 kErrorColour(1.0f, 0.45f, 0.35f, 1.0f);

/// A combo of "none" and the preset's states; true when `name` changed.
bool stateCombo(const char* label, const Preset& preset, std::string& name) {
    bool changed = false;
    if (ImGui::BeginCombo(label, name.c_str())) {
        std::vector<std::string> names{"none"};
        for (const WeatherState& s : preset.weather) names.push_back(s.name);
        for (const std::string& n : names)
            if (ImGui::Selectable(n.c_str(), n == name)) {
                name = n;
                changed = true;
            }
        ImGui::EndCombo();
    }
    return changed;
}

void drawPreview(const Document& doc, WeatherPanel& panel, double nowSeconds, std::string& status) {
    WeatherPreview& preview = panel.preview;
    const Preset& preset = doc.preset();
    std::string error;
    ImGui::TextUnformatted("Preview");
    ImGui::SameLine();
    ImGui::TextDisabled("(the viewport only: never saved)");
    const std::string shown = preview.mode() == WeatherPreview::Mode::State        ? preview.state()
                              : preview.mode() == WeatherPreview::Mode::Transition ? std::string("transition")
                                                                                   : std::string("none");
    ImGui::SetNextItemWidth(-1.0f);
    if (ImGui::BeginCombo("##preview", shown.c_str())) {
        if (ImGui::Selectable("none", shown == "none")) preview.showNone();
        for (const WeatherState& s : preset.weather)
            if (ImGui::Selectable(s.name.c_str(), shown == s.name)) preview.showState(preset, s.name, error);
        if (ImGui::Selectable("transition A -> B", shown == "transition")) {
            if (panel.from == panel.to && !preset.weather.empty()) {  // a first pick: none -> the last state
                panel.from = "none";
                panel.to = preset.weather.back().name;
            }
            preview.showTransition(preset, panel.from, panel.to, preview.fraction(), error);
        }
        ImGui::EndCombo();
    }
    if (preview.mode() != WeatherPreview::Mode::Transition) {
        if (!error.empty()) status = error;
        return;
    }
    // The transition's ends and fraction, and playing it on the clock.
    if (!preview.playing()) {
        panel.from = preview.from();
        panel.to = preview.to();
    }
    const float half = (ImGui::GetContentRegionAvail().x - ImGui::GetStyle().ItemSpacing.x) * 0.5f;
    ImGui::SetNextItemWidth(half);
    bool ends = stateCombo("##from", preset, panel.from);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(half);
    ends = stateCombo("##to", preset, panel.to) || ends;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("From (left) and to (right); none = the keyed values");
    double fraction = preview.fraction();
    const double lo = 0.0, hi = 1.0;
    ImGui::SetNextItemWidth(-1.0f);
    const bool moved = ImGui::SliderScalar("##fraction", ImGuiDataType_Double, &fraction, &lo, &hi,
                                           preview.playing() ? "%.2f (playing)" : "fraction %.2f");
    if (ends || moved) preview.showTransition(preset, panel.from, panel.to, fraction, error);
    ImGui::SetNextItemWidth(120.0f);
    const double minSeconds = 0.1, maxSeconds = 3600.0;
    ImGui::DragScalar("Duration [s]", ImGuiDataType_Double, &panel.playSeconds, 0.1f, &minSeconds,
                      &maxSeconds, "%.1f");
    panel.playSeconds = std::clamp(panel.playSeconds, minSeconds, maxSeconds);
    ImGui::SameLine();
    if (preview.playing()) {
        if (ImGui::Button("Stop")) preview.stop();
    } else if (ImGui::Button("Play transition")) {
        if (preview.play(preset, panel.from, panel.to, panel.playSeconds, nowSeconds, error))
            status = "Playing weather " + panel.from + " -> " + panel.to;
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "Runs the change with aerial::Weather, each category at its own speed (weather.hpp)");
    if (!error.empty()) status = error;
}

/// The state list and its buttons (add with the name field, rename, remove).
void drawStates(Document& doc, WeatherPanel& panel, std::string& status) {
    const Preset& preset = doc.preset();
    if (panel.selectedState < 0 && !preset.weather.empty()) panel.selectedState = 0;
    ImGui::TextUnformatted("States");
    if (ImGui::BeginListBox(
            "##states", ImVec2(-1.0f, ImGui::GetTextLineHeightWithSpacing() *
                                              float(std::clamp<std::size_t>(preset.weather.size(), 2, 5)) +
                                          6.0f))) {
        for (std::size_t i = 0; i < preset.weather.size(); ++i) {
            const WeatherState& s = preset.weather[i];
            const std::string item =
                s.name + " (" + std::to_string(s.overrides.size()) + ")##" + std::to_string(i);
            if (ImGui::Selectable(item.c_str(), int(i) == panel.selectedState)) panel.selectedState = int(i);
        }
        ImGui::EndListBox();
    }
    std::string error;
    ImGui::SetNextItemWidth(std::max(60.0f, ImGui::GetContentRegionAvail().x - 190.0f));
    const bool entered = ImGui::InputTextWithHint("##name", uniqueWeatherStateName(preset, "state").c_str(),
                                                  &panel.nameBuffer, ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    if (ImGui::Button("Add") || entered) {
        const std::string name =
            panel.nameBuffer.empty() ? uniqueWeatherStateName(preset, "state") : panel.nameBuffer;
        if (applyAddWeatherState(doc, name, error)) {
            panel.selectedState = int(doc.preset().weather.size()) - 1;
            panel.nameBuffer.clear();
            status = "Added weather state " + name;
        }
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("A new state named as the field says");
    const bool selected = panel.selectedState >= 0 && panel.selectedState < int(preset.weather.size());
    ImGui::BeginDisabled(!selected || panel.nameBuffer.empty());
    ImGui::SameLine();
    if (ImGui::Button("Rename")) {
        const std::string old = preset.weather[std::size_t(panel.selectedState)].name;
        const std::string name = panel.nameBuffer;
        if (applyRenameWeatherState(doc, panel.selectedState, name, error)) {
            // The preview follows the state it shows.
            if (panel.preview.mode() == WeatherPreview::Mode::State && panel.preview.state() == old)
                panel.preview.showState(doc.preset(), name, error);
            panel.nameBuffer.clear();
            status = "Renamed weather state " + old + " to " + name;
        }
    }
    ImGui::EndDisabled();
    ImGui::BeginDisabled(!selected);
    ImGui::SameLine();
    if (ImGui::Button("Remove")) {
        const std::string old = preset.weather[std::size_t(panel.selectedState)].name;
        if (applyRemoveWeatherState(doc, panel.selectedState, error)) status = "Removed weather state " + old;
        panel.selectedState = std::min(panel.selectedState, int(doc.preset().weather.size()) - 1);
    }
    ImGui::EndDisabled();
    if (!error.empty()) status = error;
    if (!error.empty()) ImGui::TextColored(kErrorColour, "%s", error.c_str());
}

/// One override's row: label, mode, value, keyed -> given; returns false
/// when it removed the override (the list changed).
bool drawOverride(Document& doc, EditState& edit, int state, int index, double timeHours,
                  std::string& status) {
    const Preset& preset = doc.preset();
    const std::string stateName = preset.weather[std::size_t(state)].name;
    const WeatherOverride o = preset.weather[std::size_t(state)].overrides[std::size_t(index)];
    const std::optional<ParamRef> ref = paramRefOf(preset, o.target);
    ImGui::PushID(index);
    std::string error;
    bool kept = true;
    if (!ref) {
        ImGui::TextColored(kErrorColour, "%s: no such parameter or object", curveKey(o.target).c_str());
    } else {
        const ParamDesc& desc = *ref->desc;
        double keyed[4];
        displayedValueAt(preset, edit.pending, *ref, timeHours, keyed);
        double given[4];
        overriddenValue(desc, keyed, o, given);
        const std::string label = curveLabel(preset, o.target);
        ImGui::TextUnformatted(label.c_str());
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("%s", weatherOverrideText(preset, o, stateName, keyed).c_str());
        // Mode: changing it keeps what the state gives at this time.
        int mode = int(o.mode);
        const char* modes[] = {"set", "add", "scale"};
        ImGui::SetNextItemWidth(64.0f);
        if (ImGui::Combo("##mode", &mode, modes, 3) && mode != int(o.mode)) {
            const WeatherOverrideMode m = WeatherOverrideMode(mode);
            applySetWeatherOverride(doc, state, index, m, valueForMode(desc, keyed, o, m), false, error);
        }
        ImGui::SameLine();
        // Value: set in the parameter's range, add within its span either way, scale from 0.
        const int n = desc.type == ParamType::Scalar ? 1 : desc.components();
        const double span = desc.uiMax > desc.uiMin ? desc.uiMax - desc.uiMin : 1.0;
        double lo = desc.minValue, hi = desc.maxValue;
        if (o.mode == WeatherOverrideMode::Add) lo = -(desc.maxValue - desc.minValue), hi = -lo;
        if (o.mode == WeatherOverrideMode::Scale) lo = 0.0, hi = 1e6;
        double v[3] = {o.value.x, o.value.y, o.value.z};
        ImGui::SetNextItemWidth(std::max(60.0f, ImGui::GetContentRegionAvail().x - 28.0f));
        const float speed = float(o.mode == WeatherOverrideMode::Scale ? 0.01 : span / 400.0);
        if (ImGui::DragScalarN("##value", ImGuiDataType_Double, v, n, speed, &lo, &hi, "%.4g",
                               ImGuiSliderFlags_AlwaysClamp))
            applySetWeatherOverride(doc, state, index, o.mode, glm::dvec3(v[0], v[1], v[2]), true, error);
        if (ImGui::IsItemDeactivated()) doc.closeMerge();
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("%s: %s", weatherModeName(o.mode),
                              o.mode == WeatherOverrideMode::Set   ? "replaces the keyed value"
                              : o.mode == WeatherOverrideMode::Add ? "is added to the keyed value"
                                                                   : "multiplies the keyed value");
        ImGui::SameLine();
        if (ImGui::SmallButton("x")) kept = !applyRemoveWeatherOverride(doc, state, index, error);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Remove this override");
        // "keyed 0.3 -> 0.97 storm": the value the time of day gives and the one the state gives.
        std::string keyedText, givenText;
        for (int c = 0; c < n; ++c) {
            if (c) keyedText += ", ", givenText += ", ";
            keyedText += valueWithUnit(keyed[c], "", 3);
            givenText += valueWithUnit(given[c], "", 3);
        }
        ImGui::TextDisabled("  keyed %s -> %s %s%s%s", keyedText.c_str(), givenText.c_str(),
                            stateName.c_str(), desc.unit.empty() ? "" : "  ", std::string(desc.unit).c_str());
    }
    if (!ref && ImGui::SmallButton("Remove")) kept = !applyRemoveWeatherOverride(doc, state, index, error);
    if (!error.empty()) status = error;
    ImGui::PopID();
    return kept;
}

/// The combo that adds an override of an animatable parameter not yet overridden.
void drawAddOverride(Document& doc, int state, double timeHours, std::string& status) {
    const Preset& preset = doc.preset();
    const std::string stateName = preset.weather[std::size_t(state)].name;
    ImGui::SetNextItemWidth(-1.0f);
    if (!ImGui::BeginCombo("##add_override", "Add override...", ImGuiComboFlags_HeightLarge)) return;
    std::optional<WeatherOverride> chosen;
    for (const ParamRef& ref : animatableParams(preset)) {
        const TrackTarget target = trackTargetOf(preset, ref);
        if (weatherOverrideIndex(preset.weather[std::size_t(state)], target) >= 0) continue;
        const std::string item = curveLabel(preset, target) + "##" + curveKey(target);
        if (ImGui::Selectable(item.c_str())) chosen = newWeatherOverride(preset, ref, timeHours);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", std::string(ref.desc->doc).c_str());
    }
    ImGui::EndCombo();
    std::string error;
    if (chosen && applyAddWeatherOverride(doc, state, *chosen, error))
        status = "Weather " + stateName + " overrides " + curveLabel(doc.preset(), chosen->target);
    if (!error.empty()) status = error;
}

/// The selected region's fields; each change is one undo step (a drag one).
void drawRegionFields(Document& doc, int index, std::string& status) {
    WeatherRegion r = doc.preset().weatherRegions[std::size_t(index)];
    std::string error;
    const auto set = [&](bool continuous) { applySetWeatherRegion(doc, index, r, continuous, error); };
    const auto closeDrag = [&] {
        if (ImGui::IsItemDeactivated()) doc.closeMerge();
    };
    std::string id = r.id;
    if (ImGui::InputText("Id", &id, ImGuiInputTextFlags_EnterReturnsTrue) && id != r.id) {
        r.id = id;
        set(false);
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("The region's id (Enter to apply): A-Z a-z 0-9 _ - ., unique");
    if (ImGui::InputText("Name", &r.name)) set(true);
    closeDrag();
    int shape = int(r.shape);
    const char* shapes[] = {"box", "ellipsoid"};
    if (ImGui::Combo("Shape", &shape, shapes, 2) && shape != int(r.shape)) {
        r.shape = WeatherRegionShape(shape);
        set(false);
    }
    std::string state = r.state;
    if (stateCombo("State", doc.preset(), state) && state != r.state) {
        r.state = state;
        set(false);
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("The state that holds inside; none = the keyed values");
    const double lo = -kWeatherRegionMaxCoordinate, hi = kWeatherRegionMaxCoordinate;
    if (ImGui::DragScalarN("Position [m]", ImGuiDataType_Double, &r.position.x, 3, 10.0f, &lo, &hi, "%.0f",
                           ImGuiSliderFlags_AlwaysClamp))
        set(true);
    closeDrag();
    const double minHalf = kWeatherRegionMinHalfExtent, maxHalf = kWeatherRegionMaxHalfExtent;
    if (ImGui::DragScalarN("Half extents [m]", ImGuiDataType_Double, &r.halfExtents.x, 3, 10.0f, &minHalf,
                           &maxHalf, "%.0f", ImGuiSliderFlags_AlwaysClamp))
        set(true);
    closeDrag();
    double yaw = weatherRegionYawDeg(r);
    const double minYaw = -180.0, maxYaw = 180.0;
    if (ImGui::DragScalar("Yaw [deg]", ImGuiDataType_Double, &yaw, 0.5f, &minYaw, &maxYaw, "%.1f",
                          ImGuiSliderFlags_AlwaysClamp)) {
        setWeatherRegionYawDeg(r, yaw);
        set(true);
    }
    closeDrag();
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Turn about +Y, counter-clockwise seen from above");
    const double minBlend = 0.0, maxBlend = kWeatherRegionMaxBlend;
    if (ImGui::DragScalar("Blend [m]", ImGuiDataType_Double, &r.blend, 5.0f, &minBlend, &maxBlend, "%.0f",
                          ImGuiSliderFlags_AlwaysClamp))
        set(true);
    closeDrag();
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("The soft edge, inwards from the surface: the state holds fully this deep inside");
    int priority = r.priority;
    if (ImGui::InputInt("Priority", &priority) && priority != r.priority) {
        r.priority = std::clamp(priority, -kWeatherRegionMaxPriority, kWeatherRegionMaxPriority);
        set(false);
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Higher over lower; equal ones in list order, the later on top");
    if (!error.empty()) {
        status = error;
        ImGui::TextColored(kErrorColour, "%s", error.c_str());
    }
}

/// The region list (each with its weight at the camera) and its buttons.
void drawRegions(Document& doc, WeatherPanel& panel, const CameraController& camera, std::string& status) {
    const Preset& preset = doc.preset();
    const glm::dvec3 eye = camera.eye();
    ImGui::TextUnformatted("Regions");
    ImGui::SameLine();
    bool atCamera = panel.preview.regionsAtCamera();
    if (ImGui::Checkbox("applied at the camera", &atCamera)) panel.preview.setRegionsAtCamera(atCamera);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("The viewport shows the weather at its camera, as a game does (regionalWeather)");
    const int count = int(preset.weatherRegions.size());
    if (panel.selectedRegion >= count) panel.selectedRegion = count - 1;
    if (panel.selectedRegion < 0 && count > 0) panel.selectedRegion = 0;
    if (ImGui::BeginListBox(
            "##regions",
            ImVec2(-1.0f, ImGui::GetTextLineHeightWithSpacing() * float(std::clamp(count, 2, 5)) + 6.0f))) {
        for (int i = 0; i < count; ++i) {
            const WeatherRegion& r = preset.weatherRegions[std::size_t(i)];
            char weight[32];
            std::snprintf(weight, sizeof weight, "%.2f", weatherRegionWeight(r, eye));
            const std::string item = r.id + " (" + weatherRegionShapeName(r.shape) + ", " + r.state +
                                     ") at camera " + weight + "##region" + std::to_string(i);
            if (ImGui::Selectable(item.c_str(), i == panel.selectedRegion)) panel.selectedRegion = i;
        }
        ImGui::EndListBox();
    }
    std::string error;
    const std::string state = panel.selectedState >= 0 && panel.selectedState < int(preset.weather.size())
                                  ? preset.weather[std::size_t(panel.selectedState)].name
                                  : std::string("none");
    for (WeatherRegionShape shape : {WeatherRegionShape::Box, WeatherRegionShape::Ellipsoid}) {
        const std::string label = std::string("Add ") + weatherRegionShapeName(shape);
        if (shape != WeatherRegionShape::Box) ImGui::SameLine();
        if (ImGui::Button(label.c_str())) {
            const WeatherRegion r = newWeatherRegion(preset, shape, state, camera.state().target);
            if (applyAddWeatherRegion(doc, r, error)) {
                panel.selectedRegion = int(doc.preset().weatherRegions.size()) - 1;
                status = "Added weather region " + r.id + " (" + state + ")";
            }
        }
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("A region holding the selected state (%s) around the camera's target",
                              state.c_str());
    }
    ImGui::BeginDisabled(panel.selectedRegion < 0);
    ImGui::SameLine();
    if (ImGui::Button("Remove##region") && panel.selectedRegion >= 0) {
        const std::string id = preset.weatherRegions[std::size_t(panel.selectedRegion)].id;
        if (applyRemoveWeatherRegion(doc, panel.selectedRegion, error))
            status = "Removed weather region " + id;
    }
    ImGui::EndDisabled();
    if (!error.empty()) status = error;
    if (panel.selectedRegion >= 0 && panel.selectedRegion < int(doc.preset().weatherRegions.size())) {
        ImGui::PushID("region_fields");
        drawRegionFields(doc, panel.selectedRegion, status);
        ImGui::PopID();
    }
}

}  // namespace

void drawWeatherPanel(Document& doc, EditState& edit, double timeHours, double nowSeconds,
                      const CameraController& camera, std::string& status) {
    WeatherPanel& panel = edit.weather;
    drawPreview(doc, panel, nowSeconds, status);
    ImGui::Separator();
    drawStates(doc, panel, status);
    ImGui::Separator();
    drawRegions(doc, panel, camera, status);
    const Preset& preset = doc.preset();
    if (panel.selectedState < 0 || panel.selectedState >= int(preset.weather.size())) {
        ImGui::TextDisabled("No weather state: add one (a name, then Add)");
        return;
    }
    const int state = panel.selectedState;
    ImGui::Separator();
    ImGui::Text("Overrides of %s", preset.weather[std::size_t(state)].name.c_str());
    ImGui::SameLine();
    ImGui::TextDisabled("(values at %s)", formatClock(timeHours, ClockResolution::Minutes).c_str());
    for (int i = 0; i < int(doc.preset().weather[std::size_t(state)].overrides.size()); ++i)
        if (!drawOverride(doc, edit, state, i, timeHours, status)) break;
    drawAddOverride(doc, state, timeHours, status);
}

}  // namespace aerial::editor
