// editor/editor_script_view.cpp — the actions only scripts run in the
// viewport: screenshots, gizmo drags, clicks, camera orbits, the display
// (OCIO view, fog view, resolution): entries of the editor's action table
// (see editor_script.cpp), each through the code the viewport uses (the
// gizmo and the camera get synthetic mouse input, one event a frame).
#include "editor.hpp"
#include "script_args.hpp"

#include "viewport/overlay.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace aerial::editor {

bool Editor::queueGizmoDrag(GizmoMode mode, int axis, glm::dvec2 deltaPx, int steps, std::string& error) {
    GizmoTransform transform;
    if (!gizmoTransformOfSelection(transform)) {
        error = "gizmo_drag: select a volume, an emitter or a cloud volume first";
        return false;
    }
    view_.gizmoMode = mode;
    const renderer::CameraFrame frame = viewportCameraFrame();
    const std::optional<glm::dvec2> centre = projectToViewport(frame, view_.size, transform.position);
    if (!centre) {
        error = "gizmo_drag: the selection is behind the camera";
        return false;
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
        return false;
    }
    steps = std::max(1, steps);
    view_.scriptedMouse.push_back({*press, true, true, false});
    for (int k = 1; k <= steps; ++k)
        view_.scriptedMouse.push_back({*press + deltaPx * (double(k) / steps), true, false, false});
    view_.scriptedMouse.push_back({*press + deltaPx, false, false, true});
    view_.scriptedMouseActive = true;
    runner_.waitsForMouse = true;
    std::printf("gizmo_drag: press at %.1f %.1f, %d moves\n", press->x, press->y, steps);
    return true;
}

void Editor::declareViewScriptCommands() {
    ActionTable& table = actions_;
    using W = const ActionArgs&;
    using E = std::string&;

    // --- viewport ------------------------------------------------------------------------
    table.add("screenshot")
        .takes({word("PATH")}, "screenshot PATH.png|PATH.exr")
        .helps("a full-resolution frame of the viewport; prints the selected volume's bounds in it")
        .handles([this](W w, E error) {
            if (!screenshot(w[1], error)) return false;
            std::printf("screenshot %s %dx%d\n", w[1].c_str(), int(std::lround(view_.size.x)),
                        int(std::lround(view_.size.y)));
            FogVolume shape;
            if (selectedVolumeShape(shape)) {
                // The selected (fog or cloud) volume's projected bounds in the screenshot's pixels.
                const renderer::CameraFrame frame = viewportCameraFrame();
                glm::dvec2 lo(1e30), hi(-1e30);
                for (const WorldSegment& seg : volumeOutlineSegments(shape))
                    for (const glm::dvec3& p : {seg.first, seg.second})
                        if (std::optional<glm::dvec2> q = projectToViewport(frame, view_.size, p)) {
                            lo = glm::min(lo, *q);
                            hi = glm::max(hi, *q);
                        }
                if (hi.x >= lo.x)
                    std::printf("selection_bounds %.1f %.1f %.1f %.1f\n", lo.x, lo.y, hi.x, hi.y);
            }
            std::fflush(stdout);
            return true;
        });
    table.add("gizmo_drag")
        .takes({choice("MODE", {"translate", "move", "rotate", "scale"}),
                choice("HANDLE", {"x", "y", "z", "yz", "zx", "xy", "center", "centre", "view"}), number("DX"),
                number("DY"), number("FRAMES").opt()},
               "gizmo_drag translate|rotate|scale x|y|z|yz|zx|xy|center|view DX DY [FRAMES]")
        .helps("drag a gizmo handle of the selection by DX DY pixels (synthetic mouse, one move a frame)")
        .handles([this](W w, E error) {
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
                (w.size() == 6 && !toNumber(w[5], frames))) {
                error = "gizmo_drag: bad axis or distance";
                return false;
            }
            return queueGizmoDrag(mode, axis, {dx, dy}, int(frames), error);
        });
    table.add("click")
        .takes({number("X"), number("Y")})
        .helps("a left click at viewport pixel X Y (picks)")
        .handles([this](W w, E) {
            const double x = w.number(1), y = w.number(2);
            view_.scriptedMouse.push_back({{x, y}, true, true, false});
            view_.scriptedMouse.push_back({{x, y}, false, false, true});
            view_.scriptedMouseActive = true;
            runner_.waitsForMouse = true;
            return true;
        });
    table.add("orbit")
        .takes({number("DX"), number("DY"), number("FRAMES").opt()})
        .helps("a right drag in the viewport: the camera orbits")
        .handles([this](W w, E error) {
            const double dx = w.number(1), dy = w.number(2), frames = w.has(3) ? w.number(3) : 8.0;
            if (frames < 1) {
                error = "orbit: FRAMES \"" + w[3] + "\" is less than 1";
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
        });
    table.add("print_camera").ignoresExtraWords().helps("print the camera as JSON").handles([this](W, E) {
        std::printf("camera %s\n", cameraStateToJson(view_.camera.state()).c_str());
        return true;
    });
    table.add("gizmo_space")
        .takes({choice("SPACE", {"world", "local"})})
        .helps("the gizmo's axes")
        .handles([this](W w, E) {
            view_.gizmoSpace = w[1] == "local" ? GizmoSpace::Local : GizmoSpace::World;
            return true;
        });
    table.add("view")
        .takes({word("NAME"), word("MODE").opt()},
               "view NAME | view clouds|shadows on|off | view fog preset|analytic|volumetric")
        .helps(
            "the OCIO view; or switch the view's cloud layer or sun shadows (View > Clouds, View > Sun "
            "shadows), or how it draws the fog (View > Fog ...)")
        .handles([this](W w, E error) {
            if (w.size() == 3) {
                // In the frame's signature: the next frame shows it.
                if (w[1] == "fog" && (w[2] == "preset" || w[2] == "analytic" || w[2] == "volumetric")) {
                    view_.fogView = w[2] == "preset"     ? ViewportState::FogView::Preset
                                    : w[2] == "analytic" ? ViewportState::FogView::Analytic
                                                         : ViewportState::FogView::Volumetric;
                    return true;
                }
                if ((w[1] != "clouds" && w[1] != "shadows") || (w[2] != "on" && w[2] != "off")) {
                    error = "view: view clouds|shadows on|off, or view fog preset|analytic|volumetric";
                    return false;
                }
                (w[1] == "clouds" ? view_.passes.clouds : view_.passes.shadows) = w[2] == "on";
                return true;
            }
            view_.viewName = w[1];
            rebuildDisplay();
            if (view_.viewName != w[1]) {
                error = "view: no OCIO view \"" + w[1] + "\"";
                return false;
            }
            return true;
        });
    table.add("resolution_scale")
        .takes({number("S")})
        .helps("the viewport's resolution scale (0.1 .. 1)")
        .handles([this](W w, E error) {
            const double s = w.number(1);
            if (s < 0.1 || s > 1.0) {
                error = "resolution_scale: S \"" + w[1] + "\" is not in 0.1 .. 1";
                return false;
            }
            view_.resolutionScale = s;
            return true;
        });
}

}  // namespace aerial::editor
