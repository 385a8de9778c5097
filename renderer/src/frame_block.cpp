// frame_block.cpp — makeFrameBlock: the per-frame uniforms from the camera,
// core's evaluated PresetState and the frame settings (no GL).
#include "frame_block.hpp"

#include "sky_textures.hpp"

#include <aerial/evaluate.hpp>
#include <aerial/exposure.hpp>
#include <aerial/finite.hpp>
#include <aerial/fog_light.hpp>
#include <aerial/night_sky.hpp>
#include <aerial/sky.hpp>
#include <aerial/stars.hpp>
#include <aerial/sun.hpp>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace aerial::renderer {

namespace detail {

Vec4 toVec4(const glm::dvec3& v, double w) {
    return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z), static_cast<float>(w)};
}

Vec3 toVec3(const glm::dvec3& v) {
    return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)};
}

Mat4 toMat4(const glm::dmat4& m) {
    Mat4 out;
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) out.m[c * 4 + r] = static_cast<float>(m[c][r]);
    }
    return out;
}

double nonNegative(double x, double bound) {
    return (std::isfinite(x) && x > 0.0) ? std::min(x, bound) : 0.0;
}

glm::dvec3 colourOf(const glm::dvec3& c) {
    return {nonNegative(c.x, 1e30), nonNegative(c.y, 1e30), nonNegative(c.z, 1e30)};
}

glm::dvec3 unitOr(const glm::dvec3& v, const glm::dvec3& fallback) {
    if (!isFinite(v)) return fallback;
    const double m = std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
    if (!(m > 0.0)) return fallback;
    return glm::normalize(v / m);
}

double frameStarIlluminance(const PresetState& /*state*/, const FrameDesc& frame) {
    return frame.stars ? kStarIlluminance : 0.0;
}

