// bvh.hpp — private: the fog-volume acceleration structure shared by
// fog_volume.cpp (single-volume API) and fog_query.cpp (FogScene).
//
// PreparedVolume is a FogVolume reduced to what a ray needs: the sanitised
// object-from-world transform (3x3 + translation), the normalised gradient,
// the world bounds. intersectFogVolume() and FogScene use the very same
// prepare + intersect code, so a BVH query and a brute-force loop over the
// public functions give bit-identical per-volume answers.
//
// VolumeBvh is a flat binary BVH over the world AABBs of the valid volumes,
// built once with a binned surface-area heuristic; traversal is conservative
// (bounds are padded, zero direction components handled without NaN), so it
// only ever prunes volumes the exact object-space test would also miss.
#pragma once

#include <aerial/fog_volume.hpp>
#include <aerial/height_fog.hpp>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace aerial::detail {

/// World coordinates, ray directions and half extents beyond this magnitude
/// [m] are not meaningful; a volume or ray that uses them is never hit. Keeps
/// every object-space product finite.
constexpr double kMaxCoordinate = 1.0e30;
/// Half extents below this [m] (1 um) make a volume degenerate.
constexpr double kMinHalfExtent = 1.0e-6;
/// Density, falloff and offset magnitudes are clamped to this.
constexpr double kMaxParameter = 1.0e150;

inline bool isFinite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

inline bool withinCoordinateRange(const glm::dvec3& v) {
    // NaN fails every comparison, so it is out of range too.
    return std::fabs(v.x) <= kMaxCoordinate && std::fabs(v.y) <= kMaxCoordinate &&
           std::fabs(v.z) <= kMaxCoordinate;
}

/// Not finite or negative -> 0, else clamped to [0, kMaxParameter].
inline double sanitiseNonNegative(double x) {
    return (std::isfinite(x) && x > 0.0) ? std::min(x, kMaxParameter) : 0.0;
}

/// Not finite -> 0, else clamped to [-kMaxParameter, kMaxParameter].
inline double sanitiseSigned(double x) {
    return std::isfinite(x) ? std::clamp(x, -kMaxParameter, kMaxParameter) : 0.0;
}

/// Radiance and colour components: not finite or negative -> 0, at most 1e30.
inline glm::dvec3 sanitiseColour(const glm::dvec3& c) {
    auto one = [](double x) { return (std::isfinite(x) && x > 0.0) ? std::min(x, 1.0e30) : 0.0; };
    return {one(c.x), one(c.y), one(c.z)};
}

/// Normalised direction; +Y when zero or not finite.
inline glm::dvec3 safeDirection(const glm::dvec3& v) {
    if (!isFinite(v)) {
        return {0.0, 1.0, 0.0};
    }
    // Rescale first so that tiny or huge vectors normalise without
    // underflow or overflow.
    const double m = std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
    if (!(m > 0.0)) {
        return {0.0, 1.0, 0.0};
    }
    const glm::dvec3 s = v / m;
    return s / std::sqrt(glm::dot(s, s));
}

struct PreparedVolume {
    bool valid = false;  ///< false: degenerate, never hit
    FogVolumeShape shape = FogVolumeShape::Box;
    glm::dvec3 position{0.0};
    /// Rows of objectFromWorld (3x3): object = M (world - position).
    glm::dvec3 row0{1.0, 0.0, 0.0};
    glm::dvec3 row1{0.0, 1.0, 0.0};
    glm::dvec3 row2{0.0, 0.0, 1.0};
    glm::dvec3 gradient{0.0, 1.0, 0.0};  ///< unit, world
    double gradientOffset = 0.0;         ///< [m]
    double density = 0.0;                ///< [1/m], sanitised
    double falloff = 0.0;                ///< [1/m], sanitised
    glm::dvec3 boundsMin{0.0};           ///< world AABB (exact, unpadded)
    glm::dvec3 boundsMax{0.0};
    FogColourMode colourMode = FogColourMode::Sky;
    glm::dvec3 colour{1.0};  ///< sanitised

    glm::dvec3 toObject(const glm::dvec3& worldVector) const {
        return {glm::dot(row0, worldVector), glm::dot(row1, worldVector), glm::dot(row2, worldVector)};
    }
};

