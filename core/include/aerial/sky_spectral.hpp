// aerial/sky_spectral.hpp — the sky solved at six wavelengths and returned
// in the renderer's linear Rec.709, the extraterrestrial sun white
// (Bruneton 2017, "Precomputed Atmospheric Scattering: a New
// Implementation", luminance from a few precomputed wavelength triples).
//
// Usage (a drop-in for SkySolver, <aerial/sky.hpp>):
//   aerial::SpectralSkySolver solver;                // SkySolverDesc as SkySolver
//   solver.solve(air, sunDirection);                 // air: the preset's RGB AtmosphereParams
//   glm::dvec3 L = aerial::skyRadiance(solver.table(), air.mieAnisotropy, viewDir, sunIlluminance);
//   // amortised: beginSolve(air, dir); while (!solver.continueSolve(4)) { /* next frame */ }
//
// Why: an RGB solver samples each coefficient at one wavelength per channel
// (680 / 550 / 440 nm). Along the long paths of twilight the light that
// reaches the eye is shaped by ozone's Chappuis band (500-700 nm) and by
// Rayleigh's lambda^-4 within each channel's response, which one sample
// cannot follow: with ozone taken at 680 nm the red channel keeps ~4x too
// much light and the blue hour turns magenta (DESIGN.md, "Sky").
//
// What it computes: SpectralSkySolver owns kSpectralSkyPasses (2)
// SkySolvers. Pass k solves the atmosphere spectralSkyAtmosphere(air, k),
// whose three "channels" hold the coefficients at three wavelengths
// (kSpectralSkyWavelengths: 610/520/430 nm and 660/570/470 nm). The
// solver's tables are linear in the per-wavelength integrals, and the phase
// functions (applied per pixel) and the table's mapping (geometry only) do
// not depend on the wavelength, so every channel of the combined table,
//   T_rgb = sum_k M_k T_k        (rayleigh, mie, multiple, horizon averages),
// is the linear Rec.709 value of the spectrum those six samples stand for,
// with M_k = spectralSkyMatrix(k) a 3x3 matrix per pass. The illuminance E
// given to skyRadiance stays the preset's RGB: the table is per unit
// extraterrestrial sun, and an unattenuated sun (every I = 1) maps to R = G =
// B = 1, so E keeps its meaning.
//
// The matrices: XYZ = sum_i w_i I(lambda_i) with weights w_i (three per
// wavelength) fitted by least squares to the CIE 1931 2-degree observer
// times the extraterrestrial solar spectrum (ASTM G-173, 10 nm bins) over
// 380-780 nm, on the single-scattering spectra of 2268 view rays (suns from
// -8 to 90 deg, views from the horizon to the zenith, all azimuths) of
// Earth's air with ozone x0.6 .. x1.6 and Mie x1 .. x5, each spectrum's error
// relative to its luminance, with the white (I = 1 everywhere) kept exact;
// then XYZ -> linear Rec.709 (D65) and each output channel scaled so that the
// white is R = G = B = 1. Against 41 wavelengths the fit is within Δu'v'
// 0.0007 and 0.8% in luminance on those atmospheres (sun 90 to -6 deg,
// zenith and horizon; tests/core/test_sky_spectral.cpp checks the solver
// against an independent 41-wavelength reference).
//
// The spectral atmosphere (spectralSkyAtmosphere) from the preset's RGB
// coefficients, given at the nominal channel wavelengths 680 / 550 / 440 nm
// (kSpectralSkyNominal; Bruneton 2017's demo values):
//   * Rayleigh scattering, Mie scattering and Mie extinction: a power law in
//     the wavelength through each pair of neighbouring nominal values
//     (log-linear in ln lambda; beyond 440 or 680 nm the nearest pair's law),
//     linear where a value is 0; the defaults give 1.24e-6 lambda[um]^-4 and
//     a grey Mie. Mie extinction is kept >= Mie scattering;
//   * ozone: the Chappuis-band absorption cross-section (Serdyuchenko et al.
//     2014, 233 K, 10 nm bins, as in Bruneton 2017) times the number density
//     of 300 DU spread over the 15 km tent's integral (5.374e18 /m^3, which
//     gives the defaults (0.650, 1.881, 0.085)e-6 /m at the nominal
//     wavelengths), scaled by s = (o . o_0) / (o_0 . o_0), the least-squares
//     multiple of the defaults o_0 that the preset's RGB ozone o is;
//   * ground albedo: linear in the wavelength between the nominal values,
//     the end values beyond; clamped to 0..1;
//   * everything else (radii, heights, anisotropy) as given.
// The defaults reproduce Earth as Bruneton's demo (and the test) describe it.
//
// Cost: two SkySolver solves and a pass over the table (~2x SkySolver;
// bench/bench_sky.cpp). The amortised solve runs the passes one after the
// other over continueSolve calls; table() publishes only complete combined
// tables (the last one until the next is done).
#pragma once

