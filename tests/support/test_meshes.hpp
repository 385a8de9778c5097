// test_meshes.hpp — closed, outward-oriented triangle meshes for the mesh
// fog volume tests (aerial/fog_mesh.hpp), generated in code, and their
// exact ray intervals where the tests need them.
#pragma once

#include <glm/trigonometric.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <cstdint>
#include <vector>

namespace aerial::test {

struct TriangleMesh {
    std::vector<glm::dvec3> positions;
    std::vector<std::uint32_t> indices;  ///< 3 per triangle, counter-clockwise from outside
};

/// The cube [-1, 1]^3, 12 triangles, 8 shared vertices.
inline TriangleMesh cubeMesh() {
    TriangleMesh m;
    for (int i = 0; i < 8; ++i) {
        m.positions.push_back({(i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 1.0 : -1.0});
    }
    // Each face as a quad a b c d, counter-clockwise seen from outside.
    const std::uint32_t quads[6][4] = {
        {1, 3, 7, 5},  // +X
        {0, 4, 6, 2},  // -X
        {2, 6, 7, 3},  // +Y
        {0, 1, 5, 4},  // -Y
        {4, 5, 7, 6},  // +Z
        {0, 2, 3, 1},  // -Z
    };
    for (const auto& q : quads) {
        m.indices.insert(m.indices.end(), {q[0], q[1], q[2], q[0], q[2], q[3]});
    }
    return m;
}

/// A torus around the Y axis: ring radius R, tube radius r (R > r), with
/// `around` segments around the axis and `tube` around the tube. A polygon
/// approximation: rays are checked against its own triangles, not the
/// smooth torus.
inline TriangleMesh torusMesh(double ringRadius, double tubeRadius, int around = 32, int tube = 16) {
    TriangleMesh m;
    const double twoPi = 6.283185307179586;
    for (int i = 0; i < around; ++i) {
        const double u = twoPi * i / around;
        for (int j = 0; j < tube; ++j) {
            const double v = twoPi * j / tube;
            const double radial = ringRadius + tubeRadius * std::cos(v);
            m.positions.push_back({radial * std::cos(u), tubeRadius * std::sin(v), radial * std::sin(u)});
        }
    }
    auto at = [&](int i, int j) { return std::uint32_t(((i + around) % around) * tube + (j + tube) % tube); };
    for (int i = 0; i < around; ++i) {
        for (int j = 0; j < tube; ++j) {
            // Outward: u runs towards +Z from +X (clockwise seen from +Y),
            // v runs from outside over the top; (a, c, b) faces out.
            const std::uint32_t a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
            m.indices.insert(m.indices.end(), {a, c, b, a, d, c});
        }
    }
    return m;
}

}  // namespace aerial::test
