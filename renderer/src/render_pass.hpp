// render_pass.hpp — private: the frame as a list of passes (Filament's and
// Unreal's render passes). A pass is a pair of functions: whether it runs
// this frame, and its draws. Each lives in a file of its own
// (sky_pass.cpp, scene_pass.cpp, ...) whose opening comment names what it
// reads, what it writes and the GL state it owns.
//
// GL state contract. Renderer::Impl::render binds the frame's uniform and
// storage buffers and textures (gpu_types.hpp's bindings and units), sets
// the viewport, clears the targets and leaves the frame's baseline:
//   draw framebuffer = sceneTarget with both colour attachments drawn,
//   depth test, blending, face culling, depth clamp, polygon offset,
//   scissor and stencil off, depth writes and all colour channels on.
// A pass sets what it needs on entry and returns to the baseline on exit;
// program, vertex array and texture unit 5 (base colour) are free for every
// pass to change. Renderer::render's GlStateGuard restores the caller's state
// after the frame.
#pragma once

#include "gpu_mesh.hpp"
#include "gpu_types.hpp"
#include "shader_library.hpp"
#include "sky_textures.hpp"

#include <aerial/clouds.hpp>
#include <aerial/evaluate.hpp>
#include <aerial/fog_query.hpp>
#include <aerial/fog_volume.hpp>
#include <aerial/renderer/camera.hpp>
#include <aerial/renderer/renderer.hpp>
#include <aerial/renderer/scene.hpp>
#include <aerial/sky.hpp>

#include <epoxy/gl.h>

#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

namespace aerial {
struct PresetState;
}

