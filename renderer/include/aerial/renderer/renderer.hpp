// aerial/renderer/renderer.hpp — the OpenGL 4.5 renderer: opaque scene with
// linear depth, sky, global height fog, fog volumes and emitters into an HDR
// frame (DESIGN.md; Wenzel 2006). It renders with whatever context is
// current, into its own framebuffers, and saves and restores the GL state it
// touches.
//
// Usage:
//   aerial::renderer::RendererDesc desc;
//   desc.logger = {myLogFunction, myUserData};
//   aerial::renderer::Renderer renderer(desc);   // a GL 4.5 context is current
//   if (!renderer.valid()) fail(renderer.error());
//   renderer.setScene(aerial::renderer::makeBuiltinScene());
//   renderer.setSky(sunSolver.table(), moonSolver.table());    // when re-solved
//   renderer.render(camera, state, {320, 180});   // state: core's PresetState
//   aerial::renderer::Image hdr = renderer.readColour();
//
// Passes, in order, into one HDR colour target (DESIGN.md "Global height fog"
// and fog_query.hpp's compositing contract):
//   1. scene: opaque and alpha-masked meshes (glTF metallic-roughness,
//      shaders/common/shading.glsl), writing colour and normalised linear
//      depth;
//   2. sky where no geometry is (a full-screen triangle at the far plane,
//      depth-tested): both tables with per-pixel phase functions, sun and
//      moon discs;
//   2c. (subtract volumes only, analytic fog) the union of the subtract
//      volumes along each pixel's ray, up to 4 disjoint intervals a pixel
//      (subtract_pass.cpp; RenderStats counts the pixels beyond);
//   3. global fog: L <- L T_g + L_fog (1 - T_g), its integral without the
//      subtract union;
//   4. fog volumes that add fog, back to front: L <- L T_v + C_v (1 - T_v),
//      each integral without the subtract union; a mesh volume is its
//      faces' signed antiderivatives summed per pixel (back faces minus
//      front faces, polygonal fog volumes), then composited in its place;
//   5. emitters: L <- L + S_e;
//   6. transparent (alpha-blend) meshes, back to front by the distance from
//      the eye to the centre of their world bounds (farthest first; back
//      faces of a mesh before its front faces): global fog per vertex (the
//      same integral as pass 3 for the optical depth, its colour per pixel
//      with the phase functions), fog volumes and emitters per object from the
//      CPU fog query (FogScene) at the 8 corners of the mesh's world bounds,
//      interpolated trilinearly per fragment (Wenzel 2006); with subtract
//      volumes the global fog per fragment instead, along the pixel's ray
//      without their union (the soft particles too);
//   0. (clouds only) the cloud shadow map: optical depth from the ground
//      towards the sun through the cloud layer (cloud_shadow.glsl); the
//      scene, transparent and particle lighting multiply the sun and moon by
//      its visibility;
//   0b. (shadows on, the sun or moon above the horizon) the cascaded shadow
//      maps: the opaque and masked meshes' depth seen from the brighter of
//      the two lights, 1..4 cascades fitted to slices of the view
//      (shadow_map_pass.cpp); the scene, transparent and particle lighting
//      multiply that light by its filtered visibility;
//   2b. (clouds only) the cloud layer, ray-marched per pixel over the sky
//      and the scene, before the global fog (clouds.glsl); or, with
//      FrameDesc::cloudQuality Amortised, one pixel per block traced and the
//      rest reprojected from the previous frames (cloud_reconstruct.glsl);
//   7. soft fog particles (SceneDesc::sprites), back to front, faded by the
//      scene depth; global fog per vertex, the volumes' and emitters' fog
//      from one CPU query per sprite (at its centre).
// Ordering of volumes: sorted once per frame by the distance from the eye to
// each volume's world bounds (0 when inside), farthest first, ties by index.
// fog_query.hpp sorts per segment by the clipped entry distance; the two
// orders agree on every pixel whose ray crosses volumes whose bounds do not
// overlap along it, in particular for disjoint volumes seen from outside, and
// trivially for one volume. For interpenetrating volumes the per-pixel order
// may differ.
#pragma once

