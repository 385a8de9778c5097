// print_preset_schema.cpp — writes aerial::presetJsonSchema() to stdout:
// the generator behind presets/aerial-preset.schema.json
// (scripts/update_schema.sh; test_preset's SchemaFileMatchesTheTable fails
// when the file and the table drift apart).
#include <aerial/preset.hpp>

#include <cstdio>
#include <string>

int main() {
    const std::string schema = aerial::presetJsonSchema();
    return std::fwrite(schema.data(), 1, schema.size(), stdout) == schema.size() ? 0 : 1;
}
