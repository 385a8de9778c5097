// aerial/sun.hpp — where the sun and the moon are, and how bright.
//
// Usage:
//   aerial::Location where;              // latitude, longitude, date, time mode
//   where.latitudeDeg = 47.37;
//   where.longitudeDeg = 8.54;
//   where.utcOffsetHours = 2.0;
//   where.date = "2026-06-21";
//   where.timeMode = aerial::TimeMode::Clock;
//   aerial::CelestialBody sun  = aerial::sunPosition(where, 14.5);  // 14:30 CEST
//   aerial::CelestialBody moon = aerial::moonPosition(where, 14.5);
//   // sun.direction points from the scene towards the sun (Y up, north -Z).
//
// Two models, chosen by `Location::date`:
//
// A. Dated (`date` = "YYYY-MM-DD", 1800-01-01..2200-12-31). The instant is
//    the date and the time of day `t` [h] read as
//      * TimeMode::Clock: local clock time at `utcOffsetHours`,
//        UT = t - utc_offset_h (the day rolls over as needed);
//      * TimeMode::Solar: local apparent solar time at `longitudeDeg`: the
//        sun's hour angle is exactly 15 deg * (t - 12), and
//        UT = t - longitude/15 - E (E the equation of time, solved by
//        iteration), so the moon and the stars are placed at that instant.
//    Sun: NOAA's solar position algorithm (the NOAA Solar Calculator, after
//    Meeus, "Astronomical Algorithms" 2nd ed. ch. 25, low-precision series),
//    stated accuracy ~0.01 deg for 1800..2100; right ascension and
//    declination of date, Greenwich apparent sidereal time (Meeus 12.4 and
//    low-precision nutation, ch. 22), equation of time Meeus 28.1, then
//    topocentric for an observer at sea level (parallax 8.794"/R, Meeus
//    40.2-40.3 with the IAU 1976 flattening).
//    Moon: Meeus ch. 47 (ELP-2000/82 truncated: the 60 terms of tables 47.A
//    in longitude and distance and 30 of 47.B in latitude, plus the A1..A3
//    and E corrections), nutation in longitude, topocentric (parallax up to
//    ~1 deg), illuminated fraction from the phase angle (Meeus 48.1-48.3)
//    and the bright limb's position angle (Meeus 48.5). Terrestrial time is
//    taken as UT (delta T ignored, as NOAA does: < 0.04 deg of the moon's
//    motion in 1800..2200 and negligible for the sun).
//    `dayOfYear` and `moonPhaseOffsetDays` are not used.
//
// B. Undated (`date` empty: every version-1 preset), the version-1 model,
//    kept bit for bit: `t` is local apparent solar time; `longitudeDeg`,
//    `utcOffsetHours` and `timeMode` have no effect.
//    Sun (../shared/DESIGN.md, "Sun position"):
//      declination  d = -23.44 deg * cos(360/365 * (day_of_year + 10))
//      hour angle   H = 15 deg * (t - 12)
//    Moon (simple, documented, deterministic):
//      * synodic month 29.530589 days; the moon's age on `day_of_year` is
//        (day_of_year + moonPhaseOffsetDays) mod 29.530589 days, so a preset
//        chooses which night of the month it shows (constant over the day);
//      * elongation E = 2 pi * age / synodic month (0 = new moon, pi = full);
//      * the moon moves on the ecliptic (its 5 deg inclination is ignored):
//        declination  d_m = -23.44 deg * cos(360/365 * (day_of_year + 10) + E)
//        hour angle   H_m = H - E        (it rises ~50 minutes later each day)
//      * illuminated fraction k = (1 - cos E) / 2.
//
// Both models then place a body of declination d and hour angle H:
//   sin(el) = sin(lat) sin(d) + cos(lat) cos(d) cos(H)
//   azimuth from north towards east:
//     az = atan2(-cos(d) sin(H), sin(d) cos(lat) - cos(d) cos(H) sin(lat))
//   world direction (cos(el) sin(az), sin(el), -cos(el) cos(az)), with
//   az increased by north_offset_deg first.
// `elevation`/`direction` are geometric (no refraction): the light the
// renderer and the sky use. `apparentElevation`/`apparentDirection` add
// standard refraction, Saemundsson's formula (Meeus 16.4, 1010 hPa, 10 C):
//   R [arcmin] = 1.02 / tan(h + 10.3 / (h + 5.11)),  h [deg] geometric,
// for h >= -1 deg, faded linearly to 0 at h = -6 deg below that (the formula
// has no meaning for a body well below a sea-level horizon), 0 near the
// zenith. The moon's irradiance follows the Lambert-sphere phase law
//   Phi(a) = (sin a + (pi - a) cos a) / pi,  a = phase angle,
// so a full moon gives 1, a half moon 1/pi, a new moon 0.
#pragma once

