// clouds.glsl — the cloud layer pass (renderer/src/cloud_pass.cpp): a
// full-resolution march per pixel through the shell segments of
// common/clouds.glsl (core's cloudOpticalDepth midpoint placement; the lit
// march refines it where a cloud begins, below), lit by the
// sun and moon after the atmosphere, the sky and lightning emitters, then
// faded into the air between the viewer and the cloud (DESIGN.md "Clouds").
//
// The lit march (not the transmittance mode) refines the steps where the
// surface of a cloud is: a step that enters a cloud (the sample before was
// empty) is re-marched from the sample before in kEntrySubSteps sub-steps,
// and an optically thick step is split (kSubStepDepth). Before, a dense
// cloud took a whole step's opacity at one sample, so its surface sat where
// the first sample inside it fell, and that moved by a step along the ray
// from row to row of pixels: contour bands across every cloud seen at a low
// angle (a camera 400 m up looking 3 deg above the horizon: 64 steps of
// ~530 m, optical depth ~16 each). Measured (test_renderer_clouds,
// GrazingCloudsConvergeWithoutBands: 64 against 1024 steps, 5x5-filtered
// sky PSNR; bench_renderer CloudsReferenceVsAmortised/320/180, llvmpipe
// here, the reference pass looking up from the valley), in one session:
//   midpoint march only                              30.2 dB   237 ms
//   thick steps split                                35.5 dB   381 ms
//   + sqrt(path / thickness) x the samples (<= 4x)   52.1 dB   550 ms
//   thick steps split + entries refined              46.4 dB   448 ms
//   the same + the samples on long paths (<= 2x)     56.5 dB   644 ms
//   entries refined + the far clouds' filter (this)  56.2 dB
// (the filter: common/clouds.glsl, cloudDensityFiltered; on llvmpipe it
// costs ~40% of the cloud pass, trilinear 3D lookups of two moments).
// (the timings vary by ~15% from run to run; the grazing 640x360 frame of
// above: 1.05 s before, 1.8 s now, 2.9 s with 4x the samples).
// A per-pixel offset of the samples (interleaved gradient noise) only
// turned what was left into grain (no closer to the converged march): the
// samples stay at the midpoints.
//
// Inputs: frame (eye, corner rays, lights: direction and E_ground,
//   skyAmbient), CloudBlock and the noise (common/clouds.glsl), the sky
//   tables (units 0..3, the air's colour), uLinearDepth (unit 4), the
//   emitters (binding 2).
// uTrace (location 0): zero for the reference; the amortised path's trace
//   (block size, and which pixel of each block) otherwise, see main.
// Output (location 0), blended with glBlendFunc(GL_ONE, GL_SRC_ALPHA):
//   rgb = S (the clouds' radiance reaching the eye), a = T (their
//   transmittance), so L <- L T + S: the sky and the scene behind are seen
//   through the cloud. CloudBlock.outputMode 1 (tests): rgb = (T, tau, 0),
//   a = 1, unblended, with T = exp(-tau) the plain march (no early exit),
//   which is aerial::cloudTransmittance(eye, v, scene distance, steps).
//
// The view ray stops at the scene: t <= the linear scene depth along the ray
// (sky pixels: no limit). The optical depth is continuous in that distance,
// so terrain reaching into the layer clips the clouds softly (the density
// between the eye and the terrain fades the cloud out; no hard edge).
//
// Per sample of extinction sigma_t = rho and scattering sigma_s = albedo rho:
//   S(p) = sigma_s [ sum_lights E_l sum_{i<N} a^i P_i(mu_l) exp(-b^i tau_l(p))
//                    + E_sky / (2 pi) A(f)
//                    + sum_emitters colour e / (1 + a_e r^2) / (4 pi) ]
// integrated over a step of length d with Hillaire 2015's energy-conserving
// form S_int = (S - S exp(-sigma_t d)) / sigma_t, L += T S_int,
// T *= exp(-sigma_t d).
//   Lights: E_l is the light above the atmosphere times its transmittance
//     from the cloud point (lightAtCloud: Schueler's Chapman function for
//     Rayleigh and Mie at the point's height), so high clouds keep the
//     sun after it set on the ground; tau_l the optical depth towards the
//     light by kLightSteps midpoint samples over [0, min(exit of the top
//     sphere, kLightMaxDistanceFactor x thickness)], quadratically spaced
//     (dense near p). Beer-Lambert, no powder term.
//   Multiple scattering: Wrenninge 2013 ("Oz: the great and volumetric",
//     SIGGRAPH talk) as Hillaire 2016 uses it ("Physically based sky,
//     atmosphere and cloud rendering in Frostbite", section 5.5.2): N =
//     kOctaves = 3 octaves, scattering a^i, extinction b^i, phase
//     anisotropy c^i with a = 0.5, b = 0.5, c = 0.5 (a <= b keeps it
//     energy-conserving); and, for the light deep in a thick cloud that
//     the octaves' Beer-Lambert all but loses, the two-stream diffusion
//     transmittance (1 - e^-tau) / (1 + 3/4 tau (1 - 0.85)) x mu_l / pi (Bohren 1987,
//     "Multiple scattering of light and some of its observable
//     consequences"), isotropic: cloud bases stay grey, not black.
//   Phase P_i: two Henyey-Greenstein lobes, mix(HG(mu, g c^i),
//     HG(mu, -0.3 c^i), 0.3): the forward lobe g = clouds.anisotropy gives
//     the silver lining round a cloud in front of the sun, the back lobe
//     (-0.3, weight 0.3) lightens the side facing the light.
//   Ambient: the sky above as a uniform upper hemisphere of radiance
//     L_sky = E_sky / pi (E_sky the sky's irradiance on the ground) and the
//     ground below as a uniform lower one of L_gnd = a E_gnd / pi (albedo
//     a under the sun, the moon and the sky, seen through the gaps, and a
//     city's uplight, lightPollutionUplight), each scattered towards the
//     eye by the cloud's phase: F(mu), the share of the light arriving
//     from a hemisphere that the octave-0 phase sends into a direction at
//     cosine mu from that hemisphere's pole (cloudHemisphereShare: the
//     Legendre series of the two lobes by Funk-Hecke, sum (2l+1)/2 g_l
//     c_l P_l(mu), c_l = int_0^1 P_l, exact to 1e-4). A thin
//     forward-scattering cloud seen from below hence gives back most of the
//     sky it hides (F = 0.76 at g = 0.85), seen from above little. Deeper in
//     the cloud the light from a hemisphere is dimmed and made isotropic by
//     the optical depth tau between the sample and that side of the cloud:
//     D = 1 / (1 + 3/4 tau (1 - 0.85)) (the two-stream diffuse
//     transmittance, Bohren 1987, as for the sun's diffuse light) and the share
//     mix(1/2, F, D); tau = rho (f_top - f) H above and rho f H below, from
//     the sample's own extinction rho, its height fraction f, the profile's
//     top f_top and the layer's thickness H (a local estimate: no march).
//     A thin deck's base sees the whole sky; a thick cloud's a quarter.
//   Emitters: their fog falloff read as irradiance (as in shading.glsl),
//     isotropic, unshadowed: lightning inside the layer lights it up.
// Air: the clouds' radiance is seen through the atmosphere between the eye
//   and the cloud's transmittance-weighted distance d_c = sum t (T_i -
//   T_i+1) / (1 - T): T_air = exp(-(beta_R tau(H_R) + beta_M,ext tau(H_M)))
//   with tau the exponential integral from the eye's height to the cloud
//   point's (the global fog's formula, atmosphere.glsl), and the air's own
//   light there taken from the sky behind (skyRadiance(v)), so a distant
//   cloud fades into the sky at the horizon:
//   S = S_cloud T_air + (1 - T) (1 - T_air) L_sky(v).
// Robustness: a sample with no density costs one profile test; the march
//   stops once T < kTransmittanceCutoff (lit mode); NaN or Inf never leave
//   the pass (S sanitised to [0, radianceCap], T to [0, 1]).
#include "common/frame.glsl"

