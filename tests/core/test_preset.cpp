// Presets: JSON round trips bit-exact, the shipped presets load cleanly,
// malformed files give located errors, saving is atomic, and evaluation
// binds tracks by id and uses the sun, atmosphere and emitter models.
#include <aerial/atmosphere.hpp>
#include <aerial/emitter.hpp>
#include <aerial/evaluate.hpp>
#include <aerial/limits.hpp>
#include <aerial/param_table.hpp>
#include <aerial/preset.hpp>
#include <aerial/sun.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include <sys/resource.h>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;

const fs::path kSourceRoot = fs::path(__FILE__).parent_path().parent_path().parent_path();
const fs::path kPresetDir = kSourceRoot / "presets";
const fs::path kFixtureDir = kSourceRoot / "tests" / "data" / "presets";

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

void writeFile(const fs::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
}

std::string joinIssues(const std::vector<aerial::PresetIssue>& issues) {
    std::string s;
    for (const auto& i : issues) s += i.toString() + "\n";
    return s;
}

// A scratch directory per test, removed afterwards.
class TempDir {
public:
    TempDir() {
        std::string tmpl = (fs::temp_directory_path() / "aerial_preset_XXXXXX").string();
        path_ = ::mkdtemp(tmpl.data());
    }
    ~TempDir() {
        std::error_code ec;
        fs::permissions(path_, fs::perms::owner_all, fs::perm_options::add, ec);
        fs::remove_all(path_, ec);
    }
    const fs::path& path() const { return path_; }

private:
    fs::path path_;
};

std::vector<fs::path> shippedPresets() {
    std::vector<fs::path> out;
    for (const auto& entry : fs::directory_iterator(kPresetDir)) {
        const fs::path& p = entry.path();
        if (p.extension() == ".json" && p.filename().string().find("schema") == std::string::npos)
            out.push_back(p);
    }
    std::sort(out.begin(), out.end());
    return out;
}

bool sameBits(double a, double b) {
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

// ---------------------------------------------------------------------------
// Round trips

TEST(Preset, DefaultPresetIsValid) {
    const aerial::Preset p = aerial::defaultPreset();
    EXPECT_TRUE(aerial::validatePreset(p).empty()) << joinIssues(aerial::validatePreset(p));
    EXPECT_FALSE(p.volumes.empty());
    EXPECT_FALSE(p.emitters.empty());
    EXPECT_FALSE(p.tracks.empty());
}

TEST(Preset, AwkwardDoublesRoundTripBitExact) {
    aerial::Preset p = aerial::defaultPreset();
    const double awkward[] = {0.1,
                              1e-7,
                              5.802e-6,
                              1.0 / 3.0,
                              std::nextafter(1.0, 2.0),
                              -0.0,
                              2.0 / 3.0e5,
                              4.440000000000001e-06,
                              9007199.254740993,
                              4503599627370497.0 / 1e9,
                              1e-300,
                              123456.78901234567};
    p.volumes.clear();
    for (std::size_t i = 0; i < std::size(awkward); ++i) {
        aerial::FogVolume v;
        v.id = "v";
        v.id += std::to_string(i);
        v.position = glm::dvec3(awkward[i], -awkward[i] * 1e-3, 0.1 + 0.2);
        v.density = std::min(std::abs(awkward[i]), 10.0);
        p.volumes.push_back(v);
    }
    p.environment.fog.baseHeight = 0.1 + 0.2;  // 0.30000000000000004
    p.environment.atmosphere.mieScattering = glm::dvec3(5.802e-6, 1e-7, 3.996e-6);
    p.environment.atmosphere.mieExtinction = p.environment.atmosphere.mieScattering / 0.9;
    p.tracks.clear();
    ASSERT_TRUE(aerial::validatePreset(p).empty()) << joinIssues(aerial::validatePreset(p));

    const std::string text = aerial::presetToJson(p);
    const aerial::PresetLoadResult r = aerial::parsePreset(text, "awkward.json");
    ASSERT_TRUE(r.ok()) << joinIssues(r.errors);
    EXPECT_TRUE(r.warnings.empty()) << joinIssues(r.warnings);
    for (std::size_t i = 0; i < p.volumes.size(); ++i) {
        for (int c = 0; c < 3; ++c)
            EXPECT_TRUE(sameBits(r.preset->volumes[i].position[c], p.volumes[i].position[c]))
                << i << "," << c << ": " << r.preset->volumes[i].position[c];
        EXPECT_TRUE(sameBits(r.preset->volumes[i].density, p.volumes[i].density)) << i;
    }
    EXPECT_TRUE(sameBits(r.preset->environment.fog.baseHeight, 0.1 + 0.2));
    EXPECT_TRUE(std::signbit(r.preset->volumes[5].position.x)) << "-0.0 keeps its sign";
    EXPECT_TRUE(aerial::presetsIdentical(p, *r.preset));
    // save -> load -> save gives the same text.
    EXPECT_EQ(aerial::presetToJson(*r.preset), text);
}

TEST(Preset, RandomDoublesRoundTripBitExact) {
    std::mt19937_64 rng(2026);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    aerial::Preset p;
    aerial::Track track;
    track.target = aerial::TrackTarget::global("fog.base_height_m");
    for (int i = 0; i < 2000; ++i) {
        // Normal doubles over many decades (denormals excluded), both signs.
        const double magnitude = std::pow(10.0, -300.0 + 305.0 * unit(rng));
        const double v = (unit(rng) < 0.5 ? -1.0 : 1.0) * magnitude;
        track.keys.push_back({24.0 * i / 2000.0, glm::dvec3(v, 0.0, 0.0)});
    }
    p.tracks.push_back(track);
    ASSERT_TRUE(aerial::validatePreset(p).empty()) << joinIssues(aerial::validatePreset(p));
    const aerial::PresetLoadResult r = aerial::parsePreset(aerial::presetToJson(p));
    ASSERT_TRUE(r.ok()) << joinIssues(r.errors);
    ASSERT_EQ(r.preset->tracks.size(), 1u);
    const auto& keys = r.preset->tracks[0].keys;
    ASSERT_EQ(keys.size(), track.keys.size());
    for (std::size_t i = 0; i < keys.size(); ++i) {
        ASSERT_TRUE(sameBits(keys[i].value.x, track.keys[i].value.x)) << track.keys[i].value.x;
        ASSERT_TRUE(sameBits(keys[i].timeHours, track.keys[i].timeHours));
    }
}

TEST(Preset, DefaultPresetSaveLoadSave) {
    const aerial::Preset p = aerial::defaultPreset();
    TempDir dir;
    const fs::path file = dir.path() / "default.json";
    ASSERT_TRUE(aerial::savePreset(p, file.string()).ok());
    const aerial::PresetLoadResult r = aerial::loadPreset(file.string());
    ASSERT_TRUE(r.ok()) << joinIssues(r.errors);
    EXPECT_TRUE(aerial::presetsIdentical(p, *r.preset));
    const fs::path again = dir.path() / "again.json";
    ASSERT_TRUE(aerial::savePreset(*r.preset, again.string()).ok());
    EXPECT_EQ(readFile(file), readFile(again));
    // Only the two files: no temporary file left behind.
    EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator()), 2);
}

TEST(Preset, PresetsIdenticalSeesOneBit) {
    const aerial::Preset a = aerial::defaultPreset();
    aerial::Preset b = a;
    EXPECT_TRUE(aerial::presetsIdentical(a, b));
    b.volumes[0].density = std::nextafter(b.volumes[0].density, 1.0);
    EXPECT_FALSE(aerial::presetsIdentical(a, b));
    b = a;
    b.tracks[0].keys[1].value.x = std::nextafter(b.tracks[0].keys[1].value.x, 1.0);
    EXPECT_FALSE(aerial::presetsIdentical(a, b));
}