inline PreparedVolume prepareVolume(const FogVolume& v) {
    PreparedVolume p;
    p.shape = v.shape;
    p.colourMode = v.colourMode;
    p.colour = sanitiseColour(v.colour);
    p.density = sanitiseNonNegative(v.density);
    p.falloff = sanitiseNonNegative(v.falloff);
    p.gradient = safeDirection(v.gradientDirection);
    p.gradientOffset = sanitiseSigned(v.gradientOffset);

    const glm::dvec3 s = v.halfExtents;
    const bool extentsOk = s.x >= kMinHalfExtent && s.y >= kMinHalfExtent && s.z >= kMinHalfExtent &&
                           s.x <= kMaxCoordinate && s.y <= kMaxCoordinate && s.z <= kMaxCoordinate;
    const glm::dquat q = v.rotation;
    const double qNorm2 = q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z;
    const bool rotationOk = std::isfinite(qNorm2) && qNorm2 > 1.0e-200;
    const bool positionOk = withinCoordinateRange(v.position);
    p.position = positionOk ? v.position : glm::dvec3(0.0);
    p.boundsMin = p.position;
    p.boundsMax = p.position;
    if (!(extentsOk && rotationOk && positionOk)) {
        return p;  // degenerate: never hit, density 0 everywhere
    }
    p.valid = true;

    // World from object rotation R (columns = object axes in world space).
    const glm::dmat3 r = glm::mat3_cast(q / std::sqrt(qNorm2));
    // objectFromWorld = S^-1 R^T: its rows are R's columns over the extents.
    p.row0 = r[0] / s.x;
    p.row1 = r[1] / s.y;
    p.row2 = r[2] / s.z;

    // World AABB: half width along world axis i of the image of the unit
    // cube is sum_j |R_ij| s_j; of the unit sphere sqrt(sum_j (R_ij s_j)^2).
    glm::dvec3 half;
    for (int i = 0; i < 3; ++i) {
        const double a = r[0][i] * s.x;
        const double b = r[1][i] * s.y;
        const double c = r[2][i] * s.z;
        half[i] = (v.shape == FogVolumeShape::Box) ? std::fabs(a) + std::fabs(b) + std::fabs(c)
                                                   : std::sqrt(a * a + b * b + c * c);
    }
    p.boundsMin = p.position - half;
    p.boundsMax = p.position + half;
    return p;
}

/// Ray origin + t direction, t in [0, tMax], against a prepared volume in
/// object space. Inputs must already be finite and within kMaxCoordinate
/// (tMax finite, >= 0). Returns the clipped segment.
inline VolumeSegment intersectPrepared(const PreparedVolume& p, const glm::dvec3& origin,
                                       const glm::dvec3& direction, double tMax) {
    VolumeSegment seg;
    if (!p.valid) {
        return seg;
    }
    const glm::dvec3 o = p.toObject(origin - p.position);
    const glm::dvec3 d = p.toObject(direction);
    double tNear = -std::numeric_limits<double>::infinity();
    double tFar = std::numeric_limits<double>::infinity();
    if (p.shape == FogVolumeShape::Box) {
        // Slabs |o_i + t d_i| <= 1. Divisions (not reciprocals) so that a
        // tiny d_i gives +-Inf, never NaN: (+-1 - o_i) is finite and d_i != 0.
        for (int i = 0; i < 3; ++i) {
            if (d[i] != 0.0) {
                const double t1 = (-1.0 - o[i]) / d[i];
                const double t2 = (1.0 - o[i]) / d[i];
                tNear = std::max(tNear, std::min(t1, t2));
                tFar = std::min(tFar, std::max(t1, t2));
            } else if (!(std::fabs(o[i]) <= 1.0)) {
                return seg;  // parallel to and outside this slab
            }
        }
    } else {
        // Unit sphere. With the closest approach p_perp = o + t* d,
        // t* = -(o.d)/(d.d), the roots are t* -+ sqrt((1 - |p_perp|^2) / d.d):
        // no B^2 - AC cancellation for far or grazing rays.
        const double a = glm::dot(d, d);
        if (!(a > 0.0)) {
            return seg;
        }
        const double tMid = -glm::dot(o, d) / a;
        const glm::dvec3 perp = o + tMid * d;
        const double h = 1.0 - glm::dot(perp, perp);
        if (!(h > 0.0)) {
            return seg;
        }
        const double halfChord = std::sqrt(h / a);
        tNear = tMid - halfChord;
        tFar = tMid + halfChord;
    }
    const double tIn = std::max(tNear, 0.0);
    const double tOut = std::min(tFar, tMax);
    if (tIn < tOut) {  // false for NaN as well
        seg.hit = true;
        seg.tIn = tIn;
        seg.tOut = tOut;
    }
    return seg;
}

