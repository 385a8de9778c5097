// sky_solver_impl.hpp — private: the state of one SkySolver (sky_solver.cpp
// documents the solve), shared by the solver's files.
#pragma once

#include "base/worker_pool.hpp"
#include "sky_depth.hpp"
#include "sky_kernels.hpp"
#include "sky_layers.hpp"
#include "sky_multiple.hpp"

#include <aerial/sky.hpp>

#include <atomic>
#include <memory>
#include <optional>
#include <vector>

namespace aerial {

namespace detail {

/// (1 - e^-tau) / tau, the mean transmittance across a layer of optical
/// depth tau >= 0 given its transmittance e^-tau, by its series where the
/// quotient would cancel.
inline double layerShape(double tau, double transmittance) {
    return tau < 1e-2 ? 1.0 - tau * (0.5 - tau * (1.0 / 6.0 - tau / 24.0)) : (1.0 - transmittance) / tau;
}

}  // namespace detail

struct SkySolver::Impl {
    struct Scratch {
        // view rows
        std::vector<double> crossing;                           // [layers + 1]
        std::vector<float> nodeS, nodeR, nodeM, nodeO;          // [4 layers]
        std::vector<detail::LayerConstants> layer;              // [layers]
        std::vector<double> mass;                               // [3 layers]: R, M, O column masses
        std::vector<float> layerDepth, layerT, nodeT0, nodeT1;  // [3 layers]
        std::vector<float> shells;                              // [kShellSlots][kShellRecord][padded columns]
        std::vector<float> shadowIn, shadowOut;                 // [padded columns]
        std::vector<float> acc;                                 // [9 padded columns]
        std::vector<float> anisoPoly;                           // [9][kMsCosines] shellAniso's scratch
        std::vector<float> msWeights;         // [layers + 1][kMsShellWeights] (msShellWeights)
        std::vector<float> msWeightScratch;   // [layers + 1][6]
        std::vector<unsigned char> layerLit;  // [layers] (SkyKernelArgs::layerLit)
        std::vector<unsigned char> layerShadow, shellShadow,
            shellRoots;  // [layers], [layers + 1] (SkyKernelArgs)
        // Lit pieces of the layers cut by a shadow edge (shadowEdgeLayers), at most 2 per column.
        std::vector<float> edgeCrossing;                          // [layers + 1]
        std::vector<float> edgeTauStart, edgeTauMid, edgeTauEnd;  // [3][2 padded columns]
        std::vector<float> edgeT0, edgeDt;                        // [2 padded columns]
        std::vector<float> edgeKappa, edgeOut;                    // [6][2 padded columns]
        // Per layer of the row, once a piece needs them: the view's weight's
        // fall kappa [layers][6] (R rgb, M rgb) and its weights
        // W kappa / (1 - e^-kappa) [layers][12] (then the straight-on share's).
        std::vector<float> edgeLayerKappa, edgeLayerWeight;
        // [layers][2]: z at the lower shell and 1 / (z_b - z_a); the layer's
        // start along the view ray and 1 / its length.
        std::vector<double> edgeLayerTangent, edgeLayerExtent;
        std::vector<unsigned char> edgeLayerReady;  // [layers]
        std::vector<int> edgeColumn, edgeLayer;     // [2 padded columns] each piece's column and layer
        std::vector<int> pieceAtStart;  // [2 padded columns] and the rest of edgePieceKernel's inputs
        std::vector<double> pieceFrom, pieceTo, pieceMu, pieceLitQ;
        detail::DepthRowScratch depthRow;  // optical-depth rows
        std::vector<float> depthOut;       // [3][angles] a row of the table before tablePairs
        // The row's column azimuths (rowColumns): the shared uniform ones, or
        // this row's own where the column mapping warps it.
        std::vector<double> rowPhi, rowCosPhi;             // [columns]
        std::vector<double> rowCosHalfPhi, rowSinHalfPhi;  // [columns] cos and sin of phi / 2
        std::vector<float> rowCosPhiF;                     // [padded columns]
        std::vector<int> rowSpreadIndex;                   // [4][padded columns]
        std::vector<float> rowSpreadWeight;                // [4][padded columns]
        const double* phi = nullptr;                       // [columns] azimuth of each column from the light
        const double* cosPhi = nullptr;                    // [columns]
        const double* cosHalfPhi = nullptr;                // [columns] cos(phi / 2) (planet_shadow.hpp)
        const double* sinHalfPhi = nullptr;                // [columns] sin(phi / 2)
        const float* cosPhiF = nullptr;                    // [padded columns]
        const int* spreadIndex = nullptr;                  // [4][padded columns]
        const float* spreadWeight = nullptr;               // [4][padded columns]
        // The row's distinct columns (rowColumns: a warped row's last ones
        // may all lie at the anti-light point, copies of the first there) and
        // that count rounded up to 8, the stride of the row's accumulators
        // and shell records.
        int rowColumnCount = 0;
        int rowStride = 0;
    };

    SkySolverDesc desc;
    int azimuthCount = 0, elevationCount = 0, layers = 0, angles = 0, columns = 0;
    int paddedColumns = 0;  // columns rounded up to 8: no scalar tail on AVX2 (a vector epilogue on AVX-512)

