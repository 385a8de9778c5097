// shipped_preset.hpp — a preset of presets/ loaded for a test (needs the
// target's AERIAL_SOURCE_DIR definition). A file that does not load fails
// the calling test and gives the default Preset.
#pragma once

#include <aerial/preset.hpp>

#include <gtest/gtest.h>

#include <string>

namespace aerial::test {

/// presets/<file> (with its extension, e.g. "clear_summer_day.json").
inline Preset loadShippedPreset(const std::string& file) {
    const PresetLoadResult r = loadPreset(std::string(AERIAL_SOURCE_DIR) + "/presets/" + file);
    EXPECT_TRUE(r.ok()) << file;
    return r.ok() && r.preset ? *r.preset : Preset{};
}

}  // namespace aerial::test
