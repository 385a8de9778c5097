// subtract_pass.cpp — pass 2c: the subtract volumes' union along every
// pixel's ray (fog_volume.hpp FogVolumeBlend::Subtract; DESIGN.md "Mesh and
// subtract volumes"), before the fog passes that cut it out of their
// integrals (global_fog.glsl, fog_volume.glsl, the mesh volumes through
// common/subtract.glsl; the volumetric fog's injection for mesh subtract
// volumes). Runs only with the volume pass on and a valid subtract volume
// (analytic fog) or mesh subtract volume (volumetric fog): frame.subtractActive,
// set by the renderer before the frame block is uploaded; otherwise it
// costs nothing.
//
//  1. (mesh subtract volumes only) subtract_crossings.glsl rasterises their
//     triangles, every face of each pixel's ray appended to a per-pixel list
//     (atomic counter, at most kSubtractCrossings = 16 kept: 8 chords);
//  2. subtract_resolve.glsl (compute, 8 x 8 pixels a group) adds the box and
//     ellipsoid subtract volumes analytically, sorts the interval ends, and
//     writes the union clipped to [0, depth01] as K = kSubtractIntervals = 4
//     disjoint (a, b) pairs per pixel. Beyond 4 stretches the 4th covers the
//     rest (the fog between them is removed too): counted per pixel in
//     RenderStats::subtractIntervalOverflowPixels; lost crossings in
//     subtractCrossingOverflowPixels (readSubtractStats, after the frame).
// Overlapping subtract volumes remove once: a stretch is inside while any
// volume holds the ray (a running count > 0).
//
// Reads:  the state's volumes (core's prepareFogVolume), FrameBlock, linear
//         depth (unit 4), the mesh volumes' vertex arrays.
// Writes: storage 4 (intervals, left bound for the fog passes), 5 (box /
//         ellipsoid subtract volumes), 6 (counts and statistics), 7
//         (crossings); the VolumeBlock (binding 1) per mesh volume.
// GL state: during the mesh draws colour writes off, depth clamp on (depth
//         test and culling are off in the baseline); both restored; shader
//         storage barriers after the draws and after the dispatch.
#include "render_pass.hpp"

#include <aerial/evaluate.hpp>
#include <aerial/fog_volume.hpp>

#include <algorithm>

namespace aerial::renderer::detail {
namespace {

void ensureBuffer(GLuint& buffer, GLsizeiptr bytes) {
    glDeleteBuffers(1, &buffer);
    glCreateBuffers(1, &buffer);
    glNamedBufferData(buffer, bytes, nullptr, GL_DYNAMIC_COPY);
}

/// Sizes the per-pixel buffers for width x height (crossings only when
/// mesh subtract volumes need them).
void prepareSubtractResources(RendererResources& gpu, int width, int height, bool crossings) {
    RendererResources::Subtract& s = gpu.subtract;
    const GLsizeiptr pixels = GLsizeiptr(width) * height;
    if (s.width != width || s.height != height || s.intervals == 0) {
        ensureBuffer(s.intervals, pixels * 2 * GLsizeiptr(4 * sizeof(float)));
        ensureBuffer(s.counts, (pixels + 2) * GLsizeiptr(sizeof(std::uint32_t)));
        glDeleteBuffers(1, &s.crossings);
        s.crossings = 0;
        s.crossingBytes = 0;
        s.width = width;
        s.height = height;
    }
    const GLsizeiptr crossingBytes = pixels * kSubtractCrossings * GLsizeiptr(sizeof(std::uint32_t));
    if (crossings && s.crossingBytes < crossingBytes) {
        ensureBuffer(s.crossings, crossingBytes);
        s.crossingBytes = crossingBytes;
    }
}

bool runs(const FrameContext& f) { return f.block.subtractActive != 0; }

void draw(FrameContext& f) {
    RendererResources& gpu = f.gpu;
    const int width = int(f.block.viewportSize[0]);
    const int height = int(f.block.viewportSize[1]);
    std::vector<VolumeBlock> analytic;
    std::vector<std::pair<PreparedFogVolume, VolumeBlock>> meshes;
    for (const FogVolume& v : f.state.volumes) {
        if (v.blend != FogVolumeBlend::Subtract) continue;
        PreparedFogVolume p = prepareFogVolume(v);
        VolumeBlock block;
        if (!packVolumeBlock(p, block)) continue;
        if (p.shape == FogVolumeShape::Mesh) {
            meshes.emplace_back(std::move(p), block);
        } else {
            analytic.push_back(block);
        }
    }
    f.stats.subtractVolumes = int(analytic.size() + meshes.size());
    prepareSubtractResources(gpu, width, height, !meshes.empty());
    RendererResources::Subtract& s = gpu.subtract;
    const std::uint32_t zero = 0;
    glClearNamedBufferData(s.counts, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kSubtractCountStorageBinding, s.counts);
    if (s.crossings != 0)
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kSubtractCrossingStorageBinding, s.crossings);

