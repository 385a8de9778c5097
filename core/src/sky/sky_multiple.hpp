// sky_multiple.hpp — private: the multiple-scattering LUT Psi_ms of Hillaire
// 2020 ("A Scalable and Production Ready Sky and Atmosphere Rendering
// Technique", EGSR 2020, section 5.5, eq. 5-10), built by the sky solver
// (sky_solver.cpp) once per change of the atmosphere.
//
// For a point at height h whose sun has zenith cosine mu_s:
//   L_2nd(h, mu_s) = integral over the sphere of L'(omega) P_u d omega
//   L'(omega)      = integral sigma_s T(x -> y) T(y -> sun) P_u ds
//                    + T(x -> ground) T(ground -> sun) max(mu_ground, 0) rho / pi
//   f_ms(h)        = integral over the sphere of L_f(omega) P_u d omega
//   L_f(omega)     = integral sigma_s T(x -> y) ds
//                    + T(x -> ground) rho / pi E_f,  E_f = integral L_f(ground, omega) cos d omega
// with P_u = 1 / (4 pi), sigma_s = beta_R + beta_M (scattering), rho the
// ground albedo, the sun of unit illuminance and the rays ending at the
// ground or the top. Hillaire then takes Psi_ms = L_2nd / (1 - f_ms) (eq.
// 10): every higher order as the local transfer f_ms of the one before, as if
// the field were the same everywhere around the point. Where it is not (a
// low sun: lit upper air over a dark lower one) that under-estimated the
// horizon by 30-37% against the path tracer, also with isotropic phases in
// the tracer, i.e. it was the series, not the phase. So here the orders 3 to
// kMsLastOrder (5) are integrated explicitly, each from the one before,
// through the atmosphere:
//   J_2 = L_2nd
//   J_n(h, mu_s) = mean over the sphere of ( integral sigma_s T(x -> y) J_(n-1)(h(y), mu_s(y)) ds
//                  + T(x -> ground) rho / pi (E_f J_(n-1)(0, mu_g) + [n = 3] E_1(mu_g)) )
//   Psi_ms = J_2 + .. + J_5 + J_5 f_ms / (1 - f_ms)    (the local series as the tail only)
// with E_1(mu_g) the irradiance that single scattering sends down to the
// ground where the sun's zenith cosine is mu_g (from the ground row's upward
// rays; Hillaire's ground term has the direct sun only, which left the
// skylight's bounce out). Against the path tracer with isotropic phases
// this is within 8% for suns from -2 to 90 deg (1.3x at -6 deg before the
// solver's lookups became geometric between columns, see resample). Orders
// 4 and 5 matter in twilight only, where the tail's local series is worst
// (blue, whose f_ms is largest): at sun -6 deg they took the horizon from
// 0.85x to 0.91x the tracer in blue, at -2 and 0 deg by 2%, above the
// horizon by under 1%; they cost ~1.6x the LUT build on one thread (67 ->
// 110 ms; 36 -> 48 ms on two, bench BM_SkySolve rebuild:1), which runs on a
// change of the atmosphere only, not of the sun. Psi_ms is a radiance per unit illuminance
// [1/sr]; the sky's multiple scattering along a view ray is then
// integral sigma_s T(viewer -> x) Psi_ms(h(x), mu_s(x)) ds (sky.hpp).
//
// The phases. Hillaire's LUT is isotropic twice over: the first scattering
// (of the sun's light, in L') and the last (towards the viewer, P_u). Against
// a path tracer with the real phases at the first scattering and isotropic
// ones after it, that LUT was within 5% for suns from -2 deg up (0.12 at -6
// deg), but against the real phases everywhere 0.11 at +2 deg and 0.13 at
// -2 deg (the horizon opposite a low sun, blue): the anisotropy of the later
// scatterings (made isotropic in the tracer for Rayleigh or for Mie alone,
// each accounted for about half). So the second order has the real phases:
//   L_1(omega)  = P_R(omega.sun) I_R(omega) + P_M(omega.sun) I_M(omega) + ground,
//     I_X = integral beta_X rho_X T(x -> y) T(y -> sun) ds, the phases averaged
//     over each quadrature cell (the Mie peak is narrower than a cell);
//   J_2 = mean of L_1 over the sphere (Psi_ms's order 2, isotropic), and its
//   view-dependent remainder as the Legendre series of the phases to l = 2
//   (Funk-Hecke: the band l of L_1 is scaled by the phase's coefficient g_l):
//     A_X(v) = integral (P_X(omega.v) - 1 / (4 pi)) L_1(omega) d omega
//            ~ 3 g_X1 / (4 pi) D.v + 5 g_X2 / (4 pi) (3/2 v.M.v - 1/2 M_0),
//     D = integral omega L_1, M = integral omega omega^T L_1, M_0 = trace M,
//   g_R1 = 0, g_R2 = 1/10 (Rayleigh exactly), g_M1, g_M2 of Cornette-Shanks
//   (numerically). In the point's frame (up u, the sun's horizontal s, and p)
//   L_1 is symmetric about the (u, s) plane, so A_X needs six numbers per
//   height, sun cosine and channel (aniso_, resample): D_u, D_s and
//   B_0 = 3/2 M_pp - 1/2 M_0, B_u = 3/2 (M_uu - M_pp), B_s = 3/2 (M_ss - M_pp),
//   B_us = 3 M_us, with
//     3/2 v.M.v - 1/2 M_0 = B_0 + B_u v_u^2 + B_s v_s^2 + B_us v_u v_s.
//   The sky solver adds sigma_R A_R(v) + sigma_M A_M(v) to sigma_s Psi_ms
//   along each view ray (sky_kernels.cpp, shellAniso). The field of the
//   third order, L_2 (J_2 carried along each ray, and the ground's share),
//   is view-dependent in the same way: its moments, times 1 / (1 - f_ms) for
//   the orders after it (the tail's own geometric series), are added to
//   L_1's, so A_X(v) holds the remainder of all orders >= 2 (Funk-Hecke is
//   linear in the field). The sources stay isotropic: J_2, not J_2 + A, is
//   what the third order carries. Against the path tracer this took the
//   horizon at sun 0 to +10 deg from 6.3-2.2% to 4.7-1.4% (16384 paths;
//   table in the note of the change). setAtmosphere's `isotropic` restores
//   Hillaire's phases (validation against the isotropic tracer).
//   Mie's truncation. Cornette-Shanks at g = 0.8 has g_M1 = 0.84, g_M2 =
//   0.71, g_M3 = 0.58: its series to l = 2 is far from the phase where the
//   field is directional, as at a point in the earth's shadow in twilight
//   (lit only from the sunlit air towards the sun's side of the horizon):
//   for a collimated field it sends 1.8x the isotropic radiance straight
//   back (the phase: 0.06x), which left the horizon opposite a set sun too
//   bright, red (Mie's share of the scattering is largest in red): 1.11x at
//   -2 deg, 1.25x at -6 deg against the tracer. So Mie's phase is taken
//   delta-M (Wiscombe 1977, "The delta-M method", J. Atmos. Sci. 34): the
//   forward peak's share f = g_M3 as a delta (the light going straight on)
//   and the rest, (g_l - f) / (1 - f), to l = 2. The light going straight on
//   is the field from behind the point, which only its moments give; it is
//   read through the Fejer window of the series (sigma_1 = 1/2, sigma_2 =
//   1/10: the l <= 2 reconstruction of a direction that is nowhere negative,
//   proportional to (1 + cos)^2), so that a directional field sends nothing
//   negative or spurious back. Together the Mie coefficients used are
//     g~_1 = g_M1 - f / 2,  g~_2 = g_M2 - 9 f / 10
//   (0.55 and 0.19 at g = 0.8). Against the tracer at 16384 paths the worst
//   per sun went from -6: 0.36, -2: 0.114, 0: 0.047, +2: 0.038, +10: 0.014,
//   +30: 0.011, +90: 0.018 to 0.144, 0.067, 0.054, 0.042, 0.023, 0.020,
//   0.018 (plain delta-M, the delta's share isotropic: 0.27, 0.078, 0.060,
//   0.044, 0.023, 0.024, 0.025). What the window still lost was the sun's
//   side of the horizon in twilight (0.72x the tracer's multiple scattering
//   in red at -2 deg, 0.58x at 0): there the light the Mie peak scatters on
//   is the single scattering along the view ray itself, bright and sharply
//   peaked at the horizon, which no l <= 2 field can carry. So the narrow
//   part of the peak, f_s = the phase's share within kMsStraightOnConeDeg
//   (4.5 deg: 0.072 at g = 0.8, 0.13 at 0.86; the horizon's single
//   scattering changes over a few degrees), is taken as going straight on,
//   exactly (the cone's width: "Mie's last scattering", below): along each view
//   ray the light that reaches s keeps f_s of Mie's scattering, i.e. sees
//   e^(f_s tau_M(viewer -> s)) more transmittance (tau_M Mie's scattering
//   depth), which the sky solver adds as a straight-on share of the single
//   scattering (its phases per column, into the multiple channel: the
//   single channels stay the single scattering) and as a factor on the
//   multiple scattering's own weights. Only f - f_s then goes through the
//   Fejer window, and Mie's isotropic share of Psi is 1 - f_s:
//     g~_1 = g_M1 - f_s - (f - f_s) / 2,  g~_2 = g_M2 - f_s - 9 (f - f_s) / 10.
//   The solver integrates the factor over each layer together with the
//   layer's transmittance (sky_solver_row.cpp, solveRow), so a haze of any
//   depth stays finite. With it (and orders to 5) the worst per sun is
//   -6: 0.123, -2: 0.046, 0: 0.035, +2: 0.024, +10: 0.014, +30: 0.013,
//   +90: 0.013 (in a first
//   form, carried in the single channels, f_s of 0.05 and 0.15 gave 0.053
//   and 0.046 at -2 deg; the whole e^(f tau_M) without the window, "delta-M
//   extinction" with f_s = f, 1.2x in red at -2 deg). Rows whose share stays
//   under 0.5% of their single scattering (above ~7 deg) leave it out,
//   fading it in from half that (sky_solver_row.cpp, kStraightOnFloor): it
//   costs ~3% of the solve.
//   Mie's last scattering. The series still missed most of what Mie's
//   peak does with a peaked field: at a point in the earth's shadow in
//   twilight the sunlit air is a band a few degrees above the horizon
//   towards the sun, and Mie's peak (half its light within ~25 deg) sends
//   it on towards a viewer who looks at the sun's side of the horizon; the
//   window reconstructs that band as a lobe as wide as (1 + cos)^2. At the
//   ground, for the sun 6.4 deg down (mu_s = -0.11), Mie's remainder
//   towards the horizon under the sun came to 5.1 J_2 in blue by quadrature
//   of L_1 over the 96 directions, and to 1.6 J_2 by the series; straight
//   opposite, -0.81 and -0.71 J_2. Against the path tracer at 262144 paths
//   (converged to ~1%; at the 16384 of the test the twilight references
//   move by up to 6%) the sun's side of the horizon was 12% too dark in
//   blue at -6 deg and 5.5% at -2 deg, the anti-solar horizon 6% too
//   bright in red at -6 deg. So the LUT also keeps, for the field whose
//   moments the series uses, L = L_1 + L_2 / (1 - f_ms) (field_), what the
//   series misses at kMsViews view nodes v (14 zenith positions: the 12
//   zenith nodes and the two poles; times 6 azimuths: 0, the 4 azimuth
//   nodes and pi):
//     C_v = integral P_M'(omega . v) L(omega) d omega - (1 - f_s) J - A_M(v),
//   with P_M' Mie's phase outside the straight-on cone (its share within
//   goes along the view ray, above), J = J_2 + J_3 / (1 - f_ms) the
//   field's mean and A_M(v) the series with the coefficients above; the
//   integral over the 96 directions, with the phase averaged over each
//   direction's cell and its mirror (viewMatrix_, once per g: Mie's peak is
//   narrower than the cells). The sky solver adds sigma_M C(v) at every
//   eighth shell of each view ray (with the skipped shells' weights, as A_X
//   at every fourth; not where Mie's weight is under kViewMieFloor of the
//   scattering's), bilinear between the view nodes (the view's zenith
//   position at the shell, the cosine of its azimuth from the sun's
//   horizontal) and linear between the sun-cosine columns (sky_kernels.cpp,
//   shellViews). The series stays for Rayleigh (exact to l = 2) and carries
//   Mie's part of the later orders. Against the path tracer (262144
//   paths, seed 11) the worst per sun went from -6: 0.122, -2: 0.055, 0:
//   0.042, +2: 0.027, +10: 0.013, +30: 0.013, +90: 0.013 to 0.042, 0.030,
//   0.027, 0.023, 0.019, 0.016, 0.014 (with L_1 alone: 0.054 at -6 deg;
//   every fourth shell instead of eighth: the same to 0.001; every
//   sixteenth: 0.070 at -6 deg). Tried first and left: the window replaced
//   by a Henyey-Greenstein lobe fitted to the field's first (or first and
//   second) moments, whose convolution with Mie's is closed: -6 deg 0.095,
//   but -2 deg 0.064 (the lobe is round, the field a band); a straight-on
//   cone of 0 to 15 deg moved the sun's side of the horizon by 0.3%. Cost
//   (2 threads, best of 15, the old and new library run alternately): the
//   per-sun solve +0.01 to +0.05 ms (0.57-0.96 -> 0.60-0.99 ms; at sun -0.5
//   deg, the slowest, 0.93-1.00 -> 0.96-0.99 over five runs of each), the
//   LUT's rebuild after a change of the atmosphere 6.9 -> 8.7-9.0 ms, and
//   2.3 ms more where Mie's g changes (viewMatrix_, on one thread). Its
//   fields and views (~2.3 MB) are freed once resampled (releaseViews).
//   The straight-on cone's width, with the views in place (worst per sun
//   against the path tracer, seed 11; the default air at 262144 paths for
//   -6, -2, 0, +2, +10, +30, +90 deg, hazy_sunset's at 131072 for -6, -2,
//   0, +2, +10, +45 deg):
//     2 deg:   0.043 0.030 0.025 0.020 0.016 0.014 0.016 | 0.168 0.080 0.093 0.063 0.062 0.040
//     3 deg:   0.042 0.029 0.025 0.021 0.020 0.017 0.018 | 0.160 0.079 0.070 0.072 0.087 0.063
//     4 deg:   0.043 0.034 0.022 0.018 0.016 0.015 0.016 | 0.137 0.075 0.066 0.046 0.053 0.080
//     4.5 deg: 0.043 0.030 0.024 0.018 0.016 0.012 0.014 | 0.136 0.080 0.067 0.039 0.044 0.032
//     5 deg:   0.043 0.030 0.025 0.020 0.016 0.012 0.014 | 0.143 0.123 0.068 0.047 0.041 0.035
//     6 deg:   0.042 0.030 0.027 0.023 0.019 0.016 0.014 | 0.143 0.233 0.131 0.085 0.049 0.051
//     8 deg:   0.047 0.049 0.040 0.037 0.032 0.024 0.017 | 0.167 0.485 0.293 0.179 0.107 0.073
//   A wider cone carries light the peak turns by a few degrees along the
//   view ray itself: in the haze (g = 0.86, whose peak is narrower) the
//   sun's side of the horizon at -2 deg came out 1.23x in red at 6 deg.
//   4.5 deg is as good in the default air and 0.08 against 0.23 at -2 deg
//   in the haze; in desert_dusk's (g = 0.7, 65536 paths) -2, 0, +10 deg
//   read 0.170, 0.180, 0.063 against 0.184, 0.190, 0.061 at 6 deg.
//
// Discretisation (documented in <aerial/sky.hpp>):
//  * rows: kMsRows heights, the shells of kMsLayers equal-mass layers from
//    the ground to the top (sky_layers.hpp);
//  * columns: kMsCosines (64) sun zenith cosines mu = sign(x) x^2, x uniform in
//    [-1, 1] (msCosineOfColumn): dense near the horizon, where Psi changes
//    fastest. In twilight Psi falls about exponentially with the sun's
//    depression, and linear interpolation between columns over-estimates it
//    (with 32 columns, 2.3 deg apart at -6 deg, by up to 1.8x; with 64, 1.2
//    deg apart, by up to 1.3x);
//  * directions: 96 (Hillaire: 64 uniform), crowded where a low sun's light
//    comes from: 12 zenith nodes cos theta = sign(x) x^2 (x midpoints in
//    [-1, 1]: elevations 0.4, 3.6, 10 ... deg either side of the horizon) x
//    8 azimuths phi = pi u^1.5 (u midpoints in [0, 1]: 8, 41, 89 and 147 deg
//    from the sun), each with its quadrature weight, computed as 4
//    azimuths of the sun's side and their mirrors (the integrand is symmetric
//    about the sun's vertical plane). In deep twilight (sun 9-14 deg down) the
//    only light is from the thin sunlit upper atmosphere far towards the sun,
//    near the horizon seen from every height; the 64 uniform directions
//    missed it and left the sky 10-100x too dark and red against the path
//    tracer (test_sky_multiple, DeepTwilightAgainstPathTracer); this set is
//    within a factor 2.3 there at 1.5x the LUT's cost;
//  * each ray is cut where it crosses the shells, so the sun's optical depth
//    at every crossing is a 1D lookup in one row of its own optical-depth
//    table (sky_depth.hpp, kMsAngles columns); within a segment the total
//    optical depth is linear and integrated in closed form (msSegmentKernel),
//    the segment's densities by 4-point Gauss-Legendre (nodeKernel).
#pragma once

