// sky_table_mapping.cpp — where the sky table's rows and columns go for a
// light (sky_table_mapping.hpp): the mapping's parameters and the
// coordinates every table carries (setSkyTableMapping).
#include <aerial/sky.hpp>

#include "planet_shadow.hpp"
#include "sky_table_mapping.hpp"

#include <algorithm>
#include <cmath>

namespace aerial {
namespace {

glm::dvec3 normalizedOr(const glm::dvec3& v, const glm::dvec3& fallback) {
    const double len = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    return len > 0.0 && std::isfinite(len) ? v / len : fallback;
}

}  // namespace

namespace {

constexpr double kMappingTopDeg = 1.0;   // lights above this elevation [deg]: the plain mapping
constexpr double kShadowFadeDeg = 0.01;  // the shadow rows fade in over this depression [deg]
// The horizon band's least width E [deg]. 0.4 left the rows 3-6 deg above
// the horizon opposite a light 0.005-0.05 deg down 1.1-2 deg apart (80% of
// the rows within 2 deg of the horizon): 2.5-5.1% there; 0.8: 1.4-1.9%
// there, but 2.9-3.3% 4-6 deg up opposite a light 0.03-0.3 deg down
// while E was bisected to put a row on the kink (E came out at 0.47 deg at
// -0.03); with E left at its nominal value (the shadow rows' share puts the
// row on the kink instead) and a floor of 1.2 deg: 1.0-1.5% up to 6 deg
// from -0.3 to -0.01 deg (SkyShadowOnset), SkyOffTexel within 0.3 points.
constexpr double kBandFloorDeg = 1.2;
constexpr double kDeepestDeg = 18.0;  // depressions beyond this [deg] map as this one

/// The row mapping of a table (sky.hpp) as a function of x = sqrt(elevation):
/// v(x) = (1 - a - b - d) x / sqrt(pi/2) + a atan(x^2 / E) / atan(pi/2 / E)
///        + b (atan((x^2 - c) / w) - atan(-c / w)) / (atan((pi/2 - c) / w) - atan(-c / w))
///        + d/2 (1 - B(u)) below c, d/2 (1 + cbrt(u)) above, u = min(|x^2 - c|, c) / c
///          (the cap's rows, d = skyCapRowShare(g) where the columns are warped,
///          B(u) = u^kSkyCapBelowPower: crowded towards c below it, crowded at the
///          cap's top above it, where the lit sky switches on within 1e-4 deg),
/// increasing in x, with v(0) = 0 and v(sqrt(pi/2)) = 1.
struct RowMapping {
    double plain = 1.0, a = 0.0, e = 1.0, bandNorm = 1.0;
    double b = 0.0, c = 0.0, w = 1.0, shadowLow = 0.0, shadowNorm = 1.0;
    double d = 0.0, cap = 1.0;
    /// The cap's rows below c as a function of u = (c - el) / c, 0..1, and
    /// its derivative.
    static double belowMap(double u) { return std::pow(u, kSkyCapBelowPower); }
    static double belowSlope(double u) { return kSkyCapBelowPower * std::pow(u, kSkyCapBelowPower - 1.0); }

