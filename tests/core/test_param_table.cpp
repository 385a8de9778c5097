// The parameter table: complete, consistent with the structs' defaults, and
// its accessors reach the fields they name.
#include <aerial/param_table.hpp>
#include <aerial/preset.hpp>

#include <gtest/gtest.h>

#include <cmath>

#include <map>
#include <set>
#include <string>

namespace {

using aerial::ParamDesc;
using aerial::ParamScope;
using aerial::ParamType;

constexpr ParamScope kScopes[] = {ParamScope::Global, ParamScope::Volume, ParamScope::Emitter,
                                  ParamScope::CloudVolume};

void defaultsOf(const ParamDesc& p, double out[4]) {
    aerial::Environment env;
    aerial::FogVolume volume;
    aerial::Emitter emitter;
    aerial::CloudVolume cloudVolume;
    switch (p.scope) {
        case ParamScope::Global:
            aerial::readParam(p, env, out);
            break;
        case ParamScope::Volume:
            aerial::readParam(p, volume, out);
            break;
        case ParamScope::Emitter:
            aerial::readParam(p, emitter, out);
            break;
        case ParamScope::CloudVolume:
            aerial::readParam(p, cloudVolume, out);
            break;
    }
}

TEST(ParamTable, DefaultsMatchTheStructs) {
    for (ParamScope scope : kScopes) {
        for (const ParamDesc& p : aerial::paramTable(scope)) {
            if (p.type == ParamType::String) continue;
            double v[4];
            defaultsOf(p, v);
            for (int c = 0; c < p.components(); ++c)
                EXPECT_EQ(v[c], p.defaultValue[c]) << p.path << "[" << c << "]";
        }
    }
}

TEST(ParamTable, RangesContainDefaultsAndSliders) {
    for (ParamScope scope : kScopes) {
        for (const ParamDesc& p : aerial::paramTable(scope)) {
            if (p.type == ParamType::String) continue;
            EXPECT_LT(p.minValue, p.maxValue) << p.path;
            EXPECT_LE(p.minValue, p.uiMin) << p.path;
            EXPECT_LE(p.uiMax, p.maxValue) << p.path;
            EXPECT_LT(p.uiMin, p.uiMax) << p.path;
            if (p.logScale) {
                EXPECT_GT(p.uiMin, 0.0) << p.path << ": a log slider needs uiMin > 0";
            }
            if (p.type == ParamType::Quaternion) continue;  // unit length instead
            for (int c = 0; c < p.components(); ++c) {
                EXPECT_GE(p.defaultValue[c], p.minValue) << p.path;
                EXPECT_LE(p.defaultValue[c], p.maxValue) << p.path;
            }
        }
    }
}

TEST(ParamTable, PathsAreUniqueAndFindable) {
    for (ParamScope scope : kScopes) {
        std::set<std::string> seen;
        for (const ParamDesc& p : aerial::paramTable(scope)) {
            EXPECT_TRUE(seen.insert(std::string(p.path)).second) << "duplicate " << p.path;
            EXPECT_EQ(aerial::findParam(scope, p.path), &p);
            EXPECT_EQ(p.scope, scope) << p.path;
            EXPECT_FALSE(p.label.empty()) << p.path;
            EXPECT_FALSE(p.doc.empty()) << p.path;
        }
    }
    EXPECT_EQ(aerial::findParam(ParamScope::Global, "fog.nope"), nullptr);
    EXPECT_EQ(aerial::findParam(ParamScope::Volume, "fog.density_per_m"), nullptr);
}

TEST(ParamTable, KeysCarryTheirUnits) {
    const std::map<std::string, std::string> suffix = {
        {"m", "_m"},     {"1/m", "_per_m"},   {"1/m^2", "_per_m2"},
        {"deg", "_deg"}, {"s", "_s"},         {"1/min", "_per_minute"},
        {"h", "_h"},     {"m/s", "_m_per_s"}, {"1/s", "_per_s"}};
    int checked = 0;
    for (ParamScope scope : kScopes) {
        for (const ParamDesc& p : aerial::paramTable(scope)) {
            const auto it = suffix.find(std::string(p.unit));
            if (it == suffix.end()) continue;
            const std::string key(p.key());
            ASSERT_GE(key.size(), it->second.size()) << p.path;
            EXPECT_EQ(key.substr(key.size() - it->second.size()), it->second) << p.path;
            ++checked;
        }
    }
    EXPECT_GT(checked, 20);
    EXPECT_EQ(aerial::findParam(ParamScope::Global, "location.moon_phase_offset_days")->unit, "day");
}

TEST(ParamTable, AccessorsMatchTheirType) {
    for (ParamScope scope : kScopes) {
        for (const ParamDesc& p : aerial::paramTable(scope)) {
            const int set = (p.scalar != nullptr) + (p.vec3 != nullptr) + (p.vec2 != nullptr) +
                            (p.quat != nullptr) + (p.string != nullptr) + (p.getInt != nullptr);
            EXPECT_EQ(set, 1) << p.path;
            switch (p.type) {
                case ParamType::Scalar:
                    EXPECT_NE(p.scalar, nullptr) << p.path;
                    break;
                case ParamType::Colour:
                case ParamType::Vec3:
                    EXPECT_NE(p.vec3, nullptr) << p.path;
                    break;
                case ParamType::Vec2:
                    EXPECT_NE(p.vec2, nullptr) << p.path;
                    break;
                case ParamType::Quaternion:
                    EXPECT_NE(p.quat, nullptr) << p.path;
                    break;
                case ParamType::String:
                    EXPECT_NE(p.string, nullptr) << p.path;
                    break;
                case ParamType::Enum:
                    EXPECT_FALSE(p.enumNames.empty()) << p.path;
                    [[fallthrough]];
                case ParamType::Int:
                    EXPECT_NE(p.getInt, nullptr) << p.path;
                    EXPECT_NE(p.setInt, nullptr) << p.path;
                    break;
            }
            if (p.animatable) {
                EXPECT_TRUE(p.type == ParamType::Scalar || p.type == ParamType::Colour ||
                            p.type == ParamType::Vec3 || p.type == ParamType::Vec2)
                    << p.path;
            }
        }
    }
}

TEST(ParamTable, Vec2HasTwoComponentsAndReadsXz) {
    EXPECT_EQ(ParamDesc::componentCount(ParamType::Scalar), 1);
    EXPECT_EQ(ParamDesc::componentCount(ParamType::Vec2), 2);
    EXPECT_EQ(ParamDesc::componentCount(ParamType::Vec3), 3);
    EXPECT_EQ(ParamDesc::componentCount(ParamType::Colour), 3);
    EXPECT_EQ(ParamDesc::componentCount(ParamType::Quaternion), 4);
    EXPECT_EQ(ParamDesc::componentCount(ParamType::String), 0);
    // No table entry is a Vec2 yet: a hand-made one (its field lives outside
    // Environment) exercises readParam.
    static glm::dvec2 wind(3.5, -1.25);
    ParamDesc d;
    d.scope = ParamScope::Global;
    d.type = ParamType::Vec2;
    d.path = "test.wind_m_per_s";
    d.vec2 = [](void*) { return &wind; };
    EXPECT_EQ(d.components(), 2);
    double out[4] = {9, 9, 9, 9};
    aerial::readParam(d, aerial::Environment{}, out);
    EXPECT_EQ(out[0], 3.5);
    EXPECT_EQ(out[1], -1.25);
    EXPECT_EQ(out[2], 0.0);
    EXPECT_EQ(out[3], 0.0);
}

TEST(ParamTable, AccessorsReachTheNamedFields) {
    aerial::Environment env;
    using aerial::findParam;
    EXPECT_EQ(findParam(ParamScope::Global, "fog.density_per_m")->scalar(&env), &env.fog.density);
    EXPECT_EQ(findParam(ParamScope::Global, "fog.falloff_per_m")->scalar(&env), &env.fog.falloff);
    EXPECT_EQ(findParam(ParamScope::Global, "atmosphere.mie.anisotropy")->scalar(&env),
              &env.atmosphere.mieAnisotropy);
    EXPECT_EQ(findParam(ParamScope::Global, "atmosphere.rayleigh.scale_height_m")->scalar(&env),
              &env.atmosphere.rayleighScaleHeight);
    EXPECT_EQ(findParam(ParamScope::Global, "atmosphere.mie.extinction_per_m")->vec3(&env),
              &env.atmosphere.mieExtinction);
    EXPECT_EQ(findParam(ParamScope::Global, "location.latitude_deg")->scalar(&env),
              &env.location.latitudeDeg);
    EXPECT_EQ(findParam(ParamScope::Global, "sun.intensity")->scalar(&env), &env.sun.intensity);
    EXPECT_EQ(findParam(ParamScope::Global, "moon.colour_rgb")->vec3(&env), &env.moon.colour);

    aerial::FogVolume v;
    EXPECT_EQ(findParam(ParamScope::Volume, "half_extents_m")->vec3(&v), &v.halfExtents);
    EXPECT_EQ(findParam(ParamScope::Volume, "density_per_m")->scalar(&v), &v.density);
    EXPECT_EQ(findParam(ParamScope::Volume, "rotation_xyzw")->quat(&v), &v.rotation);
    EXPECT_EQ(findParam(ParamScope::Volume, "id")->string(&v), &v.id);
    const ParamDesc* shape = findParam(ParamScope::Volume, "shape");
    shape->setInt(&v, 1);
    EXPECT_EQ(v.shape, aerial::FogVolumeShape::Ellipsoid);
    EXPECT_EQ(shape->enumNames[std::size_t(shape->getInt(&v))], "ellipsoid");

    aerial::Emitter e;
    EXPECT_EQ(findParam(ParamScope::Emitter, "attenuation_per_m2")->scalar(&e), &e.attenuation);
    const ParamDesc* seed = findParam(ParamScope::Emitter, "seed");
    seed->setInt(&e, 4294967295LL);
    EXPECT_EQ(e.seed, 4294967295u);
    findParam(ParamScope::Emitter, "kind")->setInt(&e, 1);
    EXPECT_EQ(e.kind, aerial::EmitterKind::Lightning);

    aerial::CloudVolume c;
    EXPECT_EQ(findParam(ParamScope::CloudVolume, "position_m")->vec3(&c), &c.position);
    EXPECT_EQ(findParam(ParamScope::CloudVolume, "half_extents_m")->vec3(&c), &c.halfExtents);
    EXPECT_EQ(findParam(ParamScope::CloudVolume, "rotation_xyzw")->quat(&c), &c.rotation);
    EXPECT_EQ(findParam(ParamScope::CloudVolume, "coverage")->scalar(&c), &c.coverage);
    EXPECT_EQ(findParam(ParamScope::CloudVolume, "edge_softness")->scalar(&c), &c.edgeSoftness);
    EXPECT_EQ(findParam(ParamScope::CloudVolume, "id")->string(&c), &c.id);
    const ParamDesc* cloudShape = findParam(ParamScope::CloudVolume, "shape");
    EXPECT_EQ(cloudShape->enumNames[std::size_t(cloudShape->getInt(&c))], "ellipsoid");
    cloudShape->setInt(&c, 0);
    EXPECT_EQ(c.shape, aerial::FogVolumeShape::Box);
}

TEST(ParamTable, CloudVolumeScope) {
    EXPECT_EQ(aerial::scopeName(ParamScope::CloudVolume), "cloud volume");
    for (const char* key : {"position_m", "half_extents_m", "coverage", "edge_softness"}) {
        const ParamDesc* p = aerial::findParam(ParamScope::CloudVolume, key);
        ASSERT_NE(p, nullptr) << key;
        EXPECT_TRUE(p->animatable) << key;
    }
    EXPECT_TRUE(aerial::findParam(ParamScope::CloudVolume, "id")->required);
    EXPECT_FALSE(aerial::findParam(ParamScope::CloudVolume, "shape")->animatable);
    // A storm cell is at least a metre across: zero and negative extents are out of range.
    EXPECT_EQ(aerial::findParam(ParamScope::CloudVolume, "half_extents_m")->minValue, 1.0);
    const ParamDesc* coverage = aerial::findParam(ParamScope::CloudVolume, "coverage");
    EXPECT_EQ(coverage->minValue, 0.0);
    EXPECT_EQ(coverage->maxValue, 1.0);
    EXPECT_EQ(aerial::TrackTarget::cloudVolume("storm", "coverage").scope, ParamScope::CloudVolume);
}

TEST(ParamTable, CoversEveryParameterTheIssueLists) {
    const char* global[] = {"atmosphere.rayleigh.scattering_per_m",
                            "atmosphere.rayleigh.scale_height_m",
                            "atmosphere.mie.scattering_per_m",
                            "atmosphere.mie.extinction_per_m",
                            "atmosphere.mie.scale_height_m",
                            "atmosphere.mie.anisotropy",
                            "atmosphere.ozone.absorption_per_m",
                            "sun.intensity",
                            "sun.colour_rgb",
                            "moon.intensity",
                            "moon.colour_rgb",
                            "atmosphere.viewer_height_m",
                            "location.latitude_deg",
                            "location.day_of_year",
                            "location.north_offset_deg",
                            "location.moon_phase_offset_days",
                            "fog.density_per_m",
                            "fog.falloff_per_m",
                            "fog.base_height_m",
                            "fog.colour_mode"};
    for (const char* path : global) EXPECT_NE(aerial::findParam(ParamScope::Global, path), nullptr) << path;
    for (const char* key : {"id", "name", "shape", "position_m", "rotation_xyzw", "half_extents_m",
                            "density_per_m", "falloff_per_m", "gradient_direction", "gradient_offset_m",
                            "edge_softness", "colour_mode", "colour_rgb"})
        EXPECT_NE(aerial::findParam(ParamScope::Volume, key), nullptr) << key;
    for (const char* key : {"id", "name", "kind", "position_m", "intensity_cd", "attenuation_per_m2", "temperature_k",
                            "colour_rgb", "seed", "flashes_per_minute", "flash_duration_s", "time_scale"})
        EXPECT_NE(aerial::findParam(ParamScope::Emitter, key), nullptr) << key;
}

TEST(ParamTable, LightDefaults) {
    const aerial::Environment env;
    EXPECT_EQ(env.sun.intensity, 20.0);
    // The moon is physical: full moon -12.7 mag against the sun's -26.7,
    // 10^(-0.4 x 14) = 2.5e-6 of its illuminance.
    EXPECT_NEAR(env.moon.intensity / env.sun.intensity, std::pow(10.0, -0.4 * 14.0), 0.05e-6);
    const glm::dvec3 e = env.sun.illuminance();
    EXPECT_EQ(e, glm::dvec3(20.0));
}

TEST(ParamTable, InterpolationNames) {
    for (auto i :
         {aerial::Interpolation::Step, aerial::Interpolation::Linear, aerial::Interpolation::Smooth}) {
        aerial::Interpolation back{};
        ASSERT_TRUE(aerial::parseInterpolation(aerial::interpolationName(i), back));
        EXPECT_EQ(back, i);
    }
    aerial::Interpolation unused{};
    EXPECT_FALSE(aerial::parseInterpolation("cubic", unused));
}

}  // namespace
