// spectral_data.cpp — tables for SpectralSkySolver (spectral_data.hpp).
#include "spectral_data.hpp"

namespace aerial::spectral {

// Serdyuchenko et al. 2014, "High spectral resolution ozone absorption
// cross-sections", 233 K, averaged over each 10 nm bin starting at the
// wavelength (as tabulated by Bruneton 2017's demo, atmosphere/demo/demo.cc).
const double kOzoneCrossSection[kOzoneCount] = {
    1.18e-27,  2.182e-28, 2.818e-28, 6.636e-28, 1.527e-27, 2.763e-27, 5.52e-27,  8.451e-27,
    1.582e-26, 2.316e-26, 3.669e-26, 4.924e-26, 7.752e-26, 9.016e-26, 1.48e-25,  1.602e-25,
    2.139e-25, 2.755e-25, 3.091e-25, 3.5e-25,   4.266e-25, 4.672e-25, 4.398e-25, 4.701e-25,
    5.019e-25, 4.305e-25, 3.74e-25,  3.215e-25, 2.662e-25, 2.238e-25, 1.852e-25, 1.473e-25,
    1.209e-25, 9.423e-26, 7.455e-26, 6.566e-26, 5.105e-26, 4.15e-26,  4.228e-26, 3.237e-26,
    2.451e-26, 2.801e-26, 2.534e-26, 1.624e-26, 1.465e-26, 2.078e-26, 1.383e-26, 7.105e-27};

const double kNodeWavelengths[kNodeCount] = {430.0, 470.0, 520.0, 570.0, 610.0, 660.0};

// Least-squares fit (sky_spectral.hpp, "The matrices"): for each of X, Y,
// Z, the weights minimising sum_s ((sum_i w_i I_s(lambda_i) - XYZ_s) / Y_s)^2
// over the training spectra I_s, where XYZ_s = sum over 380..780 nm in 10 nm
// steps of cmf(lambda) E_sun(lambda) I_s(lambda) 10 nm (CIE 1931 2-degree
// observer; ASTM G-173 extraterrestrial irradiance in 10 nm bins), with the
// white sum_i w_i = sum cmf E_sun 10 nm held by a penalty 1e4 times the
// data's and a ridge of 1e-3 towards linear-interpolation weights. Spectra:
// single scattering (phases applied) of 2268 view rays (sun elevations -8
// .. 90 deg in 28 steps, view elevations 0 .. 90 deg in 11, relative
// azimuths 0 .. 180 deg in 8) of Bruneton 2017's Earth with its ozone x0.6,
// 1, 1.6 and Mie x1, 5. The program that fitted them is in the history
// (commit "Add the tool that fits the spectral sky's colour weights",
// tests/tools/fit_spectral_weights.cpp); test_sky_spectral holds the
// result to 0.01 in u'v' against its own 41-wavelength reference.
const double kXyzWeights[kNodeCount][3] = {
    {17.0712493, -0.224472819, 88.9860018}, {14.341955, 6.82300441, 103.997663},
    {15.9521332, 71.6966234, 10.6425038},   {49.4813287, 71.0576006, 0.390838834},
    {76.4366863, 38.9277468, -0.581166277}, {15.5036252, 5.79261646, 0.00958507842}};

const double kXyzToRec709[3][3] = {{3.2404542, -1.5371385, -0.4985314},
                                   {-0.9692660, 1.8760108, 0.0415560},
                                   {0.0556434, -0.2040259, 1.0572252}};

}  // namespace aerial::spectral
