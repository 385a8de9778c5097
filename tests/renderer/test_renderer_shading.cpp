// test_renderer_shading.cpp — the scene pass's materials against closed
// forms computed here in double precision, every pixel of a known plane:
//   - a Lambert plane (specular factor 0) lit by point emitters:
//     L = albedo / pi * sum colour i max(n.l, 0) / (1 + a r^2), plus the
//     emitters' in-scatter along the view ray from core's FogScene;
//   - the glTF metallic-roughness BRDF (GGX, height-correlated Smith,
//     Schlick; glTF 2.0 specification, appendix B) under a sun, for a metal
//     and a dielectric, written out again here;
//   - the base-colour texture: sRGB-decoded (IEC 61966-2-1 curve), oriented
//     as glTF (uv (0, 0) = the image's top-left), and mipmapped in linear
//     light (a minified black/white checker averages to 0.5, not to the
//     sRGB-space average 0.214);
//   - alpha mask: fragments below the cutoff leave colour and depth alone.
// Pixels are located by intersecting each pixel's ray with the plane
// analytically (not from the GPU's depth). No sky is set, so the sky
// ambient and sky reflections are zero and only the named lights shine.
#include "gl_fixture.hpp"

#include <aerial/exposure.hpp>
#include <aerial/renderer/scene.hpp>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

