// aerial/limits.hpp — the hard caps on everything a file or a caller can ask
// Aerial to allocate. Presets and scenes come from other people: whatever a
// file says, loading it costs at most a few hundred megabytes and a few
// seconds, and a value over a cap is a clear error that names the file, the
// field and the limit ("presets/x.json:1:12: /volumes: 1025 volumes, over
// the limit of 1024"), never an allocation of gigabytes.
//
// Usage:
//   if (preset.volumes.size() >= aerial::limits::kMaxVolumes) disableAddButton();
//   std::printf("at most %zu keys per track\n", aerial::limits::kMaxKeysPerTrack);
//
// Where each cap is enforced:
//   * preset files (loadPreset, parsePreset, validatePreset, savePreset):
//     kMaxPresetFileBytes, kMaxJsonDepth, kMaxJsonValues, kMaxVolumes, kMaxEmitters,
//     kMaxCloudVolumes, kMaxTracks, kMaxKeysPerTrack, kMaxWeatherStates,
//     kMaxWeatherOverrides, kMaxWeatherRegions, kMaxStringBytes (name, description,
//     ids are 1..kMaxIdBytes), kMaxPresetIssues (more problems are counted
//     in one last issue, not listed);
//   * the sky solver (SkySolverDesc): kMaxSkyAzimuthCount,
//     kMaxSkyElevationCount, kMaxSkyLayerCount, kMaxOpticalDepthAngles —
//     larger requests are clamped to the cap, and desc() reports the sizes
//     used; the `aerial` CLI refuses them with an error instead;
//   * images: kMaxImageSide for `aerial render --size` and the sky tables
//     of `aerial bake --size` (the table caps above);
//   * glTF scenes (aerial/renderer/gltf.hpp, GltfLoadOptions defaults):
//     kMaxGltfFileBytes for the .gltf/.glb and every external buffer or
//     image, kMaxGltfVertices and kMaxGltfTriangles over the scene (which
//     also bound every accessor's count), kMaxGltfNodeDepth, and textures
//     of at most kMaxTextureSide per side and kMaxTexturePixels pixels
//     (kMaxTexturePixelsTotal over all images), refused before they are
//     decoded;
//   * geometry (fog volumes, emitters, fog queries, the editor's picking):
//     kMaxCoordinate, kMinHalfExtent, kMaxFogParameter — a shape or ray
//     beyond them is never hit (aerial/fog_volume.hpp, "Sanitising").
#pragma once

#include <cstddef>
#include <cstdint>

