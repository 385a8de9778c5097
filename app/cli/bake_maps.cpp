// bake_maps.cpp — the bake's per-step sky-view map, far fog map, irradiance
// coefficients and fog light (bake_maps.hpp).
#include "bake_maps.hpp"

#include <aerial/fog_light.hpp>
#include <aerial/weather.hpp>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfDoubleAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStdIO.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <cmath>
#include <string>
#include <vector>

namespace aerial::cli {

const char* const kSkyViewMapping =
    "upper hemisphere, lines packed towards the horizon (Hillaire 2020's sky-view LUT): pixel (x, y) of a "
    "W x H image looks along the world azimuth phi = 2 pi (x + 0.5) / W from north (-Z) towards east (+X) "
    "and the elevation el = pi/2 (y / (H - 1))^2: line y = 0 lies exactly on the horizon (the sky just "
    "above it), the last line at the zenith; direction = (cos el sin phi, sin el, -cos el cos phi). To "
    "sample a direction of elevation el >= 0 and azimuth phi bilinearly: u = phi / (2 pi) (repeat), "
    "v = ((H - 1) sqrt(el / (pi/2)) + 0.5) / H (clamp). Nothing below the horizon is sky: fog and ground "
    "are drawn there (far_fog)";

const char* const kFarFogMapping =
    "whole sphere, equirectangular: pixel (x, y) of a W x H image looks along the world azimuth "
    "phi = 2 pi (x + 0.5) / W from north (-Z) towards east (+X) and the elevation "
    "el = pi/2 - pi (y + 0.5) / H (line 0 near the zenith, the last near the nadir); sample bilinearly with "
    "u = phi / (2 pi) (repeat), v = (pi/2 - el) / pi (clamp)";

Json skyViewManifest(int width, int height) {
    return {{"file_pattern", "per step: sky_view_file"},
            {"width", width},
            {"height", height},
            {"channels", {"R", "G", "B"}},
            {"pixel_type", "float"},
            {"mapping", kSkyViewMapping},
            {"values",
             "scene-linear Rec.709 radiance (1 = exposure.nits_per_radiance_unit cd/m^2) of the clear sky "
             "as the sky pass draws it behind the stars: the sun's and the moon's scattered light (phases "
             "applied), the airglow and a city's glow; no clouds, stars, or discs of the sun and the moon. "
             "Within 2 % of `aerial sky` (sky_rgb) above the horizon at every sun except 0-0.3 deg below "
             "the horizon, where it blurs the cap of the earth's shadow opposite the sun"}};
}

Json farFogManifest(int width, int height) {
    return {{"file_pattern", "per step: far_fog_file"},
            {"width", width},
            {"height", height},
            {"channels", {"R", "G", "B"}},
            {"pixel_type", "float"},
            {"mapping", kFarFogMapping},
            {"values",
             "L_horizon(v): the sky right behind far fog seen along v, under the cloud deck's horizon "
             "cover (scene-linear Rec.709 radiance, before the fog's colour mode); the fog formula (fog) "
             "blends it in with the sight line's length"}};
}

Json fogFormulaManifest() {
    return {
        {"what",
         "the global height fog along a sight line from the eye p (world metres, Y up) to a scene point at "
         "distance s in the unit direction v, as `aerial fog` computes it without volumes and emitters "
         "(those are in the step's volumes and emitters and layout.gltf)"},
        {"optical_depth",
         "tau = b s exp(-c (min(y0, y1) - h0)) (1 - exp(-x)) / x, x = c |y1 - y0| (the factor is 1 at "
         "x = 0), y0 = p.y, y1 = p.y + s v.y; b = density_per_m, c = falloff_per_m, h0 = base_height_m; "
         "tau at most 1e4"},
        {"composite", "L = L_scene T + L_fog(v, s) (1 - T), T = exp(-tau) (grey)"},
        {"colour",
         "L_fog(v, s) = (1 - w) L_lit(v) + w L_horizon(v), w = 1 - exp(-(s / horizon_distance_m)^2); "
         "L_horizon(v) = far fog map at v; L_lit(v) = sum over direct of illuminance_rgb P_M(dot(v, "
         "direction), anisotropy) + max(sky_l0_rgb + sky_l1_rgb[0] v.x + sky_l1_rgb[1] v.y + "
         "sky_l1_rgb[2] v.z, 0) per channel (P_M as table.phase_mie); then by colour_mode: sky -> "
         "L_fog, tinted -> colour_rgb L_fog, custom -> colour_rgb"},
        {"fields",
         "per step in fog: density_per_m, falloff_per_m, base_height_m, colour_mode, colour_rgb, "
         "anisotropy, horizon_distance_m, direct (the sun and the moon: unit direction towards the light "
         "and the illuminance reaching the fog, clouds' visibility applied), sky_l0_rgb and sky_l1_rgb "
         "(the sky's, the ground's and the night sky's light at the fog as a mean and a windowed dipole), "
         "far_fog_file"}};
}

Json irradianceManifest() {
    return {{"what",
             "per step, sky_irradiance_sh9: nine [r, g, b] coefficients c_i of the irradiance of the "
             "whole environment as the fog sees it (the clear sky through the clouds' gaps and the deck's "
             "underside above the horizon, the ground's Lambertian reflection below it; not the sun's or "
             "the moon's direct beam): E(n) = sum c_i Y_i(n) on a surface of unit normal n, in radiance "
             "units x sr (scene-linear Rec.709)"},
            {"basis",
             "real spherical harmonics in Aerial's world axes (x east, y up, z south): Y_0 = 0.282095, "
             "Y_1 = 0.488603 y, Y_2 = 0.488603 z, Y_3 = 0.488603 x, Y_4 = 1.092548 x y, Y_5 = 1.092548 y z, "
             "Y_6 = 0.315392 (3 z^2 - 1), Y_7 = 1.092548 x z, Y_8 = 0.546274 (x^2 - y^2)"},
            {"convolution",
             "already convolved with the clamped cosine (Ramamoorthi and Hanrahan 2001): c_i = A_l L_i, "
             "A_0 = pi, A_1 = 2 pi / 3, A_2 = pi / 4, L_i the radiance's coefficients; divide by A_l (and by "
             "pi for an engine that stores radiance-times-pi, e.g. Unity's ambient probe) as the engine "
             "wants"}};
}

Json bakeWeatherManifest(const Preset& preset) {
    Json states = Json::array();
    for (const WeatherState& s : preset.weather) states.push_back(s.name);
    Json shares = Json::object();
    for (int c = 0; c < kWeatherCategoryCount; ++c)
        shares[weatherCategoryName(WeatherCategory(c))] = kWeatherCategoryShare[c];
    return {{"states", states},
            {"category_share", shares},
            {"regions", weatherRegionsToJson(preset)},
            {"regions_blend",
             "a region (a box: the unit cube, an ellipsoid: the unit sphere, placed by world = position_m + "
             "rotation_xyzw * (half_extents_m * object); +Y up, -Z north) has weight r = smoothstep(clamp(d / "
             "blend_m, 0, 1)) at the camera, d its depth inside: the distance to its surface (box: min_i "
             "(h_i - |p_i|) in object space; ellipsoid: the distance to the closest surface point), r = 0 "
             "outside. Starting from the global weights W_s,c (per state s and category c; the keyed values hold "
             "1 - sum_s W_s,c), the regions are applied in ascending priority, equal priorities in list order: "
             "W_s,c <- (1 - r) W_s,c + r [s = region.state] (\"none\": every W_s,c <- (1 - r) W_s,c). The "
             "library does this in aerial::regionalWeather"},
            {"what",
             "per step, weather.<state>: that state held fully (aerial/weather.hpp): its parameters, the "
             "light reaching the ground, its sky-view and far fog maps, irradiance coefficients and fog, as "
             "the step's own fields are for the keyed values alone. The overrides themselves are in the "
             "preset (weather.states) and `aerial eval --json`"},
            {"blend",
             "a change of duration D from state A to state B, t seconds in: each category c (the parameter's: "
             "clouds.* but the wind -> clouds, clouds.wind_m_per_s -> wind, fog.* and fog volumes -> fog, "
             "atmosphere.* -> haze, exposure/sun/moon/night -> light, emitters -> lightning) takes weight "
             "w_c = smoothstep(clamp(t / (category_share_c D), 0, 1)) of B; a parameter is (1 - w_c) A + w_c B; "
             "the maps and coefficients cross-fade with the clouds' weight (the haze's for a change without "
             "clouds). The library blends parameters exactly so; the cross-faded maps stand in for a sky "
             "solved for the blended atmosphere"}};
}

Json irradianceToJson(const IrradianceSH9& sh) {
    Json out = Json::array();
    for (const glm::dvec3& c : sh.c) out.push_back(toJson(c));
    return out;
}

void writeRgbExr(const std::filesystem::path& path, const RgbImage& image, double timeHours,
                 const char* mapping, Imf::Compression compression) {
    // 32-bit float: a moonless sky is ~1e-8 radiance units (the dark sky's
    // 2e-4 cd/m^2), below half float's normal range (6e-5). Rounded to 12
    // significant bits (0.012 %, half float's precision with float's range)
    // so that the lossless compression has something to compress: 1.7 MB a
    // map with every bit, a tenth of that rounded.
    std::vector<float> pixels(image.rgb.size());
    for (std::size_t i = 0; i < image.rgb.size(); ++i) {
        const float value = image.rgb[i];
        float v = std::isfinite(value) && value > 0.0f ? value : 0.0f;
        std::uint32_t bits = 0;
        std::memcpy(&bits, &v, sizeof bits);
        bits = (bits + 0x400u) & ~0x7FFu;  // round to nearest on the 11 bits dropped
        std::memcpy(&v, &bits, sizeof bits);
        pixels[i] = std::isfinite(v) ? v : 0.0f;
    }
    Imf::StdOSStream encoded;
    try {
        Imf::Header header(image.width, image.height);
        header.compression() = compression;
        for (const char* name : {"R", "G", "B"}) header.channels().insert(name, Imf::Channel(Imf::FLOAT));
        header.insert("aerialTimeHours", Imf::DoubleAttribute(timeHours));
        header.insert("aerialMapping", Imf::StringAttribute(mapping));
        header.insert("aerialUnits", Imf::StringAttribute("scene-linear Rec.709 radiance, 1 = 5000 cd/m^2"));
        Imf::FrameBuffer frame;
        const std::size_t xStride = sizeof(float) * 3, yStride = xStride * std::size_t(image.width);
        const char* names[3] = {"R", "G", "B"};
        for (int c = 0; c < 3; ++c)
            frame.insert(names[c],
                         Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(pixels.data() + c), xStride, yStride));
        Imf::OutputFile file(encoded, header);
        file.setFrameBuffer(frame);
        file.writePixels(image.height);
    } catch (const std::exception& e) {
        dataError("cannot encode " + path.string() + ": " + e.what());
    }
    writeFileAtomically(path, encoded.str());
}