    explicit RowMapping(const SkyTable& t) {
        if (t.bandElevation > 0.0 && t.bandShare > 0.0) {
            a = std::min(t.bandShare, 1.0);
            e = t.bandElevation;
            bandNorm = 1.0 / std::atan(0.5 * kPi / e);
        }
        if (t.shadowWidth > 0.0 && t.shadowShare > 0.0) {
            b = std::min(t.shadowShare, 1.0 - a);
            c = t.shadowElevation;
            w = t.shadowWidth;
            shadowLow = std::atan(-c / w);
            shadowNorm = 1.0 / (std::atan((0.5 * kPi - c) / w) - shadowLow);
        }
        if (skyTableColumnsWarped(t)) {
            d = std::min(skyCapRowShare(t.capStrength), 1.0 - a - b);
            cap = t.shadowElevation;
        }
        plain = (1.0 - a - b - d) / std::sqrt(0.5 * kPi);
    }
    bool quadratic() const { return a == 0.0 && b == 0.0 && d == 0.0; }
    double operator()(double x) const {
        const double el = x * x;
        double v = plain * x;
        if (a > 0.0) v += a * std::atan(el / e) * bandNorm;
        if (b > 0.0) v += b * (std::atan((el - c) / w) - shadowLow) * shadowNorm;
        if (d > 0.0 && el >= 2.0 * cap) {
            v += d;  // u = 1 above the cap: d (1 + cbrt 1) / 2, exactly
        } else if (d > 0.0) {
            const double u = std::min(std::abs(el - cap), cap) / cap;
            v += d * 0.5 * (el < cap ? 1.0 - belowMap(u) : 1.0 + std::cbrt(u));
        }
        return v;
    }
    double slope(double x) const {  // may be +inf (the cap's rows at el = c)
        const double el = x * x;
        double g = plain;
        if (d > 0.0 && el != cap && el < 2.0 * cap) {
            const double u = std::abs(el - cap) / cap;
            g += el < cap ? d * x * belowSlope(u) / cap : d * x / (3.0 * cap * std::cbrt(u * u));
        }
        if (a > 0.0) {
            const double r = el / e;
            g += a * bandNorm * 2.0 * x / (e * (1.0 + r * r));
        }
        if (b > 0.0) {
            const double r = (el - c) / w;
            g += b * shadowNorm * 2.0 * x / (w * (1.0 + r * r));
        }
        return g;
    }
};

/// The planet's shadow cylinder (radius Rg around the light's axis, behind
/// the planet) seen from the viewer of `air`, for a light `depression` [rad]
/// below the horizon.
struct ShadowCylinder {
    double r0, rt;      // the viewer's radius, the top's
    double depression;  // the light's [rad]
    double sinL, cosL;  // the light's elevation (negative)
    double c2;          // (r0 cosL)^2 - Rg^2: negative where the viewer is in the shadow
    ShadowCylinder(const AtmosphereParams& air, double lightDepression)
        : r0(air.planetRadius + std::clamp(air.viewerHeight, 0.0, air.atmosphereRadius - air.planetRadius)),
          rt(air.atmosphereRadius),
          depression(lightDepression),
          sinL(-std::sin(lightDepression)),
          cosL(std::cos(lightDepression)),
          c2((r0 * cosL - air.planetRadius) * (r0 * cosL + air.planetRadius)) {}
    /// Radius at which the view ray at elevation el and azimuth psi [rad]
    /// from the anti-light point leaves the cylinder: 2 rt for a ray along
    /// its axis, 0 for one that misses it. Without cancellation within a
    /// hair of the axis (planet_shadow.hpp), where the kink of a light just
    /// set lies.
    double exitRadius(double el, double psi) const {
        const double sinEl = std::sin(el), cosEl = std::cos(el);
        const double mu = sinEl * sinL - cosEl * cosL * std::cos(psi);  // cos(view, light)
        const double a2 = detail::oneMinusCosBetween(el, depression, psi) *
                          detail::oneMinusCosBetween(el, -depression, kPi - psi);
        const double b2 = r0 * (sinEl - sinL * mu);
        if (!(a2 > detail::kShadowAxisA2)) return 2.0 * rt;
        double lo = 0.0, s = 0.0;
        if (!detail::halfQuadraticRoots(a2, b2, c2, lo, s)) return 0.0;
        return std::sqrt(std::max(r0 * r0 + 2.0 * r0 * s * sinEl + s * s, 0.0));
    }
};

/// Where the increasing f crosses `goal` in [lo, hi], by bisection, stopped
/// once the bracket no longer changes (two neighbouring doubles): a few
/// dozen steps, where a fixed 100 ran on every solve of a light just below
/// the horizon.
template <class F>
double bisect(F&& f, double lo, double hi, double goal) {
    for (int it = 0; it < 100; ++it) {
        const double mid = 0.5 * (lo + hi), oldLo = lo, oldHi = hi;
        (f(mid) < goal ? lo : hi) = mid;
        if (lo == oldLo && hi == oldHi) break;
    }
    return 0.5 * (lo + hi);
}

/// For a light `depression` [rad] below the horizon, the elevation [rad] of
/// the kink of the earth's shadow straight opposite the light: the view ray
/// in the light's vertical plane that leaves the planet's shadow cylinder
/// exactly at the top of the atmosphere (below it the ray stays in the shadow
/// up to the top, above it the lit part grows from the top down). -1 where
/// there is none (a viewer above the shadow, an empty atmosphere).
double shadowKinkElevation(const AtmosphereParams& air, double depression) {
    if (!(air.planetRadius > 0.0) || !(air.atmosphereRadius > air.planetRadius) || !(depression > 0.0))
        return -1.0;
    const ShadowCylinder shadow(air, depression);
    if (!(shadow.c2 < 0.0)) return -1.0;  // the viewer is lit
    // The exit radius at elevation e opposite the light decreases in e above
    // the anti-light point (beyond the top where the ray never leaves the
    // shadow below it).
    auto exitRadius = [&](double e) { return shadow.exitRadius(e, 0.0); };
    const double lo = depression, hi = depression + 0.2;  // exit above the top at lo, below it at hi
    if (!(exitRadius(hi) < shadow.rt)) return -1.0;
    return bisect([&](double e) { return -exitRadius(e); }, lo, hi, -shadow.rt);
}

/// Azimuth [rad] from the anti-light point at which the onset of the lit
/// sky above the earth's shadow of a light `depression` [rad] below the
/// horizon lies at `elevation` [rad]: where the view ray at that elevation
/// leaves the planet's shadow cylinder exactly at the top of the atmosphere.
/// -1 where there is none.
double capAzimuth(const AtmosphereParams& air, double depression, double elevation) {
    const ShadowCylinder shadow(air, depression);
    // The exit radius falls as psi grows: the ray leaves the shadow sooner.
    auto exitRadius = [&](double psi) { return shadow.exitRadius(elevation, psi); };
    const double lo = 0.0, hi = 0.5 * kPi;
    if (!(exitRadius(lo) > shadow.rt) || exitRadius(hi) > shadow.rt) return -1.0;
    return bisect([&](double psi) { return -exitRadius(psi); }, lo, hi, -shadow.rt);
}

constexpr double kCapTopDeg = 0.5;  // the column warp at full strength up to this depression [deg]
constexpr double kCapEndDeg = 1.0;  // and none from this one

/// The column mapping of one row (sky_table_mapping.hpp, columns), in
/// half-columns x = 0..N/2 counted from the anti-light point and the
/// azimuth psi = 0..pi from it: piecewise linear through five knots (in
/// ln(1 + (psi^2 - psiC^2) / Y0), Y0 = (kSkyCapBandScale c)^2 +
/// (kSkyCapBandOnsetScale psiC)^2, between a0 and a0 + a1),
///   x:   0, a0,    a0 + a1,                 xE,  N/2
///   psi: 0, psiC,  sqrt((G psiC)^2 + D^2),  psiE, pi
/// where psiC = sqrt(max(c - el, 0) / k) is the onset of the lit sky around
/// the cap of the earth's shadow in this row, D = max(psiC(0) / 2, min(1
/// deg, kSkyCapBandPerKink c)) the band's width at the cap's top, G =
/// kSkyCapOnsetGrowth, psiE = min(2 (psiC(0) + max(psiC(0) / 2, 1 deg)),
/// 3 pi / 4), and (a0, a1, xE) = (3, 12, 28) / 128 of N,
/// the knots x rounded to whole columns: a knot inside a texel kinks the
/// mapping within it, where the bilinear filter is linear in the column
/// (for a light 0.009 deg down the band's end at x = 16.4 left the horizon
/// 4.5% low 7.75 deg from the anti-light point, and psiE at x = 29.4 8%
/// high at 8.25 deg, between texels exact to 0.3%).
/// Only psiC depends on the row, so every column keeps its place relative
/// to the onset from row to row. The band: at the cap's top (psiC = 0) the
/// height above the onset is k psi^2; the lit sky switches on ~10 c from
/// the anti-light point (as ~psi^5 for a light just set) and levels off
/// over ~100-1000 c, so the band is geometric in psi^2 beyond ~10 c. (For
/// a light 0.002 deg down (c ~ L) uniform in psi^2 put no column between
/// 0.03 and 0.3 deg: the pixel 60% low 0.1 deg from the anti-light point at
/// el = c; then uniform in s(y)^0.7, s(y) = y / (y + (150 c)^2), 1.7%, but
/// 3-15% at the cap's top of a light 0.0002-0.00002 deg down, sky.hpp.)
/// Below the top Y0 grows with psiC, and the band narrows with c below
/// 0.002 deg (kSkyCapBandPerKink), while psiE keeps its 1 deg floor
/// (narrowed with the band it left 4.8% on the horizon 2 deg from the
/// anti-light point of a light 0.0003 deg down).
/// Lower down the lit sky ramps up over a width that grows with psiC (the
/// level lines of the shadow's exit height fan out from the cap's top), so
/// the band widens with G psiC (G = 1.25, 1.5 and 2 tried: 2 is best at
/// -0.01 and -0.02 deg, SkyShadowOnset). The last segment, psiE .. pi, is
/// quadratic: psi = psiE + (pi - psiE) (a t + (1 - a) t^2), t = 0..1 along
/// it, a = kSkyCapFarSlope: its first columns lie at 0.2 of its mean
/// spacing, where the lit sky beyond the band still climbs steeply near the
/// horizon (a light 0.01 deg down: the radiance halves between 8.7 and 11
/// deg from the anti-light point, where linear columns 4.4 deg apart put the
/// pixel 16% high), its last (at the light's azimuth) 1.8 times it. The
/// segment before it is quadratic too (kSkyCapNearSlope): just below the
/// cap's top the lit sky beside the cap ramps up far beyond the band (at
/// 0.99 c from 0.07 to 1.5 deg from the anti-light point for a light
/// 0.0005 deg down), and linear columns 0.3 deg apart there left it 10%
/// low (its first columns lie at kSkyCapNearSlope = 0.25 of its mean). With the strength g < 1 each psi knot
/// is blended towards the uniform azimuth of its x, g psi + (1 - g) 2 pi x / N, and each a towards 1, 1 - g
/// (1 - a).
struct ColumnMapping {
    double x[5] = {0.0, 0.0, 0.0, 0.0, 0.0};
    double psi[5] = {0.0, 0.0, 0.0, 0.0, kPi};
    double farSlope = 1.0;   // a: the last segment's slope at psiE, relative to its mean
    double nearSlope = 1.0;  // the same for the segment before it, at the band's outer knot
    double bandScale = 1.0;  // Y0 of the band's ln(1 + y / Y0), y = psi^2 - psiC^2
    double bandLog = 0.0;    // ln(1 + y2 / Y0) at its outer knot, y2 = psi_2^2 - psiC^2
    bool uniform = true;

