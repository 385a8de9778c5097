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
struct alignas(16) IVec4 {
    std::int32_t x = 0, y = 0, z = 0, w = 0;
};

/// shaders/common/frame.glsl, FrameBlock (binding 0).
struct FrameBlock {
    Mat4 clipFromWorld;
    Vec4 eyeFar;
    Vec4 forwardNear;
    Vec4 farCornerRays[4];
    Vec4 viewport;
    Vec4 sunDirection;
    Vec4 sunIlluminanceSpace;
    Vec4 sunIlluminance;
    Vec4 moonDirection;
    Vec4 moonIlluminanceSpace;
    Vec4 moonIlluminance;
    Vec4 sunHorizonRayleigh;
    Vec4 sunHorizonMie;
    Vec4 moonHorizonRayleigh;
    Vec4 moonHorizonMie;
    Vec4 skyAmbient;
    Vec4 fogParams;
    Vec4 fogColour;
    Vec4 skyTableMapping;
    IVec4 counts;
    Vec4 starAxisX;          ///< w: brightest star's illuminance (0: no stars)
    Vec4 starAxisY;          ///< w: Gaussian radius of a star [rad]
    Vec4 starPole;
    Vec4 starTransmittance;  ///< rgb: zenith transmittance
};
static_assert(offsetof(FrameBlock, clipFromWorld) == 0);
static_assert(offsetof(FrameBlock, eyeFar) == 64);
static_assert(offsetof(FrameBlock, forwardNear) == 80);
static_assert(offsetof(FrameBlock, farCornerRays) == 96);
static_assert(offsetof(FrameBlock, viewport) == 160);
static_assert(offsetof(FrameBlock, sunDirection) == 176);
static_assert(offsetof(FrameBlock, sunIlluminanceSpace) == 192);
static_assert(offsetof(FrameBlock, sunIlluminance) == 208);
static_assert(offsetof(FrameBlock, moonDirection) == 224);
static_assert(offsetof(FrameBlock, moonIlluminanceSpace) == 240);
static_assert(offsetof(FrameBlock, moonIlluminance) == 256);
static_assert(offsetof(FrameBlock, sunHorizonRayleigh) == 272);
static_assert(offsetof(FrameBlock, sunHorizonMie) == 288);
static_assert(offsetof(FrameBlock, moonHorizonRayleigh) == 304);
static_assert(offsetof(FrameBlock, moonHorizonMie) == 320);
static_assert(offsetof(FrameBlock, skyAmbient) == 336);
static_assert(offsetof(FrameBlock, fogParams) == 352);
static_assert(offsetof(FrameBlock, fogColour) == 368);
static_assert(offsetof(FrameBlock, skyTableMapping) == 384);
static_assert(offsetof(FrameBlock, counts) == 400);
static_assert(offsetof(FrameBlock, starAxisX) == 416);
static_assert(offsetof(FrameBlock, starTransmittance) == 464);
static_assert(sizeof(FrameBlock) == 480);

/// shaders/fog_volume.glsl, VolumeBlock (binding 1).
struct VolumeBlock {
    Mat4 worldFromObject;
    Vec4 objectFromWorld0;  ///< w: shape (0 box, 1 ellipsoid)
    Vec4 objectFromWorld1;  ///< w: density [1/m]
    Vec4 objectFromWorld2;  ///< w: falloff [1/m]
    Vec4 positionOffset;    ///< w: gradient offset [m]
    Vec4 gradientMode;      ///< w: colour mode
    Vec4 colour;
};
static_assert(offsetof(VolumeBlock, objectFromWorld0) == 64);
static_assert(offsetof(VolumeBlock, objectFromWorld1) == 80);
static_assert(offsetof(VolumeBlock, objectFromWorld2) == 96);
static_assert(offsetof(VolumeBlock, positionOffset) == 112);
static_assert(offsetof(VolumeBlock, gradientMode) == 128);
static_assert(offsetof(VolumeBlock, colour) == 144);
static_assert(sizeof(VolumeBlock) == 160);

/// shaders/common/object.glsl, ObjectBlock (binding 3; scene and
/// transparent passes).
struct ObjectBlock {
    Mat4 worldFromObject;
    Mat4 normalFromObject;
    Vec4 albedo;     ///< w: opacity
    Vec4 emission;   ///< w: specular factor
    Vec4 material;   ///< metallic, roughness, alpha cutoff, alpha mode (0, 1, 2)
    Vec4 flags;      ///< x: base-colour texture used
    Vec4 boundsMin;  ///< world bounds [m]
    Vec4 boundsMax;
    Vec4 cornerFog[8];  ///< rgb: in-scatter S', a: transmittance T'
};
static_assert(offsetof(ObjectBlock, normalFromObject) == 64);
static_assert(offsetof(ObjectBlock, albedo) == 128);
static_assert(offsetof(ObjectBlock, emission) == 144);
static_assert(offsetof(ObjectBlock, material) == 160);
static_assert(offsetof(ObjectBlock, flags) == 176);
static_assert(offsetof(ObjectBlock, boundsMin) == 192);
static_assert(offsetof(ObjectBlock, boundsMax) == 208);
static_assert(offsetof(ObjectBlock, cornerFog) == 224);
static_assert(sizeof(ObjectBlock) == 352);

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
    Vec4 positionIntensity;
    Vec4 colourAttenuation;
};
static_assert(offsetof(EmitterGpu, colourAttenuation) == 16);
static_assert(sizeof(EmitterGpu) == 32);

/// Binding points and texture units shared with the shaders.
constexpr unsigned kFrameBinding = 0;
constexpr unsigned kVolumeBinding = 1;
constexpr unsigned kEmitterBinding = 2;
constexpr unsigned kObjectBinding = 3;
constexpr unsigned kSunRayleighUnit = 0;
constexpr unsigned kSunMieUnit = 1;
constexpr unsigned kMoonRayleighUnit = 2;
constexpr unsigned kMoonMieUnit = 3;
constexpr unsigned kLinearDepthUnit = 4;
constexpr unsigned kBaseColourUnit = 5;
constexpr unsigned kTextureUnitCount = 6;

}  // namespace aerial::renderer::detail