TEST(Preset, ViewRoundTripsAndAFileWithoutOneStaysAsItWas) {
    // A preset without a view (every file before views) loads without one
    // and writes no "view": the file comes back byte for byte.
    const aerial::Preset plain = aerial::defaultPreset();
    ASSERT_FALSE(plain.view.has_value());
    const std::string plainText = aerial::presetToJson(plain);
    EXPECT_EQ(plainText.find("\"view\""), std::string::npos);
    const aerial::PresetLoadResult plainBack = aerial::parsePreset(plainText);
    ASSERT_TRUE(plainBack.ok()) << joinIssues(plainBack.errors);
    EXPECT_FALSE(plainBack.preset->view.has_value());
    EXPECT_EQ(aerial::presetToJson(*plainBack.preset), plainText);

    // A view with awkward doubles comes back bit for bit, through a file.
    aerial::Preset framed = plain;
    framed.view = aerial::PresetView{{-61.25, 0.1 + 0.2, 1.0 / 3.0}, {5.0, 18.000000000000004, -90.0}, 47.5};
    TempDir dir;
    const fs::path file = dir.path() / "framed.json";
    ASSERT_TRUE(aerial::savePreset(framed, file.string()).ok());
    const aerial::PresetLoadResult r = aerial::loadPreset(file.string());
    ASSERT_TRUE(r.ok()) << joinIssues(r.errors);
    ASSERT_TRUE(r.preset->view.has_value());
    EXPECT_TRUE(aerial::presetsIdentical(framed, *r.preset));
    EXPECT_EQ(aerial::presetToJson(*r.preset), readFile(file));

    // presetsIdentical sees a view's one bit and its absence.
    aerial::Preset other = framed;
    other.view->verticalFovDeg = std::nextafter(other.view->verticalFovDeg, 90.0);
    EXPECT_FALSE(aerial::presetsIdentical(framed, other));
    EXPECT_FALSE(aerial::presetsIdentical(framed, plain));

    // fov_deg may be left out: the default 60.
    const aerial::PresetLoadResult bare =
        aerial::parsePreset(R"({"version": 5, "view": {"eye_m": [0, 40, 120], "target_m": [0, 10, -200]}})");
    ASSERT_TRUE(bare.ok()) << joinIssues(bare.errors);
    EXPECT_EQ(bare.preset->view->verticalFovDeg, 60.0);
    EXPECT_EQ(bare.preset->view->eye, glm::dvec3(0.0, 40.0, 120.0));
    EXPECT_TRUE(bare.warnings.empty()) << joinIssues(bare.warnings);

    // A view built in code is validated as a file's: savePreset refuses it.
    aerial::Preset bad = plain;
    bad.view = aerial::PresetView{{1.0, 2.0, 3.0}, {1.0, 2.0, 3.0}, std::nan("")};
    const std::vector<aerial::PresetIssue> issues = aerial::validatePreset(bad);
    ASSERT_EQ(issues.size(), 2u) << joinIssues(issues);
    EXPECT_EQ(issues[0].pointer, "/view/fov_deg");
    EXPECT_EQ(issues[0].message, "must be a finite number (got nan)");
    EXPECT_EQ(issues[1].pointer, "/view/target_m");
    EXPECT_FALSE(aerial::savePreset(bad, (dir.path() / "bad.json").string()).ok());
}

// ---------------------------------------------------------------------------
// Shipped presets and the schema

TEST(Preset, ShippedPresetsLoadCleanlyAndAreCanonical) {
    const auto files = shippedPresets();
    ASSERT_GE(files.size(), 5u);
    for (const fs::path& file : files) {
        SCOPED_TRACE(file.string());
        const aerial::PresetLoadResult r = aerial::loadPreset(file.string());
        ASSERT_TRUE(r.ok()) << joinIssues(r.errors);
        EXPECT_TRUE(r.warnings.empty()) << joinIssues(r.warnings);
        // The files are written by savePreset: load -> save gives the file back.
        EXPECT_EQ(aerial::presetToJson(*r.preset), readFile(file));
        // (Named as the file: mesh volumes' paths start at its folder.)
        const aerial::PresetLoadResult again = aerial::parsePreset(aerial::presetToJson(*r.preset), file.string());
        ASSERT_TRUE(again.ok()) << joinIssues(again.errors);
        EXPECT_TRUE(aerial::presetsIdentical(*r.preset, *again.preset));
        // Keyed over the whole day: some track has keys before 06:00 and after 18:00.
        bool wholeDay = false;
        for (const aerial::Track& t : r.preset->tracks)
            wholeDay = wholeDay || (t.keys.front().timeHours < 6.0 && t.keys.back().timeHours > 18.0);
        EXPECT_TRUE(wholeDay);
        EXPECT_GE(r.preset->tracks.size(), 4u);
        EXPECT_FALSE(r.preset->name.empty());
    }
}

TEST(Preset, ShippedPresetsLookDifferent) {
    auto load = [](const char* name) {
        const aerial::PresetLoadResult r = aerial::loadPreset((kPresetDir / name).string());
        EXPECT_TRUE(r.ok()) << name << "\n" << joinIssues(r.errors);
        return r.ok() ? *r.preset : aerial::Preset{};
    };
    const aerial::Preset clear = load("clear_summer_day.json");
    const aerial::Preset hazy = load("hazy_sunset.json");
    const aerial::Preset valley = load("foggy_valley_morning.json");
    const aerial::Preset storm = load("stormy_night.json");
    const aerial::Preset desert = load("desert_dusk.json");
    const double defaultMie = aerial::AtmosphereParams{}.mieScattering.x;

    // Hazy sunset: strong Mie.
    EXPECT_GT(hazy.environment.atmosphere.mieScattering.x, 4.0 * defaultMie);
    // Foggy valley: volumes that are dense at dawn and gone by noon.
    ASSERT_FALSE(valley.volumes.empty());
    const aerial::PresetState dawn = aerial::evaluate(valley, 6.5);
    const aerial::PresetState noon = aerial::evaluate(valley, 12.0);
    for (std::size_t i = 0; i < valley.volumes.size(); ++i) {
        EXPECT_GT(dawn.volumes[i].density, 0.005) << valley.volumes[i].id;
        EXPECT_EQ(noon.volumes[i].density, 0.0) << valley.volumes[i].id;
    }
    // Stormy night: lightning emitters and a moon.
    const auto lightning =
        std::count_if(storm.emitters.begin(), storm.emitters.end(),
                      [](const aerial::Emitter& e) { return e.kind == aerial::EmitterKind::Lightning; });
    EXPECT_GE(lightning, 2);
    EXPECT_GT(storm.environment.moon.intensity, 0.0);
    // Desert dusk: dusty (Mie scattering reddish-brown: more in red than blue, and strong).
    EXPECT_GT(desert.environment.atmosphere.mieScattering.x, desert.environment.atmosphere.mieScattering.z);
    EXPECT_GT(desert.environment.atmosphere.mieScattering.z, 2.0 * defaultMie);
    // Clear day: close to the Earth defaults, little fog.
    EXPECT_LT(clear.environment.atmosphere.mieScattering.x, 2.0 * defaultMie);
    EXPECT_LT(aerial::evaluate(clear, 13.0).environment.fog.density, 1e-3);
}

TEST(Preset, ShippedPresetsEvaluateInRangeAllDay) {
    // Every parameter of every shipped preset, every 10 minutes: finite and
    // inside its table range (tracks are clamped; base values validated).
    for (const fs::path& file : shippedPresets()) {
        SCOPED_TRACE(file.string());
        const aerial::PresetLoadResult r = aerial::loadPreset(file.string());
        ASSERT_TRUE(r.ok()) << joinIssues(r.errors);
        const aerial::CompiledPreset compiled(*r.preset);
        EXPECT_TRUE(compiled.issues().empty()) << joinIssues(compiled.issues());
        aerial::PresetState s;
        for (int i = 0; i < 24 * 6; ++i) {
            compiled.evaluate(i / 6.0, s);
            aerial::Preset snapshot;
            snapshot.environment = s.environment;
            snapshot.volumes = s.volumes;
            snapshot.emitters = s.emitters;
            // Lightning multiplies intensities by a flash in [0, 1]: still in range.
            const auto issues = aerial::validatePreset(snapshot);
            ASSERT_TRUE(issues.empty()) << "t = " << i / 6.0 << "\n" << joinIssues(issues);
            for (const aerial::LightState* light : {&s.sunLight, &s.moonLight}) {
                for (int c = 0; c < 3; ++c) {
                    ASSERT_TRUE(std::isfinite(light->illuminance[c]));
                    ASSERT_GE(light->transmittance[c], 0.0);
                    ASSERT_LE(light->transmittance[c], 1.0);
                }
            }
            for (double flash : s.emitterFlash) {
                ASSERT_GE(flash, 0.0);
                ASSERT_LE(flash, 1.0);
            }
        }
    }
}

