// editor/editor_parts.hpp — the parts the editor is made of. Each part owns
// one kind of state; Editor (editor.hpp) composes them and panels take the
// parts they need. Plain data with a few calls (as Dear ImGui likes it: the
// application owns its data and widgets edit it in place).
//
//   Document (document.hpp)  the preset being edited, its file, dirty, undo
//   EditState                what is selected (object, parameter, key), the
//                            key clipboard, the outliner's inline rename,
//                            the curve view's state, the Weather panel's
//                            state and the viewport's weather preview
//   Playback                 the time of day; play, loop, speed
//   SkyService               the preset evaluated at that time and the sun's
//                            and moon's sky tables solved for it
//   ViewportState            renderer, OCIO display, render target, camera,
//                            gizmo and picking state, view options
//   Dialogs                  file dialog, unsaved-changes prompt, error and
//                            recovery modals, dropped files
//   ScriptRunner             the --script commands and what they wait for
//   FrameStats               frame timing, --bench samples, idle detection
#pragma once

#include "autosave.hpp"
#include "curve_view.hpp"
#include "document.hpp"
#include "file_dialog.hpp"
#include "game_export.hpp"
#include "pending_edits.hpp"
#include "preset_edit.hpp"
#include "script.hpp"
#include "view_exposure.hpp"
#include "view_filter.hpp"
#include "viewport/camera_controller.hpp"
#include "viewport/gizmo.hpp"
#include "viewport/scene_hits.hpp"
#include "weather_preview.hpp"

#include <aerial/evaluate.hpp>
#include <aerial/photometry.hpp>
#include <aerial/renderer/display.hpp>
#include <aerial/renderer/renderer.hpp>
#include <aerial/sky.hpp>
#include <aerial/sky_spectral.hpp>

#include <chrono>
#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace aerial::editor {

/// What the outliner has selected.
struct Selection {
    enum class Kind { None, Atmosphere, Lights, Fog, Volume, Emitter, Exposure, Clouds, CloudVolume };
    Kind kind = Kind::Fog;
    int index = -1;  ///< volume, emitter or cloud volume index
    bool operator==(const Selection&) const = default;

    /// The parameter scope of an object kind (Volume, Emitter, CloudVolume);
    /// Global for the others.
    static ParamScope scopeOf(Kind kind);
    /// The object kind of a scope (None for Global).
    static Kind kindOf(ParamScope scope);
    ParamScope scope() const { return scopeOf(kind); }
};

/// The Weather panel (editor_weather.cpp): the state it shows, its fields,
/// and what the viewport previews (view state: never saved, never undone).
struct WeatherPanel {
    bool shown = false;         ///< View > Weather
    int selectedState = -1;     ///< index into Preset::weather
    int selectedRegion = -1;    ///< index into Preset::weatherRegions
    std::string nameBuffer;     ///< the name field (add, rename)
    std::string from = "none";  ///< the transition's ends (the preview's pickers)
    std::string to = "none";
    double playSeconds = 10.0;  ///< Play transition's duration [s]
    WeatherPreview preview;
};

/// The selection and the panels' editing state (outliner, inspector, timeline).
struct EditState {
    Selection selection;
    std::optional<ParamRef> selectedParam;  ///< the inspector's parameter (the timeline's track)
    int selectedKey = -1;                   ///< a key of that parameter's track
    bool draggingKey = false;
    /// The timeline's curve view: time span, curves shown, selected key points.
    CurveViewState curves;
    bool timelineHovered = false;   ///< Delete then deletes keys, not the object
    KeyClipboard keyClipboard;      ///< a key copied from the track row (Ctrl+C with no curve selection)
    CurveClipboard curveClipboard;  ///< keys copied from the curves (Ctrl+C on a curve selection)
    bool renaming = false;          ///< the outliner's inline rename
    std::string renameBuffer;
    /// Auto-key and the changes not keyed yet (pending_edits.hpp).
    PendingEdits pending;
    /// Solo and mute of volumes and emitters in the viewport (view only).
    ViewFilter viewFilter;
    /// The Weather panel and the viewport's weather preview.
    WeatherPanel weather;

