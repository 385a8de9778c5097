// test_night_sky.cpp — airglow (aerial/night_sky.hpp) against closed forms
// and an independent quadrature: the van Rhijn factor of a thin shell, the
// Kasten-Young air mass, and the irradiance as a fine Simpson integral over
// the elevation angle (not the library's midpoint rule in mu).
#include <aerial/exposure.hpp>
#include <aerial/night_sky.hpp>
#include <aerial/stars.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(NightSky, VanRhijnAndAirMassClosedForms) {
    EXPECT_DOUBLE_EQ(aerial::airglowVanRhijn(1.0), 1.0);
    const double r = 6360.0 / 6450.0;
    EXPECT_NEAR(aerial::airglowVanRhijn(0.0), 1.0 / std::sqrt(1.0 - r * r), 1e-12);  // ~6 at the horizon
    EXPECT_NEAR(aerial::airglowVanRhijn(0.5), 1.0 / std::sqrt(1.0 - r * r * 0.75), 1e-12);
    EXPECT_NEAR(aerial::relativeAirMass(1.0), 1.0, 3e-4);
    EXPECT_NEAR(aerial::relativeAirMass(0.5), 1.0 / (0.5 + 0.50572 * std::pow(96.07995 - 60.0, -1.6364)),
                1e-9);
    EXPECT_NEAR(aerial::relativeAirMass(0.0), 38.0, 0.2);  // Kasten-Young at the horizon
}

TEST(NightSky, RadianceFollowsTheModelAndIsZeroBelowTheHorizon) {
    const glm::dvec3 t(0.7, 0.8, 0.9);
    // L0 V(mu) (T + f (1 - T)), T = T_zenith^X(mu).
    const auto seen = [](double direct) {
        return direct + aerial::kAirglowScatteredFill * (1.0 - direct);
    };
    const glm::dvec3 zenith = aerial::airglowRadiance({0.0, 1.0, 0.0}, t);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(zenith[c],
                    aerial::kAirglowZenithRadiance[c] * seen(std::pow(t[c], aerial::relativeAirMass(1.0))),
                    1e-20);
    const glm::dvec3 low = aerial::airglowRadiance({0.0, 0.2, 0.9798}, t);  // not unit: normalised
    const double mu = 0.2 / std::sqrt(0.04 + 0.9798 * 0.9798);
    EXPECT_NEAR(low.y,
                aerial::kAirglowZenithRadiance.y * aerial::airglowVanRhijn(mu) *
                    seen(std::pow(0.8, aerial::relativeAirMass(mu))),
                1e-20);
    EXPECT_EQ(aerial::airglowRadiance({0.0, -0.1, 1.0}, t), glm::dvec3(0.0));
    EXPECT_EQ(aerial::airglowRadiance({std::nan(""), 1.0, 0.0}, t), glm::dvec3(0.0));
    const double inf = std::numeric_limits<double>::infinity();
    const glm::dvec3 junk = aerial::airglowRadiance({0.0, 1.0, 0.0}, {inf, -1.0, std::nan("")});
    EXPECT_TRUE(std::isfinite(junk.x) && std::isfinite(junk.y) && std::isfinite(junk.z));
}

TEST(NightSky, IrradianceIsTheCosineWeightedIntegral) {
    // Simpson's rule over the elevation e in [0, pi/2] with 20000 intervals:
    // E = 2 pi integral L(sin e) sin e cos e de.
    for (const glm::dvec3& t : {glm::dvec3(1.0), glm::dvec3(0.6, 0.75, 0.85)}) {
        const int n = 20000;
        glm::dvec3 sum(0.0);
        for (int i = 0; i <= n; ++i) {
            const double e = 0.5 * kPi * i / n;
            const double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
            sum +=
                w * aerial::airglowRadiance({std::cos(e), std::sin(e), 0.0}, t) * std::sin(e) * std::cos(e);
        }
        const glm::dvec3 reference = sum * (0.5 * kPi / n / 3.0) * (2.0 * kPi);
        const glm::dvec3 e = aerial::airglowIrradiance(t);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(e[c] / reference[c], 1.0, 1e-4) << c;
        // Without extinction the shell is brighter than a uniform sky of the
        // zenith radiance (pi L0) because of the van Rhijn factor.
        if (t == glm::dvec3(1.0)) {
            EXPECT_GT(e.y, kPi * aerial::kAirglowZenithRadiance.y);
        }
    }
}

