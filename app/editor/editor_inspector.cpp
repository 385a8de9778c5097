// editor/editor_inspector.cpp — the inspector, generated from the one
// parameter table (core/include/aerial/param_table.hpp): every label carries
// its unit, slider ranges are the table's ui range (logarithmic where the
// table says so), tooltips are the table's doc with the valid range, colours
// are linear-RGB pickers (float, HDR). Animatable parameters have a key
// button (a diamond: filled = a key at the current time, outlined = the
// parameter has a track, grey = constant) and, when animated, a curve
// button that overlays its curve in the timeline (coloured while shown). Editing a parameter that has a
// track sets a key at the current time (auto-key); editing one without a
// track changes its constant value. A slider drag is one undo step.
#include "panels.hpp"
#include "pending_edits.hpp"
#include "places.hpp"

#include "viewport/picking.hpp"

#include <aerial/clock.hpp>
#include <aerial/fog_mesh.hpp>

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_stdlib.h>

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace aerial::editor {
namespace {

constexpr double kDegrees = 180.0 / 3.14159265358979323846;

std::string labelOf(const ParamDesc& p) {
    std::string label(p.label);
    if (!p.unit.empty()) {
        label += " [";
        label += p.unit;
        label += ']';
    }
    return label;
}

bool startsWith(std::string_view text, std::string_view prefix) {
    return text.substr(0, prefix.size()) == prefix;
}

/// The group a global parameter belongs to in the outliner.
Selection::Kind globalGroup(const ParamDesc& p) {
    if (startsWith(p.path, "sun.") || startsWith(p.path, "moon.")) return Selection::Kind::Lights;
    if (startsWith(p.path, "fog.")) return Selection::Kind::Fog;
    if (startsWith(p.path, "exposure.")) return Selection::Kind::Exposure;
    if (startsWith(p.path, "clouds.")) return Selection::Kind::Clouds;
    return Selection::Kind::Atmosphere;
}

/// Section title for a global parameter's path ("atmosphere.mie.x" -> "Mie").
std::string sectionOf(const ParamDesc& p) {
    const std::string_view path = p.path;
    const std::size_t last = path.rfind('.');
    if (last == std::string_view::npos) return {};
    std::string_view head = path.substr(0, last);
    const std::size_t dot = head.rfind('.');
    if (dot != std::string_view::npos) head = head.substr(dot + 1);
    std::string s(head);
    if (!s.empty()) s[0] = char(std::toupper(static_cast<unsigned char>(s[0])));
    return s;
}

bool lightningOnly(std::string_view key) {
    return key == "seed" || key == "flashes_per_minute" || key == "flash_duration_s" || key == "time_scale";
}

}  // namespace

namespace {

bool keyButton(Document& doc, EditState& edit, const ParamRef& ref, double timeHours) {
    const float size = ImGui::GetFrameHeight();
    const Track* track = trackOf(doc.preset(), ref);
    const int keyHere = track ? keyIndexAt(*track, timeHours) : -1;
    const bool clicked = ImGui::InvisibleButton("##key", ImVec2(size * 0.8f, size));
    const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
    const ImVec2 c((lo.x + hi.x) * 0.5f, (lo.y + hi.y) * 0.5f);
    const float r = size * 0.28f;
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const ImU32 keyColour = IM_COL32(240, 190, 60, 255);
    const ImU32 colour =
        track ? keyColour
              : (ImGui::IsItemHovered() ? IM_COL32(200, 200, 200, 255) : IM_COL32(110, 110, 110, 255));
    const ImVec2 diamond[4] = {ImVec2(c.x, c.y - r), ImVec2(c.x + r, c.y), ImVec2(c.x, c.y + r),
                               ImVec2(c.x - r, c.y)};
    if (keyHere >= 0)
        dl->AddConvexPolyFilled(diamond, 4, colour);
    else
        dl->AddPolyline(diamond, 4, colour, ImDrawFlags_Closed, 1.5f);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("%s", keyHere >= 0 ? "Remove the key at this time"
                                : track      ? "Add a key at this time (the parameter is animated)"
                                             : "Animate: add a key at this time");
    if (clicked) {
        const double time = timeHours;
        if (keyHere >= 0) {
            const TrackTarget target = trackTargetOf(doc.preset(), ref);
            doc.apply("Remove key", "", [&](Preset& p) { removeKey(p, target, keyHere); });
        } else {
            keyParamNow(doc, edit, ref, time);
        }
        edit.selectedParam = ref;
        const Track* after = trackOf(doc.preset(), ref);
        edit.selectTrackKey(doc.preset(), after ? keyIndexAt(*after, time) : -1);
    }
    return clicked;
}

/// The curve button beside an animated parameter: shows (coloured) or
/// hides its curve in the timeline's curve view, beside the selected one.
void curveButton(const Document& doc, EditState& edit, const ParamRef& ref) {
    const float size = ImGui::GetFrameHeight();
    const bool animated = trackOf(doc.preset(), ref) != nullptr;
    if (!animated) {
        ImGui::Dummy(ImVec2(size * 0.8f, size));
        return;
    }
    const TrackTarget target = trackTargetOf(doc.preset(), ref);
    const bool shown = edit.curves.isShown(target);
    if (ImGui::InvisibleButton("##curve", ImVec2(size * 0.8f, size))) edit.curves.setShown(target, !shown);
    const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
    const ImU32 colour =
        shown ? ImU32(curveColour(doc.preset(), edit, target))
              : (ImGui::IsItemHovered() ? IM_COL32(200, 200, 200, 255) : IM_COL32(100, 100, 100, 255));
    // A little S-curve: the icon of a curve editor.
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const float w = hi.x - lo.x, h = hi.y - lo.y;
    const ImVec2 a(lo.x + w * 0.12f, lo.y + h * 0.72f), b(hi.x - w * 0.12f, lo.y + h * 0.28f);
    dl->AddBezierCubic(a, ImVec2(lo.x + w * 0.55f, a.y), ImVec2(lo.x + w * 0.45f, b.y), b, colour,
                       shown ? 2.0f : 1.2f);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("%s",
                          shown ? "Hide this curve in the timeline" : "Show this curve in the timeline");
}

/// The numbers artists think in, beside the physical ones (editable): a
/// density as the visibility distance it gives (the meteorological range
/// 3.912 / extinction, where contrast falls to 2 %), a height falloff as the
/// height over which the fog halves (ln 2 / falloff). Typing or dragging
/// one sets the parameter through editParam (auto-key, clamping).
void drawArtistReadout(Document& doc, EditState& edit, const ParamRef& ref, const double value[4],
                       double timeHours, std::string& status) {
    const std::string_view path = ref.desc->path;
    const bool density =
        path == "fog.density_per_m" || (ref.scope() == ParamScope::Volume && path == "density_per_m");
    const bool falloff =
        path == "fog.falloff_per_m" || (ref.scope() == ParamScope::Volume && path == "falloff_per_m");
    if (!density && !falloff) return;
    constexpr double kMeteorologicalRange = 3.912;  // -ln(0.02)
    const double ln2 = std::log(2.0);
    ImGui::Dummy(ImVec2(ImGui::GetFrameHeight() * 0.8f, ImGui::GetFrameHeight()));
    ImGui::SameLine(0.0f, 4.0f);
    const double physical = value[0];
    double shown = physical > 0.0 ? (density ? kMeteorologicalRange : ln2) / physical : 0.0;
    const char* label =
        density ? (ref.scope() == ParamScope::Volume ? "  = visibility inside [m]" : "  = visibility [m]")
                : "  = half-height [m]";
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.75f, 0.85f, 1.0f, 1.0f));
    double lo = 1.0, hi = 100000.0;
    const bool changed = ImGui::DragScalar(
        label, ImGuiDataType_Double, &shown, float(std::max(shown, 1.0) * 0.01), &lo, &hi,
        physical > 0.0 ? "%.0f" : (density ? "clear" : "uniform"), ImGuiSliderFlags_Logarithmic);
    ImGui::PopStyleColor();
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "%s", density ? "How far you see through it: 3.912 / density (2 % contrast). Type or drag "
                            "to set the density from it."
                          : "Height over which the fog density halves: ln 2 / falloff. Type or drag "
                            "to set the falloff from it.");
    if (changed && shown > 0.0) {
        double v[4] = {(density ? kMeteorologicalRange : ln2) / shown, 0, 0, 0};
        const std::string clamped = editParam(doc, edit, ref, v, true, timeHours);
        if (!clamped.empty()) status = clamped;
    }
    if (ImGui::IsItemDeactivated()) doc.closeMerge();
}

