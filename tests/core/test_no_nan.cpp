// No NaN or Inf leaves any public function of aerial_core, over a randomised
// sweep that includes edge values: zero and huge densities, degenerate
// scales, zero-length segments, the sun below the horizon, non-finite inputs.
#include <aerial/atmosphere.hpp>
#include <aerial/emitter.hpp>
#include <aerial/fog_query.hpp>
#include <aerial/fog_volume.hpp>
#include <aerial/height_fog.hpp>
#include <aerial/sky.hpp>
#include <aerial/sun.hpp>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

bool finite(double x) { return std::isfinite(x); }
bool finite(const glm::dvec3& v) { return finite(v.x) && finite(v.y) && finite(v.z); }

/// Picks an edge value or an ordinary random value in [lo, hi].
class Sweep {
public:
    explicit Sweep(unsigned seed) : rng_(seed) {}
    double pick(double lo, double hi, bool allowNonFinite = true) {
        static const double edges[] = {0.0,  -0.0, 1e-300, -1e-300, 1e-12,  -1e-12, 1.0,
                                       -1.0, 1e6,  -1e6,   1e300,   -1e300, 1e-3};
        const int choice = std::uniform_int_distribution<int>(0, 9)(rng_);
        if (choice == 0) return edges[std::uniform_int_distribution<int>(0, 12)(rng_)];
        if (choice == 1 && allowNonFinite) {
            const double bad[] = {kNaN, kInf, -kInf};
            return bad[std::uniform_int_distribution<int>(0, 2)(rng_)];
        }
        return std::uniform_real_distribution<double>(lo, hi)(rng_);
    }
    glm::dvec3 vec(double lo, double hi, bool allowNonFinite = true) {
        return {pick(lo, hi, allowNonFinite), pick(lo, hi, allowNonFinite), pick(lo, hi, allowNonFinite)};
    }
    glm::dvec3 direction() {
        glm::dvec3 d(std::normal_distribution<double>()(rng_), std::normal_distribution<double>()(rng_),
                     std::normal_distribution<double>()(rng_));
        return glm::normalize(d);
    }
    std::mt19937_64& rng() { return rng_; }

private:
    std::mt19937_64 rng_;
};

TEST(NoNaN, SunAndMoon) {
    Sweep s(1);
    for (int i = 0; i < 20000; ++i) {
        aerial::Location where;
        where.latitudeDeg = s.pick(-90, 90);
        where.dayOfYear = s.pick(1, 365);
        where.northOffsetDeg = s.pick(-360, 360);
        where.moonPhaseOffsetDays = s.pick(0, 30);
        const double t = s.pick(0, 24);
        for (const aerial::CelestialBody& body :
             {aerial::sunPosition(where, t), aerial::moonPosition(where, t)}) {
            ASSERT_TRUE(finite(body.direction) && finite(body.elevation) && finite(body.azimuth));
            ASSERT_NEAR(glm::length(body.direction), 1.0, 1e-9);
            ASSERT_TRUE(finite(body.illuminatedFraction) && finite(body.phaseIrradiance));
        }
        ASSERT_TRUE(finite(aerial::dayLengthHours(where)));
    }
}

TEST(NoNaN, PhaseFunctionsAndTransmittance) {
    Sweep s(2);
    for (int i = 0; i < 20000; ++i) {
        const double mu = s.pick(-1, 1), g = s.pick(-0.999, 0.999);
        ASSERT_TRUE(finite(aerial::rayleighPhase(mu))) << mu;
        ASSERT_TRUE(finite(aerial::miePhase(mu, g))) << mu << " " << g;
        ASSERT_GE(aerial::miePhase(mu, g), 0.0);
    }
    aerial::AtmosphereParams air;
    for (int i = 0; i < 300; ++i) {
        air.rayleighScattering = glm::dvec3(s.pick(0, 1e-4, false));
        air.mieExtinction = glm::dvec3(s.pick(0, 1e-3, false));
        air.mieScattering = air.mieExtinction * 0.9;
        const glm::dvec3 t = aerial::transmittanceToSpace(air, s.pick(0, 60000, false), s.pick(-1, 1, false));
        ASSERT_TRUE(finite(t)) << t.x;
        ASSERT_GE(t.x, 0.0);
        ASSERT_LE(t.x, 1.0);
    }
}