namespace aerial::test {
namespace {

using renderer::Camera;
using renderer::FrameDesc;
using renderer::Renderer;

constexpr double kPiD = 3.14159265358979323846;

Camera groundCamera() { return makeCamera({0.0, 6.0, 12.0}, {0.0, 0.0, -10.0}, 500.0); }

FrameDesc sceneOnly() {
    FrameDesc f = floatFrame();
    f.passes.sky = false;
    f.passes.globalFog = false;
    f.passes.volumes = false;
    return f;
}

renderer::SceneMesh groundPlane(const glm::dvec3& albedo) {
    return renderer::makeQuadMesh({-400.0, 0.0, 400.0}, {800.0, 0.0, 0.0}, {0.0, 0.0, -800.0}, albedo);
}

/// The point where pixel (x, y)'s ray meets y = 0, or false (ray upwards or
/// too grazing to resolve).
bool groundPoint(const renderer::CameraFrame& f, int x, int y, glm::dvec3& p) {
    const glm::dvec3 ray = renderer::farRayAtPixel(f, x, y, kWidth, kHeight);
    if (!(ray.y < -0.02 * glm::length(ray))) return false;
    const double t = -f.eye.y / ray.y;
    if (t > 0.9) return false;
    p = f.eye + t * ray;
    return true;
}

double srgbDecode(int c) {
    const double v = c / 255.0;
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

/// glTF 2.0 appendix B BRDF times n.l, in double (see shading.glsl).
glm::dvec3 gltfBrdfCos(const glm::dvec3& n, const glm::dvec3& v, const glm::dvec3& l, const glm::dvec3& base,
                       double metallic, double roughness, double specular) {
    const double nl = glm::dot(n, l);
    if (nl <= 0.0) return glm::dvec3(0.0);
    const double nv = std::max(glm::dot(n, v), 1e-4);
    const glm::dvec3 h = glm::normalize(l + v);
    const double vh = glm::dot(v, h);
    const double nh = glm::dot(n, h);
    const double alpha = roughness * roughness;
    const double a2 = alpha * alpha;
    const glm::dvec3 f0 = glm::mix(glm::dvec3(0.04 * specular), base, metallic);
    const glm::dvec3 f90(specular + (1.0 - specular) * metallic);
    const glm::dvec3 fresnel = f0 + (f90 - f0) * std::pow(1.0 - vh, 5.0);
    const double d = a2 / (kPiD * std::pow(nh * nh * (a2 - 1.0) + 1.0, 2.0));
    const double vis =
        0.5 / (nl * std::sqrt(nv * nv * (1.0 - a2) + a2) + nv * std::sqrt(nl * nl * (1.0 - a2) + a2));
    const glm::dvec3 diffuse = (glm::dvec3(1.0) - fresnel) * base * (1.0 - metallic) / kPiD;
    return (diffuse + fresnel * d * vis) * nl;
}

struct Worst {
    double error = 0.0;
    int x = 0, y = 0;
    int pixels = 0;
    void add(double e, int px, int py) {
        ++pixels;
        if (e > error) {
            error = e;
            x = px;
            y = py;
        }
    }
};

class Shading : public GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();
        if (HasFatalFailure()) return;
        renderer_ = std::make_unique<Renderer>(rendererDesc());
        ASSERT_TRUE(renderer_->valid()) << renderer_->error();
    }
    std::unique_ptr<Renderer> renderer_;
};

TEST_F(Shading, EmittersLightALambertPlaneAsTheClosedForm) {
    renderer::SceneMesh ground = groundPlane({0.6, 0.5, 0.4});
    ground.specularFactor = 0.0;  // pure Lambert
    renderer::SceneDesc scene;
    scene.meshes.push_back(ground);
    renderer_->setScene(scene);
    PresetState air;  // no sun, no moon
    air.sunLight.illuminance = air.moonLight.illuminance = glm::dvec3(0.0);
    Emitter a;
    a.position = {2.0, 3.0, -8.0};
    a.intensityCd = 6.0e5;  // surfaces: E = I / (1/a + r^2) lx (emitter.hpp, "Photometry")
    a.attenuation = 0.3;
    a.colour = {1.0, 0.7, 0.4};
    Emitter b;
    b.position = {-5.0, 1.5, -16.0};
    b.intensityCd = 1.2e6;
    b.attenuation = 0.05;
    b.colour = {0.3, 0.6, 1.0};
    air.emitters = {a, b};
    const Camera camera = groundCamera();
    renderer_->render(camera, air, sceneOnly());
    const renderer::Image image = renderer_->readColour();

    FogSceneDesc emittersOnly;
    emittersOnly.heightFog.density = 0.0;
    emittersOnly.emitters = air.emitters;
    const FogScene fog(emittersOnly);
    const renderer::CameraFrame f = renderer::cameraFrame(camera);
    Worst worst;
    double brightest = 0.0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            glm::dvec3 p;
            if (!groundPoint(f, x, y, p)) continue;
            glm::dvec3 irradiance(0.0);
            for (const Emitter& e : air.emitters) {
                const glm::dvec3 toLight = e.position - p;
                const double r2 = glm::dot(toLight, toLight);
                // The inverse-square law over the core, in lx, then in the
                // renderer's illuminance unit.
                const double lux = e.intensityCd / (1.0 / e.attenuation + r2);
                irradiance += e.colour * (lux / aerial::kNitsPerRadianceUnit) *
                              std::max(toLight.y / std::sqrt(r2), 0.0);
            }
            const glm::dvec3 expected =
                glm::dvec3(0.6, 0.5, 0.4) / kPiD * irradiance + fog.query(f.eye, p).inScatter;
            double e = 0.0;
            for (int c = 0; c < 3; ++c) {
                e = std::max(e, std::fabs(image.at(x, y, c) - expected[c]) / std::max({expected[c], 1e-3}));
                brightest = std::max(brightest, expected[c]);
            }
            worst.add(e, x, y);
        }
    }
    std::printf(
        "[ measured ] Lambert plane under 2 emitters: max relative error %.3g (pixel %d,%d) over %d px, "
        "brightest %.3g\n",
        worst.error, worst.x, worst.y, worst.pixels, brightest);
    EXPECT_GT(worst.pixels, kWidth * kHeight / 3);
    EXPECT_GT(brightest, 0.5);  // the lights reach the plane
    EXPECT_LE(worst.error, 1e-3);
    EXPECT_TRUE(log.errors.empty());
}

