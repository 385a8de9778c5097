// cloud_pass.cpp — pass 2b: the volumetric cloud layer, ray-marched per
// pixel at full resolution (the reference path; shaders/clouds.glsl and
// shaders/common/clouds.glsl) or, with FrameDesc::cloudQuality Amortised
// and lit output, the amortised path of cloud_amortised.cpp; and the cloud
// resources every pass shares: the noise textures of the layer's seed and
// the CloudBlock.
//
// Reads:  FrameBlock (eye, corner rays, lights, sky ambient), CloudBlock
//         (binding 4), the noise (units 8, 9), linear depth (unit 4), the
//         sky tables (units 0..3, for the air between viewer and cloud),
//         the emitters (binding 2: lightning inside the layer).
// Writes: the colour, through compositeTarget (no depth writes):
//         L <- L T_cloud + S_cloud (glBlendFunc(GL_ONE, GL_SRC_ALPHA), alpha
//         kept); in CloudOutput::Transmittance the pass writes (T, tau, 0)
//         over the colour without blending.
// GL state: beginComposite / endComposite. Runs only when the layer is
//         active (CloudField::active) and RenderPasses::clouds is on, so a
//         preset without clouds renders exactly as before.
#include "frame_block.hpp"
#include "render_pass.hpp"

#include <aerial/evaluate.hpp>
#include <aerial/limits.hpp>

#include <algorithm>
#include <cmath>

