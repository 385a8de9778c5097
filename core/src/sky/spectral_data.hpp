// spectral_data.hpp — the published spectra behind SpectralSkySolver
// (<aerial/sky_spectral.hpp>): ozone's absorption cross-section and the
// fitted colour-matching weights of the six solved wavelengths.
#pragma once

namespace aerial::spectral {

/// Ozone absorption cross-section [m^2] in 10 nm bins from 360 to 830 nm
/// (kOzoneCrossSection[i] at 360 + 10 i nm).
inline constexpr int kOzoneFirstNm = 360;
inline constexpr int kOzoneStepNm = 10;
inline constexpr int kOzoneCount = 48;
extern const double kOzoneCrossSection[kOzoneCount];

/// Number density [1/m^3] at the ozone tent's peak for 300 Dobson units
/// (2.687e20 molecules/m^2 each) spread over the tent's 15 km integral: the
/// density whose cross-sections give AtmosphereParams' default ozone.
inline constexpr double kOzonePeakDensity = 300.0 * 2.687e20 / 15000.0;

/// The six solved wavelengths [nm], ascending, and their CIE 1931 XYZ
/// weights: XYZ = sum_i kXyzWeights[i] I(kNodeWavelengths[i]) for a
/// spectrum I per unit extraterrestrial solar irradiance (fit described in
/// sky_spectral.hpp; the scale is that of sum cmf(lambda) E_sun(lambda) 10 nm
/// with E_sun in W/m^2/nm, irrelevant after the white balance).
inline constexpr int kNodeCount = 6;
extern const double kNodeWavelengths[kNodeCount];
extern const double kXyzWeights[kNodeCount][3];

/// CIE XYZ -> linear Rec.709 (D65), IEC 61966-2-1, row-major.
extern const double kXyzToRec709[3][3];

}  // namespace aerial::spectral
