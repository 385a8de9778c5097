// sky_multiple.cpp — the multiple-scattering LUT Psi_ms (sky_multiple.hpp;
// Hillaire 2020, section 5.5).
#include "sky_multiple.hpp"

#include "sky_layers.hpp"

#include <algorithm>
#include <cmath>

namespace aerial::detail {
namespace {

/// Distance from radius r0 along a ray with zenith cosine mu to the shell
/// r^2 = r0^2 + dr2: the far root for a rising ray (mu >= 0) or the exit
/// after the perigee (`far`), else the near root of a falling ray; without
/// cancellation. b2 = (r0 mu)^2 + dr2 >= 0.
double crossingDistance(double r0, double mu, double dr2, bool far) {
    const double b = r0 * mu;
    const double root = std::sqrt(std::max(b * b + dr2, 0.0));
    if (b >= 0.0) return dr2 > 0.0 ? dr2 / (b + root) : 0.0;  // rising: -b + root
    return far ? -b + root : -dr2 / (-b + root);              // falling: -b -+ root
}

/// (1 - e^-tau) / tau: the integral of sigma_s T over a segment per unit scattering depth.
double transferFactor(double tau) { return tau < 1e-4 ? 1.0 - 0.5 * tau : -std::expm1(-tau) / tau; }

}  // namespace

MsNode msZenithNode(int z) {
    // x: midpoints in (-1, 1); cos theta = sign(x) |x|^p, weight = (1/2) d(cos theta) = (p/2) |x|^(p-1) dx.
    const double dx = 2.0 / kMsZeniths;
    const double x = -1.0 + (z + 0.5) * dx;
    const double ax = std::abs(x);
    return {-(x < 0.0 ? -1.0 : 1.0) * std::pow(ax, kMsZenithPower),
            0.5 * kMsZenithPower * std::pow(ax, kMsZenithPower - 1.0) * dx};
}

MsNode msAzimuthNode(int a) {
    // u: midpoints in (0, 1); phi = pi u^q, weight = d(phi) / pi = q u^(q-1) du.
    const double du = 1.0 / kMsAzimuths;
    const double u = (a + 0.5) * du;
    return {kPi * std::pow(u, kMsAzimuthPower), kMsAzimuthPower * std::pow(u, kMsAzimuthPower - 1.0) * du};
}

double msCosineOfColumn(int column) {
    const double x = -1.0 + 2.0 * column / (kMsCosines - 1);
    return x * std::abs(x);
}

MsScratch::MsScratch() {
    depthRow.resize(kMsAngles);
    crossing.assign(kMsMaxCrossings, 0.0);
    shell.assign(kMsMaxCrossings, 0);
    for (auto* v : {&nodeS, &nodeR, &nodeM, &nodeO}) v->assign(std::size_t(4) * kMsMaxCrossings, 0.0f);
    records.assign(std::size_t(2) * 7 * kMsCombos, 0.0f);
    acc.assign(std::size_t(3) * kMsCombos, 0.0f);
    ground.assign(std::size_t(3) * kMsCombos, 0.0);
    source.assign(std::size_t(3) * 3 * kMsCombos, 0.0f);
    orderAcc.assign(std::size_t(3) * kMsCombos, 0.0f);
    column.assign(kMsCombos, 0);
    fraction.assign(kMsCombos, 0.0f);
    groundSky.assign(std::size_t(3) * kMsCombos, 0.0);
}

MultipleScatteringLut::MultipleScatteringLut() {
    height_.assign(kMsRows, 0.0);
    horizonCos_.assign(kMsRows, 0.0);
    angleScale_.assign(kMsRows, 0.0f);
    depth_.assign(std::size_t(3) * kMsRows * kMsAngles, 0.0f);
    psi_.assign(std::size_t(kMsRows) * kMsCosines * 3, 0.0f);
    for (auto& o : order_) o.assign(psi_.size(), 0.0f);
    sum_.assign(psi_.size(), 0.0);
    fms_.assign(std::size_t(kMsRows) * 3, 0.0);
    groundSky_.assign(std::size_t(kMsCosines) * 3, 0.0);
    comboP_.assign(kMsCombos, 0.0f);
    comboQ_.assign(kMsCombos, 0.0f);
    for (int j = 0; j < kMsCosines; ++j) {
        const double mu = msCosineOfColumn(j);
        const double sinS = std::sqrt(std::max(1.0 - mu * mu, 0.0));
        for (int a = 0; a < kMsAzimuths; ++a) {
            // Azimuths in (0, pi), their mirrors give the other half.
            const double phi = msAzimuthNode(a).angle;
            comboP_[std::size_t(j * kMsAzimuths + a)] = float(mu);
            comboQ_[std::size_t(j * kMsAzimuths + a)] = float(sinS * std::cos(phi));
        }
    }
}

void MultipleScatteringLut::setAtmosphere(const AtmosphereParams& air) {
    air_ = air;
    density_ = densityConstants(air);
    const double top = std::max(air.atmosphereRadius - air.planetRadius, 0.0);
    equalMassShells(air, 0.0, top, kMsLayers, height_.data());
    for (int k = 0; k < kMsRows; ++k) {
        horizonCos_[std::size_t(k)] = horizonCosine(air, height_[std::size_t(k)]);
        angleScale_[std::size_t(k)] = float(angleScale(kMsAngles, horizonCos_[std::size_t(k)]));
    }
    // The ground's share of f_ms: the radiance rho / pi E that the ground
    // reflects when the sky above it in-scatters unit isotropic luminance,
    // E = 2 pi integral_0^1 L_f(mu) mu dmu over the upward zenith bands.
    MsScratch& s = groundScratch_;
    double irradiance[3] = {0.0, 0.0, 0.0};
    for (int z = 0; z < kMsZeniths; ++z) {
        const MsNode node = msZenithNode(z);
        if (!(node.angle > 0.0)) continue;  // the upward bands
        double lf[3], endT[3];
        bool ground = false;
        rayTransfer(0, node.angle, s, lf, endT, ground);
        // d(cos theta) of the band = 2 weight.
        for (int c = 0; c < 3; ++c) irradiance[c] += 2.0 * kPi * lf[c] * node.angle * (2.0 * node.weight);
    }
    for (int c = 0; c < 3; ++c)
        groundReflection_[c] = std::clamp(air.groundAlbedo[c], 0.0, 1.0) / kPi * irradiance[c];
}

void MultipleScatteringLut::buildDepthRow(int row, MsScratch& s) {
    const std::size_t plane = std::size_t(kMsRows) * kMsAngles;
    float* out = depth_.data() + std::size_t(row) * kMsAngles;
    opticalDepthRow(air_, density_, height_[std::size_t(row)], horizonCos_[std::size_t(row)], kMsAngles,
                    s.depthRow, out, out + plane, out + 2 * plane);
}

// The crossings of the ray from shell `row` with zenith cosine cosT with
// the shells, in order (s.crossing, s.shell; the first is the start), and
// the densities at 4 Gauss-Legendre nodes per segment between them.
int MultipleScatteringLut::rayCrossings(int row, double cosT, MsScratch& s, bool& hitsGround) const {
    const double rg = air_.planetRadius;
    const double hk = height_[std::size_t(row)];
    const double rk = rg + hk;
    const double sinT = std::sqrt(std::max(1.0 - cosT * cosT, 0.0));
    // Crossings with the shells, in order along the ray.
    int n = 0;
    auto push = [&](double dist, int j) {
        s.crossing[std::size_t(n)] = dist;
        s.shell[std::size_t(n)] = j;
        ++n;
    };
    push(0.0, row);
    auto dr2Of = [&](int j) {
        const double hj = height_[std::size_t(j)];
        return (hj - hk) * (rg + hj + rk);
    };
    hitsGround = false;
    if (cosT >= 0.0) {
        for (int j = row + 1; j < kMsRows; ++j) push(crossingDistance(rk, cosT, dr2Of(j), true), j);
    } else {
        hitsGround = rk * sinT < rg;
        int lowest = row;
        for (int j = row - 1; j >= 0; --j) {
            const double b = rk * cosT;
            if (b * b + dr2Of(j) < 0.0) break;  // the perigee lies above shell j
            push(crossingDistance(rk, cosT, dr2Of(j), false), j);
            lowest = j;
        }
        if (!hitsGround) {
            for (int j = lowest; j < kMsRows; ++j) push(crossingDistance(rk, cosT, dr2Of(j), true), j);
        }
    }

    // Densities at 4 Gauss-Legendre nodes per segment.
    hitsGround = hitsGround && cosT < 0.0;
    const int segments = n - 1;
    segmentNodeDensities(s.crossing.data(), segments, hk, rk, cosT, density_, s.nodeS.data(), s.nodeR.data(),
                         s.nodeM.data(), s.nodeO.data());

    return n;
}

/// Unit isotropic in-scattering of the rays from shell `row` along cosT:
/// out = integral sigma_s T ds, and T to the ray's end.
void MultipleScatteringLut::rayTransfer(int row, double cosT, MsScratch& s, double out[3], double endT[3],
                                        bool& hitsGround) const {
    const int n = rayCrossings(row, cosT, s, hitsGround);
    for (int c = 0; c < 3; ++c) {
        out[c] = 0.0;
        endT[c] = 1.0;
    }
    for (int i = 0; i + 1 < n; ++i) {
        double scatter[3], tau[3];
        segmentDepths(i, s, scatter, tau);
        for (int c = 0; c < 3; ++c) {
            out[c] += scatter[c] * endT[c] * transferFactor(tau[c]);
            endT[c] *= std::exp(-tau[c]);
        }
    }
}

/// Scattering and extinction optical depths of segment i of the last rayCrossings.
void MultipleScatteringLut::segmentDepths(int i, const MsScratch& s, double scatter[3], double tau[3]) const {
    const double len = s.crossing[std::size_t(i) + 1] - s.crossing[std::size_t(i)];
    const MeanDensity m = segmentMeanDensity(s.nodeR.data(), s.nodeM.data(), s.nodeO.data(), i);
    const double mR = m.rayleigh * len, mM = m.mie * len, mO = m.ozone * len;
    for (int c = 0; c < 3; ++c) {
        scatter[c] = air_.rayleighScattering[c] * mR + air_.mieScattering[c] * mM;
        tau[c] = air_.rayleighScattering[c] * mR + air_.mieExtinction[c] * mM + air_.ozoneAbsorption[c] * mO;
    }
}

void MultipleScatteringLut::buildSecondOrderRow(int row, MsScratch& s) {
    const double rg = air_.planetRadius;
    const double hk = height_[std::size_t(row)];
    const double rk = rg + hk;
    const std::size_t plane = std::size_t(kMsRows) * kMsAngles;
    std::fill(s.acc.begin(), s.acc.end(), 0.0f);
    std::fill(s.ground.begin(), s.ground.end(), 0.0);
    double transfer[3] = {0.0, 0.0, 0.0};  // sum over the zenith bands of the unit in-scattering

    // Row 0 (the ground): the irradiance E_1 that single scattering sends
    // down to it, per sun column, from the upward rays' in-scattering
    // (integral L_1 cos d omega = sum over the bands of cos theta times each
    // band's share of acc, which carries 4 pi w_z L_1).
    const bool groundRow = row == 0;
    if (groundRow) std::fill(s.groundSky.begin(), s.groundSky.end(), 0.0);
    for (int z = 0; z < kMsZeniths; ++z) {
        const MsNode node = msZenithNode(z);
        const double cosT = node.angle, wz = node.weight;
        const double sinT = std::sqrt(std::max(1.0 - cosT * cosT, 0.0));
        const bool skyward = groundRow && cosT > 0.0;
        if (skyward)
            for (std::size_t m = 0; m < s.acc.size(); ++m) s.groundSky[m] -= cosT * double(s.acc[m]);
        bool hitsGround = false;
        const int n = rayCrossings(row, cosT, s, hitsGround);
        const int segments = n - 1;

        // The sun seen from crossing i at shell j: zenith cosine there
        // (r_k mu_s + s omega.sun) / r_j = alpha P + beta Q.
        auto crossingArgs = [&](int i, float* record) {
            const int j = s.shell[std::size_t(i)];
            const double dist = s.crossing[std::size_t(i)];
            const double rj = rg + height_[std::size_t(j)];
            MsCrossingArgs c{};
            c.count = kMsCombos;
            c.alpha = float((rk + dist * cosT) / rj);
            c.beta = float(dist * sinT / rj);
            c.horizonCos = float(horizonCos_[std::size_t(j)]);
            c.angleScale = angleScale_[std::size_t(j)];
            c.knee = float(kAngleKnee);
            c.maxU = float(kMsAngles - 1) - 1e-3f;
            c.p = comboP_.data();
            c.q = comboQ_.data();
            c.depth0 = depth_.data() + std::size_t(j) * kMsAngles;
            c.depth1 = c.depth0 + plane;
            c.depth2 = c.depth0 + 2 * plane;
            c.record = record;
            return c;
        };
        float* record[2] = {s.records.data(), s.records.data() + std::size_t(7) * kMsCombos};
        msCrossingKernel(crossingArgs(0, record[0]));
        double viewT[3] = {1.0, 1.0, 1.0};
        for (int i = 0; i < segments; ++i) {
            double scatter[3], tau[3];
            segmentDepths(i, s, scatter, tau);
            msCrossingKernel(crossingArgs(i + 1, record[(i + 1) % 2]));
            MsSegmentArgs seg{};
            seg.count = kMsCombos;
            seg.a = record[i % 2];
            seg.b = record[(i + 1) % 2];
            seg.acc = s.acc.data();
            double segT[3];
            for (int c = 0; c < 3; ++c) {
                seg.weight[c] = float(wz * scatter[c] * viewT[c]);
                seg.tauView[c] = float(tau[c]);
                segT[c] = std::exp(-tau[c]);
                transfer[c] += wz * scatter[c] * viewT[c] * transferFactor(tau[c]);
            }
            msSegmentKernel(seg);
            for (int c = 0; c < 3; ++c) viewT[c] *= segT[c];
        }
        if (skyward)
            for (std::size_t m = 0; m < s.acc.size(); ++m) s.groundSky[m] += cosT * double(s.acc[m]);
        if (hitsGround) {
            // The ground reflects the unit field too (f_ms's ground share).
            for (int c = 0; c < 3; ++c) transfer[c] += wz * viewT[c] * groundReflection_[c];
            // The last crossing is the ground (shell 0, horizon cosine 0): its
            // margin is the sun's zenith cosine there.
            const float* r = record[segments % 2];
            for (int c = 0; c < 3; ++c) {
                for (int m = 0; m < kMsCombos; ++m) {
                    const double mu = std::max(double(r[6 * kMsCombos + m]), 0.0);
                    s.ground[std::size_t(c * kMsCombos + m)] += wz * viewT[c] * r[(3 + c) * kMsCombos + m] * mu;
                }
            }
        }
    }

    // Means over the sphere (the weights sum to 1 in zenith and in azimuth;
    // each azimuth stands for itself and its mirror).
    for (int c = 0; c < 3; ++c) {
        const double fms = std::clamp(transfer[c], 0.0, 0.999);
        const double albedo = std::clamp(air_.groundAlbedo[c], 0.0, 1.0);
        for (int j = 0; j < kMsCosines; ++j) {
            double sum = 0.0;
            for (int a = 0; a < kMsAzimuths; ++a) {
                const std::size_t m = std::size_t(c * kMsCombos + j * kMsAzimuths + a);
                sum += msAzimuthNode(a).weight * (double(s.acc[m]) / (4.0 * kPi) + s.ground[m] * albedo / kPi);
            }
            const double l2 = std::isfinite(sum) ? sum : 0.0;
            const std::size_t at = (std::size_t(row) * kMsCosines + j) * 3 + c;
            order_[0][at] = float(l2);
            sum_[at] = l2;
            if (kMsLastOrder == 2) {  // Hillaire's series from the second order on
                const double value = l2 / (1.0 - fms);
                psi_[at] = std::isfinite(value) ? float(value) : 0.0f;
            }
        }
        fms_[std::size_t(row) * 3 + c] = fms;
        if (groundRow) {
            for (int j = 0; j < kMsCosines; ++j) {
                double e = 0.0;
                for (int a = 0; a < kMsAzimuths; ++a)
                    e += msAzimuthNode(a).weight * s.groundSky[std::size_t(c * kMsCombos + j * kMsAzimuths + a)];
                groundSky_[std::size_t(j) * 3 + c] = std::isfinite(e) ? std::max(e, 0.0) : 0.0;
            }
        }
    }
}

void MultipleScatteringLut::buildOrderRow(int row, int order, MsScratch& s) {
    if (order <= 2) {
        buildSecondOrderRow(row, s);
        return;
    }
    const std::vector<float>& from = order_[(order - 3) % 2];  // J_(order - 1)
    std::vector<float>& to = order_[(order - 2) % 2];
    const double rg = air_.planetRadius;
    const double rk = rg + height_[std::size_t(row)];
    std::fill(s.orderAcc.begin(), s.orderAcc.end(), 0.0f);
    constexpr float kMaxU = float(kMsCosines - 1) - 1e-3f;
    // The LUT column (s.column, s.fraction) of each combo's sun cosine where
    // the ray crosses shell s.shell[i] (linear in x = sign(mu) sqrt|mu|), and
    // J_(order - 1) there, as out[c][combo].
    auto sourceAt = [&](int i, float* out) {
        const int j = s.shell[std::size_t(i)];
        const double dist = s.crossing[std::size_t(i)];
        const double rj = rg + height_[std::size_t(j)];
        const float alpha = float((rk + dist * s.cosT) / rj), beta = float(dist * s.sinT / rj);
        for (int m = 0; m < kMsCombos; ++m) {
            const float mu = std::clamp(alpha * comboP_[std::size_t(m)] + beta * comboQ_[std::size_t(m)], -1.0f, 1.0f);
            const float x = std::copysign(std::sqrt(std::abs(mu)), mu);
            const float u = std::clamp((x + 1.0f) * 0.5f * float(kMsCosines - 1), 0.0f, kMaxU);
            s.column[std::size_t(m)] = int(u);
            s.fraction[std::size_t(m)] = u - float(int(u));
        }
        const float* rowJ = from.data() + std::size_t(j) * kMsCosines * 3;
        for (int c = 0; c < 3; ++c) {
            float* dst = out + std::size_t(c) * kMsCombos;
            for (int m = 0; m < kMsCombos; ++m) {
                const std::size_t at = std::size_t(s.column[std::size_t(m)]) * 3 + std::size_t(c);
                dst[m] = rowJ[at] + s.fraction[std::size_t(m)] * (rowJ[at + 3] - rowJ[at]);
            }
        }
    };
    // Every ray starts at the point itself (alpha = 1, beta = 0: the combo's
    // own sun cosine), so its source there is the same for all directions.
    const std::size_t plane = std::size_t(3) * kMsCombos;
    float* start = s.source.data() + 2 * plane;
    s.shell[0] = row;
    s.crossing[0] = 0.0;
    sourceAt(0, start);
    for (int z = 0; z < kMsZeniths; ++z) {
        const MsNode node = msZenithNode(z);
        s.cosT = node.angle;
        s.sinT = std::sqrt(std::max(1.0 - node.angle * node.angle, 0.0));
        bool hitsGround = false;
        const int n = rayCrossings(row, node.angle, s, hitsGround);
        float* g[2] = {s.source.data(), s.source.data() + plane};
        if (n > 1)
            std::copy(start, start + plane, g[0]);
        else
            sourceAt(0, g[0]);  // the ground row looking down: the ground term needs its columns
        double viewT[3] = {1.0, 1.0, 1.0};
        for (int i = 0; i + 1 < n; ++i) {
            double scatter[3], tau[3];
            segmentDepths(i, s, scatter, tau);
            sourceAt(i + 1, g[(i + 1) % 2]);
            for (int c = 0; c < 3; ++c) {
                // integral_0^1 e^(-tau t) (1 - t, t) dt = (F0 - F1, F1).
                const double t = tau[c];
                const double f0 = transferFactor(t);
                const double f1 = t < 1e-3 ? 0.5 - t / 3.0 : (1.0 - std::exp(-t) * (1.0 + t)) / (t * t);
                const double w = node.weight * scatter[c] * viewT[c];
                const float wa = float(w * (f0 - f1)), wb = float(w * f1);
                float* acc = s.orderAcc.data() + std::size_t(c) * kMsCombos;
                const float* a = g[i % 2] + std::size_t(c) * kMsCombos;
                const float* b = g[(i + 1) % 2] + std::size_t(c) * kMsCombos;
                for (int m = 0; m < kMsCombos; ++m) acc[m] += wa * a[m] + wb * b[m];
                viewT[c] *= std::exp(-t);
            }
        }
        if (hitsGround) {
            // The ground (the last crossing, whose columns sourceAt left in
            // s.column) lit by J_(order - 1)'s skylight (J around it times
            // the unit field's irradiance E_f there) reflects it; for order 3
            // also the skylight of single scattering (E_1).
            const float* gl = g[(n - 1) % 2];
            for (int c = 0; c < 3; ++c) {
                const double albedo = std::clamp(air_.groundAlbedo[c], 0.0, 1.0);
                const float w = float(node.weight * viewT[c] * groundReflection_[c]);
                const float w1 = order == 3 ? float(node.weight * viewT[c] * albedo / kPi) : 0.0f;
                float* acc = s.orderAcc.data() + std::size_t(c) * kMsCombos;
                for (int m = 0; m < kMsCombos; ++m) {
                    const std::size_t at = std::size_t(s.column[std::size_t(m)]) * 3 + std::size_t(c);
                    const double e1 = groundSky_[at] + s.fraction[std::size_t(m)] * (groundSky_[at + 3] - groundSky_[at]);
                    acc[m] += w * gl[std::size_t(c) * kMsCombos + std::size_t(m)] + w1 * float(e1);
                }
            }
        }
    }
    const bool last = order == kMsLastOrder;
    for (int c = 0; c < 3; ++c) {
        const double fms = fms_[std::size_t(row) * 3 + c];
        for (int j = 0; j < kMsCosines; ++j) {
            double value = 0.0;
            for (int a = 0; a < kMsAzimuths; ++a)
                value += msAzimuthNode(a).weight * s.orderAcc[std::size_t(c * kMsCombos + j * kMsAzimuths + a)];
            if (!std::isfinite(value)) value = 0.0;
            const std::size_t at = (std::size_t(row) * kMsCosines + j) * 3 + c;
            to[at] = float(value);
            sum_[at] += value;
            if (last) {
                const double total = sum_[at] + value * fms / (1.0 - fms);
                psi_[at] = std::isfinite(total) ? float(total) : 0.0f;
            }
        }
    }
}

void MultipleScatteringLut::resample(const double* heights, int count, float* out) const {
    for (int k = 0; k < count; ++k) {
        const double h = heights[k];
        int i = 0;
        while (i + 2 < kMsRows && height_[std::size_t(i) + 1] < h) ++i;
        const double h0 = height_[std::size_t(i)], h1 = height_[std::size_t(i) + 1];
        const double f = h1 > h0 ? std::clamp((h - h0) / (h1 - h0), 0.0, 1.0) : 0.0;
        for (int c = 0; c < 3; ++c) {
            float* dst = out + (std::size_t(c) * count + k) * kMsCosines;
            for (int j = 0; j < kMsCosines; ++j) {
                const double a = psi_[(std::size_t(i) * kMsCosines + j) * 3 + c];
                const double b = psi_[((std::size_t(i) + 1) * kMsCosines + j) * 3 + c];
                dst[j] = float(a + f * (b - a));
            }
        }
    }
}

}  // namespace aerial::detail