#include <aerial/fog_query.hpp>
#include <aerial/renderer/camera.hpp>
#include <aerial/renderer/image.hpp>
#include <aerial/renderer/log.hpp>
#include <aerial/renderer/scene.hpp>
#include <aerial/sun.hpp>

#include <glm/vec3.hpp>

#include <memory>
#include <string>
#include <vector>

namespace aerial {
struct PresetState;
struct SkyTable;
}  // namespace aerial

namespace aerial::renderer {

/// How the renderer is created. Zero values mean defaults.
struct RendererDesc {
    Logger logger;
    /// Directory of the GLSL sources for reloadShaders() (hot reload); ""
    /// = defaultShaderDirectory(). Creation always uses the sources embedded
    /// at build time.
    std::string shaderDirectory;
    /// Route GL debug output (KHR_debug) to the logger while the renderer
    /// works (the caller's callback is restored afterwards).
    bool debugOutput = true;
};

/// The source tree's shaders/ directory, compiled in (for hot reload in a
/// development build).
std::string defaultShaderDirectory();

/// Illuminance of the brightest procedural star (V magnitude -1.5, Sirius):
/// aerial::starIlluminanceLux(-1.5) = 1.01e-5 lx in illuminance units of
/// kNitsPerRadianceUnit lx (aerial/stars.hpp, exposure.hpp). Each star of
/// the field has its magnitude's share of it (shaders/sky.glsl).
constexpr double kStarIlluminance = 2.022384e-9;

/// The colour target's format. Radiance is physical in Aerial's unit
/// (5000 cd/m^2, aerial/exposure.hpp) day and night: a moonless night sky
/// is ~4e-8 of it and its twilight remnant 1e-9, below the smallest half
/// float (6e-8 subnormal, 6e-5 normal), where RGBA16F quantises the sky
/// into coloured bands. So the default is RGBA32F.
enum class ColourPrecision {
    /// RGBA16F: half the bandwidth, for daylight captures or a caller
    /// that scales its lights into the half range itself (pre-exposure).
    /// Every pass output is capped at 3e4 so no pixel overflows the half
    /// range (the sun disc, ~3e5 for the default sun, is clipped there).
    Half,
    /// RGBA32F (default): the editor, captures and comparisons against the
    /// CPU reference (cap 1e30).
    Float,
};

/// Which passes run (all by default).
struct RenderPasses {
    bool sky = true;
    bool scene = true;
    bool globalFog = true;
    bool volumes = true;
    bool emitters = true;
    /// Alpha-blended meshes. Their fog follows the other switches: no global
    /// fog when globalFog is off, no volume or emitter fog when those are off.
    bool transparent = true;
    bool particles = true;  ///< soft fog particles (SceneDesc::sprites)
    /// The volumetric cloud layer (state.environment.clouds) and its shadow
    /// on the scene; neither runs while the layer is empty (coverage 0).
    bool clouds = true;
    /// Cascaded shadow maps of the sun (or of the moon when it is the
    /// brighter light) on the scene, transparent meshes and particles
    /// (FrameDesc::shadowMap). Off, or with that light below the horizon:
    /// the frame is exactly as without the pass.
    bool shadows = true;
};

/// The cascaded shadow maps (shadow_map_pass.cpp, shaders/shadow_depth.glsl,
/// shaders/common/shadows.glsl). Out-of-range values are clamped.
struct ShadowMapSettings {
    /// Texels per side of each cascade, 256..4096. Default 1024: on Mesa's
    /// llvmpipe the depth pass of the built-in scene costs ~32 ms at 1024
    /// and ~98 ms at 2048 (three cascades), the scene pass's lookups +4 ms
    /// (320 x 180) to +33 ms (1280 x 720); 2048 is the choice on a GPU.
    int resolution = 1024;
    /// Cascades over the view, 1..4. Default 3.
    int cascades = 3;
    /// View depth [m] where the last cascade ends (and shadows fade out);
    /// at most the camera's far distance, at least 1 m. Default 300 m (the
    /// built-in scene is 800 m across).
    double maxDistanceM = 300.0;
    /// Practical split scheme (Zhang et al. 2006): each split is
    /// lambda x logarithmic + (1 - lambda) x uniform, 0..1. Default 0.7.
    double splitLambda = 0.7;
};

/// What the cloud pass writes.
enum class CloudOutput {
    Lit,  ///< clouds lit and composited over the frame (default)
    /// Test mode: rgb = (T, optical depth, 0) of the view ray through the
    /// clouds, written over the colour without blending (no lighting, no
    /// air); T matches aerial::cloudTransmittance with FrameDesc::cloudSteps.
    Transmittance,
};

/// How the cloud pass spends its time (CloudOutput::Lit only; the
/// transmittance test mode is always the reference).
enum class CloudQuality {
    /// Every pixel ray-marched every frame (default: `aerial render`, the
    /// goldens, comparisons).
    Reference,
    /// One pixel of each FrameDesc::cloudAmortisedBlock^2 block traced per frame,
    /// the others reprojected from the previous frames (Schneider 2015/2017,
    /// Nubis: 1/16 of the pixels per frame) and converging on the reference
    /// for a still view; see cloud_amortised.cpp. The editor's viewport.
    Amortised,
};

/// How the fog-volume pass integrates a volume's density.
enum class VolumeMethod {
    Analytic,      ///< the closed form (default; DESIGN.md "Fog volumes")
    RayMarched64,  ///< 64-step midpoint sum: the benchmark's reference
};

/// How the fog (global height fog, box and ellipsoid volumes, the emitters'
/// lit fog) is drawn.
enum class FogMode {
    /// Closed-form integrals per pixel (DESIGN.md; default): exact, the
    /// reference, and the cheap tier; no shadows in the fog.
    Analytic,
    /// A froxel grid fitted to the view (froxel_pass.cpp; Wronski 2014,
    /// Hillaire 2015): density injected from the same closed forms, lit per
    /// froxel with the casting light's visibility (shadow maps x cloud
    /// shadows: light shafts), integrated front to back, applied per pixel.
    /// With every shadow off it equals Analytic up to the grid's
    /// interpolation (see FroxelSettings). Beyond FroxelSettings::farM the
    /// global fog continues analytically; volumes there are not drawn.
    Volumetric,
};

/// The volumetric fog's grid (FogMode::Volumetric). Out-of-range values are clamped.
struct FroxelSettings {
    /// Side of a froxel [px], 4..32. Default 8 (Unreal, HDRP).
    int pixelsPerFroxel = 8;
    /// Depth slices, 16..256, exponentially distributed (common/froxel.glsl).
    /// Default 128: without shadows the error against the analytic fog is the
    /// same from 32 to 256 slices (a slice's optical depth is exact; what is
    /// left is the 8 px interpolation, mean 0.05-0.6 %); a shaft's edge falls
    /// within one slice, ~(z + z0) 6.2 / slices thick, so the roof's shaft of
    /// test_renderer_froxels.cpp reads 2.8 % off at 64 slices and 0.16 % at
    /// 128, for ~15 % more time (aerial_bench_renderer FogAnalyticVsVolumetric).
    int slices = 128;
    /// View depth [m] where the grid ends, 10..100000 (at most the far
    /// plane). Default 2000 m.
    double farM = 2000.0;
    /// Scale of the exponential distribution [m], 0.1..1000: slices are
    /// ~(z + z0) ln(1 + farM / z0) / slices thick at view depth z. Default 4 m.
    double nearScaleM = 4.0;
    /// Where in each slice the casting light's visibility is sampled, 0..1
    /// (0.5: the middle). Unused with `temporal`, whose jitter moves it.
    double jitter = 0.5;
    /// Temporal accumulation (the editor's viewport; off by default, so a
    /// single frame is deterministic): the sample point steps through the
    /// slice from frame to frame (golden-ratio sequence) and the visibility
    /// is averaged with the previous frames' at the same world point
    /// (reprojected), the last ~10 frames weighted, so shaft edges settle on
    /// the slice's mean instead of shimmering. The history is forgotten (the
    /// frame is exactly the non-temporal one with that frame's jitter) when
    /// resetHistory is set, on the first frame, when the grid's size
    /// changes, and when since the previous frame the time moved by more than
    /// historyMaxTimeStepHours [h] (default 2 min), the eye by more than
    /// historyMaxMoveM [m] (default 25) or the view turned by more than
    /// historyMaxTurnRad (default 0.26, 15 deg).
    bool temporal = false;
    bool resetHistory = false;
    double historyMaxTimeStepHours = 2.0 / 60.0;
    double historyMaxMoveM = 25.0;
    double historyMaxTurnRad = 0.26;
};

struct FrameDesc {
    int width = 0;   ///< [px]; 0 = 1280
    int height = 0;  ///< [px]; 0 = 720
    ColourPrecision precision = ColourPrecision::Float;
    RenderPasses passes;
    VolumeMethod volumeMethod = VolumeMethod::Analytic;
    /// Measure every pass with GL timer queries (GL_TIME_ELAPSED) into
    /// RenderStats::gpuMilliseconds, and on the CPU clock between glFinish
    /// calls around each pass into RenderStats::wallMilliseconds; waits for
    /// the GPU after every pass (for benchmarks, not for an interactive
    /// frame).
    bool gpuTimers = false;
    /// Stars in the sky pass: each star shows when it is brighter than the
    /// naked-eye limiting magnitude of the sky behind it (aerial/stars.hpp);
    /// false hides them (the editor's View > Stars). The airglow is part of
    /// the sky and its light, like the sky tables, either way.
    bool stars = true;
    /// Angular radius of the sun disc [rad]; 0 hides it. Default 0.2666 deg.
    double sunDiscRadius = 0.004653;
    /// Angular radius of the moon disc [rad]; 0 hides it. Default 0.2588 deg.
    double moonDiscRadius = 0.004517;
    CloudOutput cloudOutput = CloudOutput::Lit;
    /// Samples of the cloud pass's view-ray march, 1..1024. Default 64. The
    /// transmittance output takes exactly core's midpoint march (max(1,
    /// round(steps x share)) per shell segment); the lit march the same,
    /// with each entry into a cloud and each optically thick step re-marched
    /// in sub-steps (shaders/clouds.glsl).
    int cloudSteps = 64;
    CloudQuality cloudQuality = CloudQuality::Reference;
    /// CloudQuality::Amortised: the side of the block of which one pixel is
    /// traced per frame [px], 2 (a quarter of the pixels, converges in 4
    /// still frames) or 4 (a sixteenth, as Nubis; converges in 16). Other
    /// values are clamped to 2..4 and 3 is taken as 4. Default 4.
    int cloudAmortisedBlock = 4;
    /// CloudQuality::Amortised: forget the clouds of the previous frames
    /// this frame (the editor sets it while the time is scrubbed, a key is
    /// edited or the view is cut).
    bool cloudResetHistory = false;
    /// CloudQuality::Amortised: the history is also forgotten by itself when,
    /// since the previous frame, the time of day moved by more than
    /// cloudHistoryMaxTimeStepHours [h] (default 2 min: playback at normal
    /// speed steps far less; a scrub or jump steps more), the eye moved by
    /// more than cloudHistoryMaxMoveM [m] (default 25), or the view turned
    /// by more than cloudHistoryMaxTurnRad [rad] (default 0.26, 15 deg); and
    /// when the cloud block (CloudParams, volumes, air, steps) changed while
    /// the time stood still (an edit; keyed parameters drifting during
    /// playback are left to the neighbourhood clamp), the size or precision
    /// changed, the sky was re-solved, or the previous frame drew no
    /// amortised clouds.
    double cloudHistoryMaxTimeStepHours = 2.0 / 60.0;
    double cloudHistoryMaxMoveM = 25.0;
    double cloudHistoryMaxTurnRad = 0.26;
    /// The sun's / moon's shadow maps (RenderPasses::shadows switches them).
    ShadowMapSettings shadowMap;
    /// Analytic (default) or volumetric fog; RenderPasses::globalFog,
    /// volumes and emitters switch its parts in both modes.
    FogMode fogMode = FogMode::Analytic;
    FroxelSettings froxels;
};

struct ShaderReloadResult {
    bool ok = true;
    /// Compile and link logs of every program that failed (with the file
    /// each #line source number stands for); empty when ok.
    std::string log;
};

/// Time of each pass [ms] (FrameDesc::gpuTimers; RenderStats holds the
/// timer-query and the wall-clock measure); 0 for a pass that did not run.
struct PassTimes {
    double scene = 0.0;
    double sky = 0.0;
    double globalFog = 0.0;
    double subtract = 0.0;  ///< the subtract volumes' per-pixel intervals
    double volumes = 0.0;
    double emitters = 0.0;
    double transparent = 0.0;
    double particles = 0.0;
    double cloudShadow = 0.0;      ///< the cloud shadow map
    double clouds = 0.0;           ///< the cloud layer
    double shadowMap = 0.0;        ///< the cascaded shadow maps of the sun or moon
    double froxelInject = 0.0;     ///< volumetric fog: density and light per froxel
    double froxelIntegrate = 0.0;  ///< volumetric fog: front-to-back integration
    double froxelApply = 0.0;      ///< volumetric fog: composited over the frame
    double total() const {
        return scene + sky + globalFog + subtract + volumes + emitters + transparent + particles +
               cloudShadow + clouds + shadowMap + froxelInject + froxelIntegrate + froxelApply;
    }
};

/// Where the cloud shadow map of the last frame lies (RenderStats).
struct CloudShadowStats {
    bool drawn = false;  ///< false: no clouds this frame (no map, no shadow)
    int size = 0;        ///< texels per side
    /// World [x, z] of the map's corner [m]; texel (i, j) holds the optical
    /// depth towards the light from the ground point (originX + (i + 0.5)
    /// extentM / size, 0, originZ + (j + 0.5) extentM / size).
    double originX = 0.0, originZ = 0.0;
    double extentM = 0.0;               ///< side of the square [m]
    glm::dvec3 toLight{0.0, 1.0, 0.0};  ///< unit direction marched (the brighter of sun and moon)
};

/// What the amortised cloud path did in the last frame (RenderStats).
struct CloudHistoryStats {
    bool amortised = false;  ///< the frame drew CloudQuality::Amortised clouds
    /// The previous frames' clouds were used (false: reset this frame).
    bool historyUsed = false;
    /// Nothing changed since the previous frame (camera, time, clouds, sky,
    /// emitters): the history is exact, not clamped.
    bool still = false;
    /// Which pixel of each block was traced: 0..cloudAmortisedBlock^2 - 1, 0 after a reset.
    int sampleIndex = 0;
    /// Why the history was forgotten ("" when used): "first frame",
    /// "requested", "time jump", "camera jump", "cloud parameters".
    const char* resetReason = "";
};

/// The cascaded shadow maps of the last frame (RenderStats).
struct ShadowMapStats {
    bool drawn = false;  ///< false: shadows off, no mesh, or the light below the horizon
    bool moon = false;   ///< the moon cast them (the brighter light), not the sun
    int cascades = 0;
    int resolution = 0;  ///< texels per side of each cascade
    /// View depth [m] along the camera's forward axis where cascade k ends.
    double splitM[4] = {};
    /// World size of one texel of cascade k [m] (2 x its bounding sphere's
    /// radius / resolution).
    double texelM[4] = {};
    glm::dvec3 toLight{0.0, 1.0, 0.0};  ///< unit direction to the casting light
};

/// Statistics of the last render.
/// The volumetric fog of the last frame (RenderStats).
struct FroxelStats {
    bool drawn = false;                     ///< false: FogMode::Analytic, or nothing to fog
    int width = 0, height = 0, slices = 0;  ///< the grid [froxels]
    int volumes = 0;                        ///< fog volumes injected
    bool shadowed = false;                  ///< shadow maps or cloud shadows dimmed the light
    bool historyUsed = false;  ///< FroxelSettings::temporal: the previous frames' visibility was blended in
    /// Why the history was forgotten ("" when used or not temporal): "first
    /// frame" (also after the grid's size changed), "requested", "time
    /// jump", "camera jump".
    const char* resetReason = "";
};

struct RenderStats {
    CloudShadowStats cloudShadow;
    FroxelStats froxels;
    CloudHistoryStats cloudHistory;
    ShadowMapStats shadowMap;
    int volumesDrawn = 0;
    int volumesDrawnInside = 0;  ///< hulls drawn as back faces without depth test
    int meshVolumesDrawn = 0;    ///< mesh add volumes (also counted in volumesDrawn)
    /// Subtract volumes in this frame's per-pixel union (subtract_pass.cpp:
    /// all of them with analytic fog; in volumetric fog the mesh ones, the
    /// froxels testing box and ellipsoid ones themselves).
    int subtractVolumes = 0;
    /// Pixels whose ray met more than kSubtractCrossings (16) faces of mesh
    /// subtract volumes (the rest are dropped: that pixel's union is wrong).
    int subtractCrossingOverflowPixels = 0;
    /// Pixels whose subtract union has more than 4 disjoint stretches (the
    /// 4th is extended over the rest, removing the fog between them too) or
    /// more than 48 interval ends.
    int subtractIntervalOverflowPixels = 0;
    int emitters = 0;
    int glErrors = 0;           ///< GL errors seen (each also logged)
    int transparentDrawn = 0;   ///< alpha-blended meshes drawn
    int spritesDrawn = 0;       ///< soft fog particles drawn
    bool timed = false;         ///< the two timings below hold this frame's (FrameDesc::gpuTimers)
    PassTimes gpuMilliseconds;  ///< GL timer queries
    /// Wall time of each pass between glFinish calls: the steadier number on
    /// a CPU rasteriser such as llvmpipe, which attributes queued work to
    /// whichever query is open when it flushes.
    PassTimes wallMilliseconds;
};

class Renderer {
public:
    /// Needs a current OpenGL 4.5 core context; compiles the embedded
    /// shaders. Check valid() afterwards.
    explicit Renderer(const RendererDesc& desc = {});
    /// Must run with the same context current.
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    bool valid() const;
    /// Why creation failed ("" when valid).
    const std::string& error() const;

