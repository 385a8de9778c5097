// sky_reference.cpp — brute-force single scattering, see
// <aerial/sky_reference.hpp>. Everything is recomputed from first
// principles in double precision: sphere geometry, the density profiles, the
// optical depth towards the light at every node, and the view-ray integral.
#include <aerial/sky_reference.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

namespace aerial {
namespace {

constexpr double kPiRef = 3.14159265358979323846;

double dot3(const glm::dvec3& a, const glm::dvec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

glm::dvec3 unitOrUp(const glm::dvec3& v) {
    const double length = std::sqrt(dot3(v, v));
    if (!(length > 0.0) || !std::isfinite(length)) return glm::dvec3(0.0, 1.0, 0.0);
    return v / length;
}

glm::dvec3 expNeg(const glm::dvec3& x) { return glm::dvec3(std::exp(-x.x), std::exp(-x.y), std::exp(-x.z)); }

int evenSteps(int steps) {
    const int n = std::max(steps, 16);
    return n + (n & 1);
}

/// Relative densities at a height [m] above the ground: exp(-h/H) for
/// Rayleigh and Mie, the ozone tent (0 at centre +- width/2, 1 at centre).
struct Densities {
    double rayleigh = 0.0;
    double mie = 0.0;
    double ozone = 0.0;
};

Densities densitiesAt(const AtmosphereParams& air, double height) {
    const double h = std::max(height, 0.0);
    Densities d;
    if (air.rayleighScaleHeight > 0.0) d.rayleigh = std::exp(-h / air.rayleighScaleHeight);
    if (air.mieScaleHeight > 0.0) d.mie = std::exp(-h / air.mieScaleHeight);
    if (air.ozoneWidth > 0.0) {
        const double halfWidth = 0.5 * air.ozoneWidth;
        d.ozone = std::max(0.0, 1.0 - std::abs(h - air.ozoneCenterHeight) / halfWidth);
    }
    return d;
}

/// Extinction [1/m], RGB: Rayleigh scattering + Mie extinction + ozone absorption.
glm::dvec3 extinctionOf(const AtmosphereParams& air, const Densities& d) {
    return air.rayleighScattering * d.rayleigh + air.mieExtinction * d.mie + air.ozoneAbsorption * d.ozone;
}

double heightOf(const AtmosphereParams& air, const glm::dvec3& p) {
    return std::sqrt(dot3(p, p)) - air.planetRadius;
}

/// One piece [a, b] of a ray, marched with nodes crowded at its dense end:
/// s(u) = a + (b - a) u^2 (dense at a) or b - (b - a) (1 - u)^2 (dense at b).
struct Piece {
    double a = 0.0;
    double b = 0.0;
    bool denseAtStart = true;

    double at(double u) const {
        return denseAtStart ? a + (b - a) * u * u : b - (b - a) * (1.0 - u) * (1.0 - u);
    }
    double derivative(double u) const { return 2.0 * (b - a) * (denseAtStart ? u : 1.0 - u); }
};

/// Distances along unit `dir` from planet-centred `p` (inside the
/// atmosphere) to the top of the atmosphere (far root) and, if the ray hits
/// the ground, to the ground (near root).
struct RayExtent {
    double toTop = 0.0;
    bool hitsGround = false;
    double toGround = 0.0;
};

RayExtent rayExtent(const AtmosphereParams& air, const glm::dvec3& p, const glm::dvec3& dir) {
    RayExtent e;
    const double b = dot3(p, dir);  // r mu
    const double r2 = dot3(p, p);
    const double top2 = air.atmosphereRadius * air.atmosphereRadius;
    const double discTop = b * b - (r2 - top2);
    e.toTop = discTop > 0.0 ? std::max(-b + std::sqrt(discTop), 0.0) : 0.0;
    const double ground2 = air.planetRadius * air.planetRadius;
    const double discGround = b * b - (r2 - ground2);
    if (b < 0.0 && discGround >= 0.0) {
        e.hitsGround = true;
        e.toGround = std::max(-b - std::sqrt(discGround), 0.0);
    }
    return e;
}

/// Optical depth [dimensionless], RGB, of one piece: composite Simpson in u.
/// The nodes go in batches: their heights first (a loop that vectorises,
/// core/CMakeLists.txt), then their densities, then the sum in node order,
/// so the exponentials no longer wait on each node's square root (about
/// 3/4 of the time of one loop over the nodes, the same values; most of
/// every reference integral is spent here).
glm::dvec3 pieceOpticalDepth(const AtmosphereParams& air, const glm::dvec3& p, const glm::dvec3& dir,
                             const Piece& piece, int steps) {
    const int n = evenSteps(steps);
    const double du = 1.0 / n;
    constexpr int kBatch = 32;
    double height[kBatch], dsdu[kBatch];
    Densities density[kBatch];
    glm::dvec3 sum(0.0);
    for (int first = 0; first <= n; first += kBatch) {
        const int count = std::min(kBatch, n + 1 - first);
        for (int i = 0; i < count; ++i) {
            const double u = (first + i) * du;
            height[i] = heightOf(air, p + dir * piece.at(u));
            dsdu[i] = piece.derivative(u);
        }
        for (int i = 0; i < count; ++i) density[i] = densitiesAt(air, height[i]);
        for (int i = 0; i < count; ++i) {
            const int k = first + i;
            const double weight = (k == 0 || k == n) ? 1.0 : (k % 2 == 1 ? 4.0 : 2.0);
            sum += weight * extinctionOf(air, density[i]) * dsdu[i];
        }
    }
    return sum * (du / 3.0);
}

/// Optical depth from `p` towards the light, out to space; `shadowed` when
/// the planet is in the way.
glm::dvec3 opticalDepthToLight(const AtmosphereParams& air, const glm::dvec3& p, const glm::dvec3& light,
                               int steps, bool& shadowed) {
    const RayExtent e = rayExtent(air, p, light);
    shadowed = e.hitsGround;
    if (shadowed || !(e.toTop > 0.0)) return glm::dvec3(0.0);
    const double perigee = -dot3(p, light);
    if (perigee > 0.0 && perigee < e.toTop) {
        return pieceOpticalDepth(air, p, light, Piece{0.0, perigee, false}, steps) +
               pieceOpticalDepth(air, p, light, Piece{perigee, e.toTop, true}, steps);
    }
    return pieceOpticalDepth(air, p, light, Piece{0.0, e.toTop, true}, steps);
}

}  // namespace

SkySample referenceSkyIntegrals(const AtmosphereParams& air, const glm::dvec3& viewDirection,
                                const glm::dvec3& lightDirection, const SkyReferenceSettings& settings) {
    SkySample out;
    if (!(air.planetRadius > 0.0) || !(air.atmosphereRadius > air.planetRadius)) return out;
    const glm::dvec3 view = unitOrUp(viewDirection);
    const glm::dvec3 light = unitOrUp(lightDirection);
    const double viewerRadius = std::clamp(air.planetRadius + std::max(air.viewerHeight, 0.0),
                                           air.planetRadius, air.atmosphereRadius);
    const glm::dvec3 origin(0.0, viewerRadius, 0.0);

    // The view ray ends at the ground or the top. It is cut where the
    // integrand has a kink or a jump: the perigee of a downward ray (where
    // the density peaks) and the edges of the planet's shadow (the cylinder
    // of radius Rg behind the planet, away from the light). Each piece's
    // nodes crowd at its lower (denser) end.
    const RayExtent e = rayExtent(air, origin, view);
    const double end = e.hitsGround ? e.toGround : e.toTop;
    double cuts[6] = {0.0, end, 0.0, 0.0, 0.0, 0.0};
    int cutCount = 2;
    const double perigee = -dot3(origin, view);
    if (perigee > 0.0 && perigee < end) cuts[cutCount++] = perigee;
    const glm::dvec3 originAcross = origin - light * dot3(origin, light);  // parts across the light
    const glm::dvec3 viewAcross = view - light * dot3(view, light);
    const double qa = dot3(viewAcross, viewAcross), qb = dot3(originAcross, viewAcross);
    const double qc = dot3(originAcross, originAcross) - air.planetRadius * air.planetRadius;
    const double disc = qb * qb - qa * qc;
    if (qa > 0.0 && disc > 0.0) {
        for (double sign : {-1.0, 1.0}) {
            const double s = (-qb + sign * std::sqrt(disc)) / qa;
            if (s > 0.0 && s < end && dot3(origin + view * s, light) < 0.0) cuts[cutCount++] = s;
        }
    }
    for (int i = 1; i < cutCount; ++i)  // insertion sort of at most 5 cuts
        for (int k = i; k > 0 && cuts[k] < cuts[k - 1]; --k) std::swap(cuts[k], cuts[k - 1]);
    Piece pieces[5];
    int pieceCount = 0;
    for (int c = 0; c + 1 < cutCount; ++c) {
        const double a = cuts[c], b = cuts[c + 1];
        if (!(b > a)) continue;
        const bool lowerAtStart = heightOf(air, origin + view * a) <= heightOf(air, origin + view * b);
        pieces[pieceCount++] = Piece{a, b, lowerAtStart};
    }

    const int n = evenSteps(settings.viewSteps);
    const double du = 1.0 / n;
    glm::dvec3 depthToViewer(0.0);  // optical depth viewer -> current node
    for (int q = 0; q < pieceCount; ++q) {
        const Piece& piece = pieces[q];
        if (!(piece.b > piece.a)) continue;
        glm::dvec3 sumRayleigh(0.0), sumMie(0.0);
        for (int k = 0; k <= n; ++k) {
            const double u = k * du;
            if (k > 0) {
                // Extinction over [u - du, u]: Simpson with one midpoint.
                const double u0 = u - du, um = u - 0.5 * du;
                auto sigma = [&](double w) {
                    return extinctionOf(air, densitiesAt(air, heightOf(air, origin + view * piece.at(w)))) *
                           piece.derivative(w);
                };
                depthToViewer += (du / 6.0) * (sigma(u0) + 4.0 * sigma(um) + sigma(u));
            }
            const double s = piece.at(u);
            const glm::dvec3 x = origin + view * s;
            bool shadowed = false;
            const glm::dvec3 depthToLight = opticalDepthToLight(air, x, light, settings.lightSteps, shadowed);
            if (shadowed) continue;
            const Densities d = densitiesAt(air, heightOf(air, x));
            const double weight = (k == 0 || k == n) ? 1.0 : (k % 2 == 1 ? 4.0 : 2.0);
            const glm::dvec3 f = expNeg(depthToViewer + depthToLight) * (piece.derivative(u) * weight);
            sumRayleigh += d.rayleigh * f;
            sumMie += d.mie * f;
        }
        out.rayleigh += air.rayleighScattering * sumRayleigh * (du / 3.0);
        out.mie += air.mieScattering * sumMie * (du / 3.0);
    }
    return out;
}

glm::dvec3 referenceSkyRadiance(const AtmosphereParams& air, const glm::dvec3& viewDirection,
                                const glm::dvec3& lightDirection, const glm::dvec3& illuminance,
                                const SkyReferenceSettings& settings) {
    const SkySample s = referenceSkyIntegrals(air, viewDirection, lightDirection, settings);
    const double mu = std::clamp(dot3(unitOrUp(viewDirection), unitOrUp(lightDirection)), -1.0, 1.0);
    const double g = std::clamp(air.mieAnisotropy, -0.999, 0.999);
    // DESIGN.md, "Sky": Rayleigh 3/(16 pi) (1 + mu^2); Mie Cornette-Shanks.
    const double rayleighP = 3.0 / (16.0 * kPiRef) * (1.0 + mu * mu);
    const double mieP = 3.0 / (8.0 * kPiRef) * (1.0 - g * g) * (1.0 + mu * mu) /
                        ((2.0 + g * g) * std::pow(1.0 + g * g - 2.0 * g * mu, 1.5));
    return illuminance * (rayleighP * s.rayleigh + mieP * s.mie);
}

}  // namespace aerial
