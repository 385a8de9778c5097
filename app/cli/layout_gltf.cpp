// layout_gltf.cpp — the layout of a preset's fog volumes, cloud volumes and
// emitters as a glTF 2.0 document (`aerial bake` writes it as layout.gltf),
// so a level designer sees where the fog is in Blender, Godot, Unity or
// Unreal. Reads an evaluated PresetState (the bake's first time); writes
// nothing itself (command_bake.cpp writes the text atomically).
//
// What the file holds (checked by tests/cli/layout_test.py, also with the
// Khronos glTF validator):
//   - Coordinates: glTF is right-handed, Y up, in metres, and so is Aerial
//     (Y up, north -Z, east +X, metres): positions and rotations are copied
//     unchanged.
//   - One scene, named after the preset, whose root nodes are the fog
//     volumes, then the cloud volumes, then the emitters, in preset order;
//     each node's name is the object's id. translation = position [m],
//     rotation = the unit quaternion [x, y, z, w] (world from object),
//     scale = the half extents [m]: the node maps the object-space shape to
//     the world exactly as aerial/fog_volume.hpp does (world = position +
//     rotation * (halfExtents * object)).
//   - Meshes: a box is the unit cube [-1,1]^3 (8 vertices, 12 triangles),
//     an ellipsoid a low-poly unit sphere (16 segments x 8 rings, its
//     vertices on the sphere), each shared by every box / ellipsoid; a mesh
//     volume is its mesh's welded triangles (FogMesh::positions/indices,
//     object space), one glTF mesh per fog mesh. Positions are float VEC3
//     (with min/max), indices UNSIGNED_INT, counter-clockwise outward; no
//     normals (viewers shade flat). Everything is in one buffer, embedded as
//     a base64 data URI. A mesh volume whose mesh is not loaded has a node
//     and no mesh.
//   - Materials: translucent (alpha blend, double-sided) so the fog does
//     not hide the level: blue-grey for volumes that add fog, red for
//     subtract volumes, white for cloud volumes.
//   - Emitters: a KHR_lights_punctual point light at the emitter's position.
//     glTF colours are 0..1, so color = colour / its largest component and
//     intensity = intensity_cd x that component, in candela as the
//     extension wants (the evaluated colour has unit luminance, so the
//     light's luminous intensity is intensity_cd; lightning flash at that
//     time applied). No range (Aerial's falloff, 1 / (1 + attenuation d^2),
//     has no cutoff).
//   - extras (Blender shows them as custom properties): per node "kind"
//     (fog_volume, cloud_volume, emitter), "name" (the display name),
//     volumes "shape" and "blend", mesh volumes "mesh" (the glTF file as the
//     preset names it, relative to the preset), emitters "flash" (the
//     lightning multiplier applied), and "parameters": every parameter of
//     the object under its preset JSON key, in the preset's units (the
//     parameter table, as in manifest.json). The scene's extras: the preset
//     and the time.
//   - No NaN or Inf: a non-finite translation component is 0, a rotation
//     that is not finite or of zero length the identity, a half extent that
//     is not finite and positive 1e-6 (a degenerate volume); parameters
//     that are not finite are written as null.
#include "layout_gltf.hpp"

#include "cli_common.hpp"

#include <aerial/fog_mesh.hpp>

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

#ifndef AERIAL_VERSION
#define AERIAL_VERSION "unknown"
#endif

