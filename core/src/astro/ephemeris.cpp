// Sun and moon ephemerides of the dated model (aerial/sun.hpp): NOAA's solar
// position algorithm and Meeus, "Astronomical Algorithms" (2nd ed., 1998),
// chapters 7, 12, 16, 22, 25, 28, 47 and 48. Angles in degrees inside the
// series (as printed), radians at the interface.
#include <aerial/sun.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace aerial {
namespace {

constexpr double kPiD = 3.14159265358979323846;
constexpr double kDeg = kPiD / 180.0;
constexpr double kJ2000 = 2451545.0;

/// Wraps degrees into [0, 360).
double wrapDegrees(double x) {
    double r = std::fmod(x, 360.0);
    if (r < 0.0) r += 360.0;
    return r >= 360.0 ? 0.0 : r;
}

double sinDeg(double x) { return std::sin(x * kDeg); }
double cosDeg(double x) { return std::cos(x * kDeg); }

/// Julian centuries since J2000.0.
double centuries(double julianDay) { return (julianDay - kJ2000) / 36525.0; }

bool isLeap(int year) { return (year % 4 == 0 && year % 100 != 0) || year % 400 == 0; }

int daysInMonth(int year, int month) {
    static constexpr std::array<int, 12> kDays = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    return month == 2 && isLeap(year) ? 29 : kDays[std::size_t(month - 1)];
}

/// Meeus table 47.A: multiples of D, M, M', F; coefficients of sin (sum l,
/// 1e-6 deg) and cos (sum r, 1e-3 km).
struct LongitudeTerm {
    std::int8_t d, m, mp, f;
    std::int32_t sinL, cosR;
};
constexpr std::array<LongitudeTerm, 60> kMoonLongitude = {{
    {0, 0, 1, 0, 6288774, -20905355},
    {2, 0, -1, 0, 1274027, -3699111},
    {2, 0, 0, 0, 658314, -2955968},
    {0, 0, 2, 0, 213618, -569925},
    {0, 1, 0, 0, -185116, 48888},
    {0, 0, 0, 2, -114332, -3149},
    {2, 0, -2, 0, 58793, 246158},
    {2, -1, -1, 0, 57066, -152138},
    {2, 0, 1, 0, 53322, -170733},
    {2, -1, 0, 0, 45758, -204586},
    {0, 1, -1, 0, -40923, -129620},
    {1, 0, 0, 0, -34720, 108743},
    {0, 1, 1, 0, -30383, 104755},
    {2, 0, 0, -2, 15327, 10321},
    {0, 0, 1, 2, -12528, 0},
    {0, 0, 1, -2, 10980, 79661},
    {4, 0, -1, 0, 10675, -34782},
    {0, 0, 3, 0, 10034, -23210},
    {4, 0, -2, 0, 8548, -21636},
    {2, 1, -1, 0, -7888, 24208},
    {2, 1, 0, 0, -6766, 30824},
    {1, 0, -1, 0, -5163, -8379},
    {1, 1, 0, 0, 4987, -16675},
    {2, -1, 1, 0, 4036, -12831},
    {2, 0, 2, 0, 3994, -10445},
    {4, 0, 0, 0, 3861, -11650},
    {2, 0, -3, 0, 3665, 14403},
    {0, 1, -2, 0, -2689, -7003},
    {2, 0, -1, 2, -2602, 0},
    {2, -1, -2, 0, 2390, 10056},
    {1, 0, 1, 0, -2348, 6322},
    {2, -2, 0, 0, 2236, -9884},
    {0, 1, 2, 0, -2120, 5751},
    {0, 2, 0, 0, -2069, 0},
    {2, -2, -1, 0, 2048, -4950},
    {2, 0, 1, -2, -1773, 4130},
    {2, 0, 0, 2, -1595, 0},
    {4, -1, -1, 0, 1215, -3958},
    {0, 0, 2, 2, -1110, 0},
    {3, 0, -1, 0, -892, 3258},
    {2, 1, 1, 0, -810, 2616},
    {4, -1, -2, 0, 759, -1897},
    {0, 2, -1, 0, -713, -2117},
    {2, 2, -1, 0, -700, 2354},
    {2, 1, -2, 0, 691, 0},
    {2, -1, 0, -2, 596, 0},
    {4, 0, 1, 0, 549, -1423},
    {0, 0, 4, 0, 537, -1117},
    {4, -1, 0, 0, 520, -1571},
    {1, 0, -2, 0, -487, -1739},
    {2, 1, 0, -2, -399, 0},
    {0, 0, 2, -2, -381, -4421},
    {1, 1, 1, 0, 351, 0},
    {3, 0, -2, 0, -340, 0},
    {4, 0, -3, 0, 330, 0},
    {2, -1, 2, 0, 327, 0},
    {0, 2, 1, 0, -323, 1165},
    {1, 1, -1, 0, 299, 0},
    {2, 0, 3, 0, 294, 0},
    {2, 0, -1, -2, 0, 8752},
}};

/// Meeus table 47.B: multiples of D, M, M', F; coefficient of sin (sum b,
/// 1e-6 deg).
struct LatitudeTerm {
    std::int8_t d, m, mp, f;
    std::int32_t sinB;
};
constexpr std::array<LatitudeTerm, 30> kMoonLatitude = {{
    {0, 0, 0, 1, 5128122}, {0, 0, 1, 1, 280602},  {0, 0, 1, -1, 277693}, {2, 0, 0, -1, 173237},
    {2, 0, -1, 1, 55413},  {2, 0, -1, -1, 46271}, {2, 0, 0, 1, 32573},   {0, 0, 2, 1, 17198},
    {2, 0, 1, -1, 9266},   {0, 0, 2, -1, 8822},   {2, -1, 0, -1, 8216},  {2, 0, -2, -1, 4324},
    {2, 0, 1, 1, 4200},    {2, 1, 0, -1, -3359},  {2, -1, -1, 1, 2463},  {2, -1, 0, 1, 2211},
    {2, -1, -1, -1, 2065}, {0, 1, -1, -1, -1870}, {4, 0, -1, -1, 1828},  {0, 1, 0, 1, -1794},
    {0, 0, 0, 3, -1749},   {0, 1, -1, 1, -1565},  {1, 0, 0, 1, -1491},   {0, 1, 1, 1, -1475},
    {0, 1, 1, -1, -1410},  {0, 1, 0, -1, -1344},  {1, 0, 0, -1, -1335},  {0, 0, 3, 1, 1107},
    {4, 0, 0, -1, 1021},   {4, 0, -1, 1, 833},
}};

/// Right ascension and declination [rad] of ecliptic longitude and latitude
/// [rad] for obliquity `eps` [rad] (Meeus 13.3, 13.4).
void eclipticToEquatorial(double lambda, double beta, double eps, double& ra, double& dec) {
    ra = std::atan2(std::sin(lambda) * std::cos(eps) - std::tan(beta) * std::sin(eps), std::cos(lambda));
    if (ra < 0.0) ra += 2.0 * kPiD;
    dec = std::asin(std::clamp(
        std::sin(beta) * std::cos(eps) + std::cos(beta) * std::sin(eps) * std::sin(lambda), -1.0, 1.0));
}

}  // namespace

