// subtract_resolve.glsl — the union of the subtract volumes along each
// pixel's ray (compute, one invocation per pixel; DESIGN.md "Mesh and
// subtract volumes", fog_volume.hpp FogVolumeBlend::Subtract): the box and
// ellipsoid subtract volumes intersected analytically in object space
// (common/unit_shape.glsl), the mesh ones from the crossings that
// subtract_crossings.glsl listed; events sorted by t, a running count of
// the volumes the ray is inside (overlaps count once: inside = count > 0),
// the stretches inside clipped to [0, depth01].
//
// Inputs:
//   frame (common/frame.glsl): eye, far-plane corner rays, viewportSize
//   uLinearDepth (unit 4): normalised linear depth z/far
//   uSubtractVolumeCount (location 0): box/ellipsoid subtract volumes in
//     SubtractVolumes (std430, binding 5, VolumeBlock layout)
//   uMeshCrossings (location 1): 1 when SubtractCounts / SubtractCrossings
//     (bindings 6, 7) hold mesh crossings this frame
// Output:
//   SubtractIntervals (std430, binding 4): per pixel two vec4, 4 pairs
//     (a, b), sorted, disjoint, in [0, depth01]; unused pairs (0, 0).
//     K = 4: a fifth and later stretch are merged into the fourth (its end
//     moves to theirs), so fog between them is removed too: counted.
//   SubtractCounts[0] += 1 per pixel whose mesh crossings overflowed (more
//     than 16: the dropped ones are lost, the count at the eye may be off),
//     [1] += 1 per pixel with more than 4 stretches or more than 48 events.
#include "common/frame.glsl"
#include "common/unit_shape.glsl"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

const int kIntervals = 4;            // kSubtractIntervals in gpu_types.hpp
const uint kCrossings = 16u;         // kSubtractCrossings
const int kMaxEvents = 48;

layout(binding = 4) uniform sampler2D uLinearDepth;
layout(location = 0) uniform int uSubtractVolumeCount;
layout(location = 1) uniform int uMeshCrossings;

#include "common/packed_volume.glsl"

layout(std430, binding = 4) writeonly buffer SubtractIntervals { vec4 subtractIntervals[]; };
layout(std430, binding = 5) readonly buffer SubtractVolumes { PackedVolume subtractVolumes[]; };
layout(std430, binding = 6) buffer SubtractCounts { uint subtractCounts[]; };
layout(std430, binding = 7) readonly buffer SubtractCrossings { uint subtractCrossings[]; };

float eventT[kMaxEvents];
int eventStep[kMaxEvents];  // +1 entry, -1 exit
int eventCount = 0;
bool overflow = false;

void addEvent(float t, int step) {
    if (eventCount < kMaxEvents) {
        eventT[eventCount] = t;
        eventStep[eventCount] = step;
        ++eventCount;
    } else {
        overflow = true;
    }
}

vec2 stretches[kIntervals];
int stretchCount = 0;

void addStretch(float a, float b) {
    if (!(b > a)) return;
    if (stretchCount < kIntervals) {
        stretches[stretchCount++] = vec2(a, b);
    } else {
        stretches[kIntervals - 1].y = b;  // merged into the last
        overflow = true;
    }
}

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = ivec2(frame.viewportSize);
    if (pixel.x >= size.x || pixel.y >= size.y) return;
    uint index = uint(pixel.y * size.x + pixel.x);
    float depth01 = texelFetch(uLinearDepth, pixel, 0).r;
    vec3 farRay = farRayAtFragment(vec2(pixel) + 0.5);

    int inside = 0;  // subtract volumes holding the eye
    if (uMeshCrossings != 0) {
        uint count = subtractCounts[2u + index];
        if (count > kCrossings) atomicAdd(subtractCounts[0], 1u);
        uint kept = min(count, kCrossings);
        for (uint i = 0u; i < kept; ++i) {
            uint bits = subtractCrossings[index * kCrossings + i];
            int step = (bits & 1u) != 0u ? 1 : -1;
            inside -= step;  // closed meshes: the count at the eye is minus the changes ahead
            addEvent(uintBitsToFloat(bits & ~1u), step);
        }
    }
    for (int v = 0; v < uSubtractVolumeCount; ++v) {
        PackedVolume sv = subtractVolumes[v];
        vec3 rel = frame.eye - sv.position;
        vec3 o = vec3(dot(sv.objectFromWorldRow0, rel), dot(sv.objectFromWorldRow1, rel),
                      dot(sv.objectFromWorldRow2, rel));
        vec3 d = vec3(dot(sv.objectFromWorldRow0, farRay), dot(sv.objectFromWorldRow1, farRay),
                      dot(sv.objectFromWorldRow2, farRay));
        vec2 hit = unitShapeHit(sv.shape, o, d);
        if (!(hit.x < hit.y) || !(hit.y > 0.0)) continue;
        if (hit.x <= 0.0) {
            ++inside;
        } else {
            addEvent(hit.x, 1);
        }
        addEvent(hit.y, -1);
    }
    // Insertion sort by t (a handful of events).
    for (int i = 1; i < eventCount; ++i) {
        float t = eventT[i];
        int step = eventStep[i];
        int j = i - 1;
        while (j >= 0 && eventT[j] > t) {
            eventT[j + 1] = eventT[j];
            eventStep[j + 1] = eventStep[j];
            --j;
        }
        eventT[j + 1] = t;
        eventStep[j + 1] = step;
    }
    int count = max(inside, 0);
    float start = 0.0;
    for (int i = 0; i < eventCount; ++i) {
        float t = clamp(eventT[i], 0.0, depth01);
        int before = count;
        count = max(count + eventStep[i], 0);
        if (before == 0 && count > 0) {
            start = t;
        } else if (before > 0 && count == 0) {
            addStretch(start, t);
        }
    }
    if (count > 0) addStretch(start, depth01);
    if (overflow) atomicAdd(subtractCounts[1], 1u);

    vec4 pairs[2] = vec4[2](vec4(0.0), vec4(0.0));
    for (int k = 0; k < stretchCount; ++k) {
        if (k < 2) {
            pairs[0][2 * k] = stretches[k].x;
            pairs[0][2 * k + 1] = stretches[k].y;
        } else {
            pairs[1][2 * (k - 2)] = stretches[k].x;
            pairs[1][2 * (k - 2) + 1] = stretches[k].y;
        }
    }
    subtractIntervals[2u * index] = pairs[0];
    subtractIntervals[2u * index + 1u] = pairs[1];
}
