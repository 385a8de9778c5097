// Keys that follow the sun (TrackKey::anchor, sunEventHours): the events
// against the spherical-trigonometry closed form of the undated model (the
// dated ones against PyEphem: tests/cli/ephemeris_test.py), events that do
// not happen, and anchored keys through load, save, a new date and edits.
#include <aerial/evaluate.hpp>
#include <aerial/preset.hpp>
#include <aerial/sun.hpp>
#include <aerial/timeline.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

namespace {

const std::filesystem::path kSourceRoot =
    std::filesystem::path(__FILE__).parent_path().parent_path().parent_path();
constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;

aerial::Location undated(double latitudeDeg, double dayOfYear) {
    aerial::Location where;
    where.latitudeDeg = latitudeDeg;
    where.dayOfYear = dayOfYear;
    return where;
}

aerial::Location dated(const char* date, double latitudeDeg, double longitudeDeg, double utcOffsetHours) {
    aerial::Location where;
    where.date = date;
    where.latitudeDeg = latitudeDeg;
    where.longitudeDeg = longitudeDeg;
    where.utcOffsetHours = utcOffsetHours;
    where.timeMode = aerial::TimeMode::Clock;
    return where;
}

/// Circular distance between two times of day [h].
double hoursApart(double a, double b) {
    const double d = std::fmod(std::abs(a - b), 24.0);
    return std::min(d, 24.0 - d);
}

}  // namespace

// The undated model's sun (DESIGN "Sun position"): the hour angle H where
// sin(h0) = sin(lat) sin(dec) + cos(lat) cos(dec) cos(H), the event at
// 12 -+ H / 15 deg -- the closed form the scan and bisection must meet.
TEST(SunEvents, UndatedEventsMatchTheClosedForm) {
    struct Event {
        aerial::SunEvent event;
        double elevationDeg;
        double sign;  // -1 before noon, +1 after
    };
    const Event events[] = {
        {aerial::SunEvent::NauticalDawn, -12.0, -1.0}, {aerial::SunEvent::CivilDawn, -6.0, -1.0},
        {aerial::SunEvent::Sunrise, -0.833, -1.0},     {aerial::SunEvent::Sunset, -0.833, 1.0},
        {aerial::SunEvent::CivilDusk, -6.0, 1.0},      {aerial::SunEvent::NauticalDusk, -12.0, 1.0}};
    int checked = 0;
    for (double lat = -60.0; lat <= 60.0; lat += 7.5) {
        for (double day : {1.0, 80.0, 172.0, 264.0, 355.0}) {
            const aerial::Location where = undated(lat, day);
            const double dec = aerial::solarDeclination(day);
            for (const Event& e : events) {
                const double cosH = (std::sin(e.elevationDeg * kDeg) - std::sin(lat * kDeg) * std::sin(dec)) /
                                    (std::cos(lat * kDeg) * std::cos(dec));
                if (std::abs(cosH) >= 0.999) continue;  // no event, or one at the edge of existing
                const double expected = 12.0 + e.sign * std::acos(cosH) / (15.0 * kDeg);
                EXPECT_NEAR(aerial::sunEventHours(where, e.event), expected, 1e-6)
                    << aerial::sunEventName(e.event) << " lat " << lat << " day " << day;
                ++checked;
            }
            EXPECT_EQ(aerial::sunEventHours(where, aerial::SunEvent::Noon), 12.0);
        }
    }
    EXPECT_GT(checked, 400);
}

TEST(SunEvents, NamesRoundTripAndEventsComeInOrder) {
    for (aerial::SunEvent e : aerial::kSunEvents) {
        aerial::SunEvent back = aerial::SunEvent::Noon;
        ASSERT_TRUE(aerial::parseSunEvent(aerial::sunEventName(e), back));
        EXPECT_EQ(back, e);
    }
    aerial::SunEvent untouched = aerial::SunEvent::Noon;
    EXPECT_FALSE(aerial::parseSunEvent("dusk", untouched));
    EXPECT_EQ(untouched, aerial::SunEvent::Noon);
    // kSunEvents is in the order of a day at mid-latitudes, dated or not.
    for (const aerial::Location& where : {undated(45.0, 172.0), dated("2026-12-21", 47.37, 8.54, 1.0)}) {
        double previous = -1.0;
        for (aerial::SunEvent e : aerial::kSunEvents) {
            const double t = aerial::sunEventHours(where, e);
            EXPECT_GT(t, previous) << aerial::sunEventName(e);
            previous = t;
        }
    }
}

