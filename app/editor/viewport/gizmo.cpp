// gizmo.cpp — translate / rotate / scale gizmo: hover tests in screen space,
// drags solved in world space against the press state (see gizmo.hpp), and
// ImDrawList drawing.
#include "viewport/gizmo.hpp"

#include "viewport/overlay.hpp"
#include "viewport/picking.hpp"

#include <aerial/finite.hpp>

#include <imgui.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <optional>

namespace aerial::editor {
namespace {

constexpr int kRingSegments = 64;
constexpr double kAxisStart = 0.2;  // axis handles span [kAxisStart, 1] L
constexpr double kPlaneLo = 0.25;   // plane squares span [kPlaneLo, kPlaneHi] L on both axes
constexpr double kPlaneHi = 0.45;
constexpr double kCentreFraction = 0.08;  // centre handle radius, fraction of sizePx
constexpr double kViewRing = 1.2;         // view-ring radius, in L

glm::dquat unitOrIdentity(const glm::dquat& q) {
    const double n2 = q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z;
    if (!isFinite(q) || !(n2 > 1e-200) || !std::isfinite(n2)) {
        return glm::dquat(1.0, 0.0, 0.0, 0.0);
    }
    return q / std::sqrt(n2);
}

double distanceToSegment(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
    const glm::dvec2 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * ab));
}

bool insideConvexQuad(glm::dvec2 p, const std::array<glm::dvec2, 4>& q) {
    int sign = 0;
    for (int i = 0; i < 4; ++i) {
        const glm::dvec2 e = q[(i + 1) % 4] - q[i];
        const glm::dvec2 v = p - q[i];
        const double c = e.x * v.y - e.y * v.x;
        const int s = c > 0.0 ? 1 : (c < 0.0 ? -1 : 0);
        if (s != 0) {
            if (sign != 0 && s != sign) {
                return false;
            }
            sign = s;
        }
    }
    return true;
}

// Parameter s of the point of the line p0 + s a (|a| = 1) closest to the
// ray (unit direction): s = (b (d.w) - a.w) / (1 - b^2), b = a.d,
// w = p0 - o. nullopt when the two are (nearly) parallel or the closest point
// of the ray, at t = d.w + s b, is behind its origin (the mouse is beyond the
// axis's vanishing point).
std::optional<double> closestLineParameter(const Ray& ray, const glm::dvec3& p0, const glm::dvec3& a) {
    const double b = glm::dot(a, ray.direction);
    const double denom = 1.0 - b * b;
    if (!(denom > 1e-9)) {
        return std::nullopt;
    }
    const glm::dvec3 w = p0 - ray.origin;
    const double s = (b * glm::dot(ray.direction, w) - glm::dot(a, w)) / denom;
    const double t = glm::dot(ray.direction, w) + s * b;
    if (!std::isfinite(s) || !(t > 0.0)) {
        return std::nullopt;
    }
    return s;
}

// Positions a drag may produce: the camera controller's pivot range.
constexpr double kMaxGizmoCoordinate = 1.0e7;  // [m]

bool withinGizmoRange(const glm::dvec3& p) {
    return std::fabs(p.x) <= kMaxGizmoCoordinate && std::fabs(p.y) <= kMaxGizmoCoordinate &&
           std::fabs(p.z) <= kMaxGizmoCoordinate;  // false for NaN
}

// Hit of the ray with the plane through p0 of normal n, in front of the
// origin; nullopt when (nearly) parallel or behind.
std::optional<glm::dvec3> rayPlane(const Ray& ray, const glm::dvec3& p0, const glm::dvec3& n) {
    const double dn = glm::dot(ray.direction, n);
    if (!(std::fabs(dn) > 1e-6)) {
        return std::nullopt;
    }
    const double t = glm::dot(p0 - ray.origin, n) / dn;
    if (!(t > 0.0) || !std::isfinite(t)) {
        return std::nullopt;
    }
    return ray.origin + t * ray.direction;
}

