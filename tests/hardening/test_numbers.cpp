// test_numbers.cpp — what a preset may hold in numbers, and what happens to
// the rest (documented in aerial/preset.hpp, "Numbers"):
//   rejected (error): NaN and infinities (JSON has no literal for them; a
//     number too large for a double reads as infinite), negative densities,
//     zero or negative half-extents, a zero quaternion, a zero gradient
//     direction, anything else out of its range;
//   repaired (warning): a quaternion or gradient direction that is finite,
//     non-zero and off unit length is normalised;
// and nothing non-finite is saved, evaluated or baked.
#include "hardening_support.hpp"

#include <aerial/evaluate.hpp>
#include <aerial/preset.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace aerial::hardening {
namespace {

const char* kVolumeHead = "{\"version\": 1, \"volumes\": [{\"id\": \"v\", ";

PresetLoadResult loadVolume(const std::string& fields) {
    return parsePreset(kVolumeHead + fields + "}]}", "n.json");
}

TEST(Numbers, UnnormalisedQuaternionIsNormalisedWithAWarning) {
    const PresetLoadResult r = loadVolume("\"rotation_xyzw\": [0, 2, 0, 2]");
    ASSERT_TRUE(r.ok()) << joinIssues(r.errors);
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_EQ(
        r.warnings[0].toString(),
        "n.json:1:57: warning: /volumes/0/rotation_xyzw: not a unit quaternion (length 2.8284271247461903); "
        "normalised");
    const glm::dquat q = r.preset->volumes[0].rotation;
    EXPECT_NEAR(q.y, std::sqrt(0.5), 1e-15);
    EXPECT_NEAR(q.w, std::sqrt(0.5), 1e-15);
    EXPECT_EQ(q.x, 0.0);
    EXPECT_TRUE(validatePreset(*r.preset).empty());
    // Huge but finite components normalise without overflow.
    const PresetLoadResult big = loadVolume("\"rotation_xyzw\": [1e300, 0, 0, 1e300]");
    ASSERT_TRUE(big.ok()) << joinIssues(big.errors);
    EXPECT_NEAR(big.preset->volumes[0].rotation.x, std::sqrt(0.5), 1e-15);
    // Within 1e-6 of unit length: kept as written, no warning.
    const PresetLoadResult close = loadVolume("\"rotation_xyzw\": [0, 0, 0, 1.0000005]");
    ASSERT_TRUE(close.ok());
    EXPECT_TRUE(close.warnings.empty());
    EXPECT_EQ(close.preset->volumes[0].rotation.w, 1.0000005);
}

TEST(Numbers, ZeroQuaternionIsAnError) {
    const PresetLoadResult r = loadVolume("\"rotation_xyzw\": [0, 0, 0, 0]");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.errors[0].toString(),
              "n.json:1:57: error: /volumes/0/rotation_xyzw: must be a unit quaternion; a zero vector has no "
              "direction");
    const PresetLoadResult tiny = loadVolume("\"rotation_xyzw\": [1e-200, 0, 0, 0]");
    ASSERT_FALSE(tiny.ok());
}

TEST(Numbers, GradientDirection) {
    const PresetLoadResult r = loadVolume("\"gradient_direction\": [0, 0, -0.5]");
    ASSERT_TRUE(r.ok()) << joinIssues(r.errors);
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_EQ(
        r.warnings[0].toString(),
        "n.json:1:62: warning: /volumes/0/gradient_direction: not a unit vector (length 0.5); normalised");
    EXPECT_EQ(r.preset->volumes[0].gradientDirection, glm::dvec3(0.0, 0.0, -1.0));

    const PresetLoadResult zero = loadVolume("\"gradient_direction\": [0, 0, 0]");
    ASSERT_FALSE(zero.ok());
    EXPECT_EQ(
        zero.errors[0].toString(),
        "n.json:1:62: error: /volumes/0/gradient_direction: must be a unit vector; a zero vector has no "
        "direction");
}

TEST(Numbers, DensitiesAndExtentsAreRejected) {
    EXPECT_EQ(loadVolume("\"density_per_m\": -0.01").errors.at(0).toString(),
              "n.json:1:57: error: /volumes/0/density_per_m: out of range: -0.01 is not in 0..10 1/m");
    EXPECT_EQ(loadVolume("\"half_extents_m\": [1, 0, 1]").errors.at(0).toString(),
              "n.json:1:62: error: /volumes/0/half_extents_m/1: out of range: 0 is not in 0.001..1e+07 m");
    EXPECT_EQ(loadVolume("\"half_extents_m\": [1, 1, -2]").errors.at(0).toString(),
              "n.json:1:65: error: /volumes/0/half_extents_m/2: out of range: -2 is not in 0.001..1e+07 m");
    EXPECT_EQ(
        parsePreset("{\"version\": 1, \"fog\": {\"density_per_m\": -1}}", "n.json").errors.at(0).toString(),
        "n.json:1:41: error: /fog/density_per_m: out of range: -1 is not in 0..10 1/m");
}

