// Camera controller: orbit keeps the distance to the pivot, pan moves eye and
// pivot together (the pivot follows the mouse), zoom never crosses the pivot,
// fly mode, frame() fits a sphere, JSON round trip, no NaN for any input.
#include "viewport/camera_controller.hpp"

#include "viewport/overlay.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <random>

namespace aerial::editor {
namespace {

constexpr glm::dvec2 kSize{1280.0, 720.0};

ViewInput hoveredInput() {
    ViewInput in;
    in.hovered = true;
    in.viewportSize = kSize;
    in.dt = 1.0 / 60.0;
    return in;
}

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

TEST(CameraController, DefaultLooksNorthDownTheValley) {
    const CameraController c;
    const glm::dvec3 eye = c.eye();
    EXPECT_NEAR(eye.x, 0.0, 1e-9);
    EXPECT_GT(eye.y, 15.0);
    EXPECT_LT(eye.y, 40.0);
    EXPECT_GT(eye.z, 80.0);
    EXPECT_LT(eye.z, 160.0);
    EXPECT_LT(c.forward().z, -0.9);  // north is -Z
    EXPECT_LT(c.forward().y, 0.0);   // slightly down
    const renderer::Camera cam = c.camera(16.0 / 9.0);
    EXPECT_NEAR(glm::length(cam.eye - eye), 0.0, 1e-12);
    EXPECT_NEAR(cam.verticalFov, 60.0 * std::numbers::pi / 180.0, 1e-15);
}

TEST(CameraController, OrbitKeepsTheDistanceToThePivot) {
    for (bool altLeft : {true, false}) {
        CameraController c;
        const CameraState s0 = c.state();
        ViewInput in = hoveredInput();
        in.alt = altLeft;
        (altLeft ? in.leftDown : in.rightDown) = true;
        c.update(in);  // press
        in.mouseDelta = {40.0, -25.0};
        const ViewUpdate u = c.update(in);
        EXPECT_TRUE(u.cameraChanged);
        EXPECT_TRUE(u.capturesMouse);
        EXPECT_EQ(c.state().target, s0.target);
        EXPECT_NEAR(glm::length(c.eye() - c.state().target), s0.distance, 1e-9);
        EXPECT_NEAR(c.state().yaw, s0.yaw + 40.0 * c.rotateRadiansPerPixel, 1e-12);
        EXPECT_NEAR(c.state().pitch, s0.pitch + 25.0 * c.rotateRadiansPerPixel, 1e-12);
        // The view still looks at the pivot.
        EXPECT_NEAR(glm::length(glm::normalize(c.state().target - c.eye()) - c.forward()), 0.0, 1e-12);
        // Pitch stops short of the pole.
        in.mouseDelta = {0.0, -1e5};
        c.update(in);
        EXPECT_NEAR(c.state().pitch, kMaxPitch, 1e-15);
        EXPECT_NEAR(glm::length(c.eye() - c.state().target), s0.distance, 1e-9);
        // Release ends the drag.
        in.leftDown = in.rightDown = false;
        in.mouseDelta = {10.0, 0.0};
        const double yaw = c.state().yaw;
        EXPECT_FALSE(c.update(in).capturesMouse);
        EXPECT_EQ(c.state().yaw, yaw);
    }
}

TEST(CameraController, DragsStartOnlyOverTheViewportButContinueOutside) {
    CameraController c;
    ViewInput in = hoveredInput();
    in.hovered = false;
    in.rightDown = true;
    c.update(in);
    in.mouseDelta = {50.0, 0.0};
    EXPECT_FALSE(c.update(in).cameraChanged);  // pressed elsewhere: not ours
    in.rightDown = false;
    c.update(in);
    in.hovered = true;
    in.rightDown = true;
    in.mouseDelta = {0.0, 0.0};
    c.update(in);
    in.hovered = false;  // dragged off the viewport
    in.mouseDelta = {50.0, 0.0};
    EXPECT_TRUE(c.update(in).cameraChanged);
    // Left without Alt does not navigate (it is for picking and the gizmo).
    CameraController d;
    ViewInput l = hoveredInput();
    l.leftDown = true;
    d.update(l);
    l.mouseDelta = {30.0, 30.0};
    const ViewUpdate u = d.update(l);
    EXPECT_FALSE(u.cameraChanged);
    EXPECT_FALSE(u.capturesMouse);
}

TEST(CameraController, PanMovesEyeAndPivotTogetherAndThePivotFollowsTheMouse) {
    CameraController c;
    CameraState s = c.state();
    s.yaw = 0.7;
    s.pitch = -0.4;
    s.target = {12.0, 3.0, -40.0};
    c.setState(s);
    const glm::dvec3 eye0 = c.eye();
    const glm::dvec3 target0 = c.state().target;
    const renderer::CameraFrame f0 = c.cameraFrame(kSize.x / kSize.y);
    ViewInput in = hoveredInput();
    in.middleDown = true;
    c.update(in);
    in.mouseDelta = {37.0, -12.0};
    c.update(in);
    const glm::dvec3 moveEye = c.eye() - eye0;
    const glm::dvec3 moveTarget = c.state().target - target0;
    EXPECT_NEAR(glm::length(moveEye - moveTarget), 0.0, 1e-9);
    EXPECT_NEAR(glm::dot(moveTarget, f0.forward), 0.0, 1e-9);  // in the view plane
    const double metresPerPixel = 2.0 * s.distance * std::tan(std::numbers::pi / 6.0) / kSize.y;
    EXPECT_NEAR(glm::length(moveTarget), std::hypot(37.0, 12.0) * metresPerPixel, 1e-9);
    // The old pivot was at the viewport centre; it is now where the mouse went.
    const auto p = projectToViewport(c.cameraFrame(kSize.x / kSize.y), kSize, target0);
    ASSERT_TRUE(p.has_value());
    EXPECT_NEAR(p->x, 640.0 + 37.0, 1e-6);
    EXPECT_NEAR(p->y, 360.0 - 12.0, 1e-6);
    (void)f0;
}

TEST(CameraController, ZoomMovesTowardsThePivotAndNeverCrossesIt) {
    CameraController c;
    const CameraState s0 = c.state();
    ViewInput in = hoveredInput();
    in.wheel = 1.0;
    c.update(in);
    EXPECT_NEAR(c.state().distance, s0.distance * 0.85, 1e-12);
    EXPECT_EQ(c.state().target, s0.target);
    EXPECT_NEAR(glm::length(c.forward() - viewDirection(s0.yaw, s0.pitch)), 0.0, 1e-15);
    in.wheel = -2.0;
    c.update(in);
    EXPECT_NEAR(c.state().distance, s0.distance * 0.85 / (0.85 * 0.85), 1e-9);
    for (int i = 0; i < 200; ++i) {
        in.wheel = 50.0;
        c.update(in);
        EXPECT_GE(c.state().distance, kMinDistance);
        EXPECT_GT(glm::dot(c.state().target - c.eye(), c.forward()), 0.0);  // still in front
    }
    EXPECT_EQ(c.state().distance, kMinDistance);
    in.wheel = -1e9;
    c.update(in);
    EXPECT_EQ(c.state().distance, kMaxDistance);
    // Not hovered: the wheel belongs to another window.
    in.hovered = false;
    in.wheel = 3.0;
    EXPECT_FALSE(c.update(in).cameraChanged);
}

TEST(CameraController, AltRightDragDolliesTowardsThePivot) {
    CameraController c;
    const CameraState s0 = c.state();
    ViewInput in = hoveredInput();
    in.alt = true;
    in.rightDown = true;
    EXPECT_FALSE(c.update(in).flying);  // Alt + right is a dolly, not fly mode
    in.mouseDelta = {30.0, 10.0};
    c.update(in);
    EXPECT_NEAR(c.state().distance, s0.distance * std::exp(-0.005 * 40.0), 1e-9);
    EXPECT_EQ(c.state().target, s0.target);
    EXPECT_EQ(c.state().yaw, s0.yaw);
}

TEST(CameraController, FlyModeMovesWithWasdAndTheWheelSetsItsSpeed) {
    CameraController c;
    const glm::dvec3 eye0 = c.eye();
    const glm::dvec3 f = c.forward();
    ViewInput in = hoveredInput();
    in.rightDown = true;
    EXPECT_TRUE(c.update(in).flying);
    EXPECT_TRUE(c.flying());
    in.keyW = true;
    in.dt = 0.1;
    c.update(in);
    EXPECT_NEAR(glm::length(c.eye() - (eye0 + f * (c.state().flySpeed * 0.1))), 0.0, 1e-9);
    // D moves right (east at yaw 0), E straight up, Shift 4x.
    const glm::dvec3 eye1 = c.eye();
    in.keyW = false;
    in.keyD = true;
    c.update(in);
    EXPECT_NEAR(glm::length(c.eye() - (eye1 + glm::dvec3(1, 0, 0) * (c.state().flySpeed * 0.1))), 0.0, 1e-9);
    const glm::dvec3 eye2 = c.eye();
    in.keyD = false;
    in.keyE = true;
    in.shift = true;
    c.update(in);
    EXPECT_NEAR(glm::length(c.eye() - (eye2 + glm::dvec3(0, 4.0 * c.state().flySpeed * 0.1, 0))), 0.0, 1e-9);
    in.keyE = false;
    in.shift = false;
    // After a fly key the mouse looks around the eye.
    const glm::dvec3 eye3 = c.eye();
    in.mouseDelta = {80.0, 20.0};
    c.update(in);
    EXPECT_NEAR(glm::length(c.eye() - eye3), 0.0, 1e-9);
    in.mouseDelta = {0.0, 0.0};
    // Wheel: speed x1.2 per notch, distance untouched; clamped.
    const double speed = c.state().flySpeed;
    const double distance = c.state().distance;
    in.wheel = 2.0;
    c.update(in);
    EXPECT_NEAR(c.state().flySpeed, speed * 1.44, 1e-12);
    EXPECT_EQ(c.state().distance, distance);
    in.wheel = 1000.0;
    c.update(in);
    EXPECT_EQ(c.state().flySpeed, kMaxFlySpeed);
    in.wheel = -1000.0;
    c.update(in);
    EXPECT_EQ(c.state().flySpeed, kMinFlySpeed);
    // A stalled frame (dt 10 s) moves at most 0.25 s worth.
    in.wheel = 0.0;
    in.keyS = true;
    const glm::dvec3 eye4 = c.eye();
    in.dt = 10.0;
    c.update(in);
    EXPECT_NEAR(glm::length(c.eye() - eye4), kMinFlySpeed * 0.25, 1e-9);
    // Releasing the right button ends flying.
    in.rightDown = false;
    EXPECT_FALSE(c.update(in).flying);
    EXPECT_FALSE(c.flying());
}

// The sphere's silhouette stays inside the viewport and fills it to within the margin.
void expectFits(double aspect, glm::dvec3 centre, double radius) {
    CameraController c;
    CameraState s = c.state();
    s.yaw = 2.1;
    s.pitch = -0.5;
    c.setState(s);
    const double margin = 1.15;
    c.frame(centre, radius, aspect, margin);
    const glm::dvec2 size{720.0 * aspect, 720.0};
    const renderer::CameraFrame f = c.cameraFrame(aspect);
    EXPECT_EQ(c.state().target, centre);
    EXPECT_NEAR(c.state().pitch, -0.5, 1e-15);  // direction kept
    // The silhouette's angular radius asin(r / D) equals asin(sin(halfFov) / margin).
    const double halfV = std::numbers::pi / 6.0;
    const double halfH = std::atan(std::tan(halfV) * aspect);
    const double half = std::min(halfV, halfH);
    EXPECT_NEAR(std::asin(radius / c.state().distance), std::asin(std::sin(half) / margin), 1e-12);
    // Tangent points of the silhouette, projected: inside the viewport, and the
    // narrower extent at least 1 / margin^2 of the half viewport.
    double maxX = 0.0;
    double maxY = 0.0;
    const glm::dvec3 toCentre = centre - f.eye;
    const double dist = glm::length(toCentre);
    const double sinA = radius / dist;
    const double cosA = std::sqrt(1.0 - sinA * sinA);
    for (int i = 0; i < 360; ++i) {
        const double phi = i * std::numbers::pi / 180.0;
        const glm::dvec3 side = std::cos(phi) * f.right + std::sin(phi) * f.up;
        // A tangent point: at distance dist cosA from the eye, angle asin(r/dist) off the axis.
        const glm::dvec3 dir = cosA * f.forward + sinA * side;
        const glm::dvec3 p = f.eye + dir * (dist * cosA);
        EXPECT_NEAR(glm::length(p - centre), radius, 1e-9 * dist);
        const auto q = projectToViewport(f, size, p);
        ASSERT_TRUE(q.has_value());
        EXPECT_GE(q->x, 0.0);
        EXPECT_LE(q->x, size.x);
        EXPECT_GE(q->y, 0.0);
        EXPECT_LE(q->y, size.y);
        maxX = std::max(maxX, std::fabs(q->x - 0.5 * size.x) / (0.5 * size.x));
        maxY = std::max(maxY, std::fabs(q->y - 0.5 * size.y) / (0.5 * size.y));
    }
    EXPECT_GT(std::max(maxX, maxY), 1.0 / (margin * margin));
    EXPECT_LT(std::max(maxX, maxY), 1.0);
}

TEST(CameraController, FrameFitsTheSphereInBothFieldsOfView) {
    expectFits(16.0 / 9.0, {10.0, 5.0, -30.0}, 12.0);  // vertical fov is the narrower
    expectFits(9.0 / 16.0, {-100.0, 2.0, 7.0}, 3.0);   // horizontal fov is the narrower
    expectFits(1.0, {0.0, 0.0, 0.0}, 400.0);
    CameraController c;
    const CameraState s = c.state();
    c.frame({std::nan(""), 0.0, 0.0}, 3.0);
    EXPECT_EQ(c.state().target, s.target);
    c.frame({1.0, 2.0, 3.0}, 0.0);  // a point: radius clamped to 0.1 m
    EXPECT_GT(c.state().distance, 0.1);
}

TEST(CameraState, LookingAtAPresetViewPutsTheEyeAndTargetWhereItSays) {
    CameraState base;
    base.flySpeed = 37.0;
    const glm::dvec3 eye(-60.0, 62.5, 70.0), target(5.0, 18.0, -90.0);
    CameraController c(cameraStateLookingAt(eye, target, 45.0, base));
    EXPECT_LT(glm::length(c.eye() - eye), 1e-9);
    EXPECT_EQ(c.state().target, target);
    EXPECT_NEAR(c.state().distance, glm::length(target - eye), 1e-12);
    EXPECT_EQ(c.state().verticalFovDeg, 45.0);
    EXPECT_EQ(c.state().flySpeed, 37.0);  // the base's
    const renderer::Camera cam = c.camera(16.0 / 9.0);
    EXPECT_LT(glm::length(glm::normalize(cam.target - cam.eye) - glm::normalize(target - eye)), 1e-12);
    // Straight down tilts to the pitch limit about the target; the fov clamps to the editor's range.
    const CameraState down = cameraStateLookingAt({0.0, 100.0, 0.0}, {0.0, 0.0, 0.0}, 170.0);
    EXPECT_EQ(down.pitch, -kMaxPitch);
    EXPECT_EQ(down.verticalFovDeg, kMaxFovDeg);
    EXPECT_EQ(down.target, glm::dvec3(0.0));
}

TEST(CameraState, JsonRoundTripIsBitExact) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < 200; ++i) {
        CameraState s;
        s.target = {1e4 * u(rng), 1e3 * u(rng), 1e4 * u(rng)};
        s.distance = 1.0 + 500.0 * (u(rng) + 1.0);
        s.yaw = 3.0 * u(rng);
        s.pitch = 1.5 * u(rng);
        s.flySpeed = 1.0 + 100.0 * (u(rng) + 1.0);
        s.verticalFovDeg = 40.0 + 30.0 * u(rng);
        s = sanitisedCameraState(s);
        const std::string json = cameraStateToJson(s);
        CameraState back;
        std::string error;
        ASSERT_TRUE(cameraStateFromJson(json, back, &error)) << error;
        EXPECT_EQ(std::memcmp(&back.target, &s.target, sizeof(s.target)), 0);
        EXPECT_EQ(back.distance, s.distance);
        EXPECT_EQ(back.yaw, s.yaw);
        EXPECT_EQ(back.pitch, s.pitch);
        EXPECT_EQ(back.flySpeed, s.flySpeed);
        EXPECT_EQ(back.verticalFovDeg, s.verticalFovDeg);
    }
    // Keys carry their units.
    const std::string json = cameraStateToJson(CameraState{});
    for (const char* key :
         {"target_m", "distance_m", "yaw_rad", "pitch_rad", "fly_speed_m_per_s", "vertical_fov_deg"}) {
        EXPECT_NE(json.find(key), std::string::npos) << key;
    }
}

