// editor/editor_script_edit.cpp — the script commands that edit the preset
// (objects, parameters, keys), the time and the view (screenshots, gizmo
// drags, clicks, camera orbits, display): entries of the script command
// table (see editor_script.cpp), each through the code the panels use.
#include "editor.hpp"
#include "places.hpp"
#include "script_args.hpp"

#include "viewport/overlay.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace aerial::editor {

bool Editor::queueGizmoDrag(GizmoMode mode, int axis, glm::dvec2 deltaPx, int steps, std::string& error) {
    GizmoTransform transform;
    if (!gizmoTransformOfSelection(transform)) {
        error = "gizmo_drag: select a volume, an emitter or a cloud volume first";
        return false;
    }
    view_.gizmoMode = mode;
    const renderer::CameraFrame frame = viewportCameraFrame();
    const std::optional<glm::dvec2> centre = projectToViewport(frame, view_.size, transform.position);
    if (!centre) {
        error = "gizmo_drag: the selection is behind the camera";
        return false;
    }
    // Find a pixel on the wanted handle: search outwards from the centre.
    const GizmoHandle wanted = GizmoHandle(axis);
    std::optional<glm::dvec2> press;
    const double reach = view_.gizmo.sizePx * 1.6;
    for (double r = 0.0; r <= reach && !press; r += 2.0) {
        const int samples = std::max(1, int(r * 0.8));
        for (int i = 0; i < samples && !press; ++i) {
            const double a = 2.0 * kPi * i / samples;
            const glm::dvec2 p = *centre + r * glm::dvec2(std::cos(a), std::sin(a));
            if (p.x < 1 || p.y < 1 || p.x > view_.size.x - 1 || p.y > view_.size.y - 1) continue;
            if (view_.gizmo.hitTest(frame, view_.size, p, mode, view_.gizmoSpace, transform) == wanted &&
                (r > 6.0 || wanted == GizmoHandle::Centre))
                press = p;
        }
    }
    if (!press) {
        error = "gizmo_drag: the handle is not visible in the viewport";
        return false;
    }
    steps = std::max(1, steps);
    view_.scriptedMouse.push_back({*press, true, true, false});
    for (int k = 1; k <= steps; ++k)
        view_.scriptedMouse.push_back({*press + deltaPx * (double(k) / steps), true, false, false});
    view_.scriptedMouse.push_back({*press + deltaPx, false, false, true});
    view_.scriptedMouseActive = true;
    runner_.waitsForMouse = true;
    std::printf("gizmo_drag: press at %.1f %.1f, %d moves\n", press->x, press->y, steps);
    return true;
}