TEST(NoNaN, SkySolverEdgeAtmospheres) {
    aerial::SkySolverDesc desc;
    desc.azimuthCount = 16;
    desc.elevationCount = 8;
    desc.layerCount = 8;
    desc.threadCount = 1;
    aerial::SkySolver solver(desc);
    struct Case {
        double scatteringScale, viewerHeight, sunElevationDeg;
    };
    const Case cases[] = {{0.0, 0.0, 30.0},     {1.0, 0.0, -5.0},        {1.0, 0.0, -90.0},
                          {1.0, 0.0, 90.0},     {1e4, 0.0, 10.0},        {1e6, 0.0, 0.0},
                          {1.0, 60000.0, 10.0}, {1.0, 59999.999, -30.0}, {1.0, 30000.0, 0.0}};
    const glm::dvec3 dirs[] = {{0, 1, 0}, {1, 0, 0}, {0, -1, 0}, {0.6, 0.8, 0}, {0, 0, 0}, {kNaN, 0, 1}};
    for (const Case& c : cases) {
        aerial::AtmosphereParams air;
        air.rayleighScattering *= c.scatteringScale;
        air.mieScattering *= c.scatteringScale;
        air.mieExtinction *= c.scatteringScale;
        air.viewerHeight = c.viewerHeight;
        const double el = c.sunElevationDeg * aerial::kPi / 180.0;
        solver.solve(air, glm::dvec3(std::cos(el), std::sin(el), 0.0));
        const aerial::SkyTable& table = solver.table();
        for (float v : table.rayleigh) ASSERT_TRUE(std::isfinite(v) && v >= 0.0f) << c.scatteringScale;
        for (float v : table.mie) ASSERT_TRUE(std::isfinite(v) && v >= 0.0f) << c.scatteringScale;
        ASSERT_TRUE(finite(table.horizonRayleigh) && finite(table.horizonMie));
        for (const glm::dvec3& d : dirs) {
            ASSERT_TRUE(finite(aerial::skyRadiance(table, 0.8, d, glm::dvec3(20.0))));
            ASSERT_TRUE(finite(aerial::horizonFogRadiance(table, 0.8, d, glm::dvec3(20.0))));
        }
        if (c.scatteringScale == 0.0) {
            for (float v : table.rayleigh) ASSERT_EQ(v, 0.0f);
        }
    }
}

aerial::FogVolume randomVolume(Sweep& s, int index) {
    aerial::FogVolume v;
    char id[16];
    std::snprintf(id, sizeof id, "v%d", index);
    v.id = id;
    v.shape = index % 2 ? aerial::FogVolumeShape::Ellipsoid : aerial::FogVolumeShape::Box;
    v.position = s.vec(-200, 200);
    const glm::dvec3 axis = s.direction();
    v.rotation = glm::angleAxis(s.pick(-3, 3, false), axis);
    if (index % 7 == 0) v.rotation = glm::dquat(s.pick(0, 2), s.pick(0, 2), s.pick(0, 2), s.pick(0, 2));
    v.halfExtents = s.vec(0, 100);
    v.density = s.pick(0, 0.1);
    v.falloff = s.pick(0, 1);
    v.gradientDirection = s.vec(-1, 1);
    v.gradientOffset = s.pick(-50, 50);
    v.colourMode = static_cast<aerial::FogColourMode>(index % 3);
    v.colour = s.vec(0, 2);
    return v;
}

aerial::Emitter randomEmitter(Sweep& s, int index) {
    aerial::Emitter e;
    char id[16];
    std::snprintf(id, sizeof id, "e%d", index);
    e.id = id;
    e.kind = index % 2 ? aerial::EmitterKind::Lightning : aerial::EmitterKind::Point;
    e.position = s.vec(-200, 200);
    e.intensity = s.pick(0, 10);
    e.attenuation = s.pick(0, 1);
    e.colour = s.vec(0, 2);
    e.seed = static_cast<std::uint32_t>(s.rng()());
    e.flashesPerMinute = s.pick(0, 60);
    e.flashDurationSeconds = s.pick(0, 2);
    e.timeScale = s.pick(0, 3600);
    return e;
}