namespace aerial::cli {
namespace {

// glTF enumerations (glTF 2.0 specification, 5.1 accessor, 5.11 bufferView,
// 5.24 mesh.primitive).
constexpr int kComponentFloat = 5126;
constexpr int kComponentUnsignedInt = 5125;
constexpr int kTargetArrayBuffer = 34962;
constexpr int kTargetElementArrayBuffer = 34963;
constexpr int kModeTriangles = 4;
constexpr const char* kLightsExtension = "KHR_lights_punctual";

/// The smallest half extent written (a degenerate volume's).
constexpr double kMinScale = 1e-6;

/// Triangles in object space: positions and counter-clockwise-outward
/// triangles into them.
struct Geometry {
    std::vector<glm::vec3> positions;
    std::vector<std::uint32_t> indices;
};

/// The unit cube [-1,1]^3: vertex i has x = bit 0, y = bit 1, z = bit 2.
Geometry unitCube() {
    Geometry g;
    for (int i = 0; i < 8; ++i)
        g.positions.emplace_back(i & 1 ? 1.0f : -1.0f, i & 2 ? 1.0f : -1.0f, i & 4 ? 1.0f : -1.0f);
    // Two triangles per face, counter-clockwise seen from outside.
    g.indices = {0, 2, 3, 0, 3, 1,   // -Z
                 4, 5, 7, 4, 7, 6,   // +Z
                 0, 1, 5, 0, 5, 4,   // -Y
                 2, 6, 7, 2, 7, 3,   // +Y
                 0, 4, 6, 0, 6, 2,   // -X
                 1, 3, 7, 1, 7, 5};  // +X
    return g;
}

/// A UV sphere of radius 1: the poles and `rings - 1` circles of `segments`
/// vertices, all on the sphere.
Geometry unitSphere(int segments, int rings) {
    constexpr double kPi = 3.14159265358979323846;
    Geometry g;
    g.positions.emplace_back(0.0f, 1.0f, 0.0f);  // north pole, index 0
    for (int r = 1; r < rings; ++r) {
        const double theta = kPi * r / rings;  // from +Y
        for (int s = 0; s < segments; ++s) {
            const double phi = 2.0 * kPi * s / segments;
            g.positions.emplace_back(float(std::sin(theta) * std::cos(phi)), float(std::cos(theta)),
                                     float(-std::sin(theta) * std::sin(phi)));
        }
    }
    const auto south = std::uint32_t(g.positions.size());
    g.positions.emplace_back(0.0f, -1.0f, 0.0f);
    // phi grows counter-clockwise seen from +Y (x -> -z), so seen from
    // outside (above) a ring's quads run (ring r, s) -> (r + 1, s) -> (r + 1, s + 1).
    auto at = [segments](int ring, int s) {
        return std::uint32_t(1 + (ring - 1) * segments + (s % segments));
    };
    for (int s = 0; s < segments; ++s) g.indices.insert(g.indices.end(), {0u, at(1, s), at(1, s + 1)});
    for (int r = 1; r + 1 < rings; ++r)
        for (int s = 0; s < segments; ++s)
            g.indices.insert(g.indices.end(), {at(r, s), at(r + 1, s), at(r + 1, s + 1), at(r, s),
                                               at(r + 1, s + 1), at(r, s + 1)});
    for (int s = 0; s < segments; ++s)
        g.indices.insert(g.indices.end(), {at(rings - 1, s), south, at(rings - 1, s + 1)});
    return g;
}

/// A mesh volume's triangles as floats; empty when the mesh has none or an
/// index out of range (never expected from a built FogMesh).
Geometry fogMeshGeometry(const FogMesh& mesh) {
    Geometry g;
    const std::vector<glm::dvec3>& positions = mesh.positions();
    const std::vector<std::uint32_t>& indices = mesh.indices();
    if (positions.empty() || indices.empty() || indices.size() % 3 != 0) return g;
    for (std::uint32_t i : indices)
        if (i >= positions.size()) return g;
    constexpr double kFloatMax = double(std::numeric_limits<float>::max());
    g.positions.reserve(positions.size());
    for (const glm::dvec3& p : positions) {
        glm::vec3 f;
        for (int c = 0; c < 3; ++c)
            f[c] = std::isfinite(p[c]) ? float(std::clamp(p[c], -kFloatMax, kFloatMax)) : 0.0f;
        g.positions.push_back(f);
    }
    g.indices = indices;
    return g;
}

double finiteOr(double value, double fallback) { return std::isfinite(value) ? value : fallback; }

Json translationJson(const glm::dvec3& position) {
    return Json::array({finiteOr(position.x, 0.0), finiteOr(position.y, 0.0), finiteOr(position.z, 0.0)});
}

/// [x, y, z, w], unit length; the identity for a rotation that is not finite
/// or of zero length.
Json rotationJson(const glm::dquat& rotation) {
    const double length = std::sqrt(rotation.x * rotation.x + rotation.y * rotation.y +
                                    rotation.z * rotation.z + rotation.w * rotation.w);
    if (!std::isfinite(length) || length < 1e-12) return Json::array({0.0, 0.0, 0.0, 1.0});
    return Json::array({rotation.x / length, rotation.y / length, rotation.z / length, rotation.w / length});
}

Json scaleJson(const glm::dvec3& halfExtents) {
    Json scale = Json::array();
    for (int c = 0; c < 3; ++c)
        scale.push_back(std::isfinite(halfExtents[c]) && halfExtents[c] > kMinScale ? halfExtents[c]
                                                                                    : kMinScale);
    return scale;
}

const char* shapeName(FogVolumeShape shape) {
    switch (shape) {
        case FogVolumeShape::Box:
            return "box";
        case FogVolumeShape::Ellipsoid:
            return "ellipsoid";
        case FogVolumeShape::Mesh:
            return "mesh";
    }
    return "box";
}

const char* blendName(FogVolumeBlend blend) { return blend == FogVolumeBlend::Subtract ? "subtract" : "add"; }

std::string base64(const std::string& bytes) {
    static constexpr char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
        std::uint32_t chunk = 0;
        for (std::size_t k = 0; k < 3; ++k)
            chunk = (chunk << 8) | (k < n ? std::uint32_t(static_cast<unsigned char>(bytes[i + k])) : 0u);
        for (std::size_t k = 0; k < 4; ++k) out += k <= n ? kDigits[(chunk >> (18 - 6 * k)) & 63u] : '=';
    }
    return out;
}

/// The materials; each is added to the document when first used.
enum class Material { FogAdd, FogSubtract, Cloud };

Json materialJson(Material material) {
    auto make = [](const char* name, const std::vector<double>& rgba) {
        return Json{{"name", name},
                    {"pbrMetallicRoughness",
                     {{"baseColorFactor", rgba}, {"metallicFactor", 0.0}, {"roughnessFactor", 1.0}}},
                    {"alphaMode", "BLEND"},
                    {"doubleSided", true}};
    };
    switch (material) {
        case Material::FogAdd:
            return make("fog_volume_add", {0.70, 0.78, 0.90, 0.30});
        case Material::FogSubtract:
            return make("fog_volume_subtract", {0.90, 0.25, 0.20, 0.30});
        case Material::Cloud:
            return make("cloud_volume", {1.00, 1.00, 1.00, 0.20});
    }
    return make("fog_volume_add", {0.70, 0.78, 0.90, 0.30});
}

/// Builds the buffer, its views and accessors, and the meshes, sharing a
/// geometry between the nodes that use it and a mesh between the nodes that
/// use the same geometry and material.
class LayoutBuilder {
public:
    /// The mesh index of `geometry` (under `key`, computed on first use) in
    /// `material`, or -1 when the geometry has no triangles.
    template <class MakeGeometry>
    int mesh(const void* key, const std::string& name, Material material, MakeGeometry&& make) {
        const auto found = meshes_.find({key, material});
        if (found != meshes_.end()) return found->second;
        auto geometry = geometries_.find(key);
        if (geometry == geometries_.end()) geometry = geometries_.emplace(key, addGeometry(make())).first;
        int index = -1;
        if (geometry->second.first >= 0) {
            auto materialIndex = materials_.find(material);
            if (materialIndex == materials_.end()) {
                materialIndex = materials_.emplace(material, int(materialJson_.size())).first;
                materialJson_.push_back(materialJson(material));
            }
            index = int(meshJson_.size());
            meshJson_.push_back(
                {{"name", name},
                 {"primitives", Json::array({{{"attributes", {{"POSITION", geometry->second.first}}},
                                              {"indices", geometry->second.second},
                                              {"material", materialIndex->second},
                                              {"mode", kModeTriangles}}})}});
        }
        meshes_.emplace(std::make_pair(key, material), index);
        return index;
    }