/// Optical depth of a prepared volume over a clipped segment (world
/// distances: the parameter t is in units of |direction|).
inline double opticalDepthPrepared(const PreparedVolume& p, const glm::dvec3& origin,
                                   const glm::dvec3& direction, const VolumeSegment& seg) {
    if (!p.valid || !seg.hit) {
        return 0.0;
    }
    const double span = seg.tOut - seg.tIn;
    const double rate = glm::dot(direction, p.gradient);  // height change per unit t
    const double height = glm::dot(origin - p.position, p.gradient) + seg.tIn * rate - p.gradientOffset;
    return exponentialOpticalDepth(p.density, p.falloff, height, span * rate, span * glm::length(direction));
}

/// Flat binary BVH over world AABBs, built top-down with a binned SAH as a
/// tree of Nodes (node i's children are leftOrFirst and leftOrFirst + 1, or
/// it holds order_[leftOrFirst .. leftOrFirst + count)), then stored for
/// traversal as Pairs: the bounds of two siblings side by side, tested
/// together.
class VolumeBvh {
public:
    struct Node {
        glm::dvec3 boundsMin{0.0};
        glm::dvec3 boundsMax{0.0};
        std::uint32_t leftOrFirst = 0;
        std::uint32_t count = 0;
    };

    VolumeBvh() = default;

    /// Builds over the valid entries of `volumes`.
    explicit VolumeBvh(const std::vector<PreparedVolume>& volumes) {
        for (std::size_t i = 0; i < volumes.size(); ++i) {
            if (volumes[i].valid) {
                Prim prim;
                // Pad: the exact test in object space and the bounds come
                // from the same numbers, but both are rounded; a relative
                // margin keeps the BVH conservative.
                const glm::dvec3 centre = 0.5 * (volumes[i].boundsMin + volumes[i].boundsMax);
                const glm::dvec3 extent = volumes[i].boundsMax - volumes[i].boundsMin;
                const glm::dvec3 pad = 1.0e-9 * (glm::abs(centre) + extent) + 1.0e-12;
                prim.boundsMin = volumes[i].boundsMin - pad;
                prim.boundsMax = volumes[i].boundsMax + pad;
                prim.centroid = centre;
                prim.index = static_cast<std::uint32_t>(i);
                prims_.push_back(prim);
            }
        }
        if (prims_.empty()) {
            return;
        }
        nodes_.reserve(2 * prims_.size());
        nodes_.emplace_back();
        nodes_[0].leftOrFirst = 0;
        nodes_[0].count = static_cast<std::uint32_t>(prims_.size());
        updateBounds(0);
        subdivide(0, 0);
        order_.reserve(prims_.size());
        for (const Prim& prim : prims_) {
            order_.push_back(prim.index);
        }
        prims_.clear();
        prims_.shrink_to_fit();
        buildPairs();
    }

    bool empty() const { return pairs_.empty(); }
    /// Number of binary-tree nodes (each Pair holds two, the first one).
    std::size_t nodeCount() const { return pairs_.empty() ? 0 : 2 * pairs_.size() - 1; }
    std::size_t depth() const { return depth_; }

