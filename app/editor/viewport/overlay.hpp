// viewport/overlay.hpp — 2D overlays over the viewport image: selected volume
// outlines, emitter icons, a ground grid with world axes. Drawn with ImGui's
// ImDrawList; the projection and clipping maths are separate functions that
// need no ImGui context (and are tested).
//
// Usage (after ImGui::Image of the viewport texture):
//   ImDrawList* dl = ImGui::GetWindowDrawList();
//   glm::dvec2 origin{ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y};
//   drawGroundGrid(dl, origin, frame, size, 10.0, 40);
//   for (volume selected) drawVolumeOutline(dl, origin, frame, size, v, overlayColour(1, 0.6, 0.1));
//   for (each emitter) drawEmitterIcon(dl, origin, frame, size, e, selected);
//
// Projection: pixels from the viewport's top-left corner, x right, y down,
// consistent with picking.hpp's rayThroughPixel (a point projected here and
// shot back through rayThroughPixel lies on the ray). Points at a view depth
// below the near plane have no projection. Segments are clipped in view space
// at the near plane (never drawn through infinity) and then in 2D to the
// viewport enlarged by a guard band, so every coordinate handed to ImGui is
// finite and moderate.
#pragma once

#include <aerial/emitter.hpp>
#include <aerial/fog_volume.hpp>
#include <aerial/renderer/camera.hpp>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

struct ImDrawList;

namespace aerial::editor {

/// A segment in viewport pixels.
struct ScreenSegment {
    glm::dvec2 a{0.0};
    glm::dvec2 b{0.0};
};

/// A world segment [m].
using WorldSegment = std::pair<glm::dvec3, glm::dvec3>;

/// Projects a world point [m] to viewport pixels (top-left origin, y down).
/// nullopt when its view depth dot(p - eye, forward) is below the near
/// distance, or when anything is not finite. Points outside the view (left,
/// right, beyond far) still project, outside [0, size].
std::optional<glm::dvec2> projectToViewport(const renderer::CameraFrame& frame, glm::dvec2 viewportSize,
                                            glm::dvec3 world);

/// Clips a world segment to the half-space in front of the near plane (view
/// depth >= near) and projects it; nullopt when nothing remains or input is
/// not finite. The 2D result is then clipped to the viewport enlarged by
/// `guardBandPx` on every side (nullopt when it lies entirely outside).
std::optional<ScreenSegment> projectSegment(const renderer::CameraFrame& frame, glm::dvec2 viewportSize,
                                            const glm::dvec3& a, const glm::dvec3& b,
                                            double guardBandPx = 2048.0);

/// Liang–Barsky clip of a 2D segment to the rectangle [lo, hi]; nullopt when
/// it misses it.
std::optional<ScreenSegment> clipSegmentToRect(const ScreenSegment& segment, glm::dvec2 lo, glm::dvec2 hi);

/// World-space outline of a volume: a box's 12 edges; an ellipsoid's three
/// principal great ellipses (in its object XY, YZ and ZX planes), each as
/// `ellipseSegments` chords (clamped to [8, 512]); a mesh's edges (every
/// edge of a mesh with at most kMeshOutlineAllEdges of them but those
/// inside a flat face, such as the diagonals of its quads; else the
/// creases, where the faces meet at more than 25 degrees, and the box of
/// its bounds when a large smooth mesh has hardly any). Empty for a degenerate
/// volume (non-finite or non-positive half extents, zero rotation).
std::vector<WorldSegment> volumeOutlineSegments(const FogVolume& volume, int ellipseSegments = 64);
inline constexpr std::size_t kMeshOutlineAllEdges = 20000;

/// ImGui colour (IM_COL32 packing, 0xAABBGGRR) from display values 0..1.
std::uint32_t overlayColour(double r, double g, double b, double a = 1.0);

/// ImGui colour for a scene-linear colour shown as an icon: divided by its
/// largest component when that exceeds 1 (hue kept), sRGB-encoded. Black or
/// non-finite colours give mid grey.
std::uint32_t displayColourOfLinear(const glm::dvec3& linear, double alpha = 1.0);

/// Draws a volume's outline (volumeOutlineSegments, near-clipped) with a
/// `thickness` [px] line. `viewportOriginScreen` is the viewport's top-left
/// in ImGui screen pixels.
void drawVolumeOutline(ImDrawList* drawList, glm::dvec2 viewportOriginScreen,
                       const renderer::CameraFrame& frame, glm::dvec2 viewportSize, const FogVolume& volume,
                       std::uint32_t colour, float thickness = 1.5f);

/// Draws an emitter's icon at its projected position: a sun-like glyph
/// (disc and eight rays; a lightning emitter gets a bolt) filled with its
/// colour (displayColourOfLinear), `radiusPx` in radius, with a white ring
/// when `selected`. Nothing when behind the near plane. Use the same
/// radius for angularRadiusOfPixels when picking.
void drawEmitterIcon(ImDrawList* drawList, glm::dvec2 viewportOriginScreen,
                     const renderer::CameraFrame& frame, glm::dvec2 viewportSize, const Emitter& emitter,
                     bool selected, float radiusPx = 10.0f);

/// Draws grid lines on the plane y = 0 every `spacing` [m], `halfLineCount`
/// lines each side of the origin (clamped to [1, 500]), plus the world X
/// (red) and Z (blue) axes through the origin, near-clipped.
void drawGroundGrid(ImDrawList* drawList, glm::dvec2 viewportOriginScreen, const renderer::CameraFrame& frame,
                    glm::dvec2 viewportSize, double spacing = 10.0, int halfLineCount = 40,
                    std::uint32_t colour = 0x40FFFFFFu);

}  // namespace aerial::editor
