// editor/editor.cpp — window, frame loop, fixed layout, status bar, sky
// solves, --bench, selection and objects. See editor.hpp for the map.
#include "editor.hpp"

#include <epoxy/gl.h>  // epoxy before any other GL header

#include <GLFW/glfw3.h>  // GLFW_INCLUDE_NONE is defined for this target
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>
#include <imgui_internal.h>  // the popup stack (closeMenusOnEscape)

#include <aerial/clock.hpp>
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

}  // namespace

void dropCallback(GLFWwindow* window, int count, const char** paths) {
    auto* editor = static_cast<Editor*>(glfwGetWindowUserPointer(window));
    if (!editor) return;
    const bool shift = glfwGetKey(window, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS ||
                       glfwGetKey(window, GLFW_KEY_RIGHT_SHIFT) == GLFW_PRESS;
    for (int i = 0; i < count; ++i)
        if (paths[i]) editor->dialogs_.drops.push_back({paths[i], shift});
}

int runEditor(const EditorOptions& options) {
    Editor editor(options);
    if (std::optional<int> failed = editor.initialise()) return *failed;
    return editor.run();
}

Editor::Editor(const EditorOptions& options)
    : options_(options), recent_((fs::path(configDirectory()) / "recent.json").string()) {
    sessionFile_ = (fs::path(configDirectory()) / "session.json").string();
    declareActions();
    declareScriptCommands();
}

Editor::~Editor() {
    export_.cancel();
    if (window_) {
        glfwMakeContextCurrent(window_);
        if (view_.displayTexture) glDeleteTextures(1, &view_.displayTexture);
        if (!view_.retiredTextures.empty())
            glDeleteTextures(GLsizei(view_.retiredTextures.size()), view_.retiredTextures.data());
        if (skyPreview_.texture) glDeleteTextures(1, &skyPreview_.texture);
        view_.display.reset();
        view_.renderer.reset();
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
    desc.logger = {rendererLog, &view_.renderLogError};
    desc.debugOutput = false;
    view_.renderer = std::make_unique<renderer::Renderer>(desc);
    if (!view_.renderer->valid()) {
        std::fprintf(stderr, "aerial-editor: cannot create the renderer: %s\n",
                     view_.renderer->error().c_str());
        return kExitFailure;
    }
    sky_.sunSolver = std::make_unique<SpectralSkySolver>();
    sky_.moonSolver = std::make_unique<SpectralSkySolver>();

    if (options_.benchFrames == 0) session_.load(sessionFile_);  // --bench starts from the defaults
    recent_.load();
    if (!session_.cameraJson.empty()) {
        CameraState cameraState = view_.camera.state();
        if (cameraStateFromJson(session_.cameraJson, cameraState)) view_.camera.setState(cameraState);
    } else {
        // Above the valley floor looking north up the valley (as `aerial render`).
        CameraState s;
        s.target = {0.0, renderer::builtinTerrainHeight(0.0, -40.0) + 6.0, -40.0};
        s.distance = 70.0;
        s.yaw = 0.0;
        s.pitch = -0.18;
        view_.camera.setState(s);
    }
    view_.displayName = session_.display;
    view_.viewName = session_.view;
    view_.exposureEv = session_.exposureEv;
    view_.resolutionScale = session_.resolutionScale;
    view_.showOutliner = session_.showOutliner;
    view_.showInspector = session_.showInspector;
    view_.showTimeline = session_.showTimeline;
    view_.maximized = session_.maximized;
    view_.gameView = session_.gameView;
    view_.outlinerCollapsed = session_.outlinerCollapsed;
    // The first start (no session yet) opens the getting-started sheet;
    // scripted runs (tests, automation) never do.
    if (!session_.helpSeen && options_.script.empty() && options_.benchFrames == 0) {
        dialogs_.showHelp = true;
        session_.helpSeen = true;
    }
    view_.inspectorCollapsed = session_.inspectorCollapsed;
    view_.timelineCollapsed = session_.timelineCollapsed;
    view_.outlinerWidth = float(session_.outlinerWidth);
    view_.inspectorWidth = float(session_.inspectorWidth);
    view_.timelineHeight = float(session_.timelineHeight);
    for (const std::string& key : session_.curves)
        if (const std::optional<TrackTarget> target = curveTargetOf(key))
            edit_.curves.setShown(*target, true);
    playback_.timeHours = options_.script.empty() ? session_.timeHours : 9.0;  // scripts start at 09:00
    if (options_.script.empty())  // scripts snap to the quarter hour unless they say (curve_snap)
        for (int minutes : kSnapStepsMinutes)
            if (session_.snapMinutes == minutes) edit_.curves.snapHours = minutes / 60.0;
    rebuildDisplay();

    if (!options_.scene.empty()) {
        if (!loadScene(options_.scene)) {
            std::fprintf(stderr, "aerial-editor: %s\n", dialogs_.errorText.c_str());
            if (automated) return kExitFailure;
        }
    } else {
        setScene(renderer::makeBuiltinScene());
    }
    if (!options_.preset.empty()) {
        if (!openPreset(options_.preset)) {
            std::fprintf(stderr, "aerial-editor: cannot open %s:\n%s\n", options_.preset.c_str(),
                         dialogs_.errorText.c_str());
            if (automated) return kExitFailure;
        }
    }

    autosave_ = std::make_unique<Autosave>(stateDirectory(), options_.autosaveSeconds);
    dialogs_.recovery = autosave_->findRecovery();
    if (dialogs_.recovery) {
        if (options_.recover == "yes")
            recover(true);
        else if (options_.recover == "no")
            recover(false);
        else
            dialogs_.openRecoveryModal = true;
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
        runner_.commands = std::move(parsed.commands);
        std::printf("aerial-editor pid %d\n", int(::getpid()));  // for tests that kill -9 it
        std::fflush(stdout);
        if (runner_.commands.empty()) runner_.commands.push_back({0, {"quit"}});
    }
    glfwSetWindowTitle(window_, doc_.title().c_str());
    frames_.lastFrame = std::chrono::steady_clock::now();
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
        if (options_.benchFrames > 0 && frames_.frameIndex >= options_.benchFrames + 3) quit_ = true;
    }
    export_.wait();
    if (options_.benchFrames > 0) printBench();
    if (options_.benchFrames == 0) {
        session_.cameraJson = cameraStateToJson(view_.camera.state());
        session_.display = view_.displayName;
        session_.view = view_.viewName;
        session_.exposureEv = view_.exposureEv;
        session_.resolutionScale = view_.resolutionScale;
        session_.timeHours = playback_.timeHours;
        session_.showOutliner = view_.showOutliner;
        session_.showInspector = view_.showInspector;
        session_.showTimeline = view_.showTimeline;
        session_.maximized = view_.maximized;
        session_.gameView = view_.gameView;
        session_.outlinerCollapsed = view_.outlinerCollapsed;
        session_.inspectorCollapsed = view_.inspectorCollapsed;
        session_.timelineCollapsed = view_.timelineCollapsed;
        session_.outlinerWidth = view_.outlinerWidth;
        session_.inspectorWidth = view_.inspectorWidth;
        session_.timelineHeight = view_.timelineHeight;
        session_.curves.clear();
        for (const TrackTarget& target : edit_.curves.shown) session_.curves.push_back(curveKey(target));
        if (options_.script.empty()) session_.snapMinutes = std::round(edit_.curves.snapHours * 60.0);
        session_.save(sessionFile_);
    }
    if (autosave_) autosave_->finish();
    return exitCode_;
}

void Editor::frame() {
    const auto now = std::chrono::steady_clock::now();
    const double dt = std::chrono::duration<double>(now - frames_.lastFrame).count();
    frames_.lastFrame = now;
    frames_.frameMs = dt * 1000.0;
    if (options_.benchFrames > 0 && frames_.frameIndex >= 3 &&
        int(frames_.benchFrameMs.size()) < options_.benchFrames)
        frames_.benchFrameMs.push_back(frames_.frameMs);  // the first frames compile shaders and fill caches

    // An idle editor sleeps until the next event (or 0.25 s) instead of
    // redrawing: on a software rasteriser every frame costs a core.
    const bool automated = !options_.script.empty() || options_.benchFrames > 0;
    if (!automated && frames_.idleFrames > 3 && !playback_.playing && !export_.running() &&
        !view_.gizmo.active() && !edit_.weather.preview.playing())
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
    if (!runner_.guiMouse.empty()) {  // a script's drag on the timeline, in place of the real mouse
        const ScriptRunner::GuiMouse m = runner_.guiMouse.front();
        runner_.guiMouse.pop_front();
        ImGuiIO& io = ImGui::GetIO();
        io.MousePos = ImVec2(float(m.position.x), float(m.position.y));
        io.MouseDown[0] = m.down;
        io.MouseDown[2] = m.middle;
        io.MouseWheel = m.wheel;
        io.KeyCtrl = m.ctrl;
        io.KeyShift = m.shift;
    }
    ImGui::NewFrame();
    closeMenusOnEscape();
    // The display textures replaced last frame: no draw list refers to them now.
    if (!view_.retiredTextures.empty()) {
        glDeleteTextures(GLsizei(view_.retiredTextures.size()), view_.retiredTextures.data());
        view_.retiredTextures.clear();
    }

    {
        const ImGuiIO& io = ImGui::GetIO();
        bool active = io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f || io.MouseWheel != 0.0f ||
                      io.WantTextInput || !dialogs_.drops.empty() || ImGui::IsAnyItemActive();
        for (bool down : io.MouseDown) active = active || down;
        for (bool down : io.KeysDown) active = active || down;
        frames_.idleFrames = active ? 0 : frames_.idleFrames + 1;
    }
    if (!runner_.commands.empty()) stepScript();
    if (options_.benchFrames > 0 && frames_.frameIndex >= 3)
        playback_.timeHours = wrapHours(playback_.timeHours + 24.0 / 240.0);  // scrub
    playback_.advance(dt);
    updateEvaluation();
    updateSky();

    layout();
    drawHelpSheet();
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
    if (!runner_.windowShotPath.empty()) captureWindow(width, height);
    glfwSwapBuffers(window_);
    frames_.workMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - workStart).count();

    if (autosave_ &&
        autosave_->update(nowSeconds(), doc_.dirty(), doc_.revision(), doc_.preset(), doc_.path()))
        setStatus("Autosaved unsaved work to " + autosave_->recoveryFile());
    ++frames_.frameIndex;
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
    if (renderer::writePng(image, runner_.windowShotPath, 1.0, error))
        std::printf("window_screenshot %s %dx%d\n", runner_.windowShotPath.c_str(), width, height);
    else
        std::fprintf(stderr, "aerial-editor: %s\n", error.c_str());
    std::fflush(stdout);
    runner_.windowShotPath.clear();
}

