// ms_reference.cpp — Monte Carlo reference for the sky's multiple scattering
// (ms_reference.hpp).
#include "ms_reference.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

namespace aerial::reference {
namespace {

constexpr int kSteps = 64;     // midpoint steps per ray, s = L u^2
constexpr int kMaxDepth = 12;  // path vertices
constexpr int kTableHeights = 96;
constexpr int kTableCosines = 96;

double dot3(const glm::dvec3& a, const glm::dvec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
double length3(const glm::dvec3& a) { return std::sqrt(dot3(a, a)); }
double average(const glm::dvec3& a) { return (a.x + a.y + a.z) / 3.0; }

double henyeyGreenstein(double mu, double g) {
    return (1.0 - g * g) / (4.0 * kPi * std::pow(std::max(1.0 + g * g - 2.0 * g * mu, 1e-12), 1.5));
}

/// A unit vector whose angle to `axis` has cosine mu, at azimuth phi.
glm::dvec3 around(const glm::dvec3& axis, double mu, double phi) {
    const glm::dvec3 helper = std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    glm::dvec3 t(axis.y * helper.z - axis.z * helper.y, axis.z * helper.x - axis.x * helper.z,
                 axis.x * helper.y - axis.y * helper.x);
    t /= length3(t);
    const glm::dvec3 b(axis.y * t.z - axis.z * t.y, axis.z * t.x - axis.x * t.z, axis.x * t.y - axis.y * t.x);
    const double s = std::sqrt(std::max(1.0 - mu * mu, 0.0));
    return mu * axis + s * std::cos(phi) * t + s * std::sin(phi) * b;
}

struct Step {
    double s, ds;
    glm::dvec3 sigmaR, sigmaM, t;  // scattering coefficients and T(start -> midpoint)
    double weight;                 // mean over channels of sigma_s T ds: the sampling weight
};

struct March {
    std::array<Step, kSteps> steps;  // on the stack: a march per path vertex, no allocation
    double totalWeight = 0.0;
    glm::dvec3 single{0.0};  // once-scattered sun along the ray, unit illuminance
    glm::dvec3 exitT{1.0};
    bool ground = false;
    glm::dvec3 exit{0.0};
};

class Random {
public:
    explicit Random(std::uint64_t seed) : engine_(seed) {}
    double next() { return double(engine_() >> 11) * 0x1.0p-53; }

private:
    std::mt19937_64 engine_;
};

}  // namespace

struct MultipleScatteringTracer::Impl {
    AtmosphereParams air;
    bool isotropic = false;  // Phase::Isotropic: every scattering 1 / (4 pi)
    double rg = 0.0, rt = 0.0;
    std::vector<glm::dvec3> depth;  // [kTableHeights][kTableCosines] optical depth to the top

    // extinctionAt's coefficients (atmosphere.cpp: negative and NaN -> 0,
    // capped at 1e10), so that march() forms extinctionAt's sum from the
    // densities it needs for the scattering coefficients anyway, bit for bit.
    glm::dvec3 extinctionR{0.0}, extinctionM{0.0}, extinctionO{0.0};

    static double coefficient(double x) { return x > 0.0 ? std::min(x, 1e10) : 0.0; }
    static glm::dvec3 coefficient(const glm::dvec3& v) {
        return {coefficient(v.x), coefficient(v.y), coefficient(v.z)};
    }

    /// Optical depth from radius r along zenith cosine mu to the top (the ray
    /// misses the ground): composite Simpson in w on each monotonic piece,
    /// s = dense end + len w^2.
    glm::dvec3 opticalDepth(double r, double mu) const {
        const double length = distanceToTop(air, r, mu);
        const double perigee = -r * mu;
        glm::dvec3 sum(0.0);
        auto piece = [&](double from, double len, double direction) {
            constexpr int n = 64;
            for (int k = 0; k <= n; ++k) {
                const double w = double(k) / n;
                const double s = from + direction * len * w * w;
                const double rs = std::sqrt(std::max(r * r + 2.0 * r * mu * s + s * s, 0.0));
                const double simpson = (k == 0 || k == n) ? 1.0 : (k % 2 ? 4.0 : 2.0);
                sum += extinctionAt(air, rs - rg) * (simpson * 2.0 * len * w / (3.0 * n));
            }
        };
        if (perigee > 0.0 && perigee < length) {
            piece(perigee, perigee, -1.0);
            piece(perigee, length - perigee, 1.0);
        } else {
            piece(0.0, length, 1.0);
        }
        return sum;
    }

    explicit Impl(const AtmosphereParams& a) : air(a) {
        rg = air.planetRadius;
        rt = air.atmosphereRadius;
        extinctionR = coefficient(air.rayleighScattering);
        extinctionM = coefficient(air.mieExtinction);
        extinctionO = coefficient(air.ozoneAbsorption);
        depth.resize(std::size_t(kTableHeights) * kTableCosines);
        for (int i = 0; i < kTableHeights; ++i) {
            const double v = double(i) / (kTableHeights - 1);
            const double r = rg + (rt - rg) * v * v;
            const double ch = -std::sqrt(std::max(1.0 - (rg / r) * (rg / r), 0.0));
            for (int j = 0; j < kTableCosines; ++j) {
                const double u = double(j) / (kTableCosines - 1);
                depth[std::size_t(i * kTableCosines + j)] = opticalDepth(r, ch + (1.0 - ch) * u * u);
            }
        }
    }

