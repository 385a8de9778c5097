// editor/editor_script.cpp — automation (`aerial-editor --script FILE`): one
// command per frame, through the same code paths as the menus, the
// inspector, the timeline and the viewport (the gizmo gets synthetic mouse
// presses, moves and releases, one per frame, exactly as from ImGui). A
// failing command prints "FILE:LINE: reason" and exits 1; the script ends
// the editor (exit 0) after its last command.
//
// Parameters are addressed as in preset_edit.hpp: "fog.density_per_m",
// "volume[0].density_per_m", "emitter[1].intensity_per_m". Times are hours
// or HH:MM.
//
//   new | open PATH | open_expect_error PATH | save [PATH] | drop PATH
//   load_scene PATH | screenshot PATH.png|.exr | window_screenshot PATH.png | export DIR
//   add_volume box|ellipsoid | add_emitter point|lightning
//   select atmosphere|lights|fog|none | select volume|emitter N
//   delete | duplicate | rename NAME | frame
//   set KEY V... | key KEY | unkey KEY | interp KEY step|linear|smooth | key_all_changed
//   copy_key KEY | paste_key KEY | move_key KEY FROM TO
//   time T | scrub FROM TO FRAMES | play SPEED FRAMES
//   gizmo_drag translate|rotate|scale x|y|z|xy|yz|zx|center|view DX DY [FRAMES]
//   click X Y                  (viewport pixels: picks like a mouse click)
//   orbit DX DY [FRAMES]       (a right drag: the camera orbits) | print_camera
//   gizmo_space world|local | view NAME | exposure EV | resolution_scale S
//   request_new | request_open PATH | request_quit   (ask first, as the menus do)
//   answer save|discard|cancel  (the unsaved-changes prompt's buttons)
//   dialog_submit PATH         (confirm the open file dialog) | close_window
//   undo | redo | wait_frames N | wait_autosave | print KEY | quit
//   expect_dirty | expect_clean | expect_param KEY V... TOL
//   expect_volumes N | expect_emitters N | expect_keys KEY N | expect_selected KIND [N]
//   expect_undo N              (the number of undo steps)
//   expect_prompt | expect_no_prompt | expect_title TEXT
#include "editor.hpp"

#include "viewport/overlay.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace aerial::editor {
namespace {

bool toNumber(const std::string& text, double& out) {
    if (text.empty()) return false;
    char* end = nullptr;
    out = std::strtod(text.c_str(), &end);
    return end && *end == '\0' && std::isfinite(out);
}

bool toTime(const std::string& text, double& hours) {
    int h = 0, m = 0;
    char extra = 0;
    if (std::sscanf(text.c_str(), "%d:%d%c", &h, &m, &extra) == 2 && h >= 0 && h < 24 && m >= 0 && m < 60) {
        hours = h + m / 60.0;
        return true;
    }
    return toNumber(text, hours) && hours >= 0.0 && hours <= 24.0;
}

std::string formatValues(const double* v, int n) {
    std::string text;
    char part[40];
    for (int i = 0; i < n; ++i) {
        std::snprintf(part, sizeof part, "%s%.17g", i ? " " : "", v[i]);
        text += part;
    }
    return text;
}

int valueCount(const ParamDesc& p) {
    switch (p.type) {
        case ParamType::Colour:
        case ParamType::Vec3:
            return 3;
        case ParamType::Quaternion:
            return 4;
        default:
            return 1;
    }
}

}  // namespace