void Editor::updateEvaluation() {
    // While a field is dragged its unkeyed change is drawn without compiling the preset each frame.
    const bool dragging = imguiReady_ && ImGui::IsAnyItemActive();
    // The Weather panel's preview (view state) on the editor's clock.
    const glm::dvec3 eye = view_.camera.eye();
    edit_.weather.preview.update(doc_.preset(), nowSeconds(), &eye);  // the regions at the camera
    if (sky_.evaluate(doc_, edit_.pending, playback_.timeHours, dragging, edit_.weather.preview.mix()))
        edit_.validate(doc_.preset());
}

void Editor::updateSky() {
    if (!sky_.solve()) return;
    if (options_.benchFrames > 0 && frames_.frameIndex >= 3) frames_.benchSolveMs.push_back(sky_.solveMs);
    view_.renderer->setSky(sky_.sunSolver->table(), sky_.moonSolver->table());
}

void Editor::layout() {
    const ImGuiIO& io = ImGui::GetIO();
    const float w = io.DisplaySize.x, h = io.DisplaySize.y;
    drawMenuBar();
    const float menuH = ImGui::GetFrameHeight();
    const float statusH = ImGui::GetFrameHeight() + 4.0f;
    // Panel sizes: the splitters' (remembered in the session), else a share
    // of the window; hidden panels (View, or Maximize viewport) take none.
    const bool outliner = view_.showOutliner && !view_.maximized;
    const bool inspector = view_.showInspector && !view_.maximized;
    const bool timeline = view_.showTimeline && !view_.maximized;
    auto size = [](float chosen, float share, float lo, float hi) {
        return std::clamp(chosen > 0.0f ? chosen : share, lo, std::max(lo, hi));
    };
    // A collapsed panel keeps only its title bar (its arrow, for a side panel).
    const float titleH = ImGui::GetFrameHeight();
    const float collapsedW = titleH + 8.0f;
    const float timelineH =
        !timeline ? 0.0f
        : view_.timelineCollapsed
            ? titleH
            : size(view_.timelineHeight, std::clamp(h * 0.28f, 110.0f, 280.0f), 60.0f, h * 0.6f);
    const float leftW = !outliner ? 0.0f
                        : view_.outlinerCollapsed
                            ? collapsedW
                            : size(view_.outlinerWidth, std::clamp(w * 0.17f, 120.0f, 280.0f), 100.0f, w * 0.35f);
    const float rightW =
        !inspector ? 0.0f
        : view_.inspectorCollapsed
            ? collapsedW
            : size(view_.inspectorWidth, std::clamp(w * 0.28f, 180.0f, 440.0f), 160.0f, w * 0.45f);
    const float middleH = std::max(60.0f, h - menuH - statusH - timelineH);
    const ImGuiWindowFlags fixed = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                   ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
                                   ImGuiWindowFlags_NoBringToFrontOnFocus;
    // The panels may collapse (their title bar's arrow); the state is ours
    // (remembered in the session), handed to ImGui every frame.
    const ImGuiWindowFlags panel = fixed & ~ImGuiWindowFlags_NoCollapse;
    // A collapsed side panel is only its arrow wide: its title would show a
    // clipped first letter beside the viewport's ("OViewport"), so it shows
    // none (the same window id, "###Outliner") and the tooltip names it.
    auto beginPanel = [&](const char* title, bool& collapsed) {
        ImGui::SetNextWindowCollapsed(collapsed, ImGuiCond_Always);
        const std::string label = (collapsed ? "" : std::string(title)) + "###" + title;
        const bool open = ImGui::Begin(label.c_str(), nullptr, panel);
        collapsed = ImGui::IsWindowCollapsed();
        if (ImGui::IsItemHovered() || (collapsed && ImGui::IsWindowHovered()))
            ImGui::SetTooltip("%s: %s", title,
                              collapsed ? "expand (click the arrow or double-click the title)"
                                        : "collapse in place (click the arrow or double-click the title)");
        return open && !collapsed;
    };

    if (outliner) {
        ImGui::SetNextWindowPos(ImVec2(0, menuH));
        ImGui::SetNextWindowSize(ImVec2(leftW, middleH));
        if (beginPanel("Outliner", view_.outlinerCollapsed)) {
            drawOutliner(doc_, edit_, actions_, [this](Selection s) { select(s); });
            drawSkyPreview(skyPreview_, sky_, view_, frames_.frameIndex);
        }
        ImGui::End();
    }

    if (inspector) {
        ImGui::SetNextWindowPos(ImVec2(w - rightW, menuH));
        ImGui::SetNextWindowSize(ImVec2(rightW, middleH));
        if (beginPanel("Inspector", view_.inspectorCollapsed))
            drawInspector(doc_, edit_, playback_.timeHours, sky_.state, sky_.light, actions_, status_);
        ImGui::End();
    }

    view_.windowWidth = std::max(10.0f, w - leftW - rightW);
    view_.windowHeight = middleH;
    ImGui::SetNextWindowPos(ImVec2(leftW, menuH));
    ImGui::SetNextWindowSize(ImVec2(view_.windowWidth, middleH));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
    if (ImGui::Begin("Viewport", nullptr,
                     fixed | ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse))
        drawViewport();
    else
        view_.visible = false;
    ImGui::End();
    ImGui::PopStyleVar();

    if (timeline) {
        ImGui::SetNextWindowPos(ImVec2(0, menuH + middleH));
        ImGui::SetNextWindowSize(ImVec2(w, timelineH));
        ImGui::SetNextWindowCollapsed(view_.timelineCollapsed, ImGuiCond_Always);
        const bool timelineOpen = ImGui::Begin(
            "Timeline", nullptr, panel | ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);
        view_.timelineCollapsed = ImGui::IsWindowCollapsed();
        if (timelineOpen && !view_.timelineCollapsed)
            drawTimeline(doc_, edit_, playback_, actions_, status_);
        ImGui::End();
    }

    // The Weather panel floats over the viewport's right side (View > Weather).
    if (edit_.weather.shown) {
        const float weatherW = std::min(380.0f, w - 20.0f);
        ImGui::SetNextWindowPos(ImVec2(std::max(0.0f, w - rightW - weatherW - 10.0f), menuH + 30.0f),
                                ImGuiCond_Appearing);
        ImGui::SetNextWindowSize(ImVec2(weatherW, std::max(160.0f, std::min(480.0f, middleH - 40.0f))),
                                 ImGuiCond_Appearing);
        if (ImGui::Begin("Weather", &edit_.weather.shown, ImGuiWindowFlags_NoSavedSettings))
            drawWeatherPanel(doc_, edit_, playback_.timeHours, nowSeconds(), view_.camera, status_);
        ImGui::End();
    }

    // Splitters: drag the borders between the panels (remembered).
    auto splitter = [&](const char* id, ImVec2 pos, ImVec2 extent, bool vertical, float& value, float current,
                        float sign) {
        ImGui::SetNextWindowPos(pos);
        ImGui::SetNextWindowSize(extent);
        ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
        ImGui::Begin(id, nullptr,
                     fixed | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoBackground |
                         ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoFocusOnAppearing);
        ImGui::InvisibleButton("##drag", extent);
        if (ImGui::IsItemHovered() || ImGui::IsItemActive())
            ImGui::SetMouseCursor(vertical ? ImGuiMouseCursor_ResizeEW : ImGuiMouseCursor_ResizeNS);
        if (ImGui::IsItemActive()) {
            const float delta = vertical ? ImGui::GetIO().MouseDelta.x : ImGui::GetIO().MouseDelta.y;
            value = current + sign * delta;
        }
        ImGui::End();
        ImGui::PopStyleVar();
    };
    constexpr float kGrip = 6.0f;
    if (outliner && !view_.outlinerCollapsed)
        splitter("##split_left", ImVec2(leftW - kGrip * 0.5f, menuH), ImVec2(kGrip, middleH), true,
                 view_.outlinerWidth, leftW, 1.0f);
    if (inspector && !view_.inspectorCollapsed)
        splitter("##split_right", ImVec2(w - rightW - kGrip * 0.5f, menuH), ImVec2(kGrip, middleH), true,
                 view_.inspectorWidth, rightW, -1.0f);
    if (timeline && !view_.timelineCollapsed)
        splitter("##split_bottom", ImVec2(0, menuH + middleH - kGrip * 0.5f), ImVec2(w, kGrip), false,
                 view_.timelineHeight, timelineH, -1.0f);

    ImGui::SetNextWindowPos(ImVec2(0, h - statusH));
    ImGui::SetNextWindowSize(ImVec2(w, statusH));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(6, 2));
    if (ImGui::Begin("##status", nullptr, fixed | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar))
        drawStatusBar();
    ImGui::End();
    ImGui::PopStyleVar();
}

