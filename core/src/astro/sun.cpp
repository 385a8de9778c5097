// Sun and moon positions: the undated model of ../shared/DESIGN.md "Sun
// position" and the dated model (ephemeris.cpp), both documented in
// aerial/sun.hpp.
#include <aerial/sun.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

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
    body.apparentElevation = std::min(0.5 * kPiD, body.elevation + ephemeris::refraction(body.elevation));
    const double cosApparent = std::cos(body.apparentElevation);
    body.apparentDirection =
        glm::dvec3(cosApparent * std::sin(body.azimuth), std::sin(body.apparentElevation),
                   -cosApparent * std::cos(body.azimuth));
    return body;
}

/// Bright limb angle from the zenith through east [rad], 0..2pi, of a moon at
/// (decMoon, haMoon) lit by a sun at (decSun, haSun) [rad]: Meeus 48.5 with
/// alpha0 - alpha = H - H0, minus the parallactic angle (Meeus 14.1).
double brightLimbFromZenith(const Location& where, double decSun, double haSun, double decMoon,
                            double haMoon) {
    const double lat = std::clamp(finiteOr(where.latitudeDeg, 0.0), -90.0, 90.0) * kDegToRad;
    const double dAlpha = haMoon - haSun;  // alpha_sun - alpha_moon
    const double chi = std::atan2(
        std::cos(decSun) * std::sin(dAlpha),
        std::sin(decSun) * std::cos(decMoon) - std::cos(decSun) * std::sin(decMoon) * std::cos(dAlpha));
    const double q = std::atan2(std::sin(haMoon),
                                std::tan(lat) * std::cos(decMoon) - std::sin(decMoon) * std::cos(haMoon));
    return wrap(chi - q, 2.0 * kPiD);
}

/// Lambert-sphere phase law for phase angle `a` [rad].
double lambertPhase(double a) {
    a = std::abs(a);
    return std::max(0.0, (std::sin(a) + (kPiD - a) * std::cos(a)) / kPiD);
}

/// Topocentric declination and hour angle [rad] of a body at geocentric
/// (dec, hourAngle) with horizontal parallax sin(pi) = sinParallax, for an
/// observer at sea level (Meeus 11.1 and 40.2-40.3).
void topocentric(const Location& where, double sinParallax, double& dec, double& hourAngle) {
    const double lat = std::clamp(finiteOr(where.latitudeDeg, 0.0), -90.0, 90.0) * kDegToRad;
    constexpr double kPolarOverEquatorial = 0.99664719;  // b/a, IAU 1976
    const double u = std::atan(kPolarOverEquatorial * std::tan(lat));
    const double rhoSin = kPolarOverEquatorial * std::sin(u);
    const double rhoCos = std::cos(u);
    const double denominator = std::cos(dec) - rhoCos * sinParallax * std::cos(hourAngle);
    const double dAlpha = std::atan2(-rhoCos * sinParallax * std::sin(hourAngle), denominator);
    dec = std::atan2((std::sin(dec) - rhoSin * sinParallax) * std::cos(dAlpha), denominator);
    hourAngle -= dAlpha;
}

/// The dated instant: Julian day (UT), or NaN when undated.
struct Instant {
    double julianDay = std::numeric_limits<double>::quiet_NaN();
    bool dated() const { return std::isfinite(julianDay); }
};

Instant instantOf(const Location& where, double timeHours) { return {julianDayAt(where, timeHours)}; }

double longitudeOf(const Location& where) {
    return std::clamp(finiteOr(where.longitudeDeg, 0.0), -180.0, 180.0) * kDegToRad;
}

/// Sun's geocentric place and local hour angle at a dated instant.
void datedSun(const Location& where, double jd, ephemeris::SunPlace& s, double& hourAngle) {
    s = ephemeris::sun(jd);
    hourAngle = ephemeris::greenwichSiderealTime(jd) + longitudeOf(where) - s.rightAscension;
}

double hourAngleOf(double timeHours) {
    return 15.0 * kDegToRad * (wrap(finiteOr(timeHours, 12.0), 24.0) - 12.0);
}

}  // namespace

double solarDeclination(double dayOfYear) {
    return -kObliquity * std::cos(yearAngle(finiteOr(dayOfYear, 172.0)));
}

double julianDayAt(const Location& where, double timeHours) {
    CalendarDate date;
    if (!parseCalendarDate(where.date, date)) return std::numeric_limits<double>::quiet_NaN();
    const double t = wrap(finiteOr(timeHours, 12.0), 24.0);
    if (where.timeMode == TimeMode::Clock)
        return julianDay(date, t - std::clamp(finiteOr(where.utcOffsetHours, 0.0), -12.0, 14.0));
    // Solar: UT = t - longitude/15 - E(UT); E changes by < 1 s per hour, so
    // three fixed-point steps converge far below a microsecond.
    const double meanSolar = t - longitudeOf(where) / kDegToRad / 15.0;
    double ut = meanSolar;
    for (int i = 0; i < 3; ++i) ut = meanSolar - ephemeris::sun(julianDay(date, ut)).equationOfTimeHours;
    return julianDay(date, ut);
}

