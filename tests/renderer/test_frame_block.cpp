// test_frame_block.cpp — makeFrameBlock (renderer/src/frame_block.hpp)
// without a GL context: the per-frame std140 block's fields against
// independent computations (camera corners projected back to the NDC
// corners, normalised light directions, disc chords and solid angles, the
// fog and star fields from the state), and the std140 offsets of the C++
// mirrors against the GLSL blocks, laid out here by the std140 rules from
// the shader sources themselves.
#include "frame_block.hpp"
#include "gpu_types.hpp"

#include <aerial/evaluate.hpp>
#include <aerial/exposure.hpp>
#include <aerial/night_sky.hpp>
#include <aerial/preset.hpp>
#include <aerial/renderer/renderer.hpp>
#include <aerial/stars.hpp>
#include <aerial/sun.hpp>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include <cmath>
#include <cstddef>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <string>

namespace aerial::test {
namespace {

using renderer::detail::CloudBlock;
using renderer::detail::FrameBlock;
using renderer::detail::FrameBlockInputs;
using renderer::detail::makeFrameBlock;
using renderer::detail::makeShadowBlock;
using renderer::detail::ObjectBlock;
using renderer::detail::ShadowBlock;
using renderer::detail::Vec3;
using renderer::detail::VolumeBlock;

constexpr double kPiD = 3.14159265358979323846;

glm::dvec3 d3(const Vec3& v) { return {v.x, v.y, v.z}; }

void expectNear3(const Vec3& got, const glm::dvec3& want, double tolerance, const char* what) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(d3(got)[c], want[c], tolerance) << what << " channel " << c;
}

renderer::Camera testCamera() {
    renderer::Camera c;
    c.eye = {3.0, 12.0, 40.0};
    c.target = {-5.0, 8.0, -60.0};
    c.verticalFov = 0.9;
    c.nearDistance = 0.25;
    c.farDistance = 2000.0;
    c.aspect = 2.0;
    return c;
}

/// A state with every field makeFrameBlock reads set by hand.
PresetState testState() {
    PresetState s;
    s.sunLight.body.direction = {0.0, 2.0, -2.0};  // not unit on purpose
    s.sunLight.body.elevation = kPiD / 4.0;
    s.sunLight.illuminanceSpace = {20.0, 19.0, 18.0};
    s.sunLight.illuminance = {10.0, -1.0, std::numeric_limits<double>::quiet_NaN()};  // sanitised to 0
    s.moonLight.body.direction = {-0.6, 0.2, 0.5};
    s.moonLight.illuminanceSpace = {0.05, 0.055, 0.06};
    s.moonLight.illuminance = {0.03, 0.03, 0.03};
    s.environment.atmosphere.mieAnisotropy = 0.9995;  // clamped to 0.999
    s.environment.fog = {0.004, 0.02, 3.0};
    s.environment.fogColourMode = FogColourMode::Custom;
    s.environment.fogColour = {0.5, 0.6, 0.7};
    return s;
}

FrameBlockInputs testInputs() {
    FrameBlockInputs in;
    in.width = 320;
    in.height = 160;
    in.emitterCount = 3;
    in.sun.lightAzimuth = 1.25;
    in.sun.columns = 64;
    in.sun.rows = 32;
    in.sun.horizonRayleigh = {0.1, 0.2, 0.3};
    in.sun.horizonMie = {0.01, 0.02, 0.03};
    in.moon.lightAzimuth = 2.5;
    in.moon.columns = 16;
    in.moon.rows = 8;
    in.moon.horizonRayleigh = {0.4, 0.5, 0.6};
    in.moon.horizonMie = {0.04, 0.05, 0.06};
    return in;  // no tables: no sky ambient
}

/// The frame block of `state` seen by testCamera().
FrameBlock blockFor(const PresetState& state, const renderer::FrameDesc& frame = {},
                    const FrameBlockInputs& inputs = testInputs()) {
    const renderer::Camera camera = testCamera();
    return makeFrameBlock(camera, renderer::cameraFrame(camera), state, frame, inputs);
}

TEST(FrameBlock, CameraFieldsReproduceTheFrustum) {
    const renderer::Camera camera = testCamera();
    const renderer::CameraFrame view = renderer::cameraFrame(camera);
    const FrameBlock fb = makeFrameBlock(camera, view, testState(), {}, testInputs());
    const glm::dvec3 forward = glm::normalize(camera.target - camera.eye);
    expectNear3(fb.eye, camera.eye, 1e-5, "eye");
    expectNear3(fb.forward, forward, 1e-6, "forward");
    EXPECT_FLOAT_EQ(fb.nearDistance, 0.25f);
    EXPECT_FLOAT_EQ(fb.farDistance, 2000.0f);
    glm::dmat4 clipFromWorld;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) clipFromWorld[c][r] = fb.clipFromWorld.m[c * 4 + r];
    // Corner rays: bottom-left, bottom-right, top-left, top-right, to the far
    // plane: each lands at its NDC corner at depth 1, at the far distance
    // along the view.
    const glm::dvec2 ndc[4] = {{-1, -1}, {1, -1}, {-1, 1}, {1, 1}};
    for (int k = 0; k < 4; ++k) {
        const glm::dvec3 ray(fb.farCornerRays[k].x, fb.farCornerRays[k].y, fb.farCornerRays[k].z);
        EXPECT_NEAR(glm::dot(ray, forward), camera.farDistance, 1e-3 * camera.farDistance) << "corner " << k;
        const glm::dvec4 clip = clipFromWorld * glm::dvec4(camera.eye + ray, 1.0);
        EXPECT_NEAR(clip.x / clip.w, ndc[k].x, 1e-4) << "corner " << k;
        EXPECT_NEAR(clip.y / clip.w, ndc[k].y, 1e-4) << "corner " << k;
        EXPECT_NEAR(clip.z / clip.w, 1.0, 1e-3) << "corner " << k;
    }
    // The vertical field of view and the aspect from the corners.
    const glm::dvec3 bl(fb.farCornerRays[0].x, fb.farCornerRays[0].y, fb.farCornerRays[0].z);
    const glm::dvec3 tl(fb.farCornerRays[2].x, fb.farCornerRays[2].y, fb.farCornerRays[2].z);
    const glm::dvec3 br(fb.farCornerRays[1].x, fb.farCornerRays[1].y, fb.farCornerRays[1].z);
    const double halfHeight = camera.farDistance * std::tan(0.5 * camera.verticalFov);
    EXPECT_NEAR(glm::length(tl - bl), 2.0 * halfHeight, 1e-3 * halfHeight);
    EXPECT_NEAR(glm::length(br - bl), 2.0 * halfHeight * camera.aspect, 1e-3 * halfHeight);
    EXPECT_FLOAT_EQ(fb.viewportSize[0], 320.0f);
    EXPECT_FLOAT_EQ(fb.viewportSize[1], 160.0f);
    EXPECT_FLOAT_EQ(fb.viewportTexel[0], 1.0f / 320.0f);
    EXPECT_FLOAT_EQ(fb.viewportTexel[1], 1.0f / 160.0f);
}