#ifdef AERIAL_VERTEX_SHADER
#include "common/fullscreen.glsl"
#else
#include "common/atmosphere.glsl"
#include "common/sky_table.glsl"
#include "common/emitters.glsl"
#include "common/clouds.glsl"

layout(binding = 4) uniform sampler2D uLinearDepth;

in vec3 vFarRay;
/// (0, 0, 0): the reference, one fragment per pixel. (x, y, n): the
/// amortised trace into a target of one texel per n x n block, marching
/// the block's pixel (x, y).
layout(location = 0) uniform ivec3 uTrace;
layout(location = 0) out vec4 outColour;

const int kOctaves = 3;
const float kOctaveScattering = 0.5;  // a
const float kOctaveExtinction = 0.5;  // b
const float kDiffuseWeight = 1.0;
const float kOctavePhase = 0.5;       // c
const float kBackLobeG = -0.3;
const float kBackLobeWeight = 0.3;
const float kLightMaxDistanceFactor = 4.0;
const float kTransmittanceCutoff = 1e-3;
const float kDiffuseG = 0.85;  // the droplets' g of the two-stream terms (Bohren 1987)
const float kSubStepDepth = 0.5;  // optical depth of a sub-step of a thick step
const int kMaxSubSteps = 8;
const int kEntrySubSteps = 6;  // sub-steps of a cloud's entry (1.5 steps)