    /// Calls visit(volumeIndex) for every volume whose padded bounds the
    /// segment origin + t direction, t in [0, tMax], touches (tMax <= 1,
    /// inputs within kMaxCoordinate). Conservative.
    template <class Visit>
    void traverse(const glm::dvec3& origin, const glm::dvec3& direction, double tMax, Visit&& visit) const {
        if (pairs_.empty()) {
            return;
        }
        // A zero (or tiny) component: its slab test degenerates to "origin
        // inside the slab"; +-1e200 instead of Inf avoids 0 * Inf, and keeps
        // bounds * inv finite (|bounds| < 1e31). Within t in [0, tMax <= 1]
        // such a ray moves less than 1e-200 across the slab, far below the
        // padding, so the test stays conservative.
        // The origin is widened by 1e-15 |o_i| on each axis: that covers the
        // rounding of o_i * inv_i (the node bounds' own rounding is covered
        // by their padding), so even a camera far from the volumes cannot
        // lose a hit the exact test would find.
        Ray ray;
        for (int i = 0; i < 3; ++i) {
            const double inv = std::fabs(direction[i]) > 1.0e-200 ? 1.0 / direction[i]
                                                                  : std::copysign(1.0e200, direction[i]);
            const double slack = 1.0e-15 * std::fabs(origin[i]);
            ray.inv[i] = inv;
            ray.lowOffset[i] = (origin[i] + slack) * inv;   // for boundsMin - slack
            ray.highOffset[i] = (origin[i] - slack) * inv;  // for boundsMax + slack
        }
        ray.tMax = tMax;
        std::array<std::uint32_t, kMaxDepth + 1> stack;
        std::size_t top = 0;
        std::uint32_t pair = 0;
        for (;;) {
            const Pair& p = pairs_[pair];
            bool hit[2];
            touches(p, ray, hit);
            std::uint32_t next[2];
            int descend = 0;
            for (int k = 0; k < 2; ++k) {
                if (!hit[k]) {
                    continue;
                }
                if (p.kind[k] == kLeaf) {
                    for (std::uint32_t j = 0; j < p.count[k]; ++j) {
                        visit(order_[p.child[k] + j]);
                    }
                } else if (p.kind[k] == kInterior) {
                    next[descend++] = p.child[k];
                }
            }
            if (descend == 2) {
                stack[top++] = next[1];
                pair = next[0];
            } else if (descend == 1) {
                pair = next[0];
            } else {
                if (top == 0) {
                    return;
                }
                pair = stack[--top];
            }
        }
    }

private:
    struct Prim {
        glm::dvec3 boundsMin{0.0};
        glm::dvec3 boundsMax{0.0};
        glm::dvec3 centroid{0.0};
        std::uint32_t index = 0;
    };

    static constexpr int kBins = 12;
    static constexpr std::uint32_t kMaxLeafSize = 4;
    // Depth is bounded so the traversal stack (at most one entry per
    // level) never overflows.
    static constexpr std::size_t kMaxDepth = 48;

    struct Ray {
        glm::dvec3 inv{0.0};
        glm::dvec3 lowOffset{0.0};   ///< (origin + slack) * inv
        glm::dvec3 highOffset{0.0};  ///< (origin - slack) * inv
        double tMax = 0.0;
    };

    static constexpr std::uint8_t kEmpty = 0;
    static constexpr std::uint8_t kInterior = 1;
    static constexpr std::uint8_t kLeaf = 2;

    /// The traversal unit: the bounds of two sibling nodes side by side
    /// (lane k = sibling k), so both are tested in one go (the two lanes
    /// vectorise), and each lane either points at the Pair of its own
    /// children (interior) or at its volumes in order_ (leaf).
    struct Pair {
        std::array<double, 2> minX{}, minY{}, minZ{};
        std::array<double, 2> maxX{}, maxY{}, maxZ{};
        std::array<std::uint32_t, 2> child{};  ///< interior: Pair index; leaf: first in order_
        std::array<std::uint32_t, 2> count{};  ///< leaf: number of volumes
        std::array<std::uint8_t, 2> kind{};    ///< kEmpty, kInterior or kLeaf
    };

