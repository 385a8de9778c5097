// sky_multiple_setup.cpp — the multiple-scattering LUT Psi_ms
// (sky_multiple.hpp; Hillaire 2020, section 5.5) for an atmosphere: its
// scratch and tables, the first scattering's phases, the quadrature of Mie's
// last scattering towards the view nodes, the LUT's optical-depth rows, and
// the resampling of Psi_ms at the sky solver's shells. The scattering
// orders themselves: sky_multiple.cpp.
#include "sky_multiple.hpp"

#include "sky_layers.hpp"
#include "sky_solver_impl.hpp"

#include <algorithm>
#include <cmath>

namespace aerial::detail {

MsScratch::MsScratch() {
    depthRow.resize(kMsAngles);
    crossing.assign(kMsMaxCrossings, 0.0);
    shell.assign(kMsMaxCrossings, 0);
    for (auto* v : {&nodeS, &nodeR, &nodeM, &nodeO}) v->assign(std::size_t(4) * kMsMaxCrossings, 0.0f);
    records.assign(std::size_t(2) * 7 * kMsCombos, 0.0f);
    acc.assign(std::size_t(3) * kMsCombos, 0.0f);
    accMie.assign(std::size_t(3) * kMsCombos, 0.0f);
    ground.assign(std::size_t(3) * kMsCombos, 0.0);
    moment.assign(std::size_t(kMsAniso) * 3 * kMsCombos, 0.0);
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
    aniso_.assign(std::size_t(kMsRows) * kMsCosines * kMsAniso * 3, 0.0f);
    viewMatrix_.assign(std::size_t(kMsViews) * kMsDirections, 0.0f);
    phaseR_.assign(std::size_t(kMsZeniths) * kMsCombos, float(0.25 / kPi));
    phaseM_.assign(phaseR_.size(), float(0.25 / kPi));
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

void MultipleScatteringLut::setAtmosphere(const AtmosphereParams& air, bool isotropic) {
    air_ = air;
    isotropic_ = isotropic;
    // The build's field and views of Mie's last scattering (releaseViews).
    if (!isotropic) {
        field_.assign(std::size_t(kMsRows) * 3 * kMsDirections * kMsCosines, 0.0f);
        views_.assign(std::size_t(kMsRows) * kMsViews * 3 * kMsCosines, 0.0f);
    }
    buildPhases();
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

// The first scattering's phases per zenith node and combo, each the average
// of the phase over the node's quadrature cell (kMsPhaseSubsamples^2 points
// weighted by the cell's Jacobian): at 96 directions the Mie peak (g = 0.8:
// half its light within ~25 deg of the sun) falls inside one or two cells.
// Also Mie's Legendre coefficients g_1, g_2 (2 pi integral P P_l dmu, with
// mu = 1 - 2 t^2 to resolve the peak). Kept while g does not change.
void MultipleScatteringLut::buildPhases() {
    if (isotropic_) {
        std::fill(phaseR_.begin(), phaseR_.end(), float(0.25 / kPi));
        std::fill(phaseM_.begin(), phaseM_.end(), float(0.25 / kPi));
        mieG1_ = mieG2_ = 0.0;
        phaseG_ = NAN;
        return;
    }
    const double g = air_.mieAnisotropy;
    if (g == phaseG_) return;
    phaseG_ = g;
    constexpr int kLegendre = 4096;
    double g1 = 0.0, g2 = 0.0, g3 = 0.0, cone = 0.0;
    const double coneCos = std::cos(kMsStraightOnConeDeg * kPi / 180.0);
    for (int k = 0; k < kLegendre; ++k) {
        const double t = (k + 0.5) / kLegendre, mu = 1.0 - 2.0 * t * t;
        const double w = 2.0 * kPi * miePhase(mu, g) * 4.0 * t / kLegendre;
        g1 += w * mu;
        g2 += w * (1.5 * mu * mu - 0.5);
        g3 += w * (2.5 * mu * mu - 1.5) * mu;
        if (mu > coneCos) cone += w;
    }
    // Delta-M with f = g_3 (sky_multiple.hpp, "Mie's truncation"): the share
    // f_s within the cone straight on (the sky solver's view rays), the rest
    // f - f_s through the Fejer window.
    const double f = g3;
    const double fs = std::clamp(cone, 0.0, std::max(f, 0.0));
    mieStraightOn_ = fs;
    mieG1_ = g1 - fs - 0.5 * (f - fs);
    mieG2_ = g2 - fs - 0.9 * (f - fs);
    // The cells' sub-samples (the nodes' own mappings): zenith (cos, sin,
    // Jacobian) and azimuth (cos, Jacobian).
    constexpr int n = kMsPhaseSubsamples;
    double zc[kMsZeniths][n], zs[kMsZeniths][n], zw[kMsZeniths][n], ac[kMsAzimuths][n], aw[kMsAzimuths][n];
    for (int z = 0; z < kMsZeniths; ++z) {
        for (int i = 0; i < n; ++i) {
            const MsNode at = zenithAt(z + (i + 0.5) / n);
            zc[z][i] = at.angle;
            zs[z][i] = std::sqrt(std::max(1.0 - at.angle * at.angle, 0.0));
            zw[z][i] = at.weight;
        }
    }
    for (int a = 0; a < kMsAzimuths; ++a) {
        for (int i = 0; i < n; ++i) {
            const MsNode at = azimuthAt(a + (i + 0.5) / n);
            ac[a][i] = std::cos(at.angle);
            aw[a][i] = at.weight;
        }
    }
    for (int z = 0; z < kMsZeniths; ++z) {
        for (int j = 0; j < kMsCosines; ++j) {
            const double mus = msCosineOfColumn(j);
            const double sinS = std::sqrt(std::max(1.0 - mus * mus, 0.0));
            for (int a = 0; a < kMsAzimuths; ++a) {
                double sumR = 0.0, sumM = 0.0, sumW = 0.0;
                for (int ix = 0; ix < n; ++ix) {
                    for (int iu = 0; iu < n; ++iu) {
                        const double nu = zc[z][ix] * mus + zs[z][ix] * sinS * ac[a][iu];
                        const double w = zw[z][ix] * aw[a][iu];
                        sumR += w * rayleighPhase(nu);
                        sumM += w * miePhase(nu, g);
                        sumW += w;
                    }
                }
                const std::size_t at = std::size_t(z) * kMsCombos + std::size_t(j * kMsAzimuths + a);
                phaseR_[at] = float(sumR / sumW);
                phaseM_[at] = float(sumM / sumW);
            }
        }
    }
    buildViewMatrix();
}

// The quadrature of Mie's last scattering towards each view node v:
// K[v][d] = 4 pi w_z w_a times Mie's phase outside the straight-on cone
// (P_M' = P_M where the angle exceeds kMsStraightOnConeDeg, 0 within it:
// that share goes straight on along the view ray), averaged over direction
// d's cell and its mirror (the field is the same in both), so that
// integral P_M'(omega . v) L(omega) d omega = sum_d K[v][d] L(d).
void MultipleScatteringLut::buildViewMatrix() {
    const double g = std::isfinite(air_.mieAnisotropy) ? std::clamp(air_.mieAnisotropy, -0.999, 0.999) : 0.0;
    const double coneCos = std::cos(kMsStraightOnConeDeg * kPi / 180.0);
    // Cornette-Shanks (miePhase) as k (1 + mu^2) / (1 + g^2 - 2 g mu)^1.5.
    const double k = 3.0 / (8.0 * kPi) * (1.0 - g * g) / (2.0 + g * g);
    constexpr int n = kMsPhaseSubsamples;
    struct Sub {
        double cosT, sinT, cosP, sinP, weight;
    };
    std::vector<Sub> sub(std::size_t(kMsDirections) * n * n);
    for (int z = 0; z < kMsZeniths; ++z)
        for (int a = 0; a < kMsAzimuths; ++a)
            for (int i = 0; i < n; ++i)
                for (int q = 0; q < n; ++q) {
                    const MsNode zz = zenithAt(z + (i + 0.5) / n), aa = azimuthAt(a + (q + 0.5) / n);
                    sub[((std::size_t(z) * kMsAzimuths + std::size_t(a)) * n + std::size_t(i)) * n +
                        std::size_t(q)] = {zz.angle, std::sqrt(std::max(1.0 - zz.angle * zz.angle, 0.0)),
                                           std::cos(aa.angle), std::sin(aa.angle), zz.weight * aa.weight};
                }
    for (int v = 0; v < kMsViews; ++v) {
        const int iz = v / kMsViewAzimuths, ia = v % kMsViewAzimuths;
        float* row = viewMatrix_.data() + std::size_t(v) * kMsDirections;
        if ((iz == 0 || iz == kMsViewZeniths - 1) && ia > 0) {  // a pole: the same for every azimuth
            const float* first = row - std::size_t(ia) * kMsDirections;
            std::copy(first, first + kMsDirections, row);
            continue;
        }
        const ViewNode& node = msViewNode(v);
        const double cv = node.cosT, sv = node.sinT, phiV = node.phi;
        const double cpv = sv * std::cos(phiV), spv = sv * std::sin(phiV);
        for (int d = 0; d < kMsDirections; ++d) {
            double sumP = 0.0, sumW = 0.0;
            const Sub* x = sub.data() + std::size_t(d) * n * n;
            for (int q = 0; q < n * n; ++q) {
                // The direction and its mirror: cos(phi -+ phi_v).
                const double base = x[q].cosT * cv, along = x[q].sinT * x[q].cosP * cpv,
                             across = x[q].sinT * x[q].sinP * spv;
                for (const double mu : {base + along + across, base + along - across}) {
                    if (mu <= coneCos) {
                        const double e = 1.0 + g * g - 2.0 * g * mu;
                        sumP += x[q].weight * (1.0 + mu * mu) / (e * std::sqrt(e));
                    }
                }
                sumW += 2.0 * x[q].weight;
            }
            const MsNode zn = msZenithNode(d / kMsAzimuths), an = msAzimuthNode(d % kMsAzimuths);
            row[d] = float(4.0 * kPi * zn.weight * an.weight * k * sumP / sumW);
        }
    }
}

void MultipleScatteringLut::buildDepthRow(int row, MsScratch& s) {
    const std::size_t plane = std::size_t(kMsRows) * kMsAngles;
    float* out = depth_.data() + std::size_t(row) * kMsAngles;
    opticalDepthRow(air_, density_, height_[std::size_t(row)], horizonCos_[std::size_t(row)], kMsAngles,
                    s.depthRow, out, out + plane, out + 2 * plane);
}

void MultipleScatteringLut::resample(const double* heights, int count, int kBegin, int kEnd, float* out,
                                     float* aniso, float* mie) const {
    for (int k = std::max(kBegin, 0); k < std::min(kEnd, count); ++k) {
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
                const double psi = std::max(a + f * (b - a), kMsPsiFloor);
                dst[j] = float(-std::log(psi));
                for (int n = 0; n < kMsAniso; ++n) {
                    const double x = aniso_[((std::size_t(i) * kMsCosines + j) * kMsAniso + n) * 3 + c];
                    const double y = aniso_[(((std::size_t(i) + 1) * kMsCosines + j) * kMsAniso + n) * 3 + c];
                    aniso[(std::size_t(n * 3 + c) * count + k) * kMsCosines + std::size_t(j)] =
                        float(std::clamp((x + f * (y - x)) / psi, -kMsAnisoRatio, kMsAnisoRatio));
                }
                if (mie == nullptr) continue;
                for (int v = 0; v < kMsViews; ++v) {
                    const auto at = [&](int row) {
                        if (views_.empty()) return 0.0;  // released (releaseViews) or isotropic
                        return double(
                            views_[((std::size_t(row) * kMsViews + std::size_t(v)) * 3 + std::size_t(c)) *
                                       kMsCosines +
                                   std::size_t(j)]);
                    };
                    const double x = at(i), y = at(i + 1);
                    mie[((std::size_t(k) * kMsViews + std::size_t(v)) * 3 + std::size_t(c)) * kMsCosines +
                        std::size_t(j)] =
                        float(std::clamp((x + f * (y - x)) / psi, -kMsAnisoRatio, kMsAnisoRatio));
                }
            }
        }
    }
}

}  // namespace aerial::detail

namespace aerial {

MultipleScatteringTable SkySolver::multipleScatteringTable() const {
    MultipleScatteringTable t;
    if (!impl_->multiple) return t;
    t.heightCount = detail::kMsRows;
    t.cosineCount = detail::kMsCosines;
    t.heights = impl_->ms.heights();
    t.cosines.resize(std::size_t(detail::kMsCosines));
    for (int j = 0; j < detail::kMsCosines; ++j) t.cosines[std::size_t(j)] = detail::msCosineOfColumn(j);
    t.psi = impl_->ms.psi();
    return t;
}

}  // namespace aerial
