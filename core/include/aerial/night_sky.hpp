// aerial/night_sky.hpp — the light of a moonless night sky besides the stars:
// airglow, the faint emission of the upper atmosphere (the oxygen green
// line at 557.7 nm, OH bands) from a thin layer ~90 km up. With the moon
// down it is what lights the sky between the stars and, with the emitters,
// what a night picture is made of.
//
// Usage:
//   glm::dvec3 L = aerial::airglowRadiance(viewDirection, state.zenithTransmittance);
//   glm::dvec3 E = aerial::airglowIrradiance(state.zenithTransmittance);  // on an upward surface
//
// Model (all physical: radiance in Aerial's unit, 5000 cd/m^2, aerial/exposure.hpp):
//   * the natural moonless sky (airglow with the zodiacal light and the
//     unresolved stars) is 21.6-22.0 mag/arcsec^2 in V at the zenith, 1.7-2.5e-4
//     cd/m^2 (Leinert et al. 1998, "The 1997 reference of diffuse night sky
//     brightness"; Benn and Ellison 1998, La Palma). kAirglowZenithRadiance,
//     above the atmosphere, is 2.25e-4 cd/m^2, so the zenith seen through the
//     default air is 2.1e-4 cd/m^2 (21.8 mag/arcsec^2) and an upward surface
//     gets ~1.3 mlx (outdoors: 1-2 mlx with the stars);
//   * its colour is the spectrum integrated with the CIE 1931 observer and
//     converted to linear Rec.709 with the sun as white, as the sky is: a
//     solar-like continuum (zodiacal light, starlight) reddened by B-V ~ +0.15
//     (the dark sky's B-V is ~0.8 against the sun's 0.65) plus the airglow's
//     lines (O I 557.7 and 630.0 nm, Na D 589 nm): a pale warm grey,
//     (1.15, 0.98, 0.75) x its luminance;
//   * a thin emitting shell at kAirglowHeight is seen obliquely towards the
//     horizon: the van Rhijn factor V(mu) = 1 / sqrt(1 - (Rg / (Rg + h))^2
//     (1 - mu^2)) (x6 at the horizon for h = 90 km), mu the view's sine of
//     elevation (the viewer at the ground, Rg = 6360 km);
//   * the lower atmosphere dims it like the stars, T = T_zenith^X(mu) with X
//     the Kasten-Young (1989) relative air mass, but the shell lights the
//     whole sky, so air that scatters its light out of a line of sight also
//     scatters the rest of the shell's light into it: a uniform source seen
//     through a scattering layer keeps much of its radiance (Garstang 1989,
//     "Night-sky brightness at observatories and sites"; the horizon is not
//     reddened into an orange band). Of the extinguished share, the fraction
//     kAirglowScatteredFill comes back in the source's colour:
//     L = L0 V(mu) (T + f (1 - T));
//   * nothing below the horizon.
//
// Light pollution (optional, off by default): a city's glow, the light of
// its lamps scattered back down by the air. An artist's shape, not a
// radiative transfer: the luminance at the zenith Lz [cd/m^2] (a natural
// sky ~2e-4; Bortle's suburban 1-2e-3, a city sky 7e-3 = 18 mag/arcsec^2
// and more) times
//   s(v) = (sqrt(X(mu)) + K exp(-theta^2 / (2 sigma^2))) / (1 + K exp(-(pi/2)^2 / (2 sigma^2)))
// (X the relative air mass, theta the angle from the city's point on the
// horizon, K = 20, sigma = 30 deg), so the zenith is Lz, the horizon ~5 Lz
// away from the city and ~21 Lz towards it (the glow dome over a city on
// the horizon), nothing below the horizon. Its colour is the lamps':
// sodium (high pressure, ~2 100 K) or white LEDs (~4 000 K), as
// blackbodyColour (emitter.hpp) of that temperature.
//
// Clouds over a city are lit from below by the same light: the lamps' light
// leaves the ground as an upward flux F, the clear air scatters a fraction
// of it back, L ~ tau_up F / pi (tau_up the air's vertical scattering depth
// in V), and a cloud base above receives F itself,
//   E_up(v) = pi L(v) / tau_up,   tau_up = kLightPollutionUplightDepth,
// taking L along the direction the cloud is seen in (brighter towards the
// city). A thick deck reflects ~albedo (1 - T_d) of it, so an overcast city
// sky reads several times brighter than its clear sky (Kyba et al. 2011,
// "Cloud coverage acts as an amplifier for ecological light pollution in
// urban ecosystems", PLoS ONE 6(3): up to ~10x at the zenith in Berlin),
// while at a dark site clouds stay darker than the airglow they hide.
#pragma once