    /// A volume, an emitter or a cloud volume is selected.
    bool objectSelected() const { return selection.scope() != ParamScope::Global; }
    /// Clears what refers to objects, parameters or keys that `preset` no longer has.
    void validate(const Preset& preset);
    /// Picks `key` of the inspector's parameter's track (-1: none). The
    /// timeline has one key selection: the curve view's becomes that key,
    /// so Delete, Copy and the curves act on the key picked last.
    void selectTrackKey(const Preset& preset, int key);
    /// The track row follows the curve view's selection: while the curves
    /// have keys selected, selectedKey is the inspector parameter's one
    /// among them, else -1.
    void followCurveSelection(const Preset& preset);
};

/// The outliner's sky preview: a small fisheye of the solved sky.
struct SkyPreview {
    unsigned texture = 0;
    std::uint64_t generation = ~0ull;  ///< the SkyService::generation it shows
    std::string settings;              ///< the display, view and exposure it was made with
};

/// The time of day and its playback.
struct Playback {
    double timeHours = 9.0;  ///< [h] local solar time
    bool playing = false;
    double speed = 1.0;  ///< game hours per real second
    bool loop = true;

    /// Advances the time by `dt` real seconds while playing (at most 0.25 s a frame).
    void advance(double dt);
    void jumpTo(double hours) { timeHours = wrapHours(hours); }
};

/// The preset evaluated at a time, and the sky tables solved for it.
struct SkyService {
    std::unique_ptr<CompiledPreset> compiled;
    std::uint64_t compiledRevision = 0;
    PresetState state;                                         ///< every parameter at the current time
    std::unique_ptr<SpectralSkySolver> sunSolver, moonSolver;  ///< the colours of twilight
    bool valid = false;
    AtmosphereParams solvedAir{};
    glm::dvec3 solvedSun{0.0}, solvedMoon{0.0};
    /// The light of the solved moment in lux and cd/m^2 (aerial/photometry.hpp),
    /// what the Lights panel shows; updated with every solve.
    LightReport light;
    double solveMs = 0.0;          ///< the last solve [ms]
    std::uint64_t generation = 0;  ///< counts solves (what the sky preview compares)

    /// With unkeyed changes: the preset with them keyed (PendingEdits::
    /// applied), compiled once a change rests, and the changes over the
    /// document's evaluation while one is being dragged.
    std::unique_ptr<CompiledPreset> shown;
    std::uint64_t shownRevision = 0, shownPendingRevision = 0;
    PendingOverlay overlay;
    std::uint64_t overlayRevision = 0, overlayPendingRevision = 0;
    bool overlayBound = false;
    std::uint64_t compiles = 0;  ///< presets compiled (each a copy of the whole preset)

    /// Evaluates the document's preset, with the unkeyed changes keyed
    /// (what the artist sees), at `timeHours`, with the weather `weather`
    /// (the Weather panel's preview; empty: the keyed values). While
    /// `dragging` (a field is being dragged) the changes are written over
    /// the document's own evaluation (a dragged parameter shows its change,
    /// not the weather's), compiled only when the document changes;
    /// otherwise the preset with the changes keyed is compiled again after
    /// a change of either, once. True when it compiled or bound anything again.
    bool evaluate(const Document& doc, const PendingEdits& pending, double timeHours, bool dragging = false,
                  const WeatherMix& weather = {});
    /// Solves both tables again when the atmosphere or a light direction
    /// changed since the last solve. True when it solved.
    bool solve();
};

/// Synthetic viewport mouse input for scripts (one entry per frame).
struct ScriptedMouse {
    glm::dvec2 position{0.0};  ///< px from the viewport's top-left
    bool down = false;
    bool pressed = false;
    bool released = false;
    bool right = false;  ///< the right button (camera orbit) instead of the left (gizmo, picking)
};

