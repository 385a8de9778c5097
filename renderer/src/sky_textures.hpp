// sky_textures.hpp — private: the two hemisphere tables of one light as GL
// textures, and the sky's ambient irradiance derived from them.
#pragma once

#include <aerial/sky.hpp>

#include <epoxy/gl.h>
#include <glm/vec3.hpp>

namespace aerial::renderer::detail {

/// I_R, I_M and I_ms of one table as RGBA32F textures (alpha 0), GL_LINEAR,
/// GL_REPEAT on s (the azimuth wraps), GL_CLAMP_TO_EDGE on t.
struct SkyTextures {
    GLuint rayleigh = 0;
    GLuint mie = 0;
    GLuint multiple = 0;
    int columns = 1;
    int rows = 1;
    double lightAzimuth = 0.0;
    /// The table's row mapping (SkyTable::bandElevation .. shadowShare; 0: quadratic).
    double bandElevation = 0.0, bandShare = 0.0;
    double shadowElevation = 0.0, shadowWidth = 0.0, shadowShare = 0.0;
    double capCurvature = 0.0, capStrength = 0.0;  ///< the column mapping (SkyTable)
    glm::dvec3 lightDirection{0.0, 1.0, 0.0};
    glm::dvec3 horizonRayleigh{0.0};
    glm::dvec3 horizonMie{0.0};
    glm::dvec3 horizonMultiple{0.0};
    bool valid = false;  ///< false: the table was empty or malformed (black)

    ~SkyTextures();
    /// Uploads a table (a malformed one uploads one black texel).
    void upload(const SkyTable& table);
};

}  // namespace aerial::renderer::detail