// The dark sky as it is measured (Leinert et al. 1998; Benn and Ellison
// 1998): 21.6-22.0 mag/arcsec^2 in V at the zenith, L = 10.8e4 10^(-0.4 m)
// cd/m^2 = 1.7-2.5e-4 cd/m^2, through a clear sea-level zenith (T ~ 0.87 in
// green), and its horizon not an orange band: the colour near the horizon
// (2 deg up) keeps blue at least half of red, where extinction alone (T^38)
// leaves 1 %.
TEST(NightSky, ZenithAsMeasuredAndNoOrangeHorizon) {
    const glm::dvec3 t(0.905, 0.868, 0.830);  // the default air's zenith transmittance
    const double nits = aerial::kNitsPerRadianceUnit;
    const auto y = [](const glm::dvec3& c) { return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z; };
    const double zenith = y(aerial::airglowRadiance({0.0, 1.0, 0.0}, t)) * nits;
    EXPECT_GE(zenith, 10.8e4 * std::pow(10.0, -0.4 * 22.0)) << zenith;
    EXPECT_LE(zenith, 10.8e4 * std::pow(10.0, -0.4 * 21.6)) << zenith;
    const glm::dvec3 low = aerial::airglowRadiance({std::cos(0.035), std::sin(0.035), 0.0}, t);
    const glm::dvec3 top = aerial::airglowRadiance({0.0, 1.0, 0.0}, t);
    EXPECT_GT((low.z / low.x) / (top.z / top.x), 0.5);
    // Starlight and airglow together give 1-2 mlx outdoors; the natural sky
    // here (airglow, zodiacal light, unresolved stars) gives its share.
    const double lux = y(aerial::airglowIrradiance(t)) * nits;
    EXPECT_GE(lux, 0.5e-3) << lux;
    EXPECT_LE(lux, 2.0e-3) << lux;
}

// ---- Light pollution (night_sky.hpp, "Light pollution") ----

aerial::LightPollution cityGlow(double zenithNits, double azimuthDeg) {
    aerial::LightPollution glow;
    glow.zenithLuminance = zenithNits;
    glow.azimuthDeg = azimuthDeg;
    return glow;
}

glm::dvec3 dirAt(double elevationDeg, double azimuthDeg) {
    const double el = elevationDeg * kPi / 180.0, az = azimuthDeg * kPi / 180.0;
    return {std::cos(el) * std::sin(az), std::sin(el), -std::cos(el) * std::cos(az)};
}

double nits(const glm::dvec3& radiance) { return aerial::luminance(radiance) * aerial::kNitsPerRadianceUnit; }