#include <glm/vec3.hpp>

#include <string>
#include <string_view>

namespace aerial {

/// How a dated preset reads its time of day (see the top of this file).
enum class TimeMode {
    Solar,  ///< local apparent solar time at the longitude (version 1)
    Clock,  ///< local clock time at the UTC offset
};

/// Where and when on the planet the scene is.
struct Location {
    /// Geographic latitude [deg], -90..90, north positive. Default 45.
    double latitudeDeg = 45.0;
    /// Geographic longitude [deg], -180..180, east positive. Default 0.
    /// Dated presets only.
    double longitudeDeg = 0.0;
    /// Local clock time minus UT [h], -12..14 (e.g. 2 for CEST). Default 0.
    /// Dated presets in TimeMode::Clock only.
    double utcOffsetHours = 0.0;
    /// Calendar date "YYYY-MM-DD" (Gregorian, 1800-01-01..2200-12-31), or
    /// empty (the default, every version-1 preset) for the undated model
    /// driven by dayOfYear. When set, it alone defines the day.
    std::string date;
    /// How the time of day is read when `date` is set. Default Solar.
    TimeMode timeMode = TimeMode::Solar;
    /// Day of the year [1..365] of the undated model. Default 172 (northern
    /// summer solstice; "2026-06-21" is the same day). Unused when `date` is
    /// set.
    double dayOfYear = 172.0;
    /// Rotation of the whole sky about +Y [deg], added to every azimuth:
    /// azimuth 0 (north) points along -Z rotated by this angle towards +X.
    double northOffsetDeg = 0.0;
    /// Shifts the moon's age [days], 0..29.53; 0 makes day 0 a new moon.
    /// Undated model only (a date fixes the moon's age).
    double moonPhaseOffsetDays = 0.0;
};

/// A sun or moon as seen from the scene.
struct CelestialBody {
    double elevation = 0.0;               ///< geometric, above the horizon [rad], -pi/2..pi/2
    double azimuth = 0.0;                 ///< from north towards east [rad], 0..2pi, north offset included
    glm::dvec3 direction{0.0, 1.0, 0.0};  ///< unit vector from the scene to the body (Y up), geometric
    /// Elevation with standard refraction [rad] (see the top of this file).
    double apparentElevation = 0.0;
    /// Unit vector towards the apparent (refracted) body, same azimuth.
    glm::dvec3 apparentDirection{0.0, 1.0, 0.0};
    /// Fraction of the disc that is lit, 0..1 (sun: 1).
    double illuminatedFraction = 1.0;
    /// Irradiance relative to the body at full phase, 0..1 (sun: 1; moon:
    /// Lambert-sphere phase law).
    double phaseIrradiance = 1.0;
    /// Moon: position angle of the midpoint of the bright limb [rad], 0..2pi,
    /// measured on the disc from the direction towards the zenith through
    /// east (counter-clockwise on the sky for an observer facing the moon
    /// in the south from the north: 0 = lit from above, pi/2 = lit on the
    /// left/east side). Meeus 48.5's chi minus the parallactic angle (14.1).
    /// Sun: 0.
    double brightLimbAngle = 0.0;
};

/// A Gregorian calendar date.
struct CalendarDate {
    int year = 2000;
    int month = 1;  ///< 1..12
    int day = 1;    ///< 1..31
};

/// Parses exactly "YYYY-MM-DD" (four, two and two digits) naming a real
/// Gregorian date from 1800-01-01 to 2200-12-31. False otherwise (out is
/// then unspecified).
bool parseCalendarDate(std::string_view text, CalendarDate& out);

/// Day of the year of a date, 1..366.
int dayOfYear(const CalendarDate& date);

/// Julian day of `utHours` [h] after 0h UT of `date` (Meeus 7.1; hours may
/// be negative or over 24).
double julianDay(const CalendarDate& date, double utHours);

/// The algorithms behind the dated model, for tests and for games that want
/// them directly. Time arguments are Julian days (TT taken equal to UT).
namespace ephemeris {

/// Low-precision nutation (Meeus ch. 22): in longitude and in obliquity [rad].
struct Nutation {
    double longitude = 0.0;
    double obliquity = 0.0;
};
Nutation nutation(double julianDay);

/// Mean obliquity of the ecliptic (Meeus 22.2) [rad].
double meanObliquity(double julianDay);

/// Greenwich apparent sidereal time [rad], 0..2pi (Meeus 12.4 plus the
/// equation of the equinoxes).
double greenwichSiderealTime(double julianDay);

/// The sun by NOAA's algorithm (Meeus ch. 25, low precision): apparent
/// right ascension and declination of date [rad], distance [au], the
/// apparent longitude [rad] and the equation of time [h] (apparent minus
/// mean solar time, Meeus 28.1).
struct SunPlace {
    double rightAscension = 0.0;
    double declination = 0.0;
    double distanceAu = 1.0;
    double apparentLongitude = 0.0;
    double equationOfTimeHours = 0.0;
};
SunPlace sun(double julianDay);

/// The moon by Meeus ch. 47: geocentric ecliptic longitude and latitude of
/// the mean equinox of date without nutation [rad] (the values of example
/// 47.a), distance between the centres [km], and the apparent right
/// ascension and declination of date [rad] (nutation in longitude and the
/// true obliquity).
struct MoonPlace {
    double longitude = 0.0;
    double latitude = 0.0;
    double distanceKm = 385000.56;
    double rightAscension = 0.0;
    double declination = 0.0;
};
MoonPlace moon(double julianDay);

/// Geocentric phase angle [rad] (Meeus 48.2-48.3) and position angle of the
/// bright limb from the north celestial pole through east [rad], 0..2pi
/// (Meeus 48.5).
struct MoonPhase {
    double phaseAngle = 0.0;
    double brightLimbPositionAngle = 0.0;
};
MoonPhase moonPhase(const SunPlace& sun, const MoonPlace& moon);

/// Standard refraction [rad] for a geometric elevation [rad] (Saemundsson,
/// Meeus 16.4, with the fades described at the top of this file).
double refraction(double geometricElevation);

}  // namespace ephemeris

/// The instant of `timeHours` at a dated location as a Julian day (UT):
/// through the UTC offset in clock mode, the equation of time in solar mode.
/// NaN when `where.date` is empty or not a valid date.
double julianDayAt(const Location& where, double timeHours);

/// Solar declination [rad] of the undated model for a day of the year (1..365).
double solarDeclination(double dayOfYear);

/// The sun at the time of day `timeHours` (0..24; values outside wrap),
/// read as the location says (see the top of this file).
CelestialBody sunPosition(const Location& where, double timeHours);

/// The moon at the time of day `timeHours`, from the models above.
CelestialBody moonPosition(const Location& where, double timeHours);

/// Length of a sidereal day [h]: the stars turn once about the celestial
/// pole in this time.
constexpr double kSiderealDayHours = 23.9344696;

/// The celestial sphere as seen from `where` at the time of day `timeHours`:
/// three orthonormal world directions.
/// `pole` is the north celestial pole (elevation = latitude, azimuth north);
/// `equatorX` and `equatorY` span the celestial equator at right ascension 0
/// and 6 h. A star at right ascension ra and declination dec [rad] lies along
///   cos(dec) (cos(ra) equatorX + sin(ra) equatorY) + sin(dec) pole.
/// Dated: the frame is the true equator of date, turned by the local
/// apparent sidereal time (right ascension 0 on the meridian when it is 0).
/// Undated: the frame turns westwards about the pole once per
/// kSiderealDayHours of (dayOfYear - 1) * 24 + timeHours (right ascension 0
/// is on the meridian at hour 0 of day 1: an arbitrary epoch, as the
/// renderer's stars are procedural). A body of fixed declination keeps its angle to the pole, so
/// the sun of sunPosition stays at dot(pole, direction) = sin(declination).
struct CelestialFrame {
    glm::dvec3 equatorX{1.0, 0.0, 0.0};
    glm::dvec3 equatorY{0.0, 0.0, 1.0};
    glm::dvec3 pole{0.0, 1.0, 0.0};
};
CelestialFrame celestialFrame(const Location& where, double timeHours);

/// Hours of daylight (sun centre above the geometric horizon), 0..24:
/// sunsetHours - sunriseHours.
double dayLengthHours(const Location& where);

/// Time of day of sunrise [h] (sun centre crossing the geometric horizon
/// upwards), in the location's time of day. Undated: the closed form, and
/// the sunset is at 24 - sunrise (the formulas are symmetric about noon).
/// Dated: the first upward crossing of the day, found by bisection (1e-6 h).
/// Returns 0 during polar day and 12 during polar night (dated: when the
/// sun does not cross the horizon that day, 0 if it is up at noon, else 12).
double sunriseHours(const Location& where);

/// Time of day of sunset [h]; 24 during polar day, 12 during polar night
/// (see sunriseHours).
double sunsetHours(const Location& where);

/// Time of day of the sun's upper transit [h], 0..24 (the highest sun of a
/// day, the meridian crossing): 12 in solar time, undated or dated (the hour
/// angle is 15 deg (t - 12) by definition); in clock time
/// 12 + utcOffset - longitude/15 - E, E the equation of time that day
/// (ephemeris, iterated to the instant). A game shows it as "noon".
double solarNoonHours(const Location& where);

/// The moments of the day a key can follow (TrackKey::anchor), as almanacs
/// define them, by the geometric elevation of the sun's centre:
///   sunrise, sunset          -0.833 deg (the upper limb on a refracted
///                            horizon: 34' refraction + 16' semidiameter)
///   civil dawn, dusk         -6 deg
///   nautical dawn, dusk      -12 deg
///   noon                     the upper transit (solarNoonHours)
/// In a preset file: "sunrise", "noon", "sunset", "civil_dawn",
/// "civil_dusk", "nautical_dawn", "nautical_dusk".
enum class SunEvent { Sunrise, Noon, Sunset, CivilDawn, CivilDusk, NauticalDawn, NauticalDusk };

inline constexpr SunEvent kSunEvents[] = {SunEvent::NauticalDawn, SunEvent::CivilDawn, SunEvent::Sunrise,
                                          SunEvent::Noon,         SunEvent::Sunset,    SunEvent::CivilDusk,
                                          SunEvent::NauticalDusk};

/// The file name of an event ("civil_dusk").
const char* sunEventName(SunEvent event);

/// Parses a file name of an event; false (and `event` untouched) otherwise.
bool parseSunEvent(std::string_view name, SunEvent& event);

/// Time of day of an event [h], 0 <= t < 24, in the location's time of day
/// (as sunPosition reads it): a dawn or sunrise is the day's first upward
/// crossing of the event's elevation, a sunset or dusk the last downward one
/// (15-minute scan, then bisection to 1e-7 h; the undated and dated models
/// alike). When the sun does not reach the elevation that day the event
/// falls where the sun comes closest to it: at solar midnight (noon + 12 h)
/// when it stays above (a summer night that never gets nautically dark),
/// at noon when it stays below (polar night) -- so the event moves
/// continuously with the date and the latitude.
double sunEventHours(const Location& where, SunEvent event);

/// The same where the sun really crosses the event's elevation that day;
/// NaN where sunEventHours falls back to midnight or noon (a polar day or
/// night). Noon always happens. One scan of the day, as sunEventHours.
double sunEventCrossingHours(const Location& where, SunEvent event);

}  // namespace aerial