    bool meshCrossings = false;
    if (!meshes.empty()) {
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glEnable(GL_DEPTH_CLAMP);  // faces beyond the far plane still count
        glUseProgram(gpu.shaders.program(Pass::SubtractCrossings));
        for (const auto& [p, block] : meshes) {
            const RendererResources::FogMeshGpu* mesh = fogMeshOnGpu(gpu, p.mesh);
            if (mesh == nullptr) continue;
            glNamedBufferSubData(gpu.volumeBuffer, 0, sizeof block, &block);
            glBindVertexArray(mesh->vertexArray);
            glDrawElements(GL_TRIANGLES, mesh->indexCount, GL_UNSIGNED_INT, nullptr);
            meshCrossings = true;
        }
        glDisable(GL_DEPTH_CLAMP);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }

    const GLsizeiptr bytes = GLsizeiptr(std::max<std::size_t>(analytic.size(), 1) * sizeof(VolumeBlock));
    if (s.volumes == 0 || s.volumeCapacity < bytes) {
        ensureBuffer(s.volumes, bytes);
        s.volumeCapacity = bytes;
    }
    if (!analytic.empty()) {
        glNamedBufferSubData(s.volumes, 0, GLsizeiptr(analytic.size() * sizeof(VolumeBlock)),
                             analytic.data());
    }
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kSubtractVolumeStorageBinding, s.volumes);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kSubtractIntervalStorageBinding, s.intervals);
    const GLuint program = gpu.shaders.program(Pass::SubtractResolve);
    glUseProgram(program);
    glProgramUniform1i(program, 0, int(analytic.size()));
    glProgramUniform1i(program, 1, meshCrossings ? 1 : 0);
    glDispatchCompute(GLuint((width + 7) / 8), GLuint((height + 7) / 8), 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

}  // namespace

bool frameHasSubtractVolumes(const PresetState& state, const FrameDesc& frame) {
    if (!frame.passes.volumes) return false;
    // The volumetric fog tests box and ellipsoid subtract volumes itself
    // (froxel_inject.glsl); it reads the union only for mesh ones.
    const bool analytic = frame.fogMode == FogMode::Analytic;
    return std::any_of(state.volumes.begin(), state.volumes.end(), [analytic](const FogVolume& v) {
        return v.blend == FogVolumeBlend::Subtract && (analytic || v.shape == FogVolumeShape::Mesh) &&
               prepareFogVolume(v).valid;
    });
}

void readSubtractStats(const RendererResources& gpu, RenderStats& stats) {
    if (gpu.subtract.counts == 0) return;
    std::uint32_t counters[2] = {};
    glGetNamedBufferSubData(gpu.subtract.counts, 0, sizeof counters, counters);
    stats.subtractCrossingOverflowPixels = int(counters[0]);
    stats.subtractIntervalOverflowPixels = int(counters[1]);
}

void destroySubtractResources(RendererResources& gpu) {
    RendererResources::Subtract& s = gpu.subtract;
    for (GLuint* b : {&s.intervals, &s.counts, &s.crossings, &s.volumes}) {
        glDeleteBuffers(1, b);
        *b = 0;
    }
    s = RendererResources::Subtract{};
}

const RenderPass kSubtractPass{&PassTimes::subtract, runs, draw};

}  // namespace aerial::renderer::detail
