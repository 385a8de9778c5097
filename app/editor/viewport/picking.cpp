// picking.cpp — rays through viewport pixels; ray intersections with
// oriented boxes and ellipsoids (core's fog_volume.hpp geometry, the one the
// BVH and the renderer use), screen-constant emitter icons; click
// selection and placement of new objects (see picking.hpp).
#include "viewport/picking.hpp"

#include <aerial/finite.hpp>
#include <aerial/fog_volume.hpp>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace aerial::editor {

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

// The line against a shape through core's one geometry (fog_volume.hpp):
// the same validity rules, the same object-space intersection. Picking
// needs the whole line (an eye inside a volume picks it at its exit), so
// the interval is unclipped; infinite ends (a zero direction) are no hit.
RayInterval intersectShape(const Ray& ray, FogVolumeShape shape, const glm::dvec3& centre,
                           const glm::dquat& rotation, const glm::dvec3& halfExtents) {
    FogVolume volume;
    volume.shape = shape;
    volume.position = centre;
    volume.rotation = rotation;
    volume.halfExtents = halfExtents;
    const VolumeInterval line = intersectFogVolumeLine(prepareFogVolume(volume), ray.origin, ray.direction);
    RayInterval r;
    if (line.hit && std::isfinite(line.tNear) && std::isfinite(line.tFar)) {
        r.hit = true;
        r.tIn = line.tNear;
        r.tOut = line.tFar;
    }
    return r;
}

}  // namespace

RayInterval intersectOrientedBox(const Ray& ray, const glm::dvec3& centre, const glm::dquat& rotation,
                                 const glm::dvec3& halfExtents) {
    return intersectShape(ray, FogVolumeShape::Box, centre, rotation, halfExtents);
}

RayInterval intersectOrientedEllipsoid(const Ray& ray, const glm::dvec3& centre, const glm::dquat& rotation,
                                       const glm::dvec3& halfExtents) {
    return intersectShape(ray, FogVolumeShape::Ellipsoid, centre, rotation, halfExtents);
}

RayInterval intersectVolumeShape(const Ray& ray, const FogVolume& volume) {
    if (volume.shape != FogVolumeShape::Mesh) {
        return intersectShape(ray, volume.shape, volume.position, volume.rotation, volume.halfExtents);
    }
    // A mesh volume is picked by its real triangles: core's chords, first
    // entry to last exit.
    RayInterval r;
    if (!isFinite(ray.origin) || !isFinite(ray.direction)) return r;
    const VolumeInterval line = intersectFogVolumeLine(prepareFogVolume(volume), ray.origin, ray.direction);
    if (line.hit && std::isfinite(line.tNear) && std::isfinite(line.tFar)) {
        r.hit = true;
        r.tIn = line.tNear;
        r.tOut = line.tFar;
    }
    return r;
}

std::optional<double> intersectIcon(const Ray& ray, const glm::dvec3& position, double angularRadius) {
    if (!isFinite(ray.origin) || !isFinite(ray.direction) || !isFinite(position) ||
        !std::isfinite(angularRadius) || !(angularRadius > 0.0)) {
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

FogVolume shapeOf(const CloudVolume& cloudVolume) {
    FogVolume v;
    v.shape = cloudVolume.shape;
    v.position = cloudVolume.position;
    v.rotation = cloudVolume.rotation;
    v.halfExtents = cloudVolume.halfExtents;
    return v;
}

namespace {

// The nearest volume along a unit ray: its entry, or its exit from inside.
void nearestVolume(const Ray& r, const std::vector<FogVolume>& volumes, PickHit::Kind kind, PickHit& best,
                   double& bestDistance) {
    for (std::size_t i = 0; i < volumes.size(); ++i) {
        const RayInterval hit = intersectVolumeShape(r, volumes[i]);
        if (!hit.hit || hit.tOut < 0.0) {
            continue;
        }
        const double t = hit.tIn >= 0.0 ? hit.tIn : hit.tOut;  // inside: the exit
        if (t < bestDistance) {
            bestDistance = t;
            best.kind = kind;
            best.index = static_cast<int>(i);
            best.distance = t;
        }
    }
}

}  // namespace

PickHit pick(const Ray& ray, const std::vector<FogVolume>& volumes, const std::vector<Emitter>& emitters,
             const std::vector<CloudVolume>& cloudVolumes, double iconAngularRadius, bool emittersFirst) {
    PickHit best = pick(ray, volumes, emitters, iconAngularRadius, emittersFirst);
    const double len = glm::length(ray.direction);
    if (best.kind != PickHit::Kind::None || !isFinite(ray.origin) || !std::isfinite(len) || !(len > 0.0)) {
        return best;
    }
    std::vector<FogVolume> shapes;
    shapes.reserve(cloudVolumes.size());
    for (const CloudVolume& c : cloudVolumes) {
        shapes.push_back(shapeOf(c));
    }
    double bestDistance = std::numeric_limits<double>::infinity();
    nearestVolume(Ray{ray.origin, ray.direction / len}, shapes, PickHit::Kind::CloudVolume, best,
                  bestDistance);
    return best;
}

PickHit pick(const Ray& ray, const std::vector<FogVolume>& volumes, const std::vector<Emitter>& emitters,
             double iconAngularRadius, bool emittersFirst) {
    PickHit best;
    Ray r = ray;
    const double len = glm::length(r.direction);
    if (!isFinite(r.origin) || !std::isfinite(len) || !(len > 0.0)) {
        return best;
    }
    r.direction /= len;
    double bestDistance = std::numeric_limits<double>::infinity();
    nearestVolume(r, volumes, PickHit::Kind::Volume, best, bestDistance);
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
    b.centre = isFinite(volume.position) ? volume.position : glm::dvec3(0.0);
    const PreparedFogVolume p = prepareFogVolume(volume);
    if (p.valid && volume.shape == FogVolumeShape::Mesh) {
        b.centre = 0.5 * (p.boundsMin + p.boundsMax);
        b.radius = 0.5 * glm::length(p.boundsMax - p.boundsMin);
    } else if (p.valid) {
        const glm::dvec3& s = volume.halfExtents;
        b.radius = volume.shape == FogVolumeShape::Box ? glm::length(s) : std::max({s.x, s.y, s.z});
    }
    return b;
}

BoundingSphere boundingSphereOf(const Emitter& emitter) {
    BoundingSphere b;
    b.centre = isFinite(emitter.position) ? emitter.position : glm::dvec3(0.0);
    const double a = emitter.attenuation;
    b.radius = (std::isfinite(a) && a > 0.0) ? std::clamp(1.0 / std::sqrt(a), 1.0, 50.0) : 10.0;
    return b;
}

std::optional<glm::dvec3> placeInFront(const renderer::CameraFrame& frame, double distance,
                                       double maxGroundDistance, const GroundHeightFunction& groundHeight) {
    if (!isFinite(frame.eye) || !isFinite(frame.forward) || !std::isfinite(distance) || !(distance > 0.0)) {
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
