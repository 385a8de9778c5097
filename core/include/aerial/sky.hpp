// aerial/sky.hpp — the Nishita 1993 single-scattering sky with Hillaire 2020
// multiple scattering, solved on the CPU into a hemisphere table that the
// renderer (or a game) samples per pixel.
//
// Usage:
//   aerial::SkySolver solver;                       // 128 x 64 x 32, all cores
//   solver.solve(air, sunDirection);                // whole table, now
//   const aerial::SkyTable& sky = solver.table();
//   glm::dvec3 L = aerial::skyRadiance(sky, air.mieAnisotropy, viewDir, sunIlluminance);
//
//   // A game with a tight frame budget spreads the work over frames:
//   solver.beginSolve(air, sunDirection);
//   while (!solver.continueSolve(4)) { /* next frame */ }  // 4 rows per call
//   // table() keeps the last complete solve until the new one finishes.
//
// What the table holds (../shared/DESIGN.md, "Sky"): for each direction v of
// the upper hemisphere the two phase-less single-scattering integrals
//   I_R(v) = integral beta_R(h(s)) T(viewer -> x(s)) T(x(s) -> light) ds
//   I_M(v) = integral beta_M(h(s)) T(viewer -> x(s)) T(x(s) -> light) ds
// (RGB each, dimensionless) and the multiple scattering, its phases applied,
//   I_ms(v) = integral T(viewer -> x(s)) e^(f_s tau_M(s)) [(beta_R + (1 - f_s) beta_M)(h) Psi_ms(h, mu_s)
//                                         + beta_R(h) A_R(v) + beta_M(h) A_M(v)] ds
//           + integral T(viewer -> x(s)) (e^(f_s tau_M(s)) - 1) (P_R(mu) beta_R + P_M(mu) beta_M)(h)
//                                        T(x(s) -> light) ds
// (RGB, [1/sr]; h, mu_s and the A_X at x(s); tau_M(s) Mie's scattering depth
// from the viewer, f_s the straight-on share of Mie's peak, below), so that the radiance is
//   L(v) = E * (P_R(mu) I_R(v) + P_M(mu) I_M(v) + I_ms(v)),  mu = dot(v, light),
// with the phase functions applied per pixel. The single-scattering channels
// do not depend on the multiple scattering (they stay checkable against
// their exact integral, sky_reference.hpp).
//
// Multiple scattering (Hillaire 2020, "A Scalable and Production Ready Sky
// and Atmosphere Rendering Technique", section 5.5, eq. 5-10, with its
// orders 3 to 5 made explicit): Psi_ms(h, mu_s) is the radiance per unit sun
// illuminance [1/sr] that all orders >= 2 add at height h for a sun of
// zenith cosine mu_s, its isotropic part:
//   Psi_ms = J_2 + .. + J_5 + J_5 f_ms / (1 - f_ms),
// J_2 = Hillaire's L_2nd, the second order from 96 directions crowded at
// the horizon and towards the sun (so that the thin sunlit upper air that
// lights a deep twilight is resolved): single scattering of
// the sun along each ray to the ground or the top, plus the ground's
// Lambertian bounce with AtmosphereParams::groundAlbedo. J_3 .. J_5 are
// the next orders, each integrated from the one before through the
// atmosphere along the same directions, with the ground's reflection of its
// light (and J_3 of the single-scattered skylight); f_ms (the transfer of unit isotropic
// in-scattering) gives the geometric tail of the rest (details:
// core/src/sky/sky_multiple.hpp; why the orders 3 to 5 are explicit:
// docs/sky_table_notes.md). The second order
// has the real phases: Rayleigh's and Mie's at the first scattering
// (averaged over each direction's quadrature cell), and at the last, towards
// the viewer, the view-dependent remainder A_X(v) = integral (P_X(omega.v) -
// 1/(4 pi)) L_1(omega) d omega of each scatterer X, from the dipole and
// quadrupole moments of the once-scattered light L_1 at each height and sun
// cosine (Legendre series of the phases to l = 2: exact for Rayleigh; for
// Mie, delta-M: the forward peak's share g_3 as light going straight on and
// the rest to l = 2; of that share, f_s, the phase within 6 deg of straight on (0.12 at
// g = 0.8), is carried exactly along the view ray, the e^(f_s tau_M) above,
// and the remainder read through the moments' Fejer window; sky_multiple.hpp,
// "Mie's truncation"). What that series still misses of Mie's last
// scattering of the second and third orders' field (in twilight a band of
// sunlit air above the horizon towards the sun, which Mie's peak sends on
// towards the viewer) is kept by quadrature over the 96 directions at 74 view
// directions per height and sun cosine and interpolated between them along
// each view ray (sky_multiple.hpp, "Mie's last scattering"). The third order's field L_2
// adds its moments the same way (and the later orders theirs, as L_2's times
// the tail's 1 / (1 - f_ms)); the sources of the third and later orders stay
// isotropic. The LUT (MultipleScatteringTable) has 25 heights (the shells of
// 24 equal-mass layers from the ground to the top) x 64 sun cosines (mu =
// sign(x) x^2, x uniform in [-1, 1]: dense near the horizon). It depends
// only on the atmosphere and is cached with the optical-depth table. Along a
// view ray it is taken at each shell (height of the shell, the sun's zenith
// cosine where the ray crosses it; geometric between the LUT's sun-cosine
// columns, as Psi falls about exponentially with the sun's depression in
// twilight), linear within a layer, times the layer's exact integral of
// beta_X T(viewer -> s). That integral is done for 16 azimuths from the
// light (0, 12, ... 180 deg) and spread into the table's columns by
// Catmull-Rom in ln I_ms (smooth in azimuth: the sun's cosine at a shell is
// alpha + beta cos(phi)), within 0.12% of the pixel of integrating every
// column.
//
// Table coordinates (what every sampler reads): texel (i, j) holds the
// sky in the direction at elevation SkyTable::rowElevation[j] and azimuth
// SkyTable::columnAzimuth[j * azimuthCount + i] from the light's. Rows
// rise from the horizon (row 0, elevation 0) to the zenith (the last row,
// pi/2); each row's columns run from the light's azimuth (column 0) round
// towards east, and columns i and azimuthCount - i mirror each other about
// the light's vertical plane (single scattering is symmetric about it).
// Where they lie follows the light (setSkyTableMapping): rows crowded at the
// horizon, more so around the earth's shadow of a low or set light, and for
// a light 0-1 deg below the horizon the columns of each row crowded around
// the cap of the earth's shadow opposite it; with 128 x 64 texels the table
// is within 2% of the exact single-scattering integral relative to the
// pixel (floored at 1% of the brightest sky) in every direction
// tests/core/test_sky.cpp probes, off the texel centres too, for lights
// from -6 to 90 deg, and within 1.6% in dense sweeps around the earth's
// shadow of lights 0.0002-0.3 deg down (2.1% at 0.00002 deg, where the
// shadow's cap is 1/2400 of a pixel tall; docs/sky_table_notes.md). A
// sampler (sampleSkyTable, the renderer's sky pass, a game reading a bake)
// takes the two rows j, j + 1 around the view's elevation el with the
// upper one's weight t = f(x; m_j, m_j+1), x = (el - el_j) / (el_j+1 -
// el_j), f the monotone cubic (Fritsch and Carlson 1980)
//   f(x; m0, m1) = (x^3 - 2 x^2 + x) m0 + (3 x^2 - 2 x^3) + (x^3 - x^2) m1,
// with the slopes at the rows m_j = 2 (el_j+1 - el_j) / (el_j+1 - el_j-1),
// m_j+1 = 2 (el_j+1 - el_j) / (el_j+2 - el_j) (1 at the first and the last
// row), so that it follows how the rows' spacing changes; blends each
// column's azimuth between the two rows with t, b_i = (1 - t) phi_i,j +
// t phi_i,j+1 (wrapping: b_-1 = b_W-1 - 2 pi, b_W = 2 pi, b_W+1 = b_1 +
// 2 pi); takes the two columns i, i + 1 with b_i <= phi < b_i+1 and the
// second one's weight s = f(y; m_i, m_i+1) in the same way, y = (phi - b_i)
// / (b_i+1 - b_i) (s = y between uniform columns); and blends the four
// texels bilinearly with s and t. A column warped around the earth's
// shadow keeps its place relative to the shadow's edge from row to row, so
// blending along it follows the edge. Directions below the horizon use row 0. The RGB of texel (i, j) is
// at index (j * azimuthCount + i) * 3.
//
// Horizon average (SkyTable::horizonRayleigh / horizonMie / horizonMultiple): row 0 only
// (elevation exactly 0), all azimuthCount columns with equal weight
// 1 / azimuthCount, i.e. the azimuthal mean of the horizon ring (with warped
// columns, the mean of row 0's interpolant over 8 azimuths per column).
#pragma once

