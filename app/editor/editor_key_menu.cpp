// editor/editor_key_menu.cpp — the key menu's parts shared by the curve
// view and the track row (panels.hpp): the key's shape (flat / automatic
// tangents, unified / broken handles, the interpolation after it) and
// "Follow the sun" (anchor the keys to a sun event where they stand).
#include "panels.hpp"

#include <aerial/clock.hpp>

#include <imgui.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace aerial::editor {
namespace {

/// "Civil dusk": a menu's capitalised event.
std::string eventMenuLabel(SunEvent event) {
    std::string label = sunEventLabel(event);
    if (!label.empty()) label[0] = char(label[0] - 'a' + 'A');
    return label;
}

}  // namespace

void keyShapeMenu(Document& doc, const std::vector<CurvePoint>& picked, const std::string& suffix) {
    const int keys = keyCountOf(picked);
    if (ImGui::MenuItem(("Flat tangent" + suffix).c_str()))
        doc.apply(keys == 1 ? "Flat tangent" : "Flat tangents", "",
                  [&](Preset& p) { setFlatTangents(p, picked, true); });
    if (ImGui::MenuItem(("Automatic tangent" + suffix).c_str()))
        doc.apply(keys == 1 ? "Automatic tangent" : "Automatic tangents", "",
                  [&](Preset& p) { setFlatTangents(p, picked, false); });
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "Smooth tracks: flat levels the curve at the key; automatic follows its neighbours (and "
            "resets the key's handles)");
    // The first key's handles: -1 automatic, else its TangentMode (what the menu ticks).
    int handleMode = -1;
    if (!picked.empty())
        if (const std::optional<TangentMode> m = tangentModeOf(doc.preset(), picked.front()))
            handleMode = int(*m);
    if (ImGui::MenuItem(("Unified tangents" + suffix).c_str(), nullptr,
                        handleMode == int(TangentMode::Unified)))
        doc.apply(tangentModeLabel(picked, TangentMode::Unified), "",
                  [&](Preset& p) { setTangentMode(p, picked, TangentMode::Unified); });
    if (ImGui::MenuItem(("Broken tangents" + suffix).c_str(), nullptr,
                        handleMode == int(TangentMode::Broken)))
        doc.apply(tangentModeLabel(picked, TangentMode::Broken), "",
                  [&](Preset& p) { setTangentMode(p, picked, TangentMode::Broken); });
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "The selected key's handles (drag their ends): unified keep one slope through the key, "
            "broken move apart (a corner). Saved with the key (\"tangent_in\", \"tangent_out\")");
    // The segment after the key: its own interpolation or the track's ("interpolation" on the
    // key in the preset).
    if (ImGui::BeginMenu(("Interpolation after" + suffix).c_str())) {
        const std::pair<const char*, std::optional<Interpolation>> modes[] = {
            {"Track's", std::nullopt},
            {"Step", Interpolation::Step},
            {"Linear", Interpolation::Linear},
            {"Smooth", Interpolation::Smooth}};
        for (const auto& [label, mode] : modes) {
            if (ImGui::MenuItem(label))
                doc.apply(std::string("Interpolation: ") + label, "",
                          [&](Preset& p) { setKeyInterpolation(p, picked, mode); });
        }
        ImGui::EndMenu();
    }
}

void followTheSunMenu(Document& doc, const std::vector<CurvePoint>& picked, const std::string& suffix) {
    // The keys keep their time today and move with the event when the date or the place changes;
    // each event shows its time today.
    if (ImGui::BeginMenu(("Follow the sun" + suffix).c_str())) {
        const Location& where = doc.preset().environment.location;
        for (SunEvent event : kSunEvents) {
            const std::string when = formatClock(sunEventHours(where, event), ClockResolution::Minutes);
            if (ImGui::MenuItem(eventMenuLabel(event).c_str(), when.c_str(),
                                allAnchoredTo(doc.preset(), picked, event)))
                doc.apply(anchorLabel(picked, event), "",
                          [&](Preset& p) { anchorCurvePoints(p, picked, event); });
        }
        ImGui::Separator();
        if (ImGui::MenuItem("Fixed time", nullptr, allAnchoredTo(doc.preset(), picked, std::nullopt)))
            doc.apply(anchorLabel(picked, std::nullopt), "",
                      [&](Preset& p) { anchorCurvePoints(p, picked, std::nullopt); });
        ImGui::EndMenu();
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "Anchor the keys to a moment of the sun where they stand (\"sunset + 0:20\"): the curve "
            "stays as it is, and the keys move with the sun when the date or the place changes");
}

}  // namespace aerial::editor