TEST(FrameBlock, LightsDiscsAndSkyMapping) {
    const renderer::Camera camera = testCamera();
    renderer::FrameDesc frame;
    frame.sunDiscRadius = 0.01;
    frame.moonDiscRadius = 0.0;  // hidden
    const PresetState state = testState();
    const FrameBlock fb = makeFrameBlock(camera, renderer::cameraFrame(camera), state, frame, testInputs());
    expectNear3(fb.sunDirection, glm::dvec3(0.0, 1.0, -1.0) / std::sqrt(2.0), 1e-7, "sun direction");
    expectNear3(fb.moonDirection, glm::normalize(state.moonLight.body.direction), 1e-7, "moon direction");
    expectNear3(fb.sunIlluminanceSpace, {20.0, 19.0, 18.0}, 1e-5, "sun E space");
    expectNear3(fb.sunIlluminance, {10.0, 0.0, 0.0}, 1e-6, "sun E ground (negative and NaN -> 0)");
    expectNear3(fb.moonIlluminanceSpace, {0.05, 0.055, 0.06}, 1e-7, "moon E space");
    expectNear3(fb.moonIlluminance, {0.03, 0.03, 0.03}, 1e-7, "moon E ground");
    // Disc: chord |v - l| of the angular radius, and 1 / (2 pi (1 - cos r)).
    const double r = 0.01;
    const glm::dvec3 l(0.0, 1.0, 0.0), edge(std::sin(r), std::cos(r), 0.0);
    EXPECT_NEAR(fb.sunDiscChord, glm::length(edge - l), 1e-9);
    EXPECT_NEAR(fb.sunDiscInverseSolidAngle, 1.0 / (2.0 * kPiD * (1.0 - std::cos(r))),
                1e-6 * fb.sunDiscInverseSolidAngle);
    EXPECT_EQ(fb.moonDiscChord, 0.0f);
    EXPECT_EQ(fb.moonDiscInverseSolidAngle, 0.0f);
    EXPECT_FLOAT_EQ(fb.mieAnisotropy, 0.999f);
    expectNear3(fb.sunHorizonRayleigh, {0.1, 0.2, 0.3}, 1e-7, "sun I_R");
    expectNear3(fb.moonHorizonMie, {0.04, 0.05, 0.06}, 1e-7, "moon I_M");
    expectNear3(fb.skyAmbient, airglowIrradiance(state.zenithTransmittance), 1e-13,
                "no tables: the ambient is the night sky's airglow alone");
    EXPECT_FLOAT_EQ(fb.sunTableAzimuth, 1.25f);
    EXPECT_FLOAT_EQ(fb.moonTableAzimuth, 2.5f);
    EXPECT_EQ(fb.sunTableColumns, 64.0f);
    EXPECT_EQ(fb.sunTableRows, 32.0f);
    EXPECT_EQ(fb.moonTableColumns, 16);
    EXPECT_EQ(fb.moonTableRows, 8);
    EXPECT_EQ(fb.emitterCount, 3);
}