#include <aerial/atmosphere.hpp>
#include <aerial/sky.hpp>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <memory>

namespace aerial {

/// Number of SkySolver passes (wavelength triples).
inline constexpr int kSpectralSkyPasses = 2;
/// The wavelengths [nm] each pass solves, in its channels 0, 1, 2.
inline constexpr double kSpectralSkyWavelengths[kSpectralSkyPasses][3] = {{610.0, 520.0, 430.0},
                                                                          {660.0, 570.0, 470.0}};
/// The wavelengths [nm] at which AtmosphereParams' RGB channels are given.
inline constexpr double kSpectralSkyNominal[3] = {680.0, 550.0, 440.0};

/// The atmosphere of pass `pass` (0..kSpectralSkyPasses-1): `air` with its
/// coefficients taken at kSpectralSkyWavelengths[pass] (rules above).
AtmosphereParams spectralSkyAtmosphere(const AtmosphereParams& air, int pass);

/// The coefficient [1/m, or albedo] at `wavelength` [nm] of the spectrum
/// the rules above give for an RGB triple at kSpectralSkyNominal: kind 0
/// power law (scattering, extinction), 1 linear (albedo).
double spectralSkyCoefficient(const glm::dvec3& rgb, double wavelength, int kind);

/// Ozone's absorption cross-section [m^2] at `wavelength` [nm] (360-830,
/// linear between the 10 nm bins; the end values beyond).
double ozoneCrossSection(double wavelength);

/// Linear Rec.709 of pass `pass`'s three samples: rgb = M v (column c is
/// the contribution of the sample in channel c). Summed over the passes the
/// columns give (1, 1, 1) for the white (see above).
glm::dmat3 spectralSkyMatrix(int pass);

/// sum_k spectralSkyMatrix(k) v[k]: the Rec.709 value of per-pass samples.
glm::dvec3 spectralSkyCombine(const std::array<glm::dvec3, kSpectralSkyPasses>& v);

/// The spectral counterpart of referenceSkyIntegrals (<aerial/sky_reference.hpp>):
/// the brute-force integrals of each pass's atmosphere, combined. What
/// SpectralSkySolver's single scattering converges to.
SkySample spectralReferenceSkyIntegrals(const AtmosphereParams& air, const glm::dvec3& viewDirection,
                                        const glm::dvec3& lightDirection);

/// SkySolver's interface (<aerial/sky.hpp>) over kSpectralSkyPasses
/// SkySolvers built from the same description (each with its own threads;
/// their cached tables are shared between solvers for the same air, so the
/// moon's solver adopts what the sun's built). The combined table has the
/// passes' mapping (identical by construction; asserted) and a generation
/// counting this solver's publishes. It is linear Rec.709, not clamped: a
/// colour outside the gamut (the deep red glow around a low sun) keeps its
/// small negative component, and each table alone may hold one that the
/// others make up for once the phases are applied (Mie's blue towards a low
/// sun; clamping it there doubled the sky's blue 2 deg above the horizon).
class SpectralSkySolver {
public:
    explicit SpectralSkySolver(const SkySolverDesc& desc = {});
    ~SpectralSkySolver();
    SpectralSkySolver(const SpectralSkySolver&) = delete;
    SpectralSkySolver& operator=(const SpectralSkySolver&) = delete;

    // SkySolver's calls (<aerial/sky.hpp>), over every pass: `air` is the
    // preset's RGB atmosphere; continueSolve advances the pass in progress
    // (one pass per call) and returns true once the last is done and the
    // combined table is published; invalidateCache forgets every pass's
    // cached tables; desc() is every pass's description.
    void solve(const AtmosphereParams& air, const glm::dvec3& lightDirection);
    void beginSolve(const AtmosphereParams& air, const glm::dvec3& lightDirection);
    bool continueSolve(int rows);
    bool solving() const;
    void invalidateCache();
    /// The last completed combined table (zeros, generation 0, before the first).
    const SkyTable& table() const;
    const SkySolverDesc& desc() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace aerial
