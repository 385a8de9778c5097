// Overlays: projection consistent with picking rays, nothing behind the
// camera, near-plane and guard-band clipping of segments, outline geometry,
// and the ImDrawList output of every draw function staying finite.
#include "viewport/overlay.hpp"

#include "viewport/gizmo.hpp"
#include "viewport/picking.hpp"

#include <imgui.h>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <map>
#include <numbers>
#include <random>

namespace aerial::editor {
namespace {

renderer::CameraFrame makeFrame(glm::dvec3 eye, glm::dvec3 target, double fovDeg = 60.0,
                                double aspect = 16.0 / 9.0, double nearDistance = 0.1) {
    renderer::Camera c;
    c.eye = eye;
    c.target = target;
    c.verticalFov = fovDeg * std::numbers::pi / 180.0;
    c.aspect = aspect;
    c.nearDistance = nearDistance;
    return renderer::cameraFrame(c);
}

TEST(ProjectToViewport, KnownPixelsAndRoundTripThroughPickingRays) {
    // fov 90 deg, square 100 px viewport, looking -Z from the origin.
    const renderer::CameraFrame f = makeFrame({0, 0, 0}, {0, 0, -1}, 90.0, 1.0);
    auto p = projectToViewport(f, {100, 100}, {1, 0, -1});
    ASSERT_TRUE(p.has_value());
    EXPECT_NEAR(p->x, 100.0, 1e-12);
    EXPECT_NEAR(p->y, 50.0, 1e-12);
    p = projectToViewport(f, {100, 100}, {0, 1, -2});
    ASSERT_TRUE(p.has_value());
    EXPECT_NEAR(p->x, 50.0, 1e-12);
    EXPECT_NEAR(p->y, 25.0, 1e-12);
    // Outside the view still projects (outside the viewport).
    p = projectToViewport(f, {100, 100}, {-3, 0, -1});
    ASSERT_TRUE(p.has_value());
    EXPECT_NEAR(p->x, -100.0, 1e-12);

    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const renderer::CameraFrame g = makeFrame({5, 3, 9}, {-4, 1, -30}, 55.0, 1.6);
    const glm::dvec2 size{1600, 1000};
    int checked = 0;
    for (int i = 0; i < 2000; ++i) {
        const glm::dvec3 w = g.eye + 200.0 * glm::dvec3(u(rng), u(rng), u(rng));
        const auto q = projectToViewport(g, size, w);
        const double depth = glm::dot(w - g.eye, g.forward);
        ASSERT_EQ(q.has_value(), depth >= g.nearDistance);
        if (!q) continue;
        ++checked;
        const Ray r = rayThroughPixel(g, *q, size);
        const glm::dvec3 toPoint = w - r.origin;
        const double off = glm::length(toPoint - glm::dot(toPoint, r.direction) * r.direction);
        EXPECT_LT(off, 1e-9 * glm::length(toPoint)) << i;
        EXPECT_GT(glm::dot(toPoint, r.direction), 0.0);
    }
    EXPECT_GT(checked, 500);
}

TEST(ProjectToViewport, NothingBehindTheCameraOrBeforeTheNearPlane) {
    const renderer::CameraFrame f = makeFrame({0, 0, 0}, {0, 0, -1}, 60.0, 1.0, 0.5);
    EXPECT_FALSE(projectToViewport(f, {100, 100}, {0, 0, 1}).has_value());
    EXPECT_FALSE(projectToViewport(f, {100, 100}, {3, 2, 0}).has_value());  // the eye's plane
    EXPECT_FALSE(projectToViewport(f, {100, 100}, {0, 0, 0}).has_value());
    EXPECT_FALSE(projectToViewport(f, {100, 100}, {0, 0, -0.49}).has_value());
    EXPECT_TRUE(projectToViewport(f, {100, 100}, {0, 0, -0.5}).has_value());
    EXPECT_FALSE(projectToViewport(f, {100, 100}, {std::nan(""), 0, -3}).has_value());
}

TEST(ProjectSegment, ClipsAtTheNearPlaneNeverThroughInfinity) {
    const double nearD = 0.5;
    const renderer::CameraFrame f = makeFrame({0, 0, 0}, {0, 0, -1}, 90.0, 1.0, nearD);
    const glm::dvec2 size{100, 100};
    // From in front (depth 10) to behind (depth -10), crossing the eye's plane
    // away from the eye (a naive projection of b would land elsewhere, flipped).
    const glm::dvec3 a{-5, 1, -10};
    const glm::dvec3 b{5, 3, 10};
    const auto s = projectSegment(f, size, a, b, 1e6);
    ASSERT_TRUE(s.has_value());
    const auto pa = projectToViewport(f, size, a);
    ASSERT_TRUE(pa.has_value());
    EXPECT_NEAR(glm::length(s->a - *pa), 0.0, 1e-12);
    // The clipped end is where the segment crosses depth = near: t = (10 - 0.5) / 20.
    const glm::dvec3 onNear = a + (9.5 / 20.0) * (b - a);
    EXPECT_NEAR(-onNear.z, nearD, 1e-12);
    // (-0.25, 1.95) at depth 0.5, fov 90: ndc (-0.5, 3.9) -> pixel (25, -145).
    EXPECT_NEAR(onNear.x, -0.25, 1e-12);
    EXPECT_NEAR(onNear.y, 1.95, 1e-12);
    EXPECT_NEAR(s->b.x, 25.0, 1e-9);
    EXPECT_NEAR(s->b.y, -145.0, 1e-9);
    // Reversed order gives the same segment reversed.
    const auto r = projectSegment(f, size, b, a, 1e6);
    ASSERT_TRUE(r.has_value());
    EXPECT_NEAR(glm::length(r->a - s->b), 0.0, 1e-9);
    EXPECT_NEAR(glm::length(r->b - s->a), 0.0, 1e-9);
    // Entirely behind, or entirely before the near plane: nothing.
    EXPECT_FALSE(projectSegment(f, size, {0, 0, 1}, {4, 4, 30}).has_value());
    EXPECT_FALSE(projectSegment(f, size, {-1, 0, -0.2}, {1, 0, -0.3}).has_value());
    // A segment grazing the near plane at a huge lateral offset is cut to the guard band.
    const auto g = projectSegment(f, size, {-1e6, 0, -0.5}, {1e6, 0, -0.5}, 2048.0);
    ASSERT_TRUE(g.has_value());
    EXPECT_NEAR(g->a.x, -2048.0, 1e-6);
    EXPECT_NEAR(g->b.x, 100.0 + 2048.0, 1e-6);
    // Outside the guard band entirely.
    EXPECT_FALSE(projectSegment(f, size, {1e4, -1, -1}, {1e4, 1, -1}, 100.0).has_value());
}

TEST(ClipSegmentToRect, LiangBarskyKnownCases) {
    const glm::dvec2 lo{0, 0};
    const glm::dvec2 hi{10, 10};
    auto c = clipSegmentToRect({{-5, 5}, {15, 5}}, lo, hi);
    ASSERT_TRUE(c.has_value());
    EXPECT_EQ(c->a, glm::dvec2(0, 5));
    EXPECT_EQ(c->b, glm::dvec2(10, 5));
    c = clipSegmentToRect({{2, 3}, {4, 5}}, lo, hi);  // inside: unchanged
    ASSERT_TRUE(c.has_value());
    EXPECT_EQ(c->a, glm::dvec2(2, 3));
    EXPECT_EQ(c->b, glm::dvec2(4, 5));
    c = clipSegmentToRect({{-5, -5}, {15, 15}}, lo, hi);  // the diagonal
    ASSERT_TRUE(c.has_value());
    EXPECT_NEAR(glm::length(c->a - glm::dvec2(0, 0)), 0.0, 1e-12);
    EXPECT_NEAR(glm::length(c->b - glm::dvec2(10, 10)), 0.0, 1e-12);
    EXPECT_FALSE(clipSegmentToRect({{-5, 11}, {15, 11}}, lo, hi).has_value());  // parallel outside
    EXPECT_FALSE(clipSegmentToRect({{-5, 4}, {4, 15}}, lo, hi).has_value() &&
                 false);  // crosses the corner region: any answer inside the rect is fine
    EXPECT_FALSE(clipSegmentToRect({{-5, 6}, {3, 16}}, lo, hi).has_value());  // misses the corner
    EXPECT_FALSE(clipSegmentToRect({{std::nan(""), 0}, {1, 1}}, lo, hi).has_value());
}

TEST(VolumeOutline, BoxEdgesAndEllipsoidGreatEllipses) {
    FogVolume box;
    box.shape = FogVolumeShape::Box;
    box.position = {3, -2, 7};
    box.rotation = glm::angleAxis(0.7, glm::normalize(glm::dvec3(1, 2, -1)));
    box.halfExtents = {1, 2, 3};
    const auto edges = volumeOutlineSegments(box);
    ASSERT_EQ(edges.size(), 12u);
    std::map<std::tuple<long, long, long>, int> cornerUse;
    int perAxis[3] = {0, 0, 0};
    for (const auto& [a, b] : edges) {
        // Each edge is one object axis long: 2 half extents.
        const glm::dvec3 d = glm::inverse(box.rotation) * (b - a);
        int axis = -1;
        for (int i = 0; i < 3; ++i) {
            if (std::fabs(d[i]) > 1e-9) {
                EXPECT_EQ(axis, -1);
                axis = i;
            }
        }
        ASSERT_GE(axis, 0);
        EXPECT_NEAR(std::fabs(d[axis]), 2.0 * box.halfExtents[axis], 1e-12);
        ++perAxis[axis];
        for (const glm::dvec3& p : {a, b}) {
            const glm::dvec3 q = (glm::inverse(box.rotation) * (p - box.position)) / box.halfExtents;
            EXPECT_NEAR(std::fabs(q.x), 1.0, 1e-12);
            EXPECT_NEAR(std::fabs(q.y), 1.0, 1e-12);
            EXPECT_NEAR(std::fabs(q.z), 1.0, 1e-12);
            ++cornerUse[{std::lround(q.x), std::lround(q.y), std::lround(q.z)}];
        }
    }
    EXPECT_EQ(perAxis[0], 4);
    EXPECT_EQ(perAxis[1], 4);
    EXPECT_EQ(perAxis[2], 4);
    ASSERT_EQ(cornerUse.size(), 8u);
    for (const auto& [corner, uses] : cornerUse) EXPECT_EQ(uses, 3);

    FogVolume ellipsoid = box;
    ellipsoid.shape = FogVolumeShape::Ellipsoid;
    const auto rings = volumeOutlineSegments(ellipsoid, 48);
    ASSERT_EQ(rings.size(), 3u * 48u);
    for (const auto& [a, b] : rings) {
        for (const glm::dvec3& p : {a, b}) {
            const glm::dvec3 q =
                (glm::inverse(ellipsoid.rotation) * (p - ellipsoid.position)) / ellipsoid.halfExtents;
            EXPECT_NEAR(glm::length(q), 1.0, 1e-12);
            EXPECT_NEAR(std::min({std::fabs(q.x), std::fabs(q.y), std::fabs(q.z)}), 0.0,
                        1e-12);  // a principal plane
        }
    }
    // Closed loops: each ring ends where it starts.
    for (int ring = 0; ring < 3; ++ring) {
        EXPECT_EQ(rings[static_cast<std::size_t>(ring * 48)].first,
                  rings[static_cast<std::size_t>(ring * 48 + 47)].second);
    }
    ellipsoid.halfExtents.y = 0.0;
    EXPECT_TRUE(volumeOutlineSegments(ellipsoid).empty());
    box.rotation = glm::dquat(0, 0, 0, 0);
    EXPECT_TRUE(volumeOutlineSegments(box).empty());
}

TEST(OverlayColour, PackingAndLinearToDisplay) {
    EXPECT_EQ(overlayColour(1, 0, 0, 1), 0xFF0000FFu);  // IM_COL32(255, 0, 0, 255)
    EXPECT_EQ(overlayColour(0, 0, 1, 0.5), 0x80FF0000u);
    EXPECT_EQ(overlayColour(2, -1, std::nan(""), 1), 0xFF0000FFu);
    EXPECT_EQ(displayColourOfLinear({0, 0, 0}), overlayColour(0.5, 0.5, 0.5));
    EXPECT_EQ(displayColourOfLinear({4, 2, 0}), displayColourOfLinear({1, 0.5, 0}));  // hue kept
    EXPECT_EQ(displayColourOfLinear({1, 1, 1}), 0xFFFFFFFFu);
    // Linear 0.5 is sRGB 0.7354 -> 188.
    EXPECT_EQ(displayColourOfLinear({0.5, 0.5, 0.5}) & 0xFFu, 188u);
}

// Runs the real draw functions into an ImGui draw list (a context with a
// built font atlas, no renderer) and checks every vertex is finite and within
// the guard band around the viewport.
class DrawListTest : public ::testing::Test {
protected:
    void SetUp() override {
        IMGUI_CHECKVERSION();
        ImGui::CreateContext();
        ImGuiIO& io = ImGui::GetIO();
        io.IniFilename = nullptr;  // no imgui.ini in the working directory
        io.DisplaySize = ImVec2(1280, 720);
        io.DeltaTime = 1.0f / 60.0f;
        unsigned char* pixels = nullptr;
        int w = 0;
        int h = 0;
        io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
        ImGui::NewFrame();
        list = ImGui::GetForegroundDrawList();
    }
    void TearDown() override {
        ImGui::EndFrame();
        ImGui::DestroyContext();
    }
    void expectSane(int fromVertex, double guard) const {
        for (int i = fromVertex; i < list->VtxBuffer.Size; ++i) {
            const ImVec2 p = list->VtxBuffer[i].pos;
            ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y)) << i;
            ASSERT_GT(p.x, origin.x - guard);
            ASSERT_LT(p.x, origin.x + size.x + guard);
            ASSERT_GT(p.y, origin.y - guard);
            ASSERT_LT(p.y, origin.y + size.y + guard);
        }
    }
    ImDrawList* list = nullptr;
    glm::dvec2 origin{40, 30};
    glm::dvec2 size{1200, 650};
};