namespace aerial::limits {

// ---- Presets ---------------------------------------------------------------

/// Largest preset file [bytes]: 16 MiB (a rich preset is ~20 KiB).
inline constexpr std::size_t kMaxPresetFileBytes = std::size_t(16) << 20;
/// Deepest nesting of JSON arrays and objects in a preset (a valid preset
/// nests 4 deep: tracks / track / keys / key / value).
inline constexpr std::size_t kMaxJsonDepth = 64;
/// JSON values (numbers, strings, arrays, objects, ...) in one preset
/// file: 1 Mi. With the file size this bounds the loader's memory (~150 MB
/// at worst) before any count below is looked at; a rich preset has a few
/// thousand.
inline constexpr std::size_t kMaxJsonValues = std::size_t(1) << 20;
/// Fog volumes in one preset.
inline constexpr std::size_t kMaxVolumes = 1024;
/// Emitters in one preset.
inline constexpr std::size_t kMaxEmitters = 1024;
/// Cloud volumes in one preset. Small on purpose: every sample of the GPU's
/// cloud march tests each of them, so the renderer uploads at most this
/// many (a fixed-size uniform array), and a preset with more is refused
/// rather than drawn differently from the CPU queries.
inline constexpr std::size_t kMaxCloudVolumes = 64;
/// Timeline tracks in one preset.
inline constexpr std::size_t kMaxTracks = 4096;
/// Keys in one track (one a minute over the day is 1440).
inline constexpr std::size_t kMaxKeysPerTrack = 4096;
/// Weather states in a preset, and overrides in one state.
inline constexpr std::size_t kMaxWeatherStates = 64;
inline constexpr std::size_t kMaxWeatherOverrides = 256;
/// Weather regions in a preset (each frame tests the camera against all).
inline constexpr std::size_t kMaxWeatherRegions = 64;
/// Longest name, description or other free text [bytes of UTF-8].
inline constexpr std::size_t kMaxStringBytes = 4096;
/// Longest object id [bytes] (ids are 1..64 of A-Z a-z 0-9 _ - .).
inline constexpr std::size_t kMaxIdBytes = 64;
/// Errors (and, separately, warnings) listed for one preset; the rest are
/// summed up in one final issue.
inline constexpr std::size_t kMaxPresetIssues = 100;

// ---- Sky tables ------------------------------------------------------------

/// Sky table columns (azimuth) and rows (elevation): a 4096 x 2048 table is
/// 2 x 100 MB of floats.
inline constexpr int kMaxSkyAzimuthCount = 4096;
inline constexpr int kMaxSkyElevationCount = 2048;
/// Layers along each view ray.
inline constexpr int kMaxSkyLayerCount = 1024;
/// Optical-depth table columns.
inline constexpr int kMaxOpticalDepthAngles = 4096;

// ---- Images ----------------------------------------------------------------

/// Longest side of a rendered image [pixels] (`aerial render --size`; an
/// 8192 x 8192 RGBA float frame is 1 GiB).
inline constexpr int kMaxImageSide = 8192;

// ---- glTF scenes -----------------------------------------------------------

/// Largest .gltf/.glb, external buffer or image file [bytes]: 64 MiB.
inline constexpr std::uint64_t kMaxGltfFileBytes = std::uint64_t(64) << 20;
/// Vertices over the whole scene (after node instancing and flat normals);
/// also the largest count of any accessor.
inline constexpr std::uint64_t kMaxGltfVertices = std::uint64_t(16) << 20;
/// Triangles over the whole scene (after node instancing).
inline constexpr std::uint64_t kMaxGltfTriangles = std::uint64_t(16) << 20;
/// Deepest node hierarchy.
inline constexpr int kMaxGltfNodeDepth = 256;
/// Triangles of one fog volume mesh (aerial/fog_mesh.hpp), over all the
/// file's primitives: a fog hull is a simple shape (a room, a cave, a
/// valley), and every mesh volume is rasterised twice a frame and kept in
/// memory as a BVH by every FogScene.
inline constexpr std::size_t kMaxFogMeshTriangles = 65536;
/// Largest texture side [pixels] and pixel count, checked from the image
/// header before decoding.
inline constexpr int kMaxTextureSide = 16384;
inline constexpr std::uint64_t kMaxTexturePixels = std::uint64_t(64) << 20;
/// Pixels of all the images of one scene together (64 Mi: 256 MB as RGBA8),
/// so that many small files that each claim a large image cannot add up to
/// gigabytes.
inline constexpr std::uint64_t kMaxTexturePixelsTotal = std::uint64_t(64) << 20;

// ---- Geometry --------------------------------------------------------------

/// World coordinates, ray directions and half extents beyond this magnitude
/// [m] are not meaningful; a volume or ray that uses them is never hit. Keeps
/// every object-space product finite.
inline constexpr double kMaxCoordinate = 1.0e30;
/// Half extents below this [m] (1 um) make a fog volume degenerate.
inline constexpr double kMinHalfExtent = 1.0e-6;
/// Density, falloff and gradient-offset magnitudes are clamped to this.
inline constexpr double kMaxFogParameter = 1.0e150;
/// A key's tangent slopes (TrackKey::tangents) beyond this magnitude
/// [value unit per h] are rejected: with values within a parameter's range,
/// a Hermite segment's terms stay finite.
inline constexpr double kMaxKeyTangent = 1.0e150;

}  // namespace aerial::limits
