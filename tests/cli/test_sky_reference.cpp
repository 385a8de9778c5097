// test_sky_reference.cpp — core's brute-force sky reference
// (<aerial/sky_reference.hpp>, the ground truth `aerial sky` prints) against
// closed forms and against the independent test-support reference.
#include <aerial/atmosphere.hpp>
#include <aerial/sky_reference.hpp>

#include <gtest/gtest.h>

#include <cmath>

#include "sky_reference.hpp"  // tests/support: aerial::reference

namespace {

constexpr double kPi = 3.14159265358979323846;

glm::dvec3 direction(double elevationDeg, double azimuthDeg) {
    const double el = elevationDeg * kPi / 180.0, az = azimuthDeg * kPi / 180.0;
    return {std::cos(el) * std::sin(az), std::sin(el), -std::cos(el) * std::cos(az)};
}

void expectRelative(const glm::dvec3& got, const glm::dvec3& want, double tolerance, const char* what) {
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(got[c], want[c], tolerance * std::abs(want[c])) << what << " channel " << c;
}

// Looking straight up with the light at the zenith, every path viewer -> x ->
// light crosses the same column once: T(viewer -> x) T(x -> light) =
// exp(-tau(viewer..top)) for every x, so
//   I_k = beta_k * integral rho_k(h) dh * exp(-tau_total)
// with integral exp(-h/H) dh = H (exp(-h_v/H) - exp(-Z/H)) and the ozone
// tent's integral = width / 2 (when it lies above the viewer).
TEST(SkyReference, ZenithColumnHasAClosedForm) {
    for (double viewerHeight : {0.0, 2500.0}) {
        SCOPED_TRACE(viewerHeight);
        aerial::AtmosphereParams air;
        air.viewerHeight = viewerHeight;
        air.mieScattering = glm::dvec3(2.0e-5);
        air.mieExtinction = glm::dvec3(2.4e-5);
        const double top = air.atmosphereRadius - air.planetRadius;
        auto column = [&](double H) { return H * (std::exp(-viewerHeight / H) - std::exp(-top / H)); };
        const double rayleighColumn = column(air.rayleighScaleHeight);
        const double mieColumn = column(air.mieScaleHeight);
        const double ozoneColumn = 0.5 * air.ozoneWidth;
        const glm::dvec3 tau = air.rayleighScattering * rayleighColumn + air.mieExtinction * mieColumn +
                               air.ozoneAbsorption * ozoneColumn;
        const glm::dvec3 transmittance(std::exp(-tau.x), std::exp(-tau.y), std::exp(-tau.z));

        const aerial::SkySample s =
            aerial::referenceSkyIntegrals(air, glm::dvec3(0, 1, 0), glm::dvec3(0, 1, 0));
        expectRelative(s.rayleigh, air.rayleighScattering * rayleighColumn * transmittance, 1e-6, "rayleigh");
        expectRelative(s.mie, air.mieScattering * mieColumn * transmittance, 1e-6, "mie");
    }
}

TEST(SkyReference, EmptyAtmosphereAndFullShadowGiveZero) {
    aerial::AtmosphereParams empty;
    empty.rayleighScattering = empty.mieScattering = empty.mieExtinction = empty.ozoneAbsorption =
        glm::dvec3(0.0);
    const aerial::SkySample a = aerial::referenceSkyIntegrals(empty, direction(20, 30), direction(40, 0));
    EXPECT_EQ(a.rayleigh, glm::dvec3(0.0));
    EXPECT_EQ(a.mie, glm::dvec3(0.0));

    // Sun 30 deg below the horizon: the Earth's shadow reaches above 60 km
    // over the viewer (h > Rg (1 / cos 30 deg - 1) ~ 984 km), so the zenith
    // column is entirely dark.
    const aerial::AtmosphereParams air;
    const aerial::SkySample b = aerial::referenceSkyIntegrals(air, glm::dvec3(0, 1, 0), direction(-30, 90));
    EXPECT_EQ(b.rayleigh, glm::dvec3(0.0));
    EXPECT_EQ(b.mie, glm::dvec3(0.0));
}

TEST(SkyReference, SymmetricAboutTheLightsVerticalPlane) {
    const aerial::AtmosphereParams air;
    const glm::dvec3 light = direction(15, 100);
    for (double offset : {20.0, 75.0, 150.0}) {
        const aerial::SkySample a = aerial::referenceSkyIntegrals(air, direction(10, 100 + offset), light);
        const aerial::SkySample b = aerial::referenceSkyIntegrals(air, direction(10, 100 - offset), light);
        expectRelative(a.rayleigh, b.rayleigh, 1e-12, "rayleigh");
        expectRelative(a.mie, b.mie, 1e-12, "mie");
    }
}

TEST(SkyReference, RadianceAppliesThePhaseFunctions) {
    aerial::AtmosphereParams air;
    air.mieAnisotropy = 0.76;
    const glm::dvec3 v = direction(25, 200), l = direction(35, 170), e(20.0, 19.0, 18.0);
    const aerial::SkySample s = aerial::referenceSkyIntegrals(air, v, l);
    const double mu = v.x * l.x + v.y * l.y + v.z * l.z;
    const glm::dvec3 expected =
        e * (aerial::rayleighPhase(mu) * s.rayleigh + aerial::miePhase(mu, air.mieAnisotropy) * s.mie);
    expectRelative(aerial::referenceSkyRadiance(air, v, l, e), expected, 1e-12, "radiance");
}

// Two brute-force integrators written apart (different quadratures) agree
// while the light is up (in twilight the test-support reference, which does
// not cut its view ray at the shadow edge, is itself only good to ~2e-3).
TEST(SkyReference, AgreesWithTheTestSupportReference) {
    aerial::AtmosphereParams air;
    air.viewerHeight = 300.0;
    const glm::dvec3 lights[] = {direction(60, 180), direction(4, 90)};
    const glm::dvec3 views[] = {direction(90, 0), direction(30, 45), direction(5, 100), direction(0.5, 270),
                                direction(12, 300)};
    for (const glm::dvec3& l : lights) {
        for (const glm::dvec3& v : views) {
            const aerial::SkySample ours = aerial::referenceSkyIntegrals(air, v, l);
            const aerial::SkySample theirs = aerial::reference::singleScattering(air, v, l, {4000, 400});
            expectRelative(ours.rayleigh, theirs.rayleigh, 5e-4, "rayleigh");
            expectRelative(ours.mie, theirs.mie, 5e-4, "mie");
        }
    }
}

// In twilight (sun below the horizon, the view ray crossing the edge of the
// Earth's shadow) the default resolution is converged: 2x finer in both
// directions changes the radiance by less than 1e-4.
TEST(SkyReference, ConvergedInTwilight) {
    const aerial::AtmosphereParams air;
    const glm::dvec3 light = direction(-3, 270), e(1.0);
    for (const glm::dvec3& v :
         {direction(5, 100), direction(12, 300), direction(0.5, 270), direction(60, 0)}) {
        const glm::dvec3 coarse = aerial::referenceSkyRadiance(air, v, light, e);
        const glm::dvec3 fine = aerial::referenceSkyRadiance(air, v, light, e, {4096, 512});
        ASSERT_GT(fine.x, 0.0);
        expectRelative(coarse, fine, 1e-4, "radiance");
    }
}

}  // namespace
