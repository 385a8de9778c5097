// scene.cpp — meshes made in code: boxes, quads, the built-in terrain and
// the built-in scene (lake, rocks, buildings, glass, fence, steam).
#include <aerial/renderer/scene.hpp>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <memory>

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
            mesh.texcoords.emplace_back(0.5f * (c.x + 1.0f), 0.5f * (1.0f - c.y));  // image top = +v
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
    mesh.texcoords = {{0.0f, 1.0f}, {1.0f, 1.0f}, {1.0f, 0.0f}, {0.0f, 0.0f}};  // image top along edgeV
    mesh.indices = {0, 1, 2, 0, 2, 3};
    mesh.albedo = albedo;
    return mesh;
}

namespace {
constexpr double kPiD = 3.14159265358979323846;

// The lake basin: a Gaussian dip of the valley floor (depth 3 m, widths
// 28 m across and 38 m along the valley) around (0, 0), and the water level
// (the shore, where the basin reaches it, is an ellipse of about 35 m x 48 m).
constexpr double kLakeCentreZ = 0.0;
constexpr double kLakeLevel = -0.6;
double lakeBasin(double x, double z) {
    const double u = x / 28.0;
    const double w = (z - kLakeCentreZ) / 38.0;
    return -3.0 * std::exp(-(u * u + w * w));
}
}  // namespace

double builtinLakeLevel() { return kLakeLevel; }

double builtinTerrainHeight(double x, double z) {
    // A valley along z through x = 0 (parabolic floor), hills from a few
    // sines, flattened on the valley floor, and the lake's basin.
    const double valley = 40.0 * (1.0 - std::exp(-(x * x) / (2.0 * 90.0 * 90.0)));
    const double hills =
        12.0 * std::sin(x * 0.021 + 0.7) * std::cos(z * 0.017) + 7.0 * std::sin(z * 0.031 + x * 0.011);
    const double floorWeight = 1.0 - std::exp(-(x * x) / (2.0 * 40.0 * 40.0));
    return valley + hills * floorWeight + lakeBasin(x, z);
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

namespace {

/// A small deterministic generator (PCG-style hash of a counter): the
/// built-in scene and the particle sources are the same on every platform.
struct Random {
    std::uint32_t state;
    double next() {  // [0, 1)
        state = state * 747796405u + 2891336453u;
        std::uint32_t w = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
        w = (w >> 22u) ^ w;
        return double(w) / 4294967296.0;
    }
};

/// A rock: an icosphere-like blob (a 10 x 6 latitude-longitude sphere with
/// radial noise), flat-shaded (one normal per triangle).
SceneMesh makeRockMesh(const glm::dvec3& centre, double size, std::uint32_t seed) {
    constexpr int kAround = 10, kRows = 6;
    Random random{seed};
    std::vector<glm::dvec3> ring;
    for (int j = 0; j <= kRows; ++j) {
        const double theta = kPiD * j / kRows;
        for (int i = 0; i < kAround; ++i) {
            const double phi = 2.0 * kPiD * i / kAround;
            const double r = (j == 0 || j == kRows) ? 0.8 : 0.75 + 0.5 * random.next();
            ring.emplace_back(r * std::sin(theta) * std::cos(phi), r * std::cos(theta) * 0.7,
                              r * std::sin(theta) * std::sin(phi));
        }
    }
    SceneMesh mesh;
    auto vertex = [&](int i, int j) { return ring[std::size_t(j) * kAround + std::size_t(i % kAround)]; };
    auto triangle = [&](const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
        const glm::dvec3 n = glm::cross(b - a, c - a);
        if (glm::length(n) < 1e-12) return;
        const auto base = static_cast<std::uint32_t>(mesh.positions.size());
        for (const glm::dvec3& p : {a, b, c}) {
            mesh.positions.push_back(glm::vec3(p));
            mesh.normals.push_back(glm::vec3(glm::normalize(n)));
        }
        mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2});
    };
    for (int j = 0; j < kRows; ++j) {
        for (int i = 0; i < kAround; ++i) {
            // Counter-clockwise seen from outside.
            triangle(vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1));
            triangle(vertex(i, j), vertex(i + 1, j + 1), vertex(i, j + 1));
        }
    }
    mesh.worldFromObject = glm::translate(glm::dmat4(1.0), centre) *
                           glm::mat4_cast(glm::angleAxis(6.0 * random.next(), glm::dvec3(0, 1, 0))) *
                           glm::scale(glm::dmat4(1.0), glm::dvec3(size));
    mesh.albedo = {0.32, 0.31, 0.29};
    mesh.roughness = 0.85;
    return mesh;
}