TEST(Preset, SchemaFileMatchesTheTable) {
    const std::string shipped = readFile(kPresetDir / "aerial-preset.schema.json");
    EXPECT_EQ(shipped, aerial::presetJsonSchema())
        << "regenerate presets/aerial-preset.schema.json from aerial::presetJsonSchema()";
}

// ---------------------------------------------------------------------------
// Malformed files

struct Fixture {
    const char* file;
    const char* pointer;
    int line;
    int column;
    const char* reason;  // a substring of the message
};

// Positions counted in the fixture files (1-based, the first character of
// the offending value, key or token).
const Fixture kFixtures[] = {
    {"syntax_missing_comma.json", "", 4, 3, "unexpected string literal"},
    {"syntax_truncated.json", "/fog", 4, 1, "unexpected end of input"},
    {"syntax_bad_literal.json", "/fog/density_per_m", 3, 28, "invalid literal"},
    {"infinite.json", "/atmosphere/mie/scale_height_m", 4, 31, "overflow"},
    {"out_of_range.json", "/volumes/1/half_extents_m/1", 5, 40, "out of range: -3"},
    {"wrong_type.json", "/fog/density_per_m", 4, 22, "expected a number, got a string"},
    {"duplicate_ids.json", "/volumes/2/id", 6, 12, "duplicate id \"mist\""},
    {"unknown_target.json", "/tracks/1/volume", 6, 16, "no volume with id \"nope\""},
    {"unknown_param.json", "/tracks/0/param", 4, 15, "unknown global parameter \"fog.thickness\""},
    {"newer_version.json", "/version", 2, 14, "newer than this library reads"},
    {"missing_version.json", "/version", 1, 1, "missing \"version\""},
    {"bad_key_times.json", "/tracks/0/keys/1/time_h", 5, 54, "increase strictly"},
    {"key_time_24.json", "/tracks/0/keys/0/time_h", 4, 52, "[0, 24)"},
    {"not_animatable.json", "/tracks/0/param", 4, 15, "cannot be animated"},
    {"duplicate_json_key.json", "/fog/density_per_m", 3, 34, "duplicate key"},
    {"missing_id.json", "/emitters/1/id", 5, 5, "missing required field \"id\""},
    {"bad_enum.json", "/volumes/0/shape", 3, 36, "unknown value \"sphere\""},
    {"wrong_arity.json", "/sun/colour_rgb", 3, 25, "array of 3 numbers"},
    {"mie_extinction_below_scattering.json", "/atmosphere/mie/extinction_per_m/1", 6, 37, "must be >="},
    {"not_an_object.json", "", 1, 1, "expected an object"},
    {"bad_track_value.json", "/tracks/0/keys/0/value", 4, 65, "array of 3 numbers"},
    {"volume_edge_softness_out_of_range.json", "/volumes/0/edge_softness", 4, 53,
     "out of range: 1.5 is not in 0..1"},
    {"cloud_coverage_out_of_range.json", "/clouds/coverage", 3, 26, "out of range: 1.5 is not in 0..1"},
    {"cloud_thickness_zero.json", "/clouds/thickness_m", 4, 29, "out of range: 0 is not in 10..20000 m"},
    {"cloud_negative_density.json", "/clouds/density_per_m", 3, 31, "out of range: -0.01 is not in 0..1 1/m"},
    {"cloud_wind_arity.json", "/clouds/wind_m_per_s", 3, 30,
     "expected an array of 2 numbers, got an array of 3"},
    {"cloud_volume_zero_extent.json", "/cloud_volumes/0/half_extents_m/1", 5, 61,
     "out of range: 0 is not in 1..1e+07 m"},
    {"cloud_volume_unknown_target.json", "/tracks/1/cloud_volume", 6, 22, "no cloud volume with id \"nope\""},
    {"cloud_volume_duplicate_ids.json", "/cloud_volumes/2/id", 6, 12, "duplicate id \"cell\""},
    {"date_not_a_day.json", "/location/date", 3, 44,
     "location.date must be a calendar date \"YYYY-MM-DD\" from 1800-01-01 to 2200-12-31, or \"\" for none "
     "(got \"2026-02-30\")"},
    {"time_mode_unknown.json", "/location/time_mode", 3, 51, "unknown value \"local\""},
    {"anchor_and_time.json", "/tracks/0/keys/1/anchor", 5, 72, "either \"time_h\" (a fixed time) or \"anchor\""},
    {"anchor_unknown.json", "/tracks/0/keys/1/anchor", 5, 56, "unknown sun event \"dusk\"; expected one of sunrise"},    {"weather_unknown_param.json", "/weather/states/0/overrides/0/param", 4, 15, "unknown global parameter \"clouds.nope\""},
    {"weather_not_animatable.json", "/weather/states/0/overrides/0/param", 4, 15, "does not change with the weather"},
    {"weather_two_modes.json", "/weather/states/0/overrides/0/scale", 4, 58, "an override has one of \"set\", \"add\", \"scale\", not several"},
    {"weather_duplicate_name.json", "/weather/states/1/name", 5, 14, "a second weather state named \"storm\""},
    {"weather_out_of_range.json", "/weather/states/0/overrides/0/set", 4, 41, "out of range: 1.5 is not in 0..1"},
    {"weather_unknown_volume.json", "/weather/states/0/overrides/0/volume", 4, 16, "no volume with id \"nope\""},
    {"weather_region_unknown_state.json", "/weather/regions/0/state", 4, 82, "no weather state \"fog\" (the preset has none, storm)"},
    {"weather_region_bad_shape.json", "/weather/regions/0/shape", 4, 30, "unknown value \"cylinder\"; expected one of box, ellipsoid"},
};

TEST(Preset, MalformedFilesGiveLocatedErrors) {
    for (const Fixture& f : kFixtures) {
        SCOPED_TRACE(f.file);
        const fs::path path = kFixtureDir / f.file;
        ASSERT_TRUE(fs::exists(path));
        const aerial::PresetLoadResult r = aerial::loadPreset(path.string());
        EXPECT_FALSE(r.ok());
        EXPECT_FALSE(r.preset.has_value()) << "never half-loaded";
        ASSERT_FALSE(r.errors.empty());
        const auto it = std::find_if(r.errors.begin(), r.errors.end(),
                                     [&](const aerial::PresetIssue& e) { return e.pointer == f.pointer; });
        ASSERT_NE(it, r.errors.end()) << "no error at " << f.pointer << "; got:\n" << joinIssues(r.errors);
        EXPECT_EQ(it->file, path.string());
        EXPECT_EQ(it->line, f.line) << it->toString();
        EXPECT_EQ(it->column, f.column) << it->toString();
        EXPECT_NE(it->message.find(f.reason), std::string::npos) << it->toString();
        EXPECT_EQ(it->severity, aerial::PresetIssue::Severity::Error);
        // The one-line form names file, position, pointer and reason.
        const std::string line = it->toString();
        EXPECT_NE(line.find(path.string() + ":" + std::to_string(f.line) + ":" + std::to_string(f.column)),
                  std::string::npos)
            << line;
    }
}