TEST(LightPollution, ADomeOverTheCityOnTheHorizon) {
    const aerial::LightPollution glow = cityGlow(2e-3, 90.0);  // a suburb's glow, the city in the east
    EXPECT_NEAR(nits(aerial::lightPollutionRadiance(glow, {0, 1, 0}, 0.0)), 2e-3, 2e-3 * 1e-3);
    const double towards = nits(aerial::lightPollutionRadiance(glow, dirAt(2.0, 90.0), 0.0));
    const double away = nits(aerial::lightPollutionRadiance(glow, dirAt(2.0, 270.0), 0.0));
    std::printf("[ measured ] city glow at 2 deg: towards %.3g, away %.3g cd/m^2 (zenith 2e-3)\n", towards, away);
    EXPECT_GT(towards, 10.0 * 2e-3);
    EXPECT_GT(towards, 3.0 * away);
    EXPECT_GT(away, 2e-3);
    // The north offset turns the dome with the sky.
    EXPECT_NEAR(nits(aerial::lightPollutionRadiance(glow, dirAt(2.0, 180.0), 90.0)), towards, 1e-12);
    // Sodium is orange, LEDs near white; nothing below the horizon, nothing when off.
    const glm::dvec3 sodium = aerial::lightPollutionColour(aerial::LightPollutionLamps::Sodium);
    const glm::dvec3 led = aerial::lightPollutionColour(aerial::LightPollutionLamps::Led);
    EXPECT_GT(sodium.r, sodium.b * 2.0);
    EXPECT_LT(led.r / led.b, sodium.r / sodium.b);
    EXPECT_EQ(aerial::lightPollutionRadiance(glow, dirAt(-1.0, 90.0), 0.0), glm::dvec3(0.0));
    EXPECT_EQ(aerial::lightPollutionRadiance(cityGlow(0.0, 90.0), dirAt(20.0, 90.0), 0.0), glm::dvec3(0.0));
    EXPECT_EQ(aerial::lightPollutionIrradiance(cityGlow(0.0, 90.0)), glm::dvec3(0.0));
    EXPECT_EQ(aerial::lightPollutionRadiance(cityGlow(std::nan(""), 90.0), dirAt(20.0, 90.0), 0.0),
              glm::dvec3(0.0));
}

TEST(LightPollution, IrradianceIsTheCosineWeightedIntegral) {
    // Simpson over the elevation angle and the azimuth (not the library's
    // midpoint cells in mu).
    const aerial::LightPollution glow = cityGlow(5e-3, 30.0);
    constexpr int kElevations = 400, kAzimuths = 360;
    glm::dvec3 e(0.0);
    for (int j = 0; j <= kElevations; ++j) {
        const double h = 0.5 * kPi * j / kElevations;
        const double wj = (j == 0 || j == kElevations) ? 1.0 : (j % 2 ? 4.0 : 2.0);
        for (int i = 0; i < kAzimuths; ++i) {
            const double az = 2.0 * kPi * (i + 0.5) / kAzimuths;
            const glm::dvec3 v{std::cos(h) * std::sin(az), std::sin(h), -std::cos(h) * std::cos(az)};
            e += aerial::lightPollutionRadiance(glow, v, 0.0) *
                 (wj * std::sin(h) * std::cos(h) * (0.5 * kPi / kElevations / 3.0) * (2.0 * kPi / kAzimuths));
        }
    }
    const glm::dvec3 lib = aerial::lightPollutionIrradiance(glow);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(lib[c], e[c], 5e-3 * e[c]) << c;
}

TEST(LightPollution, ACitySkyHidesTheFaintStars) {
    // Bortle's scale: a city sky (class 8, ~18 mag/arcsec^2 = 6.8e-3 cd/m^2
    // at the zenith) shows stars to magnitude 4.5-5.0, a natural one (21.8
    // mag/arcsec^2) to 6.5 or more. Schaefer's model (stars.hpp) reads a
    // city ~0.5 mag darker than Bortle's observers: the tolerance is 0.75 mag.
    // The glow adds to the natural sky.
    const double natural = 2.1e-4;
    const aerial::LightPollution city = cityGlow(6.8e-3 - natural, 180.0);
    const double zenith = natural + nits(aerial::lightPollutionRadiance(city, {0, 1, 0}, 0.0));
    const double cityLimit = aerial::limitingMagnitude(zenith);
    const double naturalLimit = aerial::limitingMagnitude(natural);
    std::printf("[ measured ] limiting magnitude at the zenith: natural %.2f, city %.2f\n", naturalLimit, cityLimit);
    EXPECT_GE(cityLimit, 4.5 - 0.75);
    EXPECT_LE(cityLimit, 5.0 + 0.75);
    EXPECT_GT(naturalLimit, cityLimit + 1.0);
}

}  // namespace

