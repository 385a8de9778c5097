// test_limits.cpp — every cap of aerial/limits.hpp: the cap itself is
// accepted (where that is cheap), cap + 1 is a clear error naming the file,
// the field and the limit, and nothing allocates more than the cap allows.
#include "hardening_support.hpp"

#include <aerial/limits.hpp>
#include <aerial/preset.hpp>
#include <aerial/sky.hpp>

#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <vector>

namespace aerial::hardening {
namespace {

std::string firstError(const PresetLoadResult& r) { return r.errors.empty() ? "" : r.errors[0].toString(); }

bool mentionsALimit(const PresetLoadResult& r) {
    for (const PresetIssue& i : r.errors)
        if (i.message.find("limit") != std::string::npos) return true;
    return false;
}

/// {"version": 1, "<key>": [<items>]} with `count` copies of `item`.
std::string arrayPreset(const std::string& key, const std::string& item, std::size_t count,
                        const std::string& extra = "") {
    std::string s = "{\"version\": 1, " + extra + "\"";
    s += key;
    s += "\": [";
    for (std::size_t i = 0; i < count; ++i) {
        if (i) s += ",";
        s += item;
    }
    s += "]}";
    return s;
}

/// `count` objects {"id": "<prefix><i>"}.
std::string idObjects(const std::string& prefix, std::size_t count) {
    std::string s;
    for (std::size_t i = 0; i < count; ++i) {
        if (i) s += ",";
        s += "{\"id\": \"";
        s += prefix;
        s += std::to_string(i);
        s += "\"}";
    }
    return s;
}

TEST(Limits, PresetFileSize) {
    // Exactly the cap: white space around a minimal preset loads.
    std::string atCap = "{\"version\": 1}";
    atCap.append(limits::kMaxPresetFileBytes - atCap.size(), ' ');
    ASSERT_EQ(atCap.size(), limits::kMaxPresetFileBytes);
    EXPECT_TRUE(parsePreset(atCap, "big.json").ok());

    const std::string over = atCap + " ";
    const PresetLoadResult r = parsePreset(over, "big.json");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(firstError(r),
              "big.json: error: the file is 16777217 bytes, over the limit of 16777216 bytes (16 MiB) for a "
              "preset");

    // From disk: loadPreset reads no more than the cap (plus a chunk).
    TempDir dir;
    const fs::path file = dir.path() / "big.json";
    writeFile(file, over);
    EXPECT_EQ(
        firstError(loadPreset(file.string())),
        file.string() +
            ": error: the file is 16777217 bytes, over the limit of 16777216 bytes (16 MiB) for a preset");

    // A device without a size: read up to the cap (and one chunk), no further.
    const PresetLoadResult zero = loadPreset("/dev/zero");
    ASSERT_FALSE(zero.ok());
    EXPECT_NE(firstError(zero).find("/dev/zero: error: the file is at least "), std::string::npos)
        << firstError(zero);
    EXPECT_NE(firstError(zero).find(" bytes, over the limit of 16777216 bytes (16 MiB) for a preset"),
              std::string::npos)
        << firstError(zero);
}

TEST(Limits, JsonNestingDepth) {
    // The root object is level 1: 63 arrays inside it reach the cap of 64.
    auto nested = [](std::size_t levels) {
        return "{\"version\": 1, \"description\": " + std::string(levels, '[') + std::string(levels, ']') +
               "}";
    };
    const PresetLoadResult atCap = parsePreset(nested(limits::kMaxJsonDepth - 1), "deep.json");
    ASSERT_FALSE(atCap.ok());  // a description must be a string, but the depth is fine
    EXPECT_EQ(firstError(atCap), "deep.json:1:31: error: /description: expected a string, got an array");

    const PresetLoadResult over = parsePreset(nested(limits::kMaxJsonDepth), "deep.json");
    EXPECT_EQ(
        firstError(over), std::string("deep.json:1:94: error: /description") + [] {
            std::string zeros;  // the 63 arrays that fit
            for (int i = 0; i < 63; ++i) zeros += "/0";
            return zeros;
        }() + ": nested deeper than 64 levels (the limit)");

    // Far deeper than any stack could take recursively: the same error, fast.
    const PresetLoadResult huge = parsePreset(nested(1'000'000), "deep.json");
    ASSERT_FALSE(huge.ok());
    EXPECT_NE(firstError(huge).find("nested deeper than 64 levels (the limit)"), std::string::npos);
}

TEST(Limits, JsonValueCount) {
    // root + "version" + the array = 3 values; the zeros fill up to the cap.
    const std::size_t fill = limits::kMaxJsonValues - 3;
    const PresetLoadResult atCap = parsePreset(arrayPreset("padding", "0", fill), "many.json");
    EXPECT_TRUE(atCap.ok()) << firstError(atCap);  // an unknown field: a warning only
    ASSERT_EQ(atCap.warnings.size(), 1u);

    const PresetLoadResult over = parsePreset(arrayPreset("padding", "0", fill + 1), "many.json");
    ASSERT_FALSE(over.ok());
    EXPECT_EQ(firstError(over),
              "many.json:1:2097174: error: /padding/1048573: more than 1048576 JSON values (the limit)");
}

TEST(Limits, Volumes) {
    const PresetLoadResult atCap =
        parsePreset("{\"version\": 1, \"volumes\": [" + idObjects("v", limits::kMaxVolumes) + "]}", "v.json");
    EXPECT_TRUE(atCap.ok()) << firstError(atCap);
    EXPECT_EQ(atCap.preset->volumes.size(), limits::kMaxVolumes);

    const PresetLoadResult over = parsePreset(
        "{\"version\": 1, \"volumes\": [" + idObjects("v", limits::kMaxVolumes + 1) + "]}", "v.json");
    ASSERT_FALSE(over.ok());
    EXPECT_EQ(firstError(over), "v.json:1:27: error: /volumes: 1025 volumes, over the limit of 1024");
    EXPECT_EQ(over.errors.size(), 1u);

    // A preset built in code is held to the same cap: validation and saving.
    Preset p;
    p.volumes.resize(limits::kMaxVolumes + 1);
    for (std::size_t i = 0; i < p.volumes.size(); ++i) p.volumes[i].id = "v" + std::to_string(i);
    const std::vector<PresetIssue> issues = validatePreset(p);
    ASSERT_FALSE(issues.empty());
    EXPECT_EQ(issues[0].toString(), "<preset>: error: /volumes: 1025 volumes, over the limit of 1024");
    TempDir dir;
    const SaveResult saved = savePreset(p, (dir.path() / "p.json").string());
    ASSERT_FALSE(saved.ok());
    EXPECT_EQ(saved.errors[0].message, "not saved: 1025 volumes, over the limit of 1024");
    EXPECT_TRUE(listDir(dir.path()).empty());
}

TEST(Limits, Emitters) {
    const PresetLoadResult atCap = parsePreset(
        "{\"version\": 1, \"emitters\": [" + idObjects("e", limits::kMaxEmitters) + "]}", "e.json");
    EXPECT_TRUE(atCap.ok()) << firstError(atCap);
    const PresetLoadResult over = parsePreset(
        "{\"version\": 1, \"emitters\": [" + idObjects("e", limits::kMaxEmitters + 1) + "]}", "e.json");
    EXPECT_EQ(firstError(over), "e.json:1:28: error: /emitters: 1025 emitters, over the limit of 1024");
}

TEST(Limits, Tracks) {
    const std::string track = "{\"param\": \"fog.density_per_m\", \"keys\": [{\"time_h\": 1, \"value\": 0}]}";
    // At the cap the tracks are read (and, all animating the same target,
    // refused as duplicates: that is a different error, not the limit).
    const PresetLoadResult atCap = parsePreset(arrayPreset("tracks", track, limits::kMaxTracks), "t.json");
    ASSERT_FALSE(atCap.ok());
    EXPECT_FALSE(mentionsALimit(atCap)) << firstError(atCap);
    EXPECT_NE(firstError(atCap).find("a second track for the same target"), std::string::npos);
    EXPECT_EQ(atCap.errors.back().message, "3995 more errors not listed (at most 100 are)");

    const PresetLoadResult over = parsePreset(arrayPreset("tracks", track, limits::kMaxTracks + 1), "t.json");
    EXPECT_EQ(firstError(over), "t.json:1:26: error: /tracks: 4097 tracks, over the limit of 4096");
    EXPECT_EQ(over.errors.size(), 1u);
}

TEST(Limits, KeysPerTrack) {
    auto keys = [](std::size_t n) {
        std::string s;
        for (std::size_t i = 0; i < n; ++i) {
            if (i) s += ",";
            char buf[64];
            std::snprintf(buf, sizeof buf, "{\"time_h\": %.17g, \"value\": 0.001}",
                          24.0 * double(i) / double(n));
            s += buf;
        }
        return "{\"version\": 1, \"tracks\": [{\"param\": \"fog.density_per_m\", \"keys\": [" + s + "]}]}";
    };
    const PresetLoadResult atCap = parsePreset(keys(limits::kMaxKeysPerTrack), "k.json");
    EXPECT_TRUE(atCap.ok()) << firstError(atCap);
    EXPECT_EQ(atCap.preset->tracks[0].keys.size(), limits::kMaxKeysPerTrack);
    const PresetLoadResult over = parsePreset(keys(limits::kMaxKeysPerTrack + 1), "k.json");
    EXPECT_EQ(firstError(over), "k.json:1:66: error: /tracks/0/keys: 4097 keys, over the limit of 4096");
}

TEST(Limits, StringLengths) {
    for (const char* field : {"name", "description"}) {
        const std::string atCap = "{\"version\": 1, \"" + std::string(field) + "\": \"" +
                                  std::string(limits::kMaxStringBytes, 'x') + "\"}";
        EXPECT_TRUE(parsePreset(atCap, "s.json").ok()) << field;
        const std::string over = "{\"version\": 1, \"" + std::string(field) + "\": \"" +
                                 std::string(limits::kMaxStringBytes + 1, 'x') + "\"}";
        const PresetLoadResult r = parsePreset(over, "s.json");
        EXPECT_EQ(firstError(r), "s.json:1:" + std::to_string(20 + std::string(field).size()) + ": error: /" +
                                     field + ": is 4097 bytes long, over the limit of 4096");
    }
    // An object's name too.
    const PresetLoadResult r = parsePreset("{\"version\": 1, \"volumes\": [{\"id\": \"a\", \"name\": \"" +
                                               std::string(limits::kMaxStringBytes + 1, 'y') + "\"}]}",
                                           "s.json");
    EXPECT_EQ(firstError(r),
              "s.json:1:48: error: /volumes/0/name: is 4097 bytes long, over the limit of 4096");
    // Ids: 64 bytes is the cap.
    const PresetLoadResult id64 = parsePreset(
        "{\"version\": 1, \"volumes\": [{\"id\": \"" + std::string(limits::kMaxIdBytes, 'i') + "\"}]}",
        "s.json");
    EXPECT_TRUE(id64.ok()) << firstError(id64);
    const PresetLoadResult id65 = parsePreset(
        "{\"version\": 1, \"volumes\": [{\"id\": \"" + std::string(limits::kMaxIdBytes + 1, 'i') + "\"}]}",
        "s.json");
    EXPECT_NE(firstError(id65).find("s.json:1:35: error: /volumes/0/id: an id must be 1..64 characters"),
              std::string::npos)
        << firstError(id65);
}

TEST(Limits, IssuesListed) {
    // 150 unknown fields: 100 warnings listed, then one that counts the rest.
    std::string s = "{\"version\": 1";
    for (int i = 0; i < 150; ++i) {
        s += ", \"unknown";
        s += std::to_string(i);
        s += "\": 0";
    }
    s += "}";
    const PresetLoadResult r = parsePreset(s, "w.json");
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(r.warnings.size(), limits::kMaxPresetIssues + 1);
    EXPECT_EQ(r.warnings.back().toString(), "w.json: warning: 50 more warnings not listed (at most 100 are)");
}

// Files near the size cap built to make a careless loader quadratic: each
// loads (or fails) in well under the time a user would wait.
TEST(Limits, AdversarialFilesLoadInBoundedTime) {
    struct Case {
        const char* what;
        std::string text;
    };
    std::vector<Case> cases;
    {  // 400k objects in an array, each with a duplicate key (pointer per error)
        std::string s = "{\"version\": 1, \"x\": [";
        for (int i = 0; i < 400000; ++i) s += i ? ",{\"a\":1,\"a\":2}" : "{\"a\":1,\"a\":2}";
        cases.push_back({"duplicate keys", s + "]}"});
    }
    {  // 500k unknown fields (a warning each)
        std::string s = "{\"version\": 1";
        for (int i = 0; i < 500000; ++i) {
            s += ",\"u";
            s += std::to_string(i);
            s += "\":0";
        }
        cases.push_back({"unknown fields", s + "}"});
    }
    {  // 1000 volumes, every value out of range (many validation errors)
        std::string s = "{\"version\": 1, \"volumes\": [";
        for (int i = 0; i < 1000; ++i) {
            if (i) s += ",";
            s += "{\"id\":\"v" + std::to_string(i) +
                 "\",\"density_per_m\":-1,\"falloff_per_m\":-1,\"half_extents_m\":[0,0,0],\"position_m\":["
                 "1e9,1e9,1e9]}";
        }
        cases.push_back({"invalid volumes", s + "]}"});
    }
    cases.push_back({"deep nesting", std::string(8u << 20, '[')});
    cases.push_back(
        {"one long string", "{\"version\": 1, \"name\": \"" + std::string(15u << 20, 'n') + "\"}"});
    for (const Case& c : cases) {
        ASSERT_LE(c.text.size(), limits::kMaxPresetFileBytes) << c.what;
        const auto start = std::chrono::steady_clock::now();
        const PresetLoadResult r = parsePreset(c.text, "big.json");
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        EXPECT_LT(seconds, 20.0) << c.what;  // ~0.1-1 s in a release build
        EXPECT_LE(r.errors.size(), limits::kMaxPresetIssues + 1) << c.what;
        EXPECT_LE(r.warnings.size(), limits::kMaxPresetIssues + 1) << c.what;
    }
}

TEST(Limits, SkyTableSizesAreClamped) {
    SkySolverDesc d;
    d.azimuthCount = limits::kMaxSkyAzimuthCount + 1;
    d.elevationCount = 2;
    d.layerCount = limits::kMaxSkyLayerCount + 1;
    d.opticalDepthAngles = limits::kMaxOpticalDepthAngles + 1;
    d.threadCount = 1;
    const SkySolver wide(d);
    EXPECT_EQ(wide.desc().azimuthCount, limits::kMaxSkyAzimuthCount);
    EXPECT_EQ(wide.desc().layerCount, limits::kMaxSkyLayerCount);
    EXPECT_EQ(wide.desc().opticalDepthAngles, limits::kMaxOpticalDepthAngles);

    SkySolverDesc t;
    t.azimuthCount = 4;
    t.elevationCount = 1 << 30;
    t.layerCount = 2;
    t.threadCount = 1;
    const SkySolver tall(t);
    EXPECT_EQ(tall.desc().elevationCount, limits::kMaxSkyElevationCount);

    SkySolverDesc atCap = t;
    atCap.elevationCount = limits::kMaxSkyElevationCount;
    EXPECT_EQ(SkySolver(atCap).desc().elevationCount, limits::kMaxSkyElevationCount);
}

}  // namespace
}  // namespace aerial::hardening
