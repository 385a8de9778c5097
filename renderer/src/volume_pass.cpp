// volume_pass.cpp — pass 4: the fog volumes that add fog, back to front,
// each a hull (the unit cube in object space) whose fragments integrate the
// volume's density along the pixel's clipped ray (shaders/fog_volume.glsl,
// or fog_volume_marched.glsl for VolumeMethod::RayMarched64):
// L <- L T_v + C_v (1 - T_v). A mesh volume takes its place in the same
// order, drawn by drawMeshVolume (mesh_volume_pass.cpp). Subtract volumes
// draw nothing here: subtract_pass.cpp made their union, which every
// volume's integral leaves out (common/subtract.glsl).
//
// Reads:  the state's volumes (core's prepareFogVolume, packed by
//         prepareVolume), FrameBlock, linear depth (unit 4), the depth
//         buffer (hulls seen from outside are depth-tested against it).
// Writes: the colour, through compositeTarget (no depth writes); the
//         VolumeBlock per volume; RenderStats::volumesDrawn, volumesDrawnInside.
// GL state: beginComposite with glBlendFunc(GL_ONE, GL_SRC_ALPHA) for
//         colour (alpha kept); depth clamp and face culling on (set again
//         after each mesh volume, which changes them); per volume
//         either back faces without depth test (the eye may be inside) or
//         front faces depth-tested with GL_LEQUAL; all three off again and
//         endComposite on exit.
//
// Order: sorted by the distance from the eye to each volume's world bounds
// (0 when inside), farthest first, ties by ascending index (renderer.hpp).
#include "frame_block.hpp"
#include "render_pass.hpp"

#include <aerial/evaluate.hpp>
#include <aerial/fog_volume.hpp>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

