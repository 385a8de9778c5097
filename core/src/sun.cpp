// Sun and moon positions: ../shared/DESIGN.md "Sun position"; the moon model
// is documented in aerial/sun.hpp.
#include <aerial/sun.hpp>

#include <algorithm>
#include <cmath>

namespace aerial {
namespace {

constexpr double kPiD = 3.14159265358979323846;
constexpr double kDegToRad = kPiD / 180.0;
constexpr double kObliquity = 23.44 * kDegToRad;
constexpr double kSynodicMonthDays = 29.530589;

double finiteOr(double value, double fallback) { return std::isfinite(value) ? value : fallback; }

/// Wraps x into [0, period).
double wrap(double x, double period) {
    double r = std::fmod(x, period);
    if (r < 0.0) r += period;
    return r >= period ? 0.0 : r;
}

double clampedAsin(double x) { return std::asin(std::clamp(x, -1.0, 1.0)); }

/// Angle of the year [rad] used by the declination formula.
double yearAngle(double dayOfYear) { return 2.0 * kPiD / 365.0 * (dayOfYear + 10.0); }

/// Elevation, azimuth (north towards east) and world direction for a body at
/// declination `dec` and hour angle `hourAngle` (both [rad]).
CelestialBody place(const Location& where, double dec, double hourAngle) {
    const double lat = std::clamp(finiteOr(where.latitudeDeg, 0.0), -90.0, 90.0) * kDegToRad;
    const double sinEl = std::sin(lat) * std::sin(dec) + std::cos(lat) * std::cos(dec) * std::cos(hourAngle);
    CelestialBody body;
    body.elevation = clampedAsin(sinEl);
    // Standard azimuth from north towards east.
    const double y = -std::cos(dec) * std::sin(hourAngle);
    const double x = std::sin(dec) * std::cos(lat) - std::cos(dec) * std::cos(hourAngle) * std::sin(lat);
    const double az = (x == 0.0 && y == 0.0) ? 0.0 : std::atan2(y, x);  // zenith: azimuth undefined
    body.azimuth = wrap(az + finiteOr(where.northOffsetDeg, 0.0) * kDegToRad, 2.0 * kPiD);
    const double cosEl = std::cos(body.elevation);
    body.direction =
        glm::dvec3(cosEl * std::sin(body.azimuth), std::sin(body.elevation), -cosEl * std::cos(body.azimuth));
    return body;
}

double hourAngleOf(double timeHours) {
    return 15.0 * kDegToRad * (wrap(finiteOr(timeHours, 12.0), 24.0) - 12.0);
}

}  // namespace

double solarDeclination(double dayOfYear) {
    return -kObliquity * std::cos(yearAngle(finiteOr(dayOfYear, 172.0)));
}

CelestialBody sunPosition(const Location& where, double timeHours) {
    return place(where, solarDeclination(where.dayOfYear), hourAngleOf(timeHours));
}

CelestialBody moonPosition(const Location& where, double timeHours) {
    const double day = finiteOr(where.dayOfYear, 172.0);
    const double ageDays = wrap(day + finiteOr(where.moonPhaseOffsetDays, 0.0), kSynodicMonthDays);
    const double elongation = 2.0 * kPiD * ageDays / kSynodicMonthDays;
    // On the ecliptic, `elongation` further along than the sun.
    const double dec = -kObliquity * std::cos(yearAngle(day) + elongation);
    CelestialBody moon = place(where, dec, hourAngleOf(timeHours) - elongation);
    moon.illuminatedFraction = 0.5 * (1.0 - std::cos(elongation));
    const double phaseAngle = kPiD - elongation;  // 0 at full moon
    const double a = std::abs(phaseAngle);
    moon.phaseIrradiance = std::max(0.0, (std::sin(a) + (kPiD - a) * std::cos(a)) / kPiD);
    return moon;
}

CelestialFrame celestialFrame(const Location& where, double timeHours) {
    // The meridian's equator point (hour angle 0), the west point (hour angle
    // +90 deg) and the pole, from the same spherical astronomy as the sun.
    const glm::dvec3 meridian = place(where, 0.0, 0.0).direction;
    const glm::dvec3 west = place(where, 0.0, 0.5 * kPiD).direction;
    const glm::dvec3 pole = place(where, 0.5 * kPiD, 0.0).direction;
    // Hour angle of right ascension ra: H = theta - ra, so
    // direction = cos(dec) (cos(H) meridian + sin(H) west) + sin(dec) pole
    //           = cos(dec) (cos(ra) X + sin(ra) Y) + sin(dec) pole with
    // X = cos(theta) meridian + sin(theta) west, Y = sin(theta) meridian - cos(theta) west.
    const double day = std::clamp(finiteOr(where.dayOfYear, 172.0), 1.0, 366.0);
    const double hours = (day - 1.0) * 24.0 + wrap(finiteOr(timeHours, 12.0), 24.0);
    const double theta = 2.0 * kPiD * wrap(hours, kSiderealDayHours) / kSiderealDayHours;
    const double c = std::cos(theta);
    const double s = std::sin(theta);
    return {c * meridian + s * west, s * meridian - c * west, pole};
}

double sunriseHours(const Location& where) {
    const double lat = std::clamp(finiteOr(where.latitudeDeg, 0.0), -90.0, 90.0) * kDegToRad;
    const double dec = solarDeclination(where.dayOfYear);
    // cos(H0) = -tan(lat) tan(dec): the hour angle where sin(el) = 0.
    const double cosH0 = -std::tan(lat) * std::tan(dec);
    if (!std::isfinite(cosH0) || cosH0 <= -1.0) return 0.0;  // polar day
    if (cosH0 >= 1.0) return 12.0;                           // polar night
    return 12.0 - std::acos(cosH0) / (15.0 * kDegToRad);
}

double dayLengthHours(const Location& where) { return 24.0 - 2.0 * sunriseHours(where); }

}  // namespace aerial
