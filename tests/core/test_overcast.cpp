// test_overcast.cpp — the light under the cloud deck (CloudOvercast in
// aerial/clouds.hpp, OvercastLight and fogSceneDesc in aerial/evaluate.hpp,
// the fog colour in FogScene): the covers against an independent fine
// quadrature of the reference march over the hemisphere and the horizon
// band, the deck's radiance and the ambient against their closed forms, and
// a clear sky left exactly as it was.
#include <aerial/clouds.hpp>
#include <aerial/evaluate.hpp>
#include <aerial/fog_query.hpp>
#include <aerial/sky.hpp>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace aerial {
namespace {

constexpr double kRg = 6360000.0;

CloudParams brokenLayer(double coverage) {
    CloudParams p;
    p.coverage = coverage;
    p.bottomM = 1500.0;
    p.thicknessM = 2000.0;
    p.densityPerM = 0.02;
    p.type = 0.7;
    return p;
}

/// 1 - the mean transmittance from the origin by an independent midpoint
/// quadrature: over the upper hemisphere cosine-weighted (`horizon` false;
/// nz rings uniform in sin^2 of the zenith angle) or over elevations 1..11
/// deg (uniform in elevation), na azimuths each, with the reference march
/// (kCloudReferenceSteps, itself checked against a fine quadrature in
/// test_clouds.cpp). Also the cover-weighted vertical optical depth.
struct Cover {
    double cover = 0.0, depth = 0.0;
};
Cover referenceCover(const CloudField& f, bool horizon, int nz, int na) {
    double transmitted = 0.0, depth = 0.0, weight = 0.0;
    for (int i = 0; i < nz; ++i) {
        double cosT, sinT;
        if (horizon) {
            const double el = (1.0 + 10.0 * (i + 0.5) / nz) * kPi / 180.0;
            cosT = std::sin(el), sinT = std::cos(el);
        } else {
            const double s2 = (i + 0.5) / nz;
            sinT = std::sqrt(s2), cosT = std::sqrt(1.0 - s2);
        }
        for (int j = 0; j < na; ++j) {
            const double phi = 2.0 * kPi * (j + 0.25) / na;  // not the library's azimuths
            const glm::dvec3 d(sinT * std::sin(phi), cosT, -sinT * std::cos(phi));
            const double tau = cloudOpticalDepth(f, glm::dvec3(0.0), d);
            transmitted += std::exp(-tau);
            depth += (1.0 - std::exp(-tau)) * tau * cosT;
            weight += 1.0 - std::exp(-tau);
        }
    }
    return {1.0 - transmitted / (nz * na), weight > 0.0 ? depth / weight : 0.0};
}

TEST(CloudOvercast, NothingWithoutClouds) {
    const CloudOvercast o = cloudOvercast(prepareClouds(brokenLayer(0.0), {}, 12.0, kRg));
    EXPECT_EQ(o.skyCover, 0.0);
    EXPECT_EQ(o.horizonCover, 0.0);
    EXPECT_EQ(o.opticalDepth, 0.0);
    EXPECT_EQ(o.diffuseTransmittance, 1.0);
}

// The library's 64 + 64 rays against 48 x 96 (hemisphere) and 20 x 180
// (horizon band) rays of the reference march, at three moments of the wind
// and three coverages. Tolerance 0.05 in cover (the stratified 64 rays see
// cells of a few km from below; measured worst printed), 15% in depth.
TEST(CloudOvercast, CoversAgainstAFineQuadrature) {
    double worstSky = 0.0, worstHorizon = 0.0, worstDepth = 0.0;
    for (double coverage : {0.3, 0.6, 0.9}) {
        for (double hours : {8.0, 12.5, 17.0}) {
            const CloudField f = prepareClouds(brokenLayer(coverage), {}, hours, kRg);
            const CloudOvercast o = cloudOvercast(f);
            const Cover sky = referenceCover(f, false, 48, 96);
            const Cover horizon = referenceCover(f, true, 20, 180);
            EXPECT_NEAR(o.skyCover, sky.cover, 0.05) << coverage << " at " << hours << " h";
            EXPECT_NEAR(o.horizonCover, horizon.cover, 0.05) << coverage << " at " << hours << " h";
            EXPECT_NEAR(o.opticalDepth, sky.depth, 0.15 * sky.depth) << coverage << " at " << hours << " h";
            EXPECT_DOUBLE_EQ(o.diffuseTransmittance, 1.0 / (1.0 + 0.75 * 0.15 * o.opticalDepth));
            worstSky = std::max(worstSky, std::abs(o.skyCover - sky.cover));
            worstHorizon = std::max(worstHorizon, std::abs(o.horizonCover - horizon.cover));
            worstDepth = std::max(worstDepth, std::abs(o.opticalDepth / sky.depth - 1.0));
            // Through the layer's long slant a broken deck hides more of the
            // horizon than of the sky overhead.
            EXPECT_GE(horizon.cover, sky.cover - 1e-9);
            EXPECT_GT(sky.cover, 0.05);  // the test saw clouds
        }
    }
    std::printf("[ overcast ] worst |cover - reference|: sky %.4f, horizon %.4f; optical depth %.1f%%\n",
                worstSky, worstHorizon, 100.0 * worstDepth);
}

TEST(CloudOvercast, RadianceIsTheDiffuselyTransmittedLight) {
    CloudOvercast o;
    o.skyCover = 0.7;
    o.diffuseTransmittance = 0.3;
    const glm::dvec3 l = overcastRadiance(o, {0.9, 0.95, 1.0}, {10.0, 20.0, 30.0});
    EXPECT_DOUBLE_EQ(l.x, 0.9 * 0.3 * 10.0 / kPi);
    EXPECT_DOUBLE_EQ(l.y, 0.95 * 0.3 * 20.0 / kPi);
    EXPECT_DOUBLE_EQ(l.z, 1.0 * 0.3 * 30.0 / kPi);
    // Bad input: finite, never negative.
    o.diffuseTransmittance = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const glm::dvec3 bad = overcastRadiance(o, {-1.0, inf, 0.5}, {inf, -3.0, std::nan("")});
    for (int c = 0; c < 3; ++c) {
        EXPECT_TRUE(std::isfinite(bad[c]));
        EXPECT_GE(bad[c], 0.0);
    }
}

/// A noon state under a broken deck, with its sky solved.
struct CloudyNoon {
    PresetState state;
    SkySolver sun, moon;
    explicit CloudyNoon(double coverage) {
        state = CompiledPreset().evaluate(12.0);
        state.environment.clouds = brokenLayer(coverage);
        sun.solve(state.environment.atmosphere, state.sunLight.body.direction);
        moon.solve(state.environment.atmosphere, state.moonLight.body.direction);
    }
};

// What a mirror sees of the deck: the horizon band's cover for a level (or
// lower) direction, the whole sky's from 30 deg up, and in between the
// smoothstep (3 t^2 - 2 t^3 of t = y / 0.5) of the two.
TEST(CloudOvercast, CoverTowardsADirection) {
    CloudOvercast o;
    o.horizonCover = 0.9;
    o.skyCover = 0.5;
    EXPECT_DOUBLE_EQ(overcastCoverTowards(o, {1.0, 0.0, 0.0}), 0.9);
    EXPECT_DOUBLE_EQ(overcastCoverTowards(o, glm::normalize(glm::dvec3(1.0, -0.3, 0.0))), 0.9);
    EXPECT_DOUBLE_EQ(overcastCoverTowards(o, {0.0, 1.0, 0.0}), 0.5);
    EXPECT_NEAR(overcastCoverTowards(o, {std::sqrt(0.75), 0.5, 0.0}), 0.5, 1e-15);
    const double y = 0.2, t = y / 0.5, smooth = t * t * (3.0 - 2.0 * t);  // 0.352
    EXPECT_NEAR(overcastCoverTowards(o, {std::sqrt(1.0 - y * y), y, 0.0}), 0.9 - 0.4 * smooth, 1e-15);
    EXPECT_DOUBLE_EQ(overcastCoverTowards(CloudOvercast{}, {0.0, 1.0, 0.0}), 0.0);  // no clouds: none
}

TEST(OvercastLight, ClearSkyUnchanged) {
    CloudyNoon noon(0.0);
    const OvercastLight o = overcastLight(noon.state, noon.sun.table(), noon.moon.table());
    const double g = noon.state.environment.atmosphere.mieAnisotropy;
    const glm::dvec3 clear = skyIrradiance(noon.sun.table(), g, noon.state.sunLight.illuminanceSpace) +
                             skyIrradiance(noon.moon.table(), g, noon.state.moonLight.illuminanceSpace);
    EXPECT_EQ(o.clearSkyIrradiance, clear);
    EXPECT_EQ(o.groundIrradiance, clear);
    EXPECT_EQ(o.radiance, glm::dvec3(0.0));
    const FogSceneDesc d = fogSceneDesc(noon.state, noon.sun.table(), noon.moon.table());
    EXPECT_EQ(d.overcastCover, 0.0);
    EXPECT_EQ(d.overcastRadiance, glm::dvec3(0.0));
    EXPECT_GT(clear.z, clear.x);  // a blue sky
}

TEST(OvercastLight, DeckLitByTheSunAndTheSkyAndTheGroundBelowIt) {
    CloudyNoon noon(0.6);
    const OvercastLight o = overcastLight(noon.state, noon.sun.table(), noon.moon.table());
    ASSERT_GT(o.overcast.skyCover, 0.1);
    // The light on the deck's top as the deck passes it on: the sun and the
    // moon on a horizontal surface (0 below the horizon) and the clear sky,
    // each beam at zenith cosine mu weighted by the Eddington factor 1/2 + 3/4
    // mu. The sky's weighted integral by an independent 90 x 180 midpoint
    // quadrature of skyRadiance.
    const LightState& s = noon.state.sunLight;
    const LightState& m = noon.state.moonLight;
    auto beam = [](const LightState& l) {
        const double mu = std::max(l.body.direction.y, 0.0);
        return l.illuminance * mu * (0.5 + 0.75 * mu);
    };
    const double g = noon.state.environment.atmosphere.mieAnisotropy;
    glm::dvec3 sky(0.0);
    for (int i = 0; i < 90; ++i) {
        const double mu = (i + 0.5) / 90.0;  // uniform in mu: d omega = d mu d phi
        for (int j = 0; j < 180; ++j) {
            const double phi = 2.0 * kPi * (j + 0.5) / 180.0, r = std::sqrt(1.0 - mu * mu);
            const glm::dvec3 v(r * std::sin(phi), mu, -r * std::cos(phi));
            const glm::dvec3 w = (mu * (0.5 + 0.75 * mu) * (1.0 / 90.0) * (2.0 * kPi / 180.0)) *
                                 (skyRadiance(noon.sun.table(), g, v, s.illuminanceSpace) +
                                  skyRadiance(noon.moon.table(), g, v, m.illuminanceSpace));
            sky += w;
        }
    }
    const glm::dvec3 top = beam(s) + beam(m) + sky;
    const glm::dvec3 albedo = noon.state.environment.clouds.albedo;
    const double c = o.overcast.skyCover;
    for (int k = 0; k < 3; ++k) {
        // The library's 64 x 16 grid against the fine one: 1%.
        EXPECT_NEAR(o.radiance[k], albedo[k] * o.overcast.diffuseTransmittance * top[k] / kPi,
                    0.01 * o.radiance[k]);
        EXPECT_NEAR(o.groundIrradiance[k], (1.0 - c) * o.clearSkyIrradiance[k] + c * kPi * o.radiance[k],
                    1e-12 * o.groundIrradiance[k]);
        // The deck passes on no more than falls on it.
        EXPECT_LE(kPi * o.radiance[k], top[k]);
    }
    // Under a noon deck the light is whiter than the blue sky's.
    const glm::dvec3 clear = o.clearSkyIrradiance;
    EXPECT_LT(o.groundIrradiance.z / o.groundIrradiance.x, clear.z / clear.x);
}

TEST(OvercastLight, FogColourIsTheBlendOfTheSkyAndTheDeck) {
    CloudyNoon noon(0.6);
    const FogSceneDesc under = fogSceneDesc(noon.state, noon.sun.table(), noon.moon.table());
    const OvercastLight o = overcastLight(noon.state, noon.sun.table(), noon.moon.table());
    EXPECT_EQ(under.overcastCover, o.overcast.horizonCover);
    EXPECT_EQ(under.overcastRadiance, o.radiance);
    ASSERT_GT(under.overcastCover, 0.2);
    FogSceneDesc clearDesc = under;
    clearDesc.overcastCover = 0.0;
    const FogScene fog(under), clear(clearDesc);
    const double c = under.overcastCover;
    for (double az : {0.0, 1.0, 2.0, 3.0, 4.0, 5.0}) {
        for (double y : {0.0, 0.1, 0.5, 1.0}) {
            const glm::dvec3 v(std::sin(az), y, -std::cos(az));
            const glm::dvec3 a = clear.fogColour(v), b = fog.fogColour(v);
            for (int k = 0; k < 3; ++k)
                EXPECT_NEAR(b[k], (1.0 - c) * a[k] + c * o.radiance[k], 1e-12 * (a[k] + o.radiance[k]));
        }
    }
    // In the custom colour mode the colour is the artist's, deck or not.
    FogSceneDesc custom = under;
    custom.heightFogColourMode = FogColourMode::Custom;
    custom.heightFogColour = {0.2, 0.3, 0.4};
    custom.heightFog = {0.01, 0.0, 0.0};
    custom.volumes.clear();
    custom.emitters.clear();
    const FogQueryResult r = FogScene(custom).query({0, 10, 0}, {0, 10, -100});
    const double t = std::exp(-0.01 * 100.0);
    EXPECT_NEAR(r.inScatter.x, 0.2 * (1.0 - t), 1e-9);
    EXPECT_NEAR(r.inScatter.z, 0.4 * (1.0 - t), 1e-9);
}

}  // namespace
}  // namespace aerial