    /// Adds the buffer, views, accessors and meshes to the document (none
    /// when no node has a mesh: glTF forbids empty arrays).
    void finish(Json& document) const {
        if (meshJson_.empty()) return;
        document["meshes"] = meshJson_;
        document["materials"] = materialJson_;
        document["accessors"] = accessors_;
        document["bufferViews"] = views_;
        document["buffers"] =
            Json::array({{{"byteLength", bytes_.size()},
                          {"uri", "data:application/octet-stream;base64," + base64(bytes_)}}});
    }

private:
    /// (positions accessor, indices accessor), or (-1, -1) for no triangles.
    std::pair<int, int> addGeometry(const Geometry& g) {
        if (g.positions.empty() || g.indices.empty()) return {-1, -1};
        glm::vec3 low(std::numeric_limits<float>::max()), high(std::numeric_limits<float>::lowest());
        const std::size_t positionsStart = bytes_.size();
        for (const glm::vec3& p : g.positions) {
            low = glm::min(low, p), high = glm::max(high, p);
            for (int c = 0; c < 3; ++c) appendWord(std::bit_cast<std::uint32_t>(p[c]));
        }
        const int positionsView = addView(positionsStart, kTargetArrayBuffer);
        const std::size_t indicesStart = bytes_.size();
        for (std::uint32_t i : g.indices) appendWord(i);
        const int indicesView = addView(indicesStart, kTargetElementArrayBuffer);
        auto vec = [](const glm::vec3& v) { return Json::array({double(v.x), double(v.y), double(v.z)}); };
        accessors_.push_back({{"bufferView", positionsView},
                              {"componentType", kComponentFloat},
                              {"count", g.positions.size()},
                              {"type", "VEC3"},
                              {"min", vec(low)},
                              {"max", vec(high)}});
        accessors_.push_back({{"bufferView", indicesView},
                              {"componentType", kComponentUnsignedInt},
                              {"count", g.indices.size()},
                              {"type", "SCALAR"}});
        return {int(accessors_.size()) - 2, int(accessors_.size()) - 1};
    }

