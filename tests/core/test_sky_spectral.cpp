// test_sky_spectral.cpp — SpectralSkySolver (<aerial/sky_spectral.hpp>)
// against a spectral single-scattering reference written here: 41
// wavelengths 380-780 nm, the published ozone cross-sections and solar
// spectrum, the CIE 1931 2-degree observer, the sun white-balanced to R = G
// = B. The data below (and support/cie1931.hpp) are the tests' own copies,
// so the reference shares nothing with the solver but the published numbers.
#include <aerial/atmosphere.hpp>
#include <aerial/sky.hpp>
#include <aerial/sky_spectral.hpp>

#include <gtest/gtest.h>

#include "cie1931.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kBands = aerial::test::kCmfBands;  // 380, 390, .. 780 nm
using aerial::test::kCmf;

// ASTM G-173 extraterrestrial spectral irradiance [W/m^2/nm], averaged over
// each 10 nm bin starting at the wavelength (Bruneton 2017's demo table).
constexpr double kSolar[kBands] = {
    1.01249, 1.14716, 1.72765, 1.73054, 1.6887,  1.61253, 1.91198, 2.03474, 2.02042, 2.02212, 1.93377,
    1.95809, 1.91686, 1.8298,  1.8685,  1.8931,  1.85149, 1.8504,  1.8341,  1.8345,  1.8147,  1.78158,
    1.7533,  1.6965,  1.68194, 1.64654, 1.6048,  1.52143, 1.55622, 1.5113,  1.474,   1.4482,  1.41018,
    1.36775, 1.34188, 1.31429, 1.28303, 1.26758, 1.2367,  1.2082,  1.18737};
// Ozone absorption cross-section [m^2], Serdyuchenko et al. 2014 at 233 K,
// 10 nm bins (the same source).
constexpr double kOzone[kBands] = {
    2.818e-28, 6.636e-28, 1.527e-27, 2.763e-27, 5.52e-27,  8.451e-27, 1.582e-26, 2.316e-26, 3.669e-26,
    4.924e-26, 7.752e-26, 9.016e-26, 1.48e-25,  1.602e-25, 2.139e-25, 2.755e-25, 3.091e-25, 3.5e-25,
    4.266e-25, 4.672e-25, 4.398e-25, 4.701e-25, 5.019e-25, 4.305e-25, 3.74e-25,  3.215e-25, 2.662e-25,
    2.238e-25, 1.852e-25, 1.473e-25, 1.209e-25, 9.423e-26, 7.455e-26, 6.566e-26, 5.105e-26, 4.15e-26,
    4.228e-26, 3.237e-26, 2.451e-26, 2.801e-26, 2.534e-26};
// Linear Rec.709 (D65) <-> CIE XYZ, IEC 61966-2-1.
constexpr double kXyzToRgb[3][3] = {{3.2404542, -1.5371385, -0.4985314},
                                    {-0.9692660, 1.8760108, 0.0415560},
                                    {0.0556434, -0.2040259, 1.0572252}};
constexpr double kRgbToXyz[3][3] = {
    {0.4124564, 0.3575761, 0.1804375}, {0.2126729, 0.7151522, 0.0721750}, {0.0193339, 0.1191920, 0.9503041}};

// Earth as Bruneton 2017's demo describes it (the defaults of
// AtmosphereParams are its values at 680 / 550 / 440 nm).
constexpr double kRg = 6360000.0, kRt = 6420000.0;
constexpr double kRayleighHeight = 8000.0, kMieHeight = 1200.0;
constexpr double kMieScattering = 3.996e-6, kMieExtinction = 3.996e-6 / 0.9, kG = 0.8;
constexpr double kOzonePeak = 300.0 * 2.687e20 / 15000.0;  // 300 DU over the tent's 15 km

double rayleighAt(double lambdaNm) {
    const double um = lambdaNm * 1e-3;
    return 1.24062e-6 / (um * um * um * um);
}

glm::dvec3 mul(const double m[3][3], const glm::dvec3& v) {
    return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
            m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
}

struct Depth {
    double rayleigh = 0.0, mie = 0.0, ozone = 0.0;  // integral of each relative density [m]
};

Depth densities(double height) {
    return {std::exp(-height / kRayleighHeight), std::exp(-height / kMieHeight),
            std::max(0.0, 1.0 - std::abs(height - 25000.0) / 15000.0)};
}

