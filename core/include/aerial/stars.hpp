// aerial/stars.hpp — which stars a person sees: the sky's surface brightness
// in magnitudes, the naked-eye limiting magnitude of a point source against
// a sky background, a star's magnitude after the atmosphere and the clouds,
// and the magnitudes of the renderer's procedural star field.
//
// Usage:
//   double sky = skyBrightnessFromLuminance(backgroundNits);   // [mag/arcsec^2]
//   double limit = limitingMagnitude(backgroundNits);          // at the eye
//   double seen = extinctedMagnitude(m, zenithTransmittanceV, mu, cloudT);
//   double shown = starThresholdFade(seen, limit);             // 0..1
//
// Model:
//   * Surface brightness (V) and luminance: L = 10.8e4 10^(-0.4 S) cd/m^2
//     (S in mag/arcsec^2; 22 mag/arcsec^2 = 1.7e-4 cd/m^2, the natural
//     moonless sky of Leinert et al. 1998).
//   * A star of V magnitude m gives the illuminance E = 2.54e-6 10^(-0.4 m) lx
//     at the eye (Schaefer 1990's zero point, m = -16.57 - 2.5 log10(E/fc),
//     1 fc = 10.764 lx).
//   * Threshold (Hecht 1934's law with the night-vision constants of
//     Schaefer 1990, "Telescopic limiting magnitudes", PASP 102, 212, eq. 2):
//     a point source is seen when its illuminance at the eye exceeds
//     I = C (1 + sqrt(K B))^2 foot-candles, C = 10^-9.8, K = 10^-1.9, B the
//     background in nanolamberts (1 nL = 3.183e-6 cd/m^2). In magnitudes
//     this is the usual conversion of a sky brightness S into a naked-eye
//     limiting magnitude, m = 7.93 - 5 log10(10^(4.316 - S/5) + 1): 7.93 on
//     a black background, 6.62 at S = 22, 6.44 at 21.6, 4.4 under a full
//     moon (S ~ 18.5), 0 at S = 13.7 (0.36 cd/m^2), -1.75 (no star of the
//     field) at S = 11.9 (1.8 cd/m^2), -4 at S = 9.6. The stars
//     are looked for with averted (rod) vision, so the night-vision constants
//     hold for every background; Schaefer's day-vision branch (B > 1500 nL,
//     an observer fixating a star whose place he knows) would show Sirius
//     until about sunset, which a person under the sky does not see. The
//     observer is experienced and dark-adapted to the background, Snellen
//     ratio 1, both eyes (Schaefer's "clean" threshold: no further factors).
//   * Extinction: the star's magnitude grows by -2.5 log10(T^X), T the
//     zenith transmittance in V (Aerial's green channel), X the Kasten-Young
//     relative air mass (relativeAirMass, night_sky.hpp: the same dimming as
//     the sky pass applies to the stars); a cloud in front with
//     transmittance t adds -2.5 log10(t).
//   * The renderer shows a star with the weight starThresholdFade: 1 when it
//     is kStarFadeMagnitudes / 2 brighter than the limit, 0 when as much
//     fainter, smoothstep between.
//
// The procedural star field (shaders/sky.glsl): ~kStarFieldStars stars over
// the whole sphere, each with a uniform hash u in [0, 1), magnitude
// m(u) = max(kStarFieldBrightest, kStarFieldFaintest + 2 log10(1 - u)): the
// cumulative count brighter than m is N(m) = kStarFieldStars 10^((m - 6.5) / 2)
// = 10^(0.5 m + 0.674), as the real sky's (Allen's Astrophysical
// Quantities: ~15 stars brighter than 1, ~150 than 3, ~1500 than 5, ~4800
// than 6, ~9000 than 6.5 over the whole sky); one star at -1.5 (Sirius).
#pragma once

namespace aerial {

/// Luminance of a sky of surface brightness 0 V mag/arcsec^2 [cd/m^2].
inline constexpr double kSkyBrightnessZeroPointNits = 1.08e5;
/// Illuminance at the eye from a star of V magnitude 0 [lx].
inline constexpr double kZeroMagnitudeIlluminanceLux = 2.54e-6;
/// Width of the fade of a star across its threshold [mag].
inline constexpr double kStarFadeMagnitudes = 0.5;
/// What limitingMagnitude returns where no star can be seen (a background
/// luminance that is not finite).
inline constexpr double kNoStarMagnitude = -30.0;
/// What extinctedMagnitude returns for a star that cannot reach the eye.
inline constexpr double kHiddenStarMagnitude = 99.0;

/// The procedural field: cells (right ascension x sine of declination), the
/// probability that a cell holds a star, and so the expected number of stars
/// on the whole sphere.
inline constexpr unsigned kStarFieldColumns = 1024;
inline constexpr unsigned kStarFieldRows = 512;
inline constexpr double kStarFieldProbability = 0.016;
inline constexpr double kStarFieldStars = kStarFieldColumns * kStarFieldRows * kStarFieldProbability;
/// Magnitude of the brightest and of the faintest star of the field.
inline constexpr double kStarFieldBrightest = -1.5;
inline constexpr double kStarFieldFaintest = 6.5;

/// L = kSkyBrightnessZeroPointNits 10^(-0.4 S) [cd/m^2] for a surface
/// brightness S [V mag/arcsec^2]; 0 for S not finite.
double luminanceFromSkyBrightness(double magPerSquareArcsec);
/// The inverse [V mag/arcsec^2]; luminances below 1e-12 cd/m^2 (or not
/// finite) read as 1e-12 (~44 mag/arcsec^2).
double skyBrightnessFromLuminance(double nits);

/// Illuminance at the eye of a star of V magnitude m [lx].
double starIlluminanceLux(double magnitude);
/// The inverse: V magnitude of a point source of illuminance E [lx] (E
/// clamped to >= 1e-30 lx).
double starMagnitudeFromIlluminance(double lux);

/// Naked-eye limiting magnitude (V, at the eye) of a point source against a
/// background of luminance L [cd/m^2] (the model above). Negative or zero
/// L gives the dark limit (7.93); a non-finite L gives kNoStarMagnitude.
double limitingMagnitude(double backgroundNits);

/// Magnitude of a star of magnitude m above the atmosphere as seen through
/// it: m - 2.5 log10(T^X(mu) t), T the zenith transmittance in V (0..1),
/// mu the sine of the star's elevation (X = relativeAirMass(mu)), t the
/// transmittance of a cloud in front (0..1). kHiddenStarMagnitude for a
/// star below the horizon (mu <= 0) or fully hidden (T or t <= 0, or the
/// dimming beyond it).
double extinctedMagnitude(double magnitude, double zenithTransmittanceV, double mu,
                          double cloudTransmittance = 1.0);

/// How much of a star of magnitude `seen` (at the eye) shows against a
/// limit: 1 for seen <= limit - kStarFadeMagnitudes / 2, 0 for seen >=
/// limit + kStarFadeMagnitudes / 2, smoothstep between (0.5 at the limit).
double starThresholdFade(double seenMagnitude, double limitMagnitude);

/// Magnitude of the field star of hash u in [0, 1) (see the header).
double starFieldMagnitude(double u);
/// Expected number of field stars on the whole sphere brighter than m.
double starFieldCount(double magnitude);

}  // namespace aerial