CelestialBody sunPosition(const Location& where, double timeHours) {
    const Instant now = instantOf(where, timeHours);
    if (!now.dated()) return place(where, solarDeclination(where.dayOfYear), hourAngleOf(timeHours));
    ephemeris::SunPlace s;
    double hourAngle = 0.0;
    datedSun(where, now.julianDay, s, hourAngle);
    // In solar mode the hour angle is 15 deg (t - 12) by definition (equal
    // to the sidereal one to rounding, by the choice of E).
    if (where.timeMode == TimeMode::Solar) hourAngle = hourAngleOf(timeHours);
    double dec = s.declination;
    constexpr double kSolarParallax = 8.794 / 3600.0 * kDegToRad;  // at 1 au
    topocentric(where, std::sin(kSolarParallax) / s.distanceAu, dec, hourAngle);
    return place(where, dec, hourAngle);
}

CelestialBody moonPosition(const Location& where, double timeHours) {
    const Instant now = instantOf(where, timeHours);
    if (now.dated()) {
        ephemeris::SunPlace s;
        double sunHourAngle = 0.0;
        datedSun(where, now.julianDay, s, sunHourAngle);
        const ephemeris::MoonPlace m = ephemeris::moon(now.julianDay);
        double hourAngle =
            ephemeris::greenwichSiderealTime(now.julianDay) + longitudeOf(where) - m.rightAscension;
        double dec = m.declination;
        constexpr double kEarthRadiusKm = 6378.14;  // Meeus 47
        topocentric(where, kEarthRadiusKm / m.distanceKm, dec, hourAngle);
        CelestialBody moon = place(where, dec, hourAngle);
        const ephemeris::MoonPhase phase = ephemeris::moonPhase(s, m);
        moon.illuminatedFraction = 0.5 * (1.0 + std::cos(phase.phaseAngle));
        moon.phaseIrradiance = lambertPhase(phase.phaseAngle);
        moon.brightLimbAngle = brightLimbFromZenith(where, s.declination, sunHourAngle, dec, hourAngle);
        return moon;
    }
    const double day = finiteOr(where.dayOfYear, 172.0);
    const double ageDays = wrap(day + finiteOr(where.moonPhaseOffsetDays, 0.0), kSynodicMonthDays);
    const double elongation = 2.0 * kPiD * ageDays / kSynodicMonthDays;
    // On the ecliptic, `elongation` further along than the sun.
    const double dec = -kObliquity * std::cos(yearAngle(day) + elongation);
    const double hourAngle = hourAngleOf(timeHours) - elongation;
    CelestialBody moon = place(where, dec, hourAngle);
    moon.illuminatedFraction = 0.5 * (1.0 - std::cos(elongation));
    moon.phaseIrradiance = lambertPhase(kPiD - elongation);  // phase angle 0 at full moon
    moon.brightLimbAngle =
        brightLimbFromZenith(where, solarDeclination(day), hourAngleOf(timeHours), dec, hourAngle);
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
    double theta = 0.0;  // local sidereal time [rad]
    const Instant now = instantOf(where, timeHours);
    if (now.dated()) {
        theta = ephemeris::greenwichSiderealTime(now.julianDay) + longitudeOf(where);
    } else {
        const double day = std::clamp(finiteOr(where.dayOfYear, 172.0), 1.0, 366.0);
        const double hours = (day - 1.0) * 24.0 + wrap(finiteOr(timeHours, 12.0), 24.0);
        theta = 2.0 * kPiD * wrap(hours, kSiderealDayHours) / kSiderealDayHours;
    }
    const double c = std::cos(theta);
    const double s = std::sin(theta);
    return {c * meridian + s * west, s * meridian - c * west, pole};
}

namespace {

/// Dated sunrise (rising = true) or sunset: the first upward (last
/// downward) crossing of the geometric horizon in the day, by a 15-minute
/// scan and bisection.
double datedCrossing(const Location& where, bool rising) {
    constexpr int kSteps = 96;
    auto elevation = [&](double t) { return sunPosition(where, t).elevation; };
    double crossing = std::numeric_limits<double>::quiet_NaN();
    double previous = elevation(0.0);
    for (int i = 1; i <= kSteps; ++i) {
        const double t1 = 24.0 * i / kSteps;
        const double current = elevation(std::min(t1, 24.0 - 1e-9));
        const bool up = previous <= 0.0 && current > 0.0;
        const bool down = previous > 0.0 && current <= 0.0;
        if ((rising && up) || (!rising && down)) {
            double lo = 24.0 * (i - 1) / kSteps, hi = t1;
            for (int k = 0; k < 40; ++k) {
                const double mid = 0.5 * (lo + hi);
                ((elevation(mid) > 0.0) == rising ? hi : lo) = mid;
            }
            crossing = 0.5 * (lo + hi);
            if (rising) break;  // first rise; keep scanning for the last set
        }
        previous = current;
    }
    if (std::isfinite(crossing)) return crossing;
    const bool polarDay = elevation(12.0) > 0.0;
    return rising ? (polarDay ? 0.0 : 12.0) : (polarDay ? 24.0 : 12.0);
}

}  // namespace

