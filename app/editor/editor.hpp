// editor/editor.hpp — the editor application: a GLFW window with an OpenGL
// 4.5 core context, Dear ImGui (fixed layout, no docking) and the renderer.
// Private to aerial-editor. Editor composes the parts of editor_parts.hpp
// (document, edit state, playback, sky service, viewport, dialogs, script
// runner, frame stats); every user action and script command is declared
// once in its one action table (actions.hpp), from which the menus, the
// shortcuts and the script language come. The implementation is split by
// panel:
//
//   editor.cpp            window, frame loop, layout, status bar, sky
//                         solves, bench, selection
//   editor_actions.cpp    the menus' and keys' actions, the menu bar drawn
//                         from the table and the keyboard shortcuts
//   editor_viewport.cpp   viewport render + OCIO display, camera, picking,
//                         gizmo, overlays, screenshots
//   editor_inspector.cpp  the inspector, generated from the parameter table
//   editor_outliner.cpp   the outliner and the sky preview
//   editor_timeline.cpp   ruler, zoom and pan, scrubbing, play, keys
//   editor_curves.cpp     the curve view (curves overlaid, key drags, box
//                         selection, tangents)
//   editor_weather.cpp    the Weather panel: states, overrides, preview
//                         (these five are free functions, panels.hpp, that
//                         take the parts they edit)
//   editor_files.cpp      new/open/save/recent/drop/scene, unsaved-changes
//                         prompt, load-error modal, recovery
//   editor_script.cpp     the automation (--script): runner, the actions
//                         only scripts run for files, prompts and checks
//   editor_script_curves.cpp  script commands of the timeline's curve view
//   editor_script_edit.cpp  script commands that edit objects, parameters,
//                         keys, the layout and the time
//   editor_script_view.cpp  script commands of the viewport (screenshots,
//                         gizmo drags, clicks, orbits, display)
//   editor_script_weather.cpp  script commands of the Weather panel and
//                         the viewport's weather preview
//
// Every change to the preset goes through Document::apply (document.hpp),
// so it is undoable and marks the document dirty.
#pragma once

#include "actions.hpp"
#include "editor_parts.hpp"
#include "game_export.hpp"
#include "panels.hpp"
#include "settings.hpp"

#include <chrono>
#include <memory>
#include <optional>
#include <string>

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

    /// Every action: menus, shortcuts and script commands (for tests).
    const ActionTable& actions() const { return actions_; }