namespace aerial::renderer::detail {
namespace {

bool runs(const FrameContext& f) { return f.cloudsDrawn(); }

void draw(FrameContext& f) {
    if (f.desc.cloudOutput == CloudOutput::Lit && f.desc.cloudQuality == CloudQuality::Amortised) {
        drawAmortisedClouds(f);
        return;
    }
    f.stats.cloudHistory = CloudHistoryStats{};
    forgetCloudHistory(f.gpu);
    glProgramUniform3i(f.gpu.shaders.program(Pass::Clouds), 0, 0, 0, 0);  // the reference (uTrace)
    if (f.desc.cloudOutput == CloudOutput::Transmittance) {
        compositeFullscreen(f.gpu, Pass::Clouds, GL_ONE, GL_ZERO);
    } else {
        compositeFullscreen(f.gpu, Pass::Clouds, GL_ONE, GL_SRC_ALPHA);
    }
}

/// A noise field as RG32F with mipmaps: x and x^2 at level 0, their box
/// means above (common/clouds.glsl: the far clouds' variance mapping).
GLuint uploadNoise(const std::vector<float>& texels, int size) {
    GLuint t = 0;
    int levels = 1;
    while ((size >> levels) > 0) ++levels;
    std::vector<float> moments(texels.size() * 2);
    for (std::size_t i = 0; i < texels.size(); ++i) {
        moments[2 * i] = texels[i];
        moments[2 * i + 1] = texels[i] * texels[i];
    }
    glCreateTextures(GL_TEXTURE_3D, 1, &t);
    glTextureStorage3D(t, levels, GL_RG32F, size, size, size);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTextureSubImage3D(t, 0, 0, 0, 0, size, size, size, GL_RG, GL_FLOAT, moments.data());
    glGenerateTextureMipmap(t);
    glTextureParameteri(t, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(t, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R}) {
        glTextureParameteri(t, wrap, GL_REPEAT);
    }
    return t;
}

}  // namespace

const RenderPass kCloudPass{&PassTimes::clouds, runs, draw};

CloudBlock makeCloudBlock(const CloudField& field, const PresetState& state, const FrameDesc& frame,
                          const glm::dvec3& eye, CloudShadowStats& shadow) {
    CloudBlock b;
    const CloudParams& p = field.params;
    b.shapeOffset[0] = static_cast<float>(field.shapeOffset.x);
    b.shapeOffset[1] = static_cast<float>(field.shapeOffset.y);
    b.detailOffset[0] = static_cast<float>(field.detailOffset.x);
    b.detailOffset[1] = static_cast<float>(field.detailOffset.y);
    b.planetRadius = static_cast<float>(field.planetRadius);
    b.bottomM = static_cast<float>(p.bottomM);
    b.thicknessM = static_cast<float>(p.thicknessM);
    b.coverage = static_cast<float>(p.coverage);
    b.densityPerM = static_cast<float>(p.densityPerM);
    b.type = static_cast<float>(p.type);
    b.shapeScaleM = static_cast<float>(p.shapeScaleM);
    b.detailScaleM = static_cast<float>(p.detailScaleM);
    b.erosion = static_cast<float>(p.erosion);
    b.anisotropy =
        static_cast<float>(std::isfinite(p.anisotropy) ? std::clamp(p.anisotropy, 0.0, 0.95) : 0.6);
    b.steps = std::clamp(frame.cloudSteps, 1, 1024);
    b.lightSteps = 6;
    b.albedo = toVec3(glm::clamp(colourOf(p.albedo), 0.0, 1.0));
    // The cloud volumes core prepared (valid shapes only, sanitised), in order.
    b.volumeCount = int(std::min<std::size_t>(field.volumes.size(), kGpuCloudVolumes));
    for (int k = 0; k < b.volumeCount; ++k) {
        const CloudField::Volume& v = field.volumes[std::size_t(k)];
        const PreparedFogVolume& g = v.geometry;
        const glm::dvec3 rows[3] = {g.row0, g.row1, g.row2};
        const double w[3] = {g.shape == FogVolumeShape::Ellipsoid ? 1.0 : 0.0, v.coverage, v.edgeSoftness};
        for (int r = 0; r < 3; ++r) {
            float* out = b.volumeData[4 * k + r];
            out[0] = float(rows[r].x), out[1] = float(rows[r].y), out[2] = float(rows[r].z),
            out[3] = float(w[r]);
        }
        float* centre = b.volumeData[4 * k + 3];
        centre[0] = float(g.position.x), centre[1] = float(g.position.y), centre[2] = float(g.position.z);
    }
    const AtmosphereParams& air = state.environment.atmosphere;
    b.groundAlbedo = toVec3(glm::clamp(colourOf(air.groundAlbedo), 0.0, 1.0));
    b.rayleighScattering = toVec3(colourOf(air.rayleighScattering));
    b.rayleighScaleHeight = static_cast<float>(nonNegative(air.rayleighScaleHeight, 1e6));
    b.mieExtinction = toVec3(colourOf(air.mieExtinction));
    b.mieScaleHeight = static_cast<float>(nonNegative(air.mieScaleHeight, 1e6));

    // The shadow map: marched along the brighter light (the sun by day, the
    // moon by night), centred on the ground point the eye sees along it,
    // its corner snapped to whole texels in the frame that drifts with the
    // wind (the shape offset), so the shadows neither swim nor shimmer.
    const glm::dvec3 sunE = colourOf(state.sunLight.illuminance);
    const glm::dvec3 moonE = colourOf(state.moonLight.illuminance);
    const bool moon = moonE.x + moonE.y + moonE.z > sunE.x + sunE.y + sunE.z;
    const glm::dvec3 toLight =
        unitOr(moon ? state.moonLight.body.direction : state.sunLight.body.direction, {0.0, 1.0, 0.0});
    const double upward = std::max(toLight.y, 0.05);
    const double eyeHeight = std::isfinite(eye.y) ? std::clamp(eye.y, -1e6, 1e6) : 0.0;
    glm::dvec2 centre(eye.x - toLight.x * eyeHeight / upward, eye.z - toLight.z * eyeHeight / upward);
    if (!std::isfinite(centre.x) || !std::isfinite(centre.y)) centre = glm::dvec2(0.0);
    centre = glm::clamp(centre, glm::dvec2(-1e9), glm::dvec2(1e9));
    const double texel = kCloudShadowExtentM / kCloudShadowSize;
    const glm::dvec2 corner = centre - 0.5 * kCloudShadowExtentM - field.shapeOffset;
    const glm::dvec2 origin = field.shapeOffset + texel * glm::floor(corner / texel);
    shadow = CloudShadowStats{};
    shadow.drawn = field.active() && frame.passes.clouds;
    shadow.size = kCloudShadowSize;
    shadow.originX = origin.x;
    shadow.originZ = origin.y;
    shadow.extentM = kCloudShadowExtentM;
    shadow.toLight = toLight;
    b.shadowOrigin[0] = static_cast<float>(origin.x);
    b.shadowOrigin[1] = static_cast<float>(origin.y);
    b.shadowExtentM = static_cast<float>(kCloudShadowExtentM);
    b.shadowActive = shadow.drawn ? 1.0f : 0.0f;
    b.shadowToLight = toVec3(toLight);
    b.shadowSteps = kCloudSunVisibilitySteps;
    b.shadowSize = float(kCloudShadowSize);
    b.outputMode = frame.cloudOutput == CloudOutput::Transmittance ? 1 : 0;
    return b;
}

void prepareCloudResources(RendererResources& gpu, const CloudField& field) {
    if (!field.active() || !field.noise) return;
    if (gpu.cloudSeed != field.noise->seed || gpu.cloudShape == 0) {
        glDeleteTextures(1, &gpu.cloudShape);
        glDeleteTextures(1, &gpu.cloudDetail);
        gpu.cloudShape = uploadNoise(field.noise->shape, CloudNoise::kShapeSize);
        gpu.cloudDetail = uploadNoise(field.noise->detail, CloudNoise::kDetailSize);
        gpu.cloudSeed = field.noise->seed;
    }
    if (gpu.cloudShadowMap == 0) {
        glCreateTextures(GL_TEXTURE_2D, 1, &gpu.cloudShadowMap);
        glTextureStorage2D(gpu.cloudShadowMap, 1, GL_R32F, kCloudShadowSize, kCloudShadowSize);
        glTextureParameteri(gpu.cloudShadowMap, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTextureParameteri(gpu.cloudShadowMap, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTextureParameteri(gpu.cloudShadowMap, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTextureParameteri(gpu.cloudShadowMap, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glCreateFramebuffers(1, &gpu.cloudShadowTarget);
        glNamedFramebufferTexture(gpu.cloudShadowTarget, GL_COLOR_ATTACHMENT0, gpu.cloudShadowMap, 0);
    }
}

void destroyCloudResources(RendererResources& gpu) {
    glDeleteTextures(1, &gpu.cloudShape);
    glDeleteTextures(1, &gpu.cloudDetail);
    glDeleteTextures(1, &gpu.cloudShadowMap);
    glDeleteFramebuffers(1, &gpu.cloudShadowTarget);
    glDeleteBuffers(1, &gpu.cloudBuffer);
    gpu.cloudShape = gpu.cloudDetail = gpu.cloudShadowMap = gpu.cloudShadowTarget = gpu.cloudBuffer = 0;
    gpu.cloudSeed = -1;
    destroyCloudHistory(gpu);
}

}  // namespace aerial::renderer::detail