TEST(Preset, SecondOutOfRangeValueInTrackReported) {
    const aerial::PresetLoadResult r = aerial::loadPreset((kFixtureDir / "bad_track_value.json").string());
    ASSERT_FALSE(r.ok());
    const auto it = std::find_if(r.errors.begin(), r.errors.end(), [](const aerial::PresetIssue& e) {
        return e.pointer == "/tracks/1/keys/0/value";
    });
    ASSERT_NE(it, r.errors.end()) << joinIssues(r.errors);
    EXPECT_EQ(it->line, 5);
    EXPECT_EQ(it->column, 68);
    EXPECT_NE(it->message.find("out of range"), std::string::npos);
}

TEST(Preset, UnknownFieldsAreWarnings) {
    const fs::path path = kFixtureDir / "unknown_field.json";
    const aerial::PresetLoadResult r = aerial::loadPreset(path.string());
    ASSERT_TRUE(r.ok()) << joinIssues(r.errors);
    ASSERT_EQ(r.warnings.size(), 2u) << joinIssues(r.warnings);
    EXPECT_EQ(r.warnings[0].pointer, "/fog/colour");
    EXPECT_EQ(r.warnings[0].line, 3);
    EXPECT_EQ(r.warnings[0].column, 34);
    EXPECT_EQ(r.warnings[0].severity, aerial::PresetIssue::Severity::Warning);
    EXPECT_EQ(r.warnings[1].pointer, "/sky");
    EXPECT_EQ(r.preset->environment.fog.density, 0.01);
}

TEST(Preset, MissingFileIsAnError) {
    const aerial::PresetLoadResult r = aerial::loadPreset("/nonexistent/dir/none.json");
    ASSERT_FALSE(r.ok());
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_EQ(r.errors[0].file, "/nonexistent/dir/none.json");
    EXPECT_NE(r.errors[0].message.find("cannot open"), std::string::npos);
}

// A version-1 location block (no date, longitude, offset or time mode)
// loads as the undated model: the sun of day_of_year in solar time, exactly
// as before the dated model existed.
TEST(Preset, VersionOneLocationStaysUndated) {
    const aerial::PresetLoadResult r = aerial::parsePreset(
        R"({"version": 1, "location": {"latitude_deg": 38, "day_of_year": 225, "moon_phase_offset_days": 8}})");
    ASSERT_TRUE(r.ok()) << joinIssues(r.errors);
    const aerial::Location& where = r.preset->environment.location;
    EXPECT_TRUE(where.date.empty());
    EXPECT_EQ(where.timeMode, aerial::TimeMode::Solar);
    EXPECT_EQ(where.longitudeDeg, 0.0);
    EXPECT_EQ(where.utcOffsetHours, 0.0);
    const double dec = aerial::solarDeclination(225.0);
    const double lat = 38.0 * 3.14159265358979323846 / 180.0;
    EXPECT_DOUBLE_EQ(aerial::sunPosition(where, 12.0).elevation,
                     std::asin(std::sin(lat) * std::sin(dec) + std::cos(lat) * std::cos(dec)));
    // A dated file round-trips its new fields.
    const aerial::PresetLoadResult d = aerial::parsePreset(
        R"({"version": 1, "location": {"longitude_deg": 8.5, "utc_offset_h": 2, "date": "2026-06-21",
            "time_mode": "clock"}})");
    ASSERT_TRUE(d.ok()) << joinIssues(d.errors);
    EXPECT_EQ(d.preset->environment.location.date, "2026-06-21");
    EXPECT_EQ(d.preset->environment.location.timeMode, aerial::TimeMode::Clock);
    const aerial::PresetLoadResult again = aerial::parsePreset(aerial::presetToJson(*d.preset));
    ASSERT_TRUE(again.ok());
    EXPECT_TRUE(aerial::presetsIdentical(*again.preset, *d.preset));
}

TEST(Preset, MissingFieldsTakeTableDefaults) {
    const aerial::PresetLoadResult r = aerial::parsePreset(R"({"version": 1, "volumes": [{"id": "v"}]})");
    ASSERT_TRUE(r.ok()) << joinIssues(r.errors);
    const aerial::FogVolume defaults;
    EXPECT_EQ(r.preset->volumes[0].density, defaults.density);
    EXPECT_EQ(r.preset->volumes[0].halfExtents, defaults.halfExtents);
    EXPECT_EQ(r.preset->environment.sun.intensity, aerial::kDefaultSunIntensity);
    EXPECT_EQ(r.preset->environment.moon.intensity, aerial::kDefaultMoonIntensity);
}

// Version 1 kept the moon 1000x brighter than the physical moon; loading it
// gives version 2's physical values (the intensity and every key of its
// track), a moon the file leaves out the physical default, and a version-2
// file is read as written.
TEST(Preset, VersionOneMoonIsMadePhysical) {
    const char* v1 = R"({"version": 1, "moon": {"intensity": 0.05},
        "tracks": [{"param": "moon.intensity", "keys": [{"time_h": 1, "value": 0.04}, {"time_h": 5, "value": 0.08}]}]})";
    const aerial::PresetLoadResult r = aerial::parsePreset(v1);
    ASSERT_TRUE(r.ok()) << joinIssues(r.errors);
    EXPECT_DOUBLE_EQ(r.preset->environment.moon.intensity, 5e-5);
    ASSERT_EQ(r.preset->tracks.size(), 1u);
    EXPECT_DOUBLE_EQ(r.preset->tracks[0].keys[0].value.x, 4e-5);
    EXPECT_DOUBLE_EQ(r.preset->tracks[0].keys[1].value.x, 8e-5);
    // 0.25 lx at full phase above the atmosphere: Aerial's unit is 5000 lx.
    EXPECT_NEAR(aerial::kDefaultMoonIntensity * 5000.0, 0.25, 1e-12);
    const aerial::PresetLoadResult unset = aerial::parsePreset(R"({"version": 1})");
    ASSERT_TRUE(unset.ok());
    EXPECT_EQ(unset.preset->environment.moon.intensity, aerial::kDefaultMoonIntensity);
    const aerial::PresetLoadResult v2 = aerial::parsePreset(R"({"version": 2, "moon": {"intensity": 0.05}})");
    ASSERT_TRUE(v2.ok());
    EXPECT_EQ(v2.preset->environment.moon.intensity, 0.05);
    const aerial::PresetLoadResult newer =
        aerial::parsePreset("{\"version\": " + std::to_string(aerial::kPresetVersion + 1) + "}");
    EXPECT_FALSE(newer.ok());
}

TEST(Preset, MangledInputNeverCrashes) {
    // Truncations and byte flips of a valid preset: the loader returns a
    // preset or errors, never crashes, and never a preset with errors.
    const std::string text = aerial::presetToJson(aerial::defaultPreset());
    std::mt19937 rng(99);
    for (int i = 0; i < 400; ++i) {
        std::string mangled = text;
        if (i % 2 == 0) {
            mangled.resize(rng() % text.size());
        } else {
            for (int k = 0; k < 3; ++k) mangled[rng() % mangled.size()] = char(rng() % 256);
        }
        const aerial::PresetLoadResult r = aerial::parsePreset(mangled, "mangled.json");
        EXPECT_EQ(r.ok(), r.errors.empty());
        for (const auto& e : r.errors) EXPECT_FALSE(e.message.empty());
    }
}

TEST(Preset, ValidateNamesPointersForCodeBuiltPresets) {
    aerial::Preset p = aerial::defaultPreset();
    p.volumes[0].density = std::nan("");
    p.emitters[0].id = "bad id!";
    p.volumes[0].gradientDirection = glm::dvec3(0.0, 2.0, 0.0);
    const auto issues = aerial::validatePreset(p);
    auto has = [&](const char* pointer) {
        return std::any_of(issues.begin(), issues.end(),
                           [&](const aerial::PresetIssue& i) { return i.pointer == pointer; });
    };
    EXPECT_TRUE(has("/volumes/0/density_per_m")) << joinIssues(issues);
    EXPECT_TRUE(has("/emitters/0/id")) << joinIssues(issues);
    EXPECT_TRUE(has("/volumes/0/gradient_direction")) << joinIssues(issues);
    for (const auto& i : issues) EXPECT_EQ(i.line, 0);
}

// ---------------------------------------------------------------------------
// Atomic save

