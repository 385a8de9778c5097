// test_clock.cpp — times of day as text (aerial/clock.hpp): every minute and
// second of the day round-trips, and malformed text is refused.
#include <aerial/clock.hpp>

#include <gtest/gtest.h>

#include <cstdio>
#include <limits>
#include <string>

namespace {

TEST(Clock, ParsesTheWrittenForms) {
    struct Case {
        const char* text;
        double hours;
    };
    const Case cases[] = {{"00:00", 0.0},
                          {"06:30", 6.5},
                          {"6:30", 6.5},
                          {"23:59", 23.0 + 59.0 / 60.0},
                          {"18:45:30", 18.0 + 45.0 / 60.0 + 30.0 / 3600.0},
                          {" 12:00 ", 12.0},
                          {"7.5", 7.5},
                          {"7.5h", 7.5},
                          {"7.5 h", 7.5},
                          {"0", 0.0},
                          {"23.999", 23.999},
                          {"+1e1", 10.0}};
    for (const Case& c : cases) {
        double t = -1.0;
        EXPECT_TRUE(aerial::parseClock(c.text, t)) << c.text;
        EXPECT_DOUBLE_EQ(t, c.hours) << c.text;
    }
}

TEST(Clock, RefusesMalformedText) {
    const char* bad[] = {"",       "24:00", "24",      "-1",    "12:60", "12:00:60", "7:5",   "123:00",
                         "12:",    ":30",   "1:2:3:4", "nan",   "inf",   "0x10",     "1e400", "12:00x",
                         "twelve", "12h00", "h",       "12:3a", "-0.5h", "12::00"};
    for (const char* text : bad) {
        double t = 42.0;
        EXPECT_FALSE(aerial::parseClock(text, t)) << '"' << text << '"';
        EXPECT_EQ(t, 42.0) << '"' << text << '"';
    }
}

TEST(Clock, EverySecondOfTheDayRoundTrips) {
    for (int s = 0; s < 86400; ++s) {
        char expected[16];
        if (s % 60 == 0)
            std::snprintf(expected, sizeof expected, "%02d:%02d", s / 3600, s / 60 % 60);
        else
            std::snprintf(expected, sizeof expected, "%02d:%02d:%02d", s / 3600, s / 60 % 60, s % 60);
        const std::string text = aerial::formatClock(s / 3600.0);
        ASSERT_EQ(text, expected) << s;
        double back = -1.0;
        ASSERT_TRUE(aerial::parseClock(text, back)) << text;
        ASSERT_NEAR(back * 3600.0, s, 1e-9) << text;
    }
}

TEST(Clock, MinutesShowTheMinuteThatHasBegunAndTimesWrap) {
    using aerial::ClockResolution;
    EXPECT_EQ(aerial::formatClock(6.0 + 29.99 / 60.0, ClockResolution::Minutes), "06:29");
    EXPECT_EQ(aerial::formatClock(6.5, ClockResolution::Minutes), "06:30");
    EXPECT_EQ(aerial::formatClock(6.0 + 29.9999 / 60.0), "06:30");  // rounded to the second
    EXPECT_EQ(aerial::formatClock(6.0 + 29.99 / 60.0), "06:29:59");
    EXPECT_EQ(aerial::formatClock(25.25), "01:15");
    EXPECT_EQ(aerial::formatClock(-0.5), "23:30");
    EXPECT_EQ(aerial::formatClock(23.99999999), "00:00");
    EXPECT_EQ(aerial::formatClock(std::numeric_limits<double>::quiet_NaN()), "00:00");
}

}  // namespace
