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
// the tracer, i.e. it was the series, not the phase. So here the third order
// is integrated explicitly from the second, through the atmosphere:
//   J_2 = L_2nd
//   J_3(h, mu_s) = mean over the sphere of ( integral sigma_s T(x -> y) J_2(h(y), mu_s(y)) ds
//                  + T(x -> ground) rho / pi (E_f J_2(0, mu_g) + E_1(mu_g)) )
//   Psi_ms = J_2 + J_3 + J_3 f_ms / (1 - f_ms)       (the local series as the tail only)
// with E_1(mu_g) the irradiance that single scattering sends down to the
// ground where the sun's zenith cosine is mu_g (from the ground row's upward
// rays; Hillaire's ground term has the direct sun only, which left the
// skylight's bounce out). Against the path tracer with isotropic phases
// this is within 6% for suns from -2 to 90 deg (1.3x at -6 deg); more
// explicit orders change it by under 1% (kMsLastOrder). What remains against
// the real phases is their anisotropy (the LUT is isotropic): up to ~25% at
// the horizon of a low sun. Psi_ms is a radiance per unit illuminance
// [1/sr]; the sky's multiple scattering along a view ray is then
// integral sigma_s T(viewer -> x) Psi_ms(h(x), mu_s(x)) ds (sky.hpp).
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
inline constexpr int kMsLastOrder = 3;  // orders 2..kMsLastOrder explicit, the rest the geometric tail

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

/// Per-thread scratch of the LUT build.
struct MsScratch {
    DepthRowScratch depthRow;
    std::vector<double> crossing;                   // [kMsMaxCrossings]
    std::vector<int> shell;                         // [kMsMaxCrossings]
    std::vector<float> nodeS, nodeR, nodeM, nodeO;  // [4 kMsMaxCrossings]
    std::vector<float> records;                     // [2][7][kMsCombos]
    std::vector<float> acc;                         // [3][kMsCombos] in-scattering
    std::vector<double> ground;                     // [3][kMsCombos] the ground's share
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

    /// New (sanitized) atmosphere: the shells and row constants.
    void setAtmosphere(const AtmosphereParams& air);
    /// Row `row` (0..kMsRows-1) of the optical-depth table.
    void buildDepthRow(int row, MsScratch& s);
    /// Row `row` of scattering order `order` (2..kMsLastOrder): order 2 (and
    /// f_ms) needs every optical-depth row, a higher one every row of the
    /// order before; the last order completes Psi_ms's row.
    void buildOrderRow(int row, int order, MsScratch& s);
    /// Psi_ms at `count` heights [m] (linear in height between rows), as
    /// out[c][k][kMsCosines].
    void resample(const double* heights, int count, float* out) const;

    const std::vector<double>& heights() const { return height_; }
    /// Psi_ms [1/sr], RGB per entry, (row * kMsCosines + column) * 3.
    const std::vector<float>& psi() const { return psi_; }

private:
    void buildSecondOrderRow(int row, MsScratch& s);
    int rayCrossings(int row, double cosT, MsScratch& s, bool& hitsGround) const;
    void rayTransfer(int row, double cosT, MsScratch& s, double out[3], double endT[3],
                     bool& hitsGround) const;
    void segmentDepths(int i, const MsScratch& s, double scatter[3], double tau[3]) const;

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
};

}  // namespace aerial::detail
