// renderer.cpp — the passes (sky, scene, global fog, fog volumes, emitters)
// into an HDR target; see <aerial/renderer/renderer.hpp> for the order and
// the compositing contract, and shaders/*.glsl for the per-pixel formulas.
#include <aerial/renderer/renderer.hpp>

#include "gl_state.hpp"
#include "gpu_types.hpp"
#include "shader_library.hpp"
#include "sky_textures.hpp"

#include <aerial/evaluate.hpp>
#include <aerial/sky.hpp>

#include <epoxy/gl.h>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>

namespace aerial::renderer {
namespace {

using detail::Mat4;
using detail::Vec4;

Vec4 vec4(const glm::dvec3& v, double w = 0.0) {
    return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z), static_cast<float>(w)};
}

Mat4 mat4(const glm::dmat4& m) {
    Mat4 out;
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) out.m[c * 4 + r] = static_cast<float>(m[c][r]);
    }
    return out;
}

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

double nonNegative(double x, double bound) {
    return (std::isfinite(x) && x > 0.0) ? std::min(x, bound) : 0.0;
}

glm::dvec3 colourOf(const glm::dvec3& c) {
    return {nonNegative(c.x, 1e30), nonNegative(c.y, 1e30), nonNegative(c.z, 1e30)};
}

glm::dvec3 unitOr(const glm::dvec3& v, const glm::dvec3& fallback) {
    if (!finite(v)) return fallback;
    const double m = std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
    if (!(m > 0.0)) return fallback;
    return glm::normalize(v / m);
}

/// Distance [m] from a point to an axis-aligned box (0 inside).
double distanceToBox(const glm::dvec3& p, const glm::dvec3& lo, const glm::dvec3& hi) {
    return glm::length(glm::max(glm::max(lo - p, p - hi), glm::dvec3(0.0)));
}

struct GpuMesh {
    GLuint vertexArray = 0;
    GLuint vertexBuffer = 0;
    GLuint indexBuffer = 0;
    GLsizei indexCount = 0;
    GLuint texture = 0;  ///< base colour (owned by Impl::textures); 0 = none
    AlphaMode alphaMode = AlphaMode::Opaque;
    glm::dvec3 boundsMin{0.0}, boundsMax{0.0};  ///< world bounds [m]
    detail::ObjectBlock block;
};

/// x when finite, clamped to [lo, hi]; `fallback` otherwise.
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
    gpu.block.worldFromObject = mat4(mesh.worldFromObject);
    gpu.block.normalFromObject = mat4(glm::dmat4(glm::inverseTranspose(glm::dmat3(mesh.worldFromObject))));
    gpu.block.albedo =
        vec4(glm::clamp(colourOf(mesh.albedo), 0.0, 1.0), clampOr(mesh.opacity, 0.0, 1.0, 1.0));
    gpu.block.emission = vec4(colourOf(mesh.emission), clampOr(mesh.specularFactor, 0.0, 1.0, 1.0));
    const double mode = mesh.alphaMode == AlphaMode::Mask    ? 1.0
                        : mesh.alphaMode == AlphaMode::Blend ? 2.0
                                                             : 0.0;
    gpu.block.material = {static_cast<float>(clampOr(mesh.metallic, 0.0, 1.0, 0.0)),
                          static_cast<float>(clampOr(mesh.roughness, 0.0, 1.0, 1.0)),
                          static_cast<float>(clampOr(mesh.alphaCutoff, 0.0, 1.0, 0.5)),
                          static_cast<float>(mode)};
    // World bounds of the referenced vertices (the transparent pass's fog corners).
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    for (std::uint32_t index : mesh.indices) {
        const glm::dvec3 p =
            glm::dvec3(mesh.worldFromObject * glm::dvec4(glm::dvec3(mesh.positions[index]), 1.0));
        if (!finite(p)) continue;
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    if (!(lo.x <= hi.x)) lo = hi = glm::dvec3(0.0);
    gpu.boundsMin = lo;
    gpu.boundsMax = hi;
    gpu.block.boundsMin = vec4(lo);
    gpu.block.boundsMax = vec4(hi);
    for (detail::Vec4& c : gpu.block.cornerFog) c = {0.0f, 0.0f, 0.0f, 1.0f};
    return gpu;
}

/// An sRGB8_A8 texture with a full mipmap chain, repeat wrapping, trilinear
/// filtering (0 for a malformed image). Sets the unpack state it needs and
/// restores it.
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

/// A fog volume reduced to what its pass needs (mirrors core's
/// prepareVolume: the same validity rules and sanitising).
struct PreparedVolume {
    detail::VolumeBlock block;
    double sortDistance = 0.0;
    std::size_t index = 0;
    bool inside = false;
};