// A summer night that never gets nautically dark: as the latitude rises the
// nautical dusk and dawn close in on solar midnight and then stay there --
// continuously, no jump to another hour. Polar night: sunrise is at noon.
TEST(SunEvents, EventsThatDoNotHappenFallWhereTheSunComesClosest) {
    // June solstice: the lowest sun is at lat + 23.44 - 90 deg, so there is
    // no nautical dusk (-12 deg) north of 54.56 N.
    const double day = 172.0;
    double previous = aerial::sunEventHours(undated(55.0, day), aerial::SunEvent::NauticalDusk);
    double worstStep = 0.0;
    for (double lat = 55.0; lat <= 62.0; lat += 0.002) {
        const double t = aerial::sunEventHours(undated(lat, day), aerial::SunEvent::NauticalDusk);
        worstStep = std::max(worstStep, hoursApart(t, previous));
        previous = t;
    }
    // Near the limit the crossing moves as the square root of the missing
    // elevation: 0.002 deg of latitude is ~0.05 h there.
    EXPECT_LT(worstStep, 0.1);
    // At 60 N the lowest sun is -6.56 deg.
    EXPECT_NEAR(hoursApart(aerial::sunEventHours(undated(60.0, day), aerial::SunEvent::NauticalDusk), 0.0),
                0.0, 1e-12);
    EXPECT_NEAR(hoursApart(aerial::sunEventHours(undated(60.0, day), aerial::SunEvent::NauticalDawn), 0.0),
                0.0, 1e-12);
    // Civil dusk still happens at 60 N (lowest -6.56 < -6), just before midnight.
    const double civilDusk = aerial::sunEventHours(undated(60.0, day), aerial::SunEvent::CivilDusk);
    EXPECT_GT(civilDusk, 22.5);
    EXPECT_EQ(aerial::sunEventHours(undated(80.0, 355.0), aerial::SunEvent::Sunrise), 12.0);
    EXPECT_EQ(aerial::sunEventHours(undated(80.0, 355.0), aerial::SunEvent::Sunset), 12.0);
    // Polar day: sunset at solar midnight.
    EXPECT_EQ(aerial::sunEventHours(undated(80.0, 172.0), aerial::SunEvent::Sunset), 0.0);
}

namespace {

// hazy_sunset-like: 47.37 N, a fixed key at noon and one 20 minutes after
// sunset.
const char* kAnchoredPreset = R"({
  "version": 4,
  "location": {"latitude_deg": 47.37, "longitude_deg": 8.54, "utc_offset_h": 2, "date": "2026-06-21",
               "time_mode": "clock"},
  "tracks": [
    {"param": "fog.density_per_m", "interpolation": "linear",
     "keys": [{"time_h": 12, "value": 0.001}, {"anchor": "sunset", "offset_h": 0.25, "value": 0.02}]}
  ]
})";

aerial::Preset load(const std::string& text) {
    const aerial::PresetLoadResult r = aerial::parsePreset(text);
    EXPECT_TRUE(r.ok()) << (r.errors.empty() ? "" : r.errors[0].toString());
    return r.preset ? *r.preset : aerial::Preset{};
}

}  // namespace

TEST(KeyAnchors, ALoadedKeyFollowsTheSunAndIsSavedAsItsAnchor) {
    const aerial::Preset preset = load(kAnchoredPreset);
    ASSERT_EQ(preset.tracks.size(), 1u);
    const aerial::TrackKey& key = preset.tracks[0].keys[1];
    ASSERT_TRUE(key.anchor.has_value());
    EXPECT_EQ(*key.anchor, aerial::SunEvent::Sunset);
    const double sunset = aerial::sunEventHours(preset.environment.location, aerial::SunEvent::Sunset);
    EXPECT_NEAR(key.timeHours, sunset + 0.25, 1e-12);
    // Zurich on the solstice, CEST: sunset 21:26 (almanac, centre at -0.833).
    EXPECT_NEAR(sunset, 21.0 + 26.0 / 60.0, 2.0 / 60.0);

    const std::string json = aerial::presetToJson(preset);
    EXPECT_NE(json.find(R"({"anchor": "sunset", "offset_h": 0.25, "value": 0.02})"), std::string::npos)
        << json;
    const aerial::Preset back = load(json);
    EXPECT_EQ(back.tracks[0].keys[1].anchor, key.anchor);
    EXPECT_EQ(back.tracks[0].keys[1].offsetHours, 0.25);
    EXPECT_EQ(back.tracks[0].keys[1].timeHours, key.timeHours);
}