TEST_F(Shading, SunOnMetalAndDielectricMatchesTheGltfBrdf) {
    const glm::dvec3 sun = glm::normalize(glm::dvec3(0.3, 0.45, -0.8));  // low, ahead: a visible highlight
    const glm::dvec3 sunIlluminance(3.0, 2.8, 2.5);
    struct Material {
        const char* name;
        glm::dvec3 base;
        double metallic, roughness, specular;
    };
    const Material materials[] = {{"gold-like metal, roughness 0.35", {1.0, 0.78, 0.34}, 1.0, 0.35, 1.0},
                                  {"dielectric, roughness 0.6", {0.2, 0.4, 0.15}, 0.0, 0.6, 1.0},
                                  {"half metal, roughness 0.2", {0.9, 0.9, 0.9}, 0.5, 0.2, 0.7}};
    const Camera camera = groundCamera();
    const renderer::CameraFrame f = renderer::cameraFrame(camera);
    for (const Material& m : materials) {
        renderer::SceneMesh ground = groundPlane(m.base);
        ground.metallic = m.metallic;
        ground.roughness = m.roughness;
        ground.specularFactor = m.specular;
        renderer::SceneDesc scene;
        scene.meshes.push_back(ground);
        renderer_->setScene(scene);
        PresetState air;
        air.sunLight = light(sun, glm::dvec3(0.0), sunIlluminance);
        air.moonLight.illuminance = glm::dvec3(0.0);
        renderer_->render(camera, air, sceneOnly());
        const renderer::Image image = renderer_->readColour();
        Worst worst;
        double peak = 0.0;
        for (int y = 0; y < kHeight; ++y) {
            for (int x = 0; x < kWidth; ++x) {
                glm::dvec3 p;
                if (!groundPoint(f, x, y, p)) continue;
                const glm::dvec3 v = glm::normalize(f.eye - p);
                const glm::dvec3 expected =
                    gltfBrdfCos({0.0, 1.0, 0.0}, v, sun, m.base, m.metallic, m.roughness, m.specular) *
                    sunIlluminance;
                double e = 0.0;
                for (int c = 0; c < 3; ++c) {
                    e = std::max(e, std::fabs(image.at(x, y, c) - expected[c]) / std::max(expected[c], 1e-3));
                    peak = std::max(peak, expected[c]);
                }
                worst.add(e, x, y);
            }
        }
        std::printf("[ measured ] %-32s max relative error %.3g (pixel %d,%d), peak radiance %.3g\n", m.name,
                    worst.error, worst.x, worst.y, peak);
        EXPECT_GT(worst.pixels, kWidth * kHeight / 3);
        EXPECT_LE(worst.error, 2e-3) << m.name;
    }
    EXPECT_TRUE(log.errors.empty());
}

/// A quad facing the camera at eye depth `depth`, `half` metres wide each way,
/// its image upright (edgeU = right, edgeV = up).
renderer::SceneMesh facingQuad(const renderer::CameraFrame& f, double depth, double half) {
    const glm::dvec3 centre = f.eye + f.forward * depth;
    return renderer::makeQuadMesh(centre - f.right * half - f.up * half, f.right * (2 * half),
                                  f.up * (2 * half));
}

/// Where pixel (x, y) meets the facing quad, as the quad's (u, v) texture
/// coordinates (image top at v = 0); false when it misses.
bool quadTexcoord(const renderer::CameraFrame& f, double depth, double half, int x, int y, double& u,
                  double& v) {
    const glm::dvec3 ray = renderer::farRayAtPixel(f, x, y, kWidth, kHeight);
    const glm::dvec3 p = f.eye + ray * (depth / glm::dot(ray, f.forward));
    const glm::dvec3 local = p - (f.eye + f.forward * depth);
    u = (glm::dot(local, f.right) + half) / (2 * half);
    v = 1.0 - (glm::dot(local, f.up) + half) / (2 * half);
    return u >= 0.0 && u <= 1.0 && v >= 0.0 && v <= 1.0;
}

Camera frontCamera() { return makeCamera({0.0, 0.0, 0.0}, {0.0, 0.0, -1.0}, 1000.0, 0.8); }