#include <aerial/atmosphere.hpp>

#include <glm/vec3.hpp>

#include <cmath>
#include <memory>
#include <vector>

namespace aerial {

/// How the solver is built. Zero values mean defaults.
struct SkySolverDesc {
    /// Table columns (relative azimuth), 4..limits::kMaxSkyAzimuthCount (4096).
    /// Every size here is clamped into its range (aerial/limits.hpp);
    /// SkySolver::desc() reports the sizes used.
    int azimuthCount = 128;
    int elevationCount = 64;  ///< table rows (elevation 0..90 deg), 2..kMaxSkyElevationCount (2048)
    /// Layers along each view ray, 2..kMaxSkyLayerCount (1024): spherical shells between the
    /// viewer and the top holding equal mass of the mixed profile
    /// (exp(-h/H_R) and exp(-h/H_M) a quarter each, uniform in height half),
    /// so the 8 km Rayleigh and 1.2 km Mie scale heights and the upper air
    /// (the earth shadow of a set sun) are resolved. With 32 every compared
    /// texel, horizon rows included, is within 2% of the brute-force
    /// reference for suns from -5 to 90 deg (tests/core/test_sky.cpp prints
    /// the error for 16..96 layers), and so are the directions between the
    /// texels for suns from -6 to 90 deg (with the coordinates above).
    int layerCount = 32;
    /// Optical-depth table rows (height): the table has exactly one row per
    /// shell (layerCount + 1, no interpolation in height); the value given is
    /// ignored and desc() reports the one used.
    int opticalDepthHeights = 0;
    /// Optical-depth table columns: the light's zenith cosine from the
    /// geometric horizon at that height to 1, half of them within 0.05 of the
    /// horizon; 0 = 128, 8..kMaxOpticalDepthAngles (4096).
    int opticalDepthAngles = 0;
    int threadCount = 0;  ///< threads incl. the caller; 0 = all hardware threads, 1 = caller only
    /// True: no multiple scattering (SkyTable::multiple stays 0, no LUT is
    /// built); for comparisons and benchmarks. Default false.
    bool singleScatteringOnly = false;
    /// True: the multiple-scattering LUT with Hillaire's isotropic phases
    /// (no phase at the first scattering, no view dependence of the second
    /// order); for validation against a path tracer with isotropic phases.
    /// Default false: the real phases (sky.hpp, "Multiple scattering").
    bool isotropicMultipleScattering = false;
    /// True: every row integrates its multiple scattering along its view
    /// rays; for comparisons and benchmarks. Default false: where the rows lie
    /// less than 6 deg apart, every second row takes it from its neighbours
    /// (a cubic in elevation; sky_solver.cpp, "Multiple scattering between
    /// rows"), which moves the pixel by under 0.25%.
    bool multipleScatteringEveryRow = false;
    /// The multiple-scattering LUT is kept while the atmosphere's heights
    /// (radii, viewer height, scale heights, ozone profile) stay the same
    /// and its coefficients drift so little from those the LUT was built
    /// for that the sky moves by at most this fraction of the pixel (floored
    /// at 1% of the brightest sky; estimated per coefficient,
    /// sky_solver_atmosphere.cpp):
    /// a keyed haze then rebuilds the LUT (~9 ms on two threads) every few
    /// tenths of a percent of its change instead of at every evaluation. The
    /// single scattering is always exact. 0: the LUT is rebuilt on any
    /// change. Clamped to 0..0.05; default 0.0025.
    double multipleScatteringTolerance = 0.0025;
};

/// The multiple-scattering LUT Psi_ms (Hillaire 2020, eq. 10) of the cached
/// atmosphere: radiance per unit sun illuminance [1/sr] added by all
/// scattering orders >= 2 at a height for a sun zenith cosine.
struct MultipleScatteringTable {
    int heightCount = 0;          ///< rows
    int cosineCount = 0;          ///< columns
    std::vector<double> heights;  ///< [heightCount] height of each row above the ground [m]
    std::vector<double> cosines;  ///< [cosineCount] the sun's zenith cosine of each column
    std::vector<float> psi;       ///< RGB at (row * cosineCount + column) * 3
};

/// The solved hemisphere table for one light (sun or moon).
struct SkyTable {
    int azimuthCount = 0;
    int elevationCount = 0;
    std::vector<float> rayleigh;  ///< I_R, RGB per texel (see "Table coordinates" above)
    std::vector<float> mie;       ///< I_M, RGB per texel
    std::vector<float> multiple;  ///< I_ms [1/sr], RGB per texel (phases applied: none to apply)
    /// Average of the horizon row(s): the colour of far fog is
    /// E * (P_R(mu) horizonRayleigh + P_M(mu) horizonMie + horizonMultiple).
    glm::dvec3 horizonRayleigh{0.0};
    glm::dvec3 horizonMie{0.0};
    glm::dvec3 horizonMultiple{0.0};
    /// The light direction (unit, from the scene) the table was solved for.
    glm::dvec3 lightDirection{0.0, 1.0, 0.0};
    /// Azimuth of the light [rad], from north (-Z) towards east (+X).
    double lightAzimuth = 0.0;
    /// Where the texels lie (see "Table coordinates" above), set with the
    /// mapping by setSkyTableMapping: the elevation [rad] of each row
    /// (elevationCount, increasing from 0 to pi/2) and the azimuth [rad, 0..2
    /// pi) from the light's of each texel (azimuthCount per row, row after
    /// row; non-decreasing along a row: columns that meet at the anti-light
    /// point hold the same direction).
    std::vector<double> rowElevation;
    std::vector<double> columnAzimuth;
    /// The parameters the coordinates were made from (setSkyTableMapping;
    /// core/src/sky/sky_table_mapping.hpp): the rows' band at the horizon and
    /// at the earth's shadow. All 0 (the default, and any light above 1 deg):
    /// the plain rows el_j = pi/2 (j / (H - 1))^2.
    double bandElevation = 0.0;    ///< E [rad], > 0 where bandShare > 0
    double bandShare = 0.0;        ///< a, 0..1: share of the rows in the horizon band
    double shadowElevation = 0.0;  ///< c [rad]: centre of the rows at the earth's shadow
    double shadowWidth = 0.0;      ///< w [rad], > 0 where shadowShare > 0
    double shadowShare = 0.0;      ///< b, 0..1 - a: share of the rows at the earth's shadow
    /// The columns' warp: k [1/rad] of the cap of the earth's shadow, whose
    /// onset lies at el = c - k psi^2 (psi the azimuth from the anti-light
    /// point), and the warp's strength g (0..1). Both 0: columns uniform in
    /// azimuth, 2 pi i / azimuthCount.
    double capCurvature = 0.0;
    double capStrength = 0.0;
    /// Bumped on every completed solve.
    unsigned long long generation = 0;
};

/// Phase-less integrals in one direction, bilinearly interpolated.
struct SkySample {
    glm::dvec3 rayleigh{0.0};
    glm::dvec3 mie{0.0};
    glm::dvec3 multiple{0.0};  ///< 0 where the table has no multiple channel
};

/// Sets where the texels of `table` lie for a light direction and
/// atmosphere (the planet, the top and the viewer's height place the earth's
/// shadow), as SkySolver does for every solve: the mapping's parameters
/// (bandElevation .. capStrength) and the coordinates made from them
/// (rowElevation, columnAzimuth; "Table coordinates" above). Needs
/// table.azimuthCount and table.elevationCount.
void setSkyTableMapping(SkyTable& table, const AtmosphereParams& air, const glm::dvec3& lightDirection);

/// Whether the table's columns are warped (else uniform in azimuth in every row).
inline bool skyTableColumnsWarped(const SkyTable& table) {
    return table.capCurvature > 0.0 && table.capStrength > 0.0 && table.shadowElevation > 0.0 &&
           table.azimuthCount >= 4;
}

/// Table lookup for a view direction (world space; normalised here): the
/// bilinear sample through the table's coordinates ("Table coordinates"
/// above). Zeros for a table without texels or coordinates.
SkySample sampleSkyTable(const SkyTable& table, const glm::dvec3& viewDirection);

/// Radiance [same unit as illuminance / sr] in a view direction: the table
/// sample with both phase functions applied for that direction, plus the
/// multiple scattering: E (P_R I_R + P_M I_M + I_ms).
glm::dvec3 skyRadiance(const SkyTable& table, double mieAnisotropy, const glm::dvec3& viewDirection,
                       const glm::dvec3& illuminance);

/// The first two zenith-cosine moments of the sky's radiance over the upper
/// hemisphere: first = E integral of (P_R I_R + P_M I_M + I_ms) v.y d omega
/// (skyIrradiance), second = the same with v.y^2; one pass of the midpoint
/// rule below for every weight linear in v.y (a first + b second).
struct SkyCosineMoments {
    glm::dvec3 first{0.0};
    glm::dvec3 second{0.0};
};
SkyCosineMoments skyCosineMoments(const SkyTable& table, double mieAnisotropy, const glm::dvec3& illuminance);

/// Cosine-weighted irradiance of the sky on an upward surface [illuminance
/// unit]: E integral over the upper hemisphere of (P_R I_R + P_M I_M + I_ms)
/// v.y d omega, by the midpoint rule on 64 azimuths x 16 elevations of
/// skyRadiance. The clear sky's share of a scene's ambient light.
glm::dvec3 skyIrradiance(const SkyTable& table, double mieAnisotropy, const glm::dvec3& illuminance);
/// The same with a weight linear in the zenith cosine: E integral of (P_R I_R
/// + P_M I_M + I_ms) v.y (a + b v.y) d omega. a = 1, b = 0 is skyIrradiance;
/// a = 1/2, b = 3/4 is the sky's light as a thick cloud deck passes it on
/// (the Eddington beam transmission's angular factor, overcastLight).
glm::dvec3 skyIrradiance(const SkyTable& table, double mieAnisotropy, const glm::dvec3& illuminance, double a,
                         double b);

/// The sky behind far fog seen in a unit view direction v, phase-less: the
/// table's horizon row (row 0) at v's azimuth, blended with the horizon
/// averages by v's elevation,
///   H(v) = (1 - s) average + s row0(azimuth of v),  s = |v.xz| = cos(elevation),
/// so fog towards the horizon matches the sky right behind it and fog seen
/// steeply (lit from all around) takes the azimuthal mean. At twilight the
/// horizon ring varies by 100x or more in azimuth (the glow towards the sun
/// against the earth's shadow), which the mean alone would spread over every
/// fog. A table without rows gives the averages alone. A table of one row
/// (skyHorizonRow) is enough.
SkySample horizonSkySample(const SkyTable& table, const glm::dvec3& viewDirection);

/// The horizon row of `table` (row 0, all columns) as a table of one row,
/// with the light's direction and azimuth and the horizon averages: what
/// horizonSkySample needs (FogLight::horizonRow).
SkyTable skyHorizonRow(const SkyTable& table);

/// Colour of far fog seen in a view direction: horizonSkySample with the
/// per-direction phase functions, E (P_R H_R(v) + P_M H_M(v) + H_ms(v)).
glm::dvec3 horizonFogRadiance(const SkyTable& table, double mieAnisotropy, const glm::dvec3& viewDirection,
                              const glm::dvec3& illuminance);

/// The Nishita 1993 solver: a 2D optical-depth table (height x light zenith
/// angle, Rayleigh, Mie and ozone) and integration over exponentially
/// distributed layers along each view ray, plus Hillaire 2020 multiple
/// scattering with an explicit third order and the phases in the second (the
/// Psi_ms LUT, built with the optical-depth table). Multithreaded (threads made once,
/// in the constructor); allocates nothing per solve. Single-threaded,
/// multi-threaded and amortised solves give bit-identical tables. The
/// optical-depth table and the Psi_ms LUT are kept while the AtmosphereParams stay bitwise equal,
/// so a moving sun only re-solves the hemisphere; the LUT alone is also kept while the
/// atmosphere drifts within SkySolverDesc::multipleScatteringTolerance (a keyed haze), so
/// its result then depends on the atmosphere the LUT was built for (at most that far off;
/// tolerance 0 for exact results); and they are shared between solvers in
/// the process (the last four atmospheres built, by any solver with the same layer count,
/// optical-depth angles and multiple-scattering settings), so the moon's solver adopts
/// what the sun's built for the same air instead of building it again (bit-identical;
/// a solver adopts a kept LUT only within its own tolerance). Earth shadow: where
/// the ray from a point to the light hits the planet, that point is unlit (the transmittance to the light is
/// 0), also for a light below the horizon.
class SkySolver {
public:
    explicit SkySolver(const SkySolverDesc& desc = {});
    ~SkySolver();
    SkySolver(const SkySolver&) = delete;
    SkySolver& operator=(const SkySolver&) = delete;

