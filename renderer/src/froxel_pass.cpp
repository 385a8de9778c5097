// froxel_pass.cpp — the volumetric fog (FogMode::Volumetric), three passes
// over a grid fitted to the view (common/froxel.glsl; Wronski 2014,
// Hillaire 2015):
//  inject    (froxel_inject.glsl, compute) density of the global height fog,
//            every volume (box and ellipsoid ones in closed form; mesh add
//            ones over the chords of each froxel column's ray, found first
//            by mesh_volume_chords.glsl; subtract ones cutting the froxels
//            whose sample lies inside) and the emitters' in-scatter per
//            froxel in closed form over its slice, and the casting light's
//            visibility (shadow maps x cloud shadows) at its sample point;
//  integrate (froxel_integrate.glsl, compute) front to back per column,
//            Hillaire's energy-conserving slice;
//  apply     (froxel_apply.glsl, full screen) L <- L T + S per pixel with
//            its own fog colours, the global fog beyond the grid analytic.
// They stand in for the analytic global fog, volume and emitter passes
// (which do not run in this mode).
//
// Reads:  FrameBlock (binding 0), the emitters (storage 2), ShadowBlock and
//         the shadow map (binding 5, unit 14), CloudBlock and the cloud
//         shadow map (binding 4, unit 10), linear depth (unit 4), the
//         state's volumes.
// Writes: the FroxelBlock (binding 6), the volumes' buffer (storage 3), the
//         mesh volumes' chords (storage 1; the meshes bound at 6 and 7);
//         the grid's textures (image units 0-4); the colour through
//         compositeTarget (apply).
// GL state: compute dispatches with image barriers; apply binds units 11-13
//         (the amortised clouds' inputs, rebound by that pass) and uses
//         beginComposite / endComposite as the other fog passes.
#include "frame_block.hpp"
#include "render_pass.hpp"

