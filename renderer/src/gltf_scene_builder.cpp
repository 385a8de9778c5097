// gltf_scene_builder.cpp — a parsed glTF 2.0 model (tinygltf::Model) to a
// SceneDesc: the default scene's node hierarchy instanced (cycles, depth and
// instance counts bounded), triangles with positions, normals (flat where
// absent) and TEXCOORD_0, metallic-roughness materials with alpha modes and
// base-colour textures (decoded to RGBA8, shared between meshes). Every
// accessor is bounds-checked against its buffer view and buffer before a
// byte is read.
#include "gltf_model.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <vector>

namespace aerial::renderer::gltf {
namespace {

class Loader {
public:
    Loader(const tinygltf::Model& model, const GltfLoadOptions& options, GltfLoadResult& result)
        : model_(model), options_(options), result_(result) {}

    void run() {
        for (const std::string& ext : model_.extensionsRequired)
            fail("extensionsRequired", "the file requires extension " + ext + ", which is not supported");
        if (model_.scenes.empty()) fail("scenes", "the file has no scene");
        int sceneIndex = model_.defaultScene;
        if (sceneIndex < 0) sceneIndex = 0;
        if (std::size_t(sceneIndex) >= model_.scenes.size())
            fail("scene", "default scene " + std::to_string(sceneIndex) + " does not exist (" +
                              std::to_string(model_.scenes.size()) + " scenes)");
        onPath_.assign(model_.nodes.size(), false);
        const tinygltf::Scene& scene = model_.scenes[std::size_t(sceneIndex)];
        const std::string element = "scenes[" + std::to_string(sceneIndex) + "].nodes";
        for (int node : scene.nodes) visitNode(node, glm::dmat4(1.0), 0, element);
    }

private:
    void visitNode(int index, const glm::dmat4& parent, int depth, const std::string& referrer) {
        if (index < 0 || std::size_t(index) >= model_.nodes.size())
            fail(referrer, "node " + std::to_string(index) + " does not exist (" +
                               std::to_string(model_.nodes.size()) + " nodes)");
        const std::string element = "nodes[" + std::to_string(index) + "]";
        if (onPath_[std::size_t(index)])
            fail(referrer,
                 "node " + std::to_string(index) + " is its own ancestor (a cycle in the node hierarchy)");
        if (depth >= options_.maxNodeDepth)
            fail(element,
                 "the node hierarchy is deeper than " + std::to_string(options_.maxNodeDepth) + " levels");
        if (++nodeVisits_ > (1u << 20)) fail(element, "more than 1048576 node instances");
        const tinygltf::Node& node = model_.nodes[std::size_t(index)];
        const glm::dmat4 world = parent * nodeTransform(node, element);
        onPath_[std::size_t(index)] = true;
        if (node.mesh >= 0) addMesh(node.mesh, world, element);
        for (int child : node.children) visitNode(child, world, depth + 1, element + ".children");
        onPath_[std::size_t(index)] = false;
    }

    /// Checks accessors[index] against its buffer view and buffer.
    AccessorView view(int index, const std::string& what, const std::string& element) const {
        return accessorView(model_, index, what, element,
                            std::max(options_.maxVertices, options_.maxTriangles * 3));
    }

    static void expect(const AccessorView& v, const tinygltf::Accessor& accessor, int index,
                       const std::string& what, int type, std::initializer_list<int> componentTypes,
                       const std::string& expected, const std::string& element) {
        const std::string a = what + " accessor (accessors[" + std::to_string(index) + "])";
        if (accessor.type != type)
            fail(element, a + " has type " + typeName(accessor.type) + ", expected " + typeName(type));
        if (std::find(componentTypes.begin(), componentTypes.end(), v.componentType) == componentTypes.end())
            fail(element, a + " has componentType " + std::to_string(v.componentType) + " (" +
                              componentTypeName(v.componentType) + "), expected " + expected);
    }

    int attribute(const tinygltf::Primitive& p, const char* name) const {
        const auto it = p.attributes.find(name);
        return it == p.attributes.end() ? -1 : it->second;
    }

    void addMesh(int meshIndex, const glm::dmat4& world, const std::string& nodeElement) {
        if (std::size_t(meshIndex) >= model_.meshes.size())
            fail(nodeElement, "mesh " + std::to_string(meshIndex) + " does not exist (" +
                                  std::to_string(model_.meshes.size()) + " meshes)");
        const tinygltf::Mesh& mesh = model_.meshes[std::size_t(meshIndex)];
        for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
            const std::string element =
                "meshes[" + std::to_string(meshIndex) + "].primitives[" + std::to_string(p) + "]";
            addPrimitive(mesh.primitives[p], world, element);
        }
    }

