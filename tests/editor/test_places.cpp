// The city list: names found as typed, every place where its time zone says
// (noon in clock time within 10:30..14:00 all year, which a longitude with
// the wrong sign or a swapped offset breaks by hours), applied to a location.
#include "places.hpp"

#include <aerial/sun.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

namespace aerial::editor {
namespace {

TEST(Places, NamesAreUniqueAndFoundAsTyped) {
    std::set<std::string> seen;
    for (const Place& p : places()) {
        EXPECT_TRUE(seen.insert(std::string(p.name)).second) << p.name;
        EXPECT_EQ(findPlace(p.name), &p);
    }
    EXPECT_GE(places().size(), 30u);
    ASSERT_NE(findPlace("tokyo"), nullptr);
    EXPECT_EQ(findPlace("tokyo")->name, "Tokyo");
    EXPECT_EQ(findPlace("Atlantis"), nullptr);
    EXPECT_EQ(findPlace(""), nullptr);
}

TEST(Places, ClockNoonFallsNearMiddayAllYear) {
    for (const Place& p : places()) {
        EXPECT_LE(std::abs(p.latitudeDeg), 90.0) << p.name;
        EXPECT_LE(std::abs(p.longitudeDeg), 180.0) << p.name;
        for (const char* date : {"2026-02-11", "2026-05-14", "2026-07-26", "2026-11-03"}) {
            Location where;
            where.date = date;
            where.timeMode = TimeMode::Clock;
            applyPlace(where, p);
            const double noon = solarNoonHours(where);
            EXPECT_GE(noon, 10.5) << p.name << " " << date;
            EXPECT_LE(noon, 14.0) << p.name << " " << date;
        }
    }
}

TEST(Places, ApplySetsThePlaceOnly) {
    Location where;
    where.date = "2026-06-21";
    where.timeMode = TimeMode::Clock;
    where.northOffsetDeg = 30.0;
    applyPlace(where, *findPlace("Reykjavik"));
    EXPECT_EQ(where.latitudeDeg, 64.15);
    EXPECT_EQ(where.longitudeDeg, -21.94);
    EXPECT_EQ(where.utcOffsetHours, 0.0);
    EXPECT_EQ(where.date, "2026-06-21");
    EXPECT_EQ(where.timeMode, TimeMode::Clock);
    EXPECT_EQ(where.northOffsetDeg, 30.0);
    // Reykjavik keeps UTC 1.46 h east of its meridian: the sun culminates at
    // about 13:29 clock time at midsummer (equation of time -1.6 min).
    EXPECT_NEAR(solarNoonHours(where), 12.0 + 21.94 / 15.0 + 1.6 / 60.0, 3.0 / 60.0);
}

}  // namespace
}  // namespace aerial::editor
