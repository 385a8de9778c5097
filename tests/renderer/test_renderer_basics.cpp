// test_renderer_basics.cpp — the renderer's foundation on llvmpipe: the
// headless context, embedded shaders, linear depth and world positions from
// the far-plane corner rays (known planes), GL state restored, shader hot
// reload keeping the last good program, EXR/PNG capture.
#include "gl_fixture.hpp"

#include <aerial/renderer/image.hpp>
#include <aerial/renderer/scene.hpp>

#include <epoxy/gl.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

namespace aerial::test {
namespace {

using renderer::Camera;
using renderer::FrameDesc;
using renderer::Renderer;

Camera testCamera() { return makeCamera({0.0, 20.0, 0.0}, {0.0, 12.0, -100.0}, 2000.0); }

/// A quad perpendicular to the view at eye depth `depth`, covering the view.
renderer::SceneMesh facingPlane(const Camera& camera, double depth, const glm::dvec3& emission) {
    const renderer::CameraFrame f = renderer::cameraFrame(camera);
    const double half = depth * 4.0;
    const glm::dvec3 centre = f.eye + f.forward * depth;
    renderer::SceneMesh m = renderer::makeQuadMesh(centre - f.right * half - f.up * half,
                                                   f.right * (2 * half), f.up * (2 * half), glm::dvec3(0.0));
    m.emission = emission;
    return m;
}

TEST_F(GlTest, ContextIsOpenGl45Core) {
    std::string error;
    renderer::HeadlessContext* context = glContext(error);
    ASSERT_NE(context, nullptr);
    EXPECT_FALSE(context->rendererName().empty());
    GLint major = 0, minor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    EXPECT_GE(major * 10 + minor, 45);
}

TEST_F(GlTest, EmbeddedShadersBuild) {
    Renderer r(rendererDesc());
    EXPECT_TRUE(r.valid()) << r.error();
    EXPECT_TRUE(log.errors.empty()) << log.errors.front();
}

TEST_F(GlTest, LinearDepthAndWorldPositionsOfKnownPlanes) {
    Renderer r(rendererDesc());
    ASSERT_TRUE(r.valid()) << r.error();
    const Camera camera = testCamera();
    // A facing plane at 300 m and the ground y = 0 in front of it.
    renderer::SceneDesc scene;
    scene.meshes.push_back(facingPlane(camera, 300.0, glm::dvec3(1.0)));
    renderer::SceneMesh ground = renderer::makeQuadMesh({-5000.0, 0.0, 5000.0}, {10000.0, 0.0, 0.0},
                                                        {0.0, 0.0, -10000.0}, glm::dvec3(0.0));
    scene.meshes.push_back(ground);
    r.setScene(scene);
    FrameDesc frame = floatFrame();
    frame.passes.sky = false;
    r.render(camera, PresetState{}, frame);
    const renderer::Image depth = r.readLinearDepth();
    ASSERT_EQ(depth.width, kWidth);
    const renderer::CameraFrame f = renderer::cameraFrame(camera);
    double worst = 0.0;  // [m], world-position error
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const glm::dvec3 ray = renderer::farRayAtPixel(f, x, y, kWidth, kHeight);
            // Expected: the nearer of the plane (depth01 = 300 / far) and the ground.
            double t = 300.0 / camera.farDistance;
            if (ray.y < 0.0) t = std::min(t, -camera.eye.y / ray.y);
            const glm::dvec3 expected = f.eye + t * ray;
            const glm::dvec3 got = f.eye + double(depth.at(x, y, 0)) * ray;
            // Pixels on the plane / ground silhouette may go either way.
            const double tPlane = 300.0 / camera.farDistance;
            const double tGround = ray.y < 0.0 ? -camera.eye.y / ray.y : 1e9;
            if (std::fabs(tPlane - tGround) < 0.02 * tPlane) continue;
            worst = std::max(worst, glm::length(got - expected));
        }
    }
    std::printf("[ measured ] world position from linear depth: max error %.3g m (plane at 300 m)\n", worst);
    EXPECT_LT(worst, 1e-3 * 300.0 * 1e-1);  // 3 cm at 300 m: float depth and interpolation only
    EXPECT_TRUE(log.errors.empty());
}

