// common/packed_volume.glsl — one fog volume as VolumeBlock
// (renderer/src/gpu_types.hpp; the layout of common/volume.glsl's uniform
// block), packed in a std430 array: the volumetric fog's volumes
// (common/froxel_volumes.glsl) and the subtract volumes of
// subtract_resolve.glsl.
#ifndef AERIAL_PACKED_VOLUME_GLSL
#define AERIAL_PACKED_VOLUME_GLSL

struct PackedVolume {
    mat4 worldFromObject;
    vec3 objectFromWorldRow0;
    float shape;  // 0 box, 1 ellipsoid, 2 mesh
    vec3 objectFromWorldRow1;
    float density;
    vec3 objectFromWorldRow2;
    float falloff;
    vec3 position;
    float gradientOffset;
    vec3 gradientDirection;
    float colourMode;
    vec3 colour;
    float blend;  // 0 add, 1 subtract
    float edgeSoftness;  // sigma 0..1 (0 hard; common/soft_volume.glsl)
    float padSoftness0;
    float padSoftness1;
    float padSoftness2;
};

#endif
