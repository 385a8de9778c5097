// Uses the installed aerial_core: sun position, a sky solve and a fog query.
#include <aerial/fog_query.hpp>
#include <aerial/sky.hpp>
#include <aerial/sun.hpp>

#include <cmath>
#include <cstdio>

int main() {
    aerial::Location where;
    const aerial::CelestialBody sun = aerial::sunPosition(where, 12.0);
    aerial::SkySolver solver;
    const aerial::AtmosphereParams air;
    solver.solve(air, sun.direction);
    aerial::FogSceneDesc desc;
    desc.heightFog.density = 1e-3;
    const aerial::FogScene fog(desc);
    const aerial::FogQueryResult r = fog.query(glm::dvec3(0.0), glm::dvec3(0.0, 0.0, -100.0));
    // Uniform fog at the base height: T = exp(-b d) exactly.
    const double expected = std::exp(-0.1);
    std::printf("sun_elevation_deg=%.6f fog_T=%.9f expected=%.9f zenith_rayleigh=%.6g\n",
                sun.elevation * 180.0 / aerial::kPi, r.transmittance.g, expected,
                aerial::sampleSkyTable(solver.table(), glm::dvec3(0, 1, 0)).rayleigh.b);
    return std::abs(r.transmittance.g - expected) < 1e-9 ? 0 : 1;
}
