// editor/editor_viewport.cpp — the viewport: the renderer draws into its HDR
// target at the viewport size times the resolution scale, the OCIO display
// transform (DisplayTransform::applyGpu) turns it into an RGBA8 texture that
// ImGui shows (flipped: GL rows start at the bottom). Camera, picking,
// gizmo and overlays come from viewport/ (aerial_editor_viewport).
#include "editor.hpp"

#include "viewport/overlay.hpp"
#include "viewport/picking.hpp"

#include <epoxy/gl.h>  // epoxy before any other GL header

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <aerial/renderer/image.hpp>
#include <aerial/renderer/scene.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>

namespace aerial::editor {

renderer::CameraFrame Editor::viewportCameraFrame() const {
    const double aspect = view_.size.y > 0.0 ? view_.size.x / view_.size.y : 16.0 / 9.0;
    return view_.camera.cameraFrame(aspect);
}

void Editor::rebuildDisplay() {
    renderer::DisplayDesc desc;
    desc.display = view_.displayName;
    desc.view = view_.viewName;
    desc.exposureEv = view_.exposure.displayEv(sky_.state.environment.exposure, view_.exposureEv);
    desc.logger = {[](renderer::LogLevel level, const char* message, void*) {
                       if (level >= renderer::LogLevel::Warning)
                           std::fprintf(stderr, "aerial-editor: display: %s\n", message);
                   },
                   nullptr};
    auto display = std::make_unique<renderer::DisplayTransform>(desc);
    if (!display->valid()) {
        setStatus("OCIO: " + display->error() + " (using the default display and view)");
        desc.display.clear();
        desc.view.clear();
        display = std::make_unique<renderer::DisplayTransform>(desc);
    }
    view_.displayName = display->display();
    view_.viewName = display->view();
    view_.display = std::move(display);
}

void Editor::ensureDisplayTexture(int width, int height) {
    if (view_.displayTexture && view_.displayWidth == width && view_.displayHeight == height) return;
    // This frame's ImGui draw list still shows the old texture (the viewport
    // renders after ImGui::Render): it is deleted at the start of the next
    // frame, never while a draw list can bind it.
    if (view_.displayTexture) view_.retiredTextures.push_back(view_.displayTexture);
    glCreateTextures(GL_TEXTURE_2D, 1, &view_.displayTexture);
    glTextureStorage2D(view_.displayTexture, 1, GL_RGBA8, width, height);
    glTextureParameteri(view_.displayTexture, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(view_.displayTexture, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(view_.displayTexture, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(view_.displayTexture, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    view_.displayWidth = width;
    view_.displayHeight = height;
}

void Editor::renderViewport() {
    if (!view_.visible || view_.size.x < 1.0 || view_.size.y < 1.0) return;
    const auto start = std::chrono::steady_clock::now();
    const int width = std::max(1, int(std::lround(view_.size.x * view_.resolutionScale)));
    const int height = std::max(1, int(std::lround(view_.size.y * view_.resolutionScale)));
    // Nothing that the frame depends on changed: keep the last one (an idle
    // editor costs no rendering on a software rasteriser).
    char signature[512];
    const CameraState& c = view_.camera.state();
    std::snprintf(signature, sizeof signature,
                  "%d %d %.17g %llu %llu %llu %llu %.17g %.17g %.17g %.17g %.17g %.17g "
                  "%d%d%d%d%d%d%d%d%d%d%d %s %s %.17g %p w%llu",
                  width, height, playback_.timeHours, static_cast<unsigned long long>(doc_.revision()),
                  static_cast<unsigned long long>(edit_.pending.revision()), edit_.viewFilter.revision(),
                  static_cast<unsigned long long>(sky_.generation), c.target.x, c.target.y, c.target.z,
                  c.distance, c.yaw, c.pitch + 1000.0 * c.verticalFovDeg, view_.passes.sky,
                  view_.passes.scene, view_.passes.globalFog, view_.passes.volumes, view_.passes.emitters,
                  view_.passes.transparent, view_.passes.particles, view_.passes.clouds, view_.passes.shadows,
                  int(view_.fogModeFor(sky_.state.environment)), view_.showStars, view_.displayName.c_str(),
                  view_.viewName.c_str(), view_.exposureEv, static_cast<const void*>(view_.display.get()),
                  static_cast<unsigned long long>(edit_.weather.preview.revision()));
    const auto now = std::chrono::steady_clock::now();
    const double dt = view_.lastExposureStep.time_since_epoch().count() == 0
                          ? 0.0
                          : std::chrono::duration<double>(now - view_.lastExposureStep).count();
    view_.lastExposureStep = now;
    const ExposureParams& exposure = sky_.state.environment.exposure;
    // The amortised clouds converge over a few still frames (renderer.hpp,
    // CloudQuality::Amortised: one pixel of each 4 x 4 block per frame).
    constexpr int kCloudBlock = 4, kCloudConvergeFrames = kCloudBlock * kCloudBlock;
    const bool same = view_.displayTexture && view_.renderWidth == width && view_.renderHeight == height &&
                      view_.lastRenderSignature == signature;
    // So does the volumetric fog's temporal visibility (~10 frames).
    constexpr int kFroxelSettleFrames = 10;
    const bool converging =
        (view_.renderer->stats().cloudHistory.amortised && view_.stillFrames < kCloudConvergeFrames) ||
        (view_.renderer->stats().froxels.drawn && view_.stillFrames < kFroxelSettleFrames);
    if (same && !converging && options_.benchFrames == 0) {
        // The same frame; only an adapting exposure shows it again.
        if (view_.exposure.adapt(exposure, dt)) showViewport(width, height);
        return;
    }
    view_.stillFrames = same ? view_.stillFrames + 1 : 0;
    view_.lastRenderSignature = signature;
    renderer::FrameDesc frame;
    frame.width = width;
    frame.height = height;
    frame.passes = view_.passes;
    frame.fogMode = view_.fogModeFor(sky_.state.environment);  // View > Fog
    // Interactive clouds: a sixteenth of the pixels traced per frame, the
    // rest reprojected; the renderer forgets the history by itself when the
    // time, the camera or the clouds jump (scrubbing never smears).
    frame.cloudQuality = renderer::CloudQuality::Amortised;
    frame.cloudAmortisedBlock = kCloudBlock;
    frame.cloudResetHistory = view_.resetCloudHistory;
    // The volumetric fog accumulates its shafts' visibility over frames the
    // same way (FroxelSettings::temporal), forgotten at the same moments.
    // An edit (a new document revision) may move what casts into the fog.
    frame.froxels.temporal = true;
    frame.froxels.resetHistory = view_.resetCloudHistory || doc_.revision() != view_.froxelRevision;
    view_.froxelRevision = doc_.revision();
    view_.resetCloudHistory = false;
    // --bench: every 10th frame also measures the passes (glFinish around each).
    const bool timed = options_.benchFrames > 0 && frames_.frameIndex >= 3 && frames_.frameIndex % 10 == 0;
    // Every 30th rendered frame is timed pass by pass for the status bar.
    const bool sampled = ++frames_.renderedFrames % 30 == 2;
    frame.gpuTimers = timed || sampled;
    frame.stars = view_.showStars;  // View > Stars
    // Solo / mute (view only): the frame without the objects left out.
    const bool filtered = edit_.viewFilter.active();
    view_.renderer->render(view_.camera.camera(view_.size.x / view_.size.y),
                           filtered ? edit_.viewFilter.applied(sky_.state) : sky_.state, frame);
    if (timed && view_.renderer->stats().timed)
        frames_.benchPasses.push_back(view_.renderer->stats().wallMilliseconds);
    if (view_.renderer->stats().timed) {
        frames_.lastPasses = view_.renderer->stats().wallMilliseconds;
        frames_.lastPassesTimed = true;
    }
    meterViewport();
    view_.exposure.adapt(exposure, dt);
    showViewport(width, height);
    view_.renderWidth = width;
    view_.renderHeight = height;
    view_.renderMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void Editor::meterViewport() {
    const ExposureParams& exposure = sky_.state.environment.exposure;
    double average = 0.0;
    if (exposure.mode == ExposureMode::Automatic) {
        // Every 4th pixel is plenty for a 64-bin histogram.
        const renderer::Image image = view_.renderer->readColour();
        average = meterAverageLuminance(image.pixels, image.channels, image.width, image.height, 4);
    }
    view_.exposure.meter(exposure, average);
}

void Editor::showViewport(int width, int height) {
    view_.display->setExposureEv(view_.exposure.displayEv(sky_.state.environment.exposure,
                                                          view_.exposureEv + view_.display->middleGreyEv()));
    view_.display->setNightVision(view_.nightVision);
    ensureDisplayTexture(width, height);
    view_.display->applyGpu(view_.renderer->colourTexture(), view_.displayTexture, width, height);
}

void Editor::drawViewport() {
    // Toolbar: gizmo mode and space, resolution.
    ImGui::SetCursorPos(ImVec2(6.0f, ImGui::GetCursorPosY() + 2.0f));
    auto modeButton = [&](const char* label, GizmoMode mode, const char* action, const char* tip) {
        const bool on = view_.gizmoMode == mode;
        if (on) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
        if (ImGui::SmallButton(label)) actions_.run(action);
        if (on) ImGui::PopStyleColor();
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tip);
        ImGui::SameLine();
    };
    modeButton("Move", GizmoMode::Translate, "gizmo_move",
               "Move (W): drag an arrow, a plane square or the centre; Ctrl snaps to 1 m");
    modeButton("Rotate", GizmoMode::Rotate, "gizmo_rotate", "Rotate (E): drag a ring; Ctrl snaps to 15 deg");
    modeButton("Scale", GizmoMode::Scale, "gizmo_scale",
               "Scale (R): drag an axis cube or the centre; Ctrl snaps to 0.1");
    if (ImGui::SmallButton(view_.gizmoSpace == GizmoSpace::World ? "World" : "Local"))
        actions_.run("gizmo_local_axes");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Gizmo axes: world or the object's own (L)");
    ImGui::SameLine();
    // Auto-key's state where the artist looks (and the changes it holds back).
    if (edit_.pending.autoKey)
        ImGui::TextColored(ImVec4(1.0f, 0.35f, 0.3f, 1.0f), "AUTO-KEY");
    else if (!edit_.pending.empty())
        ImGui::TextColored(ImVec4(1.0f, 0.5f, 0.4f, 1.0f), "%zu unkeyed", edit_.pending.size());
    else
        ImGui::TextDisabled("auto-key off");
    ImGui::SameLine();
    // The badge: how the picture is made (display view, exposure, resolution).
    ImGui::TextDisabled("%s | EV100 %.1f%+.1f | %dx%d (%d%%)%s",
                        view_.display ? view_.display->view().c_str() : "-", view_.exposure.ev100(),
                        sky_.state.environment.exposure.compensationEv + view_.exposureEv, view_.renderWidth,
                        view_.renderHeight, int(view_.resolutionScale * 100.0 + 0.5),
                        view_.gameView ? " | game view" : "");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "RMB orbit/fly (WASDQE), Alt+LMB orbit, MMB pan, wheel zoom, F frame the selection,\n"
            "G game view, F11 maximize, F1 keys and workflow");
    // The Weather panel's preview: the picture is not the keyed one.
    if (edit_.weather.preview.mode() != WeatherPreview::Mode::None ||
        !edit_.weather.preview.regionsShown().empty()) {
        ImGui::SameLine();
        ImGui::TextColored(ImVec4(0.55f, 0.75f, 1.0f, 1.0f), "weather: %s",
                           edit_.weather.preview.describe().c_str());
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip(
                "Weather preview (View > Weather) and the weather regions at the camera: the viewport only, "
                "never "
                "saved");
    }

    const ImVec2 avail = ImGui::GetContentRegionAvail();
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    view_.origin = {origin.x, origin.y};
    view_.size = {std::max(1.0f, avail.x), std::max(1.0f, avail.y)};
    view_.visible = avail.x >= 1.0f && avail.y >= 1.0f;
    if (!view_.visible) return;
    if (view_.displayTexture)
        ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(view_.displayTexture)), avail,
                     ImVec2(0, 1), ImVec2(1, 0));
    else
        ImGui::InvisibleButton("##viewport", avail);
    const bool hovered = ImGui::IsItemHovered();
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    viewportInteraction(hovered, {double(mouse.x) - origin.x, double(mouse.y) - origin.y}, view_.origin);
}

bool Editor::gizmoTransformOfSelection(GizmoTransform& out) const {
    const Preset& p = doc_.preset();
    const ParamScope scope = edit_.selection.scope();
    const int index = edit_.selection.index;
    if (scope == ParamScope::Global || index < 0 || std::size_t(index) >= objectCount(p, scope)) return false;
    // Placed shapes (fog and cloud volumes) move, rotate and scale; emitters only move.
    auto read = [&](const char* key, double v[4]) {
        readValueAt(p, ParamRef{findParam(scope, key), index}, playback_.timeHours, v);
    };
    double v[4];
    read("position_m", v);
    out.position = {v[0], v[1], v[2]};
    out.rotation = glm::dquat(1.0, 0.0, 0.0, 0.0);
    out.scale = glm::dvec3(1.0);
    if (scope == ParamScope::Emitter) return true;
    read("rotation_xyzw", v);
    out.rotation = glm::dquat(v[3], v[0], v[1], v[2]);
    read("half_extents_m", v);
    out.scale = {v[0], v[1], v[2]};
    return true;
}

void Editor::applyGizmoTransform(const GizmoTransform& t) {
    if (!edit_.objectSelected()) return;
    const ParamScope scope = edit_.selection.scope();
    const int index = edit_.selection.index;
    const double time = playback_.timeHours;
    const char* label = view_.gizmoMode == GizmoMode::Translate ? "Move"
                        : view_.gizmoMode == GizmoMode::Rotate  ? "Rotate"
                                                                : "Scale";
    doc_.apply(label, view_.gizmoMergeKey, [&](Preset& p) {
        const double position[4] = {t.position.x, t.position.y, t.position.z, 0.0};
        setValueAt(p, ParamRef{findParam(scope, "position_m"), index}, position, time);
        if (scope == ParamScope::Emitter) return;
        const double rotation[4] = {t.rotation.x, t.rotation.y, t.rotation.z, t.rotation.w};
        setValueAt(p, ParamRef{findParam(scope, "rotation_xyzw"), index}, rotation, time);
        const double extents[4] = {t.scale.x, t.scale.y, t.scale.z, 0.0};
        setValueAt(p, ParamRef{findParam(scope, "half_extents_m"), index}, extents, time);
    });
}

bool Editor::selectedVolumeShape(FogVolume& out) const {
    const Selection& s = edit_.selection;
    if (s.kind == Selection::Kind::Volume && s.index >= 0 && s.index < int(sky_.state.volumes.size())) {
        out = sky_.state.volumes[std::size_t(s.index)];
        return true;
    }
    if (s.kind == Selection::Kind::CloudVolume && s.index >= 0 &&
        s.index < int(sky_.state.cloudVolumes.size())) {
        out = shapeOf(sky_.state.cloudVolumes[std::size_t(s.index)]);
        return true;
    }
    return false;
}

void Editor::viewportInteraction(bool hovered, glm::dvec2 mouse, glm::dvec2 origin) {
    const ImGuiIO& io = ImGui::GetIO();
    const bool scripted = !view_.scriptedMouse.empty() || view_.scriptedMouseActive;
    std::optional<ScriptedMouse> scriptedInput;
    if (scripted) {
        if (!view_.scriptedMouse.empty()) {
            scriptedInput = view_.scriptedMouse.front();
            view_.scriptedMouse.pop_front();
        }
        view_.scriptedMouseActive = !view_.scriptedMouse.empty();
    }
    ViewInput in;
    if (!scripted) {
        if (std::isfinite(io.MouseDelta.x) && std::abs(io.MouseDelta.x) < 1e6f)
            in.mouseDelta = {io.MouseDelta.x, io.MouseDelta.y};
        in.wheel = hovered ? io.MouseWheel : 0.0;
        in.leftDown = io.MouseDown[0];
        in.rightDown = io.MouseDown[1];
        in.middleDown = io.MouseDown[2];
        in.alt = io.KeyAlt;
        in.shift = io.KeyShift;
        in.ctrl = io.KeyCtrl;
        if (!io.WantTextInput) {
            in.keyW = ImGui::IsKeyDown(GLFW_KEY_W);
            in.keyA = ImGui::IsKeyDown(GLFW_KEY_A);
            in.keyS = ImGui::IsKeyDown(GLFW_KEY_S);
            in.keyD = ImGui::IsKeyDown(GLFW_KEY_D);
            in.keyQ = ImGui::IsKeyDown(GLFW_KEY_Q);
            in.keyE = ImGui::IsKeyDown(GLFW_KEY_E);
        }
        in.hovered = hovered && !ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId);
    } else if (scriptedInput && scriptedInput->right) {
        // A scripted right drag: the camera orbits as under the mouse.
        in.rightDown = scriptedInput->down;
        if (!scriptedInput->pressed) in.mouseDelta = scriptedInput->position - view_.lastScriptedMouse;
        in.hovered = true;
    }
    if (scriptedInput) view_.lastScriptedMouse = scriptedInput->position;
    in.dt = io.DeltaTime;
    in.viewportSize = view_.size;
    const ViewUpdate view = view_.camera.update(in);

    GizmoInput gi;
    if (scripted) {
        if (scriptedInput && !scriptedInput->right) {
            gi.mouse = scriptedInput->position;
            gi.down = scriptedInput->down;
            gi.pressed = scriptedInput->pressed;
            gi.released = scriptedInput->released;
        }
    } else {
        gi.mouse = mouse;
        gi.down = io.MouseDown[0];
        gi.pressed = in.hovered && ImGui::IsMouseClicked(0) && !view.capturesMouse && !io.KeyAlt;
        gi.released = ImGui::IsMouseReleased(0);
    }

    const renderer::CameraFrame frame = viewportCameraFrame();
    bool gizmoOwnsMouse = false;
    GizmoTransform transform;
    const bool haveTransform = view_.helpersShown() && gizmoTransformOfSelection(transform);
    const GizmoMode mode =
        edit_.selection.kind == Selection::Kind::Emitter ? GizmoMode::Translate : view_.gizmoMode;
    if (haveTransform) {
        GizmoSnap snap;
        snap.enabled = io.KeyCtrl && !scripted;
        const GizmoResult r =
            view_.gizmo.update(frame, view_.size, gi, mode, view_.gizmoSpace, snap, transform);
        if (r.started) {
            static unsigned long long dragCounter = 0;
            view_.gizmoMergeKey = "gizmo:" + std::to_string(++dragCounter);
            doc_.closeMerge();
        }
        if (r.changed) applyGizmoTransform(transform);
        if (r.finished) doc_.closeMerge();
        gizmoOwnsMouse = r.hovered || r.active || r.started || r.finished;
    }
    if (gi.pressed && !gizmoOwnsMouse) {
        const Ray ray = rayThroughPixel(frame, gi.mouse, view_.size);
        const double iconRadius = angularRadiusOfPixels(frame, view_.size.y, 10.0);
        const PickHit hit =
            pick(ray, sky_.state.volumes, sky_.state.emitters, sky_.state.cloudVolumes, iconRadius, true);
        if (hit.kind == PickHit::Kind::Volume)
            select({Selection::Kind::Volume, hit.index});
        else if (hit.kind == PickHit::Kind::Emitter)
            select({Selection::Kind::Emitter, hit.index});
        else if (hit.kind == PickHit::Kind::CloudVolume)
            select({Selection::Kind::CloudVolume, hit.index});
        else
            select({Selection::Kind::None, -1});
    }
    // The cloud volume under the mouse (outlined): cloud volumes fill the view, so
    // only the selected and the hovered one are drawn.
    int hoveredCloudVolume = -1;
    if (view_.helpersShown() && !sky_.state.cloudVolumes.empty() && in.hovered && !gizmoOwnsMouse &&
        !view_.gizmo.active() && !scripted) {
        const Ray ray = rayThroughPixel(frame, gi.mouse, view_.size);
        const double iconRadius = angularRadiusOfPixels(frame, view_.size.y, 10.0);
        const PickHit hit =
            pick(ray, sky_.state.volumes, sky_.state.emitters, sky_.state.cloudVolumes, iconRadius, true);
        if (hit.kind == PickHit::Kind::CloudVolume) hoveredCloudVolume = hit.index;
    }

    if (!view_.helpersShown()) return;
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->PushClipRect(ImVec2(float(origin.x), float(origin.y)),
                     ImVec2(float(origin.x + view_.size.x), float(origin.y + view_.size.y)), true);
    if (view_.showGrid) drawGroundGrid(dl, origin, frame, view_.size);
    for (std::size_t i = 0; i < sky_.state.volumes.size(); ++i) {
        const bool selected =
            edit_.selection.kind == Selection::Kind::Volume && edit_.selection.index == int(i);
        drawVolumeOutline(dl, origin, frame, view_.size, sky_.state.volumes[i],
                          selected ? overlayColour(1.0, 0.6, 0.1) : overlayColour(0.8, 0.8, 0.9, 0.25),
                          selected ? 2.0f : 1.0f);
    }
    for (std::size_t i = 0; i < sky_.state.cloudVolumes.size(); ++i) {
        const bool selected =
            edit_.selection.kind == Selection::Kind::CloudVolume && edit_.selection.index == int(i);
        if (!selected && hoveredCloudVolume != int(i)) continue;
        // Light blue-white: apart from the fog volumes' orange and grey.
        drawVolumeOutline(dl, origin, frame, view_.size, shapeOf(sky_.state.cloudVolumes[i]),
                          selected ? overlayColour(0.75, 0.88, 1.0) : overlayColour(0.75, 0.88, 1.0, 0.45),
                          selected ? 2.0f : 1.0f);
    }
    // Weather regions while the Weather panel is open: violet, the selected one brighter.
    for (std::size_t i = 0; edit_.weather.shown && i < doc_.preset().weatherRegions.size(); ++i) {
        const WeatherRegion& r = doc_.preset().weatherRegions[i];
        FogVolume outline;
        outline.shape =
            r.shape == WeatherRegionShape::Ellipsoid ? FogVolumeShape::Ellipsoid : FogVolumeShape::Box;
        outline.position = r.position;
        outline.rotation = r.rotation;
        outline.halfExtents = r.halfExtents;
        const bool selected = edit_.weather.selectedRegion == int(i);
        drawVolumeOutline(dl, origin, frame, view_.size, outline,
                          selected ? overlayColour(0.8, 0.55, 1.0) : overlayColour(0.7, 0.5, 1.0, 0.45),
                          selected ? 2.0f : 1.0f);
    }
    for (std::size_t i = 0; i < sky_.state.emitters.size(); ++i)
        drawEmitterIcon(
            dl, origin, frame, view_.size,
            doc_.preset().emitters.size() > i ? doc_.preset().emitters[i] : sky_.state.emitters[i],
            edit_.selection.kind == Selection::Kind::Emitter && edit_.selection.index == int(i));
    if (haveTransform) {
        GizmoTransform shown;
        gizmoTransformOfSelection(shown);
        view_.gizmo.draw(dl, origin, frame, view_.size, mode, view_.gizmoSpace, shown);
    }
    dl->PopClipRect();
}

void Editor::frameSelection() {
    const double aspect = view_.size.y > 0.0 ? view_.size.x / view_.size.y : 16.0 / 9.0;
    GizmoTransform t;
    if (!gizmoTransformOfSelection(t)) return;
    double radius = 2.0;
    FogVolume shape;
    if (selectedVolumeShape(shape)) {
        glm::dvec3 lo, hi;
        fogVolumeBounds(shape, lo, hi);
        radius = 0.5 * glm::length(hi - lo);
    }
    view_.camera.frame(t.position, radius, aspect);
}

void Editor::goToPresetView() {
    const std::optional<PresetView>& v = doc_.preset().view;
    if (v)
        view_.camera.setState(
            cameraStateLookingAt(v->eye, v->target, v->verticalFovDeg, view_.camera.state()));
}

void Editor::setPresetViewFromCamera() {
    PresetView v;
    v.eye = view_.camera.eye();
    v.target = view_.camera.state().target;
    v.verticalFovDeg = view_.camera.state().verticalFovDeg;
    doc_.apply("Set preset view", "", [&](Preset& p) { p.view = v; });
}

glm::dvec3 Editor::placeForNewObject() const {
    // On the scene's surface under the viewport's centre (its real
    // triangles, any scene), within twice the orbit distance; else where the
    // view ray meets the ground plane, else the orbit pivot.
    const renderer::CameraFrame frame = viewportCameraFrame();
    const double pivot = view_.camera.state().distance;
    if (view_.sceneHits)
        if (const std::optional<double> t = view_.sceneHits->intersect(frame.eye, frame.forward, 2.0 * pivot))
            return frame.eye + *t * frame.forward;
    return placeInFront(frame, pivot, pivot).value_or(frame.eye + pivot * frame.forward);
}

void Editor::setScene(const renderer::SceneDesc& scene) {
    view_.renderer->setScene(scene);
    view_.sceneHits = std::make_shared<const SceneHits>(scene);
    view_.lastRenderSignature.clear();
}

bool Editor::dropSelectionToGround() {
    const ParamScope scope = edit_.selection.scope();
    const int index = edit_.selection.index;
    if (scope != ParamScope::Volume && scope != ParamScope::Emitter) {
        setStatus("Drop to ground: select a fog volume or an emitter");
        return false;
    }
    const Preset& preset = doc_.preset();
    glm::dvec3 position = scope == ParamScope::Volume ? preset.volumes[std::size_t(index)].position
                                                      : preset.emitters[std::size_t(index)].position;
    const std::optional<double> ground =
        view_.sceneHits ? view_.sceneHits->surfaceBelow(position) : std::nullopt;
    if (!ground) {
        setStatus("Drop to ground: no surface under it");
        return false;
    }
    // A volume rests its lowest point (of its rotated hull) on the ground; an emitter floats 0.5 m above.
    double lift = 0.5;
    if (scope == ParamScope::Volume) {
        const PreparedFogVolume p = prepareFogVolume(preset.volumes[std::size_t(index)]);
        lift = p.valid ? position.y - p.boundsMin.y : 0.0;
    }
    position.y = *ground + lift;
    doc_.apply("Drop to ground", "", [&](Preset& p) {
        if (scope == ParamScope::Volume)
            p.volumes[std::size_t(index)].position = position;
        else
            p.emitters[std::size_t(index)].position = position;
    });
    // The height it now has (read back from the document), and the ground's under it.
    const Preset& after = doc_.preset();
    const double y = scope == ParamScope::Volume ? after.volumes[std::size_t(index)].position.y
                                                 : after.emitters[std::size_t(index)].position.y;
    char text[160];
    std::snprintf(text, sizeof text, "Dropped to the ground: %s at y = %.3f m (the ground at %.3f m)",
                  scope == ParamScope::Volume ? "the volume" : "the emitter", y, *ground);
    setStatus(text);
    return true;
}

bool Editor::screenshot(const std::string& path, std::string& error) {
    std::string extension = std::filesystem::path(path).extension().string();
    for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (extension != ".png" && extension != ".exr") {
        error = path + ": a screenshot is .png (display-referred) or .exr (scene-linear half float)";
        return false;
    }
    // A full-resolution frame of the viewport (not the scaled interactive one).
    const int width = std::max(1, int(std::lround(view_.size.x)));
    const int height = std::max(1, int(std::lround(view_.size.y)));
    renderer::FrameDesc frame;
    frame.width = width;
    frame.height = height;
    frame.passes = view_.passes;
    frame.fogMode = view_.fogModeFor(sky_.state.environment);
    frame.stars = view_.showStars;  // View > Stars
    view_.renderer->render(view_.camera.camera(double(width) / double(height)),
                           edit_.viewFilter.active() ? edit_.viewFilter.applied(sky_.state) : sky_.state,
                           frame);
    const renderer::Image image = view_.renderer->readColour();
    view_.renderWidth = 0;  // the next frame renders the scaled view again
    // The settled exposure of this frame (what the viewport adapts to).
    const ExposureParams& exposure = sky_.state.environment.exposure;
    ViewExposure settled;
    settled.meter(exposure, meterAverageLuminance(image.pixels, image.channels, image.width, image.height));
    settled.settle();
    view_.display->setExposureEv(
        settled.displayEv(exposure, view_.exposureEv + view_.display->middleGreyEv()));
    const bool ok = extension == ".exr" ? renderer::writeExr(image, path, error)
                                        : renderer::writePng(image, path, *view_.display, error);
    return ok;
}

}  // namespace aerial::editor