private:
    // --- editor.cpp --------------------------------------------------------
    void frame();
    void layout();
    void drawStatusBar();
    void updateEvaluation();
    void updateSky();
    void setStatus(std::string text);
    /// The status after a finished export: the bake's summary, which names the folder.
    std::string exportedStatus() const;
    /// The current time as HH:MM.
    std::string clockText() const;
    void showError(std::string title, std::string text);
    void printBench() const;
    void captureWindow(int width, int height);
    double nowSeconds() const;
    // Selection and objects.
    void select(Selection s);
    void addVolumeInFront(FogVolumeShape shape);
    void addEmitterInFront(EmitterKind kind);
    /// A cloud volume in the cloud layer above the point the camera looks at.
    void addCloudVolumeAboveView(FogVolumeShape shape);
    void deleteSelection();
    void duplicateSelection();

    // --- editor_meshes.cpp ---------------------------------------------------
    /// Opens the file dialog for a glTF mesh: a new mesh volume
    /// (volumeIndex -1) or the mesh of volume volumeIndex.
    void requestMeshFile(int volumeIndex);
    /// Adds a mesh volume from a glTF file on the surface in front of the
    /// camera; a bad mesh is said in a modal and changes nothing.
    bool addMeshVolumeFromFile(const std::string& file);
    /// Gives volume volumeIndex the mesh of `file` (shape mesh); one undo step.
    bool setVolumeMesh(int volumeIndex, const std::string& file);
    /// Before saving to `newPath`: relative mesh paths rewritten (one undo
    /// step) so that they still name the same files from the new folder.
    void rebaseMeshesForSave(const std::string& newPath);

    // --- editor_actions.cpp --------------------------------------------------
    void declareActions();
    void drawMenuBar();
    void handleShortcuts();

    // --- editor_viewport.cpp -------------------------------------------------
    void drawViewport();
    void renderViewport();
    /// Meters the frame just rendered for the preset's exposure.
    void meterViewport();
    /// The rendered frame through the display transform at the viewport's exposure.
    void showViewport(int width, int height);
    void ensureDisplayTexture(int width, int height);
    void viewportInteraction(bool hovered, glm::dvec2 mouse, glm::dvec2 origin);
    bool gizmoTransformOfSelection(GizmoTransform& out) const;
    /// The selected fog or cloud volume's shape at the current time (what
    /// picking, outlines and framing use); false for anything else.
    bool selectedVolumeShape(FogVolume& out) const;
    void applyGizmoTransform(const GizmoTransform& t);
    void frameSelection();
    /// The viewport camera at the preset's view (aerial/preset.hpp,
    /// PresetView); nothing when it has none.
    void goToPresetView();
    /// The preset's view becomes the viewport camera (one undo step).
    void setPresetViewFromCamera();
    glm::dvec3 placeForNewObject() const;
    /// Uploads a scene to the renderer and keeps its triangles for placing
    /// objects on it (view_.sceneHits).
    void setScene(const renderer::SceneDesc& scene);
    /// Edit > Drop to ground: the selected volume's bottom (or an emitter,
    /// 0.5 m above) onto the scene's surface under it; false (with the status
    /// saying why) when nothing is selected or nothing is below.
    bool dropSelectionToGround();
    bool screenshot(const std::string& path, std::string& error);
    renderer::CameraFrame viewportCameraFrame() const;
    void rebuildDisplay();

    // --- editor_files.cpp --------------------------------------------------
    void requestNew();
    void requestOpen(const std::string& path);  ///< "" = show the file dialog
    void requestQuit();
    void runPending();
    void askUnsaved(Pending action, std::string path);
    void resolveUnsaved(UnsavedChoice choice);
    /// Shows why a preset cannot be opened (the loader's errors; nothing changes).
    /// Help > Keys and workflow (F1).
    void drawHelpSheet();
    /// Escape closes open menus and popups (not modal dialogs).
    void closeMenusOnEscape();
    void reportLoadFailure(const std::string& path, const PresetLoadResult& result);
    bool openPreset(const std::string& path);    ///< error modal on failure
    bool savePresetTo(const std::string& path);  ///< error modal on failure
    void saveOrSaveAs(bool forceDialog);
    bool loadScene(const std::string& path);
    void handleDrops();
    void drawFileDialogs();
    void drawModals();
    void recover(bool accept);
    void startExport(const std::string& directory);

    // --- editor_script.cpp, editor_script_edit.cpp, editor_script_curves.cpp,
    //     editor_script_view.cpp, editor_script_weather.cpp
    void declareScriptCommands();
    void declareEditScriptCommands();
    void declareCurveScriptCommands();
    void declareViewScriptCommands();
    void declareWeatherScriptCommands();
    void stepScript();
    /// Runs one command; returns false with `error` set on failure. May ask
    /// to wait: ScriptRunner::waitFrames frames, or until the synthetic
    /// mouse queue is empty.
    bool runScriptCommand(const ScriptCommand& command, std::string& error);
    bool queueGizmoDrag(GizmoMode mode, int axis, glm::dvec2 deltaPx, int steps, std::string& error);

    EditorOptions options_;
    GLFWwindow* window_ = nullptr;
    bool imguiReady_ = false;
    bool quit_ = false;
    int exitCode_ = kExitOk;
    std::chrono::steady_clock::time_point startTime_ = std::chrono::steady_clock::now();

    // The parts (editor_parts.hpp).
    Document doc_;
    EditState edit_;
    Playback playback_;
    SkyService sky_;
    ViewportState view_;
    Dialogs dialogs_;
    ScriptRunner runner_;
    FrameStats frames_;
    SkyPreview skyPreview_;

    // Files and jobs.
    std::unique_ptr<Autosave> autosave_;
    RecentFiles recent_;
    Session session_;
    std::string sessionFile_;
    GameExport export_;
    std::string status_;
    std::string statusShown_;                              ///< status_ as last drawn
    std::chrono::steady_clock::time_point statusSince_{};  ///< when it last changed

    // Every user action and script command.
    ActionTable actions_;

    friend void dropCallback(GLFWwindow*, int, const char**);
};

}  // namespace aerial::editor