    // Atmosphere-dependent state (the optical-depth table and the layers).
    bool cacheValid = false;
    AtmosphereParams cachedAir;
    AtmosphereParams rawAir;                    // parameters of the solve in progress, as given
    AtmosphereParams air;                       // the same, sanitized
    std::vector<double> shellHeight;            // [layers + 1], shellHeight[0] = viewer height
    std::vector<float> horizonCos, angleScale;  // [layers + 1]
    std::vector<double> horizonCosD;            // [layers + 1]
    std::vector<float> layerCurvature;          // [layers] tanh(lambda / 4) / 3, see curvatureFactor
    std::vector<std::uint64_t> depthPairs;      // [3][layers + 1][angles] as lookup pairs (tablePairs)
    detail::DensityConstants density;
    // Multiple scattering (sky_multiple.hpp): the LUT and Psi_ms at the shells.
    bool multiple = true;
    detail::MultipleScatteringLut ms;
    std::vector<std::uint64_t> psiPairs;  // [3][layers + 1][kMsCosines] as lookup pairs (tablePairs)
    // [3][layers + 1][kMsCosines] resampleShell's output before tablePairs
    // (only its shell's part is read, just after it is written; not shared).
    std::vector<float> psiShell;
    std::vector<float> anisoShell;  // [kMsAniso * 3][layers + 1][kMsCosines]
    std::vector<float> viewShell;   // [layers + 1][kMsViews * 3][kMsCosines]
    // The (sanitized) atmosphere the LUT and the three above were built
    // for, which a drifting atmosphere may reuse (sky_solver_atmosphere.cpp,
    // "Multiple scattering in a drifting atmosphere").
    bool msValid = false;
    bool msPending = false;  // the running rebuild builds the LUT too
    AtmosphereParams msAir;

    // Light-dependent state.
    glm::dvec3 light{0.0, 1.0, 0.0};
    double lightAzimuth = 0.0, sinLight = 1.0, cosLight = 0.0;
    std::vector<double> phi, cosPhi;             // [columns] the uniform columns' azimuths
    std::vector<double> cosHalfPhi, sinHalfPhi;  // [columns] cos and sin of their halves
    std::vector<double> rowElevation;  // [elevationCount] the rows' elevations (the table's mapping)
    // Rows whose multiple scattering is integrated, and the others', taken
    // between those in elevation (planMultipleRows, "Multiple scattering
    // between rows" in sky_solver.cpp).
    std::vector<int> rowOrder;               // [elevationCount] the integrated rows first, then the others
    std::vector<unsigned char> msRowSolved;  // [elevationCount] 1: integrated
    std::vector<int> msRowNode;      // [elevationCount][4] the integrated rows an other row is taken from
    std::vector<float> msRowWeight;  // [elevationCount][4] and their weights
    std::vector<float> msRowValue;   // [elevationCount][3][kMsSkyColumns] an integrated row's azimuths
    std::unique_ptr<std::atomic<int>[]> msRowDone;  // [elevationCount] msRowValue written in this solve
    std::vector<float> cosPhiF;                     // [padded columns]
    std::vector<float> msCosPhiF;     // [kMsSkyColumns] the multiple scattering's azimuths (sky_kernels.hpp)
    std::vector<int> spreadIndex;     // [4][padded columns] spreadMultiple's Catmull-Rom stencil
    std::vector<float> spreadWeight;  // [4][padded columns] and weights

    // Double-buffered output: tables[front] is published.
    SkyTable tables[2];
    int front = 0;

    // Amortised solve.
    bool amortised = false;
    bool depthPending = false;
    int nextRow = 0;
    int nextStage = 0;  // of the atmosphere's rebuild, in steps (runStage)

    // Threads: per-worker scratch and the pool (last: its threads stop first).
    std::vector<Scratch> scratch;              // [threads], 0 = the caller
    std::vector<detail::MsScratch> msScratch;  // [threads]
    std::atomic<int> depthRowsDone{0};         // optical-depth rows finished in the running dispatch
    std::atomic<int> msDepthRowsDone{0};
    std::atomic<int> psiRowsDone{0};
    std::atomic<int> resampleDone{0};   // shells of Psi_ms resampled in the running dispatch
    std::atomic<bool> psiReady{false};  // psiPairs resampled in the running dispatch
    std::optional<detail::WorkerPool> pool;

    explicit Impl(const SkySolverDesc& d);

    void setAtmosphere(const AtmosphereParams& params);
    void setLight(const glm::dvec3& direction);
    void buildLayers();
    void planMultipleRows();
    void buildDepthRow(int row, Scratch& s);
    void rowColumns(int row, Scratch& s) const;
    void solveRow(int row, Scratch& s);
    void shadowEdgeLayers(Scratch& s, double r0, double sinEl, bool straightOn);
    void spreadMultiple(Scratch& s) const;
    void run(bool rebuild, int rowBegin, int rowEnd);
    // The atmosphere's rebuild in steps for an amortised solve: stage 0 the
    // optical-depth rows (the solver's and the LUT's), then each scattering
    // order's LUT rows in kMsStageRows chunks (the last resamples Psi_ms).
    int rebuildStages() const;
    void resampleShell(int k);  // Psi_ms at shell k
    void runStage(int stage);
    void publish();
    // The atmosphere's tables shared between solvers (sky_solver_atmosphere.cpp,
    // "Shared atmosphere tables"): adopt a snapshot built by another solver
    // for the same AtmosphereParams and description, or offer this one's.
    bool adoptSharedTables(const AtmosphereParams& params);
    void shareTables() const;
    bool forceRebuild = false;  // invalidateCache: the next atmosphere is built here, not adopted
};

}  // namespace aerial