    /// T(x -> sun): 0 where the planet is in the way, else the table.
    glm::dvec3 sunTransmittance(const glm::dvec3& x, const glm::dvec3& sun) const {
        const double r = std::clamp(length3(x), rg, rt);
        const double mu = std::clamp(dot3(x, sun) / length3(x), -1.0, 1.0);
        if (rayHitsGround(air, r, mu)) return glm::dvec3(0.0);
        const double v = std::sqrt((r - rg) / (rt - rg)) * (kTableHeights - 1);
        const double ch = -std::sqrt(std::max(1.0 - (rg / r) * (rg / r), 0.0));
        const double u = std::sqrt(std::clamp((mu - ch) / (1.0 - ch), 0.0, 1.0)) * (kTableCosines - 1);
        const int i = std::min(int(v), kTableHeights - 2), j = std::min(int(u), kTableCosines - 2);
        const double fi = v - i, fj = u - j;
        auto at = [&](int a, int b) { return depth[std::size_t(a * kTableCosines + b)]; };
        const glm::dvec3 tau = (1 - fi) * ((1 - fj) * at(i, j) + fj * at(i, j + 1)) +
                               fi * ((1 - fj) * at(i + 1, j) + fj * at(i + 1, j + 1));
        return glm::dvec3(std::exp(-tau.x), std::exp(-tau.y), std::exp(-tau.z));
    }

    /// Marches from x along the unit direction w to the ground or the top.
    void march(const glm::dvec3& x, const glm::dvec3& w, const glm::dvec3& sun, March& m) const {
        const double r = length3(x);
        const double mu = dot3(x, w) / r;
        m.ground = rayHitsGround(air, r, mu);
        double length = 0.0;
        if (m.ground) {
            const double disc = r * r * (mu * mu - 1.0) + rg * rg;
            length = std::max(-r * mu - std::sqrt(std::max(disc, 0.0)), 0.0);
        } else {
            length = distanceToTop(air, r, mu);
        }
        m.totalWeight = 0.0;
        m.single = glm::dvec3(0.0);
        glm::dvec3 t(1.0);
        const double mr = isotropic ? 0.25 / kPi : miePhase(dot3(w, sun), air.mieAnisotropy);
        const double rr = isotropic ? 0.25 / kPi : rayleighPhase(dot3(w, sun));
        for (int k = 0; k < kSteps; ++k) {
            const double u0 = double(k) / kSteps, u1 = double(k + 1) / kSteps;
            Step& st = m.steps[std::size_t(k)];
            st.s = length * 0.25 * (u0 + u1) * (u0 + u1);
            st.ds = length * (u1 * u1 - u0 * u0);
            const glm::dvec3 y = x + st.s * w;
            const double h = std::max(length3(y) - rg, 0.0);
            const double densityR = rayleighDensity(air, h), densityM = mieDensity(air, h);
            const glm::dvec3 ext =  // extinctionAt(air, h)
                extinctionR * densityR + extinctionM * densityM + extinctionO * ozoneDensity(air, h);
            const glm::dvec3 half(std::exp(-0.5 * ext.x * st.ds), std::exp(-0.5 * ext.y * st.ds),
                                  std::exp(-0.5 * ext.z * st.ds));
            st.sigmaR = air.rayleighScattering * densityR;
            st.sigmaM = air.mieScattering * densityM;
            st.t = t * half;
            st.weight = average((st.sigmaR + st.sigmaM) * st.t) * st.ds;
            m.totalWeight += st.weight;
            m.single += (rr * st.sigmaR + mr * st.sigmaM) * st.t * sunTransmittance(y, sun) * st.ds;
            t *= half * half;
        }
        m.exitT = t;
        m.exit = x + length * w;
    }

    /// Picks a step in proportion to its weight.
    static int pickStep(const March& m, double u) {
        double target = u * m.totalWeight;
        for (int k = 0; k < kSteps; ++k) {
            target -= m.steps[std::size_t(k)].weight;
            if (target < 0.0) return k;
        }
        return kSteps - 1;
    }

