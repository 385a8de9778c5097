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
    const double aspect = viewportSize_.y > 0.0 ? viewportSize_.x / viewportSize_.y : 16.0 / 9.0;
    return camera_.cameraFrame(aspect);
}

void Editor::rebuildDisplay() {
    renderer::DisplayDesc desc;
    desc.display = displayName_;
    desc.view = viewName_;
    desc.exposureEv = exposureEv_;
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
    displayName_ = display->display();
    viewName_ = display->view();
    display_ = std::move(display);
}

void Editor::ensureDisplayTexture(int width, int height) {
    if (displayTexture_ && displayWidth_ == width && displayHeight_ == height) return;
    if (displayTexture_) glDeleteTextures(1, &displayTexture_);
    glCreateTextures(GL_TEXTURE_2D, 1, &displayTexture_);
    glTextureStorage2D(displayTexture_, 1, GL_RGBA8, width, height);
    glTextureParameteri(displayTexture_, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(displayTexture_, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(displayTexture_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(displayTexture_, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    displayWidth_ = width;
    displayHeight_ = height;
}

void Editor::renderViewport() {
    if (!viewportVisible_ || viewportSize_.x < 1.0 || viewportSize_.y < 1.0) return;
    const auto start = std::chrono::steady_clock::now();
    const int width = std::max(1, int(std::lround(viewportSize_.x * resolutionScale_)));
    const int height = std::max(1, int(std::lround(viewportSize_.y * resolutionScale_)));
    // Nothing that the frame depends on changed: keep the last one (an idle
    // editor costs no rendering on a software rasteriser).
    char signature[512];
    const CameraState& c = camera_.state();
    std::snprintf(signature, sizeof signature,
                  "%d %d %.17g %llu %llu %.17g %.17g %.17g %.17g %.17g %.17g %d%d%d%d%d%d%d%d %s %s %.17g %p",
                  width, height, timeHours_, static_cast<unsigned long long>(doc_.revision()),
                  static_cast<unsigned long long>(skyGeneration_), c.target.x, c.target.y, c.target.z,
                  c.distance, c.yaw, c.pitch + 1000.0 * c.verticalFovDeg, passes_.sky, passes_.scene,
                  passes_.globalFog, passes_.volumes, passes_.emitters, passes_.transparent,
                  passes_.particles, showStars_, displayName_.c_str(), viewName_.c_str(), exposureEv_,
                  static_cast<const void*>(display_.get()));
    if (displayTexture_ && renderWidth_ == width && renderHeight_ == height &&
        lastRenderSignature_ == signature && options_.benchFrames == 0)
        return;
    lastRenderSignature_ = signature;
    renderer::FrameDesc frame;
    frame.width = width;
    frame.height = height;
    frame.passes = passes_;
    // --bench: every 10th frame also measures the passes (glFinish around each).
    const bool timed = options_.benchFrames > 0 && frameIndex_ >= 3 && frameIndex_ % 10 == 0;
    frame.gpuTimers = timed;
    frame.stars = showStars_;  // View > Stars
    renderer_->render(camera_.camera(viewportSize_.x / viewportSize_.y), state_, frame);
    if (timed && renderer_->stats().timed) benchPasses_.push_back(renderer_->stats().wallMilliseconds);
    ensureDisplayTexture(width, height);
    display_->applyGpu(renderer_->colourTexture(), displayTexture_, width, height);
    renderWidth_ = width;
    renderHeight_ = height;
    renderMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void Editor::drawViewport() {
    // Toolbar: gizmo mode and space, resolution.
    ImGui::SetCursorPos(ImVec2(6.0f, ImGui::GetCursorPosY() + 2.0f));
    auto modeButton = [&](const char* label, GizmoMode mode, const char* tip) {
        const bool on = gizmoMode_ == mode;
        if (on) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
        if (ImGui::SmallButton(label)) gizmoMode_ = mode;
        if (on) ImGui::PopStyleColor();
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tip);
        ImGui::SameLine();
    };
    modeButton("Move", GizmoMode::Translate,
               "Move (W): drag an arrow, a plane square or the centre; Ctrl snaps to 1 m");
    modeButton("Rotate", GizmoMode::Rotate, "Rotate (E): drag a ring; Ctrl snaps to 15 deg");
    modeButton("Scale", GizmoMode::Scale, "Scale (R): drag an axis cube or the centre; Ctrl snaps to 0.1");
    if (ImGui::SmallButton(gizmoSpace_ == GizmoSpace::World ? "World" : "Local"))
        gizmoSpace_ = gizmoSpace_ == GizmoSpace::World ? GizmoSpace::Local : GizmoSpace::World;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Gizmo axes: world or the object's own (L)");
    ImGui::SameLine();
    ImGui::TextDisabled("%dx%d (%d%%)  RMB orbit/fly (WASDQE), MMB pan, wheel zoom, F frame", renderWidth_,
                        renderHeight_, int(resolutionScale_ * 100.0 + 0.5));

    const ImVec2 avail = ImGui::GetContentRegionAvail();
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    viewportOrigin_ = {origin.x, origin.y};
    viewportSize_ = {std::max(1.0f, avail.x), std::max(1.0f, avail.y)};
    viewportVisible_ = avail.x >= 1.0f && avail.y >= 1.0f;
    if (!viewportVisible_) return;
    if (displayTexture_)
        ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(displayTexture_)), avail,
                     ImVec2(0, 1), ImVec2(1, 0));
    else
        ImGui::InvisibleButton("##viewport", avail);
    const bool hovered = ImGui::IsItemHovered();
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    viewportInteraction(hovered, {double(mouse.x) - origin.x, double(mouse.y) - origin.y}, viewportOrigin_);
}

bool Editor::gizmoTransformOfSelection(GizmoTransform& out) const {
    const Preset& p = doc_.preset();
    auto read = [&](ParamScope scope, const char* key, int index, double v[4]) {
        readValueAt(p, ParamRef{findParam(scope, key), index}, timeHours_, v);
    };
    double v[4];
    if (selection_.kind == Selection::Kind::Volume && selection_.index < int(p.volumes.size())) {
        read(ParamScope::Volume, "position_m", selection_.index, v);
        out.position = {v[0], v[1], v[2]};
        read(ParamScope::Volume, "rotation_xyzw", selection_.index, v);
        out.rotation = glm::dquat(v[3], v[0], v[1], v[2]);
        read(ParamScope::Volume, "half_extents_m", selection_.index, v);
        out.scale = {v[0], v[1], v[2]};
        return true;
    }
    if (selection_.kind == Selection::Kind::Emitter && selection_.index < int(p.emitters.size())) {
        read(ParamScope::Emitter, "position_m", selection_.index, v);
        out.position = {v[0], v[1], v[2]};
        out.rotation = glm::dquat(1.0, 0.0, 0.0, 0.0);
        out.scale = glm::dvec3(1.0);
        return true;
    }
    return false;
}

void Editor::applyGizmoTransform(const GizmoTransform& t) {
    if (!objectSelected()) return;
    const bool volume = selection_.kind == Selection::Kind::Volume;
    const ParamScope scope = volume ? ParamScope::Volume : ParamScope::Emitter;
    const int index = selection_.index;
    const double time = timeHours_;
    const char* label = gizmoMode_ == GizmoMode::Translate ? "Move"
                        : gizmoMode_ == GizmoMode::Rotate  ? "Rotate"
                                                           : "Scale";
    doc_.apply(label, gizmoMergeKey_, [&](Preset& p) {
        const double position[4] = {t.position.x, t.position.y, t.position.z, 0.0};
        setValueAt(p, ParamRef{findParam(scope, "position_m"), index}, position, time);
        if (!volume) return;
        const double rotation[4] = {t.rotation.x, t.rotation.y, t.rotation.z, t.rotation.w};
        setValueAt(p, ParamRef{findParam(scope, "rotation_xyzw"), index}, rotation, time);
        const double extents[4] = {t.scale.x, t.scale.y, t.scale.z, 0.0};
        setValueAt(p, ParamRef{findParam(scope, "half_extents_m"), index}, extents, time);
    });
}

void Editor::viewportInteraction(bool hovered, glm::dvec2 mouse, glm::dvec2 origin) {
    const ImGuiIO& io = ImGui::GetIO();
    const bool scripted = !scriptedMouse_.empty() || scriptedMouseActive_;
    std::optional<ScriptedMouse> scriptedInput;
    if (scripted) {
        if (!scriptedMouse_.empty()) {
            scriptedInput = scriptedMouse_.front();
            scriptedMouse_.pop_front();
        }
        scriptedMouseActive_ = !scriptedMouse_.empty();
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
        if (!scriptedInput->pressed) in.mouseDelta = scriptedInput->position - lastScriptedMouse_;
        in.hovered = true;
    }
    if (scriptedInput) lastScriptedMouse_ = scriptedInput->position;
    in.dt = io.DeltaTime;
    in.viewportSize = viewportSize_;
    const ViewUpdate view = camera_.update(in);

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
    const bool haveTransform = showHelpers_ && gizmoTransformOfSelection(transform);
    const GizmoMode mode = selection_.kind == Selection::Kind::Emitter ? GizmoMode::Translate : gizmoMode_;
    if (haveTransform) {
        GizmoSnap snap;
        snap.enabled = io.KeyCtrl && !scripted;
        const GizmoResult r = gizmo_.update(frame, viewportSize_, gi, mode, gizmoSpace_, snap, transform);
        if (r.started) {
            static unsigned long long dragCounter = 0;
            gizmoMergeKey_ = "gizmo:" + std::to_string(++dragCounter);
            doc_.closeMerge();
        }
        if (r.changed) applyGizmoTransform(transform);
        if (r.finished) doc_.closeMerge();
        gizmoOwnsMouse = r.hovered || r.active || r.started || r.finished;
    }
    if (gi.pressed && !gizmoOwnsMouse) {
        const Ray ray = rayThroughPixel(frame, gi.mouse, viewportSize_);
        const double iconRadius = angularRadiusOfPixels(frame, viewportSize_.y, 10.0);
        const PickHit hit = pick(ray, state_.volumes, state_.emitters, iconRadius, true);
        if (hit.kind == PickHit::Kind::Volume)
            select({Selection::Kind::Volume, hit.index});
        else if (hit.kind == PickHit::Kind::Emitter)
            select({Selection::Kind::Emitter, hit.index});
        else
            select({Selection::Kind::None, -1});
    }

    if (!showHelpers_) return;
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->PushClipRect(ImVec2(float(origin.x), float(origin.y)),
                     ImVec2(float(origin.x + viewportSize_.x), float(origin.y + viewportSize_.y)), true);
    if (showGrid_) drawGroundGrid(dl, origin, frame, viewportSize_);
    for (std::size_t i = 0; i < state_.volumes.size(); ++i) {
        const bool selected = selection_.kind == Selection::Kind::Volume && selection_.index == int(i);
        drawVolumeOutline(dl, origin, frame, viewportSize_, state_.volumes[i],
                          selected ? overlayColour(1.0, 0.6, 0.1) : overlayColour(0.8, 0.8, 0.9, 0.25),
                          selected ? 2.0f : 1.0f);
    }
    for (std::size_t i = 0; i < state_.emitters.size(); ++i)
        drawEmitterIcon(dl, origin, frame, viewportSize_,
                        doc_.preset().emitters.size() > i ? doc_.preset().emitters[i] : state_.emitters[i],
                        selection_.kind == Selection::Kind::Emitter && selection_.index == int(i));
    if (haveTransform) {
        GizmoTransform shown;
        gizmoTransformOfSelection(shown);
        gizmo_.draw(dl, origin, frame, viewportSize_, mode, gizmoSpace_, shown);
    }
    dl->PopClipRect();
}

void Editor::frameSelection() {
    const double aspect = viewportSize_.y > 0.0 ? viewportSize_.x / viewportSize_.y : 16.0 / 9.0;
    GizmoTransform t;
    if (!gizmoTransformOfSelection(t)) return;
    double radius = 2.0;
    if (selection_.kind == Selection::Kind::Volume && selection_.index < int(state_.volumes.size())) {
        glm::dvec3 lo, hi;
        fogVolumeBounds(state_.volumes[std::size_t(selection_.index)], lo, hi);
        radius = 0.5 * glm::length(hi - lo);
    }
    camera_.frame(t.position, radius, aspect);
}

glm::dvec3 Editor::placeForNewObject() const {
    const renderer::CameraFrame frame = viewportCameraFrame();
    GroundHeightFunction ground;
    if (scenePath_.empty()) ground = [](double x, double z) { return renderer::builtinTerrainHeight(x, z); };
    // Where the view ray meets the ground before the orbit pivot, else at the pivot.
    const double pivot = camera_.state().distance;
    glm::dvec3 where = placeInFront(frame, pivot, pivot, ground).value_or(frame.eye + pivot * frame.forward);
    where.y += 4.0;  // sit on the ground rather than in it
    return where;
}

bool Editor::screenshot(const std::string& path, std::string& error) {
    std::string extension = std::filesystem::path(path).extension().string();
    for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (extension != ".png" && extension != ".exr") {
        error = path + ": a screenshot is .png (display-referred) or .exr (scene-linear half float)";
        return false;
    }
    // A full-resolution frame of the viewport (not the scaled interactive one).
    const int width = std::max(1, int(std::lround(viewportSize_.x)));
    const int height = std::max(1, int(std::lround(viewportSize_.y)));
    renderer::FrameDesc frame;
    frame.width = width;
    frame.height = height;
    frame.passes = passes_;
    frame.stars = showStars_;  // View > Stars
    renderer_->render(camera_.camera(double(width) / double(height)), state_, frame);
    const renderer::Image image = renderer_->readColour();
    renderWidth_ = 0;  // the next frame renders the scaled view again
    const bool ok = extension == ".exr" ? renderer::writeExr(image, path, error)
                                        : renderer::writePng(image, path, *display_, error);
    return ok;
}

}  // namespace aerial::editor
