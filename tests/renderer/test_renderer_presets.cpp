// test_renderer_presets.cpp — no NaN or Inf in any rendered pixel (STYLE.md
// 6) over the shipped presets (presets/*.json through loadPreset and
// CompiledPreset) and a sweep of times of day, rendered with the built-in
// scene into the default RGBA16F target, sky tables solved per time.
// Cost: 40 frames of 96 x 54, ~0.4 s in Release and about the same under
// ASan + UBSan (llvmpipe itself is not instrumented), so no reduced sweep.
#include "gl_fixture.hpp"

#include <aerial/evaluate.hpp>
#include <aerial/preset.hpp>
#include <aerial/renderer/scene.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <vector>

namespace aerial::test {
namespace {

std::vector<std::string> shippedPresets() {
    std::vector<std::string> files;
    for (const auto& entry :
         std::filesystem::directory_iterator(std::string(AERIAL_SOURCE_DIR) + "/presets")) {
        if (entry.path().extension() == ".json" &&
            entry.path().filename().string().find("schema") == std::string::npos) {
            files.push_back(entry.path().string());
        }
    }
    std::sort(files.begin(), files.end());
    return files;
}

TEST_F(GlTest, ShippedPresetsOverTheDayGiveFinitePixels) {
    const std::vector<std::string> files = shippedPresets();
    ASSERT_GE(files.size(), 1u);
    const std::vector<double> times = {0.0, 4.5, 6.0, 7.5, 12.0, 17.25, 19.5, 21.75};
    renderer::Renderer r(rendererDesc());
    ASSERT_TRUE(r.valid()) << r.error();
    r.setScene(renderer::makeBuiltinScene());
    renderer::Camera camera;
    camera.eye = {0.0, 18.0, 80.0};
    camera.target = {0.0, 12.0, -100.0};
    camera.aspect = 96.0 / 54.0;
    camera.farDistance = 3000.0;
    renderer::FrameDesc frame;
    frame.width = 96;
    frame.height = 54;
    int frames = 0;
    for (const std::string& file : files) {
        PresetLoadResult loaded = loadPreset(file);
        ASSERT_TRUE(loaded.ok()) << file << ": "
                                 << (loaded.errors.empty() ? "" : loaded.errors[0].toString());
        const CompiledPreset compiled(std::move(*loaded.preset));
        PresetState state;
        for (double t : times) {
            compiled.evaluate(t, state);
            const SkyPair sky = solveSky(state.environment.atmosphere, state.sunLight.body.direction,
                                         state.moonLight.body.direction, 32, 16);
            r.setSky(sky.sun, sky.moon);
            r.render(camera, state, frame);
            const renderer::Image image = r.readColour();
            int bad = 0;
            double brightest = 0.0;
            for (float p : image.pixels) {
                bad += std::isfinite(p) ? 0 : 1;
                brightest = std::max(brightest, double(p));
            }
            EXPECT_EQ(bad, 0) << file << " at " << t << " h";
            EXPECT_LE(brightest, 65504.0) << file << " at " << t << " h";
            ++frames;
        }
    }
    std::printf("[ measured ] %d frames (%zu presets x %zu times) without NaN/Inf\n", frames, files.size(),
                times.size());
    EXPECT_TRUE(log.errors.empty()) << log.errors.front();
    EXPECT_EQ(r.stats().glErrors, 0);
}

}  // namespace
}  // namespace aerial::test
