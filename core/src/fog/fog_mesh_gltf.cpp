// fog_mesh_gltf.cpp — loadFogMesh: the triangles of a glTF file (.gltf or
// .glb) through Debian's prebuilt tinygltf (TINYGLTF_IMPLEMENTATION is never
// defined here), checked by FogMesh::build (aerial/fog_mesh.hpp); and
// fogMeshToGltf, a mesh back as a self-contained .gltf text.
//
// Reads: the file and its external buffers, each under
// limits::kMaxGltfFileBytes; images are never decoded (a fog mesh has no
// material). Every accessor is bounds-checked against its buffer view and
// buffer before a byte is read. The triangles of every primitive of the
// default scene's nodes (placed by the node transforms; without scenes,
// every mesh untransformed) make up the mesh.
#include <aerial/detail/gltf_files.hpp>
#include <aerial/detail/gltf_model.hpp>
#include <aerial/fog_mesh.hpp>
#include <aerial/limits.hpp>

#include <tiny_gltf.h>

#include <nlohmann/json.hpp>

#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <system_error>

namespace aerial {
namespace {

namespace fs = std::filesystem;

struct LoadError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

bool skipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int,
               void*) {
    return true;  // a fog mesh has no material: images are not decoded
}

namespace gltf = detail::gltf;

/// The largest accessor count a fog mesh reads (vertices or indices).
constexpr std::uint64_t kMaxAccessorCount =
    std::max<std::uint64_t>(limits::kMaxGltfVertices, std::uint64_t(limits::kMaxFogMeshTriangles) * 3);

struct Collector {
    const tinygltf::Model& model;
    std::vector<glm::dvec3> positions;
    std::vector<std::uint32_t> indices;