TEST_F(Shading, BaseColourTextureIsSrgbDecodedOrientedAndMipmapped) {
    // 4 x 4 texels in 2 x 2 blocks: top-left red 255, top-right green 128,
    // bottom-left blue 64 (alpha 255), bottom-right grey 200.
    const int block[4][3] = {{255, 0, 0}, {0, 128, 0}, {0, 0, 64}, {200, 200, 200}};
    auto texture = std::make_shared<renderer::SceneTexture>();
    texture->width = texture->height = 4;
    for (int y = 0; y < 4; ++y) {
        for (int x = 0; x < 4; ++x) {
            const int* c = block[(y / 2) * 2 + x / 2];
            texture->rgba.insert(texture->rgba.end(),
                                 {std::uint8_t(c[0]), std::uint8_t(c[1]), std::uint8_t(c[2]), 255});
        }
    }
    // A 256 x 256 one-texel black/white checker, seen minified (~24 px).
    auto checker = std::make_shared<renderer::SceneTexture>();
    checker->width = checker->height = 256;
    for (int y = 0; y < 256; ++y) {
        for (int x = 0; x < 256; ++x) {
            const std::uint8_t g = ((x + y) & 1) ? 255 : 0;
            checker->rgba.insert(checker->rgba.end(), {g, g, g, 255});
        }
    }
    const Camera camera = frontCamera();
    const renderer::CameraFrame f = renderer::cameraFrame(camera);
    const double kDepth = 10.0, kHalf = 3.0;
    renderer::SceneMesh quad = facingQuad(f, kDepth, kHalf);
    quad.albedo = {0.9, 0.8, 1.0};
    quad.specularFactor = 0.0;
    quad.baseColorTexture = texture;
    // The far checker: 180 m wide at 600 m (~34 px, ~7.5 texels per pixel),
    // left of the near quad.
    renderer::SceneMesh far =
        renderer::makeQuadMesh(f.eye + f.forward * 600.0 - f.right * 380.0 - f.up * 90.0, f.right * 180.0,
                               f.up * 180.0, glm::dvec3(1.0));
    far.specularFactor = 0.0;
    far.baseColorTexture = checker;
    renderer::SceneDesc scene;
    scene.meshes = {quad, far};
    renderer_->setScene(scene);
    // The sun straight along the view, so n.l = 1 on both quads.
    PresetState air;
    const double e = 2.0;
    air.sunLight = light(-f.forward, glm::dvec3(0.0), glm::dvec3(e));
    air.moonLight.illuminance = glm::dvec3(0.0);
    renderer_->render(camera, air, sceneOnly());
    const renderer::Image image = renderer_->readColour();

    Worst worst;
    int perBlock[4] = {};
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            double u, v;
            if (!quadTexcoord(f, kDepth, kHalf, x, y, u, v)) continue;
            // Inside a block, away from the bilinear blend between blocks.
            const double bu = std::fmod(u * 2.0, 1.0), bv = std::fmod(v * 2.0, 1.0);
            if (bu < 0.27 || bu > 0.73 || bv < 0.27 || bv > 0.73) continue;
            const int b = (v < 0.5 ? 0 : 2) + (u < 0.5 ? 0 : 1);
            ++perBlock[b];
            // Relative to the pixel's brightest channel (two channels are 0).
            double err = 0.0, brightest = 0.0;
            for (int c = 0; c < 3; ++c)
                brightest = std::max(brightest, quad.albedo[c] * srgbDecode(block[b][c]) / kPiD * e);
            for (int c = 0; c < 3; ++c) {
                const double expected = quad.albedo[c] * srgbDecode(block[b][c]) / kPiD * e;
                err = std::max(err, std::fabs(image.at(x, y, c) - expected) / brightest);
            }
            worst.add(err, x, y);
        }
    }
    std::printf("[ measured ] sRGB texture, 4 blocks: max relative error %.3g (pixel %d,%d) over %d px\n",
                worst.error, worst.x, worst.y, worst.pixels);
    for (int b = 0; b < 4; ++b) EXPECT_GT(perBlock[b], 20) << "block " << b;
    // 1e-2: llvmpipe converts sRGB to linear with a polynomial, not a table
    // (4.5e-3 relative measured at sRGB 64); an undecoded texture would be
    // off by a factor 2.3 (sRGB 128) to 4.9 (sRGB 64).
    EXPECT_LE(worst.error, 1e-2);

    // The far checker: its pixels average to the linear mean 0.5 (x albedo / pi x E).
    double sum = 0.0, maxDev = 0.0;
    int count = 0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const glm::dvec3 ray = renderer::farRayAtPixel(f, x, y, kWidth, kHeight);
            const glm::dvec3 p = f.eye + ray * (600.0 / glm::dot(ray, f.forward));
            const double s = glm::dot(p - (f.eye + f.forward * 600.0), f.right) + 380.0;
            const double t = glm::dot(p - (f.eye + f.forward * 600.0), f.up) + 90.0;
            if (s < 15.0 || s > 165.0 || t < 15.0 || t > 165.0) continue;  // interior only
            const double reflectance = image.at(x, y, 1) * kPiD / e;
            sum += reflectance;
            maxDev = std::max(maxDev, std::fabs(reflectance - 0.5));
            ++count;
        }
    }
    ASSERT_GT(count, 100);
    std::printf(
        "[ measured ] minified checker: mean reflectance %.4f (linear mean 0.5; sRGB-space mipmaps "
        "would give 0.214), max deviation %.3g over %d px\n",
        sum / count, maxDev, count);
    EXPECT_NEAR(sum / count, 0.5, 0.02);
    EXPECT_LE(maxDev, 0.05);  // no aliasing: every pixel is grey
    EXPECT_TRUE(log.errors.empty());
}