    /// Solves the whole table for these parameters and light direction, and
    /// publishes it. Abandons an amortised solve in progress.
    void solve(const AtmosphereParams& air, const glm::dvec3& lightDirection);

    /// Starts an amortised solve; nothing is computed yet. The result is
    /// bit-identical to solve() with the same arguments.
    void beginSolve(const AtmosphereParams& air, const glm::dvec3& lightDirection);
    /// Solves up to `rows` more rows. Where the atmosphere changed, its
    /// tables come first and count as rows too: the optical depths one step
    /// and, where the multiple-scattering LUT is rebuilt (not kept,
    /// multipleScatteringTolerance), 21 more (its orders in 20, its
    /// resampling), then one to share the tables with other solvers.
    /// Returns true when the new table is complete and published through
    /// table().
    bool continueSolve(int rows);
    /// True while an amortised solve is in progress.
    bool solving() const;

    /// Forgets the cached optical-depth table and Psi_ms LUT, so the next solve
    /// rebuilds them even if the AtmosphereParams are bitwise unchanged and
    /// another solver has built them (benchmarks, tests).
    void invalidateCache();

    /// A copy of the Psi_ms LUT in use: built for the last atmosphere, or
    /// kept from an earlier one (multipleScatteringTolerance); empty before
    /// the first solve and with singleScatteringOnly.
    MultipleScatteringTable multipleScatteringTable() const;

    /// The last completed table (zeros, generation 0, before the first).
    const SkyTable& table() const;
    /// The description with defaults resolved.
    const SkySolverDesc& desc() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace aerial
