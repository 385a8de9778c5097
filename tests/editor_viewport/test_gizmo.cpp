// Gizmo drags simulated with the mouse: press on the projection of a handle,
// move by a known amount, release; translation, rotation and scale against
// closed forms, snapping, local vs world axes, the drag's event flags, no NaN.
#include "viewport/gizmo.hpp"

#include "viewport/overlay.hpp"
#include "viewport/picking.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/mat2x2.hpp>

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <random>

namespace aerial::editor {
namespace {

constexpr glm::dvec2 kSize{1280.0, 720.0};
constexpr double kPi = std::numbers::pi;

renderer::CameraFrame makeFrame(glm::dvec3 eye, glm::dvec3 target, glm::dvec3 up = {0, 1, 0}) {
    renderer::Camera c;
    c.eye = eye;
    c.target = target;
    c.up = up;
    c.aspect = kSize.x / kSize.y;
    return renderer::cameraFrame(c);
}

glm::dvec2 project(const renderer::CameraFrame& f, glm::dvec3 p) {
    const auto q = projectToViewport(f, kSize, p);
    EXPECT_TRUE(q.has_value());
    return q.value_or(glm::dvec2(0.0));
}

struct Drag {
    GizmoResult press;
    GizmoResult move;
    GizmoResult release;
};

// Press at `from`, move to `to` (one frame), release there.
Drag drag(Gizmo& g, const renderer::CameraFrame& f, glm::dvec2 from, glm::dvec2 to, GizmoMode mode,
          GizmoSpace space, GizmoTransform& t, const GizmoSnap& snap = {}) {
    Drag d;
    GizmoInput in;
    in.mouse = from;
    g.update(f, kSize, in, mode, space, snap, t);  // hover
    in.pressed = true;
    in.down = true;
    d.press = g.update(f, kSize, in, mode, space, snap, t);
    in.pressed = false;
    in.mouse = to;
    d.move = g.update(f, kSize, in, mode, space, snap, t);
    in.down = false;
    in.released = true;
    d.release = g.update(f, kSize, in, mode, space, snap, t);
    return d;
}

// Signed rotation angle of q about the unit axis (q assumed a rotation about it).
double angleAbout(const glm::dquat& q, const glm::dvec3& axis) {
    const glm::dvec3 v(q.x, q.y, q.z);
    return 2.0 * std::atan2(glm::dot(v, axis), q.w);
}

// Independent reference for the axis drag: minimise |c + s a - (o + t d)|^2
// by solving the 2x2 normal equations with a matrix inverse.
double closestAxisParameter(const Ray& r, glm::dvec3 c, glm::dvec3 a) {
    const glm::dmat2 m(glm::dot(a, a), -glm::dot(a, r.direction), -glm::dot(a, r.direction),
                       glm::dot(r.direction, r.direction));
    const glm::dvec3 w = r.origin - c;
    const glm::dvec2 rhs(glm::dot(a, w), -glm::dot(r.direction, w));
    return (glm::inverse(m) * rhs).x;
}

TEST(Gizmo, TranslateAlongAnAxisFollowsTheMouseExactly) {
    const renderer::CameraFrame f = makeFrame({6, 5, 14}, {1, 0.5, -2});
    Gizmo g;
    GizmoTransform t;
    t.position = {1.0, 0.5, -2.0};
    const double L = g.worldSizeAt(f, kSize.y, t.position);
    for (int axis = 0; axis < 3; ++axis) {
        GizmoTransform moved = t;
        glm::dvec3 a(0.0);
        a[axis] = 1.0;
        const glm::dvec2 from = project(f, t.position + a * (0.6 * L));
        ASSERT_EQ(g.hitTest(f, kSize, from, GizmoMode::Translate, GizmoSpace::World, t),
                  static_cast<GizmoHandle>(axis));
        // Onto the projection of a point 2.5 m further along the axis.
        const glm::dvec2 to = project(f, t.position + a * (0.6 * L + 2.5));
        const Drag d = drag(g, f, from, to, GizmoMode::Translate, GizmoSpace::World, moved);
        EXPECT_TRUE(d.press.started);
        EXPECT_EQ(d.press.axis, axis);
        EXPECT_NEAR(glm::length(moved.position - (t.position + 2.5 * a)), 0.0, 1e-6) << axis;
        EXPECT_EQ(moved.rotation, t.rotation);
        EXPECT_EQ(moved.scale, t.scale);
        // Off the axis on screen: the closest point between ray and axis.
        moved = t;
        const glm::dvec2 off = from + glm::dvec2(31.0, -17.0);
        drag(g, f, from, off, GizmoMode::Translate, GizmoSpace::World, moved);
        const double expected = closestAxisParameter(rayThroughPixel(f, off, kSize), t.position, a) -
                                closestAxisParameter(rayThroughPixel(f, from, kSize), t.position, a);
        EXPECT_NEAR(glm::length(moved.position - (t.position + expected * a)), 0.0, 1e-6) << axis;
        EXPECT_GT(std::fabs(expected), 0.1);
    }
}

TEST(Gizmo, DraggingBeyondTheHorizonKeepsTheLastValidPosition) {
    // Looking nearly horizontally along +Z: the Z handle recedes towards the horizon.
    const renderer::CameraFrame f = makeFrame({0, 2, -10}, {0, 0, 0});
    Gizmo g;
    GizmoTransform t;
    const double L = g.worldSizeAt(f, kSize.y, t.position);
    const glm::dvec2 from = project(f, t.position + glm::dvec3(0, 0, 0.6 * L));
    ASSERT_EQ(g.hitTest(f, kSize, from, GizmoMode::Translate, GizmoSpace::World, t), GizmoHandle::Z);
    // The Z axis vanishes at the horizon (the viewport row of the eye's height).
    const glm::dvec2 horizon = project(f, {0, 2, 1e9});
    GizmoInput in;
    in.mouse = from;
    in.pressed = in.down = true;
    ASSERT_TRUE(g.update(f, kSize, in, GizmoMode::Translate, GizmoSpace::World, {}, t).started);
    in.pressed = false;
    // Towards the horizon: far, but finite and in front.
    in.mouse = {from.x, horizon.y + 0.5};
    g.update(f, kSize, in, GizmoMode::Translate, GizmoSpace::World, {}, t);
    EXPECT_GT(t.position.z, 100.0);
    EXPECT_LE(t.position.z, 1e7);
    EXPECT_EQ(t.position.x, 0.0);
    const GizmoTransform last = t;
    // Above the horizon the axis's closest point is behind the eye: nothing changes.
    in.mouse = {from.x, horizon.y - 40.0};
    const GizmoResult r = g.update(f, kSize, in, GizmoMode::Translate, GizmoSpace::World, {}, t);
    EXPECT_FALSE(r.changed);
    EXPECT_EQ(t.position, last.position);
    EXPECT_TRUE(r.active);
}

TEST(Gizmo, TranslateInAPlaneAndInTheViewPlane) {
    const renderer::CameraFrame f = makeFrame({8, 12, 15}, {0, 0, 0});
    Gizmo g;
    GizmoTransform t;
    t.position = {0.0, 0.0, 0.0};
    const double L = g.worldSizeAt(f, kSize.y, t.position);
    // The ZX plane handle (normal Y): its square spans 0.25..0.45 L on Z and X.
    const glm::dvec3 handle = t.position + 0.35 * L * glm::dvec3(1, 0, 1);
    const glm::dvec2 from = project(f, handle);
    ASSERT_EQ(g.hitTest(f, kSize, from, GizmoMode::Translate, GizmoSpace::World, t), GizmoHandle::PlaneZX);
    GizmoTransform moved = t;
    const Drag d = drag(g, f, from, project(f, handle + glm::dvec3(1.5, 0.0, -2.25)), GizmoMode::Translate,
                        GizmoSpace::World, moved);
    EXPECT_EQ(d.press.axis, static_cast<int>(GizmoHandle::PlaneZX));
    EXPECT_NEAR(glm::length(moved.position - glm::dvec3(1.5, 0.0, -2.25)), 0.0, 1e-6);
    // Centre: moves in the plane facing the camera.
    moved = t;
    const glm::dvec2 centre = project(f, t.position);
    ASSERT_EQ(g.hitTest(f, kSize, centre, GizmoMode::Translate, GizmoSpace::World, t), GizmoHandle::Centre);
    const glm::dvec3 offset = 2.0 * f.right + 1.0 * f.up;
    drag(g, f, centre, project(f, t.position + offset), GizmoMode::Translate, GizmoSpace::World, moved);
    EXPECT_NEAR(glm::length(moved.position - offset), 0.0, 1e-6);
}

TEST(Gizmo, RotateByTheAngleBetweenPressAndCurrentHits) {
    const renderer::CameraFrame f = makeFrame({5, 9, 11}, {0, 1, 0});
    Gizmo g;
    GizmoTransform t;
    t.position = {0, 1, 0};
    t.rotation = glm::angleAxis(0.3, glm::normalize(glm::dvec3(1, 2, 3)));
    const double L = g.worldSizeAt(f, kSize.y, t.position);
    // Y ring (world): points c + L (cos a, 0, sin a); the front half faces the eye.
    const auto ringY = [&](double a) { return t.position + L * glm::dvec3(std::cos(a), 0.0, -std::sin(a)); };
    // With (cos a, 0, -sin a) the angle a increases anticlockwise about +Y.
    const double a0 = std::atan2(-(f.eye - t.position).z, (f.eye - t.position).x);  // towards the eye
    const glm::dvec2 from = project(f, ringY(a0));
    ASSERT_EQ(g.hitTest(f, kSize, from, GizmoMode::Rotate, GizmoSpace::World, t), GizmoHandle::Y);
    GizmoTransform rotated = t;
    const double swept = 0.41;
    drag(g, f, from, project(f, ringY(a0 + swept)), GizmoMode::Rotate, GizmoSpace::World, rotated);
    const glm::dquat relative = rotated.rotation * glm::inverse(t.rotation);
    EXPECT_NEAR(angleAbout(relative, {0, 1, 0}), swept, 1e-6);
    EXPECT_NEAR(std::fabs(relative.w), std::cos(0.5 * swept), 1e-9);  // about Y only
    EXPECT_EQ(rotated.position, t.position);
    EXPECT_EQ(rotated.scale, t.scale);

    // A long drag accumulates past 180 deg (270 deg in 10 steps, ending behind the ring).
    rotated = t;
    GizmoInput in;
    in.mouse = from;
    g.update(f, kSize, in, GizmoMode::Rotate, GizmoSpace::World, {}, rotated);
    in.pressed = in.down = true;
    g.update(f, kSize, in, GizmoMode::Rotate, GizmoSpace::World, {}, rotated);
    in.pressed = false;
    for (int i = 1; i <= 10; ++i) {
        in.mouse = project(f, ringY(a0 + 0.1 * i * 1.5 * kPi));
        const GizmoResult r = g.update(f, kSize, in, GizmoMode::Rotate, GizmoSpace::World, {}, rotated);
        EXPECT_TRUE(r.active);
        EXPECT_TRUE(r.changed);
    }
    const glm::dquat expected = glm::angleAxis(1.5 * kPi, glm::dvec3(0, 1, 0)) * t.rotation;
    EXPECT_NEAR(std::fabs(glm::dot(rotated.rotation, expected)), 1.0, 1e-12);
    EXPECT_LT(glm::length(
                  glm::dvec4(rotated.rotation.x, rotated.rotation.y, rotated.rotation.z, rotated.rotation.w) -
                  glm::dvec4(expected.x, expected.y, expected.z, expected.w)),
              1e-6);                               // the same sign: 270 deg, not -90 deg's double cover
    EXPECT_EQ(g.dragLabel(), "Y +270.0\xc2\xb0");  // unwrapped, in degrees
    in.down = false;
    in.released = true;
    EXPECT_TRUE(g.update(f, kSize, in, GizmoMode::Rotate, GizmoSpace::World, {}, rotated).finished);
    EXPECT_EQ(g.dragLabel(), "");
}

TEST(Gizmo, RotateInLocalSpaceUsesTheObjectAxes) {
    const renderer::CameraFrame f = makeFrame({-7, 6, 10}, {0, 0, 0});
    Gizmo g;
    GizmoTransform t;
    t.rotation = glm::angleAxis(0.9, glm::normalize(glm::dvec3(0.3, -1, 0.5)));
    glm::dvec3 axes[3];
    Gizmo::axes(GizmoMode::Rotate, GizmoSpace::Local, t.rotation, axes);
    const glm::dvec3 n = axes[0];  // the local X ring
    const double L = g.worldSizeAt(f, kSize.y, t.position);
    // An orthonormal basis (u, v) of the ring with u x v = n.
    const glm::dvec3 toEye = glm::normalize(f.eye - t.position);
    const glm::dvec3 u = glm::normalize(toEye - n * glm::dot(toEye, n));
    const glm::dvec3 v = glm::cross(n, u);
    const auto ring = [&](double a) { return t.position + L * (std::cos(a) * u + std::sin(a) * v); };
    const glm::dvec2 from = project(f, ring(0.0));
    ASSERT_EQ(g.hitTest(f, kSize, from, GizmoMode::Rotate, GizmoSpace::Local, t), GizmoHandle::X);
    GizmoTransform rotated = t;
    drag(g, f, from, project(f, ring(-0.7)), GizmoMode::Rotate, GizmoSpace::Local, rotated);
    // Rotating about the local X axis: rotation = start * angleAxis(angle, X).
    const glm::dquat expected = t.rotation * glm::angleAxis(-0.7, glm::dvec3(1, 0, 0));
    EXPECT_NEAR(std::fabs(glm::dot(rotated.rotation, expected)), 1.0, 1e-12);
    EXPECT_NEAR(angleAbout(rotated.rotation * glm::inverse(t.rotation), n), -0.7, 1e-6);
}

TEST(Gizmo, ViewRingRotatesAboutTheDirectionToTheEye) {
    const renderer::CameraFrame f = makeFrame({3, 8, 10}, {0, 1, 0});
    Gizmo g;
    GizmoTransform t;
    t.position = {0.5, 1.0, -0.5};
    const double L = g.worldSizeAt(f, kSize.y, t.position);
    const glm::dvec3 n = glm::normalize(f.eye - t.position);
    const glm::dvec3 u = glm::normalize(glm::cross(n, glm::dvec3(0, 1, 0)));
    const glm::dvec3 v = glm::cross(n, u);
    const auto ring = [&](double a) { return t.position + 1.2 * L * (std::cos(a) * u + std::sin(a) * v); };
    const glm::dvec2 from = project(f, ring(0.3));
    ASSERT_EQ(g.hitTest(f, kSize, from, GizmoMode::Rotate, GizmoSpace::World, t), GizmoHandle::View);
    GizmoTransform rotated = t;
    drag(g, f, from, project(f, ring(0.3 + 1.1)), GizmoMode::Rotate, GizmoSpace::Local, rotated);
    const glm::dquat expected = glm::angleAxis(1.1, n) * t.rotation;
    EXPECT_NEAR(std::fabs(glm::dot(rotated.rotation, expected)), 1.0, 1e-12);
    EXPECT_NEAR(angleAbout(rotated.rotation, n), 1.1, 1e-6);
}

TEST(Gizmo, AnEdgeOnRingTurnsByTheMouseTravelAlongItsTangent) {
    // From 1 m up at 20 m the Y ring is 3 deg from edge-on (|cos| 0.05 < kEdgeOnRingCos).
    const renderer::CameraFrame f = makeFrame({0, 1, 20}, {0, 0, 0});
    Gizmo g;
    GizmoTransform t;
    const double L = g.worldSizeAt(f, kSize.y, t.position);
    const glm::dvec2 from = project(f, {0, 0, L});  // the ring's point nearest the eye
    ASSERT_EQ(g.hitTest(f, kSize, from, GizmoMode::Rotate, GizmoSpace::World, t), GizmoHandle::Y);
    // The tangent of increasing angle there is Y x Z = +X: to the right on screen.
    for (double travel : {50.0, -130.0}) {
        GizmoTransform r = t;
        drag(g, f, from, from + glm::dvec2(travel, 7.0), GizmoMode::Rotate, GizmoSpace::World, r);
        EXPECT_NEAR(angleAbout(r.rotation, {0, 1, 0}), travel / g.sizePx, 1e-9) << travel;
        EXPECT_NEAR(std::fabs(r.rotation.w), std::cos(0.5 * travel / g.sizePx), 1e-12);
    }
    // Snapped: 0.3 rad (17.2 deg) -> 15 deg.
    GizmoSnap snap;
    snap.enabled = true;
    GizmoTransform r = t;
    drag(g, f, from, from + glm::dvec2(30.0, 0.0), GizmoMode::Rotate, GizmoSpace::World, r, snap);
    EXPECT_NEAR(angleAbout(r.rotation, {0, 1, 0}), kPi / 12.0, 1e-12);
}

TEST(Gizmo, OnlyTheFrontHalfOfAnAxisRingIsPickable) {
    // No ring edge-on from here (an edge-on ring projects to a line through the centre).
    const renderer::CameraFrame f = makeFrame({5, 6, 12}, {0, 0, 0});
    Gizmo g;
    GizmoTransform t;
    const double L = g.worldSizeAt(f, kSize.y, t.position);
    // The Y ring (horizontal): its point nearest the eye is pickable, the farthest is not.
    const glm::dvec3 towardsEye = glm::dvec3(5, 0, 12) / 13.0;
    EXPECT_EQ(g.hitTest(f, kSize, project(f, L * towardsEye), GizmoMode::Rotate, GizmoSpace::World, t),
              GizmoHandle::Y);
    EXPECT_NE(g.hitTest(f, kSize, project(f, -L * towardsEye), GizmoMode::Rotate, GizmoSpace::World, t),
              GizmoHandle::Y);
    // The centre of a rotate gizmo is not a handle; away from everything is nothing.
    EXPECT_EQ(g.hitTest(f, kSize, project(f, t.position), GizmoMode::Rotate, GizmoSpace::World, t),
              GizmoHandle::None);
    EXPECT_EQ(g.hitTest(f, kSize, {3.0, 3.0}, GizmoMode::Rotate, GizmoSpace::World, t), GizmoHandle::None);
}

TEST(Gizmo, ScaleAlongALocalAxisByTheRatioOfDistances) {
    const renderer::CameraFrame f = makeFrame({4, 3, 12}, {0, 0, 0});
    Gizmo g;
    GizmoTransform t;
    t.rotation = glm::angleAxis(kPi / 6.0, glm::dvec3(0, 0, 1));
    t.scale = {2.0, 3.0, 4.0};
    glm::dvec3 axes[3];
    Gizmo::axes(GizmoMode::Scale, GizmoSpace::World, t.rotation, axes);  // scale is always local
    EXPECT_NEAR(glm::length(axes[0] - t.rotation * glm::dvec3(1, 0, 0)), 0.0, 1e-15);
    const double L = g.worldSizeAt(f, kSize.y, t.position);
    const glm::dvec2 from = project(f, t.position + axes[0] * (0.8 * L));
    ASSERT_EQ(g.hitTest(f, kSize, from, GizmoMode::Scale, GizmoSpace::World, t), GizmoHandle::X);
    GizmoTransform scaled = t;
    drag(g, f, from, project(f, t.position + axes[0] * (1.2 * L)), GizmoMode::Scale, GizmoSpace::World,
         scaled);
    EXPECT_NEAR(scaled.scale.x, 2.0 * 1.5, 1e-9);
    EXPECT_EQ(scaled.scale.y, 3.0);
    EXPECT_EQ(scaled.scale.z, 4.0);
    EXPECT_EQ(scaled.position, t.position);
    EXPECT_EQ(scaled.rotation, t.rotation);
    // Dragging through and past the centre never gives a scale <= 0.
    scaled = t;
    drag(g, f, from, project(f, t.position - axes[0] * (0.5 * L)), GizmoMode::Scale, GizmoSpace::World,
         scaled);
    EXPECT_EQ(scaled.scale.x, kMinGizmoScale);
    scaled = t;
    drag(g, f, from, project(f, t.position), GizmoMode::Scale, GizmoSpace::World, scaled);
    EXPECT_GE(scaled.scale.x, kMinGizmoScale);
    // Uniform: the centre handle, 50 px right and 25 px up at sizePx 100 -> x1.75.
    scaled = t;
    const glm::dvec2 centre = project(f, t.position);
    ASSERT_EQ(g.hitTest(f, kSize, centre, GizmoMode::Scale, GizmoSpace::World, t), GizmoHandle::Centre);
    drag(g, f, centre, centre + glm::dvec2(50.0, -25.0), GizmoMode::Scale, GizmoSpace::World, scaled);
    EXPECT_NEAR(glm::length(scaled.scale - t.scale * 1.75), 0.0, 1e-12);
    EXPECT_EQ(g.dragLabel(), "");  // the drag is over
    scaled = t;
    drag(g, f, centre, centre + glm::dvec2(-500.0, 0.0), GizmoMode::Scale, GizmoSpace::World, scaled);
    EXPECT_EQ(scaled.scale, glm::dvec3(kMinGizmoScale));
}

TEST(Gizmo, SnappingRoundsToTheStep) {
    const renderer::CameraFrame f = makeFrame({0, 4, 16}, {0, 0, 0});
    Gizmo g;
    GizmoTransform t;
    const double L = g.worldSizeAt(f, kSize.y, t.position);
    GizmoSnap snap;
    snap.enabled = true;
    const glm::dvec2 from = project(f, t.position + glm::dvec3(0.6 * L, 0, 0));
    for (auto [moved, step, expected] : {std::tuple{2.7, 1.0, 3.0}, std::tuple{2.4, 1.0, 2.0},
                                         std::tuple{2.7, 0.5, 2.5}, std::tuple{-1.3, 1.0, -1.0}}) {
        snap.translate = step;
        GizmoTransform m = t;
        drag(g, f, from, project(f, t.position + glm::dvec3(0.6 * L + moved, 0, 0)), GizmoMode::Translate,
             GizmoSpace::World, m, snap);
        EXPECT_NEAR(m.position.x, expected, 1e-9) << moved << " step " << step;
        EXPECT_EQ(m.position.y, 0.0);
        EXPECT_EQ(m.position.z, 0.0);
    }
    // Rotation: 20 deg -> 15, 37 -> 30, 38 -> 45 (step 15 deg), about Y.
    const auto ringY = [&](double a) { return t.position + L * glm::dvec3(std::cos(a), 0.0, -std::sin(a)); };
    const double a0 = -kPi / 2.0;  // the point nearest the eye (+Z)
    for (auto [deg, expectedDeg] :
         {std::pair{20.0, 15.0}, std::pair{37.0, 30.0}, std::pair{38.0, 45.0}, std::pair{-8.0, -15.0}}) {
        GizmoTransform r = t;
        drag(g, f, project(f, ringY(a0)), project(f, ringY(a0 + deg * kPi / 180.0)), GizmoMode::Rotate,
             GizmoSpace::World, r, snap);
        EXPECT_NEAR(angleAbout(r.rotation, {0, 1, 0}), expectedDeg * kPi / 180.0, 1e-9) << deg;
    }
    // Scale factor 1.44 -> 1.4 (step 0.1), 1.46 -> 1.5.
    for (auto [factor, expected] : {std::pair{1.44, 1.4}, std::pair{1.46, 1.5}}) {
        GizmoTransform s = t;
        drag(g, f, from, project(f, t.position + glm::dvec3(0.6 * L * factor, 0, 0)), GizmoMode::Scale,
             GizmoSpace::World, s, snap);
        EXPECT_NEAR(s.scale.x, expected, 1e-9) << factor;
    }
    // Plane and view-plane drags snap per axis.
    const glm::dvec3 planeHandle = t.position + 0.35 * L * glm::dvec3(1, 0, 1);
    GizmoTransform p = t;
    snap.translate = 1.0;
    drag(g, f, project(f, planeHandle), project(f, planeHandle + glm::dvec3(1.4, 0, -2.6)),
         GizmoMode::Translate, GizmoSpace::World, p, snap);
    EXPECT_NEAR(glm::length(p.position - glm::dvec3(1, 0, -3)), 0.0, 1e-9);
    p = t;
    drag(g, f, project(f, t.position), project(f, t.position + 1.6 * f.right + 0.4 * f.up),
         GizmoMode::Translate, GizmoSpace::World, p, snap);
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(p.position[i], std::round(p.position[i]), 1e-9) << i;  // whole metres
    }
    EXPECT_GT(glm::length(p.position), 0.5);
    // Without snapping the same drag is continuous.
    snap.enabled = false;
    GizmoTransform m = t;
    drag(g, f, from, project(f, t.position + glm::dvec3(0.6 * L + 2.7, 0, 0)), GizmoMode::Translate,
         GizmoSpace::World, m, snap);
    EXPECT_NEAR(m.position.x, 2.7, 1e-6);
}

TEST(Gizmo, LocalAndWorldAxesOfARotatedObject) {
    const renderer::CameraFrame f = makeFrame({9, 7, 9}, {0, 0, 0});
    Gizmo g;
    GizmoTransform t;
    t.rotation = glm::angleAxis(kPi / 2.0, glm::dvec3(0, 1, 0));  // local X = world -Z
    const glm::dvec3 localX = t.rotation * glm::dvec3(1, 0, 0);
    EXPECT_NEAR(glm::length(localX - glm::dvec3(0, 0, -1)), 0.0, 1e-15);
    const double L = g.worldSizeAt(f, kSize.y, t.position);
    // Local: the X handle lies along world -Z and drags along it.
    glm::dvec2 from = project(f, t.position + localX * (0.6 * L));
    ASSERT_EQ(g.hitTest(f, kSize, from, GizmoMode::Translate, GizmoSpace::Local, t), GizmoHandle::X);
    ASSERT_NE(g.hitTest(f, kSize, from, GizmoMode::Translate, GizmoSpace::World, t), GizmoHandle::X);
    GizmoTransform m = t;
    drag(g, f, from, project(f, t.position + localX * (0.6 * L + 2.0)), GizmoMode::Translate,
         GizmoSpace::Local, m);
    EXPECT_NEAR(glm::length(m.position - glm::dvec3(0, 0, -2)), 0.0, 1e-6);
    // World: the X handle is world +X.
    from = project(f, t.position + glm::dvec3(0.6 * L, 0, 0));
    ASSERT_EQ(g.hitTest(f, kSize, from, GizmoMode::Translate, GizmoSpace::World, t), GizmoHandle::X);
    m = t;
    drag(g, f, from, project(f, t.position + glm::dvec3(0.6 * L + 2.0, 0, 0)), GizmoMode::Translate,
         GizmoSpace::World, m);
    EXPECT_NEAR(glm::length(m.position - glm::dvec3(2, 0, 0)), 0.0, 1e-6);
    // Rotate in world space about world X keeps world X fixed: angleAxis(a, X) * start.
    const auto ringX = [&](double a) { return t.position + L * glm::dvec3(0.0, std::cos(a), std::sin(a)); };
    const double a0 = std::atan2((f.eye - t.position).z, (f.eye - t.position).y);
    from = project(f, ringX(a0));
    ASSERT_EQ(g.hitTest(f, kSize, from, GizmoMode::Rotate, GizmoSpace::World, t), GizmoHandle::X);
    m = t;
    drag(g, f, from, project(f, ringX(a0 + 0.5)), GizmoMode::Rotate, GizmoSpace::World, m);
    const glm::dquat expected = glm::angleAxis(0.5, glm::dvec3(1, 0, 0)) * t.rotation;
    EXPECT_NEAR(std::fabs(glm::dot(m.rotation, expected)), 1.0, 1e-12);
}

TEST(Gizmo, OneDragGivesOneStartAndOneFinish) {
    const renderer::CameraFrame f = makeFrame({0, 4, 16}, {0, 0, 0});
    Gizmo g;
    GizmoTransform t;
    const GizmoTransform original = t;
    const double L = g.worldSizeAt(f, kSize.y, t.position);
    const glm::dvec2 from = project(f, t.position + glm::dvec3(0.6 * L, 0, 0));
    GizmoInput in;
    // Far from every handle: not hovered, a press starts nothing and leaves t alone.
    in.mouse = {5.0, 5.0};
    in.pressed = in.down = true;
    GizmoResult r = g.update(f, kSize, in, GizmoMode::Translate, GizmoSpace::World, {}, t);
    EXPECT_FALSE(r.hovered);
    EXPECT_FALSE(r.started);
    EXPECT_FALSE(r.active);
    EXPECT_EQ(r.axis, -1);
    in.pressed = in.down = false;
    in.released = true;
    r = g.update(f, kSize, in, GizmoMode::Translate, GizmoSpace::World, {}, t);
    EXPECT_FALSE(r.finished);
    // Hover.
    in = {};
    in.mouse = from;
    r = g.update(f, kSize, in, GizmoMode::Translate, GizmoSpace::World, {}, t);
    EXPECT_TRUE(r.hovered);
    EXPECT_FALSE(r.active);
    EXPECT_EQ(r.axis, 0);
    // Press: started, nothing changed yet.
    in.pressed = in.down = true;
    r = g.update(f, kSize, in, GizmoMode::Translate, GizmoSpace::World, {}, t);
    EXPECT_TRUE(r.started);
    EXPECT_TRUE(r.active);
    EXPECT_FALSE(r.changed);
    EXPECT_FALSE(r.finished);
    // Moves: changed, never started or finished again; the mode switch is ignored mid-drag.
    in.pressed = false;
    int starts = 0;
    for (int i = 1; i <= 5; ++i) {
        in.mouse = from + glm::dvec2(10.0 * i, 0.0);
        r = g.update(f, kSize, in, i == 3 ? GizmoMode::Rotate : GizmoMode::Translate, GizmoSpace::World, {},
                     t);
        starts += r.started;
        EXPECT_TRUE(r.changed);
        EXPECT_TRUE(r.active);
        EXPECT_FALSE(r.finished);
        EXPECT_EQ(r.axis, 0);
    }
    EXPECT_EQ(starts, 0);
    EXPECT_GT(t.position.x, 0.0);
    char expectedLabel[32];
    std::snprintf(expectedLabel, sizeof expectedLabel, "X %+.2f m", t.position.x);
    EXPECT_EQ(g.dragLabel(), expectedLabel);
    EXPECT_EQ(t.rotation, original.rotation);
    // Holding still: no change.
    r = g.update(f, kSize, in, GizmoMode::Translate, GizmoSpace::World, {}, t);
    EXPECT_FALSE(r.changed);
    // Release: finished once, then idle.
    in.down = false;
    in.released = true;
    r = g.update(f, kSize, in, GizmoMode::Translate, GizmoSpace::World, {}, t);
    EXPECT_TRUE(r.finished);
    EXPECT_FALSE(r.active);
    in.released = false;
    r = g.update(f, kSize, in, GizmoMode::Translate, GizmoSpace::World, {}, t);
    EXPECT_FALSE(r.finished);
    EXPECT_FALSE(r.active);
    // Cancel restores the start of the drag.
    const GizmoTransform before = t;
    in = {};
    in.mouse = project(f, t.position + glm::dvec3(0.6 * g.worldSizeAt(f, kSize.y, t.position), 0, 0));
    in.pressed = in.down = true;
    g.update(f, kSize, in, GizmoMode::Translate, GizmoSpace::World, {}, t);
    in.pressed = false;
    in.mouse.x += 40.0;
    g.update(f, kSize, in, GizmoMode::Translate, GizmoSpace::World, {}, t);
    EXPECT_NE(t.position, before.position);
    EXPECT_TRUE(g.cancel(t));
    EXPECT_EQ(t.position, before.position);
    EXPECT_FALSE(g.active());
    EXPECT_FALSE(g.cancel(t));
    // A button that is up without a release event (focus lost) ends the drag too.
    in.mouse = project(f, t.position + glm::dvec3(0.6 * g.worldSizeAt(f, kSize.y, t.position), 0, 0));
    in.pressed = in.down = true;
    EXPECT_TRUE(g.update(f, kSize, in, GizmoMode::Translate, GizmoSpace::World, {}, t).started);
    in.pressed = in.down = false;
    r = g.update(f, kSize, in, GizmoMode::Translate, GizmoSpace::World, {}, t);
    EXPECT_TRUE(r.finished);
    EXPECT_FALSE(g.active());
}

TEST(Gizmo, HandlesKeepTheirScreenSize) {
    Gizmo g;
    for (double distance : {3.0, 40.0, 900.0}) {
        const renderer::CameraFrame f = makeFrame({0, 0, distance}, {0, 0, 0});
        GizmoTransform t;
        const double L = g.worldSizeAt(f, kSize.y, t.position);
        const glm::dvec2 c = project(f, t.position);
        const glm::dvec2 tip = project(f, t.position + glm::dvec3(L, 0, 0));
        EXPECT_NEAR(glm::length(tip - c), g.sizePx, 1e-9 * g.sizePx) << distance;
        EXPECT_EQ(g.hitTest(f, kSize, c + glm::dvec2(0.6 * g.sizePx, 0.0), GizmoMode::Translate,
                            GizmoSpace::World, t),
                  GizmoHandle::X);
        EXPECT_EQ(g.hitTest(f, kSize, c + glm::dvec2(0.6 * g.sizePx, 20.0), GizmoMode::Translate,
                            GizmoSpace::World, t),
                  GizmoHandle::None);
    }
    // An axis pointing at the camera is hidden (not pickable).
    const renderer::CameraFrame f = makeFrame({0, 0, 10}, {0, 0, 0});
    GizmoTransform t;
    const glm::dvec2 c = project(f, t.position);
    for (double r = 0.0; r < 40.0; r += 1.0) {
        EXPECT_NE(g.hitTest(f, kSize, c + glm::dvec2(r, r), GizmoMode::Scale, GizmoSpace::World, t),
                  GizmoHandle::Z);
    }
    // Behind the camera: nothing.
    t.position = {0, 0, 20};
    EXPECT_EQ(g.hitTest(f, kSize, c, GizmoMode::Translate, GizmoSpace::World, t), GizmoHandle::None);
}

TEST(Gizmo, NoNanForAnyInput) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::uniform_int_distribution<int> coin(0, 1);
    std::uniform_int_distribution<int> special(0, 15);
    const double specials[] = {std::nan(""), std::numeric_limits<double>::infinity(), -1e308, 0.0};
    Gizmo g;
    GizmoTransform t;
    t.scale = {1, 2, 3};
    const GizmoMode modes[] = {GizmoMode::Translate, GizmoMode::Rotate, GizmoMode::Scale};
    for (int i = 0; i < 20000; ++i) {
        if (i % 500 == 0) {
            t = {};  // keep the object near the cameras so drags actually happen
            t.scale = {1, 2, 3};
        }
        const renderer::CameraFrame f =
            makeFrame({10 * u(rng), 10 * u(rng), 10 + 5 * u(rng)}, {u(rng), u(rng), u(rng)});
        GizmoInput in;
        const int k = special(rng);
        in.mouse =
            k < 4 ? glm::dvec2(specials[k], 100.0) : glm::dvec2(640 + 300 * u(rng), 360 + 300 * u(rng));
        in.down = coin(rng) || coin(rng);
        in.pressed = coin(rng);
        in.released = !in.down;
        GizmoSnap snap;
        snap.enabled = coin(rng);
        snap.translate = k == 5 ? 0.0 : 0.5;
        snap.rotateDeg = k == 6 ? std::nan("") : 15.0;
        const GizmoResult r =
            g.update(f, kSize, in, modes[i % 3], coin(rng) ? GizmoSpace::Local : GizmoSpace::World, snap, t);
        ASSERT_TRUE(std::isfinite(t.position.x) && std::isfinite(t.position.y) && std::isfinite(t.position.z))
            << i;
        ASSERT_TRUE(std::isfinite(t.rotation.w) && std::isfinite(t.rotation.x)) << i;
        ASSERT_NEAR(glm::length(t.rotation), 1.0, 1e-9) << i;
        ASSERT_TRUE(t.scale.x >= kMinGizmoScale && t.scale.y >= kMinGizmoScale && t.scale.z >= kMinGizmoScale)
            << i;
        ASSERT_TRUE(std::isfinite(t.scale.x) && std::isfinite(t.scale.y) && std::isfinite(t.scale.z)) << i;
        (void)r;
    }
}

}  // namespace
}  // namespace aerial::editor