/// A gabled roof: a triangular prism over a w x d footprint (centred on the
/// origin, ridge along x) of height h, flat-shaded.
SceneMesh makeRoofMesh(double w, double d, double h) {
    SceneMesh mesh;
    const double x = 0.5 * w, z = 0.5 * d;
    auto face = [&](std::initializer_list<glm::dvec3> corners) {
        std::vector<glm::dvec3> c(corners);
        const glm::dvec3 n = glm::normalize(glm::cross(c[1] - c[0], c[2] - c[0]));
        const auto base = static_cast<std::uint32_t>(mesh.positions.size());
        for (const glm::dvec3& p : c) {
            mesh.positions.push_back(glm::vec3(p));
            mesh.normals.push_back(glm::vec3(n));
        }
        for (std::uint32_t k = 1; k + 1 < c.size(); ++k)
            mesh.indices.insert(mesh.indices.end(), {base, base + k, base + k + 1});
    };
    const glm::dvec3 ridgeW(-x, h, 0.0), ridgeE(x, h, 0.0);
    face({{-x, 0, z}, {x, 0, z}, ridgeE, ridgeW});    // south slope
    face({{x, 0, -z}, {-x, 0, -z}, ridgeW, ridgeE});  // north slope
    face({{-x, 0, -z}, {-x, 0, z}, ridgeW});          // west gable
    face({{x, 0, z}, {x, 0, -z}, ridgeE});            // east gable
    mesh.albedo = {0.45, 0.16, 0.1};
    mesh.roughness = 0.7;
    return mesh;
}

/// A facade: plaster with rows of dark, glossy-looking windows (sRGB).
std::shared_ptr<const SceneTexture> makeFacadeTexture() {
    auto t = std::make_shared<SceneTexture>();
    t->width = t->height = 32;
    t->rgba.resize(32 * 32 * 4);
    for (int y = 0; y < 32; ++y) {
        for (int x = 0; x < 32; ++x) {
            const bool window = (x % 16) >= 4 && (x % 16) < 12 && (y % 16) >= 3 && (y % 16) < 12;
            const bool frame = !window && (x % 16) >= 3 && (x % 16) < 13 && (y % 16) >= 2 && (y % 16) < 13;
            static constexpr std::uint8_t kWindow[4] = {48, 62, 78, 255};
            static constexpr std::uint8_t kFrame[4] = {235, 232, 222, 255};
            static constexpr std::uint8_t kPlaster[4] = {200, 184, 160, 255};
            const std::uint8_t* c = window ? kWindow : frame ? kFrame : kPlaster;
            std::copy(c, c + 4, t->rgba.begin() + (std::size_t(y) * 32 + std::size_t(x)) * 4);
        }
    }
    return t;
}

/// A picket fence: opaque vertical boards and rails, transparent gaps
/// (alpha 0) for the alpha-mask mode.
std::shared_ptr<const SceneTexture> makeFenceTexture() {
    auto t = std::make_shared<SceneTexture>();
    t->width = t->height = 32;
    t->rgba.resize(32 * 32 * 4);
    for (int y = 0; y < 32; ++y) {
        for (int x = 0; x < 32; ++x) {
            const bool board = (x % 8) < 5 && y >= 2;
            const bool rail = (y >= 8 && y < 11) || (y >= 22 && y < 25);
            const std::uint8_t a = (board || rail) ? 255 : 0;
            const std::uint8_t g = std::uint8_t(150 + (x % 8) * 6);
            const std::uint8_t rgba[4] = {std::uint8_t(g + 20), g, std::uint8_t(g - 40), a};
            std::copy(rgba, rgba + 4, t->rgba.begin() + (std::size_t(y) * 32 + std::size_t(x)) * 4);
        }
    }
    return t;
}

