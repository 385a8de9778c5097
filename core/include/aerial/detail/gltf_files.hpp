// aerial/detail/gltf_files.hpp — the file callbacks Aerial gives tinygltf
// (its FsCallbacks), shared by the fog volume meshes (core's loadFogMesh)
// and the renderer's glTF scenes: every file read under a size cap (a
// glTF's external buffers and images too), no ~ or $VAR expansion, writing
// refused. Not part of the stable API (namespace detail); the signatures
// are tinygltf's, so this header needs none of its types.
//
// Usage:
//   aerial::detail::GltfFileLimit limit{limits::kMaxGltfFileBytes};
//   gltf.SetFsCallbacks({&detail::gltfFileExists, &detail::gltfExpandNothing,
//                        &detail::gltfReadCapped, &detail::gltfRefuseWrite, &limit});
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace aerial::detail {

/// The user data of the callbacks: the largest file they read [bytes].
struct GltfFileLimit {
    std::uint64_t maxBytes;
};

/// Reads `path` whole into `out` unless it is over the GltfFileLimit that
/// `user` points to; on failure appends "cannot read 'path': reason" or
/// "'path' is N bytes, over the limit of M" (and a newline) to `err`.
bool gltfReadCapped(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user);
/// Whether `path` is a regular file.
bool gltfFileExists(const std::string& path, void* user);
/// `path` unchanged: no ~ or $VAR expansion.
std::string gltfExpandNothing(const std::string& path, void* user);
/// Always false, "writing is not supported".
bool gltfRefuseWrite(std::string* err, const std::string& path, const std::vector<unsigned char>& bytes,
                     void* user);

}  // namespace aerial::detail
