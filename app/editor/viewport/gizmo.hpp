// viewport/gizmo.hpp — the move / rotate / scale gizmo of the viewport:
// immediate mode (like ImGuizmo), with the maths (update) separate from the
// drawing (draw) so it is tested without a window or an ImGui context.
//
// Usage (each frame, after the camera controller):
//   GizmoInput in;
//   in.mouse = mouseInViewportPx; in.down = io.MouseDown[0];
//   in.pressed = viewportHovered && ImGui::IsMouseClicked(0) && !cameraCapturesMouse;
//   in.released = ImGui::IsMouseReleased(0);
//   GizmoTransform t{volume.position, volume.rotation, volume.halfExtents};
//   GizmoSnap snap; snap.enabled = io.KeyCtrl;
//   GizmoResult r = gizmo.update(frame, viewportSize, in, mode, space, snap, t);
//   if (r.started)  undo.beginDrag(selection);          // remember the old values
//   if (r.changed)  { volume.position = t.position; ... } // live, no undo step
//   if (r.finished) undo.commitDrag();                   // ONE step per drag
//   if (!r.hovered && !r.active && in.pressed) pick(...); // click selects
//   gizmo.draw(ImGui::GetWindowDrawList(), viewportOriginScreen, frame, viewportSize, mode, space, t);
// The gizmo writes `inout` only while its own drag is active (it reads it
// every frame for the hover test); on other frames it leaves it untouched. For an emitter pass scale {1,1,1} and
// use Translate only (or ignore rotation/scale changes).
//
// Handles (axis ids in GizmoResult::axis, GizmoHandle):
//   Translate: arrows along X (red), Y (green), Z (blue); squares for the
//              planes YZ, ZX, XY (coloured by their normal axis); a centre
//              square that moves in the view plane.
//   Rotate:    rings about X, Y, Z (their front halves are pickable), and an
//              outer ring (View) about the view direction.
//   Scale:     lines with cubes along X, Y, Z (always the object's LOCAL
//              axes: a world-axis scale of a rotated object would shear), and a
//              centre cube for uniform scale.
// Size: screen-constant, sizePx pixels for an axis, whatever the distance.
// Axes in GizmoSpace::Local are the columns of the start rotation; in World
// the world axes. Axis handles nearly parallel to the view (projected length
// under 10% of sizePx) and plane squares nearly edge-on (|cos| of the angle
// between their normal and the direction to the eye under 0.15) are hidden
// and not pickable.
//
// Drag maths (all relative to the state at the press, so a drag never
// drifts):
//   translate axis:  the closest point between the mouse ray and the axis
//                    line through the start position; offset = s - s0 (the
//                    line parameters at the current and the press ray);
//   translate plane: ray-plane hit on the plane through the start position;
//                    offset = hit - hit0 (centre handle: the plane facing the
//                    camera at the press);
//   rotate:          the signed angle about the axis between hit0 - centre and
//                    hit - centre on the plane through the centre, unwrapped
//                    frame to frame so drags beyond +-180 deg accumulate;
//                    rotation = axisAngle(angle, worldAxis) * startRotation.
//                    A ring seen nearly edge-on at the press (|cos| of the
//                    angle between its axis and the direction to the eye
//                    below kEdgeOnRingCos), where plane hits are unstable,
//                    turns by the mouse's travel along the ring's projected
//                    tangent at the press point instead: angle = travel [px] /
//                    sizePx [px] (100 px = 1 rad at the default size);
//   scale axis:      factor = s / s0 (ratio of the projected distances from
//                    the centre along the axis); scale[i] = start[i] * factor;
//   scale uniform:   factor = 1 + ((mouse - press).x - (mouse - press).y) / sizePx
//                    (right or up grows), every component * factor.
// Snapping (GizmoSnap::enabled, the shell passes Ctrl): the translation offset
// is rounded to a multiple of `translate` along each moved axis (in the
// gizmo's space; the view-plane handle snaps the world components), the angle
// to a multiple of `rotateDeg`, the scale factor to 1 + k * `scale`.
// Scale never reaches 0: every component stays >= kMinGizmoScale (the factor
// is clamped). A ray parallel to a drag plane, one whose hit or closest point
// is behind the eye (the mouse beyond the plane's horizon or the axis's
// vanishing point), or a position beyond 1e7 m keeps the last valid value for
// that frame. Non-finite input changes nothing.
#pragma once

#include <aerial/renderer/camera.hpp>

#include <glm/gtc/quaternion.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <string>

struct ImDrawList;