    int addView(std::size_t start, int target) {
        views_.push_back({{"buffer", 0},
                          {"byteOffset", start},
                          {"byteLength", bytes_.size() - start},
                          {"target", target}});
        return int(views_.size()) - 1;
    }

    /// Little-endian, as glTF buffers are.
    void appendWord(std::uint32_t word) {
        for (int b = 0; b < 4; ++b) bytes_ += char((word >> (8 * b)) & 0xffu);
    }

    std::string bytes_;
    Json views_ = Json::array();
    Json accessors_ = Json::array();
    Json meshJson_ = Json::array();
    Json materialJson_ = Json::array();
    std::map<Material, int> materials_;
    std::map<const void*, std::pair<int, int>> geometries_;
    std::map<std::pair<const void*, Material>, int> meshes_;
};

// Keys of the shared shapes in LayoutBuilder (their addresses only).
constexpr char kCubeKey = 'c';
constexpr char kSphereKey = 's';

/// The mesh of a box or ellipsoid (or -1 for any other shape).
int primitiveMesh(LayoutBuilder& builder, FogVolumeShape shape, Material material, const char* materialName) {
    if (shape == FogVolumeShape::Box)
        return builder.mesh(&kCubeKey, std::string("unit_cube_") + materialName, material, unitCube);
    if (shape == FogVolumeShape::Ellipsoid)
        return builder.mesh(&kSphereKey, std::string("unit_sphere_") + materialName, material,
                            [] { return unitSphere(16, 8); });
    return -1;
}

Json volumeNode(LayoutBuilder& builder, const FogVolume& v) {
    Json node = {{"name", v.id},
                 {"translation", translationJson(v.position)},
                 {"rotation", rotationJson(v.rotation)},
                 {"scale", scaleJson(v.halfExtents)}};
    const bool subtract = v.blend == FogVolumeBlend::Subtract;
    const Material material = subtract ? Material::FogSubtract : Material::FogAdd;
    const char* materialName = subtract ? "subtract" : "add";
    int mesh = -1;
    if (v.shape == FogVolumeShape::Mesh) {
        if (v.meshData) {
            const FogMesh& fogMesh = *v.meshData;
            mesh = builder.mesh(&fogMesh, v.mesh + " (" + materialName + ")", material,
                                [&fogMesh] { return fogMeshGeometry(fogMesh); });
        }
    } else {
        mesh = primitiveMesh(builder, v.shape, material, materialName);
    }
    if (mesh >= 0) node["mesh"] = mesh;
    Json extras = {{"kind", "fog_volume"},
                   {"name", v.name},
                   {"shape", shapeName(v.shape)},
                   {"blend", blendName(v.blend)}};
    if (v.shape == FogVolumeShape::Mesh) extras["mesh"] = v.mesh;
    extras["parameters"] = parametersToJson(v);
    node["extras"] = std::move(extras);
    return node;
}

Json cloudVolumeNode(LayoutBuilder& builder, const CloudVolume& v) {
    Json node = {{"name", v.id},
                 {"translation", translationJson(v.position)},
                 {"rotation", rotationJson(v.rotation)},
                 {"scale", scaleJson(v.halfExtents)}};
    const int mesh = primitiveMesh(builder, v.shape, Material::Cloud, "cloud");
    if (mesh >= 0) node["mesh"] = mesh;
    node["extras"] = {{"kind", "cloud_volume"},
                      {"name", v.name},
                      {"shape", shapeName(v.shape)},
                      {"parameters", parametersToJson(v)}};
    return node;
}

/// The KHR_lights_punctual light of an emitter (see the header comment).
Json emitterLight(const Emitter& e) {
    glm::dvec3 colour;
    for (int c = 0; c < 3; ++c)
        colour[c] = std::isfinite(e.colour[c]) && e.colour[c] > 0.0 ? e.colour[c] : 0.0;
    const double largest = std::max({colour.x, colour.y, colour.z});
    const double intensity = std::isfinite(e.intensityCd) && e.intensityCd > 0.0 ? e.intensityCd : 0.0;
    Json colourJson = largest > 0.0
                          ? Json::array({colour.x / largest, colour.y / largest, colour.z / largest})
                          : Json::array({1.0, 1.0, 1.0});
    const double scaled = intensity * largest;
    return {{"name", e.id},
            {"type", "point"},
            {"color", std::move(colourJson)},
            {"intensity", std::isfinite(scaled) ? scaled : 0.0}};
}

Json emitterNode(const Emitter& e, double flash, int light) {
    Json node = {{"name", e.id}, {"translation", translationJson(e.position)}};
    node["extensions"] = {{kLightsExtension, {{"light", light}}}};
    node["extras"] = {{"kind", "emitter"},
                      {"name", e.name},
                      {"flash", finiteOr(flash, 0.0)},
                      {"parameters", parametersToJson(e)}};
    return node;
}

}  // namespace