/// Henyey-Greenstein (1 - g^2) / (4 pi (1 + g^2 - 2 g mu)^1.5) [1/sr].
float henyeyGreenstein(float mu, float g) {
    float g2 = g * g;
    float denom = max(1.0 + g2 - 2.0 * g * clamp(mu, -1.0, 1.0), 1e-6);
    return (1.0 - g2) / (4.0 * kPi * denom * sqrt(denom));
}

/// The two-lobe phase of octave i (anisotropies scaled by c^i).
float cloudPhase(float mu, float octaveScale) {
    return mix(henyeyGreenstein(mu, clouds.anisotropy * octaveScale),
               henyeyGreenstein(mu, kBackLobeG * octaveScale), kBackLobeWeight);
}

/// The share of light arriving uniformly from a hemisphere that the octave-0
/// phase scatters into a direction at cosine mu from the hemisphere's pole
/// (the direction the light travels in): F(mu) = int_hemisphere P(w . d) dw,
/// 1/2 for an isotropic phase, F(mu) + F(-mu) = 1. By Funk-Hecke on the
/// Legendre series of each HG lobe (coefficients g^l): F = 1/2 + sum over
/// odd l of g_l (P_(l-1)(0) - P_(l+1)(0)) / 2 P_l(mu), g_l the lobes'
/// mixed g^l, summed until they fall below 1e-4 (l <= ~180 at g = 0.95).
float cloudHemisphereShare(float mu) {
    mu = clamp(mu, -1.0, 1.0);
    float share = 0.5;
    float forward = clouds.anisotropy, back = kBackLobeG;  // g^l of the two lobes, l odd
    float p0Below = 1.0;                                    // P_(l-1)(0)
    float pBelow = 1.0, p = mu;                             // P_(l-1)(mu), P_l(mu)
    for (int l = 1; l < 400; l += 2) {
        float gl = mix(forward, back, kBackLobeWeight);
        if (abs(forward) + abs(back) < 1e-4) break;
        float p0Above = -p0Below * float(l) / float(l + 1);  // P_(l+1)(0)
        share += gl * 0.5 * (p0Below - p0Above) * p;
        float pNext = (float(2 * l + 1) * mu * p - float(l) * pBelow) / float(l + 1);  // P_(l+1)
        float pNext2 = (float(2 * l + 3) * mu * pNext - float(l + 1) * p) / float(l + 2);
        pBelow = pNext;
        p = pNext2;
        p0Below = p0Above;
        forward *= clouds.anisotropy * clouds.anisotropy;
        back *= kBackLobeG * kBackLobeG;
    }
    return clamp(share, 0.0, 1.0);
}

/// The light of a hemisphere of radiance L at a cloud sample: L D mix(1/2,
/// F, D), D the two-stream transmittance of the optical depth tau between
/// the sample and that side of the cloud (the Ambient paragraph above).
vec3 hemisphereLight(vec3 radiance, float share, float tau) {
    float d = 1.0 / (1.0 + 0.75 * (1.0 - kDiffuseG) * max(tau, 0.0));
    return radiance * (d * mix(0.5, share, d));
}

