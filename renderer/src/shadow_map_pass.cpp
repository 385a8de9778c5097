// shadow_map_pass.cpp — pass 0b: the cascaded shadow maps of the sun, or of
// the moon when it is the brighter light (the light makeCloudBlock
// chooses), shaders/shadow_depth.glsl; the lookup is shaders/common/shadows.glsl.
//
// Cascades: the view from the near plane to ShadowMapSettings::maxDistanceM
// is cut at the practical splits (Zhang et al. 2006, "Parallel-split shadow
// maps"): z_k = lambda n (f / n)^(k / N) + (1 - lambda) (n + (f - n) k / N).
// Each cascade's slice (extended towards the eye by the blend band the
// shading mixes over) is enclosed in its bounding sphere, which depends only
// on the slice's depths and the field of view, so it neither grows nor
// shrinks as the camera turns; an orthographic projection along the light
// covers that sphere (2 r square, plus a margin of kMarginTexels), and its
// centre is snapped to whole texels in light space, so the texel grid stays
// fixed in the world while the camera moves (no shimmering). Depth runs
// along the light from r beyond the sphere on the light's side (nearest:
// depth 0) to the sphere's far side; casters nearer the light than that are
// clamped to depth 0 (GL_DEPTH_CLAMP), so they still shade.
//
// Reads:  the scene's opaque and masked meshes (masked ones discard by
//         their base-colour alpha), ShadowBlock (binding 5).
// Writes: gpu.shadowMap, one layer per cascade, through gpu.shadowTarget.
// GL state: binds the shadow target and a resolution^2 viewport, enables the
//         depth test (GL_LESS), depth clamp and a slope-scaled polygon
//         offset; on exit all three off and the sceneTarget and the frame's
//         viewport again (the baseline).
#include "frame_block.hpp"
#include "render_pass.hpp"

#include <aerial/evaluate.hpp>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>
#include <cmath>

namespace aerial::renderer::detail {
namespace {

/// Slope-scaled depth bias of the casters (glPolygonOffset factor, units):
/// the receiver side adds a normal offset (common/shadows.glsl).
constexpr GLfloat kSlopeBias = 1.5f;
constexpr GLfloat kConstantBias = 1.0f;
/// Texels of margin around each cascade's bounding sphere: the PCF
/// footprint (+-2 texels) and the normal offset stay inside the layer.
constexpr double kMarginTexels = 4.0;
/// Share of a cascade's depth range blended into the next one.
constexpr double kBlendFraction = 0.1;
/// The shadow_depth.glsl uniform that selects the cascade.
constexpr GLint kCascadeLocation = 0;

bool runs(const FrameContext& f) { return f.shadowBlock.castingLight > 0.5f && f.gpu.shadowTarget != 0; }

/// False when the world box lies wholly outside the cascade's square.
bool overlapsCascade(const Mat4& shadowFromWorld, const glm::dvec3& lo, const glm::dvec3& hi) {
    double uMin = 1e30, uMax = -1e30, vMin = 1e30, vMax = -1e30;
    const float* m = shadowFromWorld.m;
    for (int c = 0; c < 8; ++c) {
        const glm::dvec3 p((c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z);
        const double u = m[0] * p.x + m[4] * p.y + m[8] * p.z + m[12];
        const double v = m[1] * p.x + m[5] * p.y + m[9] * p.z + m[13];
        uMin = std::min(uMin, u), uMax = std::max(uMax, u), vMin = std::min(vMin, v),
        vMax = std::max(vMax, v);
    }
    return uMax >= 0.0 && uMin <= 1.0 && vMax >= 0.0 && vMin <= 1.0;
}

void draw(FrameContext& f) {
    RendererResources& gpu = f.gpu;
    const ShadowBlock& b = f.shadowBlock;
    const GLsizei size = static_cast<GLsizei>(b.resolution);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, gpu.shadowTarget);
    glViewport(0, 0, size, size);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glEnable(GL_DEPTH_CLAMP);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(kSlopeBias, kConstantBias);
    const GLuint program = gpu.shaders.program(Pass::ShadowDepth);
    glUseProgram(program);
    const float farDepth = 1.0f;
    for (int k = 0; k < b.cascadeCount; ++k) {
        glNamedFramebufferTextureLayer(gpu.shadowTarget, GL_DEPTH_ATTACHMENT, gpu.shadowMap, 0, k);
        glClearBufferfv(GL_DEPTH, 0, &farDepth);
        glProgramUniform1i(program, kCascadeLocation, k);
        for (const GpuMesh& m : gpu.meshes) {
            if (m.alphaMode == AlphaMode::Blend) continue;
            if (!overlapsCascade(b.shadowFromWorld[k], m.boundsMin, m.boundsMax)) continue;
            glNamedBufferSubData(gpu.objectBuffer, 0, sizeof m.block, &m.block);
            glBindTextureUnit(kBaseColourUnit, m.texture != 0 ? m.texture : gpu.whiteTexture);
            glBindVertexArray(m.vertexArray);
            glDrawElements(GL_TRIANGLES, m.indexCount, GL_UNSIGNED_INT, nullptr);
        }
    }
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_DEPTH_CLAMP);
    glDisable(GL_DEPTH_TEST);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, gpu.sceneTarget);
    glViewport(0, 0, static_cast<GLsizei>(f.block.viewportSize[0]),
               static_cast<GLsizei>(f.block.viewportSize[1]));
}

