// sky_textures.cpp — uploading the solver's tables with their coordinates
// (<aerial/sky.hpp>, "Table coordinates") as textures.
#include "sky_textures.hpp"

#include <aerial/atmosphere.hpp>

#include <cmath>
#include <vector>

namespace aerial::renderer::detail {
namespace {

GLuint makeTexture(int columns, int rows, const std::vector<float>& rgba) {
    GLuint texture = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &texture);
    glTextureStorage2D(texture, 1, GL_RGBA32F, columns, rows);
    glTextureSubImage2D(texture, 0, 0, 0, columns, rows, GL_RGBA, GL_FLOAT, rgba.data());
    glTextureParameteri(texture, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(texture, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(texture, GL_TEXTURE_WRAP_S, GL_REPEAT);         // azimuth wraps
    glTextureParameteri(texture, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);  // elevation does not
    return texture;
}

}  // namespace

SkyTextures::~SkyTextures() {
    if (rayleigh != 0) glDeleteTextures(1, &rayleigh);
    if (mie != 0) glDeleteTextures(1, &mie);
    if (multiple != 0) glDeleteTextures(1, &multiple);
}

void SkyTextures::upload(const SkyTable& table) {
    if (rayleigh != 0) glDeleteTextures(1, &rayleigh);
    if (mie != 0) glDeleteTextures(1, &mie);
    if (multiple != 0) glDeleteTextures(1, &multiple);
    const std::size_t texels = table.azimuthCount > 0 && table.elevationCount > 0
                                   ? static_cast<std::size_t>(table.azimuthCount) * table.elevationCount
                                   : 0;
    valid = texels > 0 && table.rayleigh.size() >= texels * 3 && table.mie.size() >= texels * 3 &&
            table.rowElevation.size() == std::size_t(table.elevationCount) &&
            table.columnAzimuth.size() == texels;
    columns = valid ? table.azimuthCount : 1;
    rows = valid ? table.elevationCount : 1;
    std::vector<float> r(static_cast<std::size_t>(columns) * rows * 4, 0.0f);
    std::vector<float> m(r.size(), 0.0f);
    std::vector<float> x(r.size(), 0.0f);
    const bool hasMultiple = valid && table.multiple.size() >= texels * 3;  // absent: zeros
    if (valid) {
        for (std::size_t i = 0; i < texels; ++i) {
            for (int c = 0; c < 3; ++c) {
                r[i * 4 + c] = table.rayleigh[i * 3 + c];
                m[i * 4 + c] = table.mie[i * 3 + c];
                if (hasMultiple) x[i * 4 + c] = table.multiple[i * 3 + c];
            }
            // Where the texel lies (the difference from pi in double: exact
            // near the anti-light point, where a light just set needs it).
            r[i * 4 + 3] = static_cast<float>(table.columnAzimuth[i] - kPi);
            m[i * 4 + 3] = static_cast<float>(table.rowElevation[i / std::size_t(columns)]);
        }
    }
    rayleigh = makeTexture(columns, rows, r);
    mie = makeTexture(columns, rows, m);
    multiple = makeTexture(columns, rows, x);
    lightAzimuth = valid ? table.lightAzimuth : 0.0;
    warped = valid && skyTableColumnsWarped(table);
    lightDirection = table.lightDirection;
    horizonRayleigh = valid ? table.horizonRayleigh : glm::dvec3(0.0);
    horizonMie = valid ? table.horizonMie : glm::dvec3(0.0);
    horizonMultiple = valid ? table.horizonMultiple : glm::dvec3(0.0);
}

}  // namespace aerial::renderer::detail
