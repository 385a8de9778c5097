// fog_mesh.cpp — FogMesh: the checks that make a triangle mesh a fog
// volume (closed, manifold, consistently and outward oriented, no degenerate
// triangle; aerial/fog_mesh.hpp), and its chords along a line through a BVH
// over the triangles.
//
// Exactness: the chords come from the crossings of the line with the
// triangles (Moeller-Trumbore in double precision, edges inclusive), so a
// box built from triangles gives the box's interval to rounding. A crossing
// counted on both triangles of an edge is merged (same sign, within 1e-12 of
// the mesh's size); the winding count (entries minus exits) then says where
// the line is inside.
#include <aerial/fog_mesh.hpp>
#include <aerial/limits.hpp>

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <sstream>
#include <unordered_map>
#include <utility>

namespace aerial {
namespace {

std::string pointText(const glm::dvec3& p) {
    std::ostringstream s;
    s.precision(6);
    s << "(" << p.x << ", " << p.y << ", " << p.z << ")";
    return s.str();
}

/// Exact-position key for welding (-0 and +0 are one position).
struct PositionKey {
    std::array<std::uint64_t, 3> bits;
    bool operator==(const PositionKey& o) const { return bits == o.bits; }
};
struct PositionHash {
    std::size_t operator()(const PositionKey& k) const {
        std::uint64_t h = 1469598103934665603ull;
        for (std::uint64_t b : k.bits) h = (h ^ b) * 1099511628211ull;
        return std::size_t(h);
    }
};
PositionKey keyOf(const glm::dvec3& p) {
    PositionKey k;
    for (int i = 0; i < 3; ++i) {
        const double v = p[i] == 0.0 ? 0.0 : p[i];
        std::memcpy(&k.bits[std::size_t(i)], &v, sizeof v);
    }
    return k;
}

struct Node {
    glm::dvec3 lo{0.0}, hi{0.0};
    std::uint32_t leftOrFirst = 0;  ///< inner: left child (right = left + 1); leaf: first triangle
    std::uint32_t count = 0;        ///< triangles in a leaf, 0 for an inner node
};

/// Slab test of the line o + t d against a box, t unrestricted; conservative
/// (a tiny pad), NaN-free for zero direction components.
bool lineHitsBox(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& lo, const glm::dvec3& hi) {
    double tNear = -std::numeric_limits<double>::infinity();
    double tFar = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 3; ++i) {
        const double pad = 1e-9 * (std::fabs(lo[i]) + std::fabs(hi[i])) + 1e-300;
        const double a = lo[i] - pad, b = hi[i] + pad;
        if (d[i] != 0.0) {
            const double t1 = (a - o[i]) / d[i], t2 = (b - o[i]) / d[i];
            tNear = std::max(tNear, std::min(t1, t2));
            tFar = std::min(tFar, std::max(t1, t2));
        } else if (o[i] < a || o[i] > b) {
            return false;
        }
    }
    return tNear <= tFar;
}

}  // namespace

struct FogMesh::Impl {
    std::vector<glm::dvec3> positions;
    std::vector<std::uint32_t> indices;
    std::vector<std::uint32_t> order;  ///< triangles in BVH leaf order
    std::vector<Node> nodes;
    glm::dvec3 lo{0.0}, hi{0.0};
    double volume = 0.0;
    double mergeEpsilon = 0.0;  ///< object-space distance within which equal-sign crossings merge

    glm::dvec3 vertex(std::uint32_t triangle, int corner) const {
        return positions[indices[3 * std::size_t(triangle) + std::size_t(corner)]];
    }

    void buildBvh() {
        const std::uint32_t n = std::uint32_t(indices.size() / 3);
        order.resize(n);
        std::vector<glm::dvec3> centroid(n);
        for (std::uint32_t i = 0; i < n; ++i) {
            order[i] = i;
            centroid[i] = (vertex(i, 0) + vertex(i, 1) + vertex(i, 2)) / 3.0;
        }
        nodes.reserve(2 * std::size_t(n));
        nodes.push_back({});
        // Iterative top-down build, median split on the longest centroid axis.
        struct Task {
            std::uint32_t node, first, count;
        };
        std::vector<Task> stack{{0, 0, n}};
        while (!stack.empty()) {
            const Task task = stack.back();
            stack.pop_back();
            Node& node = nodes[task.node];
            node.lo = glm::dvec3(std::numeric_limits<double>::infinity());
            node.hi = -node.lo;
            glm::dvec3 cLo = node.lo, cHi = node.hi;
            for (std::uint32_t k = task.first; k < task.first + task.count; ++k) {
                for (int c = 0; c < 3; ++c) {
                    node.lo = glm::min(node.lo, vertex(order[k], c));
                    node.hi = glm::max(node.hi, vertex(order[k], c));
                }
                cLo = glm::min(cLo, centroid[order[k]]);
                cHi = glm::max(cHi, centroid[order[k]]);
            }
            if (task.count <= 4) {
                node.leftOrFirst = task.first;
                node.count = task.count;
                continue;
            }
            const glm::dvec3 extent = cHi - cLo;
            const int axis =
                extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
            const std::uint32_t half = task.count / 2;
            auto first = order.begin() + task.first;
            std::nth_element(first, first + half, first + task.count, [&](std::uint32_t a, std::uint32_t b) {
                return centroid[a][axis] < centroid[b][axis];
            });
            const std::uint32_t left = std::uint32_t(nodes.size());
            nodes[task.node].leftOrFirst = left;
            nodes[task.node].count = 0;
            nodes.push_back({});
            nodes.push_back({});
            stack.push_back({left, task.first, half});
            stack.push_back({left + 1, task.first + half, task.count - half});
        }
    }

