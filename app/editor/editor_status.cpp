// editor_status.cpp — the status bar (time, sun, exposure, frame and solve
// times, the viewport's passes on hover, the message that clears itself)
// and --bench's report.
#include "editor.hpp"

#include <aerial/clock.hpp>

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <utility>
#include <vector>

namespace aerial::editor {
namespace {

double percentile(std::vector<double> values, double p) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    const double rank = p * double(values.size() - 1);
    const std::size_t lo = std::size_t(std::floor(rank)), hi = std::size_t(std::ceil(rank));
    return values[lo] + (values[hi] - values[lo]) * (rank - double(lo));
}

}  // namespace

void Editor::drawStatusBar() {
    const double elevationDeg = sky_.state.sunLight.body.elevation * 180.0 / kPi;
    const ExposureParams& exposure = sky_.state.environment.exposure;
    ImGui::Text("%s   sun %+.1f deg   EV100 %.1f %s%+.1f   frame %.1f ms   render %dx%d   sky solve %.2f ms",
                aerial::formatClock(playback_.timeHours, ClockResolution::Minutes).c_str(), elevationDeg,
                view_.exposure.ev100(), exposure.mode == ExposureMode::Manual ? "manual " : "auto ",
                exposure.compensationEv + view_.exposureEv, frames_.workMs, view_.renderWidth,
                view_.renderHeight, sky_.solveMs);
    if (ImGui::IsItemHovered() && frames_.lastPassesTimed) {
        // The viewport's passes, timed every 30th rendered frame (glFinish around each).
        const renderer::PassTimes& t = frames_.lastPasses;
        const std::pair<const char*, double> passes[] = {{"shadow maps", t.shadowMap},
                                                         {"cloud shadow", t.cloudShadow},
                                                         {"scene", t.scene},
                                                         {"sky", t.sky},
                                                         {"clouds", t.clouds},
                                                         {"subtract volumes", t.subtract},
                                                         {"global fog", t.globalFog},
                                                         {"fog volumes", t.volumes},
                                                         {"emitters", t.emitters},
                                                         {"froxel inject", t.froxelInject},
                                                         {"froxel integrate", t.froxelIntegrate},
                                                         {"froxel apply", t.froxelApply},
                                                         {"transparent", t.transparent},
                                                         {"particles", t.particles}};
        ImGui::BeginTooltip();
        ImGui::Text("Viewport passes [ms] (%s fog)",
                    view_.fogModeFor(sky_.state.environment) == renderer::FogMode::Volumetric ? "volumetric"
                                                                                              : "analytic");
        for (const auto& [name, ms] : passes)
            if (ms > 0.0) ImGui::Text("  %-17s %7.2f", name, ms);
        ImGui::Text("  %-17s %7.2f", "total", t.total());
        ImGui::EndTooltip();
    }
    if (export_.running()) {
        ImGui::SameLine();
        ImGui::SetNextItemWidth(160.0f);
        ImGui::ProgressBar(float(export_.progress()), ImVec2(160.0f, 0.0f), "Exporting...");
        ImGui::SameLine();
        if (ImGui::SmallButton("Cancel")) {
            export_.cancel();
            setStatus("Export cancelled");
        }
    }
    // A message stays 10 s after it was last changed, then the bar clears.
    const auto now = std::chrono::steady_clock::now();
    if (status_ != statusShown_) {
        statusShown_ = status_;
        statusSince_ = now;
    } else if (!status_.empty() && now - statusSince_ > std::chrono::seconds(10)) {
        status_.clear();
        statusShown_.clear();
    }
    if (!status_.empty()) {
        ImGui::SameLine();
        ImGui::TextDisabled("|  %s", status_.c_str());
    }
}

void Editor::printBench() const {
    auto passMedian = [&](double (*of)(const renderer::PassTimes&)) {
        std::vector<double> v;
        for (const renderer::PassTimes& t : frames_.benchPasses) v.push_back(of(t));
        return percentile(v, 0.5);
    };
    const std::vector<double>& f = frames_.benchFrameMs;
    const double mean = f.empty() ? 0.0 : std::accumulate(f.begin(), f.end(), 0.0) / double(f.size());
    const double solveMean = frames_.benchSolveMs.empty() ? 0.0
                                                          : std::accumulate(frames_.benchSolveMs.begin(),
                                                                            frames_.benchSolveMs.end(), 0.0) /
                                                                double(frames_.benchSolveMs.size());
    int winW = 0, winH = 0;
    glfwGetFramebufferSize(window_, &winW, &winH);
    std::printf(
        "aerial-editor bench: %zu frames (window %dx%d, viewport render %dx%d at resolution scale %.2f, "
        "scrubbing the day, sky re-solved every frame)\n"
        "  frame time [ms]: mean %.2f  median %.2f  p95 %.2f  max %.2f  (%.1f fps)\n"
        "  sky solve [ms]: mean %.2f  median %.2f  max %.2f (sun + moon tables, %zu solves)\n"
        "  viewport passes [ms]: median %.2f (wall time between glFinish calls, %zu frames sampled)\n",
        f.size(), winW, winH, view_.renderWidth, view_.renderHeight, view_.resolutionScale, mean,
        percentile(f, 0.5), percentile(f, 0.95), f.empty() ? 0.0 : *std::max_element(f.begin(), f.end()),
        mean > 0 ? 1000.0 / mean : 0.0, solveMean, percentile(frames_.benchSolveMs, 0.5),
        frames_.benchSolveMs.empty()
            ? 0.0
            : *std::max_element(frames_.benchSolveMs.begin(), frames_.benchSolveMs.end()),
        frames_.benchSolveMs.size(), passMedian([](const renderer::PassTimes& t) { return t.total(); }),
        frames_.benchPasses.size());
    std::printf(
        "    scene %.2f  sky %.2f  clouds %.2f  cloud shadow %.2f  shadow maps %.2f  subtract %.2f  "
        "global fog %.2f  volumes %.2f  "
        "emitters %.2f  froxel inject %.2f  integrate %.2f  apply %.2f  transparent %.2f  particles %.2f\n",
        passMedian([](const renderer::PassTimes& t) { return t.scene; }),
        passMedian([](const renderer::PassTimes& t) { return t.sky; }),
        passMedian([](const renderer::PassTimes& t) { return t.clouds; }),
        passMedian([](const renderer::PassTimes& t) { return t.cloudShadow; }),
        passMedian([](const renderer::PassTimes& t) { return t.shadowMap; }),
        passMedian([](const renderer::PassTimes& t) { return t.subtract; }),
        passMedian([](const renderer::PassTimes& t) { return t.globalFog; }),
        passMedian([](const renderer::PassTimes& t) { return t.volumes; }),
        passMedian([](const renderer::PassTimes& t) { return t.emitters; }),
        passMedian([](const renderer::PassTimes& t) { return t.froxelInject; }),
        passMedian([](const renderer::PassTimes& t) { return t.froxelIntegrate; }),
        passMedian([](const renderer::PassTimes& t) { return t.froxelApply; }),
        passMedian([](const renderer::PassTimes& t) { return t.transparent; }),
        passMedian([](const renderer::PassTimes& t) { return t.particles; }));
    std::fflush(stdout);
}

}  // namespace aerial::editor
