// events.cpp — the sun's events, hours, lightning strikes and weather
// changes in a time range (aerial/events.hpp).
#include <aerial/events.hpp>

#include <algorithm>
#include <cmath>

namespace aerial {
namespace {

/// Appends the time-of-day events in (from, to] of one day, 0 <= from <= to <= 24.
void dayEvents(const CompiledPreset& compiled, const WeatherMix& mix, double from, double to,
               std::vector<Event>& events) {
    if (!(from < to)) return;
    const Preset& preset = compiled.preset();
    const Location& where = preset.environment.location;
    for (SunEvent e : kSunEvents) {
        const double t = sunEventCrossingHours(where, e);  // NaN: no such event that day
        if (t > from && t <= to) {
            Event ev;
            ev.kind = EventKind::Sun;
            ev.timeHours = t;
            ev.sunEvent = e;
            events.push_back(ev);
        }
    }
    for (int h = int(std::floor(from)) + 1; h <= int(std::floor(to)); ++h) {
        Event ev;
        ev.kind = EventKind::Hour;
        ev.timeHours = h;
        ev.hour = h % 24;
        events.push_back(ev);
    }
    // Lightning: each emitter as keyed (and as the weather has it) at the
    // middle of the range: its rate does not jump within a frame. A preset
    // without lightning is not evaluated.
    if (std::none_of(preset.emitters.begin(), preset.emitters.end(),
                     [](const Emitter& e) { return e.kind == EmitterKind::Lightning; }))
        return;
    PresetState state;
    compiled.evaluate(0.5 * (from + to), mix, state);
    std::vector<double> starts;
    for (const Emitter& e : state.emitters) {
        if (e.kind != EmitterKind::Lightning) continue;
        starts.clear();
        lightningStrikeHours(e, from, to, starts);
        for (double t : starts) {
            Event ev;
            ev.kind = EventKind::LightningStrike;
            ev.timeHours = t;
            ev.emitterId = e.id;
            ev.position = e.position;
            events.push_back(ev);
        }
    }
}

}  // namespace

void pollEvents(const CompiledPreset& compiled, const Weather* weather, double fromHours, double toHours,
                double fromSeconds, double toSeconds, std::vector<Event>& events) {
    events.clear();
    WeatherMix mix;
    if (weather && std::isfinite(toSeconds)) weather->mix(toSeconds, mix);
    if (std::isfinite(fromHours) && std::isfinite(toHours)) {
        const double from = std::fmod(std::fmod(fromHours, 24.0) + 24.0, 24.0);
        double to = std::fmod(std::fmod(toHours, 24.0) + 24.0, 24.0);
        if (toHours - fromHours >= 24.0) to = from;  // a whole day
        if (to > from) {
            dayEvents(compiled, mix, from, to, events);
        } else if (to < from || toHours - fromHours >= 24.0) {
            dayEvents(compiled, mix, from, 24.0, events);  // across midnight: 24 h is 0 h
            std::size_t before = events.size();
            dayEvents(compiled, mix, 0.0, to, events);
            for (std::size_t k = before; k < events.size(); ++k)
                if (events[k].kind == EventKind::Hour && events[k].hour == 0) events[k].timeHours = 24.0;
        }
        std::stable_sort(events.begin(), events.end(), [from](const Event& a, const Event& b) {
            auto order = [from](double t) { return t <= from ? t + 24.0 : t; };
            return order(a.timeHours) < order(b.timeHours);
        });
    }
    if (!weather || !std::isfinite(fromSeconds) || !std::isfinite(toSeconds)) return;
    for (const WeatherChange& c : weather->changes()) {
        const double end = c.startSeconds + c.durationSeconds;
        if (c.startSeconds > fromSeconds && c.startSeconds <= toSeconds) {
            Event ev;
            ev.kind = EventKind::WeatherStart;
            ev.gameSeconds = c.startSeconds;
            ev.state = c.state;
            events.push_back(ev);
        }
        if (end > fromSeconds && end <= toSeconds) {
            Event ev;
            ev.kind = EventKind::WeatherEnd;
            ev.gameSeconds = end;
            ev.state = c.state;
            events.push_back(ev);
        }
    }
}

}  // namespace aerial
