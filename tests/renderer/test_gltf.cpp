// test_gltf.cpp — the glTF loader (renderer/gltf.hpp) on files written by
// the test itself: a cube in a node hierarchy (world positions against the
// hand-computed transform), uint8/16/32 indices, computed normals, material
// factors, a textured quad with a hand-made PNG, .glb against .gltf, and
// malformed files that must fail with a precise message (never crash). One
// GPU check: the loaded cube's linear depth at the centre pixel.
#include "gl_fixture.hpp"

#include <aerial/renderer/camera.hpp>
#include <aerial/renderer/gltf.hpp>
#include <aerial/renderer/image.hpp>
#include <aerial/renderer/scene.hpp>

#include <glm/geometric.hpp>

#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace aerial::test {
namespace {

namespace fs = std::filesystem;
using renderer::GltfLoadResult;
using renderer::loadGltfScene;

using Bytes = std::vector<std::uint8_t>;

/// A directory of this process's files, removed at exit.
fs::path tempDir() {
    struct Dir {
        fs::path path = fs::temp_directory_path() / ("aerial_gltf_test_" + std::to_string(::getpid()));
        Dir() { fs::create_directories(path); }
        ~Dir() {
            std::error_code ec;
            fs::remove_all(path, ec);
        }
    };
    static const Dir dir;
    return dir.path;
}

void writeFile(const fs::path& path, const void* data, std::size_t size) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(static_cast<const char*>(data), std::streamsize(size));
}
void writeFile(const fs::path& path, const std::string& text) { writeFile(path, text.data(), text.size()); }

std::string base64(const Bytes& data) {
    static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < data.size(); i += 3) {
        const std::uint32_t b0 = data[i], b1 = i + 1 < data.size() ? data[i + 1] : 0,
                            b2 = i + 2 < data.size() ? data[i + 2] : 0;
        const std::uint32_t v = (b0 << 16) | (b1 << 8) | b2;
        out += table[(v >> 18) & 63];
        out += table[(v >> 12) & 63];
        out += i + 1 < data.size() ? table[(v >> 6) & 63] : '=';
        out += i + 2 < data.size() ? table[v & 63] : '=';
    }
    return out;
}

template <typename T>
void append(Bytes& bytes, T value) {
    const auto* p = reinterpret_cast<const std::uint8_t*>(&value);
    bytes.insert(bytes.end(), p, p + sizeof(T));
}

void replaceAll(std::string& text, const std::string& from, const std::string& to) {
    for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
        text.replace(at, from.size(), to);
}

/// A glTF document: JSON with "@URI@" where buffers[0] gets its uri, and the
/// bytes of buffers[0].
struct Doc {
    std::string json;
    Bytes bin;
};

fs::path writeGltf(const std::string& name, Doc doc) {
    replaceAll(doc.json, "@URI@",
               ",\"uri\":\"data:application/octet-stream;base64," + base64(doc.bin) + "\"");
    const fs::path path = tempDir() / name;
    writeFile(path, doc.json);
    return path;
}

fs::path writeGlb(const std::string& name, Doc doc, std::uint32_t magic = 0x46546C67u, int lengthDelta = 0) {
    replaceAll(doc.json, "@URI@", "");
    while (doc.json.size() % 4 != 0) doc.json += ' ';
    while (doc.bin.size() % 4 != 0) doc.bin.push_back(0);
    Bytes glb;
    append(glb, magic);
    append(glb, std::uint32_t(2));
    const auto length = std::uint32_t(12 + 8 + doc.json.size() + 8 + doc.bin.size());
    append(glb, std::uint32_t(std::int64_t(length) + lengthDelta));
    append(glb, std::uint32_t(doc.json.size()));
    append(glb, std::uint32_t(0x4E4F534Au));  // JSON
    glb.insert(glb.end(), doc.json.begin(), doc.json.end());
    append(glb, std::uint32_t(doc.bin.size()));
    append(glb, std::uint32_t(0x004E4942u));  // BIN
    glb.insert(glb.end(), doc.bin.begin(), doc.bin.end());
    const fs::path path = tempDir() / name;
    writeFile(path, glb.data(), glb.size());
    return path;
}