double sum(const glm::dvec3& c) { return c.x + c.y + c.z; }

}  // namespace

const RenderPass kShadowMapPass{&PassTimes::shadowMap, runs, draw};

ShadowBlock makeShadowBlock(const CameraFrame& view, const PresetState& state, const FrameDesc& frame,
                            bool hasCasters, ShadowMapStats& stats) {
    ShadowBlock b;
    stats = ShadowMapStats{};
    // The brighter light, as makeCloudBlock chooses it.
    const glm::dvec3 sunE = colourOf(state.sunLight.illuminance);
    const glm::dvec3 moonE = colourOf(state.moonLight.illuminance);
    const bool moon = sum(moonE) > sum(sunE);
    const glm::dvec3 toLight =
        unitOr(moon ? state.moonLight.body.direction : state.sunLight.body.direction, {0.0, 1.0, 0.0});
    stats.moon = moon;
    stats.toLight = toLight;
    b.toLight = toVec3(toLight);
    const ShadowMapSettings& settings = frame.shadowMap;
    if (!frame.passes.shadows || !hasCasters || !(toLight.y > 0.0) || !(sum(moon ? moonE : sunE) > 0.0)) {
        return b;
    }
    const int cascades = std::clamp(settings.cascades, 1, kMaxShadowCascades);
    const int resolution = std::clamp(settings.resolution, 256, 4096);
    const double lambda = clampOr(settings.splitLambda, 0.0, 1.0, 0.7);
    const double nearM = view.nearDistance;
    const double farM =
        std::max(std::min(clampOr(settings.maxDistanceM, 1.0, 1e7, 300.0), view.farDistance), 2.0 * nearM);

    // Half-diagonal of the view per unit of depth (the corner rays' slope).
    const glm::dvec3 corner = view.farCornerRays[3];
    const double cornerDepth = glm::dot(corner, view.forward);
    const double k = cornerDepth > 0.0 ? glm::length(corner - cornerDepth * view.forward) / cornerDepth : 1.0;
    const double k2 = k * k;

    // The light's frame: x and y across it, z towards it.
    const glm::dvec3 reference =
        std::fabs(toLight.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 0.0, 1.0);
    const glm::dvec3 lightY = glm::normalize(glm::cross(toLight, reference));
    const glm::dvec3 lightX = glm::cross(lightY, toLight);

    double previous = nearM, previousStart = nearM;
    for (int c = 0; c < cascades; ++c) {
        const double i = double(c + 1) / cascades;
        const double split = c + 1 == cascades ? farM
                                               : lambda * nearM * std::pow(farM / nearM, i) +
                                                     (1.0 - lambda) * (nearM + (farM - nearM) * i);
        // The slice this cascade must hold: from where the previous one
        // starts blending into it to its split.
        const double z0 = c == 0 ? nearM : previous - kBlendFraction * (previous - previousStart);
        const double z1 = split;
        // Its bounding sphere, centred on the view axis at depth centre:
        // equidistant from the near and far corner rings, or the far ring's
        // own sphere when that centre would lie beyond the far plane.
        double centre = 0.5 * (z0 + z1) * (1.0 + k2);
        double radius;
        if (centre >= z1) {
            centre = z1;
            radius = z1 * k;
        } else {
            radius = std::sqrt((centre - z0) * (centre - z0) + z0 * z0 * k2);
        }
        radius *= double(resolution) / (double(resolution) - 2.0 * kMarginTexels);
        const double texel = 2.0 * radius / resolution;
        const glm::dvec3 world = view.eye + centre * view.forward;
        const double cx = texel * std::round(glm::dot(world, lightX) / texel);
        const double cy = texel * std::round(glm::dot(world, lightY) / texel);
        const double cz = texel * std::round(glm::dot(world, toLight) / texel);
        const double top = cz + 2.0 * radius;  // r beyond the sphere on the light's side
        const double range = 3.0 * radius;
        // shadowFromWorld: u = (x - cx) / 2r + 1/2, v likewise, depth =
        // (top - z) / range, for the light-frame coordinates (x, y, z).
        glm::dmat4 m(0.0);
        for (int a = 0; a < 3; ++a) {
            m[a][0] = lightX[a] / (2.0 * radius);
            m[a][1] = lightY[a] / (2.0 * radius);
            m[a][2] = -toLight[a] / range;
        }
        m[3][0] = 0.5 - cx / (2.0 * radius);
        m[3][1] = 0.5 - cy / (2.0 * radius);
        m[3][2] = top / range;
        m[3][3] = 1.0;
        b.shadowFromWorld[c] = toMat4(m);
        b.splitM[c] = static_cast<float>(split);
        b.texelM[c] = static_cast<float>(texel);
        b.depthPerM[c] = static_cast<float>(1.0 / range);
        stats.splitM[c] = split;
        stats.texelM[c] = texel;
        previousStart = previous;
        previous = split;
    }
    b.castingLight = moon ? 2.0f : 1.0f;
    b.cascadeCount = cascades;
    b.resolution = float(resolution);
    b.blendFraction = static_cast<float>(kBlendFraction);
    stats.drawn = true;
    stats.cascades = cascades;
    stats.resolution = resolution;
    return b;
}

