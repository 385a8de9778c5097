// sky_textures.hpp — private: the two hemisphere tables of one light as GL
// textures, and the sky's ambient irradiance derived from them.
#pragma once

#include <aerial/sky.hpp>

#include <epoxy/gl.h>
#include <glm/vec3.hpp>

namespace aerial::renderer::detail {

/// I_R, I_M and I_ms of one table as RGBA32F textures, GL_LINEAR, GL_REPEAT
/// on s (the azimuth wraps), GL_CLAMP_TO_EDGE on t. The alphas carry the
/// table's coordinates (aerial/sky.hpp, "Table coordinates"; read by
/// common/sky_table.glsl): the Mie texture's the row's elevation [rad], the
/// Rayleigh texture's the texel's azimuth from the point opposite the light,
/// phi - pi [rad, -pi..pi); the multiple's alpha is 0.
struct SkyTextures {
    GLuint rayleigh = 0;
    GLuint mie = 0;
    GLuint multiple = 0;
    int columns = 1;
    int rows = 1;
    double lightAzimuth = 0.0;
    bool warped = false;  ///< the columns are warped (skyTableColumnsWarped): searched per row
    glm::dvec3 lightDirection{0.0, 1.0, 0.0};
    glm::dvec3 horizonRayleigh{0.0};
    glm::dvec3 horizonMie{0.0};
    glm::dvec3 horizonMultiple{0.0};
    bool valid = false;  ///< false: the table was empty, malformed or without coordinates (black)

    ~SkyTextures();
    /// Uploads a table (a malformed one uploads one black texel).
    void upload(const SkyTable& table);
};

}  // namespace aerial::renderer::detail