// Under a cloud deck (FrameBlockInputs::overcast) the surfaces' ambient is
// the clear sky's through the gaps plus the deck's underside, the clouds keep
// the clear sky's, and the fog's horizon takes the deck's cover and radiance.
TEST(FrameBlock, GroundAmbientAndFogUnderTheOvercast) {
    PresetState night = testState();
    night.sunLight.body.elevation = -20.0 * kPiD / 180.0;  // the airglow is on
    night.zenithTransmittance = {0.8, 0.85, 0.9};
    FrameBlockInputs inputs = testInputs();
    const FrameBlock clear = blockFor(night, {}, inputs);
    EXPECT_EQ(clear.groundAmbient.x, clear.skyAmbient.x);
    EXPECT_EQ(clear.groundAmbient.z, clear.skyAmbient.z);
    EXPECT_EQ(clear.overcastCover, 0.0f);
    inputs.overcast.overcast.skyCover = 0.75;
    inputs.overcast.overcast.horizonCover = 0.9;
    inputs.overcast.radiance = {0.01, 0.02, -1.0};  // a negative channel is sanitised to 0
    const FrameBlock under = blockFor(night, {}, inputs);
    expectNear3(under.skyAmbient, d3(clear.skyAmbient), 0.0, "the clouds keep the clear sky's ambient");
    const glm::dvec3 sky = d3(clear.skyAmbient);
    expectNear3(under.groundAmbient, 0.25 * sky + 0.75 * kPiD * glm::dvec3(0.01, 0.02, 0.0), 1e-7,
                "ground ambient under the deck");
    EXPECT_FLOAT_EQ(under.overcastCover, 0.9f);
    EXPECT_FLOAT_EQ(under.overcastSkyCover, 0.75f);
    EXPECT_EQ(clear.overcastSkyCover, 0.0f);
    expectNear3(under.overcastRadiance, {0.01, 0.02, 0.0}, 1e-9, "deck radiance");
    ASSERT_GT(sky.x, 0.0);  // the airglow made the comparison meaningful
    // A clear sky's irradiance computed already (the renderer's overcastLight)
    // replaces the tables' integral, sanitised like it.
    const glm::dvec3 given(0.3, 0.4, std::nan(""));
    inputs.clearSkyIrradiance = &given;
    const FrameBlock reused = blockFor(night, {}, inputs);
    expectNear3(reused.skyAmbient, sky + glm::dvec3(0.3, 0.4, 0.0), 1e-7, "clear sky given");
}

TEST(FrameBlock, DiscsAtTheApparentPositionWithTheMoonsPhase) {
    // A real evaluation: the built-in preset's sun at 19:54, 1.6 deg below
    // the horizon, stands ~0.4 deg higher refracted (Saemundsson's formula,
    // faded out below -1 deg); the disc is drawn there, the light stays
    // geometric.
    aerial::PresetState state = aerial::evaluate(aerial::defaultPreset(), 19.9);
    const double geometric = state.sunLight.body.elevation, apparent = state.sunLight.body.apparentElevation;
    ASSERT_GT(apparent - geometric, 0.1 * kPi / 180.0) << "refraction near the horizon";
    const renderer::Camera camera = testCamera();
    FrameBlock fb = makeFrameBlock(camera, renderer::cameraFrame(camera), state, {}, testInputs());
    expectNear3(fb.sunDiscDirection, state.sunLight.body.apparentDirection, 1e-6, "sun disc");
    expectNear3(fb.sunDirection, state.sunLight.body.direction, 1e-6, "sun light");
    // A body built by hand without an apparent direction keeps its own.
    state.sunLight.body.apparentDirection = glm::dvec3(0.0, 1.0, 0.0);
    state.sunLight.body.direction = glm::normalize(glm::dvec3(1.0, 0.2, 0.0));
    fb = makeFrameBlock(camera, renderer::cameraFrame(camera), state, {}, testInputs());
    expectNear3(fb.sunDiscDirection, state.sunLight.body.direction, 1e-6, "hand-built sun");
    // The moon's bright limb: position angle 90 deg from the zenith through
    // east is east on the sky, a tangent to the disc.
    state.moonLight.body.direction = state.moonLight.body.apparentDirection =
        glm::dvec3(0.0, 0.0, 1.0);  // south
    state.moonLight.body.brightLimbAngle = kPi / 2.0;
    state.moonLight.body.illuminatedFraction = 0.25;
    fb = makeFrameBlock(camera, renderer::cameraFrame(camera), state, {}, testInputs());
    expectNear3(fb.moonBrightLimb, glm::dvec3(1.0, 0.0, 0.0), 1e-6, "bright limb east");
    EXPECT_FLOAT_EQ(fb.moonLitFraction, 0.25f);
}

