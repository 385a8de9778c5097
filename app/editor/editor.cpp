// editor/editor.cpp — window, frame loop, fixed layout, menus, shortcuts,
// status bar, sky solves, --bench, modals. See editor.hpp for the map.
#include "editor.hpp"

#include <epoxy/gl.h>  // epoxy before any other GL header

#include <GLFW/glfw3.h>  // GLFW_INCLUDE_NONE is defined for this target
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <aerial/renderer/image.hpp>
#include <aerial/renderer/scene.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <numeric>

#include <unistd.h>

namespace aerial::editor {
namespace fs = std::filesystem;

namespace {

std::string lastGlfwError;

void glfwError(int code, const char* description) {
    lastGlfwError = description ? description : "unknown";
    (void)code;
}

void rendererLog(renderer::LogLevel level, const char* message, void* user) {
    if (level == renderer::LogLevel::Error || level == renderer::LogLevel::Warning) {
        std::fprintf(stderr, "aerial-editor: renderer %s: %s\n",
                     level == renderer::LogLevel::Error ? "error" : "warning", message);
        if (level == renderer::LogLevel::Error && user) *static_cast<std::string*>(user) = message;
    }
}

void printNoDisplay(const char* why) {
    std::fprintf(
        stderr,
        "aerial-editor: no display found (%s).\n"
        "The editor needs a window (X11 or Wayland). Without one, use the headless command-line tool:\n"
        "  aerial render default --time 18:30 --out frame.png   # a frame of the built-in scene (EGL, no "
        "window)\n"
        "  aerial day                                           # the default preset through a whole day\n"
        "  aerial eval PRESET --time 7 --json                   # every parameter at a time\n"
        "  aerial bake PRESET --out DIR                         # sky tables + parameters for a game\n"
        "or run the editor under a virtual display: xvfb-run -a aerial-editor\n",
        why);
}

std::string formatClock(double hours) {
    const double t = wrapHours(hours);
    int minutes = int(std::floor(t * 60.0 + 1e-6));
    char text[16];
    std::snprintf(text, sizeof text, "%02d:%02d", (minutes / 60) % 24, minutes % 60);
    return text;
}

double percentile(std::vector<double> values, double p) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    const double rank = p * double(values.size() - 1);
    const std::size_t lo = std::size_t(std::floor(rank)), hi = std::size_t(std::ceil(rank));
    return values[lo] + (values[hi] - values[lo]) * (rank - double(lo));
}

}  // namespace

void dropCallback(GLFWwindow* window, int count, const char** paths) {
    auto* editor = static_cast<Editor*>(glfwGetWindowUserPointer(window));
    if (!editor) return;
    for (int i = 0; i < count; ++i)
        if (paths[i]) editor->drops_.emplace_back(paths[i]);
}

int runEditor(const EditorOptions& options) {
    Editor editor(options);
    if (std::optional<int> failed = editor.initialise()) return *failed;
    return editor.run();
}

Editor::Editor(const EditorOptions& options)
    : options_(options), recent_((fs::path(configDirectory()) / "recent.json").string()) {
    sessionFile_ = (fs::path(configDirectory()) / "session.json").string();
}

Editor::~Editor() {
    export_.cancel();
    if (window_) {
        glfwMakeContextCurrent(window_);
        if (displayTexture_) glDeleteTextures(1, &displayTexture_);
        if (skyPreviewTexture_) glDeleteTextures(1, &skyPreviewTexture_);
        display_.reset();
        renderer_.reset();
        if (imguiReady_) {
            ImGui_ImplOpenGL3_Shutdown();
            ImGui_ImplGlfw_Shutdown();
            ImGui::DestroyContext();
        }
        glfwDestroyWindow(window_);
#if !defined(__SANITIZE_ADDRESS__)
        glfwTerminate();
#endif
        // A sanitizer build leaves the X connection (and with it Mesa's GL
        // driver) loaded until the process exits: once the driver is unloaded
        // LeakSanitizer can no longer attribute the driver's own allocations
        // to it, and the suppressions in main.cpp would not match (the CLI
        // keeps its EGL context alive for the same reason).
    }
}

double Editor::nowSeconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - startTime_).count();
}

