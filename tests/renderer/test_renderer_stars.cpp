// test_renderer_stars.cpp — the sky pass's stars against a CPU copy of
// sky.glsl's starRadiance (same hash, cells, magnitudes, Gaussian, air mass
// and limiting magnitude, in double precision) per pixel; the Kasten-Young
// dimming against the exact slant transmittance of core; the field's star
// counts; which stars show in twilight (the limiting magnitude of the sky
// behind each, aerial/stars.hpp); stars hidden by the switch and the scene.
#include "gl_fixture.hpp"
#include "sun_times.hpp"

#include <aerial/atmosphere.hpp>
#include <aerial/clouds.hpp>
#include <aerial/evaluate.hpp>
#include <aerial/exposure.hpp>
#include <aerial/night_sky.hpp>
#include <aerial/preset.hpp>
#include <aerial/sky.hpp>
#include <aerial/stars.hpp>
#include <aerial/sun.hpp>

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

namespace aerial::test {
namespace {

constexpr int kStarsWidth = 160;
constexpr int kStarsHeight = 90;
constexpr double kTwoPi = 6.28318530717958647692;

// sky.glsl's constants (float on the GPU).
constexpr std::uint32_t kStarColumns = 1024u;
constexpr std::uint32_t kStarRows = 512u;
constexpr double kStarProbability = double(0.016f);

std::uint32_t starHash(std::uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}
double starUnit(std::uint32_t h) { return double(h >> 8) * (1.0 / 16777216.0); }

double airMass(double mu) {
    const double zenithDeg = std::acos(std::clamp(mu, 0.0, 1.0)) * 180.0 / (kTwoPi / 2.0);
    return 1.0 / (mu + 0.50572 * std::pow(96.07995 - zenithDeg, -1.6364));
}

/// What the sky pass's stars read from a state: the brightest star's
/// illuminance, the celestial frame and the zenith transmittance.
struct StarSky {
    double starIlluminance = 0.0;
    CelestialFrame celestial;
    glm::dvec3 zenithTransmittance{1.0};
};

StarSky starSky(const PresetState& state) {
    return {renderer::kStarIlluminance, celestialFrame(state.environment.location, state.timeHours),
            state.zenithTransmittance};
}

/// One star of the field: its cell, place on the celestial sphere (unit, in
/// the frame's (equatorX, equatorY, pole) coordinates), V magnitude above
/// the atmosphere and tint.
struct FieldStar {
    std::uint32_t i = 0, j = 0;
    glm::dvec3 celestial{0.0};
    double magnitude = 0.0;
    glm::dvec3 tint{1.0};
};

/// The star of cell (i, j), if it has one (sky.glsl's hashes).
bool fieldStar(std::uint32_t i, std::uint32_t j, FieldStar& out) {
    const std::uint32_t h = starHash(j * kStarColumns + i + 0x5bd1e995u);
    if (starUnit(h) >= kStarProbability) return false;
    const std::uint32_t h1 = starHash(h), h2 = starHash(h1), h3 = starHash(h2), h4 = starHash(h3);
    const double ra = kTwoPi * (i + 0.15 + 0.7 * starUnit(h1)) / kStarColumns;
    const double sinDec = (j + 0.15 + 0.7 * starUnit(h2)) / kStarRows * 2.0 - 1.0;
    const double cosDec = std::sqrt(std::max(1.0 - sinDec * sinDec, 0.0));
    out.i = i;
    out.j = j;
    out.celestial = {cosDec * std::cos(ra), cosDec * std::sin(ra), sinDec};
    out.magnitude = starFieldMagnitude(starUnit(h3));
    out.tint = glm::mix(glm::dvec3(1.0, 0.82, 0.64), glm::dvec3(0.72, 0.84, 1.0), starUnit(h4));
    return true;
}

std::vector<FieldStar> fieldStars() {
    std::vector<FieldStar> stars;
    for (std::uint32_t j = 0; j < kStarRows; ++j) {
        for (std::uint32_t i = 0; i < kStarColumns; ++i) {
            FieldStar s;
            if (fieldStar(i, j, s)) stars.push_back(s);
        }
    }
    return stars;
}

glm::dvec3 worldFromCelestial(const CelestialFrame& f, const glm::dvec3& c) {
    return c.x * f.equatorX + c.y * f.equatorY + c.z * f.pole;
}

/// How much of a star of magnitude m shows towards v (above the horizon)
/// against the sky radiance `background` there: sky.glsl's fade.
double shownFraction(double magnitude, const glm::dvec3& v, const StarSky& air,
                     const glm::dvec3& background) {
    const double nits = luminance(background) * kNitsPerRadianceUnit;
    return starThresholdFade(extinctedMagnitude(magnitude, air.zenithTransmittance.y, v.y),
                             limitingMagnitude(nits));
}

/// The CPU copy of sky.glsl's starRadiance, against the sky radiance
/// `background` towards v.
glm::dvec3 starRadiance(const glm::dvec3& v, const StarSky& air, double sigma, const glm::dvec3& background) {
    if (!(air.starIlluminance > 0.0) || v.y <= 0.0) return glm::dvec3(0.0);
    const glm::dvec3 c(glm::dot(v, air.celestial.equatorX), glm::dot(v, air.celestial.equatorY),
                       glm::dot(v, air.celestial.pole));
    double u = std::atan2(c.y, c.x) / kTwoPi + 1.0;
    u -= std::floor(u);
    const double z = std::clamp(c.z, -1.0, 1.0);
    const int column = int(std::min(u * kStarColumns, double(kStarColumns - 1)));
    const int row = int(std::min((z * 0.5 + 0.5) * kStarRows, double(kStarRows - 1)));
    glm::dvec3 sum(0.0);
    for (int dj = -1; dj <= 1; ++dj) {
        const int j = row + dj;
        if (j < 0 || j >= int(kStarRows)) continue;
        for (int di = -1; di <= 1; ++di) {
            const std::uint32_t i = std::uint32_t(column + di + int(kStarColumns)) % kStarColumns;
            FieldStar s;
            if (!fieldStar(i, std::uint32_t(j), s)) continue;
            const glm::dvec3 d = c - s.celestial;
            const double flux = std::pow(10.0, -0.4 * (s.magnitude - kStarFieldBrightest)) *
                                shownFraction(s.magnitude, v, air, background);
            sum += flux * std::exp(-glm::dot(d, d) / (2.0 * sigma * sigma)) * s.tint;
        }
    }
    const double m = airMass(v.y);
    const glm::dvec3 t(std::pow(air.zenithTransmittance.x, m), std::pow(air.zenithTransmittance.y, m),
                       std::pow(air.zenithTransmittance.z, m));
    return sum * (air.starIlluminance / (kTwoPi * sigma * sigma)) * t;
}

/// The clear sky's radiance as the sky pass composes it behind the stars:
/// the sun's and the moon's tables (the solver's default size) and the
/// airglow.
class SkyBehindStars {
public:
    explicit SkyBehindStars(const PresetState& state) : state_(state), air_(starSky(state)) {
        sun_.solve(state.environment.atmosphere, state.sunLight.body.direction);
        moon_.solve(state.environment.atmosphere, state.moonLight.body.direction);
    }
    glm::dvec3 radiance(const glm::dvec3& v) const {
        const double g = state_.environment.atmosphere.mieAnisotropy;
        return skyRadiance(sun_.table(), g, v, state_.sunLight.illuminanceSpace) +
               skyRadiance(moon_.table(), g, v, state_.moonLight.illuminanceSpace) +
               airglowRadiance(v, state_.zenithTransmittance);
    }
    const StarSky& air() const { return air_; }

private:
    PresetState state_;
    StarSky air_;
    SkySolver sun_, moon_;
};

/// Magnitudes of the field stars that show (any fade > 0) in a state's sky.
std::vector<double> visibleStars(const PresetState& state) {
    const SkyBehindStars sky(state);
    std::vector<double> shown;
    for (const FieldStar& s : fieldStars()) {
        const glm::dvec3 v = worldFromCelestial(sky.air().celestial, s.celestial);
        if (v.y <= 0.0) continue;
        if (shownFraction(s.magnitude, v, sky.air(), sky.radiance(v)) > 0.0) shown.push_back(s.magnitude);
    }
    return shown;
}

class Stars : public GlTest {
protected:
    /// A moonless night: no sun or moon light, only stars.
    static PresetState night(double timeHours) {
        PresetState air;
        air.sunLight.illuminance = air.sunLight.illuminanceSpace = glm::dvec3(0.0);
        air.moonLight.illuminance = air.moonLight.illuminanceSpace = glm::dvec3(0.0);
        air.sunLight.body.elevation = -0.5;  // night: no twilight behind the stars
        air.environment.fog.density = 0.0;
        air.environment.location = Location{};
        air.timeHours = timeHours;  // the celestial frame: celestialFrame(Location{}, timeHours)
        air.zenithTransmittance =
            transmittanceToSpace(AtmosphereParams{}, AtmosphereParams{}.viewerHeight, 1.0);
        return air;
    }
    static renderer::Camera camera(const glm::dvec3& target, double fov) {
        renderer::Camera c;
        c.eye = {0.0, 2.0, 0.0};
        c.target = c.eye + target;
        c.verticalFov = fov;
        c.aspect = double(kStarsWidth) / kStarsHeight;
        return c;
    }
    static renderer::Image render(renderer::Renderer& r, const renderer::Camera& c, const PresetState& air,
                                  bool scene = false, bool stars = true) {
        renderer::FrameDesc f;
        f.stars = stars;
        f.sunDiscRadius = f.moonDiscRadius = 0.0;
        f.width = kStarsWidth;
        f.height = kStarsHeight;
        f.precision = renderer::ColourPrecision::Float;
        f.passes.scene = scene;
        f.passes.globalFog = f.passes.volumes = f.passes.emitters = false;
        f.passes.transparent = f.passes.particles = false;
        r.render(c, air, f);
        return r.readColour();
    }
};

/// The views of the per-pixel test: the zenith, the three brightest stars
/// that show above 5 deg, and the star nearest the middle of its fade.
struct StarViews {
    std::array<glm::dvec3, 5> look{};
    std::size_t count = 0;
    bool fading = false;
};
StarViews starViews(const StarSky& air, const std::vector<FieldStar>& field) {
    StarViews views;
    views.look[views.count++] = glm::dvec3(0.01, 1.0, 0.0);
    std::vector<std::pair<double, glm::dvec3>> shown;
    double nearestHalf = 1.0;
    glm::dvec3 fading(0.0);
    for (const FieldStar& s : field) {
        const glm::dvec3 v = worldFromCelestial(air.celestial, s.celestial);
        if (v.y < std::sin(5.0 * kTwoPi / 360.0)) continue;
        const double f = shownFraction(s.magnitude, v, air, airglowRadiance(v, air.zenithTransmittance));
        if (f > 0.0) shown.push_back({s.magnitude, v});
        if (f > 0.0 && f < 1.0 && std::abs(f - 0.5) < nearestHalf) {
            nearestHalf = std::abs(f - 0.5);
            fading = v;
        }
    }
    std::sort(shown.begin(), shown.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (std::size_t k = 0; k < std::min<std::size_t>(3, shown.size()); ++k)
        views.look[views.count++] = shown[k].second;
    if (nearestHalf < 0.5) {
        views.look[views.count++] = fading;
        views.fading = true;
    }
    return views;
}

// Every pixel against the CPU copy: |GPU - CPU| <= 1e-3 of a brightest
// star's peak radiance E / (2 pi sigma^2). At two times, views of the
// zenith, of the three brightest stars that show and of a star in its fade
// (starViews); at least 12 star pixels in all and one star in its fade, so
// the comparison is not of two black images.
TEST_F(Stars, EveryPixelMatchesTheCpuCopy) {
    renderer::Renderer r(rendererDesc());
    ASSERT_TRUE(r.valid()) << r.error();
    const double fov = 0.2;  // narrow: sigma = 0.6 px = 0.00133 rad (below the 0.0015 cap)
    const double sigma = std::min(0.6 * fov / kStarsHeight, 0.0015);
    const std::vector<FieldStar> field = fieldStars();
    int starPixels = 0, fadingViews = 0;
    double worst = 0.0;
    for (double t : {1.0, 4.5}) {
        const PresetState air = night(t);
        const StarSky stars = starSky(air);
        EXPECT_EQ(stars.starIlluminance, renderer::kStarIlluminance);
        const double peak = stars.starIlluminance / (kTwoPi * sigma * sigma);
        const StarViews views = starViews(stars, field);
        fadingViews += views.fading ? 1 : 0;
        for (std::size_t k = 0; k < views.count; ++k) {
            const renderer::Camera cam = camera(glm::normalize(views.look[k]), fov);
            const renderer::Image img = render(r, cam, air);
            const renderer::CameraFrame cf = renderer::cameraFrame(cam);
            for (int y = 0; y < kStarsHeight; ++y) {
                for (int x = 0; x < kStarsWidth; ++x) {
                    const glm::dvec3 v =
                        glm::normalize(renderer::farRayAtPixel(cf, x, y, kStarsWidth, kStarsHeight));
                    // The stars and the airglow (core's reference), the
                    // stars against the airglow.
                    const glm::dvec3 airglow = airglowRadiance(v, air.zenithTransmittance);
                    const glm::dvec3 star = starRadiance(v, stars, sigma, airglow);
                    const glm::dvec3 cpu = star + airglow;
                    for (int ch = 0; ch < 3; ++ch) {
                        const double gpu = img.at(x, y, ch);
                        ASSERT_TRUE(std::isfinite(gpu));
                        worst = std::max(worst, std::abs(gpu - cpu[ch]) / peak);
                    }
                    if (star.g > 1e-3 * peak) ++starPixels;
                }
            }
        }
    }
    std::printf(
        "stars: %d pixels above 0.1%% of the peak (%d views of a fading star); worst |GPU - CPU| = "
        "%.2e of the peak\n",
        starPixels, fadingViews, worst);
    EXPECT_GE(starPixels, 12);
    EXPECT_GE(fadingViews, 1);
    EXPECT_LE(worst, 1e-3);
}

// Stars behind a cloud: the cloud pass draws over the sky as L T + S
// (cloud_pass.cpp), so a star there keeps T of its radiance. A thin, still
// deck (wind 0) at two instants 72 s apart: the clouds and the airglow are
// the same, the stars moved by ~2 pixels, so the difference of the frames
// is T (stars(t1) - stars(t2)); against the CPU copy times the cloud pass's
// transmittance output T, within 5 % of each pixel's difference where the
// cloud passes 5-95 % (the lit march refines its steps; the transmittance
// mode does not), on at least 5 such star pixels.
TEST_F(Stars, BehindACloudTheyKeepItsTransmittance) {
    renderer::Renderer r(rendererDesc());
    ASSERT_TRUE(r.valid()) << r.error();
    const double fov = 0.2;
    const double sigma = std::min(0.6 * fov / kStarsHeight, 0.0015);
    auto cloudy = [](double t) {
        PresetState air = night(t);
        CloudParams& c = air.environment.clouds;
        c.coverage = 1.0;
        c.densityPerM = 1e-3;
        c.windMPerS = glm::dvec2(0.0);
        return air;
    };
    const double t1 = 1.0, t2 = 1.0 + 0.02;
    const StarSky air1 = starSky(cloudy(t1)), air2 = starSky(cloudy(t2));
    const double peak = air1.starIlluminance / (kTwoPi * sigma * sigma);
    const StarViews views = starViews(air1, fieldStars());
    int partly = 0;
    double worst = 0.0, meanT = 0.0;
    ASSERT_GE(views.count, 2u);
    renderer::FrameDesc f;
    f.sunDiscRadius = f.moonDiscRadius = 0.0;
    f.width = kStarsWidth;
    f.height = kStarsHeight;
    f.precision = renderer::ColourPrecision::Float;
    f.cloudSteps = 16;
    f.passes.scene = f.passes.globalFog = f.passes.volumes = false;
    f.passes.emitters = f.passes.transparent = f.passes.particles = false;
    {
        const renderer::Camera cam = camera(glm::normalize(views.look[1]), fov);  // the brightest star shown
        r.render(cam, cloudy(t1), f);
        const renderer::Image a = r.readColour();
        r.render(cam, cloudy(t2), f);
        const renderer::Image b = r.readColour();
        f.passes.sky = false;
        f.cloudOutput = renderer::CloudOutput::Transmittance;
        r.render(cam, cloudy(t1), f);
        const renderer::Image transmittance = r.readColour();
        const renderer::CameraFrame cf = renderer::cameraFrame(cam);
        for (int y = 0; y < kStarsHeight; ++y) {
            for (int x = 0; x < kStarsWidth; ++x) {
                const glm::dvec3 v =
                    glm::normalize(renderer::farRayAtPixel(cf, x, y, kStarsWidth, kStarsHeight));
                const glm::dvec3 airglow = airglowRadiance(v, air1.zenithTransmittance);
                const double cpu =
                    starRadiance(v, air1, sigma, airglow).g - starRadiance(v, air2, sigma, airglow).g;
                const double t = transmittance.at(x, y, 0);
                if (std::abs(cpu) < 1e-2 * peak || t < 0.05 || t > 0.95) continue;
                const double gpu = double(a.at(x, y, 1)) - double(b.at(x, y, 1));
                worst = std::max(worst, std::abs(gpu - t * cpu) / std::abs(cpu));
                meanT += t;
                ++partly;
            }
        }
    }
    std::printf("stars behind the deck: %d pixels (mean T %.2f), worst |GPU - T CPU| = %.3f of the star\n",
                partly, partly > 0 ? meanT / partly : 0.0, worst);
    EXPECT_GE(partly, 5);
    EXPECT_LE(worst, 0.05);
}

// Issue 48.3, "thin clouds dim the stars behind them by their
// transmittance", against core rather than the pass's own T: the brightest
// star shown, seen through a still full deck, its flux (the frame with the
// stars less the frame without, summed over 8 x 8 pixels round it) with the
// cloud pass on over the same flux with it off, against core's
// cloudTransmittance along the star's ray (64 steps, as the pass). A thin
// deck keeps T of the star; a thick one hides it. Rules out stars drawn
// over the clouds or not dimmed (ratio 1), hidden outright behind any
// cloud (ratio 0), dimmed by a threshold on the cloud's opacity, or twice
// (T^2: the thin deck's T ~0.6 would give ~0.36).
TEST_F(Stars, ThroughACloudTheyKeepCoresTransmittance) {
    renderer::Renderer r(rendererDesc());
    ASSERT_TRUE(r.valid()) << r.error();
    const StarViews views = starViews(starSky(night(1.0)), fieldStars());
    ASSERT_GE(views.count, 2u);
    const glm::dvec3 star = glm::normalize(views.look[1]);  // the brightest star shown
    const renderer::Camera cam = camera(star, 0.2);
    renderer::FrameDesc f;
    f.sunDiscRadius = f.moonDiscRadius = 0.0;
    f.width = kStarsWidth;
    f.height = kStarsHeight;
    f.precision = renderer::ColourPrecision::Float;
    f.cloudSteps = 64;
    f.passes.scene = f.passes.globalFog = f.passes.volumes = false;
    f.passes.emitters = f.passes.transparent = f.passes.particles = false;
    auto flux = [&](const PresetState& air, bool clouds) {
        f.passes.clouds = clouds;
        f.stars = true;
        r.render(cam, air, f);
        const renderer::Image with = r.readColour();
        f.stars = false;
        r.render(cam, air, f);
        const renderer::Image without = r.readColour();
        double sum = 0.0;
        for (int y = kStarsHeight / 2 - 4; y < kStarsHeight / 2 + 4; ++y)
            for (int x = kStarsWidth / 2 - 4; x < kStarsWidth / 2 + 4; ++x)
                sum += double(with.at(x, y, 1)) - double(without.at(x, y, 1));
        return sum;
    };
    for (double density : {1e-3, 2e-2}) {
        PresetState air = night(1.0);
        CloudParams& c = air.environment.clouds;
        c.coverage = 1.0;
        c.densityPerM = density;
        c.windMPerS = glm::dvec2(0.0);
        const double clear = flux(air, false), cloudy = flux(air, true);
        const double t = cloudTransmittance(prepareClouds(air), cam.eye, star,
                                            std::numeric_limits<double>::infinity(), 64);
        std::printf("stars through a %.0e /m deck: flux kept %.4f, core's T along the ray %.4f\n", density,
                    cloudy / clear, t);
        EXPECT_GT(clear, 0.0);
        // 0.01: the lit march refines each cloud's entry (the plain march of
        // core does not) and stops below T = 1e-3; measured 0.0026 (thin)
        // and 0.0008 (thick).
        EXPECT_NEAR(cloudy / clear, t, 0.01) << density;
    }
}

// The Kasten-Young dimming T_zenith^X(z) against core's exact slant
// transmittance (double quadrature through the spherical atmosphere), default
// atmosphere: within 2 % from the zenith down to 10 deg elevation (measured
// 0.0 / 0.06 / 1.5 % at 90 / 30 / 10 deg); 20 % at 3 deg (measured 16.5 %,
// green), where the ozone and aerosol layers' own air masses differ from the
// single formula and T is already ~0.1.
TEST(StarsAirMass, FollowsTheExactSlantTransmittance) {
    const AtmosphereParams air;
    const glm::dvec3 zenith = transmittanceToSpace(air, air.viewerHeight, 1.0);
    for (double elevationDeg : {90.0, 60.0, 30.0, 10.0, 3.0}) {
        const double mu = std::sin(elevationDeg * kTwoPi / 360.0);
        const glm::dvec3 exact = transmittanceToSpace(air, air.viewerHeight, mu);
        const double m = airMass(mu);
        for (int ch = 0; ch < 3; ++ch) {
            const double approx = std::pow(zenith[ch], m);
            const double tolerance = elevationDeg >= 10.0 ? 0.02 : 0.20;
            std::printf("elevation %4.0f deg channel %d: T exact %.4f, T_zenith^X %.4f (%+.2f %%)\n",
                        elevationDeg, ch, exact[ch], approx, 100.0 * (approx / exact[ch] - 1.0));
            EXPECT_NEAR(approx / exact[ch], 1.0, tolerance) << elevationDeg << " deg, channel " << ch;
        }
    }
}

// The frame a preset state gives: no star by
// day (the default preset at noon: the limit over the sky is brighter than
// every star), nothing where the scene covers the sky or with the stars off.
TEST_F(Stars, NoneByDayAndHiddenBehindTheScene) {
    const CompiledPreset preset;  // the default preset
    const PresetState noon = preset.evaluate(12.0);
    EXPECT_EQ(visibleStars(noon).size(), 0u);
    const PresetState midnight = preset.evaluate(0.0);
    ASSERT_LT(midnight.sunLight.body.elevation, -12.0 * kTwoPi / 360.0);
    const StarSky air = starSky(midnight);
    EXPECT_EQ(air.starIlluminance, renderer::kStarIlluminance);
    const AtmosphereParams& atmosphere = midnight.environment.atmosphere;
    const glm::dvec3 zenith = transmittanceToSpace(atmosphere, atmosphere.viewerHeight, 1.0);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(air.zenithTransmittance[c], zenith[c], 5e-4);  // tabulated in evaluate
    EXPECT_NEAR(glm::dot(air.celestial.pole, midnight.sunLight.body.direction),
                std::sin(solarDeclination(midnight.environment.location.dayOfYear)), 1e-12);

    renderer::Renderer r(rendererDesc());
    ASSERT_TRUE(r.valid()) << r.error();
    const renderer::Camera up = camera({0.01, 1.0, 0.0}, 0.2);
    const PresetState dark = night(1.0);
    const renderer::Image none = render(r, up, dark, false, false);  // FrameDesc::stars off
    // No star: every pixel is the airglow, which stays part of the sky.
    const renderer::CameraFrame upFrame = renderer::cameraFrame(up);
    double maxValue = 0.0, worst = 0.0;
    for (int y = 0; y < kStarsHeight; ++y)
        for (int x = 0; x < kStarsWidth; ++x) {
            const glm::dvec3 v =
                glm::normalize(renderer::farRayAtPixel(upFrame, x, y, kStarsWidth, kStarsHeight));
            const double airglow = airglowRadiance(v, dark.zenithTransmittance).g;
            maxValue = std::max(maxValue, double(none.at(x, y, 1)));
            worst = std::max(worst, std::fabs(none.at(x, y, 1) - airglow) / airglow);
        }
    EXPECT_LT(worst, 1e-4);

    // A wall in front of the camera covers every star.
    renderer::SceneDesc wall;
    wall.meshes.push_back(
        renderer::makeBoxMesh({0.0, 2.0, -5.0}, {50.0, 50.0, 0.5}, glm::dquat(1, 0, 0, 0), glm::dvec3(0.0)));
    r.setScene(wall);
    const renderer::Image covered = render(r, camera({0.0, 0.0, -1.0}, 0.2), night(1.0), true);
    maxValue = 0.0;
    for (int y = 0; y < kStarsHeight; ++y)
        for (int x = 0; x < kStarsWidth; ++x) maxValue = std::max(maxValue, double(covered.at(x, y, 1)));
    // The black wall reflects only the airglow's ambient (~4e-7), far below
    // a brightest star's peak (~2e-4 here).
    EXPECT_LT(maxValue, 1e-5);
}

// The field the hashes make: its star count and magnitudes against
// aerial/stars.hpp's expected counts (Poisson: within 4 sigma), i.e. the
// real sky's (~15 stars brighter than 1, ~4700 than 6; test_stars.cpp).
TEST(StarsField, CountsFollowTheModel) {
    const std::vector<FieldStar> field = fieldStars();
    for (double m : {1.0, 3.0, 5.0, 6.0, 6.5}) {
        const double expected = starFieldCount(m);
        const auto n =
            std::count_if(field.begin(), field.end(), [m](const FieldStar& s) { return s.magnitude < m; });
        std::printf("field: %ld stars brighter than %.1f (expected %.0f)\n", long(n), m, expected);
        EXPECT_NEAR(double(n), expected, 4.0 * std::sqrt(expected) + 1.0) << m;
    }
    const auto brightest =
        std::min_element(field.begin(), field.end(),
                         [](const FieldStar& a, const FieldStar& b) { return a.magnitude < b.magnitude; });
    ASSERT_NE(brightest, field.end());
    EXPECT_LT(brightest->magnitude, -0.5);  // ~1 star at -1.5 expected
}

// hazy_sunset at 19:15-ish (sun -5 deg): outdoors only the brightest stars
// (magnitude <= 1) show. Every field star above the horizon against the
// sky behind it (the sun's and moon's tables and the airglow): at most 10
// show, none fainter than magnitude 1. (The sun-elevation fade of before
// drew every star above the horizon, ~4200, at 35 % of its flux: the issue
// counted 43 in a frame.)
TEST(StarsTwilight, OnlyTheBrightestShowAtSunMinusFive) {
    PresetLoadResult loaded = loadPreset(std::string(AERIAL_SOURCE_DIR) + "/presets/hazy_sunset.json");
    ASSERT_TRUE(loaded.ok());
    const CompiledPreset preset(std::move(*loaded.preset));
    const PresetState dusk = preset.evaluate(aerial::test::eveningTimeOfSun(preset, -5.0));
    const std::vector<double> shown = visibleStars(dusk);
    double faintest = -10.0;
    for (double m : shown) faintest = std::max(faintest, m);
    std::printf("hazy_sunset, sun -5 deg: %zu stars show, the faintest of magnitude %.2f\n", shown.size(),
                shown.empty() ? 0.0 : faintest);
    EXPECT_LE(shown.size(), 10u);
    EXPECT_LE(faintest, 1.0);
    // And with the sun at -3 deg, none.
    EXPECT_EQ(visibleStars(preset.evaluate(aerial::test::eveningTimeOfSun(preset, -3.0))).size(), 0u);
}

}  // namespace
}  // namespace aerial::test