TEST(FrameBlock, FogFieldsAndRadianceCap) {
    renderer::FrameDesc frame;
    EXPECT_EQ(frame.precision, renderer::ColourPrecision::Float);  // the physical night needs it
    frame.precision = renderer::ColourPrecision::Half;
    const FrameBlock half = blockFor(testState(), frame);
    EXPECT_FLOAT_EQ(half.fogDensity, 0.004f);
    EXPECT_FLOAT_EQ(half.fogFalloff, 0.02f);
    EXPECT_FLOAT_EQ(half.fogBaseHeight, 3.0f);
    EXPECT_EQ(half.fogColourMode, 2.0f);  // FogColourMode::Custom
    expectNear3(half.fogColour, {0.5, 0.6, 0.7}, 1e-7, "fog colour");
    EXPECT_EQ(half.radianceCap, 3.0e4f);
    frame.precision = renderer::ColourPrecision::Float;
    frame.passes.globalFog = false;  // no global fog anywhere, the transparent passes included
    const FrameBlock full = blockFor(testState(), frame);
    EXPECT_EQ(full.radianceCap, 1.0e30f);
    EXPECT_EQ(full.fogDensity, 0.0f);
    EXPECT_FLOAT_EQ(full.fogFalloff, 0.02f);
}

TEST(FrameBlock, StarsFollowTheSwitchAndTheAirglowTheSun) {
    const renderer::Camera camera = testCamera();
    PresetState night = testState();
    night.sunLight.body.elevation = -0.5;  // below -10 deg
    night.timeHours = 1.5;
    night.environment.location.latitudeDeg = 30.0;
    night.zenithTransmittance = {0.8, 0.85, 0.9};
    const FrameBlockInputs inputs = testInputs();
    const FrameBlock fb = blockFor(night, {}, inputs);
    EXPECT_FLOAT_EQ(fb.starIlluminance, float(renderer::kStarIlluminance));
    const CelestialFrame sky = celestialFrame(night.environment.location, night.timeHours);
    expectNear3(fb.starAxisX, sky.equatorX, 1e-6, "equator x");
    expectNear3(fb.starAxisY, sky.equatorY, 1e-6, "equator y");
    expectNear3(fb.starPole, sky.pole, 1e-6, "pole");
    expectNear3(fb.starTransmittance, night.zenithTransmittance, 1e-7, "zenith transmittance");
    EXPECT_FLOAT_EQ(fb.starSigma, float(std::min(0.6 * camera.verticalFov / inputs.height, 0.0015)));
    // The brightest star (-1.5 mag) and what the sky pass's limiting
    // magnitude needs (aerial/stars.hpp).
    EXPECT_NEAR(renderer::kStarIlluminance, starIlluminanceLux(kStarFieldBrightest) / kNitsPerRadianceUnit,
                1e-6 * renderer::kStarIlluminance);
    EXPECT_FLOAT_EQ(fb.starNitsPerUnit, float(kNitsPerRadianceUnit));
    EXPECT_FLOAT_EQ(fb.starDarkLimit, float(limitingMagnitude(0.0)));

    renderer::FrameDesc off;
    off.stars = false;
    EXPECT_EQ(blockFor(night, off, inputs).starIlluminance, 0.0f);
    // Which stars show is decided per pixel by the sky's limiting magnitude
    // (sky.glsl): the illuminance is the same by day.
    EXPECT_FLOAT_EQ(blockFor(testState(), {}, inputs).starIlluminance, float(renderer::kStarIlluminance));

    // The airglow is physical and part of the sky by day and night, with the
    // stars on or off: core's model constants, and its irradiance in the sky
    // ambient (no sky tables here, so the ambient is the airglow alone).
    for (const FrameBlock& b : {fb, blockFor(night, off, inputs), blockFor(testState(), {}, inputs)}) {
        expectNear3(b.airglowZenithRadiance, kAirglowZenithRadiance, 1e-14, "airglow zenith");
        EXPECT_FLOAT_EQ(b.airglowScatteredFill, float(kAirglowScatteredFill));
        EXPECT_FLOAT_EQ(b.airglowShell, float(kAirglowShellRatio));
    }
    // The zenith transmittance dims the airglow with the stars off too.
    expectNear3(blockFor(night, off, inputs).starTransmittance, night.zenithTransmittance, 1e-7,
                "zenith transmittance, stars off");
    expectNear3(fb.skyAmbient, airglowIrradiance(night.zenithTransmittance), 1e-10, "airglow ambient");
    expectNear3(blockFor(night, off, inputs).skyAmbient, airglowIrradiance(night.zenithTransmittance), 1e-10,
                "airglow ambient, stars off");
}

// --- std140 offsets: the GLSL blocks laid out by the rules, against offsetof.

struct Std140Member {
    std::string name;
    std::size_t offset = 0;
};