    void addPrimitive(const tinygltf::Primitive& primitive, const glm::dmat4& world,
                      const std::string& element) {
        const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
        if (mode != TINYGLTF_MODE_TRIANGLES) {
            result_.warnings.push_back(element + ": mode " + std::to_string(mode) + " (" + modeName(mode) +
                                       ") is not supported, only TRIANGLES (4); primitive skipped");
            return;
        }
        SceneMesh out;
        out.worldFromObject = world;

        const int positionIndex = attribute(primitive, "POSITION");
        if (positionIndex < 0) fail(element, "has no POSITION attribute");
        const AccessorView positions = view(positionIndex, "POSITION", element);
        expect(positions, model_.accessors[std::size_t(positionIndex)], positionIndex, "POSITION",
               TINYGLTF_TYPE_VEC3, {TINYGLTF_COMPONENT_TYPE_FLOAT}, "FLOAT (5126)", element);
        const std::uint64_t vertexCount = positions.count;
        totalVertices_ += vertexCount;
        if (totalVertices_ > options_.maxVertices)
            fail(element,
                 "the scene has more than " + std::to_string(options_.maxVertices) + " vertices (the limit)");
        out.positions.resize(vertexCount);
        for (std::uint64_t k = 0; k < vertexCount; ++k) {
            for (int c = 0; c < 3; ++c) {
                const double value = positions.component(k, std::uint64_t(c));
                if (!std::isfinite(value))
                    fail(element, "POSITION " + std::to_string(k) + " has a non-finite coordinate");
                out.positions[k][c] = float(value);
            }
        }

        // Indices: given (uint8/16/32) or 0..n-1.
        if (primitive.indices >= 0) {
            const AccessorView indices = view(primitive.indices, "indices", element);
            expect(indices, model_.accessors[std::size_t(primitive.indices)], primitive.indices, "indices",
                   TINYGLTF_TYPE_SCALAR,
                   {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                    TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT},
                   "UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT", element);
            out.indices.resize(indices.count);
            for (std::uint64_t k = 0; k < indices.count; ++k) {
                const std::uint32_t i = indices.index(k);
                if (i >= vertexCount)
                    fail(element, "index " + std::to_string(i) + " (indices element " + std::to_string(k) +
                                      ") is out of range of the " + std::to_string(vertexCount) +
                                      " vertices");
                out.indices[k] = i;
            }
        } else {
            out.indices.resize(vertexCount);
            for (std::uint64_t k = 0; k < vertexCount; ++k) out.indices[k] = std::uint32_t(k);
        }
        if (out.indices.size() % 3 != 0)
            fail(element,
                 std::to_string(out.indices.size()) + " vertices/indices is not a multiple of 3 (TRIANGLES)");
        totalTriangles_ += out.indices.size() / 3;
        if (totalTriangles_ > options_.maxTriangles)
            fail(element, "the scene has more than " + std::to_string(options_.maxTriangles) +
                              " triangles (the limit)");

        const int texcoordIndex = attribute(primitive, "TEXCOORD_0");
        if (texcoordIndex >= 0) {
            const AccessorView uv = view(texcoordIndex, "TEXCOORD_0", element);
            const tinygltf::Accessor& accessor = model_.accessors[std::size_t(texcoordIndex)];
            expect(uv, accessor, texcoordIndex, "TEXCOORD_0", TINYGLTF_TYPE_VEC2,
                   {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                    TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT},
                   "FLOAT or normalized UNSIGNED_BYTE/UNSIGNED_SHORT", element);
            if (uv.count != vertexCount)
                fail(element, "TEXCOORD_0 has " + std::to_string(uv.count) + " elements, POSITION " +
                                  std::to_string(vertexCount));
            out.texcoords.resize(vertexCount);
            for (std::uint64_t k = 0; k < vertexCount; ++k)
                out.texcoords[k] = glm::vec2(float(uv.component(k, 0)), float(uv.component(k, 1)));
        }

        const int normalIndex = attribute(primitive, "NORMAL");
        if (normalIndex >= 0) {
            const AccessorView normals = view(normalIndex, "NORMAL", element);
            expect(normals, model_.accessors[std::size_t(normalIndex)], normalIndex, "NORMAL",
                   TINYGLTF_TYPE_VEC3, {TINYGLTF_COMPONENT_TYPE_FLOAT}, "FLOAT (5126)", element);
            if (normals.count != vertexCount)
                fail(element, "NORMAL has " + std::to_string(normals.count) + " elements, POSITION " +
                                  std::to_string(vertexCount));
            out.normals.resize(vertexCount);
            bool bad = false;
            for (std::uint64_t k = 0; k < vertexCount; ++k) {
                const glm::dvec3 n(normals.component(k, 0), normals.component(k, 1), normals.component(k, 2));
                const double len = glm::length(n);
                if (!(len > 1e-12) || !std::isfinite(len)) {
                    bad = true;
                    out.normals[k] = glm::vec3(0.0f, 1.0f, 0.0f);
                } else {
                    out.normals[k] = glm::vec3(n / len);
                }
            }
            if (bad) result_.warnings.push_back(element + ": some normals are zero or non-finite; set to +Y");
        } else {
            computeNormals(out);
        }

        // Flat normals give every triangle its own vertices: count what is kept.
        totalVertices_ += out.positions.size() - vertexCount;
        if (totalVertices_ > options_.maxVertices)
            fail(element, "the scene has more than " + std::to_string(options_.maxVertices) +
                              " vertices (the limit, after flat normals)");
        applyMaterial(primitive.material, out, element);
        result_.scene.meshes.push_back(std::move(out));
    }