void Editor::declareEditScriptCommands() {
    ScriptCommandTable& table = scriptCommands_;
    using W = const ScriptWords&;
    using E = std::string&;
    const auto param = [this](const std::string& address, std::string& error) {
        return parseParamAddress(doc_.preset(), address, &error);
    };

    // --- objects ------------------------------------------------------------------------
    table.add({"add_volume", 1, 1, "add_volume box|ellipsoid", "a fog volume in front of the camera",
               [this](W w, E error) {
                   if (w[1] != "box" && w[1] != "ellipsoid") {
                       error = "add_volume: box or ellipsoid";
                       return false;
                   }
                   actions_.run(w[1] == "box" ? "add_box_volume" : "add_ellipsoid_volume");
                   const FogVolume& v = doc_.preset().volumes.back();
                   std::printf("added volume %zu at %.17g %.17g %.17g\n", doc_.preset().volumes.size() - 1,
                               v.position.x, v.position.y, v.position.z);
                   return true;
               }});
    table.add({"add_mesh_volume", 1, 1, "add_mesh_volume FILE.gltf",
               "a mesh fog volume from a glTF file, on the surface in front of the camera",
               [this](W w, E error) {
                   const std::size_t before = doc_.preset().volumes.size();
                   if (!addMeshVolumeFromFile(w[1]) || doc_.preset().volumes.size() == before) {
                       error = "add_mesh_volume: " + dialogs_.errorText;
                       return false;
                   }
                   const FogVolume& v = doc_.preset().volumes.back();
                   std::printf("added mesh volume %zu \"%s\" at %.17g %.17g %.17g\n", before, v.mesh.c_str(),
                               v.position.x, v.position.y, v.position.z);
                   return true;
               }});
    table.add({"set_volume_mesh", 2, 2, "set_volume_mesh INDEX FILE.gltf",
               "give fog volume INDEX the mesh of a glTF file (shape mesh)", [this](W w, E error) {
                   char* end = nullptr;
                   const long index = std::strtol(w[1].c_str(), &end, 10);
                   if (end == w[1].c_str() || *end != '\0' || index < 0 ||
                       std::size_t(index) >= doc_.preset().volumes.size()) {
                       error = "set_volume_mesh: no volume " + w[1];
                       return false;
                   }
                   if (!setVolumeMesh(int(index), w[2])) {
                       error = "set_volume_mesh: " + dialogs_.errorText;
                       return false;
                   }
                   return true;
               }});
    table.add({"add_emitter", 1, 1, "add_emitter point|lightning", "an emitter in front of the camera",
               [this](W w, E error) {
                   if (w[1] != "point" && w[1] != "lightning") {
                       error = "add_emitter: point or lightning";
                       return false;
                   }
                   actions_.run(w[1] == "point" ? "add_point_emitter" : "add_lightning");
                   return true;
               }});
    table.add({"add_cloud_volume", 1, 1, "add_cloud_volume box|ellipsoid",
               "a cloud volume in the cloud layer above the point the camera looks at", [this](W w, E error) {
                   if (w[1] != "box" && w[1] != "ellipsoid") {
                       error = "add_cloud_volume: box or ellipsoid";
                       return false;
                   }
                   actions_.run(w[1] == "box" ? "add_cloud_box" : "add_cloud_ellipsoid");
                   const CloudVolume& v = doc_.preset().cloudVolumes.back();
                   std::printf("added cloud volume %zu at %.17g %.17g %.17g\n",
                               doc_.preset().cloudVolumes.size() - 1, v.position.x, v.position.y,
                               v.position.z);
                   return true;
               }});
    table.add({"select", 1, 2,
               "select atmosphere|lights|fog|exposure|clouds|none | select volume|emitter|cloud_volume N",
               "select in the outliner", [this](W w, E error) {
                   double index = -1;
                   if (w.size() == 3 && !toNumber(w[2], index)) {
                       error = "select: bad index";
                       return false;
                   }
                   const Preset& p = doc_.preset();
                   if (w[1] == "volume" && index >= 0 && index < double(p.volumes.size()))
                       select({Selection::Kind::Volume, int(index)});
                   else if (w[1] == "emitter" && index >= 0 && index < double(p.emitters.size()))
                       select({Selection::Kind::Emitter, int(index)});
                   else if (w[1] == "cloud_volume" && index >= 0 && index < double(p.cloudVolumes.size()))
                       select({Selection::Kind::CloudVolume, int(index)});
                   else if (w[1] == "atmosphere")
                       select({Selection::Kind::Atmosphere, -1});
                   else if (w[1] == "lights")
                       select({Selection::Kind::Lights, -1});
                   else if (w[1] == "fog")
                       select({Selection::Kind::Fog, -1});
                   else if (w[1] == "exposure")
                       select({Selection::Kind::Exposure, -1});
                   else if (w[1] == "clouds")
                       select({Selection::Kind::Clouds, -1});
                   else if (w[1] == "none")
                       select({Selection::Kind::None, -1});
                   else {
                       error = "select: no such object";
                       return false;
                   }
                   return true;
               }});
    // Solo and mute (view only).
    const auto filterCommand = [this](bool solo) {
        return [this, solo](W w, E error) {
            if (w.size() == 2 && w[1] == "off") {
                edit_.viewFilter.clear();
                return true;
            }
            const ParamScope scope = w[1] == "volume"    ? ParamScope::Volume
                                     : w[1] == "emitter" ? ParamScope::Emitter
                                                         : ParamScope::Global;
            double index = -1;
            const Preset& p = doc_.preset();
            if (w.size() != 3 || scope == ParamScope::Global || !toNumber(w[2], index) || index < 0 ||
                index >= double(objectCount(p, scope))) {
                error = w[0] + ": " + w[0] + " volume|emitter N, or " + w[0] + " off";
                return false;
            }
            const std::string& id = scope == ParamScope::Volume ? p.volumes[std::size_t(index)].id
                                                                : p.emitters[std::size_t(index)].id;
            solo ? edit_.viewFilter.toggleSolo(scope, id) : edit_.viewFilter.toggleMute(scope, id);
            return true;
        };
    };
    table.add({"solo", 1, 2, "solo volume|emitter N | solo off",
               "show only that volume or emitter in the viewport (again: all); off ends solo and mute",
               filterCommand(true)});
    table.add({"mute", 1, 2, "mute volume|emitter N | mute off",
               "hide (again: show) that object in the viewport", filterCommand(false)});
    table.add({"print_drawn", 0, 0, "print_drawn",
               "prints \"drawn V volumes E emitters\" of the last viewport frame", [this](W, E) {
                   const renderer::RenderStats& s = view_.renderer->stats();
                   std::printf("drawn %d volumes %d emitters\n", s.volumesDrawn, s.emitters);
                   std::fflush(stdout);
                   return true;
               }});
    table.add({"set_id", 3, 3, "set_id volume|emitter|cloud_volume N ID",
               "change an object's id (its tracks follow; duplicates and bad characters refused)",
               [this](W w, E error) {
                   const ParamScope scope = w[1] == "volume"         ? ParamScope::Volume
                                            : w[1] == "emitter"      ? ParamScope::Emitter
                                            : w[1] == "cloud_volume" ? ParamScope::CloudVolume
                                                                     : ParamScope::Global;
                   double index = -1;
                   if (scope == ParamScope::Global || !toNumber(w[2], index)) {
                       error = "set_id: set_id volume|emitter|cloud_volume N ID";
                       return false;
                   }
                   std::string why;
                   Preset trial = doc_.preset();
                   if (!setObjectId(trial, scope, int(index), w[3], why)) {
                       error = "set_id: " + why;
                       return false;
                   }
                   doc_.apply("Change id", "",
                              [&](Preset& p) { setObjectId(p, scope, int(index), w[3], why); });
                   return true;
               }});
    table.add({"rename", 1, 1, "rename NAME", "rename the selected volume, emitter or cloud volume",
               [this](W w, E error) {
                   if (!edit_.objectSelected()) {
                       error = "rename: select a volume, an emitter or a cloud volume first";
                       return false;
                   }
                   const ParamScope scope = edit_.selection.scope();
                   const int index = edit_.selection.index;
                   doc_.apply("Rename", "", [&](Preset& p) { renameObject(p, scope, index, w[1]); });
                   return true;
               }});

    table.add({"place", 1, kAnyArgs, "place CITY",
               "set latitude, longitude and UTC offset from the city list", [this](W w, E error) {
                   std::string name = w[1];
                   for (std::size_t i = 2; i < w.size(); ++i) name += " " + w[i];
                   const Place* place = findPlace(name);
                   if (!place) {
                       error = "place: \"" + name + "\" is not in the city list";
                       return false;
                   }
                   doc_.apply("Place: " + std::string(place->name), "",
                              [&](Preset& p) { applyPlace(p.environment.location, *place); });
                   return true;
               }});

    // --- parameters and keys --------------------------------------------------------------
    table.add({"set", 2, kAnyArgs, "set KEY V...",
               "set a parameter as the inspector does (a key when animated)", [this, param](W w, E error) {
                   const std::optional<ParamRef> ref = param(w[1], error);
                   if (!ref) return false;
                   if (ref->desc->type == ParamType::String) {  // location.date
                       std::string why;
                       if (!editTextParam(doc_, *ref, w.size() > 2 ? w[2] : std::string(), why)) {
                           error = "set " + w[1] + ": " + why;
                           return false;
                       }
                       return true;
                   }
                   const int n = valueCount(*ref->desc);
                   const std::size_t argc = w.size() - 1;
                   double v[4] = {0, 0, 0, 0};
                   if (ref->desc->type == ParamType::Enum && argc == 2) {
                       bool found = false;
                       for (std::size_t i = 0; i < ref->desc->enumNames.size(); ++i)
                           if (ref->desc->enumNames[i] == w[2]) v[0] = double(i), found = true;
                       if (!found && !toNumber(w[2], v[0])) {
                           error = "set: \"" + w[2] + "\" is not a value of " + w[1];
                           return false;
                       }
                   } else {
                       if (int(argc) - 1 != n) {
                           error = "set: " + w[1] + " takes " + std::to_string(n) + " values";
                           return false;
                       }
                       for (int i = 0; i < n; ++i)
                           if (!toNumber(w[std::size_t(2 + i)], v[i])) {
                               error = "set: \"" + w[std::size_t(2 + i)] + "\" is not a number";
                               return false;
                           }
                   }
                   const std::string clamped = editParam(doc_, edit_, *ref, v, false, playback_.timeHours);
                   if (!clamped.empty()) setStatus(clamped);
                   edit_.selectedParam = ref;
                   return true;
               }});
    // The window's layout.
    const auto onOff = [this](const char* name, bool ViewportState::*flag) {
        return [this, name, flag](W w, E error) {
            if (w[1] != "on" && w[1] != "off") {
                error = std::string(name) + ": " + name + " on|off";
                return false;
            }
            view_.*flag = w[1] == "on";
            return true;
        };
    };
    table.add({"maximize_viewport", 1, 1, "maximize_viewport on|off", "hide the side panels and the timeline",
               onOff("maximize_viewport", &ViewportState::maximized)});
    table.add({"collapse", 2, 2, "collapse outliner|inspector|timeline on|off",
               "collapse a panel in place (its title bar stays) or expand it", [this](W w, E error) {
                   bool* flag = w[1] == "outliner"    ? &view_.outlinerCollapsed
                                : w[1] == "inspector" ? &view_.inspectorCollapsed
                                : w[1] == "timeline"  ? &view_.timelineCollapsed
                                                      : nullptr;
                   if (!flag || (w[2] != "on" && w[2] != "off")) {
                       error = "collapse: outliner, inspector or timeline, then on or off";
                       return false;
                   }
                   *flag = w[2] == "on";
                   return true;
               }});
    table.add({"game_view", 1, 1, "game_view on|off", "the picture without helpers (G)",
               onOff("game_view", &ViewportState::gameView)});
    table.add({"print_viewport", 0, 0, "print_viewport", "prints \"viewport WxH\" (the viewport's window)",
               [this](W, E) {
                   std::printf("viewport %dx%d\n", int(std::lround(view_.windowWidth)),
                               int(std::lround(view_.windowHeight)));
                   std::fflush(stdout);
                   return true;
               }});
    // Auto-key and the unkeyed changes (pending_edits.hpp).
    table.add({"autokey", 1, 1, "autokey on|off", "auto-key: every edit of an animated parameter keys it",
               [this](W w, E error) {
                   if (w[1] != "on" && w[1] != "off") {
                       error = "autokey: autokey on|off";
                       return false;
                   }
                   edit_.pending.autoKey = w[1] == "on";
                   return true;
               }});
    const auto pendingCommand = [this, param](bool key) {
        return [this, param, key](W w, E error) {
            std::vector<ParamRef> refs;
            if (w.size() > 1) {
                const std::optional<ParamRef> ref = param(w[1], error);
                if (!ref) return false;
                if (!edit_.pending.find(*ref)) {
                    error = w[0] + ": " + w[1] + " has no unkeyed change";
                    return false;
                }
                refs.push_back(*ref);
            } else {
                for (const PendingEdit& e : edit_.pending.all()) refs.push_back(e.ref);
            }
            for (const ParamRef& ref : refs) {
                if (key)
                    keyParamNow(doc_, edit_, ref, playback_.timeHours);
                else
                    edit_.pending.erase(ref);
            }
            return true;
        };
    };
    table.add({"key_pending", 0, 1, "key_pending [KEY]",
               "key the unkeyed change of KEY (all when none is named)", pendingCommand(true)});
    table.add({"revert_pending", 0, 1, "revert_pending [KEY]",
               "forget the unkeyed change of KEY (all when none is named)", pendingCommand(false)});
    table.add({"expect_pending", 1, 1, "expect_pending N", "how many unkeyed changes there are",
               [this](W w, E error) {
                   double n = -1;
                   if (!toNumber(w[1], n) || double(edit_.pending.size()) != n) {
                       error = "expect_pending: " + std::to_string(edit_.pending.size()) +
                               " unkeyed changes, want " + w[1];
                       return false;
                   }
                   return true;
               }});
    const auto keyCommand = [this, param](bool add) {
        return [this, param, add](W w, E error) {
            const std::optional<ParamRef> ref = param(w[1], error);
            if (!ref) return false;
            if (!ref->desc->animatable) {
                error = w[1] + " is not animatable";
                return false;
            }
            const double t = playback_.timeHours;
            if (add) {
                keyParamNow(doc_, edit_, *ref, t);
            } else {
                const Track* track = trackOf(doc_.preset(), *ref);
                const int index = track ? keyIndexAt(*track, t) : -1;
                if (index < 0) {
                    error = "unkey: no key of " + w[1] + " at this time";
                    return false;
                }
                const TrackTarget target = trackTargetOf(doc_.preset(), *ref);
                doc_.apply("Remove key", "", [&](Preset& p) { removeKey(p, target, index); });
            }
            edit_.selectedParam = ref;
            return true;
        };
    };
    table.add({"key", 1, 1, "key KEY", "key a parameter at the current time", keyCommand(true)});
    table.add(
        {"unkey", 1, 1, "unkey KEY", "remove a parameter's key at the current time", keyCommand(false)});
    table.add({"copy_key", 1, 1, "copy_key KEY", "the timeline's Copy: KEY's key at the current time",
               [this, param](W w, E error) {
                   const std::optional<ParamRef> ref = param(w[1], error);
                   if (!ref) return false;
                   const Track* track = trackOf(doc_.preset(), *ref);
                   const int index = track ? keyIndexAt(*track, playback_.timeHours) : -1;
                   if (index < 0) {
                       error = "copy_key: no key of " + w[1] + " at this time";
                       return false;
                   }
                   edit_.keyClipboard = {true, ref->desc->type, track->keys[std::size_t(index)].value};
                   return true;
               }});
    table.add({"paste_key", 1, 1, "paste_key KEY", "the timeline's Paste: a key of KEY at the current time",
               [this, param](W w, E error) {
                   const std::optional<ParamRef> ref = param(w[1], error);
                   if (!ref) return false;
                   const double t = playback_.timeHours;
                   bool ok = false;
                   const KeyClipboard clip = edit_.keyClipboard;
                   doc_.apply("Paste key", "", [&](Preset& p) { ok = pasteKey(p, *ref, clip, t); });
                   if (!ok) error = "paste_key: nothing copied, or a key of another kind";
                   return ok;
               }});
    table.add({"move_key", 3, 3, "move_key KEY FROM TO", "the timeline's key drag: one undo step",
               [this, param](W w, E error) {
                   const std::optional<ParamRef> ref = param(w[1], error);
                   double from, to;
                   if (!ref || !toTime(w[2], from) || !toTime(w[3], to)) {
                       if (error.empty()) error = "move_key: bad time";
                       return false;
                   }
                   const Track* track = trackOf(doc_.preset(), *ref);
                   const int index = track ? keyIndexAt(*track, from) : -1;
                   if (index < 0) {
                       error = "move_key: no key of " + w[1] + " at " + w[2];
                       return false;
                   }
                   const TrackTarget target = trackTargetOf(doc_.preset(), *ref);
                   const std::string merge = "move-key:" + w[1];
                   for (int step = 1; step <= 4; ++step) {  // a drag: several moves, one step
                       const double t = from + (to - from) * step / 4.0;
                       doc_.apply("Move key", merge, [&](Preset& p) {
                           if (Track* tr = findTrack(p, target)) moveKey(*tr, index, t);
                       });
                   }
                   doc_.closeMerge();
                   return true;
               }});
    table.add({"interp", 2, 2, "interp KEY step|linear|smooth", "a track's interpolation",
               [this, param](W w, E error) {
                   const std::optional<ParamRef> ref = param(w[1], error);
                   if (!ref) return false;
                   Interpolation interpolation;
                   if (!parseInterpolation(w[2], interpolation)) {
                       error = "interp: step, linear or smooth";
                       return false;
                   }
                   const TrackTarget target = trackTargetOf(doc_.preset(), *ref);
                   if (!findTrack(doc_.preset(), target)) {
                       error = "interp: " + w[1] + " has no track";
                       return false;
                   }
                   doc_.apply("Interpolation", "",
                              [&](Preset& p) { findTrack(p, target)->interpolation = interpolation; });
                   return true;
               }});
    table.add({"wrap", 2, 2, "wrap KEY on|off", "a track wraps through midnight (on) or holds its ends (off)",
               [this, param](W w, E error) {
                   const std::optional<ParamRef> ref = param(w[1], error);
                   if (!ref) return false;
                   const TrackTarget target = trackTargetOf(doc_.preset(), *ref);
                   if (!findTrack(doc_.preset(), target) || (w[2] != "on" && w[2] != "off")) {
                       error = "wrap: wrap KEY on|off, for a parameter with a track";
                       return false;
                   }
                   const bool wrap = w[2] == "on";
                   doc_.apply(wrap ? "Wrap at midnight" : "Hold the ends", "",
                              [&](Preset& p) { findTrack(p, target)->wrap = wrap; });
                   return true;
               }});
    table.add({"key_all_changed", 0, kAnyArgs, "key_all_changed",
               "key every parameter that differs from the saved preset", [this](W, E) {
                   std::printf("keyed %d parameters\n", keyAllChangedAt(doc_, playback_.timeHours));
                   return true;
               }});

    // --- time -------------------------------------------------------------------------
    table.add({"time", 1, 1, "time T", "jump to a time (hours or HH:MM)", [this](W w, E error) {
                   double t;
                   if (!toTime(w[1], t)) {
                       error = "time: \"" + w[1] + "\" is not HH:MM or hours in [0, 24]";
                       return false;
                   }
                   playback_.jumpTo(t);
                   return true;
               }});
    table.add({"scrub", 3, 3, "scrub FROM TO FRAMES", "scrub from FROM to TO over FRAMES frames",
               [this](W w, E error) {
                   double from, to, frames;
                   if (!toTime(w[1], from) || !toTime(w[2], to) || !toNumber(w[3], frames) || frames < 1) {
                       error = "scrub: bad arguments";
                       return false;
                   }
                   for (int k = 0; k <= int(frames); ++k)
                       runner_.times.push_back(std::min(from + (to - from) * k / frames, 24.0 - 1e-6));
                   return true;
               }});
    table.add({"play", 2, 2, "play SPEED FRAMES", "play at SPEED game hours per second for FRAMES frames",
               [this](W w, E error) {
                   double speed, frames;
                   if (!toNumber(w[1], speed) || !toNumber(w[2], frames) || frames < 1) {
                       error = "play: bad arguments";
                       return false;
                   }
                   playback_.speed = speed;
                   playback_.playing = true;
                   runner_.waitFrames = int(frames);
                   return true;
               }});
    table.add({"pause", 0, kAnyArgs, "pause", "stop playing", [this](W, E) {
                   playback_.playing = false;
                   return true;
               }});

    // --- viewport ------------------------------------------------------------------------
    table.add({"screenshot", 1, 1, "screenshot PATH.png|PATH.exr",
               "a full-resolution frame of the viewport; prints the selected volume's bounds in it",
               [this](W w, E error) {
                   if (!screenshot(w[1], error)) return false;
                   std::printf("screenshot %s %dx%d\n", w[1].c_str(), int(std::lround(view_.size.x)),
                               int(std::lround(view_.size.y)));
                   FogVolume shape;
                   if (selectedVolumeShape(shape)) {
                       // The selected (fog or cloud) volume's projected bounds in the screenshot's pixels.
                       const renderer::CameraFrame frame = viewportCameraFrame();
                       glm::dvec2 lo(1e30), hi(-1e30);
                       for (const WorldSegment& seg : volumeOutlineSegments(shape))
                           for (const glm::dvec3& p : {seg.first, seg.second})
                               if (std::optional<glm::dvec2> q = projectToViewport(frame, view_.size, p)) {
                                   lo = glm::min(lo, *q);
                                   hi = glm::max(hi, *q);
                               }
                       if (hi.x >= lo.x)
                           std::printf("selection_bounds %.1f %.1f %.1f %.1f\n", lo.x, lo.y, hi.x, hi.y);
                   }
                   std::fflush(stdout);
                   return true;
               }});
    table.add({"gizmo_drag", 4, 5,
               "gizmo_drag translate|rotate|scale x|y|z|yz|zx|xy|center|view DX DY [FRAMES]",
               "drag a gizmo handle of the selection by DX DY pixels (synthetic mouse, one move a frame)",
               [this](W w, E error) {
                   GizmoMode mode;
                   if (w[1] == "translate" || w[1] == "move")
                       mode = GizmoMode::Translate;
                   else if (w[1] == "rotate")
                       mode = GizmoMode::Rotate;
                   else if (w[1] == "scale")
                       mode = GizmoMode::Scale;
                   else {
                       error = "gizmo_drag: translate, rotate or scale";
                       return false;
                   }
                   const std::string& a = w[2];
                   const int axis = a == "x"                         ? 0
                                    : a == "y"                       ? 1
                                    : a == "z"                       ? 2
                                    : a == "yz"                      ? 3
                                    : a == "zx"                      ? 4
                                    : a == "xy"                      ? 5
                                    : a == "center" || a == "centre" ? 6
                                    : a == "view"                    ? 7
                                                                     : -1;
                   double dx, dy, frames = 8;
                   if (axis < 0 || !toNumber(w[3], dx) || !toNumber(w[4], dy) ||
                       (w.size() == 6 && !toNumber(w[5], frames))) {
                       error = "gizmo_drag: bad axis or distance";
                       return false;
                   }
                   return queueGizmoDrag(mode, axis, {dx, dy}, int(frames), error);
               }});
    table.add(
        {"click", 2, 2, "click X Y", "a left click at viewport pixel X Y (picks)", [this](W w, E error) {
             double x, y;
             if (!toNumber(w[1], x) || !toNumber(w[2], y)) {
                 error = "click: bad position";
                 return false;
             }
             view_.scriptedMouse.push_back({{x, y}, true, true, false});
             view_.scriptedMouse.push_back({{x, y}, false, false, true});
             view_.scriptedMouseActive = true;
             runner_.waitsForMouse = true;
             return true;
         }});
    table.add({"orbit", 2, 3, "orbit DX DY [FRAMES]", "a right drag in the viewport: the camera orbits",
               [this](W w, E error) {
                   double dx, dy, frames = 8;
                   if (!toNumber(w[1], dx) || !toNumber(w[2], dy) ||
                       (w.size() == 4 && !toNumber(w[3], frames)) || frames < 1) {
                       error = "orbit: bad arguments";
                       return false;
                   }
                   const glm::dvec2 start = view_.size * 0.5;
                   ScriptedMouse press{start, true, true, false, true};
                   view_.scriptedMouse.push_back(press);
                   for (int k = 1; k <= int(frames); ++k)
                       view_.scriptedMouse.push_back(
                           {start + glm::dvec2(dx, dy) * (double(k) / frames), true, false, false, true});
                   view_.scriptedMouse.push_back({start + glm::dvec2(dx, dy), false, false, true, true});
                   view_.scriptedMouseActive = true;
                   runner_.waitsForMouse = true;
                   return true;
               }});
    table.add({"print_camera", 0, kAnyArgs, "print_camera", "print the camera as JSON", [this](W, E) {
                   std::printf("camera %s\n", cameraStateToJson(view_.camera.state()).c_str());
                   return true;
               }});
    table.add({"gizmo_space", 1, 1, "gizmo_space world|local", "the gizmo's axes", [this](W w, E) {
                   view_.gizmoSpace = w[1] == "local" ? GizmoSpace::Local : GizmoSpace::World;
                   return true;
               }});
    table.add({"view", 1, 2, "view NAME | view clouds|shadows on|off | view fog preset|analytic|volumetric",
               "the OCIO view; or switch the view's cloud layer or sun shadows (View > Clouds, View > Sun "
               "shadows), or how it draws the fog (View > Fog ...)",
               [this](W w, E error) {
                   if (w.size() == 3) {
                       // In the frame's signature: the next frame shows it.
                       if (w[1] == "fog" &&
                           (w[2] == "preset" || w[2] == "analytic" || w[2] == "volumetric")) {
                           view_.fogView = w[2] == "preset"     ? ViewportState::FogView::Preset
                                           : w[2] == "analytic" ? ViewportState::FogView::Analytic
                                                                : ViewportState::FogView::Volumetric;
                           return true;
                       }
                       if ((w[1] != "clouds" && w[1] != "shadows") || (w[2] != "on" && w[2] != "off")) {
                           error = "view: view clouds|shadows on|off, or view fog preset|analytic|volumetric";
                           return false;
                       }
                       (w[1] == "clouds" ? view_.passes.clouds : view_.passes.shadows) = w[2] == "on";
                       return true;
                   }
                   view_.viewName = w[1];
                   rebuildDisplay();
                   if (view_.viewName != w[1]) {
                       error = "view: no OCIO view \"" + w[1] + "\"";
                       return false;
                   }
                   return true;
               }});
    table.add({"exposure", 1, 1, "exposure EV", "the view's exposure offset, on top of the preset's",
               [this](W w, E error) {
                   double ev;
                   if (!toNumber(w[1], ev)) {
                       error = "exposure: \"" + w[1] + "\" is not a number";
                       return false;
                   }
                   view_.exposureEv = ev;  // the next frame shows it (it is in the frame's signature)
                   return true;
               }});
    table.add({"resolution_scale", 1, 1, "resolution_scale S", "the viewport's resolution scale (0.1 .. 1)",
               [this](W w, E error) {
                   double s;
                   if (!toNumber(w[1], s) || s < 0.1 || s > 1.0) {
                       error = "resolution_scale: 0.1 .. 1";
                       return false;
                   }
                   view_.resolutionScale = s;
                   return true;
               }});
}

}  // namespace aerial::editor
