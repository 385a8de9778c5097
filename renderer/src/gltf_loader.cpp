// gltf_loader.cpp — glTF 2.0 to SceneDesc through Debian's prebuilt
// tinygltf (libtinygltf-dev, built with its defaults: stb_image and
// nlohmann/json inside the library; TINYGLTF_IMPLEMENTATION is never
// defined here). Every accessor is bounds-checked against its buffer view
// and buffer before a byte is read (gltf_scene_builder.cpp); this file
// reads the file under the size and image limits (aerial/limits.hpp).
#include "gltf_model.hpp"

#include <aerial/detail/gltf_files.hpp>

#include <stb_image.h>  // Debian's prebuilt libstb: stbi_info_from_memory only

#include <cctype>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>

namespace aerial::renderer {
namespace {

namespace fs = std::filesystem;
using gltf::fail;
using gltf::LoadError;

/// Images larger than this are refused before they are decoded (a small
/// compressed file can claim a huge image).
/// (aerial/limits.hpp)
constexpr int kMaxImageSide = limits::kMaxTextureSide;
constexpr std::uint64_t kMaxImagePixels = limits::kMaxTexturePixels;

/// What the scene's images may still decode to, over all of them: many small
/// files that each claim a large image must not add up to gigabytes.
struct ImageBudget {
    std::uint64_t limit;  ///< GltfLoadOptions::maxImagePixels
    std::uint64_t used = 0;
};

bool loadImageChecked(tinygltf::Image* image, const int index, std::string* err, std::string* warn,
                      int reqWidth, int reqHeight, const unsigned char* bytes, int size, void* user) {
    int w = 0, h = 0, comp = 0;
    if (stbi_info_from_memory(bytes, size, &w, &h, &comp)) {
        if (w > kMaxImageSide || h > kMaxImageSide || std::uint64_t(w) * std::uint64_t(h) > kMaxImagePixels) {
            if (err)
                *err += "images[" + std::to_string(index) + "] is " + std::to_string(w) + "x" +
                        std::to_string(h) + ", over the limit of " + std::to_string(kMaxImageSide) +
                        " per side and 64 Mi pixels\n";
            return false;
        }
        auto* budget = static_cast<ImageBudget*>(user);
        const std::uint64_t pixels = std::uint64_t(w) * std::uint64_t(h);
        if (budget && pixels > budget->limit - budget->used) {
            if (err)
                *err += "images[" + std::to_string(index) + "] (" + std::to_string(w) + "x" +
                        std::to_string(h) + ") takes the scene's images over the limit of " +
                        std::to_string(budget->limit) + " pixels in all\n";
            return false;
        }
        if (budget) budget->used += pixels;
    }
    // tinygltf reads its own options from the user pointer: pass none.
    return tinygltf::LoadImageData(image, index, err, warn, reqWidth, reqHeight, bytes, size, nullptr);
}

/// The 12-byte GLB header, checked before tinygltf sees the file.
void checkGlbHeader(const std::string& path, std::uint64_t fileSize) {
    unsigned char header[12] = {};
    std::ifstream in(path, std::ios::binary);
    if (fileSize < 12 || !in.read(reinterpret_cast<char*>(header), 12))
        fail("GLB header",
             "the file is " + std::to_string(fileSize) + " bytes, shorter than the 12-byte header");
    if (std::memcmp(header, "glTF", 4) != 0)
        fail("GLB header", "bad magic: the file does not start with 'glTF'");
    std::uint32_t version = 0, length = 0;
    std::memcpy(&version, header + 4, 4);
    std::memcpy(&length, header + 8, 4);
    if (version != 2) fail("GLB header", "version " + std::to_string(version) + ", expected 2");
    if (length != fileSize)
        fail("GLB header", "length field says " + std::to_string(length) + " bytes but the file has " +
                               std::to_string(fileSize));
}

}  // namespace

GltfLoadResult loadGltfScene(const std::string& path, const GltfLoadOptions& options) {
    GltfLoadResult result;
    try {
        std::error_code ec;
        if (!fs::is_regular_file(path, ec)) fail("", "no such file");
        const std::uintmax_t size = fs::file_size(path, ec);
        if (ec) fail("", "cannot read the file size: " + ec.message());
        if (size > options.maxFileBytes)
            fail("", "the file is " + std::to_string(size) + " bytes, over the limit of " +
                         std::to_string(options.maxFileBytes) + " bytes");
        std::string extension = fs::path(path).extension().string();
        for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
        const bool binary = extension == ".glb";
        if (!binary && extension != ".gltf")
            fail("", "unsupported extension \"" + extension + "\" (expected .gltf or .glb)");
        if (binary) checkGlbHeader(path, size);

        tinygltf::TinyGLTF gltf;
        // Every file tinygltf reads (external buffers and images too) capped.
        aerial::detail::GltfFileLimit limit{options.maxFileBytes};
        ImageBudget imageBudget{options.maxImagePixels};
        gltf.SetImageLoader(&loadImageChecked, &imageBudget);
        gltf.SetFsCallbacks({&aerial::detail::gltfFileExists, &aerial::detail::gltfExpandNothing,
                             &aerial::detail::gltfReadCapped, &aerial::detail::gltfRefuseWrite, &limit});
        tinygltf::Model model;
        std::string err, warn;
        const bool ok = binary ? gltf.LoadBinaryFromFile(&model, &err, &warn, path)
                               : gltf.LoadASCIIFromFile(&model, &err, &warn, path);
        if (!ok) fail("", "not a valid glTF 2.0 file: " + gltf::oneLine(err.empty() ? warn : err));
        if (!warn.empty()) {
            // A missing external image is only a warning to tinygltf; it becomes an error below.
            result.warnings.push_back("tinygltf: " + gltf::oneLine(warn));
        }
        gltf::buildScene(model, options, result);
    } catch (const LoadError& e) {
        result.scene = {};
        result.error = path + ": " + e.message;
    } catch (const std::bad_alloc&) {
        result.scene = {};
        result.error = path + ": out of memory";
    } catch (const std::exception& e) {  // e.g. nlohmann::json inside tinygltf
        result.scene = {};
        result.error = path + ": " + e.what();
    }
    return result;
}

}  // namespace aerial::renderer