/// The members of `uniform <block> { ... }` in a shader source, with their
/// std140 offsets (scalars, vec2..4, ivec4, mat4 and arrays of vec4 or mat4).
std::vector<Std140Member> std140Layout(const std::string& file, const std::string& block) {
    std::ifstream in(std::string(AERIAL_SOURCE_DIR) + "/shaders/" + file);
    std::stringstream text;
    text << in.rdbuf();
    const std::string s = text.str();
    const std::size_t begin = s.find("uniform " + block + " {");
    const std::size_t end = s.find('}', begin);
    EXPECT_NE(begin, std::string::npos) << file << " " << block;
    if (begin == std::string::npos || end == std::string::npos) return {};
    const std::string body = s.substr(begin, end - begin);
    static const std::map<std::string, std::pair<std::size_t, std::size_t>> kTypes = {
        // type: (base alignment, size) [bytes]
        {"float", {4, 4}},  {"int", {4, 4}},     {"vec2", {8, 8}},   {"vec3", {16, 12}},
        {"vec4", {16, 16}}, {"ivec4", {16, 16}}, {"mat4", {16, 64}},
    };
    std::vector<Std140Member> members;
    std::size_t offset = 0;
    // Statements "type name;" or "type name[N];" (comments stripped), after
    // the block's opening brace.
    std::istringstream lines(body.substr(body.find('{') + 1));
    std::string line;
    while (std::getline(lines, line)) {
        line = line.substr(0, line.find("//"));
        std::istringstream words(line);
        std::string type, name;
        if (!(words >> type >> name) || name.empty() || name.back() != ';') continue;
        name.pop_back();
        const auto found = kTypes.find(type);
        EXPECT_NE(found, kTypes.end()) << type;
        if (found == kTypes.end()) continue;
        std::size_t alignment = found->second.first, size = found->second.second;
        const std::size_t bracket = name.find('[');
        if (bracket != std::string::npos) {  // arrays: elements rounded up to vec4
            alignment = 16;
            size = (size + 15) / 16 * 16 * std::stoul(name.substr(bracket + 1));
            name = name.substr(0, bracket);
        }
        offset = (offset + alignment - 1) / alignment * alignment;
        members.push_back({name, offset});
        offset += size;
    }
    return members;
}

void expectLayout(const std::string& file, const std::string& block,
                  const std::map<std::string, std::size_t>& cpp, std::size_t cppSize) {
    const std::vector<Std140Member> glsl = std140Layout(file, block);
    ASSERT_FALSE(glsl.empty());
    std::size_t checked = 0;
    for (const Std140Member& m : glsl) {
        const auto found = cpp.find(m.name);
        if (found == cpp.end()) continue;  // padding members need not be named alike
        EXPECT_EQ(found->second, m.offset) << block << "." << m.name;
        ++checked;
    }
    EXPECT_EQ(checked, cpp.size()) << block << ": a C++ member has no GLSL counterpart";
    EXPECT_EQ(cppSize % 16, 0u);
}