// The same preset on the winter solstice: the key moves with the sunset
// (4 h 50 min earlier) and the curve reaches its value there.
TEST(KeyAnchors, ANewDateMovesTheKeyWithTheSun) {
    aerial::Preset preset = load(kAnchoredPreset);
    const aerial::CompiledPreset june(preset);
    preset.environment.location.date = "2026-12-21";
    preset.environment.location.utcOffsetHours = 1.0;
    const aerial::CompiledPreset december(preset);
    const double juneKey = june.preset().tracks[0].keys[1].timeHours;
    const double decemberKey = december.preset().tracks[0].keys[1].timeHours;
    EXPECT_NEAR(decemberKey,
                aerial::sunEventHours(preset.environment.location, aerial::SunEvent::Sunset) + 0.25, 1e-12);
    EXPECT_NEAR(juneKey - decemberKey, 21.0 + 26.0 / 60.0 - (16.0 + 38.0 / 60.0), 4.0 / 60.0);
    EXPECT_NEAR(june.evaluate(juneKey).environment.fog.density, 0.02, 1e-12);
    EXPECT_NEAR(december.evaluate(decemberKey).environment.fog.density, 0.02, 1e-12);
    // Half-way between noon and the December key, half-way in value.
    EXPECT_NEAR(december.evaluate(0.5 * (12.0 + decemberKey)).environment.fog.density, 0.0105, 1e-9);
}

// A fixed key at 18:00 and one at sunset - 0:30: in June the anchored key
// comes after it, in December before. Resolving puts the keys in order, so
// the track stays valid and the curve follows.
TEST(KeyAnchors, KeysTakeTheirOrderFromTheResolvedTimes) {
    aerial::Preset preset = load(R"({
  "version": 4,
  "location": {"latitude_deg": 47.37, "longitude_deg": 8.54, "utc_offset_h": 2, "date": "2026-06-21",
               "time_mode": "clock"},
  "tracks": [
    {"param": "fog.density_per_m", "interpolation": "step",
     "keys": [{"time_h": 18, "value": 0.001}, {"anchor": "sunset", "offset_h": -0.5, "value": 0.02}]}
  ]
})");
    EXPECT_FALSE(preset.tracks[0].keys[0].anchor.has_value());
    preset.environment.location.date = "2026-12-21";
    preset.environment.location.utcOffsetHours = 1.0;
    EXPECT_EQ(aerial::resolveKeyAnchors(preset), 1u);
    ASSERT_TRUE(preset.tracks[0].keys[0].anchor.has_value());
    EXPECT_LT(preset.tracks[0].keys[0].timeHours, 18.0);
    EXPECT_TRUE(aerial::validatePreset(preset).empty());
    const aerial::CompiledPreset compiled(preset);
    EXPECT_EQ(compiled.evaluate(17.0).environment.fog.density, 0.02);
    EXPECT_EQ(compiled.evaluate(19.0).environment.fog.density, 0.001);
    EXPECT_EQ(aerial::resolveKeyAnchors(preset), 0u);  // already in place
}

TEST(KeyAnchors, MovingAnAnchoredKeyChangesItsOffsetAndAnchoringKeepsItsTime) {
    const aerial::Location where = dated("2026-06-21", 47.37, 8.54, 2.0);
    const double sunset = aerial::sunEventHours(where, aerial::SunEvent::Sunset);
    aerial::TrackKey key;
    key.timeHours = sunset + 0.5;
    aerial::anchorKey(key, aerial::SunEvent::Sunset, where);
    EXPECT_NEAR(key.offsetHours, 0.5, 1e-12);
    EXPECT_NEAR(aerial::anchoredKeyHours(key, where), key.timeHours, 1e-12);
    aerial::setKeyTime(key, key.timeHours - 1.0);  // dragged an hour earlier
    EXPECT_NEAR(key.offsetHours, -0.5, 1e-12);
    EXPECT_NEAR(aerial::anchoredKeyHours(key, where), key.timeHours, 1e-12);
    // Anchored to noon from 03:00: the offset is taken the short way round.
    key.timeHours = 3.0;
    aerial::anchorKey(key, aerial::SunEvent::Noon, where);
    EXPECT_GE(key.offsetHours, -12.0);
    EXPECT_LE(key.offsetHours, 12.0);
    EXPECT_NEAR(aerial::anchoredKeyHours(key, where), 3.0, 1e-12);
    aerial::anchorKey(key, std::nullopt, where);
    EXPECT_FALSE(key.anchor.has_value());
    EXPECT_EQ(key.offsetHours, 0.0);
    EXPECT_EQ(key.timeHours, 3.0);
}

