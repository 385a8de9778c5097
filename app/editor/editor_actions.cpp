// editor/editor_actions.cpp — the actions of the menus and the keys, each
// declared once in the editor's one action table (actions.hpp): the main
// menu bar is drawn from it (same order, labels, shortcuts and enabled
// states), the keyboard shortcuts are matched against it (each in its part
// of the window), the Help sheet lists its keys, a script runs any of them
// by name (editor_script.cpp declares the actions only scripts run) and
// panels run them by name.
#include "editor.hpp"

#include <GLFW/glfw3.h>  // GLFW_INCLUDE_NONE is defined for this target
#include <imgui.h>

#include <aerial/renderer/scene.hpp>

#include <cmath>
#include <cstdio>

namespace aerial::editor {

void Editor::declareActions() {
    ActionTable& t = actions_;
    using S = Shortcut;
    const auto objectSelected = [this] { return edit_.objectSelected(); };
    const auto needsObject = [](const std::string& name) {
        return name + ": select a volume, an emitter or a cloud volume first";
    };

    // --- File ------------------------------------------------------------------
    t.add("request_new", "New", "File").key(GLFW_KEY_N, S::kCtrl).does([this] { requestNew(); });
    t.add("open_dialog", "Open...", "File").key(GLFW_KEY_O, S::kCtrl).does([this] { requestOpen(""); });
    t.add("open_recent", "Open Recent", "File").drawsMenu([this](const char* label) {
        if (!ImGui::BeginMenu(label, !recent_.files().empty())) return;
        std::string chosen;
        for (const std::string& file : recent_.files())
            if (ImGui::MenuItem(file.c_str())) chosen = file;
        ImGui::Separator();
        if (ImGui::MenuItem("Clear recent files")) recent_.clear();
        ImGui::EndMenu();
        if (!chosen.empty()) requestOpen(chosen);
    });
    t.add("save_current", "Save", "File").key(GLFW_KEY_S, S::kCtrl).does([this] { saveOrSaveAs(false); });
    t.add("save_as", "Save As...", "File").key(GLFW_KEY_S, S::kCtrl | S::kShift).does([this] {
        saveOrSaveAs(true);
    });
    t.add("load_scene_dialog", "Load scene (glTF)...", "File").separated().does([this] {
        dialogs_.purpose = DialogPurpose::Scene;
        dialogs_.fileDialog.open("Load scene (glTF)", FileDialog::Mode::Open, {".gltf", ".glb"},
                                 view_.scenePath);
    });
    t.add("builtin_scene", "Built-in scene", "File")
        .enabledWhen([this] { return !view_.scenePath.empty(); })
        .does([this] {
            setScene(renderer::makeBuiltinScene());
            view_.scenePath.clear();
            setStatus("Built-in scene");
        });
    t.add("screenshot_dialog", "Screenshot...", "File").separated().does([this] {
        dialogs_.purpose = DialogPurpose::Screenshot;
        dialogs_.fileDialog.open("Screenshot (.png display-referred, .exr scene-linear)",
                                 FileDialog::Mode::Save, {".png", ".exr"}, "");
    });
    t.add("export_dialog", "Export for game...", "File")
        .enabledWhen([this] { return !export_.running(); })
        .does([this] {
            dialogs_.purpose = DialogPurpose::Export;
            dialogs_.fileDialog.open("Export for game (aerial bake) into folder", FileDialog::Mode::Directory,
                                     {}, "");
        });
    t.add("export_options_menu", "Export options", "File").drawsMenu([this](const char* label) {
        if (!ImGui::BeginMenu(label)) return;
        ExportOptions& o = dialogs_.exportOptions;
        ImGui::TextDisabled("Step over the day");
        for (const auto& [name, hours] : {std::pair{"15 min", 0.25}, std::pair{"30 min", 0.5},
                                          std::pair{"1 h", 1.0}, std::pair{"2 h", 2.0}})
            if (ImGui::MenuItem(name, nullptr, std::abs(o.stepHours - hours) < 1e-9)) o.stepHours = hours;
        ImGui::Separator();
        ImGui::TextDisabled("Sky table size");
        for (const auto& [w, h] :
             {std::pair{64, 32}, std::pair{128, 64}, std::pair{256, 128}, std::pair{512, 256}}) {
            const std::string text = std::to_string(w) + " x " + std::to_string(h);
            if (ImGui::MenuItem(text.c_str(), nullptr, o.azimuthCount == w && o.elevationCount == h))
                o.azimuthCount = w, o.elevationCount = h;
        }
        ImGui::EndMenu();
    });
    t.add("request_quit", "Quit", "File").separated().key(GLFW_KEY_Q, S::kCtrl).does([this] {
        requestQuit();
    });

    // --- Edit ------------------------------------------------------------------
    t.add("undo", "Undo", "Edit")
        .key(GLFW_KEY_Z, S::kCtrl, true)
        .labelledBy([this] { return "Undo " + doc_.undoLabel(); })
        .enabledWhen([this] { return doc_.canUndo(); }, "nothing to undo")
        .does([this] {
            if (doc_.undo()) edit_.validate(doc_.preset());
        });
    t.add("redo", "Redo", "Edit")
        .key(GLFW_KEY_Z, S::kCtrl | S::kShift, true)
        .key(GLFW_KEY_Y, S::kCtrl, true)
        .labelledBy([this] { return "Redo " + doc_.redoLabel(); })
        .enabledWhen([this] { return doc_.canRedo(); }, "nothing to redo")
        .does([this] {
            if (doc_.redo()) edit_.validate(doc_.preset());
        });
    t.add("delete", "Delete", "Edit")
        .separated()
        .key(GLFW_KEY_DELETE, S::kNone, false, KeyContext::OutsideTimeline)  // the timeline deletes keys
        .oneUndoStep()
        .enabledWhen(objectSelected, needsObject("delete"))
        .does([this] { deleteSelection(); });
    t.add("duplicate", "Duplicate", "Edit")
        .key(GLFW_KEY_D, S::kCtrl)
        .oneUndoStep()
        .enabledWhen(objectSelected, needsObject("duplicate"))
        .does([this] { duplicateSelection(); });
    t.add("key_all_changed", "Key all changed parameters", "Edit")
        .separated()
        .oneUndoStep()
        .ignoresExtraWords()
        .helps("key every parameter that differs from the saved preset")
        .does([this] {
            const int count = keyAllChangedAt(doc_, playback_.timeHours);
            setStatus(std::to_string(count) + " keys set at " + clockText());
            std::printf("keyed %d parameters\n", count);
        });

    // --- Create: in front of the camera --------------------------------------------
    t.add("add_box_volume", "Box volume", "Create").key(GLFW_KEY_B, S::kShift).oneUndoStep().does([this] {
        addVolumeInFront(FogVolumeShape::Box);
    });
    t.add("add_ellipsoid_volume", "Ellipsoid volume", "Create")
        .key(GLFW_KEY_E, S::kShift)
        .oneUndoStep()
        .does([this] { addVolumeInFront(FogVolumeShape::Ellipsoid); });
    t.add("add_mesh_volume", "Mesh volume (glTF)...", "Create")
        .takes({word("FILE.gltf").opt()})
        .helps(
            "a mesh fog volume from a glTF file, on the surface in front of the camera (without FILE: "
            "the file dialog)")
        .handles([this](const ActionArgs& a, std::string& error) {
            if (!a.has(1)) {
                requestMeshFile(-1);
                return true;
            }
            const std::size_t before = doc_.preset().volumes.size();
            if (!addMeshVolumeFromFile(a[1]) || doc_.preset().volumes.size() == before) {
                error = "add_mesh_volume: " + dialogs_.errorText;
                return false;
            }
            const FogVolume& v = doc_.preset().volumes.back();
            std::printf("added mesh volume %zu \"%s\" at %.17g %.17g %.17g\n", before, v.mesh.c_str(),
                        v.position.x, v.position.y, v.position.z);
            return true;
        });
    t.add("choose_volume_mesh", "Choose mesh of the volume...", "Edit").does([this] {
        if (edit_.selection.kind == Selection::Kind::Volume)
            requestMeshFile(edit_.selection.index);
        else
            setStatus("Select a fog volume to give it a mesh");
    });
    t.add("add_point_emitter", "Emitter", "Create").key(GLFW_KEY_P, S::kShift).oneUndoStep().does([this] {
        addEmitterInFront(EmitterKind::Point);
    });
    t.add("add_lightning", "Lightning", "Create").key(GLFW_KEY_T, S::kShift).oneUndoStep().does([this] {
        addEmitterInFront(EmitterKind::Lightning);
    });
    // Cloud volumes: in the cloud layer, above the point the camera looks at.
    t.add("add_cloud_box", "Cloud box", "Create").separated().oneUndoStep().does([this] {
        addCloudVolumeAboveView(FogVolumeShape::Box);
    });
    t.add("add_cloud_ellipsoid", "Cloud ellipsoid", "Create").oneUndoStep().does([this] {
        addCloudVolumeAboveView(FogVolumeShape::Ellipsoid);
    });

    // --- View --------------------------------------------------------------------
    t.add("ocio_display", "OCIO display", "View").drawsMenu([this](const char* label) {
        if (!view_.display || !ImGui::BeginMenu(label)) return;
        for (const std::string& d : view_.display->displays())
            if (ImGui::MenuItem(d.c_str(), nullptr, d == view_.display->display())) {
                view_.displayName = d;
                view_.viewName.clear();
                rebuildDisplay();
            }
        ImGui::EndMenu();
    });
    t.add("ocio_view", "OCIO view", "View").drawsMenu([this](const char* label) {
        if (!view_.display || !ImGui::BeginMenu(label)) return;
        for (const std::string& v : view_.display->views())
            if (ImGui::MenuItem(v.c_str(), nullptr, v == view_.display->view())) {
                view_.viewName = v;
                rebuildDisplay();
            }
        ImGui::EndMenu();
    });
    t.add("exposure", "Exposure offset [EV]", "View")
        .takes({number("EV")})
        .helps("the view's exposure offset, on top of the preset's")
        .handles([this](const ActionArgs& a, std::string&) {
            view_.exposureEv = a.number(1);  // the next frame shows it (it is in the frame's signature)
            return true;
        })
        .drawsMenu([this](const char* label) {
            // On top of the preset's exposure (Environment > Exposure), for this view only.
            float ev = float(view_.exposureEv);
            ImGui::SetNextItemWidth(140.0f);
            if (ImGui::SliderFloat(label, &ev, -10.0f, 10.0f, "%+.2f")) view_.exposureEv = ev;
        });
    t.add("resolution_scale_menu", "Resolution scale", "View").drawsMenu([this](const char* label) {
        if (!ImGui::BeginMenu(label)) return;
        for (double s : {0.25, 0.5, 0.75, 1.0}) {
            char percent[32];
            std::snprintf(percent, sizeof percent, "%d%%", int(s * 100.0 + 0.5));
            if (ImGui::MenuItem(percent, nullptr, std::abs(view_.resolutionScale - s) < 1e-9))
                view_.resolutionScale = s;
        }
        ImGui::EndMenu();
    });
    // View switches: a check mark, toggled by the item.
    const auto toggle = [&t](const char* name, const char* label, bool& flag, bool separated = false) {
        Action& a = t.add(name, label, "View");
        if (separated) a.separated();
        bool* f = &flag;
        a.checkedWhen([f] { return *f; }).does([f] { *f = !*f; });
    };
    // A switch a script sets (on|off) and a menu item or key toggles.
    const auto switchTo = [](bool& flag) {
        return [f = &flag](const ActionArgs& a, std::string&) {
            *f = a.has(1) ? a[1] == "on" : !*f;
            return true;
        };
    };
    t.add("maximize_viewport", "Maximize viewport", "View")
        .key(GLFW_KEY_F11)
        .separated()
        .takes({onOff().opt()})
        .helps("hide the side panels and the timeline (without on|off: toggle)")
        .checkedWhen([this] { return view_.maximized; })
        .handles(switchTo(view_.maximized));
    t.add("game_view", "Game view (no helpers)", "View")
        .key(GLFW_KEY_G)
        .takes({onOff().opt()})
        .helps("the picture without helpers (without on|off: toggle)")
        .checkedWhen([this] { return view_.gameView; })
        .handles(switchTo(view_.gameView));
    toggle("show_outliner", "Outliner", view_.showOutliner);
    toggle("show_inspector", "Inspector", view_.showInspector);
    toggle("show_timeline", "Timeline", view_.showTimeline);
    t.add("show_weather", "Weather", "View")
        .takes({onOff().opt()})
        .helps("the Weather panel: states, overrides and the viewport's preview (without on|off: toggle)")
        .checkedWhen([this] { return edit_.weather.shown; })
        .handles(switchTo(edit_.weather.shown));
    toggle("collapse_outliner", "Collapse outliner", view_.outlinerCollapsed, true);
    toggle("collapse_inspector", "Collapse inspector", view_.inspectorCollapsed);
    toggle("collapse_timeline", "Collapse timeline", view_.timelineCollapsed);
    toggle("show_helpers", "Helpers (outlines, icons, gizmo)", view_.showHelpers, true);
    toggle("show_grid", "Ground grid", view_.showGrid);
    toggle("pass_sky", "Sky", view_.passes.sky, true);
    toggle("show_stars", "Stars", view_.showStars);
    toggle("night_vision", "Night vision (the eye's blue night below 5 cd/m2)", view_.nightVision);
    toggle("pass_scene", "Scene geometry", view_.passes.scene);
    toggle("pass_global_fog", "Global fog", view_.passes.globalFog);
    toggle("pass_volumes", "Fog volumes", view_.passes.volumes);
    toggle("pass_emitters", "Emitters", view_.passes.emitters);
    toggle("pass_transparent", "Transparent objects", view_.passes.transparent);
    toggle("pass_particles", "Fog particles", view_.passes.particles);
    toggle("pass_clouds", "Clouds", view_.passes.clouds);
    toggle("pass_shadows", "Sun shadows", view_.passes.shadows);
    const auto fogView = [&t, this](const char* name, const char* label, ViewportState::FogView v,
                                    bool separated = false) {
        Action& a = t.add(name, label, "View");
        if (separated) a.separated();
        a.checkedWhen([this, v] { return view_.fogView == v; }).does([this, v] { view_.fogView = v; });
    };
    fogView("fog_as_preset", "Fog as the preset says", ViewportState::FogView::Preset, true);
    fogView("fog_analytic", "Fog analytic (exact, no shafts)", ViewportState::FogView::Analytic);
    fogView("fog_volumetric", "Fog volumetric (light shafts)", ViewportState::FogView::Volumetric);
    const auto gizmoMode = [&t, this](const char* name, const char* label, int key, GizmoMode mode,
                                      bool separated = false) {
        Action& a = t.add(name, label, "View");
        if (separated) a.separated();
        a.key(key).checkedWhen([this, mode] { return view_.gizmoMode == mode; }).does([this, mode] {
            view_.gizmoMode = mode;
        });
    };
    gizmoMode("gizmo_move", "Move", GLFW_KEY_W, GizmoMode::Translate, true);
    gizmoMode("gizmo_rotate", "Rotate", GLFW_KEY_E, GizmoMode::Rotate);
    gizmoMode("gizmo_scale", "Scale", GLFW_KEY_R, GizmoMode::Scale);
    t.add("gizmo_local_axes", "Local axes", "View")
        .key(GLFW_KEY_L)
        .checkedWhen([this] { return view_.gizmoSpace == GizmoSpace::Local; })
        .does([this] {
            view_.gizmoSpace = view_.gizmoSpace == GizmoSpace::World ? GizmoSpace::Local : GizmoSpace::World;
        });
    t.add("frame", "Frame selection", "View")
        .key(GLFW_KEY_F, S::kNone, false, KeyContext::OutsideTimeline)  // over the timeline F fits its view
        .enabledWhen(objectSelected, needsObject("frame"))
        .does([this] { frameSelection(); });
    t.add("preset_view", "Go to the preset's view", "View")
        .key(GLFW_KEY_HOME, S::kNone, false, KeyContext::OutsideTimeline)
        .helps(
            "put the viewport camera at the preset's view (its \"view\": where it is meant to be seen from)")
        .enabledWhen([this] { return doc_.preset().view.has_value(); }, "preset_view: the preset has no view")
        .does([this] { goToPresetView(); });
    t.add("set_preset_view", "Set the preset's view to this camera", "View")
        .oneUndoStep()
        .helps("save the viewport camera as the preset's view (aerial render and the contact sheet use it)")
        .does([this] { setPresetViewFromCamera(); });

    t.add("timeline_fit", "Timeline: whole day", "View")
        .key(GLFW_KEY_F, S::kNone, false, KeyContext::Timeline)
        .does([this] {
            edit_.curves.time = fitView();
            edit_.curves.resetRanges();  // the curves' value ranges follow their keys again
        });

    t.add("drop_to_ground", "Drop to ground", "Edit")
        .key(GLFW_KEY_END)
        .separated()
        .enabledWhen([this] {
            const ParamScope s = edit_.selection.scope();
            return s == ParamScope::Volume || s == ParamScope::Emitter;
        })
        .does([this] { dropSelectionToGround(); });

    // --- Help --------------------------------------------------------------------------
    t.add("help_sheet", "Keys and workflow", "Help").key(GLFW_KEY_F1).does([this] {
        dialogs_.showHelp = !dialogs_.showHelp;
    });

    // --- The timeline's keys: while the mouse is over it ---------------------------
    t.add("timeline_delete_keys", "Timeline: delete keys")
        .key(GLFW_KEY_DELETE, S::kNone, false, KeyContext::Timeline)
        .oneUndoStep()
        .helps("delete the keys selected on the curves, else the selected key of the inspector's parameter")
        .handles([this](const ActionArgs&, std::string& error) {
            if (deleteTimelineKeys(doc_, edit_)) return true;
            error = "timeline_delete_keys: no key selected";
            return false;
        });
    t.add("timeline_copy_key", "Timeline: copy keys")
        .key(GLFW_KEY_C, S::kCtrl, false, KeyContext::Timeline)
        .helps(
            "copy the keys selected on the curves (several curves, their times relative to each other), "
            "else the selected key of the inspector's parameter")
        .handles([this](const ActionArgs&, std::string& error) {
            if (copyTimelineKey(doc_, edit_)) return true;
            error = "timeline_copy_key: no key selected";
            return false;
        });
    t.add("timeline_paste_key", "Timeline: paste keys")
        .key(GLFW_KEY_V, S::kCtrl, false, KeyContext::Timeline)
        .oneUndoStep()
        .helps(
            "paste the copied keys at the current time: curve keys each onto its own curve, the earliest "
            "at the time and the others at their offsets (a key on an existing key replaces it, at its "
            "time); a track row's key on the inspector's parameter")
        .enabledWhen(
            [this] {
                return !edit_.curveClipboard.empty() ||
                       (edit_.keyClipboard.valid && edit_.selectedParam.has_value());
            },
            "timeline_paste_key: copy a key and select a parameter first")
        .handles([this](const ActionArgs&, std::string& error) {
            if (pasteTimelineKey(doc_, edit_, playback_.timeHours)) return true;
            error = "timeline_paste_key: the copied key does not fit this parameter";
            return false;
        });

    // --- Keys only -----------------------------------------------------------------
    t.add("play_pause", "Play / pause").key(GLFW_KEY_SPACE).does([this] {
        playback_.playing = !playback_.playing;
    });
    t.add("cancel_gizmo_drag", "Cancel the gizmo drag")
        .key(GLFW_KEY_ESCAPE)
        .enabledWhen([this] { return view_.gizmo.active(); })
        .does([this] {
            GizmoTransform transform;
            if (gizmoTransformOfSelection(transform) && view_.gizmo.cancel(transform)) {
                applyGizmoTransform(transform);
                doc_.closeMerge();
            }
        });
}

void Editor::drawMenuBar() {
    if (!ImGui::BeginMainMenuBar()) return;
    for (const std::string& menu : ActionTable::menus()) {
        if (!ImGui::BeginMenu(menu.c_str())) continue;
        for (const Action& a : actions_.all()) {
            if (a.menu != menu) continue;
            if (a.separatorBefore) ImGui::Separator();
            if (a.drawMenu) {
                a.drawMenu(a.label.c_str());
                continue;
            }
            const std::string label = a.text ? a.text() : a.label;
            const std::string keys = a.keys.empty() ? std::string() : shortcutText(a.keys.front());
            if (ImGui::MenuItem(label.c_str(), keys.empty() ? nullptr : keys.c_str(),
                                a.checked && a.checked(), a.isEnabled())) {
                std::string error;
                if (!actions_.run(a.name, &error)) setStatus(error);
            }
        }
        ImGui::EndMenu();
    }
    ImGui::EndMainMenuBar();
}

void Editor::drawHelpSheet() {
    if (!dialogs_.showHelp) return;
    ImGui::SetNextWindowSize(ImVec2(620, 520), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_FirstUseEver,
                            ImVec2(0.5f, 0.5f));
    if (!ImGui::Begin("Aerial: keys and workflow (F1)", &dialogs_.showHelp)) {
        ImGui::End();
        return;
    }
    ImGui::TextWrapped(
        "1. Pick an hour on the timeline (drag the ruler, Sunrise / Noon / Sunset, or type HH:MM) and look.\n"
        "2. Select what to change in the outliner (Atmosphere, Sun & moon, Global fog, Exposure, Clouds, "
        "volumes, emitters) or click it in the viewport; add volumes and emitters with the + buttons or "
        "Create.\n"
        "3. Change it in the inspector: drag a field, or double-click / Ctrl+click it to type. Beside "
        "density "
        "and falloff you can set the visibility and the half-height instead.\n"
        "4. Animate: the diamond keys a parameter at this hour. With Auto-key off (the default) a change of "
        "an animated parameter between keys waits, red, until you Key or Revert it.\n"
        "5. Play the day (Space), look at dawn, noon, dusk and night, then Save (Ctrl+S) and File > Export "
        "for game.\n"
        "Fog of any shape: Create > Mesh volume adds a closed glTF mesh; set a volume's Blend to subtract "
        "for a fog-free room or tunnel. Room for the picture: drag the panel borders, collapse a panel "
        "with its title's arrow, F11 maximizes the viewport, G shows the game view. This sheet: F1.");
    ImGui::Separator();
    if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY)) {
        ImGui::TableSetupColumn("Command");
        ImGui::TableSetupColumn("Keys", ImGuiTableColumnFlags_WidthFixed, 220.0f);
        ImGui::TableHeadersRow();
        for (const Action& a : actions_.all()) {
            if (a.keys.empty()) continue;
            ImGui::TableNextRow();
            ImGui::TableSetColumnIndex(0);
            ImGui::TextUnformatted((a.menu.empty() ? a.label : a.menu + " > " + a.label).c_str());
            ImGui::TableSetColumnIndex(1);
            std::string keys;
            for (const Shortcut& k : a.keys) {
                keys += (keys.empty() ? "" : ", ") + shortcutText(k);
                if (k.context != KeyContext::Anywhere)
                    keys += " (" + std::string(keyContextName(k.context)) + ")";
            }
            ImGui::TextUnformatted(keys.c_str());
        }
        const char* mouse[][2] = {{"Orbit / fly (with W A S D Q E)", "right drag"},
                                  {"Orbit", "Alt + left drag"},
                                  {"Pan", "middle drag"},
                                  {"Zoom", "wheel"},
                                  {"Select", "click in the viewport"},
                                  {"Gizmo snapping", "Ctrl while dragging"},
                                  {"Timeline: zoom / pan the time", "wheel / middle or Alt drag"},
                                  {"Timeline: the whole day", "F, double-click the ruler"},
                                  {"Curves: move keys (time and value)", "drag a key"},
                                  {"Curves: no snapping while moving", "Shift"},
                                  {"Curves: select keys in a box", "drag on empty curve area"},
                                  {"Curves: add to the selection", "Ctrl + click / drag"},
                                  {"Curves: go to a time", "click empty curve area"},
                                  {"Curves: flat / automatic tangent", "right-click a key"},
                                  {"Curves: show a parameter's curve", "curve button in the inspector"}};
        for (const auto& row : mouse) {
            ImGui::TableNextRow();
            ImGui::TableSetColumnIndex(0);
            ImGui::TextUnformatted(row[0]);
            ImGui::TableSetColumnIndex(1);
            ImGui::TextUnformatted(row[1]);
        }
        ImGui::EndTable();
    }
    ImGui::End();
}

void Editor::handleShortcuts() {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantTextInput || ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId)) return;
    const bool ctrl = io.KeyCtrl, shift = io.KeyShift;
    if (!ctrl && view_.camera.flying()) return;  // W A S D Q E fly
    const int held = (ctrl ? Shortcut::kCtrl : 0) | (shift ? Shortcut::kShift : 0);
    const KeyContext where = edit_.timelineHovered ? KeyContext::Timeline : KeyContext::OutsideTimeline;
    const Action* action = actions_.actionForKey(
        held, where, [](const Shortcut& s) { return ImGui::IsKeyPressed(s.key, s.repeat); });
    if (action && action->isEnabled()) actions_.run(action->name);
}

}  // namespace aerial::editor