#include "sky_depth.hpp"

#include <aerial/atmosphere.hpp>

#include <cmath>
#include <vector>

namespace aerial::detail {

inline constexpr int kMsLayers = 24;
inline constexpr int kMsRows = kMsLayers + 1;
inline constexpr int kMsCosines = 64;
inline constexpr int kMsAngles = 64;
inline constexpr int kMsZeniths = 12;
inline constexpr double kMsZenithPower = 2.0;   // cos theta = sign(x) |x|^2
inline constexpr int kMsAzimuths = 4;           // of 8, by symmetry
inline constexpr double kMsAzimuthPower = 1.5;  // phi = pi u^1.5
inline constexpr int kMsCombos = kMsCosines * kMsAzimuths;  // per crossing, a multiple of 16
inline constexpr int kMsMaxCrossings = 2 * kMsLayers + 2;
inline constexpr int kMsLastOrder = 5;  // orders 2..kMsLastOrder explicit, the rest the geometric tail
inline constexpr int kMsAniso = 6;      // D_u, D_s, B_0, B_u, B_s, B_us (the phases, above)
inline constexpr int kMsPhaseSubsamples = 8;    // per cell side, for the cell-averaged phases
inline constexpr double kMsPsiFloor = 1e-30;    // 1/sr, below any sky that shows (resample)
inline constexpr double kMsAnisoRatio = 100.0;  // |A_n / Psi| at most (resample)
inline constexpr double kMsStraightOnConeDeg = 4.5;  // Mie's straight-on share ("Mie's truncation")
/// The field's directions (one side of the sun's vertical plane), and the
/// view nodes of Mie's last scattering ("Mie's last scattering"): the
/// poles and the zenith nodes, times 0, the azimuth nodes and pi from the sun.
inline constexpr int kMsDirections = kMsZeniths * kMsAzimuths;
inline constexpr int kMsViewZeniths = kMsZeniths + 2;
inline constexpr int kMsViewAzimuths = kMsAzimuths + 2;
inline constexpr int kMsViews = kMsViewZeniths * kMsViewAzimuths;

/// A quadrature node: a zenith cosine or an azimuth [rad], and its weight.
struct MsNode {
    double angle;
    double weight;
};
/// Zenith node z (cosines from +1 down to -1, crowded at the horizon); the weights sum to 1.
MsNode msZenithNode(int z);
/// Azimuth node a in (0, pi) from the sun (crowded towards the sun); the weights sum to 1.
MsNode msAzimuthNode(int a);

/// Sun zenith cosine of LUT column j: sign(x) x^2, x = -1 + 2 j / (kMsCosines - 1).
double msCosineOfColumn(int column);

/// The zenith mapping at cell position t (node z's midpoint: t = z + 0.5):
/// x = -1 + t dx in (-1, 1), cos theta = sign(x) |x|^p (from +1 down), and
/// the weight (1/2) d(cos theta) = (p/2) |x|^(p-1) dx of a whole cell there.
MsNode zenithAt(double t);
/// The azimuth mapping at cell position t: u = t du in (0, 1), phi = pi u^q,
/// and the weight d(phi) / pi = q u^(q-1) du of a whole cell there.
MsNode azimuthAt(double t);

/// View node v's direction in the point's frame: its zenith cosine and
/// sine, and its azimuth from the sun's horizontal.
struct ViewNode {
    double cosT, sinT, phi;
};
/// View node v's direction (viewNodeAt), computed once.
const ViewNode& msViewNode(int v);

/// Per-thread scratch of the LUT build.
struct MsScratch {
    DepthRowScratch depthRow;
    std::vector<double> crossing;                   // [kMsMaxCrossings]
    std::vector<int> shell;                         // [kMsMaxCrossings]
    std::vector<float> nodeS, nodeR, nodeM, nodeO;  // [4 kMsMaxCrossings]
    std::vector<float> records;                     // [2][7][kMsCombos]
    std::vector<float> acc, accMie;                 // [3][kMsCombos] one ray's I_R, I_M
    std::vector<double> ground;                     // [3][kMsCombos] one ray's ground share
    std::vector<double> moment;                     // [kMsAniso + 1][3][kMsCombos] of L_1 (sums)
    std::vector<float> source;                      // [3][3][kMsCombos] J_n at two crossings and the start
    std::vector<float> orderAcc;                    // [3][kMsCombos]
    std::vector<int> column;                        // [kMsCombos] LUT column of a crossing
    std::vector<float> fraction;                    // [kMsCombos] and the fraction towards the next
    double cosT = 1.0, sinT = 0.0;                  // the ray of buildOrderRow
    std::vector<double> groundSky;                  // [3][kMsCombos]
    MsScratch();
};

/// The LUT and its own optical-depth table.
class MultipleScatteringLut {
public:
    MultipleScatteringLut();

