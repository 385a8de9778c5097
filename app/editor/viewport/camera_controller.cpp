// camera_controller.cpp — orbit / pan / zoom / fly camera of the editor
// viewport (see camera_controller.hpp for the controls and conventions).
#include "viewport/camera_controller.hpp"

#include <aerial/finite.hpp>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace aerial::editor {
namespace {

constexpr double kMaxCoordinate = 1.0e7;  // [m] the pivot stays within this box
constexpr double kMaxDt = 0.25;           // [s] a stalled frame does not teleport the fly camera
constexpr double kMaxWheel = 100.0;       // notches per frame
constexpr double kMaxMouseDelta = 1.0e5;  // [px] per frame

double finiteOr(double v, double fallback) { return std::isfinite(v) ? v : fallback; }

double wrapAngle(double a) {
    // std::remainder gives [-pi, pi]; map -pi to pi so the range is (-pi, pi].
    double r = std::remainder(a, 2.0 * std::numbers::pi);
    if (r <= -std::numbers::pi) {
        r += 2.0 * std::numbers::pi;
    }
    return r;
}

}  // namespace

glm::dvec3 viewDirection(double yaw, double pitch) {
    const double cp = std::cos(pitch);
    return {cp * std::sin(yaw), std::sin(pitch), -cp * std::cos(yaw)};
}

CameraState sanitisedCameraState(const CameraState& state) {
    const CameraState d{};
    CameraState s;
    s.target = isFinite(state.target)
                   ? glm::clamp(state.target, glm::dvec3(-kMaxCoordinate), glm::dvec3(kMaxCoordinate))
                   : d.target;
    s.distance = std::clamp(finiteOr(state.distance, d.distance), kMinDistance, kMaxDistance);
    s.yaw = wrapAngle(finiteOr(state.yaw, d.yaw));
    s.pitch = std::clamp(finiteOr(state.pitch, d.pitch), -kMaxPitch, kMaxPitch);
    s.flySpeed = std::clamp(finiteOr(state.flySpeed, d.flySpeed), kMinFlySpeed, kMaxFlySpeed);
    s.verticalFovDeg = std::clamp(finiteOr(state.verticalFovDeg, d.verticalFovDeg), kMinFovDeg, kMaxFovDeg);
    return s;
}

CameraState cameraStateLookingAt(const glm::dvec3& eye, const glm::dvec3& target, double verticalFovDeg,
                                 const CameraState& base) {
    CameraState s = base;
    const glm::dvec3 d = target - eye;
    const double distance = glm::length(d);
    s.target = target;
    s.distance = distance;
    if (distance > 0.0 && std::isfinite(distance)) {
        s.yaw = std::atan2(d.x, -d.z);
        s.pitch = std::asin(std::clamp(d.y / distance, -1.0, 1.0));
    }
    s.verticalFovDeg = verticalFovDeg;
    return sanitisedCameraState(s);
}

std::string cameraStateToJson(const CameraState& state) {
    nlohmann::json j;
    j["target_m"] = {state.target.x, state.target.y, state.target.z};
    j["distance_m"] = state.distance;
    j["yaw_rad"] = state.yaw;
    j["pitch_rad"] = state.pitch;
    j["fly_speed_m_per_s"] = state.flySpeed;
    j["vertical_fov_deg"] = state.verticalFovDeg;
    return j.dump();
}

bool cameraStateFromJson(std::string_view json, CameraState& state, std::string* error) {
    const auto fail = [error](const std::string& why) {
        if (error != nullptr) {
            *error = why;
        }
        return false;
    };
    const nlohmann::json j = nlohmann::json::parse(json.begin(), json.end(), nullptr, false);
    if (j.is_discarded()) {
        return fail("camera state: not valid JSON");
    }
    if (!j.is_object()) {
        return fail("camera state: expected a JSON object");
    }
    CameraState s = state;
    const auto number = [&j](const char* key, double& out, std::string& why) {
        const auto it = j.find(key);
        if (it == j.end()) {
            return true;
        }
        if (!it->is_number() || !std::isfinite(it->get<double>())) {
            why = "camera state: ";
            why += key;
            why += " must be a finite number";
            return false;
        }
        out = it->get<double>();
        return true;
    };
    std::string why;
    if (const auto it = j.find("target_m"); it != j.end()) {
        if (!it->is_array() || it->size() != 3) {
            return fail("camera state: target_m must be an array of 3 numbers");
        }
        for (int i = 0; i < 3; ++i) {
            const auto& e = (*it)[static_cast<std::size_t>(i)];
            if (!e.is_number() || !std::isfinite(e.get<double>())) {
                return fail("camera state: target_m must be an array of 3 finite numbers");
            }
            s.target[i] = e.get<double>();
        }
    }
    if (!number("distance_m", s.distance, why) || !number("yaw_rad", s.yaw, why) ||
        !number("pitch_rad", s.pitch, why) || !number("fly_speed_m_per_s", s.flySpeed, why) ||
        !number("vertical_fov_deg", s.verticalFovDeg, why)) {
        return fail(why);
    }
    state = sanitisedCameraState(s);
    return true;
}

