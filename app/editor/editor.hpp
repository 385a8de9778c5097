// editor/editor.hpp — the editor application: a GLFW window with an OpenGL
// 4.5 core context, Dear ImGui (fixed layout, no docking) and the renderer.
// Private to aerial-editor; the implementation is split by panel:
//
//   editor.cpp            window, frame loop, layout, menus, shortcuts,
//                         status bar, sky solves, bench, modals
//   editor_viewport.cpp   viewport render + OCIO display, camera, picking,
//                         gizmo, overlays, screenshots
//   editor_inspector.cpp  the inspector, generated from the parameter table
//   editor_outliner.cpp   the outliner and the sky preview
//   editor_timeline.cpp   ruler, scrubbing, play, keys, curve view
//   editor_files.cpp      new/open/save/recent/drop/scene, unsaved-changes
//                         prompts, load-error modal, recovery
//   editor_script.cpp     the automation commands (--script)
//
// Every change to the preset goes through Document::apply (document.hpp),
// so it is undoable and marks the document dirty.
#pragma once

#include "autosave.hpp"
#include "document.hpp"
#include "file_dialog.hpp"
#include "game_export.hpp"
#include "preset_edit.hpp"
#include "script.hpp"
#include "settings.hpp"
#include "viewport/camera_controller.hpp"
#include "viewport/gizmo.hpp"

#include <aerial/evaluate.hpp>
#include <aerial/renderer/display.hpp>
#include <aerial/renderer/renderer.hpp>
#include <aerial/sky.hpp>

#include <chrono>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

struct GLFWwindow;

namespace aerial::editor {

/// The command line of aerial-editor.
struct EditorOptions {
    std::string preset;  ///< "" = the built-in default
    std::string scene;   ///< "" = the built-in scene
    std::string script;  ///< automation script ("" = interactive)
    int benchFrames = 0;
    int width = 1280;
    int height = 720;
    std::string recover;            ///< "" (ask), "yes", "no"
    double autosaveSeconds = 30.0;  ///< unsaved work before the recovery file is written
};

/// Exit codes.
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;  ///< a script failed, a file could not be read
inline constexpr int kExitNoDisplay = 2;
inline constexpr int kExitUsage = 2;  ///< bad command line

/// Runs the editor; returns the process exit code.
int runEditor(const EditorOptions& options);

/// What the outliner has selected.
struct Selection {
    enum class Kind { None, Atmosphere, Lights, Fog, Volume, Emitter };
    Kind kind = Kind::Fog;
    int index = -1;  ///< volume or emitter index
    bool operator==(const Selection&) const = default;
};

/// Synthetic viewport mouse input for scripts (one entry per frame).
struct ScriptedMouse {
    glm::dvec2 position{0.0};  ///< px from the viewport's top-left
    bool down = false;
    bool pressed = false;
    bool released = false;
    bool right = false;  ///< the right button (camera orbit) instead of the left (gizmo, picking)
};

class Editor {
public:
    explicit Editor(const EditorOptions& options);
    ~Editor();
    Editor(const Editor&) = delete;
    Editor& operator=(const Editor&) = delete;

    /// Window, GL, ImGui, renderer. Returns an exit code on failure.
    std::optional<int> initialise();
    /// The frame loop; returns the exit code.
    int run();

private:
    // --- editor.cpp --------------------------------------------------------
    void frame();
    void layout();
    void drawMenuBar();
    void drawStatusBar();
    void handleShortcuts();
    void updateEvaluation();
    void updateSky();
    void drawModals();
    void setStatus(std::string text);
    void showError(std::string title, std::string text);
    void printBench() const;
    void captureWindow(int width, int height);
    double nowSeconds() const;

    // --- editor_viewport.cpp -------------------------------------------------
    void drawViewport();
    void renderViewport();
    void ensureDisplayTexture(int width, int height);
    void viewportInteraction(bool hovered, glm::dvec2 mouse, glm::dvec2 origin);
    bool gizmoTransformOfSelection(GizmoTransform& out) const;
    void applyGizmoTransform(const GizmoTransform& t);
    void frameSelection();
    glm::dvec3 placeForNewObject() const;
    bool screenshot(const std::string& path, std::string& error);
    renderer::CameraFrame viewportCameraFrame() const;
    void rebuildDisplay();

    // --- editor_inspector.cpp ----------------------------------------------
    void drawInspector();
    void drawParam(const ParamRef& ref);
    bool keyButton(const ParamRef& ref);
    void editParam(const ParamRef& ref, const double value[4], bool continuous);

    // --- editor_outliner.cpp -----------------------------------------------
    void drawOutliner();
    void drawSkyPreview();
    void updateSkyPreview();

    // --- editor_timeline.cpp -----------------------------------------------
    void drawTimeline();
    void advancePlayback(double dt);
    void jumpTo(double hours);

    // --- editor_files.cpp --------------------------------------------------
    enum class Pending { None, New, Open, Quit, OpenRecovery };
    void requestNew();
    void requestOpen(const std::string& path);  ///< "" = show the file dialog
    void requestQuit();
    void runPending();
    void askUnsaved(Pending action, std::string path);
    enum class UnsavedChoice { Save, Discard, Cancel };
    /// The unsaved-changes prompt's buttons (and the script's `answer`).
    void resolveUnsaved(UnsavedChoice choice);
    bool openPreset(const std::string& path);    ///< error modal on failure
    bool savePresetTo(const std::string& path);  ///< error modal on failure
    void saveOrSaveAs(bool forceDialog);
    bool loadScene(const std::string& path);
    void handleDrops();
    void drawFileDialogs();
    void offerRecovery();
    void recover(bool accept);
    void startExport(const std::string& directory);