/// The 8 corners of the cube [-1, 1]^3 and its 12 triangles, counter-clockwise
/// seen from outside.
void cubeGeometry(std::vector<glm::vec3>& corners, std::vector<std::uint32_t>& indices) {
    corners.clear();
    indices.clear();
    for (int k = 0; k < 8; ++k) corners.emplace_back(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1);
    const glm::vec3 normals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (const glm::vec3& n : normals) {
        const glm::vec3 u = std::fabs(n.y) > 0.5f ? glm::vec3(0, 0, n.y) : glm::vec3(-n.z, 0, n.x);
        const glm::vec3 v = glm::cross(n, u);
        std::uint32_t quad[4];
        int q = 0;
        for (const glm::vec2 c : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
            const glm::vec3 p = n + c.x * u + c.y * v;
            quad[q++] = std::uint32_t((p.x > 0 ? 1 : 0) | (p.y > 0 ? 2 : 0) | (p.z > 0 ? 4 : 0));
        }
        for (int k : {0, 1, 2, 0, 2, 3}) indices.push_back(quad[k]);
    }
}

constexpr double kHalfSqrt2 = 0.70710678118654752440;

/// The cube under a parent node (translation 1,2,3) and a child node
/// (90 degrees about +Y, uniform scale 2), indices of the given component
/// type, material factors 0.8, 0.4, 0.2, 1 / metallic 0.25 / roughness 0.75.
Doc cubeDoc(int indexType = 5123, const std::string& mode = "") {
    std::vector<glm::vec3> corners;
    std::vector<std::uint32_t> indices;
    cubeGeometry(corners, indices);
    Doc doc;
    for (const glm::vec3& c : corners) {
        append(doc.bin, c.x);
        append(doc.bin, c.y);
        append(doc.bin, c.z);
    }
    for (std::uint32_t i : indices) {
        if (indexType == 5121) append(doc.bin, std::uint8_t(i));
        if (indexType == 5123) append(doc.bin, std::uint16_t(i));
        if (indexType == 5125) append(doc.bin, std::uint32_t(i));
    }
    const std::size_t indexBytes = doc.bin.size() - 96;
    char rotation[64];
    std::snprintf(rotation, sizeof rotation, "[0,%.17g,0,%.17g]", kHalfSqrt2, kHalfSqrt2);
    doc.json = std::string(R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],)") +
               R"("nodes":[{"translation":[1,2,3],"children":[1]},{"mesh":0,"rotation":)" + rotation +
               R"(,"scale":[2,2,2]}],)" +
               R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1,)" + mode +
               R"("material":0}]}],)" +
               R"("materials":[{"pbrMetallicRoughness":{"baseColorFactor":[0.8,0.4,0.2,1.0],)" +
               R"("metallicFactor":0.25,"roughnessFactor":0.75}}],)" + R"("buffers":[{"byteLength":)" +
               std::to_string(doc.bin.size()) + "@URI@}]," +
               R"("bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":96},)" +
               R"({"buffer":0,"byteOffset":96,"byteLength":)" + std::to_string(indexBytes) + "}]," +
               R"("accessors":[{"bufferView":0,"componentType":5126,"count":8,"type":"VEC3",)" +
               R"("min":[-1,-1,-1],"max":[1,1,1]},)" + R"({"bufferView":1,"componentType":)" +
               std::to_string(indexType) + R"(,"count":36,"type":"SCALAR"}]})";
    return doc;
}

/// World position of the cube corner p: (1,2,3) + 2 * R_y(90) p, R_y(90) (x,y,z) = (z, y, -x).
glm::dvec3 expectedWorld(const glm::dvec3& p) {
    return glm::dvec3(1, 2, 3) + 2.0 * glm::dvec3(p.z, p.y, -p.x);
}

// --- A minimal PNG encoder (stored deflate blocks) -------------------------