#define AERIAL_OFFSET(type, name) \
    { #name, offsetof(type, name) }

TEST(FrameBlock, Std140OffsetsMatchTheGlslBlocks) {
    expectLayout("common/frame.glsl", "FrameBlock",
                 {AERIAL_OFFSET(FrameBlock, clipFromWorld),
                  AERIAL_OFFSET(FrameBlock, eye),
                  AERIAL_OFFSET(FrameBlock, farDistance),
                  AERIAL_OFFSET(FrameBlock, forward),
                  AERIAL_OFFSET(FrameBlock, nearDistance),
                  AERIAL_OFFSET(FrameBlock, farCornerRays),
                  AERIAL_OFFSET(FrameBlock, viewportSize),
                  AERIAL_OFFSET(FrameBlock, viewportTexel),
                  AERIAL_OFFSET(FrameBlock, sunDirection),
                  AERIAL_OFFSET(FrameBlock, sunDiscChord),
                  AERIAL_OFFSET(FrameBlock, sunIlluminanceSpace),
                  AERIAL_OFFSET(FrameBlock, sunIlluminance),
                  AERIAL_OFFSET(FrameBlock, sunDiscInverseSolidAngle),
                  AERIAL_OFFSET(FrameBlock, moonDirection),
                  AERIAL_OFFSET(FrameBlock, moonDiscChord),
                  AERIAL_OFFSET(FrameBlock, moonIlluminanceSpace),
                  AERIAL_OFFSET(FrameBlock, airglowScatteredFill),
                  AERIAL_OFFSET(FrameBlock, moonIlluminance),
                  AERIAL_OFFSET(FrameBlock, moonDiscInverseSolidAngle),
                  AERIAL_OFFSET(FrameBlock, sunHorizonRayleigh),
                  AERIAL_OFFSET(FrameBlock, mieAnisotropy),
                  AERIAL_OFFSET(FrameBlock, sunHorizonMie),
                  AERIAL_OFFSET(FrameBlock, moonHorizonRayleigh),
                  AERIAL_OFFSET(FrameBlock, moonHorizonMie),
                  AERIAL_OFFSET(FrameBlock, skyAmbient),
                  AERIAL_OFFSET(FrameBlock, overcastCover),
                  AERIAL_OFFSET(FrameBlock, fogDensity),
                  AERIAL_OFFSET(FrameBlock, fogFalloff),
                  AERIAL_OFFSET(FrameBlock, fogBaseHeight),
                  AERIAL_OFFSET(FrameBlock, fogColourMode),
                  AERIAL_OFFSET(FrameBlock, fogColour),
                  AERIAL_OFFSET(FrameBlock, radianceCap),
                  AERIAL_OFFSET(FrameBlock, sunTableAzimuth),
                  AERIAL_OFFSET(FrameBlock, moonTableAzimuth),
                  AERIAL_OFFSET(FrameBlock, sunTableColumns),
                  AERIAL_OFFSET(FrameBlock, sunTableRows),
                  AERIAL_OFFSET(FrameBlock, emitterCount),
                  AERIAL_OFFSET(FrameBlock, moonTableColumns),
                  AERIAL_OFFSET(FrameBlock, moonTableRows),
                  AERIAL_OFFSET(FrameBlock, starAxisX),
                  AERIAL_OFFSET(FrameBlock, starIlluminance),
                  AERIAL_OFFSET(FrameBlock, starAxisY),
                  AERIAL_OFFSET(FrameBlock, starSigma),
                  AERIAL_OFFSET(FrameBlock, starPole),
                  AERIAL_OFFSET(FrameBlock, starNitsPerUnit),
                  AERIAL_OFFSET(FrameBlock, starTransmittance),
                  AERIAL_OFFSET(FrameBlock, starDarkLimit),
                  AERIAL_OFFSET(FrameBlock, sunHorizonMultiple),
                  AERIAL_OFFSET(FrameBlock, moonHorizonMultiple),
                  AERIAL_OFFSET(FrameBlock, sunDiscDirection),
                  AERIAL_OFFSET(FrameBlock, moonLitFraction),
                  AERIAL_OFFSET(FrameBlock, moonDiscDirection),
                  AERIAL_OFFSET(FrameBlock, moonBrightLimb),
                  AERIAL_OFFSET(FrameBlock, sunTableWarped),
                  AERIAL_OFFSET(FrameBlock, moonTableWarped),
                  AERIAL_OFFSET(FrameBlock, groundAmbient),
                  AERIAL_OFFSET(FrameBlock, overcastRadiance),
                  AERIAL_OFFSET(FrameBlock, overcastSkyCover),
                  AERIAL_OFFSET(FrameBlock, fogSkyL0),
                  AERIAL_OFFSET(FrameBlock, fogHorizonDistance),
                  AERIAL_OFFSET(FrameBlock, fogSkyL1x),
                  AERIAL_OFFSET(FrameBlock, fogDirectVisibility),
                  AERIAL_OFFSET(FrameBlock, fogSkyL1y),
                  AERIAL_OFFSET(FrameBlock, fogSkyL1z),
                  AERIAL_OFFSET(FrameBlock, airglowZenithRadiance),
                  AERIAL_OFFSET(FrameBlock, airglowShell)},
                 sizeof(FrameBlock));
    expectLayout(
        "common/volume.glsl", "VolumeBlock",
        {AERIAL_OFFSET(VolumeBlock, worldFromObject), AERIAL_OFFSET(VolumeBlock, objectFromWorldRow0),
         AERIAL_OFFSET(VolumeBlock, shape), AERIAL_OFFSET(VolumeBlock, objectFromWorldRow1),
         AERIAL_OFFSET(VolumeBlock, density), AERIAL_OFFSET(VolumeBlock, objectFromWorldRow2),
         AERIAL_OFFSET(VolumeBlock, falloff), AERIAL_OFFSET(VolumeBlock, position),
         AERIAL_OFFSET(VolumeBlock, gradientOffset), AERIAL_OFFSET(VolumeBlock, gradientDirection),
         AERIAL_OFFSET(VolumeBlock, colourMode), AERIAL_OFFSET(VolumeBlock, colour)},
        sizeof(VolumeBlock));
    expectLayout("common/object.glsl", "ObjectBlock",
                 {AERIAL_OFFSET(ObjectBlock, worldFromObject), AERIAL_OFFSET(ObjectBlock, normalFromObject),
                  AERIAL_OFFSET(ObjectBlock, albedo), AERIAL_OFFSET(ObjectBlock, opacity),
                  AERIAL_OFFSET(ObjectBlock, emission), AERIAL_OFFSET(ObjectBlock, specularFactor),
                  AERIAL_OFFSET(ObjectBlock, metallic), AERIAL_OFFSET(ObjectBlock, roughness),
                  AERIAL_OFFSET(ObjectBlock, alphaCutoff), AERIAL_OFFSET(ObjectBlock, alphaMode),
                  AERIAL_OFFSET(ObjectBlock, baseColourTextured), AERIAL_OFFSET(ObjectBlock, boundsMin),
                  AERIAL_OFFSET(ObjectBlock, boundsMax), AERIAL_OFFSET(ObjectBlock, cornerFog)},
                 sizeof(ObjectBlock));
    expectLayout("common/clouds.glsl", "CloudBlock",
                 {AERIAL_OFFSET(CloudBlock, shapeOffset),
                  AERIAL_OFFSET(CloudBlock, detailOffset),
                  AERIAL_OFFSET(CloudBlock, planetRadius),
                  AERIAL_OFFSET(CloudBlock, bottomM),
                  AERIAL_OFFSET(CloudBlock, thicknessM),
                  AERIAL_OFFSET(CloudBlock, coverage),
                  AERIAL_OFFSET(CloudBlock, densityPerM),
                  AERIAL_OFFSET(CloudBlock, type),
                  AERIAL_OFFSET(CloudBlock, shapeScaleM),
                  AERIAL_OFFSET(CloudBlock, detailScaleM),
                  AERIAL_OFFSET(CloudBlock, erosion),
                  AERIAL_OFFSET(CloudBlock, anisotropy),
                  AERIAL_OFFSET(CloudBlock, steps),
                  AERIAL_OFFSET(CloudBlock, lightSteps),
                  AERIAL_OFFSET(CloudBlock, albedo),
                  AERIAL_OFFSET(CloudBlock, volumeCount),
                  AERIAL_OFFSET(CloudBlock, rayleighScattering),
                  AERIAL_OFFSET(CloudBlock, rayleighScaleHeight),
                  AERIAL_OFFSET(CloudBlock, mieExtinction),
                  AERIAL_OFFSET(CloudBlock, mieScaleHeight),
                  AERIAL_OFFSET(CloudBlock, shadowOrigin),
                  AERIAL_OFFSET(CloudBlock, shadowExtentM),
                  AERIAL_OFFSET(CloudBlock, shadowActive),
                  AERIAL_OFFSET(CloudBlock, shadowToLight),
                  AERIAL_OFFSET(CloudBlock, shadowSteps),
                  AERIAL_OFFSET(CloudBlock, outputMode),
                  AERIAL_OFFSET(CloudBlock, shadowSize),
                  AERIAL_OFFSET(CloudBlock, groundAlbedo),
                  AERIAL_OFFSET(CloudBlock, volumeData)},
                 sizeof(CloudBlock));
    expectLayout("common/shadows.glsl", "ShadowBlock",
                 {AERIAL_OFFSET(ShadowBlock, shadowFromWorld), AERIAL_OFFSET(ShadowBlock, splitM),
                  AERIAL_OFFSET(ShadowBlock, texelM), AERIAL_OFFSET(ShadowBlock, depthPerM),
                  AERIAL_OFFSET(ShadowBlock, toLight), AERIAL_OFFSET(ShadowBlock, castingLight),
                  AERIAL_OFFSET(ShadowBlock, cascadeCount), AERIAL_OFFSET(ShadowBlock, resolution),
                  AERIAL_OFFSET(ShadowBlock, blendFraction)},
                 sizeof(ShadowBlock));
}

// --- makeShadowBlock: the cascades' placement, without a GL context.

glm::dvec3 shadowCoords(const ShadowBlock& b, int k, const glm::dvec3& p) {
    const float* m = b.shadowFromWorld[k].m;
    glm::dvec3 s;
    for (int r = 0; r < 3; ++r) s[r] = m[r] * p.x + m[4 + r] * p.y + m[8 + r] * p.z + m[12 + r];
    return s;
}

PresetState sunState(const glm::dvec3& toSun) {
    PresetState s;
    s.sunLight.body.direction = toSun;
    s.sunLight.illuminance = {1.0, 1.0, 1.0};
    s.moonLight.illuminance = {0.001, 0.001, 0.001};
    s.moonLight.body.direction = {0.0, 1.0, 0.0};
    return s;
}

TEST(ShadowBlock, CascadesCoverTheirSlicesAndFollowThePracticalSplits) {
    const renderer::Camera camera = testCamera();
    const renderer::CameraFrame view = renderer::cameraFrame(camera);
    renderer::FrameDesc frame;
    frame.shadowMap.maxDistanceM = 300.0;
    renderer::ShadowMapStats stats;
    const ShadowBlock b = makeShadowBlock(view, sunState({0.3, 0.8, -0.2}), frame, true, stats);
    ASSERT_TRUE(stats.drawn);
    ASSERT_EQ(b.cascadeCount, 3);
    EXPECT_EQ(b.castingLight, 1.0f);
    // z_k = 0.7 n (f/n)^(k/3) + 0.3 (n + (f - n) k/3), n = 0.25, f = 300.
    const double n = 0.25, f = 300.0;
    for (int k = 0; k < 3; ++k) {
        const double i = (k + 1) / 3.0;
        const double want = 0.7 * n * std::pow(f / n, i) + 0.3 * (n + (f - n) * i);
        EXPECT_NEAR(stats.splitM[k], want, 1e-9 * want) << "split " << k;
    }
    // Every point of each slice (and of the blend band before it) lands
    // inside its cascade, at least the margin (4 texels) from the edge, at
    // a depth within [0, 1].
    double previous = n, previousStart = n;
    for (int k = 0; k < 3; ++k) {
        const double z0 = k == 0 ? n : previous - 0.1 * (previous - previousStart);
        const double z1 = stats.splitM[k];
        const double margin = 3.99 / b.resolution;
        for (int sample = 0; sample < 9 * 9 * 9; ++sample) {
            const double a = (sample % 9) / 8.0, c = (sample / 9 % 9) / 8.0, d = (sample / 81) / 8.0;
            const double z = z0 + (z1 - z0) * d;
            const glm::dvec3 ray = renderer::farRayAtNdc(view, 2.0 * a - 1.0, 2.0 * c - 1.0);
            const glm::dvec3 p = view.eye + ray * (z / view.farDistance);
            const glm::dvec3 s = shadowCoords(b, k, p);
            EXPECT_GE(s.x, margin) << k;
            EXPECT_LE(s.x, 1.0 - margin) << k;
            EXPECT_GE(s.y, margin) << k;
            EXPECT_LE(s.y, 1.0 - margin) << k;
            EXPECT_GT(s.z, 0.0) << k;
            EXPECT_LT(s.z, 1.0) << k;
        }
        previousStart = previous;
        previous = z1;
    }
}

TEST(ShadowBlock, TurningTheCameraKeepsTheTexelSizeAndMovingItKeepsTheTexelGrid) {
    renderer::FrameDesc frame;
    const PresetState state = sunState({0.3, 0.8, -0.2});
    renderer::Camera camera = testCamera();
    renderer::ShadowMapStats stats, turned, moved;
    const ShadowBlock b = makeShadowBlock(renderer::cameraFrame(camera), state, frame, true, stats);
    renderer::Camera turnedCamera = camera;
    turnedCamera.target = camera.eye + glm::dvec3(70.0, -20.0, 40.0);  // another direction entirely
    makeShadowBlock(renderer::cameraFrame(turnedCamera), state, frame, true, turned);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(turned.texelM[k], stats.texelM[k], 1e-12 * stats.texelM[k]) << k;
    // A small move: a fixed world point keeps its position in texels modulo
    // whole texels (the grid stays put in the world), for every cascade.
    renderer::Camera movedCamera = camera;
    const glm::dvec3 step(0.37 * stats.texelM[0], 0.11, -0.23 * stats.texelM[0]);
    movedCamera.eye += step;
    movedCamera.target += step;
    const ShadowBlock m = makeShadowBlock(renderer::cameraFrame(movedCamera), state, frame, true, moved);
    const glm::dvec3 point = camera.eye + glm::dvec3(-3.0, -10.0, -20.0);
    for (int k = 0; k < 3; ++k) {
        const glm::dvec3 a = shadowCoords(b, k, point) * double(b.resolution);
        const glm::dvec3 c = shadowCoords(m, k, point) * double(m.resolution);
        for (int axis = 0; axis < 2; ++axis) {
            const double shift = c[axis] - a[axis];
            EXPECT_NEAR(shift, std::round(shift), 2e-3) << "cascade " << k << " axis " << axis;
        }
    }
}

TEST(ShadowBlock, OffBelowTheHorizonOrWithoutCastersAndTheMoonAtNight) {
    const renderer::CameraFrame view = renderer::cameraFrame(testCamera());
    renderer::ShadowMapStats stats;
    renderer::FrameDesc off;
    off.passes.shadows = false;
    EXPECT_EQ(makeShadowBlock(view, sunState({0.3, 0.8, -0.2}), off, true, stats).castingLight, 0.0f);
    EXPECT_FALSE(stats.drawn);
    EXPECT_EQ(makeShadowBlock(view, sunState({0.3, 0.8, -0.2}), {}, false, stats).castingLight, 0.0f);
    EXPECT_EQ(makeShadowBlock(view, sunState({0.3, -0.1, -0.2}), {}, true, stats).castingLight, 0.0f);
    // Night: the moon is the brighter light and casts.
    PresetState night = sunState({0.3, -0.4, -0.2});
    night.sunLight.illuminance = glm::dvec3(0.0);
    night.moonLight.body.direction = {-0.5, 0.6, 0.1};
    const ShadowBlock moon = makeShadowBlock(view, night, {}, true, stats);
    EXPECT_EQ(moon.castingLight, 2.0f);
    EXPECT_TRUE(stats.moon);
    EXPECT_NEAR(glm::dot(stats.toLight, glm::normalize(glm::dvec3(-0.5, 0.6, 0.1))), 1.0, 1e-12);
    // Out-of-range settings are clamped; nothing is NaN.
    renderer::FrameDesc odd;
    odd.shadowMap.cascades = 9;
    odd.shadowMap.resolution = 1;
    odd.shadowMap.maxDistanceM = std::numeric_limits<double>::quiet_NaN();
    odd.shadowMap.splitLambda = 7.0;
    const ShadowBlock clamped = makeShadowBlock(view, sunState({0.0, 1.0, 0.0}), odd, true, stats);
    EXPECT_EQ(clamped.cascadeCount, 4);
    EXPECT_EQ(clamped.resolution, 256.0f);
    for (int k = 0; k < 4; ++k) {
        EXPECT_TRUE(std::isfinite(clamped.splitM[k]) && std::isfinite(clamped.texelM[k]));
        for (float v : clamped.shadowFromWorld[k].m) EXPECT_TRUE(std::isfinite(v));
    }
}

}  // namespace
}  // namespace aerial::test