    // --- editor_script.cpp -------------------------------------------------
    void stepScript();
    /// Runs one command; returns false with `error` set on failure. May ask
    /// to wait: scriptWait_ frames, or until the synthetic mouse queue is empty.
    bool runScriptCommand(const ScriptCommand& command, std::string& error);
    void queueGizmoDrag(GizmoMode mode, int axis, glm::dvec2 deltaPx, int steps, bool& ok,
                        std::string& error);

    // --- selection helpers ---------------------------------------------------
    void select(Selection s);
    void validateSelection();
    void addVolumeInFront(FogVolumeShape shape);
    void addEmitterInFront(EmitterKind kind);
    void deleteSelection();
    void duplicateSelection();
    bool objectSelected() const {
        return selection_.kind == Selection::Kind::Volume || selection_.kind == Selection::Kind::Emitter;
    }

    EditorOptions options_;
    GLFWwindow* window_ = nullptr;
    bool imguiReady_ = false;
    bool quit_ = false;
    int exitCode_ = kExitOk;
    std::chrono::steady_clock::time_point startTime_ = std::chrono::steady_clock::now();

    Document doc_;
    std::unique_ptr<Autosave> autosave_;
    RecentFiles recent_;
    Session session_;
    std::string sessionFile_;

    // Evaluation and sky.
    std::unique_ptr<CompiledPreset> compiled_;
    std::uint64_t compiledRevision_ = 0;
    PresetState state_;
    double timeHours_ = 9.0;
    std::unique_ptr<SkySolver> sunSolver_, moonSolver_;
    bool skyValid_ = false;
    AtmosphereParams solvedAir_{};
    glm::dvec3 solvedSun_{0.0}, solvedMoon_{0.0};
    double skySolveMs_ = 0.0;
    std::uint64_t skyGeneration_ = 0;

    // Playback.
    bool playing_ = false;
    double playSpeed_ = 1.0;  ///< game hours per real second
    bool loop_ = true;

    // Renderer and viewport.
    std::unique_ptr<renderer::Renderer> renderer_;
    std::unique_ptr<renderer::DisplayTransform> display_;
    std::string displayName_, viewName_;
    double exposureEv_ = 0.0;
    double resolutionScale_ = 0.5;
    bool showHelpers_ = true;
    bool showGrid_ = false;
    renderer::RenderPasses passes_;
    bool showStars_ = true;  ///< View > Stars (the sky pass's stars at night)
    unsigned displayTexture_ = 0;
    int displayWidth_ = 0, displayHeight_ = 0;
    mutable int renderWidth_ = 0, renderHeight_ = 0;
    glm::dvec2 viewportOrigin_{0.0}, viewportSize_{640.0, 360.0};
    bool viewportVisible_ = false;
    std::string renderLogError_;
    std::string lastRenderSignature_;  ///< what the last viewport frame was rendered from
    CameraController camera_;
    Gizmo gizmo_;
    GizmoMode gizmoMode_ = GizmoMode::Translate;
    GizmoSpace gizmoSpace_ = GizmoSpace::World;
    std::string gizmoMergeKey_;
    std::deque<ScriptedMouse> scriptedMouse_;
    bool scriptedMouseActive_ = false;
    glm::dvec2 lastScriptedMouse_{0.0};

    // Panels.
    Selection selection_;
    std::optional<ParamRef> selectedParam_;
    int selectedKey_ = -1;
    bool draggingKey_ = false;
    bool timelineHovered_ = false;
    KeyClipboard keyClipboard_;
    bool renaming_ = false;
    std::string renameBuffer_;
    unsigned skyPreviewTexture_ = 0;
    std::uint64_t skyPreviewGeneration_ = ~0ull;
    std::string skyPreviewSettings_;

    // Status and timing.
    std::string status_;
    double frameMs_ = 0.0;  ///< frame to frame [ms] (--bench)
    double workMs_ = 0.0;   ///< the last frame's work without waiting for events [ms] (status bar)
    double renderMs_ = 0.0;
    std::chrono::steady_clock::time_point lastFrame_ = std::chrono::steady_clock::now();
    std::vector<double> benchFrameMs_;
    std::vector<double> benchSolveMs_;
    std::vector<renderer::PassTimes>
        benchPasses_;  ///< viewport passes, timed with glFinish (every 10th frame)
    int frameIndex_ = 0;
    int idleFrames_ = 0;  ///< frames without input (the loop then waits for events)

    // Modals and dialogs.
    std::string errorTitle_, errorText_;
    bool openErrorModal_ = false;
    Pending pending_ = Pending::None;
    std::string pendingPath_;
    bool openUnsavedModal_ = false;
    bool unsavedPromptOpen_ = false;
    bool continueAfterSave_ = false;  ///< a Save As started from the unsaved prompt
    std::optional<RecoveryCandidate> recovery_;
    bool openRecoveryModal_ = false;
    FileDialog fileDialog_;
    enum class DialogPurpose { None, Open, SaveAs, Scene, Screenshot, Export };
    DialogPurpose dialogPurpose_ = DialogPurpose::None;
    std::vector<std::string> drops_;
    GameExport export_;
    std::string scenePath_;

    // Script.
    std::string windowShotPath_;  ///< window_screenshot: captured after the next frame is drawn
    std::vector<ScriptCommand> script_;
    std::size_t scriptIndex_ = 0;
    int scriptWait_ = 0;
    bool scriptWaitsForMouse_ = false;
    std::deque<double> scriptTimes_;  ///< scrub: one time per frame
    bool scriptWaitsForAutosave_ = false;
    int scriptAutosaveWrites_ = 0;

    friend void dropCallback(GLFWwindow*, int, const char**);
};

}  // namespace aerial::editor