void CameraController::setState(const CameraState& state) {
    state_ = sanitisedCameraState(state);
    drag_ = Drag::None;
    mouseLook_ = false;
}

glm::dvec3 CameraController::forward() const { return viewDirection(state_.yaw, state_.pitch); }

glm::dvec3 CameraController::eye() const { return state_.target - state_.distance * forward(); }

ViewUpdate CameraController::update(const ViewInput& input) {
    const CameraState before = state_;

    glm::dvec2 delta = input.mouseDelta;
    if (!std::isfinite(delta.x) || !std::isfinite(delta.y)) {
        delta = glm::dvec2(0.0);
    }
    delta = glm::clamp(delta, glm::dvec2(-kMaxMouseDelta), glm::dvec2(kMaxMouseDelta));
    const double wheel = std::isfinite(input.wheel) ? std::clamp(input.wheel, -kMaxWheel, kMaxWheel) : 0.0;
    const double dt = std::isfinite(input.dt) ? std::clamp(input.dt, 0.0, kMaxDt) : 0.0;
    const double height =
        (std::isfinite(input.viewportSize.y) && input.viewportSize.y >= 1.0) ? input.viewportSize.y : 1.0;

    // Drag start (only when the press happens over the viewport) and end.
    const bool leftPressed = input.leftDown && !prevLeft_;
    const bool rightPressed = input.rightDown && !prevRight_;
    const bool middlePressed = input.middleDown && !prevMiddle_;
    prevLeft_ = input.leftDown;
    prevRight_ = input.rightDown;
    prevMiddle_ = input.middleDown;
    switch (drag_) {
        case Drag::AltLeft:
            if (!input.leftDown) drag_ = Drag::None;
            break;
        case Drag::Right:
        case Drag::AltRight:
            if (!input.rightDown) drag_ = Drag::None;
            break;
        case Drag::Middle:
            if (!input.middleDown) drag_ = Drag::None;
            break;
        case Drag::None:
            break;
    }
    if (drag_ == Drag::None) {
        mouseLook_ = false;
        if (input.hovered) {
            if (rightPressed) {
                drag_ = input.alt ? Drag::AltRight : Drag::Right;
            } else if (middlePressed) {
                drag_ = Drag::Middle;
            } else if (leftPressed && input.alt) {
                drag_ = Drag::AltLeft;
            }
        }
    }

    const double rotateSensitivity =
        std::isfinite(rotateRadiansPerPixel) ? std::clamp(rotateRadiansPerPixel, 0.0, 1.0) : 0.005;
    const auto turn = [&] {
        state_.yaw = wrapAngle(state_.yaw + delta.x * rotateSensitivity);
        state_.pitch = std::clamp(state_.pitch - delta.y * rotateSensitivity, -kMaxPitch, kMaxPitch);
    };

    switch (drag_) {
        case Drag::AltLeft:
            turn();  // orbit: the pivot stays, the eye moves on the sphere around it
            break;
        case Drag::Right: {
            const bool anyFlyKey =
                input.keyW || input.keyA || input.keyS || input.keyD || input.keyQ || input.keyE;
            if (anyFlyKey) {
                mouseLook_ = true;
            }
            if (mouseLook_) {
                // Mouse-look: the eye stays, the pivot swings around it.
                const glm::dvec3 eyeBefore = eye();
                turn();
                state_.target = eyeBefore + state_.distance * forward();
            } else {
                turn();
            }
            const glm::dvec3 f = forward();
            const glm::dvec3 right = glm::dvec3(std::cos(state_.yaw), 0.0, std::sin(state_.yaw));
            glm::dvec3 move = f * (double(input.keyW) - double(input.keyS)) +
                              right * (double(input.keyD) - double(input.keyA)) +
                              glm::dvec3(0.0, 1.0, 0.0) * (double(input.keyE) - double(input.keyQ));
            const double len = glm::length(move);
            if (len > 1e-12) {
                const double speed = state_.flySpeed * (input.shift ? 4.0 : 1.0);
                state_.target += move / len * (speed * dt);
            }
            break;
        }
        case Drag::Middle: {
            // The pivot follows the mouse: metres per pixel at the pivot's depth.
            const double tanHalf = std::tan(0.5 * state_.verticalFovDeg * std::numbers::pi / 180.0);
            const double metresPerPixel = 2.0 * state_.distance * tanHalf / height;
            const glm::dvec3 f = forward();
            const glm::dvec3 right = glm::dvec3(std::cos(state_.yaw), 0.0, std::sin(state_.yaw));
            const glm::dvec3 up = glm::cross(right, f);
            state_.target += (-delta.x * right + delta.y * up) * metresPerPixel;
            break;
        }
        case Drag::AltRight:
            // Dolly by dragging: right or down moves in.
            state_.distance = std::clamp(state_.distance * std::exp(-0.005 * (delta.x + delta.y)),
                                         kMinDistance, kMaxDistance);
            break;
        case Drag::None:
            break;
    }

    if (wheel != 0.0 && input.hovered) {
        if (drag_ == Drag::Right) {
            state_.flySpeed =
                std::clamp(state_.flySpeed * std::pow(kFlySpeedPerNotch, wheel), kMinFlySpeed, kMaxFlySpeed);
        } else {
            const double perNotch = (std::isfinite(zoomPerNotch) && zoomPerNotch > 0.0 && zoomPerNotch < 1.0)
                                        ? zoomPerNotch
                                        : 0.85;
            state_.distance =
                std::clamp(state_.distance * std::pow(perNotch, wheel), kMinDistance, kMaxDistance);
        }
    }

    state_ = sanitisedCameraState(state_);
    ViewUpdate u;
    u.cameraChanged = state_.target != before.target || state_.distance != before.distance ||
                      state_.yaw != before.yaw || state_.pitch != before.pitch ||
                      state_.flySpeed != before.flySpeed || state_.verticalFovDeg != before.verticalFovDeg;
    u.capturesMouse = drag_ != Drag::None;
    u.flying = drag_ == Drag::Right;
    return u;
}

