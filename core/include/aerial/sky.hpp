// aerial/sky.hpp — the Nishita 1993 single-scattering sky with Hillaire 2020
// multiple scattering, solved on the CPU into a hemisphere table that the
// renderer (or a game) samples per pixel.
//
// Usage:
//   aerial::SkySolver solver;                       // 128 x 64 x 32, all cores
//   solver.solve(air, sunDirection);                // whole table, now
//   const aerial::SkyTable& sky = solver.table();
//   glm::dvec3 L = aerial::skyRadiance(sky, air.mieAnisotropy, viewDir, sunIlluminance);
//
//   // A game with a tight frame budget spreads the work over frames:
//   solver.beginSolve(air, sunDirection);
//   while (!solver.continueSolve(4)) { /* next frame */ }  // 4 rows per call
//   // table() keeps the last complete solve until the new one finishes.
//
// What the table holds (../shared/DESIGN.md, "Sky"): for each direction v of
// the upper hemisphere the two phase-less single-scattering integrals
//   I_R(v) = integral beta_R(h(s)) T(viewer -> x(s)) T(x(s) -> light) ds
//   I_M(v) = integral beta_M(h(s)) T(viewer -> x(s)) T(x(s) -> light) ds
// (RGB each, dimensionless) and the multiple scattering, its phases applied,
//   I_ms(v) = integral T(viewer -> x(s)) e^(f_s tau_M(s)) [(beta_R + (1 - f_s) beta_M)(h) Psi_ms(h, mu_s)
//                                         + beta_R(h) A_R(v) + beta_M(h) A_M(v)] ds
//           + integral T(viewer -> x(s)) (e^(f_s tau_M(s)) - 1) (P_R(mu) beta_R + P_M(mu) beta_M)(h)
//                                        T(x(s) -> light) ds
// (RGB, [1/sr]; h, mu_s and the A_X at x(s); tau_M(s) Mie's scattering depth
// from the viewer, f_s the straight-on share of Mie's peak, below), so that the radiance is
//   L(v) = E * (P_R(mu) I_R(v) + P_M(mu) I_M(v) + I_ms(v)),  mu = dot(v, light),
// with the phase functions applied per pixel. The single-scattering channels
// do not depend on the multiple scattering (they stay checkable against
// their exact integral, sky_reference.hpp).
//
// Multiple scattering (Hillaire 2020, "A Scalable and Production Ready Sky
// and Atmosphere Rendering Technique", section 5.5, eq. 5-10, with its
// orders 3 to 5 made explicit): Psi_ms(h, mu_s) is the radiance per unit sun
// illuminance [1/sr] that all orders >= 2 add at height h for a sun of
// zenith cosine mu_s, its isotropic part:
//   Psi_ms = J_2 + .. + J_5 + J_5 f_ms / (1 - f_ms),
// J_2 = Hillaire's L_2nd, the second order from 96 directions crowded at
// the horizon and towards the sun (so that the thin sunlit upper air that
// lights a deep twilight is resolved): single scattering of
// the sun along each ray to the ground or the top, plus the ground's
// Lambertian bounce with AtmosphereParams::groundAlbedo. J_3 .. J_5 are
// the next orders, each integrated from the one before through the
// atmosphere along the same directions, with the ground's reflection of its
// light (and J_3 of the single-scattered skylight); f_ms (the transfer of unit isotropic
// in-scattering) gives the geometric tail of the rest (details:
// core/src/sky/sky_multiple.hpp; why the orders 3 to 5 are explicit:
// docs/sky_table_notes.md). The second order
// has the real phases: Rayleigh's and Mie's at the first scattering
// (averaged over each direction's quadrature cell), and at the last, towards
// the viewer, the view-dependent remainder A_X(v) = integral (P_X(omega.v) -
// 1/(4 pi)) L_1(omega) d omega of each scatterer X, from the dipole and
// quadrupole moments of the once-scattered light L_1 at each height and sun
// cosine (Legendre series of the phases to l = 2: exact for Rayleigh; for
// Mie, delta-M: the forward peak's share g_3 as light going straight on and
// the rest to l = 2; of that share, f_s, the phase within 6 deg of straight on (0.12 at
// g = 0.8), is carried exactly along the view ray, the e^(f_s tau_M) above,
// and the remainder read through the moments' Fejer window; sky_multiple.hpp,
// "Mie's truncation"). What that series still misses of Mie's last
// scattering of the second and third orders' field (in twilight a band of
// sunlit air above the horizon towards the sun, which Mie's peak sends on
// towards the viewer) is kept by quadrature over the 96 directions at 74 view
// directions per height and sun cosine and interpolated between them along
// each view ray (sky_multiple.hpp, "Mie's last scattering"). The third order's field L_2
// adds its moments the same way (and the later orders theirs, as L_2's times
// the tail's 1 / (1 - f_ms)); the sources of the third and later orders stay
// isotropic. The LUT (MultipleScatteringTable) has 25 heights (the shells of
// 24 equal-mass layers from the ground to the top) x 64 sun cosines (mu =
// sign(x) x^2, x uniform in [-1, 1]: dense near the horizon). It depends
// only on the atmosphere and is cached with the optical-depth table. Along a
// view ray it is taken at each shell (height of the shell, the sun's zenith
// cosine where the ray crosses it; geometric between the LUT's sun-cosine
// columns, as Psi falls about exponentially with the sun's depression in
// twilight), linear within a layer, times the layer's exact integral of
// beta_X T(viewer -> s). That integral is done for 16 azimuths from the
// light (0, 12, ... 180 deg) and spread into the table's columns by
// Catmull-Rom in ln I_ms (smooth in azimuth: the sun's cosine at a shell is
// alpha + beta cos(phi)), within 0.12% of the pixel of integrating every
// column.
//
// Table mapping (the one contract between the solver and every sampler):
//   * rows j = 0..elevationCount-1 hold the elevation el_j with
//     v(el_j) = j / (elevationCount - 1), v increasing from v(0) = 0 to
//     v(pi/2) = 1 (skyTableRow, skyTableElevation):
//       v(el) = (1 - a - b - d) sqrt(el / (pi/2))
//             + a atan(el / E) / atan(pi/2 / E)
//             + b (atan((el - c) / w) - atan(-c / w)) / (atan((pi/2 - c) / w) - atan(-c / w))
//             + d/2 (1 - u^0.35) below c, d/2 (1 + cbrt(u)) above, u = min(|el - c|, c) / c,
//     E = bandElevation, a = bandShare, c = shadowElevation, w = shadowWidth,
//     b = shadowShare, carried in the SkyTable and set by the solver from the
//     light (setSkyTableMapping). The rows go where the light changes fastest:
//     - a light above 1 deg: a = b = 0, the quadratic el_j = pi/2 (j / (H - 1))^2
//       (more rows near the horizon);
//     - a light below 1 deg: a = 0.7 (fading to 0 at 1 deg) of the rows in a
//       horizon band of width E = max(1.8 L^0.7, 1.2) deg, L = the light's
//       depression below the horizon [deg]: the band between the horizon and
//       the top of the earth's shadow, whose edge rises to about L above the
//       horizon opposite the light;
//     - a light below the horizon also: b = 0.15 (0.05 from L = 6 deg; fading
//       in over the first 0.01 deg; L beyond 18 deg counts as 18) of the rows
//       around c with width w = 0.25 L min(L / 0.3, 1): the edge of the earth's shadow
//       opposite the light, which is sharpest (a kink in the radiance a few
//       hundredths of a degree above a black sliver) for a light just set;
//       the lit sky's onset above the kink narrows about as L^2 there, so
//       below 0.3 deg the width does too.
//       c is the kink's elevation straight opposite the light (the view ray
//       that leaves the shadow cylinder exactly at the top of the
//       atmosphere, about 1.1 L; for a light more than ~6 deg down that ray
//       is shadowed up to the top and c = 1.1 L), and b is adjusted so that
//       a row lies exactly on it;
//     - a light 0-1 deg below the horizon also: d = (16/63) g of the rows
//       (twice that for c below 0.005 deg, fading in from 0.01 deg:
//       skyCapRowShare)
//       (taken from the band's a) between 0 and 2c, half below c uniform in
//       (c - el)^0.35 (kSkyCapBelowPower: crowded towards c, where the lit
//       sky beside the cap ramps up over a width that grows fast with
//       c - el), blending into uniform in ln(1 + u / s), u = (c - el) / c,
//       s = min(5e-4, 3 c), as the boost comes in (kSkyCapLogScale,
//       kSkyCapLogScalePerKink), half above c uniform in cbrt(el - c),
//       crowded at the cap's top where straight opposite the light the lit
//       sky switches on within a few 1e-4 deg for a light 0.01 deg down;
//       g = capStrength, 1 up to 0.5 deg, fading to 0 at 1 deg;
//     With 128 x 64 texels this keeps the table within 2% of the exact
//     single-scattering integral relative to the pixel (floored at 1% of the
//     brightest sky) in every direction tests/core/test_sky.cpp probes, off
//     the texel centres too, for suns from -6 to 90 deg (SkyOffTexel), and
//     within 1.5% in dense sweeps of the anti-light quarter near the kink
//     for suns 0.00002-0.3 deg below the horizon (SkyShadowOnset,
//     AERIAL_SKY_SHADOW_ONSET; docs/sky_table_notes.md has the figures and
//     their history);
//   * columns i = 0..azimuthCount-1 hold the azimuth relative to the light
//       phi_i = 2 pi * i / azimuthCount,
//     measured from the light's azimuth towards east (the same sense as the
//     world azimuth); the azimuth wraps. Because single scattering is
//     symmetric about the light's vertical plane, column i equals column
//     azimuthCount - i. Except for a light 0-1 deg below the horizon
//     (capCurvature k > 0, capStrength g > 0): opposite it the earth's
//     shadow is a cap, dark below a parabola el = c - k psi^2 (psi: azimuth
//     from the anti-light point, k ~ 0.069/rad fitted to the exact onset
//     where it crosses c/2), above which the lit sky switches on within
//     thousandths of a degree. The columns of the row at elevation el are
//     then piecewise linear in psi (in psi^2 between the second and third
//     knot) through the knots
//       x = |i - W/2| = (0, 3, 15, 28, 64) W / 128,
//       psi = (0, P, sqrt((2 P)^2 + D^2), F2, pi),  P = min(sqrt(max(c - el, 0) / k), F),
//       F = min(sqrt(c / k), pi/4),  D = max(F / 2, min(1 deg, 500 c)),
//       F2 = min(2 (F + max(F / 2, 1 deg)), 3 pi / 4),
//     except that the last two segments are quadratic, psi = p + (q - p)
//     (a t + (1 - a) t^2) with t = 0..1 along the segment from p to q and
//     a = 1 - g (1 - kSkyCapNearSlope) from the band's outer knot to F2, a
//     = 1 - g (1 - kSkyCapFarSlope) from F2 to pi (their columns crowd
//     at the segment's start: beyond the band just below the cap's top,
//     where the lit sky beside the cap still ramps up, and beyond F2, where
//     it still climbs steeply near the horizon), and each inner psi blended
//     with g towards 2 pi x / W (skyTableColumn, skyTableAzimuth): the onset lies on column W/2 -+ 3 W / 128
//     in every row below the cap's top, with 12 columns in the band above it. Only P depends on the row, so
//     between two rows the onset stays on its column. The band is uniform in ln(1 + (psi^2 - P^2) / Y0), Y0 =
//     (kSkyCapBandScale c)^2 + (kSkyCapBandOnsetScale P)^2 (10 c and P): geometric in the height above the
//     onset beyond Y0, where the lit sky at the cap's top switches on (~10 c from the anti-light point) and
//     levels off (~100-1000 c), and widens with P (the 2 in its outer knot is kSkyCapOnsetGrowth): lower down
//     the cap the lit sky ramps up over an azimuth that grows with P. For a light just set (c below 0.01
//     deg, the boost fraction m of the rows) the shares and G blend towards 2 columns inside the cap, 20 in
//     the band and G = 6 (SkyCapShape), each blended knot x rounded to a whole column (so that no knot
//     bends the bilinear filter's line inside a texel). The knots are mirror-symmetric, so
//     column i still equals column W - i. The horizon averages then weight row 0 by azimuth;
//   * texel (i, j) is stored at index (j * azimuthCount + i) * 3 (RGB, float).
//   Directions below the horizon use row 0.
//
// Horizon average (SkyTable::horizonRayleigh / horizonMie / horizonMultiple): row 0 only
// (elevation exactly 0), all azimuthCount columns with equal weight
// 1 / azimuthCount, i.e. the azimuthal mean of the horizon ring (with warped
// columns, the mean of row 0's interpolant over 8 azimuths per column).
#pragma once

