// gpu_mesh.cpp — uploads of scene meshes and textures (gpu_mesh.hpp).
#include "gpu_mesh.hpp"

#include "frame_block.hpp"

#include <aerial/finite.hpp>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace aerial::renderer::detail {

double clampOr(double x, double lo, double hi, double fallback) {
    return std::isfinite(x) ? std::clamp(x, lo, hi) : fallback;
}

GpuMesh uploadMesh(const SceneMesh& mesh, bool withNormals) {
    GpuMesh gpu;
    const std::size_t n = mesh.positions.size();
    constexpr int kFloats = 8;  // position, normal, TEXCOORD_0
    std::vector<float> interleaved;
    interleaved.reserve(n * kFloats);
    for (std::size_t i = 0; i < n; ++i) {
        const glm::vec3 p = mesh.positions[i];
        const glm::vec3 nn = i < mesh.normals.size() ? mesh.normals[i] : glm::vec3(0, 1, 0);
        const glm::vec2 uv = i < mesh.texcoords.size() ? mesh.texcoords[i] : glm::vec2(0.0f);
        interleaved.insert(interleaved.end(), {p.x, p.y, p.z, nn.x, nn.y, nn.z, uv.x, uv.y});
    }
    glCreateBuffers(1, &gpu.vertexBuffer);
    glNamedBufferStorage(
        gpu.vertexBuffer,
        static_cast<GLsizeiptr>(std::max<std::size_t>(interleaved.size(), kFloats) * sizeof(float)),
        interleaved.empty() ? nullptr : interleaved.data(), 0);
    glCreateBuffers(1, &gpu.indexBuffer);
    glNamedBufferStorage(
        gpu.indexBuffer,
        static_cast<GLsizeiptr>(std::max<std::size_t>(mesh.indices.size(), 3) * sizeof(std::uint32_t)),
        mesh.indices.empty() ? nullptr : mesh.indices.data(), 0);
    glCreateVertexArrays(1, &gpu.vertexArray);
    glVertexArrayVertexBuffer(gpu.vertexArray, 0, gpu.vertexBuffer, 0, kFloats * sizeof(float));
    glVertexArrayElementBuffer(gpu.vertexArray, gpu.indexBuffer);
    glEnableVertexArrayAttrib(gpu.vertexArray, 0);
    glVertexArrayAttribFormat(gpu.vertexArray, 0, 3, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(gpu.vertexArray, 0, 0);
    if (withNormals) {
        glEnableVertexArrayAttrib(gpu.vertexArray, 1);
        glVertexArrayAttribFormat(gpu.vertexArray, 1, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float));
        glVertexArrayAttribBinding(gpu.vertexArray, 1, 0);
        glEnableVertexArrayAttrib(gpu.vertexArray, 2);
        glVertexArrayAttribFormat(gpu.vertexArray, 2, 2, GL_FLOAT, GL_FALSE, 6 * sizeof(float));
        glVertexArrayAttribBinding(gpu.vertexArray, 2, 0);
    }
    gpu.indexCount = static_cast<GLsizei>(mesh.indices.size());
    gpu.alphaMode = mesh.alphaMode;
    gpu.block.worldFromObject = toMat4(mesh.worldFromObject);
    gpu.block.normalFromObject = toMat4(glm::dmat4(glm::inverseTranspose(glm::dmat3(mesh.worldFromObject))));
    gpu.block.albedo = toVec3(glm::clamp(colourOf(mesh.albedo), 0.0, 1.0));
    gpu.block.opacity = static_cast<float>(clampOr(mesh.opacity, 0.0, 1.0, 1.0));
    gpu.block.emission = toVec3(colourOf(mesh.emission));
    gpu.block.specularFactor = static_cast<float>(clampOr(mesh.specularFactor, 0.0, 1.0, 1.0));
    const double mode = mesh.alphaMode == AlphaMode::Mask    ? 1.0
                        : mesh.alphaMode == AlphaMode::Blend ? 2.0
                                                             : 0.0;
    gpu.block.metallic = static_cast<float>(clampOr(mesh.metallic, 0.0, 1.0, 0.0));
    gpu.block.roughness = static_cast<float>(clampOr(mesh.roughness, 0.0, 1.0, 1.0));
    gpu.block.alphaCutoff = static_cast<float>(clampOr(mesh.alphaCutoff, 0.0, 1.0, 0.5));
    gpu.block.alphaMode = static_cast<float>(mode);
    // World bounds of the referenced vertices (the transparent pass's fog corners).
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    for (std::uint32_t index : mesh.indices) {
        const glm::dvec3 p =
            glm::dvec3(mesh.worldFromObject * glm::dvec4(glm::dvec3(mesh.positions[index]), 1.0));
        if (!isFinite(p)) continue;
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    if (!(lo.x <= hi.x)) lo = hi = glm::dvec3(0.0);
    gpu.boundsMin = lo;
    gpu.boundsMax = hi;
    gpu.block.boundsMin = toVec3(lo);
    gpu.block.boundsMax = toVec3(hi);
    for (Vec4& c : gpu.block.cornerFog) c = {0.0f, 0.0f, 0.0f, 1.0f};
    return gpu;
}

GLuint uploadTexture(const SceneTexture& t) {
    if (t.width <= 0 || t.height <= 0 || t.width > 16384 || t.height > 16384 ||
        t.rgba.size() != std::size_t(t.width) * std::size_t(t.height) * 4)
        return 0;
    GLint unpackBuffer = 0, alignment = 4, rowLength = 0, skipRows = 0, skipPixels = 0;
    glGetIntegerv(GL_PIXEL_UNPACK_BUFFER_BINDING, &unpackBuffer);
    glGetIntegerv(GL_UNPACK_ALIGNMENT, &alignment);
    glGetIntegerv(GL_UNPACK_ROW_LENGTH, &rowLength);
    glGetIntegerv(GL_UNPACK_SKIP_ROWS, &skipRows);
    glGetIntegerv(GL_UNPACK_SKIP_PIXELS, &skipPixels);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    int levels = 1;
    while ((std::max(t.width, t.height) >> levels) > 0) ++levels;
    GLuint texture = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &texture);
    glTextureStorage2D(texture, levels, GL_SRGB8_ALPHA8, t.width, t.height);
    // Rows top first: glTF's (u, v) = (0, 0) is the image's top-left texel,
    // which lands at t = 0 here, so TEXCOORD_0 is used unflipped.
    glTextureSubImage2D(texture, 0, 0, 0, t.width, t.height, GL_RGBA, GL_UNSIGNED_BYTE, t.rgba.data());
    glGenerateTextureMipmap(texture);
    glTextureParameteri(texture, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(texture, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(texture, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(texture, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, static_cast<GLuint>(unpackBuffer));
    glPixelStorei(GL_UNPACK_ALIGNMENT, alignment);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, rowLength);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, skipRows);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, skipPixels);
    return texture;
}

void destroyMesh(GpuMesh& mesh) {
    glDeleteVertexArrays(1, &mesh.vertexArray);
    glDeleteBuffers(1, &mesh.vertexBuffer);
    glDeleteBuffers(1, &mesh.indexBuffer);
    mesh = {};
}

}  // namespace aerial::renderer::detail
