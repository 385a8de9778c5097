// picking.cpp — rays through viewport pixels; closed-form ray intersections
// with oriented boxes and ellipsoids, screen-constant emitter icons; click
// selection and placement of new objects (see picking.hpp).
#include "viewport/picking.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace aerial::editor {
namespace {

constexpr double kMaxCoordinate = 1.0e30;  // core's limit (fog_volume.hpp, "Sanitising")
constexpr double kMinHalfExtent = 1.0e-6;  // [m], core's limit

bool withinRange(const glm::dvec3& v) {
    return std::fabs(v.x) <= kMaxCoordinate && std::fabs(v.y) <= kMaxCoordinate &&
           std::fabs(v.z) <= kMaxCoordinate;  // false for NaN
}

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Takes the ray into the object space of an oriented unit shape:
// object = (conj(q) (world - centre)) / halfExtents. False when the shape is
// degenerate by core's rules or the ray is not usable.
bool toObjectSpace(const Ray& ray, const glm::dvec3& centre, const glm::dquat& rotation,
                   const glm::dvec3& halfExtents, glm::dvec3& o, glm::dvec3& d) {
    const glm::dvec3& s = halfExtents;
    if (!(s.x >= kMinHalfExtent && s.y >= kMinHalfExtent && s.z >= kMinHalfExtent && s.x <= kMaxCoordinate &&
          s.y <= kMaxCoordinate && s.z <= kMaxCoordinate)) {
        return false;
    }
    const double qNorm2 =
        rotation.w * rotation.w + rotation.x * rotation.x + rotation.y * rotation.y + rotation.z * rotation.z;
    if (!(std::isfinite(qNorm2) && qNorm2 > 1.0e-200) || !withinRange(centre) || !withinRange(ray.origin) ||
        !withinRange(ray.direction)) {
        return false;
    }
    const glm::dquat inverse = glm::conjugate(rotation / std::sqrt(qNorm2));
    o = (inverse * (ray.origin - centre)) / s;
    d = (inverse * ray.direction) / s;
    return glm::dot(d, d) > 0.0;
}

}  // namespace

Ray rayThroughPixel(const renderer::CameraFrame& frame, glm::dvec2 pixelFromTopLeft,
                    glm::dvec2 viewportSize) {
    const double w = (std::isfinite(viewportSize.x) && viewportSize.x >= 1.0) ? viewportSize.x : 1.0;
    const double h = (std::isfinite(viewportSize.y) && viewportSize.y >= 1.0) ? viewportSize.y : 1.0;
    Ray ray;
    ray.origin = frame.eye;
    glm::dvec3 dir = frame.forward;
    if (std::isfinite(pixelFromTopLeft.x) && std::isfinite(pixelFromTopLeft.y)) {
        // The same arithmetic as renderer::farRayAtPixel, with x + 0.5 given.
        const double ndcX = pixelFromTopLeft.x / w * 2.0 - 1.0;
        const double ndcY = 1.0 - pixelFromTopLeft.y / h * 2.0;
        const glm::dvec3 far = renderer::farRayAtNdc(frame, ndcX, ndcY);
        const double len = glm::length(far);
        if (std::isfinite(len) && len > 0.0) {
            dir = far / len;
        }
    }
    ray.direction = dir;
    return ray;
}

double angularRadiusOfPixels(const renderer::CameraFrame& frame, double viewportHeight, double pixels) {
    const double tanHalf = 1.0 / frame.clipFromView[1][1];
    const double h = (std::isfinite(viewportHeight) && viewportHeight >= 1.0) ? viewportHeight : 1.0;
    if (!std::isfinite(tanHalf) || !(tanHalf > 0.0) || !std::isfinite(pixels) || !(pixels > 0.0)) {
        return 0.0;
    }
    return std::atan(pixels * 2.0 * tanHalf / h);
}

namespace {

// The object-space ray o + t d against the unit cube.
RayInterval intersectUnitCube(const glm::dvec3& o, const glm::dvec3& d) {
    RayInterval r;
    // Slabs -1 <= o_i + t d_i <= 1.
    double tNear = -std::numeric_limits<double>::infinity();
    double tFar = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 3; ++i) {
        if (d[i] == 0.0) {
            if (!(std::fabs(o[i]) <= 1.0)) {
                return r;
            }
            continue;
        }
        // Divisions (not a reciprocal) so a tiny d_i gives +-Inf, never NaN.
        double t0 = (-1.0 - o[i]) / d[i];
        double t1 = (1.0 - o[i]) / d[i];
        if (t0 > t1) {
            std::swap(t0, t1);
        }
        tNear = std::max(tNear, t0);
        tFar = std::min(tFar, t1);
    }
    if (tNear <= tFar && std::isfinite(tNear) && std::isfinite(tFar)) {
        r.hit = true;
        r.tIn = tNear;
        r.tOut = tFar;
    }
    return r;
}

