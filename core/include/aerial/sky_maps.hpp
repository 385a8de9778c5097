// aerial/sky_maps.hpp — the sky and the light of the environment as images
// and coefficients an engine samples without the library: what `aerial
// bake` writes per step (README, "Using a bake in an engine").
//
// Usage:
//   aerial::RgbImage sky = aerial::skyViewMap(state, sunTable, moonTable, 512, 256);
//   aerial::RgbImage farFog = aerial::farFogMap(aerial::FogScene(fogSceneDesc(state, sunTable,
//                                               moonTable)), 256, 128);
//   aerial::IrradianceSH9 ambient = aerial::environmentIrradianceSH9(state, sunTable, moonTable,
//                                               aerial::overcastLight(state, sunTable, moonTable));
//   glm::dvec3 E = aerial::evaluateIrradianceSH9(ambient, normal);   // irradiance on a surface
//
// The sky-view map (after Hillaire 2020, "A Scalable and Production Ready Sky
// and Atmosphere Rendering Technique", its sky-view LUT: lines packed towards
// the horizon, where the sky changes fastest) covers the upper hemisphere:
// texel (x, y) of a W x H map looks along the world azimuth
//   phi_x = 2 pi (x + 0.5) / W      (from north, -Z, towards east, +X)
// and the elevation
//   el_y = pi/2 (y / (H - 1))^2     (line 0 exactly on the horizon, line H - 1 at the zenith),
// so a direction of elevation el >= 0 and azimuth phi samples bilinearly at
//   x = phi W / (2 pi) - 0.5 (wrapping),  y = (H - 1) sqrt(el / (pi/2)),
// i.e. the texture coordinates u = phi / (2 pi), v = (y + 0.5) / H with
// repeat in u and clamp in v. Line 0 holds the sky just above the horizon;
// nothing below the horizon is sky (the far fog map holds what fog shows
// there). The value is the clear sky as the sky pass draws it behind the stars
// (clearSkyRadiance): no clouds, stars or discs of the sun and the moon.
//
// The far fog map holds L_horizon(v) of fog_light.hpp (FogScene::fogColour
// with an infinite distance: the sky behind far fog, under the overcast)
// over the whole sphere, equirectangular: texel (x, y) of W x H at azimuth
// phi_x as above and elevation pi/2 - pi (y + 0.5) / H.
//
// The irradiance coefficients project the radiance arriving from every
// direction, as the fog's light (fogSkyLight, evaluate.hpp) sees it: above
// the horizon the clear sky (clearSkyRadiance) through the gaps of the cloud
// deck plus the deck's underside (OvercastLight), below it the ground's
// Lambertian reflection (groundAlbedo / pi times the irradiance of the sky
// and the sun's and moon's light that reach the ground), onto the real
// spherical harmonics of bands 0-2 and convolve them with the clamped cosine
// (Ramamoorthi and Hanrahan 2001, "An Efficient Representation for Irradiance
// Environment Maps"): E(n) = sum_i c_i Y_i(n) is the irradiance on a surface
// of unit normal n. The basis, in Aerial's world axes (x east, y up, z
// south), in the order engines use (Sloan 2008, "Stupid Spherical Harmonics
// (SH) Tricks"):
//   Y_0 = 0.282095,
//   Y_1 = 0.488603 y,  Y_2 = 0.488603 z,  Y_3 = 0.488603 x,
//   Y_4 = 1.092548 x y,  Y_5 = 1.092548 y z,  Y_6 = 0.315392 (3 z^2 - 1),
//   Y_7 = 1.092548 x z,  Y_8 = 0.546274 (x^2 - y^2);
// c_i = A_l L_i with L_i the radiance's coefficient and A_0 = pi,
// A_1 = 2 pi / 3, A_2 = pi / 4 (divide by A_l for radiance coefficients).
#pragma once

#include <aerial/evaluate.hpp>
#include <aerial/fog_query.hpp>
#include <aerial/sky.hpp>

#include <glm/vec3.hpp>

#include <vector>

namespace aerial {

/// The bake's default sky-view map size: within 2 % of the sky (skyRadiance
/// of 128 x 64 tables) in every direction above the horizon at every sun
/// (tests/core/test_sky_maps.cpp).
inline constexpr int kSkyViewMapWidth = 512;
inline constexpr int kSkyViewMapHeight = 320;
/// The bake's default far fog map size.
inline constexpr int kFarFogMapWidth = 256;
inline constexpr int kFarFogMapHeight = 128;

/// An RGB float image, line 0 first, three floats per texel, finite and >= 0.
struct RgbImage {
    int width = 0;
    int height = 0;
    std::vector<float> rgb;
};

/// Elevation [rad] of the (fractional) line y of a sky-view map of `height`
/// lines: pi/2 (y / (height - 1))^2, y clamped to [0, height - 1].
double skyViewElevation(double line, int height);

/// The fractional line of a sky-view map of `height` lines that holds the
/// elevation `elevation` [rad]: (height - 1) sqrt(el / (pi/2)), el clamped
/// to [0, pi/2].
double skyViewLine(double elevation, int height);

/// The world direction (unit) of texel (x, y) of a W x H sky-view map.
glm::dvec3 skyViewDirection(int x, int y, int width, int height);

/// The clear sky in a unit direction as the sky pass draws it behind the
/// stars [radiance unit, 1 = kNitsPerRadianceUnit cd/m^2]: both tables'
/// skyRadiance (sky.hpp) plus airglowRadiance and lightPollutionRadiance
/// (night_sky.hpp). No clouds, stars, or the discs of the sun and the moon.
glm::dvec3 clearSkyRadiance(const PresetState& state, const SkyTable& sun, const SkyTable& moon,
                            const glm::dvec3& direction);

/// The sky-view map (above) of a state with its solved sun and moon tables.
/// width >= 1, height >= 2.
RgbImage skyViewMap(const PresetState& state, const SkyTable& sun, const SkyTable& moon, int width,
                    int height);

/// The far fog map (above): FogScene::fogColour(v) with an infinite
/// distance, before the fog's colour mode. width, height >= 1.
RgbImage farFogMap(const FogScene& fog, int width, int height);

/// Nine RGB coefficients of the irradiance (above): E(n) = sum c_i Y_i(n).
struct IrradianceSH9 {
    glm::dvec3 c[9] = {};
};

/// The basis function Y_i (above) at a unit direction, i in 0..8.
double sh9Basis(int i, const glm::dvec3& direction);

/// The environment's irradiance coefficients of a state (above): the
/// radiance arriving from every direction integrated by the midpoint rule
/// on 128 azimuths x 64 rings uniform in the zenith cosine per hemisphere.
IrradianceSH9 environmentIrradianceSH9(const PresetState& state, const SkyTable& sun, const SkyTable& moon,
                                       const OvercastLight& overcast);

/// Irradiance on a surface of unit normal n: sum c_i Y_i(n), at least 0.
glm::dvec3 evaluateIrradianceSH9(const IrradianceSH9& sh, const glm::dvec3& normal);

}  // namespace aerial