double distanceToTop(const glm::dvec3& x, const glm::dvec3& d) {
    const double b = glm::dot(x, d), c = glm::dot(x, x) - kRt * kRt;
    return std::max(-b + std::sqrt(std::max(b * b - c, 0.0)), 0.0);
}

// Midpoint rule on t0..t1 with the nodes crowded at t0 (towardsEnd false)
// or t1 (true), quadratically.
Depth integrate(const glm::dvec3& x, const glm::dvec3& d, double t0, double t1, int steps, bool towardsEnd) {
    Depth sum;
    auto at = [&](double u) {
        return towardsEnd ? t1 - (t1 - t0) * (1.0 - u) * (1.0 - u) : t0 + (t1 - t0) * u * u;
    };
    for (int k = 0; k < steps; ++k) {
        const double a = at(double(k) / steps), b = at(double(k + 1) / steps), m = at((k + 0.5) / steps);
        const Depth q = densities(glm::length(x + d * m) - kRg);
        sum.rayleigh += q.rayleigh * (b - a);
        sum.mie += q.mie * (b - a);
        sum.ozone += q.ozone * (b - a);
    }
    return sum;
}

struct Sample {
    double rayleighWeight, mieWeight;  // relative density x ds [m]
    Depth depth;                       // viewer -> x -> sun
};

// The lit samples along the view ray of a viewer on the ground: the
// wavelength-independent integrals, split so that any spectrum follows.
std::vector<Sample> traceView(const glm::dvec3& view, const glm::dvec3& sun) {
    constexpr int kViewSteps = 1000, kSunSteps = 200;
    const glm::dvec3 x0(0.0, kRg, 0.0);
    const double length = distanceToTop(x0, view);
    std::vector<Sample> out;
    Depth toViewer;
    for (int k = 0; k < kViewSteps; ++k) {
        const double u0 = double(k) / kViewSteps, u1 = double(k + 1) / kViewSteps,
                     um = (k + 0.5) / kViewSteps;
        const double ds = length * (u1 * u1 - u0 * u0);
        const glm::dvec3 p = x0 + view * (length * um * um);
        const Depth q = densities(glm::length(p) - kRg);
        const Depth half{toViewer.rayleigh + 0.5 * q.rayleigh * ds, toViewer.mie + 0.5 * q.mie * ds,
                         toViewer.ozone + 0.5 * q.ozone * ds};
        toViewer.rayleigh += q.rayleigh * ds;
        toViewer.mie += q.mie * ds;
        toViewer.ozone += q.ozone * ds;
        // The earth's shadow: the ray to the sun passes below the ground.
        const double perigee = -glm::dot(p, sun);
        if (perigee > 0.0 && glm::dot(p, p) - perigee * perigee < kRg * kRg) continue;
        const double top = distanceToTop(p, sun);
        Depth toSun;
        if (perigee > 0.0) {
            const Depth a = integrate(p, sun, 0.0, perigee, kSunSteps, true);
            const Depth b = integrate(p, sun, perigee, top, kSunSteps, false);
            toSun = {a.rayleigh + b.rayleigh, a.mie + b.mie, a.ozone + b.ozone};
        } else {
            toSun = integrate(p, sun, 0.0, top, kSunSteps, false);
        }
        out.push_back({q.rayleigh * ds,
                       q.mie * ds,
                       {half.rayleigh + toSun.rayleigh, half.mie + toSun.mie, half.ozone + toSun.ozone}});
    }
    return out;
}

// Linear Rec.709 of the single-scattered sky per unit extraterrestrial
// irradiance, the sun white (R = G = B = 1 for a spectrum of 1).
glm::dvec3 referenceSky(const glm::dvec3& view, const glm::dvec3& sun) {
    const std::vector<Sample> samples = traceView(view, sun);
    const double mu = glm::dot(view, sun);
    const double rayleighPhase = 3.0 / (16.0 * kPi) * (1.0 + mu * mu);
    const double miePhase = 3.0 / (8.0 * kPi) * (1.0 - kG * kG) * (1.0 + mu * mu) /
                            ((2.0 + kG * kG) * std::pow(1.0 + kG * kG - 2.0 * kG * mu, 1.5));
    glm::dvec3 xyz(0.0), white(0.0);
    for (int i = 0; i < kBands; ++i) {
        const double rayleigh = rayleighAt(380.0 + 10.0 * i), ozone = kOzonePeak * kOzone[i];
        double r = 0.0, m = 0.0;
        for (const Sample& s : samples) {
            const double t = std::exp(
                -(rayleigh * s.depth.rayleigh + kMieExtinction * s.depth.mie + ozone * s.depth.ozone));
            r += s.rayleighWeight * t;
            m += s.mieWeight * t;
        }
        const double radiance = rayleighPhase * rayleigh * r + miePhase * kMieScattering * m;
        for (int c = 0; c < 3; ++c) {
            xyz[c] += kCmf[i][c] * kSolar[i] * radiance;
            white[c] += kCmf[i][c] * kSolar[i];
        }
    }
    return mul(kXyzToRgb, xyz) / mul(kXyzToRgb, white);
}