bool prepareVolume(const FogVolume& v, std::size_t index, const CameraFrame& camera,
                   double nearCornerDistance, PreparedVolume& out) {
    constexpr double kMaxCoordinate = 1.0e30;
    const glm::dvec3 s = v.halfExtents;
    const bool extentsOk = s.x >= 1e-6 && s.y >= 1e-6 && s.z >= 1e-6 && s.x <= kMaxCoordinate &&
                           s.y <= kMaxCoordinate && s.z <= kMaxCoordinate;
    const glm::dquat q = v.rotation;
    const double qNorm2 = q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z;
    const bool positionOk = finite(v.position) && std::fabs(v.position.x) <= kMaxCoordinate &&
                            std::fabs(v.position.y) <= kMaxCoordinate &&
                            std::fabs(v.position.z) <= kMaxCoordinate;
    const double density = nonNegative(v.density, 1e150);
    if (!extentsOk || !(std::isfinite(qNorm2) && qNorm2 > 1e-200) || !positionOk || !(density > 0.0)) {
        return false;
    }
    const glm::dmat3 r = glm::mat3_cast(q / std::sqrt(qNorm2));
    const glm::dvec3 rows[3] = {r[0] / s.x, r[1] / s.y, r[2] / s.z};  // objectFromWorld = S^-1 R^T

    glm::dmat4 worldFromObject(1.0);
    for (int c = 0; c < 3; ++c) worldFromObject[c] = glm::dvec4(r[c] * s[c], 0.0);
    worldFromObject[3] = glm::dvec4(v.position, 1.0);

    const double shape = v.shape == FogVolumeShape::Ellipsoid ? 1.0 : 0.0;
    out.block.worldFromObject = mat4(worldFromObject);
    out.block.objectFromWorld0 = vec4(rows[0], shape);
    out.block.objectFromWorld1 = vec4(rows[1], density);
    out.block.objectFromWorld2 = vec4(rows[2], nonNegative(v.falloff, 1e150));
    const double offset = std::isfinite(v.gradientOffset) ? std::clamp(v.gradientOffset, -1e150, 1e150) : 0.0;
    out.block.positionOffset = vec4(v.position, offset);
    out.block.gradientMode =
        vec4(unitOr(v.gradientDirection, {0.0, 1.0, 0.0}), static_cast<double>(v.colourMode));
    out.block.colour = vec4(colourOf(v.colour));

    glm::dvec3 lo, hi;
    fogVolumeBounds(v, lo, hi);
    out.sortDistance = distanceToBox(camera.eye, lo, hi);
    out.index = index;
    // Inside mode when the hull may reach the eye's near-plane sphere: the
    // world distance to the hull is at least min(s) times the object-space
    // distance (conservative; inside mode is always correct, only slower).
    const glm::dvec3 o =
        glm::dvec3(glm::dot(rows[0], camera.eye - v.position), glm::dot(rows[1], camera.eye - v.position),
                   glm::dot(rows[2], camera.eye - v.position));
    const double objectDistance = glm::length(o - glm::clamp(o, glm::dvec3(-1.0), glm::dvec3(1.0)));
    out.inside = std::min({s.x, s.y, s.z}) * objectDistance <= 1.01 * nearCornerDistance;
    return true;
}

}  // namespace

std::string defaultShaderDirectory() { return AERIAL_SHADER_SOURCE_DIR; }

AtmosphereFrame atmosphereFrameFromState(const PresetState& state) {
    AtmosphereFrame f;
    f.sun = {state.sunLight.body.direction, state.sunLight.illuminanceSpace, state.sunLight.illuminance};
    f.moon = {state.moonLight.body.direction, state.moonLight.illuminanceSpace, state.moonLight.illuminance};
    f.mieAnisotropy = state.environment.atmosphere.mieAnisotropy;
    f.fog = state.environment.fog;
    f.fogColourMode = state.environment.fogColourMode;
    f.fogColour = state.environment.fogColour;
    f.volumes = state.volumes;
    f.emitters = state.emitters;
    f.starIlluminance = kStarIlluminance * starVisibility(state.sunLight.body.elevation);
    if (f.starIlluminance > 0.0) {
        f.celestial = celestialFrame(state.environment.location, state.timeHours);
        f.zenithTransmittance = state.zenithTransmittance;
    }
    return f;
}

/// sky.glsl's stars: the Gaussian radius never exceeds 0.4 of a cell's
/// height (2 / 512 in sin declination, ~0.0039 rad at the equator), so the
/// 3 x 3 cells summed hold the whole star; below ~250 rows a star is thus
/// narrower than a pixel.
constexpr double kStarMaxSigma = 0.0015;