#include <aerial/atmosphere.hpp>

#include <glm/vec3.hpp>

#include <cmath>
#include <memory>
#include <vector>

namespace aerial {

/// How the solver is built. Zero values mean defaults.
struct SkySolverDesc {
    /// Table columns (relative azimuth), 4..limits::kMaxSkyAzimuthCount (4096).
    /// Every size here is clamped into its range (aerial/limits.hpp);
    /// SkySolver::desc() reports the sizes used.
    int azimuthCount = 128;
    int elevationCount = 64;  ///< table rows (elevation 0..90 deg), 2..kMaxSkyElevationCount (2048)
    /// Layers along each view ray, 2..kMaxSkyLayerCount (1024): spherical shells between the
    /// viewer and the top holding equal mass of the mixed profile
    /// (exp(-h/H_R) and exp(-h/H_M) a quarter each, uniform in height half),
    /// so the 8 km Rayleigh and 1.2 km Mie scale heights and the upper air
    /// (the earth shadow of a set sun) are resolved. With 32 every compared
    /// texel, horizon rows included, is within 2% of the brute-force
    /// reference for suns from -5 to 90 deg (tests/core/test_sky.cpp prints
    /// the error for 16..96 layers), and so are the directions between the
    /// texels for suns from -6 to 90 deg (with the row mapping above).
    int layerCount = 32;
    /// Optical-depth table rows (height): the table has exactly one row per
    /// shell (layerCount + 1, no interpolation in height); the value given is
    /// ignored and desc() reports the one used.
    int opticalDepthHeights = 0;
    /// Optical-depth table columns: the light's zenith cosine from the
    /// geometric horizon at that height to 1, half of them within 0.05 of the
    /// horizon; 0 = 128, 8..kMaxOpticalDepthAngles (4096).
    int opticalDepthAngles = 0;
    int threadCount = 0;  ///< threads incl. the caller; 0 = all hardware threads, 1 = caller only
    /// True: no multiple scattering (SkyTable::multiple stays 0, no LUT is
    /// built); for comparisons and benchmarks. Default false.
    bool singleScatteringOnly = false;
    /// True: the multiple-scattering LUT with Hillaire's isotropic phases
    /// (no phase at the first scattering, no view dependence of the second
    /// order); for validation against a path tracer with isotropic phases.
    /// Default false: the real phases (sky.hpp, "Multiple scattering").
    bool isotropicMultipleScattering = false;
    /// True: every row integrates its multiple scattering along its view
    /// rays; for comparisons and benchmarks. Default false: where the rows lie
    /// less than 6 deg apart, every second row takes it from its neighbours
    /// (a cubic in elevation; sky_solver.cpp, "Multiple scattering between
    /// rows"), which moves the pixel by under 0.25%.
    bool multipleScatteringEveryRow = false;
    /// The multiple-scattering LUT is kept while the atmosphere's heights
    /// (radii, viewer height, scale heights, ozone profile) stay the same
    /// and its coefficients drift so little from those the LUT was built
    /// for that the sky moves by at most this fraction of the pixel (floored
    /// at 1% of the brightest sky; estimated per coefficient,
    /// sky_solver_atmosphere.cpp):
    /// a keyed haze then rebuilds the LUT (~9 ms on two threads) every few
    /// tenths of a percent of its change instead of at every evaluation. The
    /// single scattering is always exact. 0: the LUT is rebuilt on any
    /// change. Clamped to 0..0.05; default 0.0025.
    double multipleScatteringTolerance = 0.0025;
};

/// The multiple-scattering LUT Psi_ms (Hillaire 2020, eq. 10) of the cached
/// atmosphere: radiance per unit sun illuminance [1/sr] added by all
/// scattering orders >= 2 at a height for a sun zenith cosine.
struct MultipleScatteringTable {
    int heightCount = 0;          ///< rows
    int cosineCount = 0;          ///< columns
    std::vector<double> heights;  ///< [heightCount] height of each row above the ground [m]
    std::vector<double> cosines;  ///< [cosineCount] the sun's zenith cosine of each column
    std::vector<float> psi;       ///< RGB at (row * cosineCount + column) * 3
};

/// The solved hemisphere table for one light (sun or moon).
struct SkyTable {
    int azimuthCount = 0;
    int elevationCount = 0;
    std::vector<float> rayleigh;  ///< I_R, RGB per texel (see mapping above)
    std::vector<float> mie;       ///< I_M, RGB per texel
    std::vector<float> multiple;  ///< I_ms [1/sr], RGB per texel (phases applied: none to apply)
    /// Average of the horizon row(s): the colour of far fog is
    /// E * (P_R(mu) horizonRayleigh + P_M(mu) horizonMie + horizonMultiple).
    glm::dvec3 horizonRayleigh{0.0};
    glm::dvec3 horizonMie{0.0};
    glm::dvec3 horizonMultiple{0.0};
    /// The light direction (unit, from the scene) the table was solved for.
    glm::dvec3 lightDirection{0.0, 1.0, 0.0};
    /// Azimuth of the light [rad], from north (-Z) towards east (+X).
    double lightAzimuth = 0.0;
    /// The row mapping (see "Table mapping" above), set by the solver from
    /// the light (setSkyTableMapping). All 0 (the default, and any light above
    /// 1 deg): the quadratic mapping.
    double bandElevation = 0.0;    ///< E [rad], > 0 where bandShare > 0
    double bandShare = 0.0;        ///< a, 0..1: share of the rows in the horizon band
    double shadowElevation = 0.0;  ///< c [rad]: centre of the rows at the earth's shadow
    double shadowWidth = 0.0;      ///< w [rad], > 0 where shadowShare > 0
    double shadowShare = 0.0;      ///< b, 0..1 - a: share of the rows at the earth's shadow
    /// The column mapping (see "Table mapping" above): k [1/rad] of the cap
    /// of the earth's shadow, whose onset lies at el = c - k psi^2, and the
    /// warp's strength g (0..1). Both 0: columns uniform in azimuth.
    double capCurvature = 0.0;
    double capStrength = 0.0;
    /// Bumped on every completed solve.
    unsigned long long generation = 0;
};

/// Phase-less integrals in one direction, bilinearly interpolated.
struct SkySample {
    glm::dvec3 rayleigh{0.0};
    glm::dvec3 mie{0.0};
    glm::dvec3 multiple{0.0};  ///< 0 where the table has no multiple channel
};

/// Sets the row mapping of `table` (bandElevation .. shadowShare) for a
/// light direction and atmosphere (the planet, the top and the viewer's
/// height place the earth's shadow), as SkySolver does for every solve (the
/// mapping above). Needs table.elevationCount.
void setSkyTableMapping(SkyTable& table, const AtmosphereParams& air, const glm::dvec3& lightDirection);

/// Continuous row (0..elevationCount-1) of an elevation [rad, clamped to
/// 0..pi/2] in the table's mapping (sky.hpp, "Table mapping").
double skyTableRow(const SkyTable& table, double elevation);
/// Elevation [rad] of a continuous row (0..elevationCount-1), the inverse of
/// skyTableRow; row elevationCount-1 is exactly pi/2.
double skyTableElevation(const SkyTable& table, double row);
/// skyTableElevation of the whole rows 0..count-1 (the same to within
/// 1e-13 of the mapped position; each row's root is started from the row
/// before, a fraction of the cost).
void skyTableElevations(const SkyTable& table, int count, double* out);

/// The column mapping's constants (sky.hpp, "Table mapping", columns): the
/// shares of azimuthCount (each side of the anti-light point) inside the cap
/// of the earth's shadow, in the band of its onset and between that band
/// and the knot psiE; and the band's least width [deg].
inline constexpr double kSkyCapInsideShare = 3.0 / 128.0;
inline constexpr double kSkyCapOnsetShare = 12.0 / 128.0;
inline constexpr double kSkyCapNearShare = 13.0 / 128.0;
inline constexpr double kSkyCapMinBandDeg = 1.0;
/// The onset band's outer knot: sqrt((kSkyCapOnsetGrowth P)^2 + D^2).
inline constexpr double kSkyCapOnsetGrowth = 2.0;
/// The band's width D is at most this many times c (below kSkyCapMinBandDeg;
/// psiE keeps the 1 deg floor).
inline constexpr double kSkyCapBandPerKink = 500.0;
/// The band's columns are uniform in ln(1 + y / Y0), y = psi^2 - P^2, Y0
/// = (kSkyCapBandScale c)^2 + (kSkyCapBandOnsetScale P)^2: geometric in
/// the height above the onset beyond Y0. At the cap's top the lit sky
/// switches on as ~psi^5 ~10 c from the anti-light point and levels off
/// over ~100-1000 c, and below it it ramps up over ~10 P: two decades of
/// azimuth in the band's 12-20 columns.
inline constexpr double kSkyCapBandScale = 10.0;
inline constexpr double kSkyCapBandOnsetScale = 1.0;
/// The last segment (psiE .. pi) is quadratic in its columns, with this
/// slope at psiE relative to its mean (and 2 - it at pi).
inline constexpr double kSkyCapFarSlope = 0.2;
/// The segment between the band's outer knot and psiE likewise: just below
/// the cap's top of a light less than 0.005 deg down the lit sky beside the
/// cap levels off 0.2-0.4 deg from the anti-light point, just beyond the
/// band, where its kSkyCapNearShare columns crowd.
inline constexpr double kSkyCapNearSlope = 0.25;
/// The share of the rows in the cap (0 .. c) and as far above it (c .. 2c),
/// taken from the horizon band's: half uniform in (c - el)^kSkyCapBelowPower
/// below c, half in cbrt(el - c) above.
inline constexpr double kSkyCapRowShare = 16.0 / 63.0;
/// The power of the cap's rows below c (0.5 would be uniform in the
/// onset's azimuth; 0.35 crowds them towards c).
inline constexpr double kSkyCapBelowPower = 0.35;
/// For a light just set the cap's share grows by up to kSkyCapRowBoost, as
/// the kink's elevation c falls from kSkyCapBoostStartDeg to
/// kSkyCapBoostFullDeg (c ~ L there), taken from the band's share too:
/// below c the lit sky beside the cap ramps up over a width that grows from
/// ~0.3 to ~1.5 deg within 1% of c.
inline constexpr double kSkyCapRowBoost = 2.0;
inline constexpr double kSkyCapBoostStartDeg = 0.01;
inline constexpr double kSkyCapBoostFullDeg = 0.005;
/// The cap's share of the rows, d = kSkyCapRowShare g times the boost, for
/// the kink's elevation c [rad] and the cap's strength g.
/// Below c the cap's rows go from uniform in u^kSkyCapBelowPower (u = (c -
/// el) / c) to uniform in ln(1 + u / kSkyCapLogScale) as the boost comes in
/// (skyCapBoostFraction): for a light less than 0.005 deg down the lit sky
/// beside the cap changes its shape about as ln u, from ~0.05 deg wide at
/// 0.9998 c to 1.5 deg at 0.97 c; with ln(1 + u / 5e-4) the 16 rows below
/// c are ~1.6x apart in u from 3e-4 to 0.2.
inline constexpr double kSkyCapLogScale = 5e-4;
/// 0..1, how far the cap's rows are boosted for the kink's elevation c
/// [rad]: 0 above kSkyCapBoostStartDeg, 1 below kSkyCapBoostFullDeg.
inline double skyCapBoostFraction(double c) {
    const double t = (kSkyCapBoostStartDeg - c * 180.0 / kPi) / (kSkyCapBoostStartDeg - kSkyCapBoostFullDeg);
    return t > 1.0 ? 1.0 : t > 0.0 ? t : 0.0;
}
/// For a light just set the column mapping's shares and the band's outer
/// knot change with the boost fraction m (skyCapBoostFraction), from the
/// constants above at m = 0 to these at m = 1: 20 columns in the band (2
/// from inside the cap, whose single scattering is dark, and 6 from the last
/// segment), its outer knot at 6 P (just below the cap's top the lit sky
/// ramps up over ~10 P), and the cap's rows below c logarithmic on the
/// scale min(kSkyCapLogScale, 3 c).
inline constexpr double kSkyCapInsideShareSet = 2.0 / 128.0;
inline constexpr double kSkyCapOnsetShareSet = 20.0 / 128.0;
inline constexpr double kSkyCapOnsetGrowthSet = 6.0;
inline constexpr double kSkyCapLogScalePerKink = 3.0;
/// The column mapping's shape for the kink's elevation c [rad] (above).
struct SkyCapShape {
    double insideShare = kSkyCapInsideShare;  ///< of the columns, each side
    double onsetShare = kSkyCapOnsetShare;
    double onsetGrowth = kSkyCapOnsetGrowth;
    double logScale = kSkyCapLogScale;  ///< of the cap's rows below c (skyCapBelowRow)
};
inline SkyCapShape skyCapShape(double c) {
    const double m = skyCapBoostFraction(c);
    SkyCapShape s;
    s.insideShare = kSkyCapInsideShare + m * (kSkyCapInsideShareSet - kSkyCapInsideShare);
    s.onsetShare = kSkyCapOnsetShare + m * (kSkyCapOnsetShareSet - kSkyCapOnsetShare);
    s.onsetGrowth = kSkyCapOnsetGrowth + m * (kSkyCapOnsetGrowthSet - kSkyCapOnsetGrowth);
    const double scale = kSkyCapLogScalePerKink * c;
    s.logScale = scale > 0.0 && scale < kSkyCapLogScale ? scale : kSkyCapLogScale;
    return s;
}
inline double skyCapRowShare(double c, double g) {
    const double boost = 1.0 + (kSkyCapRowBoost - 1.0) * skyCapBoostFraction(c);
    return kSkyCapRowShare * boost * (g > 1.0 ? 1.0 : g > 0.0 ? g : 0.0);
}
/// The cap's rows below c: 0 at u = (c - el) / c = 0 (the kink) to 1 at u = 1
/// (the horizon), (1 - m) u^kSkyCapBelowPower + m ln(1 + u / s) / ln(1 + 1 /
/// s) for the boost fraction m and the log scale s (SkyCapShape::logScale).
/// The terms whose weight is 0 are skipped (the same value: m is 0 or 1
/// but for kinks 0.005-0.01 deg up); `logNorm` = ln(1 + 1 / s), for a caller
/// that evaluates many u with one s.
inline double skyCapBelowRow(double u, double m, double s, double logNorm) {
    if (m == 0.0) return std::pow(u, kSkyCapBelowPower);
    if (m == 1.0) return std::log1p(u / s) / logNorm;
    return (1.0 - m) * std::pow(u, kSkyCapBelowPower) + m * std::log1p(u / s) / logNorm;
}
inline double skyCapBelowRow(double u, double m, double s) {
    return skyCapBelowRow(u, m, s, std::log1p(1.0 / s));
}

/// Continuous column (0..azimuthCount, wrapping) of an azimuth `relative`
/// [rad] from the light's (any value, wrapped into [0, 2 pi)) in the row at
/// `elevation` [rad] (the column mapping: uniform except around the cap of
/// the earth's shadow opposite a light just set).
double skyTableColumn(const SkyTable& table, double relative, double elevation);
/// skyTableAzimuth of the whole columns 0..count-1 of the row at `elevation`
/// into out[0..count-1] (the row's mapping set up once).
void skyTableAzimuths(const SkyTable& table, double elevation, int count, double* out);
/// Whether the table's columns are warped (else uniform in azimuth in every row).
inline bool skyTableColumnsWarped(const SkyTable& table) {
    return table.capCurvature > 0.0 && table.capStrength > 0.0 && table.shadowElevation > 0.0 &&
           table.azimuthCount >= 4;
}
/// Azimuth from the light [rad, 0..2 pi] of a continuous column
/// (0..azimuthCount) in the row at `elevation`, the inverse of skyTableColumn.
double skyTableAzimuth(const SkyTable& table, double column, double elevation);

/// Table lookup for a unit view direction (world space).
SkySample sampleSkyTable(const SkyTable& table, const glm::dvec3& viewDirection);

/// Radiance [same unit as illuminance / sr] in a view direction: the table
/// sample with both phase functions applied for that direction, plus the
/// multiple scattering: E (P_R I_R + P_M I_M + I_ms).
glm::dvec3 skyRadiance(const SkyTable& table, double mieAnisotropy, const glm::dvec3& viewDirection,
                       const glm::dvec3& illuminance);

/// The first two zenith-cosine moments of the sky's radiance over the upper
/// hemisphere: first = E integral of (P_R I_R + P_M I_M + I_ms) v.y d omega
/// (skyIrradiance), second = the same with v.y^2; one pass of the midpoint
/// rule below for every weight linear in v.y (a first + b second).
struct SkyCosineMoments {
    glm::dvec3 first{0.0};
    glm::dvec3 second{0.0};
};
SkyCosineMoments skyCosineMoments(const SkyTable& table, double mieAnisotropy, const glm::dvec3& illuminance);

/// Cosine-weighted irradiance of the sky on an upward surface [illuminance
/// unit]: E integral over the upper hemisphere of (P_R I_R + P_M I_M + I_ms)
/// v.y d omega, by the midpoint rule on 64 azimuths x 16 elevations of
/// skyRadiance. The clear sky's share of a scene's ambient light.
glm::dvec3 skyIrradiance(const SkyTable& table, double mieAnisotropy, const glm::dvec3& illuminance);
/// The same with a weight linear in the zenith cosine: E integral of (P_R I_R
/// + P_M I_M + I_ms) v.y (a + b v.y) d omega. a = 1, b = 0 is skyIrradiance;
/// a = 1/2, b = 3/4 is the sky's light as a thick cloud deck passes it on
/// (the Eddington beam transmission's angular factor, overcastLight).
glm::dvec3 skyIrradiance(const SkyTable& table, double mieAnisotropy, const glm::dvec3& illuminance, double a,
                         double b);

/// The sky behind far fog seen in a unit view direction v, phase-less: the
/// table's horizon row (row 0) at v's azimuth, blended with the horizon
/// averages by v's elevation,
///   H(v) = (1 - s) average + s row0(azimuth of v),  s = |v.xz| = cos(elevation),
/// so fog towards the horizon matches the sky right behind it and fog seen
/// steeply (lit from all around) takes the azimuthal mean. At twilight the
/// horizon ring varies by 100x or more in azimuth (the glow towards the sun
/// against the earth's shadow), which the mean alone would spread over every
/// fog. A table without rows gives the averages alone. A table of one row
/// (skyHorizonRow) is enough.
SkySample horizonSkySample(const SkyTable& table, const glm::dvec3& viewDirection);

/// The horizon row of `table` (row 0, all columns) as a table of one row,
/// with the light's direction and azimuth and the horizon averages: what
/// horizonSkySample needs (FogLight::horizonRow).
SkyTable skyHorizonRow(const SkyTable& table);

/// Colour of far fog seen in a view direction: horizonSkySample with the
/// per-direction phase functions, E (P_R H_R(v) + P_M H_M(v) + H_ms(v)).
glm::dvec3 horizonFogRadiance(const SkyTable& table, double mieAnisotropy, const glm::dvec3& viewDirection,
                              const glm::dvec3& illuminance);

/// The Nishita 1993 solver: a 2D optical-depth table (height x light zenith
/// angle, Rayleigh, Mie and ozone) and integration over exponentially
/// distributed layers along each view ray, plus Hillaire 2020 multiple
/// scattering with an explicit third order and the phases in the second (the
/// Psi_ms LUT, built with the optical-depth table). Multithreaded (threads made once,
/// in the constructor); allocates nothing per solve. Single-threaded,
/// multi-threaded and amortised solves give bit-identical tables. The
/// optical-depth table and the Psi_ms LUT are kept while the AtmosphereParams stay bitwise equal,
/// so a moving sun only re-solves the hemisphere; the LUT alone is also kept while the
/// atmosphere drifts within SkySolverDesc::multipleScatteringTolerance (a keyed haze), so
/// its result then depends on the atmosphere the LUT was built for (at most that far off;
/// tolerance 0 for exact results); and they are shared between solvers in
/// the process (the last four atmospheres built, by any solver with the same layer count,
/// optical-depth angles and multiple-scattering settings), so the moon's solver adopts
/// what the sun's built for the same air instead of building it again (bit-identical;
/// a solver adopts a kept LUT only within its own tolerance). Earth shadow: where
/// the ray from a point to the light hits the planet, that point is unlit (the transmittance to the light is
/// 0), also for a light below the horizon.
class SkySolver {
public:
    explicit SkySolver(const SkySolverDesc& desc = {});
    ~SkySolver();
    SkySolver(const SkySolver&) = delete;
    SkySolver& operator=(const SkySolver&) = delete;

