// param_table.cpp — the one declaration of every editable parameter
// (../shared/STYLE.md, point 3). Defaults mirror the structs' default member
// initialisers (test_param_table checks they agree); ranges are the valid
// ranges the loader enforces.
#include <aerial/param_table.hpp>

#include <array>
#include <cmath>

namespace aerial {
namespace {

using sv = std::string_view;

Environment& env(void* o) { return *static_cast<Environment*>(o); }
FogVolume& vol(void* o) { return *static_cast<FogVolume*>(o); }
Emitter& emi(void* o) { return *static_cast<Emitter*>(o); }
CloudVolume& cvol(void* o) { return *static_cast<CloudVolume*>(o); }

constexpr std::array<sv, 3> kColourModeNames = {"sky", "tinted", "custom"};
constexpr std::array<sv, 2> kFogRenderModeNames = {"analytic", "volumetric"};
constexpr std::array<sv, 2> kFogPhaseModeNames = {"sky", "custom"};
constexpr std::array<sv, 2> kShapeNames = {"box", "ellipsoid"};
constexpr std::array<sv, 3> kVolumeShapeNames = {"box", "ellipsoid", "mesh"};
constexpr std::array<sv, 2> kBlendNames = {"add", "subtract"};
constexpr std::array<sv, 2> kEmitterKindNames = {"point", "lightning"};
constexpr std::array<sv, 2> kExposureModeNames = {"manual", "automatic"};
constexpr std::array<sv, 2> kLampNames = {"sodium", "led"};
constexpr std::array<sv, 2> kTimeModeNames = {"solar", "clock"};

struct Range {
    double min, max, uiMin, uiMax;
};

ParamDesc scalar(ParamScope scope, sv path, sv label, sv unit, Range r, double def, bool log, bool animatable,
                 double* (*access)(void*), sv doc) {
    ParamDesc p;
    p.scope = scope;
    p.type = ParamType::Scalar;
    p.path = path;
    p.label = label;
    p.unit = unit;
    p.doc = doc;
    p.minValue = r.min;
    p.maxValue = r.max;
    p.uiMin = r.uiMin;
    p.uiMax = r.uiMax;
    p.defaultValue[0] = def;
    p.logScale = log;
    p.animatable = animatable;
    p.scalar = access;
    return p;
}

ParamDesc triple(ParamScope scope, ParamType type, sv path, sv label, sv unit, Range r, glm::dvec3 def,
                 bool log, bool animatable, glm::dvec3* (*access)(void*), sv doc) {
    ParamDesc p;
    p.scope = scope;
    p.type = type;
    p.path = path;
    p.label = label;
    p.unit = unit;
    p.doc = doc;
    p.minValue = r.min;
    p.maxValue = r.max;
    p.uiMin = r.uiMin;
    p.uiMax = r.uiMax;
    p.defaultValue[0] = def.x;
    p.defaultValue[1] = def.y;
    p.defaultValue[2] = def.z;
    p.logScale = log;
    p.animatable = animatable;
    p.vec3 = access;
    return p;
}

/// A horizontal 2-vector [x, z] (x = world X, y = world Z), such as a wind
/// velocity; `r` bounds each component.
ParamDesc vector2(ParamScope scope, sv path, sv label, sv unit, Range r, glm::dvec2 def, bool animatable,
                  glm::dvec2* (*access)(void*), sv doc) {
    ParamDesc p;
    p.scope = scope;
    p.type = ParamType::Vec2;
    p.path = path;
    p.label = label;
    p.unit = unit;
    p.doc = doc;
    p.minValue = r.min;
    p.maxValue = r.max;
    p.uiMin = r.uiMin;
    p.uiMax = r.uiMax;
    p.defaultValue[0] = def.x;
    p.defaultValue[1] = def.y;
    p.animatable = animatable;
    p.vec2 = access;
    return p;
}

ParamDesc enumeration(ParamScope scope, sv path, sv label, std::span<const sv> names, int def,
                      std::int64_t (*get)(const void*), void (*set)(void*, std::int64_t), sv doc) {
    ParamDesc p;
    p.scope = scope;
    p.type = ParamType::Enum;
    p.path = path;
    p.label = label;
    p.doc = doc;
    p.minValue = p.uiMin = 0.0;
    p.maxValue = p.uiMax = double(names.size() - 1);
    p.defaultValue[0] = def;
    p.enumNames = names;
    p.getInt = get;
    p.setInt = set;
    return p;
}

/// A seed: an integer 0..4294967295, default 1, never animated.
ParamDesc seedParam(ParamScope scope, sv path, sv doc, std::int64_t (*get)(const void*),
                    void (*set)(void*, std::int64_t)) {
    ParamDesc p;
    p.scope = scope;
    p.type = ParamType::Int;
    p.path = path;
    p.label = "Seed";
    p.doc = doc;
    p.minValue = p.uiMin = 0.0;
    p.maxValue = p.uiMax = 4294967295.0;
    p.defaultValue[0] = 1.0;
    p.getInt = get;
    p.setInt = set;
    return p;
}

ParamDesc text(ParamScope scope, sv path, sv label, bool required, std::string* (*access)(void*), sv doc) {
    ParamDesc p;
    p.scope = scope;
    p.type = ParamType::String;
    p.path = path;
    p.label = label;
    p.doc = doc;
    p.required = required;
    p.string = access;
    return p;
}

/// A field most objects leave at its default: not written then.
ParamDesc omittedWhenDefault(ParamDesc p) {
    p.omitWhenDefault = true;
    return p;
}

/// The id and name every placed object (volume, emitter) carries.
template <class Object>
std::vector<ParamDesc> identityParams(ParamScope scope, sv idDoc) {
    return {text(
                scope, "id", "Id", true, [](void* o) { return &static_cast<Object*>(o)->id; }, idDoc),
            text(
                scope, "name", "Name", false, [](void* o) { return &static_cast<Object*>(o)->name; },
                "Name shown to the artist. Default empty.")};
}

/// The orientation every placed shape (fog volume, cloud volume) carries.
ParamDesc rotationParam(ParamScope scope, glm::dquat* (*access)(void*)) {
    ParamDesc p;
    p.scope = scope;
    p.type = ParamType::Quaternion;
    p.path = "rotation_xyzw";
    p.label = "Rotation";
    p.doc =
        "Orientation, world from object, unit quaternion [x, y, z, w]. "
        "Default identity [0, 0, 0, 1].";
    p.minValue = p.uiMin = -1.0;
    p.maxValue = p.uiMax = 1.0;
    p.defaultValue[3] = 1.0;
    p.quat = access;
    return p;
}

constexpr ParamScope G = ParamScope::Global;
constexpr ParamScope V = ParamScope::Volume;
constexpr ParamScope E = ParamScope::Emitter;
constexpr ParamScope C = ParamScope::CloudVolume;
constexpr double kTopOfAtmosphere = 60000.0;  // Rt - Rg with the default radii [m]

const std::vector<ParamDesc>& globalTable() {
    static const std::vector<ParamDesc> table = {
        // Location (sun.hpp).
        scalar(
            G, "location.latitude_deg", "Latitude", "deg", {-90, 90, -90, 90}, 45, false, false,
            [](void* o) { return &env(o).location.latitudeDeg; },
            "Geographic latitude [deg], -90..90, north positive. Default 45."),
        scalar(
            G, "location.longitude_deg", "Longitude", "deg", {-180, 180, -180, 180}, 0, false, false,
            [](void* o) { return &env(o).location.longitudeDeg; },
            "Geographic longitude [deg], -180..180, east positive. Used with a date only. Default 0."),
        scalar(
            G, "location.utc_offset_h", "UTC offset", "h", {-12, 14, -12, 14}, 0, false, false,
            [](void* o) { return &env(o).location.utcOffsetHours; },
            "Local clock time minus UT [h], -12..14 (2 for CEST). Used with a date in clock mode only. "
            "Default 0."),
        text(
            G, "location.date", "Date", false, [](void* o) { return &env(o).location.date; },
            "Calendar date \"YYYY-MM-DD\", 1800-01-01..2200-12-31: the sun and moon come from "
            "ephemerides for that day (NOAA, Meeus 47) and day_of_year and moon_phase_offset_days are "
            "unused. Empty (the default, every version-1 preset): the undated model of day_of_year."),
        enumeration(
            G, "location.time_mode", "Time mode", kTimeModeNames, 0,
            [](const void* o) { return std::int64_t(static_cast<const Environment*>(o)->location.timeMode); },
            [](void* o, std::int64_t v) { env(o).location.timeMode = TimeMode(v); },
            "How a dated preset reads its time of day. solar: local apparent solar time at the longitude "
            "(noon = the sun on the meridian); clock: local clock time at the UTC offset (the equation of "
            "time applies). Without a date, time is always solar. Default solar."),
        scalar(
            G, "location.day_of_year", "Day of year", "day", {1, 365, 1, 365}, 172, false, false,
            [](void* o) { return &env(o).location.dayOfYear; },
            "Day of the year [1..365] of the undated model (no date); sets the solar declination. "
            "Unused when a date is set. Default 172 (June solstice, as 2026-06-21)."),
        scalar(
            G, "location.north_offset_deg", "North offset", "deg", {-360, 360, -180, 180}, 0, false, false,
            [](void* o) { return &env(o).location.northOffsetDeg; },
            "Rotation of the whole sky about +Y [deg], added to every azimuth. Default 0."),
        scalar(
            G, "location.moon_phase_offset_days", "Moon phase offset", "day", {0, 29.530589, 0, 29.530589}, 0,
            false, false, [](void* o) { return &env(o).location.moonPhaseOffsetDays; },
            "Shifts the moon's age [days], 0..29.53, in the undated model: chooses the night of the "
            "month (~14.8 after a new moon is full). Unused when a date is set. Default 0."),
        // Atmosphere (atmosphere.hpp).
        scalar(
            G, "atmosphere.viewer_height_m", "Viewer height", "m", {0, kTopOfAtmosphere, 0, 20000}, 0, false,
            false, [](void* o) { return &env(o).atmosphere.viewerHeight; },
            "Viewer height above the ground [m], 0..60000. Default 0."),
        triple(
            G, ParamType::Vec3, "atmosphere.rayleigh.scattering_per_m", "Rayleigh scattering", "1/m",
            {0, 1e-3, 1e-7, 1e-4}, {5.802e-6, 13.558e-6, 33.1e-6}, true, true,
            [](void* o) { return &env(o).atmosphere.rayleighScattering; },
            "Rayleigh scattering at sea level [1/m] per RGB channel, 0..1e-3 "
            "(extinction equals scattering). Default (5.802, 13.558, 33.1)e-6."),
        scalar(
            G, "atmosphere.rayleigh.scale_height_m", "Rayleigh scale height", "m", {10, 100000, 1000, 20000},
            8000, false, true, [](void* o) { return &env(o).atmosphere.rayleighScaleHeight; },
            "Rayleigh density scale height H_R [m], 10..100000. Default 8000."),
        triple(
            G, ParamType::Vec3, "atmosphere.mie.scattering_per_m", "Mie scattering", "1/m",
            {0, 1e-3, 1e-7, 1e-3}, glm::dvec3(3.996e-6), true, true,
            [](void* o) { return &env(o).atmosphere.mieScattering; },
            "Mie (aerosol) scattering at sea level [1/m] per RGB channel, 0..1e-3; haze and "
            "dust raise it. Default 3.996e-6."),
        triple(
            G, ParamType::Vec3, "atmosphere.mie.extinction_per_m", "Mie extinction", "1/m",
            {0, 2e-3, 1e-7, 2e-3}, glm::dvec3(3.996e-6 / 0.9), true, true,
            [](void* o) { return &env(o).atmosphere.mieExtinction; },
            "Mie extinction at sea level [1/m] per RGB channel, 0..2e-3, >= scattering. "
            "Default scattering / 0.9 = 4.44e-6."),
        scalar(
            G, "atmosphere.mie.scale_height_m", "Mie scale height", "m", {10, 100000, 100, 10000}, 1200,
            false, true, [](void* o) { return &env(o).atmosphere.mieScaleHeight; },
            "Mie density scale height H_M [m], 10..100000. Default 1200."),
        scalar(
            G, "atmosphere.mie.anisotropy", "Mie anisotropy", "", {-0.999, 0.999, 0.0, 0.99}, 0.8, false,
            true, [](void* o) { return &env(o).atmosphere.mieAnisotropy; },
            "Cornette-Shanks asymmetry g, -0.999..0.999; larger is a tighter sun halo. "
            "Default 0.8."),
        triple(
            G, ParamType::Vec3, "atmosphere.ozone.absorption_per_m", "Ozone absorption", "1/m",
            {0, 1e-4, 1e-8, 1e-5}, {0.650e-6, 1.881e-6, 0.085e-6}, true, true,
            [](void* o) { return &env(o).atmosphere.ozoneAbsorption; },
            "Ozone absorption at the peak of its tent profile [1/m] per RGB channel, 0..1e-4; "
            "0 turns it off. Default (0.650, 1.881, 0.085)e-6 (Bruneton 2017)."),
        scalar(
            G, "atmosphere.ozone.peak_height_m", "Ozone peak height", "m",
            {0, kTopOfAtmosphere, 0, kTopOfAtmosphere}, 25000, false, false,
            [](void* o) { return &env(o).atmosphere.ozoneCenterHeight; },
            "Height of the ozone peak [m], 0..60000. Default 25000."),
        scalar(
            G, "atmosphere.ozone.width_m", "Ozone layer width", "m",
            {1, 2 * kTopOfAtmosphere, 1000, kTopOfAtmosphere}, 30000, false, false,
            [](void* o) { return &env(o).atmosphere.ozoneWidth; },
            "Full width of the ozone tent [m], 1..120000 (zero density at peak +- width/2). "
            "Default 30000."),
        triple(
            G, ParamType::Colour, "atmosphere.ground_albedo_rgb", "Ground albedo", "", {0, 1, 0, 1},
            glm::dvec3(0.3), false, true, [](void* o) { return &env(o).atmosphere.groundAlbedo; },
            "Lambertian albedo of the ground per RGB channel, 0..1: the sunlight the ground "
            "reflects back into the sky (multiple scattering). Default 0.3 grey."),
        // Sun and moon (preset.hpp, LightParams).
        triple(
            G, ParamType::Colour, "sun.colour_rgb", "Sun colour", "", {0, 100, 0, 2}, glm::dvec3(1.0), false,
            true, [](void* o) { return &env(o).sun.colour; },
            "Sun colour above the atmosphere, scene-linear Rec.709, 0..100 per channel; "
            "illuminance = colour x intensity. Default white."),
        scalar(
            G, "sun.intensity", "Sun intensity", "", {0, 1e5, 0.01, 1000}, kDefaultSunIntensity, true, true,
            [](void* o) { return &env(o).sun.intensity; },
            "Sun intensity (multiplier of the colour, renderer radiance units), 0..1e5. "
            "Default 20, as in common Nishita implementations."),
        triple(
            G, ParamType::Colour, "moon.colour_rgb", "Moon colour", "", {0, 100, 0, 2}, {0.85, 0.92, 1.0},
            false, true, [](void* o) { return &env(o).moon.colour; },
            "Moon colour above the atmosphere, scene-linear Rec.709, 0..100 per channel. "
            "Default (0.85, 0.92, 1.0): an artistic cool tint."),
        scalar(
            G, "moon.intensity", "Moon intensity", "", {0, 1e5, 1e-6, 10}, kDefaultMoonIntensity, true, true,
            [](void* o) { return &env(o).moon.intensity; },
            "Moon illuminance above the atmosphere at full phase (scaled by the phase law) "
            "[5000 lx], 0..1e5. Default 0.00005 = 0.25 lx, the physical moon (2.5e-6 x the "
            "default sun); the exposure makes a moonlit night readable. Version-1 presets "
            "held 1000x this and are converted on load."),
        // Global height fog (height_fog.hpp).
        scalar(
            G, "fog.density_per_m", "Fog density", "1/m", {0, 10, 1e-6, 0.1}, 0.0, true, true,
            [](void* o) { return &env(o).fog.density; },
            "Global fog density b at the base height [1/m], 0..10; 0 is no fog. Default 0."),
        scalar(
            G, "fog.falloff_per_m", "Fog height falloff", "1/m", {0, 10, 1e-5, 1}, 0.0, true, true,
            [](void* o) { return &env(o).fog.falloff; },
            "Height falloff c [1/m], 0..10; 0 is a uniform fog. Default 0."),
        scalar(
            G, "fog.base_height_m", "Fog base height", "m", {-1e5, 1e5, -500, 2000}, 0.0, false, true,
            [](void* o) { return &env(o).fog.baseHeight; },
            "Base height h0 [m] where the density equals b, -1e5..1e5. Default 0."),
        enumeration(
            G, "fog.colour_mode", "Fog colour mode", kColourModeNames, 0,
            [](const void* o) { return std::int64_t(static_cast<const Environment*>(o)->fogColourMode); },
            [](void* o, std::int64_t v) { env(o).fogColourMode = FogColourMode(v); },
            "Where the fog colour comes from: sky (horizon colour with phase), tinted (sky x "
            "colour), custom (colour as radiance). Default sky."),
        triple(
            G, ParamType::Colour, "fog.colour_rgb", "Fog colour", "", {0, 1e5, 0, 2}, glm::dvec3(1.0), false,
            true, [](void* o) { return &env(o).fogColour; },
            "Fog tint (tinted) or in-scattered radiance (custom), scene-linear Rec.709, "
            "0..1e5 per channel. Default white."),
        enumeration(
            G, "fog.render_mode", "Fog render mode", kFogRenderModeNames, 0,
            [](const void* o) { return std::int64_t(static_cast<const Environment*>(o)->fogRenderMode); },
            [](void* o, std::int64_t v) { env(o).fogRenderMode = FogRenderMode(v); },
            "How the fog is meant to be drawn: analytic (exact closed forms, no shadows in the "
            "fog) or volumetric (a froxel grid: sun, moon and cloud shadows cut light shafts). "
            "Games' fog queries are analytic either way. Default analytic."),
        enumeration(
            G, "fog.volumetric.phase", "Volumetric phase", kFogPhaseModeNames, 0,
            [](const void* o) {
                return std::int64_t(static_cast<const Environment*>(o)->volumetricFog.phase);
            },
            [](void* o, std::int64_t v) { env(o).volumetricFog.phase = FogPhaseMode(v); },
            "Volumetric mode only: the phase of the sunlight (moonlight) scattered by the fog: sky "
            "(the sky's fog colour, as the analytic fog) or custom (the anisotropy below in place of "
            "the atmosphere's Mie anisotropy). Default sky."),
        scalar(
            G, "fog.volumetric.anisotropy", "Volumetric anisotropy", "", {-0.95, 0.95, -0.95, 0.95}, 0.6,
            false, true, [](void* o) { return &env(o).volumetricFog.anisotropy; },
            "Volumetric mode, custom phase: the fog's Cornette-Shanks g, -0.95..0.95; larger is a "
            "brighter glow towards the sun, 0 scatters evenly. Default 0.6."),
        scalar(
            G, "fog.volumetric.noise_amount", "Volumetric detail noise", "", {0, 1, 0, 1}, 0.0, false, true,
            [](void* o) { return &env(o).volumetricFog.noiseAmount; },
            "Volumetric mode only: the global fog's density varies by this share around its value "
            "(a smooth 3D noise drifting with the clouds' wind), 0..1; 0 is the exact height fog. "
            "Default 0."),
        scalar(
            G, "fog.volumetric.noise_scale_m", "Volumetric noise scale", "m", {1, 1000, 1, 200}, 25.0, true,
            true, [](void* o) { return &env(o).volumetricFog.noiseScaleM; },
            "Volumetric mode: the size of the detail noise's features [m], 1..1000. Default 25."),
        // Exposure (exposure.hpp).
        enumeration(
            G, "exposure.mode", "Exposure mode", kExposureModeNames, 1,
            [](const void* o) { return std::int64_t(static_cast<const Environment*>(o)->exposure.mode); },
            [](void* o, std::int64_t v) { env(o).exposure.mode = ExposureMode(v); },
            "manual: the EV100 below; automatic: metered from each frame (the 10-90 % band of its "
            "luminance), clamped to min..max EV100 and adapting over time. Default automatic."),
        scalar(
            G, "exposure.ev100", "EV100 (manual)", "EV", {-10, 25, -6, 20}, 15.0, false, true,
            [](void* o) { return &env(o).exposure.ev100; },
            "Manual exposure value at ISO 100 [EV], -10..25: 15 a sunny noon, 11 an overcast day, "
            "5 a lit street at night, -2 moonlight. Default 15."),
        scalar(
            G, "exposure.compensation_ev", "Exposure compensation", "EV", {-10, 10, -5, 5}, 0.0, false, true,
            [](void* o) { return &env(o).exposure.compensationEv; },
            "Added to the exposure [EV], -10..10, in both modes; positive is brighter. Key it to set "
            "how dusk and night read. Default 0."),
        scalar(
            G, "exposure.min_ev100", "Minimum EV100", "EV", {-16, 25, -16, 20}, -12.0, false, true,
            [](void* o) { return &env(o).exposure.minEv100; },
            "Automatic: the darkest scene exposed to middle grey [EV100], -16..25; darker scenes read "
            "dark (night stays night). Default -12: the light is physical, a full moon's landscape "
            "meters about -3 and a moonless one -11 to -13."),
        scalar(
            G, "exposure.max_ev100", "Maximum EV100", "EV", {-10, 25, 0, 25}, 17.0, false, true,
            [](void* o) { return &env(o).exposure.maxEv100; },
            "Automatic: the brightest scene exposed to middle grey [EV100], -10..25. Default 17."),
        scalar(
            G, "exposure.adapt_up_per_s", "Adaptation to brighter", "1/s", {0, 100, 0.1, 20}, 3.0, true,
            false, [](void* o) { return &env(o).exposure.adaptUpPerSecond; },
            "Automatic: how fast the exposure follows a brighter scene [1/s], 0..100 (the fraction "
            "1 - exp(-speed dt) of the gap closes in dt seconds; 0 jumps at once). Default 3."),
        scalar(
            G, "exposure.adapt_down_per_s", "Adaptation to darker", "1/s", {0, 100, 0.1, 20}, 1.0, true,
            false, [](void* o) { return &env(o).exposure.adaptDownPerSecond; },
            "Automatic: how fast the exposure follows a darker scene [1/s], 0..100 (0 jumps at once). "
            "Default 1."),
        // Clouds (clouds.hpp).
        scalar(
            G, "clouds.coverage", "Cloud coverage", "", {0, 1, 0, 1}, 0.0, false, true,
            [](void* o) { return &env(o).clouds.coverage; },
            "Fraction of the sky the cloud layer covers, 0..1 (0 clear, 1 overcast). Default 0."),
        scalar(
            G, "clouds.bottom_m", "Cloud base", "m", {0, 20000, 0, 8000}, 1500.0, false, true,
            [](void* o) { return &env(o).clouds.bottomM; },
            "Height of the layer's base above the ground [m], 0..20000. Default 1500."),
        scalar(
            G, "clouds.thickness_m", "Cloud layer thickness", "m", {10, 20000, 100, 8000}, 2000.0, false,
            true, [](void* o) { return &env(o).clouds.thicknessM; },
            "Thickness of the layer [m], 10..20000 (must be > 0). Default 2000."),
        scalar(
            G, "clouds.density_per_m", "Cloud density", "1/m", {0, 1, 1e-4, 0.5}, 0.02, true, true,
            [](void* o) { return &env(o).clouds.densityPerM; },
            "Extinction inside a full cloud [1/m], 0..1; visibility inside ~3.9 / density. Default 0.02."),
        vector2(
            G, "clouds.wind_m_per_s", "Wind", "m/s", {-1000, 1000, -40, 40}, glm::dvec2(10.0, 3.0), true,
            [](void* o) { return &env(o).clouds.windMPerS; },
            "Wind drifting the clouds [m/s], horizontal [x, z] (world X, Z), -1000..1000 per component; "
            "the layer at time t is the layer at 00:00 moved by wind x t. Default [10, 3]."),
        seedParam(
            G, "clouds.seed",
            "Seed of the cloud noise, 0..4294967295; a game regenerates the same noise "
            "from it. Default 1.",
            [](const void* o) { return static_cast<const Environment*>(o)->clouds.seed; },
            [](void* o, std::int64_t v) { env(o).clouds.seed = v; }),
        scalar(
            G, "clouds.type", "Cloud type", "", {0, 1, 0, 1}, 0.6, false, true,
            [](void* o) { return &env(o).clouds.type; },
            "Shape of the height profile, 0 flat stratus .. 0.5 stratocumulus .. 1 towering cumulus. "
            "Default 0.6."),
        scalar(
            G, "clouds.shape_scale_m", "Cloud shape scale", "m", {500, 200000, 2000, 60000}, 12000.0, true,
            true, [](void* o) { return &env(o).clouds.shapeScaleM; },
            "Size of one tile of the shape noise [m], 500..200000; cloud cells are about a quarter of "
            "it. Default 12000."),
        scalar(
            G, "clouds.detail_scale_m", "Cloud detail scale", "m", {50, 20000, 100, 5000}, 1200.0, true, true,
            [](void* o) { return &env(o).clouds.detailScaleM; },
            "Size of one tile of the erosion noise [m], 50..20000. Default 1200."),
        scalar(
            G, "clouds.erosion", "Cloud erosion", "", {0, 0.9, 0, 0.9}, 0.35, false, true,
            [](void* o) { return &env(o).clouds.erosion; },
            "How much the detail noise eats the cloud edges, 0..0.9 (0 smooth blobs). Default 0.35."),
        scalar(
            G, "clouds.anisotropy", "Cloud anisotropy", "", {0, 0.95, 0, 0.95}, 0.6, false, true,
            [](void* o) { return &env(o).clouds.anisotropy; },
            "Forward-scattering asymmetry g, 0..0.95: the bright silver lining of a cloud in front of "
            "the sun. Default 0.6."),
        triple(
            G, ParamType::Colour, "clouds.albedo_rgb", "Cloud albedo", "", {0, 1, 0, 1}, glm::dvec3(0.98),
            false, true, [](void* o) { return &env(o).clouds.albedo; },
            "Single-scattering albedo per RGB channel, 0..1 (scattering = albedo x extinction); "
            "below 1 tints and darkens the clouds. Default 0.98."),
        // A city's glow (night_sky.hpp, "Light pollution").
        scalar(
            G, "night.light_pollution_cd_m2", "Light pollution", "cd/m^2", {0, 1, 1e-5, 0.05}, 0.0, true, true,
            [](void* o) { return &env(o).lightPollution.zenithLuminance; },
            "A city's glow: the luminance it adds at the zenith [cd/m^2], 0..1 (the natural night sky "
            "is ~2e-4; a suburb 1e-3..2e-3, a city 7e-3 and more), brightest over the city on the "
            "horizon. Default 0 (off)."),
        scalar(
            G, "night.light_pollution_azimuth_deg", "City azimuth", "deg", {0, 360, 0, 360}, 180.0, false,
            true, [](void* o) { return &env(o).lightPollution.azimuthDeg; },
            "Where the city lies [deg from north towards east], 0..360: the glow's dome. Default 180."),
        enumeration(
            G, "night.light_pollution_lamps", "City lamps", kLampNames, 0,
            [](const void* o) { return std::int64_t(static_cast<const Environment*>(o)->lightPollution.lamps); },
            [](void* o, std::int64_t v) { env(o).lightPollution.lamps = LightPollutionLamps(v); },
            "The colour of the glow: sodium (orange, ~2100 K) or led (white, ~4000 K). Default sodium."),
    };
    return table;
}

const std::vector<ParamDesc>& volumeTable() {
    static const std::vector<ParamDesc> table = [] {
        std::vector<ParamDesc> t =
            identityParams<FogVolume>(V,
                                      "Stable identifier (1..64 of A-Z a-z 0-9 _ - .), unique among volumes; "
                                      "timeline tracks refer to it. Required.");
        t.insert(
            t.end(),
            {
                enumeration(
                    V, "shape", "Shape", kVolumeShapeNames, 0,
                    [](const void* o) { return std::int64_t(static_cast<const FogVolume*>(o)->shape); },
                    [](void* o, std::int64_t v) { vol(o).shape = FogVolumeShape(v); },
                    "box (unit cube [-1,1]^3), ellipsoid (unit sphere) or mesh (the glTF mesh of \"mesh\") "
                    "in object space, scaled by the half extents. Default box."),
                omittedWhenDefault(text(
                    V, "mesh", "Mesh", false, [](void* o) { return &vol(o).mesh; },
                    "Shape mesh: the glTF file (.gltf or .glb) of the closed, outward-facing triangle mesh, "
                    "relative to the preset's folder. Default none.")),
                omittedWhenDefault(enumeration(
                    V, "blend", "Blend", kBlendNames, 0,
                    [](const void* o) { return std::int64_t(static_cast<const FogVolume*>(o)->blend); },
                    [](void* o, std::int64_t v) { vol(o).blend = FogVolumeBlend(v); },
                    "add (fog inside) or subtract (no fog inside: removes the global fog and every add "
                    "volume "
                    "there, for fog-free interiors; overlaps count once). Default add.")),
                triple(
                    V, ParamType::Vec3, "position_m", "Position", "m", {-1e7, 1e7, -1000, 1000},
                    glm::dvec3(0.0), false, true, [](void* o) { return &vol(o).position; },
                    "Centre [m], world space (Y up, north -Z), -1e7..1e7. Default 0."),
            });
        t.push_back(rotationParam(V, [](void* o) { return &vol(o).rotation; }));
        t.push_back(triple(
            V, ParamType::Vec3, "half_extents_m", "Half extents", "m", {1e-3, 1e7, 0.1, 1000},
            glm::dvec3(10.0), false, true, [](void* o) { return &vol(o).halfExtents; },
            "Half extents along the object axes [m], 0.001..1e7. Default 10."));
        t.push_back(scalar(
            V, "density_per_m", "Density", "1/m", {0, 10, 1e-5, 1}, 0.02, true, true,
            [](void* o) { return &vol(o).density; },
            "Density b_v at the offset plane [1/m], 0..10. Default 0.02."));
        t.push_back(scalar(
            V, "falloff_per_m", "Falloff", "1/m", {0, 10, 1e-4, 1}, 0.0, true, true,
            [](void* o) { return &vol(o).falloff; },
            "Density falloff c_v along the gradient [1/m], 0..10; 0 is uniform. "
            "Default 0."));
        ParamDesc gradient = triple(
            V, ParamType::Vec3, "gradient_direction", "Gradient direction", "", {-1, 1, -1, 1},
            {0.0, 1.0, 0.0}, false, false, [](void* o) { return &vol(o).gradientDirection; },
            "Direction g the density falls off along, world space, unit "
            "length. Default +Y [0, 1, 0].");
        gradient.unitLength = true;
        t.push_back(gradient);
        t.push_back(scalar(
            V, "gradient_offset_m", "Gradient offset", "m", {-1e7, 1e7, -100, 100}, 0.0, false, true,
            [](void* o) { return &vol(o).gradientOffset; },
            "Offset of the b_v plane from the centre along g [m]. Default 0."));
        ParamDesc softness = scalar(
            V, "edge_softness", "Edge softness", "", {0, 1, 0, 1}, 0.0, false, true,
            [](void* o) { return &vol(o).edgeSoftness; },
            "Outer fraction of a box or ellipsoid over which its density falls to 0 (no hard line "
            "at the top of a haze bank), 0..1 (0 a hard edge). Unused by mesh and subtract volumes. "
            "Default 0.");
        softness.omitWhenDefault = true;  // presets without soft volumes stay as they were
        t.push_back(softness);
        t.push_back(enumeration(
            V, "colour_mode", "Colour mode", kColourModeNames, 0,
            [](const void* o) { return std::int64_t(static_cast<const FogVolume*>(o)->colourMode); },
            [](void* o, std::int64_t v) { vol(o).colourMode = FogColourMode(v); },
            "sky (the sky's fog colour), tinted (sky x colour) or custom (colour as radiance). "
            "Default sky."));
        t.push_back(triple(
            V, ParamType::Colour, "colour_rgb", "Colour", "", {0, 1e5, 0, 2}, glm::dvec3(1.0), false, true,
            [](void* o) { return &vol(o).colour; },
            "Tint or radiance (see colour mode), scene-linear Rec.709, 0..1e5 per "
            "channel. Default white."));
        return t;
    }();
    return table;
}

const std::vector<ParamDesc>& emitterTable() {
    static const std::vector<ParamDesc> table = [] {
        std::vector<ParamDesc> t =
            identityParams<Emitter>(E,
                                    "Stable identifier (1..64 of A-Z a-z 0-9 _ - .), unique among emitters; "
                                    "timeline tracks refer to it. Required.");
        t.insert(t.end(),
                 {
                     enumeration(
                         E, "kind", "Kind", kEmitterKindNames, 0,
                         [](const void* o) { return std::int64_t(static_cast<const Emitter*>(o)->kind); },
                         [](void* o, std::int64_t v) { emi(o).kind = EmitterKind(v); },
                         "point (steady) or lightning (seeded flashes). Default point."),
                     triple(
                         E, ParamType::Vec3, "position_m", "Position", "m", {-1e7, 1e7, -1000, 1000},
                         glm::dvec3(0.0), false, true, [](void* o) { return &emi(o).position; },
                         "Position [m], world space. Default 0."),
                     scalar(
                         E, "intensity_cd", "Intensity", "cd", {0, 1e12, 0.01, 1e6}, 100.0, true, true,
                         [](void* o) { return &emi(o).intensityCd; },
                         "Luminous intensity I [cd], 0..1e12: a 1 000 lm campfire ~80, a sodium street "
                         "lamp 1 000-3 000, lightning 1e9-1e11. The fog next to it scatters "
                         "sigma_s I / (4 pi r^2) per metre (sigma_s the fog's own scattering there). "
                         "Default 100."),
                     scalar(
                         E, "attenuation_per_m2", "Attenuation", "1/m^2", {0, 1e4, 1e-5, 100}, 1.0, true,
                         true, [](void* o) { return &emi(o).attenuation; },
                         "Attenuation a [1/m^2], 0..1e4: the glowing core's radius is 1/sqrt(a), the "
                         "light E = I / (1/a + r^2). Default 1 (a 1 m core)."),
                     scalar(
                         E, "temperature_k", "Temperature", "K", {0, 25000, 1000, 10000}, 0.0, false, true,
                         [](void* o) { return &emi(o).temperatureK; },
                         "Colour temperature [K] of a blackbody, 0 or 1667..25000 (campfire ~1900, "
                         "sodium lamp ~2100, LED 3000-5000); 0 takes colour_rgb. Default 0."),
                     triple(
                         E, ParamType::Colour, "colour_rgb", "Colour", "", {0, 1e5, 0, 2}, glm::dvec3(1.0),
                         false, true, [](void* o) { return &emi(o).colour; },
                         "Colour, scene-linear Rec.709, 0..1e5 per channel (the hue: its luminance is "
                         "divided out; used when temperature_k is 0). Default white."),
                 });
        t.push_back(seedParam(
            E, "seed", "Seed of the lightning flash pattern, 0..4294967295. Default 1.",
            [](const void* o) { return std::int64_t(static_cast<const Emitter*>(o)->seed); },
            [](void* o, std::int64_t v) { emi(o).seed = std::uint32_t(v); }));
        t.push_back(scalar(
            E, "flashes_per_minute", "Flashes per minute", "1/min", {0, 6000, 0, 120}, 6.0, false, false,
            [](void* o) { return &emi(o).flashesPerMinute; },
            "Lightning: mean flashes per minute of the flash clock, 0..6000. "
            "Default 6."));
        t.push_back(scalar(
            E, "flash_duration_s", "Flash duration", "s", {1e-3, 3600, 0.01, 5}, 0.35, true, false,
            [](void* o) { return &emi(o).flashDurationSeconds; },
            "Lightning: length of one flash [s of the flash clock], 0.001..3600. "
            "Default 0.35."));
        t.push_back(scalar(
            E, "time_scale", "Time scale", "", {1e-3, 1e6, 1, 3600}, 60.0, true, false,
            [](void* o) { return &emi(o).timeScale; },
            "Lightning: game seconds per second of the flash clock, 0.001..1e6 "
            "(a day at 60x shows real-time flashes). Default 60."));
        return t;
    }();
    return table;
}

const std::vector<ParamDesc>& cloudVolumeTable() {
    static const std::vector<ParamDesc> table = [] {
        std::vector<ParamDesc> t = identityParams<CloudVolume>(
            C,
            "Stable identifier (1..64 of A-Z a-z 0-9 _ - .), unique among cloud volumes; "
            "timeline tracks refer to it. Required.");
        t.push_back(enumeration(
            C, "shape", "Shape", kShapeNames, int(FogVolumeShape::Ellipsoid),
            [](const void* o) { return std::int64_t(static_cast<const CloudVolume*>(o)->shape); },
            [](void* o, std::int64_t v) { cvol(o).shape = FogVolumeShape(v); },
            "box (unit cube [-1,1]^3) or ellipsoid (unit sphere) in object space. Default ellipsoid."));
        t.push_back(triple(
            C, ParamType::Vec3, "position_m", "Position", "m", {-1e7, 1e7, -50000, 50000}, {0.0, 2500.0, 0.0},
            false, true, [](void* o) { return &cvol(o).position; },
            "Centre [m], world space (Y up, north -Z), -1e7..1e7; the layer's height is above the "
            "ground at y = 0. Default [0, 2500, 0]."));
        t.push_back(rotationParam(C, [](void* o) { return &cvol(o).rotation; }));
        t.push_back(triple(
            C, ParamType::Vec3, "half_extents_m", "Half extents", "m", {1, 1e7, 100, 50000},
            {4000.0, 2000.0, 4000.0}, false, true, [](void* o) { return &cvol(o).halfExtents; },
            "Half extents along the object axes [m], 1..1e7. Default [4000, 2000, 4000] (a storm "
            "cell 8 km across)."));
        t.push_back(scalar(
            C, "coverage", "Coverage", "", {0, 1, 0, 1}, 1.0, false, true,
            [](void* o) { return &cvol(o).coverage; },
            "Cloud coverage inside, 0..1, replacing the layer's (clouds.coverage): 1 a storm cell, "
            "0 a clear hole. Default 1."));
        t.push_back(scalar(
            C, "edge_softness", "Edge softness", "", {0, 1, 0, 1}, 0.3, false, true,
            [](void* o) { return &cvol(o).edgeSoftness; },
            "Outer fraction of the shape (in object-space radius) over which the coverage blends "
            "smoothly back to the layer's, 0..1 (0 a hard edge). Default 0.3."));
        return t;
    }();
    return table;
}

}  // namespace

std::span<const ParamDesc> paramTable(ParamScope scope) {
    switch (scope) {
        case ParamScope::Global:
            return globalTable();
        case ParamScope::Volume:
            return volumeTable();
        case ParamScope::Emitter:
            return emitterTable();
        case ParamScope::CloudVolume:
            return cloudVolumeTable();
    }
    return {};
}

const ParamDesc* findParam(ParamScope scope, std::string_view path) {
    for (const ParamDesc& p : paramTable(scope))
        if (p.path == path) return &p;
    return nullptr;
}

}  // namespace aerial