std::uint32_t crc32(const std::uint8_t* data, std::size_t size, std::uint32_t crc = 0) {
    crc = ~crc;
    for (std::size_t i = 0; i < size; ++i) {
        crc ^= data[i];
        for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

void appendBigEndian(Bytes& out, std::uint32_t v) {
    for (int s = 24; s >= 0; s -= 8) out.push_back(std::uint8_t(v >> s));
}

void pngChunk(Bytes& out, const char* type, const Bytes& data) {
    appendBigEndian(out, std::uint32_t(data.size()));
    Bytes typed(type, type + 4);
    typed.insert(typed.end(), data.begin(), data.end());
    out.insert(out.end(), typed.begin(), typed.end());
    appendBigEndian(out, crc32(typed.data(), typed.size()));
}

Bytes encodePng(int width, int height, const Bytes& rgba) {
    Bytes raw;
    for (int y = 0; y < height; ++y) {
        raw.push_back(0);  // filter: none
        raw.insert(raw.end(), rgba.begin() + std::ptrdiff_t(y * width * 4),
                   rgba.begin() + std::ptrdiff_t((y + 1) * width * 4));
    }
    Bytes z = {0x78, 0x01, 0x01};  // zlib header, one final stored block (raw < 65536)
    const auto len = std::uint16_t(raw.size());
    z.push_back(std::uint8_t(len & 0xFF));
    z.push_back(std::uint8_t(len >> 8));
    z.push_back(std::uint8_t(~len & 0xFF));
    z.push_back(std::uint8_t((~len >> 8) & 0xFF));
    z.insert(z.end(), raw.begin(), raw.end());
    std::uint32_t a = 1, b = 0;
    for (std::uint8_t c : raw) {
        a = (a + c) % 65521;
        b = (b + a) % 65521;
    }
    appendBigEndian(z, (b << 16) | a);
    Bytes png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    Bytes ihdr;
    appendBigEndian(ihdr, std::uint32_t(width));
    appendBigEndian(ihdr, std::uint32_t(height));
    for (std::uint8_t v : {8, 6, 0, 0, 0}) ihdr.push_back(v);  // 8-bit RGBA
    pngChunk(png, "IHDR", ihdr);
    pngChunk(png, "IDAT", z);
    pngChunk(png, "IEND", {});
    return png;
}

const Bytes kQuadPixels = {255, 0, 0,   255, 0,  255, 0,  128,  // row 0: red, half-transparent green
                           0,   0, 255, 255, 10, 20,  30, 40};  // row 1: blue, (10, 20, 30, 40)

/// A textured unit quad (alpha BLEND); `imageJson` is images[0].
Doc quadDoc(const std::string& imageJson) {
    Doc doc;
    const float positions[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    const float uvs[4][2] = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
    for (const auto& p : positions)
        for (float v : p) append(doc.bin, v);
    for (const auto& t : uvs)
        for (float v : t) append(doc.bin, v);
    for (std::uint16_t i : {0, 1, 2, 0, 2, 3}) append(doc.bin, i);
    doc.json =
        std::string(R"({"asset":{"version":"2.0"},"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)") +
        R"("meshes":[{"primitives":[{"attributes":{"POSITION":0,"TEXCOORD_0":1},"indices":2,"material":0}]}],)" +
        R"("materials":[{"alphaMode":"BLEND","pbrMetallicRoughness":{"baseColorTexture":{"index":0},)" +
        R"("baseColorFactor":[1,1,1,0.5]}}],)" + R"("textures":[{"source":0}],"images":[)" + imageJson +
        "]," + R"("buffers":[{"byteLength":)" + std::to_string(doc.bin.size()) + "@URI@}]," +
        R"("bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":48},{"buffer":0,"byteOffset":48,"byteLength":32},)" +
        R"({"buffer":0,"byteOffset":80,"byteLength":12}],)" +
        R"("accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3"},)" +
        R"({"bufferView":1,"componentType":5126,"count":4,"type":"VEC2"},)" +
        R"({"bufferView":2,"componentType":5123,"count":6,"type":"SCALAR"}]})";
    return doc;
}

// --- Tests -----------------------------------------------------------------

TEST(Gltf, CubeHierarchyWorldPositions) {
    const GltfLoadResult r = loadGltfScene(writeGltf("cube.gltf", cubeDoc()).string());
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
    ASSERT_EQ(r.scene.meshes.size(), 1u);
    const renderer::SceneMesh& m = r.scene.meshes[0];
    ASSERT_EQ(m.indices.size(), 36u);
    ASSERT_EQ(m.normals.size(), m.positions.size());
    double worst = 0.0;
    for (const glm::vec3& p : m.positions) {
        const glm::dvec3 world = glm::dvec3(m.worldFromObject * glm::dvec4(glm::dvec3(p), 1.0));
        worst = std::max(worst, glm::length(world - expectedWorld(glm::dvec3(p))));
    }
    EXPECT_LT(worst, 1e-6);
    // Material factors.
    EXPECT_NEAR(m.albedo.r, 0.8, 1e-12);
    EXPECT_NEAR(m.albedo.g, 0.4, 1e-12);
    EXPECT_NEAR(m.albedo.b, 0.2, 1e-12);
    EXPECT_DOUBLE_EQ(m.opacity, 1.0);
    EXPECT_DOUBLE_EQ(m.metallic, 0.25);
    EXPECT_DOUBLE_EQ(m.roughness, 0.75);
    EXPECT_EQ(m.alphaMode, renderer::AlphaMode::Opaque);
    EXPECT_EQ(m.baseColorTexture, nullptr);
}

TEST(Gltf, MatrixTransformEqualsTrs) {
    Doc d = cubeDoc();
    const std::size_t from = d.json.find(R"("rotation":)");
    const std::size_t to = d.json.find(R"("scale":[2,2,2])");
    ASSERT_NE(from, std::string::npos);
    ASSERT_NE(to, std::string::npos);
    // 2 R_y(90), column-major: x -> (0, 0, -2), y -> (0, 2, 0), z -> (2, 0, 0).
    d.json.replace(from, to + std::strlen(R"("scale":[2,2,2])") - from,
                   R"("matrix":[0,0,-2,0, 0,2,0,0, 2,0,0,0, 0,0,0,1])");
    const GltfLoadResult r = loadGltfScene(writeGltf("matrix.gltf", d).string());
    ASSERT_TRUE(r.ok()) << r.error;
    const renderer::SceneMesh& m = r.scene.meshes.at(0);
    for (const glm::vec3& p : m.positions) {
        const glm::dvec3 world = glm::dvec3(m.worldFromObject * glm::dvec4(glm::dvec3(p), 1.0));
        EXPECT_LT(glm::length(world - expectedWorld(glm::dvec3(p))), 1e-12);
    }
}

TEST(Gltf, DefaultSceneOrSceneZero) {
    Doc chosen = cubeDoc();
    replaceAll(chosen.json, R"("scene":0,"scenes":[{"nodes":[0]}])",
               R"("scene":1,"scenes":[{"nodes":[]},{"nodes":[0]}])");
    const GltfLoadResult a = loadGltfScene(writeGltf("scene1.gltf", chosen).string());
    ASSERT_TRUE(a.ok()) << a.error;
    EXPECT_EQ(a.scene.meshes.size(), 1u);
    Doc first = cubeDoc();
    replaceAll(first.json, R"("scene":0,"scenes":[{"nodes":[0]}])",
               R"("scenes":[{"nodes":[]},{"nodes":[0]}])");
    const GltfLoadResult b = loadGltfScene(writeGltf("scene0.gltf", first).string());
    ASSERT_TRUE(b.ok()) << b.error;
    EXPECT_EQ(b.scene.meshes.size(), 0u);  // no "scene": scenes[0], which is empty
}

TEST(Gltf, ComputedNormalsAreUnitAndOutward) {
    for (auto mode : {renderer::GltfNormals::Flat, renderer::GltfNormals::Smooth}) {
        renderer::GltfLoadOptions options;
        options.computedNormals = mode;
        const GltfLoadResult r = loadGltfScene(writeGltf("normals.gltf", cubeDoc()).string(), options);
        ASSERT_TRUE(r.ok()) << r.error;
        const renderer::SceneMesh& m = r.scene.meshes.at(0);
        ASSERT_EQ(m.normals.size(), m.positions.size());
        EXPECT_EQ(m.positions.size(), mode == renderer::GltfNormals::Flat ? 36u : 8u);
        for (std::size_t t = 0; t < m.indices.size() / 3; ++t) {
            const glm::vec3 centroid = (m.positions[m.indices[3 * t]] + m.positions[m.indices[3 * t + 1]] +
                                        m.positions[m.indices[3 * t + 2]]) /
                                       3.0f;
            for (int k = 0; k < 3; ++k) {
                const glm::vec3 n = m.normals[m.indices[3 * t + std::size_t(k)]];
                EXPECT_NEAR(glm::length(n), 1.0f, 1e-6f);
                EXPECT_GT(glm::dot(n, centroid), 0.5f);     // outward
                if (mode == renderer::GltfNormals::Flat) {  // the face's axis: centroid is 2/3 along it
                    EXPECT_NEAR(glm::dot(n, centroid), 1.0f, 1e-6f);
                }
            }
        }
    }
}

TEST(Gltf, IndexTypesUint8Uint16Uint32) {
    std::vector<glm::vec3> corners;
    std::vector<std::uint32_t> indices;
    cubeGeometry(corners, indices);
    renderer::GltfLoadOptions options;
    options.computedNormals = renderer::GltfNormals::Smooth;  // keeps the file's vertices and indices
    for (int type : {5121, 5123, 5125}) {
        const GltfLoadResult r = loadGltfScene(
            writeGltf("index_" + std::to_string(type) + ".gltf", cubeDoc(type)).string(), options);
        ASSERT_TRUE(r.ok()) << r.error;
        EXPECT_EQ(r.scene.meshes.at(0).indices, indices) << "componentType " << type;
    }
}

TEST(Gltf, GlbEqualsGltf) {
    const GltfLoadResult a = loadGltfScene(writeGltf("same.gltf", cubeDoc()).string());
    const GltfLoadResult b = loadGltfScene(writeGlb("same.glb", cubeDoc()).string());
    ASSERT_TRUE(a.ok()) << a.error;
    ASSERT_TRUE(b.ok()) << b.error;
    ASSERT_EQ(a.scene.meshes.size(), b.scene.meshes.size());
    const renderer::SceneMesh &ma = a.scene.meshes[0], &mb = b.scene.meshes[0];
    EXPECT_EQ(ma.positions, mb.positions);
    EXPECT_EQ(ma.normals, mb.normals);
    EXPECT_EQ(ma.indices, mb.indices);
    EXPECT_EQ(ma.worldFromObject, mb.worldFromObject);
    EXPECT_EQ(ma.albedo, mb.albedo);
}

TEST(Gltf, TexturedQuadWithPng) {
    const Bytes png = encodePng(2, 2, kQuadPixels);
    writeFile(tempDir() / "quad.png", png.data(), png.size());
    const std::string embedded = R"({"uri":"data:image/png;base64,)" + base64(png) + "\"}";
    for (const std::string& image : {std::string(R"({"uri":"quad.png"})"), embedded}) {
        const GltfLoadResult r = loadGltfScene(writeGltf("quad.gltf", quadDoc(image)).string());
        ASSERT_TRUE(r.ok()) << r.error;
        const renderer::SceneMesh& m = r.scene.meshes.at(0);
        ASSERT_NE(m.baseColorTexture, nullptr);
        EXPECT_EQ(m.baseColorTexture->width, 2);
        EXPECT_EQ(m.baseColorTexture->height, 2);
        ASSERT_EQ(m.baseColorTexture->rgba.size(), 16u);
        EXPECT_EQ(m.baseColorTexture->rgba, kQuadPixels);
        EXPECT_EQ(m.baseColorTexture->rgba[7], 128);  // pixel (1, 0) alpha
        EXPECT_EQ(m.alphaMode, renderer::AlphaMode::Blend);
        EXPECT_DOUBLE_EQ(m.opacity, 0.5);
        EXPECT_EQ(m.texcoords.size(), m.positions.size());
    }
}

/// Loads and expects an error containing `expected` (and the file name).
void expectError(const fs::path& path, const std::string& expected,
                 const renderer::GltfLoadOptions& options = {}) {
    const GltfLoadResult r = loadGltfScene(path.string(), options);
    std::printf("[ message  ] %s\n", r.error.c_str());
    EXPECT_FALSE(r.ok()) << path;
    EXPECT_NE(r.error.find(expected), std::string::npos)
        << "error: " << r.error << "\nexpected: " << expected;
    EXPECT_NE(r.error.find(path.string()), std::string::npos) << r.error;
    EXPECT_EQ(r.error.find('\n'), std::string::npos) << r.error;
    EXPECT_TRUE(r.scene.meshes.empty());
}

TEST(Gltf, MalformedFilesFailWithTheReason) {
    {
        Doc d = cubeDoc();
        d.json.resize(d.json.size() / 2);
        expectError(writeGltf("truncated.gltf", d), "not a valid glTF 2.0 file");
    }
    {
        Doc d = cubeDoc();
        replaceAll(d.json, "@URI@", R"(,"uri":"missing.bin")");
        expectError(writeGltf("missing_buffer.gltf", d), "missing.bin");
    }
    {
        Doc d = cubeDoc();
        replaceAll(d.json, R"("byteOffset":96,"byteLength":72)", R"("byteOffset":96,"byteLength":4000)");
        expectError(writeGltf("view_out_of_range.gltf", d),
                    "bufferViews[1]: bytes 96..4096 lie outside buffers[0]");
    }
    {
        Doc d = cubeDoc();
        replaceAll(d.json, R"("count":8,)", R"("count":1000,)");
        expectError(writeGltf("count_too_large.gltf", d), "accessors[0]: count 1000");
    }
    {
        Doc d = cubeDoc();  // 7 * 16 + 12 = 124 bytes of a 96-byte view
        replaceAll(d.json, R"("byteOffset":0,"byteLength":96})",
                   R"("byteOffset":0,"byteLength":96,"byteStride":16})");
        expectError(
            writeGltf("stride.gltf", d),
            "accessors[0]: count 8 with byteOffset 0 and stride 16 reaches past the end of bufferViews[0] "
            "(96 bytes)");
    }
    {
        Doc d = cubeDoc();
        replaceAll(d.json, R"("componentType":5126,"count":8)", R"("componentType":5121,"count":8)");
        expectError(writeGltf("position_type.gltf", d),
                    "meshes[0].primitives[0]: POSITION accessor (accessors[0]) has componentType 5121 "
                    "(UNSIGNED_BYTE), expected FLOAT (5126)");
    }
    {
        Doc d = cubeDoc();
        d.bin[96 + 2 * 5] = 8;  // indices element 5 -> vertex 8 of 8
        expectError(writeGltf("index_range.gltf", d),
                    "index 8 (indices element 5) is out of range of the 8 vertices");
    }
    expectError(writeGlb("magic.glb", cubeDoc(), 0x46546C66u), "GLB header: bad magic");
    expectError(writeGlb("length.glb", cubeDoc(), 0x46546C67u, 4), "GLB header: length field says");
    expectError(writeGltf("missing_image.gltf", quadDoc(R"({"uri":"nowhere.png"})")),
                "images[0] ('nowhere.png'): the image could not be loaded");
    {
        Doc d = cubeDoc();
        replaceAll(d.json, R"("children":[1]},{"mesh":0,)", R"("children":[1]},{"mesh":0,"children":[0],)");
        expectError(writeGltf("cycle.gltf", d), "nodes[1].children: node 0 is its own ancestor");
    }
    {
        Doc d = cubeDoc();
        replaceAll(d.json, R"("max":[1,1,1]})",
                   R"("max":[1,1,1],"sparse":{"count":1,"indices":{"bufferView":1,"componentType":5123},)"
                   R"("values":{"bufferView":0}}})");
        expectError(writeGltf("sparse.gltf", d), "accessors[0]: sparse accessors are not supported");
    }
    {
        renderer::GltfLoadOptions small;
        small.maxFileBytes = 100;
        expectError(writeGltf("big.gltf", cubeDoc()), "bytes, over the limit of 100 bytes", small);
        renderer::GltfLoadOptions fewVertices;
        fewVertices.maxVertices = 4;
        expectError(writeGltf("many.gltf", cubeDoc()), "the scene has more than 4 vertices", fewVertices);
        fewVertices.maxVertices = 20;  // 8 in the file, 36 with flat normals
        expectError(writeGltf("many_flat.gltf", cubeDoc()),
                    "more than 20 vertices (the limit, after flat normals)", fewVertices);
    }
    expectError(tempDir() / "does_not_exist.gltf", "no such file");
    {
        const fs::path path = tempDir() / "cube.obj";
        writeFile(path, "v 0 0 0\n");
        expectError(path, "unsupported extension");
    }
}

TEST(Gltf, HugeImageIsRefusedBeforeDecoding) {
    // A valid 1x1 PNG whose IHDR claims 12000 x 12000 (144 Mi pixels): refused from the header.
    Bytes png = encodePng(1, 1, {1, 2, 3, 4});
    const Bytes side = {0x00, 0x00, 0x2E, 0xE0};  // 12000, big-endian
    std::copy(side.begin(), side.end(), png.begin() + 16);
    std::copy(side.begin(), side.end(), png.begin() + 20);
    const std::string image = R"({"uri":"data:image/png;base64,)" + base64(png) + "\"}";
    expectError(writeGltf("huge_image.gltf", quadDoc(image)), "images[0] is 12000x12000, over the limit");
}

/// Every single-byte corruption of a .glb and a .gltf at a few hundred
/// places loads or fails with a message; none crashes or reads out of bounds
/// (run under the sanitizers in the ASan build).
TEST(Gltf, CorruptedFilesNeverCrash) {
    const Bytes png = encodePng(2, 2, kQuadPixels);
    const std::string image = R"({"uri":"data:image/png;base64,)" + base64(png) + "\"}";
    writeGlb("fuzz_source.glb", quadDoc(image));
    std::ifstream in(tempDir() / "fuzz_source.glb", std::ios::binary);
    const Bytes glb((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    Doc text = cubeDoc();
    replaceAll(text.json, "@URI@",
               ",\"uri\":\"data:application/octet-stream;base64," + base64(text.bin) + "\"");
    const Bytes gltf(text.json.begin(), text.json.end());
    std::uint32_t state = 12345;
    auto next = [&] { return state = state * 1664525u + 1013904223u; };
    int failures = 0, loads = 0;
    for (const auto& [source, name] : {std::pair(glb, "fuzz.glb"), std::pair(gltf, "fuzz.gltf")}) {
        for (int k = 0; k < 300; ++k) {
            Bytes bytes = source;
            for (int flips = 1 + int(next() % 3); flips > 0; --flips)
                bytes[next() % bytes.size()] = std::uint8_t(next() >> 24);
            if (k % 50 == 0) bytes.resize(next() % bytes.size());  // truncated
            writeFile(tempDir() / name, bytes.data(), bytes.size());
            const GltfLoadResult r = loadGltfScene((tempDir() / name).string());
            (r.ok() ? loads : failures) += 1;
            if (!r.ok()) {
                EXPECT_EQ(r.error.find('\n'), std::string::npos) << r.error;
            }
        }
    }
    std::printf("[ measured ] corrupted files: %d loaded, %d failed with a message\n", loads, failures);
    EXPECT_GT(failures, 0);
}

TEST(Gltf, UnsupportedPrimitiveModeIsAWarning) {
    const GltfLoadResult r = loadGltfScene(writeGltf("lines.gltf", cubeDoc(5123, R"("mode":1,)")).string());
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_TRUE(r.scene.meshes.empty());
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_NE(r.warnings[0].find("meshes[0].primitives[0]: mode 1 (LINES) is not supported"),
              std::string::npos)
        << r.warnings[0];
}

/// A float frame of the meshes alone: no sky, no stars (the states here are
/// built by hand).
renderer::FrameDesc meshOnlyFrame(int width, int height) {
    renderer::FrameDesc frame;
    frame.stars = false;
    frame.width = width;
    frame.height = height;
    frame.precision = renderer::ColourPrecision::Float;
    frame.passes.sky = false;
    return frame;
}

TEST_F(GlTest, GltfCubeLinearDepthAtCentre) {
    const GltfLoadResult loaded = loadGltfScene(writeGltf("depth_cube.gltf", cubeDoc()).string());
    ASSERT_TRUE(loaded.ok()) << loaded.error;
    renderer::Renderer r(rendererDesc());
    ASSERT_TRUE(r.valid()) << r.error();
    r.setScene(loaded.scene);
    // The cube spans [-1, 3] x [0, 4] x [1, 5]; look at its +Z face (z = 5) from 8 m away.
    renderer::Camera camera;
    camera.eye = {1.0, 2.0, 13.0};
    camera.target = {1.0, 2.0, 3.0};
    camera.verticalFov = 0.5;
    camera.nearDistance = 0.1;
    camera.farDistance = 100.0;
    constexpr int kW = 64, kH = 48;
    camera.aspect = double(kW) / kH;
    const renderer::FrameDesc frame = meshOnlyFrame(kW, kH);
    r.render(camera, PresetState{}, frame);
    const renderer::Image depth = r.readLinearDepth();
    ASSERT_EQ(depth.width, kW);
    const renderer::CameraFrame f = renderer::cameraFrame(camera);
    const int x = kW / 2, y = kH / 2;
    const glm::dvec3 ray = renderer::farRayAtPixel(f, x, y, kW, kH);
    const double expected = (5.0 - camera.eye.z) / ray.z;  // fraction of the far ray to z = 5
    const double got = depth.at(x, y, 0);
    EXPECT_NEAR(got, expected, 1e-3 * expected);
    EXPECT_NEAR(got * glm::length(ray), 8.0, 8e-3 * 1.01);  // about 8 m
    EXPECT_TRUE(log.errors.empty()) << log.errors.front();
}

double srgbToLinear(int c) {
    const double v = c / 255.0;
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

TEST_F(GlTest, GltfTexturedQuadRendersItsTexelsBlended) {
    // The textured BLEND quad (2 x 2 sRGB texels, baseColorFactor alpha 0.5)
    // from a real file, seen face on and lit by a sun along its normal with
    // E = pi, over black: every pixel is alpha x base (premultiplied), with
    // base and alpha filtered bilinearly (GL_REPEAT) in linear light after
    // the sRGB decode, the texture upright as glTF says (uv (0, 0) = the
    // image's top-left). Made a pure Lambert non-metal (the file's default
    // metallic factor is 1) so the expected value is the closed form.
    const Bytes png = encodePng(2, 2, kQuadPixels);
    const std::string image = R"({"uri":"data:image/png;base64,)" + base64(png) + "\"}";
    GltfLoadResult loaded = loadGltfScene(writeGltf("render_quad.gltf", quadDoc(image)).string());
    ASSERT_TRUE(loaded.ok()) << loaded.error;
    ASSERT_EQ(loaded.scene.meshes.size(), 1u);
    loaded.scene.meshes[0].metallic = 0.0;
    loaded.scene.meshes[0].specularFactor = 0.0;
    renderer::Renderer r(rendererDesc());
    ASSERT_TRUE(r.valid()) << r.error();
    r.setScene(loaded.scene);
    renderer::Camera camera;
    camera.eye = {0.5, 0.5, 3.0};
    camera.target = {0.5, 0.5, 0.0};
    camera.verticalFov = 0.4;
    camera.farDistance = 100.0;
    constexpr int kW = 64, kH = 64;
    camera.aspect = 1.0;
    PresetState air;
    air.sunLight = light({0.0, 0.0, 1.0}, glm::dvec3(0.0), glm::dvec3(3.14159265358979323846));
    air.moonLight.illuminance = glm::dvec3(0.0);
    const renderer::FrameDesc frame = meshOnlyFrame(kW, kH);
    r.render(camera, air, frame);
    EXPECT_EQ(r.stats().transparentDrawn, 1);
    const renderer::Image colour = r.readColour();
    const renderer::CameraFrame f = renderer::cameraFrame(camera);
    auto texel = [&](int i, int j, int c) {  // linear value, wrapped (GL_REPEAT)
        const std::uint8_t v = kQuadPixels[std::size_t(((j & 1) * 2 + (i & 1)) * 4 + c)];
        return c == 3 ? v / 255.0 : srgbToLinear(v);
    };
    auto bilinear = [&](double u, double v, int c) {
        const double s = u * 2.0 - 0.5, t = v * 2.0 - 0.5;
        const int i = int(std::floor(s)), j = int(std::floor(t));
        const double a = s - i, b = t - j;
        return (1 - a) * (1 - b) * texel(i, j, c) + a * (1 - b) * texel(i + 1, j, c) +
               (1 - a) * b * texel(i, j + 1, c) + a * b * texel(i + 1, j + 1, c);
    };
    double worst = 0.0;
    int n = 0;
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            const glm::dvec3 ray = renderer::farRayAtPixel(f, x, y, kW, kH);
            const glm::dvec3 p = f.eye + ray * (-f.eye.z / ray.z);  // on z = 0
            if (p.x < 0.02 || p.x > 0.98 || p.y < 0.02 || p.y > 0.98) continue;
            const double u = p.x, v = 1.0 - p.y;
            const double alpha = 0.5 * bilinear(u, v, 3);
            for (int c = 0; c < 3; ++c) {
                const double expected = alpha * bilinear(u, v, c);  // base / pi * E, E = pi
                worst = std::max(worst, std::fabs(colour.at(x, y, c) - expected));
            }
            ++n;
        }
    }
    std::printf("[ measured ] glTF textured blend quad: max error %.3g over %d px\n", worst, n);
    EXPECT_GT(n, 1000);
    EXPECT_LE(worst, 1e-3);  // llvmpipe's approximate sRGB decode (~1.5e-4 at most) and filter weights
    EXPECT_TRUE(log.errors.empty()) << log.errors.front();
}

}  // namespace
}  // namespace aerial::test
