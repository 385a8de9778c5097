// gpu_types.hpp — private: C++ mirrors of the shaders' std140 uniform blocks
// and std430 storage buffers, offsets checked against the GLSL layout rules.
#pragma once

#include <cstddef>
#include <cstdint>

namespace aerial::renderer::detail {

struct alignas(16) Vec4 {
    float x = 0.0f, y = 0.0f, z = 0.0f, w = 0.0f;
};
struct alignas(16) Mat4 {
    float m[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};  ///< column-major
};

/// Three floats, for a std140 / std430 vec3 that a scalar completes to 16
/// bytes (the member before it keeps it on a 16-byte boundary).
struct Vec3 {
    float x = 0.0f, y = 0.0f, z = 0.0f;
};
static_assert(sizeof(Vec3) == 12);

/// shaders/common/frame.glsl, FrameBlock (binding 0): the per-frame
/// uniforms of every pass (units and meanings there); built by
/// makeFrameBlock (frame_block.hpp).
struct FrameBlock {
    Mat4 clipFromWorld;
    Vec3 eye;  ///< [m]
    float farDistance = 0.0f;
    Vec3 forward;
    float nearDistance = 0.0f;
    Vec4 farCornerRays[4];
    float viewportSize[2] = {};   ///< [px]
    float viewportTexel[2] = {};  ///< 1 / viewportSize
    Vec3 sunDirection;
    float sunDiscChord = 0.0f;  ///< 2 sin(r/2), 0 = no disc
    Vec3 sunIlluminanceSpace;
    float padSun = 0.0f;
    Vec3 sunIlluminance;
    float sunDiscInverseSolidAngle = 0.0f;  ///< [1/sr]
    Vec3 moonDirection;
    float moonDiscChord = 0.0f;
    Vec3 moonIlluminanceSpace;
    float airglowScatteredFill = 0.0f;  ///< aerial::kAirglowScatteredFill
    Vec3 moonIlluminance;
    float moonDiscInverseSolidAngle = 0.0f;
    Vec3 sunHorizonRayleigh;
    float mieAnisotropy = 0.0f;
    Vec3 sunHorizonMie;
    float padSunMie = 0.0f;
    Vec3 moonHorizonRayleigh;
    float padMoonRayleigh = 0.0f;
    Vec3 moonHorizonMie;
    float padMoonMie = 0.0f;
    Vec3 skyAmbient;             ///< the clear sky's, on the clouds (and on the ground without them)
    float overcastCover = 0.0f;  ///< CloudOvercast::horizonCover: the deck in front of the fog's horizon
    float fogDensity = 0.0f;     ///< [1/m]
    float fogFalloff = 0.0f;     ///< [1/m]
    float fogBaseHeight = 0.0f;  ///< [m]
    float fogColourMode = 0.0f;  ///< 0 sky, 1 tinted, 2 custom
    Vec3 fogColour;
    float radianceCap = 0.0f;
    float sunTableAzimuth = 0.0f;   ///< [rad]
    float moonTableAzimuth = 0.0f;  ///< [rad]
    float sunTableColumns = 0.0f;
    float sunTableRows = 0.0f;
    std::int32_t emitterCount = 0;
    std::int32_t moonTableColumns = 0;
    std::int32_t moonTableRows = 0;
    /// 1 when the frame's subtract intervals (subtract_pass.cpp) are in the
    /// SubtractIntervals buffer (storage 4) for the fog passes to read, 0 else.
    std::int32_t subtractActive = 0;
    Vec3 starAxisX;
    float starIlluminance = 0.0f;  ///< 0: no stars
    Vec3 starAxisY;
    float starSigma = 0.0f;  ///< Gaussian radius of a star [rad]
    Vec3 starPole;
    float starNitsPerUnit = 0.0f;  ///< [cd/m^2] per radiance unit (kNitsPerRadianceUnit)
    Vec3 starTransmittance;
    float starDarkLimit = 0.0f;  ///< limitingMagnitude(0) (aerial/stars.hpp): the black sky's limit [mag]
    Vec3 sunHorizonMultiple;     ///< horizon average of I_ms [1/sr]
    float padSunMultiple = 0.0f;
    Vec3 moonHorizonMultiple;
    float padMoonMultiple = 0.0f;
    /// Where the discs are drawn: the apparent (refracted) directions.
    Vec3 sunDiscDirection;
    float moonLitFraction = 1.0f;  ///< illuminated fraction of the moon's disc, 0..1
    Vec3 moonDiscDirection;
    float padMoonDisc = 0.0f;
    /// Unit tangent on the sky at the moon towards the midpoint of its
    /// bright limb (the terminator lies across it).
    Vec3 moonBrightLimb;
    float padBrightLimb = 0.0f;
    /// 1 where a table's columns are warped (aerial/sky.hpp,
    /// skyTableColumnsWarped: its texels' azimuths are searched), else 0
    /// (uniform columns); the rows are always searched (sky_table.glsl).
    float sunTableWarped = 0.0f;
    float moonTableWarped = 0.0f;
    float padTableWarped0 = 0.0f;
    float padTableWarped1 = 0.0f;
    /// Ambient on an upward surface under the cloud deck (OvercastLight::
    /// groundIrradiance, with the airglow through the gaps); skyAmbient
    /// exactly without clouds.
    Vec3 groundAmbient;
    float padGroundAmbient = 0.0f;
    /// The deck's underside [E / sr] (OvercastLight::radiance).
    Vec3 overcastRadiance;
    /// CloudOvercast::skyCover: the deck over the whole sky (cosine-weighted),
    /// what a mirror sees of it looking up (atmosphere.glsl, overcastCoverTowards).
    float overcastSkyCover = 0.0f;
    // The light that reaches the fog (aerial/fog_light.hpp): the sky's two
    // spherical-harmonic bands a_0, a_1 (fogSkyLight), the clouds' mean
    // visibility of the sun and moon (fogDirectVisibility) and D of the
    // blend into the horizon [m].
    Vec3 fogSkyL0;
    float fogHorizonDistance = 0.0f;
    Vec3 fogSkyL1x;
    float fogDirectVisibility = 0.0f;
    Vec3 fogSkyL1y;
    float padFogSkyL1y = 0.0f;
    Vec3 fogSkyL1z;
    float padFogSkyL1z = 0.0f;
    /// The night sky's airglow above the atmosphere at the zenith
    /// (aerial::kAirglowZenithRadiance; its model: night_sky.hpp).
    Vec3 airglowZenithRadiance;
    float airglowShell = 0.0f;  ///< Rg / (Rg + kAirglowHeight), the van Rhijn factor's ratio
    /// A city's glow (night_sky.hpp, "Light pollution"): its radiance at the
    /// zenith (lamps' colour x Lz / kNitsPerRadianceUnit; 0 when off) and
    /// the city's unit direction on the horizon.
    Vec3 lightPollutionZenith;
    float lightPollutionUplightDepth = 0.0f;
    Vec3 lightPollutionCity;
    float padLightPollutionCity = 0.0f;
};
static_assert(offsetof(FrameBlock, clipFromWorld) == 0);
static_assert(offsetof(FrameBlock, eye) == 64);
static_assert(offsetof(FrameBlock, farDistance) == 76);
static_assert(offsetof(FrameBlock, forward) == 80);
static_assert(offsetof(FrameBlock, nearDistance) == 92);
static_assert(offsetof(FrameBlock, farCornerRays) == 96);
static_assert(offsetof(FrameBlock, viewportSize) == 160);
static_assert(offsetof(FrameBlock, viewportTexel) == 168);
static_assert(offsetof(FrameBlock, sunDirection) == 176);
static_assert(offsetof(FrameBlock, sunDiscChord) == 188);
static_assert(offsetof(FrameBlock, sunIlluminanceSpace) == 192);
static_assert(offsetof(FrameBlock, sunIlluminance) == 208);
static_assert(offsetof(FrameBlock, sunDiscInverseSolidAngle) == 220);
static_assert(offsetof(FrameBlock, moonDirection) == 224);
static_assert(offsetof(FrameBlock, moonDiscChord) == 236);
static_assert(offsetof(FrameBlock, moonIlluminanceSpace) == 240);
static_assert(offsetof(FrameBlock, moonIlluminance) == 256);
static_assert(offsetof(FrameBlock, moonDiscInverseSolidAngle) == 268);
static_assert(offsetof(FrameBlock, sunHorizonRayleigh) == 272);
static_assert(offsetof(FrameBlock, mieAnisotropy) == 284);
static_assert(offsetof(FrameBlock, sunHorizonMie) == 288);
static_assert(offsetof(FrameBlock, moonHorizonRayleigh) == 304);
static_assert(offsetof(FrameBlock, moonHorizonMie) == 320);
static_assert(offsetof(FrameBlock, skyAmbient) == 336);
static_assert(offsetof(FrameBlock, fogDensity) == 352);
static_assert(offsetof(FrameBlock, fogFalloff) == 356);
static_assert(offsetof(FrameBlock, fogBaseHeight) == 360);
static_assert(offsetof(FrameBlock, fogColourMode) == 364);
static_assert(offsetof(FrameBlock, fogColour) == 368);
static_assert(offsetof(FrameBlock, radianceCap) == 380);
static_assert(offsetof(FrameBlock, sunTableAzimuth) == 384);
static_assert(offsetof(FrameBlock, sunTableRows) == 396);
static_assert(offsetof(FrameBlock, emitterCount) == 400);
static_assert(offsetof(FrameBlock, moonTableColumns) == 404);
static_assert(offsetof(FrameBlock, moonTableRows) == 408);
static_assert(offsetof(FrameBlock, starAxisX) == 416);
static_assert(offsetof(FrameBlock, starIlluminance) == 428);
static_assert(offsetof(FrameBlock, starAxisY) == 432);
static_assert(offsetof(FrameBlock, starSigma) == 444);
static_assert(offsetof(FrameBlock, starPole) == 448);
static_assert(offsetof(FrameBlock, starTransmittance) == 464);
static_assert(offsetof(FrameBlock, starNitsPerUnit) == 460);
static_assert(offsetof(FrameBlock, starDarkLimit) == 476);
static_assert(offsetof(FrameBlock, sunHorizonMultiple) == 480);
static_assert(offsetof(FrameBlock, moonHorizonMultiple) == 496);
static_assert(offsetof(FrameBlock, sunDiscDirection) == 512);
static_assert(offsetof(FrameBlock, moonLitFraction) == 524);
static_assert(offsetof(FrameBlock, moonDiscDirection) == 528);
static_assert(offsetof(FrameBlock, moonBrightLimb) == 544);
static_assert(offsetof(FrameBlock, sunTableWarped) == 560);
static_assert(offsetof(FrameBlock, moonTableWarped) == 564);
static_assert(offsetof(FrameBlock, overcastCover) == 348);
static_assert(offsetof(FrameBlock, groundAmbient) == 576);
static_assert(offsetof(FrameBlock, overcastRadiance) == 592);
static_assert(offsetof(FrameBlock, overcastSkyCover) == 604);
static_assert(offsetof(FrameBlock, fogSkyL0) == 608);
static_assert(offsetof(FrameBlock, fogHorizonDistance) == 620);
static_assert(offsetof(FrameBlock, fogSkyL1x) == 624);
static_assert(offsetof(FrameBlock, fogDirectVisibility) == 636);
static_assert(offsetof(FrameBlock, fogSkyL1y) == 640);
static_assert(offsetof(FrameBlock, fogSkyL1z) == 656);
static_assert(offsetof(FrameBlock, airglowZenithRadiance) == 672);
static_assert(offsetof(FrameBlock, lightPollutionZenith) == 688);
static_assert(offsetof(FrameBlock, lightPollutionCity) == 704);
static_assert(sizeof(FrameBlock) == 720);

/// shaders/common/volume.glsl, VolumeBlock (binding 1): one fog volume.
struct VolumeBlock {
    Mat4 worldFromObject;      ///< the hull: position + rotation * halfExtents
    Vec3 objectFromWorldRow0;  ///< rows of S^-1 R^T
    float shape = 0.0f;        ///< 0 box, 1 ellipsoid, 2 mesh
    Vec3 objectFromWorldRow1;
    float density = 0.0f;  ///< b_v [1/m]
    Vec3 objectFromWorldRow2;
    float falloff = 0.0f;         ///< c_v [1/m]
    Vec3 position;                ///< centre [m]
    float gradientOffset = 0.0f;  ///< [m]
    Vec3 gradientDirection;       ///< unit
    float colourMode = 0.0f;      ///< 0 sky, 1 tinted, 2 custom
    Vec3 colour;
    float blend = 0.0f;         ///< 0 adds fog, 1 subtracts it (FogVolumeBlend)
    float edgeSoftness = 0.0f;  ///< sigma, 0..1 (0 hard; fog_volume.hpp "Soft edges")
    float padSoftness[3] = {};
};
static_assert(offsetof(VolumeBlock, objectFromWorldRow0) == 64);
static_assert(offsetof(VolumeBlock, shape) == 76);
static_assert(offsetof(VolumeBlock, objectFromWorldRow1) == 80);
static_assert(offsetof(VolumeBlock, density) == 92);
static_assert(offsetof(VolumeBlock, objectFromWorldRow2) == 96);
static_assert(offsetof(VolumeBlock, falloff) == 108);
static_assert(offsetof(VolumeBlock, position) == 112);
static_assert(offsetof(VolumeBlock, gradientOffset) == 124);
static_assert(offsetof(VolumeBlock, gradientDirection) == 128);
static_assert(offsetof(VolumeBlock, colourMode) == 140);
static_assert(offsetof(VolumeBlock, colour) == 144);
static_assert(offsetof(VolumeBlock, blend) == 156);
static_assert(offsetof(VolumeBlock, edgeSoftness) == 160);
static_assert(sizeof(VolumeBlock) == 176);

/// shaders/common/object.glsl, ObjectBlock (binding 3; scene and
/// transparent passes).
struct ObjectBlock {
    Mat4 worldFromObject;
    Mat4 normalFromObject;
    Vec3 albedo;
    float opacity = 1.0f;
    Vec3 emission;
    float specularFactor = 1.0f;
    float metallic = 0.0f;
    float roughness = 1.0f;
    float alphaCutoff = 0.5f;
    float alphaMode = 0.0f;           ///< 0 opaque, 1 mask, 2 blend
    float baseColourTextured = 0.0f;  ///< 1 when the base-colour texture (unit 5) is used
    float padFlags[3] = {};
    Vec3 boundsMin;  ///< world bounds [m]
    float padBoundsMin = 0.0f;
    Vec3 boundsMax;
    float padBoundsMax = 0.0f;
    Vec4 cornerFog[8];  ///< rgb: in-scatter S', a: transmittance T'
};
static_assert(offsetof(ObjectBlock, normalFromObject) == 64);
static_assert(offsetof(ObjectBlock, albedo) == 128);
static_assert(offsetof(ObjectBlock, opacity) == 140);
static_assert(offsetof(ObjectBlock, emission) == 144);
static_assert(offsetof(ObjectBlock, specularFactor) == 156);
static_assert(offsetof(ObjectBlock, metallic) == 160);
static_assert(offsetof(ObjectBlock, roughness) == 164);
static_assert(offsetof(ObjectBlock, alphaCutoff) == 168);
static_assert(offsetof(ObjectBlock, alphaMode) == 172);
static_assert(offsetof(ObjectBlock, baseColourTextured) == 176);
static_assert(offsetof(ObjectBlock, boundsMin) == 192);
static_assert(offsetof(ObjectBlock, boundsMax) == 208);
static_assert(offsetof(ObjectBlock, cornerFog) == 224);
static_assert(sizeof(ObjectBlock) == 352);

/// shaders/common/clouds.glsl, CloudBlock (binding 4): the cloud layer of
/// the frame (aerial::CloudField in float) and the cloud shadow map's
/// placement; built by makeCloudBlock (cloud_pass.cpp).
/// Cloud volumes the GPU takes: every one a preset may hold
/// (limits::kMaxCloudVolumes).
constexpr int kGpuCloudVolumes = 64;

struct CloudBlock {
    float shapeOffset[2] = {};   ///< wind offset mod the shape tile [m], [x, z]
    float detailOffset[2] = {};  ///< wind offset mod the detail tile [m]
    float planetRadius = 0.0f;   ///< Rg [m]
    float bottomM = 0.0f;        ///< [m] above the ground
    float thicknessM = 0.0f;     ///< [m]
    float coverage = 0.0f;       ///< 0..1
    float densityPerM = 0.0f;    ///< [1/m]
    float type = 0.0f;           ///< 0 stratus .. 1 cumulus
    float shapeScaleM = 0.0f;    ///< [m]
    float detailScaleM = 0.0f;   ///< [m]
    float erosion = 0.0f;
    float anisotropy = 0.0f;           ///< forward HG g
    std::int32_t steps = 0;            ///< view-ray samples (midpoint march)
    std::int32_t lightSteps = 0;       ///< samples towards the light
    Vec3 albedo;                       ///< single-scattering albedo, rgb
    std::int32_t volumeCount = 0;      ///< cloud volumes (always 0: not in presets yet)
    Vec3 rayleighScattering;           ///< sea level [1/m]
    float rayleighScaleHeight = 0.0f;  ///< [m]
    Vec3 mieExtinction;                ///< sea level [1/m]
    float mieScaleHeight = 0.0f;       ///< [m]
    float shadowOrigin[2] =
        {};  ///< world [x, z] of the shadow map's corner (texel (0, 0)'s outer corner) [m]
    float shadowExtentM = 0.0f;    ///< side of the square the map covers [m]
    float shadowActive = 0.0f;     ///< 1: scene lights multiply by the map's visibility
    Vec3 shadowToLight;            ///< unit direction the map was marched along
    std::int32_t shadowSteps = 0;  ///< samples per texel (kCloudSunVisibilitySteps)
    std::int32_t outputMode = 0;   ///< 0 lit, 1 transmittance only (CloudOutput)
    float shadowSize = 0.0f;       ///< texels per side of the map
    float padShadow[2] = {};
    Vec3 groundAlbedo;  ///< the atmosphere's ground albedo: light bounced up into the cloud bases
    float padGround = 0.0f;
    /// Cloud volumes, four vec4 each (clouds.glsl cloudCoverageAt):
    /// [4k] objectFromWorld row 0, w = shape (0 box, 1 ellipsoid); [4k+1]
    /// row 1, w = coverage; [4k+2] row 2, w = edge softness; [4k+3] centre [m].
    float volumeData[kGpuCloudVolumes * 4][4] = {};
};
static_assert(offsetof(CloudBlock, detailOffset) == 8);
static_assert(offsetof(CloudBlock, planetRadius) == 16);
static_assert(offsetof(CloudBlock, bottomM) == 20);
static_assert(offsetof(CloudBlock, thicknessM) == 24);
static_assert(offsetof(CloudBlock, coverage) == 28);
static_assert(offsetof(CloudBlock, densityPerM) == 32);
static_assert(offsetof(CloudBlock, type) == 36);
static_assert(offsetof(CloudBlock, shapeScaleM) == 40);
static_assert(offsetof(CloudBlock, detailScaleM) == 44);
static_assert(offsetof(CloudBlock, erosion) == 48);
static_assert(offsetof(CloudBlock, anisotropy) == 52);
static_assert(offsetof(CloudBlock, steps) == 56);
static_assert(offsetof(CloudBlock, lightSteps) == 60);
static_assert(offsetof(CloudBlock, albedo) == 64);
static_assert(offsetof(CloudBlock, volumeCount) == 76);
static_assert(offsetof(CloudBlock, rayleighScattering) == 80);
static_assert(offsetof(CloudBlock, rayleighScaleHeight) == 92);
static_assert(offsetof(CloudBlock, mieExtinction) == 96);
static_assert(offsetof(CloudBlock, mieScaleHeight) == 108);
static_assert(offsetof(CloudBlock, shadowOrigin) == 112);
static_assert(offsetof(CloudBlock, shadowExtentM) == 120);
static_assert(offsetof(CloudBlock, shadowActive) == 124);
static_assert(offsetof(CloudBlock, shadowToLight) == 128);
static_assert(offsetof(CloudBlock, shadowSteps) == 140);
static_assert(offsetof(CloudBlock, outputMode) == 144);
static_assert(offsetof(CloudBlock, shadowSize) == 148);
static_assert(offsetof(CloudBlock, groundAlbedo) == 160);
static_assert(offsetof(CloudBlock, volumeData) == 176);
static_assert(sizeof(CloudBlock) == 176 + 64 * kGpuCloudVolumes);

/// shaders/common/shadows.glsl, ShadowBlock (binding 5): the cascaded
/// shadow maps of the frame; built by makeShadowBlock (shadow_map_pass.cpp).
constexpr int kMaxShadowCascades = 4;

struct ShadowBlock {
    /// Per cascade: world [m] -> (u, v, depth) in [0, 1]^3 of its layer
    /// (orthographic along the light; depth 0 nearest the light).
    Mat4 shadowFromWorld[kMaxShadowCascades];
    float splitM[kMaxShadowCascades] = {};     ///< view depth where cascade k ends [m]
    float texelM[kMaxShadowCascades] = {};     ///< world size of a texel of cascade k [m]
    float depthPerM[kMaxShadowCascades] = {};  ///< depth units per metre along the light of cascade k
    Vec3 toLight;                              ///< unit, towards the casting light
    float castingLight = 0.0f;                 ///< 0 none, 1 the sun casts, 2 the moon casts
    std::int32_t cascadeCount = 0;
    float resolution = 0.0f;     ///< texels per side
    float blendFraction = 0.0f;  ///< share of a cascade's depth range blended into the next
    float padShadow = 0.0f;
};
static_assert(offsetof(ShadowBlock, splitM) == 256);
static_assert(offsetof(ShadowBlock, texelM) == 272);
static_assert(offsetof(ShadowBlock, depthPerM) == 288);
static_assert(offsetof(ShadowBlock, toLight) == 304);
static_assert(offsetof(ShadowBlock, castingLight) == 316);
static_assert(offsetof(ShadowBlock, cascadeCount) == 320);
static_assert(offsetof(ShadowBlock, resolution) == 324);
static_assert(offsetof(ShadowBlock, blendFraction) == 328);
static_assert(sizeof(ShadowBlock) == 336);

/// shaders/common/froxel.glsl, FroxelBlock (binding 6): the volumetric
/// fog's grid; built by makeFroxelBlock (froxel_pass.cpp).
struct FroxelBlock {
    std::int32_t gridSize[3] = {0, 0, 0};  ///< froxels x, y, slices
    std::int32_t volumeCount = 0;          ///< VolumeBlocks in the froxel volume buffer
    float pixelsPerFroxel = 8.0f;
    float z0 = 4.0f;        ///< [m]
    float farM = 0.0f;      ///< [m]
    float logScale = 0.0f;  ///< ln(1 + farM / z0)
    float castIsMoon = 0.0f;
    float sceneShadows = 0.0f;
    float cloudShadows = 0.0f;
    float jitter = 0.5f;
    float globalFog = 0.0f;  ///< 1: the global height fog is part of it (RenderPasses::globalFog)
    /// Temporal: the weight of this frame's visibility against the history
    /// (1: none read), and where the history's grid was: the previous
    /// frame's clip transform, eye and forward axis.
    float historyWeight = 1.0f;
    float padFroxel[2] = {};
    Mat4 previousClipFromWorld;
    Vec3 previousEye;
    float padPreviousEye = 0.0f;
    Vec3 previousForward;
    float padPreviousForward = 0.0f;
    /// The preset's volumetric settings (VolumetricFogParams): 1 for the
    /// custom phase, its anisotropy, the detail noise's amount and scale [m],
    /// and the noise's drift (the clouds' wind x time, reduced modulo its
    /// period) [m].
    float customPhase = 0.0f;
    float anisotropy = 0.0f;
    float noiseAmount = 0.0f;
    float noiseScaleM = 25.0f;
    Vec3 noiseOffset;
    float padNoise = 0.0f;
};
static_assert(offsetof(FroxelBlock, volumeCount) == 12);
static_assert(offsetof(FroxelBlock, pixelsPerFroxel) == 16);
static_assert(offsetof(FroxelBlock, logScale) == 28);
static_assert(offsetof(FroxelBlock, castIsMoon) == 32);
static_assert(offsetof(FroxelBlock, jitter) == 44);
static_assert(offsetof(FroxelBlock, globalFog) == 48);
static_assert(offsetof(FroxelBlock, historyWeight) == 52);
static_assert(offsetof(FroxelBlock, previousClipFromWorld) == 64);
static_assert(offsetof(FroxelBlock, previousEye) == 128);
static_assert(offsetof(FroxelBlock, previousForward) == 144);
static_assert(offsetof(FroxelBlock, customPhase) == 160);
static_assert(offsetof(FroxelBlock, noiseOffset) == 176);
static_assert(sizeof(FroxelBlock) == 192);

/// shaders/particles.glsl, per-instance vertex attributes (locations 0..3).
struct SpriteInstance {
    float centreRadius[4];
    float albedoOpacity[4];
    float emissionFade[4];
    float localFog[4];  ///< volumes and emitters at the centre: rgb S', a T'
};
static_assert(sizeof(SpriteInstance) == 64);

/// shaders/emitters.glsl and scene.glsl, EmitterGpu (std430, binding 2).
struct EmitterGpu {
    Vec3 position;           ///< [m]
    float intensity = 0.0f;  ///< i [radiance unit/m], the fog's in-scatter next to it, flash applied
    Vec3 colour;             ///< unit luminance (aerial::emitterColour)
    float attenuation = 0.0f;  ///< a [1/m^2]
    float illuminance = 0.0f;  ///< e = a I / kNitsPerRadianceUnit: E(r) = e / (1 + a r^2) on surfaces and clouds
    float extinction = 0.0f;   ///< sigma_t [1/m]: the light dimmed by exp(-sigma_t distance)
    float pad1 = 0.0f, pad2 = 0.0f;
};
static_assert(offsetof(EmitterGpu, intensity) == 12);
static_assert(offsetof(EmitterGpu, colour) == 16);
static_assert(offsetof(EmitterGpu, attenuation) == 28);
static_assert(offsetof(EmitterGpu, illuminance) == 32);
static_assert(offsetof(EmitterGpu, extinction) == 36);
static_assert(sizeof(EmitterGpu) == 48);

/// Binding points and texture units shared with the shaders.
constexpr unsigned kFrameBinding = 0;
constexpr unsigned kVolumeBinding = 1;
constexpr unsigned kEmitterBinding = 2;
constexpr unsigned kObjectBinding = 3;
constexpr unsigned kCloudBinding = 4;
constexpr unsigned kShadowBinding = 5;
constexpr unsigned kFroxelBinding = 6;
/// Shader storage: the fog volumes of the froxel grid (VolumeBlock[]).
constexpr unsigned kFroxelVolumeStorageBinding = 3;
constexpr unsigned kSunRayleighUnit = 0;
constexpr unsigned kSunMieUnit = 1;
constexpr unsigned kMoonRayleighUnit = 2;
constexpr unsigned kMoonMieUnit = 3;
constexpr unsigned kLinearDepthUnit = 4;
constexpr unsigned kBaseColourUnit = 5;
constexpr unsigned kTextureUnitCount = 8;
/// The cloud layer's units (bound by the frame next to the 8 above).
constexpr unsigned kCloudShapeUnit = 8;
constexpr unsigned kCloudDetailUnit = 9;
constexpr unsigned kCloudShadowUnit = 10;
/// The amortised cloud path's inputs (cloud_reconstruct.glsl).
constexpr unsigned kCloudTraceUnit = 11;
constexpr unsigned kCloudHistoryUnit = 12;
constexpr unsigned kPreviousDepthUnit = 13;
/// The cascaded shadow maps (GL_DEPTH_COMPONENT32F 2D array, comparison on).
constexpr unsigned kShadowMapUnit = 14;
/// The volumetric fog's integrated grid (froxel_apply.glsl): the amortised
/// clouds' units, bound by each pass that reads them (16 units per stage is
/// all OpenGL promises).
constexpr unsigned kFroxelLitSkyUnit = 11;
constexpr unsigned kFroxelSkyUnit = 12;
constexpr unsigned kFroxelOwnUnit = 13;
/// The previous frame's froxel visibility (froxel_inject.glsl, compute).
constexpr unsigned kFroxelHistoryUnit = 15;
/// Subtract volumes (subtract_pass.cpp, common/subtract.glsl), shader
/// storage: the union of the subtract volumes' intervals per pixel (K = 4
/// pairs, vec4[2] per pixel; read by the fog passes), the box and
/// ellipsoid subtract volumes (VolumeBlock[]), and the mesh subtract
/// volumes' crossings per pixel (a count, then kSubtractCrossings slots).
constexpr unsigned kSubtractIntervalStorageBinding = 4;
constexpr unsigned kSubtractVolumeStorageBinding = 5;
constexpr unsigned kSubtractCountStorageBinding = 6;
constexpr unsigned kSubtractCrossingStorageBinding = 7;
/// Disjoint subtract intervals kept per pixel (subtract_resolve.glsl).
constexpr int kSubtractIntervals = 4;
/// Mesh subtract crossings kept per pixel (subtract_crossings.glsl).
constexpr int kSubtractCrossings = 16;
/// The volumetric fog's mesh add volumes (mesh_volume_chords.glsl): the
/// chords of each froxel column's ray (kFroxelMeshChords vec2 per mesh
/// volume and column), and the mesh's positions and indices bound as
/// storage while its chords are found.
constexpr unsigned kFroxelMeshChordStorageBinding = 1;
constexpr unsigned kMeshPositionStorageBinding = 6;
constexpr unsigned kMeshIndexStorageBinding = 7;
constexpr int kFroxelMeshChords = 8;
/// A mesh add volume's accumulation target (R: sum of +-F, G: sum of the
/// signs; mesh_volume_accumulate.glsl), read by its composite on the
/// base-colour unit (free for every pass).
constexpr unsigned kMeshVolumeAccumulationUnit = kBaseColourUnit;

}  // namespace aerial::renderer::detail
