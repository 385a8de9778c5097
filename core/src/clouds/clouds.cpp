// clouds.cpp — the cloud layer's density and the runtime queries
// (aerial/clouds.hpp). The GLSL in renderer/shaders/common/clouds.glsl is the
// same arithmetic in float; tests/renderer compare the two.
#include <aerial/clouds.hpp>

#include <aerial/atmosphere.hpp>
#include <aerial/finite.hpp>
#include <aerial/height_fog.hpp>

#include "fog/volume_geometry.hpp"

#include <algorithm>
#include <cmath>

namespace aerial {
namespace {

double saturate(double v) { return std::clamp(v, 0.0, 1.0); }
double smooth01(double t) {
    t = saturate(t);
    return t * t * (3.0 - 2.0 * t);
}

/// Roots of |o + t d - c|^2 = r^2 (c the planet's centre), or false.
bool sphereRoots(const glm::dvec3& o, const glm::dvec3& d, double planetRadius, double radius, double& t0,
                 double& t1) {
    // Relative to the centre (0, -Rg, 0): oc = o + (0, Rg, 0). |oc|^2 - r^2
    // is formed as (|o_h|^2 + y^2 + 2 y Rg) + (Rg^2 - r^2) with r = Rg + h_s,
    // so nothing of size Rg^2 cancels.
    const double shellHeight = radius - planetRadius;
    const glm::dvec3 oc = o + glm::dvec3(0.0, planetRadius, 0.0);
    const double a = glm::dot(d, d);
    const double b = glm::dot(oc, d);
    const double c = (o.x * o.x + o.z * o.z + o.y * o.y + 2.0 * o.y * planetRadius) -
                     shellHeight * (2.0 * planetRadius + shellHeight);
    const double disc = b * b - a * c;
    if (!(disc >= 0.0) || !(a > 0.0)) return false;
    // Numerically stable pair.
    const double q = -(b + std::copysign(std::sqrt(disc), b));
    const double ra = q / a;
    const double rb = q != 0.0 ? c / q : -b / a;
    t0 = std::min(ra, rb);
    t1 = std::max(ra, rb);
    return true;
}

double volumeWeight(const CloudField::Volume& v, const glm::dvec3& p) {
    const PreparedFogVolume& g = v.geometry;
    if (!g.valid) return 0.0;
    const glm::dvec3 o = g.toObject(p - g.position);
    const double r = g.shape == FogVolumeShape::Box
                         ? std::max({std::fabs(o.x), std::fabs(o.y), std::fabs(o.z)})
                         : std::sqrt(o.x * o.x + o.y * o.y + o.z * o.z);
    if (r >= 1.0) return 0.0;
    const double soft = saturate(v.edgeSoftness);
    if (soft <= 0.0) return 1.0;
    return smooth01((1.0 - r) / soft);
}

}  // namespace

double cloudHeightProfile(double heightFraction, double type) {
    const double f = heightFraction, k = saturate(type);
    if (!(f > 0.0) || !(f < 1.0)) return 0.0;
    const double top = 0.3 + 0.7 * k;
    const double fall = top * (0.5 + 0.3 * k);
    return smooth01(f / 0.08) * smooth01((top - f) / fall);
}

bool CloudField::active() const {
    return params.densityPerM > 0.0 && noise != nullptr && (params.coverage > 0.0 || !volumes.empty());
}

CloudField prepareClouds(const CloudParams& params, std::span<const CloudVolume> volumes, double timeHours,
                         double planetRadius) {
    CloudField field;
    field.params = params;
    CloudParams& p = field.params;
    // Sanitise what a query reads: out-of-range values clamp into the
    // parameter table's ranges, non-finite ones take their defaults.
    const CloudParams defaults;
    auto clampOr = [](double v, double lo, double hi, double fallback) {
        return std::isfinite(v) ? std::clamp(v, lo, hi) : fallback;
    };
    p.coverage = clampOr(p.coverage, 0.0, 1.0, 0.0);
    p.bottomM = clampOr(p.bottomM, 0.0, 20000.0, defaults.bottomM);
    p.thicknessM = clampOr(p.thicknessM, 10.0, 20000.0, defaults.thicknessM);
    p.densityPerM = clampOr(p.densityPerM, 0.0, 1.0, 0.0);
    p.type = clampOr(p.type, 0.0, 1.0, defaults.type);
    p.shapeScaleM = clampOr(p.shapeScaleM, 500.0, 200000.0, defaults.shapeScaleM);
    p.detailScaleM = clampOr(p.detailScaleM, 50.0, 20000.0, defaults.detailScaleM);
    p.erosion = clampOr(p.erosion, 0.0, 0.9, defaults.erosion);
    if (!isFinite(p.windMPerS)) p.windMPerS = glm::dvec2(0.0);
    field.planetRadius = std::isfinite(planetRadius) && planetRadius > 1.0 ? planetRadius : 6360000.0;

    // Wind offset in double, reduced modulo each tile so the GPU's floats
    // stay small (exact: both textures have period 1 in uvw).
    const double seconds =
        std::isfinite(timeHours) ? (timeHours - 24.0 * std::floor(timeHours / 24.0)) * 3600.0 : 0.0;
    const glm::dvec2 w = glm::clamp(p.windMPerS, glm::dvec2(-1000.0), glm::dvec2(1000.0)) * seconds;
    auto reduce = [](const glm::dvec2& v, double period) { return v - period * glm::floor(v / period); };
    field.shapeOffset = reduce(w, p.shapeScaleM);
    field.detailOffset = reduce(w, p.detailScaleM);

    for (const CloudVolume& v : volumes) {
        FogVolume shape;
        shape.shape = v.shape;
        shape.position = v.position;
        shape.rotation = v.rotation;
        shape.halfExtents = v.halfExtents;
        CloudField::Volume prepared;
        prepared.geometry = prepareFogVolume(shape);
        prepared.coverage = clampOr(v.coverage, 0.0, 1.0, 0.0);
        prepared.edgeSoftness = clampOr(v.edgeSoftness, 0.0, 1.0, 0.0);
        if (prepared.geometry.valid) field.volumes.push_back(prepared);
    }
    if (p.densityPerM > 0.0 && (p.coverage > 0.0 || !field.volumes.empty())) field.noise = cloudNoise(p.seed);
    return field;
}

double cloudHeightAboveGround(const glm::dvec3& p, double planetRadius) {
    const double r2minusRg2 = p.x * p.x + p.z * p.z + p.y * p.y + 2.0 * p.y * planetRadius;
    const glm::dvec3 oc = p + glm::dvec3(0.0, planetRadius, 0.0);
    return r2minusRg2 / (std::sqrt(glm::dot(oc, oc)) + planetRadius);
}

double cloudCoverageAt(const CloudField& clouds, const glm::dvec3& point) {
    double c = clouds.params.coverage;
    if (!withinCoordinateRange(point)) return c;
    for (const CloudField::Volume& v : clouds.volumes) {
        const double w = volumeWeight(v, point);
        if (w > 0.0) c += w * (v.coverage - c);
    }
    return saturate(c);
}

double cloudDensityAt(const CloudField& clouds, const glm::dvec3& p) {
    if (!clouds.active() || !withinCoordinateRange(p)) return 0.0;
    const CloudParams& cp = clouds.params;
    const double h = cloudHeightAboveGround(p, clouds.planetRadius);
    const double f = (h - cp.bottomM) / cp.thicknessM;
    const double profile = cloudHeightProfile(f, cp.type);
    if (profile <= 0.0) return 0.0;
    const double c = cloudCoverageAt(clouds, p);
    if (c <= 0.0) return 0.0;
    const CloudNoise& n = *clouds.noise;
    const glm::dvec3 qs(p.x - clouds.shapeOffset.x, h, p.z - clouds.shapeOffset.y);
    const double x = sampleTileable(n.shape, CloudNoise::kShapeSize, qs / cp.shapeScaleM) * profile;
    const double d = saturate((x - (1.0 - c)) / c);
    if (d <= 0.0) return 0.0;
    const glm::dvec3 qd(p.x - clouds.detailOffset.x, h, p.z - clouds.detailOffset.y);
    const double e = cp.erosion * sampleTileable(n.detail, CloudNoise::kDetailSize, qd / cp.detailScaleM);
    return cp.densityPerM * saturate((d - e) / (1.0 - e));
}

CloudSegments cloudLayerSegments(const CloudField& clouds, const glm::dvec3& origin,
                                 const glm::dvec3& direction, double tMax) {
    CloudSegments out;
    if (!withinCoordinateRange(origin) || !withinCoordinateRange(direction) || std::isnan(tMax) ||
        !(tMax > 0.0))
        return out;
    const double rg = clouds.planetRadius;
    const double bottom = clouds.params.bottomM, top = bottom + clouds.params.thicknessM;
    double o0, o1;
    if (!sphereRoots(origin, direction, rg, rg + top, o0, o1)) return out;
    // The ground ends the ray (a layer at height 0 starts at the ground).
    double g0, g1;
    if (sphereRoots(origin, direction, rg, rg, g0, g1) && g0 > 0.0) tMax = std::min(tMax, g0);
    double i0, i1;
    const bool inner = bottom > 0.0 && sphereRoots(origin, direction, rg, rg + bottom, i0, i1);
    auto add = [&](double a, double b) {
        a = std::max(a, 0.0);
        b = std::min(b, tMax);
        if (b > a && out.count < 2) {
            out.t0[out.count] = a;
            out.t1[out.count] = b;
            ++out.count;
        }
    };
    if (!inner) {
        add(o0, o1);
    } else {
        add(o0, std::min(o1, i0));
        add(std::max(o0, i1), o1);
    }
    return out;
}

double cloudOpticalDepth(const CloudField& clouds, const glm::dvec3& origin, const glm::dvec3& direction,
                         double tMax, int steps) {
    if (!clouds.active()) return 0.0;
    const CloudSegments s = cloudLayerSegments(clouds, origin, direction, tMax);
    if (s.count == 0) return 0.0;
    steps = std::clamp(steps, 1, 1 << 16);
    const double total = (s.t1[0] - s.t0[0]) + (s.count > 1 ? s.t1[1] - s.t0[1] : 0.0);
    const double length = std::sqrt(glm::dot(direction, direction));
    double tau = 0.0;
    for (int k = 0; k < s.count; ++k) {
        const double span = s.t1[k] - s.t0[k];
        const int n = std::max(1, int(std::floor(steps * span / total + 0.5)));
        const double dt = span / n;
        double sum = 0.0;
        for (int i = 0; i < n; ++i)
            sum += cloudDensityAt(clouds, origin + direction * (s.t0[k] + (i + 0.5) * dt));
        tau += sum * dt * length;
    }
    return std::min(tau, kMaxOpticalDepth);
}

double cloudTransmittance(const CloudField& clouds, const glm::dvec3& origin, const glm::dvec3& direction,
                          double tMax, int steps) {
    return std::exp(-cloudOpticalDepth(clouds, origin, direction, tMax, steps));
}

double cloudSunVisibility(const CloudField& clouds, const glm::dvec3& point, const glm::dvec3& toLight,
                          int steps) {
    return cloudTransmittance(clouds, point, toLight, std::numeric_limits<double>::infinity(), steps);
}

CloudOvercast cloudOvercast(const CloudField& clouds) {
    CloudOvercast out;
    if (!clouds.active()) return out;
    const glm::dvec3 origin(0.0);
    // Zenith band: kCloudOvercastRays directions of equal cosine-weighted
    // solid angle (rings of equal sin^2 of the zenith angle, azimuths
    // staggered between rings), so the plain mean of T is the cosine-weighted one.
    constexpr int kRings = 8, kPerRing = kCloudOvercastRays / kRings;
    double transmitted = 0.0, depthSum = 0.0, coverSum = 0.0;
    for (int i = 0; i < kRings; ++i) {
        const double sin2 = (i + 0.5) / kRings;
        const double sinT = std::sqrt(sin2), cosT = std::sqrt(1.0 - sin2);
        for (int j = 0; j < kPerRing; ++j) {
            const double phi = 2.0 * kPi * (j + 0.5 * (1 + i % 2)) / kPerRing;
            const glm::dvec3 d(sinT * std::sin(phi), cosT, -sinT * std::cos(phi));
            const double tau = cloudOpticalDepth(clouds, origin, d, std::numeric_limits<double>::infinity(),
                                                 kCloudOvercastSteps);
            const double t = std::exp(-tau);
            transmitted += t;
            depthSum += (1.0 - t) * tau * cosT;
            coverSum += 1.0 - t;
        }
    }
    out.skyCover = std::clamp(1.0 - transmitted / kCloudOvercastRays, 0.0, 1.0);
    out.opticalDepth = coverSum > 0.0 ? std::min(depthSum / coverSum, kMaxOpticalDepth) : 0.0;
    out.diffuseTransmittance = 1.0 / (1.0 + 0.75 * (1.0 - 0.85) * out.opticalDepth);
    // Horizon band: elevations 1..11 deg, uniform in elevation and azimuth.
    constexpr int kElevations = 4, kAzimuths = kCloudOvercastRays / kElevations;
    double horizon = 0.0;
    for (int i = 0; i < kElevations; ++i) {
        const double el = (1.0 + 10.0 * (i + 0.5) / kElevations) * kPi / 180.0;
        for (int j = 0; j < kAzimuths; ++j) {
            const double phi = 2.0 * kPi * (j + 0.5 * (1 + i % 2)) / kAzimuths;
            const glm::dvec3 d(std::cos(el) * std::sin(phi), std::sin(el), -std::cos(el) * std::cos(phi));
            horizon += cloudTransmittance(clouds, origin, d, std::numeric_limits<double>::infinity(),
                                          kCloudOvercastSteps);
        }
    }
    out.horizonCover = std::clamp(1.0 - horizon / kCloudOvercastRays, 0.0, 1.0);
    return out;
}

glm::dvec3 overcastRadiance(const CloudOvercast& overcast, const glm::dvec3& albedo,
                            const glm::dvec3& irradianceOnTop) {
    glm::dvec3 out(0.0);
    const double td = std::isfinite(overcast.diffuseTransmittance)
                          ? std::clamp(overcast.diffuseTransmittance, 0.0, 1.0)
                          : 1.0;
    for (int c = 0; c < 3; ++c) {
        const double a = std::isfinite(albedo[c]) ? std::clamp(albedo[c], 0.0, 1.0) : 0.0;
        const double e = std::isfinite(irradianceOnTop[c]) ? std::clamp(irradianceOnTop[c], 0.0, 1e30) : 0.0;
        out[c] = a * td * e / kPi;
    }
    return out;
}

double overcastCoverTowards(const CloudOvercast& overcast, const glm::dvec3& direction) {
    const double x = std::clamp(direction.y / 0.5, 0.0, 1.0);
    const double t = x * x * (3.0 - 2.0 * x);  // smoothstep(0, 0.5, y), as GLSL
    return overcast.horizonCover + (overcast.skyCover - overcast.horizonCover) * t;
}

}  // namespace aerial
