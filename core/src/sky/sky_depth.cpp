// sky_depth.cpp — one row of an optical-depth table (sky_depth.hpp).
#include "sky_depth.hpp"

#include <algorithm>
#include <cmath>

namespace aerial::detail {

DensityConstants densityConstants(const AtmosphereParams& air) {
    DensityConstants k;
    if (air.rayleighScaleHeight > 0.0) {
        k.invRayleighH = float(1.0 / air.rayleighScaleHeight);
        k.rayleighOn = 1.0f;
    }
    if (air.mieScaleHeight > 0.0) {
        k.invMieH = float(1.0 / air.mieScaleHeight);
        k.mieOn = 1.0f;
    }
    if (air.ozoneWidth > 0.0) {
        k.ozoneCenter = float(air.ozoneCenterHeight);
        k.ozoneInvHalfWidth = float(2.0 / air.ozoneWidth);
        k.ozoneOn = 1.0f;
    }
    return k;
}

double horizonCosine(const AtmosphereParams& air, double height) {
    const double ratio = air.planetRadius / (air.planetRadius + height);
    return -safeSqrt(1.0 - ratio * ratio);
}

double angleScale(int angles, double horizonCos) {
    const double range = 1.0 - horizonCos;
    return (angles - 1) * (range + kAngleKnee) / range;
}

void DepthRowScratch::resize(int angles) {
    for (auto* v : {&q, &len1, &start2, &len2, &depthR, &depthM, &depthO})
        v->assign(std::size_t(angles), 0.0f);
}

void opticalDepthRow(const AtmosphereParams& air, const DensityConstants& density, double height,
                     double horizonCos, int angles, DepthRowScratch& s, float* out0, float* out1,
                     float* out2) {
    const double rg = air.planetRadius;
    const double rt = std::max(air.atmosphereRadius, rg);
    const double h = height;
    const double r = rg + h;
    const double ch = horizonCos;
    const double range = 1.0 - ch;
    const double capacity = range / (range + kAngleKnee);  // a at u = 1
    const double r2MinusRg2 = h * (r + rg);
    const double rt2MinusRg2 = (rt - rg) * (rt + rg);
    for (int m = 0; m < angles; ++m) {
        const double a = capacity * m / (angles - 1);
        const double c = std::min(ch + a * kAngleKnee / (1.0 - a), 1.0);
        // p^2 - Rg^2 = (r^2 - Rg^2) - r^2 c^2; negative for rising rays whose
        // line passes below the ground, >= 0 for falling rays above the horizon.
        double q = r2MinusRg2 - r * r * c * c;
        if (c < 0.0) q = std::max(q, 0.0);
        const double dStart = r * c;  // signed distance of the start from the perigee
        const double dTop = safeSqrt(rt2MinusRg2 - q);
        s.q[std::size_t(m)] = float(q);
        s.len1[std::size_t(m)] = float(std::max(-dStart, 0.0));
        s.start2[std::size_t(m)] = float(std::max(dStart, 0.0));
        s.len2[std::size_t(m)] = float(std::max(dTop - std::max(dStart, 0.0), 0.0));
    }
    DepthKernelArgs args{};
    args.count = angles;
    args.planetRadius = float(rg);
    args.planetRadius2 = float(rg * rg);
    args.density = density;
    args.q = s.q.data();
    args.len1 = s.len1.data();
    args.start2 = s.start2.data();
    args.len2 = s.len2.data();
    args.depthR = s.depthR.data();
    args.depthM = s.depthM.data();
    args.depthO = s.depthO.data();
    depthKernel(args);
    float* out[3] = {out0, out1, out2};
    for (int ch3 = 0; ch3 < 3; ++ch3) {
        const float br = float(air.rayleighScattering[ch3]);
        const float bm = float(air.mieExtinction[ch3]);
        const float bo = float(air.ozoneAbsorption[ch3]);
        for (int m = 0; m < angles; ++m)
            out[ch3][m] =
                br * s.depthR[std::size_t(m)] + bm * s.depthM[std::size_t(m)] + bo * s.depthO[std::size_t(m)];
    }
}

}  // namespace aerial::detail