bool parseCalendarDate(std::string_view text, CalendarDate& out) {
    if (text.size() != 10 || text[4] != '-' || text[7] != '-') return false;
    auto digits = [&](std::size_t at, std::size_t count, int& value) {
        value = 0;
        for (std::size_t i = at; i < at + count; ++i) {
            if (text[i] < '0' || text[i] > '9') return false;
            value = value * 10 + (text[i] - '0');
        }
        return true;
    };
    if (!digits(0, 4, out.year) || !digits(5, 2, out.month) || !digits(8, 2, out.day)) return false;
    if (out.year < 1800 || out.year > 2200 || out.month < 1 || out.month > 12) return false;
    return out.day >= 1 && out.day <= daysInMonth(out.year, out.month);
}

int dayOfYear(const CalendarDate& date) {
    int day = date.day;
    for (int m = 1; m < date.month; ++m) day += daysInMonth(date.year, m);
    return day;
}

double julianDay(const CalendarDate& date, double utHours) {
    // Meeus 7.1, Gregorian calendar.
    int y = date.year, m = date.month;
    if (m <= 2) {
        y -= 1;
        m += 12;
    }
    const int a = y / 100;
    const int b = 2 - a + a / 4;
    return std::floor(365.25 * (y + 4716)) + std::floor(30.6001 * (m + 1)) + date.day + b - 1524.5 +
           utHours / 24.0;
}