void prepareShadowResources(RendererResources& gpu, int resolution, int layers) {
    if (gpu.shadowMap != 0 && gpu.shadowMapSize == resolution && gpu.shadowMapLayers == layers) return;
    glDeleteTextures(1, &gpu.shadowMap);
    glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &gpu.shadowMap);
    glTextureStorage3D(gpu.shadowMap, 1, GL_DEPTH_COMPONENT32F, resolution, resolution, layers);
    glTextureParameteri(gpu.shadowMap, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(gpu.shadowMap, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(gpu.shadowMap, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(gpu.shadowMap, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTextureParameteri(gpu.shadowMap, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTextureParameteri(gpu.shadowMap, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    if (gpu.shadowTarget == 0) {
        glCreateFramebuffers(1, &gpu.shadowTarget);
        glNamedFramebufferDrawBuffer(gpu.shadowTarget, GL_NONE);
        glNamedFramebufferReadBuffer(gpu.shadowTarget, GL_NONE);
    }
    gpu.shadowMapSize = resolution;
    gpu.shadowMapLayers = layers;
}

void destroyShadowResources(RendererResources& gpu) {
    glDeleteTextures(1, &gpu.shadowMap);
    glDeleteFramebuffers(1, &gpu.shadowTarget);
    glDeleteBuffers(1, &gpu.shadowBuffer);
    gpu.shadowMap = gpu.shadowTarget = gpu.shadowBuffer = 0;
    gpu.shadowMapSize = gpu.shadowMapLayers = 0;
}

}  // namespace aerial::renderer::detail