// The offset from the ring's centre c to where the ray meets the ring's
// plane (normal n); for an edge-on ring (no hit), to the ray's closest point
// to the centre, flattened onto the plane.
glm::dvec3 ringVector(const Ray& ray, const glm::dvec3& c, const glm::dvec3& n) {
    if (const auto hit = rayPlane(ray, c, n)) return *hit - c;
    const glm::dvec3 p = ray.origin + glm::dot(c - ray.origin, ray.direction) * ray.direction;
    return (p - c) - n * glm::dot(p - c, n);
}

double snapTo(double value, double step) { return std::round(value / step) * step; }

bool validStep(double step) { return std::isfinite(step) && step > 0.0; }

bool sameTransform(const GizmoTransform& a, const GizmoTransform& b) {
    return a.position == b.position && a.rotation == b.rotation && a.scale == b.scale;
}

// Two unit vectors spanning the plane normal to unit n.
void planeBasis(const glm::dvec3& n, glm::dvec3& u, glm::dvec3& v) {
    const glm::dvec3 helper = std::fabs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    u = glm::normalize(glm::cross(n, helper));
    v = glm::cross(n, u);
}

struct Layout {
    bool valid = false;
    glm::dvec3 centre{0.0};
    glm::dvec2 centreScreen{0.0};
    double length = 1.0;  // L [m]
    glm::dvec3 axes[3]{};
    bool axisVisible[3]{};
    bool planeVisible[3]{};  // normal axis k
    glm::dvec3 toEye{0.0, 0.0, 1.0};
};

Layout computeLayout(const Gizmo& gizmo, const renderer::CameraFrame& frame, glm::dvec2 size, GizmoMode mode,
                     GizmoSpace space, const GizmoTransform& t) {
    Layout l;
    if (!isFinite(t.position) || !isFinite(frame.eye)) {
        return l;
    }
    const auto c = projectToViewport(frame, size, t.position);
    if (!c) {
        return l;
    }
    l.centre = t.position;
    l.centreScreen = *c;
    l.length = gizmo.worldSizeAt(frame, size.y, t.position);
    if (!(l.length > 0.0) || !std::isfinite(l.length)) {
        return l;
    }
    Gizmo::axes(mode, space, t.rotation, l.axes);
    const glm::dvec3 toEye = frame.eye - t.position;
    const double toEyeLen = glm::length(toEye);
    l.toEye = toEyeLen > 0.0 ? toEye / toEyeLen : -frame.forward;
    for (int i = 0; i < 3; ++i) {
        const auto tip = projectToViewport(frame, size, t.position + l.axes[i] * l.length);
        l.axisVisible[i] = tip && glm::length(*tip - l.centreScreen) >= 0.1 * gizmo.sizePx;
        l.planeVisible[i] = std::fabs(glm::dot(l.axes[i], l.toEye)) >= 0.15;
    }
    l.valid = true;
    return l;
}

std::array<glm::dvec3, 4> planeQuad(const Layout& l, int normalAxis) {
    const glm::dvec3 a = l.axes[(normalAxis + 1) % 3] * l.length;
    const glm::dvec3 b = l.axes[(normalAxis + 2) % 3] * l.length;
    return {l.centre + kPlaneLo * a + kPlaneLo * b, l.centre + kPlaneHi * a + kPlaneLo * b,
            l.centre + kPlaneHi * a + kPlaneHi * b, l.centre + kPlaneLo * a + kPlaneHi * b};
}

// Points of a ring of `radius` [m] about unit `axis` through the centre.
std::array<glm::dvec3, kRingSegments + 1> ringPoints(const Layout& l, const glm::dvec3& axis, double radius) {
    glm::dvec3 u;
    glm::dvec3 v;
    planeBasis(axis, u, v);
    std::array<glm::dvec3, kRingSegments + 1> pts{};
    for (int i = 0; i <= kRingSegments; ++i) {
        const double a = 2.0 * std::numbers::pi * (i % kRingSegments) / kRingSegments;
        pts[static_cast<std::size_t>(i)] = l.centre + radius * (std::cos(a) * u + std::sin(a) * v);
    }
    return pts;
}

