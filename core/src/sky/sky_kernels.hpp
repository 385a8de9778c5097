// sky_kernels.hpp — private: the hot loops of the sky solver
// (sky_kernels*.cpp), each over contiguous float arrays of one row, and the
// plain structs that carry their inputs. sky_solver_row.cpp prepares those
// inputs per row in double precision and calls these once per row.
//
// The kernels are compiled for x86-64-v4 (AVX-512), x86-64-v3 (AVX2 with
// FMA) and the baseline (target_clones, chosen at load time; no global
// -march needed). Their
// helpers live in sky_kernels_inline.hpp and the kernels' files, forced inline, so that each clone runs
// vector code throughout. A call costs one indirect jump per row.
#pragma once

#include <cstddef>
#include <cstdint>

namespace aerial::detail {

// 4-point Gauss-Legendre on [0, 1].
inline constexpr double kGaussT[4] = {0.0694318442029737, 0.3300094782075719, 0.6699905217924281,
                                      0.9305681557970263};
inline constexpr double kGaussW[4] = {0.1739274225687269, 0.3260725774312731, 0.3260725774312731,
                                      0.1739274225687269};

/// Density constants in the form the kernels use (float, 1/H or 0).
struct DensityConstants {
    float invRayleighH = 0.0f, rayleighOn = 0.0f;
    float invMieH = 0.0f, mieOn = 0.0f;
    float ozoneCenter = 0.0f, ozoneInvHalfWidth = 0.0f, ozoneOn = 0.0f;
};

struct DepthKernelArgs {
    int count;
    float planetRadius2;
    float planetRadius;
    DensityConstants density;
    const float* q;       // p^2 - Rg^2 per column (p: impact parameter)
    const float* len1;    // length of the descending piece (0 for rising rays)
    const float* start2;  // distance from the perigee where the rising piece starts
    const float* len2;    // length of the rising piece
    float* depthR;
    float* depthM;
    float* depthO;
};

/// Optical depths (column masses) of Rayleigh, Mie and ozone density along
/// `count` rays from one row of the optical-depth table: each piece is
/// mapped d = dense + len t^2 (dense end: the perigee or the start) and
/// integrated with 4-point Gauss-Legendre panels in t.
void depthKernel(const DepthKernelArgs& a);

struct NodeKernelArgs {
    int count;
    float viewerHeight;
    float r0;
    float twoR0Mu;  // 2 r0 mu_view
    DensityConstants density;
    const float* s;  // node distances from the viewer
    float* rayleigh;
    float* mie;
    float* ozone;
};

/// Densities at the view-ray quadrature nodes of one row.
void nodeKernel(const NodeKernelArgs& a);

/// Mean Rayleigh, Mie and ozone densities of segment i, from its 4
/// Gauss-Legendre node densities (times the segment's length: its column
/// masses; the callers multiply in their own order).
struct MeanDensity {
    double rayleigh, mie, ozone;
};
inline MeanDensity segmentMeanDensity(const float* rayleigh, const float* mie, const float* ozone, int i) {
    MeanDensity m{0.0, 0.0, 0.0};
    for (int g = 0; g < 4; ++g) {
        m.rayleigh += kGaussW[g] * rayleigh[4 * i + g];
        m.mie += kGaussW[g] * mie[4 * i + g];
        m.ozone += kGaussW[g] * ozone[4 * i + g];
    }
    return m;
}

/// The same for a ray cut at `crossing[0..segments]` (distances from its
/// start at height h0, radius r0, zenith cosine mu): the 4 Gauss-Legendre
/// nodes of each segment into s[4 segments], then nodeKernel.
void segmentNodeDensities(const double* crossing, int segments, double h0, double r0, double mu,
                          const DensityConstants& density, float* s, float* rayleigh, float* mie,
                          float* ozone);

/// Per-row transmittances of the layers: e^-tau, e^(-tau t_0), e^(-tau t_1).
void layerExpKernel(int n, const float* __restrict tau, float* __restrict layerT, float* __restrict nodeT0,
                    float* __restrict nodeT1);

/// cos(phi / 2), sin(phi / 2) and cos phi = (c - s)(c + s) (without
/// cancellation) of n azimuths phi in [0, pi] (clamped), cos phi also as
/// float: a row's own columns where the column mapping warps it. Within 2
/// ulp of std::cos and std::sin (their Taylor series on [0, pi/4], the
/// upper half mirrored about pi/4), and vectorised where libm's sincos
/// is not.
void halfAngleKernel(int n, const double* __restrict phi, double* __restrict cosHalf,
                     double* __restrict sinHalf, double* __restrict cosPhi, float* __restrict cosPhiF);

/// Where each column's view ray of a row lies in the planet's shadow
/// (sky_solver_row.cpp, solveRow): the cylinder of radius Rg around the light's
/// axis behind the planet, with 1 - mu^2 from the angles and the roots
/// without cancellation (planet_shadow.hpp); [in, out] along the ray, both
/// -1 where it has no shadow.
struct ShadowSpanArgs {
    int count = 0;
    const double* cosPhi = nullptr;  // per column: cos phi, cos(phi / 2), sin(phi / 2)
    const double* cosHalfPhi = nullptr;
    const double* sinHalfPhi = nullptr;
    double sinEl = 0.0, cosEl = 1.0;  // the row's view elevation
    double sinL = 0.0, cosL = 1.0;    // the light's
    double r0 = 0.0;                  // the viewer's radius [m]
    double viewLength = 0.0;          // to the top of the atmosphere [m]
    double towardsAnti = 0.0;         // sin((el + lambda) / 2), lambda the light's elevation
    double towardsLight = 0.0;        // sin((el - lambda) / 2)
    double cosCos = 0.0;              // cos el cos lambda
    double c2 = 0.0;                  // (r0 cosL)^2 - Rg^2
    double parallelLit = 0.0;         // a ray along the axis is lit where c2 exceeds this
    float* in = nullptr;
    float* out = nullptr;
};
void shadowSpanKernel(const ShadowSpanArgs& a);

/// The straight-on share of a row (skyKernel's acc 9..14: Rayleigh rgb,
/// Mie rgb, phase-less) into its multiple scattering (acc 6..8), times
/// `fade` and the phases of each column's angle to the light, mu = nuA +
/// nuB cos phi: rayleighPhaseOf and miePhaseOf (phase.hpp, what
/// rayleighPhase and miePhase compute; g clamped to +-0.999 by the
/// caller). Channels `stride` apart.
struct StraightOnArgs {
    int count = 0;
    int stride = 0;
    const double* cosPhi = nullptr;
    double nuA = 0.0, nuB = 0.0;
    double g = 0.0;
    double fade = 1.0;
    float* acc = nullptr;
};
void straightOnKernel(const StraightOnArgs& a);

/// spreadMultiple's stencil (sky_solver_row.cpp) for n columns at azimuths
/// phi [rad, 0..pi] from the light: u = phi (K - 1) / pi in units of the K
/// = kMsSkyColumns azimuths; Catmull-Rom through the azimuths k - 1 .. k + 2
/// around it, mirrored at 0 and K - 1. index and weight are [4][padded]
/// (the padding keeps what it holds).
void spreadStencilKernel(int n, const double* __restrict phi, int padded, int* __restrict index,
                         float* __restrict weight);

/// Per-layer constants of a sky row.
struct LayerConstants {
    float alpha, beta, horizonCos, angleScale;  // upper shell: light cosine alpha + beta cos(phi), table row
    float start, end;                           // layer extent along the view ray
    float p[6], q[6];                           // weight p + q t: R rgb, M rgb
    float msA[6], msB[6];  // multiple scattering: sigma_X T weights at a and b, R rgb, M rgb
    float straightP[6],
        straightQ[6];        // the straight-on share's weight (p + q t) (e^(f tau_M) - 1), see skyLayer
    float viewUp;            // the view ray's zenith cosine at the upper shell
    float curvature;         // tanh(lambda / 4) / 3, see curvatureFactor
    int stencilC, stencilD;  // the stencil's two shells besides the layer's own (curvatureFactor)
    float stencil[4];        // -2/3 (cubic at mid-layer - chord): weights of tau at shells a, b, C, D
};

/// A lookup table as pairs: entry a holds table[a] in its low 32 bits and
/// table[a + 1] (the last: itself) in its high 32 bits, so that linear
/// interpolation at u = a + f reads one 8-byte value per column instead of
/// two floats, with the same result. GCC does not use the gather
/// instructions for the kernels' lookups (its generic tuning; on this
/// machine's AMD EPYC they were 9% slower than what it does instead) but
/// loads each column's entries one by one, and one 8-byte load instead of
/// two 4-byte ones took a quarter off a lookup loop (skyShell's).
void tablePairs(const float* table, int count, std::uint64_t* pairs);

/// Floats per column of a shell record (skyShell: 10; shellPsi: 3 more;
/// the LUT column of shellPsi and shellAniso's scratch).
constexpr int kShellRecord = 15;
/// The second order's anisotropy is evaluated at every this many shells (skyKernel).
constexpr int kAnisoShellStride = 4;
/// Mie's last scattering at the view nodes (sky_multiple.hpp) is evaluated
/// at every second anisotropy shell, and left out where Mie's weight there
/// is under this share of the scattering's (high above the haze): |C / Psi|
/// came to 13 at most in the default air and 16 in hazy_sunset's, so what
/// is left out stays under 1% of that shell's multiple scattering.
constexpr float kViewMieFloor = 5e-4f;
/// Floats per shell of msShellWeights' output: the anisotropy's
/// K_q = W_R r2 + W_M m2 and K_d = W_M m1 (rgb each; shellAniso), Mie's view
/// weight W_M (rgb; shellViews), and a flag: 0 no anisotropy at this shell,
/// 1 the anisotropy, 2 the anisotropy and the views.
constexpr int kMsShellWeights = 10;
/// Shell records kept at a time: a layer's stencil spans four shells.
constexpr int kShellSlots = 4;
/// Multiple scattering is integrated along the view rays of this many
/// azimuths only, phi_k = pi k / (kMsSkyColumns - 1) from the light, and
/// interpolated between them into the table's columns (sky_solver_row.cpp,
/// spreadMultiple): it is smooth in azimuth (the light's zenith cosine at a
/// shell is alpha + beta cos(phi)), and this is its cost divided by ~5.
constexpr int kMsSkyColumns = 16;

struct SkyKernelArgs {
    int columns;  // the stride of the records and the accumulators (a multiple of 8)
    /// Columns whose single scattering is integrated, a multiple of 8 up to
    /// `columns`: those after it lie in the earth's shadow along the whole
    /// view ray (it would add +0 there; their accumulators stay 0).
    int litColumns;
    int layers;
    int angles;
    float knee;
    float alpha0, beta0, horizonCos0, angleScale0;  // the viewer's shell
    const float* cosPhi;                            // [columns]
    const float* msCosPhi;                          // [kMsSkyColumns] the multiple scattering's azimuths
    const float* shadowIn;                          // [columns]
    const float* shadowOut;                         // [columns]
    const LayerConstants* layer;                    // [layers]
    /// [layers] 0 where the earth's shadow overlaps the layer in every
    /// column (shadowIn, shadowOut; padding aside): its single scattering is
    /// 0 there, and the kernel skips it (its multiple scattering stays).
    const unsigned char* layerLit;
    /// [3][layers + 1][angles] the optical depth to the light as lookup
    /// pairs (tablePairs: each entry with the next one)
    const std::uint64_t* depthPairs;
    /// Multiple scattering: Psi_ms resampled at the shells, [3][layers + 1][psiCosines]
    /// (sky_multiple.hpp, column mapping msColumnOfCosine); null: single scattering only.
    const std::uint64_t* psi;  ///< as lookup pairs (tablePairs)
    int psiCosines;
    /// The second order's anisotropy (sky_multiple.hpp) resampled at the shells,
    /// [kMsAniso * 3][layers + 1][psiCosines] (D_u, D_s, B_0, B_u, B_s, B_us, each rgb);
    /// null: none (isotropic, or single scattering only).
    const float* aniso;
    /// What the series misses of Mie's last scattering of the second and third
    /// orders' field, C_v / Psi at the view nodes (sky_multiple.hpp),
    /// resampled at the shells, [layers + 1][kMsViews * 3][psiCosines]; null
    /// with aniso.
    const float* views;
    float viewUp0;   // the view ray's zenith cosine at the viewer (sin of the row's elevation)
    float nuA, nuB;  // the view ray's cosine to the light: nuA + nuB cos(phi)
    float rayleighBand2, mieBand1, mieBand2;  // MultipleScatteringLut's Legendre factors
    float mieIsotropicShare;                  // 1 - f_s: Mie's isotropic share of Psi (MultipleScatteringLut)
    bool straightOn;                          // sum the straight-on share (acc 9..14)
    /// Whether any shell of the row may have the light below its horizon in
    /// some column (its margin alpha + beta cos(phi) - horizonCos negative):
    /// false skips the roots and margins (curvatureFactor's first case), which
    /// then change nothing. Where it is true, per layer (layerShadow
    /// [layers]) whether a shell of its stencil may, and per shell
    /// (shellRoots [layers + 1]) whether a layer beside it may: the others
    /// skip them too.
    bool shadow;
    const unsigned char* layerShadow;
    const unsigned char* shellRoots;
    /// [layers + 1][kMsShellWeights] the multiple scattering's weights per shell (msShellWeights).
    const float* msWeights;
    float* anisoPoly;  // [9][psiCosines] scratch of shellAniso
    float* shells;     // [kShellSlots][kShellRecord][columns] scratch: the light at the shells in use
    /// [15][columns]: R rgb, M rgb, multiple rgb (with psi; its first
    /// kMsSkyColumns entries per channel only, at msCosPhi; columns >= kMsSkyColumns),
    /// and with straightOn the straight-on share of the single scattering, R rgb, M rgb
    /// (phase-less, as the first six: LayerConstants::straightP)
    float* acc;
};

/// The inner loop of a sky row over contiguous float arrays, no branch: the
/// light at every shell (table lookup), then each layer's closed-form
/// integral times its curvature factor and lit fraction, summed into acc
/// (Rayleigh rgb, Mie rgb), and with `psi` the multiple scattering of each
/// layer, msA Psi(a) + msB Psi(b) (multiple rgb; with `aniso`, each
/// scatterer's sigma_X A_X(v) added to its Psi, per shell) at the
/// kMsSkyColumns azimuths msCosPhi. `columns` is a multiple of 8 (no scalar tail), at least kMsSkyColumns.
void skyKernel(const SkyKernelArgs& a);

/// The weights with which each shell of a row adds the multiple
/// scattering's view dependence (kMsShellWeights per shell, `out`
/// [layers + 1][kMsShellWeights]): the layers on both sides weight a
/// shell's A_R, A_M by W_R, W_M (msB of the layer below, msA of the one
/// above); an evaluated shell (every kAnisoShellStride-th and the last)
/// also takes its share of the skipped shells' weights, linear between the
/// evaluated ones; the views the same at every second evaluated shell,
/// where Mie's weight is at least kViewMieFloor of the scattering's.
/// Once per row (`scratch` [6 (layers + 1)]).
void msShellWeights(const LayerConstants* layer, int layers, float rayleighBand2, float mieBand1,
                    float mieBand2, float* scratch, float* out);

/// The multiple scattering's spread from its kMsSkyColumns azimuths into
/// the table's columns (sky_solver_row.cpp, spreadMultiple): per column
/// out = exp(sum of 4 weights x ln value at 4 indices), Catmull-Rom in ln.
struct SpreadKernelArgs {
    int count;              // columns, a multiple of 8
    const int* index;       // [4][count] azimuths 0..kMsSkyColumns-1 (mirrored at the ends)
    const float* weight;    // [4][count]
    const float* logValue;  // [kMsSkyColumns] ln of the azimuths' values, in [-69, 60]
    float* out;             // [count]
};
void spreadKernel(const SpreadKernelArgs& a);

struct EdgePieceArgs {
    int count;   // lit pieces (shadowEdgeLayers)
    int stride;  // >= count: distance between the channels' output arrays
    // Per piece:
    const double* from;  // [count] its start and end along the view ray [m]
    const double* to;    // [count]
    const double* mu;    // [count] the view ray's cosine to the light
    const double* litQ;  // [count] the light's margin above the lit shell's horizon, mapped x / (x + knee)
    const int* layer;    // [count] its layer l (shells l and l + 1)
    /// [count] 1: the piece starts at the shadow's edge (its lit shell l + 1), 0: ends there (l)
    const int* edgeAtStart;
    // The row and the atmosphere:
    double tangent2;   // r0^2 - Rg^2 at the viewer
    double viewTwice;  // 2 r0 sin(elevation)
    double planetRadius2;
    double lightAtViewer;  // r0 sinL
    double knee, maxU;     // the optical-depth table's mapping (opticalDepthRow)
    int angles;
    const float* angleScale;          // [layers + 1]
    const std::uint64_t* depthPairs;  // [3][layers + 1][angles] (tablePairs)
    std::size_t plane;                // (layers + 1) angles
    // Per layer (shadowEdgeLayers):
    const float* layerKappa;     // [layers][6] the fall of the view's weight e^(-kappa t)
    const double* layerTangent;  // [layers][2] z = sqrt(r^2 - Rg^2) at the lower shell, 1 / (z_b - z_a) or 0
    const double* layerExtent;   // [layers][2] the layer's start along the view ray, 1 / its length
    // Scratch, [3][stride] each: the optical depth to the light at each
    // piece's start, middle and end; [stride]: its start and length in its
    // layer's t = (s - s0) / (s1 - s0); [6][stride] its kappa.
    float* tauStart;
    float* tauMid;
    float* tauEnd;
    float* t0;
    float* dt;
    float* kappa;
    float* out;  // [6][stride] out: the pieces' shape integrals, R rgb, M rgb
};

/// The lit pieces of the layers that an edge of the earth's shadow cuts
/// (sky_solver_shadow.cpp, shadowEdgeLayers). First, in double precision, the
/// optical depths to the light at each piece's start, middle and end: at the
/// shadow's edge the grazing rays' of the layer's shells, linear in the
/// tangent length; at the middle the table's rows of both shells at the
/// point's own margin, linear in the tangent length; at the lit shell the
/// table's. Then for each the integral over it of e^(-kappa t) e^(-tau(t)),
/// the view's weight's shape times the light's transmittance, as two halves
/// with tau linear in each (through tau at the piece's middle), in closed
/// form (exponentialMoments); `count` rounded up to 8 of them (those past
/// the real ones keep earlier, finite values; stride >= that).
void edgePieceKernel(const EdgePieceArgs& a);

struct MsCrossingArgs {
    int count;                                 // combinations of sun cosine and azimuth, a multiple of 16
    float alpha, beta;                         // sun zenith cosine at the crossing: alpha P + beta Q
    float horizonCos, angleScale, knee, maxU;  // the crossing's optical-depth row
    const float* p;                            // [count] mu_s
    const float* q;                            // [count] sqrt(1 - mu_s^2) cos(phi)
    const float* depth0;                       // the row, per channel [angles]
    const float* depth1;
    const float* depth2;
    float* record;  // [7][count]: tau rgb, T = e^-tau rgb, margin above the horizon cosine
};

/// The sun seen from one crossing of a multiple-scattering ray with a shell
/// (sky_multiple.cpp), for every combination: table lookup as in skyShell.
void msCrossingKernel(const MsCrossingArgs& a);

struct MsSourceArgs {
    int count;          // combinations, a multiple of 16
    float alpha, beta;  // sun zenith cosine at the crossing: alpha P + beta Q
    int cosines;        // the LUT's columns (kMsCosines)
    const float* p;     // [count] mu_s
    const float* q;     // [count] sqrt(1 - mu_s^2) cos(phi)
    const float* row;   // the LUT row of the crossing's shell, [cosines][3] (rgb interleaved)
    int* column;        // [count] out: the LUT column of each combination's sun cosine
    float* fraction;    // [count] out: the fraction towards the next column
    float* out;         // [3][count] out: the row interpolated there, per channel
};

/// The previous order's source J seen from one crossing of a
/// multiple-scattering ray, for every combination (sky_multiple.cpp,
/// buildOrderRow): the sun's zenith cosine mu there, clamped to [-1, 1], ->
/// LUT column u = (x + 1) / 2 (cosines - 1), x = sign(mu) sqrt|mu| ->
/// the row linear between columns.
void msSourceKernel(const MsSourceArgs& a);

struct MsSegmentArgs {
    int count;
    float weight[3];     // the segment's Rayleigh scattering column mass times T(start -> segment start), rgb
    float weightMie[3];  // ... Mie's
    float tauView[3];
    const float* a;  // crossing records (msCrossingKernel) at the segment's ends
    const float* b;
    float* acc;     // [3][count] Rayleigh
    float* accMie;  // [3][count] Mie
};

/// One segment between two crossings, for every combination: the integrals of
/// sigma_R T(start -> s) T(s -> sun) and of sigma_M T T over it, with the total optical depth
/// linear along the segment (closed form), times the lit fraction (the part
/// where the margin, interpolated linearly, is positive).
void msSegmentKernel(const MsSegmentArgs& a);

}  // namespace aerial::detail