glm::dvec2 chromaticity(const glm::dvec3& rgb) {
    const glm::dvec3 xyz = mul(kRgbToXyz, rgb);
    const double d = xyz.x + 15.0 * xyz.y + 3.0 * xyz.z;
    return {4.0 * xyz.x / d, 9.0 * xyz.y / d};
}

double luminance(const glm::dvec3& rgb) { return 0.2126729 * rgb.x + 0.7151522 * rgb.y + 0.0721750 * rgb.z; }

// Elevation and azimuth [deg] from north (-Z) towards east (+X).
glm::dvec3 direction(double elevationDeg, double azimuthDeg) {
    const double el = elevationDeg * kPi / 180.0, az = azimuthDeg * kPi / 180.0;
    return {std::cos(el) * std::sin(az), std::sin(el), -std::cos(el) * std::cos(az)};
}

// The chromaticity of the single-scattered sky, SpectralSkySolver against
// the 41-wavelength reference, and the plain RGB SkySolver against it (the
// three-wavelength shortcut this replaces: magenta twilight). Zenith and 3
// deg above the horizon towards, across and away from the sun; away from a
// set sun higher, 3 + 5 x its depression: lower, single scattering is the
// earth's shadow (black) or its onset, where the lit sky switches on and the
// table's own error (2% of the pixel per wavelength, sky.hpp) reaches 0.013
// in chromaticity at sun -6 deg 18 deg up while the six wavelengths' exact
// integrals stay within 0.0008 of the 41.
TEST(SkySpectral, TwilightChromaticityMatchesSpectralReference) {
    aerial::SkySolverDesc desc;
    desc.singleScatteringOnly = true;
    aerial::SpectralSkySolver spectral(desc);
    aerial::SkySolver rgb(desc);
    const aerial::AtmosphereParams air;  // Earth, Bruneton 2017
    const glm::dvec3 white(1.0);
    double worstSpectral = 0.0, worstRgb = 0.0, worstLuminance = 0.0;
    for (double sunDeg : {90.0, 30.0, 10.0, 2.0, 0.0, -2.0, -4.0, -6.0}) {
        const glm::dvec3 sun = direction(sunDeg, 0.0);
        spectral.solve(air, sun);
        rgb.solve(air, sun);
        const double awayDeg = 3.0 + 5.0 * std::max(-sunDeg, 0.0);
        const struct {
            const char* name;
            glm::dvec3 view;
        } views[] = {{"zenith", direction(90.0, 0.0)},
                     {"towards", direction(3.0, 0.0)},
                     {"across", direction(3.0, 90.0)},
                     {"away", direction(awayDeg, 180.0)}};
        for (const auto& v : views) {
            const glm::dvec3 want = referenceSky(v.view, sun);
            const glm::dvec3 got = aerial::skyRadiance(spectral.table(), air.mieAnisotropy, v.view, white);
            const glm::dvec3 old = aerial::skyRadiance(rgb.table(), air.mieAnisotropy, v.view, white);
            ASSERT_GT(luminance(want), 0.0) << sunDeg << " " << v.name;
            const double duv = glm::length(chromaticity(got) - chromaticity(want));
            const double duvRgb = glm::length(chromaticity(old) - chromaticity(want));
            const double dY = luminance(got) / luminance(want) - 1.0;
            std::printf("sun %5.1f deg %-8s Y %.3e  spectral du'v' %.4f dY %+.4f   RGB solver du'v' %.4f\n",
                        sunDeg, v.name, luminance(want), duv, dY, duvRgb);
            EXPECT_LE(duv, 0.01) << "sun " << sunDeg << " deg, " << v.name;
            EXPECT_LE(std::abs(dY), 0.03) << "sun " << sunDeg << " deg, " << v.name;
            worstSpectral = std::max(worstSpectral, duv);
            worstRgb = std::max(worstRgb, duvRgb);
            worstLuminance = std::max(worstLuminance, std::abs(dY));
        }
    }
    std::printf("worst du'v': spectral %.4f, RGB solver %.4f; worst luminance %.2f%%\n", worstSpectral,
                worstRgb, 100.0 * worstLuminance);
    // The reference tells the two apart: three wavelengths leave the blue
    // hour magenta.
    EXPECT_GT(worstRgb, 0.05);
}

