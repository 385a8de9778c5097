// sky_depth.hpp — private: one row of an optical-depth table (Nishita's 2D
// table: height x light zenith cosine), shared by the sky solver's table
// (sky_solver.cpp, one row per shell) and the multiple-scattering LUT's
// (sky_multiple.cpp, one row per shell from the ground).
//
// Column mapping of a row at radius r: the light's zenith cosine c in
// [c_h(r), 1], c_h = -sqrt(1 - (Rg/r)^2) the cosine of the geometric horizon,
// with u = x / (x + kAngleKnee), x = c - c_h, scaled to the columns
// (angleScale): half of the columns lie within kAngleKnee of the horizon,
// where the optical depth changes fastest. Below c_h the ray hits the ground;
// lookups there clamp to c_h, the grazing ray.
#pragma once

#include "sky_kernels.hpp"

#include <aerial/atmosphere.hpp>

#include <cmath>
#include <vector>

namespace aerial::detail {

/// Knee of the angle mapping u = x / (x + k) (x = c - c_h): half the columns
/// lie within k of the horizon cosine.
inline constexpr double kAngleKnee = 0.05;

inline double safeSqrt(double x) { return x > 0.0 ? std::sqrt(x) : 0.0; }

/// The densities of `air` in the kernels' form.
DensityConstants densityConstants(const AtmosphereParams& air);

/// Cosine of the geometric horizon at height h [m] (<= 0).
double horizonCosine(const AtmosphereParams& air, double height);

/// Mapped-column scale of a row with this horizon cosine: column
/// u = x / (x + kAngleKnee) * scale.
double angleScale(int angles, double horizonCos);

/// Scratch of opticalDepthRow, `angles` floats each.
struct DepthRowScratch {
    std::vector<float> q, len1, start2, len2, depthR, depthM, depthO;
    void resize(int angles);
};

/// One row of an optical-depth table at height h [m] (horizon cosine
/// horizonCos): for each of `angles` columns the optical depth to the top
/// of the atmosphere, tau = beta_R m_R + beta_M^ext m_M + beta_O m_O per
/// channel, written to out[c][column] (Gauss-Legendre panels on each side of
/// the perigee, depthKernel).
void opticalDepthRow(const AtmosphereParams& air, const DensityConstants& density, double height,
                     double horizonCos, int angles, DepthRowScratch& s, float* out0, float* out1,
                     float* out2);

}  // namespace aerial::detail
