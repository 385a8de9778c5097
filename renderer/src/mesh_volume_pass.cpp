// mesh_volume_pass.cpp — mesh fog volumes on the GPU (DESIGN.md "Mesh and
// subtract volumes"; seed 001, polygonal fog volumes): the meshes' vertex
// arrays (uploaded once per FogMesh, released when a frame stops using
// them) and the draw of one mesh add volume, called by the volume pass in
// its back-to-front order:
//  1. accumulate (mesh_volume_accumulate.glsl): the accumulation target
//     (RG32F) cleared, every triangle drawn with culling and depth test off,
//     depth clamp on, additive blending: R += s F(clamp(t, 0, depth)),
//     G += s (s = +1 back face / exit, -1 front face / entry);
//  2. composite (mesh_volume_composite.glsl), full screen:
//     tau = R + G integral(0, tRef), L <- L T + C (1 - T).
// Both are scissored to the volume's screen rectangle (the corners of the
// mesh's object bounds placed in the world, projected; the whole frame when
// a corner is not in front of the eye's plane).
//
// Reads:  the volume's FogMesh, FrameBlock, linear depth (unit 4), the
//         subtract intervals (storage 4, when active).
// Writes: the accumulation texture (its own target), then the colour
//         through compositeTarget; the VolumeBlock (binding 1).
// GL state: on entry the volume pass's beginComposite; the accumulation
//         sets blending (GL_ONE, GL_ONE) and binds its target, the
//         composite returns to compositeTarget with beginComposite(GL_ONE,
//         GL_SRC_ALPHA); culling and depth test off, depth clamp off and
//         scissor off on exit; program, vertex array and unit 5 changed.
#include "gl_state.hpp"
#include "render_pass.hpp"

#include <aerial/fog_mesh.hpp>

#include <glm/mat4x4.hpp>

#include <algorithm>
#include <cmath>

