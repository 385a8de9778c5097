// bvh.hpp — private: the fog-volume acceleration structure of FogScene
// (fog_query.cpp).
//
// VolumeBvh is a flat binary BVH over the world AABBs of the valid prepared
// volumes (aerial/fog_volume.hpp, prepareFogVolume), built once with a binned
// surface-area heuristic; traversal is conservative (bounds are padded, zero
// direction components handled without NaN), so it only ever prunes volumes
// the exact object-space test would also miss. FogScene and the public
// single-volume functions share the one geometry of fog_volume.hpp, so a BVH
// query and a brute-force loop over the public functions give bit-identical
// per-volume answers.
#pragma once

#include <aerial/fog_volume.hpp>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace aerial::detail {

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
    explicit VolumeBvh(const std::vector<PreparedFogVolume>& volumes) {
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