TEST(KeyAnchors, BadOffsetsAreErrorsNamingTheField) {
    const auto errorsOf = [](const std::string& keys) {
        return aerial::parsePreset(R"({"version": 4, "tracks": [{"param": "fog.density_per_m", "keys": [)" +
                                   keys + "]}]}")
            .errors;
    };
    auto first = errorsOf(R"({"anchor": "sunrise", "offset_h": 13, "value": 0.01})");
    ASSERT_FALSE(first.empty());
    EXPECT_EQ(first[0].pointer, "/tracks/0/keys/0/offset_h");
    EXPECT_NE(first[0].message.find("[-12, 12] h (got 13)"), std::string::npos) << first[0].message;
    first = errorsOf(R"({"time_h": 6, "offset_h": 1, "value": 0.01})");
    ASSERT_FALSE(first.empty());
    EXPECT_EQ(first[0].pointer, "/tracks/0/keys/0/offset_h");
    EXPECT_NE(first[0].message.find("no \"anchor\""), std::string::npos) << first[0].message;
    first = errorsOf(R"({"value": 0.01})");
    ASSERT_FALSE(first.empty());
    EXPECT_EQ(first[0].pointer, "/tracks/0/keys/0/time_h");
    // Two keys of a track on one event: the second names its anchor.
    first = errorsOf(R"({"anchor": "sunset", "value": 0.01}, {"anchor": "sunset", "value": 0.02})");
    ASSERT_FALSE(first.empty());
    EXPECT_EQ(first[0].pointer, "/tracks/0/keys/1/anchor");
    EXPECT_NE(first[0].message.find("(sunset + 00:00)"), std::string::npos) << first[0].message;
}

// Issue 50's repro: an edit 20 s from the key at 19:30 wrote a second key
// there. A file with two keys of a track under a minute apart loads, with a
// warning at the second; across midnight too; a minute apart is fine.
TEST(KeyTimes, KeysUnderAMinuteApartGetAWarning) {
    const auto warningsOf = [](const std::string& keys, bool wrap) {
        const aerial::PresetLoadResult r = aerial::parsePreset(
            R"({"version": 4, "tracks": [{"param": "fog.density_per_m", )" +
            std::string(wrap ? "" : R"("wrap": false, )") + R"("keys": [)" + keys + "]}]}");
        EXPECT_TRUE(r.ok());
        return r.warnings;
    };
    auto w = warningsOf(R"({"time_h": 6, "value": 0.01}, {"time_h": 19.5, "value": 0.0018},
                           {"time_h": 19.505555555555556, "value": 0.003})",
                        true);
    ASSERT_EQ(w.size(), 1u);
    EXPECT_EQ(w[0].pointer, "/tracks/0/keys/2/time_h");
    EXPECT_EQ(w[0].line, 2);
    EXPECT_NE(w[0].message.find("keys at 19:30 and 19:30:20 are 20 s apart"), std::string::npos)
        << w[0].message;
    w = warningsOf(
        R"({"time_h": 0.005, "value": 0.01}, {"time_h": 12, "value": 0.02}, {"time_h": 23.995, "value": 0.0})",
        true);
    ASSERT_EQ(w.size(), 1u);
    EXPECT_EQ(w[0].pointer, "/tracks/0/keys/0/time_h");
    EXPECT_TRUE(
        warningsOf(R"({"time_h": 0.005, "value": 0.01}, {"time_h": 23.995, "value": 0.0})", false).empty());
    EXPECT_TRUE(
        warningsOf(R"({"time_h": 19.5, "value": 0.01}, {"time_h": 19.516666666666667, "value": 0.0})", true)
            .empty());
    // Every shipped preset is free of them.
    for (const char* name : {"clear_summer_day", "desert_dusk", "foggy_valley_morning", "hazy_sunset",
                             "misty_river_farm", "stormy_night"}) {
        const aerial::PresetLoadResult r =
            aerial::loadPreset((kSourceRoot / "presets" / (std::string(name) + ".json")).string());
        ASSERT_TRUE(r.ok()) << name;
        for (const aerial::PresetIssue& i : r.warnings) ADD_FAILURE() << name << ": " << i.toString();
    }
}

