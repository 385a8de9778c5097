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
//   Psi_ms         = L_2nd / (1 - f_ms)                                 (eq. 10)
// with P_u = 1 / (4 pi), sigma_s = beta_R + beta_M (scattering), rho the
// ground albedo, the sun of unit illuminance and the rays ending at the
// ground or the top. Unlike Hillaire, f_ms includes the ground's reflection
// of the unit field (E_f from the upward rays at the ground): without it the
// higher orders lose the skylight that the ground sends back (measured
// against the path tracer of tests/support/ms_reference.hpp: with albedo 0.3
// the horizon's multiple scattering came out 25-35% low). Psi_ms is a radiance per unit illuminance [1/sr];
// the sky's multiple scattering along a view ray is then integral sigma_s T(viewer -> x) Psi_ms(h(x),
// mu_s(x)) ds (sky.hpp).
//
// Discretisation (documented in <aerial/sky.hpp>):
//  * rows: kMsRows heights, the shells of kMsLayers equal-mass layers from
//    the ground to the top (sky_layers.hpp);
//  * columns: kMsCosines sun zenith cosines mu = sign(x) x^2, x uniform in
//    [-1, 1] (msCosineOfColumn): dense near the horizon, where Psi changes fastest;
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
inline constexpr int kMsCosines = 32;
inline constexpr int kMsAngles = 64;
inline constexpr int kMsZeniths = 12;
inline constexpr double kMsZenithPower = 2.0;   // cos theta = sign(x) |x|^2
inline constexpr int kMsAzimuths = 4;           // of 8, by symmetry
inline constexpr double kMsAzimuthPower = 1.5;  // phi = pi u^1.5
inline constexpr int kMsCombos = kMsCosines * kMsAzimuths;  // per crossing, a multiple of 16
inline constexpr int kMsMaxCrossings = 2 * kMsLayers + 2;

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
    /// Row `row` of Psi_ms; needs every optical-depth row.
    void buildPsiRow(int row, MsScratch& s);
    /// Psi_ms at `count` heights [m] (linear in height between rows), as
    /// out[c][k][kMsCosines].
    void resample(const double* heights, int count, float* out) const;

    const std::vector<double>& heights() const { return height_; }
    /// Psi_ms [1/sr], RGB per entry, (row * kMsCosines + column) * 3.
    const std::vector<float>& psi() const { return psi_; }

private:
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
};

}  // namespace aerial::detail