/// A box standing on the terrain at (x, z) with its texture coordinates in
/// units of `tile` metres.
SceneMesh standingBox(double x, double z, const glm::dvec3& half, double yaw, double tile) {
    const glm::dvec3 centre(x, builtinTerrainHeight(x, z) + half.y - 0.5, z);
    SceneMesh box = makeBoxMesh(centre, half, glm::angleAxis(yaw, glm::dvec3(0.0, 1.0, 0.0)));
    // makeBoxMesh's faces: +x, -x, +y, -y, +z, -z, 4 vertices each; scale
    // each face's 0..1 coordinates by its size in tiles.
    for (std::size_t v = 0; v < box.texcoords.size(); ++v) {
        const glm::vec3 n = box.normals[v];
        const double across = std::fabs(n.x) > 0.5 ? half.z : half.x;
        const double up = std::fabs(n.y) > 0.5 ? half.z : half.y;
        box.texcoords[v] *= glm::vec2(float(2.0 * across / tile), float(2.0 * up / tile));
    }
    return box;
}

}  // namespace

std::vector<FogSprite> makeFogParticleSource(const glm::dvec3& base, double radius, double height, int count,
                                             std::uint32_t seed) {
    std::vector<FogSprite> sprites;
    count = std::clamp(count, 0, 1 << 16);
    Random random{seed};
    for (int i = 0; i < count; ++i) {
        const double t = (i + 0.5) / count;  // 0 at the source, 1 at the top
        const double angle = 2.0 * kPiD * random.next();
        const double spread = radius * (0.15 + 0.85 * t) * std::sqrt(random.next());
        FogSprite p;
        p.position = base + glm::dvec3(spread * std::cos(angle), height * t, spread * std::sin(angle));
        p.radius = radius * (0.35 + 0.45 * t + 0.2 * random.next());
        p.albedo = glm::dvec3(0.9);
        p.opacity = 0.45 * (1.0 - 0.7 * t);
        p.fadeDistance = std::max(0.25 * radius, 0.1);
        sprites.push_back(p);
    }
    return sprites;
}

