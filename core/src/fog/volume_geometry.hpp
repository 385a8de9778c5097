// volume_geometry.hpp — private: the ray tests of a prepared fog volume
// (aerial/fog_volume.hpp) as inline functions, so FogScene's BVH loop
// (fog_query.cpp) inlines them; the public functions in fog_volume.cpp are
// thin wrappers over these. Inputs are assumed finite and within
// limits::kMaxCoordinate (the public wrappers check).
#pragma once

#include <aerial/fog_mesh.hpp>
#include <aerial/fog_volume.hpp>
#include <aerial/height_fog.hpp>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace aerial::detail {

inline VolumeInterval lineInterval(const PreparedFogVolume& p, const glm::dvec3& origin,
                                   const glm::dvec3& direction) {
    VolumeInterval line;
    if (!p.valid) {
        return line;
    }
    const glm::dvec3 o = p.toObject(origin - p.position);
    const glm::dvec3 d = p.toObject(direction);
    double tNear = -std::numeric_limits<double>::infinity();
    double tFar = std::numeric_limits<double>::infinity();
    if (p.shape == FogVolumeShape::Mesh) {
        // The hull of the chords: first entry to last exit.
        thread_local std::vector<VolumeSegment> chords;
        chords.clear();
        if (p.mesh->lineChords(o, d, chords) == 0) {
            return line;
        }
        tNear = chords.front().tIn;
        tFar = chords.back().tOut;
    } else if (p.shape == FogVolumeShape::Box) {
        // Slabs |o_i + t d_i| <= 1. Divisions (not reciprocals) so that a
        // tiny d_i gives +-Inf, never NaN: (+-1 - o_i) is finite and d_i != 0.
        for (int i = 0; i < 3; ++i) {
            if (d[i] != 0.0) {
                const double t1 = (-1.0 - o[i]) / d[i];
                const double t2 = (1.0 - o[i]) / d[i];
                tNear = std::max(tNear, std::min(t1, t2));
                tFar = std::min(tFar, std::max(t1, t2));
            } else if (!(std::fabs(o[i]) <= 1.0)) {
                return line;  // parallel to and outside this slab
            }
        }
    } else {
        // Unit sphere. With the closest approach p_perp = o + t* d,
        // t* = -(o.d)/(d.d), the roots are t* -+ sqrt((1 - |p_perp|^2) / d.d):
        // no B^2 - AC cancellation for far or grazing rays.
        const double a = glm::dot(d, d);
        if (!(a > 0.0)) {
            return line;
        }
        const double tMid = -glm::dot(o, d) / a;
        const glm::dvec3 perp = o + tMid * d;
        const double h = 1.0 - glm::dot(perp, perp);
        if (!(h > 0.0)) {
            return line;
        }
        const double halfChord = std::sqrt(h / a);
        tNear = tMid - halfChord;
        tFar = tMid + halfChord;
    }
    if (tNear <= tFar) {  // false for NaN as well
        line.hit = true;
        line.tNear = tNear;
        line.tFar = tFar;
    }
    return line;
}

inline VolumeSegment clippedSegment(const PreparedFogVolume& p, const glm::dvec3& origin,
                                    const glm::dvec3& direction, double tMax) {
    VolumeSegment seg;
    const VolumeInterval line = lineInterval(p, origin, direction);
    if (!line.hit) {
        return seg;
    }
    const double tIn = std::max(line.tNear, 0.0);
    const double tOut = std::min(line.tFar, tMax);
    if (tIn < tOut) {  // false for NaN as well
        seg.hit = true;
        seg.tIn = tIn;
        seg.tOut = tOut;
    }
    return seg;
}

/// The chords of the line inside the volume clipped to [tMin, tMax],
/// appended to `out` (sorted, disjoint): one for a box or ellipsoid, any
/// number for a mesh.
inline void clippedChords(const PreparedFogVolume& p, const glm::dvec3& origin, const glm::dvec3& direction,
                          double tMin, double tMax, std::vector<VolumeSegment>& out) {
    if (!p.valid) {
        return;
    }
    if (p.shape != FogVolumeShape::Mesh) {
        const VolumeInterval line = lineInterval(p, origin, direction);
        const double tIn = std::max(line.tNear, tMin);
        const double tOut = std::min(line.tFar, tMax);
        if (line.hit && tIn < tOut) {
            out.push_back({true, tIn, tOut});
        }
        return;
    }
    const std::size_t first = out.size();
    p.mesh->lineChords(p.toObject(origin - p.position), p.toObject(direction), out);
    std::size_t kept = first;
    for (std::size_t i = first; i < out.size(); ++i) {
        const double tIn = std::max(out[i].tIn, tMin);
        const double tOut = std::min(out[i].tOut, tMax);
        if (tIn < tOut) {
            out[kept++] = {true, tIn, tOut};
        }
    }
    out.resize(kept);
}

/// Optical depth of one stretch [seg.tIn, seg.tOut] of the line under the
/// volume's density law, ignoring its shape (the caller knows the stretch
/// is inside).
double softStretchOpticalDepth(const PreparedFogVolume& p, const glm::dvec3& origin,
                               const glm::dvec3& direction, const VolumeSegment& seg);

inline double stretchOpticalDepth(const PreparedFogVolume& p, const glm::dvec3& origin,
                                  const glm::dvec3& direction, const VolumeSegment& seg) {
    if (p.edgeSoftness > 0.0) {
        return softStretchOpticalDepth(p, origin, direction, seg);  // box or ellipsoid that adds
    }
    const double span = seg.tOut - seg.tIn;
    const double rate = glm::dot(direction, p.gradient);  // height change per unit t
    const double height = glm::dot(origin - p.position, p.gradient) + seg.tIn * rate - p.gradientOffset;
    return exponentialOpticalDepth(p.density, p.falloff, height, span * rate, span * glm::length(direction));
}

inline double segmentOpticalDepth(const PreparedFogVolume& p, const glm::dvec3& origin,
                                  const glm::dvec3& direction, const VolumeSegment& seg) {
    if (!p.valid || !seg.hit) {
        return 0.0;
    }
    if (p.shape == FogVolumeShape::Mesh) {
        thread_local std::vector<VolumeSegment> chords;
        chords.clear();
        clippedChords(p, origin, direction, seg.tIn, seg.tOut, chords);
        double tau = 0.0;
        for (const VolumeSegment& c : chords) {
            tau += stretchOpticalDepth(p, origin, direction, c);
        }
        return std::min(tau, kMaxOpticalDepth);
    }
    return stretchOpticalDepth(p, origin, direction, seg);
}

}  // namespace aerial::detail