    void addMesh(int meshIndex, const glm::dmat4& transform) {
        if (meshIndex < 0 || std::size_t(meshIndex) >= model.meshes.size())
            throw LoadError("mesh " + std::to_string(meshIndex) + " does not exist");
        const tinygltf::Mesh& mesh = model.meshes[std::size_t(meshIndex)];
        // A mirroring transform turns the triangles inside out: swap the winding back.
        const bool mirrored = glm::determinant(glm::dmat3(transform)) < 0.0;
        for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
            const tinygltf::Primitive& prim = mesh.primitives[p];
            const std::string what =
                "meshes[" + std::to_string(meshIndex) + "].primitives[" + std::to_string(p) + "]";
            if (prim.mode != -1 && prim.mode != TINYGLTF_MODE_TRIANGLES)
                throw LoadError(what + ": mode " + std::to_string(prim.mode) +
                                "; a fog mesh is made of triangles (mode 4)");
            const auto position = prim.attributes.find("POSITION");
            if (position == prim.attributes.end()) throw LoadError(what + ": no POSITION attribute");
            const gltf::AccessorView pos =
                gltf::accessorView(model, position->second, "POSITION", what, kMaxAccessorCount);
            if (pos.components != 3 || pos.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
                throw LoadError(what + ": POSITION is not float VEC3");
            if (positions.size() + pos.count > limits::kMaxGltfVertices)
                throw LoadError("too many vertices (over " + std::to_string(limits::kMaxGltfVertices) + ")");
            const std::uint32_t base = std::uint32_t(positions.size());
            for (std::uint64_t i = 0; i < pos.count; ++i) {
                const glm::dvec4 at(pos.component(i, 0), pos.component(i, 1), pos.component(i, 2), 1.0);
                positions.push_back(glm::dvec3(transform * at));
            }
            std::vector<std::uint32_t> local;
            if (prim.indices >= 0) {
                const gltf::AccessorView idx =
                    gltf::accessorView(model, prim.indices, "indices", what, kMaxAccessorCount);
                if (idx.components != 1 || (idx.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
                                            idx.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
                                            idx.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
                    throw LoadError(what + ": indices are not unsigned integer scalars");
                for (std::uint64_t i = 0; i < idx.count; ++i) {
                    const std::uint32_t v = idx.index(i);
                    if (v >= pos.count)
                        throw LoadError(what + ": index " + std::to_string(v) + " past the " +
                                        std::to_string(pos.count) + " vertices");
                    local.push_back(v);
                }
            } else {
                for (std::uint64_t i = 0; i < pos.count; ++i) local.push_back(std::uint32_t(i));
            }
            if (local.size() % 3 != 0)
                throw LoadError(what + ": " + std::to_string(local.size()) + " indices, not a multiple of 3");
            if ((indices.size() + local.size()) / 3 > limits::kMaxFogMeshTriangles)
                throw LoadError("more than " + std::to_string(limits::kMaxFogMeshTriangles) +
                                " triangles, the limit for a fog volume mesh");
            for (std::size_t i = 0; i < local.size(); i += 3) {
                indices.push_back(base + local[i]);
                indices.push_back(base + local[i + (mirrored ? 2 : 1)]);
                indices.push_back(base + local[i + (mirrored ? 1 : 2)]);
            }
        }
    }

    void addNode(int nodeIndex, const glm::dmat4& parent, int depth) {
        if (nodeIndex < 0 || std::size_t(nodeIndex) >= model.nodes.size())
            throw LoadError("node " + std::to_string(nodeIndex) + " does not exist");
        if (depth > limits::kMaxGltfNodeDepth)
            throw LoadError("the node hierarchy is deeper than " + std::to_string(limits::kMaxGltfNodeDepth) +
                            " (a cycle?)");
        const tinygltf::Node& node = model.nodes[std::size_t(nodeIndex)];
        const glm::dmat4 transform =
            parent * gltf::nodeTransform(node, "nodes[" + std::to_string(nodeIndex) + "]");
        if (node.mesh >= 0) addMesh(node.mesh, transform);
        for (int child : node.children) addNode(child, transform, depth + 1);
    }
};

std::string base64(const std::vector<unsigned char>& bytes) {
    static const char* const kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::uint32_t b = std::uint32_t(bytes[i]) << 16 |
                                (i + 1 < bytes.size() ? std::uint32_t(bytes[i + 1]) << 8 : 0u) |
                                (i + 2 < bytes.size() ? std::uint32_t(bytes[i + 2]) : 0u);
        out += kAlphabet[(b >> 18) & 63];
        out += kAlphabet[(b >> 12) & 63];
        out += i + 1 < bytes.size() ? kAlphabet[(b >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? kAlphabet[b & 63] : '=';
    }
    return out;
}

}  // namespace

std::string fogMeshToGltf(const FogMesh& mesh, const std::string& name) {
    std::vector<unsigned char> buffer;
    auto append = [&](const void* data, std::size_t size) {
        const auto* p = static_cast<const unsigned char*>(data);
        buffer.insert(buffer.end(), p, p + size);
    };
    float lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    for (std::size_t i = 0; i < mesh.positions().size(); ++i) {
        const float f[3] = {float(mesh.positions()[i].x), float(mesh.positions()[i].y),
                            float(mesh.positions()[i].z)};
        for (int c = 0; c < 3; ++c) {
            lo[c] = i == 0 ? f[c] : std::min(lo[c], f[c]);
            hi[c] = i == 0 ? f[c] : std::max(hi[c], f[c]);
        }
        append(f, sizeof f);
    }
    const std::size_t positionBytes = buffer.size();
    for (const std::uint32_t index : mesh.indices()) append(&index, sizeof index);
    nlohmann::json doc = {
        {"asset", {{"version", "2.0"}, {"generator", "Aerial (aerial_core fogMeshToGltf)"}}},
        {"scene", 0},
        {"scenes", {{{"nodes", {0}}}}},
        {"nodes", {{{"name", name}, {"mesh", 0}}}},
        {"meshes",
         {{{"name", name},
           {"primitives", {{{"attributes", {{"POSITION", 0}}}, {"indices", 1}, {"mode", 4}}}}}}},
        {"accessors",
         {{{"bufferView", 0},
           {"componentType", 5126},
           {"count", mesh.positions().size()},
           {"type", "VEC3"},
           {"min", {lo[0], lo[1], lo[2]}},
           {"max", {hi[0], hi[1], hi[2]}}},
          {{"bufferView", 1},
           {"componentType", 5125},
           {"count", mesh.indices().size()},
           {"type", "SCALAR"}}}},
        {"bufferViews",
         {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", positionBytes}, {"target", 34962}},
          {{"buffer", 0},
           {"byteOffset", positionBytes},
           {"byteLength", buffer.size() - positionBytes},
           {"target", 34963}}}},
        {"buffers",
         {{{"byteLength", buffer.size()},
           {"uri", "data:application/octet-stream;base64," + base64(buffer)}}}},
    };
    return doc.dump(1) + "\n";
}

FogMeshLoadResult loadFogMesh(const std::string& path) {
    FogMeshLoadResult result;
    try {
        std::error_code ec;
        if (!fs::is_regular_file(path, ec)) throw LoadError("no such file");
        const std::uintmax_t size = fs::file_size(path, ec);
        if (ec) throw LoadError("cannot read the file size: " + ec.message());
        if (size > limits::kMaxGltfFileBytes)
            throw LoadError("the file is " + std::to_string(size) + " bytes, over the limit of " +
                            std::to_string(limits::kMaxGltfFileBytes) + " bytes");
        std::string extension = fs::path(path).extension().string();
        for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
        const bool binary = extension == ".glb";
        if (!binary && extension != ".gltf")
            throw LoadError("unsupported extension \"" + extension + "\" (a fog mesh is .gltf or .glb)");

        tinygltf::TinyGLTF gltf;
        gltf.SetImageLoader(&skipImage, nullptr);
        detail::GltfFileLimit limit{limits::kMaxGltfFileBytes};
        gltf.SetFsCallbacks({&detail::gltfFileExists, &detail::gltfExpandNothing, &detail::gltfReadCapped,
                             &detail::gltfRefuseWrite, &limit});
        tinygltf::Model model;
        std::string err, warn;
        const bool ok = binary ? gltf.LoadBinaryFromFile(&model, &err, &warn, path)
                               : gltf.LoadASCIIFromFile(&model, &err, &warn, path);
        if (!ok) throw LoadError("not a valid glTF 2.0 file: " + gltf::oneLine(err.empty() ? warn : err));

        Collector collect{model, {}, {}};
        if (!model.scenes.empty()) {
            const std::size_t scene =
                model.defaultScene >= 0 && std::size_t(model.defaultScene) < model.scenes.size()
                    ? std::size_t(model.defaultScene)
                    : 0;
            for (int node : model.scenes[scene].nodes) collect.addNode(node, glm::dmat4(1.0), 0);
        } else {
            for (std::size_t m = 0; m < model.meshes.size(); ++m) collect.addMesh(int(m), glm::dmat4(1.0));
        }
        if (collect.indices.empty()) throw LoadError("no triangles (no mesh in the scene)");
        std::string why;
        result.mesh = FogMesh::build(collect.positions, collect.indices, why);
        if (!result.mesh) throw LoadError(why);
    } catch (const LoadError& e) {
        result.mesh.reset();
        result.error = path + ": " + e.what();
    } catch (const gltf::LoadError& e) {  // an accessor or a node transform
        result.mesh.reset();
        result.error = path + ": " + e.message;
    } catch (const std::bad_alloc&) {
        result.mesh.reset();
        result.error = path + ": out of memory";
    } catch (const std::exception& e) {  // nlohmann::json inside tinygltf
        result.mesh.reset();
        result.error = path + ": " + e.what();
    }
    return result;
}

namespace detail {

bool gltfReadCapped(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
    const auto* limit = static_cast<const GltfFileLimit*>(user);
    std::error_code ec;
    const std::uintmax_t size = fs::file_size(path, ec);
    if (ec) {
        if (err) *err += "cannot read '" + path + "': " + ec.message() + "\n";
        return false;
    }
    if (size > limit->maxBytes) {
        if (err)
            *err += "'" + path + "' is " + std::to_string(size) + " bytes, over the limit of " +
                    std::to_string(limit->maxBytes) + "\n";
        return false;
    }
    std::ifstream in(path, std::ios::binary);
    out->resize(size);
    if (size > 0 && !in.read(reinterpret_cast<char*>(out->data()), std::streamsize(size))) {
        if (err) *err += "cannot read '" + path + "'\n";
        return false;
    }
    return true;
}

bool gltfFileExists(const std::string& path, void*) {
    std::error_code ec;
    return fs::is_regular_file(path, ec);
}

std::string gltfExpandNothing(const std::string& path, void*) { return path; }

bool gltfRefuseWrite(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err) *err += "writing is not supported\n";
    return false;
}

}  // namespace detail

}  // namespace aerial