std::optional<int> Editor::initialise() {
    const char* x11 = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    if ((!x11 || !*x11) && (!wayland || !*wayland)) {
        printNoDisplay("neither DISPLAY nor WAYLAND_DISPLAY is set");
        return kExitNoDisplay;
    }
    glfwSetErrorCallback(glfwError);
    if (!glfwInit()) {
        const std::string why = "GLFW could not connect to it: " + lastGlfwError;
        printNoDisplay(why.c_str());
        return kExitNoDisplay;
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    window_ = glfwCreateWindow(options_.width, options_.height, "Aerial", nullptr, nullptr);
    if (!window_) {
        std::fprintf(stderr,
                     "aerial-editor: cannot create a window with an OpenGL 4.5 core context: %s\n"
                     "Headless alternatives: aerial render ..., aerial day (see aerial --help).\n",
                     lastGlfwError.c_str());
        glfwTerminate();
        return kExitFailure;
    }
    glfwMakeContextCurrent(window_);
    const bool automated = !options_.script.empty() || options_.benchFrames > 0;
    glfwSwapInterval(automated ? 0 : 1);
    glfwSetWindowUserPointer(window_, this);
    glfwSetDropCallback(window_, dropCallback);

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // the layout is computed from the window size
    ImGui::StyleColorsDark();
    ImGuiStyle& style = ImGui::GetStyle();
    style.WindowRounding = 0.0f;
    style.FrameRounding = 2.0f;
    style.WindowBorderSize = 1.0f;
    style.ItemSpacing = ImVec2(6.0f, 4.0f);
    ImGui_ImplGlfw_InitForOpenGL(window_, true);
    ImGui_ImplOpenGL3_Init("#version 450");
    imguiReady_ = true;

    renderer::RendererDesc desc;
    desc.logger = {rendererLog, &renderLogError_};
    desc.debugOutput = false;
    renderer_ = std::make_unique<renderer::Renderer>(desc);
    if (!renderer_->valid()) {
        std::fprintf(stderr, "aerial-editor: cannot create the renderer: %s\n", renderer_->error().c_str());
        return kExitFailure;
    }
    sunSolver_ = std::make_unique<SkySolver>();
    moonSolver_ = std::make_unique<SkySolver>();

    if (options_.benchFrames == 0) session_.load(sessionFile_);  // --bench starts from the defaults
    recent_.load();
    if (!session_.cameraJson.empty()) {
        CameraState cameraState = camera_.state();
        if (cameraStateFromJson(session_.cameraJson, cameraState)) camera_.setState(cameraState);
    } else {
        // Above the valley floor looking north up the valley (as `aerial render`).
        CameraState s;
        s.target = {0.0, renderer::builtinTerrainHeight(0.0, -40.0) + 6.0, -40.0};
        s.distance = 70.0;
        s.yaw = 0.0;
        s.pitch = -0.18;
        camera_.setState(s);
    }
    displayName_ = session_.display;
    viewName_ = session_.view;
    exposureEv_ = session_.exposureEv;
    resolutionScale_ = session_.resolutionScale;
    timeHours_ = options_.script.empty() ? session_.timeHours : 9.0;  // scripts start at 09:00
    rebuildDisplay();

    if (!options_.scene.empty()) {
        if (!loadScene(options_.scene)) {
            std::fprintf(stderr, "aerial-editor: %s\n", errorText_.c_str());
            if (automated) return kExitFailure;
        }
    } else {
        renderer_->setScene(renderer::makeBuiltinScene());
        lastRenderSignature_.clear();
    }
    if (!options_.preset.empty()) {
        if (!openPreset(options_.preset)) {
            std::fprintf(stderr, "aerial-editor: cannot open %s:\n%s\n", options_.preset.c_str(),
                         errorText_.c_str());
            if (automated) return kExitFailure;
        }
    }

    autosave_ = std::make_unique<Autosave>(stateDirectory(), options_.autosaveSeconds);
    recovery_ = autosave_->findRecovery();
    if (recovery_) {
        if (options_.recover == "yes")
            recover(true);
        else if (options_.recover == "no")
            recover(false);
        else
            openRecoveryModal_ = true;
    }
    std::string error;
    if (!autosave_->start(doc_.path(), &error))
        std::fprintf(stderr, "aerial-editor: autosave is off: %s\n", error.c_str());

    if (!options_.script.empty()) {
        ScriptParseResult parsed = loadScript(options_.script);
        if (!parsed.ok()) {
            std::fprintf(stderr, "aerial-editor: %s\n", parsed.error.c_str());
            return kExitFailure;
        }
        script_ = std::move(parsed.commands);
        std::printf("aerial-editor pid %d\n", int(::getpid()));  // for tests that kill -9 it
        std::fflush(stdout);
        if (script_.empty()) script_.push_back({0, {"quit"}});
    }
    glfwSetWindowTitle(window_, doc_.title().c_str());
    lastFrame_ = std::chrono::steady_clock::now();
    return std::nullopt;
}

int Editor::run() {
    std::string title = doc_.title();
    while (!quit_) {
        frame();
        if (doc_.title() != title) {
            title = doc_.title();
            glfwSetWindowTitle(window_, title.c_str());
        }
        if (options_.benchFrames > 0 && frameIndex_ >= options_.benchFrames + 3) quit_ = true;
    }
    export_.wait();
    if (options_.benchFrames > 0) printBench();
    if (options_.benchFrames == 0) {
        session_.cameraJson = cameraStateToJson(camera_.state());
        session_.display = displayName_;
        session_.view = viewName_;
        session_.exposureEv = exposureEv_;
        session_.resolutionScale = resolutionScale_;
        session_.timeHours = timeHours_;
        session_.save(sessionFile_);
    }
    if (autosave_) autosave_->finish();
    return exitCode_;
}

void Editor::frame() {
    const auto now = std::chrono::steady_clock::now();
    const double dt = std::chrono::duration<double>(now - lastFrame_).count();
    lastFrame_ = now;
    frameMs_ = dt * 1000.0;
    if (options_.benchFrames > 0 && frameIndex_ >= 3 && int(benchFrameMs_.size()) < options_.benchFrames)
        benchFrameMs_.push_back(frameMs_);  // the first frames compile shaders and fill caches

    // An idle editor sleeps until the next event (or 0.25 s) instead of
    // redrawing: on a software rasteriser every frame costs a core.
    const bool automated = !options_.script.empty() || options_.benchFrames > 0;
    if (!automated && idleFrames_ > 3 && !playing_ && !export_.running() && !gizmo_.active())
        glfwWaitEventsTimeout(0.25);
    else
        glfwPollEvents();
    const auto workStart = std::chrono::steady_clock::now();  // the frame's work, without the idle wait
    if (glfwWindowShouldClose(window_)) {
        glfwSetWindowShouldClose(window_, GLFW_FALSE);
        requestQuit();
    }
    handleDrops();
    export_.poll();

    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();

    {
        const ImGuiIO& io = ImGui::GetIO();
        bool active = io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f || io.MouseWheel != 0.0f ||
                      io.WantTextInput || !drops_.empty() || ImGui::IsAnyItemActive();
        for (bool down : io.MouseDown) active = active || down;
        for (bool down : io.KeysDown) active = active || down;
        idleFrames_ = active ? 0 : idleFrames_ + 1;
    }
    if (!script_.empty()) stepScript();
    if (options_.benchFrames > 0 && frameIndex_ >= 3)
        timeHours_ = wrapHours(timeHours_ + 24.0 / 240.0);  // scrub
    advancePlayback(dt);
    updateEvaluation();
    updateSky();

    layout();
    drawModals();
    drawFileDialogs();
    handleShortcuts();
    ImGui::Render();

    updateEvaluation();  // the UI may have changed the preset or the time
    updateSky();
    renderViewport();

    int width = 0, height = 0;
    glfwGetFramebufferSize(window_, &width, &height);
    glViewport(0, 0, width, height);
    glClearColor(0.1f, 0.1f, 0.11f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    if (!windowShotPath_.empty()) captureWindow(width, height);
    glfwSwapBuffers(window_);
    workMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - workStart).count();

    if (autosave_ &&
        autosave_->update(nowSeconds(), doc_.dirty(), doc_.revision(), doc_.preset(), doc_.path()))
        setStatus("Autosaved unsaved work to " + autosave_->recoveryFile());
    ++frameIndex_;
}

void Editor::captureWindow(int width, int height) {
    // The whole window as shown (UI included), for documentation and tests.
    std::vector<std::uint8_t> rgba(std::size_t(width) * std::size_t(height) * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    renderer::Image image;
    image.width = width;
    image.height = height;
    image.channels = 3;
    image.pixels.resize(std::size_t(width) * std::size_t(height) * 3);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < 3; ++c) {
                // writePng encodes with the sRGB curve: decode the displayed bytes first.
                const double v =
                    rgba[(std::size_t(height - 1 - y) * std::size_t(width) + std::size_t(x)) * 4 +
                         std::size_t(c)] /
                    255.0;
                image.pixels[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3 + std::size_t(c)] =
                    float(v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4));
            }
    std::string error;
    if (renderer::writePng(image, windowShotPath_, 1.0, error))
        std::printf("window_screenshot %s %dx%d\n", windowShotPath_.c_str(), width, height);
    else
        std::fprintf(stderr, "aerial-editor: %s\n", error.c_str());
    std::fflush(stdout);
    windowShotPath_.clear();
}