namespace {

const char* colourModeName(FogColourMode mode) {
    switch (mode) {
        case FogColourMode::Tinted: return "tinted";
        case FogColourMode::Custom: return "custom";
        case FogColourMode::Sky:
        default: return "sky";
    }
}

}  // namespace

StepMaps bakeStepMaps(const PresetState& state, const SkyTable& sun, const SkyTable& moon, int skyViewWidth,
                      int skyViewHeight, int farFogWidth, int farFogHeight) {
    StepMaps maps;
    const bool clouds = prepareClouds(state).active();
    const OvercastLight overcast = clouds ? overcastLight(state, sun, moon) : OvercastLight{};
    const FogSceneDesc desc = fogSceneDesc(state, sun, moon, overcast);
    const FogScene fog(desc);
    maps.skyView = skyViewMap(state, sun, moon, skyViewWidth, skyViewHeight);
    maps.farFog = farFogMap(fog, farFogWidth, farFogHeight);
    maps.irradiance = environmentIrradianceSH9(state, sun, moon, overcast);

    // The sky's band as a mean and a dipole, read off the library's own
    // windowed form: it swings at most half the mean, so it is never clamped
    // along the axes and (L(+e) -+ L(-e)) / 2 recovers both exactly.
    const double k1 = miePhaseFirstMoment(desc.mieAnisotropy);
    glm::dvec3 l1[3];
    glm::dvec3 l0(0.0);
    for (int k = 0; k < 3; ++k) {
        glm::dvec3 axis(0.0);
        axis[k] = 1.0;
        const glm::dvec3 plus = fogSkyInScatter(desc.skyLight, k1, axis);
        const glm::dvec3 minus = fogSkyInScatter(desc.skyLight, k1, -axis);
        if (k == 0) l0 = 0.5 * (plus + minus);  // the same on every axis
        l1[k] = 0.5 * (plus - minus);
    }
    Json direct = Json::array();
    const char* names[2] = {"sun", "moon"};
    for (int k = 0; k < 2; ++k)
        direct.push_back({{"light", names[k]},
                          {"direction", toJson(desc.lights[k].direction)},
                          {"illuminance_rgb", toJson(desc.directVisibility * desc.lights[k].reaching)}});
    maps.fog = {{"density_per_m", desc.heightFog.density},
                {"falloff_per_m", desc.heightFog.falloff},
                {"base_height_m", desc.heightFog.baseHeight},
                {"colour_mode", colourModeName(desc.heightFogColourMode)},
                {"colour_rgb", toJson(desc.heightFogColour)},
                {"anisotropy", std::clamp(desc.mieAnisotropy, -0.999, 0.999)},
                {"horizon_distance_m", desc.horizonDistance},
                {"direct", direct},
                {"sky_l0_rgb", toJson(l0)},
                {"sky_l1_rgb", {toJson(l1[0]), toJson(l1[1]), toJson(l1[2])}}};
    return maps;
}

}  // namespace aerial::cli