void Editor::stepScript() {
    if (frames_.frameIndex < 2) return;  // the first frames lay out the window and render once
    if (runner_.waitFrames > 0) {
        --runner_.waitFrames;
        return;
    }
    if (runner_.waitsForMouse) {
        if (!view_.scriptedMouse.empty() || view_.scriptedMouseActive) return;
        runner_.waitsForMouse = false;
    }
    if (!runner_.times.empty()) {
        playback_.timeHours = runner_.times.front();
        runner_.times.pop_front();
        return;
    }
    if (runner_.waitsForAutosave) {
        if (autosave_ && autosave_->writes() > runner_.autosaveWrites) {
            runner_.waitsForAutosave = false;
            std::printf("autosaved %s\n", autosave_->recoveryFile().c_str());
            std::fflush(stdout);
        }
        return;
    }
    if (export_.running()) return;
    if (runner_.next >= runner_.commands.size()) {
        quit_ = true;
        return;
    }
    const ScriptCommand& command = runner_.commands[runner_.next++];
    std::string error;
    if (!runScriptCommand(command, error)) {
        std::fprintf(stderr, "aerial-editor: %s:%d: %s\n", options_.script.c_str(), command.line,
                     error.c_str());
        exitCode_ = kExitFailure;
        quit_ = true;
    }
}

void Editor::queueGizmoDrag(GizmoMode mode, int axis, glm::dvec2 deltaPx, int steps, bool& ok,
                            std::string& error) {
    ok = false;
    GizmoTransform transform;
    if (!gizmoTransformOfSelection(transform)) {
        error = "gizmo_drag: select a volume or an emitter first";
        return;
    }
    view_.gizmoMode = mode;
    const renderer::CameraFrame frame = viewportCameraFrame();
    const std::optional<glm::dvec2> centre = projectToViewport(frame, view_.size, transform.position);
    if (!centre) {
        error = "gizmo_drag: the selection is behind the camera";
        return;
    }
    // Find a pixel on the wanted handle: search outwards from the centre.
    const GizmoHandle wanted = GizmoHandle(axis);
    std::optional<glm::dvec2> press;
    const double reach = view_.gizmo.sizePx * 1.6;
    for (double r = 0.0; r <= reach && !press; r += 2.0) {
        const int samples = std::max(1, int(r * 0.8));
        for (int i = 0; i < samples && !press; ++i) {
            const double a = 2.0 * kPi * i / samples;
            const glm::dvec2 p = *centre + r * glm::dvec2(std::cos(a), std::sin(a));
            if (p.x < 1 || p.y < 1 || p.x > view_.size.x - 1 || p.y > view_.size.y - 1) continue;
            if (view_.gizmo.hitTest(frame, view_.size, p, mode, view_.gizmoSpace, transform) == wanted &&
                (r > 6.0 || wanted == GizmoHandle::Centre))
                press = p;
        }
    }
    if (!press) {
        error = "gizmo_drag: the handle is not visible in the viewport";
        return;
    }
    steps = std::max(1, steps);
    view_.scriptedMouse.push_back({*press, true, true, false});
    for (int k = 1; k <= steps; ++k)
        view_.scriptedMouse.push_back({*press + deltaPx * (double(k) / steps), true, false, false});
    view_.scriptedMouse.push_back({*press + deltaPx, false, false, true});
    view_.scriptedMouseActive = true;
    runner_.waitsForMouse = true;
    std::printf("gizmo_drag: press at %.1f %.1f, %d moves\n", press->x, press->y, steps);
    ok = true;
}