TEST(CameraState, BadJsonChangesNothingAndSaysWhy) {
    CameraState s;
    s.distance = 33.0;
    const CameraState before = s;
    std::string error;
    for (const char* bad :
         {"", "{", "[1,2]", "{\"distance_m\": \"far\"}", "{\"target_m\": [1, 2]}",
          "{\"target_m\": [1, 2, \"x\"]}", "{\"yaw_rad\": null}", "{\"pitch_rad\": 1e999}"}) {
        error.clear();
        EXPECT_FALSE(cameraStateFromJson(bad, s, &error)) << bad;
        EXPECT_FALSE(error.empty()) << bad;
        EXPECT_EQ(s.distance, before.distance);
        EXPECT_EQ(s.target, before.target);
    }
    // Missing keys keep their values; out-of-range values are clamped.
    ASSERT_TRUE(cameraStateFromJson("{\"pitch_rad\": 3.0, \"extra\": 1}", s, &error)) << error;
    EXPECT_EQ(s.distance, 33.0);
    EXPECT_EQ(s.pitch, kMaxPitch);
}

TEST(CameraController, NoNanForAnyInput) {
    std::mt19937_64 rng(77);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::uniform_int_distribution<int> coin(0, 1);
    std::uniform_int_distribution<int> pickSpecial(0, 9);
    const double specials[] = {std::nan(""),
                               std::numeric_limits<double>::infinity(),
                               -std::numeric_limits<double>::infinity(),
                               1e308,
                               -1e308,
                               0.0,
                               1e-320,
                               -5.0};
    const auto value = [&](double scale) {
        const int k = pickSpecial(rng);
        return k < 8 && coin(rng) && coin(rng) ? specials[k] : scale * u(rng);
    };
    CameraController c;
    for (int i = 0; i < 100000; ++i) {
        ViewInput in;
        in.mouseDelta = {value(500.0), value(500.0)};
        in.wheel = value(10.0);
        in.leftDown = coin(rng);
        in.rightDown = coin(rng);
        in.middleDown = coin(rng);
        in.alt = coin(rng);
        in.shift = coin(rng);
        in.keyW = coin(rng);
        in.keyA = coin(rng);
        in.keyS = coin(rng);
        in.keyD = coin(rng);
        in.keyQ = coin(rng);
        in.keyE = coin(rng);
        in.dt = value(0.1);
        in.viewportSize = {value(2000.0), value(2000.0)};
        in.hovered = coin(rng);
        c.update(in);
        if (i % 997 == 0) {
            c.frame({value(1e4), value(1e4), value(1e4)}, value(1e3), value(3.0), value(2.0));
        }
        const CameraState& s = c.state();
        ASSERT_TRUE(finite(s.target)) << i;
        ASSERT_TRUE(s.distance >= kMinDistance && s.distance <= kMaxDistance) << i;
        ASSERT_TRUE(s.pitch >= -kMaxPitch && s.pitch <= kMaxPitch) << i;
        ASSERT_TRUE(std::isfinite(s.yaw)) << i;
        ASSERT_TRUE(s.flySpeed >= kMinFlySpeed && s.flySpeed <= kMaxFlySpeed) << i;
        const renderer::CameraFrame f = c.cameraFrame(value(2.0));
        ASSERT_TRUE(finite(f.eye) && finite(f.forward) && finite(f.right) && finite(f.up)) << i;
        for (int col = 0; col < 4; ++col) {
            for (int row = 0; row < 4; ++row) {
                ASSERT_TRUE(std::isfinite(f.clipFromWorld[col][row])) << i;
            }
        }
    }
}

}  // namespace
}  // namespace aerial::editor