void Editor::updateEvaluation() {
    if (!compiled_ || compiledRevision_ != doc_.revision()) {
        compiled_ = std::make_unique<CompiledPreset>(doc_.preset());
        compiledRevision_ = doc_.revision();
        validateSelection();
    }
    compiled_->evaluate(timeHours_, state_);
}

void Editor::updateSky() {
    const AtmosphereParams& air = state_.environment.atmosphere;
    const glm::dvec3 sun = state_.sunLight.body.direction, moon = state_.moonLight.body.direction;
    if (skyValid_ && std::memcmp(&air, &solvedAir_, sizeof air) == 0 && sun == solvedSun_ &&
        moon == solvedMoon_)
        return;
    const auto start = std::chrono::steady_clock::now();
    sunSolver_->solve(air, sun);
    moonSolver_->solve(air, moon);
    skySolveMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    if (options_.benchFrames > 0 && frameIndex_ >= 3) benchSolveMs_.push_back(skySolveMs_);
    renderer_->setSky(sunSolver_->table(), moonSolver_->table());
    solvedAir_ = air;
    solvedSun_ = sun;
    solvedMoon_ = moon;
    skyValid_ = true;
    ++skyGeneration_;
}

void Editor::layout() {
    const ImGuiIO& io = ImGui::GetIO();
    const float w = io.DisplaySize.x, h = io.DisplaySize.y;
    drawMenuBar();
    const float menuH = ImGui::GetFrameHeight();
    const float statusH = ImGui::GetFrameHeight() + 4.0f;
    const float timelineH = std::clamp(h * 0.28f, 110.0f, 280.0f);
    const float leftW = std::clamp(w * 0.17f, 120.0f, 280.0f);
    const float rightW = std::clamp(w * 0.28f, 180.0f, 440.0f);
    const float middleH = std::max(60.0f, h - menuH - statusH - timelineH);
    const ImGuiWindowFlags fixed = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                   ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
                                   ImGuiWindowFlags_NoBringToFrontOnFocus;

    ImGui::SetNextWindowPos(ImVec2(0, menuH));
    ImGui::SetNextWindowSize(ImVec2(leftW, middleH));
    if (ImGui::Begin("Outliner", nullptr, fixed)) drawOutliner();
    ImGui::End();

    ImGui::SetNextWindowPos(ImVec2(w - rightW, menuH));
    ImGui::SetNextWindowSize(ImVec2(rightW, middleH));
    if (ImGui::Begin("Inspector", nullptr, fixed)) drawInspector();
    ImGui::End();

    ImGui::SetNextWindowPos(ImVec2(leftW, menuH));
    ImGui::SetNextWindowSize(ImVec2(std::max(10.0f, w - leftW - rightW), middleH));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
    if (ImGui::Begin("Viewport", nullptr,
                     fixed | ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse))
        drawViewport();
    else
        viewportVisible_ = false;
    ImGui::End();
    ImGui::PopStyleVar();

    ImGui::SetNextWindowPos(ImVec2(0, menuH + middleH));
    ImGui::SetNextWindowSize(ImVec2(w, timelineH));
    if (ImGui::Begin("Timeline", nullptr, fixed | ImGuiWindowFlags_NoScrollbar)) drawTimeline();
    ImGui::End();

    ImGui::SetNextWindowPos(ImVec2(0, h - statusH));
    ImGui::SetNextWindowSize(ImVec2(w, statusH));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(6, 2));
    if (ImGui::Begin("##status", nullptr, fixed | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar))
        drawStatusBar();
    ImGui::End();
    ImGui::PopStyleVar();
}