TEST(NoNaN, FogVolumesEmittersAndHeightFog) {
    Sweep s(3);
    for (int i = 0; i < 20000; ++i) {
        const glm::dvec3 o = s.vec(-300, 300), d = s.vec(-500, 500);
        aerial::HeightFogParams fog;
        fog.density = s.pick(0, 0.1);
        fog.falloff = s.pick(0, 1);
        fog.baseHeight = s.pick(-100, 100);
        const double tau = aerial::heightFogOpticalDepth(fog, o, d);
        ASSERT_TRUE(finite(tau)) << i;
        ASSERT_GE(tau, 0.0);
        ASSERT_TRUE(finite(aerial::oneMinusExpOverX(s.pick(-1000, 1000))));

        const aerial::FogVolume v = randomVolume(s, i);
        const double len = glm::length(d);
        const aerial::VolumeSegment seg = aerial::intersectFogVolume(v, o, d, s.pick(0, 2));
        ASSERT_TRUE(finite(seg.tIn) && finite(seg.tOut));
        const double vtau = aerial::fogVolumeOpticalDepth(v, o, d, seg);
        ASSERT_TRUE(finite(vtau) && vtau >= 0.0) << i << " " << len;
        ASSERT_TRUE(finite(aerial::fogVolumeDensityAt(v, o)));

        const aerial::Emitter e = randomEmitter(s, i);
        ASSERT_TRUE(finite(aerial::emitterInScatter(e, o, d, 1.0))) << i;
        ASSERT_TRUE(finite(aerial::emitterIntegral(e, o, d)));
        const double flash = aerial::lightningFlash(e, s.pick(0, 24));
        ASSERT_TRUE(finite(flash) && flash >= 0.0 && flash <= 1.0);
    }
}

TEST(NoNaN, FogSceneQueries) {
    Sweep s(4);
    for (int scene = 0; scene < 20; ++scene) {
        aerial::FogSceneDesc desc;
        desc.heightFog.density = s.pick(0, 0.05);
        desc.heightFog.falloff = s.pick(0, 0.5);
        desc.heightFog.baseHeight = s.pick(-10, 10);
        for (int i = 0; i < 40; ++i) desc.volumes.push_back(randomVolume(s, i));
        for (int i = 0; i < 6; ++i) desc.emitters.push_back(randomEmitter(s, i));
        desc.lights[0] = {s.direction(), glm::dvec3(20.0), glm::dvec3(s.pick(0, 1)),
                          glm::dvec3(s.pick(0, 1))};
        desc.lights[1] = {glm::dvec3(0, 0, 0), glm::dvec3(s.pick(0, 1)), glm::dvec3(0.1), glm::dvec3(0.1)};
        desc.mieAnisotropy = s.pick(-0.999, 0.999, false);
        desc.lights[0].reaching = glm::dvec3(s.pick(0, 20), s.pick(0, 20), s.pick(0, 20));
        desc.lights[1].reaching = glm::dvec3(s.pick(0, 1));
        desc.skyLight.l0 = glm::dvec3(s.pick(0, 1), s.pick(0, 1), s.pick(0, 1));
        for (glm::dvec3& l1 : desc.skyLight.l1) l1 = glm::dvec3(s.pick(-1, 1), s.pick(-1, 1), s.pick(-1, 1));
        desc.directVisibility = s.pick(0, 1);
        desc.horizonDistance = s.pick(0, 1e4);
        const aerial::FogScene fog(desc);
        std::vector<aerial::VolumeContribution> parts;
        std::vector<aerial::FogSegment> batch;
        for (int q = 0; q < 500; ++q) {
            const glm::dvec3 from = s.vec(-300, 300);
            const glm::dvec3 to = q % 10 == 0 ? from : s.vec(-300, 300);  // zero-length segments too
            batch.push_back({from, to});
            const aerial::FogQueryResult r = fog.query(from, to, parts);
            ASSERT_TRUE(finite(r.transmittance) && finite(r.inScatter)) << scene << " " << q;
            for (int c = 0; c < 3; ++c) {
                ASSERT_GE(r.transmittance[c], 0.0);
                ASSERT_LE(r.transmittance[c], 1.0);
            }
            for (const aerial::VolumeContribution& p : parts)
                ASSERT_TRUE(finite(p.opticalDepth) && finite(p.colour));
            ASSERT_TRUE(finite(fog.fogColour(s.vec(-1, 1))));
            ASSERT_TRUE(finite(fog.fogColour(s.vec(-1, 1), s.pick(0, 1e5))));
        }
        std::vector<aerial::FogQueryResult> results(batch.size());
        fog.queryBatch(batch.data(), results.data(), batch.size());
        for (const aerial::FogQueryResult& r : results)
            ASSERT_TRUE(finite(r.transmittance) && finite(r.inScatter));
    }
}

}  // namespace