// The ring segment i faces the camera (its midpoint on the eye's side).
bool ringSegmentInFront(const Layout& l, const glm::dvec3& a, const glm::dvec3& b) {
    return glm::dot(0.5 * (a + b) - l.centre, l.toEye) >= -1e-9 * l.length;
}

std::uint32_t handleColour(int axis, bool highlighted, double alpha = 1.0) {
    if (highlighted) {
        return overlayColour(1.0, 0.85, 0.1, alpha);
    }
    switch (axis) {
        case 0:
            return overlayColour(0.9, 0.2, 0.2, alpha);
        case 1:
            return overlayColour(0.3, 0.85, 0.25, alpha);
        case 2:
            return overlayColour(0.25, 0.45, 1.0, alpha);
        default:
            return overlayColour(0.9, 0.9, 0.9, alpha);
    }
}

}  // namespace

void Gizmo::axes(GizmoMode mode, GizmoSpace space, const glm::dquat& rotation, glm::dvec3 out[3]) {
    if (space == GizmoSpace::Local || mode == GizmoMode::Scale) {
        const glm::dquat q = unitOrIdentity(rotation);
        out[0] = glm::normalize(q * glm::dvec3(1, 0, 0));
        out[1] = glm::normalize(q * glm::dvec3(0, 1, 0));
        out[2] = glm::normalize(q * glm::dvec3(0, 0, 1));
    } else {
        out[0] = {1, 0, 0};
        out[1] = {0, 1, 0};
        out[2] = {0, 0, 1};
    }
}

double Gizmo::worldSizeAt(const renderer::CameraFrame& frame, double viewportHeight,
                          const glm::dvec3& position) const {
    const double h = (std::isfinite(viewportHeight) && viewportHeight >= 1.0) ? viewportHeight : 1.0;
    const double nearD =
        (std::isfinite(frame.nearDistance) && frame.nearDistance > 0.0) ? frame.nearDistance : 1e-3;
    double depth = glm::dot(position - frame.eye, frame.forward);
    if (!std::isfinite(depth)) {
        return 0.0;
    }
    depth = std::max(depth, nearD);
    const double tanHalf = 1.0 / frame.clipFromView[1][1];
    const double px = (std::isfinite(sizePx) && sizePx > 0.0) ? sizePx : 100.0;
    const double l = px * 2.0 * tanHalf * depth / h;
    return std::isfinite(l) ? l : 0.0;
}

