// sky_multiple.cpp — the multiple-scattering LUT Psi_ms (sky_multiple.hpp;
// Hillaire 2020, section 5.5).
// This file: the quadrature nodes and the scattering orders of the LUT's
// rows; sky_multiple_setup.cpp its set-up for an atmosphere (phases, view
// matrix, optical depths) and its resampling at the sky solver's shells.
#include "sky_multiple.hpp"

#include "sky_layers.hpp"
#include "sky_solver_impl.hpp"

#include <algorithm>
#include <array>
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

/// View node v's direction (ViewNode, sky_multiple.hpp): the poles and
/// 0 / pi sit at the mappings' ends, the others on the zenith and azimuth
/// nodes.
ViewNode viewNodeAt(int v) {
    const int iz = v / kMsViewAzimuths, ia = v % kMsViewAzimuths;
    const double tz = iz == 0 ? 0.0 : (iz == kMsViewZeniths - 1 ? double(kMsZeniths) : iz - 0.5);
    const double ta = ia == 0 ? 0.0 : (ia == kMsViewAzimuths - 1 ? double(kMsAzimuths) : ia - 0.5);
    const double c = zenithAt(tz).angle;
    return {c, std::sqrt(std::max(1.0 - c * c, 0.0)), azimuthAt(ta).angle};
}

}  // namespace

MsNode zenithAt(double t) {
    const double dx = 2.0 / kMsZeniths;
    const double x = -1.0 + t * dx;
    const double ax = std::abs(x);
    return {-(x < 0.0 ? -1.0 : 1.0) * std::pow(ax, kMsZenithPower),
            0.5 * kMsZenithPower * std::pow(ax, kMsZenithPower - 1.0) * dx};
}

MsNode azimuthAt(double t) {
    const double du = 1.0 / kMsAzimuths;
    const double u = t * du;
    return {kPi * std::pow(u, kMsAzimuthPower), kMsAzimuthPower * std::pow(u, kMsAzimuthPower - 1.0) * du};
}

// The nodes are asked for in the LUT's inner loops: computed once (pow
// and cos there were a tenth of the LUT's build).
template <class T, int N, class F>
std::array<T, N> tabulate(F&& f) {
    std::array<T, N> out{};
    for (int k = 0; k < N; ++k) out[std::size_t(k)] = f(k);
    return out;
}

MsNode msZenithNode(int z) {
    static const auto nodes = tabulate<MsNode, kMsZeniths>([](int k) { return zenithAt(k + 0.5); });
    return nodes[std::size_t(z)];
}

MsNode msAzimuthNode(int a) {
    static const auto nodes = tabulate<MsNode, kMsAzimuths>([](int k) { return azimuthAt(k + 0.5); });
    return nodes[std::size_t(a)];
}

const ViewNode& msViewNode(int v) {
    static const auto nodes = tabulate<ViewNode, kMsViews>(viewNodeAt);
    return nodes[std::size_t(v)];
}

/// cos of azimuth node a's angle.
static double msAzimuthCos(int a) {
    static const auto cosines =
        tabulate<double, kMsAzimuths>([](int k) { return std::cos(msAzimuthNode(k).angle); });
    return cosines[std::size_t(a)];
}