    ColumnMapping(const SkyTable& t, double elevation) {
        const double n = t.azimuthCount;
        const double k = t.capCurvature, g = std::clamp(t.capStrength, 0.0, 1.0);
        const double c = t.shadowElevation;
        if (!(k > 0.0) || !(g > 0.0) || !(c > 0.0) || !(n >= 4.0)) return;
        constexpr double kDeg = kPi / 180.0;
        const double foot = std::min(std::sqrt(c / k), 0.25 * kPi);  // psiC at the horizon
        const double wide = std::max(0.5 * foot, kSkyCapMinBandDeg * kDeg);
        const double band = std::max(0.5 * foot, std::min(kSkyCapMinBandDeg * kDeg, kSkyCapBandPerKink * c));
        const double end = std::min(2.0 * (foot + wide), 0.75 * kPi);
        const double onset = std::min(std::sqrt(std::max(c - std::max(elevation, 0.0), 0.0) / k), foot);
        bandScale = std::pow(kSkyCapBandScale * c, 2) + std::pow(kSkyCapBandOnsetScale * onset, 2);
        // On whole columns where that keeps each knot above the one before
        // it (tables under ~32 columns keep a knot that rounds onto it).
        const double share[3] = {kSkyCapInsideShare, kSkyCapInsideShare + kSkyCapOnsetShare,
                                 kSkyCapInsideShare + kSkyCapOnsetShare + kSkyCapNearShare};
        for (int m = 1; m < 4; ++m) {
            const double whole = std::round(share[m - 1] * n);
            x[m] = whole > x[m - 1] ? whole : share[m - 1] * n;
        }
        x[4] = 0.5 * n;
        // psiE lies at least half the band's outer knot beyond it: nearer,
        // the horizon 7-9 deg from the anti-light point of a light
        // 0.005-0.01 deg down is 2.0-2.4% off (SkyCapFoot).
        const double bandKnot = std::hypot(kSkyCapOnsetGrowth * onset, band);
        const double capPsi[5] = {0.0, onset, bandKnot, std::min(std::max(end, 1.5 * bandKnot), 0.75 * kPi),
                                  kPi};
        for (int m = 1; m < 4; ++m) psi[m] = g * capPsi[m] + (1.0 - g) * 2.0 * kPi * x[m] / n;
        farSlope = 1.0 - g * (1.0 - kSkyCapFarSlope);
        nearSlope = 1.0 - g * (1.0 - kSkyCapNearSlope);
        uniform = false;
        bandLog = std::log1p((psi[2] * psi[2] - psi[1] * psi[1]) / bandScale);
    }
    double halfColumn(double p) const {  // psi -> x
        if (!(p > 0.0)) return 0.0;      // the anti-light point (columns 0..a0 from it when psiC = 0)
        for (int m = 0; m < 4; ++m)
            if (p < psi[m + 1] || m == 3) {
                if (!(psi[m + 1] > psi[m])) return x[m + 1];
                const double q = std::min(p, kPi);
                const double u = m == 1 ? std::log1p((q * q - psi[1] * psi[1]) / bandScale) / bandLog
                                        : (q - psi[m]) / (psi[m + 1] - psi[m]);
                // The last two segments' u = a t + (1 - a) t^2, solved for t without cancellation.
                const double a = m == 3 ? farSlope : nearSlope;
                const double t = m >= 2 ? 2.0 * u / (a + std::sqrt(a * a + 4.0 * (1.0 - a) * u)) : u;
                return x[m] + (x[m + 1] - x[m]) * t;
            }
        return x[4];
    }
    double azimuthOf(double h) const {  // x -> psi
        for (int m = 0; m < 4; ++m)
            if (h < x[m + 1] || m == 3) {
                if (!(x[m + 1] > x[m])) return psi[m + 1];
                const double t = (std::min(h, x[4]) - x[m]) / (x[m + 1] - x[m]);
                const double a = m == 3 ? farSlope : nearSlope;
                double u = m >= 2 ? t * (a + (1.0 - a) * t) : t;
                if (m == 1)  // ln(1 + y / Y0) = u ln(1 + y2 / Y0), solved for y
                    return std::sqrt(psi[1] * psi[1] + bandScale * std::expm1(u * bandLog));
                return psi[m] + (psi[m + 1] - psi[m]) * u;
            }
        return kPi;
    }
};

}  // namespace

double skyTableColumn(const SkyTable& table, double relative, double elevation) {
    const int n = table.azimuthCount;
    if (n < 1) return 0.0;
    double phi = relative - 2.0 * kPi * std::floor(relative / (2.0 * kPi));
    if (!(phi >= 0.0) || !(phi < 2.0 * kPi)) phi = 0.0;  // NaN, or 2 pi by rounding
    const ColumnMapping map(table, elevation);
    if (map.uniform) return std::min(phi / (2.0 * kPi) * n, std::nextafter(double(n), 0.0));
    const double half = 0.5 * n;
    const double col = phi <= kPi ? half - map.halfColumn(kPi - phi) : half + map.halfColumn(phi - kPi);
    return std::clamp(col, 0.0, std::nextafter(double(n), 0.0));
}

void skyTableAzimuths(const SkyTable& table, double elevation, int count, double* out) {
    const int n = table.azimuthCount;
    const ColumnMapping map(table, elevation);
    const double half = 0.5 * n;
    for (int i = 0; i < count; ++i) {
        const double col = std::clamp(double(i), 0.0, double(std::max(n, 0)));
        out[i] = n < 1         ? 0.0
                 : map.uniform ? 2.0 * kPi * col / n
                 : col <= half ? kPi - map.azimuthOf(half - col)
                               : kPi + map.azimuthOf(col - half);
    }
}

double skyTableAzimuth(const SkyTable& table, double column, double elevation) {
    const int n = table.azimuthCount;
    if (n < 1) return 0.0;
    const double col = std::clamp(column, 0.0, double(n));
    const ColumnMapping map(table, elevation);
    if (map.uniform) return 2.0 * kPi * col / n;
    const double half = 0.5 * n;
    return col <= half ? kPi - map.azimuthOf(half - col) : kPi + map.azimuthOf(col - half);
}

// The row mapping for a light (sky_table_mapping.hpp). Where the rows go
// follows the light where it changes fastest: the earth's shadow opposite a
// set light is a band from the horizon to about its depression L above it,
// whose upper edge is a kink (where the shadow's exit reaches the top of the
// atmosphere) for a light just set and a broad ramp for a deep one. The
// numbers (band E = max(1.8 L^0.7, 1.2) deg with 70% of the rows, 15% of
// them within ~0.25 L of the kink, 5% from L = 6 deg) are fitted against the
// exact integral (tests/core/test_sky.cpp, SkyOffTexel, and a denser grid of
// the anti-light quarter: 700 directions per sun): with them the worst error
// of a 128 x 64 table is 0.8-1.6% for suns from -6 to 0 deg, against 3-49%
// with the quadratic rows. For a light 0-1 deg below the horizon the cap of
// the earth's shadow opposite it gets its own rows (crowded towards the
// kink below it and at the kink above it) and warped
// columns (the onset on one column in every row): 0.8-1.3% in a dense sweep
// of the anti-light quarter from -0.3 to -0.01 deg, from the horizon to 6
// deg up (SkyShadowOnset; 1.9% at -0.01 deg with probes within 3e-4 deg of
// the kink before the cap's saturating columns); for lights 0.005-0.0002
// deg down the cap's rows are doubled and below c logarithmic, 1.2-1.8%
// there on a dense grid just below the kink (sky.hpp).
namespace {

void setMappingParameters(SkyTable& table, const AtmosphereParams& air, const glm::dvec3& lightDirection) {
    constexpr double kDeg = kPi / 180.0;
    const glm::dvec3 l = normalizedOr(lightDirection, glm::dvec3(0.0, 1.0, 0.0));
    const double light = std::asin(std::clamp(l.y, -1.0, 1.0)) / kDeg;  // elevation [deg]
    table.bandElevation = table.bandShare = 0.0;
    table.shadowElevation = table.shadowWidth = table.shadowShare = 0.0;
    table.capCurvature = table.capStrength = 0.0;
    if (!(light < kMappingTopDeg)) return;
    // [deg]; below 18 deg (night) the mapping stays that of 18 deg.
    const double depression = std::clamp(-light, 0.0, kDeepestDeg);
    table.bandElevation = std::max(1.8 * std::pow(depression, 0.7), kBandFloorDeg) * kDeg;
    table.bandShare = 0.7 * std::min(1.0 - light / kMappingTopDeg, 1.0);
    if (depression > 0.0) {
        table.shadowElevation = 1.1 * depression * kDeg;
        // The onset above the kink narrows about as L^2 for a light just set
        // (a ray just above it leaves the shadow Rg L^2 / (2 (e - L)) from the
        // viewer): below 0.3 deg the rows' width narrows with it.
        table.shadowWidth = 0.25 * depression * std::min(depression / 0.3, 1.0) * kDeg;
        table.shadowShare = 0.15 - 0.1 * std::clamp((depression - 2.0) / 4.0, 0.0, 1.0);
        // In full from 0.01 deg: straight opposite a light just set these rows
        // are what resolves the lit sky's switch-on just above the kink (a
        // fade over 0.1 deg left 6.2% at -0.01 deg and 4.6% at -0.02 within
        // 3e-4 deg above it; now at most 1.9% and 1.8% over the whole sweep).
        table.shadowShare *= std::min(depression / kShadowFadeDeg, 1.0);
        // A row exactly on the kink of the shadow opposite the light: the
        // shadow rows centred there, and their share b adjusted so that the
        // kink's row is whole.
        const double kink = shadowKinkElevation(air, depression * kDeg);
        if (kink > 0.0 && table.elevationCount > 1) {
            table.shadowElevation = kink;
            // The cap of the earth's shadow around the anti-light point: its
            // onset el(psi) = c - k psi^2, k fitted where it crosses c / 2;
            // its rows (skyCapRowShare) come out of the band's.
            const double halfway = capAzimuth(air, depression * kDeg, 0.5 * kink);
            if (halfway > 0.0 && depression < kCapEndDeg) {
                table.capCurvature = 0.5 * kink / (halfway * halfway);
                table.capStrength =
                    std::clamp((kCapEndDeg - depression) / (kCapEndDeg - kCapTopDeg), 0.0, 1.0);
                table.bandShare -= skyCapRowShare(table.capStrength);
            }
            const double rows = table.elevationCount - 1;
            // The kink's row with shadow share b (the mapping only, no
            // texels copied); it grows with b (~b/2 of the rows lie below
            // the kink). Adjusting the band's width E instead (as before)
            // hardly moves the kink's row for a light less than ~0.015 deg
            // down, and elsewhere pulled E down to ~0.5 deg, which left the
            // rows 4-6 deg up 1-2 deg apart (2.9-3.3% there opposite a light
            // 0.03-0.3 deg down; now 1.0-1.5%).
            auto rowOfKink = [&](double b) {
                SkyTable t = {};
                t.azimuthCount = table.azimuthCount;
                t.elevationCount = table.elevationCount;
                t.bandElevation = table.bandElevation;
                t.bandShare = table.bandShare;
                t.shadowElevation = table.shadowElevation;
                t.shadowWidth = table.shadowWidth;
                t.shadowShare = b;
                t.capCurvature = table.capCurvature;
                t.capStrength = table.capStrength;
                return skyTableRow(t, kink);
            };
            double goal = std::round(rowOfKink(table.shadowShare));
            const double bLo = 0.0, bHi = table.shadowShare + 0.1;
            if (rowOfKink(bLo) > goal) goal += 1.0;
            if (goal > 0.0 && goal < rows && rowOfKink(bLo) <= goal && rowOfKink(bHi) >= goal)
                table.shadowShare = bisect(rowOfKink, bLo, bHi, goal);
        }
    }
}

}  // namespace

double skyTableRow(const SkyTable& table, double elevation) {
    const int h = table.elevationCount;
    if (h <= 1) return 0.0;
    const double el = std::clamp(elevation, 0.0, 0.5 * kPi);
    const RowMapping map(table);
    const double v = map.quadratic() ? std::sqrt(el / (0.5 * kPi)) : map(std::sqrt(el));
    return std::clamp((h - 1) * v, 0.0, double(h - 1));
}

namespace {

/// x = sqrt(el) of mapped position v in (0, 1) (map(x) = v) by Newton kept
/// inside the bracket [lo, hi] (bisection where a step would leave it),
/// starting at x; v(x) is increasing. Stops once map(x) is within a few
/// rounding errors of v (1e-15, v <= 1: the row within 1e-13 of its place,
/// the elevation within ~1e-14 rad), or once the bracket holds no double
/// between its ends (the cap's rows of a light 0.00002 deg down, where the
/// slope is ~4e6 and f cannot get below ~2e-13). Iterating on to f = 0
/// danced on the last bits for three more steps, a step that no longer
/// moved x counted as leaving the bracket and bisected it again, and a
/// relative bracket width of 1e-16 was never reached between neighbouring
/// doubles (100 steps and 200 bisections there): a light 0.5 deg down took
/// 9 steps and 1.6 bisections a row, now none (skyTableElevations at
/// -0.00002 deg: 447 -> 33 us).
double rowRoot(const RowMapping& map, double v, double lo, double hi, double x) {
    constexpr double kTolerance = 1e-15;
    auto closed = [&] { return !(std::nextafter(lo, hi) < hi); };
    for (int it = 0; it < 100; ++it) {
        const double f = map(x) - v;
        if (std::abs(f) <= kTolerance) return x;
        (f < 0.0 ? lo : hi) = x;
        if (closed()) return x;
        const double slope = map.slope(x);
        double next = slope > 0.0 && std::isfinite(slope) ? x - f / slope : 0.5 * (lo + hi);
        if (std::abs(next - x) <= 1e-16 * hi) {
            // Converged, or stalled where the slope is near infinite (the
            // cap's rows at el = c): bisect then.
            if (std::abs(f) <= 1e-13) return next;
            next = 0.5 * (lo + hi);
        }
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        x = next;
    }
    // Newton can crawl along the cap's steep rows: finish by bisection.
    for (int it = 0; it < 200 && std::abs(map(x) - v) > 1e-13 && !closed(); ++it) {
        x = 0.5 * (lo + hi);
        (map(x) < v ? lo : hi) = x;
    }
    return x;
}

}  // namespace

double skyTableElevation(const SkyTable& table, double row) {
    const int h = table.elevationCount;
    if (h <= 1) return 0.0;
    const double v = std::clamp(row / (h - 1), 0.0, 1.0);
    const RowMapping map(table);
    if (map.quadratic()) return 0.5 * kPi * v * v;
    if (v >= 1.0) return 0.5 * kPi;
    if (v <= 0.0) return 0.0;
    const double top = std::sqrt(0.5 * kPi);
    const double x = rowRoot(map, v, 0.0, top, v * top);
    return std::min(x * x, 0.5 * kPi);
}

void skyTableElevations(const SkyTable& table, int count, double* out) {
    const int h = table.elevationCount;
    const RowMapping map(table);
    if (h <= 1 || map.quadratic()) {
        for (int j = 0; j < count; ++j) out[j] = skyTableElevation(table, double(j));
        return;
    }
    const double top = std::sqrt(0.5 * kPi);
    double x1 = 0.0, x2 = 0.0, x3 = 0.0;  // x of the three rows before
    for (int j = 0; j < count; ++j) {
        const double v = std::clamp(double(j) / (h - 1), 0.0, 1.0);
        double x = v >= 1.0 ? top : 0.0;
        if (v > 0.0 && v < 1.0) {
            // The rows rise: the row before bounds it below. The first guess
            // is the parabola through the three rows before (the rows are
            // evenly spaced in v), which costs no evaluation of the mapping
            // (the tangent from the row before took two): 3.3-3.7
            // evaluations a row in all, 5.3 where the cap's rows bend (a
            // light 0-1 deg down), 7.4 at -0.00002 deg.
            const double guess = j >= 3 ? 3.0 * (x1 - x2) + x3 : (j == 2 ? 2.0 * x1 - x2 : v * top);
            x = rowRoot(map, v, x1, top, std::clamp(guess, x1, top));
        }
        out[j] = std::min(x * x, 0.5 * kPi);
        x3 = x2;
        x2 = x1;
        x1 = x;
    }
}

void setSkyTableMapping(SkyTable& table, const AtmosphereParams& air, const glm::dvec3& lightDirection) {
    setMappingParameters(table, air, lightDirection);
    // The coordinates every sampler reads (sky.hpp, "Table coordinates").
    const int w = std::max(table.azimuthCount, 0), h = std::max(table.elevationCount, 0);
    table.rowElevation.assign(std::size_t(h), 0.0);
    table.columnAzimuth.assign(std::size_t(w) * std::size_t(h), 0.0);
    if (h == 0 || w == 0) return;
    skyTableElevations(table, h, table.rowElevation.data());
    if (h > 1) table.rowElevation[std::size_t(h - 1)] = 0.5 * kPi;  // the zenith, exactly
    for (int j = 0; j < h; ++j) {
        double* row = table.columnAzimuth.data() + std::size_t(j) * std::size_t(w);
        skyTableAzimuths(table, table.rowElevation[std::size_t(j)], w, row);
        for (int i = 0; i < w; ++i) row[i] = std::clamp(row[i], 0.0, std::nextafter(2.0 * kPi, 0.0));
    }
}

}  // namespace aerial
