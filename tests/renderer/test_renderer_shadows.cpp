// test_renderer_shadows.cpp — the sun's cascaded shadow maps
// (shadow_map_pass.cpp, shaders/common/shadows.glsl) on small scenes built
// here, lit by the sun alone (no sky tables: no ambient), so a shadowed
// Lambert ground is black and a lit one equals the frame without shadows:
//   - a box on a plane against the exact shadow polygon (the box's corners
//     projected along the light onto the plane, convex hull), pixels
//     classified outside a band of the filter's width around its edge;
//   - a masked quad with a checkerboard alpha casts a checkerboard;
//   - moving the camera by less than a texel leaves the shadow where it was
//     in the world (texel snapping): pixel for pixel, once the image shift
//     is undone;
//   - shadows off, a plane alone (nothing to shadow: no acne) and the sun
//     below the horizon all render bit-identical to the frame without the
//     pass; no NaN or Inf under extreme settings.
#include "gl_fixture.hpp"

#include <aerial/renderer/scene.hpp>

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace aerial::test {
namespace {

using renderer::Camera;
using renderer::FrameDesc;
using renderer::Image;
using renderer::Renderer;

FrameDesc sceneOnly(bool shadows) {
    FrameDesc f = floatFrame();
    f.passes.sky = false;
    f.passes.globalFog = false;
    f.passes.volumes = false;
    f.passes.shadows = shadows;
    return f;
}

renderer::SceneMesh lambert(renderer::SceneMesh mesh) {
    mesh.specularFactor = 0.0;
    return mesh;
}

renderer::SceneMesh groundPlane() {
    return lambert(
        renderer::makeQuadMesh({-200.0, 0.0, 200.0}, {400.0, 0.0, 0.0}, {0.0, 0.0, -400.0}, glm::dvec3(0.5)));
}

PresetState sunOnly(const glm::dvec3& toSun) {
    PresetState s;
    s.sunLight = light(toSun, glm::dvec3(10.0), glm::dvec3(10.0));
    s.moonLight = light({0.0, -1.0, 0.0}, glm::dvec3(0.0), glm::dvec3(0.0));
    return s;
}

double luminanceAt(const Image& image, int x, int y) {
    const float* p = &image.pixels[(std::size_t(y) * image.width + x) * image.channels];
    return (p[0] + p[1] + p[2]) / 3.0;
}

bool allFinite(const Image& image) {
    return std::all_of(image.pixels.begin(), image.pixels.end(), [](float v) { return std::isfinite(v); });
}

/// The point where pixel (x, y)'s ray meets y = 0 (false when it does not).
bool groundPoint(const renderer::CameraFrame& f, int x, int y, glm::dvec3& p, double& t) {
    const glm::dvec3 ray = renderer::farRayAtPixel(f, x, y, kWidth, kHeight);
    if (!(ray.y < -1e-3 * glm::length(ray))) return false;
    t = -f.eye.y / ray.y;
    if (t > 0.99) return false;
    p = f.eye + t * ray;
    return true;
}

/// Whether the segment eye + s ray, s in [0, tMax], meets the box [lo, hi].
bool hitsBox(const glm::dvec3& eye, const glm::dvec3& ray, double tMax, const glm::dvec3& lo,
             const glm::dvec3& hi) {
    double t0 = 0.0, t1 = tMax;
    for (int a = 0; a < 3; ++a) {
        if (std::fabs(ray[a]) < 1e-300) {
            if (eye[a] < lo[a] || eye[a] > hi[a]) return false;
            continue;
        }
        double ta = (lo[a] - eye[a]) / ray[a], tb = (hi[a] - eye[a]) / ray[a];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
    }
    return t0 <= t1;
}

double cross2(const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

/// Convex hull, counter-clockwise (Andrew's monotone chain).
std::vector<glm::dvec2> convexHull(std::vector<glm::dvec2> points) {
    std::sort(points.begin(), points.end(), [](const glm::dvec2& a, const glm::dvec2& b) {
        return a.x < b.x || (a.x == b.x && a.y < b.y);
    });
    std::vector<glm::dvec2> hull(2 * points.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        while (k >= 2 && cross2(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
        hull[k++] = points[i];
    }
    for (std::size_t i = points.size() - 1, t = k + 1; i > 0; --i) {
        while (k >= t && cross2(hull[k - 2], hull[k - 1], points[i - 1]) <= 0.0) --k;
        hull[k++] = points[i - 1];
    }
    hull.resize(k - 1);
    return hull;
}

/// Signed distance from q to the convex polygon's boundary: negative inside.
double signedDistance(const std::vector<glm::dvec2>& polygon, const glm::dvec2& q) {
    bool inside = true;
    double nearest = 1e300;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const glm::dvec2 a = polygon[i], b = polygon[(i + 1) % polygon.size()];
        inside = inside && cross2(a, b, q) > 0.0;
        const glm::dvec2 ab = b - a;
        const double s = std::clamp(glm::dot(q - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
        nearest = std::min(nearest, glm::length(q - (a + s * ab)));
    }
    return inside ? -nearest : nearest;
}

/// The cascade texel [m] at view depth `depth` (the larger of two while
/// they blend), from the frame's statistics.
double texelAt(const renderer::ShadowMapStats& stats, double depth) {
    double texel = stats.texelM[stats.cascades - 1];
    for (int k = 0; k < stats.cascades; ++k) {
        if (depth <= stats.splitM[k]) {
            texel = stats.texelM[std::min(k + 1, stats.cascades - 1)];
            break;
        }
    }
    return texel;
}

class Shadows : public GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();
        if (HasFatalFailure()) return;
        renderer_ = std::make_unique<Renderer>(rendererDesc());
        ASSERT_TRUE(renderer_->valid()) << renderer_->error();
    }
    Image render(const Camera& camera, const PresetState& state, const FrameDesc& frame) {
        renderer_->render(camera, state, frame);
        return renderer_->readColour();
    }
    std::unique_ptr<Renderer> renderer_;
};

TEST_F(Shadows, BoxOnAPlaneCastsTheExactShadowPolygon) {
    const glm::dvec3 lo(-1.5, 0.0, -1.5), hi(1.5, 3.0, 1.5);
    renderer::SceneDesc scene;
    scene.meshes.push_back(groundPlane());
    scene.meshes.push_back(lambert(renderer::makeBoxMesh(0.5 * (lo + hi), 0.5 * (hi - lo))));
    renderer_->setScene(scene);
    const glm::dvec3 toSun = glm::normalize(glm::dvec3(0.8, 0.6, 0.45));
    const PresetState state = sunOnly(toSun);
    const Camera camera = makeCamera({-2.5, 12.0, 6.0}, {-2.2, 0.0, -1.0}, 500.0, 0.5);
    const Image lit = render(camera, state, sceneOnly(false));
    const Image shadowed = render(camera, state, sceneOnly(true));
    const renderer::ShadowMapStats stats = renderer_->stats().shadowMap;
    ASSERT_TRUE(stats.drawn);
    EXPECT_FALSE(stats.moon);
    EXPECT_EQ(stats.cascades, 3);
    ASSERT_TRUE(allFinite(shadowed));

    // The exact shadow: the hull of the box's footprint and its top corners
    // projected along the light onto y = 0.
    std::vector<glm::dvec2> corners;
    for (int c = 0; c < 8; ++c) {
        const glm::dvec3 p((c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z);
        const glm::dvec3 ground = p - toSun * (p.y / toSun.y);
        corners.push_back({ground.x, ground.z});
    }
    const std::vector<glm::dvec2> polygon = convexHull(corners);
    ASSERT_GE(polygon.size(), 4u);

    // Band around the edge: the PCF footprint (+-2 texels) and a texel of
    // rasterisation, plus the normal offset's shift of the lookup along the
    // light (2.5 texels up, so 2.5 tan(theta) texels across the ground).
    const double tanTheta = std::sqrt(toSun.x * toSun.x + toSun.z * toSun.z) / toSun.y;
    const renderer::CameraFrame view = renderer::cameraFrame(camera);
    int inside = 0, outside = 0;
    double worstInside = 0.0, worstOutside = 0.0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            glm::dvec3 p;
            double t = 0.0;
            if (!groundPoint(view, x, y, p, t)) continue;
            const glm::dvec3 ray = renderer::farRayAtPixel(view, x, y, kWidth, kHeight);
            if (hitsBox(view.eye, ray, t, lo - 1e-3, hi + 1e-3)) continue;  // the box hides the ground
            const double band = (3.0 + 2.5 * tanTheta) * texelAt(stats, glm::dot(p - view.eye, view.forward));
            const double d = signedDistance(polygon, {p.x, p.z});
            const double unshadowed = luminanceAt(lit, x, y);
            ASSERT_GT(unshadowed, 0.1);
            const double ratio = luminanceAt(shadowed, x, y) / unshadowed;
            if (d < -band) {
                ++inside;
                worstInside = std::max(worstInside, ratio);
            } else if (d > band) {
                ++outside;
                worstOutside = std::max(worstOutside, std::fabs(ratio - 1.0));
            }
        }
    }
    std::printf(
        "box shadow: %d pixels inside, %d outside (band %.3f m at cascade 0); worst inside %.2e, "
        "worst outside |ratio - 1| %.2e\n",
        inside, outside, (3.0 + 2.5 * tanTheta) * stats.texelM[0], worstInside, worstOutside);
    EXPECT_GT(inside, 400);
    EXPECT_GT(outside, 3000);
    EXPECT_LT(worstInside, 0.02);   // fully in shadow
    EXPECT_LT(worstOutside, 1e-6);  // exactly lit: no acne, no light leak
    EXPECT_TRUE(log.errors.empty());
}

TEST_F(Shadows, MaskedCheckerboardCastsACheckerboard) {
    // A 4 m square at y = 2 with a 4 x 4 checker of alpha 1 / 0 (1 m cells).
    auto checker = std::make_shared<renderer::SceneTexture>();
    checker->width = checker->height = 4;
    for (int row = 0; row < 4; ++row) {
        for (int col = 0; col < 4; ++col) {
            const std::uint8_t a = (row + col) % 2 == 0 ? 255 : 0;
            checker->rgba.insert(checker->rgba.end(), {255, 255, 255, a});
        }
    }
    renderer::SceneMesh quad =
        lambert(renderer::makeQuadMesh({-2.0, 2.0, 2.0}, {4.0, 0.0, 0.0}, {0.0, 0.0, -4.0}, glm::dvec3(1.0)));
    quad.alphaMode = renderer::AlphaMode::Mask;
    quad.alphaCutoff = 0.5;
    quad.baseColorTexture = checker;
    renderer::SceneDesc scene;
    scene.meshes.push_back(groundPlane());
    scene.meshes.push_back(quad);
    renderer_->setScene(scene);
    const glm::dvec3 toSun = glm::normalize(glm::dvec3(0.3, 1.0, 0.0));
    const PresetState state = sunOnly(toSun);
    const Camera camera = makeCamera({0.0, 1.8, 6.0}, {-0.6, 0.0, -0.5}, 500.0);  // under the quad's plane
    const Image lit = render(camera, state, sceneOnly(false));
    const Image shadowed = render(camera, state, sceneOnly(true));
    ASSERT_TRUE(allFinite(shadowed));
    const renderer::CameraFrame view = renderer::cameraFrame(camera);
    // Cell (col, row) covers x in [-2 + col, -1 + col], z in [-2 + row, -1 + row]
    // (the image's top row at z = -2, makeQuadMesh's texture coordinates);
    // its centre's shadow lies 2 m along the light below it.
    int checked = 0;
    for (int row = 1; row <= 2; ++row) {
        std::string pattern;
        for (int col = 0; col < 4; ++col) {
            const glm::dvec3 centre(-1.5 + col, 2.0, -1.5 + row);
            const glm::dvec3 ground = centre - toSun * (2.0 / toSun.y);
            const glm::dvec4 clip = view.clipFromWorld * glm::dvec4(ground, 1.0);
            const int x = int(std::floor((clip.x / clip.w * 0.5 + 0.5) * kWidth));
            const int y = int(std::floor((0.5 - clip.y / clip.w * 0.5) * kHeight));
            ASSERT_TRUE(x >= 0 && x < kWidth && y >= 0 && y < kHeight) << col << " " << row;
            const double ratio = luminanceAt(shadowed, x, y) / luminanceAt(lit, x, y);
            const bool opaque = (row + col) % 2 == 0;
            pattern += ratio < 0.5 ? '#' : '.';
            if (opaque) {
                EXPECT_LT(ratio, 0.02) << "cell " << col << ", " << row << " should be shadowed";
            } else {
                EXPECT_NEAR(ratio, 1.0, 1e-6) << "cell " << col << ", " << row << " should be lit";
            }
            ++checked;
        }
        std::printf("checker row %d along x: %s\n", row, pattern.c_str());
    }
    EXPECT_EQ(checked, 8);
    EXPECT_TRUE(log.errors.empty());
}

TEST_F(Shadows, SubTexelCameraMovesLeaveTheShadowInPlace) {
    renderer::SceneDesc scene;
    scene.meshes.push_back(groundPlane());
    scene.meshes.push_back(lambert(renderer::makeBoxMesh({0.0, 1.0, 0.0}, {1.0, 1.0, 1.0})));
    renderer_->setScene(scene);
    const PresetState state = sunOnly(glm::normalize(glm::dvec3(0.6, 1.0, 0.35)));
    FrameDesc frame = sceneOnly(true);
    frame.shadowMap.resolution = 256;  // texels larger than pixels: the move is a fraction of a texel
    // Straight down from 10 m: moving the camera by one pixel's footprint
    // along its right axis shifts the image by exactly one pixel, so pixel
    // (x, y) after the move sees the ground point pixel (x + 1, y) saw.
    const double height = 10.0, fov = 1.0;
    const double pixelM = 2.0 * height * std::tan(0.5 * fov) / kHeight;
    auto downCamera = [&](double x) {
        Camera c = makeCamera({x, height, 0.2}, {x, 0.0, 0.2}, 500.0, fov);
        c.up = {0.0, 0.0, -1.0};
        return c;
    };
    const Image before = render(downCamera(-1.3), state, frame);
    const double texel = renderer_->stats().shadowMap.texelM[0];
    ASSERT_LT(pixelM, 0.6 * texel);
    const Image after = render(downCamera(-1.3 + pixelM), state, frame);
    ASSERT_TRUE(allFinite(before) && allFinite(after));
    const double litValue = luminanceAt(before, 0, 0);  // a lit corner of the ground
    int penumbra = 0, changed = 0;
    double worst = 0.0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x + 1 < kWidth; ++x) {
            const double a = luminanceAt(before, x + 1, y) / litValue;
            const double b = luminanceAt(after, x, y) / litValue;
            if (a > 0.05 && a < 0.95) ++penumbra;
            const double d = std::fabs(a - b);
            worst = std::max(worst, d);
            if (d > 1e-3) ++changed;
        }
    }
    std::printf("sub-texel move (%.3f of a texel): %d penumbra pixels, %d changed by > 1e-3, worst %.2e\n",
                pixelM / texel, penumbra, changed, worst);
    EXPECT_GT(penumbra, 20);  // there are soft edges that a shimmering map would change
    EXPECT_EQ(changed, 0);
    EXPECT_TRUE(log.errors.empty());
}

TEST_F(Shadows, OffUnshadowedOrBelowTheHorizonIsBitIdentical) {
    const Camera camera = makeCamera({-6.0, 8.0, 6.0}, {-0.5, 0.0, -0.3}, 500.0);
    renderer::SceneDesc plane;
    plane.meshes.push_back(groundPlane());
    plane.meshes.back().specularFactor = 1.0;  // specular too: the lit plane must not change at all
    renderer_->setScene(plane);
    for (const glm::dvec3& toSun : {glm::dvec3(0.6, 1.0, 0.35), glm::dvec3(-1.0, 0.15, 0.2)}) {
        const PresetState state = sunOnly(glm::normalize(toSun));
        const Image off = render(camera, state, sceneOnly(false));
        const Image on = render(camera, state, sceneOnly(true));
        EXPECT_TRUE(renderer_->stats().shadowMap.drawn);
        ASSERT_EQ(off.pixels.size(), on.pixels.size());
        EXPECT_TRUE(off.pixels == on.pixels) << "a plane alone shadows itself (acne), sun " << toSun.y;
        EXPECT_TRUE(allFinite(on));
    }
    renderer::SceneDesc box = plane;
    box.meshes.push_back(lambert(renderer::makeBoxMesh({0.0, 1.0, 0.0}, {1.0, 1.0, 1.0})));
    renderer_->setScene(box);
    PresetState night = sunOnly(glm::normalize(glm::dvec3(0.6, -0.2, 0.35)));
    night.sunLight.illuminance = glm::dvec3(0.5);  // below the horizon, yet not dark: still no shadows
    const Image off = render(camera, night, sceneOnly(false));
    const Image on = render(camera, night, sceneOnly(true));
    EXPECT_FALSE(renderer_->stats().shadowMap.drawn);
    EXPECT_TRUE(off.pixels == on.pixels);
    EXPECT_EQ(renderer_->stats().wallMilliseconds.shadowMap, 0.0);
    EXPECT_TRUE(log.errors.empty());
}

TEST_F(Shadows, NoNanOrInfUnderExtremeSettings) {
    renderer::SceneDesc scene;
    scene.meshes.push_back(groundPlane());
    scene.meshes.push_back(lambert(renderer::makeBoxMesh({0.0, 1.0, 0.0}, {1.0, 1.0, 1.0})));
    scene.meshes.push_back(lambert(renderer::makeBoxMesh({30.0, 20.0, -80.0}, {5.0, 20.0, 5.0})));
    renderer_->setScene(scene);
    const Camera camera = makeCamera({-6.0, 8.0, 6.0}, {-0.5, 0.0, -0.3}, 500.0);
    struct Case {
        glm::dvec3 toSun;
        int resolution, cascades;
        double maxDistanceM, lambda;
    };
    const Case cases[] = {
        {{1.0, 1e-4, 0.0}, 2048, 3, 300.0, 0.7},   // grazing sun
        {{0.0, 1.0, 0.0}, 1, 9, 1e12, 2.0},        // zenith, clamped settings
        {{0.2, 0.5, -0.9}, 100000, 0, 0.0, -1.0},  // one cascade, 1 m
        {{0.2, 0.5, -0.9}, 512, 4, std::nan(""), std::nan("")},
    };
    for (const Case& c : cases) {
        FrameDesc frame = sceneOnly(true);
        frame.gpuTimers = true;
        frame.shadowMap.resolution = c.resolution;
        frame.shadowMap.cascades = c.cascades;
        frame.shadowMap.maxDistanceM = c.maxDistanceM;
        frame.shadowMap.splitLambda = c.lambda;
        const Image image = render(camera, sunOnly(glm::normalize(c.toSun)), frame);
        EXPECT_TRUE(allFinite(image)) << "sun y " << c.toSun.y << " cascades " << c.cascades;
        EXPECT_TRUE(renderer_->stats().shadowMap.drawn);
        EXPECT_GT(renderer_->stats().wallMilliseconds.shadowMap, 0.0);
    }
    EXPECT_TRUE(log.errors.empty());
}

}  // namespace
}  // namespace aerial::test