TEST_F(GlTest, RestoresTheGlStateItTouches) {
    Renderer r(rendererDesc());
    ASSERT_TRUE(r.valid());
    r.setScene(renderer::makeBuiltinScene());
    GLuint fbo = 0, tex = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &tex);
    glTextureStorage2D(tex, 1, GL_RGBA8, 8, 8);
    glCreateFramebuffers(1, &fbo);
    glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0, tex, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glViewport(1, 2, 3, 4);
    glEnable(GL_BLEND);
    glBlendFunc(GL_DST_COLOR, GL_ZERO);
    glEnable(GL_SCISSOR_TEST);
    glDepthMask(GL_FALSE);
    glActiveTexture(GL_TEXTURE3);
    glBindTextureUnit(4, tex);

    // The caller's debug callback survives (the renderer routes GL debug
    // output to its logger only while it works).
    const GLDEBUGPROC callerCallback = [](GLenum, GLenum, GLuint, GLenum, GLsizei, const GLchar*,
                                          const void*) {};
    int callerTag = 7;
    glDebugMessageCallback(callerCallback, &callerTag);

    r.render(testCamera(), PresetState{}, floatFrame());

    void* callback = nullptr;
    void* userParam = nullptr;
    glGetPointerv(GL_DEBUG_CALLBACK_FUNCTION, &callback);
    glGetPointerv(GL_DEBUG_CALLBACK_USER_PARAM, &userParam);
    EXPECT_EQ(callback, reinterpret_cast<void*>(callerCallback));
    EXPECT_EQ(userParam, &callerTag);
    glDebugMessageCallback(nullptr, nullptr);

    GLint value = 0;
    GLint viewport[4] = {};
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &value);
    EXPECT_EQ(GLuint(value), fbo);
    glGetIntegerv(GL_VIEWPORT, viewport);
    EXPECT_EQ(viewport[0], 1);
    EXPECT_EQ(viewport[3], 4);
    EXPECT_TRUE(glIsEnabled(GL_BLEND));
    EXPECT_TRUE(glIsEnabled(GL_SCISSOR_TEST));
    EXPECT_FALSE(glIsEnabled(GL_DEPTH_TEST));
    glGetIntegerv(GL_BLEND_SRC_RGB, &value);
    EXPECT_EQ(value, GL_DST_COLOR);
    GLboolean mask = GL_TRUE;
    glGetBooleanv(GL_DEPTH_WRITEMASK, &mask);
    EXPECT_EQ(mask, GL_FALSE);
    glGetIntegerv(GL_ACTIVE_TEXTURE, &value);
    EXPECT_EQ(value, GL_TEXTURE3);
    glActiveTexture(GL_TEXTURE4);
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &value);
    EXPECT_EQ(GLuint(value), tex);
    glGetIntegerv(GL_CURRENT_PROGRAM, &value);
    EXPECT_EQ(value, 0);

    // Back to the defaults for the other tests.
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDisable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ZERO);
    glDisable(GL_SCISSOR_TEST);
    glDepthMask(GL_TRUE);
    glBindTextureUnit(4, 0);
    glActiveTexture(GL_TEXTURE0);
    glDeleteFramebuffers(1, &fbo);
    glDeleteTextures(1, &tex);
    EXPECT_TRUE(log.errors.empty());
}

TEST_F(GlTest, DegenerateInputsGiveFinitePixelsAndNoGlErrors) {
    Renderer r(rendererDesc());
    ASSERT_TRUE(r.valid());
    r.setScene(renderer::makeBuiltinScene());
    const double nan = std::nan("");
    const double inf = std::numeric_limits<double>::infinity();
    Camera camera = testCamera();
    camera.target = camera.eye;  // looks along -Z
    camera.verticalFov = 0.0;    // clamped
    camera.up = {0.0, 0.0, 0.0};
    PresetState air;
    air.sunLight = light({nan, 1.0, 0.0}, {inf, 1.0, 1.0}, {1.0, nan, 1.0});
    air.environment.fog = {inf, nan, 1e300};
    air.environment.atmosphere.mieAnisotropy = nan;
    FogVolume v;
    v.halfExtents = {0.0, 1.0, 1.0};  // degenerate: skipped
    air.volumes.push_back(v);
    v.halfExtents = {10.0, 10.0, 10.0};
    v.density = inf;
    v.falloff = nan;
    v.gradientDirection = {0.0, 0.0, 0.0};
    v.position = camera.eye;
    air.volumes.push_back(v);
    Emitter e;
    e.position = {nan, 0.0, 0.0};
    air.emitters.push_back(e);
    e.position = {0.0, 10.0, -20.0};
    e.intensity = inf;
    e.attenuation = -1.0;
    air.emitters.push_back(e);
    r.render(camera, air, floatFrame());
    const renderer::Image image = r.readColour();
    int bad = 0;
    for (float p : image.pixels) bad += std::isfinite(p) ? 0 : 1;
    EXPECT_EQ(bad, 0);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    EXPECT_EQ(r.stats().glErrors, 0);
    EXPECT_TRUE(log.errors.empty());
}