namespace ephemeris {

Nutation nutation(double jd) {
    // Meeus ch. 22, the low-precision form (0.5" in longitude, 0.1" in
    // obliquity).
    const double t = centuries(jd);
    const double omega = 125.04452 - 1934.136261 * t;
    const double sunL = 280.4665 + 36000.7698 * t;
    const double moonL = 218.3165 + 481267.8813 * t;
    Nutation n;
    n.longitude = (-17.20 * sinDeg(omega) - 1.32 * sinDeg(2 * sunL) - 0.23 * sinDeg(2 * moonL) +
                   0.21 * sinDeg(2 * omega)) /
                  3600.0 * kDeg;
    n.obliquity = (9.20 * cosDeg(omega) + 0.57 * cosDeg(2 * sunL) + 0.10 * cosDeg(2 * moonL) -
                   0.09 * cosDeg(2 * omega)) /
                  3600.0 * kDeg;
    return n;
}

double meanObliquity(double jd) {
    const double t = centuries(jd);  // Meeus 22.2
    return (23.0 + (26.0 + (21.448 - t * (46.8150 + t * (0.00059 - t * 0.001813))) / 60.0) / 60.0) * kDeg;
}

double greenwichSiderealTime(double jd) {
    const double t = centuries(jd);  // Meeus 12.4, then + delta psi cos(eps)
    const double mean =
        280.46061837 + 360.98564736629 * (jd - kJ2000) + t * t * (0.000387933 - t / 38710000.0);
    const Nutation n = nutation(jd);
    const double eps = meanObliquity(jd) + n.obliquity;
    return wrapDegrees(mean + n.longitude * std::cos(eps) / kDeg) * kDeg;
}

SunPlace sun(double jd) {
    // NOAA Solar Calculator = Meeus ch. 25, low precision (25.2-25.8).
    const double t = centuries(jd);
    const double l0 = wrapDegrees(280.46646 + t * (36000.76983 + t * 0.0003032));
    const double m = 357.52911 + t * (35999.05029 - 0.0001537 * t);
    const double e = 0.016708634 - t * (0.000042037 + 0.0000001267 * t);
    const double c = sinDeg(m) * (1.914602 - t * (0.004817 + 0.000014 * t)) +
                     sinDeg(2 * m) * (0.019993 - 0.000101 * t) + sinDeg(3 * m) * 0.000289;
    const double trueLongitude = l0 + c;
    const double trueAnomaly = m + c;
    const double omega = 125.04 - 1934.136 * t;
    const double lambda = trueLongitude - 0.00569 - 0.00478 * sinDeg(omega);
    const double eps = meanObliquity(jd) / kDeg + 0.00256 * cosDeg(omega);  // 25.8
    SunPlace s;
    s.distanceAu = 1.000001018 * (1.0 - e * e) / (1.0 + e * cosDeg(trueAnomaly));
    s.apparentLongitude = wrapDegrees(lambda) * kDeg;
    s.rightAscension = wrapDegrees(std::atan2(cosDeg(eps) * sinDeg(lambda), cosDeg(lambda)) / kDeg) * kDeg;
    s.declination = std::asin(std::clamp(sinDeg(eps) * sinDeg(lambda), -1.0, 1.0));
    // Meeus 28.1: E = L0 - 0.0057183 deg - alpha + delta psi cos(eps), with
    // the same nutation as the sidereal time so that H = theta + lon - alpha
    // equals 15 (UT + lon/15 + E - 12) exactly.
    const Nutation n = nutation(jd);
    const double epsTrue = meanObliquity(jd) + n.obliquity;
    double eot = l0 - 0.0057183 - s.rightAscension / kDeg + n.longitude * std::cos(epsTrue) / kDeg;
    eot = std::remainder(eot, 360.0);
    s.equationOfTimeHours = eot / 15.0;
    return s;
}

MoonPlace moon(double jd) {
    const double t = centuries(jd);
    const double t2 = t * t, t3 = t2 * t, t4 = t3 * t;
    // Meeus 47.1-47.5 (degrees).
    const double lp =
        wrapDegrees(218.3164477 + 481267.88123421 * t - 0.0015786 * t2 + t3 / 538841.0 - t4 / 65194000.0);
    const double d =
        wrapDegrees(297.8501921 + 445267.1114034 * t - 0.0018819 * t2 + t3 / 545868.0 - t4 / 113065000.0);
    const double m = wrapDegrees(357.5291092 + 35999.0502909 * t - 0.0001536 * t2 + t3 / 24490000.0);
    const double mp =
        wrapDegrees(134.9633964 + 477198.8675055 * t + 0.0087414 * t2 + t3 / 69699.0 - t4 / 14712000.0);
    const double f =
        wrapDegrees(93.2720950 + 483202.0175233 * t - 0.0036539 * t2 - t3 / 3526000.0 + t4 / 863310000.0);
    const double a1 = wrapDegrees(119.75 + 131.849 * t);
    const double a2 = wrapDegrees(53.09 + 479264.290 * t);
    const double a3 = wrapDegrees(313.45 + 481266.484 * t);
    const double ecc = 1.0 - 0.002516 * t - 0.0000074 * t2;  // 47.6
    auto eccentricity = [&](int mMultiple) {
        return mMultiple == 0 ? 1.0 : (mMultiple == 1 || mMultiple == -1 ? ecc : ecc * ecc);
    };
    double sumL = 0.0, sumR = 0.0, sumB = 0.0;
    for (const LongitudeTerm& k : kMoonLongitude) {
        const double arg = (k.d * d + k.m * m + k.mp * mp + k.f * f) * kDeg;
        const double w = eccentricity(k.m);
        sumL += k.sinL * w * std::sin(arg);
        sumR += k.cosR * w * std::cos(arg);
    }
    for (const LatitudeTerm& k : kMoonLatitude) {
        const double arg = (k.d * d + k.m * m + k.mp * mp + k.f * f) * kDeg;
        sumB += k.sinB * eccentricity(k.m) * std::sin(arg);
    }
    // Venus, Jupiter and the flattening of the Earth.
    sumL += 3958.0 * sinDeg(a1) + 1962.0 * sinDeg(lp - f) + 318.0 * sinDeg(a2);
    sumB += -2235.0 * sinDeg(lp) + 382.0 * sinDeg(a3) + 175.0 * sinDeg(a1 - f) + 175.0 * sinDeg(a1 + f) +
            127.0 * sinDeg(lp - mp) - 115.0 * sinDeg(lp + mp);
    MoonPlace place;
    place.longitude = wrapDegrees(lp + sumL / 1e6) * kDeg;
    place.latitude = sumB / 1e6 * kDeg;
    place.distanceKm = 385000.56 + sumR / 1000.0;
    const Nutation n = nutation(jd);
    eclipticToEquatorial(place.longitude + n.longitude, place.latitude, meanObliquity(jd) + n.obliquity,
                         place.rightAscension, place.declination);
    return place;
}

MoonPhase moonPhase(const SunPlace& s, const MoonPlace& m) {
    constexpr double kAuKm = 149597870.7;
    // Meeus 48.2 (elongation), 48.3 (phase angle), 48.5 (bright limb).
    const double cosPsi =
        std::sin(s.declination) * std::sin(m.declination) +
        std::cos(s.declination) * std::cos(m.declination) * std::cos(s.rightAscension - m.rightAscension);
    const double psi = std::acos(std::clamp(cosPsi, -1.0, 1.0));
    const double r = s.distanceAu * kAuKm;
    MoonPhase phase;
    phase.phaseAngle = std::atan2(r * std::sin(psi), m.distanceKm - r * std::cos(psi));
    const double chi = std::atan2(std::cos(s.declination) * std::sin(s.rightAscension - m.rightAscension),
                                  std::sin(s.declination) * std::cos(m.declination) -
                                      std::cos(s.declination) * std::sin(m.declination) *
                                          std::cos(s.rightAscension - m.rightAscension));
    phase.brightLimbPositionAngle = chi < 0.0 ? chi + 2.0 * kPiD : chi;
    return phase;
}

double refraction(double geometricElevation) {
    // Saemundsson (Meeus 16.4) in arc minutes for h [deg]; valid from the
    // zenith down to about -1 deg, faded linearly to 0 at -6 deg.
    const double h = geometricElevation / kDeg;
    if (!std::isfinite(h) || h <= -6.0) return 0.0;
    auto saemundsson = [](double hDeg) {
        const double r = 1.02 / std::tan((hDeg + 10.3 / (hDeg + 5.11)) * kDeg);
        return std::max(0.0, r);
    };
    const double arcmin = h >= -1.0 ? saemundsson(std::min(h, 90.0)) : saemundsson(-1.0) * (h + 6.0) / 5.0;
    return arcmin / 60.0 * kDeg;
}

}  // namespace ephemeris
}  // namespace aerial
