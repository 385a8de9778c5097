// common/frame.glsl — the per-frame uniform block shared by every pass, and
// world-position reconstruction from linear depth (Wenzel 2006, "Real-Time
// Atmospheric Effects in Games", section 6.3: one multiply-add per pixel).
//
// Inputs (std140, binding 0; mirrored by FrameBlock in
// renderer/src/gpu_types.hpp with static_asserted offsets):
//   clipFromWorld       world [m] -> clip space
//   eyeFar              xyz: camera position [m], w: far distance [m]
//   forwardNear         xyz: unit view direction, w: near distance [m]
//   farCornerRays[4]    eye -> far-plane corner [m], world space:
//                       bottom-left, bottom-right, top-left, top-right
//   viewport            width, height [px], 1/width, 1/height
//   lights              sun / moon: direction (unit, towards the light; w:
//                       the disc's chord 2 sin(r/2), 0 = no disc),
//                       illuminance above the atmosphere E (rgb),
//                       illuminance reaching the ground (rgb; w: 1 / the
//                       disc's solid angle [1/sr]), phase-less
//                       horizon averages I_R, I_M (w of sunHorizonRayleigh:
//                       Mie anisotropy g), table mapping (light azimuth [rad]
//                       and table size)
//   skyAmbient          rgb: cosine-weighted sky irradiance on an upward
//                       surface (E_sky, same unit as E)
//   fogParams           x: density b [1/m], y: falloff c [1/m], z: base
//                       height h0 [m], w: colour mode (0 sky, 1 tinted, 2 custom)
//   fogColour           rgb: tint or radiance of the global fog; w: the
//                       radiance cap of every pass output (3e4 for an RGBA16F
//                       target, so sky/scene plus emitters stay below the half
//                       maximum 65504 and no pixel becomes Inf; 1e30 for RGBA32F).
//                       The fog passes only interpolate between the target and
//                       capped colours, so they stay below the cap too.
//   skyTableMapping     x, y: the sun's / moon's table light azimuth [rad];
//                       z, w: the sun table's columns and rows
//   counts              x: emitter count; y, z: the moon table's columns, rows
//   starAxisX, starAxisY, starPole   the celestial frame (world, unit);
//                       starAxisX.w: the brightest star's illuminance (0 = no
//                       stars), starAxisY.w: a star's Gaussian radius [rad]
//   starTransmittance   rgb: transmittance viewer -> space at the zenith
//
// Linear depth (the frame's R32F texture): normalised linear eye depth,
// z_view / far, 0 at the camera and 1 at the far plane (sky pixels hold 1),
// as in CryEngine 2. The ray to the far plane through a pixel, interpolated
// bilinearly between the four corner rays, gives the world position with one
// multiply-add:  p = eye + depth01 * farRay.
#ifndef AERIAL_FRAME_GLSL
#define AERIAL_FRAME_GLSL

layout(std140, binding = 0) uniform FrameBlock {
    mat4 clipFromWorld;
    vec4 eyeFar;
    vec4 forwardNear;
    vec4 farCornerRays[4];
    vec4 viewport;
    vec4 sunDirection;
    vec4 sunIlluminanceSpace;
    vec4 sunIlluminance;
    vec4 moonDirection;
    vec4 moonIlluminanceSpace;
    vec4 moonIlluminance;
    vec4 sunHorizonRayleigh;
    vec4 sunHorizonMie;
    vec4 moonHorizonRayleigh;
    vec4 moonHorizonMie;
    vec4 skyAmbient;
    vec4 fogParams;
    vec4 fogColour;
    vec4 skyTableMapping;  // x, y: sun / moon light azimuth [rad]; z, w: sun table columns, rows
    ivec4 counts;          // x: emitters; y, z: moon table columns, rows
    vec4 starAxisX;
    vec4 starAxisY;
    vec4 starPole;
    vec4 starTransmittance;
} frame;

// Ray from the eye to the far plane at normalised device coordinates ndc
// (-1..1): bilinear in the corner rays, hence affine in ndc.
vec3 farRayAtNdc(vec2 ndc) {
    vec2 f = ndc * 0.5 + 0.5;
    vec3 bottom = mix(frame.farCornerRays[0].xyz, frame.farCornerRays[1].xyz, f.x);
    vec3 top = mix(frame.farCornerRays[2].xyz, frame.farCornerRays[3].xyz, f.x);
    return mix(bottom, top, f.y);
}

// The same ray for a fragment (pixel centre) of the frame.
vec3 farRayAtFragment(vec2 fragCoord) { return farRayAtNdc(fragCoord * frame.viewport.zw * 2.0 - 1.0); }

// World position [m] of a pixel from its normalised linear depth.
vec3 worldFromDepth(float depth01, vec3 farRay) { return frame.eyeFar.xyz + depth01 * farRay; }

#endif