TEST(PresetSave, MissingDirectoryFailsWithReason) {
    const aerial::SaveResult r = aerial::savePreset(aerial::defaultPreset(), "/nonexistent/dir/x.json");
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.errors[0].message.find("No such file or directory"), std::string::npos)
        << r.errors[0].toString();
}

TEST(PresetSave, FailedWriteLeavesOldFileIntact) {
    TempDir dir;
    const fs::path file = dir.path() / "scene.json";
    const std::string old = "old contents, not even JSON\n";
    writeFile(file, old);

    aerial::Preset big = aerial::defaultPreset();
    for (int i = 0; i < 200; ++i) {
        aerial::FogVolume v;
        v.id = "v";
        v.id += std::to_string(i);
        big.volumes.push_back(v);
    }
    // Make the write fail half-way: a file size limit (works as root too).
    std::signal(SIGXFSZ, SIG_IGN);
    rlimit saved{};
    ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &saved), 0);
    rlimit small = saved;
    small.rlim_cur = 4096;
    ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &small), 0);
    const aerial::SaveResult r = aerial::savePreset(big, file.string());
    ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &saved), 0);

    ASSERT_FALSE(r.ok());
    EXPECT_EQ(
        r.errors[0].message.rfind("not saved: cannot write " + (dir.path() / ".scene.json.tmp-").string(), 0),
        0u)
        << r.errors[0].toString();
    EXPECT_NE(r.errors[0].message.find(": File too large"), std::string::npos) << r.errors[0].toString();
    EXPECT_EQ(readFile(file), old);
    EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator()), 1)
        << "the temporary file is removed";
}

TEST(PresetSave, ReadOnlyDirectoryLeavesOldFileIntact) {
    if (::geteuid() == 0)
        GTEST_SKIP() << "root ignores directory permissions (covered by the size-limit test)";
    TempDir dir;
    const fs::path file = dir.path() / "scene.json";
    writeFile(file, "old\n");
    fs::permissions(dir.path(), fs::perms::owner_read | fs::perms::owner_exec);
    const aerial::SaveResult r = aerial::savePreset(aerial::defaultPreset(), file.string());
    fs::permissions(dir.path(), fs::perms::owner_all);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.errors[0].message.find("Permission denied"), std::string::npos) << r.errors[0].toString();
    EXPECT_EQ(readFile(file), "old\n");
}

TEST(PresetSave, InvalidPresetIsNotWritten) {
    TempDir dir;
    const fs::path file = dir.path() / "scene.json";
    writeFile(file, "old\n");
    aerial::Preset p = aerial::defaultPreset();
    p.environment.fog.density = INFINITY;
    const aerial::SaveResult r = aerial::savePreset(p, file.string());
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.errors[0].pointer, "/fog/density_per_m");
    EXPECT_EQ(readFile(file), "old\n");
}