// The object-space ray o + t d against the unit sphere.
RayInterval intersectUnitSphere(const glm::dvec3& o, const glm::dvec3& d) {
    RayInterval r;
    // |o + t d|^2 = 1  <=>  a t^2 + 2 b t + c = 0, a = d.d, b = o.d, c = o.o - 1.
    // Discriminant b^2 - a c = a (1 - |o_perp|^2), o_perp = o - (b / a) d the
    // closest approach (no cancellation for far rays); roots by the stable
    // pair q = -(b + sign(b) sqrt(disc)), t = q / a and t = c / q.
    const double a = glm::dot(d, d);
    const double b = glm::dot(o, d);
    const double c = glm::dot(o, o) - 1.0;
    const glm::dvec3 perp = o - (b / a) * d;
    const double disc = a * (1.0 - glm::dot(perp, perp));
    if (!(disc >= 0.0) || !std::isfinite(disc)) {
        return r;
    }
    const double q = -(b + std::copysign(std::sqrt(disc), b));
    double t0;
    double t1;
    if (q == 0.0) {
        t0 = 0.0;  // b = 0 and disc = 0: tangent at the origin
        t1 = 0.0;
    } else {
        t0 = q / a;
        t1 = c / q;
    }
    if (t0 > t1) {
        std::swap(t0, t1);
    }
    if (std::isfinite(t0) && std::isfinite(t1)) {
        r.hit = true;
        r.tIn = t0;
        r.tOut = t1;
    }
    return r;
}

}  // namespace

RayInterval intersectOrientedBox(const Ray& ray, const glm::dvec3& centre, const glm::dquat& rotation,
                                 const glm::dvec3& halfExtents) {
    glm::dvec3 o;
    glm::dvec3 d;
    return toObjectSpace(ray, centre, rotation, halfExtents, o, d) ? intersectUnitCube(o, d) : RayInterval{};
}

RayInterval intersectOrientedEllipsoid(const Ray& ray, const glm::dvec3& centre, const glm::dquat& rotation,
                                       const glm::dvec3& halfExtents) {
    glm::dvec3 o;
    glm::dvec3 d;
    return toObjectSpace(ray, centre, rotation, halfExtents, o, d) ? intersectUnitSphere(o, d)
                                                                   : RayInterval{};
}

RayInterval intersectVolumeShape(const Ray& ray, const FogVolume& volume) {
    return volume.shape == FogVolumeShape::Box
               ? intersectOrientedBox(ray, volume.position, volume.rotation, volume.halfExtents)
               : intersectOrientedEllipsoid(ray, volume.position, volume.rotation, volume.halfExtents);
}

std::optional<double> intersectIcon(const Ray& ray, const glm::dvec3& position, double angularRadius) {
    if (!finite(ray.origin) || !finite(ray.direction) || !finite(position) || !std::isfinite(angularRadius) ||
        !(angularRadius > 0.0)) {
        return std::nullopt;
    }
    const double alpha = std::min(angularRadius, 1.5);  // below a right angle
    const double dirLen = glm::length(ray.direction);
    if (!(dirLen > 0.0) || !std::isfinite(dirLen)) {
        return std::nullopt;
    }
    const glm::dvec3 n = ray.direction / dirLen;
    const glm::dvec3 toPoint = position - ray.origin;
    const double distance = glm::length(toPoint);
    if (!(distance > 0.0) || !std::isfinite(distance)) {
        return std::nullopt;
    }
    const glm::dvec3 u = toPoint / distance;
    const double cosTheta = glm::dot(u, n);
    const double sinTheta = glm::length(glm::cross(u, n));
    // theta <= alpha (theta in [0, pi] from atan2 of the two).
    if (std::atan2(sinTheta, cosTheta) > alpha) {
        return std::nullopt;
    }
    // Entry into the sphere of radius D sin(alpha): D (cos(theta) - sqrt(sin^2 alpha - sin^2 theta)).
    const double sinAlpha = std::sin(alpha);
    const double under = std::max((sinAlpha - sinTheta) * (sinAlpha + sinTheta), 0.0);
    return distance * std::max(cosTheta - std::sqrt(under), 0.0);
}