    /// Uploads the scene (replaces the previous one): meshes (with their
    /// base-colour textures, sRGB with mipmaps, shared when the meshes share
    /// the texture) and fog sprites.
    void setScene(const SceneDesc& scene);
    /// Uploads the two hemisphere tables (sun, moon) as RGBA32F textures and
    /// derives the sky ambient irradiance; call when a solve completes. A
    /// table of the wrong size (or empty) counts as black.
    void setSky(const SkyTable& sunTable, const SkyTable& moonTable);

    /// Renders one frame of core's evaluated state (CompiledPreset::evaluate)
    /// into the renderer's HDR target (resized as needed). The fog the
    /// passes draw is core's fogSceneDesc(state, sunTable, moonTable) with
    /// the tables of the last setSky.
    void render(const Camera& camera, const PresetState& state, const FrameDesc& frame);

    /// Recompiles every program from RendererDesc::shaderDirectory. A
    /// program that fails keeps its last good version; the log says why.
    ShaderReloadResult reloadShaders();
    /// Same, from another directory.
    ShaderReloadResult reloadShaders(const std::string& directory);

    /// The last frame: RGBA colour (scene-linear) and normalised linear
    /// depth (1 channel, z_view / far; 1 where only sky is seen).
    Image readColour() const;
    Image readLinearDepth() const;
    /// The last frame's cloud shadow map (1 channel: optical depth towards
    /// the light, RenderStats::cloudShadow says where); empty without clouds.
    Image readCloudShadow() const;
    /// GL names of the frame's textures (for an editor's viewport).
    unsigned int colourTexture() const;
    unsigned int linearDepthTexture() const;

    const RenderStats& stats() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace aerial::renderer