    /// Slab test of the segment against both lanes' padded bounds, widened
    /// by the ray's slack: t1 = (min - slack - o) inv, t2 = (max + slack - o)
    /// inv. No NaN can form (inv and the offsets are finite).
    static void touches(const Pair& p, const Ray& r, bool hit[2]) {
        for (int k = 0; k < 2; ++k) {
            const double x1 = p.minX[k] * r.inv.x - r.lowOffset.x;
            const double x2 = p.maxX[k] * r.inv.x - r.highOffset.x;
            const double y1 = p.minY[k] * r.inv.y - r.lowOffset.y;
            const double y2 = p.maxY[k] * r.inv.y - r.highOffset.y;
            const double z1 = p.minZ[k] * r.inv.z - r.lowOffset.z;
            const double z2 = p.maxZ[k] * r.inv.z - r.highOffset.z;
            const double tNear =
                std::max(std::max(std::min(x1, x2), std::min(y1, y2)), std::max(std::min(z1, z2), 0.0));
            const double tFar =
                std::min(std::min(std::max(x1, x2), std::max(y1, y2)), std::min(std::max(z1, z2), r.tMax));
            hit[k] = tNear <= tFar && p.kind[k] != kEmpty;
        }
    }

    static void setLane(Pair& p, int k, const Node& n) {
        p.minX[k] = n.boundsMin.x;
        p.minY[k] = n.boundsMin.y;
        p.minZ[k] = n.boundsMin.z;
        p.maxX[k] = n.boundsMax.x;
        p.maxY[k] = n.boundsMax.y;
        p.maxZ[k] = n.boundsMax.z;
    }

    /// Converts the binary node tree into Pairs: Pair 0 holds the root (lane
    /// 0; lane 1 empty); every interior node becomes the Pair of its two
    /// children.
    void buildPairs() {
        pairs_.clear();
        pairs_.reserve(nodes_.size());
        pairs_.emplace_back();
        setLane(pairs_[0], 0, nodes_[0]);
        pairs_[0].kind[1] = kEmpty;
        fillLane(0, 0, 0);
        nodes_.clear();
        nodes_.shrink_to_fit();
    }

    /// Lane k of Pair `pairIndex` stands for binary node `nodeIndex`.
    void fillLane(std::uint32_t pairIndex, int k, std::uint32_t nodeIndex) {
        const Node n = nodes_[nodeIndex];
        if (n.count != 0) {
            pairs_[pairIndex].kind[k] = kLeaf;
            pairs_[pairIndex].child[k] = n.leftOrFirst;
            pairs_[pairIndex].count[k] = n.count;
            return;
        }
        const std::uint32_t childPair = static_cast<std::uint32_t>(pairs_.size());
        pairs_.emplace_back();
        setLane(pairs_[childPair], 0, nodes_[n.leftOrFirst]);
        setLane(pairs_[childPair], 1, nodes_[n.leftOrFirst + 1]);
        pairs_[pairIndex].kind[k] = kInterior;
        pairs_[pairIndex].child[k] = childPair;
        fillLane(childPair, 0, n.leftOrFirst);
        fillLane(childPair, 1, n.leftOrFirst + 1);
    }

    static double halfArea(const glm::dvec3& e) { return e.x * e.y + e.y * e.z + e.z * e.x; }

    void updateBounds(std::uint32_t nodeIndex) {
        Node& n = nodes_[nodeIndex];
        n.boundsMin = glm::dvec3(std::numeric_limits<double>::max());
        n.boundsMax = glm::dvec3(-std::numeric_limits<double>::max());
        for (std::uint32_t k = 0; k < n.count; ++k) {
            const Prim& prim = prims_[n.leftOrFirst + k];
            n.boundsMin = glm::min(n.boundsMin, prim.boundsMin);
            n.boundsMax = glm::max(n.boundsMax, prim.boundsMax);
        }
    }