// A key's own interpolation in a preset file: read, written back only on the
// keys that have one, refused when unknown.
TEST(KeyTimes, AKeysInterpolationRoundTrips) {
    const aerial::PresetLoadResult r = aerial::parsePreset(
        R"({"version": 4, "tracks": [{"param": "fog.density_per_m", "interpolation": "smooth", "keys": [
            {"time_h": 6, "value": 0.01, "interpolation": "step"}, {"time_h": 12, "value": 0.02},
            {"anchor": "sunset", "value": 0.001, "interpolation": "linear"}]}]})");
    ASSERT_TRUE(r.ok()) << r.errors[0].toString();
    const aerial::Track& track = r.preset->tracks[0];
    EXPECT_EQ(track.keys[0].interpolation, aerial::Interpolation::Step);
    EXPECT_FALSE(track.keys[1].interpolation.has_value());
    EXPECT_EQ(track.keys[2].interpolation, aerial::Interpolation::Linear);
    const std::string json = aerial::presetToJson(*r.preset);
    EXPECT_NE(json.find(R"({"time_h": 6, "value": 0.01, "interpolation": "step"})"), std::string::npos)
        << json;
    EXPECT_NE(json.find(R"({"time_h": 12, "value": 0.02})"), std::string::npos) << json;
    const aerial::PresetLoadResult back = aerial::parsePreset(json);
    ASSERT_TRUE(back.ok());
    EXPECT_EQ(back.preset->tracks[0].keys[2].interpolation, aerial::Interpolation::Linear);
    const aerial::CompiledPreset compiled(*r.preset);
    EXPECT_EQ(compiled.evaluate(9.0).environment.fog.density, 0.01);  // held by the step key
    const auto bad = aerial::parsePreset(
        R"({"version": 4, "tracks": [{"param": "fog.density_per_m", "keys": [{"time_h": 6, "value": 0.01, "interpolation": "cubic"}]}]})");
    ASSERT_FALSE(bad.errors.empty());
    EXPECT_EQ(bad.errors[0].pointer, "/tracks/0/keys/0/interpolation");
    EXPECT_NE(bad.errors[0].message.find("unknown interpolation \"cubic\""), std::string::npos);
}