TEST_F(Shading, AlphaMaskDiscardsColourAndDepthBelowTheCutoff) {
    // Left half of the texture alpha 0, right half alpha 255 (white).
    auto texture = std::make_shared<renderer::SceneTexture>();
    texture->width = texture->height = 8;
    for (int y = 0; y < 8; ++y) {
        for (int x = 0; x < 8; ++x)
            texture->rgba.insert(texture->rgba.end(), {255, 255, 255, std::uint8_t(x < 4 ? 0 : 255)});
    }
    const Camera camera = frontCamera();
    const renderer::CameraFrame f = renderer::cameraFrame(camera);
    const double kDepth = 10.0, kHalf = 3.0;
    renderer::SceneMesh masked = facingQuad(f, kDepth, kHalf);
    masked.albedo = glm::dvec3(0.0);
    masked.specularFactor = 0.0;
    masked.emission = {0.0, 1.0, 0.0};
    masked.baseColorTexture = texture;
    masked.alphaMode = renderer::AlphaMode::Mask;
    masked.alphaCutoff = 0.5;
    renderer::SceneMesh wall = facingQuad(f, 50.0, 100.0);
    wall.albedo = glm::dvec3(0.0);
    wall.specularFactor = 0.0;
    wall.emission = {1.0, 0.0, 0.0};
    for (double opacity : {1.0, 0.4}) {  // 0.4 x 1 < 0.5: everything masked
        masked.opacity = opacity;
        renderer::SceneDesc scene;
        scene.meshes = {masked, wall};
        renderer_->setScene(scene);
        PresetState air;
        air.sunLight.illuminance = air.moonLight.illuminance = glm::dvec3(0.0);
        renderer_->render(camera, air, sceneOnly());
        const renderer::Image image = renderer_->readColour();
        const renderer::Image depth = renderer_->readLinearDepth();
        int checked = 0;
        double worst = 0.0;
        for (int y = 0; y < kHeight; ++y) {
            for (int x = 0; x < kWidth; ++x) {
                double u, v;
                const bool onQuad = quadTexcoord(f, kDepth, kHalf, x, y, u, v);
                // The alpha edge blends bilinearly (also across the repeat wrap at u = 0, 1).
                if (onQuad && (std::fabs(u - 0.5) < 0.1 || u < 0.1 || u > 0.9)) continue;
                const bool kept = onQuad && u > 0.5 && opacity > 0.5;
                const double expectedDepth = (kept ? kDepth : 50.0) / camera.farDistance;
                const glm::dvec3 expectedColour = kept ? masked.emission : wall.emission;
                double e = std::fabs(depth.at(x, y, 0) - expectedDepth) / expectedDepth;
                for (int c = 0; c < 3; ++c) e = std::max(e, std::fabs(image.at(x, y, c) - expectedColour[c]));
                worst = std::max(worst, e);
                ++checked;
            }
        }
        std::printf("[ measured ] alpha mask, opacity %.1f: max error %.3g over %d px\n", opacity, worst,
                    checked);
        EXPECT_GT(checked, kWidth * kHeight / 2);
        EXPECT_LE(worst, 1e-4) << "opacity " << opacity;
    }
    EXPECT_TRUE(log.errors.empty());
}

}  // namespace
}  // namespace aerial::test