namespace aerial::renderer::detail {
namespace {

/// Distance [m] from a point to an axis-aligned box (0 inside).
double distanceToBox(const glm::dvec3& p, const glm::dvec3& lo, const glm::dvec3& hi) {
    return glm::length(glm::max(glm::max(lo - p, p - hi), glm::dvec3(0.0)));
}

/// A fog volume reduced to what its pass needs: core's prepareFogVolume
/// (its validity rules and sanitising) packed for the GPU.
struct PreparedVolume {
    VolumeBlock block;
    PreparedFogVolume mesh;  ///< a mesh volume's preparation (shape Mesh); unused otherwise
    bool isMesh = false;
    double sortDistance = 0.0;
    std::size_t index = 0;
    bool inside = false;
};

bool prepareVolume(const FogVolume& v, std::size_t index, const CameraFrame& camera,
                   double nearCornerDistance, PreparedVolume& out) {
    if (v.blend == FogVolumeBlend::Subtract) return false;
    PreparedFogVolume p = prepareFogVolume(v);
    if (!packVolumeBlock(p, out.block)) return false;

    out.sortDistance = distanceToBox(camera.eye, p.boundsMin, p.boundsMax);
    out.index = index;
    // Inside mode when the hull may reach the eye's near-plane sphere: the
    // world distance to the hull is at least min(s) times the object-space
    // distance (conservative; inside mode is always correct, only slower).
    const glm::dvec3 o = p.toObject(camera.eye - p.position);
    const double objectDistance = glm::length(o - glm::clamp(o, glm::dvec3(-1.0), glm::dvec3(1.0)));
    const glm::dvec3 s = v.halfExtents;
    out.inside = std::min({s.x, s.y, s.z}) * objectDistance <= 1.01 * nearCornerDistance;
    out.isMesh = p.shape == FogVolumeShape::Mesh;
    if (out.isMesh) out.mesh = std::move(p);
    return true;
}

bool runs(const FrameContext& f) {
    return f.desc.fogMode == FogMode::Analytic && f.desc.passes.volumes && !f.state.volumes.empty();
}

void draw(FrameContext& f) {
    RendererResources& gpu = f.gpu;
    const Camera& camera = f.camera;
    const CameraFrame& cam = f.view;
    const std::vector<FogVolume>& all = f.state.volumes;
    const double tanHalf = std::tan(0.5 * std::clamp(camera.verticalFov, 1e-4, 3.14149));
    const double aspect = camera.aspect > 0.0 && std::isfinite(camera.aspect) ? camera.aspect : 1.0;
    const double nearCorner = cam.nearDistance * std::sqrt(1.0 + tanHalf * tanHalf * (1.0 + aspect * aspect));
    std::vector<PreparedVolume> volumes;
    volumes.reserve(all.size());
    for (std::size_t i = 0; i < all.size(); ++i) {
        PreparedVolume p;
        if (prepareVolume(all[i], i, cam, nearCorner, p)) volumes.push_back(p);
    }
    // Back to front: farthest first, ties by ascending index (the lower
    // index composited first), as fog_query.hpp.
    std::stable_sort(volumes.begin(), volumes.end(), [](const PreparedVolume& a, const PreparedVolume& b) {
        return a.sortDistance > b.sortDistance;
    });
    beginComposite(gpu, GL_ONE, GL_SRC_ALPHA);
    const GLuint hullProgram = gpu.shaders.program(
        f.desc.volumeMethod == VolumeMethod::RayMarched64 ? Pass::FogVolumeMarched : Pass::FogVolume);
    for (const PreparedVolume& v : volumes) {
        if (v.isMesh) {
            if (drawMeshVolume(f, v.mesh, v.block)) ++f.stats.volumesDrawn;
            continue;
        }
        glUseProgram(hullProgram);
        glBindVertexArray(gpu.hull.vertexArray);
        glEnable(GL_DEPTH_CLAMP);  // hull parts beyond the far plane still rasterise (at depth 1)
        glEnable(GL_CULL_FACE);
        if (v.inside) {
            // Back faces, no depth test: every ray that meets the hull
            // leaves it through exactly one back face.
            glCullFace(GL_FRONT);
            glDisable(GL_DEPTH_TEST);
            ++f.stats.volumesDrawnInside;
        } else {
            // Front faces behind the scene cannot contribute.
            glCullFace(GL_BACK);
            glEnable(GL_DEPTH_TEST);
            glDepthFunc(GL_LEQUAL);
        }
        glNamedBufferSubData(gpu.volumeBuffer, 0, sizeof v.block, &v.block);
        glDrawElements(GL_TRIANGLES, gpu.hull.indexCount, GL_UNSIGNED_INT, nullptr);
        ++f.stats.volumesDrawn;
    }
    glDisable(GL_CULL_FACE);
    glDisable(GL_DEPTH_CLAMP);
    glDisable(GL_DEPTH_TEST);
    endComposite(gpu);
}

}  // namespace

bool packVolumeBlock(const PreparedFogVolume& p, VolumeBlock& block) {
    const bool subtract = p.blend == FogVolumeBlend::Subtract;
    if (!p.valid || (!subtract && !(p.density > 0.0))) return false;
    glm::dmat4 worldFromObject(1.0);
    for (int c = 0; c < 3; ++c) worldFromObject[c] = glm::dvec4(p.worldFromObject[c], 0.0);
    worldFromObject[3] = glm::dvec4(p.position, 1.0);

    block.worldFromObject = toMat4(worldFromObject);
    block.objectFromWorldRow0 = toVec3(p.row0);
    block.shape = p.shape == FogVolumeShape::Mesh ? 2.0f : p.shape == FogVolumeShape::Ellipsoid ? 1.0f : 0.0f;
    block.objectFromWorldRow1 = toVec3(p.row1);
    block.density = static_cast<float>(p.density);
    block.objectFromWorldRow2 = toVec3(p.row2);
    block.falloff = static_cast<float>(p.falloff);
    block.position = toVec3(p.position);
    block.gradientOffset = static_cast<float>(p.gradientOffset);
    block.gradientDirection = toVec3(p.gradient);
    block.colourMode = static_cast<float>(static_cast<int>(p.colourMode));
    block.colour = toVec3(p.colour);
    block.blend = subtract ? 1.0f : 0.0f;
    block.edgeSoftness = static_cast<float>(p.edgeSoftness);
    return true;
}

const RenderPass kVolumePass{&PassTimes::volumes, runs, draw};

}  // namespace aerial::renderer::detail