/// The viewport: renderer and display transform, the texture ImGui shows,
/// camera, gizmo and picking state, and the View menu's options.
struct ViewportState {
    std::unique_ptr<renderer::Renderer> renderer;
    std::unique_ptr<renderer::DisplayTransform> display;
    std::string displayName, viewName;  ///< the OCIO display and view asked for
    double exposureEv = 0.0;            ///< View > Exposure offset [EV], on top of the preset's
    ViewExposure exposure;              ///< the preset's exposure, metered and adapting
    std::chrono::steady_clock::time_point lastExposureStep{};
    double resolutionScale = 0.5;
    bool showHelpers = true;
    /// View > Game view (G): the picture as the game shows it, no helpers.
    bool gameView = false;
    /// View > Maximize viewport: the side panels and the timeline hidden.
    bool maximized = false;
    /// Which panels show, and their sizes [px] (0: the default share of the
    /// window); the splitters between them set the sizes.
    bool showOutliner = true, showInspector = true, showTimeline = true;
    float outlinerWidth = 0.0f, inspectorWidth = 0.0f, timelineHeight = 0.0f;
    /// Panels collapsed in place (the arrow of their title bar, or a
    /// double-click on it): a side panel shrinks to its title's arrow, the
    /// timeline to its title bar, and the viewport takes the room.
    bool outlinerCollapsed = false, inspectorCollapsed = false, timelineCollapsed = false;
    /// The outlines, icons, gizmo and grid are drawn.
    bool helpersShown() const { return showHelpers && !gameView; }
    /// Size of the viewport's window [px] (print_viewport).
    float windowWidth = 0.0f, windowHeight = 0.0f;
    bool showGrid = false;
    renderer::RenderPasses passes;
    /// View > Fog: as the preset says (its fog.render_mode, the default),
    /// or analytic / volumetric whatever it says (the froxel grid with light
    /// shafts costs ~+50 ms per frame at 640 x 360 on llvmpipe).
    enum class FogView { Preset, Analytic, Volumetric } fogView = FogView::Preset;
    /// The fog mode the viewport draws for a preset state.
    renderer::FogMode fogModeFor(const Environment& environment) const {
        if (fogView == FogView::Preset)
            return environment.fogRenderMode == FogRenderMode::Volumetric ? renderer::FogMode::Volumetric
                                                                          : renderer::FogMode::Analytic;
        return fogView == FogView::Volumetric ? renderer::FogMode::Volumetric : renderer::FogMode::Analytic;
    }
    bool showStars = true;                       ///< View > Stars (the sky pass's stars at night)
    bool nightVision = true;                     ///< View > Night vision (aerial::nightVision in the display)
    std::string scenePath;                       ///< "" = the built-in scene
    std::shared_ptr<const SceneHits> sceneHits;  ///< the scene's triangles (placement, drop to ground)

    unsigned displayTexture = 0;
    std::vector<unsigned> retiredTextures;  ///< replaced display textures, deleted next frame
    int displayWidth = 0, displayHeight = 0;
    int renderWidth = 0, renderHeight = 0;
    glm::dvec2 origin{0.0}, size{640.0, 360.0};  ///< [px] in the window
    bool visible = false;
    std::string renderLogError;
    std::string lastRenderSignature;  ///< what the last viewport frame was rendered from
    /// Frames rendered since the signature last changed: the amortised clouds
    /// (one pixel of each 4 x 4 block traced per frame) converge to the
    /// reference in kCloudConvergeFrames still frames, so an idle viewport
    /// renders that many more, then stops.
    int stillFrames = 0;
    /// The next frame forgets the amortised clouds' history (a preset was
    /// opened: nothing of the old one may show).
    bool resetCloudHistory = true;
    unsigned long long froxelRevision = 0;  ///< document revision of the volumetric fog's history
    double renderMs = 0.0;