    /// New (sanitized) atmosphere: the shells, row constants and phases;
    /// `isotropic`: Hillaire's isotropic phases (no anisotropic remainder).
    void setAtmosphere(const AtmosphereParams& air, bool isotropic = false);
    /// Row `row` (0..kMsRows-1) of the optical-depth table.
    void buildDepthRow(int row, MsScratch& s);
    /// Row `row` of scattering order `order` (2..kMsLastOrder): order 2 (and
    /// f_ms) needs every optical-depth row, a higher one every row of the
    /// order before; the last order completes Psi_ms's row.
    void buildOrderRow(int row, int order, MsScratch& s);
    /// Psi_ms at `count` heights [m] (linear in height between rows) for the
    /// sky solver's kernel, which interpolates it geometrically between the
    /// sun-cosine columns (in twilight Psi falls about exponentially with the
    /// sun's depression, and linear interpolation over-estimated it by up to
    /// 1.3x between columns 1.2 deg apart): out[c][k][kMsCosines] = -ln Psi
    /// (Psi floored at kMsPsiFloor), and the anisotropy relative to Psi,
    /// aniso[n * 3 + c][k][kMsCosines] = A_n / Psi (clamped to +-kMsAnisoRatio).
    /// With `mie` (non-null where anisotropic()) also what the series misses
    /// of Mie's last scattering at the view nodes, relative to Psi:
    /// mie[k][v][c][kMsCosines] = C_v / Psi (clamped to +-kMsAnisoRatio), v =
    /// iz * kMsViewAzimuths + ia ("Mie's last scattering").
    /// Writes the shells kBegin..kEnd-1 of the count (the rest untouched:
    /// the shells go to threads apart).
    void resample(const double* heights, int count, int kBegin, int kEnd, float* out, float* aniso,
                  float* mie) const;
    /// Frees what only the build and resample use (the fields and views of
    /// Mie's last scattering, ~2.3 MB): a solver's shared snapshot copies
    /// the LUT. setAtmosphere allocates them again.
    void releaseViews();
    /// Whether the anisotropic remainder is in use (not isotropic, see setAtmosphere).
    bool anisotropic() const { return !isotropic_; }
    /// The Legendre coefficients 3 g_1 / (4 pi) and 5 g_2 / (4 pi) of Rayleigh
    /// (r1 = 0) and Mie: A_X = r1 D.v + r2 (B_0 + ...), see above.
    double rayleighBand2() const { return isotropic_ ? 0.0 : 5.0 * 0.1 / (4.0 * kPi); }
    double mieBand1() const { return isotropic_ ? 0.0 : 3.0 * mieG1_ / (4.0 * kPi); }
    double mieBand2() const { return isotropic_ ? 0.0 : 5.0 * mieG2_ / (4.0 * kPi); }
    /// f_s, the share of Mie's phase within kMsStraightOnConeDeg of straight
    /// on (0 with isotropic phases): taken as unscattered, see above.
    double mieStraightOn() const { return isotropic_ ? 0.0 : mieStraightOn_; }