    void computeNormals(SceneMesh& mesh) const {
        auto faceNormal = [&](std::size_t t, bool areaWeighted) {
            const glm::dvec3 a(mesh.positions[mesh.indices[3 * t]]),
                b(mesh.positions[mesh.indices[3 * t + 1]]), c(mesh.positions[mesh.indices[3 * t + 2]]);
            const glm::dvec3 n = glm::cross(b - a, c - a);
            const double len = glm::length(n);
            if (!(len > 0.0)) return glm::dvec3(0.0);
            return areaWeighted ? n : n / len;
        };
        const std::size_t triangles = mesh.indices.size() / 3;
        if (options_.computedNormals == GltfNormals::Smooth) {
            std::vector<glm::dvec3> sum(mesh.positions.size(), glm::dvec3(0.0));
            for (std::size_t t = 0; t < triangles; ++t) {
                const glm::dvec3 n = faceNormal(t, true);
                for (int k = 0; k < 3; ++k) sum[mesh.indices[3 * t + std::size_t(k)]] += n;
            }
            mesh.normals.resize(mesh.positions.size());
            for (std::size_t k = 0; k < sum.size(); ++k) {
                const double len = glm::length(sum[k]);
                mesh.normals[k] = len > 0.0 ? glm::vec3(sum[k] / len) : glm::vec3(0.0f, 1.0f, 0.0f);
            }
            return;
        }
        // Flat: three vertices of its own per triangle.
        std::vector<glm::vec3> positions;
        std::vector<glm::vec2> texcoords;
        positions.reserve(triangles * 3);
        mesh.normals.clear();
        mesh.normals.reserve(triangles * 3);
        for (std::size_t t = 0; t < triangles; ++t) {
            glm::dvec3 n = faceNormal(t, false);
            if (n == glm::dvec3(0.0)) n = glm::dvec3(0.0, 1.0, 0.0);
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t i = mesh.indices[3 * t + std::size_t(k)];
                positions.push_back(mesh.positions[i]);
                if (!mesh.texcoords.empty()) texcoords.push_back(mesh.texcoords[i]);
                mesh.normals.push_back(glm::vec3(n));
            }
        }
        mesh.positions = std::move(positions);
        mesh.texcoords = std::move(texcoords);
        for (std::size_t k = 0; k < mesh.indices.size(); ++k) mesh.indices[k] = std::uint32_t(k);
    }

