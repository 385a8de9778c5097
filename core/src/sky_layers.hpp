// sky_layers.hpp — private: where the sky solver's layers lie along the
// view rays (sky_layers.cpp): the shell heights of equal mixed mass, and
// the curvature stencil of one layer of a row.
#pragma once

#include "sky_kernels.hpp"

#include <aerial/atmosphere.hpp>

namespace aerial::detail {

/// Heights [m] of the layers + 1 shells between the viewer height h0 and
/// the top: shell k holds the mixed mass F = k / layers, F the weighted
/// mean of the normalised cumulative Rayleigh and Mie densities above h0
/// (one share each) and a uniform-in-height share (kUniformShare), solved by
/// Newton's method. shellHeight[0] = h0, shellHeight[layers] = top (all h0
/// when top <= h0).
void equalMassShells(const AtmosphereParams& air, double h0, double top, int layers, double* shellHeight);

/// The curvature stencil of layer l of a row whose view ray crosses the
/// shells at distances crossing[0..layers] (LayerConstants::stencil,
/// stencilC, stencilD).
void layerStencil(const double* crossing, int layers, int l, LayerConstants& lc);

}  // namespace aerial::detail