TEST_F(DrawListTest, CameraInsideAVolumeDrawsOnlyClippedFiniteLines) {
    FogVolume v;
    v.shape = FogVolumeShape::Box;
    v.halfExtents = {50, 20, 50};
    const renderer::CameraFrame f = makeFrame({1, 2, 3}, {10, 0, -40}, 60.0, size.x / size.y);
    const int before = list->VtxBuffer.Size;
    drawVolumeOutline(list, origin, f, size, v, overlayColour(1, 0.6, 0.1));
    EXPECT_GT(list->VtxBuffer.Size, before);  // some edges are in front
    expectSane(before, 2048.0 + 10.0);
    v.shape = FogVolumeShape::Ellipsoid;
    int mark = list->VtxBuffer.Size;
    drawVolumeOutline(list, origin, f, size, v, overlayColour(1, 0.6, 0.1));
    EXPECT_GT(list->VtxBuffer.Size, mark);
    expectSane(mark, 2048.0 + 10.0);
    mark = list->VtxBuffer.Size;
    drawGroundGrid(list, origin, f, size, 10.0, 40);
    EXPECT_GT(list->VtxBuffer.Size, mark);
    expectSane(mark, 2048.0 + 10.0);
}

TEST_F(DrawListTest, EmitterIconsOnlyInFront) {
    const renderer::CameraFrame f = makeFrame({0, 0, 0}, {0, 0, -1}, 60.0, size.x / size.y);
    Emitter e;
    e.position = {0, 0, 5};  // behind
    int mark = list->VtxBuffer.Size;
    drawEmitterIcon(list, origin, f, size, e, true);
    EXPECT_EQ(list->VtxBuffer.Size, mark);
    e.position = {1, 0.5, -5};
    drawEmitterIcon(list, origin, f, size, e, true);
    EXPECT_GT(list->VtxBuffer.Size, mark);
    expectSane(mark, 30.0);
    e.kind = EmitterKind::Lightning;
    e.colour = {std::nan(""), 5.0, -1.0};
    mark = list->VtxBuffer.Size;
    drawEmitterIcon(list, origin, f, size, e, false);
    EXPECT_GT(list->VtxBuffer.Size, mark);
    expectSane(mark, 30.0);
}