void Editor::drawMenuBar() {
    if (!ImGui::BeginMainMenuBar()) return;
    if (ImGui::BeginMenu("File")) {
        if (ImGui::MenuItem("New", "Ctrl+N")) requestNew();
        if (ImGui::MenuItem("Open...", "Ctrl+O")) requestOpen("");
        if (ImGui::BeginMenu("Open Recent", !recent_.files().empty())) {
            std::string chosen;
            for (const std::string& file : recent_.files())
                if (ImGui::MenuItem(file.c_str())) chosen = file;
            ImGui::Separator();
            if (ImGui::MenuItem("Clear recent files")) recent_.clear();
            ImGui::EndMenu();
            if (!chosen.empty()) requestOpen(chosen);
        }
        if (ImGui::MenuItem("Save", "Ctrl+S")) saveOrSaveAs(false);
        if (ImGui::MenuItem("Save As...", "Ctrl+Shift+S")) saveOrSaveAs(true);
        ImGui::Separator();
        if (ImGui::MenuItem("Load scene (glTF)...")) {
            dialogPurpose_ = DialogPurpose::Scene;
            fileDialog_.open("Load scene (glTF)", FileDialog::Mode::Open, {".gltf", ".glb"}, scenePath_);
        }
        if (ImGui::MenuItem("Built-in scene", nullptr, false, !scenePath_.empty())) {
            renderer_->setScene(renderer::makeBuiltinScene());
            lastRenderSignature_.clear();
            scenePath_.clear();
            setStatus("Built-in scene");
        }
        ImGui::Separator();
        if (ImGui::MenuItem("Screenshot...")) {
            dialogPurpose_ = DialogPurpose::Screenshot;
            fileDialog_.open("Screenshot (.png display-referred, .exr scene-linear)", FileDialog::Mode::Save,
                             {".png", ".exr"}, "");
        }
        if (ImGui::MenuItem("Export for game...", nullptr, false, !export_.running())) {
            dialogPurpose_ = DialogPurpose::Export;
            fileDialog_.open("Export for game (aerial bake) into folder", FileDialog::Mode::Directory, {},
                             "");
        }
        ImGui::Separator();
        if (ImGui::MenuItem("Quit", "Ctrl+Q")) requestQuit();
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Edit")) {
        const std::string undo = "Undo " + doc_.undoLabel(), redo = "Redo " + doc_.redoLabel();
        if (ImGui::MenuItem(undo.c_str(), "Ctrl+Z", false, doc_.canUndo())) {
            doc_.undo();
            validateSelection();
        }
        if (ImGui::MenuItem(redo.c_str(), "Ctrl+Shift+Z", false, doc_.canRedo())) {
            doc_.redo();
            validateSelection();
        }
        ImGui::Separator();
        if (ImGui::MenuItem("Delete", "Del", false, objectSelected())) deleteSelection();
        if (ImGui::MenuItem("Duplicate", "Ctrl+D", false, objectSelected())) duplicateSelection();
        ImGui::Separator();
        if (ImGui::MenuItem("Key all changed parameters")) {
            int count = 0;
            const Preset baseline = doc_.baseline();
            doc_.apply("Key all changed", "",
                       [&](Preset& p) { count = keyAllChanged(p, baseline, timeHours_); });
            setStatus(std::to_string(count) + " keys set at " + formatClock(timeHours_));
        }
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Create")) {
        if (ImGui::MenuItem("Box volume", "Shift+B")) addVolumeInFront(FogVolumeShape::Box);
        if (ImGui::MenuItem("Ellipsoid volume", "Shift+E")) addVolumeInFront(FogVolumeShape::Ellipsoid);
        if (ImGui::MenuItem("Emitter", "Shift+P")) addEmitterInFront(EmitterKind::Point);
        if (ImGui::MenuItem("Lightning", "Shift+T")) addEmitterInFront(EmitterKind::Lightning);
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("View")) {
        if (display_ && ImGui::BeginMenu("OCIO display")) {
            for (const std::string& d : display_->displays())
                if (ImGui::MenuItem(d.c_str(), nullptr, d == display_->display())) {
                    displayName_ = d;
                    viewName_.clear();
                    rebuildDisplay();
                }
            ImGui::EndMenu();
        }
        if (display_ && ImGui::BeginMenu("OCIO view")) {
            for (const std::string& v : display_->views())
                if (ImGui::MenuItem(v.c_str(), nullptr, v == display_->view())) {
                    viewName_ = v;
                    rebuildDisplay();
                }
            ImGui::EndMenu();
        }
        float ev = float(exposureEv_);
        ImGui::SetNextItemWidth(140.0f);
        if (ImGui::SliderFloat("Exposure [EV]", &ev, -10.0f, 10.0f, "%.2f")) {
            exposureEv_ = ev;
            if (display_) display_->setExposureEv(ev);
        }
        if (ImGui::BeginMenu("Resolution scale")) {
            for (double s : {0.25, 0.5, 0.75, 1.0}) {
                char label[32];
                std::snprintf(label, sizeof label, "%d%%", int(s * 100.0 + 0.5));
                if (ImGui::MenuItem(label, nullptr, std::abs(resolutionScale_ - s) < 1e-9))
                    resolutionScale_ = s;
            }
            ImGui::EndMenu();
        }
        ImGui::Separator();
        ImGui::MenuItem("Helpers (outlines, icons, gizmo)", nullptr, &showHelpers_);
        ImGui::MenuItem("Ground grid", nullptr, &showGrid_);
        ImGui::Separator();
        ImGui::MenuItem("Sky", nullptr, &passes_.sky);
        ImGui::MenuItem("Stars", nullptr, &showStars_);
        ImGui::MenuItem("Scene geometry", nullptr, &passes_.scene);
        ImGui::MenuItem("Global fog", nullptr, &passes_.globalFog);
        ImGui::MenuItem("Fog volumes", nullptr, &passes_.volumes);
        ImGui::MenuItem("Emitters", nullptr, &passes_.emitters);
        ImGui::MenuItem("Transparent objects", nullptr, &passes_.transparent);
        ImGui::MenuItem("Fog particles", nullptr, &passes_.particles);
        ImGui::Separator();
        if (ImGui::MenuItem("Move", "W", gizmoMode_ == GizmoMode::Translate))
            gizmoMode_ = GizmoMode::Translate;
        if (ImGui::MenuItem("Rotate", "E", gizmoMode_ == GizmoMode::Rotate)) gizmoMode_ = GizmoMode::Rotate;
        if (ImGui::MenuItem("Scale", "R", gizmoMode_ == GizmoMode::Scale)) gizmoMode_ = GizmoMode::Scale;
        bool local = gizmoSpace_ == GizmoSpace::Local;
        if (ImGui::MenuItem("Local axes", "L", &local))
            gizmoSpace_ = local ? GizmoSpace::Local : GizmoSpace::World;
        if (ImGui::MenuItem("Frame selection", "F", false, objectSelected())) frameSelection();
        ImGui::EndMenu();
    }
    ImGui::EndMainMenuBar();
}