    /// A direction from the phase functions at a step about the axis
    /// `look` (the direction looked along): Rayleigh with probability q,
    /// else Henyey-Greenstein; returns the estimator factor
    /// (sigma_R P_R + sigma_M P_M) / pdf.
    glm::dvec3 scatter(const Step& st, const glm::dvec3& look, double u0, double u1, double u2,
                       glm::dvec3& out) const {
        const double sr = average(st.sigmaR), sm = average(st.sigmaM);
        const double q = sr + sm > 0.0 ? sr / (sr + sm) : 1.0;
        const double g = std::clamp(air.mieAnisotropy, -0.95, 0.95);
        double mu = 0.0;
        if (isotropic) {
            out = around(look, 1.0 - 2.0 * u1, 2.0 * kPi * u2);
            return st.sigmaR + st.sigmaM;  // (sigma_R + sigma_M) / (4 pi) over the pdf 1 / (4 pi)
        }
        if (u0 < q) {
            const double qq = 4.0 - 8.0 * u1;  // F(mu) = (mu^3 + 3 mu + 4) / 8 = u1
            const double a = std::cbrt(-0.5 * qq + std::sqrt(0.25 * qq * qq + 1.0));
            mu = a - 1.0 / a;
        } else if (std::abs(g) > 1e-4) {
            const double f = (1.0 - g * g) / (1.0 - g + 2.0 * g * u1);
            mu = (1.0 + g * g - f * f) / (2.0 * g);
        } else {
            mu = 1.0 - 2.0 * u1;
        }
        mu = std::clamp(mu, -1.0, 1.0);
        out = around(look, mu, 2.0 * kPi * u2);
        const double pdf = q * rayleighPhase(mu) + (1.0 - q) * henyeyGreenstein(mu, g);
        return (st.sigmaR * rayleighPhase(mu) + st.sigmaM * miePhase(mu, air.mieAnisotropy)) / pdf;
    }

    /// Radiance arriving at x from direction w (looking along w), all
    /// orders >= 1 and ground reflections, no direct sun.
    glm::dvec3 incoming(const glm::dvec3& x, const glm::dvec3& w, const glm::dvec3& sun, int depthIndex,
                        Random& rng) const {
        March m;
        march(x, w, sun, m);
        glm::dvec3 radiance = m.single;
        glm::dvec3 normal(0.0);
        if (m.ground) {
            normal = m.exit / length3(m.exit);
            radiance += m.exitT * air.groundAlbedo / kPi * sunTransmittance(m.exit, sun) *
                        std::max(dot3(normal, sun), 0.0);
        }
        if (depthIndex >= kMaxDepth) return radiance;
        const double survive = depthIndex < 2 ? 1.0 : 0.5;
        if (rng.next() >= survive) return radiance;
        const bool canGround = m.ground;
        const bool viaGround = canGround && rng.next() < 0.5;
        const double choice = canGround ? 0.5 : 1.0;
        if (viaGround) {
            const double u1 = rng.next(), u2 = rng.next();
            const double cosT = std::sqrt(u1);
            const glm::dvec3 dir = around(normal, cosT, 2.0 * kPi * u2);
            const glm::dvec3 from = m.exit + normal * 0.01;
            return radiance + m.exitT * air.groundAlbedo * incoming(from, dir, sun, depthIndex + 1, rng) /
                                  (survive * choice);
        }
        if (!(m.totalWeight > 0.0)) return radiance;
        const int k = pickStep(m, rng.next());
        const Step& st = m.steps[std::size_t(k)];
        glm::dvec3 dir;
        const glm::dvec3 f = scatter(st, w, rng.next(), rng.next(), rng.next(), dir);
        const double p = st.weight / m.totalWeight;
        return radiance + st.t * f * st.ds / p * incoming(x + st.s * w, dir, sun, depthIndex + 1, rng) /
                              (survive * choice);
    }
};

MultipleScatteringTracer::MultipleScatteringTracer(const AtmosphereParams& air, Phase phase)
    : impl_(std::make_unique<Impl>(air)) {
    impl_->isotropic = phase == Phase::Isotropic;
}
MultipleScatteringTracer::~MultipleScatteringTracer() = default;

glm::dvec3 MultipleScatteringTracer::multipleScattering(const glm::dvec3& view, const glm::dvec3& sun,
                                                        int paths, std::uint64_t seed) const {
    const Impl& m = *impl_;
    const glm::dvec3 x0(0.0, m.rg + std::max(m.air.viewerHeight, 0.0) + 0.01, 0.0);
    March viewRay;
    m.march(x0, view, sun, viewRay);
    if (!(viewRay.totalWeight > 0.0) || paths < 1) return glm::dvec3(0.0);
    Random rng(seed);
    // Randomly shifted R_4 sequence (Roberts 2018) for the first vertex.
    const double phi = 1.1673039782614187;  // x^5 = x + 1
    double alpha[4], shift[4];
    for (int d = 0; d < 4; ++d) {
        alpha[d] = 1.0 / std::pow(phi, d + 1);
        shift[d] = rng.next();
    }
    glm::dvec3 sum(0.0);
    for (int n = 0; n < paths; ++n) {
        double u[4];
        for (int d = 0; d < 4; ++d) u[d] = std::fmod(shift[d] + alpha[d] * (n + 1), 1.0);
        const int k = m.pickStep(viewRay, u[0]);
        const Step& st = viewRay.steps[std::size_t(k)];
        glm::dvec3 dir;
        const glm::dvec3 f = m.scatter(st, view, u[1], u[2], u[3], dir);
        const double p = st.weight / viewRay.totalWeight;
        sum += st.t * f * st.ds / p * m.incoming(x0 + st.s * view, dir, sun, 1, rng);
    }
    return sum / double(paths);
}

}  // namespace aerial::reference
