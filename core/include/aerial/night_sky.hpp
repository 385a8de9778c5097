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
// Model:
//   * the zenith radiance above the atmosphere is the constant
//     kAirglowZenithRadiance, a documented artistic value: the natural
//     moonless sky (airglow with the zodiacal light and the unresolved
//     stars) is ~22 mag/arcsec^2 in V, ~1.7e-4 cd/m^2 (Leinert et al. 1998,
//     "The 1997 reference of diffuse night sky brightness"); Aerial's
//     default moon is 1000x the physical moon (preset.hpp), so the airglow
//     is scaled by the same 1000 to keep a moonlit and a moonless sky in
//     their real ratio (~16x): 0.17 cd/m^2 = 3.4e-5 radiance units
//     (aerial/exposure.hpp: 5000 cd/m^2 per unit), slightly blue-green;
//   * a thin emitting shell at kAirglowHeight is seen obliquely towards the
//     horizon: the van Rhijn factor V(mu) = 1 / sqrt(1 - (Rg / (Rg + h))^2
//     (1 - mu^2)) (x6 at the horizon for h = 90 km), mu the view's sine of
//     elevation (the viewer at the ground, Rg = 6360 km);
//   * the lower atmosphere dims it like the stars: T_zenith^X(mu), X the
//     Kasten-Young (1989) relative air mass;
//   * nothing below the horizon.
#pragma once

#include <glm/vec3.hpp>

namespace aerial {

/// Airglow radiance at the zenith above the atmosphere [radiance units], RGB.
inline constexpr glm::dvec3 kAirglowZenithRadiance{2.6e-5, 3.5e-5, 4.2e-5};
/// Height of the emitting layer [m].
inline constexpr double kAirglowHeight = 90000.0;

/// Kasten and Young (1989) relative optical air mass for a direction of
/// sine of elevation mu (1 at the zenith, ~38 at the horizon; mu clamped to
/// [0, 1]): X = 1 / (mu + 0.50572 (96.07995 - z)^-1.6364), z the zenith
/// angle in degrees.
double relativeAirMass(double mu);

/// The van Rhijn factor of the airglow layer (see the header), mu clamped
/// to [0, 1].
double airglowVanRhijn(double mu);

/// Airglow radiance seen along a unit view direction (world, +Y up):
/// kAirglowZenithRadiance V(mu) T_zenith^X(mu); 0 below the horizon.
glm::dvec3 airglowRadiance(const glm::dvec3& viewDirection, const glm::dvec3& zenithTransmittance);

/// Irradiance of the airglow on an upward surface, integral of
/// airglowRadiance(v) cos(theta) over the upper hemisphere (numeric, 256
/// rings, exact to ~1e-5 relative).
glm::dvec3 airglowIrradiance(const glm::dvec3& zenithTransmittance);

}  // namespace aerial