GizmoHandle Gizmo::hitTest(const renderer::CameraFrame& frame, glm::dvec2 viewportSize, glm::dvec2 mouse,
                           GizmoMode mode, GizmoSpace space, const GizmoTransform& transform) const {
    if (!isFinite(mouse)) {
        return GizmoHandle::None;
    }
    const Layout l = computeLayout(*this, frame, viewportSize, mode, space, transform);
    if (!l.valid) {
        return GizmoHandle::None;
    }
    const double radius = (std::isfinite(pickRadiusPx) && pickRadiusPx > 0.0) ? pickRadiusPx : 8.0;
    const double px = (std::isfinite(sizePx) && sizePx > 0.0) ? sizePx : 100.0;
    if (mode != GizmoMode::Rotate &&
        glm::length(mouse - l.centreScreen) <= std::max(radius, kCentreFraction * px)) {
        return GizmoHandle::Centre;
    }
    GizmoHandle best = GizmoHandle::None;
    double bestDistance = radius;
    const auto consider = [&](GizmoHandle h, double d) {
        if (d <= bestDistance) {
            bestDistance = d;
            best = h;
        }
    };
    if (mode == GizmoMode::Rotate) {
        for (int k = 0; k < 3; ++k) {
            const auto pts = ringPoints(l, l.axes[k], l.length);
            for (int i = 0; i < kRingSegments; ++i) {
                const glm::dvec3& a = pts[static_cast<std::size_t>(i)];
                const glm::dvec3& b = pts[static_cast<std::size_t>(i + 1)];
                if (!ringSegmentInFront(l, a, b)) {
                    continue;
                }
                if (const auto s = projectSegment(frame, viewportSize, a, b)) {
                    consider(static_cast<GizmoHandle>(k), distanceToSegment(mouse, s->a, s->b));
                }
            }
        }
        const auto pts = ringPoints(l, l.toEye, kViewRing * l.length);
        for (int i = 0; i < kRingSegments; ++i) {
            if (const auto s = projectSegment(frame, viewportSize, pts[static_cast<std::size_t>(i)],
                                              pts[static_cast<std::size_t>(i + 1)])) {
                consider(GizmoHandle::View, distanceToSegment(mouse, s->a, s->b));
            }
        }
        return best;
    }
    if (mode == GizmoMode::Translate) {
        for (int k = 0; k < 3; ++k) {
            if (!l.planeVisible[k]) {
                continue;
            }
            const auto quad = planeQuad(l, k);
            std::array<glm::dvec2, 4> screen{};
            bool ok = true;
            for (int i = 0; i < 4; ++i) {
                const auto p = projectToViewport(frame, viewportSize, quad[static_cast<std::size_t>(i)]);
                ok = ok && p.has_value();
                if (p) screen[static_cast<std::size_t>(i)] = *p;
            }
            if (ok && insideConvexQuad(mouse, screen)) {
                return static_cast<GizmoHandle>(static_cast<int>(GizmoHandle::PlaneYZ) + k);
            }
        }
    }
    for (int k = 0; k < 3; ++k) {
        if (!l.axisVisible[k]) {
            continue;
        }
        if (const auto s = projectSegment(frame, viewportSize, l.centre + l.axes[k] * (kAxisStart * l.length),
                                          l.centre + l.axes[k] * l.length)) {
            consider(static_cast<GizmoHandle>(k), distanceToSegment(mouse, s->a, s->b));
        }
    }
    return best;
}