    CameraController camera;
    Gizmo gizmo;
    GizmoMode gizmoMode = GizmoMode::Translate;
    GizmoSpace gizmoSpace = GizmoSpace::World;
    std::string gizmoMergeKey;
    std::deque<ScriptedMouse> scriptedMouse;
    bool scriptedMouseActive = false;
    glm::dvec2 lastScriptedMouse{0.0};
};

/// What waits behind the unsaved-changes prompt.
enum class Pending { None, New, Open, Quit, OpenRecovery };
/// The unsaved-changes prompt's buttons (and the script's `answer`).
enum class UnsavedChoice { Save, Discard, Cancel };
/// What the file dialog's result is for.
enum class DialogPurpose { None, Open, SaveAs, Scene, Screenshot, Export, Mesh };

/// Modals, prompts and the file dialog.
struct Dialogs {
    ExportOptions exportOptions;  ///< File > Export for game's step and table size
    bool showHelp = false;        ///< Help > Keys and workflow (F1)
    std::string errorTitle, errorText;
    bool openErrorModal = false;
    Pending pending = Pending::None;
    std::string pendingPath;
    bool openUnsavedModal = false;
    bool unsavedPromptOpen = false;
    bool continueAfterSave = false;  ///< a Save As started from the unsaved prompt
    std::optional<RecoveryCandidate> recovery;
    bool openRecoveryModal = false;
    FileDialog fileDialog;
    DialogPurpose purpose = DialogPurpose::None;
    int meshVolumeIndex = -1;  ///< DialogPurpose::Mesh: the volume to give the mesh, -1 a new volume
    /// A file dropped on the window, handled at the next frame; asMesh: a
    /// glTF dropped with Shift held becomes a mesh fog volume, not the scene.
    struct Drop {
        std::string path;
        bool asMesh = false;
    };
    std::vector<Drop> drops;

    /// The unsaved-changes prompt is open or about to open.
    bool unsavedPromptShown() const { return unsavedPromptOpen || openUnsavedModal; }
};

/// The automation script (--script) and what its current command waits for.
struct ScriptRunner {
    std::vector<ScriptCommand> commands;
    std::size_t next = 0;
    int waitFrames = 0;
    bool waitsForMouse = false;
    std::deque<double> times;  ///< scrub: one time per frame
    bool waitsForAutosave = false;
    bool waitsForWeather = false;  ///< weather_wait: until the played transition ends
    int autosaveWrites = 0;
    std::string windowShotPath;  ///< window_screenshot: captured after the next frame is drawn
    /// curve_drag, curve_drag_box, curve_wheel, curve_pan_drag: ImGui's
    /// mouse (and Ctrl, Shift) one frame each, over the real timeline widgets.
    struct GuiMouse {
        glm::dvec2 position{0.0};  ///< [px] in the window
        bool down = false;
        bool ctrl = false, shift = false;
        bool middle = false;  ///< the middle button is down
        float wheel = 0.0f;   ///< wheel steps this frame
    };
    std::deque<GuiMouse> guiMouse;
};

/// Frame timing, --bench samples and idle detection.
struct FrameStats {
    double frameMs = 0.0;  ///< frame to frame [ms] (--bench)
    double workMs = 0.0;   ///< the last frame's work without waiting for events [ms] (status bar)
    std::chrono::steady_clock::time_point lastFrame = std::chrono::steady_clock::now();
    std::vector<double> benchFrameMs;
    std::vector<double> benchSolveMs;
    std::vector<renderer::PassTimes>
        benchPasses;  ///< viewport passes, timed with glFinish (every 10th frame)
    /// The viewport's passes the last time they were timed (every 30th
    /// rendered frame; the status bar's tooltip); timed = false before.
    renderer::PassTimes lastPasses;
    bool lastPassesTimed = false;
    int renderedFrames = 0;
    int frameIndex = 0;
    int idleFrames = 0;  ///< frames without input (the loop then waits for events)
};

}  // namespace aerial::editor