TEST_F(DrawListTest, GizmoDrawsInEveryModeAndNothingBehindTheCamera) {
    const renderer::CameraFrame f = makeFrame({6, 4, 12}, {0, 0, 0}, 60.0, size.x / size.y);
    Gizmo g;
    GizmoTransform t;
    t.rotation = glm::angleAxis(0.5, glm::dvec3(0, 1, 0));
    for (GizmoMode m : {GizmoMode::Translate, GizmoMode::Rotate, GizmoMode::Scale}) {
        for (GizmoSpace s : {GizmoSpace::World, GizmoSpace::Local}) {
            const int mark = list->VtxBuffer.Size;
            g.draw(list, origin, f, size, m, s, t);
            EXPECT_GT(list->VtxBuffer.Size, mark);
            expectSane(mark, 2048.0 + 10.0);
        }
    }
    // During a rotate drag the swept fan and the label are drawn as well.
    const double L = g.worldSizeAt(f, size.y, t.position);
    const auto ringY = [&](double a) { return t.position + L * glm::dvec3(std::cos(a), 0.0, -std::sin(a)); };
    const double a0 = std::atan2(-(f.eye - t.position).z, (f.eye - t.position).x);
    const auto from = projectToViewport(f, size, ringY(a0));
    const auto to = projectToViewport(f, size, ringY(a0 + 1.0));
    ASSERT_TRUE(from && to);
    int idle = list->VtxBuffer.Size;
    g.draw(list, origin, f, size, GizmoMode::Rotate, GizmoSpace::World, t);
    idle = list->VtxBuffer.Size - idle;
    GizmoInput in;
    in.mouse = *from;
    in.pressed = in.down = true;
    ASSERT_TRUE(g.update(f, size, in, GizmoMode::Rotate, GizmoSpace::World, {}, t).started);
    in.pressed = false;
    in.mouse = *to;
    g.update(f, size, in, GizmoMode::Rotate, GizmoSpace::World, {}, t);
    EXPECT_EQ(g.dragLabel(), "Y +57.3\xc2\xb0");
    int dragging = list->VtxBuffer.Size;
    g.draw(list, origin, f, size, GizmoMode::Rotate, GizmoSpace::World, t);
    dragging = list->VtxBuffer.Size - dragging;
    EXPECT_GT(dragging, idle + 30);  // a fan of 10 triangles and the label's glyphs
    expectSane(list->VtxBuffer.Size - dragging, 2048.0 + 10.0);

    t.position = {12, 8, 24};  // behind the eye
    const int mark = list->VtxBuffer.Size;
    g.draw(list, origin, f, size, GizmoMode::Rotate, GizmoSpace::World, t);
    EXPECT_EQ(list->VtxBuffer.Size, mark);
}

}  // namespace
}  // namespace aerial::editor