double starVisibility(double sunElevation) {
    if (!std::isfinite(sunElevation)) return 0.0;
    const double x = std::clamp((2.0 - sunElevation * (180.0 / kPi)) / 12.0, 0.0, 1.0);
    return x * x * (3.0 - 2.0 * x);
}

FogSceneDesc fogSceneDesc(const AtmosphereFrame& frame, const SkyTable& sunTable, const SkyTable& moonTable) {
    FogSceneDesc d;
    d.heightFog = frame.fog;
    d.volumes = frame.volumes;
    d.emitters = frame.emitters;
    d.lights[0] = {frame.sun.direction, frame.sun.illuminanceSpace, sunTable.horizonRayleigh,
                   sunTable.horizonMie};
    d.lights[1] = {frame.moon.direction, frame.moon.illuminanceSpace, moonTable.horizonRayleigh,
                   moonTable.horizonMie};
    d.mieAnisotropy = frame.mieAnisotropy;
    d.heightFogColourMode = frame.fogColourMode;
    d.heightFogColour = frame.fogColour;
    return d;
}

struct Renderer::Impl {
    RendererDesc desc;
    std::string error;
    RenderStats stats;
    detail::ShaderLibrary shaders;

    GLuint emptyVertexArray = 0;
    GpuMesh hull;  // unit cube
    std::vector<GpuMesh> meshes;
    std::vector<GLuint> textures;  // base-colour textures of the meshes
    GLuint whiteTexture = 0;       // bound to the base-colour unit when a mesh has none
    std::vector<FogSprite> sprites;
    GLuint spriteArray = 0, spriteBuffer = 0;
    static constexpr int kTimers = 7;  // scene, sky, global fog, volumes, emitters, transparent, particles
    GLuint timerQueries[kTimers] = {};
    GLuint frameBuffer = 0, volumeBuffer = 0, objectBuffer = 0, emitterBuffer = 0;
    GLsizeiptr emitterCapacity = 0;

    int width = 0, height = 0;
    ColourPrecision precision = ColourPrecision::Half;
    GLuint colour = 0, linearDepth = 0, depth = 0;
    GLuint sceneTarget = 0, compositeTarget = 0;