void Editor::closeMenusOnEscape() {
    // Escape closes open menus and popups (ImGui leaves that to keyboard
    // navigation, which the editor keeps off); modal dialogs handle it themselves.
    ImGuiContext& g = *GImGui;
    if (g.OpenPopupStack.Size == 0 || !ImGui::IsKeyPressed(GLFW_KEY_ESCAPE, false)) return;
    int keep = 0;
    while (keep < g.OpenPopupStack.Size && g.OpenPopupStack[keep].Window &&
           (g.OpenPopupStack[keep].Window->Flags & ImGuiWindowFlags_Modal))
        ++keep;
    if (keep < g.OpenPopupStack.Size) ImGui::ClosePopupToLevel(keep, true);
}

void Editor::setStatus(std::string text) { status_ = std::move(text); }

std::string Editor::clockText() const {
    return aerial::formatClock(playback_.timeHours, ClockResolution::Minutes);
}

void Editor::showError(std::string title, std::string text) {
    dialogs_.errorTitle = std::move(title);
    dialogs_.errorText = std::move(text);
    dialogs_.openErrorModal = true;
    if (!options_.script.empty())
        std::fprintf(stderr, "aerial-editor: %s:\n%s\n", dialogs_.errorTitle.c_str(),
                     dialogs_.errorText.c_str());
}