void Editor::drawStatusBar() {
    const double elevationDeg = state_.sunLight.body.elevation * 180.0 / kPi;
    ImGui::Text("%s   sun %+.1f deg   frame %.1f ms   render %dx%d   sky solve %.2f ms",
                formatClock(timeHours_).c_str(), elevationDeg, workMs_, renderWidth_, renderHeight_,
                skySolveMs_);
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
    if (!status_.empty()) {
        ImGui::SameLine();
        ImGui::TextDisabled("|  %s", status_.c_str());
    }
}

void Editor::setStatus(std::string text) { status_ = std::move(text); }

void Editor::showError(std::string title, std::string text) {
    errorTitle_ = std::move(title);
    errorText_ = std::move(text);
    openErrorModal_ = true;
    if (!options_.script.empty())
        std::fprintf(stderr, "aerial-editor: %s:\n%s\n", errorTitle_.c_str(), errorText_.c_str());
}

void Editor::handleShortcuts() {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantTextInput || ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId)) return;
    const bool ctrl = io.KeyCtrl, shift = io.KeyShift;
    auto pressed = [](int key) { return ImGui::IsKeyPressed(key, false); };
    if (ctrl) {
        if (pressed(GLFW_KEY_N)) requestNew();
        if (pressed(GLFW_KEY_O)) requestOpen("");
        if (pressed(GLFW_KEY_S)) saveOrSaveAs(shift);
        if (pressed(GLFW_KEY_Q)) requestQuit();
        if (pressed(GLFW_KEY_D)) duplicateSelection();
        if (ImGui::IsKeyPressed(GLFW_KEY_Z, true)) {
            if (shift ? doc_.redo() : doc_.undo()) validateSelection();
        }
        if (ImGui::IsKeyPressed(GLFW_KEY_Y, true) && doc_.redo()) validateSelection();
        return;
    }
    if (camera_.flying()) return;  // W A S D Q E fly
    if (shift) {  // Create: in front of the camera
        if (pressed(GLFW_KEY_B)) addVolumeInFront(FogVolumeShape::Box);
        if (pressed(GLFW_KEY_E)) addVolumeInFront(FogVolumeShape::Ellipsoid);
        if (pressed(GLFW_KEY_P)) addEmitterInFront(EmitterKind::Point);
        if (pressed(GLFW_KEY_T)) addEmitterInFront(EmitterKind::Lightning);
        return;
    }
    if (pressed(GLFW_KEY_W)) gizmoMode_ = GizmoMode::Translate;
    if (pressed(GLFW_KEY_E)) gizmoMode_ = GizmoMode::Rotate;
    if (pressed(GLFW_KEY_R)) gizmoMode_ = GizmoMode::Scale;
    if (pressed(GLFW_KEY_L))
        gizmoSpace_ = gizmoSpace_ == GizmoSpace::World ? GizmoSpace::Local : GizmoSpace::World;
    if (pressed(GLFW_KEY_F)) frameSelection();
    if (pressed(GLFW_KEY_SPACE)) playing_ = !playing_;
    if (pressed(GLFW_KEY_DELETE) && !timelineHovered_) deleteSelection();  // the timeline deletes keys
    if (pressed(GLFW_KEY_ESCAPE) && gizmo_.active()) {
        GizmoTransform t;
        if (gizmoTransformOfSelection(t) && gizmo_.cancel(t)) {
            applyGizmoTransform(t);
            doc_.closeMerge();
        }
    }
}