PickHit pick(const Ray& ray, const std::vector<FogVolume>& volumes, const std::vector<Emitter>& emitters,
             double iconAngularRadius, bool emittersFirst) {
    PickHit best;
    Ray r = ray;
    const double len = glm::length(r.direction);
    if (!finite(r.origin) || !std::isfinite(len) || !(len > 0.0)) {
        return best;
    }
    r.direction /= len;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < volumes.size(); ++i) {
        const RayInterval hit = intersectVolumeShape(r, volumes[i]);
        if (!hit.hit || hit.tOut < 0.0) {
            continue;
        }
        const double t = hit.tIn >= 0.0 ? hit.tIn : hit.tOut;  // inside: the exit
        if (t < bestDistance) {
            bestDistance = t;
            best.kind = PickHit::Kind::Volume;
            best.index = static_cast<int>(i);
            best.distance = t;
        }
    }
    if (emittersFirst) {
        bestDistance = std::numeric_limits<double>::infinity();
    }
    for (std::size_t i = 0; i < emitters.size(); ++i) {
        const std::optional<double> t = intersectIcon(r, emitters[i].position, iconAngularRadius);
        if (t && *t < bestDistance) {
            bestDistance = *t;
            best.kind = PickHit::Kind::Emitter;
            best.index = static_cast<int>(i);
            best.distance = *t;
        }
    }
    return best;
}

BoundingSphere boundingSphereOf(const FogVolume& volume) {
    BoundingSphere b;
    b.centre = finite(volume.position) ? volume.position : glm::dvec3(0.0);
    const glm::dvec3& s = volume.halfExtents;
    const double qNorm2 = volume.rotation.w * volume.rotation.w + volume.rotation.x * volume.rotation.x +
                          volume.rotation.y * volume.rotation.y + volume.rotation.z * volume.rotation.z;
    const bool valid = s.x >= kMinHalfExtent && s.y >= kMinHalfExtent && s.z >= kMinHalfExtent &&
                       s.x <= kMaxCoordinate && s.y <= kMaxCoordinate && s.z <= kMaxCoordinate &&
                       std::isfinite(qNorm2) && qNorm2 > 1.0e-200 && withinRange(volume.position);
    if (valid) {
        b.radius = volume.shape == FogVolumeShape::Box ? glm::length(s) : std::max({s.x, s.y, s.z});
    }
    return b;
}

BoundingSphere boundingSphereOf(const Emitter& emitter) {
    BoundingSphere b;
    b.centre = finite(emitter.position) ? emitter.position : glm::dvec3(0.0);
    const double a = emitter.attenuation;
    b.radius = (std::isfinite(a) && a > 0.0) ? std::clamp(1.0 / std::sqrt(a), 1.0, 50.0) : 10.0;
    return b;
}

std::optional<glm::dvec3> placeInFront(const renderer::CameraFrame& frame, double distance,
                                       double maxGroundDistance, const GroundHeightFunction& groundHeight) {
    if (!finite(frame.eye) || !finite(frame.forward) || !std::isfinite(distance) || !(distance > 0.0)) {
        return std::nullopt;
    }
    const double fLen = glm::length(frame.forward);
    if (!(fLen > 0.0)) {
        return std::nullopt;
    }
    const glm::dvec3 f = frame.forward / fLen;
    const glm::dvec3& eye = frame.eye;
    const double maxGround =
        std::isfinite(maxGroundDistance) ? std::clamp(maxGroundDistance, 0.0, 1.0e6) : 0.0;
    if (maxGround > 0.0) {
        if (!groundHeight) {
            if (eye.y > 0.0 && f.y < 0.0) {
                const double t = -eye.y / f.y;
                if (t <= maxGround) {
                    glm::dvec3 p = eye + t * f;
                    p.y = 0.0;
                    return p;
                }
            }
        } else {
            // Height above the ground along the ray; a non-finite ground
            // height counts as "no ground here".
            const auto above = [&](double t) {
                const glm::dvec3 p = eye + t * f;
                const double g = groundHeight(p.x, p.z);
                return std::isfinite(g) ? p.y - g : 1.0;
            };
            if (above(0.0) > 0.0) {
                const double step = std::max(1.0, maxGround / 20000.0);
                double t0 = 0.0;
                for (double t1 = std::min(step, maxGround); t0 < maxGround;
                     t1 = std::min(t1 + step, maxGround)) {
                    if (above(t1) <= 0.0) {
                        for (int i = 0; i < 200 && t1 - t0 > 1e-6; ++i) {
                            const double mid = 0.5 * (t0 + t1);
                            (above(mid) > 0.0 ? t0 : t1) = mid;
                        }
                        return eye + t1 * f;
                    }
                    t0 = t1;
                }
            }
        }
    }
    return eye + distance * f;
}

}  // namespace aerial::editor