// --- selection ---------------------------------------------------------------

void Editor::select(Selection s) {
    if (!(s == edit_.selection)) {
        edit_.renaming = false;
        if (view_.gizmo.active()) doc_.closeMerge();
    }
    edit_.selection = s;
}

void Editor::addVolumeInFront(FogVolumeShape shape) {
    glm::dvec3 where = placeForNewObject();
    where.y += FogVolume{}.halfExtents.y;  // resting on the surface
    int index = -1;
    doc_.apply(shape == FogVolumeShape::Box ? "Add box volume" : "Add ellipsoid volume", "",
               [&](Preset& p) { index = addVolume(p, shape, where); });
    select({Selection::Kind::Volume, index});
    setStatus("Added " + doc_.preset().volumes[std::size_t(index)].name);
}

void Editor::addCloudVolumeAboveView(FogVolumeShape shape) {
    // In the layer as it is now, above the orbit pivot (the point the camera looks at).
    const CloudVolume placed = newCloudVolumeAt(sky_.state.environment.clouds, view_.camera.state().target);
    int index = -1;
    doc_.apply(shape == FogVolumeShape::Box ? "Add cloud box" : "Add cloud ellipsoid", "",
               [&](Preset& p) { index = addCloudVolume(p, shape, placed); });
    select({Selection::Kind::CloudVolume, index});
    setStatus("Added " + doc_.preset().cloudVolumes[std::size_t(index)].name);
}