#include <aerial/clouds.hpp>
#include <aerial/evaluate.hpp>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace aerial::renderer::detail {
namespace {

double finiteClamp(double v, double lo, double hi, double fallback) {
    return std::isfinite(v) ? std::clamp(v, lo, hi) : fallback;
}

GLuint makeGridTexture(int width, int height, int depth, GLenum format = GL_RGBA32F) {
    GLuint texture = 0;
    glCreateTextures(GL_TEXTURE_3D, 1, &texture);
    glTextureStorage3D(texture, 1, format, width, height, depth);
    glTextureParameteri(texture, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(texture, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
        glTextureParameteri(texture, wrap, GL_CLAMP_TO_EDGE);
    return texture;
}

void prepareFroxelResources(RendererResources& gpu, int width, int height, int slices) {
    RendererResources::Froxels& g = gpu.froxels;
    if (g.width == width && g.height == height && g.slices == slices) return;
    GLuint textures[7] = {g.medium, g.light, g.litSky, g.sky, g.own, g.history[0], g.history[1]};
    glDeleteTextures(7, textures);
    for (GLuint& h : g.history) h = makeGridTexture(width, height, slices, GL_R32F);
    g.valid = false;
    g.medium = makeGridTexture(width, height, slices);
    g.light = makeGridTexture(width, height, slices);
    g.litSky = makeGridTexture(width, height, slices + 1);
    g.sky = makeGridTexture(width, height, slices + 1);
    g.own = makeGridTexture(width, height, slices + 1);
    g.width = width;
    g.height = height;
    g.slices = slices;
}

void uploadFroxelVolumes(RendererResources& gpu, const std::vector<VolumeBlock>& blocks) {
    RendererResources::Froxels& g = gpu.froxels;
    const GLsizeiptr bytes = GLsizeiptr(std::max<std::size_t>(blocks.size(), 1) * sizeof(VolumeBlock));
    if (g.volumes == 0 || g.volumeCapacity < bytes) {
        glDeleteBuffers(1, &g.volumes);
        glCreateBuffers(1, &g.volumes);
        glNamedBufferData(g.volumes, bytes, nullptr, GL_DYNAMIC_DRAW);
        g.volumeCapacity = bytes;
    }
    if (!blocks.empty())
        glNamedBufferSubData(g.volumes, 0, GLsizeiptr(blocks.size() * sizeof(VolumeBlock)), blocks.data());
}

/// The chords of each froxel column's ray through each mesh add volume
/// (mesh_volume_chords.glsl) into g.meshChords, bound at storage 1 for the
/// injection (a 1-chord buffer when there are none).
void findMeshChords(RendererResources& gpu, const FroxelBlock& block,
                    const std::vector<std::pair<int, const RendererResources::FogMeshGpu*>>& meshes) {
    RendererResources::Froxels& g = gpu.froxels;
    const GLsizeiptr columns = GLsizeiptr(block.gridSize[0]) * block.gridSize[1];
    const GLsizeiptr bytes = std::max<GLsizeiptr>(
        GLsizeiptr(meshes.size()) * columns * kFroxelMeshChords * GLsizeiptr(2 * sizeof(float)), 16);
    if (g.meshChords == 0 || g.meshChordCapacity < bytes) {
        glDeleteBuffers(1, &g.meshChords);
        glCreateBuffers(1, &g.meshChords);
        glNamedBufferData(g.meshChords, bytes, nullptr, GL_DYNAMIC_COPY);
        g.meshChordCapacity = bytes;
    }
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kFroxelMeshChordStorageBinding, g.meshChords);
    if (meshes.empty()) return;
    const GLuint program = gpu.shaders.program(Pass::MeshVolumeChords);
    glUseProgram(program);
    for (std::size_t m = 0; m < meshes.size(); ++m) {
        const RendererResources::FogMeshGpu& mesh = *meshes[m].second;
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kMeshPositionStorageBinding, mesh.vertexBuffer);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kMeshIndexStorageBinding, mesh.indexBuffer);
        glProgramUniform1i(program, 0, meshes[m].first);
        glProgramUniform1i(program, 1, int(m));
        glProgramUniform1i(program, 2, int(mesh.indexCount / 3));
        glDispatchCompute(GLuint((block.gridSize[0] + 7) / 8), GLuint((block.gridSize[1] + 7) / 8), 1);
    }
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

bool injectRuns(const FrameContext& f) {
    if (f.desc.fogMode != FogMode::Volumetric) return false;
    return (f.desc.passes.globalFog && f.block.fogDensity > 0.0f) ||
           (f.desc.passes.volumes && !f.state.volumes.empty()) ||
           (f.desc.passes.emitters && f.block.emitterCount > 0);
}

void injectDraw(FrameContext& f) {
    RendererResources& gpu = f.gpu;
    std::vector<VolumeBlock> blocks;
    // (index in blocks, uploaded mesh) of the mesh add volumes
    std::vector<std::pair<int, const RendererResources::FogMeshGpu*>> meshes;
    if (f.desc.passes.volumes) {
        blocks.reserve(f.state.volumes.size());
        for (const FogVolume& v : f.state.volumes) {
            VolumeBlock b;
            const PreparedFogVolume p = prepareFogVolume(v);
            if (!packVolumeBlock(p, b)) continue;
            if (p.shape == FogVolumeShape::Mesh) {
                // Mesh subtract volumes reach the froxels through the
                // per-pixel union (subtract_pass.cpp); add ones by chords.
                const RendererResources::FogMeshGpu* mesh =
                    p.blend == FogVolumeBlend::Add ? fogMeshOnGpu(gpu, p.mesh) : nullptr;
                if (mesh == nullptr) continue;
                meshes.emplace_back(int(blocks.size()), mesh);
            }
            blocks.push_back(b);
        }
    }
    FroxelBlock block =
        makeFroxelBlock(f.desc, int(f.block.viewportSize[0]), int(f.block.viewportSize[1]),
                        f.view.farDistance, f.state, f.shadowBlock, f.cloudBlock, int(blocks.size()));
    prepareFroxelResources(gpu, block.gridSize[0], block.gridSize[1], block.gridSize[2]);
    RendererResources::Froxels& g = gpu.froxels;
    FroxelStats& stats = f.stats.froxels;
    const FroxelSettings& settings = f.desc.froxels;
    if (settings.temporal) {
        // Keep the history unless something jumped (renderer.hpp, FroxelSettings::temporal).
        double timeStep = std::fabs(f.state.timeHours - g.timeHours);
        timeStep =
            std::isfinite(timeStep) ? std::min(timeStep, std::fabs(24.0 - timeStep)) : 1e30;  // 24 h wrap
        const double move = glm::length(f.view.eye - g.eye);
        const double turn = std::acos(std::clamp(glm::dot(f.view.forward, g.forward), -1.0, 1.0));
        const char* reason = "";
        if (!g.valid)
            reason = "first frame";
        else if (settings.resetHistory)
            reason = "requested";
        else if (!(timeStep <= settings.historyMaxTimeStepHours))
            reason = "time jump";
        else if (!(move <= settings.historyMaxMoveM) || !(turn <= settings.historyMaxTurnRad))
            reason = "camera jump";
        g.framesSinceReset = *reason ? 0 : g.framesSinceReset + 1;
        // A running mean over the frames since the reset, then an exponential
        // one over the last ~10 (the jitter's golden-ratio steps fill the slice).
        block.historyWeight = float(std::max(1.0 / double(g.framesSinceReset + 1), 0.1));
        block.jitter = float(std::fmod(0.5 + 0.6180339887498949 * g.framesSinceReset, 1.0));
        block.previousClipFromWorld = toMat4(g.clipFromWorld);
        block.previousEye = toVec3(g.eye);
        block.previousForward = toVec3(g.forward);
        stats.historyUsed = !*reason;
        stats.resetReason = reason;
    }
    f.froxelBlock = block;
    glNamedBufferSubData(gpu.froxels.block, 0, sizeof block, &block);
    uploadFroxelVolumes(gpu, blocks);
    glBindBufferBase(GL_UNIFORM_BUFFER, kFroxelBinding, gpu.froxels.block);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kFroxelVolumeStorageBinding, gpu.froxels.volumes);
    findMeshChords(gpu, block, meshes);

