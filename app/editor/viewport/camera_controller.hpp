// viewport/camera_controller.hpp — the editor viewport's camera: orbit, pan,
// zoom, fly and frame-selection, driven by one plain input struct per frame.
//
// Usage (once per frame, before picking and the gizmo):
//   aerial::editor::ViewInput in;
//   in.mouseDelta = {io.MouseDelta.x, io.MouseDelta.y};  in.wheel = io.MouseWheel;
//   in.leftDown = io.MouseDown[0]; in.rightDown = io.MouseDown[1]; in.middleDown = io.MouseDown[2];
//   in.alt = io.KeyAlt; ...; in.dt = io.DeltaTime; in.viewportSize = {w, h};
//   in.hovered = ImGui::IsItemHovered();   // the viewport image
//   ViewUpdate u = controller.update(in);
//   if (!u.capturesMouse) { /* clicks go to the gizmo / picking */ }
//   if (!controller.flying()) { /* W/E/R switch gizmo modes */ }
//   renderer::Camera cam = controller.camera(double(w) / h);
//   controller.frame(centre, radius, double(w) / h);       // on F
//   session["camera"] = cameraStateToJson(controller.state());   // string
//
// Controls (issue 5, "Viewport"; as in Unity/Unreal):
//   - orbit: Alt + left drag, or right drag  -> yaw/pitch about the pivot
//     (the target), the distance to it unchanged;
//   - pan: middle drag (or Alt + middle)      -> eye and target move together
//     in the view plane so the pivot follows the mouse;
//   - zoom: wheel (or Alt + right drag)       -> the distance to the pivot is
//     multiplied by zoomPerNotch^notches; it never reaches or crosses the
//     pivot (kMinDistance);
//   - fly: hold the right button and press W A S D (forward, left, back,
//     right) or Q E (down, up, world Y); Shift moves 4x faster. From the first
//     fly key of a right drag to its release the mouse turns the view about the
//     eye (mouse-look) instead of orbiting, the pivot carried along at the
//     same distance. While the right button is held the wheel changes the fly
//     speed by x1.2 per notch (clamped to [kMinFlySpeed, kMaxFlySpeed]) instead
//     of zooming.
//   - a drag belongs to the viewport only when its button went down while the
//     viewport was hovered; it then continues (and keeps capturing the mouse)
//     outside the viewport until the button is released. The wheel acts only
//     while hovered.
//
// Angles: yaw is the azimuth of the view direction from north (-Z) towards
// east (+X) [rad]; pitch its elevation [rad], negative looking down, clamped
// to +-kMaxPitch so the view never reaches a pole. The view direction is
// (cos(pitch) sin(yaw), sin(pitch), -cos(pitch) cos(yaw)) (DESIGN.md's sun
// convention) and eye = target - distance * forward.
//
// No NaN: every input (NaN, Inf, huge deltas, zero or negative sizes and dt)
// leaves the state finite and inside its ranges; non-finite inputs are
// ignored.
#pragma once

#include <aerial/renderer/camera.hpp>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <string>
#include <string_view>