#include <glm/vec3.hpp>

namespace aerial {

/// The lamps whose light a city's glow is made of.
enum class LightPollutionLamps {
    Sodium,  ///< high-pressure sodium, orange (~2 100 K)
    Led,     ///< white LEDs (~4 000 K)
};

/// A city's glow on the night sky (preset "night.*"; off when zenith 0).
struct LightPollution {
    /// Luminance the glow adds at the zenith [cd/m^2], 0..1. Default 0 (off).
    double zenithLuminance = 0.0;
    /// Azimuth of the city [deg from north towards east], the glow's dome.
    double azimuthDeg = 180.0;
    LightPollutionLamps lamps = LightPollutionLamps::Sodium;
};

/// Airglow radiance at the zenith above the atmosphere [radiance units], RGB:
/// 2.25e-4 cd/m^2 of luminance in the colour above (see the header).
inline constexpr glm::dvec3 kAirglowZenithRadiance{1.15 * 4.5e-8, 0.98 * 4.5e-8, 0.75 * 4.5e-8};
/// Height of the emitting layer [m].
inline constexpr double kAirglowHeight = 90000.0;
/// Rg / (Rg + kAirglowHeight), Rg = 6360 km: the ratio in the van Rhijn factor.
inline constexpr double kAirglowShellRatio = 6360000.0 / (6360000.0 + kAirglowHeight);
/// Share of the airglow scattered out of a line of sight that the rest of
/// the shell scatters back into it (see the header), 0..1.
inline constexpr double kAirglowScatteredFill = 0.5;

/// Kasten and Young (1989) relative optical air mass for a direction of
/// sine of elevation mu (1 at the zenith, ~38 at the horizon; mu clamped to
/// [0, 1]): X = 1 / (mu + 0.50572 (96.07995 - z)^-1.6364), z the zenith
/// angle in degrees.
double relativeAirMass(double mu);

/// The van Rhijn factor of the airglow layer (see the header), mu clamped
/// to [0, 1].
double airglowVanRhijn(double mu);

/// Airglow radiance seen along a unit view direction (world, +Y up):
/// kAirglowZenithRadiance V(mu) (T + f (1 - T)), T = T_zenith^X(mu), f =
/// kAirglowScatteredFill; 0 below the horizon.
glm::dvec3 airglowRadiance(const glm::dvec3& viewDirection, const glm::dvec3& zenithTransmittance);

/// Irradiance of the airglow on an upward surface, integral of
/// airglowRadiance(v) cos(theta) over the upper hemisphere (numeric, 256
/// rings, exact to ~1e-5 relative).
glm::dvec3 airglowIrradiance(const glm::dvec3& zenithTransmittance);

/// Unit world direction of the city's point on the horizon: azimuth
/// azimuthDeg + northOffsetDeg, as the sun's (sun.hpp: (sin az, 0, -cos az)).
glm::dvec3 lightPollutionCityDirection(const LightPollution& glow, double northOffsetDeg);

/// Linear Rec.709 colour of the lamps, luminance 1.
glm::dvec3 lightPollutionColour(LightPollutionLamps lamps);

/// The city's glow seen along a unit view direction [radiance units]: Lz
/// s(v) times the lamps' colour over kNitsPerRadianceUnit (see the header);
/// 0 below the horizon or when off. Non-finite inputs give 0.
glm::dvec3 lightPollutionRadiance(const LightPollution& glow, const glm::dvec3& viewDirection,
                                  double northOffsetDeg);

/// Its irradiance on an upward surface [illuminance units] (numeric, 128 x
/// 64 cells; independent of the azimuth).
glm::dvec3 lightPollutionIrradiance(const LightPollution& glow);

/// The air's vertical scattering optical depth in V that turns a city's
/// upward flux into its glow (see the header): Rayleigh's 0.1 plus a light
/// haze.
inline constexpr double kLightPollutionUplightDepth = 0.12;

/// The city's light reaching a cloud base from below, for a cloud seen along
/// the unit view direction [illuminance units]: pi lightPollutionRadiance /
/// kLightPollutionUplightDepth. 0 when off or below the horizon.
glm::dvec3 lightPollutionUplight(const LightPollution& glow, const glm::dvec3& viewDirection,
                                 double northOffsetDeg);

}  // namespace aerial