namespace aerial::editor {

enum class GizmoMode { Translate, Rotate, Scale };
enum class GizmoSpace { World, Local };

/// Handle ids; GizmoResult::axis holds static_cast<int>(handle).
enum class GizmoHandle : int {
    None = -1,
    X = 0,
    Y = 1,
    Z = 2,
    PlaneYZ = 3,  ///< translate in the plane normal to X
    PlaneZX = 4,  ///< normal to Y
    PlaneXY = 5,  ///< normal to Z
    Centre = 6,   ///< translate in the view plane / uniform scale
    View = 7,     ///< rotate about the view direction
};

/// The object being edited: position [m], rotation (world from object) and
/// scale (for fog volumes their half extents [m]).
struct GizmoTransform {
    glm::dvec3 position{0.0};
    glm::dquat rotation{1.0, 0.0, 0.0, 0.0};
    glm::dvec3 scale{1.0};
};

/// Rings whose axis makes |cos| below this with the direction to the eye
/// (within about 11.5 deg of edge-on) rotate by the tangent drag.
inline constexpr double kEdgeOnRingCos = 0.2;

/// Smallest scale component a drag can produce.
inline constexpr double kMinGizmoScale = 1e-3;

struct GizmoSnap {
    bool enabled = false;
    double translate = 1.0;   ///< translation step [m], > 0 (else no snapping)
    double rotateDeg = 15.0;  ///< angle step [deg], > 0
    double scale = 0.1;       ///< scale factor step, > 0
};

/// The left mouse button this frame, positions in pixels from the viewport's
/// top-left corner. `pressed`: went down this frame (pass it only when the
/// viewport is hovered and the camera does not capture the mouse);
/// `released`: went up this frame.
struct GizmoInput {
    glm::dvec2 mouse{0.0};
    bool down = false;
    bool pressed = false;
    bool released = false;
};

struct GizmoResult {
    bool hovered = false;   ///< the mouse is over a handle (or a drag is active): do not pick
    bool active = false;    ///< a drag is in progress (after this frame)
    bool started = false;   ///< a drag began this frame: take the undo snapshot now
    bool changed = false;   ///< `inout` was modified this frame
    bool finished = false;  ///< the drag ended this frame: commit ONE undo step
                            ///< (it may have changed nothing: compare before committing)
    int axis = -1;          ///< GizmoHandle of the active or else hovered handle
};

class Gizmo {
public:
    /// Axis length on screen [px]. Default 100.
    double sizePx = 100.0;
    /// How near the mouse must be to a handle [px]. Default 8.
    double pickRadiusPx = 8.0;

    /// Hover test, drag start / progress / end; see the header comment.
    /// `mode` and `space` are latched when a drag starts. A drag ends on
    /// `released` or when `down` is false.
    GizmoResult update(const renderer::CameraFrame& frame, glm::dvec2 viewportSize, const GizmoInput& input,
                       GizmoMode mode, GizmoSpace space, const GizmoSnap& snap, GizmoTransform& inout);

    /// Ends an active drag and restores the transform it started from (for
    /// Escape). Returns false (and leaves `inout`) when no drag is active.
    bool cancel(GizmoTransform& inout);

    bool active() const { return active_; }
    /// The handle under the mouse at the last update (None while dragging
    /// another one).
    GizmoHandle hoveredHandle() const { return hovered_; }
    GizmoHandle activeHandle() const { return active_ ? activeHandle_ : GizmoHandle::None; }

    /// World length [m] that spans sizePx pixels at `position` (the gizmo's
    /// axis length there); sizePx * 2 tan(fov/2) depth / height, with the depth
    /// clamped to the near plane.
    double worldSizeAt(const renderer::CameraFrame& frame, double viewportHeight,
                       const glm::dvec3& position) const;

    /// The three unit axes of the gizmo for a space and rotation (Scale mode
    /// always uses Local).
    static void axes(GizmoMode mode, GizmoSpace space, const glm::dquat& rotation, glm::dvec3 out[3]);

    /// The handle under `mouse` [px from the viewport's top-left] or None.
    GizmoHandle hitTest(const renderer::CameraFrame& frame, glm::dvec2 viewportSize, glm::dvec2 mouse,
                        GizmoMode mode, GizmoSpace space, const GizmoTransform& transform) const;

    /// A short description of the drag in progress for the status bar and
    /// the viewport: "X +2.50 m" (axis), "+1.00 +0.00 -2.25 m" (plane or view
    /// plane, world components), "Y +37.5°" (rotation, unwrapped), "X x1.40"
    /// (scale factor); empty when no drag is active.
    std::string dragLabel() const;

    /// Draws the handles into `drawList` (ImGui), the viewport's top-left at
    /// `viewportOriginScreen` [ImGui screen px]; the hovered or active handle
    /// is drawn highlighted (yellow). Needs an ImGui context (this is the
    /// only function here that does). Draws nothing when the gizmo centre is
    /// behind the near plane. While rotating, the swept angle is shown as a
    /// translucent fan; during any drag dragLabel() is written beside the
    /// centre.
    void draw(ImDrawList* drawList, glm::dvec2 viewportOriginScreen, const renderer::CameraFrame& frame,
              glm::dvec2 viewportSize, GizmoMode mode, GizmoSpace space,
              const GizmoTransform& transform) const;

private:
    bool active_ = false;
    GizmoHandle activeHandle_ = GizmoHandle::None;
    GizmoHandle hovered_ = GizmoHandle::None;
    GizmoMode activeMode_ = GizmoMode::Translate;
    GizmoSpace activeSpace_ = GizmoSpace::World;
    GizmoTransform start_{};
    glm::dvec3 axes_[3]{};         // latched at the press
    glm::dvec3 planeNormal_{0.0};  // drag plane (plane handles, centre, rotate)
    glm::dvec3 pressPoint_{0.0};   // hit of the press ray on the drag plane / axis point
    double pressParam_ = 0.0;      // line parameter at the press (axis handles)
    glm::dvec2 pressMouse_{0.0};
    double angle_ = 0.0;  // accumulated rotation angle [rad], unsnapped
    glm::dvec3 prevRotateVector_{0.0};
    bool rotateByTangent_ = false;   // edge-on ring: angle from the mouse travel along the tangent
    glm::dvec2 tangentScreen_{0.0};  // unit screen direction of increasing angle at the press
    double worldSize_ = 1.0;         // axis length [m] at the press
    GizmoTransform last_{};          // last value written
    double appliedAngle_ = 0.0;      // rotation angle of last_ [rad] (snapped, unwrapped)
};

}  // namespace aerial::editor
