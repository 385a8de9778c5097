// sky_layers.hpp — private: where the sky solver's layers lie
// (sky_layers.cpp): the heights of the shells of equal mixed mass.
#pragma once

#include <aerial/atmosphere.hpp>

namespace aerial::detail {

/// Heights [m] of the layers + 1 shells between the viewer height h0 and
/// the top: shell k holds the mixed mass F = k / layers, F the weighted
/// mean of the normalised cumulative Rayleigh and Mie densities above h0
/// (one share each) and a uniform-in-height share (kUniformShare), solved by
/// Newton's method. shellHeight[0] = h0, shellHeight[layers] = top (all h0
/// when top <= h0).
void equalMassShells(const AtmosphereParams& air, double h0, double top, int layers, double* shellHeight);

}  // namespace aerial::detail