TEST(PresetSave, ReplacesAndKeepsPermissions) {
    TempDir dir;
    const fs::path file = dir.path() / "scene.json";
    writeFile(file, "old\n");
    fs::permissions(file, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
    ASSERT_TRUE(aerial::savePreset(aerial::defaultPreset(), file.string()).ok());
    EXPECT_EQ(readFile(file), aerial::presetToJson(aerial::defaultPreset()));
    EXPECT_EQ(fs::status(file).permissions() & fs::perms::all,
              fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
}

// ---------------------------------------------------------------------------
// Evaluation

aerial::Preset twoVolumePreset() {
    aerial::Preset p;
    aerial::FogVolume a, b;
    a.id = "alpha";
    a.name = "Alpha";
    a.density = 0.1;
    b.id = "beta";
    b.name = "Beta";
    b.density = 0.2;
    p.volumes = {a, b};
    aerial::Track ta;
    ta.target = aerial::TrackTarget::volume("alpha", "density_per_m");
    ta.interpolation = aerial::Interpolation::Linear;
    ta.keys = {{0.0, glm::dvec3(0.0)}, {12.0, glm::dvec3(1.2, 0, 0)}};
    aerial::Track tb;
    tb.target = aerial::TrackTarget::volume("beta", "colour_rgb");
    tb.interpolation = aerial::Interpolation::Step;
    tb.keys = {{6.0, glm::dvec3(1.0, 0.0, 0.0)}, {18.0, glm::dvec3(0.0, 0.0, 1.0)}};
    p.tracks = {ta, tb};
    return p;
}

TEST(Evaluate, TracksSurviveReorderAndRename) {
    const aerial::Preset p = twoVolumePreset();
    aerial::Preset q = p;
    std::reverse(q.volumes.begin(), q.volumes.end());
    q.volumes[0].name = "Renamed beta";
    q.volumes[1].name = "Renamed alpha";
    std::reverse(q.tracks.begin(), q.tracks.end());
    ASSERT_TRUE(aerial::validatePreset(q).empty());
    // Through the file as well.
    const aerial::PresetLoadResult r = aerial::parsePreset(aerial::presetToJson(q));
    ASSERT_TRUE(r.ok()) << joinIssues(r.errors);

    for (double t : {3.0, 9.0, 20.0}) {
        const aerial::PresetState s = aerial::evaluate(p, t);
        const aerial::PresetState u = aerial::evaluate(*r.preset, t);
        EXPECT_EQ(u.volumes[1].id, "alpha");
        // Linear 0 -> 1.2 from 00:00 to 12:00, back to 0 at 24:00.
        const double expected = t <= 12.0 ? t * 0.1 : 1.2 * (24.0 - t) / 12.0;
        EXPECT_NEAR(s.volumes[0].density, expected, 1e-12) << t;
        EXPECT_EQ(u.volumes[1].density, s.volumes[0].density) << t;
        EXPECT_EQ(u.volumes[0].colour, s.volumes[1].colour) << t;
        EXPECT_EQ(u.volumes[0].name, "Renamed beta");
    }
    EXPECT_EQ(aerial::evaluate(p, 9.0).volumes[1].colour, glm::dvec3(1.0, 0.0, 0.0));
    EXPECT_EQ(aerial::evaluate(p, 3.0).volumes[1].colour, glm::dvec3(0.0, 0.0, 1.0));
}

TEST(Evaluate, SunMoonAndTransmittanceFollowTheModels) {
    aerial::Preset p = aerial::defaultPreset();
    p.environment.location.moonPhaseOffsetDays = 10.0;
    p.environment.sun.colour = glm::dvec3(1.0, 0.9, 0.8);
    const aerial::CompiledPreset compiled(p);
    EXPECT_TRUE(compiled.issues().empty()) << joinIssues(compiled.issues());
    for (double t = 0.0; t < 24.0; t += 0.37) {
        const aerial::PresetState s = compiled.evaluate(t);
        const aerial::CelestialBody sun = aerial::sunPosition(p.environment.location, t);
        const aerial::CelestialBody moon = aerial::moonPosition(p.environment.location, t);
        EXPECT_EQ(s.sunLight.body.direction, sun.direction);
        EXPECT_EQ(s.moonLight.body.direction, moon.direction);
        const aerial::AtmosphereParams& air = s.environment.atmosphere;
        const glm::dvec3 tSun = aerial::transmittanceToSpace(air, air.viewerHeight, sun.direction.y);
        const glm::dvec3 tMoon = aerial::transmittanceToSpace(air, air.viewerHeight, moon.direction.y);
        const glm::dvec3 tZenith = aerial::transmittanceToSpace(air, air.viewerHeight, 1.0);
        for (int c = 0; c < 3; ++c) {
            // Tabulated optical depths: within 5e-4 of the direct quadrature.
            EXPECT_NEAR(s.sunLight.transmittance[c], tSun[c], 5e-4) << "t " << t;
            EXPECT_NEAR(s.moonLight.transmittance[c], tMoon[c], 5e-4) << "t " << t;
            EXPECT_NEAR(s.zenithTransmittance[c], tZenith[c], 5e-4) << "t " << t;
        }
        const glm::dvec3 eSun = p.environment.sun.colour * p.environment.sun.intensity;
        EXPECT_EQ(s.sunLight.illuminanceSpace, eSun);
        EXPECT_EQ(s.sunLight.illuminance, eSun * s.sunLight.transmittance);
        EXPECT_EQ(s.moonLight.illuminanceSpace,
                  p.environment.moon.colour * p.environment.moon.intensity * moon.phaseIrradiance);
    }
}

TEST(Evaluate, HazyAtmosphereTransmittanceMatchesDirect) {
    aerial::Preset p;
    p.environment.atmosphere.mieScattering = glm::dvec3(8e-5, 6e-5, 4e-5);
    p.environment.atmosphere.mieExtinction = glm::dvec3(1e-4, 8e-5, 6e-5);
    p.environment.atmosphere.viewerHeight = 1500.0;
    const aerial::CompiledPreset compiled(p);
    for (double t = 3.0; t < 21.0; t += 0.05) {
        const aerial::PresetState s = compiled.evaluate(t);
        const aerial::AtmosphereParams& air = s.environment.atmosphere;
        const glm::dvec3 direct =
            aerial::transmittanceToSpace(air, air.viewerHeight, s.sunLight.body.direction.y);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(s.sunLight.transmittance[c], direct[c], 5e-4) << t;
    }
}

TEST(Evaluate, AnimatedScaleHeightUsesDirectTransmittance) {
    aerial::Preset p;
    aerial::Track t;
    t.target = aerial::TrackTarget::global("atmosphere.mie.scale_height_m");
    t.keys = {{6.0, glm::dvec3(800.0, 0, 0)}, {15.0, glm::dvec3(2500.0, 0, 0)}};
    p.tracks = {t};
    const aerial::PresetState s = aerial::evaluate(p, 10.0);
    const aerial::AtmosphereParams& air = s.environment.atmosphere;
    EXPECT_GT(air.mieScaleHeight, 800.0);
    EXPECT_LT(air.mieScaleHeight, 2500.0);
    EXPECT_EQ(s.sunLight.transmittance,
              aerial::transmittanceToSpace(air, air.viewerHeight, s.sunLight.body.direction.y));
}

TEST(Evaluate, LightningFlashIsApplied) {
    aerial::Preset p;
    aerial::Emitter bolt;
    bolt.id = "bolt";
    bolt.kind = aerial::EmitterKind::Lightning;
    bolt.intensityCd = 5.0;
    bolt.flashesPerMinute = 30.0;
    aerial::Emitter lamp;
    lamp.id = "lamp";
    lamp.intensityCd = 2.0;
    p.emitters = {bolt, lamp};
    const aerial::CompiledPreset compiled(p);
    aerial::PresetState s;
    int lit = 0;
    for (int i = 0; i < 2000; ++i) {
        const double t = 22.0 + i * 0.001;
        compiled.evaluate(t, s);
        const double flash = aerial::lightningFlash(bolt, s.timeHours);
        EXPECT_EQ(s.emitterFlash[0], flash);
        EXPECT_EQ(s.emitters[0].intensityCd, 5.0 * flash);
        EXPECT_EQ(s.emitterFlash[1], 1.0);
        EXPECT_EQ(s.emitters[1].intensityCd, 2.0);
        lit += flash > 0.0;
    }
    EXPECT_GT(lit, 0) << "30 flashes per minute of flash clock must flash within 2 h of game time";
}

TEST(Evaluate, ClampsAnimatedValuesAndKeepsExtinctionAboveScattering) {
    aerial::Preset p;
    aerial::Track t;
    t.target = aerial::TrackTarget::global("atmosphere.mie.scattering_per_m");
    t.interpolation = aerial::Interpolation::Linear;
    t.keys = {{0.0, glm::dvec3(1e-5)}, {12.0, glm::dvec3(1e-4)}};
    p.tracks = {t};
    const aerial::PresetState s = aerial::evaluate(p, 12.0);
    EXPECT_EQ(s.environment.atmosphere.mieScattering, glm::dvec3(1e-4));
    EXPECT_EQ(s.environment.atmosphere.mieExtinction, glm::dvec3(1e-4));
}

TEST(Preset, TracksThatHoldTheirEndsRoundTripAndBadWrapIsRefused) {
    aerial::Preset p;
    aerial::Track t;
    t.target = aerial::TrackTarget::global("fog.density_per_m");
    t.keys = {{6.0, glm::dvec3(0.02)}, {10.0, glm::dvec3(0.0)}};
    t.wrap = false;
    p.tracks = {t};
    const std::string text = aerial::presetToJson(p);
    EXPECT_NE(text.find("\"wrap\": false"), std::string::npos);
    aerial::PresetLoadResult back = aerial::parsePreset(text);
    ASSERT_TRUE(back.ok());
    ASSERT_EQ(back.preset->tracks.size(), 1u);
    EXPECT_FALSE(back.preset->tracks[0].wrap);
    EXPECT_EQ(back.preset->tracks[0].keys.size(), 2u);
    EXPECT_EQ(aerial::evaluate(*back.preset, 3.0).environment.fog.density, 0.02);  // held, not wrapped
    // A cyclic track (the default) writes no "wrap" at all: old files stay as they are.
    p.tracks[0].wrap = true;
    EXPECT_EQ(aerial::presetToJson(p).find("\"wrap\""), std::string::npos);
    // Not a boolean: refused with the pointer and the reason.
    std::string bad = text;
    const std::string wrapFalse = "\"wrap\": false";
    bad.replace(bad.find(wrapFalse), wrapFalse.size(), "\"wrap\": \"no\"");
    const aerial::PresetLoadResult refused = aerial::parsePreset(bad, "bad.json");
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.errors[0].pointer, "/tracks/0/wrap");
    EXPECT_NE(refused.errors[0].message.find("wrap must be true"), std::string::npos);
}

TEST(Preset, FlatKeysRoundTripAndBadFlatIsRefused) {
    aerial::Preset p;
    aerial::Track t;
    t.target = aerial::TrackTarget::global("fog.density_per_m");
    t.keys = {{6.0, glm::dvec3(0.0)}, {12.0, glm::dvec3(0.02), true}, {18.0, glm::dvec3(0.01)}};
    p.tracks = {t};
    const std::string text = aerial::presetToJson(p);
    EXPECT_NE(text.find("\"flat\": true"), std::string::npos);
    aerial::PresetLoadResult back = aerial::parsePreset(text);
    ASSERT_TRUE(back.ok());
    ASSERT_EQ(back.preset->tracks[0].keys.size(), 3u);
    EXPECT_FALSE(back.preset->tracks[0].keys[0].flat);
    EXPECT_TRUE(back.preset->tracks[0].keys[1].flat);
    // The flag is part of a preset's identity (undo records it).
    aerial::Preset level = *back.preset;
    EXPECT_TRUE(aerial::presetsIdentical(level, *back.preset));
    level.tracks[0].keys[1].flat = false;
    EXPECT_FALSE(aerial::presetsIdentical(level, *back.preset));
    // No flat key: no "flat" in the file.
    EXPECT_EQ(aerial::presetToJson(level).find("\"flat\""), std::string::npos);
    std::string bad = text;
    const std::string flatTrue = "\"flat\": true";
    bad.replace(bad.find(flatTrue), flatTrue.size(), "\"flat\": 1");
    const aerial::PresetLoadResult refused = aerial::parsePreset(bad, "bad.json");
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.errors[0].pointer, "/tracks/0/keys/1/flat");
}

TEST(Evaluate, ReusesTheCallersStateWithoutReallocating) {
    const aerial::CompiledPreset compiled(aerial::defaultPreset());
    aerial::PresetState s;
    compiled.evaluate(5.0, s);
    const void* volumes = s.volumes.data();
    const void* emitters = s.emitters.data();
    const void* id = s.volumes[0].id.data();
    compiled.evaluate(6.0, s);
    EXPECT_EQ(s.volumes.data(), volumes);
    EXPECT_EQ(s.emitters.data(), emitters);
    EXPECT_EQ(s.volumes[0].id.data(), id);
    EXPECT_EQ(s.timeHours, 6.0);
}