    const std::vector<double>& heights() const { return height_; }
    /// Psi_ms [1/sr], RGB per entry, (row * kMsCosines + column) * 3.
    const std::vector<float>& psi() const { return psi_; }

private:
    void buildSecondOrderRow(int row, MsScratch& s);
    double storeMoments(int row, int c, int j, const MsScratch& s, bool add, double scale);
    int rayCrossings(int row, double cosT, MsScratch& s, bool& hitsGround) const;
    void rayTransfer(int row, double cosT, MsScratch& s, double out[3], double endT[3],
                     bool& hitsGround) const;
    void segmentDepths(int i, const MsScratch& s, double scatter[3], double tau[3],
                       double* mieScatter = nullptr) const;
    void buildPhases();
    void buildViewMatrix();
    void storeViews(int row);

    AtmosphereParams air_;
    MsScratch groundScratch_;
    double groundReflection_[3] = {0.0, 0.0, 0.0};
    DensityConstants density_;
    std::vector<double> height_;          // [kMsRows]
    std::vector<double> horizonCos_;      // [kMsRows]
    std::vector<float> angleScale_;       // [kMsRows]
    std::vector<float> depth_;            // [3][kMsRows][kMsAngles]
    std::vector<float> comboP_, comboQ_;  // [kMsCombos]
    std::vector<float> psi_;              // [kMsRows][kMsCosines][3]
    std::vector<float> order_[2];         // J_n, J_n+1: [kMsRows][kMsCosines][3]
    std::vector<double> sum_;             // J_2 + .. J_n [kMsRows][kMsCosines][3]
    std::vector<double> fms_;             // [kMsRows][3]
    std::vector<double> groundSky_;       // E_1 at the ground [kMsCosines][3]
    bool isotropic_ = false;
    double phaseG_ = NAN;                 // the Mie g of phaseM_
    double mieG1_ = 0.0, mieG2_ = 0.0;    // Cornette-Shanks' Legendre coefficients, delta-M (above)
    double mieStraightOn_ = 0.0;          // f_s (mieStraightOn)
    std::vector<float> phaseR_, phaseM_;  // cell-averaged first phases [kMsZeniths][kMsCombos]
    std::vector<float> aniso_;            // [kMsRows][kMsCosines][kMsAniso][3]
    std::vector<float> viewMatrix_;       // [kMsViews][kMsDirections] (buildViewMatrix)
    std::vector<float> views_;            // C_v [kMsRows][kMsViews][3][kMsCosines]
    std::vector<float> field_;            // L_1 + L_2 / (1 - f_ms) [kMsRows][3][kMsDirections][kMsCosines]
};

}  // namespace aerial::detail