namespace aerial::renderer::detail {

/// The GL objects the renderer owns and its passes draw with (created and
/// destroyed by Renderer::Impl, which holds one).
struct RendererResources {
    ShaderLibrary shaders;
    GLuint emptyVertexArray = 0;     ///< full-screen triangles (fullscreen.glsl)
    GpuMesh hull;                    ///< unit cube: the fog volumes' hull
    std::vector<GpuMesh> meshes;     ///< the scene
    GLuint whiteTexture = 0;         ///< bound to the base-colour unit when a mesh has none
    std::vector<FogSprite> sprites;  ///< sanitised at setScene
    GLuint spriteArray = 0, spriteBuffer = 0;
    GLuint frameBuffer = 0, volumeBuffer = 0, objectBuffer = 0, emitterBuffer = 0;
    GLsizeiptr emitterCapacity = 0;  ///< [bytes]
    GLuint colour = 0, linearDepth = 0, depth = 0;
    /// sceneTarget: colour + linear depth + depth; compositeTarget: colour +
    /// depth (the passes that blend into the colour and read linear depth).
    GLuint sceneTarget = 0, compositeTarget = 0;
    SkyTextures sunSky, moonSky;
    SkyTable sunTable, moonTable;
    /// The cloud layer (cloud_pass.cpp): the noise of cloudSeed (R32F 3D,
    /// created on the first frame with clouds), the shadow map and its
    /// target, the CloudBlock buffer.
    GLuint cloudShape = 0, cloudDetail = 0;
    std::int64_t cloudSeed = -1;  ///< seed of the uploaded noise (-1: none)
    GLuint cloudShadowMap = 0, cloudShadowTarget = 0;
    GLuint cloudBuffer = 0;
    /// The amortised cloud path (cloud_amortised.cpp): its targets and what
    /// it remembers of the previous frame.
    struct CloudHistory {
        int width = 0, height = 0, block = 0;  ///< of the targets (0: none)
        ColourPrecision precision = ColourPrecision::Half;
        GLuint trace = 0, traceTarget = 0;  ///< one sample per block: (S, T)
        /// Full resolution, ping-pong: (S, T) of a traced or reprojected
        /// pixel, (S, T + 2) of an estimate; written with the colour.
        GLuint history[2] = {}, target[2] = {};
        GLuint previousDepth = 0;  ///< the previous frame's linear depth
        int current = 0;           ///< history[current] is the last frame's
        bool valid = false;        ///< history[current] holds a frame to reuse
        int sampleIndex = 0;       ///< of the last frame
        glm::dmat4 clipFromWorld{1.0};
        glm::dvec3 eye{0.0}, forward{0.0, 0.0, -1.0};
        double timeHours = 0.0;
        FrameBlock frameBlock;
        CloudBlock cloudBlock;
        std::vector<double> emitters;  ///< the emitters' numbers, to see a change
    } cloudHistory;
    /// The cascaded shadow maps (shadow_map_pass.cpp): a
    /// GL_DEPTH_COMPONENT32F 2D array (one layer per cascade, comparison
    /// sampling on), its depth-only target, the ShadowBlock buffer.
    GLuint shadowMap = 0, shadowTarget = 0, shadowBuffer = 0;
    int shadowMapSize = 0, shadowMapLayers = 0;  ///< of the allocated array
    /// The volumetric fog (froxel_pass.cpp): the injected grid (medium,
    /// light: x, y, slices), the integrated grid (litSky, sky, own: slices
    /// + 1 layers), all RGBA32F; the FroxelBlock and the volumes' buffer.
    struct Froxels {
        int width = 0, height = 0, slices = 0;  ///< of the allocated textures (0: none)
        GLuint medium = 0, light = 0;
        GLuint litSky = 0, sky = 0, own = 0;
        GLuint block = 0, volumes = 0;
        GLsizeiptr volumeCapacity = 0;  ///< [bytes]
        /// The mesh add volumes' chords per froxel column (storage 1).
        GLuint meshChords = 0;
        GLsizeiptr meshChordCapacity = 0;  ///< [bytes]
        /// Temporal: the visibility of the last two frames (R32F, ping-pong),
        /// and what the last frame was.
        GLuint history[2] = {};
        int current = 0;      ///< history[current] holds the last frame's
        bool valid = false;   ///< it holds a frame to reuse
        int framesSinceReset = 0;
        glm::dmat4 clipFromWorld{1.0};
        glm::dvec3 eye{0.0}, forward{0.0, 0.0, -1.0};
        double timeHours = 0.0;
    } froxels;
    /// Mesh fog volumes' triangles (mesh_volume_pass.cpp): uploaded once
    /// per FogMesh (keyed by its address, the weak pointer telling a new
    /// mesh at a reused address apart), released after a frame that did not
    /// use them. Positions in object space (float), 32-bit indices.
    struct FogMeshGpu {
        std::weak_ptr<const FogMesh> mesh;
        GLuint vertexArray = 0, vertexBuffer = 0, indexBuffer = 0;
        GLsizei indexCount = 0;
        std::uint64_t lastFrame = 0;  ///< frameNumber of its last use
    };
    std::unordered_map<const FogMesh*, FogMeshGpu> fogMeshes;
    std::uint64_t frameNumber = 0;  ///< frames rendered (for fogMeshes)
    /// Subtract volumes (subtract_pass.cpp), storage buffers sized for
    /// width x height pixels: the per-pixel union intervals (2 vec4), the
    /// crossing counts (2 statistics, then one per pixel), the crossings
    /// (kSubtractCrossings per pixel, only with mesh subtract volumes) and
    /// the box/ellipsoid subtract volumes (VolumeBlock[]).
    struct Subtract {
        int width = 0, height = 0;
        GLuint intervals = 0, counts = 0, crossings = 0, volumes = 0;
        GLsizeiptr crossingBytes = 0, volumeCapacity = 0;
    } subtract;
    /// A mesh add volume's accumulation (RG32F) and its target
    /// (mesh_volume_pass.cpp), created at the first mesh volume.
    GLuint meshAccumulation = 0, meshAccumulationTarget = 0;
    int meshAccumulationWidth = 0, meshAccumulationHeight = 0;
};

/// One frame as the passes see it.
class FrameContext {
public:
    FrameContext(const Camera& c, const CameraFrame& v, const PresetState& s, const FrameDesc& d,
                 const FrameBlock& b, RendererResources& g, RenderStats& st)
        : camera(c), view(v), state(s), desc(d), block(b), gpu(g), stats(st) {}

    const Camera& camera;
    const CameraFrame& view;
    const PresetState& state;
    const FrameDesc& desc;
    const FrameBlock& block;  ///< already uploaded to gpu.frameBuffer
    RendererResources& gpu;
    RenderStats& stats;
    /// The frame's cloud layer (prepareClouds of the state) and its block,
    /// already uploaded to gpu.cloudBuffer; set by Renderer::Impl::render.
    const CloudField* clouds = nullptr;
    /// The frame's overcast (in the frame block too); null: none.
    const OvercastLight* overcast = nullptr;
    CloudBlock cloudBlock;
    /// The frame's shadow maps' block, already uploaded to gpu.shadowBuffer;
    /// castingLight > 0 when the shadow-map pass draws this frame.
    ShadowBlock shadowBlock;
    /// The layer is drawn this frame: clouds active and the pass on.
    bool cloudsDrawn() const { return clouds != nullptr && clouds->active() && desc.passes.clouds; }
    /// The volumetric fog's block of this frame (froxel_pass.cpp, set by the
    /// inject pass; gridSize 0 when the fog is analytic or empty).
    FroxelBlock froxelBlock;

