// frame_block.hpp — private: the per-frame uniform block (FrameBlock,
// shaders/common/frame.glsl) from the camera, core's evaluated state and the
// frame settings. Pure: no GL, so a test checks it without a context.
#pragma once

#include "gpu_types.hpp"

#include <aerial/evaluate.hpp>
#include <aerial/renderer/camera.hpp>
#include <aerial/renderer/renderer.hpp>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace aerial::renderer::detail {

/// What the frame block needs from one light's sky tables (SkyTextures
/// after an upload, or the table itself).
struct FrameSkyInput {
    const SkyTable* table = nullptr;  ///< for the ambient irradiance; null = black
    bool valid = false;               ///< false: the table was empty or malformed
    double lightAzimuth = 0.0;        ///< [rad]
    int columns = 1;
    int rows = 1;
    bool warped = false;  ///< the table's columns are warped (skyTableColumnsWarped)
    glm::dvec3 horizonRayleigh{0.0};
    glm::dvec3 horizonMie{0.0};
    glm::dvec3 horizonMultiple{0.0};
};

/// Everything makeFrameBlock reads besides the camera and the state.
struct FrameBlockInputs {
    int width = 1;         ///< [px], after FrameDesc's defaults and clamps
    int height = 1;        ///< [px]
    int emitterCount = 0;  ///< emitters uploaded this frame (after validation)
    /// Subtract volumes cut the fog this frame (subtract_pass.cpp).
    bool subtractActive = false;
    FrameSkyInput sun;
    FrameSkyInput moon;
    /// The cloud deck's light (overcastLight of the state and these tables;
    /// the default: no clouds).
    OvercastLight overcast;
    /// The clear sky's irradiance when already computed for these tables
    /// (overcast.clearSkyIrradiance, valid tables only); null: makeFrameBlock
    /// integrates the tables itself (skyIrradiance).
    const glm::dvec3* clearSkyIrradiance = nullptr;
};

/// sky.glsl's stars: the Gaussian radius never exceeds 0.4 of a cell's
/// height (2 / 512 in sin declination, ~0.0039 rad at the equator), so the
/// 3 x 3 cells summed hold the whole star; below ~250 rows a star is thus
/// narrower than a pixel.
constexpr double kStarMaxSigma = 0.0015;

/// Brightest star's illuminance this frame: kStarIlluminance, 0 with
/// FrameDesc::stars off (which stars show is decided per pixel, sky.glsl).
double frameStarIlluminance(const PresetState& state, const FrameDesc& frame);

/// The std140 block of one frame: camera matrices and rays, lights (sanitised:
/// unit directions, non-negative finite colours), disc chords and inverse
/// solid angles, the Mie anisotropy (clamped to +-0.999), sky ambient, global
/// fog (density 0 when FrameDesc::passes.globalFog is off), radiance cap
/// (3e4 for ColourPrecision::Half, 1e30 for Float), table mapping, emitter
/// count and the star frame.
FrameBlock makeFrameBlock(const Camera& camera, const CameraFrame& view, const PresetState& state,
                          const FrameDesc& frame, const FrameBlockInputs& inputs);

/// The frame's shadow-map block (shadow_map_pass.cpp; no GL): the brighter
/// of sun and moon (as makeCloudBlock chooses), inactive when
/// RenderPasses::shadows is off, `hasCasters` is false, or that light is
/// below the horizon or dark; otherwise the cascades of `frame.shadowMap`
/// (practical splits up to maxDistanceM), each an orthographic projection
/// along the light fitted to its view slice's bounding sphere and snapped
/// to whole texels. Fills `stats`.
ShadowBlock makeShadowBlock(const CameraFrame& view, const PresetState& state, const FrameDesc& frame,
                            bool hasCasters, ShadowMapStats& stats);

/// Conversions of the blocks' fields from double precision.
Vec4 toVec4(const glm::dvec3& v, double w = 0.0);
Vec3 toVec3(const glm::dvec3& v);
Mat4 toMat4(const glm::dmat4& m);

/// Finite, non-negative, at most `bound`; 0 otherwise.
double nonNegative(double x, double bound);
/// Each channel through nonNegative(c, 1e30).
glm::dvec3 colourOf(const glm::dvec3& c);
/// v normalised, or `fallback` when v is zero or not finite.
glm::dvec3 unitOr(const glm::dvec3& v, const glm::dvec3& fallback);

}  // namespace aerial::renderer::detail