double sunriseHours(const Location& where) {
    if (instantOf(where, 12.0).dated()) return datedCrossing(where, true);
    const double lat = std::clamp(finiteOr(where.latitudeDeg, 0.0), -90.0, 90.0) * kDegToRad;
    const double dec = solarDeclination(where.dayOfYear);
    // cos(H0) = -tan(lat) tan(dec): the hour angle where sin(el) = 0.
    const double cosH0 = -std::tan(lat) * std::tan(dec);
    if (!std::isfinite(cosH0) || cosH0 <= -1.0) return 0.0;  // polar day
    if (cosH0 >= 1.0) return 12.0;                           // polar night
    return 12.0 - std::acos(cosH0) / (15.0 * kDegToRad);
}

double sunsetHours(const Location& where) {
    if (instantOf(where, 12.0).dated()) return datedCrossing(where, false);
    return 24.0 - sunriseHours(where);
}

double dayLengthHours(const Location& where) { return sunsetHours(where) - sunriseHours(where); }

double solarNoonHours(const Location& where) {
    CalendarDate date;
    if (where.timeMode != TimeMode::Clock || !parseCalendarDate(where.date, date)) return 12.0;
    // Hour angle 0: UT = 12 - longitude/15 - E(UT), the fixed point of julianDayAt's solar branch.
    const double meanNoon = 12.0 - longitudeOf(where) / kDegToRad / 15.0;
    double ut = meanNoon;
    for (int i = 0; i < 3; ++i) ut = meanNoon - ephemeris::sun(julianDay(date, ut)).equationOfTimeHours;
    return wrap(ut + std::clamp(finiteOr(where.utcOffsetHours, 0.0), -12.0, 14.0), 24.0);
}


namespace {

struct SunEventInfo {
    SunEvent event;
    const char* name;
    double elevationDeg;
    bool rising;
};

constexpr SunEventInfo kSunEventInfo[] = {
    {SunEvent::Sunrise, "sunrise", -0.833, true},
    {SunEvent::Noon, "noon", 0.0, false},
    {SunEvent::Sunset, "sunset", -0.833, false},
    {SunEvent::CivilDawn, "civil_dawn", -6.0, true},
    {SunEvent::CivilDusk, "civil_dusk", -6.0, false},
    {SunEvent::NauticalDawn, "nautical_dawn", -12.0, true},
    {SunEvent::NauticalDusk, "nautical_dusk", -12.0, false},
};

const SunEventInfo& infoOf(SunEvent event) {
    for (const SunEventInfo& info : kSunEventInfo)
        if (info.event == event) return info;
    return kSunEventInfo[0];
}

/// The first upward (rising) or last downward crossing of `elevation` [rad]
/// in [0, 24) h, or NaN. The day is scanned as a cycle: the step from just
/// before 24 h to 0 h counts too (a dusk on the stroke of midnight).
double crossingHours(const Location& where, double elevation, bool rising) {
    constexpr int kSteps = 96;
    auto above = [&](double t) { return sunPosition(where, t).elevation > elevation; };
    double crossing = std::numeric_limits<double>::quiet_NaN();
    bool previous = above(0.0);
    for (int i = 1; i <= kSteps; ++i) {
        const double t1 = 24.0 * i / kSteps;
        const bool current = above(i == kSteps ? 0.0 : t1);
        if (previous != current && current == rising) {
            double lo = 24.0 * (i - 1) / kSteps, hi = t1;
            for (int k = 0; k < 48; ++k) {
                const double mid = 0.5 * (lo + hi);
                (above(mid) == rising ? hi : lo) = mid;
            }
            crossing = wrap(0.5 * (lo + hi), 24.0);
            if (rising) break;  // the first rise; the scan goes on for the last set
        }
        previous = current;
    }
    return crossing;
}

}  // namespace

const char* sunEventName(SunEvent event) { return infoOf(event).name; }

bool parseSunEvent(std::string_view name, SunEvent& event) {
    for (const SunEventInfo& info : kSunEventInfo) {
        if (name == info.name) {
            event = info.event;
            return true;
        }
    }
    return false;
}

double sunEventCrossingHours(const Location& where, SunEvent event) {
    if (event == SunEvent::Noon) return wrap(solarNoonHours(where), 24.0);
    const SunEventInfo& info = infoOf(event);
    return crossingHours(where, info.elevationDeg * kDegToRad, info.rising);
}

double sunEventHours(const Location& where, SunEvent event) {
    const double t = sunEventCrossingHours(where, event);
    if (std::isfinite(t)) return t;
    const double noon = solarNoonHours(where);
    const double elevation = infoOf(event).elevationDeg * kDegToRad;
    // No crossing: where the sun comes closest to the elevation.
    const bool staysAbove = sunPosition(where, noon + 12.0).elevation > elevation;
    return wrap(staysAbove ? noon + 12.0 : noon, 24.0);
}

}  // namespace aerial