GizmoResult Gizmo::update(const renderer::CameraFrame& frame, glm::dvec2 viewportSize,
                          const GizmoInput& input, GizmoMode mode, GizmoSpace space, const GizmoSnap& snap,
                          GizmoTransform& inout) {
    GizmoResult result;
    const bool mouseOk = isFinite(input.mouse);
    const Ray ray = rayThroughPixel(frame, input.mouse, viewportSize);

    if (!active_) {
        hovered_ =
            mouseOk ? hitTest(frame, viewportSize, input.mouse, mode, space, inout) : GizmoHandle::None;
        if (input.pressed && hovered_ != GizmoHandle::None && isFinite(inout.position) &&
            isFinite(inout.scale) && isFinite(inout.rotation)) {
            // Start a drag: latch everything the drag is relative to.
            start_ = inout;
            start_.rotation = unitOrIdentity(inout.rotation);
            activeMode_ = mode;
            activeSpace_ = space;
            activeHandle_ = hovered_;
            axes(mode, space, start_.rotation, axes_);
            worldSize_ = worldSizeAt(frame, viewportSize.y, start_.position);
            pressMouse_ = input.mouse;
            angle_ = 0.0;
            const glm::dvec3 c = start_.position;
            const int k = static_cast<int>(activeHandle_);
            bool ok = true;
            if (mode == GizmoMode::Rotate) {
                planeNormal_ = activeHandle_ == GizmoHandle::View ? glm::normalize(frame.eye - c) : axes_[k];
                ok = isFinite(planeNormal_);
                const glm::dvec3 v = ringVector(ray, c, planeNormal_);
                ok = ok && glm::length(v) > 1e-12 * std::max(worldSize_, 1e-300);
                prevRotateVector_ = ok ? glm::normalize(v) : glm::dvec3(0.0);
                pressPoint_ = c + prevRotateVector_;  // unit offset: the press direction
                // A ring seen nearly edge-on: turn by the mouse travel along its tangent.
                rotateByTangent_ = false;
                if (ok && activeHandle_ != GizmoHandle::View &&
                    std::fabs(glm::dot(planeNormal_, glm::normalize(frame.eye - c))) < kEdgeOnRingCos) {
                    const glm::dvec3 p0 = c + prevRotateVector_ * worldSize_;
                    const glm::dvec3 tangent = glm::cross(planeNormal_, prevRotateVector_);
                    const auto a = projectToViewport(frame, viewportSize, p0);
                    const auto b = projectToViewport(frame, viewportSize, p0 + tangent * (1e-3 * worldSize_));
                    if (a && b && glm::length(*b - *a) > 1e-9) {
                        rotateByTangent_ = true;
                        tangentScreen_ = glm::normalize(*b - *a);
                    }
                }
            } else if (activeHandle_ == GizmoHandle::Centre) {
                if (mode == GizmoMode::Translate) {
                    planeNormal_ = frame.forward;
                    const auto hit = rayPlane(ray, c, planeNormal_);
                    ok = hit.has_value();
                    if (hit) pressPoint_ = *hit;
                }
            } else if (k >= 3) {  // translate planes
                planeNormal_ = axes_[k - 3];
                const auto hit = rayPlane(ray, c, planeNormal_);
                ok = hit.has_value();
                if (hit) pressPoint_ = *hit;
            } else {  // axis handles
                const auto s = closestLineParameter(ray, c, axes_[k]);
                ok = s.has_value() && (mode != GizmoMode::Scale || std::fabs(*s) > 1e-6 * worldSize_);
                pressParam_ = s.value_or(0.0);
            }
            if (ok) {
                active_ = true;
                last_ = start_;
                appliedAngle_ = 0.0;
                result.started = true;
            }
        }
    }

    if (active_) {
        GizmoTransform t = last_;
        const glm::dvec3 c = start_.position;
        const int k = static_cast<int>(activeHandle_);
        const bool snapping = snap.enabled;
        if (mouseOk) {
            if (activeMode_ == GizmoMode::Translate) {
                if (activeHandle_ == GizmoHandle::Centre) {
                    if (const auto hit = rayPlane(ray, c, planeNormal_)) {
                        glm::dvec3 offset = *hit - pressPoint_;
                        if (snapping && validStep(snap.translate)) {
                            for (int i = 0; i < 3; ++i) offset[i] = snapTo(offset[i], snap.translate);
                        }
                        t.position = c + offset;
                    }
                } else if (k >= 3) {
                    if (const auto hit = rayPlane(ray, c, planeNormal_)) {
                        glm::dvec3 offset = *hit - pressPoint_;
                        if (snapping && validStep(snap.translate)) {
                            const glm::dvec3& a = axes_[(k - 3 + 1) % 3];
                            const glm::dvec3& b = axes_[(k - 3 + 2) % 3];
                            offset = snapTo(glm::dot(offset, a), snap.translate) * a +
                                     snapTo(glm::dot(offset, b), snap.translate) * b;
                        }
                        t.position = c + offset;
                    }
                } else if (const auto s = closestLineParameter(ray, c, axes_[k])) {
                    double offset = *s - pressParam_;
                    if (snapping && validStep(snap.translate)) offset = snapTo(offset, snap.translate);
                    t.position = c + axes_[k] * offset;
                }
            } else if (activeMode_ == GizmoMode::Rotate && rotateByTangent_) {
                const double px = (std::isfinite(sizePx) && sizePx > 0.0) ? sizePx : 100.0;
                double angle = glm::dot(input.mouse - pressMouse_, tangentScreen_) / px;
                if (snapping && validStep(snap.rotateDeg)) {
                    angle = snapTo(angle, snap.rotateDeg * std::numbers::pi / 180.0);
                }
                if (std::isfinite(angle)) {
                    appliedAngle_ = angle;
                    t.rotation = glm::normalize(glm::angleAxis(angle, planeNormal_) * start_.rotation);
                    prevRotateVector_ = glm::angleAxis(angle, planeNormal_) * (pressPoint_ - c);
                }
            } else if (activeMode_ == GizmoMode::Rotate) {
                glm::dvec3 v = ringVector(ray, c, planeNormal_);
                const double len = glm::length(v);
                if (len > 1e-12 * std::max(worldSize_, 1e-300) && std::isfinite(len)) {
                    v /= len;
                    // Unwrapped: accumulate the signed step since the last frame.
                    angle_ += std::atan2(glm::dot(glm::cross(prevRotateVector_, v), planeNormal_),
                                         glm::dot(prevRotateVector_, v));
                    prevRotateVector_ = v;
                }
                double angle = angle_;
                if (snapping && validStep(snap.rotateDeg)) {
                    angle = snapTo(angle, snap.rotateDeg * std::numbers::pi / 180.0);
                }
                appliedAngle_ = angle;
                t.rotation = glm::normalize(glm::angleAxis(angle, planeNormal_) * start_.rotation);
            } else {  // Scale
                double factor = 1.0;
                bool have = false;
                if (activeHandle_ == GizmoHandle::Centre) {
                    const double px = (std::isfinite(sizePx) && sizePx > 0.0) ? sizePx : 100.0;
                    const glm::dvec2 d = input.mouse - pressMouse_;
                    factor = 1.0 + (d.x - d.y) / px;
                    have = std::isfinite(factor);
                } else if (const auto s = closestLineParameter(ray, c, axes_[k])) {
                    factor = *s / pressParam_;
                    have = std::isfinite(factor);
                }
                if (have) {
                    if (snapping && validStep(snap.scale)) factor = 1.0 + snapTo(factor - 1.0, snap.scale);
                    for (int i = 0; i < 3; ++i) {
                        if (activeHandle_ == GizmoHandle::Centre || i == k) {
                            const double s = start_.scale[i] * factor;
                            t.scale[i] = std::isfinite(s) ? std::max(s, kMinGizmoScale) : start_.scale[i];
                        } else {
                            t.scale[i] = start_.scale[i];
                        }
                    }
                }
            }
        }
        if (withinGizmoRange(t.position) && isFinite(t.rotation) && isFinite(t.scale)) {
            result.changed = !sameTransform(t, inout);
            inout = t;
            last_ = t;
        }
        if (input.released || !input.down) {
            active_ = false;
            result.finished = true;
        }
    }

    result.active = active_;
    const GizmoHandle shown = active_ || result.finished ? activeHandle_ : hovered_;
    result.axis = static_cast<int>(shown);
    result.hovered = active_ || result.finished || hovered_ != GizmoHandle::None;
    if (active_) {
        hovered_ = GizmoHandle::None;
    }
    return result;
}

