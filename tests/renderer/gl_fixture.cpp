// gl_fixture.cpp — see gl_fixture.hpp.
#include "gl_fixture.hpp"

#include <aerial/renderer/scene.hpp>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

// Leaks inside Mesa's drivers (llvmpipe's JIT, the DRI loader) are not ours;
// LeakSanitizer reads these suppressions in an ASan build and ignores them
// otherwise.
extern "C" __attribute__((used)) const char* __lsan_default_suppressions() {
    return aerial::renderer::kMesaLeakSuppressions;
}

namespace aerial::test {

renderer::Camera makeCamera(const glm::dvec3& eye, const glm::dvec3& target, double farDistance,
                            double verticalFov) {
    renderer::Camera c;
    c.eye = eye;
    c.target = target;
    c.verticalFov = verticalFov;
    c.nearDistance = 0.1;
    c.farDistance = farDistance;
    c.aspect = double(kWidth) / kHeight;
    return c;
}

renderer::FrameDesc floatFrame() {
    renderer::FrameDesc f;
    f.width = kWidth;
    f.height = kHeight;
    f.precision = renderer::ColourPrecision::Float;
    f.stars = false;
    return f;
}

LightState light(const glm::dvec3& direction, const glm::dvec3& illuminanceSpace,
                 const glm::dvec3& illuminance) {
    LightState l;
    l.body.direction = direction;
    l.body.elevation = std::asin(std::clamp(direction.y / glm::length(direction), -1.0, 1.0));
    l.illuminanceSpace = illuminanceSpace;
    l.illuminance = illuminance;
    return l;
}

renderer::HeadlessContext* glContext(std::string& error) {
    // Never destroyed: tearing the context down at exit unloads Mesa's
    // driver (eglTerminate), after which LeakSanitizer cannot name the
    // library of Mesa's own allocations and its suppressions (above) miss.
    static renderer::HeadlessContext* context = nullptr;
    static std::string creationError;
    static bool tried = false;
    if (!tried) {
        tried = true;
        auto c = std::make_unique<renderer::HeadlessContext>();
        if (c->create()) {
            context = c.release();
            std::printf("[ renderer ] %s\n", context->rendererName().c_str());
        } else {
            creationError = c->error();
        }
    }
    if (!context) {
        error = creationError;
        return nullptr;
    }
    if (!context->makeCurrent()) {
        error = context->error();
        return nullptr;
    }
    return context;
}

renderer::Logger LogCapture::logger() {
    renderer::Logger l;
    l.userData = this;
    l.function = [](renderer::LogLevel level, const char* message, void* user) {
        auto* self = static_cast<LogCapture*>(user);
        if (level == renderer::LogLevel::Error) self->errors.emplace_back(message);
        if (level == renderer::LogLevel::Warning) self->warnings.emplace_back(message);
    };
    return l;
}

void GlTest::SetUp() {
    std::string error;
    ASSERT_NE(glContext(error), nullptr)
        << "cannot create a headless OpenGL 4.5 context through EGL (Mesa's surfaceless platform): " << error
        << "\nThe renderer tests need Mesa (libegl-mesa0, libgl1-mesa-dri); they do not skip.";
}

SkyPair solveSky(const AtmosphereParams& air, const glm::dvec3& sunDirection, const glm::dvec3& moonDirection,
                 int columns, int rows) {
    SkySolverDesc desc;
    desc.azimuthCount = columns;
    desc.elevationCount = rows;
    desc.layerCount = 16;
    desc.opticalDepthAngles = 32;
    SkySolver solver(desc);
    SkyPair pair;
    solver.solve(air, sunDirection);
    pair.sun = solver.table();
    solver.solve(air, moonDirection);
    pair.moon = solver.table();
    return pair;
}

void SkyRendererTest::SetUp() {
    GlTest::SetUp();
    if (HasFatalFailure()) return;
    struct Solved {
        glm::dvec3 sun, moon;
        SkyPair sky;
    };
    static std::vector<std::unique_ptr<Solved>> solved;
    sky_ = nullptr;
    for (const auto& s : solved) {
        if (s->sun == sunDirection_ && s->moon == moonDirection_) sky_ = &s->sky;
    }
    if (!sky_) {
        solved.push_back(std::make_unique<Solved>(Solved{
            sunDirection_, moonDirection_, solveSky(AtmosphereParams{}, sunDirection_, moonDirection_)}));
        sky_ = &solved.back()->sky;
    }
    renderer_ = std::make_unique<renderer::Renderer>(rendererDesc());
    ASSERT_TRUE(renderer_->valid()) << renderer_->error();
    renderer_->setSky(sky_->sun, sky_->moon);
}

FogComparison compareWithCpu(const renderer::Image& fogged, const renderer::Image& unfogged,
                             const renderer::Image& depth01, const renderer::Camera& camera,
                             const FogScene& scene, double floor) {
    FogComparison result;
    const renderer::CameraFrame frame = renderer::cameraFrame(camera);
    double sumT = 0.0;
    double sumS = 0.0;
    for (int y = 0; y < fogged.height; ++y) {
        for (int x = 0; x < fogged.width; ++x) {
            const double d01 = depth01.at(x, y, 0);
            const glm::dvec3 point =
                frame.eye + d01 * renderer::farRayAtPixel(frame, x, y, fogged.width, fogged.height);
            const FogQueryResult q = scene.query(frame.eye, point);
            double unfoggedMax = 0.0;
            double cpuMax = 0.0;
            double difference = 0.0;
            for (int c = 0; c < 3; ++c) {
                const double scene0 = unfogged.at(x, y, c);
                const double cpu = scene0 * q.transmittance[c] + q.inScatter[c];
                unfoggedMax = std::max(unfoggedMax, std::fabs(scene0));
                cpuMax = std::max(cpuMax, std::fabs(cpu));
                const double gpu = fogged.at(x, y, c);
                difference = std::max(difference, std::isfinite(gpu) ? std::fabs(gpu - cpu) : 1e30);
            }
            const double error = difference / std::max({unfoggedMax, cpuMax, floor});
            if (error > result.maxError) {
                result.maxError = error;
                result.worstX = x;
                result.worstY = y;
            }
            sumT += q.transmittance.x;
            sumS += std::max({q.inScatter.x, q.inScatter.y, q.inScatter.z});
        }
    }
    const double n = double(fogged.width) * fogged.height;
    result.meanTransmittance = sumT / n;
    result.meanInScatter = sumS / n;
    return result;
}

renderer::SceneDesc emissiveTestScene(const renderer::Camera& camera, double wallDepth) {
    const renderer::CameraFrame f = renderer::cameraFrame(camera);
    renderer::SceneDesc scene;
    const double half = wallDepth * 4.0;
    renderer::SceneMesh wall =
        renderer::makeQuadMesh(f.eye + f.forward * wallDepth - f.right * half - f.up * half,
                               f.right * (2 * half), f.up * (2 * half), glm::dvec3(0.0));
    wall.emission = {1.0, 0.8, 0.6};
    scene.meshes.push_back(wall);
    renderer::SceneMesh ground = renderer::makeQuadMesh({-4000.0, 0.0, 4000.0}, {8000.0, 0.0, 0.0},
                                                        {0.0, 0.0, -8000.0}, glm::dvec3(0.0));
    ground.emission = {0.3, 0.35, 0.25};
    scene.meshes.push_back(ground);
    renderer::SceneMesh box = renderer::makeBoxMesh(
        {15.0, 6.0, -70.0}, {5.0, 6.0, 3.0}, glm::angleAxis(0.6, glm::normalize(glm::dvec3(0.2, 1.0, 0.1))),
        glm::dvec3(0.0));
    box.emission = {0.9, 0.2, 0.1};
    scene.meshes.push_back(box);
    return scene;
}

renderer::Camera fogCamera(const glm::dvec3& eye, const glm::dvec3& target) {
    return makeCamera(eye, target, 1500.0, 1.1);
}

FogVolume testVolume(FogVolumeShape shape) {
    FogVolume v;
    v.shape = shape;
    v.position = {-5.0, 8.0, -60.0};
    v.rotation = glm::angleAxis(0.7, glm::normalize(glm::dvec3(0.3, 1.0, -0.4)));
    v.halfExtents = {25.0, 9.0, 14.0};
    v.density = 0.03;
    v.falloff = 0.08;
    v.gradientDirection = glm::normalize(glm::dvec3(0.4, 0.8, -0.45));
    v.gradientOffset = 2.5;
    return v;
}

void addTestCloudDeck(PresetState& air) {
    air.environment.clouds.coverage = 0.8;
    air.environment.clouds.bottomM = 1500.0;
    air.environment.clouds.thicknessM = 2000.0;
}

glm::dvec3 FogVsCpuTest::sunDirection() { return glm::normalize(glm::dvec3(0.5, 0.35, -0.8)); }
glm::dvec3 FogVsCpuTest::moonDirection() { return glm::normalize(glm::dvec3(-0.6, 0.2, 0.5)); }

PresetState FogVsCpuTest::baseFrame() const {
    PresetState air;
    air.sunLight = light(sun_, glm::dvec3(20.0), glm::dvec3(12.0, 10.0, 8.0));
    air.moonLight = light(moon_, glm::dvec3(0.05, 0.055, 0.06), glm::dvec3(0.03));
    air.environment.atmosphere.mieAnisotropy = 0.8;
    return air;
}

FogComparison FogVsCpuTest::renderAndCompare(const renderer::Camera& camera, const PresetState& air,
                                             double wallDepth) {
    renderer_->setScene(emissiveTestScene(camera, wallDepth));
    renderer::FrameDesc frame = floatFrame();
    frame.passes.sky = false;
    frame.passes.globalFog = frame.passes.volumes = frame.passes.emitters = false;
    renderer_->render(camera, air, frame);
    const renderer::Image unfogged = renderer_->readColour();
    frame.passes.globalFog = frame.passes.volumes = frame.passes.emitters = true;
    renderer_->render(camera, air, frame);
    const renderer::Image fogged = renderer_->readColour();
    const renderer::Image depth = renderer_->readLinearDepth();
    const FogScene scene(aerial::fogSceneDesc(air, sky_->sun, sky_->moon));
    return compareWithCpu(fogged, unfogged, depth, camera, scene);
}

}  // namespace aerial::test