// The spectral atmosphere of the defaults is Bruneton 2017's Earth at the
// solved wavelengths (Rayleigh 1.24062e-6 lambda[um]^-4, grey Mie, 300 DU of
// ozone), and the white maps to R = G = B = 1.
TEST(SkySpectral, DefaultsReproduceEarthAndTheSunIsWhite) {
    const aerial::AtmosphereParams air;
    std::array<glm::dvec3, aerial::kSpectralSkyPasses> ones;
    for (int k = 0; k < aerial::kSpectralSkyPasses; ++k) {
        const aerial::AtmosphereParams s = aerial::spectralSkyAtmosphere(air, k);
        for (int c = 0; c < 3; ++c) {
            const double lambda = aerial::kSpectralSkyWavelengths[k][c];
            const int bin = int(std::lround((lambda - 380.0) / 10.0));
            EXPECT_NEAR(s.rayleighScattering[c], rayleighAt(lambda), 2e-4 * rayleighAt(lambda)) << lambda;
            EXPECT_NEAR(s.mieScattering[c], kMieScattering, 1e-12) << lambda;
            EXPECT_NEAR(s.mieExtinction[c], kMieExtinction, 1e-12) << lambda;
            EXPECT_NEAR(s.ozoneAbsorption[c], kOzonePeak * kOzone[bin], 2e-3 * kOzonePeak * kOzone[bin])
                << lambda;
            EXPECT_DOUBLE_EQ(s.groundAlbedo[c], air.groundAlbedo[c]);
        }
        ones[std::size_t(k)] = glm::dvec3(1.0);
    }
    const glm::dvec3 sunWhite = aerial::spectralSkyCombine(ones);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(sunWhite[c], 1.0, 1e-12);
    // No ozone in the preset: none in any pass.
    aerial::AtmosphereParams clear;
    clear.ozoneAbsorption = glm::dvec3(0.0);
    for (int k = 0; k < aerial::kSpectralSkyPasses; ++k)
        EXPECT_EQ(aerial::spectralSkyAtmosphere(clear, k).ozoneAbsorption, glm::dvec3(0.0));
}

// The amortised solve publishes nothing until every pass is done, then the
// same table as solve(), bit for bit.
TEST(SkySpectral, AmortisedSolveIsBitIdentical) {
    aerial::SkySolverDesc desc;
    desc.azimuthCount = 32;
    desc.elevationCount = 16;
    aerial::SpectralSkySolver once(desc), spread(desc);
    aerial::AtmosphereParams air;
    air.mieScattering = glm::dvec3(1.2e-5, 1.0e-5, 0.8e-5);
    air.mieExtinction = air.mieScattering / 0.9;
    const glm::dvec3 sun = direction(-3.0, 40.0);
    once.solve(air, sun);
    spread.beginSolve(air, sun);
    int calls = 0;
    while (!spread.continueSolve(5)) {
        ASSERT_TRUE(spread.solving());
        EXPECT_EQ(spread.table().generation, 0u);
        ++calls;
    }
    EXPECT_GE(calls, aerial::kSpectralSkyPasses);
    EXPECT_FALSE(spread.solving());
    const aerial::SkyTable& a = once.table();
    const aerial::SkyTable& b = spread.table();
    EXPECT_EQ(b.generation, 1u);
    EXPECT_EQ(a.rayleigh, b.rayleigh);
    EXPECT_EQ(a.mie, b.mie);
    EXPECT_EQ(a.multiple, b.multiple);
    EXPECT_EQ(a.horizonMultiple, b.horizonMultiple);
    EXPECT_EQ(a.shadowElevation, b.shadowElevation);
    ASSERT_EQ(a.rayleigh.size(), std::size_t(32 * 16 * 3));
    for (float v : a.multiple) ASSERT_TRUE(std::isfinite(v));
}

}  // namespace