void Editor::drawModals() {
    if (openErrorModal_) {
        ImGui::OpenPopup("Error##modal");
        openErrorModal_ = false;
    }
    ImGui::SetNextWindowSize(ImVec2(std::min(720.0f, ImGui::GetIO().DisplaySize.x - 40.0f), 0.0f),
                             ImGuiCond_Appearing);
    if (ImGui::BeginPopupModal("Error##modal", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::TextUnformatted(errorTitle_.c_str());
        ImGui::Separator();
        ImGui::PushTextWrapPos(ImGui::GetIO().DisplaySize.x - 80.0f);
        ImGui::TextUnformatted(errorText_.c_str());
        ImGui::PopTextWrapPos();
        if (ImGui::Button("Copy")) ImGui::SetClipboardText(errorText_.c_str());
        ImGui::SameLine();
        if (ImGui::Button("OK", ImVec2(100, 0)) || ImGui::IsKeyPressed(GLFW_KEY_ENTER))
            ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
    }

    if (openUnsavedModal_) {
        ImGui::OpenPopup("Unsaved changes");
        openUnsavedModal_ = false;
        unsavedPromptOpen_ = true;
    }
    if (ImGui::BeginPopupModal("Unsaved changes", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        const std::string name =
            doc_.path().empty() ? std::string("Untitled") : fs::path(doc_.path()).filename().string();
        ImGui::Text("Save the changes to %s first?", name.c_str());
        ImGui::TextDisabled("Discarded changes cannot be undone.");
        if (ImGui::Button("Save", ImVec2(100, 0))) resolveUnsaved(UnsavedChoice::Save);
        ImGui::SameLine();
        if (ImGui::Button("Discard", ImVec2(100, 0))) resolveUnsaved(UnsavedChoice::Discard);
        ImGui::SameLine();
        if (ImGui::Button("Cancel", ImVec2(100, 0)) || ImGui::IsKeyPressed(GLFW_KEY_ESCAPE))
            resolveUnsaved(UnsavedChoice::Cancel);
        if (!unsavedPromptOpen_) ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
    }

    if (openRecoveryModal_) {
        ImGui::OpenPopup("Recover unsaved work?");
        openRecoveryModal_ = false;
    }
    if (ImGui::BeginPopupModal("Recover unsaved work?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        if (recovery_) {
            ImGui::Text("Aerial did not exit cleanly last time (process %d).", recovery_->pid);
            ImGui::Text("Unsaved work on %s was autosaved.", recovery_->documentPath.empty()
                                                                 ? "an untitled preset"
                                                                 : recovery_->documentPath.c_str());
        }
        if (ImGui::Button("Recover", ImVec2(110, 0))) {
            ImGui::CloseCurrentPopup();
            recover(true);
        }
        ImGui::SameLine();
        if (ImGui::Button("Discard", ImVec2(110, 0))) {
            ImGui::CloseCurrentPopup();
            recover(false);
        }
        ImGui::EndPopup();
    }
}

void Editor::resolveUnsaved(UnsavedChoice choice) {
    unsavedPromptOpen_ = false;
    switch (choice) {
        case UnsavedChoice::Save:
            if (doc_.path().empty()) {
                continueAfterSave_ = true;  // the pending action runs once Save As succeeds
                saveOrSaveAs(true);
            } else if (savePresetTo(doc_.path())) {
                runPending();
            } else {
                pending_ = Pending::None;
            }
            break;
        case UnsavedChoice::Discard:
            runPending();
            break;
        case UnsavedChoice::Cancel:
            pending_ = Pending::None;
            break;
    }
}

void Editor::printBench() const {
    auto passMedian = [&](double (*of)(const renderer::PassTimes&)) {
        std::vector<double> v;
        for (const renderer::PassTimes& t : benchPasses_) v.push_back(of(t));
        return percentile(v, 0.5);
    };
    const std::vector<double>& f = benchFrameMs_;
    const double mean = f.empty() ? 0.0 : std::accumulate(f.begin(), f.end(), 0.0) / double(f.size());
    const double solveMean =
        benchSolveMs_.empty()
            ? 0.0
            : std::accumulate(benchSolveMs_.begin(), benchSolveMs_.end(), 0.0) / double(benchSolveMs_.size());
    int winW = 0, winH = 0;
    glfwGetFramebufferSize(window_, &winW, &winH);
    std::printf(
        "aerial-editor bench: %zu frames (window %dx%d, viewport render %dx%d at resolution scale %.2f, "
        "scrubbing the day, sky re-solved every frame)\n"
        "  frame time [ms]: mean %.2f  median %.2f  p95 %.2f  max %.2f  (%.1f fps)\n"
        "  sky solve [ms]: mean %.2f  median %.2f  max %.2f (sun + moon tables, %zu solves)\n"
        "  viewport passes [ms]: median %.2f (wall time between glFinish calls, %zu frames sampled)\n",
        f.size(), winW, winH, renderWidth_, renderHeight_, resolutionScale_, mean, percentile(f, 0.5),
        percentile(f, 0.95), f.empty() ? 0.0 : *std::max_element(f.begin(), f.end()),
        mean > 0 ? 1000.0 / mean : 0.0, solveMean, percentile(benchSolveMs_, 0.5),
        benchSolveMs_.empty() ? 0.0 : *std::max_element(benchSolveMs_.begin(), benchSolveMs_.end()),
        benchSolveMs_.size(), passMedian([](const renderer::PassTimes& t) { return t.total(); }),
        benchPasses_.size());
    std::printf(
        "    scene %.2f  sky %.2f  global fog %.2f  volumes %.2f  emitters %.2f  transparent %.2f  "
        "particles %.2f\n",
        passMedian([](const renderer::PassTimes& t) { return t.scene; }),
        passMedian([](const renderer::PassTimes& t) { return t.sky; }),
        passMedian([](const renderer::PassTimes& t) { return t.globalFog; }),
        passMedian([](const renderer::PassTimes& t) { return t.volumes; }),
        passMedian([](const renderer::PassTimes& t) { return t.emitters; }),
        passMedian([](const renderer::PassTimes& t) { return t.transparent; }),
        passMedian([](const renderer::PassTimes& t) { return t.particles; }));
    std::fflush(stdout);
}

// --- selection ---------------------------------------------------------------

void Editor::select(Selection s) {
    if (!(s == selection_)) {
        renaming_ = false;
        if (gizmo_.active()) doc_.closeMerge();
    }
    selection_ = s;
}

void Editor::validateSelection() {
    const Preset& p = doc_.preset();
    if (selection_.kind == Selection::Kind::Volume && selection_.index >= int(p.volumes.size()))
        selection_ = p.volumes.empty() ? Selection{Selection::Kind::Fog, -1}
                                       : Selection{Selection::Kind::Volume, int(p.volumes.size()) - 1};
    if (selection_.kind == Selection::Kind::Emitter && selection_.index >= int(p.emitters.size()))
        selection_ = p.emitters.empty() ? Selection{Selection::Kind::Fog, -1}
                                        : Selection{Selection::Kind::Emitter, int(p.emitters.size()) - 1};
    if (selectedParam_ && selectedParam_->object >= 0) {
        const std::size_t count =
            selectedParam_->scope() == ParamScope::Volume ? p.volumes.size() : p.emitters.size();
        if (std::size_t(selectedParam_->object) >= count) selectedParam_.reset();
    }
    if (selectedParam_) {
        const Track* track = trackOf(p, *selectedParam_);
        if (!track || selectedKey_ >= int(track->keys.size())) selectedKey_ = -1;
    } else {
        selectedKey_ = -1;
    }
}

void Editor::addVolumeInFront(FogVolumeShape shape) {
    const glm::dvec3 where = placeForNewObject();
    int index = -1;
    doc_.apply(shape == FogVolumeShape::Box ? "Add box volume" : "Add ellipsoid volume", "",
               [&](Preset& p) { index = addVolume(p, shape, where); });
    select({Selection::Kind::Volume, index});
    setStatus("Added " + doc_.preset().volumes[std::size_t(index)].name);
}

void Editor::addEmitterInFront(EmitterKind kind) {
    glm::dvec3 where = placeForNewObject();
    where.y +=
        kind == EmitterKind::Lightning ? 200.0 : 3.0;  // a lamp above the ground, lightning in the clouds
    int index = -1;
    doc_.apply(kind == EmitterKind::Lightning ? "Add lightning" : "Add emitter", "",
               [&](Preset& p) { index = addEmitter(p, kind, where); });
    select({Selection::Kind::Emitter, index});
    setStatus("Added " + doc_.preset().emitters[std::size_t(index)].name);
}

void Editor::deleteSelection() {
    if (!objectSelected()) return;
    const ParamScope scope =
        selection_.kind == Selection::Kind::Volume ? ParamScope::Volume : ParamScope::Emitter;
    const int index = selection_.index;
    doc_.apply("Delete", "", [&](Preset& p) { deleteObject(p, scope, index); });
    selectedParam_.reset();
    validateSelection();
}

void Editor::duplicateSelection() {
    if (!objectSelected()) return;
    const ParamScope scope =
        selection_.kind == Selection::Kind::Volume ? ParamScope::Volume : ParamScope::Emitter;
    int index = -1;
    const int from = selection_.index;
    doc_.apply("Duplicate", "",
               [&](Preset& p) { index = duplicateObject(p, scope, from, glm::dvec3(5.0, 0.0, 0.0)); });
    if (index >= 0) select({selection_.kind, index});
}

}  // namespace aerial::editor
