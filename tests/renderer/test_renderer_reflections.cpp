// test_renderer_reflections.cpp — the sky seen in a mirror against the CPU,
// every pixel of a polished metal plane (roughness 0.045, shading.glsl's
// least), with and without a cloud deck:
//   L = (F0 A + F90 B) mix(L_mirror(r), E_ground (0.5 + 0.5 r.y) / pi, 0.045)
//   L_mirror(r) = mix(L_sky(r), L_deck, c(r)),
//   c(r) = horizonCover + (skyCover - horizonCover) smoothstep(0, 0.5, r.y),
// with L_sky from core's skyRadiance on the same tables, the deck's L_deck,
// covers and E_ground from core's overcastLight, and Karis' environment BRDF
// fit (A, B) written out again here. No sun or moon reaches the ground (their
// illuminance there is 0), so the plane shows the sky and nothing else.
#include "gl_fixture.hpp"

#include <aerial/clouds.hpp>
#include <aerial/evaluate.hpp>
#include <aerial/renderer/scene.hpp>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace aerial::test {
namespace {

constexpr double kPiD = 3.14159265358979323846;
constexpr double kRoughness = 0.045;
constexpr double kTolerance = 1e-3;  // relative, as the sky pass against the CPU (measured 2e-5)

/// Karis 2014's analytic fit of the split-sum environment BRDF (A, B).
glm::dvec2 environmentBrdf(double roughness, double nv) {
    const double rx = -roughness + 1.0, ry = -0.0275 * roughness + 0.0425;
    const double rz = -0.572 * roughness + 1.04, rw = 0.022 * roughness - 0.04;
    const double a004 = std::min(rx * rx, std::exp2(-9.28 * nv)) * rx + ry;
    return {-1.04 * a004 + rz, 1.04 * a004 + rw};
}

double smoothstep(double a, double b, double x) {
    const double t = std::clamp((x - a) / (b - a), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

struct MirrorComparison {
    double maxError = 0.0;       ///< against the expected radiance with the deck
    double clearSkyError = 0.0;  ///< against the same without the deck in the mirror
    int pixels = 0;
};

class Reflections : public FogVsCpuTest {
protected:
    /// Renders the plane under `air` and compares every plane pixel.
    MirrorComparison run(const char* name, const PresetState& air) {
        const glm::dvec3 base(0.9, 0.8, 0.7);
        renderer::SceneMesh plane =
            renderer::makeQuadMesh({-2000.0, 0.0, 2000.0}, {4000.0, 0.0, 0.0}, {0.0, 0.0, -4000.0}, base);
        plane.metallic = 1.0;
        plane.roughness = kRoughness;
        plane.specularFactor = 1.0;
        renderer::SceneDesc scene;
        scene.meshes.push_back(plane);
        renderer_->setScene(scene);
        const renderer::Camera camera = fogCamera({0.0, 8.0, 0.0}, {0.0, 2.0, -40.0});
        renderer::FrameDesc frame = floatFrame();
        frame.passes.globalFog = frame.passes.volumes = frame.passes.emitters = false;
        renderer_->render(camera, air, frame);
        const renderer::Image image = renderer_->readColour();
        EXPECT_TRUE(log.errors.empty()) << log.errors.front();

        const OvercastLight overcast = overcastLight(air, sky_->sun, sky_->moon);
        const double g = air.environment.atmosphere.mieAnisotropy;
        const renderer::CameraFrame f = renderer::cameraFrame(camera);
        MirrorComparison result;
        for (int y = 0; y < image.height; ++y) {
            for (int x = 0; x < image.width; ++x) {
                const glm::dvec3 ray = renderer::farRayAtPixel(f, x, y, image.width, image.height);
                if (!(ray.y < -0.02 * glm::length(ray))) continue;
                const glm::dvec3 p = f.eye + (-f.eye.y / ray.y) * ray;
                if (glm::length(p - f.eye) > 1500.0) continue;
                const glm::dvec3 v = glm::normalize(f.eye - p);
                const glm::dvec3 r(-v.x, v.y, -v.z);  // reflect(-v, up)
                const glm::dvec3 clear = skyRadiance(sky_->sun, g, r, air.sunLight.illuminanceSpace) +
                                         skyRadiance(sky_->moon, g, r, air.moonLight.illuminanceSpace);
                const CloudOvercast& o = overcast.overcast;
                const double c = o.horizonCover + (o.skyCover - o.horizonCover) * smoothstep(0.0, 0.5, r.y);
                const glm::dvec3 diffuseSky = overcast.groundIrradiance * (0.5 + 0.5 * r.y) / kPiD;
                const glm::dvec2 ab = environmentBrdf(kRoughness, std::clamp(v.y, 1e-4, 1.0));
                const glm::dvec3 weight = base * ab.x + ab.y;
                auto shade = [&](const glm::dvec3& mirrored) {
                    return weight * glm::mix(mirrored, diffuseSky, kRoughness);
                };
                const glm::dvec3 expected = shade(glm::mix(clear, overcast.radiance, c));
                const glm::dvec3 withoutDeck = shade(clear);
                double e = 0.0, eClear = 0.0;
                for (int k = 0; k < 3; ++k) {
                    const double gpu = image.at(x, y, k);
                    e = std::max(e, std::fabs(gpu - expected[k]) / std::max(expected[k], 1e-4));
                    eClear =
                        std::max(eClear, std::fabs(gpu - withoutDeck[k]) / std::max(withoutDeck[k], 1e-4));
                }
                result.maxError = std::max(result.maxError, std::isfinite(e) ? e : 1e30);
                result.clearSkyError = std::max(result.clearSkyError, eClear);
                ++result.pixels;
            }
        }
        std::printf(
            "[ measured ] %-24s max relative error %.3g over %d pixels (%.3g against the clear sky "
            "alone); sky cover %.3f, horizon cover %.3f\n",
            name, result.maxError, result.pixels, result.clearSkyError, overcast.overcast.skyCover,
            overcast.overcast.horizonCover);
        EXPECT_GT(result.pixels, image.width * image.height / 4) << name;
        return result;
    }

    /// baseFrame with no light reaching the ground: only the sky shines.
    PresetState skyOnly() const {
        PresetState air = baseFrame();
        air.sunLight.illuminance = glm::dvec3(0.0);
        air.moonLight.illuminance = glm::dvec3(0.0);
        return air;
    }
};

TEST_F(Reflections, AMirrorShowsTheClearSky) {
    const MirrorComparison c = run("clear sky in a mirror", skyOnly());
    EXPECT_LT(c.maxError, kTolerance);
}

// Under the deck a mirror shows its underside, not the clear sky's blue.
TEST_F(Reflections, AMirrorShowsTheDeckUnderAnOvercast) {
    PresetState air = skyOnly();
    addTestCloudDeck(air);
    const MirrorComparison c = run("overcast in a mirror", air);
    EXPECT_LT(c.maxError, kTolerance);
    EXPECT_GT(c.clearSkyError, 20.0 * kTolerance);  // the deck's part is there and seen
}

}  // namespace
}  // namespace aerial::test