    /// Every crossing of the line with a triangle: (t, +1 entry / -1 exit).
    void crossings(const glm::dvec3& o, const glm::dvec3& d, std::vector<std::pair<double, int>>& out) const {
        std::uint32_t stack[64];
        int top = 0;
        stack[top++] = 0;
        while (top > 0) {
            const Node& node = nodes[stack[--top]];
            if (!lineHitsBox(o, d, node.lo, node.hi)) continue;
            if (node.count == 0) {
                if (top + 2 > 64) continue;  // depth is ~log2(n / 4) < 20
                stack[top++] = node.leftOrFirst;
                stack[top++] = node.leftOrFirst + 1;
                continue;
            }
            for (std::uint32_t k = node.leftOrFirst; k < node.leftOrFirst + node.count; ++k) {
                const glm::dvec3 a = vertex(order[k], 0), b = vertex(order[k], 1), c = vertex(order[k], 2);
                const glm::dvec3 e1 = b - a, e2 = c - a;
                const glm::dvec3 p = glm::cross(d, e2);
                const double det = glm::dot(e1, p);
                if (det == 0.0 || !std::isfinite(det)) continue;  // parallel to the plane
                const double inv = 1.0 / det;
                const glm::dvec3 s = o - a;
                const double u = glm::dot(s, p) * inv;
                if (u < 0.0 || u > 1.0) continue;
                const glm::dvec3 q = glm::cross(s, e1);
                const double v = glm::dot(d, q) * inv;
                if (v < 0.0 || u + v > 1.0) continue;
                const double t = glm::dot(e2, q) * inv;
                if (!std::isfinite(t)) continue;
                // Outward normal e1 x e2: moving against it is an entry.
                out.push_back({t, det > 0.0 ? 1 : -1});
            }
        }
    }
};

FogMesh::FogMesh() : impl_(std::make_unique<Impl>()) {}
FogMesh::~FogMesh() = default;