    detail::SkyTextures sunSky, moonSky;
    SkyTable sunTable, moonTable;

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
        auto texture = [&](GLenum format) {
            GLuint t = 0;
            glCreateTextures(GL_TEXTURE_2D, 1, &t);
            glTextureStorage2D(t, 1, format, w, h);
            glTextureParameteri(t, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            glTextureParameteri(t, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
            glTextureParameteri(t, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
            glTextureParameteri(t, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
            return t;
        };
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

    void uploadEmitters(const std::vector<Emitter>& emitters, int& count) {
        std::vector<detail::EmitterGpu> gpu;
        gpu.reserve(emitters.size());
        for (const Emitter& e : emitters) {
            const bool positionOk = finite(e.position) && std::fabs(e.position.x) <= 1e30 &&
                                    std::fabs(e.position.y) <= 1e30 && std::fabs(e.position.z) <= 1e30;
            const double intensity = nonNegative(e.intensity, 1e30);
            if (!positionOk || !(intensity > 0.0)) continue;
            detail::EmitterGpu g;
            g.positionIntensity = vec4(e.position, intensity);
            g.colourAttenuation = vec4(colourOf(e.colour), nonNegative(e.attenuation, 1e30));
            gpu.push_back(g);
        }
        count = static_cast<int>(gpu.size());
        const auto bytes =
            static_cast<GLsizeiptr>(std::max<std::size_t>(gpu.size(), 1) * sizeof(detail::EmitterGpu));
        if (bytes > emitterCapacity) {
            glDeleteBuffers(1, &emitterBuffer);
            glCreateBuffers(1, &emitterBuffer);
            glNamedBufferData(emitterBuffer, bytes, nullptr, GL_DYNAMIC_DRAW);
            emitterCapacity = bytes;
        }
        if (!gpu.empty()) {
            glNamedBufferSubData(emitterBuffer, 0,
                                 static_cast<GLsizeiptr>(gpu.size() * sizeof(detail::EmitterGpu)),
                                 gpu.data());
        }
    }

    void destroyScene() {
        for (GpuMesh& m : meshes) destroyMesh(m);
        meshes.clear();
        if (!textures.empty()) glDeleteTextures(static_cast<GLsizei>(textures.size()), textures.data());
        textures.clear();
        sprites.clear();
    }

    /// The CPU fog of the volumes and emitters for the transparent meshes
    /// and the particles (the global fog is theirs on the GPU).
    FogScene localFog(const AtmosphereFrame& air, const FrameDesc& frameDesc) const {
        FogSceneDesc fogDesc = fogSceneDesc(air, sunTable, moonTable);
        fogDesc.heightFog.density = 0.0;
        if (!frameDesc.passes.volumes) fogDesc.volumes.clear();
        if (!frameDesc.passes.emitters) fogDesc.emitters.clear();
        return FogScene(fogDesc);
    }
    void drawTransparent(const FogScene& fog, const CameraFrame& cam);
    void drawParticles(const FogScene& fog, const CameraFrame& cam);

    void drawFullscreen(detail::Pass pass) {
        glUseProgram(shaders.program(pass));
        glBindVertexArray(emptyVertexArray);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }

    void render(const Camera& camera, const AtmosphereFrame& air, const FrameDesc& frameDesc);
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
    s.hull = uploadMesh(makeBoxMesh(glm::dvec3(0.0), glm::dvec3(1.0)), false);
    SceneTexture white;
    white.width = white.height = 1;
    white.rgba = {255, 255, 255, 255};
    s.whiteTexture = uploadTexture(white);
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
    glCreateQueries(GL_TIME_ELAPSED, Impl::kTimers, s.timerQueries);
    glCreateBuffers(1, &s.frameBuffer);
    glNamedBufferData(s.frameBuffer, sizeof(detail::FrameBlock), nullptr, GL_DYNAMIC_DRAW);
    glCreateBuffers(1, &s.volumeBuffer);
    glNamedBufferData(s.volumeBuffer, sizeof(detail::VolumeBlock), nullptr, GL_DYNAMIC_DRAW);
    glCreateBuffers(1, &s.objectBuffer);
    glNamedBufferData(s.objectBuffer, sizeof(detail::ObjectBlock), nullptr, GL_DYNAMIC_DRAW);
    int none = 0;
    s.uploadEmitters({}, none);
    s.sunSky.upload(SkyTable{});
    s.moonSky.upload(SkyTable{});
    detail::drainGlErrors(s.desc.logger, "Renderer()");
}

Renderer::~Renderer() {
    Impl& s = *impl_;
    if (s.emptyVertexArray == 0) return;  // never initialised (no context)
    s.destroyTargets();
    s.destroyScene();
    destroyMesh(s.hull);
    glDeleteTextures(1, &s.whiteTexture);
    glDeleteVertexArrays(1, &s.spriteArray);
    glDeleteBuffers(1, &s.spriteBuffer);
    glDeleteQueries(Impl::kTimers, s.timerQueries);
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
        GpuMesh gpu = uploadMesh(mesh, true);
        if (const SceneTexture* texture = mesh.baseColorTexture.get()) {
            auto found = uploaded.find(texture);
            if (found == uploaded.end()) {
                const GLuint name = uploadTexture(*texture);
                if (name == 0) {
                    s.log(LogLevel::Warning,
                          "renderer: a base-colour texture has a bad size or pixel count; drawn untextured");
                } else {
                    s.textures.push_back(name);
                }
                found = uploaded.emplace(texture, name).first;
            }
            gpu.texture = found->second;
            gpu.block.flags.x = gpu.texture != 0 ? 1.0f : 0.0f;
        }
        s.meshes.push_back(gpu);
    }
    for (const FogSprite& sprite : scene.sprites) {
        const bool ok = finite(sprite.position) && std::isfinite(sprite.radius) && sprite.radius > 0.0 &&
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
    detail::drainGlErrors(s.desc.logger, "Renderer::setSky");
}

void Renderer::render(const Camera& camera, const AtmosphereFrame& atmosphere, const FrameDesc& frame) {
    Impl& s = *impl_;
    if (s.emptyVertexArray == 0 || !s.shaders.complete()) return;
    detail::GlStateGuard guard(&s.desc.logger, s.desc.debugOutput, &s.stats.glErrors);
    s.render(camera, atmosphere, frame);
    s.stats.glErrors += detail::drainGlErrors(s.desc.logger, "Renderer::render");
}

void Renderer::Impl::render(const Camera& camera, const AtmosphereFrame& air, const FrameDesc& frameDesc) {
    const int w = frameDesc.width > 0 ? std::min(frameDesc.width, 16384) : 1280;
    const int h = frameDesc.height > 0 ? std::min(frameDesc.height, 16384) : 720;
    ensureTargets(w, h, frameDesc.precision);
    stats = RenderStats{};
    const CameraFrame cam = cameraFrame(camera);

    // Per-frame uniforms.
    detail::FrameBlock fb;
    fb.clipFromWorld = mat4(cam.clipFromWorld);
    fb.eyeFar = vec4(cam.eye, cam.farDistance);
    fb.forwardNear = vec4(cam.forward, cam.nearDistance);
    for (int k = 0; k < 4; ++k) fb.farCornerRays[k] = vec4(cam.farCornerRays[k]);
    fb.viewport = {float(w), float(h), 1.0f / float(w), 1.0f / float(h)};
    const glm::dvec3 sunDirection = unitOr(air.sun.direction, {0.0, 1.0, 0.0});
    const glm::dvec3 moonDirection = unitOr(air.moon.direction, {0.0, 1.0, 0.0});
    const double sunDisc = nonNegative(air.sunDiscRadius, 0.5);
    const double moonDisc = nonNegative(air.moonDiscRadius, 0.5);
    // Discs: chord 2 sin(r/2) and 1 / solid angle = 1 / (4 pi sin^2(r/2)),
    // in double (1 - cos r in float loses 3 digits at the sun's 0.27 deg).
    auto chord = [](double r) { return 2.0 * std::sin(0.5 * r); };
    auto perSolidAngle = [](double r) {
        const double s = std::sin(0.5 * r);
        return r > 0.0 ? 1.0 / (4.0 * kPi * s * s) : 0.0;
    };
    fb.sunDirection = vec4(sunDirection, chord(sunDisc));
    fb.sunIlluminanceSpace = vec4(colourOf(air.sun.illuminanceSpace));
    fb.sunIlluminance = vec4(colourOf(air.sun.illuminance), perSolidAngle(sunDisc));
    fb.moonDirection = vec4(moonDirection, chord(moonDisc));
    fb.moonIlluminanceSpace = vec4(colourOf(air.moon.illuminanceSpace));
    fb.moonIlluminance = vec4(colourOf(air.moon.illuminance), perSolidAngle(moonDisc));
    const double g = std::isfinite(air.mieAnisotropy) ? std::clamp(air.mieAnisotropy, -0.999, 0.999) : 0.0;
    fb.sunHorizonRayleigh = vec4(colourOf(sunSky.horizonRayleigh), g);
    fb.sunHorizonMie = vec4(colourOf(sunSky.horizonMie));
    fb.moonHorizonRayleigh = vec4(colourOf(moonSky.horizonRayleigh));
    fb.moonHorizonMie = vec4(colourOf(moonSky.horizonMie));
    const glm::dvec3 ambient =
        (sunSky.valid ? detail::skyIrradiance(sunTable, g, colourOf(air.sun.illuminanceSpace))
                      : glm::dvec3(0.0)) +
        (moonSky.valid ? detail::skyIrradiance(moonTable, g, colourOf(air.moon.illuminanceSpace))
                       : glm::dvec3(0.0));
    fb.skyAmbient = vec4(colourOf(ambient));
    const double baseHeight =
        std::isfinite(air.fog.baseHeight) ? std::clamp(air.fog.baseHeight, -1e30, 1e30) : 0.0;
    // Without the global fog pass, the transparent meshes and particles get
    // no global fog either (they read the same density).
    const double globalDensity = frameDesc.passes.globalFog ? nonNegative(air.fog.density, 1e30) : 0.0;
    fb.fogParams = {static_cast<float>(globalDensity), static_cast<float>(nonNegative(air.fog.falloff, 1e30)),
                    static_cast<float>(baseHeight), static_cast<float>(static_cast<int>(air.fogColourMode))};
    // Radiance cap per pass output: an RGBA16F target must never reach Inf
    // (the sun disc alone is ~3e5 for the default sun); see frame.glsl.
    const double cap = frameDesc.precision == ColourPrecision::Float ? 1e30 : 3.0e4;
    fb.fogColour = vec4(colourOf(air.fogColour), cap);
    fb.skyTableMapping = {static_cast<float>(sunSky.lightAzimuth), static_cast<float>(moonSky.lightAzimuth),
                          float(sunSky.columns), float(sunSky.rows)};
    int emitterCount = 0;
    uploadEmitters(frameDesc.passes.emitters ? air.emitters : std::vector<Emitter>{}, emitterCount);
    stats.emitters = emitterCount;
    fb.counts = {emitterCount, moonSky.columns, moonSky.rows, 0};
    // Stars: the celestial frame, the brightest star's illuminance and the
    // Gaussian radius of a star, sigma = 0.6 pixel (vertical angle / rows).
    const double starE = nonNegative(air.starIlluminance, 1e30);
    const double fov = std::isfinite(camera.verticalFov) ? std::clamp(camera.verticalFov, 1e-4, kPi - 1e-4) : 1.0;
    const double starSigma = std::min(0.6 * fov / double(h), kStarMaxSigma);
    fb.starAxisX = vec4(unitOr(air.celestial.equatorX, {1.0, 0.0, 0.0}), starE);
    fb.starAxisY = vec4(unitOr(air.celestial.equatorY, {0.0, 0.0, 1.0}), starSigma);
    fb.starPole = vec4(unitOr(air.celestial.pole, {0.0, 1.0, 0.0}));
    fb.starTransmittance = vec4(glm::clamp(colourOf(air.zenithTransmittance), 0.0, 1.0));
    glNamedBufferSubData(frameBuffer, 0, sizeof fb, &fb);

    glBindBufferBase(GL_UNIFORM_BUFFER, detail::kFrameBinding, frameBuffer);
    glBindBufferBase(GL_UNIFORM_BUFFER, detail::kVolumeBinding, volumeBuffer);
    glBindBufferBase(GL_UNIFORM_BUFFER, detail::kObjectBinding, objectBuffer);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, detail::kEmitterBinding, emitterBuffer);
    const GLuint unitTextures[detail::kTextureUnitCount] = {sunSky.rayleigh, sunSky.mie,  moonSky.rayleigh,
                                                            moonSky.mie,     linearDepth, whiteTexture};
    for (unsigned unit = 0; unit < detail::kTextureUnitCount; ++unit) {
        glBindTextureUnit(unit, unitTextures[unit]);
        glBindSampler(unit, 0);
    }

    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_CLAMP);
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

    // GPU timers (FrameDesc::gpuTimers): one GL_TIME_ELAPSED query per pass.
    bool timerUsed[kTimers] = {};
    double wallMs[kTimers] = {};
    int openTimer = -1;
    std::chrono::steady_clock::time_point passStart;
    auto beginTimer = [&](int k) {
        if (!frameDesc.gpuTimers) return;
        glFinish();
        passStart = std::chrono::steady_clock::now();
        glBeginQuery(GL_TIME_ELAPSED, timerQueries[k]);
        timerUsed[k] = true;
        openTimer = k;
    };
    auto endTimer = [&] {
        if (!frameDesc.gpuTimers) return;
        glEndQuery(GL_TIME_ELAPSED);
        glFinish();
        wallMs[openTimer] =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - passStart).count();
    };

    // 1. Opaque and masked meshes: colour and linear depth.
    if (frameDesc.passes.scene && !meshes.empty()) {
        beginTimer(0);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glDepthMask(GL_TRUE);
        glUseProgram(shaders.program(detail::Pass::Scene));
        for (const GpuMesh& m : meshes) {
            if (m.alphaMode == AlphaMode::Blend) continue;
            glNamedBufferSubData(objectBuffer, 0, sizeof m.block, &m.block);
            glBindTextureUnit(detail::kBaseColourUnit, m.texture != 0 ? m.texture : whiteTexture);
            glBindVertexArray(m.vertexArray);
            glDrawElements(GL_TRIANGLES, m.indexCount, GL_UNSIGNED_INT, nullptr);
        }
        endTimer();
    }

    // 2. Sky (colour only), drawn after the scene at the far plane (depth
    // 1, GL_LEQUAL): only pixels no geometry covered run the sky shader.
    if (frameDesc.passes.sky) {
        beginTimer(1);
        const GLenum colourOnly[2] = {GL_COLOR_ATTACHMENT0, GL_NONE};
        glNamedFramebufferDrawBuffers(sceneTarget, 2, colourOnly);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LEQUAL);
        glDepthMask(GL_FALSE);
        drawFullscreen(detail::Pass::Sky);
        glNamedFramebufferDrawBuffers(sceneTarget, 2, both);
        endTimer();
    }

