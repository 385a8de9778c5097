// Sun and moon positions against hand-checkable values.
#include <aerial/sun.hpp>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;
constexpr double kEquinoxDay = 81.25;  // 360/365 (d + 10) = 90 deg: declination 0

aerial::Location at(double latitudeDeg, double day) {
    aerial::Location where;
    where.latitudeDeg = latitudeDeg;
    where.dayOfYear = day;
    return where;
}

/// Sunrise found by bisection on the elevation itself (independent of the
/// closed form in sunriseHours).
double bisectSunrise(const aerial::Location& where) {
    double lo = 0.0, hi = 12.0;  // below at midnight, above at noon
    for (int i = 0; i < 80; ++i) {
        const double mid = 0.5 * (lo + hi);
        (aerial::sunPosition(where, mid).elevation < 0.0 ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

TEST(Sun, DeclinationMatchesDesignFormula) {
    EXPECT_NEAR(aerial::solarDeclination(172.0), -23.44 * kDeg * std::cos(2 * kPi / 365 * 182), 1e-15);
    EXPECT_NEAR(aerial::solarDeclination(kEquinoxDay), 0.0, 1e-15);
    // Solstices: |declination| close to the obliquity.
    EXPECT_NEAR(aerial::solarDeclination(172.5), 23.44 * kDeg, 0.01 * kDeg);
    EXPECT_NEAR(aerial::solarDeclination(355.0), -23.44 * kDeg, 0.01 * kDeg);
}

TEST(Sun, SolarNoonElevationIs90MinusLatitudeMinusDeclination) {
    for (double lat : {-60.0, -33.9, 0.0, 12.5, 45.0, 51.5, 66.0}) {
        for (double day : {1.0, 81.25, 172.0, 264.0, 355.0}) {
            const double dec = aerial::solarDeclination(day) / kDeg;
            const aerial::CelestialBody sun = aerial::sunPosition(at(lat, day), 12.0);
            EXPECT_NEAR(sun.elevation / kDeg, 90.0 - std::abs(lat - dec), 1e-9) << lat << " " << day;
        }
    }
}

TEST(Sun, NoonSunIsDueSouthInTheNorth) {
    const aerial::CelestialBody sun = aerial::sunPosition(at(45.0, 172.0), 12.0);
    EXPECT_NEAR(sun.azimuth, kPi, 1e-12);
    // South is +Z (north is -Z).
    EXPECT_NEAR(sun.direction.x, 0.0, 1e-12);
    EXPECT_NEAR(sun.direction.z, std::cos(sun.elevation), 1e-12);
    // Southern hemisphere in June: the noon sun is due north (-Z).
    const aerial::CelestialBody south = aerial::sunPosition(at(-35.0, 172.0), 12.0);
    EXPECT_NEAR(std::fmod(south.azimuth + kPi, 2 * kPi) - kPi, 0.0, 1e-12);
    EXPECT_LT(south.direction.z, -0.5);
}

TEST(Sun, MorningSunIsEastEveningSunIsWest) {
    const aerial::CelestialBody morning = aerial::sunPosition(at(45.0, 172.0), 7.0);
    const aerial::CelestialBody evening = aerial::sunPosition(at(45.0, 172.0), 17.0);
    EXPECT_GT(morning.direction.x, 0.3);  // east = +X
    EXPECT_LT(evening.direction.x, -0.3);
}

TEST(Sun, SymmetricAboutNoon) {
    for (double lat : {-40.0, 10.0, 47.0}) {
        for (double dx : {0.5, 3.0, 5.25, 7.0, 11.0}) {
            const aerial::CelestialBody am = aerial::sunPosition(at(lat, 120.0), 12.0 - dx);
            const aerial::CelestialBody pm = aerial::sunPosition(at(lat, 120.0), 12.0 + dx);
            EXPECT_NEAR(am.elevation, pm.elevation, 1e-12);
            EXPECT_NEAR(am.direction.x, -pm.direction.x, 1e-12);
            EXPECT_NEAR(am.direction.z, pm.direction.z, 1e-12);
        }
    }
}

TEST(Sun, SunriseAndSunsetSymmetricAboutNoon) {
    for (double lat : {-50.0, 0.0, 30.0, 60.0}) {
        for (double day : {20.0, 140.0, 250.0}) {
            const aerial::Location where = at(lat, day);
            const double rise = bisectSunrise(where);
            // Sunset by bisection from the other side of noon.
            double lo = 12.0, hi = 24.0;
            for (int i = 0; i < 80; ++i) {
                const double mid = 0.5 * (lo + hi);
                (aerial::sunPosition(where, mid).elevation > 0.0 ? lo : hi) = mid;
            }
            const double set = 0.5 * (lo + hi);
            EXPECT_NEAR(12.0 - rise, set - 12.0, 1e-9) << lat << " " << day;
            EXPECT_NEAR(aerial::sunriseHours(where), rise, 1e-9);
        }
    }
}

TEST(Sun, EquinoxDayLastsTwelveHours) {
    for (double lat : {-70.0, -45.0, 0.0, 23.0, 45.0, 70.0}) {
        const aerial::Location where = at(lat, kEquinoxDay);
        EXPECT_NEAR(aerial::dayLengthHours(where), 12.0, 1e-9) << lat;
        EXPECT_NEAR(bisectSunrise(where), 6.0, 1e-9) << lat;
    }
}

TEST(Sun, PolarDayAndNight) {
    EXPECT_DOUBLE_EQ(aerial::dayLengthHours(at(80.0, 172.0)), 24.0);
    EXPECT_DOUBLE_EQ(aerial::dayLengthHours(at(80.0, 355.0)), 0.0);
    EXPECT_GT(aerial::sunPosition(at(80.0, 172.0), 0.0).elevation, 0.0);  // midnight sun
}

TEST(Sun, NorthOffsetRotatesAboutY) {
    aerial::Location where = at(45.0, 172.0);
    const aerial::CelestialBody base = aerial::sunPosition(where, 9.0);
    where.northOffsetDeg = 90.0;
    const aerial::CelestialBody turned = aerial::sunPosition(where, 9.0);
    EXPECT_NEAR(turned.elevation, base.elevation, 1e-15);
    // Azimuth +90 deg maps (x, z) = (sin az, -cos az) to (cos az, sin az) = (-z, x).
    EXPECT_NEAR(turned.direction.x, -base.direction.z, 1e-12);
    EXPECT_NEAR(turned.direction.z, base.direction.x, 1e-12);
}

TEST(Sun, DirectionIsUnitAndTimeWraps) {
    for (double t = -30.0; t < 50.0; t += 0.37) {
        const aerial::CelestialBody sun = aerial::sunPosition(at(33.0, 200.0), t);
        EXPECT_NEAR(glm::length(sun.direction), 1.0, 1e-12);
        const aerial::CelestialBody wrapped = aerial::sunPosition(at(33.0, 200.0), std::fmod(t + 48.0, 24.0));
        EXPECT_NEAR(sun.elevation, wrapped.elevation, 1e-9);
    }
    EXPECT_NEAR(aerial::sunPosition(at(33.0, 200.0), 24.0).elevation,
                aerial::sunPosition(at(33.0, 200.0), 0.0).elevation, 1e-15);
}

TEST(Moon, PhasesFollowTheSynodicMonth) {
    aerial::Location where = at(45.0, 100.0);
    const double synodic = 29.530589;
    where.moonPhaseOffsetDays = -100.0;  // age 0 on day 100: new moon
    aerial::CelestialBody moon = aerial::moonPosition(where, 0.0);
    EXPECT_NEAR(moon.illuminatedFraction, 0.0, 1e-12);
    EXPECT_NEAR(moon.phaseIrradiance, 0.0, 1e-12);
    where.moonPhaseOffsetDays = -100.0 + synodic / 2.0;  // full moon
    moon = aerial::moonPosition(where, 0.0);
    EXPECT_NEAR(moon.illuminatedFraction, 1.0, 1e-12);
    EXPECT_NEAR(moon.phaseIrradiance, 1.0, 1e-12);
    where.moonPhaseOffsetDays = -100.0 + synodic / 4.0;  // first quarter
    moon = aerial::moonPosition(where, 0.0);
    EXPECT_NEAR(moon.illuminatedFraction, 0.5, 1e-12);
    EXPECT_NEAR(moon.phaseIrradiance, 1.0 / kPi, 1e-12);  // Lambert sphere at 90 deg
}

TEST(Moon, FullMoonTransitsAtMidnightOppositeTheSun) {
    aerial::Location where = at(40.0, kEquinoxDay);
    where.moonPhaseOffsetDays = 29.530589 / 2.0 - kEquinoxDay;  // full moon today
    const aerial::CelestialBody moon = aerial::moonPosition(where, 0.0);
    const aerial::CelestialBody sunAtNoon = aerial::sunPosition(where, 12.0);
    // Due south at midnight, and on the equinox as high as the noon sun.
    EXPECT_NEAR(moon.azimuth, kPi, 1e-9);
    EXPECT_NEAR(moon.elevation, sunAtNoon.elevation, 1e-9);
    // A moonlit night: the moon is up at 02:00.
    EXPECT_GT(aerial::moonPosition(where, 2.0).elevation, 20.0 * kDeg);
}

TEST(Moon, TransitIsAboutFiftyMinutesLaterEachDay) {
    aerial::Location where = at(0.0, 50.0);
    auto transit = [&](double day) {
        where.dayOfYear = day;
        // Time of the highest elevation, by golden-section-free scan + refinement.
        double best = 0.0, bestEl = -10.0;
        for (double t = 0.0; t < 24.0; t += 0.01) {
            const double el = aerial::moonPosition(where, t).elevation;
            if (el > bestEl) bestEl = el, best = t;
        }
        return best;
    };
    double delay = transit(51.0) - transit(50.0);
    if (delay < 0) delay += 24.0;
    EXPECT_NEAR(delay * 60.0, 24.0 * 60.0 / 29.530589, 1.5);  // minutes, scan step 0.6 min
}

// The celestial frame: orthonormal, pole at elevation = latitude due north
// (north offset included), the sun's angle to the pole fixed by its
// declination all day, one turn per sidereal day, westwards.
TEST(CelestialFrame, PoleAndSunFollowSphericalAstronomy) {
    for (double lat : {-60.0, -10.0, 0.0, 37.0, 89.0}) {
        for (double offset : {0.0, 25.0}) {
            aerial::Location where = at(lat, 100.0);
            where.northOffsetDeg = offset;
            const aerial::CelestialFrame f = aerial::celestialFrame(where, 3.7);
            EXPECT_NEAR(glm::dot(f.equatorX, f.equatorY), 0.0, 1e-12);
            EXPECT_NEAR(glm::dot(f.equatorX, f.pole), 0.0, 1e-12);
            EXPECT_NEAR(glm::dot(f.equatorY, f.pole), 0.0, 1e-12);
            EXPECT_NEAR(glm::length(f.equatorX), 1.0, 1e-12);
            EXPECT_NEAR(glm::length(f.pole), 1.0, 1e-12);
            EXPECT_NEAR(f.pole.y, std::sin(lat * kDeg), 1e-12);
            if (lat < 89.0) {  // azimuth of the pole: north (-Z) turned by the offset towards +X
                EXPECT_NEAR(std::atan2(f.pole.x, -f.pole.z), offset * kDeg, 1e-9);
            }
            const double sinDec = std::sin(aerial::solarDeclination(where.dayOfYear));
            for (double t = 0.0; t < 24.0; t += 1.3) {
                EXPECT_NEAR(glm::dot(aerial::celestialFrame(where, t).pole,
                                     aerial::sunPosition(where, t).direction),
                            sinDec, 1e-12);
            }
        }
    }
}

TEST(CelestialFrame, TurnsOncePerSiderealDayWestwards) {
    const aerial::Location day1 = at(45.0, 200.0);
    aerial::Location day2 = day1;
    day2.dayOfYear += 1.0;
    const double ra = 1.1, dec = 0.3;
    auto star = [&](const aerial::Location& where, double t) {
        const aerial::CelestialFrame f = aerial::celestialFrame(where, t);
        return std::cos(dec) * (std::cos(ra) * f.equatorX + std::sin(ra) * f.equatorY) + std::sin(dec) * f.pole;
    };
    // One sidereal day later (the next calendar day, 3 min 56 s earlier).
    const glm::dvec3 a = star(day1, 5.0);
    const glm::dvec3 b = star(day2, 5.0 - (24.0 - aerial::kSiderealDayHours));
    EXPECT_NEAR(glm::length(a - b), 0.0, 1e-9);
    // The sky turns about the pole by 2 pi / sidereal day per hour, in the
    // sense -pole x star (the earth turns eastwards): westwards.
    const aerial::CelestialFrame now = aerial::celestialFrame(day1, 5.0);
    const aerial::CelestialFrame later = aerial::celestialFrame(day1, 6.0);
    const double turned = std::acos(std::clamp(glm::dot(now.equatorX, later.equatorX), -1.0, 1.0));
    EXPECT_NEAR(turned, 2.0 * kPi / aerial::kSiderealDayHours, 1e-9);
    EXPECT_GT(glm::dot(later.equatorX - now.equatorX, -glm::cross(now.pole, now.equatorX)), 0.0);
    EXPECT_NEAR(glm::length(later.pole - now.pole), 0.0, 1e-12);
}

}  // namespace