bool Editor::runScriptCommand(const ScriptCommand& command, std::string& error) {
    const std::vector<std::string>& w = command.words;
    const std::string& name = w[0];
    const std::size_t argc = w.size() - 1;
    auto need = [&](std::size_t lo, std::size_t hi, const char* usage) {
        if (argc < lo || argc > hi) {
            error = name + ": usage: " + usage;
            return false;
        }
        return true;
    };
    auto param = [&](const std::string& address) -> std::optional<ParamRef> {
        return parseParamAddress(doc_.preset(), address, &error);
    };
    std::printf("script:%d: %s\n", command.line, name.c_str());
    std::fflush(stdout);

    if (name == "new") {
        if (!need(0, 0, "new")) return false;
        dialogs_.pending = Pending::New;
        runPending();
        return true;
    }
    if (name == "open") {
        if (!need(1, 1, "open PATH")) return false;
        if (!openPreset(w[1])) {
            error = "open " + w[1] + " failed:\n" + dialogs_.errorText;
            return false;
        }
        return true;
    }
    if (name == "open_expect_error") {
        if (!need(1, 1, "open_expect_error PATH")) return false;
        const std::uint64_t before = doc_.revision();
        const std::string beforePath = doc_.path();
        if (openPreset(w[1])) {
            error = "open_expect_error: " + w[1] + " loaded";
            return false;
        }
        if (doc_.revision() != before || doc_.path() != beforePath) {
            error = "open_expect_error: the document changed";
            return false;
        }
        std::printf("load error shown:\n%s", dialogs_.errorText.c_str());
        return true;
    }
    if (name == "save") {
        if (!need(0, 1, "save [PATH]")) return false;
        const std::string path = argc == 1 ? w[1] : doc_.path();
        if (path.empty()) {
            error = "save: the document has no file yet; give a PATH";
            return false;
        }
        if (!savePresetTo(path)) {
            error = "save failed: " + dialogs_.errorText;
            return false;
        }
        return true;
    }
    if (name == "drop") {
        if (!need(1, 1, "drop PATH")) return false;
        dialogs_.drops.push_back(w[1]);
        return true;
    }
    if (name == "load_scene") {
        if (!need(1, 1, "load_scene PATH")) return false;
        if (!loadScene(w[1])) {
            error = dialogs_.errorText;
            return false;
        }
        return true;
    }
    if (name == "screenshot") {
        if (!need(1, 1, "screenshot PATH.png|PATH.exr")) return false;
        if (!screenshot(w[1], error)) return false;
        std::printf("screenshot %s %dx%d\n", w[1].c_str(), int(std::lround(view_.size.x)),
                    int(std::lround(view_.size.y)));
        if (edit_.selection.kind == Selection::Kind::Volume &&
            edit_.selection.index < int(sky_.state.volumes.size())) {
            // The selected volume's projected bounds in the screenshot's pixels.
            const renderer::CameraFrame frame = viewportCameraFrame();
            glm::dvec2 lo(1e30), hi(-1e30);
            for (const WorldSegment& s :
                 volumeOutlineSegments(sky_.state.volumes[std::size_t(edit_.selection.index)]))
                for (const glm::dvec3& p : {s.first, s.second})
                    if (std::optional<glm::dvec2> q = projectToViewport(frame, view_.size, p)) {
                        lo = glm::min(lo, *q);
                        hi = glm::max(hi, *q);
                    }
            if (hi.x >= lo.x) std::printf("selection_bounds %.1f %.1f %.1f %.1f\n", lo.x, lo.y, hi.x, hi.y);
        }
        std::fflush(stdout);
        return true;
    }
    if (name == "answer") {
        if (!need(1, 1, "answer save|discard|cancel")) return false;
        if (!dialogs_.unsavedPromptOpen && !dialogs_.openUnsavedModal) {
            error = "answer: no unsaved-changes prompt is open";
            return false;
        }
        dialogs_.openUnsavedModal = false;
        if (w[1] == "save")
            resolveUnsaved(UnsavedChoice::Save);
        else if (w[1] == "discard")
            resolveUnsaved(UnsavedChoice::Discard);
        else if (w[1] == "cancel")
            resolveUnsaved(UnsavedChoice::Cancel);
        else {
            error = "answer: save, discard or cancel";
            return false;
        }
        return true;
    }
    if (name == "request_new" || name == "request_open" || name == "request_quit") {
        // As the menu items do: they ask first when there is unsaved work.
        if (name == "request_open" ? !need(1, 1, "request_open PATH") : !need(0, 0, name.c_str()))
            return false;
        if (name == "request_new") requestNew();
        if (name == "request_open") requestOpen(w[1]);
        if (name == "request_quit") requestQuit();
        return true;
    }
    if (name == "dialog_submit") {
        // The open file dialog (Open, Save As, ...) confirmed with PATH.
        if (!need(1, 1, "dialog_submit PATH")) return false;
        if (!dialogs_.fileDialog.isOpen()) {
            error = "dialog_submit: no file dialog is open";
            return false;
        }
        if (!dialogs_.fileDialog.submit(w[1])) {
            error = "dialog_submit: " + dialogs_.fileDialog.error();
            return false;
        }
        return true;
    }
    if (name == "close_window") {
        // As the window manager's close button: the same path (asks first).
        glfwSetWindowShouldClose(window_, GLFW_TRUE);
        return true;
    }
    if (name == "expect_prompt" || name == "expect_no_prompt") {
        const bool open = dialogs_.unsavedPromptOpen || dialogs_.openUnsavedModal;
        if (open != (name == "expect_prompt")) {
            error = std::string("the unsaved-changes prompt is ") + (open ? "open" : "not open");
            return false;
        }
        return true;
    }
    if (name == "expect_title") {
        if (!need(1, 1, "expect_title TEXT")) return false;
        if (doc_.title() != w[1]) {
            error = "expect_title: have \"" + doc_.title() + "\"";
            return false;
        }
        return true;
    }
    if (name == "window_screenshot") {
        if (!need(1, 1, "window_screenshot PATH.png")) return false;
        runner_.windowShotPath = w[1];
        return true;
    }
    if (name == "export") {
        if (!need(1, 1, "export DIR")) return false;
        if (!export_.start(doc_.preset(), w[1], 0.5, error)) return false;
        export_.wait();
        export_.poll();
        if (!export_.succeeded()) {
            error = "export failed: " + export_.summary();
            export_.acknowledge();
            return false;
        }
        std::printf("exported %s: %s\n", w[1].c_str(), export_.summary().c_str());
        export_.acknowledge();
        return true;
    }
    if (name == "add_volume") {
        if (!need(1, 1, "add_volume box|ellipsoid")) return false;
        if (w[1] != "box" && w[1] != "ellipsoid") {
            error = "add_volume: box or ellipsoid";
            return false;
        }
        addVolumeInFront(w[1] == "box" ? FogVolumeShape::Box : FogVolumeShape::Ellipsoid);
        const FogVolume& v = doc_.preset().volumes.back();
        std::printf("added volume %zu at %.17g %.17g %.17g\n", doc_.preset().volumes.size() - 1, v.position.x,
                    v.position.y, v.position.z);
        return true;
    }
    if (name == "add_emitter") {
        if (!need(1, 1, "add_emitter point|lightning")) return false;
        if (w[1] != "point" && w[1] != "lightning") {
            error = "add_emitter: point or lightning";
            return false;
        }
        addEmitterInFront(w[1] == "point" ? EmitterKind::Point : EmitterKind::Lightning);
        return true;
    }
    if (name == "select") {
        if (!need(1, 2, "select atmosphere|lights|fog|none | select volume|emitter N")) return false;
        double index = -1;
        if (argc == 2 && !toNumber(w[2], index)) {
            error = "select: bad index";
            return false;
        }
        const Preset& p = doc_.preset();
        if (w[1] == "volume" && index >= 0 && index < double(p.volumes.size()))
            select({Selection::Kind::Volume, int(index)});
        else if (w[1] == "emitter" && index >= 0 && index < double(p.emitters.size()))
            select({Selection::Kind::Emitter, int(index)});
        else if (w[1] == "atmosphere")
            select({Selection::Kind::Atmosphere, -1});
        else if (w[1] == "lights")
            select({Selection::Kind::Lights, -1});
        else if (w[1] == "fog")
            select({Selection::Kind::Fog, -1});
        else if (w[1] == "none")
            select({Selection::Kind::None, -1});
        else {
            error = "select: no such object";
            return false;
        }
        return true;
    }
    if (name == "delete" || name == "duplicate" || name == "frame") {
        if (!need(0, 0, "delete|duplicate|frame")) return false;
        if (!edit_.objectSelected()) {
            error = name + ": select a volume or an emitter first";
            return false;
        }
        if (name == "delete") deleteSelection();
        if (name == "duplicate") duplicateSelection();
        if (name == "frame") frameSelection();
        return true;
    }
    if (name == "rename") {
        if (!need(1, 1, "rename NAME")) return false;
        if (!edit_.objectSelected()) {
            error = "rename: select a volume or an emitter first";
            return false;
        }
        const ParamScope scope =
            edit_.selection.kind == Selection::Kind::Volume ? ParamScope::Volume : ParamScope::Emitter;
        const int index = edit_.selection.index;
        doc_.apply("Rename", "", [&](Preset& p) { renameObject(p, scope, index, w[1]); });
        return true;
    }
    if (name == "set") {
        if (argc < 2) {
            error = "set: usage: set KEY V...";
            return false;
        }
        const std::optional<ParamRef> ref = param(w[1]);
        if (!ref) return false;
        const int n = valueCount(*ref->desc);
        double v[4] = {0, 0, 0, 0};
        if (ref->desc->type == ParamType::Enum && argc == 2) {
            bool found = false;
            for (std::size_t i = 0; i < ref->desc->enumNames.size(); ++i)
                if (ref->desc->enumNames[i] == w[2]) v[0] = double(i), found = true;
            if (!found && !toNumber(w[2], v[0])) {
                error = "set: \"" + w[2] + "\" is not a value of " + w[1];
                return false;
            }
        } else {
            if (int(argc) - 1 != n) {
                error = "set: " + w[1] + " takes " + std::to_string(n) + " values";
                return false;
            }
            for (int i = 0; i < n; ++i)
                if (!toNumber(w[std::size_t(2 + i)], v[i])) {
                    error = "set: \"" + w[std::size_t(2 + i)] + "\" is not a number";
                    return false;
                }
        }
        editParam(*ref, v, false);
        edit_.selectedParam = ref;
        return true;
    }
    if (name == "key" || name == "unkey") {
        if (!need(1, 1, "key|unkey KEY")) return false;
        const std::optional<ParamRef> ref = param(w[1]);
        if (!ref) return false;
        if (!ref->desc->animatable) {
            error = w[1] + " is not animatable";
            return false;
        }
        const double t = playback_.timeHours;
        if (name == "key") {
            doc_.apply("Add key", "", [&](Preset& p) { keyParam(p, *ref, t); });
        } else {
            const Track* track = trackOf(doc_.preset(), *ref);
            const int index = track ? keyIndexAt(*track, t) : -1;
            if (index < 0) {
                error = "unkey: no key of " + w[1] + " at this time";
                return false;
            }
            const TrackTarget target = trackTargetOf(doc_.preset(), *ref);
            doc_.apply("Remove key", "", [&](Preset& p) { removeKey(p, target, index); });
        }
        edit_.selectedParam = ref;
        return true;
    }
    if (name == "copy_key" || name == "paste_key") {
        // The timeline's Copy (the key of KEY at the current time) and Paste (at the current time).
        if (!need(1, 1, "copy_key|paste_key KEY")) return false;
        const std::optional<ParamRef> ref = param(w[1]);
        if (!ref) return false;
        const double t = playback_.timeHours;
        if (name == "copy_key") {
            const Track* track = trackOf(doc_.preset(), *ref);
            const int index = track ? keyIndexAt(*track, t) : -1;
            if (index < 0) {
                error = "copy_key: no key of " + w[1] + " at this time";
                return false;
            }
            edit_.keyClipboard = {true, ref->desc->type, track->keys[std::size_t(index)].value};
            return true;
        }
        bool ok = false;
        const KeyClipboard clip = edit_.keyClipboard;
        doc_.apply("Paste key", "", [&](Preset& p) { ok = pasteKey(p, *ref, clip, t); });
        if (!ok) error = "paste_key: nothing copied, or a key of another kind";
        return ok;
    }
    if (name == "move_key") {
        // The timeline's key drag: KEY's key at FROM moves to TO, one undo step.
        if (!need(3, 3, "move_key KEY FROM TO")) return false;
        const std::optional<ParamRef> ref = param(w[1]);
        double from, to;
        if (!ref || !toTime(w[2], from) || !toTime(w[3], to)) {
            if (error.empty()) error = "move_key: bad time";
            return false;
        }
        const Track* track = trackOf(doc_.preset(), *ref);
        const int index = track ? keyIndexAt(*track, from) : -1;
        if (index < 0) {
            error = "move_key: no key of " + w[1] + " at " + w[2];
            return false;
        }
        const TrackTarget target = trackTargetOf(doc_.preset(), *ref);
        const std::string merge = "move-key:" + w[1];
        for (int step = 1; step <= 4; ++step) {  // a drag: several moves, one step
            const double t = from + (to - from) * step / 4.0;
            doc_.apply("Move key", merge, [&](Preset& p) {
                if (Track* tr = findTrack(p, target)) moveKey(*tr, index, t);
            });
        }
        doc_.closeMerge();
        return true;
    }
    if (name == "interp") {
        if (!need(2, 2, "interp KEY step|linear|smooth")) return false;
        const std::optional<ParamRef> ref = param(w[1]);
        if (!ref) return false;
        Interpolation interpolation;
        if (!parseInterpolation(w[2], interpolation)) {
            error = "interp: step, linear or smooth";
            return false;
        }
        const TrackTarget target = trackTargetOf(doc_.preset(), *ref);
        if (!findTrack(doc_.preset(), target)) {
            error = "interp: " + w[1] + " has no track";
            return false;
        }
        doc_.apply("Interpolation", "",
                   [&](Preset& p) { findTrack(p, target)->interpolation = interpolation; });
        return true;
    }
    if (name == "key_all_changed") {
        int count = 0;
        const Preset baseline = doc_.baseline();
        doc_.apply("Key all changed", "",
                   [&](Preset& p) { count = keyAllChanged(p, baseline, playback_.timeHours); });
        std::printf("keyed %d parameters\n", count);
        return true;
    }
    if (name == "time") {
        if (!need(1, 1, "time T")) return false;
        double t;
        if (!toTime(w[1], t)) {
            error = "time: \"" + w[1] + "\" is not HH:MM or hours in [0, 24]";
            return false;
        }
        playback_.jumpTo(t);
        return true;
    }
    if (name == "scrub") {
        if (!need(3, 3, "scrub FROM TO FRAMES")) return false;
        double from, to, frames;
        if (!toTime(w[1], from) || !toTime(w[2], to) || !toNumber(w[3], frames) || frames < 1) {
            error = "scrub: bad arguments";
            return false;
        }
        for (int k = 0; k <= int(frames); ++k)
            runner_.times.push_back(std::min(from + (to - from) * k / frames, 24.0 - 1e-6));
        return true;
    }
    if (name == "play") {
        if (!need(2, 2, "play SPEED FRAMES")) return false;
        double speed, frames;
        if (!toNumber(w[1], speed) || !toNumber(w[2], frames) || frames < 1) {
            error = "play: bad arguments";
            return false;
        }
        playback_.speed = speed;
        playback_.playing = true;
        runner_.waitFrames = int(frames);
        return true;
    }
    if (name == "pause") {
        playback_.playing = false;
        return true;
    }
    if (name == "gizmo_drag") {
        if (!need(4, 5, "gizmo_drag translate|rotate|scale x|y|z|yz|zx|xy|center|view DX DY [FRAMES]"))
            return false;
        GizmoMode mode;
        if (w[1] == "translate" || w[1] == "move")
            mode = GizmoMode::Translate;
        else if (w[1] == "rotate")
            mode = GizmoMode::Rotate;
        else if (w[1] == "scale")
            mode = GizmoMode::Scale;
        else {
            error = "gizmo_drag: translate, rotate or scale";
            return false;
        }
        const std::string& a = w[2];
        const int axis = a == "x"                         ? 0
                         : a == "y"                       ? 1
                         : a == "z"                       ? 2
                         : a == "yz"                      ? 3
                         : a == "zx"                      ? 4
                         : a == "xy"                      ? 5
                         : a == "center" || a == "centre" ? 6
                         : a == "view"                    ? 7
                                                          : -1;
        double dx, dy, frames = 8;
        if (axis < 0 || !toNumber(w[3], dx) || !toNumber(w[4], dy) ||
            (argc == 5 && !toNumber(w[5], frames))) {
            error = "gizmo_drag: bad axis or distance";
            return false;
        }
        bool ok = false;
        queueGizmoDrag(mode, axis, {dx, dy}, int(frames), ok, error);
        return ok;
    }
    if (name == "click") {
        if (!need(2, 2, "click X Y")) return false;
        double x, y;
        if (!toNumber(w[1], x) || !toNumber(w[2], y)) {
            error = "click: bad position";
            return false;
        }
        view_.scriptedMouse.push_back({{x, y}, true, true, false});
        view_.scriptedMouse.push_back({{x, y}, false, false, true});
        view_.scriptedMouseActive = true;
        runner_.waitsForMouse = true;
        return true;
    }
    if (name == "orbit") {
        // A right drag in the viewport (the camera controller's orbit).
        double dx, dy, frames = 8;
        if (!need(2, 3, "orbit DX DY [FRAMES]") || !toNumber(w[1], dx) || !toNumber(w[2], dy) ||
            (argc == 3 && !toNumber(w[3], frames)) || frames < 1) {
            if (error.empty()) error = "orbit: bad arguments";
            return false;
        }
        const glm::dvec2 start = view_.size * 0.5;
        ScriptedMouse press{start, true, true, false, true};
        view_.scriptedMouse.push_back(press);
        for (int k = 1; k <= int(frames); ++k)
            view_.scriptedMouse.push_back(
                {start + glm::dvec2(dx, dy) * (double(k) / frames), true, false, false, true});
        view_.scriptedMouse.push_back({start + glm::dvec2(dx, dy), false, false, true, true});
        view_.scriptedMouseActive = true;
        runner_.waitsForMouse = true;
        return true;
    }
    if (name == "print_camera") {
        std::printf("camera %s\n", cameraStateToJson(view_.camera.state()).c_str());
        return true;
    }
    if (name == "gizmo_space") {
        if (!need(1, 1, "gizmo_space world|local")) return false;
        view_.gizmoSpace = w[1] == "local" ? GizmoSpace::Local : GizmoSpace::World;
        return true;
    }
    if (name == "view") {
        if (!need(1, 1, "view NAME")) return false;
        view_.viewName = w[1];
        rebuildDisplay();
        if (view_.viewName != w[1]) {
            error = "view: no OCIO view \"" + w[1] + "\"";
            return false;
        }
        return true;
    }
    if (name == "exposure") {
        double ev;
        if (!need(1, 1, "exposure EV") || !toNumber(w[1], ev)) return false;
        view_.exposureEv = ev;
        view_.display->setExposureEv(ev);
        return true;
    }
    if (name == "resolution_scale") {
        double s;
        if (!need(1, 1, "resolution_scale S") || !toNumber(w[1], s) || s < 0.1 || s > 1.0) {
            error = "resolution_scale: 0.1 .. 1";
            return false;
        }
        view_.resolutionScale = s;
        return true;
    }
    if (name == "undo" || name == "redo") {
        if (!need(0, 0, "undo|redo")) return false;
        if (!(name == "undo" ? doc_.undo() : doc_.redo())) {
            error = "nothing to " + name;
            return false;
        }
        edit_.validate(doc_.preset());
        return true;
    }
    if (name == "wait_frames") {
        double n;
        if (!need(1, 1, "wait_frames N") || !toNumber(w[1], n) || n < 0) return false;
        runner_.waitFrames = int(n);
        return true;
    }
    if (name == "wait_autosave") {
        if (!autosave_) {
            error = "wait_autosave: autosave is off";
            return false;
        }
        runner_.waitsForAutosave = true;
        runner_.autosaveWrites = autosave_->writes();
        if (!doc_.dirty()) {
            error = "wait_autosave: the document has no unsaved work";
            return false;
        }
        return true;
    }
    if (name == "print") {
        if (!need(1, 1, "print KEY")) return false;
        const std::optional<ParamRef> ref = param(w[1]);
        if (!ref) return false;
        double v[4];
        readValueAt(doc_.preset(), *ref, playback_.timeHours, v);
        std::printf("%s = %s\n", w[1].c_str(), formatValues(v, valueCount(*ref->desc)).c_str());
        return true;
    }
    if (name == "quit") {
        quit_ = true;
        return true;
    }
    if (name == "expect_dirty" || name == "expect_clean") {
        if (doc_.dirty() != (name == "expect_dirty")) {
            error = std::string("the document is ") + (doc_.dirty() ? "dirty" : "clean") + " (title \"" +
                    doc_.title() + "\")";
            return false;
        }
        return true;
    }
    if (name == "expect_param") {
        if (argc < 3) {
            error = "expect_param: usage: expect_param KEY V... TOL";
            return false;
        }
        const std::optional<ParamRef> ref = param(w[1]);
        if (!ref) return false;
        const int n = valueCount(*ref->desc);
        if (int(argc) != n + 2) {
            error = "expect_param: " + w[1] + " has " + std::to_string(n) + " values, then TOL";
            return false;
        }
        double want[4] = {0, 0, 0, 0}, tol = 0, have[4];
        for (int i = 0; i < n; ++i)
            if (!toNumber(w[std::size_t(2 + i)], want[i])) return false;
        if (!toNumber(w.back(), tol)) return false;
        readValueAt(doc_.preset(), *ref, playback_.timeHours, have);
        for (int i = 0; i < n; ++i)
            if (!(std::abs(have[i] - want[i]) <= tol)) {
                error = "expect_param " + w[1] + ": have " + formatValues(have, n) + ", want " +
                        formatValues(want, n) + " (tolerance " + w.back() + ")";
                return false;
            }
        return true;
    }
    if (name == "expect_volumes" || name == "expect_emitters" || name == "expect_undo") {
        double n;
        if (!need(1, 1, "expect_volumes|expect_emitters|expect_undo N") || !toNumber(w[1], n)) return false;
        const std::size_t have = name == "expect_volumes"    ? doc_.preset().volumes.size()
                                 : name == "expect_emitters" ? doc_.preset().emitters.size()
                                                             : doc_.undoCount();
        if (double(have) != n) {
            error = name + ": have " + std::to_string(have);
            return false;
        }
        return true;
    }
    if (name == "expect_keys") {
        double n;
        if (!need(2, 2, "expect_keys KEY N") || !toNumber(w[2], n)) return false;
        const std::optional<ParamRef> ref = param(w[1]);
        if (!ref) return false;
        const Track* track = trackOf(doc_.preset(), *ref);
        const std::size_t have = track ? track->keys.size() : 0;
        if (double(have) != n) {
            error = "expect_keys " + w[1] + ": have " + std::to_string(have);
            return false;
        }
        return true;
    }
    if (name == "expect_selected") {
        if (!need(1, 2, "expect_selected volume|emitter|none|fog|atmosphere|lights [N]")) return false;
        static const char* kinds[] = {"none", "atmosphere", "lights", "fog", "volume", "emitter"};
        const std::string have = kinds[int(edit_.selection.kind)];
        double n = -1;
        if (argc == 2 && !toNumber(w[2], n)) return false;
        if (have != w[1] || (argc == 2 && edit_.selection.index != int(n))) {
            error = "expect_selected: have " + have + " " + std::to_string(edit_.selection.index);
            return false;
        }
        return true;
    }
    error = "unknown command \"" + name + "\"";
    return false;
}

}  // namespace aerial::editor