    // 3..5 composite into the colour, reading linear depth.
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, compositeTarget);
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendEquationSeparate(GL_FUNC_ADD, GL_FUNC_ADD);
    // L <- src.rgb + L * src.a; alpha stays.
    glBlendFuncSeparate(GL_ONE, GL_SRC_ALPHA, GL_ZERO, GL_ONE);

    if (frameDesc.passes.globalFog && fb.fogParams.x > 0.0f) {
        beginTimer(2);
        glDisable(GL_DEPTH_TEST);
        drawFullscreen(detail::Pass::GlobalFog);
        endTimer();
    }

    if (frameDesc.passes.volumes && !air.volumes.empty()) {
        beginTimer(3);
        const double tanHalf = std::tan(0.5 * std::clamp(camera.verticalFov, 1e-4, 3.14149));
        const double aspect = camera.aspect > 0.0 && std::isfinite(camera.aspect) ? camera.aspect : 1.0;
        const double nearCorner =
            cam.nearDistance * std::sqrt(1.0 + tanHalf * tanHalf * (1.0 + aspect * aspect));
        std::vector<PreparedVolume> volumes;
        volumes.reserve(air.volumes.size());
        for (std::size_t i = 0; i < air.volumes.size(); ++i) {
            PreparedVolume p;
            if (prepareVolume(air.volumes[i], i, cam, nearCorner, p)) volumes.push_back(p);
        }
        // Back to front: farthest first, ties by ascending index (the lower
        // index composited first), as fog_query.hpp.
        std::stable_sort(
            volumes.begin(), volumes.end(),
            [](const PreparedVolume& a, const PreparedVolume& b) { return a.sortDistance > b.sortDistance; });
        glUseProgram(shaders.program(frameDesc.volumeMethod == VolumeMethod::RayMarched64
                                         ? detail::Pass::FogVolumeMarched
                                         : detail::Pass::FogVolume));
        glBindVertexArray(hull.vertexArray);
        glEnable(GL_DEPTH_CLAMP);  // hull parts beyond the far plane still rasterise (at depth 1)
        glEnable(GL_CULL_FACE);
        for (const PreparedVolume& v : volumes) {
            if (v.inside) {
                // Back faces, no depth test: every ray that meets the hull
                // leaves it through exactly one back face.
                glCullFace(GL_FRONT);
                glDisable(GL_DEPTH_TEST);
                ++stats.volumesDrawnInside;
            } else {
                // Front faces behind the scene cannot contribute.
                glCullFace(GL_BACK);
                glEnable(GL_DEPTH_TEST);
                glDepthFunc(GL_LEQUAL);
            }
            glNamedBufferSubData(volumeBuffer, 0, sizeof v.block, &v.block);
            glDrawElements(GL_TRIANGLES, hull.indexCount, GL_UNSIGNED_INT, nullptr);
            ++stats.volumesDrawn;
        }
        glDisable(GL_CULL_FACE);
        glDisable(GL_DEPTH_CLAMP);
        glDisable(GL_DEPTH_TEST);
        endTimer();
    }

    if (frameDesc.passes.emitters && emitterCount > 0) {
        beginTimer(4);
        glDisable(GL_DEPTH_TEST);
        glBlendFuncSeparate(GL_ONE, GL_ONE, GL_ZERO, GL_ONE);
        drawFullscreen(detail::Pass::Emitters);
        endTimer();
    }

    // 6, 7: premultiplied "over", depth-tested against the opaque scene,
    // without depth writes.
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    const bool anyTransparent = std::any_of(meshes.begin(), meshes.end(),
                                            [](const GpuMesh& m) { return m.alphaMode == AlphaMode::Blend; });
    const bool drawMeshes = frameDesc.passes.transparent && anyTransparent;
    const bool drawSprites = frameDesc.passes.particles && !sprites.empty();
    if (drawMeshes || drawSprites) {
        const FogScene fog = localFog(air, frameDesc);
        if (drawMeshes) {
            beginTimer(5);
            drawTransparent(fog, cam);
            endTimer();
        }
        if (drawSprites) {
            beginTimer(6);
            drawParticles(fog, cam);
            endTimer();
        }
    }
    glDisable(GL_DEPTH_TEST);

    if (frameDesc.gpuTimers) {
        double* out[kTimers] = {&stats.gpuMilliseconds.scene,     &stats.gpuMilliseconds.sky,
                                &stats.gpuMilliseconds.globalFog, &stats.gpuMilliseconds.volumes,
                                &stats.gpuMilliseconds.emitters,  &stats.gpuMilliseconds.transparent,
                                &stats.gpuMilliseconds.particles};
        double* wall[kTimers] = {&stats.wallMilliseconds.scene,     &stats.wallMilliseconds.sky,
                                 &stats.wallMilliseconds.globalFog, &stats.wallMilliseconds.volumes,
                                 &stats.wallMilliseconds.emitters,  &stats.wallMilliseconds.transparent,
                                 &stats.wallMilliseconds.particles};
        for (int k = 0; k < kTimers; ++k) {
            GLuint64 ns = 0;
            if (timerUsed[k]) glGetQueryObjectui64v(timerQueries[k], GL_QUERY_RESULT, &ns);
            *out[k] = static_cast<double>(ns) * 1e-6;
            *wall[k] = wallMs[k];
        }
        stats.timed = true;
    }
}

