// test_gltf_limits.cpp — the glTF loader's caps (aerial/limits.hpp, the
// defaults of GltfLoadOptions): file and buffer sizes, node depth, texture
// size, and the vertex and triangle budgets, each at the cap and one over.
#include "hardening_support.hpp"

#include <aerial/limits.hpp>
#include <aerial/renderer/gltf.hpp>

#include <gtest/gtest.h>

namespace aerial::hardening {
namespace {

using renderer::GltfLoadOptions;
using renderer::GltfLoadResult;
using renderer::loadGltfScene;

const fs::path kGltf = kBadInputs / "gltf";

TEST(GltfLimits, OptionsDefaultToTheDocumentedCaps) {
    const GltfLoadOptions o;
    EXPECT_EQ(o.maxFileBytes, limits::kMaxGltfFileBytes);
    EXPECT_EQ(o.maxVertices, limits::kMaxGltfVertices);
    EXPECT_EQ(o.maxTriangles, limits::kMaxGltfTriangles);
    EXPECT_EQ(o.maxNodeDepth, limits::kMaxGltfNodeDepth);
}

TEST(GltfLimits, FileSize) {
    TempDir dir;
    // Sparse files: one byte over costs no disk and is refused before reading.
    for (const char* name : {"huge.gltf", "huge.glb"}) {
        const fs::path file = dir.path() / name;
        writeFile(file, "");
        fs::resize_file(file, limits::kMaxGltfFileBytes + 1);
        const GltfLoadResult r = loadGltfScene(file.string());
        EXPECT_EQ(r.error, file.string() + ": the file is 67108865 bytes, over the limit of 67108864 bytes");
    }
}

TEST(GltfLimits, ExternalBufferSize) {
    TempDir dir;
    const fs::path gltf = dir.path() / "scene.gltf";
    fs::copy_file(kGltf / "missing_external_buffer.gltf", gltf);
    const fs::path bin = dir.path() / "missing.bin";
    writeFile(bin, "");
    fs::resize_file(bin, limits::kMaxGltfFileBytes + 1);
    const GltfLoadResult r = loadGltfScene(gltf.string());
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error.find("'" + bin.string() + "' is 67108865 bytes, over the limit of 67108864"),
              std::string::npos)
        << r.error;
}

TEST(GltfLimits, NodeDepth) {
    const GltfLoadResult atCap = loadGltfScene((kGltf / "node_depth_256.gltf").string());
    EXPECT_TRUE(atCap.ok()) << atCap.error;
    EXPECT_EQ(atCap.scene.meshes.size(), 1u);
    const fs::path over = kGltf / "node_depth_257.gltf";
    EXPECT_EQ(loadGltfScene(over.string()).error,
              over.string() + ": nodes[256]: the node hierarchy is deeper than 256 levels");
}

TEST(GltfLimits, TextureSize) {
    const GltfLoadResult atCap = loadGltfScene((kGltf / "texture_16384_wide.gltf").string());
    ASSERT_TRUE(atCap.ok()) << atCap.error;
    ASSERT_EQ(atCap.scene.meshes.size(), 1u);
    ASSERT_TRUE(atCap.scene.meshes[0].baseColorTexture);
    EXPECT_EQ(atCap.scene.meshes[0].baseColorTexture->width, limits::kMaxTextureSide);

    const fs::path over = kGltf / "texture_16385_wide.gltf";
    const GltfLoadResult r = loadGltfScene(over.string());
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error.find("images[0] is 16385x1, over the limit of 16384 per side and 64 Mi pixels"),
              std::string::npos)
        << r.error;
}

TEST(GltfLimits, ImagePixelsOverAllImages) {
    // Two 16384 x 1 images: within a budget of 2 x 16384 pixels, not within one less.
    const fs::path file = kGltf / "texture_16384_twice.gltf";
    GltfLoadOptions o;
    o.maxImagePixels = 2 * 16384;
    const GltfLoadResult ok = loadGltfScene(file.string(), o);
    EXPECT_TRUE(ok.ok()) << ok.error;
    o.maxImagePixels = 2 * 16384 - 1;
    EXPECT_EQ(
        loadGltfScene(file.string(), o).error,
        file.string() +
            ": not a valid glTF 2.0 file: images[1] (16384x1) takes the scene's images over the limit of "
            "32767 pixels in all");
    EXPECT_EQ(GltfLoadOptions{}.maxImagePixels, limits::kMaxTexturePixelsTotal);
}

TEST(GltfLimits, VertexAndTriangleBudgets) {
    // A triangle (3 vertices, 1 triangle; flat normals keep 3): the fuzz
    // seed minus its form byte.
    TempDir dir;
    const fs::path file = dir.path() / "tri.gltf";
    const std::string seed =
        readFile(kSourceRoot / "tests" / "fuzz" / "corpus" / "gltf" / "triangle_u8.gltf.seed");
    ASSERT_FALSE(seed.empty());
    writeFile(file, seed.substr(1));

    GltfLoadOptions o;
    o.maxVertices = 3;
    o.maxTriangles = 1;
    EXPECT_TRUE(loadGltfScene(file.string(), o).ok());
    o.maxVertices = 2;
    EXPECT_EQ(loadGltfScene(file.string(), o).error,
              file.string() + ": meshes[0].primitives[0]: the scene has more than 2 vertices (the limit)");
    o.maxVertices = 3;
    o.maxTriangles = 0;
    EXPECT_EQ(loadGltfScene(file.string(), o).error,
              file.string() + ": meshes[0].primitives[0]: the scene has more than 0 triangles (the limit)");
}

}  // namespace
}  // namespace aerial::hardening
