// editor/editor_outliner.cpp — the outliner (atmosphere, sun and moon,
// global fog, every fog volume, emitter and cloud volume: select, rename
// inline, duplicate, delete) and, below it, the sky preview: the solved sky seen from below as a
// fisheye (zenith in the centre, the horizon on the rim, north up, east
// right), with the cloud layer's opacity over it, through the same OCIO
// display transform as the viewport.
#include "panels.hpp"

#include <epoxy/gl.h>  // epoxy before any other GL header

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_stdlib.h>

#include <aerial/clouds.hpp>
#include <aerial/evaluate.hpp>
#include <aerial/renderer/image.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <vector>

namespace aerial::editor {
namespace {

constexpr int kSkyPreviewSize = 96;
/// Where the sky preview looks from [m]: above the ground at the origin.
constexpr glm::dvec3 kPreviewEye(0.0, 2.0, 0.0);

bool hasTracks(const Preset& preset, ParamScope scope, const std::string& id) {
    for (const Track& t : preset.tracks)
        if (t.target.scope == scope && t.target.objectId == id) return true;
    return false;
}

}  // namespace

void drawOutliner(Document& doc, EditState& edit, const ActionTable& actions,
                  const std::function<void(Selection)>& select) {
    const Preset& preset = doc.preset();
    const float previewHeight =
        std::min(ImGui::GetContentRegionAvail().x, 150.0f) + ImGui::GetTextLineHeightWithSpacing();
    ImGui::BeginChild("##outliner", ImVec2(0, -previewHeight), false);
    // A context-menu item for an action, with the action's shortcut.
    auto menuItem = [&](const char* label, const char* action) {
        const std::string keys = actions.shortcutOf(action);
        return ImGui::MenuItem(label, keys.empty() ? nullptr : keys.c_str());
    };
    auto item = [&](const char* label, Selection s) {
        if (ImGui::Selectable(label, edit.selection == s)) select(s);
    };
    item("Atmosphere", {Selection::Kind::Atmosphere, -1});
    item("Sun & moon", {Selection::Kind::Lights, -1});
    item("Global fog", {Selection::Kind::Fog, -1});
    item("Exposure", {Selection::Kind::Exposure, -1});
    item("Clouds", {Selection::Kind::Clouds, -1});

    // The id and the shown name of object `i` of a scope.
    auto idAndName = [&](ParamScope scope,
                         std::size_t i) -> std::pair<const std::string*, const std::string*> {
        switch (scope) {
            case ParamScope::Volume:
                return {&preset.volumes[i].id, &preset.volumes[i].name};
            case ParamScope::Emitter:
                return {&preset.emitters[i].id, &preset.emitters[i].name};
            default:
                return {&preset.cloudVolumes[i].id, &preset.cloudVolumes[i].name};
        }
    };
    auto objects = [&](ParamScope scope) {
        const Selection::Kind kind = Selection::kindOf(scope);
        const std::size_t count = objectCount(preset, scope);
        const char* title = scope == ParamScope::Volume    ? "Fog volumes"
                            : scope == ParamScope::Emitter ? "Emitters"
                                                           : "Cloud volumes";
        char header[64];
        std::snprintf(header, sizeof header, "%s (%zu)###%s", title, count,
                      std::string(addressPrefix(scope)).c_str());
        if (!ImGui::TreeNodeEx(header, ImGuiTreeNodeFlags_DefaultOpen | ImGuiTreeNodeFlags_SpanAvailWidth))
            return;
        if (ImGui::BeginPopupContextItem()) {
            if (scope == ParamScope::Volume) {
                if (ImGui::MenuItem("Add box volume")) actions.run("add_box_volume");
                if (ImGui::MenuItem("Add ellipsoid volume")) actions.run("add_ellipsoid_volume");
                if (ImGui::MenuItem("Add mesh volume (glTF)...")) actions.run("add_mesh_volume");
            } else if (scope == ParamScope::Emitter) {
                if (ImGui::MenuItem("Add emitter")) actions.run("add_point_emitter");
                if (ImGui::MenuItem("Add lightning")) actions.run("add_lightning");
            } else {
                if (ImGui::MenuItem("Add cloud box")) actions.run("add_cloud_box");
                if (ImGui::MenuItem("Add cloud ellipsoid")) actions.run("add_cloud_ellipsoid");
            }
            ImGui::EndPopup();
        }
        for (std::size_t i = 0; i < count; ++i) {
            const std::string id = *idAndName(scope, i).first;
            const std::string name = *idAndName(scope, i).second;
            const Selection s{kind, int(i)};
            ImGui::PushID(id.c_str());
            if (edit.renaming && edit.selection == s) {
                ImGui::SetNextItemWidth(-1.0f);
                if (ImGui::IsWindowAppearing() || !ImGui::IsAnyItemActive()) ImGui::SetKeyboardFocusHere();
                if (ImGui::InputText(
                        "##rename", &edit.renameBuffer,
                        ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll)) {
                    const std::string newName = edit.renameBuffer;
                    const int index = int(i);
                    doc.apply("Rename", "", [&](Preset& p) { renameObject(p, scope, index, newName); });
                    edit.renaming = false;
                } else if (ImGui::IsItemDeactivated() || ImGui::IsKeyPressed(GLFW_KEY_ESCAPE)) {
                    edit.renaming = false;
                }
            } else {
                std::string label = name.empty() ? id : name;
                if (hasTracks(preset, scope, id)) label += "  ~";
                const bool filterable = scope == ParamScope::Volume || scope == ParamScope::Emitter;
                if (filterable && edit.viewFilter.soloed(scope, id)) label += "  [solo]";
                if (filterable && edit.viewFilter.muted(scope, id)) label += "  [muted]";
                const bool hidden = filterable && !edit.viewFilter.shows(scope, id);
                if (hidden)
                    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
                if (ImGui::Selectable(label.c_str(), edit.selection == s,
                                      ImGuiSelectableFlags_AllowDoubleClick)) {
                    select(s);
                    if (ImGui::IsMouseDoubleClicked(0)) {
                        edit.renaming = true;
                        edit.renameBuffer = name;
                    }
                }
                if (hidden) ImGui::PopStyleColor();
                if (ImGui::IsItemHovered())
                    ImGui::SetTooltip("%s (id %s)%s. Double-click to rename, right-click for more.",
                                      name.c_str(), id.c_str(),
                                      hasTracks(preset, scope, id) ? ", animated" : "");
                if (ImGui::BeginPopupContextItem()) {
                    select(s);
                    if (ImGui::MenuItem("Rename")) {
                        edit.renaming = true;
                        edit.renameBuffer = name;
                    }
                    if (menuItem("Duplicate", "duplicate")) actions.run("duplicate");
                    if (menuItem("Delete", "delete")) actions.run("delete");
                    if (menuItem("Frame", "frame")) actions.run("frame");
                    if (filterable) {
                        ImGui::Separator();
                        if (ImGui::MenuItem("Solo (view only)", nullptr, edit.viewFilter.soloed(scope, id)))
                            edit.viewFilter.toggleSolo(scope, id);
                        if (ImGui::MenuItem("Mute (view only)", nullptr, edit.viewFilter.muted(scope, id)))
                            edit.viewFilter.toggleMute(scope, id);
                        if (edit.viewFilter.active() && ImGui::MenuItem("Show all")) edit.viewFilter.clear();
                    }
                    ImGui::EndPopup();
                }
            }
            ImGui::PopID();
            if (i >= objectCount(doc.preset(), scope)) break;
        }
        ImGui::TreePop();
    };
    objects(ParamScope::Volume);
    objects(ParamScope::Emitter);
    objects(ParamScope::CloudVolume);
    ImGui::Spacing();
    // The add buttons flow onto a new line when the panel is narrow.
    // (The room left on the line is measured from the end of the button
    // before: once a button is drawn the cursor is already on the next line.)
    auto flowButton = [first = true](const char* label) mutable {
        const ImGuiStyle& style = ImGui::GetStyle();
        const float width = ImGui::CalcTextSize(label).x + style.FramePadding.x * 2.0f;
        const float lineEnd = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
        if (!first && ImGui::GetItemRectMax().x + style.ItemSpacing.x + width <= lineEnd) ImGui::SameLine();
        first = false;
        return ImGui::SmallButton(label);
    };
    if (flowButton("+ Box")) actions.run("add_box_volume");
    if (flowButton("+ Ellipsoid")) actions.run("add_ellipsoid_volume");
    if (flowButton("+ Mesh")) actions.run("add_mesh_volume");
    if (flowButton("+ Emitter")) actions.run("add_point_emitter");
    ImGui::EndChild();
}

namespace {

void updateSkyPreview(SkyPreview& preview, const SkyService& sky, const ViewportState& view, int frameIndex) {
    // The clouds, when there are any: they move with the time and change
    // with their parameters without a new sky solve.
    const CloudField clouds = prepareClouds(sky.state);
    const CloudParams& cp = sky.state.environment.clouds;
    char settings[256];
    // The viewport's exposure (the preset's, adapting, plus the offset), to 0.1 EV.
    std::snprintf(settings, sizeof settings, "%s|%s|%.1f|%d|%.3f|%.4g|%.4g|%.4g|%.4g|%.3f|%lld",
                  view.displayName.c_str(), view.viewName.c_str(),
                  view.display ? view.display->exposureEv() : 0.0, clouds.active() ? 1 : 0,
                  clouds.active() ? sky.state.timeHours : 0.0, cp.coverage, cp.densityPerM, cp.bottomM,
                  cp.thicknessM, cp.type, static_cast<long long>(cp.seed));
    std::string key = settings;
    for (const CloudVolume& v : sky.state.cloudVolumes) {  // cloud volumes change the preview too
        std::snprintf(settings, sizeof settings, "|%d %.4g %.4g %.4g %.4g %.4g %.4g %.4g %.4g %.4g %.3f %.3f",
                      int(v.shape), v.position.x, v.position.y, v.position.z, v.halfExtents.x,
                      v.halfExtents.y, v.halfExtents.z, v.rotation.x, v.rotation.y, v.rotation.z, v.coverage,
                      v.edgeSoftness);
        key += settings;
    }
    if (preview.texture && preview.generation == sky.generation && preview.settings == key) return;
    // While scrubbing, refresh every 4th frame: the preview is small and the viewport matters more.
    if (preview.texture && preview.settings == key && (frameIndex % 4) != 0) return;
    const int n = kSkyPreviewSize;
    renderer::Image image;
    image.width = image.height = n;
    image.channels = 4;
    image.pixels.assign(std::size_t(n) * std::size_t(n) * 4, 0.0f);
    const double g = sky.state.environment.atmosphere.mieAnisotropy;
    const SkyTable& sun = sky.sunSolver->table();
    const SkyTable& moon = sky.moonSolver->table();
    glm::dvec3 cloudLight(0.0);
    if (clouds.active()) {
        const glm::dvec3 up(0.0, 1.0, 0.0);
        glm::dvec3 zenith(0.0);
        if (sun.generation > 0) zenith += skyRadiance(sun, g, up, sky.state.sunLight.illuminanceSpace);
        if (moon.generation > 0) zenith += skyRadiance(moon, g, up, sky.state.moonLight.illuminanceSpace);
        cloudLight =
            cp.albedo * (0.04 * (sky.state.sunLight.illuminance + sky.state.moonLight.illuminance) + zenith);
    }
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const double u = (x + 0.5) / n * 2.0 - 1.0, v = (y + 0.5) / n * 2.0 - 1.0;
            const double r = std::sqrt(u * u + v * v);
            float* px = &image.pixels[(std::size_t(y) * std::size_t(n) + std::size_t(x)) * 4];
            if (r > 1.0) {
                px[0] = px[1] = px[2] = 0.0f;
                px[3] = 0.0f;
                continue;
            }
            const double elevation = (1.0 - r) * kPi * 0.5;
            const double azimuth = std::atan2(u, -v);  // north up, east right
            const glm::dvec3 dir(std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
                                 -std::cos(elevation) * std::cos(azimuth));
            glm::dvec3 L(0.0);
            if (sun.generation > 0) L += skyRadiance(sun, g, dir, sky.state.sunLight.illuminanceSpace);
            if (moon.generation > 0) L += skyRadiance(moon, g, dir, sky.state.moonLight.illuminanceSpace);
            if (clouds.active()) {
                // A preview, not the renderer's lighting: the cloud's opacity
                // along the ray (16 samples) over a cloud lit by a share of
                // the sun and moon that reach the viewer and by the zenith sky.
                const double t =
                    cloudTransmittance(clouds, kPreviewEye, dir, std::numeric_limits<double>::infinity(), 16);
                L = L * t + cloudLight * (1.0 - t);
            }
            px[0] = float(L.x), px[1] = float(L.y), px[2] = float(L.z), px[3] = 1.0f;
        }
    const renderer::Image shown = view.display->applyCpu(image);
    std::vector<std::uint8_t> bytes(std::size_t(n) * std::size_t(n) * 4);
    for (std::size_t i = 0; i < bytes.size(); ++i) {
        const float c =
            i % 4 == 3 ? image.pixels[i] : (shown.pixels.size() == bytes.size() ? shown.pixels[i] : 0.0f);
        bytes[i] = std::uint8_t(std::lround(std::clamp(c, 0.0f, 1.0f) * 255.0f));
    }
    if (!preview.texture) {
        glCreateTextures(GL_TEXTURE_2D, 1, &preview.texture);
        glTextureStorage2D(preview.texture, 1, GL_RGBA8, n, n);
        glTextureParameteri(preview.texture, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTextureParameteri(preview.texture, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    }
    GLint alignment = 4;
    glGetIntegerv(GL_UNPACK_ALIGNMENT, &alignment);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTextureSubImage2D(preview.texture, 0, 0, 0, n, n, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, alignment);
    preview.generation = sky.generation;
    preview.settings = key;
}

}  // namespace

void drawSkyPreview(SkyPreview& preview, const SkyService& sky, const ViewportState& view, int frameIndex) {
    updateSkyPreview(preview, sky, view, frameIndex);
    ImGui::TextDisabled("Sky preview");
    const float size = std::min(ImGui::GetContentRegionAvail().x, 150.0f);
    if (size < 8.0f || !preview.texture) return;
    ImGui::SetCursorPosX(ImGui::GetCursorPosX() + (ImGui::GetContentRegionAvail().x - size) * 0.5f);
    ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(preview.texture)),
                 ImVec2(size, size));
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "The sun's and the moon's sky tables with the per-pixel phase functions\n"
            "(zenith in the centre, horizon on the rim). Sky solve %.2f ms.",
            sky.solveMs);
}

}  // namespace aerial::editor