    glUseProgram(gpu.shaders.program(Pass::FroxelInject));
    glBindImageTexture(0, gpu.froxels.medium, 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glBindImageTexture(1, gpu.froxels.light, 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    const int next = 1 - g.current;
    glBindImageTexture(2, g.history[next], 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_R32F);
    glBindTextureUnit(kFroxelHistoryUnit, g.history[g.current]);
    glBindSampler(kFroxelHistoryUnit, 0);
    glDispatchCompute(GLuint((block.gridSize[0] + 7) / 8), GLuint((block.gridSize[1] + 7) / 8),
                      GLuint(block.gridSize[2]));
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    glBindTextureUnit(kFroxelHistoryUnit, 0);
    // This frame's visibility is the next frame's history.
    g.current = next;
    g.valid = settings.temporal;
    g.clipFromWorld = f.view.clipFromWorld;
    g.eye = f.view.eye;
    g.forward = f.view.forward;
    g.timeHours = f.state.timeHours;

    stats.drawn = true;
    stats.width = block.gridSize[0];
    stats.height = block.gridSize[1];
    stats.slices = block.gridSize[2];
    stats.volumes = block.volumeCount;
    stats.shadowed = block.sceneShadows > 0.5f || block.cloudShadows > 0.5f;
}

bool drawnThisFrame(const FrameContext& f) { return f.froxelBlock.gridSize[0] > 0; }

void integrateDraw(FrameContext& f) {
    RendererResources& gpu = f.gpu;
    glUseProgram(gpu.shaders.program(Pass::FroxelIntegrate));
    glBindImageTexture(0, gpu.froxels.medium, 0, GL_TRUE, 0, GL_READ_ONLY, GL_RGBA32F);
    glBindImageTexture(1, gpu.froxels.light, 0, GL_TRUE, 0, GL_READ_ONLY, GL_RGBA32F);
    glBindImageTexture(2, gpu.froxels.litSky, 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glBindImageTexture(3, gpu.froxels.sky, 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glBindImageTexture(4, gpu.froxels.own, 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glDispatchCompute(GLuint((f.froxelBlock.gridSize[0] + 7) / 8),
                      GLuint((f.froxelBlock.gridSize[1] + 7) / 8), 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    for (GLuint unit = 0; unit < 5; ++unit)
        glBindImageTexture(unit, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
}

void applyDraw(FrameContext& f) {
    RendererResources& gpu = f.gpu;
    const GLuint units[3][2] = {{kFroxelLitSkyUnit, gpu.froxels.litSky},
                                {kFroxelSkyUnit, gpu.froxels.sky},
                                {kFroxelOwnUnit, gpu.froxels.own}};
    for (const auto& [unit, texture] : units) {
        glBindTextureUnit(unit, texture);
        glBindSampler(unit, 0);
    }
    compositeFullscreen(gpu, Pass::FroxelApply, GL_ONE, GL_SRC_ALPHA);
}

}  // namespace

FroxelBlock makeFroxelBlock(const FrameDesc& frame, int width, int height, double farDistance,
                            const PresetState& state, const ShadowBlock& shadows, const CloudBlock& clouds,
                            int volumeCount) {
    FroxelBlock b;
    if (frame.fogMode != FogMode::Volumetric || width < 1 || height < 1) return b;
    const FroxelSettings& s = frame.froxels;
    const int pixels = std::clamp(s.pixelsPerFroxel, 4, 32);
    b.gridSize[0] = (width + pixels - 1) / pixels;
    b.gridSize[1] = (height + pixels - 1) / pixels;
    b.gridSize[2] = std::clamp(s.slices, 16, 256);
    b.volumeCount = std::max(volumeCount, 0);
    b.pixelsPerFroxel = float(pixels);
    const double far = std::min(finiteClamp(s.farM, 10.0, 1e5, 2000.0),
                                std::isfinite(farDistance) && farDistance > 0.0 ? farDistance : 1e5);
    const double z0 = finiteClamp(s.nearScaleM, 0.1, 1000.0, 4.0);
    b.farM = float(far);
    b.z0 = float(z0);
    b.logScale = float(std::log1p(far / z0));
    // The light the shadows dim: the shadow maps' when they are drawn, else
    // the brighter of sun and moon (as the shadow maps and clouds choose it).
    bool moon = false;
    if (shadows.castingLight > 0.5f) {
        moon = shadows.castingLight > 1.5f;
    } else {
        const auto sum = [](const glm::dvec3& c) { return c.x + c.y + c.z; };
        moon = sum(state.moonLight.illuminance) > sum(state.sunLight.illuminance);
    }
    b.castIsMoon = moon ? 1.0f : 0.0f;
    b.sceneShadows = shadows.castingLight > 0.5f ? 1.0f : 0.0f;
    b.cloudShadows = clouds.shadowActive > 0.5f ? 1.0f : 0.0f;
    b.jitter = float(finiteClamp(s.jitter, 0.0, 1.0, 0.5));
    b.globalFog = frame.passes.globalFog ? 1.0f : 0.0f;
    // The preset's volumetric settings (VolumetricFogParams).
    const VolumetricFogParams& v = state.environment.volumetricFog;
    b.customPhase = v.phase == FogPhaseMode::Custom ? 1.0f : 0.0f;
    b.anisotropy = float(finiteClamp(v.anisotropy, -0.95, 0.95, 0.6));
    b.noiseAmount = float(finiteClamp(v.noiseAmount, 0.0, 1.0, 0.0));
    const double scale = finiteClamp(v.noiseScaleM, 1.0, 1000.0, 25.0);
    b.noiseScaleM = float(scale);
    // The noise drifts with the clouds' wind: offset = wind x seconds since
    // 00:00, reduced modulo the lattice's period (256 cells) in double.
    const glm::dvec2 wind = state.environment.clouds.windMPerS;
    const double seconds = (std::isfinite(state.timeHours) ? state.timeHours : 0.0) * 3600.0;
    const double period = 256.0 * scale;
    auto reduce = [period](double x) { return std::isfinite(x) ? x - period * std::floor(x / period) : 0.0; };
    b.noiseOffset = toVec3(glm::dvec3(reduce(wind.x * seconds), 0.0, reduce(wind.y * seconds)));
    return b;
}

void destroyFroxelResources(RendererResources& gpu) {
    RendererResources::Froxels& g = gpu.froxels;
    GLuint textures[7] = {g.medium, g.light, g.litSky, g.sky, g.own, g.history[0], g.history[1]};
    glDeleteTextures(7, textures);
    glDeleteBuffers(1, &g.block);
    glDeleteBuffers(1, &g.volumes);
    glDeleteBuffers(1, &g.meshChords);
    g = RendererResources::Froxels{};
}

const RenderPass kFroxelInjectPass{&PassTimes::froxelInject, injectRuns, injectDraw};
const RenderPass kFroxelIntegratePass{&PassTimes::froxelIntegrate, drawnThisFrame, integrateDraw};
const RenderPass kFroxelApplyPass{&PassTimes::froxelApply, drawnThisFrame, applyDraw};

}  // namespace aerial::renderer::detail
