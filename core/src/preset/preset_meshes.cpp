// preset_meshes.cpp — resolveFogMeshes: the glTF mesh of every mesh fog
// volume of a preset, read relative to the preset's folder (loadFogMesh,
// aerial/fog_mesh.hpp). A mesh already read from the same file (same path,
// size and modification time) is shared, not read again, so an editor that
// resolves after every edit pays for a file once.
#include <aerial/fog_mesh.hpp>
#include <aerial/preset.hpp>

#include <filesystem>
#include <map>
#include <mutex>
#include <system_error>

namespace aerial {
namespace {

namespace fs = std::filesystem;

struct CachedMesh {
    std::uintmax_t size = 0;
    fs::file_time_type modified;
    std::weak_ptr<const FogMesh> mesh;
};

/// The mesh of `path`, from the cache while the file is unchanged.
FogMeshLoadResult cachedLoad(const fs::path& path) {
    static std::mutex mutex;
    static std::map<std::string, CachedMesh> cache;
    std::error_code ec;
    const fs::path absolute = fs::absolute(path, ec).lexically_normal();
    const std::string key = ec ? path.string() : absolute.string();
    const std::uintmax_t size = fs::file_size(path, ec);
    const fs::file_time_type modified = ec ? fs::file_time_type() : fs::last_write_time(path, ec);
    {
        std::lock_guard<std::mutex> lock(mutex);
        const auto it = cache.find(key);
        if (!ec && it != cache.end() && it->second.size == size && it->second.modified == modified) {
            if (auto mesh = it->second.mesh.lock()) return {mesh, ""};
        }
    }
    FogMeshLoadResult result = loadFogMesh(path.string());
    if (result.mesh && !ec) {
        std::lock_guard<std::mutex> lock(mutex);
        cache[key] = {size, modified, result.mesh};
    }
    return result;
}

}  // namespace

std::vector<PresetIssue> resolveFogMeshes(Preset& preset, const std::string& baseFolder) {
    std::vector<PresetIssue> issues;
    for (std::size_t i = 0; i < preset.volumes.size(); ++i) {
        FogVolume& v = preset.volumes[i];
        if (v.shape != FogVolumeShape::Mesh) {
            v.meshData.reset();
            continue;
        }
        PresetIssue issue;
        issue.pointer = "/volumes/" + std::to_string(i) + "/mesh";
        if (v.mesh.empty()) {
            issue.message = "a mesh volume needs \"mesh\": the glTF file of its closed mesh";
            issues.push_back(std::move(issue));
            v.meshData.reset();
            continue;
        }
        fs::path path(v.mesh);
        if (path.is_relative() && !baseFolder.empty()) path = fs::path(baseFolder) / path;
        FogMeshLoadResult loaded = cachedLoad(path);
        v.meshData = loaded.mesh;
        if (!loaded.mesh) {
            // Name the file as the preset writes it (the reader knows where
            // the preset is), then the loader's reason.
            std::string reason = loaded.error;
            const std::string prefix = path.string() + ": ";
            if (reason.compare(0, prefix.size(), prefix) == 0) reason.erase(0, prefix.size());
            if (reason == "no such file" && fs::path(v.mesh).is_relative())
                reason += " (a relative path starts at the preset's folder)";
            issue.message = "mesh volume \"" + v.id + "\": " + v.mesh + ": " + reason;
            issues.push_back(std::move(issue));
        }
    }
    return issues;
}

}  // namespace aerial
