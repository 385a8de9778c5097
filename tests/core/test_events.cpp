// Events a game polls (aerial/events.hpp): the sun's events and hours over
// a day and across midnight, lightning strikes against the flashes the
// renderer draws, the weather's changes, and no sunrise in a polar day.
#include <aerial/events.hpp>
#include <aerial/preset.hpp>

#include <gtest/gtest.h>

#include "shipped_preset.hpp"

#include <string>
#include <vector>

namespace aerial {
namespace {

int count(const std::vector<Event>& events, EventKind kind) {
    int n = 0;
    for (const Event& e : events) n += e.kind == kind;
    return n;
}

TEST(Events, ADayHasItsHoursAndItsSunEventsInOrder) {
    const CompiledPreset compiled(test::loadShippedPreset("clear_summer_day.json"));
    std::vector<Event> events;
    pollEvents(compiled, nullptr, 0.0, 24.0, 0.0, 0.0, events);
    EXPECT_EQ(count(events, EventKind::Hour), 24);
    EXPECT_EQ(count(events, EventKind::Sun), 7);  // 45 deg N in June: every event happens
    for (std::size_t k = 1; k < events.size(); ++k) EXPECT_LE(events[k - 1].timeHours, events[k].timeHours);
    const Location& where = compiled.preset().environment.location;
    for (const Event& e : events) {
        if (e.kind == EventKind::Sun) {
            EXPECT_EQ(e.timeHours, sunEventHours(where, e.sunEvent));
        }
    }
    // A frame of a few seconds holds nothing, or just what falls in it.
    const double sunrise = sunEventHours(where, SunEvent::Sunrise);
    pollEvents(compiled, nullptr, sunrise - 1e-3, sunrise + 1e-3, 0.0, 0.0, events);
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].sunEvent, SunEvent::Sunrise);
    pollEvents(compiled, nullptr, sunrise, sunrise + 1e-3, 0.0, 0.0, events);
    EXPECT_TRUE(events.empty()) << "the range is (from, to]: no event twice";
}

TEST(Events, MidnightIsCrossedOnce) {
    const CompiledPreset compiled(test::loadShippedPreset("clear_summer_day.json"));
    std::vector<Event> events;
    pollEvents(compiled, nullptr, 23.5, 0.5, 0.0, 0.0, events);
    ASSERT_EQ(count(events, EventKind::Hour), 1);
    EXPECT_EQ(events.front().hour, 0);
}

TEST(Events, NoSunriseInAPolarDay) {
    Preset p = test::loadShippedPreset("clear_summer_day.json");
    p.environment.location.latitudeDeg = 80.0;  // June
    p.environment.location.date.clear();
    p.environment.location.dayOfYear = 172.0;
    const CompiledPreset compiled(std::move(p));
    std::vector<Event> events;
    pollEvents(compiled, nullptr, 0.0, 24.0, 0.0, 0.0, events);
    EXPECT_EQ(count(events, EventKind::Sun), 1);  // noon alone
}

// Every flash lightningFlash draws starts at a reported strike (scanned at
// a tenth of a flash), and each strike starts a flash.
TEST(Events, LightningStrikesAreTheFlashesTheRendererDraws) {
    const CompiledPreset compiled(test::loadShippedPreset("stormy_night.json"));
    std::vector<Event> events;
    pollEvents(compiled, nullptr, 1.0, 2.0, 0.0, 0.0, events);
    const PresetState state = compiled.evaluate(1.5);
    int strikes = 0;
    for (const Emitter& e : state.emitters) {
        if (e.kind != EmitterKind::Lightning) continue;
        std::vector<double> starts;
        for (const Event& ev : events)
            if (ev.kind == EventKind::LightningStrike && ev.emitterId == e.id) {
                starts.push_back(ev.timeHours);
                EXPECT_EQ(ev.position, e.position);
            }
        strikes += int(starts.size());
        const double flash = e.flashDurationSeconds * e.timeScale / 3600.0;  // [h]
        const double step = 0.1 * flash;
        bool was = lightningFlash(e, 1.0) > 0.0;
        std::size_t next = 0;
        for (double t = 1.0 + step; t <= 2.0; t += step) {
            const bool is = lightningFlash(e, t) > 0.0;
            if (is && !was) {  // a flash began in (t - step, t]
                while (next < starts.size() && starts[next] <= t - step) ++next;
                ASSERT_LT(next, starts.size()) << e.id << " flash at " << t << " h not reported";
                EXPECT_GT(starts[next], t - step - 1e-12) << e.id;
                EXPECT_LE(starts[next], t + 1e-12) << e.id;
            }
            was = is;
        }
        for (double s : starts) EXPECT_GT(lightningFlash(e, s + 1e-9), 0.0) << e.id << " at " << s;
    }
    EXPECT_GE(strikes, 5);  // a stormy hour
}

TEST(Events, WeatherChangesStartAndEnd) {
    const CompiledPreset compiled(test::loadShippedPreset("clear_summer_day.json"));
    Weather weather(compiled.preset(), "clear");
    ASSERT_TRUE(weather.change("storm", 300.0, 10.0));
    std::vector<Event> events;
    pollEvents(compiled, &weather, 12.0, 12.001, 0.0, 20.0, events);
    ASSERT_EQ(count(events, EventKind::WeatherStart), 1);
    EXPECT_EQ(events.back().state, "storm");
    EXPECT_EQ(events.back().gameSeconds, 10.0);
    pollEvents(compiled, &weather, 12.0, 12.001, 300.0, 320.0, events);
    EXPECT_EQ(count(events, EventKind::WeatherEnd), 1);
    pollEvents(compiled, &weather, 12.0, 12.001, 20.0, 300.0, events);
    EXPECT_TRUE(events.empty());
}

}  // namespace
}  // namespace aerial
