// scene.cpp — meshes made in code: boxes, quads, the built-in terrain.
#include <aerial/renderer/scene.hpp>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace aerial::renderer {

SceneMesh makeBoxMesh(const glm::dvec3& centre, const glm::dvec3& halfExtents, const glm::dquat& rotation,
                      const glm::dvec3& albedo) {
    SceneMesh mesh;
    // Six faces of the unit cube, each with its outward normal n and two
    // in-plane axes u, v (u x v = n, so the winding is counter-clockwise).
    const glm::vec3 normals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (const glm::vec3& n : normals) {
        const glm::vec3 u = std::fabs(n.y) > 0.5f ? glm::vec3(0, 0, n.y) : glm::vec3(-n.z, 0, n.x);
        const glm::vec3 v = glm::cross(n, u);
        const auto base = static_cast<std::uint32_t>(mesh.positions.size());
        for (const glm::vec2 c : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
            mesh.positions.push_back(n + c.x * u + c.y * v);
            mesh.normals.push_back(n);
        }
        for (std::uint32_t k : {0u, 1u, 2u, 0u, 2u, 3u}) mesh.indices.push_back(base + k);
    }
    const glm::dmat4 translate = glm::translate(glm::dmat4(1.0), centre);
    const glm::dmat4 rotate = glm::mat4_cast(glm::normalize(rotation));
    mesh.worldFromObject = translate * rotate * glm::scale(glm::dmat4(1.0), halfExtents);
    mesh.albedo = albedo;
    return mesh;
}

SceneMesh makeQuadMesh(const glm::dvec3& corner, const glm::dvec3& edgeU, const glm::dvec3& edgeV,
                       const glm::dvec3& albedo) {
    SceneMesh mesh;
    const glm::vec3 n = glm::vec3(glm::normalize(glm::cross(edgeU, edgeV)));
    for (const glm::dvec3& p : {corner, corner + edgeU, corner + edgeU + edgeV, corner + edgeV}) {
        mesh.positions.push_back(glm::vec3(p));
        mesh.normals.push_back(n);
    }
    mesh.indices = {0, 1, 2, 0, 2, 3};
    mesh.albedo = albedo;
    return mesh;
}

double builtinTerrainHeight(double x, double z) {
    // A valley along z through x = 0 (parabolic floor), hills from a few
    // sines, flattened on the valley floor.
    const double valley = 40.0 * (1.0 - std::exp(-(x * x) / (2.0 * 90.0 * 90.0)));
    const double hills =
        12.0 * std::sin(x * 0.021 + 0.7) * std::cos(z * 0.017) + 7.0 * std::sin(z * 0.031 + x * 0.011);
    const double floorWeight = 1.0 - std::exp(-(x * x) / (2.0 * 40.0 * 40.0));
    return valley + hills * floorWeight;
}

SceneMesh makeTerrainMesh(double halfSize, int cells) {
    SceneMesh mesh;
    cells = cells < 1 ? 1 : cells;
    const double step = 2.0 * halfSize / cells;
    const double h = 0.5 * step;
    for (int j = 0; j <= cells; ++j) {
        for (int i = 0; i <= cells; ++i) {
            const double x = -halfSize + i * step;
            const double z = -halfSize + j * step;
            mesh.positions.emplace_back(x, builtinTerrainHeight(x, z), z);
            // Central differences of the height give the normal.
            const double dx = (builtinTerrainHeight(x + h, z) - builtinTerrainHeight(x - h, z)) / (2.0 * h);
            const double dz = (builtinTerrainHeight(x, z + h) - builtinTerrainHeight(x, z - h)) / (2.0 * h);
            mesh.normals.push_back(glm::vec3(glm::normalize(glm::dvec3(-dx, 1.0, -dz))));
        }
    }
    const auto row = static_cast<std::uint32_t>(cells + 1);
    for (std::uint32_t j = 0; j < static_cast<std::uint32_t>(cells); ++j) {
        for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(cells); ++i) {
            const std::uint32_t a = j * row + i;
            // Counter-clockwise seen from above (+Y): a, a+row, a+1.
            for (std::uint32_t k : {a, a + row, a + 1, a + 1, a + row, a + row + 1})
                mesh.indices.push_back(k);
        }
    }
    mesh.albedo = glm::dvec3(0.18, 0.22, 0.12);
    return mesh;
}

SceneDesc makeBuiltinScene() {
    SceneDesc scene;
    scene.meshes.push_back(makeTerrainMesh(400.0, 128));
    struct Box {
        glm::dvec3 at, half;
        double yaw;
        glm::dvec3 albedo;
    };
    const Box boxes[] = {
        {{0.0, 0.0, -60.0}, {6.0, 6.0, 6.0}, 0.3, {0.6, 0.55, 0.5}},
        {{12.0, 0.0, -120.0}, {4.0, 14.0, 4.0}, 0.9, {0.5, 0.5, 0.55}},
        {{-15.0, 0.0, -30.0}, {8.0, 3.0, 5.0}, -0.4, {0.55, 0.35, 0.25}},
        {{90.0, 0.0, -150.0}, {10.0, 10.0, 10.0}, 0.2, {0.45, 0.45, 0.45}},
    };
    for (const Box& b : boxes) {
        const glm::dvec3 centre(b.at.x, builtinTerrainHeight(b.at.x, b.at.z) + b.half.y - 0.5, b.at.z);
        scene.meshes.push_back(
            makeBoxMesh(centre, b.half, glm::angleAxis(b.yaw, glm::dvec3(0.0, 1.0, 0.0)), b.albedo));
    }
    return scene;
}

}  // namespace aerial::renderer