TEST(Evaluate, BrokenTracksAreSkippedAndReported) {
    aerial::Preset p = twoVolumePreset();
    p.tracks[0].target.objectId = "gone";
    const aerial::CompiledPreset compiled(p);
    ASSERT_FALSE(compiled.issues().empty());
    EXPECT_EQ(compiled.issues()[0].pointer, "/tracks/0/volume");
    const aerial::PresetState s = compiled.evaluate(9.0);
    EXPECT_EQ(s.volumes[0].density, 0.1);                       // untouched base value
    EXPECT_EQ(s.volumes[1].colour, glm::dvec3(1.0, 0.0, 0.0));  // the good track still runs
}

TEST(Evaluate, ChangingAnIdRetargetsTracksAndRemovingDropsThem) {
    aerial::Preset p = twoVolumePreset();
    ASSERT_TRUE(aerial::changeObjectId(p, aerial::ParamScope::Volume, "alpha", "alpha_2"));
    EXPECT_EQ(p.volumes[0].id, "alpha_2");
    EXPECT_NE(aerial::findTrack(p, aerial::TrackTarget::volume("alpha_2", "density_per_m")), nullptr);
    EXPECT_TRUE(aerial::validatePreset(p).empty()) << joinIssues(aerial::validatePreset(p));
    EXPECT_NEAR(aerial::evaluate(p, 9.0).volumes[0].density, 0.9, 1e-12);
    // Taken, malformed or unknown ids change nothing.
    EXPECT_FALSE(aerial::changeObjectId(p, aerial::ParamScope::Volume, "alpha_2", "beta"));
    EXPECT_FALSE(aerial::changeObjectId(p, aerial::ParamScope::Volume, "alpha_2", "has space"));
    EXPECT_FALSE(aerial::changeObjectId(p, aerial::ParamScope::Volume, "nope", "fresh"));
    EXPECT_EQ(p.volumes[0].id, "alpha_2");

    ASSERT_TRUE(aerial::removeObject(p, aerial::ParamScope::Volume, "alpha_2"));
    ASSERT_EQ(p.volumes.size(), 1u);
    ASSERT_EQ(p.tracks.size(), 1u);
    EXPECT_EQ(p.tracks[0].target.objectId, "beta");
    EXPECT_TRUE(aerial::validatePreset(p).empty());
}

// ---------------------------------------------------------------------------
// Cloud volumes

// A layer of coverage 0.2, a storm cell (coverage 0.9) keyed to drift along
// +X over the day and a clear hole (box, coverage 0) at a fixed place.
aerial::Preset cloudVolumePreset() {
    aerial::Preset p;
    p.environment.clouds.coverage = 0.2;
    aerial::CloudVolume storm;
    storm.id = "storm";
    storm.name = "Storm cell";
    storm.position = glm::dvec3(0.1 + 0.2, 2500.0, -1.0 / 3.0);
    storm.halfExtents = glm::dvec3(4000.0, 1500.0, 1e-3 + 4000.0);
    storm.coverage = 0.9;
    storm.edgeSoftness = 0.25;
    aerial::CloudVolume hole;
    hole.id = "hole";
    hole.shape = aerial::FogVolumeShape::Box;
    hole.position = glm::dvec3(-30000.0, 2500.0, 5000.0);
    hole.rotation = glm::normalize(glm::dquat(0.9, 0.0, 0.3, 0.0));
    hole.coverage = 0.0;
    hole.edgeSoftness = 0.0;
    p.cloudVolumes = {storm, hole};
    aerial::Track move;
    move.target = aerial::TrackTarget::cloudVolume("storm", "position_m");
    move.interpolation = aerial::Interpolation::Linear;
    move.keys = {{6.0, glm::dvec3(0.0, 2500.0, 0.0)}, {18.0, glm::dvec3(24000.0, 2500.0, 0.0)}};
    aerial::Track grow;
    grow.target = aerial::TrackTarget::cloudVolume("storm", "coverage");
    grow.interpolation = aerial::Interpolation::Step;
    grow.keys = {{0.0, glm::dvec3(0.9, 0.0, 0.0)}, {20.0, glm::dvec3(1.0 / 3.0, 0.0, 0.0)}};
    p.tracks = {move, grow};
    return p;
}

TEST(CloudVolumes, RoundTripBitExactWithTracks) {
    const aerial::Preset p = cloudVolumePreset();
    ASSERT_TRUE(aerial::validatePreset(p).empty()) << joinIssues(aerial::validatePreset(p));
    const std::string text = aerial::presetToJson(p);
    // Canonical place: after "emitters", before "tracks"; tracks name it by "cloud_volume".
    const std::size_t emitters = text.find("\"emitters\"");
    const std::size_t cloudVolumes = text.find("\"cloud_volumes\"");
    const std::size_t tracks = text.find("\"tracks\"");
    ASSERT_NE(cloudVolumes, std::string::npos) << text;
    EXPECT_LT(emitters, cloudVolumes);
    EXPECT_LT(cloudVolumes, tracks);
    EXPECT_NE(text.find("\"cloud_volume\": \"storm\""), std::string::npos) << text;

    const aerial::PresetLoadResult r = aerial::parsePreset(text, "clouds.json");
    ASSERT_TRUE(r.ok()) << joinIssues(r.errors);
    EXPECT_TRUE(r.warnings.empty()) << joinIssues(r.warnings);
    ASSERT_EQ(r.preset->cloudVolumes.size(), 2u);
    EXPECT_TRUE(aerial::presetsIdentical(p, *r.preset));
    EXPECT_TRUE(sameBits(r.preset->cloudVolumes[0].position.x, 0.1 + 0.2));
    EXPECT_TRUE(sameBits(r.preset->cloudVolumes[0].position.z, -1.0 / 3.0));
    EXPECT_EQ(r.preset->cloudVolumes[1].shape, aerial::FogVolumeShape::Box);
    EXPECT_EQ(r.preset->tracks[0].target, aerial::TrackTarget::cloudVolume("storm", "position_m"));
    EXPECT_EQ(aerial::presetToJson(*r.preset), text);

    // presetsIdentical sees one bit of a cloud volume.
    aerial::Preset q = p;
    q.cloudVolumes[1].edgeSoftness = std::nextafter(0.0, 1.0);
    EXPECT_FALSE(aerial::presetsIdentical(p, q));
    q = p;
    q.cloudVolumes.pop_back();
    EXPECT_FALSE(aerial::presetsIdentical(p, q));
}

TEST(CloudVolumes, MissingFieldsTakeTheStructDefaults) {
    const aerial::PresetLoadResult r =
        aerial::parsePreset(R"({"version": 1, "cloud_volumes": [{"id": "c"}]})");
    ASSERT_TRUE(r.ok()) << joinIssues(r.errors);
    const aerial::CloudVolume defaults;
    const aerial::CloudVolume& c = r.preset->cloudVolumes.at(0);
    EXPECT_EQ(c.shape, aerial::FogVolumeShape::Ellipsoid);
    EXPECT_EQ(c.position, defaults.position);
    EXPECT_EQ(c.halfExtents, defaults.halfExtents);
    EXPECT_EQ(c.coverage, defaults.coverage);
    EXPECT_EQ(c.edgeSoftness, defaults.edgeSoftness);
    // Without cloud volumes the canonical text still lists the (empty) array.
    EXPECT_NE(aerial::presetToJson(aerial::Preset{}).find("\"cloud_volumes\": []"), std::string::npos);
}