double msCosineOfColumn(int column) {
    const double x = -1.0 + 2.0 * column / (kMsCosines - 1);
    return x * std::abs(x);
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
void MultipleScatteringLut::segmentDepths(int i, const MsScratch& s, double scatter[3], double tau[3],
                                          double* mieScatter) const {
    const double len = s.crossing[std::size_t(i) + 1] - s.crossing[std::size_t(i)];
    const MeanDensity m = segmentMeanDensity(s.nodeR.data(), s.nodeM.data(), s.nodeO.data(), i);
    const double mR = m.rayleigh * len, mM = m.mie * len, mO = m.ozone * len;
    for (int c = 0; c < 3; ++c) {
        scatter[c] = air_.rayleighScattering[c] * mR + air_.mieScattering[c] * mM;
        tau[c] = air_.rayleighScattering[c] * mR + air_.mieExtinction[c] * mM + air_.ozoneAbsorption[c] * mO;
        if (mieScatter != nullptr) mieScatter[c] = air_.mieScattering[c] * mM;
    }
}

// The moments of the in-scattered field L (sums over the quadrature in
// s.moment, planes 1, cos, sin, cos^2, sin^2, cos sin of the ray's zenith
// angle, each times the ray's zenith weight) at row `row`, channel c, sun
// column j: the means over the sphere (the weights sum to 1 in zenith and in
// azimuth; each azimuth stands for itself and its mirror) and the integrals
// (4 pi times the means) turned into D_u, D_s, B_0, B_u, B_s, B_us (above),
// stored into aniso_ or, with `add`, added to it. Returns the mean of L.
double MultipleScatteringLut::storeMoments(int row, int c, int j, const MsScratch& s, bool add,
                                           double scale) {
    const std::size_t channel = std::size_t(3) * kMsCombos;  // one moment plane
    double m[kMsAniso] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    for (int a = 0; a < kMsAzimuths; ++a) {
        const MsNode az = msAzimuthNode(a);
        const double cp = msAzimuthCos(a);
        const double factor[kMsAniso] = {1.0, 1.0, cp, 1.0, cp * cp, cp};
        const std::size_t at = std::size_t(c * kMsCombos + j * kMsAzimuths + a);
        for (int k = 0; k < kMsAniso; ++k)
            m[k] += az.weight * factor[k] * s.moment[std::size_t(k) * channel + at];
    }
    // D_u, D_s, M_uu, M_ss, M_us, M_pp; a sun at the zenith or the nadir has
    // no horizontal direction: symmetric about the vertical.
    const double m0 = 4.0 * kPi * m[0], du = 4.0 * kPi * m[1], muu = 4.0 * kPi * m[3];
    const bool axial = j == 0 || j == kMsCosines - 1;
    const double ds = axial ? 0.0 : 4.0 * kPi * m[2];
    const double mss = axial ? 0.5 * (m0 - muu) : 4.0 * kPi * m[4];
    const double mus = axial ? 0.0 : 4.0 * kPi * m[5];
    const double mpp = m0 - muu - mss;
    const double out[kMsAniso] = {du,       ds, 1.5 * mpp - 0.5 * m0, 1.5 * (muu - mpp), 1.5 * (mss - mpp),
                                  3.0 * mus};
    for (int k = 0; k < kMsAniso; ++k) {
        const double v = isotropic_ || !std::isfinite(out[k]) ? 0.0 : scale * out[k];
        float& dst = aniso_[((std::size_t(row) * kMsCosines + j) * kMsAniso + k) * 3 + c];
        dst = add ? dst + float(v) : float(v);
    }
    return std::isfinite(m[0]) ? m[0] : 0.0;
}

void MultipleScatteringLut::buildSecondOrderRow(int row, MsScratch& s) {
    const double rg = air_.planetRadius;
    const double hk = height_[std::size_t(row)];
    const double rk = rg + hk;
    const std::size_t plane = std::size_t(kMsRows) * kMsAngles;
    const std::size_t channel = std::size_t(3) * kMsCombos;  // one moment plane
    std::fill(s.moment.begin(), s.moment.end(), 0.0);
    double transfer[3] = {0.0, 0.0, 0.0};  // sum over the zenith bands of the unit in-scattering

    // Row 0 (the ground) also gathers the irradiance E_1 that single
    // scattering sends down to it, per sun column, from the upward rays
    // (integral L_1 cos d omega).
    const bool groundRow = row == 0;
    if (groundRow) std::fill(s.groundSky.begin(), s.groundSky.end(), 0.0);
    // L_1 per direction for Mie's last scattering (none with isotropic phases).
    float* field = isotropic_ ? nullptr : field_.data() + std::size_t(row) * 3 * kMsDirections * kMsCosines;
    double albedoPi[3];
    for (int c = 0; c < 3; ++c) albedoPi[c] = std::clamp(air_.groundAlbedo[c], 0.0, 1.0) / kPi;
    for (int z = 0; z < kMsZeniths; ++z) {
        const MsNode node = msZenithNode(z);
        const double cosT = node.angle, wz = node.weight;
        const double sinT = std::sqrt(std::max(1.0 - cosT * cosT, 0.0));
        std::fill(s.acc.begin(), s.acc.end(), 0.0f);
        std::fill(s.accMie.begin(), s.accMie.end(), 0.0f);
        std::fill(s.ground.begin(), s.ground.end(), 0.0);
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
            double scatter[3], tau[3], mie[3];
            segmentDepths(i, s, scatter, tau, mie);
            msCrossingKernel(crossingArgs(i + 1, record[(i + 1) % 2]));
            MsSegmentArgs seg{};
            seg.count = kMsCombos;
            seg.a = record[i % 2];
            seg.b = record[(i + 1) % 2];
            seg.acc = s.acc.data();
            seg.accMie = s.accMie.data();
            double segT[3];
            for (int c = 0; c < 3; ++c) {
                seg.weight[c] = float(wz * (scatter[c] - mie[c]) * viewT[c]);
                seg.weightMie[c] = float(wz * mie[c] * viewT[c]);
                seg.tauView[c] = float(tau[c]);
                segT[c] = std::exp(-tau[c]);
                transfer[c] += wz * scatter[c] * viewT[c] * transferFactor(tau[c]);
            }
            msSegmentKernel(seg);
            for (int c = 0; c < 3; ++c) viewT[c] *= segT[c];
        }
        if (hitsGround) {
            // The ground reflects the unit field too (f_ms's ground share).
            for (int c = 0; c < 3; ++c) transfer[c] += wz * viewT[c] * groundReflection_[c];
            // The last crossing is the ground (shell 0, horizon cosine 0): its
            // margin is the sun's zenith cosine there.
            const float* r = record[segments % 2];
            for (int c = 0; c < 3; ++c) {
                for (int m = 0; m < kMsCombos; ++m) {
                    const double mu = std::max(double(r[6 * kMsCombos + m]), 0.0);
                    s.ground[std::size_t(c * kMsCombos + m)] =
                        wz * viewT[c] * r[(3 + c) * kMsCombos + m] * mu;
                }
            }
        }
        // This ray's L_1 (times w_z) per combo, into the moments' sums
        // (planes: 1, cos, sin, cos^2, sin^2, cos sin of the ray's zenith
        // angle; the azimuth's factors come with the azimuth weights below).
        const double f[kMsAniso] = {1.0, cosT, sinT, cosT * cosT, sinT * sinT, cosT * sinT};
        const float* phR = phaseR_.data() + std::size_t(z) * kMsCombos;
        const float* phM = phaseM_.data() + std::size_t(z) * kMsCombos;
        const bool skyward = groundRow && cosT > 0.0;
        for (int c = 0; c < 3; ++c) {
            for (int m = 0; m < kMsCombos; ++m) {
                const std::size_t at = std::size_t(c * kMsCombos + m);
                const double l1 =
                    double(phR[m]) * s.acc[at] + double(phM[m]) * s.accMie[at] + s.ground[at] * albedoPi[c];
                for (int k = 0; k < kMsAniso; ++k) s.moment[std::size_t(k) * channel + at] += f[k] * l1;
                if (skyward) s.groundSky[at] += 4.0 * kPi * cosT * l1;
                if (field != nullptr) {
                    const int j = m / kMsAzimuths, a = m % kMsAzimuths;
                    field[(std::size_t(c) * kMsDirections + std::size_t(z * kMsAzimuths + a)) * kMsCosines +
                          std::size_t(j)] = float(l1 / wz);
                }
            }
        }
    }

    // The sphere's mean of L_1 (J_2) per sun column, and its moments (aniso_).
    for (int c = 0; c < 3; ++c) {
        const double fms = std::clamp(transfer[c], 0.0, 0.999);
        for (int j = 0; j < kMsCosines; ++j) {
            const double l2 = storeMoments(row, c, j, s, false, 1.0);
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

// C_v = (integral P_M' L over the sphere) - (1 - f_s) J - (the l <= 2
// series of Mie's remainder for L), at every view node v and sun column:
// what the series (and its window) miss of Mie's last scattering of the
// field L = L_1 + L_2 / (1 - f_ms) whose moments the series uses (field_,
// aniso_, both complete once the third order's row is), J = J_2 + J_3 / (1 -
// f_ms) its mean.
void MultipleScatteringLut::storeViews(int row) {
    const double m1 = mieBand1(), m2 = mieBand2(), isotropicShare = 1.0 - mieStraightOn();
    constexpr int block = 16;  // sun columns per register block
    static_assert(kMsCosines % block == 0);
    for (int c = 0; c < 3; ++c) {
        const double scale = 1.0 / (1.0 - fms_[std::size_t(row) * 3 + std::size_t(c)]);
        const float* field =
            field_.data() + (std::size_t(row) * 3 + std::size_t(c)) * kMsDirections * kMsCosines;
        for (int v = 0; v < kMsViews; ++v) {
            const int iz = v / kMsViewAzimuths, ia = v % kMsViewAzimuths;
            float* out = views_.data() +
                         ((std::size_t(row) * kMsViews + std::size_t(v)) * 3 + std::size_t(c)) * kMsCosines;
            if ((iz == 0 || iz == kMsViewZeniths - 1) && ia > 0) {
                // A pole: the same for every azimuth.
                const float* first = out - std::size_t(ia) * 3 * kMsCosines;
                std::copy(first, first + kMsCosines, out);
                continue;
            }
            float sum[kMsCosines];
            const float* k = viewMatrix_.data() + std::size_t(v) * kMsDirections;
            for (int j0 = 0; j0 < kMsCosines; j0 += block) {
                float acc[block] = {};
                for (int d = 0; d < kMsDirections; ++d) {
                    const float w = k[d];
                    const float* __restrict l = field + std::size_t(d) * kMsCosines + std::size_t(j0);
                    for (int j = 0; j < block; ++j) acc[j] += w * l[j];
                }
                std::copy(acc, acc + block, sum + j0);
            }
            const ViewNode& node = msViewNode(v);
            const double vu = node.cosT, vs = node.sinT * std::cos(node.phi);
            for (int j = 0; j < kMsCosines; ++j) {
                const std::size_t at = (std::size_t(row) * kMsCosines + std::size_t(j)) * 3 + std::size_t(c);
                // D_u, D_s, B_0, B_u, B_s, B_us, channels 3 apart (storeMoments).
                const float* m = aniso_.data() +
                                 (std::size_t(row) * kMsCosines + std::size_t(j)) * kMsAniso * 3 +
                                 std::size_t(c);
                const double series = m1 * (m[0] * vu + m[3] * vs) +
                                      m2 * (m[6] + m[9] * vu * vu + m[12] * vs * vs + m[15] * vu * vs);
                const double mean = order_[0][at] + scale * order_[1][at];
                const double value = sum[j] - isotropicShare * mean - series;
                out[j] = std::isfinite(value) ? float(value) : 0.0f;
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
    // The LUT column (s.column, s.fraction) of each combo's sun cosine where
    // the ray crosses shell s.shell[i] (msSourceKernel), and J_(order - 1)
    // there, as out[c][combo].
    auto sourceAt = [&](int i, float* out) {
        const int j = s.shell[std::size_t(i)];
        const double dist = s.crossing[std::size_t(i)];
        const double rj = rg + height_[std::size_t(j)];
        MsSourceArgs a{};
        a.count = kMsCombos;
        a.alpha = float((rk + dist * s.cosT) / rj);
        a.beta = float(dist * s.sinT / rj);
        a.cosines = kMsCosines;
        a.p = comboP_.data();
        a.q = comboQ_.data();
        a.row = from.data() + std::size_t(j) * kMsCosines * 3;
        a.column = s.column.data();
        a.fraction = s.fraction.data();
        a.out = out;
        msSourceKernel(a);
    };
    // Every ray starts at the point itself (alpha = 1, beta = 0: the combo's
    // own sun cosine), so its source there is the same for all directions.
    const std::size_t plane = std::size_t(3) * kMsCombos;
    float* start = s.source.data() + 2 * plane;
    s.shell[0] = row;
    s.crossing[0] = 0.0;
    sourceAt(0, start);
    // The third order's field L_2 is view-dependent too: its moments are
    // added to L_1's (aniso_), as the later orders' are not (isotropic).
    const bool moments = order == 3 && !isotropic_;
    if (moments) std::fill(s.moment.begin(), s.moment.end(), 0.0);
    for (int z = 0; z < kMsZeniths; ++z) {
        const MsNode node = msZenithNode(z);
        s.cosT = node.angle;
        s.sinT = std::sqrt(std::max(1.0 - node.angle * node.angle, 0.0));
        std::fill(s.acc.begin(), s.acc.end(), 0.0f);  // this ray's L_(order - 1), times its weight
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
                float* acc = s.acc.data() + std::size_t(c) * kMsCombos;
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
                float* acc = s.acc.data() + std::size_t(c) * kMsCombos;
                for (int m = 0; m < kMsCombos; ++m) {
                    const std::size_t at = std::size_t(s.column[std::size_t(m)]) * 3 + std::size_t(c);
                    const double e1 = groundSky_[at] + s.fraction[std::size_t(m)] * (groundSky_[at + 3] - groundSky_[at]);
                    acc[m] += w * gl[std::size_t(c) * kMsCombos + std::size_t(m)] + w1 * float(e1);
                }
            }
        }
        for (std::size_t at = 0; at < s.orderAcc.size(); ++at) s.orderAcc[at] += s.acc[at];
        if (moments) {
            // L_2 into the field of Mie's last scattering, times the tail's 1 / (1 - f_ms) as its moments.
            float* field = field_.data() + std::size_t(row) * 3 * kMsDirections * kMsCosines;
            for (int c = 0; c < 3; ++c) {
                const double scale = 1.0 / ((1.0 - fms_[std::size_t(row) * 3 + c]) * node.weight);
                for (int m = 0; m < kMsCombos; ++m)
                    field[(std::size_t(c) * kMsDirections + std::size_t(z * kMsAzimuths + m % kMsAzimuths)) *
                              kMsCosines +
                          std::size_t(m / kMsAzimuths)] +=
                        float(scale * s.acc[std::size_t(c * kMsCombos + m)]);
            }
            const std::size_t channel = std::size_t(3) * kMsCombos;
            const double f[kMsAniso] = {
                1.0, s.cosT, s.sinT, s.cosT * s.cosT, s.sinT * s.sinT, s.cosT * s.sinT};
            for (std::size_t at = 0; at < channel; ++at)
                for (int k = 0; k < kMsAniso; ++k)
                    s.moment[std::size_t(k) * channel + at] += f[k] * s.acc[at];
        }
    }
    const bool last = order == kMsLastOrder;
    for (int c = 0; c < 3; ++c) {
        const double fms = fms_[std::size_t(row) * 3 + c];
        for (int j = 0; j < kMsCosines; ++j) {
            if (moments) storeMoments(row, c, j, s, true, 1.0 / (1.0 - fms));
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
    if (moments) storeViews(row);
}

void MultipleScatteringLut::releaseViews() {
    std::vector<float>().swap(field_);
    std::vector<float>().swap(views_);
}

}  // namespace aerial::detail