void Renderer::Impl::drawTransparent(const FogScene& fog, const CameraFrame& cam) {
    std::vector<std::pair<double, std::size_t>> order;  // (distance to the bounds centre, mesh)
    for (std::size_t i = 0; i < meshes.size(); ++i) {
        if (meshes[i].alphaMode != AlphaMode::Blend) continue;
        order.emplace_back(glm::length(0.5 * (meshes[i].boundsMin + meshes[i].boundsMax) - cam.eye), i);
    }
    if (order.empty()) return;
    // Back to front; equal distances keep the scene order.
    std::stable_sort(order.begin(), order.end(),
                     [](const auto& a, const auto& b) { return a.first > b.first; });
    // Volumes and emitters per object from the CPU (the global fog is per
    // vertex on the GPU and composited first, as fog_query.hpp's contract).
    glUseProgram(shaders.program(detail::Pass::Transparent));
    glEnable(GL_CULL_FACE);
    for (const auto& entry : order) {
        const GpuMesh& m = meshes[entry.second];
        detail::ObjectBlock block = m.block;
        for (int k = 0; k < 8; ++k) {
            const glm::dvec3 corner((k & 1) ? m.boundsMax.x : m.boundsMin.x,
                                    (k & 2) ? m.boundsMax.y : m.boundsMin.y,
                                    (k & 4) ? m.boundsMax.z : m.boundsMin.z);
            const FogQueryResult q = fog.query(cam.eye, corner);
            block.cornerFog[k] = vec4(colourOf(q.inScatter), std::clamp(q.transmittance.x, 0.0, 1.0));
        }
        glNamedBufferSubData(objectBuffer, 0, sizeof block, &block);
        glBindTextureUnit(detail::kBaseColourUnit, m.texture != 0 ? m.texture : whiteTexture);
        glBindVertexArray(m.vertexArray);
        // Back faces first, then front faces: a closed convex mesh blends in
        // the right order without sorting its triangles.
        glCullFace(GL_FRONT);
        glDrawElements(GL_TRIANGLES, m.indexCount, GL_UNSIGNED_INT, nullptr);
        glCullFace(GL_BACK);
        glDrawElements(GL_TRIANGLES, m.indexCount, GL_UNSIGNED_INT, nullptr);
        ++stats.transparentDrawn;
    }
    glDisable(GL_CULL_FACE);
}

