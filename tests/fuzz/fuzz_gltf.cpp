// fuzz_gltf.cpp — libFuzzer target for the glTF 2.0 scene loader
// (aerial::renderer::loadGltfScene).
//
// The loader reads files (external buffers and images resolve next to the
// .gltf), so each input is written to a private temporary file and loaded
// from there. The first byte picks the form, the rest is the file:
//   byte 0 even -> "fuzz.gltf" (JSON), odd -> "fuzz.glb" (binary).
// Seed files (tests/fuzz/corpus/gltf) carry that prefix byte; replay_main
// and libFuzzer feed them the same way.
//
// Properties: loading never crashes, never throws, never hangs and stays
// within the limits of aerial/limits.hpp; a failure is one line naming the
// file; a scene that loads has finite positions and normals, indices in
// range, unit normals, a whole number of triangles and textures whose pixel
// buffer matches their size. Any broken property aborts.
#include <aerial/renderer/gltf.hpp>

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <unistd.h>

namespace {

void check(bool ok, const char* what) {
    if (!ok) {
        std::fprintf(stderr, "fuzz_gltf: property broken: %s\n", what);
        std::abort();
    }
}

/// A directory of our own for the temporary files (in /dev/shm when there
/// is one: no disk writes per input), removed at exit. Plain char storage:
/// nothing here is destroyed before the exit handler runs.
char gWorkDir[256] = {};

void removeWorkDir() {
    for (const char* name : {"/fuzz.gltf", "/fuzz.glb"}) {
        char path[300];
        std::snprintf(path, sizeof path, "%s%s", gWorkDir, name);
        unlink(path);
    }
    rmdir(gWorkDir);
}

const char* workDir() {
    if (gWorkDir[0] == '\0') {
        std::snprintf(gWorkDir, sizeof gWorkDir, "%s/aerial_fuzz_gltf_XXXXXX",
                      access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp");
        if (!mkdtemp(gWorkDir)) {
            std::perror("fuzz_gltf: mkdtemp");
            std::abort();
        }
        std::atexit(removeWorkDir);
    }
    return gWorkDir;
}

bool writeAll(const std::string& path, const std::uint8_t* data, std::size_t size) {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) return false;
    const bool ok = std::fwrite(data, 1, size, f) == size;
    return std::fclose(f) == 0 && ok;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 1) return 0;
    const bool binary = (data[0] & 1) != 0;
    const std::string name = binary ? "fuzz.glb" : "fuzz.gltf";
    const std::string path = std::string(workDir()) + "/" + name;
    if (!writeAll(path, data + 1, size - 1)) {
        std::perror("fuzz_gltf: cannot write the input");
        std::abort();
    }
    aerial::renderer::GltfLoadOptions options;
    options.computedNormals =
        (data[0] & 2) ? aerial::renderer::GltfNormals::Smooth : aerial::renderer::GltfNormals::Flat;
    const aerial::renderer::GltfLoadResult r = aerial::renderer::loadGltfScene(path, options);
    if (!r.ok()) {
        check(r.error.rfind(path, 0) == 0, "the error names the file");
        check(r.error.find('\n') == std::string::npos, "the error is one line");
        check(r.scene.meshes.empty(), "a failed load returns no meshes");
        return 0;
    }
    for (const aerial::renderer::SceneMesh& m : r.scene.meshes) {
        check(m.indices.size() % 3 == 0, "whole triangles");
        for (std::uint32_t i : m.indices) check(i < m.positions.size(), "indices in range");
        for (const glm::vec3& p : m.positions)
            check(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z), "finite positions");
        check(m.normals.size() == m.positions.size(), "a normal per vertex");
        for (const glm::vec3& n : m.normals)
            check(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z) &&
                      std::abs(glm::length(n) - 1.0f) < 1e-3f,
                  "finite unit normals");
        check(m.texcoords.empty() || m.texcoords.size() == m.positions.size(), "a texcoord per vertex");
        if (m.baseColorTexture)
            check(m.baseColorTexture->width > 0 && m.baseColorTexture->height > 0 &&
                      m.baseColorTexture->rgba.size() == std::size_t(m.baseColorTexture->width) *
                                                             std::size_t(m.baseColorTexture->height) * 4,
                  "texture size matches its pixels");
    }
    return 0;
}