std::shared_ptr<const FogMesh> FogMesh::build(const std::vector<glm::dvec3>& positions,
                                              const std::vector<std::uint32_t>& indices, std::string& error) {
    error.clear();
    if (indices.empty() || indices.size() % 3 != 0) {
        error = indices.empty()
                    ? "no triangles"
                    : "the index count " + std::to_string(indices.size()) + " is not a multiple of 3";
        return nullptr;
    }
    const std::size_t triangles = indices.size() / 3;
    if (triangles > limits::kMaxFogMeshTriangles) {
        error = std::to_string(triangles) + " triangles, over the limit of " +
                std::to_string(limits::kMaxFogMeshTriangles) + " for a fog volume mesh";
        return nullptr;
    }
    std::shared_ptr<FogMesh> mesh(new FogMesh());
    Impl& m = *mesh->impl_;
    // Weld equal positions.
    std::unordered_map<PositionKey, std::uint32_t, PositionHash> welded;
    std::vector<std::uint32_t> remap(positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i) {
        const glm::dvec3& p = positions[i];
        if (!(std::fabs(p.x) <= limits::kMaxCoordinate && std::fabs(p.y) <= limits::kMaxCoordinate &&
              std::fabs(p.z) <= limits::kMaxCoordinate)) {
            error = "vertex " + std::to_string(i) + " is not finite or beyond 1e30";
            return nullptr;
        }
        const auto [it, inserted] = welded.try_emplace(keyOf(p), std::uint32_t(m.positions.size()));
        if (inserted) m.positions.push_back(p);
        remap[i] = it->second;
    }
    m.indices.resize(indices.size());
    for (std::size_t i = 0; i < indices.size(); ++i) {
        if (indices[i] >= positions.size()) {
            error = "triangle " + std::to_string(i / 3) + " refers to vertex " + std::to_string(indices[i]) +
                    " of " + std::to_string(positions.size());
            return nullptr;
        }
        m.indices[i] = remap[indices[i]];
    }
    // Degenerate triangles, directed edges, enclosed volume.
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::pair<int, std::uint32_t>>
        edges;  // count, a triangle
    double volume = 0.0;
    for (std::uint32_t t = 0; t < triangles; ++t) {
        const std::uint32_t i[3] = {m.indices[3 * t], m.indices[3 * t + 1], m.indices[3 * t + 2]};
        const glm::dvec3 a = m.positions[i[0]], b = m.positions[i[1]], c = m.positions[i[2]];
        if (i[0] == i[1] || i[1] == i[2] || i[0] == i[2] || !(glm::length(glm::cross(b - a, c - a)) > 0.0)) {
            error = "triangle " + std::to_string(t) + " is degenerate (zero area) at " + pointText(a);
            return nullptr;
        }
        volume += glm::dot(a, glm::cross(b, c)) / 6.0;
        for (int e = 0; e < 3; ++e) {
            auto& entry = edges[{i[e], i[(e + 1) % 3]}];
            ++entry.first;
            entry.second = t;
        }
    }
    for (const auto& [edge, entry] : edges) {
        const auto reverse = edges.find({edge.second, edge.first});
        const int back = reverse == edges.end() ? 0 : reverse->second.first;
        const std::string where =
            " between " + pointText(m.positions[edge.first]) + " and " + pointText(m.positions[edge.second]);
        if (entry.first + back > 2) {
            error = "non-manifold edge" + where + " (shared by " + std::to_string(entry.first + back) +
                    " triangles; a fog mesh is a closed surface)";
            return nullptr;
        }
        if (entry.first == 2) {
            error = "flipped triangle " + std::to_string(entry.second) + ": the edge" + where +
                    " runs the same way in both its triangles (the mesh is not consistently oriented)";
            return nullptr;
        }
        if (back == 0) {
            error = "open edge" + where + " (triangle " + std::to_string(entry.second) +
                    "; a fog mesh must be closed)";
            return nullptr;
        }
    }
    if (!(volume > 0.0)) {
        error = "the triangles face inwards (enclosed volume " + std::to_string(volume) +
                " < 0); flip the normals so they point out of the fog";
        return nullptr;
    }
    m.volume = volume;
    m.lo = glm::dvec3(std::numeric_limits<double>::infinity());
    m.hi = -m.lo;
    for (const glm::dvec3& p : m.positions) {
        m.lo = glm::min(m.lo, p);
        m.hi = glm::max(m.hi, p);
    }
    m.mergeEpsilon = 1e-12 * glm::length(m.hi - m.lo);
    m.buildBvh();
    return mesh;
}

const std::vector<glm::dvec3>& FogMesh::positions() const { return impl_->positions; }
const std::vector<std::uint32_t>& FogMesh::indices() const { return impl_->indices; }
glm::dvec3 FogMesh::boundsMin() const { return impl_->lo; }
glm::dvec3 FogMesh::boundsMax() const { return impl_->hi; }
double FogMesh::enclosedVolume() const { return impl_->volume; }

std::size_t FogMesh::lineChords(const glm::dvec3& origin, const glm::dvec3& direction,
                                std::vector<VolumeSegment>& chords) const {
    const double length = glm::length(direction);
    if (!(length > 0.0) || !std::isfinite(length)) return 0;
    thread_local std::vector<std::pair<double, int>> hits;
    hits.clear();
    impl_->crossings(origin, direction, hits);
    std::sort(hits.begin(), hits.end());
    // Merge an edge or vertex crossing counted on several triangles.
    const double epsilon = impl_->mergeEpsilon / length;
    std::size_t kept = 0;
    for (std::size_t i = 0; i < hits.size(); ++i) {
        bool duplicate = false;
        for (std::size_t j = kept; j-- > 0 && hits[i].first - hits[j].first <= epsilon;) {
            if (hits[j].second == hits[i].second) {
                duplicate = true;
                break;
            }
        }
        if (!duplicate) hits[kept++] = hits[i];
    }
    hits.resize(kept);
    const std::size_t before = chords.size();
    int winding = 0;
    double start = 0.0;
    for (const auto& [t, sign] : hits) {
        const int next = std::max(winding + sign, 0);
        if (winding == 0 && next > 0) start = t;
        if (winding > 0 && next == 0 && t > start) chords.push_back({true, start, t});
        winding = next;
    }
    return chords.size() - before;
}

bool FogMesh::contains(const glm::dvec3& point) const {
    // An irrational-ish direction: no axis-aligned face or edge is grazed.
    const glm::dvec3 direction =
        glm::normalize(glm::dvec3(0.5773502691896258, 0.6123724356957945, 0.5403023058681398));
    thread_local std::vector<VolumeSegment> chords;
    chords.clear();
    lineChords(point, direction, chords);
    for (const VolumeSegment& c : chords) {
        if (c.tIn <= 0.0 && 0.0 <= c.tOut) return true;
    }
    return false;
}

}  // namespace aerial