// A key's own tangents ("tangent_in", "tangent_out", "tangent_mode") load,
// save as written (in the value's shape, only where set) and load back bit
// for bit; the library evaluates them as the Hermite slopes.
TEST(KeyTimes, AKeysTangentsRoundTrip) {
    const aerial::PresetLoadResult r = aerial::parsePreset(
        R"({"version": 5, "tracks": [{"param": "fog.density_per_m", "keys": [
            {"time_h": 0, "value": 0}, {"time_h": 8, "value": 1, "tangent_in": 0.5, "tangent_out": -0.25,
            "tangent_mode": "broken"}, {"time_h": 16, "value": 2}]},
            {"param": "fog.colour_rgb", "keys": [{"time_h": 6, "value": [1, 0.5, 0.25],
            "tangent_in": [0.125, 0, -0.125], "tangent_out": [0.125, 0, -0.125]}, {"time_h": 18, "value": [0.5, 0.5, 0.5]}]}]})");
    ASSERT_TRUE(r.ok()) << r.errors[0].toString();
    const aerial::TrackKey& scalar = r.preset->tracks[0].keys[1];
    ASSERT_TRUE(scalar.tangents.has_value());
    EXPECT_EQ(scalar.tangents->in.x, 0.5);
    EXPECT_EQ(scalar.tangents->out.x, -0.25);
    EXPECT_EQ(scalar.tangents->mode, aerial::TangentMode::Broken);
    const aerial::TrackKey& colour = r.preset->tracks[1].keys[0];
    ASSERT_TRUE(colour.tangents.has_value());
    EXPECT_EQ(colour.tangents->mode, aerial::TangentMode::Unified);  // the default
    EXPECT_EQ(colour.tangents->out, glm::dvec3(0.125, 0.0, -0.125));
    EXPECT_FALSE(r.preset->tracks[0].keys[0].tangents.has_value());
    const std::string json = aerial::presetToJson(*r.preset);
    EXPECT_NE(
        json.find(
            R"({"time_h": 8, "value": 1, "tangent_in": 0.5, "tangent_out": -0.25, "tangent_mode": "broken"})"),
        std::string::npos)
        << json;
    EXPECT_NE(
        json.find(
            R"("tangent_in": [0.125, 0, -0.125], "tangent_out": [0.125, 0, -0.125], "tangent_mode": "unified"})"),
        std::string::npos)
        << json;
    EXPECT_NE(json.find(R"({"time_h": 16, "value": 2})"), std::string::npos) << json;
    const aerial::PresetLoadResult back = aerial::parsePreset(json);
    ASSERT_TRUE(back.ok()) << back.errors[0].toString();
    EXPECT_TRUE(aerial::presetsIdentical(*r.preset, *back.preset));
    aerial::Preset changed = *back.preset;
    changed.tracks[0].keys[1].tangents->out.x = -0.3;
    EXPECT_FALSE(aerial::presetsIdentical(*r.preset, changed));
    // The game's evaluation: 2s^3 - s^2 on 0..8 h (Timeline's closed form), at s = 3/4 0.28125.
    const aerial::CompiledPreset compiled(*r.preset);
    EXPECT_NEAR(compiled.evaluate(6.0).environment.fog.density, 2.0 * 27.0 / 64.0 - 9.0 / 16.0, 1e-15);
}

// Malformed tangents: each error names the field and the reason.
TEST(KeyTimes, BadKeyTangentsAreNamed) {
    struct Case {
        const char* key;
        const char* pointer;
        const char* message;
    };
    const Case cases[] = {
        {R"({"time_h": 6, "value": 0.01, "tangent_in": 0.1})", "/tracks/0/keys/0/tangent_out",
         "missing field \"tangent_out\""},
        {R"({"time_h": 6, "value": 0.01, "tangent_mode": "broken"})", "/tracks/0/keys/0/tangent_mode",
         "\"tangent_mode\" goes with \"tangent_in\" and \"tangent_out\""},
        {R"({"time_h": 6, "value": 0.01, "tangent_in": 0.1, "tangent_out": 0.1, "tangent_mode": "free"})",
         "/tracks/0/keys/0/tangent_mode", "unknown tangent mode \"free\"; expected one of unified, broken"},
        {R"({"time_h": 6, "value": 0.01, "tangent_in": 0.1, "tangent_out": 0.2})",
         "/tracks/0/keys/0/tangent_out",
         "unified tangents have one slope: tangent_in 0.1 and tangent_out 0.2 differ"},
        {R"({"time_h": 6, "value": 0.01, "tangent_in": "up", "tangent_out": 0.2, "tangent_mode": "broken"})",
         "/tracks/0/keys/0/tangent_in", "expected a number"},
        {R"({"time_h": 6, "value": 0.01, "tangent_in": 1e300, "tangent_out": 1e300})",
         "/tracks/0/keys/0/tangent_in",
         "a tangent must be a finite slope of at most 1e+150 per hour (got 1e+300)"},
        {R"({"time_h": 6, "value": 0.01, "flat": true, "tangent_in": 0.1, "tangent_out": 0.1})",
         "/tracks/0/keys/0/flat", "either flat (tangent 0) or has its own tangents, not both"},
    };
    for (const Case& c : cases) {
        const std::string text =
            std::string(R"({"version": 5, "tracks": [{"param": "fog.density_per_m", "keys": [)") + c.key +
            "]}]}";
        const aerial::PresetLoadResult r = aerial::parsePreset(text);
        ASSERT_FALSE(r.errors.empty()) << c.key;
        EXPECT_EQ(r.errors[0].pointer, c.pointer) << c.key;
        EXPECT_NE(r.errors[0].message.find(c.message), std::string::npos)
            << c.key << ": " << r.errors[0].message;
    }
}
