// aerial/sun.hpp — where the sun and the moon are, and how bright.
//
// Usage:
//   aerial::Location where;              // latitude, day of year, north offset
//   where.latitudeDeg = 47.0;
//   aerial::CelestialBody sun  = aerial::sunPosition(where, 14.5);  // 14:30
//   aerial::CelestialBody moon = aerial::moonPosition(where, 14.5);
//   // sun.direction points from the scene towards the sun (Y up, north -Z).
//
// Formulas (../shared/DESIGN.md, "Sun position"):
//   declination  d = -23.44 deg * cos(360/365 * (day_of_year + 10))
//   hour angle   H = 15 deg * (t - 12)
//   sin(el) = sin(lat) sin(d) + cos(lat) cos(d) cos(H)
//   azimuth from north towards east:
//     az = atan2(-cos(d) sin(H), sin(d) cos(lat) - cos(d) cos(H) sin(lat))
//   world direction (cos(el) sin(az), sin(el), -cos(el) cos(az)), with
//   az increased by north_offset_deg first.
//
// Moon model (simple, documented, deterministic):
//   * synodic month 29.530589 days; the moon's age on `day_of_year` is
//     (day_of_year + moonPhaseOffsetDays) mod 29.530589 days, so a preset
//     chooses which night of the month it shows;
//   * elongation E = 2 pi * age / synodic month (0 = new moon, pi = full);
//   * the moon moves on the ecliptic (its 5 deg inclination is ignored):
//     declination  d_m = -23.44 deg * cos(360/365 * (day_of_year + 10) + E)
//     hour angle   H_m = H - E        (it rises ~50 minutes later each day)
//     and elevation/azimuth from the same formulas as the sun;
//   * illuminated fraction k = (1 - cos E) / 2;
//   * irradiance scale = Lambert-sphere phase law
//       Phi(a) = (sin a + (pi - a) cos a) / pi,  phase angle a = pi - E,
//     so a full moon gives 1, a half moon 1/pi, a new moon 0.
#pragma once

#include <glm/vec3.hpp>

namespace aerial {

/// Where and when on the planet the scene is.
struct Location {
    /// Geographic latitude [deg], -90..90, north positive. Default 45.
    double latitudeDeg = 45.0;
    /// Day of the year [1..365]. Default 172 (northern summer solstice).
    double dayOfYear = 172.0;
    /// Rotation of the whole sky about +Y [deg], added to every azimuth:
    /// azimuth 0 (north) points along -Z rotated by this angle towards +X.
    double northOffsetDeg = 0.0;
    /// Shifts the moon's age [days], 0..29.53; 0 makes day 0 a new moon.
    double moonPhaseOffsetDays = 0.0;
};

/// A sun or moon as seen from the scene.
struct CelestialBody {
    double elevation = 0.0;  ///< above the horizon [rad], -pi/2..pi/2
    double azimuth = 0.0;    ///< from north towards east [rad], 0..2pi, north offset included
    glm::dvec3 direction{0.0, 1.0, 0.0};  ///< unit vector from the scene to the body (Y up)
    /// Fraction of the disc that is lit, 0..1 (sun: 1).
    double illuminatedFraction = 1.0;
    /// Irradiance relative to the body at full phase, 0..1 (sun: 1; moon:
    /// Lambert-sphere phase law).
    double phaseIrradiance = 1.0;
};

/// Solar declination [rad] for a day of the year (1..365).
double solarDeclination(double dayOfYear);

/// The sun at local solar time `timeHours` (0..24; values outside wrap).
CelestialBody sunPosition(const Location& where, double timeHours);

/// The moon at local solar time `timeHours`, from the model above.
CelestialBody moonPosition(const Location& where, double timeHours);

/// Length of a sidereal day [h]: the stars turn once about the celestial
/// pole in this time.
constexpr double kSiderealDayHours = 23.9344696;

/// The celestial sphere as seen from `where` at local solar time
/// `timeHours` of its day of the year: three orthonormal world directions.
/// `pole` is the north celestial pole (elevation = latitude, azimuth north);
/// `equatorX` and `equatorY` span the celestial equator at right ascension 0
/// and 6 h. A star at right ascension ra and declination dec [rad] lies along
///   cos(dec) (cos(ra) equatorX + sin(ra) equatorY) + sin(dec) pole.
/// The frame turns westwards about the pole once per kSiderealDayHours of
/// (dayOfYear - 1) * 24 + timeHours (right ascension 0 is on the meridian at
/// hour 0 of day 1: an arbitrary epoch, as the renderer's stars are
/// procedural). A body of fixed declination keeps its angle to the pole, so
/// the sun of sunPosition stays at dot(pole, direction) = sin(declination).
struct CelestialFrame {
    glm::dvec3 equatorX{1.0, 0.0, 0.0};
    glm::dvec3 equatorY{0.0, 0.0, 1.0};
    glm::dvec3 pole{0.0, 1.0, 0.0};
};
CelestialFrame celestialFrame(const Location& where, double timeHours);

/// Hours of daylight (sun centre above the geometric horizon), 0..24.
double dayLengthHours(const Location& where);

/// Local solar time of sunrise [h]; the sunset is at 24 - sunrise (the
/// formulas are symmetric about noon). Returns 0 during polar day and 12
/// during polar night.
double sunriseHours(const Location& where);

}  // namespace aerial
