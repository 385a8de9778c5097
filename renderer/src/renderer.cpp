// renderer.cpp — the Renderer: its GL resources (targets, buffers, the
// uploaded scene and sky tables) and the frame as a list of passes (one
// file each: scene_pass.cpp, sky_pass.cpp, global_fog_pass.cpp,
// subtract_pass.cpp, volume_pass.cpp (mesh_volume_pass.cpp), emitter_pass.cpp, transparent_pass.cpp,
// particle_pass.cpp, cloud_shadow_pass.cpp, cloud_pass.cpp,
// shadow_map_pass.cpp, froxel_pass.cpp; render_pass.hpp for their
// contract). See
// <aerial/renderer/renderer.hpp> for the order and the compositing contract,
// and shaders/*.glsl for the per-pixel formulas.
#include <aerial/renderer/renderer.hpp>

#include "frame_block.hpp"
#include "gl_state.hpp"
#include "gpu_mesh.hpp"
#include "gpu_types.hpp"
#include "render_pass.hpp"
#include "shader_library.hpp"
#include "sky_textures.hpp"

#include <aerial/clouds.hpp>
#include <aerial/evaluate.hpp>
#include <aerial/finite.hpp>
#include <aerial/sky.hpp>

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace aerial::renderer {
namespace {

using detail::clampOr;
using detail::colourOf;
using detail::GpuMesh;

/// The frame, in order (renderer.hpp).
const detail::RenderPass* const kFramePasses[] = {
    &detail::kCloudShadowPass,  &detail::kShadowMapPass,       &detail::kScenePass,
    &detail::kSkyPass,          &detail::kCloudPass,           &detail::kSubtractPass,
    &detail::kGlobalFogPass,    &detail::kVolumePass,          &detail::kEmitterPass,
    &detail::kFroxelInjectPass, &detail::kFroxelIntegratePass, &detail::kFroxelApplyPass,
    &detail::kTransparentPass,  &detail::kParticlePass,
};

}  // namespace

std::string defaultShaderDirectory() { return AERIAL_SHADER_SOURCE_DIR; }

struct Renderer::Impl : detail::RendererResources {
    RendererDesc desc;
    std::string error;
    RenderStats stats;
    std::vector<GLuint> textures;  // base-colour textures of the meshes
    detail::PassTimer timer;
    int width = 0, height = 0;
    ColourPrecision precision = ColourPrecision::Half;

    void log(LogLevel level, const std::string& text) const {
        detail::logMessage(desc.logger, level, text.c_str());
    }

    void destroyTargets() {
        glDeleteFramebuffers(1, &sceneTarget);
        glDeleteFramebuffers(1, &compositeTarget);
        glDeleteTextures(1, &colour);
        glDeleteTextures(1, &linearDepth);
        glDeleteTextures(1, &depth);
        sceneTarget = compositeTarget = colour = linearDepth = depth = 0;
        width = height = 0;
    }

    void ensureTargets(int w, int h, ColourPrecision p) {
        if (w == width && h == height && p == precision && colour != 0) return;
        destroyTargets();
        width = w;
        height = h;
        precision = p;
        auto texture = [&](GLenum format) { return detail::makeTargetTexture(format, w, h); };
        colour = texture(p == ColourPrecision::Float ? GL_RGBA32F : GL_RGBA16F);
        linearDepth = texture(GL_R32F);
        depth = texture(GL_DEPTH_COMPONENT32F);
        glCreateFramebuffers(1, &sceneTarget);
        glNamedFramebufferTexture(sceneTarget, GL_COLOR_ATTACHMENT0, colour, 0);
        glNamedFramebufferTexture(sceneTarget, GL_COLOR_ATTACHMENT1, linearDepth, 0);
        glNamedFramebufferTexture(sceneTarget, GL_DEPTH_ATTACHMENT, depth, 0);
        glCreateFramebuffers(1, &compositeTarget);
        glNamedFramebufferTexture(compositeTarget, GL_COLOR_ATTACHMENT0, colour, 0);
        glNamedFramebufferTexture(compositeTarget, GL_DEPTH_ATTACHMENT, depth, 0);
        for (GLuint fb : {sceneTarget, compositeTarget}) {
            const GLenum status = glCheckNamedFramebufferStatus(fb, GL_DRAW_FRAMEBUFFER);
            if (status != GL_FRAMEBUFFER_COMPLETE) {
                log(LogLevel::Error, "renderer: incomplete framebuffer, status " + std::to_string(status));
            }
        }
    }

    void destroyScene() {
        for (GpuMesh& m : meshes) detail::destroyMesh(m);
        meshes.clear();
        if (!textures.empty()) glDeleteTextures(static_cast<GLsizei>(textures.size()), textures.data());
        textures.clear();
        sprites.clear();
    }

    void render(const Camera& camera, const PresetState& state, const FrameDesc& frameDesc);
};

Renderer::Renderer(const RendererDesc& desc) : impl_(std::make_unique<Impl>()) {
    Impl& s = *impl_;
    s.desc = desc;
    if (s.desc.shaderDirectory.empty()) s.desc.shaderDirectory = defaultShaderDirectory();
    if (epoxy_gl_version() < 45 || epoxy_is_desktop_gl() == 0) {
        s.error = "renderer: needs a current desktop OpenGL 4.5 context (found version " +
                  std::to_string(epoxy_gl_version()) + ")";
        s.log(LogLevel::Error, s.error);
        return;
    }
    detail::GlStateGuard guard(&s.desc.logger, s.desc.debugOutput, &s.stats.glErrors);
    std::string log;
    if (!s.shaders.build(detail::embeddedShaderReader(), log)) {
        s.error = "renderer: embedded shaders failed to build:\n" + log;
        s.log(LogLevel::Error, s.error);
    }
    glCreateVertexArrays(1, &s.emptyVertexArray);
    s.hull = detail::uploadMesh(makeBoxMesh(glm::dvec3(0.0), glm::dvec3(1.0)), false);
    SceneTexture white;
    white.width = white.height = 1;
    white.rgba = {255, 255, 255, 255};
    s.whiteTexture = detail::uploadTexture(white);
    glCreateBuffers(1, &s.spriteBuffer);
    glNamedBufferData(s.spriteBuffer, sizeof(detail::SpriteInstance), nullptr, GL_STREAM_DRAW);
    glCreateVertexArrays(1, &s.spriteArray);
    glVertexArrayVertexBuffer(s.spriteArray, 0, s.spriteBuffer, 0, sizeof(detail::SpriteInstance));
    glVertexArrayBindingDivisor(s.spriteArray, 0, 1);
    for (GLuint a = 0; a < 4; ++a) {
        glEnableVertexArrayAttrib(s.spriteArray, a);
        glVertexArrayAttribFormat(s.spriteArray, a, 4, GL_FLOAT, GL_FALSE, a * 4 * sizeof(float));
        glVertexArrayAttribBinding(s.spriteArray, a, 0);
    }
    s.timer.create();
    glCreateBuffers(1, &s.frameBuffer);
    glNamedBufferData(s.frameBuffer, sizeof(detail::FrameBlock), nullptr, GL_DYNAMIC_DRAW);
    glCreateBuffers(1, &s.volumeBuffer);
    glNamedBufferData(s.volumeBuffer, sizeof(detail::VolumeBlock), nullptr, GL_DYNAMIC_DRAW);
    glCreateBuffers(1, &s.cloudBuffer);
    glNamedBufferData(s.cloudBuffer, sizeof(detail::CloudBlock), nullptr, GL_DYNAMIC_DRAW);
    glCreateBuffers(1, &s.shadowBuffer);
    glNamedBufferData(s.shadowBuffer, sizeof(detail::ShadowBlock), nullptr, GL_DYNAMIC_DRAW);
    glCreateBuffers(1, &s.froxels.block);
    glNamedBufferData(s.froxels.block, sizeof(detail::FroxelBlock), nullptr, GL_DYNAMIC_DRAW);
    glCreateBuffers(1, &s.objectBuffer);
    glNamedBufferData(s.objectBuffer, sizeof(detail::ObjectBlock), nullptr, GL_DYNAMIC_DRAW);
    detail::uploadEmitters(s, {});
    s.sunSky.upload(SkyTable{});
    s.moonSky.upload(SkyTable{});
    detail::drainGlErrors(s.desc.logger, "Renderer()");
}

Renderer::~Renderer() {
    Impl& s = *impl_;
    if (s.emptyVertexArray == 0) return;  // never initialised (no context)
    s.destroyTargets();
    s.destroyScene();
    detail::destroyCloudResources(s);
    detail::destroyShadowResources(s);
    detail::destroyFroxelResources(s);
    detail::destroySubtractResources(s);
    detail::destroyMeshVolumeResources(s);
    detail::destroyMesh(s.hull);
    glDeleteTextures(1, &s.whiteTexture);
    glDeleteVertexArrays(1, &s.spriteArray);
    glDeleteBuffers(1, &s.spriteBuffer);
    s.timer.destroy();
    glDeleteVertexArrays(1, &s.emptyVertexArray);
    for (GLuint b : {s.frameBuffer, s.volumeBuffer, s.objectBuffer, s.emitterBuffer}) glDeleteBuffers(1, &b);
}

bool Renderer::valid() const { return impl_->error.empty(); }
const std::string& Renderer::error() const { return impl_->error; }
const RenderStats& Renderer::stats() const { return impl_->stats; }
unsigned int Renderer::colourTexture() const { return impl_->colour; }
unsigned int Renderer::linearDepthTexture() const { return impl_->linearDepth; }

void Renderer::setScene(const SceneDesc& scene) {
    Impl& s = *impl_;
    if (s.emptyVertexArray == 0) return;
    detail::GlStateGuard guard(&s.desc.logger, s.desc.debugOutput, &s.stats.glErrors);
    s.destroyScene();
    std::map<const SceneTexture*, GLuint> uploaded;  // textures shared between meshes upload once
    for (const SceneMesh& mesh : scene.meshes) {
        if (mesh.indices.empty()) continue;
        const std::size_t n = mesh.positions.size();
        const bool indicesOk =
            std::all_of(mesh.indices.begin(), mesh.indices.end(), [n](std::uint32_t i) { return i < n; });
        if (!indicesOk || mesh.indices.size() % 3 != 0) {
            s.log(LogLevel::Warning, "renderer: a scene mesh has out-of-range indices; skipped");
            continue;
        }
        GpuMesh gpu = detail::uploadMesh(mesh, true);
        if (const SceneTexture* texture = mesh.baseColorTexture.get()) {
            auto found = uploaded.find(texture);
            if (found == uploaded.end()) {
                const GLuint name = detail::uploadTexture(*texture);
                if (name == 0) {
                    s.log(LogLevel::Warning,
                          "renderer: a base-colour texture has a bad size or pixel count; drawn untextured");
                } else {
                    s.textures.push_back(name);
                }
                found = uploaded.emplace(texture, name).first;
            }
            gpu.texture = found->second;
            gpu.block.baseColourTextured = gpu.texture != 0 ? 1.0f : 0.0f;
        }
        s.meshes.push_back(gpu);
    }
    for (const FogSprite& sprite : scene.sprites) {
        const bool ok = isFinite(sprite.position) && std::isfinite(sprite.radius) && sprite.radius > 0.0 &&
                        sprite.radius < 1e6 && std::fabs(sprite.position.x) < 1e15 &&
                        std::fabs(sprite.position.y) < 1e15 && std::fabs(sprite.position.z) < 1e15;
        if (!ok) continue;
        FogSprite clean = sprite;
        clean.albedo = glm::clamp(colourOf(sprite.albedo), 0.0, 1.0);
        clean.opacity = clampOr(sprite.opacity, 0.0, 1.0, 0.0);
        clean.emission = colourOf(sprite.emission);
        clean.fadeDistance = clampOr(sprite.fadeDistance, 1e-3, 1e6, 1.0);
        if (clean.opacity > 0.0) s.sprites.push_back(clean);
    }
    detail::drainGlErrors(s.desc.logger, "Renderer::setScene");
}

void Renderer::setSky(const SkyTable& sunTable, const SkyTable& moonTable) {
    Impl& s = *impl_;
    if (s.emptyVertexArray == 0) return;
    detail::GlStateGuard guard(&s.desc.logger, s.desc.debugOutput, &s.stats.glErrors);
    s.sunTable = sunTable;
    s.moonTable = moonTable;
    s.sunSky.upload(sunTable);
    s.moonSky.upload(moonTable);
    detail::forgetCloudHistory(s);  // the clouds' ambient light changed
    detail::drainGlErrors(s.desc.logger, "Renderer::setSky");
}

void Renderer::render(const Camera& camera, const PresetState& state, const FrameDesc& frame) {
    Impl& s = *impl_;
    if (s.emptyVertexArray == 0 || !s.shaders.complete()) return;
    detail::GlStateGuard guard(&s.desc.logger, s.desc.debugOutput, &s.stats.glErrors);
    s.render(camera, state, frame);
    s.stats.glErrors += detail::drainGlErrors(s.desc.logger, "Renderer::render");
}

void Renderer::Impl::render(const Camera& camera, const PresetState& state, const FrameDesc& frameDesc) {
    const int w = frameDesc.width > 0 ? std::min(frameDesc.width, 16384) : 1280;
    const int h = frameDesc.height > 0 ? std::min(frameDesc.height, 16384) : 720;
    ensureTargets(w, h, frameDesc.precision);
    stats = RenderStats{};
    const CameraFrame view = cameraFrame(camera);

    // Per-frame data: the emitters (their count goes into the frame block),
    // then the frame block.
    stats.emitters =
        detail::uploadEmitters(*this, frameDesc.passes.emitters ? state.emitters : std::vector<Emitter>{});
    detail::FrameBlockInputs inputs;
    inputs.width = w;
    inputs.height = h;
    inputs.emitterCount = stats.emitters;
    inputs.subtractActive = detail::frameHasSubtractVolumes(state, frameDesc);
    auto skyInput = [](const detail::SkyTextures& sky, const SkyTable& table) {
        detail::FrameSkyInput in;
        in.table = &table;
        in.valid = sky.valid;
        in.lightAzimuth = sky.lightAzimuth;
        in.columns = sky.columns;
        in.rows = sky.rows;
        in.warped = sky.warped;
        in.horizonRayleigh = sky.horizonRayleigh;
        in.horizonMie = sky.horizonMie;
        in.horizonMultiple = sky.horizonMultiple;
        return in;
    };
    inputs.sun = skyInput(sunSky, sunTable);
    inputs.moon = skyInput(moonSky, moonTable);
    // The cloud deck greys and dims the fog's colour and the ambient light
    // below it, while the layer is drawn (OvercastLight, aerial/evaluate.hpp).
    if (frameDesc.passes.clouds) {
        inputs.overcast = overcastLight(state, sunTable, moonTable);
        // Its clear sky is the frame block's too (the same integral of the same tables).
        if (inputs.sun.valid && inputs.moon.valid)
            inputs.clearSkyIrradiance = &inputs.overcast.clearSkyIrradiance;
    }
    const detail::FrameBlock block = detail::makeFrameBlock(camera, view, state, frameDesc, inputs);
    glNamedBufferSubData(frameBuffer, 0, sizeof block, &block);

    // The cloud layer at this time (the noise re-uploaded when the seed
    // changes; nothing at all while the layer is empty), with its volumes.
    const CloudField clouds = prepareClouds(state);
    static_assert(detail::kGpuCloudVolumes >= int(limits::kMaxCloudVolumes),
                  "the GPU takes every cloud volume a preset may hold");
    if (frameDesc.passes.clouds) detail::prepareCloudResources(*this, clouds);
    const detail::CloudBlock cloudBlock =
        detail::makeCloudBlock(clouds, state, frameDesc, view.eye, stats.cloudShadow);
    glNamedBufferSubData(cloudBuffer, 0, sizeof cloudBlock, &cloudBlock);

    // The shadow maps of the brighter light (nothing while it is below the
    // horizon, the pass is off or nothing casts).
    const bool casters = frameDesc.passes.scene &&
                         std::any_of(meshes.begin(), meshes.end(),
                                     [](const GpuMesh& m) { return m.alphaMode != AlphaMode::Blend; });
    const detail::ShadowBlock shadowBlock =
        detail::makeShadowBlock(view, state, frameDesc, casters, stats.shadowMap);
    if (stats.shadowMap.drawn) {
        detail::prepareShadowResources(*this, stats.shadowMap.resolution, stats.shadowMap.cascades);
    }
    glNamedBufferSubData(shadowBuffer, 0, sizeof shadowBlock, &shadowBlock);
    // No volumetric fog until its inject pass says otherwise (the transparent
    // and particle shaders test froxel.gridSize).
    const detail::FroxelBlock noFroxels{};
    glNamedBufferSubData(froxels.block, 0, sizeof noFroxels, &noFroxels);

    // The frame's bindings and the baseline state of render_pass.hpp.
    glBindBufferBase(GL_UNIFORM_BUFFER, detail::kFrameBinding, frameBuffer);
    glBindBufferBase(GL_UNIFORM_BUFFER, detail::kVolumeBinding, volumeBuffer);
    glBindBufferBase(GL_UNIFORM_BUFFER, detail::kObjectBinding, objectBuffer);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, detail::kEmitterBinding, emitterBuffer);
    glBindBufferBase(GL_UNIFORM_BUFFER, detail::kCloudBinding, cloudBuffer);
    glBindBufferBase(GL_UNIFORM_BUFFER, detail::kShadowBinding, shadowBuffer);
    glBindBufferBase(GL_UNIFORM_BUFFER, detail::kFroxelBinding, froxels.block);
    const GLuint unitTextures[detail::kTextureUnitCount] = {
        sunSky.rayleigh, sunSky.mie,   moonSky.rayleigh, moonSky.mie,
        linearDepth,     whiteTexture, sunSky.multiple,  moonSky.multiple};
    for (unsigned unit = 0; unit < detail::kTextureUnitCount; ++unit) {
        glBindTextureUnit(unit, unitTextures[unit]);
        glBindSampler(unit, 0);
    }
    const GLuint frameTextures[4][2] = {{detail::kCloudShapeUnit, cloudShape},
                                        {detail::kCloudDetailUnit, cloudDetail},
                                        {detail::kCloudShadowUnit, cloudShadowMap},
                                        {detail::kShadowMapUnit, stats.shadowMap.drawn ? shadowMap : 0u}};
    for (const auto& [unit, texture] : frameTextures) {
        glBindTextureUnit(unit, texture);
        glBindSampler(unit, 0);
    }
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_CLAMP);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_DEPTH_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glViewport(0, 0, w, h);

    // Clear: black, depth01 = 1 (far plane), depth buffer 1.
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, sceneTarget);
    const GLenum both[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glNamedFramebufferDrawBuffers(sceneTarget, 2, both);
    glDepthMask(GL_TRUE);
    const float black[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    const float far01[4] = {1.0f, 0.0f, 0.0f, 0.0f};
    glClearBufferfv(GL_COLOR, 0, black);
    glClearBufferfv(GL_COLOR, 1, far01);
    glClearBufferfi(GL_DEPTH_STENCIL, 0, 1.0f, 0);

    detail::FrameContext frame(camera, view, state, frameDesc, block, *this, stats);
    frame.clouds = &clouds;
    frame.overcast = &inputs.overcast;
    frame.cloudBlock = cloudBlock;
    frame.shadowBlock = shadowBlock;
    ++frameNumber;
    timer.beginFrame(frameDesc.gpuTimers);
    for (const detail::RenderPass* pass : kFramePasses) timer.run(*pass, frame);
    timer.endFrame(stats);
    if (block.subtractActive != 0) detail::readSubtractStats(*this, stats);
    // Meshes that no volume of this frame drew are released.
    detail::releaseUnusedFogMeshes(*this);
    if (!frame.cloudsDrawn()) detail::forgetCloudHistory(*this);  // the next amortised frame starts afresh
    if (!stats.froxels.drawn) froxels.valid = false;              // likewise the volumetric fog's
}

ShaderReloadResult Renderer::reloadShaders() { return reloadShaders(impl_->desc.shaderDirectory); }

ShaderReloadResult Renderer::reloadShaders(const std::string& directory) {
    Impl& s = *impl_;
    ShaderReloadResult result;
    if (s.emptyVertexArray == 0) {
        return {false, s.error};
    }
    detail::GlStateGuard guard(&s.desc.logger, s.desc.debugOutput, &s.stats.glErrors);
    result.ok = s.shaders.build(detail::directoryShaderReader(directory), result.log);
    if (!result.ok) {
        s.log(LogLevel::Warning,
              "renderer: shader reload failed, keeping the last good programs:\n" + result.log);
    }
    detail::drainGlErrors(s.desc.logger, "Renderer::reloadShaders");
    return result;
}

namespace {
Image readTexture(GLuint texture, int width, int height, int channels, GLenum format) {
    Image image;
    if (texture == 0) return image;
    image.width = width;
    image.height = height;
    image.channels = channels;
    const std::size_t rowFloats = static_cast<std::size_t>(width) * channels;
    std::vector<float> bottomUp(rowFloats * height);
    glGetTextureImage(texture, 0, format, GL_FLOAT, static_cast<GLsizei>(bottomUp.size() * sizeof(float)),
                      bottomUp.data());
    image.pixels.resize(bottomUp.size());
    for (int y = 0; y < height; ++y) {
        std::copy_n(bottomUp.data() + rowFloats * (height - 1 - y), rowFloats,
                    image.pixels.data() + rowFloats * y);
    }
    return image;
}
}  // namespace

Image Renderer::readColour() const {
    const Impl& s = *impl_;
    detail::GlStateGuard guard(&s.desc.logger, s.desc.debugOutput, &impl_->stats.glErrors);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    return readTexture(s.colour, s.width, s.height, 4, GL_RGBA);
}

Image Renderer::readCloudShadow() const {
    const Impl& s = *impl_;
    if (!s.stats.cloudShadow.drawn) return {};
    detail::GlStateGuard guard(&s.desc.logger, s.desc.debugOutput, &impl_->stats.glErrors);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    return readTexture(s.cloudShadowMap, detail::kCloudShadowSize, detail::kCloudShadowSize, 1, GL_RED);
}

Image Renderer::readLinearDepth() const {
    const Impl& s = *impl_;
    detail::GlStateGuard guard(&s.desc.logger, s.desc.debugOutput, &impl_->stats.glErrors);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    return readTexture(s.linearDepth, s.width, s.height, 1, GL_RED);
}

}  // namespace aerial::renderer