TEST(Numbers, OverflowingNumbersAreRejected) {
    const PresetLoadResult r = parsePreset("{\"version\": 1, \"fog\": {\"density_per_m\": 1e400}}", "n.json");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.errors[0].toString().substr(0, 12), "n.json:1:41:");
}

TEST(Numbers, NonFiniteValuesAreNeverSaved) {
    TempDir dir;
    const fs::path file = dir.path() / "p.json";
    struct Poison {
        const char* what;
        void (*apply)(Preset&);
        const char* expected;
    };
    const double nan = std::numeric_limits<double>::quiet_NaN();
    (void)nan;
    const Poison cases[] = {
        {"NaN fog density", [](Preset& p) { p.environment.fog.density = std::nan(""); },
         "/fog/density_per_m: not saved: must be a finite number (got nan)"},
        {"infinite sun", [](Preset& p) { p.environment.sun.intensity = INFINITY; },
         "/sun/intensity: not saved: must be a finite number (got inf)"},
        {"NaN volume position", [](Preset& p) { p.volumes[0].position.y = std::nan(""); },
         "/volumes/0/position_m/1: not saved: must be a finite number (got nan)"},
        {"NaN rotation", [](Preset& p) { p.volumes[0].rotation.w = std::nan(""); },
         "/volumes/0/rotation_xyzw/3: not saved: must be a finite number (got nan)"},
        {"unnormalised rotation", [](Preset& p) { p.volumes[0].rotation.w = 2.0; },
         "/volumes/0/rotation_xyzw: not saved: must be a unit quaternion (length 2)"},
        {"-inf key", [](Preset& p) { p.tracks[0].keys[1].value.x = -INFINITY; },
         "/tracks/0/keys/1/value: not saved: must be a finite number (got -inf)"},
        {"NaN key time", [](Preset& p) { p.tracks[0].keys[0].timeHours = std::nan(""); },
         "/tracks/0/keys/0/time_h: not saved: a key's time must be in [0, 24) h (got nan)"},
    };
    for (const Poison& c : cases) {
        writeFile(file, "old\n");
        Preset p = defaultPreset();
        c.apply(p);
        const SaveResult r = savePreset(p, file.string());
        ASSERT_FALSE(r.ok()) << c.what;
        std::string got = r.errors[0].pointer + ": " + r.errors[0].message;
        EXPECT_EQ(got, c.expected) << c.what;
        EXPECT_EQ(r.errors[0].file, file.string());
        EXPECT_EQ(readFile(file), "old\n") << c.what;
        EXPECT_EQ(listDir(dir.path()), std::vector<std::string>{"p.json"}) << c.what;
    }
}

TEST(Numbers, EvaluationOfExtremeButValidPresetsStaysFinite) {
    // Every scalar at its minimum, then at its maximum: evaluation is finite.
    for (int extreme = 0; extreme < 2; ++extreme) {
        Preset p = defaultPreset();
        p.environment.fog.density = extreme ? 10.0 : 0.0;
        p.environment.fog.falloff = extreme ? 10.0 : 0.0;
        p.environment.fog.baseHeight = extreme ? 1e5 : -1e5;
        p.environment.sun.intensity = extreme ? 1e5 : 0.0;
        p.environment.atmosphere.viewerHeight = extreme ? 60000.0 : 0.0;
        p.volumes[0].density = extreme ? 10.0 : 0.0;
        p.volumes[0].falloff = extreme ? 10.0 : 0.0;
        p.volumes[0].halfExtents = glm::dvec3(extreme ? 1e7 : 1e-3);
        p.emitters[0].attenuation = extreme ? 1e4 : 0.0;
        p.tracks.clear();
        ASSERT_TRUE(validatePreset(p).empty()) << joinIssues(validatePreset(p));
        const CompiledPreset compiled(p);
        for (double t : {0.0, 5.5, 12.0, 19.25}) {
            const PresetState s = compiled.evaluate(t);
            for (const glm::dvec3& v :
                 {s.sunLight.illuminance, s.moonLight.illuminance, s.sunLight.transmittance,
                  s.volumes[0].position, s.emitters[0].colour})
                for (int c = 0; c < 3; ++c) EXPECT_TRUE(std::isfinite(v[c])) << "t = " << t;
        }
    }
}

}  // namespace
}  // namespace aerial::hardening
