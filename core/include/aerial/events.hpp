// aerial/events.hpp — what happens between two frames, for a game's sound
// and gameplay to follow: the sun's events, each whole hour, lightning
// strikes, and the weather's changes starting and ending. Polled with a
// time range; no callbacks into engine threads.
//
// Usage (once per frame, after advancing the clocks):
//   std::vector<aerial::Event> events;            // reused
//   aerial::pollEvents(compiled, &weather, lastHours, nowHours, lastSeconds, nowSeconds, events);
//   for (const aerial::Event& e : events)
//       if (e.kind == aerial::EventKind::LightningStrike) playThunder(e.position, e.timeHours);
//
// The time of day runs in (fromHours, toHours], wrapping at midnight when
// toHours < fromHours (at most one whole day); the game clock in
// (fromSeconds, toSeconds]. The events come sorted by time of day, the
// weather's by game clock after them. Everything is computed from the
// preset and the times alone, as the flashes the renderer draws
// (lightningFlash, emitter.hpp): the same range gives the same events on
// every machine.
#pragma once

#include <aerial/evaluate.hpp>
#include <aerial/sun.hpp>
#include <aerial/weather.hpp>

#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace aerial {

enum class EventKind {
    Sun,              ///< a sun event (sunEvent): dawn, sunrise, noon, sunset, dusk
    Hour,             ///< a whole hour of the time of day (hour)
    LightningStrike,  ///< a lightning emitter's flash starts (emitterId, position)
    WeatherStart,     ///< a weather change starts (state: where it goes)
    WeatherEnd,       ///< a weather change ends (state)
};

struct Event {
    EventKind kind = EventKind::Hour;
    /// When, in the time of day [h] (time-of-day events) ...
    double timeHours = 0.0;
    /// ... or on the game clock [s] (weather events; 0 for the others).
    double gameSeconds = 0.0;
    SunEvent sunEvent = SunEvent::Noon;  ///< Sun
    int hour = 0;                        ///< Hour: 0..23
    std::string emitterId;               ///< LightningStrike
    glm::dvec3 position{0.0};            ///< LightningStrike: the emitter's position [m]
    std::string state;                   ///< WeatherStart / WeatherEnd
};

/// The events of the range (above) into `events` (cleared first). The sun's
/// events are those of the preset's location and date (sunEventHours) where
/// the sun really crosses the event's elevation (none in a polar day or
/// night); lightning strikes of the preset's lightning emitters with their
/// keyed rate (and the weather's at toSeconds; an emitter keyed to a zero
/// rate does not strike); `weather` may be null. Allocates (the events, one
/// evaluation of the preset).
void pollEvents(const CompiledPreset& compiled, const Weather* weather, double fromHours, double toHours,
                double fromSeconds, double toSeconds, std::vector<Event>& events);

}  // namespace aerial
