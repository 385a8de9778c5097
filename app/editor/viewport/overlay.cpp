// overlay.cpp — projection, near-plane and guard-band clipping, outlines of
// volumes, emitter icons and the ground grid drawn with ImGui's ImDrawList
// (see overlay.hpp).
#include "viewport/overlay.hpp"

#include <aerial/finite.hpp>
#include <aerial/fog_mesh.hpp>

#include <imgui.h>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <numbers>
#include <utility>

namespace aerial::editor {
namespace {

/// The edges of a mesh worth drawing (object space vertex pairs): all of
/// them for a small mesh, the creases of a large one. Cached per mesh (the
/// outline is drawn every frame).
const std::vector<std::pair<std::uint32_t, std::uint32_t>>& meshOutlineEdges(
    const std::shared_ptr<const FogMesh>& mesh) {
    struct Entry {
        std::weak_ptr<const FogMesh> mesh;
        std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
    };
    static std::map<const FogMesh*, Entry> cache;
    for (auto it = cache.begin(); it != cache.end();) it = it->second.mesh.expired() ? cache.erase(it) : ++it;
    Entry& entry = cache[mesh.get()];
    if (entry.mesh.lock() == mesh) return entry.edges;
    entry = {mesh, {}};
    const std::vector<glm::dvec3>& p = mesh->positions();
    const std::vector<std::uint32_t>& idx = mesh->indices();
    // Each undirected edge with the normals of its (two) triangles.
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::pair<glm::dvec3, glm::dvec3>> faces;
    for (std::size_t t = 0; t + 2 < idx.size(); t += 3) {
        const glm::dvec3 n = glm::normalize(glm::cross(p[idx[t + 1]] - p[idx[t]], p[idx[t + 2]] - p[idx[t]]));
        for (int e = 0; e < 3; ++e) {
            std::uint32_t a = idx[t + std::size_t(e)], b = idx[t + std::size_t((e + 1) % 3)];
            if (a > b) std::swap(a, b);
            auto [it, inserted] = faces.try_emplace({a, b}, n, n);
            if (!inserted) it->second.second = n;
        }
    }
    // A small mesh: every edge but those inside a flat face (the diagonal
    // of a quad); a large one: its creases.
    const bool all = faces.size() <= kMeshOutlineAllEdges;
    const double creaseCos = std::cos((all ? 0.5 : 25.0) * std::numbers::pi / 180.0);
    for (const auto& [edge, normals] : faces) {
        if (glm::dot(normals.first, normals.second) < creaseCos) entry.edges.push_back(edge);
    }
    return entry.edges;
}

glm::dvec2 sanitisedSize(glm::dvec2 size) {
    return {(std::isfinite(size.x) && size.x >= 1.0) ? size.x : 1.0,
            (std::isfinite(size.y) && size.y >= 1.0) ? size.y : 1.0};
}

// Viewport pixels of a view-space offset (right, up, depth > 0). Uses the
// projection's own scale factors, so it matches rayThroughPixel exactly.
glm::dvec2 projectView(const renderer::CameraFrame& frame, glm::dvec2 size, double x, double y,
                       double depth) {
    const double ndcX = x * frame.clipFromView[0][0] / depth;
    const double ndcY = y * frame.clipFromView[1][1] / depth;
    return {(ndcX + 1.0) * 0.5 * size.x, (1.0 - ndcY) * 0.5 * size.y};
}

double nearOf(const renderer::CameraFrame& frame) {
    return (std::isfinite(frame.nearDistance) && frame.nearDistance > 0.0) ? frame.nearDistance : 1e-3;
}

ImVec2 toIm(glm::dvec2 origin, glm::dvec2 p) {
    return ImVec2(static_cast<float>(origin.x + p.x), static_cast<float>(origin.y + p.y));
}

double srgbEncode(double c) {
    c = std::clamp(c, 0.0, 1.0);
    return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

}  // namespace

std::optional<glm::dvec2> projectToViewport(const renderer::CameraFrame& frame, glm::dvec2 viewportSize,
                                            glm::dvec3 world) {
    if (!isFinite(world) || !isFinite(frame.eye)) {
        return std::nullopt;
    }
    const glm::dvec3 v = world - frame.eye;
    const double depth = glm::dot(v, frame.forward);
    if (!(depth >= nearOf(frame))) {
        return std::nullopt;
    }
    const glm::dvec2 p = projectView(frame, sanitisedSize(viewportSize), glm::dot(v, frame.right),
                                     glm::dot(v, frame.up), depth);
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
        return std::nullopt;
    }
    return p;
}

std::optional<ScreenSegment> clipSegmentToRect(const ScreenSegment& segment, glm::dvec2 lo, glm::dvec2 hi) {
    const glm::dvec2 d = segment.b - segment.a;
    double t0 = 0.0;
    double t1 = 1.0;
    // Liang–Barsky: for each edge, p t <= q.
    const std::array<double, 4> p{-d.x, d.x, -d.y, d.y};
    const std::array<double, 4> q{segment.a.x - lo.x, hi.x - segment.a.x, segment.a.y - lo.y,
                                  hi.y - segment.a.y};
    for (int i = 0; i < 4; ++i) {
        if (!std::isfinite(p[i]) || !std::isfinite(q[i])) {
            return std::nullopt;
        }
        if (p[i] == 0.0) {
            if (q[i] < 0.0) {
                return std::nullopt;  // parallel and outside
            }
            continue;
        }
        const double r = q[i] / p[i];
        if (p[i] < 0.0) {
            t0 = std::max(t0, r);
        } else {
            t1 = std::min(t1, r);
        }
        if (t0 > t1) {
            return std::nullopt;
        }
    }
    ScreenSegment out;
    out.a = segment.a + t0 * d;
    out.b = segment.a + t1 * d;
    if (t0 == 0.0) out.a = segment.a;
    if (t1 == 1.0) out.b = segment.b;
    return out;
}

std::optional<ScreenSegment> projectSegment(const renderer::CameraFrame& frame, glm::dvec2 viewportSize,
                                            const glm::dvec3& a, const glm::dvec3& b, double guardBandPx) {
    if (!isFinite(a) || !isFinite(b) || !isFinite(frame.eye)) {
        return std::nullopt;
    }
    const glm::dvec2 size = sanitisedSize(viewportSize);
    const double n = nearOf(frame);
    glm::dvec3 va = a - frame.eye;
    glm::dvec3 vb = b - frame.eye;
    // View-space coordinates (right, up, depth).
    glm::dvec3 pa{glm::dot(va, frame.right), glm::dot(va, frame.up), glm::dot(va, frame.forward)};
    glm::dvec3 pb{glm::dot(vb, frame.right), glm::dot(vb, frame.up), glm::dot(vb, frame.forward)};
    if (!isFinite(pa) || !isFinite(pb)) {
        return std::nullopt;
    }
    const bool aIn = pa.z >= n;
    const bool bIn = pb.z >= n;
    if (!aIn && !bIn) {
        return std::nullopt;
    }
    if (!aIn || !bIn) {
        // Exactly one end behind the near plane: move it onto the plane.
        const double t = (n - pa.z) / (pb.z - pa.z);  // in [0, 1], denominator != 0
        glm::dvec3 onPlane = pa + t * (pb - pa);
        onPlane.z = n;
        (aIn ? pb : pa) = onPlane;
    }
    ScreenSegment s;
    s.a = projectView(frame, size, pa.x, pa.y, pa.z);
    s.b = projectView(frame, size, pb.x, pb.y, pb.z);
    const double guard =
        (std::isfinite(guardBandPx) && guardBandPx >= 0.0) ? std::min(guardBandPx, 1e6) : 0.0;
    return clipSegmentToRect(s, glm::dvec2(-guard), size + glm::dvec2(guard));
}

std::vector<WorldSegment> volumeOutlineSegments(const FogVolume& volume, int ellipseSegments) {
    std::vector<WorldSegment> out;
    // Core's geometry (fog_volume.hpp): the same validity rules and the same
    // world-from-object map as the renderer and the picking.
    const PreparedFogVolume prepared = prepareFogVolume(volume);
    if (!prepared.valid) {
        return out;
    }
    const auto world = [&](const glm::dvec3& object) {
        return prepared.position + prepared.worldFromObject * object;
    };
    if (volume.shape == FogVolumeShape::Mesh) {
        const auto& edges = meshOutlineEdges(prepared.mesh);
        const std::vector<glm::dvec3>& p = prepared.mesh->positions();
        out.reserve(edges.size());
        for (const auto& [a, b] : edges) out.emplace_back(world(p[a]), world(p[b]));
        if (edges.size() >= 12) return out;
        // A large smooth mesh: its bounds, so that it is seen at all.
        const glm::dvec3 lo = prepared.mesh->boundsMin(), hi = prepared.mesh->boundsMax();
        for (int corner = 0; corner < 8; ++corner) {
            const glm::dvec3 a{(corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y,
                               (corner & 4) ? hi.z : lo.z};
            for (int bit = 0; bit < 3; ++bit) {
                if ((corner & (1 << bit)) == 0) {
                    glm::dvec3 b = a;
                    b[bit] = hi[bit];
                    out.emplace_back(world(a), world(b));
                }
            }
        }
        return out;
    }
    if (volume.shape == FogVolumeShape::Box) {
        out.reserve(12);
        for (int corner = 0; corner < 8; ++corner) {
            const glm::dvec3 a{(corner & 1) ? 1.0 : -1.0, (corner & 2) ? 1.0 : -1.0,
                               (corner & 4) ? 1.0 : -1.0};
            for (int bit = 0; bit < 3; ++bit) {
                if ((corner & (1 << bit)) == 0) {  // each edge once: from its "-" end
                    glm::dvec3 b = a;
                    b[bit] = 1.0;
                    out.emplace_back(world(a), world(b));
                }
            }
        }
        return out;
    }
    const int n = std::clamp(ellipseSegments, 8, 512);
    out.reserve(static_cast<std::size_t>(3 * n));
    for (int plane = 0; plane < 3; ++plane) {
        const int u = plane;  // XY, YZ, ZX
        const int v = (plane + 1) % 3;
        const auto pointAt = [&](int i) {
            const double angle = 2.0 * std::numbers::pi * i / n;
            glm::dvec3 o(0.0);
            o[u] = std::cos(angle);
            o[v] = std::sin(angle);
            return world(o);
        };
        glm::dvec3 prev = pointAt(0);
        for (int i = 1; i <= n; ++i) {
            const glm::dvec3 next = pointAt(i % n);
            out.emplace_back(prev, next);
            prev = next;
        }
    }
    return out;
}

std::uint32_t overlayColour(double r, double g, double b, double a) {
    const auto byte = [](double c) {
        return static_cast<std::uint32_t>(
            std::lround(std::clamp(std::isfinite(c) ? c : 0.0, 0.0, 1.0) * 255.0));
    };
    return (byte(a) << 24) | (byte(b) << 16) | (byte(g) << 8) | byte(r);
}

std::uint32_t displayColourOfLinear(const glm::dvec3& linear, double alpha) {
    glm::dvec3 c;
    for (int i = 0; i < 3; ++i) {
        c[i] = (std::isfinite(linear[i]) && linear[i] > 0.0) ? linear[i] : 0.0;
    }
    const double m = std::max({c.x, c.y, c.z});
    if (!(m > 0.0)) {
        return overlayColour(0.5, 0.5, 0.5, alpha);
    }
    if (m > 1.0) {
        c /= m;
    }
    return overlayColour(srgbEncode(c.x), srgbEncode(c.y), srgbEncode(c.z), alpha);
}

void drawVolumeOutline(ImDrawList* drawList, glm::dvec2 viewportOriginScreen,
                       const renderer::CameraFrame& frame, glm::dvec2 viewportSize, const FogVolume& volume,
                       std::uint32_t colour, float thickness) {
    if (drawList == nullptr) {
        return;
    }
    for (const WorldSegment& seg : volumeOutlineSegments(volume)) {
        if (const auto s = projectSegment(frame, viewportSize, seg.first, seg.second)) {
            drawList->AddLine(toIm(viewportOriginScreen, s->a), toIm(viewportOriginScreen, s->b), colour,
                              thickness);
        }
    }
}

void drawEmitterIcon(ImDrawList* drawList, glm::dvec2 viewportOriginScreen,
                     const renderer::CameraFrame& frame, glm::dvec2 viewportSize, const Emitter& emitter,
                     bool selected, float radiusPx) {
    if (drawList == nullptr) {
        return;
    }
    const auto p = projectToViewport(frame, viewportSize, emitter.position);
    const float r = (std::isfinite(radiusPx) && radiusPx > 0.0f) ? std::min(radiusPx, 200.0f) : 10.0f;
    const glm::dvec2 size = sanitisedSize(viewportSize);
    if (!p || p->x < -2.0 * r || p->y < -2.0 * r || p->x > size.x + 2.0 * r || p->y > size.y + 2.0 * r) {
        return;
    }
    const ImVec2 c = toIm(viewportOriginScreen, *p);
    const ImU32 fill = displayColourOfLinear(emitter.colour);
    const ImU32 outline = overlayColour(0.0, 0.0, 0.0, 0.8);
    if (emitter.kind == EmitterKind::Lightning) {
        // A bolt: a zigzag polygon inside the icon's circle.
        const ImVec2 bolt[] = {
            ImVec2(c.x + 0.15f * r, c.y - 1.0f * r),  ImVec2(c.x - 0.45f * r, c.y + 0.1f * r),
            ImVec2(c.x - 0.02f * r, c.y + 0.1f * r),  ImVec2(c.x - 0.2f * r, c.y + 1.0f * r),
            ImVec2(c.x + 0.45f * r, c.y - 0.15f * r), ImVec2(c.x + 0.02f * r, c.y - 0.15f * r),
        };
        drawList->AddCircleFilled(c, r, overlayColour(0.1, 0.1, 0.15, 0.6));
        drawList->AddCircle(c, r, fill, 0, 1.5f);
        drawList->AddTriangleFilled(bolt[0], bolt[1], bolt[2], fill);
        drawList->AddTriangleFilled(bolt[0], bolt[2], bolt[5], fill);
        drawList->AddTriangleFilled(bolt[5], bolt[3], bolt[4], fill);
        drawList->AddTriangleFilled(bolt[5], bolt[2], bolt[3], fill);
        if (r >= 16.0f) {  // small bolts read better without the dark edge
            drawList->AddPolyline(bolt, 6, outline, ImDrawFlags_Closed, 1.0f);
        }
    } else {
        // A sun: a disc and eight rays.
        for (int i = 0; i < 8; ++i) {
            const float angle = static_cast<float>(i) * 0.25f * static_cast<float>(std::numbers::pi);
            const ImVec2 dir(std::cos(angle), std::sin(angle));
            drawList->AddLine(ImVec2(c.x + dir.x * 0.7f * r, c.y + dir.y * 0.7f * r),
                              ImVec2(c.x + dir.x * r, c.y + dir.y * r), fill, 2.0f);
        }
        drawList->AddCircleFilled(c, 0.5f * r, fill);
        drawList->AddCircle(c, 0.5f * r, outline, 0, 1.0f);
    }
    if (selected) {
        drawList->AddCircle(c, 1.3f * r, overlayColour(1.0, 1.0, 1.0, 1.0), 0, 2.0f);
    }
}

void drawGroundGrid(ImDrawList* drawList, glm::dvec2 viewportOriginScreen, const renderer::CameraFrame& frame,
                    glm::dvec2 viewportSize, double spacing, int halfLineCount, std::uint32_t colour) {
    if (drawList == nullptr || !std::isfinite(spacing) || !(spacing > 0.0)) {
        return;
    }
    const int n = std::clamp(halfLineCount, 1, 500);
    const double extent = spacing * n;
    const auto line = [&](const glm::dvec3& a, const glm::dvec3& b, std::uint32_t c, float thickness) {
        if (const auto s = projectSegment(frame, viewportSize, a, b)) {
            drawList->AddLine(toIm(viewportOriginScreen, s->a), toIm(viewportOriginScreen, s->b), c,
                              thickness);
        }
    };
    for (int i = -n; i <= n; ++i) {
        if (i == 0) {
            continue;  // the axes below
        }
        const double w = spacing * i;
        line({w, 0.0, -extent}, {w, 0.0, extent}, colour, 1.0f);
        line({-extent, 0.0, w}, {extent, 0.0, w}, colour, 1.0f);
    }
    line({-extent, 0.0, 0.0}, {extent, 0.0, 0.0}, overlayColour(0.9, 0.25, 0.25, 0.8), 1.5f);
    line({0.0, 0.0, -extent}, {0.0, 0.0, extent}, overlayColour(0.25, 0.45, 0.95, 0.8), 1.5f);
}

}  // namespace aerial::editor
