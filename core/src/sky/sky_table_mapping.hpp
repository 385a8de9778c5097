// sky_table_mapping.hpp — private to core: where the sky table's rows and
// columns go, the one formula that produces the coordinates every table
// carries (SkyTable::rowElevation, SkyTable::columnAzimuth, aerial/sky.hpp).
// setSkyTableMapping sets the mapping's parameters and writes the
// coordinates from them; the solver solves each texel at its coordinates;
// every sampler (sampleSkyTable, the renderer's shaders, a bake's reader,
// the tests' reference) reads the coordinates and never this formula.
//
// The mapping (SkyTable::bandElevation .. capStrength, set by
// setSkyTableMapping from the light):
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
//       (skyCapRowShare, taken from the band's a) between 0 and 2c, half
//       below c uniform in (c - el)^0.35 (kSkyCapBelowPower: crowded towards
//       c, where the lit sky beside the cap ramps up over a width that grows
//       fast with c - el), half above c uniform in cbrt(el - c),
//       crowded at the cap's top where straight opposite the light the lit
//       sky switches on within a few 1e-4 deg for a light 0.01 deg down;
//       g = capStrength, 1 up to 0.5 deg, fading to 0 at 1 deg;
//     With 128 x 64 texels this keeps the table within 2% of the exact
//     single-scattering integral relative to the pixel (floored at 1% of the
//     brightest sky) in every direction tests/core/test_sky.cpp probes, off
//     the texel centres too, for suns from -6 to 90 deg (SkyOffTexel), and
//     averaged over a pixel (1920 px across 90 deg) in dense sweeps of the
//     anti-light quarter near the kink for suns 0.00002-0.3 deg below the
//     horizon (SkyShadowOnset; docs/sky_table_notes.md has the figures);
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
//     the cap the lit sky ramps up over an azimuth that grows with P. Each knot x is rounded to a whole
//     column (so that no knot bends the bilinear filter's line inside a texel). The knots are
//     mirror-symmetric, so column i still equals column W - i. The horizon averages then weight row 0 by
//     azimuth;
//   * texel (i, j) is stored at index (j * azimuthCount + i) * 3 (RGB, float).
//   Directions below the horizon use row 0.
//
#pragma once

#include <aerial/sky.hpp>

#include <cmath>

namespace aerial {

/// Continuous row (0..elevationCount-1) of an elevation [rad, clamped to
/// 0..pi/2] in the table's mapping (the mapping above).
double skyTableRow(const SkyTable& table, double elevation);
/// Elevation [rad] of a continuous row (0..elevationCount-1), the inverse of
/// skyTableRow; row elevationCount-1 is exactly pi/2.
double skyTableElevation(const SkyTable& table, double row);
/// skyTableElevation of the whole rows 0..count-1 (the same to within
/// 1e-13 of the mapped position; each row's root is started from the row
/// before, a fraction of the cost).
void skyTableElevations(const SkyTable& table, int count, double* out);

/// The column mapping's constants (the mapping above, columns): the
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
/// The cap's share of the rows, d = kSkyCapRowShare g, for the cap's
/// strength g (clamped to 0..1).
inline double skyCapRowShare(double g) { return kSkyCapRowShare * (g > 1.0 ? 1.0 : g > 0.0 ? g : 0.0); }

/// Continuous column (0..azimuthCount, wrapping) of an azimuth `relative`
/// [rad] from the light's (any value, wrapped into [0, 2 pi)) in the row at
/// `elevation` [rad] (the column mapping: uniform except around the cap of
/// the earth's shadow opposite a light just set).
double skyTableColumn(const SkyTable& table, double relative, double elevation);
/// skyTableAzimuth of the whole columns 0..count-1 of the row at `elevation`
/// into out[0..count-1] (the row's mapping set up once).
void skyTableAzimuths(const SkyTable& table, double elevation, int count, double* out);
/// Azimuth from the light [rad, 0..2 pi] of a continuous column
/// (0..azimuthCount) in the row at `elevation`, the inverse of skyTableColumn.
double skyTableAzimuth(const SkyTable& table, double column, double elevation);

}  // namespace aerial