SceneDesc makeBuiltinScene() {
    SceneDesc scene;
    SceneMesh terrain = makeTerrainMesh(400.0, 128);
    terrain.roughness = 1.0;  // (no sky-reflection lookup: cheap on llvmpipe)
    terrain.specularFactor = 0.5;
    scene.meshes.push_back(terrain);

    // The lake: flat water in the basin, dark and slightly specular (smooth
    // dielectric, F0 = 0.04 x 0.5: mostly the sky's reflection near grazing).
    SceneMesh lake = makeQuadMesh({-45.0, kLakeLevel, kLakeCentreZ + 60.0}, {90.0, 0.0, 0.0},
                                  {0.0, 0.0, -120.0}, glm::dvec3(0.03, 0.06, 0.07));
    lake.roughness = 0.08;
    lake.specularFactor = 0.5;
    scene.meshes.push_back(lake);

    // Rocks on the shore and the slopes.
    const glm::dvec3 rocks[] = {{-30.0, 0, 10.0}, {26.0, 0, 62.0},  {34.0, 0, 0.0},
                                {-44.0, 0, 70.0}, {55.0, 0, -40.0}, {-60.0, 0, -80.0}};
    std::uint32_t seed = 11;
    for (const glm::dvec3& r : rocks) {
        const double size = 2.0 + 2.0 * Random{seed}.next();
        scene.meshes.push_back(
            makeRockMesh({r.x, builtinTerrainHeight(r.x, r.z) + 0.3 * size, r.z}, size, seed));
        seed += 7;
    }

    // Buildings: textured walls (sRGB facade) with gabled roofs.
    const std::shared_ptr<const SceneTexture> facade = makeFacadeTexture();
    struct House {
        double x, z, yaw;
        glm::dvec3 half;
    };
    const House houses[] = {
        {0.0, -60.0, 0.3, {6.0, 6.0, 6.0}},
        {-45.0, -35.0, -0.4, {8.0, 3.0, 5.0}},
        {90.0, -150.0, 0.2, {10.0, 10.0, 10.0}},
        {-48.0, -95.0, 0.7, {5.0, 4.0, 7.0}},
    };
    for (const House& h : houses) {
        SceneMesh walls = standingBox(h.x, h.z, h.half, h.yaw, 4.0);
        walls.albedo = glm::dvec3(1.0);
        walls.baseColorTexture = facade;
        walls.roughness = 0.8;
        scene.meshes.push_back(walls);
        SceneMesh roof = makeRoofMesh(2.0 * h.half.x + 1.0, 2.0 * h.half.z + 1.0, 0.6 * h.half.z);
        const double top = builtinTerrainHeight(h.x, h.z) + 2.0 * h.half.y - 0.5;
        roof.worldFromObject = glm::translate(glm::dmat4(1.0), glm::dvec3(h.x, top, h.z)) *
                               glm::mat4_cast(glm::angleAxis(h.yaw, glm::dvec3(0.0, 1.0, 0.0)));
        scene.meshes.push_back(roof);
    }
    // A metal mast (brushed steel) and a concrete tower.
    SceneMesh mast = standingBox(12.0, -120.0, {0.6, 16.0, 0.6}, 0.9, 4.0);
    mast.albedo = {0.91, 0.92, 0.92};
    mast.metallic = 1.0;
    mast.roughness = 0.35;
    scene.meshes.push_back(mast);

    // A fence west of the lake, facing the default camera: alpha-masked boards.
    const std::shared_ptr<const SceneTexture> boards = makeFenceTexture();
    for (int k = 0; k < 4; ++k) {
        const double x0 = -64.0 + 6.0 * k;
        const double y0 =
            std::min(builtinTerrainHeight(x0, 48.0), builtinTerrainHeight(x0 + 6.0, 48.0)) - 0.2;
        SceneMesh fence = makeQuadMesh({x0, y0, 48.0}, {6.0, 0.0, 0.0}, {0.0, 1.6, 0.0});
        for (glm::vec2& uv : fence.texcoords) uv.x *= 2.0f;  // two tiles across 6 m
        fence.albedo = glm::dvec3(1.0);
        fence.baseColorTexture = boards;
        fence.alphaMode = AlphaMode::Mask;
        fence.alphaCutoff = 0.5;
        fence.roughness = 0.9;
        scene.meshes.push_back(fence);
    }

    // Alpha-blended objects: a glass shelter east of the lake (three panes
    // and a tinted roof pane), a greenhouse (a glass box) west of it and a
    // translucent red sail on the water.
    auto glass = [](SceneMesh m, const glm::dvec3& tint, double opacity) {
        m.albedo = tint;
        m.opacity = opacity;
        m.alphaMode = AlphaMode::Blend;
        m.roughness = 0.05;
        return m;
    };
    const glm::dvec3 glassTint(0.75, 0.88, 0.9);
    const double sx = 14.0, sz = 62.0;  // the shelter's south-west corner
    const double sy = std::min(builtinTerrainHeight(sx, sz), builtinTerrainHeight(sx + 8.0, sz)) - 0.1;
    scene.meshes.push_back(
        glass(makeQuadMesh({sx, sy, sz}, {8.0, 0.0, 0.0}, {0.0, 2.8, 0.0}), glassTint, 0.2));
    scene.meshes.push_back(
        glass(makeQuadMesh({sx, sy, sz - 4.0}, {0.0, 0.0, 4.0}, {0.0, 2.8, 0.0}), glassTint, 0.2));
    scene.meshes.push_back(
        glass(makeQuadMesh({sx + 8.0, sy, sz}, {0.0, 0.0, -4.0}, {0.0, 2.8, 0.0}), glassTint, 0.2));
    scene.meshes.push_back(
        glass(makeQuadMesh({sx - 0.5, sy + 2.8, sz + 0.5}, {9.0, 0.0, 0.0}, {0.0, 0.0, -5.0}),
              glm::dvec3(0.55, 0.75, 0.6), 0.45));
    SceneMesh greenhouse = standingBox(-24.0, 58.0, {5.0, 2.5, 3.5}, 0.25, 4.0);
    scene.meshes.push_back(glass(greenhouse, glm::dvec3(0.8, 0.95, 0.85), 0.25));
    SceneMesh sail = makeQuadMesh({6.0, kLakeLevel + 0.6, 14.0}, {5.0, 0.0, -1.5}, {-0.8, 6.5, 0.0});
    sail = glass(sail, glm::dvec3(0.8, 0.12, 0.08), 0.6);
    sail.roughness = 0.9;
    scene.meshes.push_back(sail);

    // The river: flowing down the valley into the lake, along the bends
    // misty_river_farm's river mist follows (scripts/make_fog_meshes.py:
    // x = 18 sin(z / 45)), 9 m wide, a hand's breadth above the ground it
    // runs over; the same water as the lake.
    {
        SceneMesh river;
        constexpr int kSteps = 96;
        constexpr double kZ0 = -30.0, kZ1 = -300.0, kHalfWidth = 4.5;
        for (int i = 0; i <= kSteps; ++i) {
            const double z = kZ0 + (kZ1 - kZ0) * i / kSteps;
            const double x = 18.0 * std::sin(z / 45.0);
            // Across the flow: the path's direction (dx/dz, 1) turned a quarter.
            const glm::dvec2 across = glm::normalize(glm::dvec2(1.0, -18.0 / 45.0 * std::cos(z / 45.0)));
            for (double side : {-1.0, 1.0}) {
                const double px = x + side * kHalfWidth * across.x, pz = z + side * kHalfWidth * across.y;
                river.positions.emplace_back(float(px), float(builtinTerrainHeight(px, pz) + 0.12), float(pz));
                river.normals.emplace_back(0.0f, 1.0f, 0.0f);
                river.texcoords.emplace_back(float(side > 0.0), float(i) / 8.0f);
            }
            if (i > 0) {
                const std::uint32_t a = std::uint32_t(2 * i - 2);
                // Counter-clockwise seen from above (+y).
                for (std::uint32_t k : {a, a + 1, a + 2, a + 1, a + 3, a + 2}) river.indices.push_back(k);
            }
        }
        river.albedo = glm::dvec3(0.03, 0.06, 0.07);
        river.roughness = 0.08;
        river.specularFactor = 0.5;
        scene.meshes.push_back(std::move(river));
    }

    // The farm yard round the house at (0, -60) (misty_river_farm keeps it
    // clear of fog): a barn and a picket fence round a 36 m square.
    {
        SceneMesh barn = standingBox(13.0, -72.0, {5.0, 3.5, 9.0}, 0.3, 4.0);
        barn.albedo = glm::dvec3(0.55, 0.2, 0.14);
        barn.roughness = 0.85;
        scene.meshes.push_back(barn);
        SceneMesh barnRoof = makeRoofMesh(11.0, 19.0, 3.0);
        barnRoof.albedo = glm::dvec3(0.25, 0.25, 0.27);
        barnRoof.worldFromObject =
            glm::translate(glm::dmat4(1.0), glm::dvec3(13.0, builtinTerrainHeight(13.0, -72.0) + 6.5, -72.0)) *
            glm::mat4_cast(glm::angleAxis(0.3, glm::dvec3(0.0, 1.0, 0.0)));
        scene.meshes.push_back(barnRoof);
        constexpr double kYardHalf = 18.0, kPanel = 6.0;
        const glm::dvec2 centre(0.0, -60.0);
        const glm::dvec2 corners[] = {{-kYardHalf, kYardHalf}, {kYardHalf, kYardHalf}, {kYardHalf, -kYardHalf},
                                      {-kYardHalf, -kYardHalf}};
        for (int side = 0; side < 4; ++side) {
            const glm::dvec2 a = centre + corners[side], b = centre + corners[(side + 1) % 4];
            const int panels = int(std::round(glm::length(b - a) / kPanel));
            for (int k = 0; k < panels; ++k) {
                if (side == 0 && k == panels / 2) continue;  // the gate, towards the camera
                const glm::dvec2 p0 = a + (b - a) * (double(k) / panels), p1 = a + (b - a) * (double(k + 1) / panels);
                const double y0 = std::min(builtinTerrainHeight(p0.x, p0.y), builtinTerrainHeight(p1.x, p1.y)) - 0.2;
                SceneMesh fence = makeQuadMesh({p0.x, y0, p0.y}, {p1.x - p0.x, 0.0, p1.y - p0.y}, {0.0, 1.4, 0.0});
                for (glm::vec2& uv : fence.texcoords) uv.x *= 2.0f;
                fence.albedo = glm::dvec3(1.0);
                fence.baseColorTexture = boards;
                fence.alphaMode = AlphaMode::Mask;
                fence.alphaCutoff = 0.5;
                fence.roughness = 0.9;
                scene.meshes.push_back(std::move(fence));
            }
        }
    }

    // The particle fog source: steam rising from the east side of the lake.
    scene.sprites = makeFogParticleSource({28.0, kLakeLevel, -6.0}, 7.0, 26.0, 28, 7u);
    return scene;
}

}  // namespace aerial::renderer
