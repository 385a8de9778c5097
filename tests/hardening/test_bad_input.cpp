// test_bad_input.cpp — a table of malformed inputs (tests/data/bad_inputs/,
// written by make_bad_inputs.py there), each with the exact error it must
// produce: the file, the position and JSON pointer (presets) or the glTF
// element, and the reason. Loading never crashes, never throws and never
// returns a half-loaded preset or scene.
//
// Presets: the first error's toString() is "FILE" + the expected text.
// glTF: GltfLoadResult::error is "FILE" + the expected text.
#include "hardening_support.hpp"

#include <aerial/preset.hpp>
#ifdef AERIAL_HAVE_RENDERER
#include <aerial/renderer/gltf.hpp>
#endif

#include <gtest/gtest.h>

#include <cctype>
#include <ostream>
#include <set>
#include <string>

namespace aerial::hardening {
namespace {

struct BadInput {
    const char* file;      ///< under tests/data/bad_inputs/presets or /gltf
    const char* expected;  ///< the error after the file's path
};

// gtest names the case by this (instead of its bytes).
void PrintTo(const BadInput& c, std::ostream* os) { *os << c.file; }

std::string caseName(const char* file) {
    std::string name;
    for (const char* c = file; *c; ++c) name += std::isalnum(static_cast<unsigned char>(*c)) ? *c : '_';
    return name;
}

// ---------------------------------------------------------------------------
// Presets

const BadInput kBadPresets[] = {
    {"anchor_offset_out_of_range.json",
     ":5:52: error: /tracks/0/keys/0/offset_h: an offset from a sun event must be in [-12, 12] h (got -13)"},
    {"binary_garbage.bin", ":2:91: error: a NUL byte: a preset is UTF-8 JSON text, not binary data"},
    {"bom_only.json",
     ":1:2: error: syntax error while parsing value - unexpected end of input; expected '[', '{', or a "
     "literal"},
    {"colour_is_string.json", ":5:19: error: /sun/colour_rgb: expected an array of 3 numbers, got a string"},
    {"colour_key_wrong_arity.json",
     ":10:20: error: /tracks/0/keys/0/value: expected an array of 3 numbers, got an array of 2"},
    {"comment.json", ":1:1: error: syntax error while parsing value - invalid literal; last read: '/'"},
    {"dangling_track_emitter.json", ":6:18: error: /tracks/0/emitter: no emitter with id \"lamp\""},
    {"dangling_track_volume.json", ":29:17: error: /tracks/0/volume: no volume with id \"valley\""},
    {"deep_nesting.json",
     ":1:94: error: "
     "/description/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/"
     "0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0/0: nested deeper than 64 levels (the limit)"},
    {"duplicate_json_key.json", ":1:29: error: /name: duplicate key \"name\""},
    {"duplicate_volume_ids.json", ":27:13: error: /volumes/1/id: duplicate id \"fog\" (also /volumes/0)"},
    {"empty.json",
     ":1:1: error: syntax error while parsing value - unexpected end of input; expected '[', '{', or a "
     "literal"},
    {"fractional_seed.json", ":13:15: error: /emitters/0/seed: expected an integer, got a number"},
    {"huge_integer_seed.json",
     ":13:15: error: /emitters/0/seed: out of range: 1e+23 is not in 0..4294967295"},
    {"huge_negative_number.json", ":1:41: error: /fog/base_height_m: number overflow parsing '-1e999'"},
    {"huge_number.json", ":1:41: error: /fog/density_per_m: number overflow parsing '1e400'"},
    {"id_bad_characters.json",
     ":6:13: error: /volumes/0/id: an id must be 1..64 characters of A-Z a-z 0-9 _ - . (got \"my fog/1\")"},
    {"id_missing.json", ":5:5: error: /volumes/0/id: missing required field \"id\""},
    {"id_too_long.json",
     ":6:13: error: /volumes/0/id: an id must be 1..64 characters of A-Z a-z 0-9 _ - . (got "
     "\"vvvvvvvvvvvvvvvvvvvvvvvvvvvvvvvvvvvvvvvvvvvvvvvvvvvvvvvvvvvvvvvvv\")"},
    {"invalid_utf8_name.json",
     ":1:24: error: /name: syntax error while parsing value - invalid string: ill-formed UTF-8 byte; last "
     "read: '\"caf\\xE9\"'"},
    {"key_time_negative.json",
     ":9:21: error: /tracks/0/keys/0/time_h: a key's time must be in [0, 24) h (got -1)"},
    {"keys_not_increasing.json",
     ":13:21: error: /tracks/0/keys/1/time_h: key times must increase strictly (6 after 8)"},
    {"latitude_out_of_range.json",
     ":5:21: error: /location/latitude_deg: out of range: 91 is not in -90..90 deg"},
    {"mesh_degenerate_triangle.json",
     ":25:15: error: /volumes/0/mesh: mesh volume \"room\": ../meshes/degenerate_triangle.gltf: triangle 12 "
     "is "
     "degenerate (zero area) at (-1, -1, -1)"},
    {"mesh_flipped_triangle.json",
     ":25:15: error: /volumes/0/mesh: mesh volume \"room\": ../meshes/flipped_triangle.gltf: flipped "
     "triangle 1: "
     "the edge between (1, -1, -1) and (1, 1, 1) runs the same way in both its triangles (the mesh is not "
     "consistently oriented)"},
    {"mesh_index_count_overflow.json",
     ":25:15: error: /volumes/0/mesh: mesh volume \"room\": ../meshes/index_count_overflow.gltf: "
     "accessors[1]: "
     "count 4611686018427387905 is over the limit of 16777216"},
    {"mesh_inside_out.json",
     ":25:15: error: /volumes/0/mesh: mesh volume \"room\": ../meshes/inside_out.gltf: the triangles face "
     "inwards (enclosed volume -8.000000 < 0); flip the normals so they point out of the fog"},
    {"mesh_lines.json",
     ":25:15: error: /volumes/0/mesh: mesh volume \"room\": ../meshes/lines.gltf: meshes[0].primitives[0]: "
     "mode "
     "1; a fog mesh is made of triangles (mode 4)"},
    {"mesh_missing_file.json",
     ":25:15: error: /volumes/0/mesh: mesh volume \"room\": ../meshes/no_such_mesh.gltf: no such file (a "
     "relative path starts at the preset's folder)"},
    {"mesh_non_manifold.json",
     ":25:15: error: /volumes/0/mesh: mesh volume \"room\": ../meshes/non_manifold.gltf: non-manifold edge "
     "between (1, -1, -1) and (1, 1, -1) (shared by 4 triangles; a fog mesh is a closed surface)"},
    {"mesh_not_gltf.json",
     ":25:15: error: /volumes/0/mesh: mesh volume \"room\": ../meshes/not_gltf.gltf: not a valid glTF 2.0 "
     "file: "
     "[json.exception.parse_error.101] parse error at line 1, column 2: syntax error while parsing value - "
     "invalid literal; last read: 'th'"},
    {"mesh_open_edge.json",
     ":25:15: error: /volumes/0/mesh: mesh volume \"room\": ../meshes/open_edge.gltf: open edge between (-1, "
     "-1, "
     "-1) and (1, -1, -1) (triangle 6; a fog mesh must be closed)"},
    {"mesh_unknown_blend.json",
     ":25:16: error: /volumes/0/blend: unknown value \"multiply\"; expected one of add, subtract"},
    {"mesh_without_file.json",
     ":25:15: error: /volumes/0/mesh: a mesh volume needs \"mesh\": the glTF file of its closed mesh"},
    {"mesh_zero_rotation.json",
     ":25:15: error: /volumes/0/mesh: mesh volume \"room\": ../meshes/zero_rotation.gltf: nodes[0]: rotation "
     "is "
     "not a unit quaternion"},
    {"mie_extinction_below_scattering.json",
     ":13:9: error: /atmosphere/mie/extinction_per_m/1: Mie extinction 1e-06 must be >= Mie scattering "
     "4e-06"},
    {"name_too_long.json", ":3:11: error: /name: is 4097 bytes long, over the limit of 4096"},
    {"nan_literal.json",
     ":1:41: error: /fog/density_per_m: syntax error while parsing value - invalid literal; last read: "
     "'\"density_per_m\": N'"},
    {"negative_density.json",
     ":24:24: error: /volumes/0/density_per_m: out of range: -0.5 is not in 0..10 1/m"},
    {"negative_half_extent.json",
     ":22:9: error: /volumes/0/half_extents_m/2: out of range: -3 is not in 0.001..1e+07 m"},
    {"not_animatable_track.json",
     ":6:16: error: /tracks/0/param: parameter \"location.latitude_deg\" cannot be animated"},
    {"nul_byte.json", ":1:15: error: a NUL byte: a preset is UTF-8 JSON text, not binary data"},
    {"position_two_numbers.json",
     ":8:21: error: /volumes/0/position_m: expected an array of 3 numbers, got an array of 2"},
    {"region_bad_shape.json",
     ":14:18: error: /weather/regions/0/shape: unknown value \"cone\"; expected one of box, ellipsoid"},
    {"region_duplicate_id.json",
     ":29:15: error: /weather/regions/1/id: duplicate id \"ridge_storm\" (also /weather/regions/0)"},
    {"region_fractional_priority.json",
     ":27:21: error: /weather/regions/0/priority: expected an integer, got a number"},
    {"region_huge_number.json", ":2:43: error: /weather/regions/0/blend_m: number overflow parsing '1e400'"},
    {"region_missing_state.json", ":12:7: error: /weather/regions/0/state: missing required field \"state\""},
    {"region_negative_blend.json",
     ":25:20: error: /weather/regions/0/blend_m: out of range: -50 is not in 0..1e+07 m"},
    {"region_negative_size.json",
     ":21:11: error: /weather/regions/0/half_extents_m/0: out of range: -3000 is not in 1..1e+07 m"},
    {"region_unknown_state.json",
     ":26:18: error: /weather/regions/0/state: no weather state \"hail\" (the preset has none, storm)"},
    {"region_zero_size.json",
     ":22:11: error: /weather/regions/0/half_extents_m/1: out of range: 0 is not in 1..1e+07 m"},
    {"root_array.json", ":1:1: error: expected an object, got an array"},
    {"root_string.json", ":1:1: error: expected an object, got a string"},
    {"single_quotes.json",
     ":1:2: error: syntax error while parsing object key - invalid literal; last read: '{''; expected string "
     "literal"},
    {"tangents_unified_differ.json",
     ":5:80: error: /tracks/0/keys/0/tangent_out: unified tangents have one slope: tangent_in 0.002 and "
     "tangent_out 0.004 differ (\"tangent_mode\": \"broken\" for two)"},
    {"track_without_keys.json", ":7:15: error: /tracks/0/keys: a track needs at least one key"},
    {"trailing_comma.json",
     ":1:28: error: syntax error while parsing object key - unexpected '}'; expected string literal"},
    {"trailing_garbage.json",
     ":2:1: error: syntax error while parsing value - invalid literal; last read: '1}<U+000A>e'; expected "
     "end of input"},
    {"truncated_object.json",
     ":3:28: error: /fog/density_per_m: syntax error while parsing value - invalid number; expected digit "
     "after '.'; last read: '0.'"},
    {"truncated_string.json",
     ":1:24: error: /name: syntax error while parsing value - invalid string: missing closing quote; last "
     "read: '\"unterminated'"},
    {"unknown_shape.json",
     ":7:16: error: /volumes/0/shape: unknown value \"cylinder\"; expected one of box, ellipsoid, mesh"},
    {"unknown_track_param.json", ":6:16: error: /tracks/0/param: unknown global parameter \"fog.thickness\""},
    {"utf16_bom.json", ":1:1: error: UTF-16 text (byte order mark); a preset is UTF-8 JSON"},
    {"version_fraction.json", ":2:14: error: /version: expected an integer, got a number"},
    {"version_missing.json",
     ":1:1: error: /version: missing \"version\" (this library reads versions 1 to 5)"},
    {"version_newer.json",
     ":2:14: error: /version: preset version 7 is newer than this library reads (5); update Aerial to load "
     "it"},
    {"version_string.json", ":2:14: error: /version: expected an integer, got a string"},
    {"version_zero.json", ":2:14: error: /version: unsupported version 0"},
    {"view_eye_two_numbers.json", ":5:14: error: /view/eye_m: expected an array of 3 numbers, got an array of 2"},
    {"view_far_away.json", ":8:7: error: /view/eye_m/2: out of range: 2e+07 is not in -1e+07..1e+07 m"},
    {"view_fov_out_of_range.json", ":15:16: error: /view/fov_deg: out of range: 180 is not in 1..179 deg"},
    {"view_missing_target.json", ":4:11: error: /view/target_m: missing required field \"target_m\""},
    {"view_not_object.json", ":4:11: error: /view: expected an object, got an array"},
    {"view_same_point.json",
     ":10:17: error: /view/target_m: the target is 0 m from the eye; a view needs a direction (at least 0.01 m "
     "apart)"},
    {"volume_not_object.json", ":5:5: error: /volumes/0: expected an object, got a number"},
    {"volumes_not_array.json", ":4:14: error: /volumes: expected an array, got an object"},
    {"whitespace_only.json",
     ":3:1: error: syntax error while parsing value - unexpected end of input; expected '[', '{', or a "
     "literal"},
    {"zero_gradient.json",
     ":25:29: error: /volumes/0/gradient_direction: must be a unit vector; a zero vector has no direction"},
    {"zero_half_extent.json",
     ":21:9: error: /volumes/0/half_extents_m/1: out of range: 0 is not in 0.001..1e+07 m"},
    {"zero_quaternion.json",
     ":13:24: error: /volumes/0/rotation_xyzw: must be a unit quaternion; a zero vector has no direction"},
};

class BadPreset : public ::testing::TestWithParam<BadInput> {};

TEST_P(BadPreset, GivesItsExactError) {
    const BadInput& c = GetParam();
    const fs::path path = kBadInputs / "presets" / c.file;
    ASSERT_TRUE(fs::is_regular_file(path)) << path;
    const PresetLoadResult r = loadPreset(path.string());
    ASSERT_FALSE(r.ok()) << c.file << " loaded";
    EXPECT_FALSE(r.preset.has_value());
    ASSERT_FALSE(r.errors.empty());
    EXPECT_EQ(r.errors[0].toString(), path.string() + c.expected);
    for (const PresetIssue& e : r.errors) EXPECT_EQ(e.file, path.string());
    // The same bytes from memory give the same first error.
    const PresetLoadResult m = parsePreset(readFile(path), path.string());
    ASSERT_FALSE(m.errors.empty());
    EXPECT_EQ(m.errors[0].toString(), r.errors[0].toString());
}

INSTANTIATE_TEST_SUITE_P(Table, BadPreset, ::testing::ValuesIn(kBadPresets),
                         [](const ::testing::TestParamInfo<BadInput>& p) { return caseName(p.param.file); });

TEST(BadInputTable, EveryPresetFileIsInTheTable) {
    std::set<std::string> listed;
    for (const BadInput& c : kBadPresets) listed.insert(c.file);
    for (const std::string& name : listDir(kBadInputs / "presets"))
        EXPECT_TRUE(listed.count(name)) << name << " has no row in the table";
    EXPECT_GE(listed.size(), 40u);
}

#ifdef AERIAL_HAVE_RENDERER
// ---------------------------------------------------------------------------
// glTF

const BadInput kBadGltf[] = {
    {"accessor_bad_buffer_view.gltf", ": accessors[0]: bufferView 9 does not exist"},
    {"accessor_past_buffer_view.gltf",
     ": accessors[0]: count 1000 with byteOffset 0 and stride 12 reaches past the end of bufferViews[0] (36 "
     "bytes)"},
    {"bad_base64_buffer.gltf",
     ": not a valid glTF 2.0 file: Failed to decode 'uri' : "
     "data:application/octet-stream;base64,@@@not-base64@@@ in Buffer"},
    {"bad_magic.glb", ": GLB header: bad magic: the file does not start with 'glTF'"},
    {"base_colour_over_one.gltf", ": materials[0]: baseColorFactor 2.000000 is outside [0, 1]"},
    {"buffer_view_past_buffer.gltf", ": bufferViews[0]: bytes 0..4096 lie outside buffers[0] (42 bytes)"},
    {"empty.gltf", ": not a valid glTF 2.0 file: Empty file."},
    {"glb_length_mismatch.glb", ": GLB header: length field says 536 bytes but the file has 528"},
    {"glb_too_short.glb", ": GLB header: the file is 6 bytes, shorter than the 12-byte header"},
    {"glb_truncated.glb", ": GLB header: length field says 528 bytes but the file has 60"},
    {"glb_version_1.glb", ": GLB header: version 1, expected 2"},
    {"index_out_of_range.gltf",
     ": meshes[0].primitives[0]: index 7 (indices element 2) is out of range of the 3 vertices"},
    {"json_array.gltf", ": not a valid glTF 2.0 file: Root element is not a JSON object"},
    {"missing_external_buffer.gltf", ": not a valid glTF 2.0 file: File not found : missing.bin"},
    {"missing_texture.gltf",
     ": images[0] ('missing_texture.png'): the image could not be loaded (missing file or undecodable data)"},
    {"no_asset.gltf",
     ": not a valid glTF 2.0 file: \"asset\" object not found in .gltf or not an object type"},
    {"no_scene.gltf", ": scenes: the file has no scene"},
    {"node_cycle.gltf", ": nodes[1].children: node 0 is its own ancestor (a cycle in the node hierarchy)"},
    {"not_json.gltf",
     ": not a valid glTF 2.0 file: [json.exception.parse_error.101] parse error at line 1, column 2: syntax "
     "error while parsing value - invalid literal; last read: 'th'"},
    {"not_whole_triangles.gltf",
     ": meshes[0].primitives[0]: 2 vertices/indices is not a multiple of 3 (TRIANGLES)"},
    {"position_vec2.gltf",
     ": meshes[0].primitives[0]: POSITION accessor (accessors[0]) has type VEC2, expected VEC3"},
    {"required_extension.gltf",
     ": extensionsRequired: the file requires extension KHR_draco_mesh_compression, which is not supported"},
    {"scale_two_values.gltf", ": nodes[0]: scale needs 3 values"},
    {"scene_node_missing.gltf", ": scenes[0].nodes: node 4 does not exist (1 nodes)"},
    {"stride_too_small.gltf",
     ": bufferViews[0]: byteStride 4 is smaller than the 12-byte elements of accessors[0]"},
    {"texture_index_out_of_range.gltf",
     ": materials[0].pbrMetallicRoughness.baseColorTexture: texture 5 does not exist"},
};

class BadGltf : public ::testing::TestWithParam<BadInput> {};

TEST_P(BadGltf, GivesItsExactError) {
    const BadInput& c = GetParam();
    const fs::path path = kBadInputs / "gltf" / c.file;
    ASSERT_TRUE(fs::is_regular_file(path)) << path;
    const renderer::GltfLoadResult r = renderer::loadGltfScene(path.string());
    ASSERT_FALSE(r.ok()) << c.file << " loaded";
    EXPECT_TRUE(r.scene.meshes.empty());
    EXPECT_EQ(r.error, path.string() + c.expected);
}

INSTANTIATE_TEST_SUITE_P(Table, BadGltf, ::testing::ValuesIn(kBadGltf),
                         [](const ::testing::TestParamInfo<BadInput>& p) { return caseName(p.param.file); });

TEST(BadInputTable, EveryGltfFileIsInTheTableOrACapTest) {
    std::set<std::string> listed;
    for (const BadInput& c : kBadGltf) listed.insert(c.file);
    for (const std::string& name : listDir(kBadInputs / "gltf")) {
        const bool capTest = name.rfind("node_depth_", 0) == 0 || name.rfind("texture_163", 0) == 0;
        EXPECT_TRUE(listed.count(name) || capTest) << name << " has no row in the table";
    }
}
#endif

}  // namespace
}  // namespace aerial::hardening
