// fog_query.cpp — CPU fog queries for transparent objects (../shared/
// DESIGN.md, "Transparent objects"; Wenzel 2006, section 6.7: the volumes in
// front of an object are found through a hierarchy and weighted back to
// front, farthest first).
//
// A query: the union of the subtract volumes' chords along the segment,
// then global fog over the rest of the segment, then every add volume the
// BVH reports and the exact object-space test confirms (its chords outside
// the union), sorted back to front, then the emitters. No heap allocation
// unless a segment crosses more than kInlineHits volumes (the chord lists
// are per-thread buffers that keep their capacity).
#include "bvh.hpp"
#include "base/sanitise.hpp"
#include "volume_geometry.hpp"

#include <aerial/atmosphere.hpp>
#include <aerial/finite.hpp>
#include <aerial/fog_query.hpp>

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace aerial {
namespace {

/// One crossed volume, in units of the segment parameter t in [0, 1].
struct Hit {
    std::uint32_t index;
    double tIn;
    double tOut;
    double opticalDepth;
};

/// Back to front: larger entry first; equal entries by ascending index.
bool backToFront(const Hit& a, const Hit& b) {
    if (a.tIn != b.tIn) {
        return a.tIn > b.tIn;
    }
    return a.index < b.index;
}

/// Hits on the stack, spilling into a heap vector only past kInlineHits.
class HitBuffer {
public:
    static constexpr std::size_t kInlineHits = 64;

    void push(const Hit& hit) {
        if (size_ < kInlineHits) {
            inline_[size_] = hit;
        } else {
            if (size_ == kInlineHits) {
                spill_.assign(inline_.begin(), inline_.end());
            }
            spill_.push_back(hit);
        }
        ++size_;
    }
    Hit* begin() { return size_ <= kInlineHits ? inline_.data() : spill_.data(); }
    Hit* end() { return begin() + size_; }
    std::size_t size() const { return size_; }
    /// Shrinks to the first `size` hits.
    void resize(std::size_t size) {
        size_ = std::min(size, size_);
        if (size_ > kInlineHits) {
            spill_.resize(size_);
        } else if (!spill_.empty()) {
            std::copy(spill_.begin(), spill_.begin() + std::ptrdiff_t(size_), inline_.begin());
            spill_.clear();
        }
    }

private:
    std::array<Hit, kInlineHits> inline_;
    std::vector<Hit> spill_;
    std::size_t size_ = 0;
};

struct PreparedLight {
    glm::dvec3 direction{0.0, 1.0, 0.0};
    glm::dvec3 illuminance{0.0};
    SkyTable horizon;  // the row (if any) and the sanitised averages (horizonSkySample)
};

/// A light's illuminance that reaches the fog, times the clouds' visibility.
struct DirectLight {
    glm::dvec3 direction{0.0, 1.0, 0.0};
    glm::dvec3 illuminance{0.0};
};

/// Non-finite or negative entries of a table row become 0.
void sanitiseRow(std::vector<float>& row) {
    for (float& x : row)
        if (!(std::isfinite(x) && x > 0.0f)) x = 0.0f;
}

}  // namespace

struct FogScene::Impl {
    FogSceneDesc desc;
    std::vector<PreparedFogVolume> volumes;
    detail::VolumeBvh bvh;
    std::array<PreparedLight, 2> lights;
    std::size_t lightCount = 0;
    std::array<DirectLight, 2> direct;
    std::size_t directCount = 0;
    FogSkyLight skyLight;
    double firstMoment = 0.0;
    double horizonDistance = kFogHorizonDistance;
    double mieAnisotropy = 0.0;
    FogColourMode heightFogColourMode = FogColourMode::Sky;
    glm::dvec3 heightFogColour{1.0};
    double overcastCover = 0.0;
    glm::dvec3 overcastRadiance{0.0};

    explicit Impl(const FogSceneDesc& d) : desc(d) {
        volumes.reserve(desc.volumes.size());
        for (const FogVolume& v : desc.volumes) {
            volumes.push_back(prepareFogVolume(v));
        }
        bvh = detail::VolumeBvh(volumes);
        for (const FogLight& light : desc.lights) {
            PreparedLight p;
            p.direction = detail::safeDirection(light.direction);
            p.illuminance = detail::sanitiseColour(light.illuminance);
            p.horizon = light.horizonRow;
            for (auto* row : {&p.horizon.rayleigh, &p.horizon.mie, &p.horizon.multiple}) sanitiseRow(*row);
            p.horizon.horizonRayleigh = detail::sanitiseColour(light.horizonRayleigh);
            p.horizon.horizonMie = detail::sanitiseColour(light.horizonMie);
            p.horizon.horizonMultiple = detail::sanitiseColour(light.horizonMultiple);
            const auto any = [](const std::vector<float>& row) {
                return std::any_of(row.begin(), row.end(), [](float x) { return x > 0.0f; });
            };
            const SkyTable& h = p.horizon;
            const bool on = glm::dot(p.illuminance, p.illuminance) > 0.0 &&
                            (glm::dot(h.horizonRayleigh, h.horizonRayleigh) > 0.0 ||
                             glm::dot(h.horizonMie, h.horizonMie) > 0.0 ||
                             glm::dot(h.horizonMultiple, h.horizonMultiple) > 0.0 || any(h.rayleigh) ||
                             any(h.mie) || any(h.multiple));
            if (on) {
                lights[lightCount++] = p;
            }
        }
        const double visibility =
            std::isfinite(desc.directVisibility) ? std::clamp(desc.directVisibility, 0.0, 1.0) : 1.0;
        for (const FogLight& light : desc.lights) {
            const glm::dvec3 e = detail::sanitiseColour(light.reaching) * visibility;
            if (glm::dot(e, e) > 0.0) direct[directCount++] = {detail::safeDirection(light.direction), e};
        }
        skyLight.l0 = detail::sanitiseColour(desc.skyLight.l0);
        for (int k = 0; k < 3; ++k) {
            const glm::dvec3& l1 = desc.skyLight.l1[k];
            skyLight.l1[k] = isFinite(l1) ? glm::clamp(l1, -1.0e30, 1.0e30) : glm::dvec3(0.0);
        }
        horizonDistance = (std::isfinite(desc.horizonDistance) && desc.horizonDistance > 0.0)
                              ? desc.horizonDistance
                              : kFogHorizonDistance;
        mieAnisotropy = std::isnan(desc.mieAnisotropy) ? 0.0 : std::clamp(desc.mieAnisotropy, -0.999, 0.999);
        firstMoment = miePhaseFirstMoment(mieAnisotropy);
        heightFogColourMode = desc.heightFogColourMode;
        heightFogColour = detail::sanitiseColour(desc.heightFogColour);
        overcastCover = std::isfinite(desc.overcastCover) ? std::clamp(desc.overcastCover, 0.0, 1.0) : 0.0;
        overcastRadiance = detail::sanitiseColour(desc.overcastRadiance);
    }

    /// The in-scattered colour of a fog with this colour mode, given the
    /// sky's fog colour for the segment's direction.
    static glm::dvec3 fogColourFor(FogColourMode mode, const glm::dvec3& colour, const glm::dvec3& sky) {
        switch (mode) {
            case FogColourMode::Sky:
                return sky;
            case FogColourMode::Tinted:
                return colour * sky;
            case FogColourMode::Custom:
            default:
                return colour;
        }
    }

    /// L_fog(v, s) for a unit (sanitised) direction and a sight line of
    /// length s (fog_light.hpp).
    glm::dvec3 fogColourUnit(const glm::dvec3& v, double distance) const {
        const double w = fogHorizonWeight(distance, horizonDistance);
        glm::dvec3 colour(0.0);
        if (w < 1.0) colour = (1.0 - w) * litColour(v);
        if (w > 0.0) colour += w * horizonColour(v);
        return colour;
    }

    /// L_lit(v): the lights that reach the fog through its phase, and the sky's bands.
    glm::dvec3 litColour(const glm::dvec3& v) const {
        glm::dvec3 colour = fogSkyInScatter(skyLight, firstMoment, v);
        for (std::size_t k = 0; k < directCount; ++k) {
            const double mu = std::clamp(glm::dot(v, direct[k].direction), -1.0, 1.0);
            colour += direct[k].illuminance * miePhase(mu, mieAnisotropy);
        }
        return colour;
    }

    /// L_horizon(v): the sky behind far fog, under the overcast.
    glm::dvec3 horizonColour(const glm::dvec3& v) const {
        glm::dvec3 colour(0.0);
        for (std::size_t k = 0; k < lightCount; ++k) {
            const PreparedLight& l = lights[k];
            const double mu = std::clamp(glm::dot(v, l.direction), -1.0, 1.0);
            const SkySample h = horizonSkySample(l.horizon, v);
            colour += l.illuminance *
                      (rayleighPhase(mu) * h.rayleigh + miePhase(mu, mieAnisotropy) * h.mie + h.multiple);
        }
        if (overcastCover > 0.0) colour = (1.0 - overcastCover) * colour + overcastCover * overcastRadiance;
        return colour;
    }

    /// Collects the crossed volumes of from + t delta, t in [0, 1]: the add
    /// volumes' hits (their chords outside the subtract union, back to
    /// front) and the union of the subtract volumes' chords (`removed`,
    /// sorted, disjoint).
    void collect(const glm::dvec3& from, const glm::dvec3& delta, HitBuffer& hits,
                 std::vector<VolumeSegment>& removed) const {
        // Box and ellipsoid add volumes go straight to `hits`; the chord
        // buffers are touched only by mesh and subtract volumes, so a scene
        // without them never allocates.
        thread_local std::vector<std::uint32_t> meshAdds;
        meshAdds.clear();
        removed.clear();
        bvh.traverse(from, delta, 1.0, [&](std::uint32_t index) {
            const PreparedFogVolume& v = volumes[index];
            if (v.blend == FogVolumeBlend::Subtract) {
                detail::clippedChords(v, from, delta, 0.0, 1.0, removed);
            } else if (v.shape == FogVolumeShape::Mesh) {
                meshAdds.push_back(index);
            } else {
                const VolumeSegment seg = detail::clippedSegment(v, from, delta, 1.0);
                if (seg.hit) {
                    hits.push({index, seg.tIn, seg.tOut, detail::segmentOpticalDepth(v, from, delta, seg)});
                }
            }
        });
        if (removed.empty() && meshAdds.empty()) {
            std::sort(hits.begin(), hits.end(), backToFront);
            return;
        }
        // The union of the subtract chords: sorted, overlaps merged once.
        std::sort(removed.begin(), removed.end(),
                  [](const VolumeSegment& a, const VolumeSegment& b) { return a.tIn < b.tIn; });
        std::size_t merged = 0;
        for (const VolumeSegment& c : removed) {
            if (merged > 0 && c.tIn <= removed[merged - 1].tOut) {
                removed[merged - 1].tOut = std::max(removed[merged - 1].tOut, c.tOut);
            } else {
                removed[merged++] = c;
            }
        }
        removed.resize(merged);
        // Every add volume's chords outside the union.
        thread_local std::vector<VolumeSegment> chords;
        thread_local std::vector<VolumeSegment> pieces;
        auto cut = [&](std::uint32_t index, Hit& hit) {
            const PreparedFogVolume& v = volumes[index];
            chords.clear();
            detail::clippedChords(v, from, delta, 0.0, 1.0, chords);
            pieces.clear();
            subtractUnion(chords, removed, pieces);
            if (pieces.empty()) {
                return false;
            }
            double tau = 0.0;
            for (const VolumeSegment& piece : pieces) {
                tau += detail::stretchOpticalDepth(v, from, delta, piece);
            }
            hit = {index, pieces.front().tIn, pieces.back().tOut, std::min(tau, kMaxOpticalDepth)};
            return true;
        };
        if (!removed.empty()) {
            Hit* kept = hits.begin();
            for (Hit* h = hits.begin(); h != hits.end(); ++h) {
                Hit cutHit;
                if (cut(h->index, cutHit)) *kept++ = cutHit;
            }
            hits.resize(std::size_t(kept - hits.begin()));
        }
        for (const std::uint32_t index : meshAdds) {
            Hit hit;
            if (cut(index, hit)) hits.push(hit);
        }
        std::sort(hits.begin(), hits.end(), backToFront);
    }

    /// The parts of sorted disjoint `chords` outside the sorted disjoint
    /// `removed`, appended to `out`.
    static void subtractUnion(const std::vector<VolumeSegment>& chords,
                              const std::vector<VolumeSegment>& removed, std::vector<VolumeSegment>& out) {
        std::size_t r = 0;
        for (const VolumeSegment& c : chords) {
            double start = c.tIn;
            while (r < removed.size() && removed[r].tOut <= start) ++r;
            for (std::size_t k = r; k < removed.size() && removed[k].tIn < c.tOut; ++k) {
                if (removed[k].tIn > start) out.push_back({true, start, removed[k].tIn});
                start = std::max(start, removed[k].tOut);
            }
            if (start < c.tOut) out.push_back({true, start, c.tOut});
        }
    }

    FogQueryResult run(const glm::dvec3& from, const glm::dvec3& to,
                       std::vector<VolumeContribution>* contributions) const {
        FogQueryResult result;
        if (!withinCoordinateRange(from) || !withinCoordinateRange(to)) {
            return result;  // non-finite or absurd input: no fog
        }
        const glm::dvec3 delta = to - from;
        if (!withinCoordinateRange(delta)) {
            return result;
        }
        const double length = glm::length(delta);

        HitBuffer hits;
        thread_local std::vector<VolumeSegment> removed;
        collect(from, delta, hits, removed);

        // 1. Global fog over the segment outside the subtract volumes: the
        //    integral over each remaining piece (no difference of large
        //    numbers, never negative).
        double tauGlobal = 0.0;
        if (removed.empty()) {
            tauGlobal = heightFogOpticalDepth(desc.heightFog, from, delta);
        } else {
            thread_local const std::vector<VolumeSegment> whole{VolumeSegment{true, 0.0, 1.0}};
            thread_local std::vector<VolumeSegment> open;
            open.clear();
            subtractUnion(whole, removed, open);
            for (const VolumeSegment& piece : open) {
                tauGlobal += heightFogOpticalDepth(desc.heightFog, from + piece.tIn * delta,
                                                   (piece.tOut - piece.tIn) * delta);
            }
            tauGlobal = std::min(tauGlobal, kMaxOpticalDepth);
        }
        result.globalOpticalDepth = tauGlobal;

        // The sky's fog colour is needed only where some fog uses it.
        bool needFogColour = tauGlobal > 0.0 && desc.heightFogColourMode != FogColourMode::Custom;
        for (const Hit& h : hits) {
            needFogColour = needFogColour ||
                            (h.opticalDepth > 0.0 && volumes[h.index].colourMode != FogColourMode::Custom);
        }
        if (contributions != nullptr) {
            needFogColour = needFogColour || hits.size() > 0;
        }
        const glm::dvec3 fogColour =
            needFogColour ? fogColourUnit(detail::safeDirection(delta), length) : glm::dvec3(0.0);

        double transmittance = std::exp(-tauGlobal);
        glm::dvec3 inScatter =
            fogColourFor(heightFogColourMode, heightFogColour, fogColour) * -std::expm1(-tauGlobal);

        // 2. Volumes, back to front: L <- L T_v + C_v (1 - T_v).
        for (const Hit& h : hits) {
            const PreparedFogVolume& v = volumes[h.index];
            const glm::dvec3 colour = fogColourFor(v.colourMode, v.colour, fogColour);
            const double tv = std::exp(-h.opticalDepth);
            inScatter = inScatter * tv + colour * -std::expm1(-h.opticalDepth);
            transmittance *= tv;
            if (contributions != nullptr) {
                VolumeContribution c;
                c.volumeIndex = h.index;
                c.tIn = h.tIn * length;
                c.tOut = h.tOut * length;
                c.opticalDepth = h.opticalDepth;
                c.colour = colour;
                contributions->push_back(c);
            }
        }

        // 3. Emitters, additive.
        glm::dvec3 emitted(0.0);
        for (const Emitter& e : desc.emitters) {
            emitted += emitterInScatter(e, from, delta, 1.0);
        }
        result.transmittance = glm::dvec3(transmittance);
        result.inScatter = inScatter + emitted;
        result.emitterInScatter = emitted;
        return result;
    }
};

FogScene::FogScene(const FogSceneDesc& desc) : impl_(std::make_unique<Impl>(desc)) {}
FogScene::~FogScene() = default;
FogScene::FogScene(FogScene&&) noexcept = default;
FogScene& FogScene::operator=(FogScene&&) noexcept = default;

FogQueryResult FogScene::query(const glm::dvec3& from, const glm::dvec3& to) const {
    return impl_->run(from, to, nullptr);
}

FogQueryResult FogScene::query(const glm::dvec3& from, const glm::dvec3& to,
                               std::vector<VolumeContribution>& volumes) const {
    volumes.clear();
    return impl_->run(from, to, &volumes);
}

void FogScene::queryBatch(const FogSegment* segments, FogQueryResult* results, std::size_t count) const {
    for (std::size_t i = 0; i < count; ++i) {
        results[i] = impl_->run(segments[i].from, segments[i].to, nullptr);
    }
}

glm::dvec3 FogScene::fogColour(const glm::dvec3& viewDirection, double distance) const {
    return impl_->fogColourUnit(detail::safeDirection(viewDirection), std::isnan(distance) ? 0.0 : distance);
}

const FogSceneDesc& FogScene::desc() const { return impl_->desc; }

}  // namespace aerial