    void subdivide(std::uint32_t nodeIndex, std::size_t level) {
        depth_ = std::max(depth_, level + 1);
        const std::uint32_t first = nodes_[nodeIndex].leftOrFirst;
        const std::uint32_t count = nodes_[nodeIndex].count;
        if (count <= 1 || level + 1 >= kMaxDepth) {
            return;
        }
        // Centroid bounds choose the binning range.
        glm::dvec3 cMin(std::numeric_limits<double>::max());
        glm::dvec3 cMax(-std::numeric_limits<double>::max());
        for (std::uint32_t k = 0; k < count; ++k) {
            cMin = glm::min(cMin, prims_[first + k].centroid);
            cMax = glm::max(cMax, prims_[first + k].centroid);
        }
        // Binned SAH: cost of a split = A_left N_left + A_right N_right
        // (relative to the parent's area; traversal cost folded in).
        int bestAxis = -1;
        int bestSplit = 0;
        double bestCost = std::numeric_limits<double>::infinity();
        for (int axis = 0; axis < 3; ++axis) {
            const double lo = cMin[axis];
            const double hi = cMax[axis];
            if (!(hi > lo)) {
                continue;
            }
            struct Bin {
                glm::dvec3 bmin{std::numeric_limits<double>::max()};
                glm::dvec3 bmax{-std::numeric_limits<double>::max()};
                std::uint32_t count = 0;
            };
            std::array<Bin, kBins> bins{};
            const double scale = kBins / (hi - lo);
            for (std::uint32_t k = 0; k < count; ++k) {
                const Prim& prim = prims_[first + k];
                const int b = std::min(kBins - 1, static_cast<int>((prim.centroid[axis] - lo) * scale));
                bins[b].bmin = glm::min(bins[b].bmin, prim.boundsMin);
                bins[b].bmax = glm::max(bins[b].bmax, prim.boundsMax);
                ++bins[b].count;
            }
            std::array<double, kBins - 1> leftCost{};
            glm::dvec3 bmin(std::numeric_limits<double>::max());
            glm::dvec3 bmax(-std::numeric_limits<double>::max());
            std::uint32_t n = 0;
            for (int b = 0; b < kBins - 1; ++b) {
                n += bins[b].count;
                bmin = glm::min(bmin, bins[b].bmin);
                bmax = glm::max(bmax, bins[b].bmax);
                leftCost[b] = n > 0 ? n * halfArea(bmax - bmin) : 0.0;
            }
            bmin = glm::dvec3(std::numeric_limits<double>::max());
            bmax = glm::dvec3(-std::numeric_limits<double>::max());
            n = 0;
            for (int b = kBins - 1; b > 0; --b) {
                n += bins[b].count;
                bmin = glm::min(bmin, bins[b].bmin);
                bmax = glm::max(bmax, bins[b].bmax);
                const double cost = leftCost[b - 1] + (n > 0 ? n * halfArea(bmax - bmin) : 0.0);
                if (cost < bestCost) {
                    bestCost = cost;
                    bestAxis = axis;
                    bestSplit = b;
                }
            }
        }
        const Node parent = nodes_[nodeIndex];
        const double leafCost = count * halfArea(parent.boundsMax - parent.boundsMin);
        if (bestAxis < 0 || (count <= kMaxLeafSize && bestCost >= leafCost)) {
            return;  // all centroids coincide, or a leaf is cheaper
        }
        // Partition by bin (same arithmetic as the binning above).
        const double lo = cMin[bestAxis];
        const double scale = kBins / (cMax[bestAxis] - lo);
        auto mid =
            std::partition(prims_.begin() + first, prims_.begin() + first + count, [&](const Prim& prim) {
                const int b = std::min(kBins - 1, static_cast<int>((prim.centroid[bestAxis] - lo) * scale));
                return b < bestSplit;
            });
        const std::uint32_t leftCount = static_cast<std::uint32_t>(mid - (prims_.begin() + first));
        if (leftCount == 0 || leftCount == count) {
            return;
        }
        const std::uint32_t left = static_cast<std::uint32_t>(nodes_.size());
        nodes_.emplace_back();
        nodes_.emplace_back();
        nodes_[left].leftOrFirst = first;
        nodes_[left].count = leftCount;
        nodes_[left + 1].leftOrFirst = first + leftCount;
        nodes_[left + 1].count = count - leftCount;
        nodes_[nodeIndex].leftOrFirst = left;
        nodes_[nodeIndex].count = 0;
        updateBounds(left);
        updateBounds(left + 1);
        subdivide(left, level + 1);
        subdivide(left + 1, level + 1);
    }

    std::vector<Node> nodes_;           ///< build only: the binary tree
    std::vector<Pair> pairs_;           ///< traversal
    std::vector<std::uint32_t> order_;  ///< volume indices, leaf ranges
    std::vector<Prim> prims_;           ///< build only
    std::size_t depth_ = 0;
};

}  // namespace aerial::detail