FrameBlock makeFrameBlock(const Camera& camera, const CameraFrame& view, const PresetState& state,
                          const FrameDesc& frame, const FrameBlockInputs& in) {
    const int w = in.width, h = in.height;
    const LightState& sun = state.sunLight;
    const LightState& moon = state.moonLight;
    const Environment& env = state.environment;
    FrameBlock fb;
    fb.clipFromWorld = toMat4(view.clipFromWorld);
    fb.eye = toVec3(view.eye);
    fb.farDistance = static_cast<float>(view.farDistance);
    fb.forward = toVec3(view.forward);
    fb.nearDistance = static_cast<float>(view.nearDistance);
    for (int k = 0; k < 4; ++k) fb.farCornerRays[k] = toVec4(view.farCornerRays[k]);
    fb.viewportSize[0] = float(w);
    fb.viewportSize[1] = float(h);
    fb.viewportTexel[0] = 1.0f / float(w);
    fb.viewportTexel[1] = 1.0f / float(h);

    // Discs: chord 2 sin(r/2) and 1 / solid angle = 1 / (4 pi sin^2(r/2)),
    // in double (1 - cos r in float loses 3 digits at the sun's 0.27 deg).
    const double sunDisc = nonNegative(frame.sunDiscRadius, 0.5);
    const double moonDisc = nonNegative(frame.moonDiscRadius, 0.5);
    auto chord = [](double r) { return 2.0 * std::sin(0.5 * r); };
    auto perSolidAngle = [](double r) {
        const double s = std::sin(0.5 * r);
        return r > 0.0 ? 1.0 / (4.0 * kPi * s * s) : 0.0;
    };
    fb.sunDirection = toVec3(unitOr(sun.body.direction, {0.0, 1.0, 0.0}));
    fb.sunDiscChord = static_cast<float>(chord(sunDisc));
    fb.sunIlluminanceSpace = toVec3(colourOf(sun.illuminanceSpace));
    fb.sunIlluminance = toVec3(colourOf(sun.illuminance));
    fb.sunDiscInverseSolidAngle = static_cast<float>(perSolidAngle(sunDisc));
    fb.moonDirection = toVec3(unitOr(moon.body.direction, {0.0, 1.0, 0.0}));
    fb.moonDiscChord = static_cast<float>(chord(moonDisc));
    fb.moonIlluminanceSpace = toVec3(colourOf(moon.illuminanceSpace));
    fb.moonIlluminance = toVec3(colourOf(moon.illuminance));
    fb.moonDiscInverseSolidAngle = static_cast<float>(perSolidAngle(moonDisc));
    // The discs at the apparent (refracted) position — refraction is at most
    // ~0.6 deg; a body whose apparent direction is farther than 1 deg from
    // its geometric one was built by hand without it, and keeps the latter.
    auto discDirection = [](const CelestialBody& b) {
        const glm::dvec3 geometric = unitOr(b.direction, {0.0, 1.0, 0.0});
        const glm::dvec3 apparent = unitOr(b.apparentDirection, geometric);
        return glm::dot(apparent, geometric) > std::cos(kPi / 180.0) ? apparent : geometric;
    };
    const glm::dvec3 sunDisc3 = discDirection(sun.body), moonDisc3 = discDirection(moon.body);
    fb.sunDiscDirection = toVec3(sunDisc3);
    fb.moonDiscDirection = toVec3(moonDisc3);
    // The moon's phase the right way round: the lit fraction k and the bright
    // limb's position angle chi (from the zenith through east, sun.hpp) as a
    // tangent b = cos(chi) up + sin(chi) east at the moon's disc.
    const double k = moon.body.illuminatedFraction;
    fb.moonLitFraction = static_cast<float>(std::isfinite(k) ? std::clamp(k, 0.0, 1.0) : 1.0);
    const glm::dvec3 upWorld(0.0, 1.0, 0.0);
    glm::dvec3 up = upWorld - moonDisc3 * glm::dot(moonDisc3, upWorld);
    glm::dvec3 east = glm::cross(upWorld, moonDisc3);
    if (glm::dot(up, up) < 1e-12 || glm::dot(east, east) < 1e-12) {  // the moon at the zenith
        east = glm::dvec3(1.0, 0.0, 0.0);
        up = glm::cross(moonDisc3, east);
    }
    const double chi = std::isfinite(moon.body.brightLimbAngle) ? moon.body.brightLimbAngle : 0.0;
    fb.moonBrightLimb = toVec3(unitOr(
        std::cos(chi) * glm::normalize(up) + std::sin(chi) * glm::normalize(east), glm::normalize(up)));

    const double mie = env.atmosphere.mieAnisotropy;
    const double g = std::isfinite(mie) ? std::clamp(mie, -0.999, 0.999) : 0.0;
    fb.sunHorizonRayleigh = toVec3(colourOf(in.sun.horizonRayleigh));
    fb.mieAnisotropy = static_cast<float>(g);
    fb.sunHorizonMie = toVec3(colourOf(in.sun.horizonMie));
    fb.moonHorizonRayleigh = toVec3(colourOf(in.moon.horizonRayleigh));
    fb.moonHorizonMie = toVec3(colourOf(in.moon.horizonMie));
    fb.sunHorizonMultiple = toVec3(colourOf(in.sun.horizonMultiple));
    fb.moonHorizonMultiple = toVec3(colourOf(in.moon.horizonMultiple));
    const glm::dvec3 ambient =
        in.clearSkyIrradiance
            ? colourOf(*in.clearSkyIrradiance)
            : (in.sun.valid && in.sun.table ? skyIrradiance(*in.sun.table, g, colourOf(sun.illuminanceSpace))
                                            : glm::dvec3(0.0)) +
                  (in.moon.valid && in.moon.table
                       ? skyIrradiance(*in.moon.table, g, colourOf(moon.illuminanceSpace))
                       : glm::dvec3(0.0));
    // The airglow is physical (1e-9 of a day sky) and always part of the
    // sky, as in sky.glsl and core's fog light and light report; a city's
    // glow, when the preset has one, joins it.
    const LightPollution& glow = env.lightPollution;
    const glm::dvec3 airglow = airglowIrradiance(state.zenithTransmittance) + lightPollutionIrradiance(glow);
    fb.lightPollutionZenith = toVec3(
        colourOf(lightPollutionRadiance(glow, glm::dvec3(0.0, 1.0, 0.0), env.location.northOffsetDeg)));
    fb.lightPollutionCity = toVec3(lightPollutionCityDirection(glow, env.location.northOffsetDeg));
    fb.lightPollutionUplightDepth = static_cast<float>(kLightPollutionUplightDepth);
    fb.airglowZenithRadiance = toVec3(kAirglowZenithRadiance);
    fb.airglowScatteredFill = static_cast<float>(kAirglowScatteredFill);
    fb.airglowShell = static_cast<float>(kAirglowShellRatio);
    fb.skyAmbient = toVec3(colourOf(ambient + airglow));
    // Below the cloud deck: the clear sky (and the airglow) through its gaps
    // and the deck's underside (OvercastLight::groundIrradiance).
    const CloudOvercast& overcast = in.overcast.overcast;
    const double skyCover = std::isfinite(overcast.skyCover) ? std::clamp(overcast.skyCover, 0.0, 1.0) : 0.0;
    const glm::dvec3 deck = colourOf(in.overcast.radiance);
    fb.groundAmbient = skyCover > 0.0
                           ? toVec3(colourOf((1.0 - skyCover) * (ambient + airglow) + skyCover * kPi * deck))
                           : fb.skyAmbient;
    fb.overcastCover = static_cast<float>(
        std::isfinite(overcast.horizonCover) ? std::clamp(overcast.horizonCover, 0.0, 1.0) : 0.0);
    fb.overcastRadiance = toVec3(deck);
    fb.overcastSkyCover = static_cast<float>(skyCover);

    // The light that reaches the fog (aerial/fog_light.hpp), as FogScene
    // takes it (fogSceneDesc): the same core functions of the same inputs.
    {
        const SkyTable empty;
        const FogSkyLight fogSky =
            fogSkyLight(state, in.sun.valid && in.sun.table ? *in.sun.table : empty,
                        in.moon.valid && in.moon.table ? *in.moon.table : empty, in.overcast);
        fb.fogSkyL0 = toVec3(colourOf(fogSky.l0));
        const auto band = [](const glm::dvec3& v) {
            return isFinite(v) ? toVec3(glm::clamp(v, -1e30, 1e30)) : Vec3{};
        };
        fb.fogSkyL1x = band(fogSky.l1[0]);
        fb.fogSkyL1y = band(fogSky.l1[1]);
        fb.fogSkyL1z = band(fogSky.l1[2]);
        fb.fogDirectVisibility = static_cast<float>(fogDirectVisibility(in.overcast));
        fb.fogHorizonDistance = static_cast<float>(kFogHorizonDistance);
    }

    // Without the global fog pass, the transparent meshes and particles get
    // no global fog either (they read the same density).
    const HeightFogParams& fog = env.fog;
    fb.fogDensity = static_cast<float>(frame.passes.globalFog ? nonNegative(fog.density, 1e30) : 0.0);
    fb.fogFalloff = static_cast<float>(nonNegative(fog.falloff, 1e30));
    fb.fogBaseHeight =
        static_cast<float>(std::isfinite(fog.baseHeight) ? std::clamp(fog.baseHeight, -1e30, 1e30) : 0.0);
    fb.fogColourMode = static_cast<float>(static_cast<int>(env.fogColourMode));
    fb.fogColour = toVec3(colourOf(env.fogColour));
    // Radiance cap per pass output: an RGBA16F target must never reach Inf
    // (the sun disc alone is ~3e5 for the default sun); see frame.glsl.
    fb.radianceCap = static_cast<float>(frame.precision == ColourPrecision::Float ? 1e30 : 3.0e4);

    fb.sunTableAzimuth = static_cast<float>(in.sun.lightAzimuth);
    fb.moonTableAzimuth = static_cast<float>(in.moon.lightAzimuth);
    fb.sunTableColumns = float(in.sun.columns);
    fb.sunTableRows = float(in.sun.rows);
    fb.emitterCount = in.emitterCount;
    fb.subtractActive = in.subtractActive ? 1 : 0;
    fb.moonTableColumns = in.moon.columns;
    fb.moonTableRows = in.moon.rows;
    fb.sunTableWarped = in.sun.warped ? 1.0f : 0.0f;
    fb.moonTableWarped = in.moon.warped ? 1.0f : 0.0f;

    // Stars: the celestial frame, the brightest star's illuminance, the
    // Gaussian radius of a star, sigma = 0.6 pixel (vertical angle / rows),
    // and what the limiting magnitude needs (aerial/stars.hpp).
    const double starE = nonNegative(frameStarIlluminance(state, frame), 1e30);
    CelestialFrame celestial;
    if (starE > 0.0) celestial = celestialFrame(env.location, state.timeHours);
    // The zenith's transmittance dims the stars and the airglow, which is
    // drawn with the stars off too.
    const glm::dvec3 zenithTransmittance = state.zenithTransmittance;
    const double fov =
        std::isfinite(camera.verticalFov) ? std::clamp(camera.verticalFov, 1e-4, kPi - 1e-4) : 1.0;
    const double starSigma = std::min(0.6 * fov / double(h), kStarMaxSigma);
    fb.starAxisX = toVec3(unitOr(celestial.equatorX, {1.0, 0.0, 0.0}));
    fb.starIlluminance = static_cast<float>(starE);
    fb.starAxisY = toVec3(unitOr(celestial.equatorY, {0.0, 0.0, 1.0}));
    fb.starSigma = static_cast<float>(starSigma);
    fb.starPole = toVec3(unitOr(celestial.pole, {0.0, 1.0, 0.0}));
    fb.starTransmittance = toVec3(glm::clamp(colourOf(zenithTransmittance), 0.0, 1.0));
    fb.starNitsPerUnit = static_cast<float>(kNitsPerRadianceUnit);
    fb.starDarkLimit = static_cast<float>(limitingMagnitude(0.0));
    return fb;
}

}  // namespace detail
}  // namespace aerial::renderer