std::string Gizmo::dragLabel() const {
    if (!active_) {
        return {};
    }
    static const char* const kAxisNames[] = {"X", "Y", "Z"};
    const int k = static_cast<int>(activeHandle_);
    char text[96];
    if (activeMode_ == GizmoMode::Translate) {
        const glm::dvec3 offset = last_.position - start_.position;
        if (k >= 0 && k < 3) {
            std::snprintf(text, sizeof text, "%s %+.2f m", kAxisNames[k], glm::dot(offset, axes_[k]));
        } else {
            std::snprintf(text, sizeof text, "%+.2f %+.2f %+.2f m", offset.x, offset.y, offset.z);
        }
    } else if (activeMode_ == GizmoMode::Rotate) {
        std::snprintf(text, sizeof text, "%s %+.1f\xc2\xb0", k >= 0 && k < 3 ? kAxisNames[k] : "View",
                      appliedAngle_ * 180.0 / std::numbers::pi);
    } else {
        const int i = (k >= 0 && k < 3) ? k : 0;
        const double factor = start_.scale[i] != 0.0 ? last_.scale[i] / start_.scale[i] : 1.0;
        std::snprintf(text, sizeof text, "%s x%.2f", k >= 0 && k < 3 ? kAxisNames[k] : "XYZ", factor);
    }
    return text;
}