namespace aerial::renderer::detail {
namespace {

void destroyFogMesh(RendererResources::FogMeshGpu& m) {
    glDeleteVertexArrays(1, &m.vertexArray);
    glDeleteBuffers(1, &m.vertexBuffer);
    glDeleteBuffers(1, &m.indexBuffer);
    m = RendererResources::FogMeshGpu{};
}

void prepareAccumulation(RendererResources& gpu, int width, int height) {
    if (gpu.meshAccumulation != 0 && gpu.meshAccumulationWidth == width &&
        gpu.meshAccumulationHeight == height)
        return;
    glDeleteFramebuffers(1, &gpu.meshAccumulationTarget);
    glDeleteTextures(1, &gpu.meshAccumulation);
    gpu.meshAccumulation = makeTargetTexture(GL_RG32F, width, height);
    glCreateFramebuffers(1, &gpu.meshAccumulationTarget);
    glNamedFramebufferTexture(gpu.meshAccumulationTarget, GL_COLOR_ATTACHMENT0, gpu.meshAccumulation, 0);
    gpu.meshAccumulationWidth = width;
    gpu.meshAccumulationHeight = height;
}

/// The pixel rectangle [x0, x1) x [y0, y1) covering the mesh's object
/// bounds placed in the world, seen by clipFromWorld (a pixel of margin);
/// the whole frame when a corner is not in front of the eye.
void screenRectangle(const glm::dmat4& clipFromWorld, const PreparedFogVolume& volume, int width, int height,
                     int rect[4]) {
    const glm::dvec3 lo = volume.mesh->boundsMin();
    const glm::dvec3 hi = volume.mesh->boundsMax();
    double minX = 1e30, minY = 1e30, maxX = -1e30, maxY = -1e30;
    for (int i = 0; i < 8; ++i) {
        const glm::dvec3 corner((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z);
        const glm::dvec3 world = volume.position + volume.worldFromObject * corner;
        const glm::dvec4 clip = clipFromWorld * glm::dvec4(world, 1.0);
        if (!(clip.w > 1e-6)) {
            rect[0] = rect[1] = 0;
            rect[2] = width;
            rect[3] = height;
            return;
        }
        const double x = (clip.x / clip.w * 0.5 + 0.5) * width;
        const double y = (clip.y / clip.w * 0.5 + 0.5) * height;
        minX = std::min(minX, x);
        maxX = std::max(maxX, x);
        minY = std::min(minY, y);
        maxY = std::max(maxY, y);
    }
    rect[0] = int(std::clamp(std::floor(minX) - 1.0, 0.0, double(width)));
    rect[1] = int(std::clamp(std::floor(minY) - 1.0, 0.0, double(height)));
    rect[2] = int(std::clamp(std::ceil(maxX) + 1.0, 0.0, double(width)));
    rect[3] = int(std::clamp(std::ceil(maxY) + 1.0, 0.0, double(height)));
}

}  // namespace

const RendererResources::FogMeshGpu* fogMeshOnGpu(RendererResources& gpu,
                                                  const std::shared_ptr<const FogMesh>& mesh) {
    if (!mesh || mesh->indices().empty()) return nullptr;
    auto found = gpu.fogMeshes.find(mesh.get());
    if (found != gpu.fogMeshes.end() && found->second.mesh.lock() != mesh) {
        destroyFogMesh(found->second);  // a new mesh at the address of a released one
        gpu.fogMeshes.erase(found);
        found = gpu.fogMeshes.end();
    }
    if (found == gpu.fogMeshes.end()) {
        RendererResources::FogMeshGpu m;
        m.mesh = mesh;
        std::vector<float> positions;
        positions.reserve(mesh->positions().size() * 3);
        for (const glm::dvec3& p : mesh->positions()) {
            positions.insert(positions.end(), {float(p.x), float(p.y), float(p.z)});
        }
        const std::vector<std::uint32_t>& indices = mesh->indices();
        glCreateBuffers(1, &m.vertexBuffer);
        glNamedBufferStorage(m.vertexBuffer, GLsizeiptr(positions.size() * sizeof(float)), positions.data(),
                             0);
        glCreateBuffers(1, &m.indexBuffer);
        glNamedBufferStorage(m.indexBuffer, GLsizeiptr(indices.size() * sizeof(std::uint32_t)),
                             indices.data(), 0);
        glCreateVertexArrays(1, &m.vertexArray);
        glVertexArrayVertexBuffer(m.vertexArray, 0, m.vertexBuffer, 0, 3 * sizeof(float));
        glVertexArrayElementBuffer(m.vertexArray, m.indexBuffer);
        glEnableVertexArrayAttrib(m.vertexArray, 0);
        glVertexArrayAttribFormat(m.vertexArray, 0, 3, GL_FLOAT, GL_FALSE, 0);
        glVertexArrayAttribBinding(m.vertexArray, 0, 0);
        m.indexCount = GLsizei(indices.size());
        found = gpu.fogMeshes.emplace(mesh.get(), m).first;
    }
    found->second.lastFrame = gpu.frameNumber;
    return &found->second;
}

void releaseUnusedFogMeshes(RendererResources& gpu) {
    for (auto it = gpu.fogMeshes.begin(); it != gpu.fogMeshes.end();) {
        if (it->second.lastFrame != gpu.frameNumber || it->second.mesh.expired()) {
            destroyFogMesh(it->second);
            it = gpu.fogMeshes.erase(it);
        } else {
            ++it;
        }
    }
}

bool drawMeshVolume(FrameContext& f, const PreparedFogVolume& volume, const VolumeBlock& block) {
    RendererResources& gpu = f.gpu;
    const RendererResources::FogMeshGpu* mesh = fogMeshOnGpu(gpu, volume.mesh);
    if (mesh == nullptr) return false;
    const int width = int(f.block.viewportSize[0]);
    const int height = int(f.block.viewportSize[1]);
    prepareAccumulation(gpu, width, height);
    int rect[4];
    screenRectangle(f.view.clipFromWorld, volume, width, height, rect);
    if (rect[2] <= rect[0] || rect[3] <= rect[1]) return false;  // off screen
    glNamedBufferSubData(gpu.volumeBuffer, 0, sizeof block, &block);
    glEnable(GL_SCISSOR_TEST);
    glScissor(rect[0], rect[1], rect[2] - rect[0], rect[3] - rect[1]);

    // 1. Accumulate the signed antiderivatives of every face.
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, gpu.meshAccumulationTarget);
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearBufferfv(GL_COLOR, 0, zero);
    glBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
    glDisable(GL_CULL_FACE);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_DEPTH_CLAMP);  // faces beyond the far plane still count
    glUseProgram(gpu.shaders.program(Pass::MeshVolumeAccumulate));
    glBindVertexArray(mesh->vertexArray);
    glDrawElements(GL_TRIANGLES, mesh->indexCount, GL_UNSIGNED_INT, nullptr);
    glDisable(GL_DEPTH_CLAMP);

    // 2. Composite the volume over the colour.
    beginComposite(gpu, GL_ONE, GL_SRC_ALPHA);
    glBindTextureUnit(kMeshVolumeAccumulationUnit, gpu.meshAccumulation);
    glBindSampler(kMeshVolumeAccumulationUnit, 0);
    drawFullscreen(gpu, Pass::MeshVolumeComposite);
    glDisable(GL_SCISSOR_TEST);
    ++f.stats.meshVolumesDrawn;
    return true;
}

void destroyMeshVolumeResources(RendererResources& gpu) {
    for (auto& [key, mesh] : gpu.fogMeshes) destroyFogMesh(mesh);
    gpu.fogMeshes.clear();
    glDeleteFramebuffers(1, &gpu.meshAccumulationTarget);
    glDeleteTextures(1, &gpu.meshAccumulation);
    gpu.meshAccumulationTarget = gpu.meshAccumulation = 0;
    gpu.meshAccumulationWidth = gpu.meshAccumulationHeight = 0;
}

}  // namespace aerial::renderer::detail
