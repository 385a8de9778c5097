// sky_reference.hpp — brute-force, double-precision single scattering
// (Nishita 1993, ../../shared/DESIGN.md "Sky") for tests and benchmarks.
//
// Written independently of core's solver: no optical-depth table, no layers.
// Each view ray is marched with viewSteps (>= 1000) midpoint steps, and from
// every step the optical depth towards the light is marched again with
// lightSteps (>= 200) steps per monotonic piece of the light ray. The only
// things it shares with core are the AtmosphereParams struct and the table
// mapping documented in <aerial/sky.hpp>, which it re-implements.
#pragma once

#include <aerial/atmosphere.hpp>
#include <aerial/sky.hpp>

#include <glm/vec3.hpp>

namespace aerial::reference {

struct SkyReferenceOptions {
    int viewSteps = 1000;  ///< midpoint steps along the view ray, >= 1000 for tests
    int lightSteps = 200;  ///< steps per piece of each ray towards the light, >= 200
};

/// Phase-less single-scattering integrals I_R and I_M (RGB, dimensionless)
/// seen from the viewer (AtmosphereParams::viewerHeight) looking along the
/// unit direction `view`, lit from the unit direction `light` (both world
/// space, +Y = local zenith).
SkySample singleScattering(const AtmosphereParams& air, const glm::dvec3& view, const glm::dvec3& light,
                           const SkyReferenceOptions& options = {});

/// Optical depth [dimensionless], RGB extinction, from height h [m] along a
/// ray with zenith cosine muZenith to the top of the atmosphere; +infinity
/// when the ray hits the ground.
glm::dvec3 opticalDepthToTop(const AtmosphereParams& air, double height, double muZenith, int steps);

/// Azimuth [rad] of a direction, from north (-Z) towards east (+X).
double azimuthOf(const glm::dvec3& direction);

/// Elevation [rad] of row j of a table: its coordinates
/// (SkyTable::rowElevation, aerial/sky.hpp "Table coordinates").
double texelElevation(int j, const SkyTable& table);

/// Azimuth from the light [rad] of texel (i, j): the table's coordinates
/// (SkyTable::columnAzimuth).
double texelAzimuth(int i, int j, const SkyTable& table);

/// World direction of texel (i, j) of a table (its light's azimuth and its
/// coordinates).
glm::dvec3 texelDirection(int i, int j, const SkyTable& table);

/// Fills a whole SkyTable by brute force (same layout and row mapping as
/// SkySolver, setSkyTableMapping), solving
/// only the rows in [rowBegin, rowEnd) and columns 0..azimuthCount/2, then
/// mirroring. Slow: seconds for a full table.
void solveTable(const AtmosphereParams& air, const glm::dvec3& light, int azimuthCount, int elevationCount,
                SkyTable& table, int rowBegin, int rowEnd, const SkyReferenceOptions& options = {});

}  // namespace aerial::reference