std::string readText(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

TEST_F(GlTest, HotReloadKeepsTheLastGoodProgramAndReturnsTheLog) {
    namespace fs = std::filesystem;
    const fs::path source = renderer::defaultShaderDirectory();
    const fs::path copy = fs::temp_directory_path() / ("aerial_shaders_" + std::to_string(::getpid()));
    fs::remove_all(copy);
    fs::copy(source, copy, fs::copy_options::recursive);

    Renderer r(rendererDesc());
    ASSERT_TRUE(r.valid());
    const Camera camera = testCamera();
    renderer::SceneDesc scene;
    scene.meshes.push_back(facingPlane(camera, 200.0, glm::dvec3(0.5, 0.25, 0.125)));
    r.setScene(scene);
    PresetState air;
    air.environment.fog.density = 0.005;
    air.environment.fogColourMode = FogColourMode::Custom;
    air.environment.fogColour = {1.0, 1.0, 1.0};
    r.render(camera, air, floatFrame());
    const renderer::Image before = r.readColour();

    // A good reload from the copy: identical image.
    renderer::ShaderReloadResult ok = r.reloadShaders(copy.string());
    EXPECT_TRUE(ok.ok) << ok.log;
    EXPECT_TRUE(ok.log.empty());

    // Break the shared include: every pass fails, the log names the file.
    const fs::path atmosphere = copy / "common" / "atmosphere.glsl";
    const std::string good = readText(atmosphere);
    std::ofstream(atmosphere, std::ios::binary) << good << "\nthis is not glsl;\n";
    renderer::ShaderReloadResult bad = r.reloadShaders(copy.string());
    EXPECT_FALSE(bad.ok);
    EXPECT_NE(bad.log.find("common/atmosphere.glsl"), std::string::npos) << bad.log;
    EXPECT_FALSE(log.warnings.empty());
    r.render(camera, air, floatFrame());
    const renderer::Image during = r.readColour();
    EXPECT_EQ(during.pixels, before.pixels) << "the last good programs must keep rendering";

    // A missing include is reported too.
    std::ofstream(copy / "global_fog.glsl", std::ios::app) << "\n#include \"common/missing.glsl\"\n";
    renderer::ShaderReloadResult missing = r.reloadShaders(copy.string());
    EXPECT_FALSE(missing.ok);
    EXPECT_NE(missing.log.find("common/missing.glsl"), std::string::npos) << missing.log;

    // Fixed again.
    std::ofstream(atmosphere, std::ios::binary) << good;
    fs::copy_file(source / "global_fog.glsl", copy / "global_fog.glsl", fs::copy_options::overwrite_existing);
    renderer::ShaderReloadResult fixed = r.reloadShaders(copy.string());
    EXPECT_TRUE(fixed.ok) << fixed.log;
    r.render(camera, air, floatFrame());
    EXPECT_EQ(r.readColour().pixels, before.pixels);
    fs::remove_all(copy);
}

TEST_F(GlTest, CapturesExrAndPng) {
    namespace fs = std::filesystem;
    Renderer r(rendererDesc());
    ASSERT_TRUE(r.valid());
    r.setScene(renderer::makeBuiltinScene());
    FrameDesc frame = floatFrame();
    frame.precision = renderer::ColourPrecision::Half;
    r.render(testCamera(), PresetState{}, frame);
    const renderer::Image image = r.readColour();
    const fs::path dir = fs::temp_directory_path();
    const fs::path exr = dir / ("aerial_capture_" + std::to_string(::getpid()) + ".exr");
    const fs::path png = dir / ("aerial_capture_" + std::to_string(::getpid()) + ".png");
    std::string error;
    ASSERT_TRUE(renderer::writeExr(image, exr.string(), error)) << error;
    ASSERT_TRUE(renderer::writePng(image, png.string(), 1.0, error)) << error;
    const std::string exrBytes = readText(exr);
    const std::string pngBytes = readText(png);
    ASSERT_GE(exrBytes.size(), 4u);
    EXPECT_EQ(static_cast<unsigned char>(exrBytes[0]), 0x76);  // OpenEXR magic 20000630
    EXPECT_EQ(static_cast<unsigned char>(exrBytes[1]), 0x2f);
    EXPECT_EQ(static_cast<unsigned char>(exrBytes[2]), 0x31);
    EXPECT_EQ(static_cast<unsigned char>(exrBytes[3]), 0x01);
    ASSERT_GE(pngBytes.size(), 8u);
    EXPECT_EQ(pngBytes.substr(1, 3), "PNG");
    EXPECT_FALSE(renderer::writeExr(image, (dir / "no_such_dir" / "x.exr").string(), error));
    EXPECT_NE(error.find("no_such_dir"), std::string::npos);
    fs::remove(exr);
    fs::remove(png);
}

}  // namespace
}  // namespace aerial::test