void drawParam(Document& doc, EditState& edit, const ParamRef& ref, double timeHours, std::string& status) {
    const ParamDesc& p = *ref.desc;
    ImGui::PushID(paramAddress(ref).c_str());
    if (p.animatable)
        keyButton(doc, edit, ref, timeHours);
    else
        ImGui::Dummy(ImVec2(ImGui::GetFrameHeight() * 0.8f, ImGui::GetFrameHeight()));
    ImGui::SameLine(0.0f, 0.0f);
    curveButton(doc, edit, ref);
    ImGui::SameLine(0.0f, 4.0f);
    std::string label = labelOf(p);
    double v[4];
    displayedValueAt(doc.preset(), edit.pending, ref, timeHours, v);
    const bool animated = trackOf(doc.preset(), ref) != nullptr;
    const bool unkeyed = edit.pending.find(ref) != nullptr;
    const bool selected = edit.selectedParam && *edit.selectedParam == ref;
    // Animated: amber; an unkeyed change (auto-key off): red, with Key and Revert after it.
    if (animated)
        ImGui::PushStyleColor(ImGuiCol_FrameBg, unkeyed ? ImVec4(0.55f, 0.16f, 0.14f, 0.9f)
                                                        : ImVec4(0.35f, 0.27f, 0.10f, 0.8f));
    if (selected) ImGui::PushStyleColor(ImGuiCol_Border, ImVec4(0.95f, 0.75f, 0.25f, 1.0f));
    if (selected) ImGui::PushStyleVar(ImGuiStyleVar_FrameBorderSize, 1.0f);
    // An unkeyed change puts Key and Revert after the field: the field leaves them room.
    const ImGuiStyle& style = ImGui::GetStyle();
    const float buttonsW = unkeyed ? ImGui::CalcTextSize("KeyRevert").x + 4.0f * style.FramePadding.x +
                                         2.0f * style.ItemSpacing.x
                                   : 0.0f;
    ImGui::PushItemWidth(std::max(1.0f, ImGui::CalcItemWidth() - buttonsW));
    // A label longer than the label column ("Volumetric noise scale [m]" in a
    // narrow panel): on its own line, the field across the panel below it.
    const std::string visible = label.substr(0, label.find("##"));
    const bool ownLine = p.type != ParamType::Quaternion &&
                         ImGui::CalcTextSize(visible.c_str()).x > ImGui::GetContentRegionAvail().x -
                                                                      ImGui::CalcItemWidth() -
                                                                      style.ItemInnerSpacing.x;
    if (ownLine) {
        ImGui::TextUnformatted(visible.c_str());
        ImGui::SetNextItemWidth(std::max(1.0f, ImGui::GetContentRegionAvail().x - buttonsW));
        std::string hidden = "##";  // (not "##" + label: GCC 12 warns falsely, -Wrestrict)
        hidden += label;
        label = hidden;
    }
    // A row of numbers too narrow for them ("5.802e-06" for each of Rayleigh's
    // three): the label on its own line, the numbers across the panel below it.
    auto numbersLabel = [&](int count) {
        const float need =
            float(count) * (ImGui::CalcTextSize("-0.000e-00").x + 2.0f * style.FramePadding.x) +
            float(count - 1) * style.ItemInnerSpacing.x;
        if (ownLine || ImGui::CalcItemWidth() >= need) return label;
        ImGui::TextUnformatted(label.c_str());
        ImGui::SetNextItemWidth(std::max(1.0f, ImGui::GetContentRegionAvail().x - buttonsW));
        std::string hidden = "##";  // (not "##" + label: GCC 12 warns falsely, -Wrestrict)
        hidden += label;
        return hidden;
    };
    bool changed = false;
    bool continuous = true;
    switch (p.type) {
        case ParamType::Scalar: {
            // A drag field: dragging changes the value relative to where it
            // was (no jump to the click), double-click or Ctrl+click types
            // one; typed values may leave the slider's range (up to the valid
            // range, beyond it clamped with a message).
            double lo = p.uiMin, hi = p.uiMax;
            if (!(hi > lo)) lo = p.minValue, hi = p.maxValue;
            const ImGuiSliderFlags flags = p.logScale ? ImGuiSliderFlags_Logarithmic : 0;
            const float speed = float((hi - lo) / 300.0);
            changed =
                ImGui::DragScalar(label.c_str(), ImGuiDataType_Double, &v[0], speed, &lo, &hi, "%.5g", flags);
            break;
        }
        case ParamType::Vec3: {
            const double lo = p.minValue, hi = p.maxValue;
            const double span = (p.uiMax > p.uiMin ? p.uiMax - p.uiMin : 1.0);
            changed = ImGui::DragScalarN(numbersLabel(3).c_str(), ImGuiDataType_Double, v, 3,
                                         float(span / 400.0), &lo, &hi, "%.4g");
            break;
        }
        case ParamType::Vec2: {  // [x, z], the label carries the unit
            const double lo = p.minValue, hi = p.maxValue;
            const double span = (p.uiMax > p.uiMin ? p.uiMax - p.uiMin : 1.0);
            changed = ImGui::DragScalarN(numbersLabel(2).c_str(), ImGuiDataType_Double, v, 2,
                                         float(span / 400.0), &lo, &hi, "%.4g");
            break;
        }
        case ParamType::Colour: {
            float c[3] = {float(v[0]), float(v[1]), float(v[2])};
            changed =
                ImGui::ColorEdit3(label.c_str(), c, ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR);
            v[0] = c[0], v[1] = c[1], v[2] = c[2];
            break;
        }
        case ParamType::Quaternion: {
            const glm::dquat q(v[3], v[0], v[1], v[2]);
            glm::dvec3 euler = glm::eulerAngles(q) * kDegrees;
            double e[3] = {euler.x, euler.y, euler.z};
            const std::string eulerLabel = std::string(p.label) + " [deg XYZ]";
            changed = ImGui::DragScalarN(eulerLabel.c_str(), ImGuiDataType_Double, e, 3, 0.5f, nullptr,
                                         nullptr, "%.1f");
            if (changed) {
                const glm::dquat r(glm::dvec3(e[0], e[1], e[2]) / kDegrees);
                v[0] = r.x, v[1] = r.y, v[2] = r.z, v[3] = r.w;
            }
            break;
        }
        case ParamType::Enum: {
            int current = int(v[0]);
            const std::string preview = current >= 0 && current < int(p.enumNames.size())
                                            ? std::string(p.enumNames[std::size_t(current)])
                                            : "?";
            if (ImGui::BeginCombo(label.c_str(), preview.c_str())) {
                for (std::size_t i = 0; i < p.enumNames.size(); ++i) {
                    const std::string name(p.enumNames[i]);
                    if (ImGui::Selectable(name.c_str(), int(i) == current)) {
                        v[0] = double(i);
                        changed = true;
                    }
                }
                ImGui::EndCombo();
            }
            continuous = false;
            break;
        }
        case ParamType::Int: {
            long long i = (long long)(v[0]);
            changed = ImGui::InputScalar(label.c_str(), ImGuiDataType_S64, &i, nullptr, nullptr, nullptr,
                                         ImGuiInputTextFlags_EnterReturnsTrue);
            v[0] = double(i);
            continuous = false;
            break;
        }
        case ParamType::String: {
            // Text parameters of the environment (location.date): typed, then
            // checked on Enter; a wrong one is shown and changes nothing.
            if (ref.scope() != ParamScope::Global) break;
            static std::string rejectedAddress, rejectedMessage;
            Environment env = doc.preset().environment;
            std::string text = *p.string(&env);
            if (ImGui::InputText(label.c_str(), &text, ImGuiInputTextFlags_EnterReturnsTrue)) {
                std::string why;
                if (editTextParam(doc, ref, text, why)) {
                    rejectedAddress.clear();
                } else {
                    rejectedAddress = paramAddress(ref);
                    rejectedMessage = why;
                }
            }
            if (rejectedAddress == paramAddress(ref))
                ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.35f, 1.0f), "%s (not changed)",
                                   rejectedMessage.c_str());
            continuous = false;
            break;
        }
    }
    ImGui::PopItemWidth();
    if (selected) ImGui::PopStyleVar();
    if (selected) ImGui::PopStyleColor();
    if (animated) ImGui::PopStyleColor();
    if (p.animatable && (ImGui::IsItemActivated() || ImGui::IsItemClicked())) {
        if (!(edit.selectedParam && *edit.selectedParam == ref)) edit.selectedKey = -1;
        edit.selectedParam = ref;
    }
    if (changed) {
        const std::string clamped = editParam(doc, edit, ref, v, continuous, timeHours);
        if (!clamped.empty()) status = clamped;
    }
    if (ImGui::IsItemDeactivated()) doc.closeMerge();
    if (ImGui::IsItemHovered()) {
        ImGui::BeginTooltip();
        ImGui::PushTextWrapPos(360.0f);
        ImGui::TextUnformatted(std::string(p.doc).c_str());
        ImGui::PopTextWrapPos();
        if (p.type != ParamType::Enum && p.type != ParamType::Quaternion && p.type != ParamType::String)
            ImGui::TextDisabled("valid %g .. %g %s%s", p.minValue, p.maxValue, std::string(p.unit).c_str(),
                                p.logScale ? "  (log slider)" : "");
        ImGui::TextDisabled("%s", paramAddress(ref).c_str());
        if (const Track* track = trackOf(doc.preset(), ref))
            ImGui::TextDisabled("animated: %zu keys (%s)", track->keys.size(),
                                std::string(interpolationName(track->interpolation)).c_str());
        if (const PendingEdit* held = edit.pending.find(ref))
            ImGui::TextColored(ImVec4(1.0f, 0.5f, 0.4f, 1.0f), "unkeyed change made at %s (auto-key off)",
                               formatClock(held->timeHours, ClockResolution::Minutes).c_str());
        ImGui::EndTooltip();
    }
    if (edit.pending.find(ref)) {
        ImGui::SameLine();
        if (ImGui::SmallButton("Key")) keyParamNow(doc, edit, ref, timeHours);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Key this change (auto-key is off)");
        ImGui::SameLine();
        if (ImGui::SmallButton("Revert")) edit.pending.erase(ref);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Back to the animated value");
    }
    if (p.type == ParamType::Scalar) drawArtistReadout(doc, edit, ref, v, timeHours, status);
    ImGui::PopID();
}

