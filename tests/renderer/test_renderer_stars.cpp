// test_renderer_stars.cpp — the sky pass's stars against a CPU copy of
// sky.glsl's starRadiance (same hash, cells, Gaussian and air mass, in
// double precision) per pixel; the Kasten-Young dimming against the exact
// slant transmittance of core; the night fade; stars hidden by a zero
// illuminance and by the scene.
#include "gl_fixture.hpp"

#include <aerial/atmosphere.hpp>
#include <aerial/evaluate.hpp>
#include <aerial/night_sky.hpp>
#include <aerial/preset.hpp>
#include <aerial/sun.hpp>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace aerial::test {
namespace {

constexpr int kStarsWidth = 160;
constexpr int kStarsHeight = 90;
constexpr double kTwoPi = 6.28318530717958647692;

// sky.glsl's constants (float on the GPU).
constexpr std::uint32_t kStarColumns = 1024u;
constexpr std::uint32_t kStarRows = 512u;
constexpr double kStarProbability = double(0.016f);

std::uint32_t starHash(std::uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}
double starUnit(std::uint32_t h) { return double(h >> 8) * (1.0 / 16777216.0); }

double airMass(double mu) {
    const double zenithDeg = std::acos(std::clamp(mu, 0.0, 1.0)) * 180.0 / (kTwoPi / 2.0);
    return 1.0 / (mu + 0.50572 * std::pow(96.07995 - zenithDeg, -1.6364));
}

/// What the sky pass's stars read from a state: the brightest star's
/// illuminance (kStarIlluminance times the night fade), the celestial frame
/// and the zenith transmittance.
struct StarSky {
    double starIlluminance = 0.0;
    CelestialFrame celestial;
    glm::dvec3 zenithTransmittance{1.0};
};

StarSky starSky(const PresetState& state) {
    return {renderer::kStarIlluminance * renderer::starVisibility(state.sunLight.body.elevation),
            celestialFrame(state.environment.location, state.timeHours), state.zenithTransmittance};
}

/// The CPU copy of sky.glsl's starRadiance.
glm::dvec3 starRadiance(const glm::dvec3& v, const StarSky& air, double sigma) {
    if (!(air.starIlluminance > 0.0) || v.y <= 0.0) return glm::dvec3(0.0);
    const glm::dvec3 c(glm::dot(v, air.celestial.equatorX), glm::dot(v, air.celestial.equatorY),
                       glm::dot(v, air.celestial.pole));
    double u = std::atan2(c.y, c.x) / kTwoPi + 1.0;
    u -= std::floor(u);
    const double z = std::clamp(c.z, -1.0, 1.0);
    const int column = int(std::min(u * kStarColumns, double(kStarColumns - 1)));
    const int row = int(std::min((z * 0.5 + 0.5) * kStarRows, double(kStarRows - 1)));
    glm::dvec3 sum(0.0);
    for (int dj = -1; dj <= 1; ++dj) {
        const int j = row + dj;
        if (j < 0 || j >= int(kStarRows)) continue;
        for (int di = -1; di <= 1; ++di) {
            const std::uint32_t i = std::uint32_t(column + di + int(kStarColumns)) % kStarColumns;
            const std::uint32_t h = starHash(std::uint32_t(j) * kStarColumns + i + 0x5bd1e995u);
            if (starUnit(h) >= kStarProbability) continue;
            const std::uint32_t h1 = starHash(h), h2 = starHash(h1), h3 = starHash(h2), h4 = starHash(h3);
            const double ra = kTwoPi * (i + 0.15 + 0.7 * starUnit(h1)) / kStarColumns;
            const double sinDec = (j + 0.15 + 0.7 * starUnit(h2)) / kStarRows * 2.0 - 1.0;
            const double cosDec = std::sqrt(std::max(1.0 - sinDec * sinDec, 0.0));
            const glm::dvec3 s(cosDec * std::cos(ra), cosDec * std::sin(ra), sinDec);
            const glm::dvec3 d = c - s;
            const double weight =
                std::pow(starUnit(h3), 6.0) * std::exp(-glm::dot(d, d) / (2.0 * sigma * sigma));
            const glm::dvec3 tint =
                glm::mix(glm::dvec3(1.0, 0.82, 0.64), glm::dvec3(0.72, 0.84, 1.0), starUnit(h4));
            sum += weight * tint;
        }
    }
    const double m = airMass(v.y);
    const glm::dvec3 t(std::pow(air.zenithTransmittance.x, m), std::pow(air.zenithTransmittance.y, m),
                       std::pow(air.zenithTransmittance.z, m));
    return sum * (air.starIlluminance / (kTwoPi * sigma * sigma)) * t;
}

class Stars : public GlTest {
protected:
    /// A moonless night: no sun or moon light, only stars.
    static PresetState night(double timeHours) {
        PresetState air;
        air.sunLight.illuminance = air.sunLight.illuminanceSpace = glm::dvec3(0.0);
        air.moonLight.illuminance = air.moonLight.illuminanceSpace = glm::dvec3(0.0);
        air.sunLight.body.elevation = -0.5;  // below -10 deg: every star (kStarIlluminance)
        air.environment.fog.density = 0.0;
        air.environment.location = Location{};
        air.timeHours = timeHours;  // the celestial frame: celestialFrame(Location{}, timeHours)
        air.zenithTransmittance =
            transmittanceToSpace(AtmosphereParams{}, AtmosphereParams{}.viewerHeight, 1.0);
        return air;
    }
    static renderer::Camera camera(const glm::dvec3& target, double fov) {
        renderer::Camera c;
        c.eye = {0.0, 2.0, 0.0};
        c.target = c.eye + target;
        c.verticalFov = fov;
        c.aspect = double(kStarsWidth) / kStarsHeight;
        return c;
    }
    static renderer::Image render(renderer::Renderer& r, const renderer::Camera& c, const PresetState& air,
                                  bool scene = false, bool stars = true) {
        renderer::FrameDesc f;
        f.stars = stars;
        f.sunDiscRadius = f.moonDiscRadius = 0.0;
        f.width = kStarsWidth;
        f.height = kStarsHeight;
        f.precision = renderer::ColourPrecision::Float;
        f.passes.scene = scene;
        f.passes.globalFog = f.passes.volumes = f.passes.emitters = false;
        f.passes.transparent = f.passes.particles = false;
        r.render(c, air, f);
        return r.readColour();
    }
};

// Every pixel against the CPU copy: |GPU - CPU| <= 1e-3 of a brightest
// star's peak radiance E / (2 pi sigma^2). Three views (zenith, mid sky,
// near the horizon) and two times; at least 20 star pixels in all, so the
// comparison is not of two black images.
TEST_F(Stars, EveryPixelMatchesTheCpuCopy) {
    renderer::Renderer r(rendererDesc());
    ASSERT_TRUE(r.valid()) << r.error();
    const double fov = 0.2;  // narrow: sigma = 0.6 px = 0.00133 rad (below the 0.0015 cap)
    const double sigma = std::min(0.6 * fov / kStarsHeight, 0.0015);
    int starPixels = 0;
    double worst = 0.0;
    for (double t : {1.0, 4.5}) {
        const PresetState air = night(t);
        const StarSky stars = starSky(air);
        ASSERT_EQ(stars.starIlluminance, renderer::kStarIlluminance);
        const double peak = stars.starIlluminance / (kTwoPi * sigma * sigma);
        for (const glm::dvec3& look :
             {glm::dvec3(0.01, 1.0, 0.0), glm::dvec3(0.3, 0.5, -1.0), glm::dvec3(-1.0, 0.12, 0.2)}) {
            const renderer::Camera cam = camera(glm::normalize(look), fov);
            const renderer::Image img = render(r, cam, air);
            const renderer::CameraFrame cf = renderer::cameraFrame(cam);
            for (int y = 0; y < kStarsHeight; ++y) {
                for (int x = 0; x < kStarsWidth; ++x) {
                    const glm::dvec3 v =
                        glm::normalize(renderer::farRayAtPixel(cf, x, y, kStarsWidth, kStarsHeight));
                    // The stars and the airglow (core's reference; the night fade is 1 here).
                    const glm::dvec3 cpu =
                        starRadiance(v, stars, sigma) + airglowRadiance(v, air.zenithTransmittance);
                    for (int ch = 0; ch < 3; ++ch) {
                        const double gpu = img.at(x, y, ch);
                        ASSERT_TRUE(std::isfinite(gpu));
                        worst = std::max(worst, std::abs(gpu - cpu[ch]) / peak);
                    }
                    if (cpu.g > 1e-2 * peak) ++starPixels;
                }
            }
        }
    }
    std::printf("stars: %d pixels above 1%% of the peak; worst |GPU - CPU| = %.2e of the peak\n", starPixels,
                worst);
    EXPECT_GE(starPixels, 20);
    EXPECT_LE(worst, 1e-3);
}

// The Kasten-Young dimming T_zenith^X(z) against core's exact slant
// transmittance (double quadrature through the spherical atmosphere), default
// atmosphere: within 2 % from the zenith down to 10 deg elevation (measured
// 0.0 / 0.06 / 1.5 % at 90 / 30 / 10 deg); 20 % at 3 deg (measured 16.5 %,
// green), where the ozone and aerosol layers' own air masses differ from the
// single formula and T is already ~0.1.
TEST(StarsAirMass, FollowsTheExactSlantTransmittance) {
    const AtmosphereParams air;
    const glm::dvec3 zenith = transmittanceToSpace(air, air.viewerHeight, 1.0);
    for (double elevationDeg : {90.0, 60.0, 30.0, 10.0, 3.0}) {
        const double mu = std::sin(elevationDeg * kTwoPi / 360.0);
        const glm::dvec3 exact = transmittanceToSpace(air, air.viewerHeight, mu);
        const double m = airMass(mu);
        for (int ch = 0; ch < 3; ++ch) {
            const double approx = std::pow(zenith[ch], m);
            const double tolerance = elevationDeg >= 10.0 ? 0.02 : 0.20;
            std::printf("elevation %4.0f deg channel %d: T exact %.4f, T_zenith^X %.4f (%+.2f %%)\n",
                        elevationDeg, ch, exact[ch], approx, 100.0 * (approx / exact[ch] - 1.0));
            EXPECT_NEAR(approx / exact[ch], 1.0, tolerance) << elevationDeg << " deg, channel " << ch;
        }
    }
}

// The night fade and the frame a preset state gives: no stars by day, all
// of them at night, nothing where the scene covers the sky or with zero
// illuminance.
TEST_F(Stars, FadeWithTheSunAndHideBehindTheScene) {
    EXPECT_EQ(renderer::starVisibility(5.0 * kTwoPi / 360.0), 0.0);
    EXPECT_EQ(renderer::starVisibility(-12.0 * kTwoPi / 360.0), 1.0);
    EXPECT_NEAR(renderer::starVisibility(-4.0 * kTwoPi / 360.0), 0.5, 1e-12);
    const CompiledPreset preset;  // the default preset
    EXPECT_EQ(starSky(preset.evaluate(12.0)).starIlluminance, 0.0);
    const PresetState midnight = preset.evaluate(0.0);
    ASSERT_LT(midnight.sunLight.body.elevation, -12.0 * kTwoPi / 360.0);
    const StarSky air = starSky(midnight);
    EXPECT_EQ(air.starIlluminance, renderer::kStarIlluminance);
    const AtmosphereParams& atmosphere = midnight.environment.atmosphere;
    const glm::dvec3 zenith = transmittanceToSpace(atmosphere, atmosphere.viewerHeight, 1.0);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(air.zenithTransmittance[c], zenith[c], 5e-4);  // tabulated in evaluate
    EXPECT_NEAR(glm::dot(air.celestial.pole, midnight.sunLight.body.direction),
                std::sin(solarDeclination(midnight.environment.location.dayOfYear)), 1e-12);

    renderer::Renderer r(rendererDesc());
    ASSERT_TRUE(r.valid()) << r.error();
    const renderer::Camera up = camera({0.01, 1.0, 0.0}, 0.2);
    const renderer::Image none = render(r, up, night(1.0), false, false);  // FrameDesc::stars off
    double maxValue = 0.0;
    for (int y = 0; y < kStarsHeight; ++y)
        for (int x = 0; x < kStarsWidth; ++x) maxValue = std::max(maxValue, double(none.at(x, y, 1)));
    EXPECT_EQ(maxValue, 0.0);

    // A wall in front of the camera covers every star.
    renderer::SceneDesc wall;
    wall.meshes.push_back(
        renderer::makeBoxMesh({0.0, 2.0, -5.0}, {50.0, 50.0, 0.5}, glm::dquat(1, 0, 0, 0), glm::dvec3(0.0)));
    r.setScene(wall);
    const renderer::Image covered = render(r, camera({0.0, 0.0, -1.0}, 0.2), night(1.0), true);
    maxValue = 0.0;
    for (int y = 0; y < kStarsHeight; ++y)
        for (int x = 0; x < kStarsWidth; ++x) maxValue = std::max(maxValue, double(covered.at(x, y, 1)));
    // The black wall reflects only the airglow's ambient (~4e-7), far below
    // a star's peak (~0.2 here).
    EXPECT_LT(maxValue, 1e-5);
}

}  // namespace
}  // namespace aerial::test