/// Schueler's analytic Chapman function (Schueler 2012, "An efficient and
/// physically plausible real-time sky shading model", GPU Pro 3): the
/// optical depth of an exponential atmosphere from normalised height h =
/// height / H towards zenith cosine mu, in units of beta H, with X = Rg / H;
/// below the point's horizon it goes through the grazing point, so a light
/// behind the planet gets an enormous depth (no light).
float chapman(float X, float h, float mu) {
    float c = sqrt(X + h);
    if (mu >= 0.0) return c / (c * mu + 1.0) * exp(-h);
    float x0 = sqrt(max(1.0 - mu * mu, 0.0)) * (X + h);
    float c0 = sqrt(x0);
    return 2.0 * c0 * exp(X - x0) - c / (1.0 - c * mu) * exp(-h);
}

/// The light above the atmosphere as it reaches the point p: at the cloud's
/// height, not the viewer's, so a layer at 6 km stays lit red after the
/// sun has set on the ground (Rayleigh and Mie extinction; ozone left out).
vec3 lightAtCloud(vec3 p, vec3 l, vec3 illuminanceSpace) {
    float height = max(cloudHeightAboveGround(p), 0.0);
    // The light's zenith cosine at p (the local vertical of the sphere).
    vec3 up = normalize(p + vec3(0.0, clouds.planetRadius, 0.0));
    float mu = dot(up, l);
    float hR = max(clouds.rayleighScaleHeight, 1.0), hM = max(clouds.mieScaleHeight, 1.0);
    vec3 tau = clouds.rayleighScattering * hR * chapman(clouds.planetRadius / hR, height / hR, mu) +
               clouds.mieExtinction * hM * chapman(clouds.planetRadius / hM, height / hM, mu);
    return illuminanceSpace * exp(-min(tau, vec3(80.0)));
}

/// Optical depth from p towards the light l (unit) through the layer.
float lightOpticalDepth(vec3 p, vec3 l) {
    float t0, t1;
    if (!cloudSphereRoots(p, l, clouds.bottomM + clouds.thicknessM, t0, t1)) return 0.0;
    float len = min(max(t1, 0.0), kLightMaxDistanceFactor * clouds.thicknessM);
    if (!(len > 0.0)) return 0.0;
    int n = max(clouds.lightSteps, 1);
    float tau = 0.0;
    float previous = 0.0;
    for (int i = 1; i <= n; ++i) {
        float s = float(i) / float(n);
        float edge = len * s * s;
        tau += cloudDensityAt(p + l * (0.5 * (previous + edge))) * (edge - previous);
        previous = edge;
    }
    return tau;
}

/// In-scattering of one light with illuminance E at p (per unit sigma_s).
vec3 lightScattering(vec3 p, vec3 l, vec3 E, float mu) {
    if (all(equal(E, vec3(0.0)))) return vec3(0.0);
    float tau = lightOpticalDepth(p, l);
    vec3 sum = vec3(0.0);
    float a = 1.0, b = 1.0, c = 1.0;
    for (int i = 0; i < kOctaves; ++i) {
        sum += a * cloudPhase(mu, c) * exp(-b * tau) * E;
        a *= kOctaveScattering;
        b *= kOctaveExtinction;
        c *= kOctavePhase;
    }
    // The light that scattered many times: inside a thick cloud it is a
    // nearly isotropic diffuse field of radiance F_d / pi, F_d = E mu_l T_d
    // the diffuse flux, T_d = 1 / (1 + 3/4 tau (1 - g)) the two-stream
    // (diffusion) transmittance of a slab of optical depth tau with the
    // droplets' g = 0.85 (Bohren 1987); with a normalised phase the source
    // per unit sigma_s is that radiance. Faded in with (1 - e^-tau) so the
    // edges keep the octaves' look. Without it sunlit tops read darker than
    // the ground between them and bases go black.
    float muUp = max(dot(normalize(p + vec3(0.0, clouds.planetRadius, 0.0)), l), 0.0);
    sum += kDiffuseWeight * (1.0 - exp(-tau)) / (1.0 + 0.75 * tau * (1.0 - kDiffuseG)) * muUp / kPi * E;
    return sum;
}