    void applyMaterial(int materialIndex, SceneMesh& mesh, const std::string& element) {
        if (materialIndex < 0) {  // the glTF default material
            mesh.albedo = glm::dvec3(1.0);
            mesh.metallic = 1.0;
            mesh.roughness = 1.0;
            return;
        }
        if (std::size_t(materialIndex) >= model_.materials.size())
            fail(element, "material " + std::to_string(materialIndex) + " does not exist (" +
                              std::to_string(model_.materials.size()) + " materials)");
        const std::string m = "materials[" + std::to_string(materialIndex) + "]";
        const tinygltf::Material& material = model_.materials[std::size_t(materialIndex)];
        const tinygltf::PbrMetallicRoughness& pbr = material.pbrMetallicRoughness;
        if (pbr.baseColorFactor.size() != 4) fail(m, "baseColorFactor needs 4 values");
        auto unit = [&](double v, const char* name) {
            if (!(v >= 0.0 && v <= 1.0))
                fail(m, std::string(name) + " " + std::to_string(v) + " is outside [0, 1]");
            return v;
        };
        mesh.albedo = {unit(pbr.baseColorFactor[0], "baseColorFactor"),
                       unit(pbr.baseColorFactor[1], "baseColorFactor"),
                       unit(pbr.baseColorFactor[2], "baseColorFactor")};
        mesh.opacity = unit(pbr.baseColorFactor[3], "baseColorFactor");
        mesh.metallic = unit(pbr.metallicFactor, "metallicFactor");
        mesh.roughness = unit(pbr.roughnessFactor, "roughnessFactor");
        if (material.alphaMode.empty() || material.alphaMode == "OPAQUE")
            mesh.alphaMode = AlphaMode::Opaque;
        else if (material.alphaMode == "MASK")
            mesh.alphaMode = AlphaMode::Mask;
        else if (material.alphaMode == "BLEND")
            mesh.alphaMode = AlphaMode::Blend;
        else
            fail(m, "alphaMode \"" + material.alphaMode + "\" is not OPAQUE, MASK or BLEND");
        mesh.alphaCutoff = material.alphaCutoff;
        if (pbr.baseColorTexture.index >= 0) {
            if (pbr.baseColorTexture.texCoord != 0)
                fail(m, "baseColorTexture uses TEXCOORD_" + std::to_string(pbr.baseColorTexture.texCoord) +
                            "; only TEXCOORD_0 is supported");
            mesh.baseColorTexture =
                texture(pbr.baseColorTexture.index, m + ".pbrMetallicRoughness.baseColorTexture");
            if (mesh.texcoords.empty())
                result_.warnings.push_back(element + ": " + m +
                                           " has a base-colour texture but the primitive has no TEXCOORD_0");
        }
    }

    std::shared_ptr<const SceneTexture> texture(int textureIndex, const std::string& element) {
        if (std::size_t(textureIndex) >= model_.textures.size())
            fail(element, "texture " + std::to_string(textureIndex) + " does not exist");
        const int source = model_.textures[std::size_t(textureIndex)].source;
        const std::string t = "textures[" + std::to_string(textureIndex) + "]";
        if (source < 0 || std::size_t(source) >= model_.images.size())
            fail(t, "source image " + std::to_string(source) + " does not exist");
        if (auto it = textures_.find(source); it != textures_.end()) return it->second;
        const std::string i = "images[" + std::to_string(source) + "]";
        const tinygltf::Image& image = model_.images[std::size_t(source)];
        const std::string label =
            image.uri.empty() || image.uri.rfind("data:", 0) == 0 ? std::string() : " ('" + image.uri + "')";
        if (image.image.empty() || image.width <= 0 || image.height <= 0)
            fail(i + label, "the image could not be loaded (missing file or undecodable data)");
        const int components = image.component;
        const int bits = image.bits;
        if (components < 1 || components > 4 || (bits != 8 && bits != 16))
            fail(i + label, "unsupported pixel layout (" + std::to_string(components) + " channels of " +
                                std::to_string(bits) + " bits)");
        const std::uint64_t pixels = std::uint64_t(image.width) * std::uint64_t(image.height);
        const std::uint64_t bytesPer = std::uint64_t(components) * std::uint64_t(bits / 8);
        if (pixels > (64u << 20) || image.image.size() < pixels * bytesPer)
            fail(i + label, "the decoded image is too large or shorter than width x height");
        auto out = std::make_shared<SceneTexture>();
        out->width = image.width;
        out->height = image.height;
        out->rgba.resize(pixels * 4);
        for (std::uint64_t p = 0; p < pixels; ++p) {
            std::uint8_t v[4] = {0, 0, 0, 255};
            for (int c = 0; c < components; ++c) {
                const std::uint64_t at = (p * std::uint64_t(components) + std::uint64_t(c)) * (bits / 8);
                // 16-bit samples are little-endian from stb; keep the high byte.
                v[c] = bits == 8 ? image.image[at] : image.image[at + 1];
            }
            if (components == 1 || components == 2) {  // grey (+ alpha)
                const std::uint8_t alpha = components == 2 ? v[1] : 255;
                v[1] = v[2] = v[0];
                v[3] = alpha;
            }
            std::memcpy(&out->rgba[p * 4], v, 4);
        }
        textures_[source] = out;
        return out;
    }

    const tinygltf::Model& model_;
    const GltfLoadOptions& options_;
    GltfLoadResult& result_;
    std::vector<bool> onPath_;
    std::uint64_t nodeVisits_ = 0;
    std::uint64_t totalVertices_ = 0;
    std::uint64_t totalTriangles_ = 0;
    std::map<int, std::shared_ptr<const SceneTexture>> textures_;
};

}  // namespace

void buildScene(const tinygltf::Model& model, const GltfLoadOptions& options, GltfLoadResult& result) {
    Loader(model, options, result).run();
}

}  // namespace aerial::renderer::gltf