    /// Solves the whole table for these parameters and light direction, and
    /// publishes it. Abandons an amortised solve in progress.
    void solve(const AtmosphereParams& air, const glm::dvec3& lightDirection);

    /// Starts an amortised solve; nothing is computed yet. The result is
    /// bit-identical to solve() with the same arguments.
    void beginSolve(const AtmosphereParams& air, const glm::dvec3& lightDirection);
    /// Solves up to `rows` more rows. Where the atmosphere changed, its
    /// tables come first and count as rows too: the optical depths one step
    /// and, where the multiple-scattering LUT is rebuilt (not kept,
    /// multipleScatteringTolerance), 21 more (its orders in 20, its
    /// resampling), then one to share the tables with other solvers.
    /// Returns true when the new table is complete and published through
    /// table().
    bool continueSolve(int rows);
    /// True while an amortised solve is in progress.
    bool solving() const;

    /// Forgets the cached optical-depth table and Psi_ms LUT, so the next solve
    /// rebuilds them even if the AtmosphereParams are bitwise unchanged and
    /// another solver has built them (benchmarks, tests).
    void invalidateCache();

    /// A copy of the Psi_ms LUT in use: built for the last atmosphere, or
    /// kept from an earlier one (multipleScatteringTolerance); empty before
    /// the first solve and with singleScatteringOnly.
    MultipleScatteringTable multipleScatteringTable() const;

    /// The last completed table (zeros, generation 0, before the first).
    const SkyTable& table() const;
    /// The description with defaults resolved.
    const SkySolverDesc& desc() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace aerial