void main() {
    // The amortised path's trace (cloud_amortised.cpp): this fragment is one
    // block of uTrace.z x uTrace.z pixels and marches the ray of the block's
    // pixel uTrace.xy (clamped to the frame), with that pixel's depth.
    vec3 farRay = vFarRay;
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    if (uTrace.z > 0) {
        pixel = min(pixel * uTrace.z + uTrace.xy, ivec2(frame.viewportSize) - 1);
        farRay = farRayAtFragment(vec2(pixel) + 0.5);
    }
    float farLength = length(farRay);
    vec3 v = farRay / farLength;
    // The pixel's angular width [rad]. A sample at distance t stands for a
    // footprint of 8 t pixelAngle (the far clouds' filter,
    // cloudDensityFiltered): the thresholded noise needs more than the
    // pixel's own width -- clear_summer_day at 09:30, 640 x 360, looked at:
    // 1, 2 and 4 pixels left pixel noise within 2 deg of the horizon and a
    // hard line above the terrain, 8 none. The step along the ray is not
    // counted (the picture would then depend on clouds.steps).
    float pixelAngle = length(farRayAtFragment(vec2(pixel) + vec2(0.5, 1.5)) - farRay) / farLength;
    float depth01 = texelFetch(uLinearDepth, pixel, 0).r;
    float tMax = depth01 >= 1.0 ? 1.0e30 : depth01 * farLength;
    vec3 o = frame.eye;

    if (clouds.outputMode == 1) {
        float tau = cloudOpticalDepth(o, v, tMax, clouds.steps);
        outColour = vec4(exp(-tau), tau, 0.0, 1.0);
        return;
    }

    vec2 segments[2];
    int count = cloudLayerSegments(o, v, tMax, segments[0], segments[1]);
    if (count == 0) {
        outColour = vec4(0.0, 0.0, 0.0, 1.0);
        return;
    }
    float total = (segments[0].y - segments[0].x) + (count > 1 ? segments[1].y - segments[1].x : 0.0);
    float muSun = dot(v, frame.sunDirection);
    float muMoon = dot(v, frame.moonDirection);
    // The sky above and the ground below as uniform hemispheres (the
    // Ambient paragraph): the ground a Lambertian of the atmosphere's albedo
    // under the sun, the moon and the sky, seen through the gaps between the
    // clouds (the clear fraction, 1 - coverage), and a city's light from
    // below (lightPollutionUplight, night_sky.hpp): clouds over a city glow.
    vec3 skyLight = frame.skyAmbient / kPi;
    vec3 groundIrradiance = frame.sunIlluminance * max(frame.sunDirection.y, 0.0) +
                            frame.moonIlluminance * max(frame.moonDirection.y, 0.0) + frame.skyAmbient;
    vec3 groundLight = clouds.groundAlbedo * groundIrradiance * (1.0 - 0.8 * cloudSaturate(clouds.coverage)) / kPi +
                       lightPollutionUplight(v) / kPi;
    // The light travels from the sky down (pole -y) and towards the eye (-v).
    float skyShare = cloudHemisphereShare(v.y);
    float layerTop = cloudProfileTop(clouds.type) * clouds.thicknessM;
    // The moon's light is marched only when it matters (> 1 % of the sun's).
    bool moonLit = dot(frame.moonIlluminanceSpace, vec3(1.0)) > 0.01 * dot(frame.sunIlluminanceSpace, vec3(1.0)) ||
                   frame.sunDirection.y < -0.15;
    vec3 radiance = vec3(0.0);
    float transmittance = 1.0;
    float weightedDistance = 0.0;
    // The samples at the steps' midpoints, as core's march, refined below
    // where a step holds a cloud's entry or is optically thick. A function
    // of the ray only (no noise), so the amortised path traces exactly the
    // reference.
    for (int k = 0; k < count && transmittance >= kTransmittanceCutoff; ++k) {
        float span = segments[k].y - segments[k].x;
        int n = cloudSegmentSamples(clouds.steps, span, total);
        float dt = span / float(n);
        bool empty = true;  // the sample before held no cloud
        for (int i = 0; i < n && transmittance >= kTransmittanceCutoff; ++i) {
            float t = segments[k].x + (float(i) + 0.5) * dt;
            float f;
            float footprint = 8.0 * t * pixelAngle;
            float rho = cloudDensityFiltered(o + v * t, footprint, f);
            if (!(rho > 0.0)) {
                empty = true;
                continue;
            }
            // The piece this sample stands for: its step, or, entering a
            // cloud (the sample before was empty), from the sample before:
            // the cloud's surface lies somewhere after it. A piece that is
            // optically thick or a cloud's entry would put the surface at
            // one sample, and the surface would jump by a step from pixel to
            // pixel (contour bands): it is split into sub-steps of optical
            // depth <= kSubStepDepth (an entry into at least kEntrySubSteps,
            // at most kMaxSubSteps), each with its own density sample.
            float start = segments[k].x + float(i) * dt - (empty && i > 0 ? 0.5 * dt : 0.0);
            float piece = segments[k].x + float(i + 1) * dt - start;
            int m = clamp(int(ceil(rho * piece / kSubStepDepth)), empty ? kEntrySubSteps : 1, kMaxSubSteps);
            empty = false;
            float h = piece / float(m);
            for (int j = 0; j < m; ++j) {
                float ts = m == 1 ? t : start + (float(j) + 0.5) * h;
                vec3 p = o + v * ts;
                float rhoSub = rho;
                if (m > 1) {
                    rhoSub = cloudDensityFiltered(p, footprint, f);
                    if (!(rhoSub > 0.0)) continue;
                }
                vec3 S = lightScattering(p, frame.sunDirection,
                                         lightAtCloud(p, frame.sunDirection, frame.sunIlluminanceSpace), muSun) +
                         hemisphereLight(skyLight, skyShare, rhoSub * (layerTop - f * clouds.thicknessM)) +
                         hemisphereLight(groundLight, 1.0 - skyShare, rhoSub * f * clouds.thicknessM);
                if (moonLit)
                    S += lightScattering(p, frame.moonDirection,
                                         lightAtCloud(p, frame.moonDirection, frame.moonIlluminanceSpace), muMoon);
                for (int e = 0; e < frame.emitterCount; ++e) {
                    vec3 toEmitter = emitters[e].position - p;
                    S += emitters[e].colour * emitters[e].light.x * emitterDimming(e, p) /
                         ((1.0 + max(emitters[e].attenuation, 0.0) * dot(toEmitter, toEmitter)) * 4.0 * kPi);
                }
                S *= clouds.albedo * rhoSub;
                float stepTransmittance = exp(-rhoSub * h);
                radiance += transmittance * (S - S * stepTransmittance) / rhoSub;
                weightedDistance += ts * transmittance * (1.0 - stepTransmittance);
                transmittance *= stepTransmittance;
                if (transmittance < kTransmittanceCutoff) break;
            }
        }
    }

    // The air between the eye and the cloud.
    float opacity = 1.0 - transmittance;
    float cloudDistance = opacity > 1e-6 ? weightedDistance / opacity : segments[0].x;
    float eyeHeight = cloudHeightAboveGround(o);
    float rise = cloudHeightAboveGround(o + v * cloudDistance) - eyeHeight;
    float rayleighScale = clouds.rayleighScaleHeight > 0.0 ? 1.0 / clouds.rayleighScaleHeight : 0.0;
    float mieScale = clouds.mieScaleHeight > 0.0 ? 1.0 / clouds.mieScaleHeight : 0.0;
    vec3 airTau = clouds.rayleighScattering * exponentialOpticalDepth(1.0, rayleighScale, eyeHeight, rise, cloudDistance) +
                  clouds.mieExtinction * exponentialOpticalDepth(1.0, mieScale, eyeHeight, rise, cloudDistance);
    vec3 air = exp(-airTau);
    vec3 skyBehind = min(skyRadiance(v, false), vec3(frame.radianceCap));
    vec3 S = radiance * air + opacity * (1.0 - air) * skyBehind;

    // Nothing non-finite or negative leaves the pass.
    bool finite = all(greaterThanEqual(S, vec3(0.0))) && all(lessThan(S, vec3(3.0e38)));
    S = finite ? min(S, vec3(frame.radianceCap)) : vec3(0.0);
    transmittance = transmittance >= 0.0 && transmittance <= 1.0 ? transmittance : 1.0;
    outColour = vec4(S, transmittance);
}
#endif