void CameraController::frame(const glm::dvec3& centre, double radius, double aspect, double margin) {
    if (!isFinite(centre) || !std::isfinite(radius)) {
        return;
    }
    const double a = (std::isfinite(aspect) && aspect > 0.0) ? std::clamp(aspect, 1e-3, 1e3) : 1.0;
    const double m = (std::isfinite(margin) && margin >= 1.0) ? std::min(margin, 100.0) : 1.0;
    const double r = std::max(radius, 0.1);
    const double halfV = 0.5 * state_.verticalFovDeg * std::numbers::pi / 180.0;
    const double halfH = std::atan(std::tan(halfV) * a);
    const double half = std::min(halfV, halfH);
    // A sphere at distance D subtends asin(r / D); asin(r / D) = asin(sin(half) / m) <= half.
    state_.target = centre;
    state_.distance = r * m / std::sin(half);
    state_ = sanitisedCameraState(state_);
}

renderer::Camera CameraController::camera(double aspect) const {
    renderer::Camera c;
    c.eye = eye();
    c.target = state_.target;
    c.up = glm::dvec3(0.0, 1.0, 0.0);
    c.verticalFov = state_.verticalFovDeg * std::numbers::pi / 180.0;
    const double nearD = (std::isfinite(nearDistance) && nearDistance > 0.0) ? nearDistance : 0.1;
    const double farD = (std::isfinite(farDistance) && farDistance > nearD) ? farDistance : 5000.0;
    c.nearDistance = std::max(nearD, state_.distance * 1e-4);
    c.farDistance = std::max(farD, 4.0 * state_.distance);
    c.aspect = (std::isfinite(aspect) && aspect > 0.0) ? std::clamp(aspect, 1e-3, 1e3) : 16.0 / 9.0;
    return c;
}

renderer::CameraFrame CameraController::cameraFrame(double aspect) const {
    return renderer::cameraFrame(camera(aspect));
}

}  // namespace aerial::editor