/// A city instead of typed coordinates: one undo step that sets latitude,
/// longitude and UTC offset (places.hpp).
void drawPlacePicker(Document& doc) {
    if (ImGui::BeginCombo("Place", "Choose a city...", ImGuiComboFlags_HeightLarge)) {
        for (const Place& place : places()) {
            const std::string label = std::string(place.name);
            if (ImGui::Selectable(label.c_str()))
                doc.apply("Place: " + label, "",
                          [&](Preset& p) { applyPlace(p.environment.location, place); });
        }
        ImGui::EndCombo();
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "Sets latitude, longitude and the UTC offset of standard time (add 1 h for summer "
            "time).\nLongitude and offset take effect once the preset has a date; the offset in "
            "clock time mode.");
}

/// A mesh volume's file: the path the preset stores, what was read from it
/// and a button to choose another (the file dialog; the mesh is checked
/// before anything changes).
void drawMeshRow(const FogVolume& v, const ActionTable& actions) {
    if (v.shape != FogVolumeShape::Mesh) return;
    ImGui::Dummy(ImVec2(ImGui::GetFrameHeight() * 0.8f, 1.0f));
    ImGui::SameLine(0.0f, 4.0f);
    if (ImGui::Button("Choose mesh...")) actions.run("choose_volume_mesh");
    ImGui::SameLine();
    ImGui::TextUnformatted(v.mesh.empty() ? "(no file)" : v.mesh.c_str());
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "The glTF file of the volume's closed mesh, relative to the preset's folder; "
            "its position, rotation and half extents (as scale) place it");
    if (v.meshData)
        ImGui::TextDisabled("%zu triangles, %.3g m^3 before scaling", v.meshData->triangleCount(),
                            v.meshData->enclosedVolume());
    else
        ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.35f, 1.0f),
                           "No mesh: choose a closed glTF mesh (draws nothing)");
}

}  // namespace