bool Gizmo::cancel(GizmoTransform& inout) {
    if (!active_) {
        return false;
    }
    active_ = false;
    inout = start_;
    return true;
}

void Gizmo::draw(ImDrawList* drawList, glm::dvec2 viewportOriginScreen, const renderer::CameraFrame& frame,
                 glm::dvec2 viewportSize, GizmoMode mode, GizmoSpace space,
                 const GizmoTransform& transform) const {
    if (drawList == nullptr) {
        return;
    }
    // While dragging, draw with the latched mode and space.
    const GizmoMode m = active_ ? activeMode_ : mode;
    const GizmoSpace sp = active_ ? activeSpace_ : space;
    GizmoTransform shown = transform;
    if (active_) {
        shown.rotation =
            (m == GizmoMode::Rotate || sp == GizmoSpace::World) ? start_.rotation : transform.rotation;
    }
    const Layout l = computeLayout(*this, frame, viewportSize, m, sp, shown);
    if (!l.valid) {
        return;
    }
    const GizmoHandle highlighted = active_ ? activeHandle_ : hovered_;
    const auto im = [&](glm::dvec2 p) {
        return ImVec2(static_cast<float>(viewportOriginScreen.x + p.x),
                      static_cast<float>(viewportOriginScreen.y + p.y));
    };
    const auto line = [&](const glm::dvec3& a, const glm::dvec3& b, std::uint32_t colour, float thickness) {
        if (const auto s = projectSegment(frame, viewportSize, a, b)) {
            drawList->AddLine(im(s->a), im(s->b), colour, thickness);
        }
    };
    const double px = (std::isfinite(sizePx) && sizePx > 0.0) ? sizePx : 100.0;
    const ImVec2 centre = im(l.centreScreen);
    const auto drawLabel = [&] {
        const std::string label = dragLabel();
        if (!label.empty() && ImGui::GetCurrentContext() != nullptr) {
            const ImVec2 at(centre.x + 14.0f, centre.y + 10.0f);
            const ImVec2 size = ImGui::CalcTextSize(label.c_str());
            drawList->AddRectFilled(ImVec2(at.x - 3.0f, at.y - 1.0f),
                                    ImVec2(at.x + size.x + 3.0f, at.y + size.y + 1.0f),
                                    overlayColour(0.0, 0.0, 0.0, 0.6), 3.0f);
            drawList->AddText(at, overlayColour(1.0, 1.0, 1.0), label.c_str());
        }
    };

    if (m == GizmoMode::Rotate) {
        const auto view = ringPoints(l, l.toEye, kViewRing * l.length);
        for (int i = 0; i < kRingSegments; ++i) {
            line(view[static_cast<std::size_t>(i)], view[static_cast<std::size_t>(i + 1)],
                 handleColour(3, highlighted == GizmoHandle::View, 0.8), 1.5f);
        }
        for (int k = 0; k < 3; ++k) {
            const bool hi = highlighted == static_cast<GizmoHandle>(k);
            const auto pts = ringPoints(l, l.axes[k], l.length);
            for (int i = 0; i < kRingSegments; ++i) {
                const glm::dvec3& a = pts[static_cast<std::size_t>(i)];
                const glm::dvec3& b = pts[static_cast<std::size_t>(i + 1)];
                const bool front = ringSegmentInFront(l, a, b);
                line(a, b, handleColour(k, hi, front ? 1.0 : 0.25), front ? 2.5f : 1.0f);
            }
        }
        if (active_) {
            // The swept angle as a fan from the press direction, and the current direction.
            const double radius = (activeHandle_ == GizmoHandle::View ? kViewRing : 1.0) * l.length;
            const glm::dvec3 r0 = pressPoint_ - start_.position;  // unit, in the ring plane
            const double swept = std::clamp(appliedAngle_, -2.0 * std::numbers::pi, 2.0 * std::numbers::pi);
            const int steps = std::clamp(static_cast<int>(std::ceil(std::fabs(swept) / 0.1)), 1, 64);
            const std::uint32_t fan = handleColour(static_cast<int>(activeHandle_), false, 0.25);
            std::optional<glm::dvec2> prev = projectToViewport(frame, viewportSize, l.centre + r0 * radius);
            for (int i = 1; i <= steps && std::fabs(swept) > 0.0; ++i) {
                const glm::dvec3 r = glm::angleAxis(swept * i / steps, planeNormal_) * r0;
                const auto next = projectToViewport(frame, viewportSize, l.centre + r * radius);
                if (prev && next) {
                    drawList->AddTriangleFilled(centre, im(*prev), im(*next), fan);
                }
                prev = next;
            }
            line(l.centre, l.centre + prevRotateVector_ * radius, handleColour(3, true), 1.5f);
        }
        drawList->AddCircleFilled(centre, 3.0f, handleColour(3, false));
        drawLabel();
        return;
    }

    if (m == GizmoMode::Translate) {
        for (int k = 0; k < 3; ++k) {
            if (!l.planeVisible[k]) {
                continue;
            }
            const auto quad = planeQuad(l, k);
            std::array<ImVec2, 4> pts{};
            bool ok = true;
            for (int i = 0; i < 4; ++i) {
                const auto p = projectToViewport(frame, viewportSize, quad[static_cast<std::size_t>(i)]);
                ok = ok && p.has_value();
                if (p) pts[static_cast<std::size_t>(i)] = im(*p);
            }
            if (ok) {
                const bool hi =
                    highlighted == static_cast<GizmoHandle>(static_cast<int>(GizmoHandle::PlaneYZ) + k);
                drawList->AddQuadFilled(pts[0], pts[1], pts[2], pts[3], handleColour(k, hi, 0.35));
                drawList->AddQuad(pts[0], pts[1], pts[2], pts[3], handleColour(k, hi, 0.9), 1.0f);
            }
        }
    }
    for (int k = 0; k < 3; ++k) {
        if (!l.axisVisible[k]) {
            continue;
        }
        const bool hi = highlighted == static_cast<GizmoHandle>(k);
        const std::uint32_t colour = handleColour(k, hi);
        const glm::dvec3 tip = l.centre + l.axes[k] * l.length;
        line(l.centre + l.axes[k] * (kAxisStart * l.length), tip, colour, hi ? 3.5f : 2.5f);
        const auto tipScreen = projectToViewport(frame, viewportSize, tip);
        if (!tipScreen) {
            continue;
        }
        const glm::dvec2 dir2 = glm::normalize(*tipScreen - l.centreScreen);
        const glm::dvec2 side(-dir2.y, dir2.x);
        const double head = 0.12 * px;
        if (m == GizmoMode::Translate) {
            const glm::dvec2 base = *tipScreen - dir2 * head;
            drawList->AddTriangleFilled(im(*tipScreen + dir2 * (0.3 * head)), im(base + side * (0.4 * head)),
                                        im(base - side * (0.4 * head)), colour);
        } else {
            const float h = static_cast<float>(0.35 * head);
            const ImVec2 p = im(*tipScreen);
            drawList->AddRectFilled(ImVec2(p.x - h, p.y - h), ImVec2(p.x + h, p.y + h), colour);
        }
    }
    const float c = static_cast<float>(kCentreFraction * px * 0.7);
    const bool hiCentre = highlighted == GizmoHandle::Centre;
    if (m == GizmoMode::Scale) {
        drawList->AddRectFilled(ImVec2(centre.x - c, centre.y - c), ImVec2(centre.x + c, centre.y + c),
                                handleColour(3, hiCentre, 0.9));
    } else {
        drawList->AddRect(ImVec2(centre.x - c, centre.y - c), ImVec2(centre.x + c, centre.y + c),
                          handleColour(3, hiCentre, 0.9), 0.0f, 0, 2.0f);
    }
    drawLabel();
}

}  // namespace aerial::editor