    /// The CPU fog of the volumes and emitters for the transparent meshes
    /// and the particles (core's fogSceneDesc without the global fog, which
    /// is theirs on the GPU; volumes and emitters only when their passes
    /// are on). Built on first use, shared by the passes of the frame.
    const FogScene& localFog();

private:
    std::unique_ptr<FogScene> localFog_;
};

/// One pass of the frame.
struct RenderPass {
    double PassTimes::*time;  ///< its slot in RenderStats' timings
    bool (*runs)(const FrameContext& frame);
    void (*draw)(FrameContext& frame);
};

// The passes, in the order of renderer.hpp (each in its own file).
extern const RenderPass kScenePass;        // scene_pass.cpp
extern const RenderPass kSkyPass;          // sky_pass.cpp
extern const RenderPass kSubtractPass;     // subtract_pass.cpp
extern const RenderPass kGlobalFogPass;    // global_fog_pass.cpp
extern const RenderPass kVolumePass;       // volume_pass.cpp
extern const RenderPass kEmitterPass;      // emitter_pass.cpp
extern const RenderPass kTransparentPass;  // transparent_pass.cpp
extern const RenderPass kParticlePass;     // particle_pass.cpp
extern const RenderPass kCloudShadowPass;  // cloud_shadow_pass.cpp
extern const RenderPass kCloudPass;        // cloud_pass.cpp
extern const RenderPass kShadowMapPass;    // shadow_map_pass.cpp
extern const RenderPass kFroxelInjectPass;     // froxel_pass.cpp
extern const RenderPass kFroxelIntegratePass;  // froxel_pass.cpp
extern const RenderPass kFroxelApplyPass;      // froxel_pass.cpp

/// Runs passes, measuring each when FrameDesc::gpuTimers: a GL_TIME_ELAPSED
/// query around its draws and the wall time between glFinish calls before
/// and after (pass_timer.cpp). The one place passes are timed.
class PassTimer {
public:
    static constexpr int kMaxPasses = 16;
    /// Creates the queries (a GL context is current).
    void create();
    void destroy();
    /// Starts a frame: nothing measured yet.
    void beginFrame(bool enabled);
    /// Runs the pass when it runs this frame, timed when enabled.
    void run(const RenderPass& pass, FrameContext& frame);
    /// Writes the frame's timings into stats (gpuMilliseconds,
    /// wallMilliseconds, timed) when enabled; waits for the queries.
    void endFrame(RenderStats& stats);

private:
    GLuint queries_[kMaxPasses] = {};
    double PassTimes::*slots_[kMaxPasses] = {};
    double wallMs_[kMaxPasses] = {};
    int used_ = 0;
    bool enabled_ = false;
};

// Helpers the passes share.

/// Draws one full-screen triangle with the program of `program`.
void drawFullscreen(const RendererResources& gpu, Pass program);

/// Composite state of the fog passes: compositeTarget (colour and depth, no
/// linear depth: the passes read it), no depth writes, blending with
/// GL_FUNC_ADD and (srcRgb, dstRgb) for colour, (GL_ZERO, GL_ONE) for alpha
/// (alpha stays). endComposite returns to the baseline.
void beginComposite(const RendererResources& gpu, GLenum srcRgb, GLenum dstRgb);
void endComposite(const RendererResources& gpu);

/// One full-screen triangle of `program` composited with (srcRgb, dstRgb):
/// beginComposite, drawFullscreen, endComposite (the global fog, emitters).
void compositeFullscreen(const RendererResources& gpu, Pass program, GLenum srcRgb, GLenum dstRgb);

/// Uploads the valid emitters (finite position, positive intensity; colours
/// and attenuations sanitised) to gpu.emitterBuffer, growing it as needed;
/// returns how many (emitter_pass.cpp).
int uploadEmitters(RendererResources& gpu, const std::vector<Emitter>& emitters);

/// Side of the cloud shadow map [texels] and of the ground square it covers
/// [m]: 62.5 m texels, finer than a cloud shadow's soft edge (a cloud's edge
/// softness over a layer ~1-2 km above the ground); 128^2 x 48 samples costs
/// a quarter of 256^2, measured 90 -> ~22 ms per frame on llvmpipe here.
constexpr int kCloudShadowSize = 128;
constexpr double kCloudShadowExtentM = 8000.0;

/// The frame's cloud block (cloud_pass.cpp; no GL): the field's parameters
/// and wind offsets in float, the air for the clouds' fade into the
/// atmosphere, the march settings of `frame`, and the shadow map placed
/// around the eye (see cloud_shadow_pass.cpp); shadowActive when the field
/// is active and the cloud pass is on. Fills `shadow` with the placement.
CloudBlock makeCloudBlock(const CloudField& field, const PresetState& state, const FrameDesc& frame,
                          const glm::dvec3& eye, CloudShadowStats& shadow);

/// Uploads the field's noise when its seed differs from gpu.cloudSeed
/// (cloud_pass.cpp); creates the shadow map on first use.
void prepareCloudResources(RendererResources& gpu, const CloudField& field);
void destroyCloudResources(RendererResources& gpu);

/// The amortised cloud path (cloud_amortised.cpp): the trace of one pixel
/// per block, then the reconstruction that reprojects the history and
/// composites (L <- L T + S) in one draw. Decides itself whether the
/// history is kept (FrameDesc's thresholds) and reports in stats.cloudHistory.
void drawAmortisedClouds(FrameContext& frame);
/// Forgets the history (the targets stay).
void forgetCloudHistory(RendererResources& gpu);
void destroyCloudHistory(RendererResources& gpu);
/// Creates (or re-creates at a new size) the shadow map array, its target
/// and buffer; destroyShadowResources deletes them.
void prepareShadowResources(RendererResources& gpu, int resolution, int layers);
void destroyShadowResources(RendererResources& gpu);

/// A prepared fog volume as the GPU takes it (volume_pass.cpp); false when
/// it is invalid or empty (nothing to draw; a valid subtract volume is
/// never empty: its density is unused).
bool packVolumeBlock(const PreparedFogVolume& volume, VolumeBlock& block);

/// Whether subtract volumes cut the fog this frame (no GL): analytic fog,
/// the volume pass on and a valid subtract volume in the state.
bool frameHasSubtractVolumes(const PresetState& state, const FrameDesc& frame);
/// Reads the subtract pass's overflow counters into the stats (after the
/// frame's passes; a wait for the GPU, only in frames with subtract volumes).
void readSubtractStats(const RendererResources& gpu, RenderStats& stats);
void destroySubtractResources(RendererResources& gpu);

/// A mesh volume's triangles on the GPU, uploaded on first use
/// (mesh_volume_pass.cpp); null when the mesh is empty.
const RendererResources::FogMeshGpu* fogMeshOnGpu(RendererResources& gpu,
                                                  const std::shared_ptr<const FogMesh>& mesh);
/// Releases the meshes the frame numbered gpu.frameNumber did not use.
void releaseUnusedFogMeshes(RendererResources& gpu);
/// Draws one mesh add volume (accumulate, then composite over the colour);
/// called by the volume pass in its back-to-front order, inside its
/// beginComposite; false when nothing was drawn (no mesh, off screen). Leaves compositeTarget bound and blending as
/// beginComposite(GL_ONE, GL_SRC_ALPHA); changes program, vertex array,
/// culling, depth test and clamp (the caller sets them per volume).
bool drawMeshVolume(FrameContext& frame, const PreparedFogVolume& volume, const VolumeBlock& block);
void destroyMeshVolumeResources(RendererResources& gpu);

/// The volumetric fog's grid for a frame of width x height pixels (no GL):
/// FroxelSettings clamped, the far depth at most the camera's, the casting
/// light (the brighter of sun and moon, as the shadow maps choose it) and
/// which shadows dim it. gridSize stays 0 unless `frame.fogMode` is
/// Volumetric.
FroxelBlock makeFroxelBlock(const FrameDesc& frame, int width, int height, double farDistance,
                            const PresetState& state, const ShadowBlock& shadows, const CloudBlock& clouds,
                            int volumeCount);
void destroyFroxelResources(RendererResources& gpu);

}  // namespace aerial::renderer::detail
