// test_display.cpp — the OpenColorIO display transform: the built-in config,
// OCIO's GLSL on the GPU against OCIO's CPU processor, the un-tone-mapped
// view against the closed-form sRGB curve, $OCIO and its fallback, and the
// PNG written through the transform.
#include <aerial/renderer/display.hpp>

#include <gtest/gtest.h>
#include <stb_image.h>

#include <unistd.h>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include "gl_fixture.hpp"

namespace aerial::test {
namespace {

namespace fs = std::filesystem;
using renderer::DisplayDesc;
using renderer::DisplayTransform;
using renderer::Image;

constexpr const char* kUntoneMapped = "Un-tone-mapped";
constexpr const char* kAces = "ACES 1.0 - SDR Video";

/// 64 x 32: the top half a grey ramp of scene-linear values 0..16 (x), the
/// bottom half the ramp in one or two channels and saturated colours.
Image testImage() {
    Image image;
    image.width = 64;
    image.height = 32;
    image.channels = 4;
    image.pixels.resize(std::size_t(64) * 32 * 4);
    for (int y = 0; y < 32; ++y) {
        for (int x = 0; x < 64; ++x) {
            const float v = 16.0f * float(x) / 63.0f;
            float rgb[3] = {v, v, v};
            const int band = y / 4;
            switch (band) {
                case 4:
                    rgb[1] = rgb[2] = 0.0f;
                    break;
                case 5:
                    rgb[0] = rgb[2] = 0.0f;
                    break;
                case 6:
                    rgb[0] = rgb[1] = 0.0f;
                    break;
                case 7: {
                    // Colours at several intensities.
                    const float colours[4][3] = {
                        {1.0f, 0.5f, 0.1f}, {0.1f, 0.4f, 1.0f}, {0.2f, 0.9f, 0.3f}, {0.9f, 0.1f, 0.8f}};
                    const float* c = colours[x % 4];
                    const float scale = 0.05f + 4.0f * float(x) / 63.0f;
                    for (int k = 0; k < 3; ++k) rgb[k] = c[k] * scale;
                    break;
                }
                default:
                    break;
            }
            float* px = &image.pixels[(std::size_t(y) * 64 + x) * 4];
            px[0] = rgb[0];
            px[1] = rgb[1];
            px[2] = rgb[2];
            px[3] = float(y) / 31.0f;
        }
    }
    return image;
}

double srgbOetf(double x) { return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055; }

double maxAbsDifference(const Image& a, const Image& b, int channels = 3) {
    double worst = 0.0;
    const std::size_t count = std::size_t(a.width) * a.height;
    for (std::size_t i = 0; i < count; ++i)
        for (int c = 0; c < channels; ++c)
            worst = std::max(worst, double(std::abs(a.pixels[i * 4 + c] - b.pixels[i * 4 + c])));
    return worst;
}

/// Sets (or unsets) $OCIO for one scope.
class ScopedOcio {
public:
    explicit ScopedOcio(const std::optional<std::string>& value) {
        if (const char* old = std::getenv("OCIO")) previous_ = old;
        if (value)
            setenv("OCIO", value->c_str(), 1);
        else
            unsetenv("OCIO");
    }
    ~ScopedOcio() {
        if (previous_)
            setenv("OCIO", previous_->c_str(), 1);
        else
            unsetenv("OCIO");
    }
    ScopedOcio(const ScopedOcio&) = delete;
    ScopedOcio& operator=(const ScopedOcio&) = delete;

private:
    std::optional<std::string> previous_;
};

fs::path tempDirectory(const std::string& name) {
    const fs::path dir =
        fs::temp_directory_path() / ("aerial_test_display_" + name + "_" + std::to_string(getpid()));
    fs::create_directories(dir);
    return dir;
}

TEST(Display, BuiltinConfigHasTheViews) {
    ScopedOcio noEnv(std::nullopt);
    DisplayTransform display;
    ASSERT_TRUE(display.valid()) << display.error();
    EXPECT_EQ(display.configSource(), "built-in");
    EXPECT_FALSE(display.fellBack());
    EXPECT_EQ(display.display(), "sRGB - Display");
    EXPECT_EQ(display.view(), kAces);  // the default: tone-mapped, as a game shows it
    const std::vector<std::string> views = display.views();
    EXPECT_NE(std::find(views.begin(), views.end(), kUntoneMapped), views.end());
    EXPECT_NE(std::find(views.begin(), views.end(), kAces), views.end());
    EXPECT_FALSE(display.shaderText().empty());
    EXPECT_NE(DisplayTransform::builtinConfigText().find("ocio_profile_version: 2"), std::string::npos);
}

TEST(Display, UnknownViewListsTheViews) {
    ScopedOcio noEnv(std::nullopt);
    DisplayDesc desc;
    desc.view = "Filmic";
    DisplayTransform display(desc);
    EXPECT_FALSE(display.valid());
    EXPECT_NE(display.error().find("Filmic"), std::string::npos) << display.error();
    EXPECT_NE(display.error().find(kAces), std::string::npos) << display.error();
    desc.view = "";
    desc.display = "Nope";
    DisplayTransform noDisplay(desc);
    EXPECT_FALSE(noDisplay.valid());
    EXPECT_NE(noDisplay.error().find("sRGB - Display"), std::string::npos) << noDisplay.error();
}

TEST(Display, UntoneMappedIsTheSrgbCurveOfClampedExposedLinear) {
    ScopedOcio noEnv(std::nullopt);
    const Image image = testImage();
    for (double ev : {0.0, 2.0, -1.5}) {
        DisplayDesc desc;
        desc.view = kUntoneMapped;
        desc.exposureEv = ev;
        DisplayTransform display(desc);
        ASSERT_TRUE(display.valid()) << display.error();
        const Image shown = display.applyCpu(image);
        ASSERT_EQ(shown.pixels.size(), image.pixels.size());
        double worst = 0.0;
        for (std::size_t i = 0; i < shown.pixels.size(); ++i) {
            if (i % 4 == 3) {
                EXPECT_EQ(shown.pixels[i], image.pixels[i]);  // alpha passes through
                continue;
            }
            const double expected = srgbOetf(std::clamp(double(image.pixels[i]) * std::exp2(ev), 0.0, 1.0));
            worst = std::max(worst, std::abs(double(shown.pixels[i]) - expected));
        }
        EXPECT_LE(worst, 1e-3) << "EV " << ev;
    }
}

TEST(Display, AcesViewToneMaps) {
    ScopedOcio noEnv(std::nullopt);
    DisplayDesc desc;
    desc.view = kAces;
    DisplayTransform display(desc);
    ASSERT_TRUE(display.valid()) << display.error();
    float grey[3] = {0.18f, 0.18f, 0.18f};
    display.applyCpu(grey);
    EXPECT_NEAR(grey[0], grey[1], 1e-4);
    EXPECT_GT(grey[0], 0.3f);  // mid grey lands a little darker than the plain curve (0.46)
    EXPECT_LT(grey[0], 0.42f);
    float bright[3] = {16.0f, 16.0f, 16.0f};
    display.applyCpu(bright);
    EXPECT_GT(bright[0], 0.95f);  // rolls off towards white instead of clipping at 1
    EXPECT_LE(bright[0], 1.0f);
    float one[3] = {1.0f, 1.0f, 1.0f};
    display.applyCpu(one);
    EXPECT_LT(one[0], 0.9f);  // an untone-mapped 1 clips; ACES keeps headroom
}

TEST(Display, MiddleGreyEvShowsTheMeteredGreyAsACameraDoes) {
    ScopedOcio noEnv(std::nullopt);
    const double encodedGrey = 1.055 * std::pow(0.18, 1.0 / 2.4) - 0.055;  // 118/255
    DisplayDesc plainDesc;
    plainDesc.view = kUntoneMapped;
    DisplayTransform plain(plainDesc);
    ASSERT_TRUE(plain.valid()) << plain.error();
    EXPECT_NEAR(plain.middleGreyEv(), 0.0, 1e-6);  // the sRGB curve shows 0.18 at 118/255 already
    DisplayDesc acesDesc;
    acesDesc.view = kAces;
    DisplayTransform aces(acesDesc);
    ASSERT_TRUE(aces.valid()) << aces.error();
    const double ev = aces.middleGreyEv();
    EXPECT_GT(ev, 0.3);  // the filmic curve shows 0.18 darker (AcesViewToneMaps)
    EXPECT_LT(ev, 0.8);
    aces.setExposureEv(ev);
    float grey[3] = {0.18f, 0.18f, 0.18f};
    aces.applyCpu(grey);
    for (float c : grey) EXPECT_NEAR(c, encodedGrey, 1e-3);
    EXPECT_EQ(aces.middleGreyEv(), ev);  // the exposure does not enter
}

class DisplayGpu : public GlTest {};

TEST_F(DisplayGpu, GpuMatchesCpu) {
    ScopedOcio noEnv(std::nullopt);
    const Image image = testImage();
    for (const char* view : {kUntoneMapped, kAces}) {
        for (double ev : {0.0, 2.0}) {
            DisplayDesc desc;
            desc.view = view;
            desc.exposureEv = ev;
            desc.logger = log.logger();
            DisplayTransform display(desc);
            ASSERT_TRUE(display.valid()) << display.error();
            const Image cpu = display.applyCpu(image);
            const Image gpu = display.applyGpu(image, renderer::DisplayTarget::Rgba16F);
            ASSERT_EQ(gpu.pixels.size(), cpu.pixels.size())
                << view << " " << ev << ": " << (log.errors.empty() ? std::string() : log.errors.front());
            // RGBA16F stores the result with 11 significant bits: about 5e-4
            // at 1, well inside the 1e-3 tolerance.
            const double error = maxAbsDifference(gpu, cpu);
            std::printf("[ display ] %s, %+g EV: max |GPU - CPU| = %.3g (RGBA16F target)\n", view, ev, error);
            EXPECT_LE(error, 1e-3) << view << " " << ev;
            // RGBA32F: what the shader itself computes.
            const Image exact = display.applyGpu(image, renderer::DisplayTarget::Rgba32F);
            ASSERT_EQ(exact.pixels.size(), cpu.pixels.size());
            const double shaderError = maxAbsDifference(exact, cpu);
            std::printf("[ display ] %s, %+g EV: max |GPU - CPU| = %.3g (RGBA32F target)\n", view, ev,
                        shaderError);
            EXPECT_LE(shaderError, 1e-3) << view << " " << ev;
            // Alpha passes through.
            EXPECT_NEAR(gpu.pixels[4 * 64 * 31 + 3], 1.0f, 1e-3);

            // The 8-bit target: within one code value.
            const Image bytes = display.applyGpu(image, renderer::DisplayTarget::Rgba8);
            ASSERT_EQ(bytes.pixels.size(), cpu.pixels.size());
            EXPECT_LE(maxAbsDifference(bytes, cpu), 1.0 / 255.0 + 1e-4) << view << " " << ev;
        }
    }
    EXPECT_TRUE(log.errors.empty()) << log.errors.front();
}

TEST_F(DisplayGpu, NightVisionGpuMatchesCpu) {
    // The test image scaled into the night (1e-7 .. 1.6e-6 radiance units,
    // 5e-4 .. 8e-3 cd/m^2: scotopic to mesopic) and exposed back up: the
    // shader's aerialNight against core's aerial::nightVision on the CPU.
    ScopedOcio noEnv(std::nullopt);
    Image image = testImage();
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        if (i % 4 != 3) image.pixels[i] *= 1e-7f;
    DisplayDesc desc;
    desc.view = kUntoneMapped;
    desc.exposureEv = 20.0;
    desc.logger = log.logger();
    DisplayTransform display(desc);
    ASSERT_TRUE(display.valid()) << display.error();
    ASSERT_TRUE(display.nightVision());
    const Image cpu = display.applyCpu(image);
    const Image gpu = display.applyGpu(image, renderer::DisplayTarget::Rgba32F);
    ASSERT_EQ(gpu.pixels.size(), cpu.pixels.size());
    const double error = maxAbsDifference(gpu, cpu);
    std::printf("[ display ] night vision: max |GPU - CPU| = %.3g (RGBA32F target)\n", error);
    EXPECT_LE(error, 1e-3);
    // Night vision is a choice: off, the pixels are the plain exposure.
    display.setNightVision(false);
    const Image plain = display.applyCpu(image);
    EXPECT_GT(maxAbsDifference(plain, cpu), 0.05) << "night vision changed nothing";
    const Image plainGpu = display.applyGpu(image, renderer::DisplayTarget::Rgba32F);
    EXPECT_LE(maxAbsDifference(plainGpu, plain), 1e-3);
    EXPECT_TRUE(log.errors.empty()) << log.errors.front();
}

/// The roles and file rules of the small test configs: everything is "lin".
constexpr const char* kLinearRoles =
    "roles:\n"
    "  default: lin\n"
    "  scene_linear: lin\n"
    "file_rules:\n"
    "  - !<Rule> {name: Default, colorspace: default}\n";

/// A config whose views need LUT textures on the GPU (a 3D cube and a 1D
/// curve, written beside it), to exercise the texture upload.
TEST_F(DisplayGpu, LutTexturesMatchTheCpu) {
    const fs::path dir = tempDirectory("luts");
    {
        std::ofstream cube(dir / "look.cube");
        const int n = 17;
        cube << "LUT_3D_SIZE " << n << "\n";
        for (int b = 0; b < n; ++b)
            for (int g = 0; g < n; ++g)
                for (int r = 0; r < n; ++r) {
                    const double R = r / double(n - 1), G = g / double(n - 1), B = b / double(n - 1);
                    cube << std::sqrt(0.7 * R + 0.3 * B) << " " << G * G << " " << 0.5 * (B + R * G) << "\n";
                }
        std::ofstream curve(dir / "curve.cube");
        curve << "LUT_1D_SIZE 1024\n";
        for (int i = 0; i < 1024; ++i) {
            const double v = std::pow(i / 1023.0, 1.0 / 2.2);
            curve << v << " " << v * v << " " << 1.0 - v << "\n";
        }
        std::ofstream config(dir / "luts.ocio");
        config << "ocio_profile_version: 2\n"
                  "search_path: .\n"
               << kLinearRoles
               << "displays:\n"
                  "  LUT Display:\n"
                  "    - !<View> {name: Cube, colorspace: cube}\n"
                  "    - !<View> {name: Curve, colorspace: curve}\n"
                  "colorspaces:\n"
                  "  - !<ColorSpace> {name: lin}\n"
                  "  - !<ColorSpace>\n"
                  "    name: cube\n"
                  "    from_scene_reference: !<FileTransform> {src: look.cube, interpolation: linear}\n"
                  "  - !<ColorSpace>\n"
                  "    name: curve\n"
                  "    from_scene_reference: !<FileTransform> {src: curve.cube, interpolation: linear}\n";
    }
    Image image = testImage();
    for (float& v : image.pixels) v = std::min(v / 16.0f, 1.0f);  // the LUTs' domain
    for (const char* view : {"Cube", "Curve"}) {
        DisplayDesc desc;
        desc.config = (dir / "luts.ocio").string();
        desc.view = view;
        desc.logger = log.logger();
        DisplayTransform display(desc);
        ASSERT_TRUE(display.valid()) << display.error();
        EXPECT_FALSE(display.fellBack());
        // The shader samples a LUT texture (3D for the cube, 1D/2D for the curve).
        EXPECT_NE(display.shaderText().find(std::string(view) == "Cube" ? "sampler3D" : "sampler"),
                  std::string::npos)
            << display.shaderText();
        const Image cpu = display.applyCpu(image);
        const Image gpu = display.applyGpu(image, renderer::DisplayTarget::Rgba32F);
        ASSERT_EQ(gpu.pixels.size(), cpu.pixels.size())
            << view << ": " << (log.errors.empty() ? std::string() : log.errors.front());
        const double error = maxAbsDifference(gpu, cpu);
        std::printf("[ display ] LUT view %s: max |GPU - CPU| = %.3g (RGBA32F target)\n", view, error);
        EXPECT_LE(error, 1e-3) << view;
    }
    EXPECT_TRUE(log.errors.empty()) << log.errors.front();
    fs::remove_all(dir);
}

TEST(Display, OcioEnvironmentIsHonoured) {
    const fs::path dir = tempDirectory("env");
    const fs::path config = dir / "tiny.ocio";
    {
        std::ofstream out(config);
        out << "ocio_profile_version: 2\n"
            << kLinearRoles
            << "displays:\n"
               "  Tiny Display:\n"
               "    - !<View> {name: Half Gain, colorspace: half}\n"
               "colorspaces:\n"
               "  - !<ColorSpace> {name: lin}\n"
               "  - !<ColorSpace>\n"
               "    name: half\n"
               "    from_scene_reference: !<MatrixTransform> {matrix: [0.5, 0, 0, 0, 0, 0.5, 0, 0, 0, 0, "
               "0.5, 0, 0, 0, 0, 1]}\n";
    }
    ScopedOcio env(config.string());
    LogCapture log;
    DisplayDesc desc;
    desc.logger = log.logger();
    DisplayTransform display(desc);
    ASSERT_TRUE(display.valid()) << display.error();
    EXPECT_EQ(display.configSource(), config.string());
    EXPECT_FALSE(display.fellBack());
    EXPECT_EQ(display.display(), "Tiny Display");
    const std::vector<std::string> views = display.views();
    ASSERT_EQ(views.size(), 1u);
    EXPECT_EQ(views[0], "Half Gain");
    float rgb[3] = {1.0f, 2.0f, 4.0f};
    display.applyCpu(rgb);
    EXPECT_NEAR(rgb[0], 0.5f, 1e-6);
    EXPECT_NEAR(rgb[2], 2.0f, 1e-6);
    EXPECT_TRUE(log.warnings.empty());
    fs::remove_all(dir);
}

TEST(Display, BadOcioFallsBackWithAWarning) {
    const fs::path dir = tempDirectory("bad");
    const fs::path config = dir / "broken.ocio";
    {
        std::ofstream out(config);
        out << "this is: [not an OCIO config\n";
    }
    for (const std::string& path : {config.string(), (dir / "missing.ocio").string()}) {
        ScopedOcio env(path);
        LogCapture log;
        DisplayDesc desc;
        desc.logger = log.logger();
        DisplayTransform display(desc);
        ASSERT_TRUE(display.valid()) << display.error();
        EXPECT_TRUE(display.fellBack());
        EXPECT_EQ(display.configSource(), "built-in");
        EXPECT_EQ(display.display(), "sRGB - Display");
        ASSERT_EQ(log.warnings.size(), 1u);
        EXPECT_NE(log.warnings[0].find(path), std::string::npos) << log.warnings[0];
        EXPECT_NE(log.warnings[0].find("$OCIO"), std::string::npos) << log.warnings[0];
    }
    fs::remove_all(dir);
}

TEST(Display, PngGoesThroughTheTransform) {
    ScopedOcio noEnv(std::nullopt);
    const Image image = testImage();
    DisplayDesc desc;
    desc.view = kAces;
    desc.exposureEv = 1.0;
    DisplayTransform display(desc);
    ASSERT_TRUE(display.valid()) << display.error();
    const fs::path dir = tempDirectory("png");
    const fs::path png = dir / "aces.png";
    std::string error;
    ASSERT_TRUE(renderer::writePng(image, png.string(), display, error)) << error;
    int w = 0, h = 0, n = 0;
    unsigned char* bytes = stbi_load(png.string().c_str(), &w, &h, &n, 3);
    ASSERT_NE(bytes, nullptr);
    ASSERT_EQ(w, 64);
    ASSERT_EQ(h, 32);
    const Image cpu = display.applyCpu(image);
    int worst = 0;
    for (std::size_t i = 0; i < std::size_t(w) * h; ++i)
        for (int c = 0; c < 3; ++c) {
            const int expected = int(std::lround(std::clamp(cpu.pixels[i * 4 + c], 0.0f, 1.0f) * 255.0f));
            worst = std::max(worst, std::abs(int(bytes[i * 3 + c]) - expected));
        }
    stbi_image_free(bytes);
    EXPECT_LE(worst, 0);
    fs::remove_all(dir);
}

}  // namespace
}  // namespace aerial::test
