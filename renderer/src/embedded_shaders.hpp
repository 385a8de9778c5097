// embedded_shaders.hpp — private: the GLSL sources of shaders/, embedded at
// build time by renderer/cmake/embed_shaders.cmake (generated .cpp).
#pragma once

#include <vector>

namespace aerial::renderer::detail {

struct EmbeddedShader {
    const char* path;  ///< relative to shaders/, e.g. "common/atmosphere.glsl"
    const char* text;
};

const std::vector<EmbeddedShader>& embeddedShaders();

}  // namespace aerial::renderer::detail