void Editor::addEmitterInFront(EmitterKind kind) {
    glm::dvec3 where = placeForNewObject();
    where.y +=
        kind == EmitterKind::Lightning ? 200.0 : 3.0;  // a lamp above the surface, lightning in the clouds
    int index = -1;
    doc_.apply(kind == EmitterKind::Lightning ? "Add lightning" : "Add emitter", "",
               [&](Preset& p) { index = addEmitter(p, kind, where); });
    select({Selection::Kind::Emitter, index});
    setStatus("Added " + doc_.preset().emitters[std::size_t(index)].name);
}

void Editor::deleteSelection() {
    if (!edit_.objectSelected()) return;
    const ParamScope scope = edit_.selection.scope();
    const int index = edit_.selection.index;
    doc_.apply("Delete", "", [&](Preset& p) { deleteObject(p, scope, index); });
    edit_.selectedParam.reset();
    edit_.validate(doc_.preset());
}

void Editor::duplicateSelection() {
    if (!edit_.objectSelected()) return;
    const ParamScope scope = edit_.selection.scope();
    int index = -1;
    const int from = edit_.selection.index;
    // Beside the original: 5 m for fog volumes and emitters, a kilometre for cloud volumes.
    const glm::dvec3 offset(scope == ParamScope::CloudVolume ? 1000.0 : 5.0, 0.0, 0.0);
    doc_.apply("Duplicate", "", [&](Preset& p) { index = duplicateObject(p, scope, from, offset); });
    if (index >= 0) select({edit_.selection.kind, index});
}

}  // namespace aerial::editor