int keyAllChangedAt(Document& doc, double timeHours) {
    int count = 0;
    const Preset baseline = doc.baseline();
    doc.apply("Key all changed", "", [&](Preset& p) { count = keyAllChanged(p, baseline, timeHours); });
    return count;
}

void drawInspector(Document& doc, EditState& edit, double timeHours, const PresetState& state,
                   const LightReport& light, const ActionTable& actions, std::string& status) {
    const Preset& preset = doc.preset();
    ImGui::PushItemWidth(-std::min(190.0f, ImGui::GetWindowWidth() * 0.48f));
    if (ImGui::Button("Key all changed"))
        status = std::to_string(keyAllChangedAt(doc, timeHours)) + " keys set";
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Key every animatable parameter whose value here differs from the saved preset");
    ImGui::Separator();

    switch (edit.selection.kind) {
        case Selection::Kind::None:
            ImGui::TextDisabled("Nothing selected.");
            ImGui::TextWrapped(
                "Click a volume or an emitter in the viewport, or pick an item in the outliner.");
            break;
        case Selection::Kind::Atmosphere:
        case Selection::Kind::Lights:
        case Selection::Kind::Fog:
        case Selection::Kind::Exposure:
        case Selection::Kind::Clouds: {
            if (edit.selection.kind == Selection::Kind::Atmosphere) {
                std::string name = preset.name, description = preset.description;
                if (ImGui::InputText("Preset name", &name))
                    doc.apply("Rename preset", "preset-name", [&](Preset& p) { p.name = name; });
                if (ImGui::IsItemDeactivated()) doc.closeMerge();
                if (ImGui::InputTextMultiline("Description", &description,
                                              ImVec2(0, ImGui::GetTextLineHeight() * 3)))
                    doc.apply("Edit description", "preset-description",
                              [&](Preset& p) { p.description = description; });
                if (ImGui::IsItemDeactivated()) doc.closeMerge();
            }
            std::string section;
            for (const ParamDesc& p : paramTable(ParamScope::Global)) {
                if (globalGroup(p) != edit.selection.kind) continue;
                const std::string s = sectionOf(p);
                if (s != section) {
                    section = s;
                    ImGui::Spacing();
                    ImGui::TextDisabled("%s", section.c_str());
                    ImGui::Separator();
                }
                drawParam(doc, edit, {&p, -1}, timeHours, status);
            }
            if (edit.selection.kind == Selection::Kind::Lights) {
                drawPlacePicker(doc);
                ImGui::Spacing();
                ImGui::TextDisabled("Now");
                ImGui::Separator();
                const Location& where = preset.environment.location;
                // When and where: the date and time as the preset reads them (aerial/sun.hpp).
                const std::string when = formatClock(timeHours, ClockResolution::Minutes);
                const char ns = where.latitudeDeg < 0.0 ? 'S' : 'N';
                const char ew = where.longitudeDeg < 0.0 ? 'W' : 'E';
                if (std::isfinite(julianDayAt(where, timeHours))) {
                    const bool clock = where.timeMode == TimeMode::Clock;
                    ImGui::Text("%s %s %s%+g, %.2f %c %.2f %c", where.date.c_str(), when.c_str(),
                                clock ? "UTC" : "solar time, lon ",
                                clock ? where.utcOffsetHours : where.longitudeDeg,
                                std::abs(where.latitudeDeg), ns, std::abs(where.longitudeDeg), ew);
                } else {
                    ImGui::Text("Undated: day %.0f, %s solar time, %.2f %c", where.dayOfYear, when.c_str(),
                                std::abs(where.latitudeDeg), ns);
                }
                ImGui::Text("Sun elevation %.2f deg (apparent %.2f), azimuth %.1f deg",
                            state.sunLight.body.elevation * kDegrees,
                            state.sunLight.body.apparentElevation * kDegrees,
                            state.sunLight.body.azimuth * kDegrees);
                ImGui::Text("Moon elevation %.2f deg, lit %.0f%%", state.moonLight.body.elevation * kDegrees,
                            state.moonLight.body.illuminatedFraction * 100.0);
                // The light as a meter reads it, to check against the outdoors
                // (clear noon ~100 000 lx, civil dusk ~3 lx, full moon ~0.25 lx).
                const HorizontalIlluminance& lux = light.horizontalIlluminanceLux;
                ImGui::Text("On the ground %.3g lx: sun %.3g, sky %.3g, moon %.3g, night sky %.3g", lux.total,
                            lux.sun, lux.sky, lux.moon, lux.night);
                ImGui::Text("Zenith %.3g cd/m^2", light.zenithLuminance);
                const double rise = sunriseHours(where), set = sunsetHours(where);
                ImGui::Text("Sunrise %s, noon %s, sunset %s, day %.1f h",
                            formatClock(rise, ClockResolution::Minutes).c_str(),
                            formatClock(solarNoonHours(where), ClockResolution::Minutes).c_str(),
                            formatClock(set, ClockResolution::Minutes).c_str(), dayLengthHours(where));
            }
            if (edit.selection.kind == Selection::Kind::Clouds) {
                ImGui::Spacing();
                ImGui::TextDisabled("Now");
                ImGui::Separator();
                const CloudParams& c = state.environment.clouds;
                const double speed = std::hypot(c.windMPerS.x, c.windMPerS.y);
                ImGui::Text("Coverage %.0f%%, layer %.0f..%.0f m", c.coverage * 100.0, c.bottomM,
                            c.bottomM + c.thicknessM);
                ImGui::Text("Inside a full cloud you see %.0f m",
                            c.densityPerM > 0.0 ? 3.912 / c.densityPerM : 0.0);
                ImGui::Text("Drifting %.1f m/s (%.0f km/h) towards azimuth %.0f deg", speed, speed * 3.6,
                            std::fmod(std::atan2(c.windMPerS.x, -c.windMPerS.y) * kDegrees + 360.0, 360.0));
                if (c.coverage <= 0.0)
                    ImGui::TextWrapped(
                        "Coverage 0: a clear sky. Raise the coverage (and key it over the day).");
            }
            if (edit.selection.kind == Selection::Kind::Exposure) {
                ImGui::Spacing();
                ImGui::TextDisabled("Now");
                ImGui::Separator();
                const ExposureParams& e = state.environment.exposure;
                ImGui::Text("Compensation %+.2f EV at this time", e.compensationEv);
                ImGui::TextWrapped(
                    "The viewport shows it (status bar: the EV100 in use); View > Exposure offset "
                    "adds to it for this view only, without changing the preset.");
            }
            break;
        }
        case Selection::Kind::Volume:
        case Selection::Kind::Emitter:
        case Selection::Kind::CloudVolume: {
            const ParamScope scope = edit.selection.scope();
            const bool volume = scope == ParamScope::Volume;
            const bool emitter = scope == ParamScope::Emitter;
            const int index = edit.selection.index;
            if (index < 0 || std::size_t(index) >= objectCount(preset, scope)) break;
            const std::size_t i = std::size_t(index);
            std::string name = volume    ? preset.volumes[i].name
                               : emitter ? preset.emitters[i].name
                                         : preset.cloudVolumes[i].name;
            const std::string id = volume    ? preset.volumes[i].id
                                   : emitter ? preset.emitters[i].id
                                             : preset.cloudVolumes[i].id;
            ImGui::Dummy(ImVec2(ImGui::GetFrameHeight() * 0.8f, 1.0f));
            ImGui::SameLine(0.0f, 4.0f);
            if (ImGui::InputText("Name", &name))
                doc.apply("Rename", "rename:" + id, [&](Preset& p) { renameObject(p, scope, index, name); });
            if (ImGui::IsItemDeactivated()) doc.closeMerge();
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("The name shown in the outliner");
            // The id: what tracks and games refer to; typed, checked on Enter
            // (unique, the loader's characters), the tracks follow it.
            ImGui::Dummy(ImVec2(ImGui::GetFrameHeight() * 0.8f, 1.0f));
            ImGui::SameLine(0.0f, 4.0f);
            std::string newId = id;
            if (ImGui::InputText("Id", &newId, ImGuiInputTextFlags_EnterReturnsTrue) && newId != id) {
                std::string why;
                Preset changed = preset;
                if (setObjectId(changed, scope, index, newId, why))
                    doc.apply("Change id", "", [&](Preset& p) { setObjectId(p, scope, index, newId, why); });
                else
                    status = "Id not changed: " + why;
            }
            if (ImGui::IsItemHovered())
                ImGui::SetTooltip(
                    "What the timeline's tracks and games (the bake manifest) refer to; "
                    "unique, A-Z a-z 0-9 _ - .");
            const bool lightning = emitter && preset.emitters[i].kind == EmitterKind::Lightning;
            for (const ParamDesc& p : paramTable(scope)) {
                if (p.type == ParamType::String) {  // id and name above; a mesh volume's file
                    if (scope == ParamScope::Volume && p.path == "mesh")
                        drawMeshRow(preset.volumes[i], actions);
                    continue;
                }
                if (emitter && !lightning && lightningOnly(p.path)) continue;
                if (volume && p.path == "edge_softness" &&
                    (preset.volumes[i].shape == FogVolumeShape::Mesh ||
                     preset.volumes[i].blend == FogVolumeBlend::Subtract))
                    continue;  // a mesh or subtract volume keeps a hard edge
                drawParam(doc, edit, {&p, index}, timeHours, status);
            }
            if (scope == ParamScope::CloudVolume && i < state.cloudVolumes.size()) {
                ImGui::Spacing();
                ImGui::TextDisabled("Now");
                ImGui::Separator();
                const CloudVolume& v = state.cloudVolumes[i];
                const CloudParams& c = state.environment.clouds;
                ImGui::Text("Coverage %.0f%% inside (the layer's %.0f%%)", v.coverage * 100.0,
                            c.coverage * 100.0);
                ImGui::Text("Centre %.1f, %.1f km (x, z), %.0f m up", v.position.x / 1000.0,
                            v.position.z / 1000.0, v.position.y);
                ImGui::Text("Layer %.0f..%.0f m", c.bottomM, c.bottomM + c.thicknessM);
                glm::dvec3 lo, hi;
                fogVolumeBounds(shapeOf(v), lo, hi);
                if (hi.y < c.bottomM || lo.y > c.bottomM + c.thicknessM)
                    ImGui::TextWrapped("Above or below the cloud layer: it changes no cloud.");
            }
            if (lightning) {
                ImGui::Spacing();
                ImGui::Text("Flash now: %.2f", lightningFlash(preset.emitters[i], timeHours));
            }
            ImGui::Spacing();
            if (ImGui::Button("Duplicate")) actions.run("duplicate");
            ImGui::SameLine();
            if (ImGui::Button("Delete")) actions.run("delete");
            ImGui::SameLine();
            if (ImGui::Button("Frame (F)")) actions.run("frame");
            break;
        }
    }
    ImGui::PopItemWidth();
}

}  // namespace aerial::editor