TEST(CloudVolumes, ValidationNamesTheField) {
    auto has = [](const std::vector<aerial::PresetIssue>& issues, const char* pointer, const char* reason) {
        return std::any_of(issues.begin(), issues.end(), [&](const aerial::PresetIssue& i) {
            return i.pointer == pointer && i.message.find(reason) != std::string::npos;
        });
    };
    aerial::Preset p = cloudVolumePreset();
    p.cloudVolumes[1].id = "storm";
    p.cloudVolumes[0].halfExtents.y = 0.0;
    p.cloudVolumes[0].coverage = 1.5;
    p.cloudVolumes[1].rotation = glm::dquat(2.0, 0.0, 0.0, 0.0);
    p.tracks[1].target.objectId = "nope";
    const auto issues = aerial::validatePreset(p);
    EXPECT_TRUE(has(issues, "/cloud_volumes/1/id", "duplicate id \"storm\"")) << joinIssues(issues);
    EXPECT_TRUE(has(issues, "/cloud_volumes/0/half_extents_m/1", "out of range: 0 is not in 1..1e+07 m"))
        << joinIssues(issues);
    EXPECT_TRUE(has(issues, "/cloud_volumes/0/coverage", "out of range: 1.5")) << joinIssues(issues);
    EXPECT_TRUE(has(issues, "/cloud_volumes/1/rotation_xyzw", "unit quaternion")) << joinIssues(issues);
    EXPECT_TRUE(has(issues, "/tracks/1/cloud_volume", "no cloud volume with id \"nope\""))
        << joinIssues(issues);

    // Over the cap: refused, naming the limit (in code and in a file).
    aerial::Preset many;
    for (std::size_t i = 0; i <= aerial::limits::kMaxCloudVolumes; ++i) {
        aerial::CloudVolume c;
        c.id = std::to_string(i);  // (not "c" + ...: GCC 12 warns falsely, -Wrestrict)
        many.cloudVolumes.push_back(c);
    }
    EXPECT_TRUE(
        has(aerial::validatePreset(many), "/cloud_volumes", "65 cloud volumes, over the limit of 64"));
    const aerial::PresetLoadResult r = aerial::parsePreset(aerial::presetToJson(many), "many.json");
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(has(r.errors, "/cloud_volumes", "over the limit of 64")) << joinIssues(r.errors);
    many.cloudVolumes.pop_back();
    EXPECT_TRUE(aerial::validatePreset(many).empty());
}

TEST(CloudVolumes, ATrackNamesOneObject) {
    const aerial::PresetLoadResult r = aerial::parsePreset(R"({"version": 1,
  "volumes": [{"id": "a"}], "cloud_volumes": [{"id": "a"}],
  "tracks": [{"volume": "a", "cloud_volume": "a", "param": "position_m", "keys": [{"time_h": 1, "value": [0, 0, 0]}]}]})");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.errors[0].pointer, "/tracks/0/cloud_volume") << joinIssues(r.errors);
    EXPECT_NE(r.errors[0].message.find("not several"), std::string::npos) << joinIssues(r.errors);
}

TEST(CloudVolumes, EvaluateMovesAKeyedVolumeAndPrepareCloudsUsesIt) {
    const aerial::CompiledPreset compiled(cloudVolumePreset());
    ASSERT_TRUE(compiled.issues().empty()) << joinIssues(compiled.issues());
    const aerial::PresetState noon = compiled.evaluate(12.0);
    ASSERT_EQ(noon.cloudVolumes.size(), 2u);
    // Linear 0 -> 24000 m from 06:00 to 18:00: halfway at noon.
    EXPECT_NEAR(noon.cloudVolumes[0].position.x, 12000.0, 1e-9);
    EXPECT_EQ(noon.cloudVolumes[0].coverage, 0.9);
    EXPECT_EQ(noon.cloudVolumes[1].position, compiled.preset().cloudVolumes[1].position);

    const aerial::CloudField clouds = aerial::prepareClouds(noon);
    ASSERT_EQ(clouds.volumes.size(), 2u);
    // The storm's centre (weight 1 inside the soft edge) has its coverage;
    // where it stood at 06:00 (now 12 km away, outside it) the layer's.
    EXPECT_DOUBLE_EQ(aerial::cloudCoverageAt(clouds, {12000.0, 2500.0, 0.0}), 0.9);
    EXPECT_DOUBLE_EQ(aerial::cloudCoverageAt(clouds, {0.0, 2500.0, 0.0}), 0.2);
    // The hole clears its box; its hard edge (softness 0) is clear right up to it.
    EXPECT_EQ(aerial::cloudCoverageAt(clouds, {-30000.0, 2500.0, 5000.0}), 0.0);
    // Half-way through the storm's soft edge: between the two.
    const double edge = aerial::cloudCoverageAt(clouds, {12000.0 + 4000.0 * (1.0 - 0.125), 2500.0, 0.0});
    EXPECT_GT(edge, 0.2);
    EXPECT_LT(edge, 0.9);

    // Step-keyed coverage after 20:00.
    const aerial::PresetState night = compiled.evaluate(21.0);
    EXPECT_EQ(night.cloudVolumes[0].coverage, 1.0 / 3.0);
    const aerial::CloudField later = aerial::prepareClouds(night);
    const glm::dvec3 centre = night.cloudVolumes[0].position;
    EXPECT_DOUBLE_EQ(aerial::cloudCoverageAt(later, centre), 1.0 / 3.0);
}

TEST(CloudVolumes, ChangingAnIdRetargetsTracksAndRemovingDropsThem) {
    aerial::Preset p = cloudVolumePreset();
    ASSERT_TRUE(aerial::changeObjectId(p, aerial::ParamScope::CloudVolume, "storm", "cell"));
    EXPECT_EQ(p.cloudVolumes[0].id, "cell");
    EXPECT_NE(aerial::findTrack(p, aerial::TrackTarget::cloudVolume("cell", "coverage")), nullptr);
    EXPECT_FALSE(aerial::changeObjectId(p, aerial::ParamScope::CloudVolume, "cell", "hole"));
    EXPECT_TRUE(aerial::validatePreset(p).empty()) << joinIssues(aerial::validatePreset(p));
    ASSERT_TRUE(aerial::removeObject(p, aerial::ParamScope::CloudVolume, "cell"));
    EXPECT_EQ(p.cloudVolumes.size(), 1u);
    EXPECT_TRUE(p.tracks.empty());
    EXPECT_FALSE(aerial::removeObject(p, aerial::ParamScope::CloudVolume, "cell"));
}

}  // namespace

TEST(FogVolumes, EdgeSoftnessRoundTripsAndIsLeftOutAtItsDefault) {
    aerial::Preset p;
    aerial::FogVolume hard;
    hard.id = "hard";
    aerial::FogVolume soft;
    soft.id = "soft";
    soft.edgeSoftness = 0.1 + 0.2;  // not a short decimal
    p.volumes = {hard, soft};
    aerial::Track track;
    track.target = aerial::TrackTarget::volume("soft", "edge_softness");
    track.keys = {{6.0, glm::dvec3(0.25, 0.0, 0.0)}, {18.0, glm::dvec3(1.0, 0.0, 0.0)}};
    p.tracks.push_back(track);
    ASSERT_TRUE(aerial::validatePreset(p).empty()) << joinIssues(aerial::validatePreset(p));
    const std::string text = aerial::presetToJson(p);
    // Written once (the soft volume), absent for the hard one: old presets
    // save as they were.
    const std::size_t first = text.find("\"edge_softness\": ");
    ASSERT_NE(first, std::string::npos) << text;
    EXPECT_EQ(text.find("\"edge_softness\": ", first + 1), std::string::npos) << text;
    EXPECT_NE(text.find("\"param\": \"edge_softness\""), std::string::npos) << text;  // keyable
    const aerial::PresetLoadResult r = aerial::parsePreset(text, "soft.json");
    ASSERT_TRUE(r.ok()) << joinIssues(r.errors);
    EXPECT_TRUE(aerial::presetsIdentical(p, *r.preset));
    EXPECT_TRUE(sameBits(r.preset->volumes[1].edgeSoftness, 0.1 + 0.2));
    EXPECT_TRUE(sameBits(r.preset->volumes[0].edgeSoftness, 0.0));
    EXPECT_EQ(aerial::presetToJson(*r.preset), text);
    aerial::Preset q = p;
    q.volumes[1].edgeSoftness = std::nextafter(0.1 + 0.2, 1.0);
    EXPECT_FALSE(aerial::presetsIdentical(p, q));
}