std::string layoutGltf(const PresetState& state, const std::string& presetName) {
    LayoutBuilder builder;
    Json nodes = Json::array();
    for (const FogVolume& v : state.volumes) nodes.push_back(volumeNode(builder, v));
    for (const CloudVolume& v : state.cloudVolumes) nodes.push_back(cloudVolumeNode(builder, v));
    Json lights = Json::array();
    for (std::size_t i = 0; i < state.emitters.size(); ++i) {
        const double flash = i < state.emitterFlash.size() ? state.emitterFlash[i] : 1.0;
        nodes.push_back(emitterNode(state.emitters[i], flash, int(lights.size())));
        lights.push_back(emitterLight(state.emitters[i]));
    }

    Json document = {
        {"asset",
         {{"version", "2.0"},
          {"generator", "Aerial " AERIAL_VERSION " (aerial bake)"},
          {"extras",
           {{"coordinates", "right-handed, Y up, north -Z, east +X, metres (as glTF)"},
            {"what",
             "one node per fog volume, cloud volume and emitter (name = id); scale = half extents of the "
             "unit "
             "cube (box), unit sphere (ellipsoid) or the mesh's own coordinates; extras.parameters as in the "
             "preset"}}}}},
        {"scene", 0}};
    if (!lights.empty()) {
        document["extensionsUsed"] = Json::array({kLightsExtension});
        document["extensions"] = {{kLightsExtension, {{"lights", std::move(lights)}}}};
    }
    Json scene = {{"name", presetName}};
    if (!nodes.empty()) {  // glTF forbids an empty nodes array
        Json roots = Json::array();
        for (std::size_t i = 0; i < nodes.size(); ++i) roots.push_back(i);
        scene["nodes"] = std::move(roots);
    }
    scene["extras"] = {{"preset", presetName},
                       {"time_h", finiteOr(state.timeHours, 0.0)},
                       {"time", formatTime(state.timeHours)}};
    document["scenes"] = Json::array({std::move(scene)});
    if (!nodes.empty()) document["nodes"] = std::move(nodes);
    builder.finish(document);
    return jsonText(document) + "\n";
}

}  // namespace aerial::cli