void Renderer::Impl::drawParticles(const FogScene& fog, const CameraFrame& cam) {
    std::vector<std::pair<double, std::size_t>> order;  // (view depth, sprite)
    order.reserve(sprites.size());
    for (std::size_t i = 0; i < sprites.size(); ++i)
        order.emplace_back(glm::dot(sprites[i].position - cam.eye, cam.forward), i);
    std::stable_sort(order.begin(), order.end(),
                     [](const auto& a, const auto& b) { return a.first > b.first; });
    std::vector<detail::SpriteInstance> instances;
    instances.reserve(order.size());
    for (const auto& entry : order) {
        const FogSprite& p = sprites[entry.second];
        if (entry.first + p.radius < cam.nearDistance) continue;  // wholly behind the eye
        detail::SpriteInstance in;
        // The volumes' and emitters' fog in front of the sprite, at its centre.
        const FogQueryResult q = fog.query(cam.eye, p.position);
        const glm::dvec4 values[4] = {
            glm::dvec4(p.position, p.radius), glm::dvec4(p.albedo, p.opacity),
            glm::dvec4(p.emission, p.fadeDistance),
            glm::dvec4(colourOf(q.inScatter), std::clamp(q.transmittance.x, 0.0, 1.0))};
        float* targets[4] = {in.centreRadius, in.albedoOpacity, in.emissionFade, in.localFog};
        for (int a = 0; a < 4; ++a) {
            for (int c = 0; c < 4; ++c) targets[a][c] = static_cast<float>(values[a][c]);
        }
        instances.push_back(in);
    }
    if (instances.empty()) return;
    glNamedBufferData(spriteBuffer,
                      static_cast<GLsizeiptr>(instances.size() * sizeof(detail::SpriteInstance)),
                      instances.data(), GL_STREAM_DRAW);
    glUseProgram(shaders.program(detail::Pass::Particles));
    glBindVertexArray(spriteArray);
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(instances.size()));
    stats.spritesDrawn = static_cast<int>(instances.size());
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

Image Renderer::readLinearDepth() const {
    const Impl& s = *impl_;
    detail::GlStateGuard guard(&s.desc.logger, s.desc.debugOutput, &impl_->stats.glErrors);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    return readTexture(s.linearDepth, s.width, s.height, 1, GL_RED);
}

}  // namespace aerial::renderer