namespace aerial::editor {

/// One frame of viewport input. Zero values mean "nothing happened".
struct ViewInput {
    glm::dvec2 mouseDelta{0.0};  ///< mouse motion since last frame [px], +x right, +y down
    double wheel = 0.0;          ///< wheel notches this frame, > 0 away from the user (zoom in)
    bool leftDown = false;       ///< left button held
    bool rightDown = false;      ///< right button held
    bool middleDown = false;     ///< middle button held
    bool alt = false;
    bool shift = false;
    bool ctrl = false;
    bool keyW = false;                       ///< fly forward (while the right button is held)
    bool keyA = false;                       ///< fly left
    bool keyS = false;                       ///< fly back
    bool keyD = false;                       ///< fly right
    bool keyQ = false;                       ///< fly down (world -Y)
    bool keyE = false;                       ///< fly up (world +Y)
    double dt = 0.0;                         ///< frame time [s], clamped to [0, 0.25] for flying
    glm::dvec2 viewportSize{1280.0, 720.0};  ///< viewport size [px]
    bool hovered = false;                    ///< the mouse is over the viewport (no other window on top)
};

/// The camera as saved with the editor session (not the preset).
struct CameraState {
    glm::dvec3 target{0.0, 8.0, 0.0};  ///< pivot [m]
    double distance = 120.0;           ///< eye to pivot [m], [kMinDistance, kMaxDistance]
    double yaw = 0.0;                  ///< view azimuth from north (-Z) towards east (+X) [rad]
    double pitch = -0.14;              ///< view elevation [rad], [-kMaxPitch, kMaxPitch]; < 0 looks down
    double flySpeed = 20.0;            ///< fly speed [m/s], [kMinFlySpeed, kMaxFlySpeed]
    double verticalFovDeg = 60.0;      ///< vertical field of view [deg], [kMinFovDeg, kMaxFovDeg]
};

/// What one update did.
struct ViewUpdate {
    bool cameraChanged = false;  ///< the state changed this frame
    bool capturesMouse = false;  ///< a navigation drag owns the mouse (do not pick or start gizmo drags)
    bool flying = false;         ///< a right drag is active (W A S D Q E are fly keys, not shortcuts)
};

inline constexpr double kMinDistance = 0.05;             ///< [m]
inline constexpr double kMaxDistance = 1.0e5;            ///< [m]
inline constexpr double kMaxPitch = 1.5533430342749532;  ///< 89 deg [rad]
inline constexpr double kMinFlySpeed = 0.1;              ///< [m/s]
inline constexpr double kMaxFlySpeed = 5000.0;           ///< [m/s]
inline constexpr double kMinFovDeg = 5.0;
inline constexpr double kMaxFovDeg = 120.0;
inline constexpr double kFlySpeedPerNotch = 1.2;  ///< fly speed factor per wheel notch

/// Returns `state` with every field made finite and clamped to its range;
/// non-finite fields take the defaults of CameraState{}; yaw is wrapped to
/// (-pi, pi].
CameraState sanitisedCameraState(const CameraState& state);

/// Unit view direction of a yaw/pitch pair (see the header comment).
glm::dvec3 viewDirection(double yaw, double pitch);

/// The orbit state that looks from `eye` at `target` [m] with a vertical
/// field of view of `verticalFovDeg` (a preset's view, aerial/preset.hpp):
/// the target is the pivot, the distance |target - eye|; the fly speed
/// comes from `base`. Sanitised as setState does, so a view steeper than
/// kMaxPitch tilts to it (about the pivot) and the field of view clamps to
/// [kMinFovDeg, kMaxFovDeg].
CameraState cameraStateLookingAt(const glm::dvec3& eye, const glm::dvec3& target, double verticalFovDeg,
                                 const CameraState& base = {});

/// The camera state as a one-line JSON object:
/// {"target_m":[x,y,z],"distance_m":..,"yaw_rad":..,"pitch_rad":..,
///  "fly_speed_m_per_s":..,"vertical_fov_deg":..}. Numbers are written with
/// round-trip precision, so cameraStateFromJson gives back the same bits.
std::string cameraStateToJson(const CameraState& state);

/// Parses cameraStateToJson's format (a JSON object; missing keys keep the
/// values already in `state`, unknown keys are ignored). On success the
/// result is sanitised into `state` and true returned; on a syntax error or a
/// wrongly typed or non-finite field `state` is untouched, false returned and
/// `error` (if given) says why.
bool cameraStateFromJson(std::string_view json, CameraState& state, std::string* error = nullptr);

/// Orbit / pan / zoom / fly camera of the viewport. Holds the state and the
/// drag in progress; no window or ImGui dependency.
class CameraController {
public:
    /// Orbit and mouse-look sensitivity [rad/px]. Default 0.005.
    double rotateRadiansPerPixel = 0.005;
    /// Distance factor per wheel notch towards the pivot, in (0, 1). Default 0.85.
    double zoomPerNotch = 0.85;
    /// Near plane [m] for camera(): max(nearDistance, distance * 1e-4). Default 0.1.
    double nearDistance = 0.1;
    /// Far plane [m] for camera(): max(farDistance, 4 * distance). Default 5000.
    double farDistance = 5000.0;

    CameraController() = default;
    explicit CameraController(const CameraState& state) { setState(state); }

    /// Applies one frame of input; see the header comment for the controls.
    ViewUpdate update(const ViewInput& input);

    /// Places the camera so a sphere of `radius` [m] around `centre` fits the
    /// vertical and the horizontal field of view (for `aspect` = width /
    /// height) with a margin (its silhouette spans at most 1/margin of the
    /// narrower half-fov); keeps the view direction. The radius is clamped
    /// to at least 0.1 m; non-finite arguments are ignored.
    void frame(const glm::dvec3& centre, double radius, double aspect = 16.0 / 9.0, double margin = 1.15);

    /// The renderer camera for a viewport of `aspect` = width / height.
    renderer::Camera camera(double aspect) const;

    /// Shorthand for renderer::cameraFrame(camera(aspect)).
    renderer::CameraFrame cameraFrame(double aspect) const;

    /// Eye position [m] and unit view direction.
    glm::dvec3 eye() const;
    glm::dvec3 forward() const;

    const CameraState& state() const { return state_; }
    /// Replaces the state (sanitised) and ends any drag in progress.
    void setState(const CameraState& state);

    /// True while a right drag is active (fly keys and speed wheel).
    bool flying() const { return drag_ == Drag::Right; }
    /// True while any navigation drag owns the mouse.
    bool capturesMouse() const { return drag_ != Drag::None; }

private:
    enum class Drag { None, AltLeft, Right, Middle, AltRight };
    CameraState state_{};
    Drag drag_ = Drag::None;
    bool mouseLook_ = false;  // a fly key was used during this right drag
    bool prevLeft_ = false;
    bool prevRight_ = false;
    bool prevMiddle_ = false;
};

}  // namespace aerial::editor
