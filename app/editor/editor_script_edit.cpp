// editor/editor_script_edit.cpp — the actions only scripts run that edit
// the preset (objects, parameters, keys), the window's layout and the time:
// entries of the editor's action table (see editor_script.cpp), each
// through the code the panels use. Those of the viewport are in
// editor_script_view.cpp.
#include "editor.hpp"
#include "places.hpp"
#include "script_args.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace aerial::editor {

void Editor::declareEditScriptCommands() {
    ActionTable& table = actions_;
    using W = const ActionArgs&;
    using E = std::string&;
    const auto param = [this](const std::string& address, std::string& error) {
        return parseParamAddress(doc_.preset(), address, &error);
    };

    // --- objects ------------------------------------------------------------------------
    table.add("add_volume")
        .takes({choice("SHAPE", {"box", "ellipsoid"})})
        .helps("a fog volume in front of the camera")
        .handles([this](W w, E error) {
            if (w[1] != "box" && w[1] != "ellipsoid") {
                error = "add_volume: box or ellipsoid";
                return false;
            }
            actions_.run(w[1] == "box" ? "add_box_volume" : "add_ellipsoid_volume");
            const FogVolume& v = doc_.preset().volumes.back();
            std::printf("added volume %zu at %.17g %.17g %.17g\n", doc_.preset().volumes.size() - 1,
                        v.position.x, v.position.y, v.position.z);
            return true;
        });
    table.add("set_volume_mesh")
        .takes({count("INDEX"), word("FILE.gltf")})
        .helps("give fog volume INDEX the mesh of a glTF file (shape mesh)")
        .handles([this](W w, E error) {
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
        });
    table.add("add_emitter")
        .takes({choice("KIND", {"point", "lightning"})})
        .helps("an emitter in front of the camera")
        .handles([this](W w, E error) {
            if (w[1] != "point" && w[1] != "lightning") {
                error = "add_emitter: point or lightning";
                return false;
            }
            actions_.run(w[1] == "point" ? "add_point_emitter" : "add_lightning");
            return true;
        });
    table.add("add_cloud_volume")
        .takes({choice("SHAPE", {"box", "ellipsoid"})})
        .helps("a cloud volume in the cloud layer above the point the camera looks at")
        .handles([this](W w, E error) {
            if (w[1] != "box" && w[1] != "ellipsoid") {
                error = "add_cloud_volume: box or ellipsoid";
                return false;
            }
            actions_.run(w[1] == "box" ? "add_cloud_box" : "add_cloud_ellipsoid");
            const CloudVolume& v = doc_.preset().cloudVolumes.back();
            std::printf("added cloud volume %zu at %.17g %.17g %.17g\n",
                        doc_.preset().cloudVolumes.size() - 1, v.position.x, v.position.y, v.position.z);
            return true;
        });
    table.add("select")
        .takes({word("OBJECT"), count("N").opt()},
               "select atmosphere|lights|fog|exposure|clouds|none | select volume|emitter|cloud_volume N")
        .helps("select in the outliner")
        .handles([this](W w, E error) {
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
        });
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
    table.add("solo")
        .takes({word("OBJECT"), count("N").opt()}, "solo volume|emitter N | solo off")
        .helps("show only that volume or emitter in the viewport (again: all); off ends solo and mute")
        .handles(filterCommand(true));
    table.add("mute")
        .takes({word("OBJECT"), count("N").opt()}, "mute volume|emitter N | mute off")
        .helps("hide (again: show) that object in the viewport")
        .handles(filterCommand(false));
    table.add("print_drawn")
        .helps("prints \"drawn V volumes E emitters\" of the last viewport frame")
        .handles([this](W, E) {
            const renderer::RenderStats& s = view_.renderer->stats();
            std::printf("drawn %d volumes %d emitters\n", s.volumesDrawn, s.emitters);
            std::fflush(stdout);
            return true;
        });
    table.add("set_id")
        .takes({choice("KIND", {"volume", "emitter", "cloud_volume"}), count("N"), word("ID")})
        .helps("change an object's id (its tracks follow; duplicates and bad characters refused)")
        .handles([this](W w, E error) {
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
            doc_.apply("Change id", "", [&](Preset& p) { setObjectId(p, scope, int(index), w[3], why); });
            return true;
        });
    table.add("rename")
        .takes({word("NAME")})
        .helps("rename the selected volume, emitter or cloud volume")
        .handles([this](W w, E error) {
            if (!edit_.objectSelected()) {
                error = "rename: select a volume, an emitter or a cloud volume first";
                return false;
            }
            const ParamScope scope = edit_.selection.scope();
            const int index = edit_.selection.index;
            doc_.apply("Rename", "", [&](Preset& p) { renameObject(p, scope, index, w[1]); });
            return true;
        });

    table.add("place")
        .takes({rest("CITY")}, "place CITY")
        .helps("set latitude, longitude and UTC offset from the city list")
        .handles([this](W w, E error) {
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
        });

    // --- parameters and keys --------------------------------------------------------------
    table.add("set")
        .takes({word("KEY"), rest("V")})
        .helps("set a parameter as the inspector does (a key when animated)")
        .handles([this, param](W w, E error) {
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
        });
    // The window's layout.
    table.add("collapse")
        .takes({choice("PANEL", {"outliner", "inspector", "timeline"}), onOff()})
        .helps("collapse a panel in place (its title bar stays) or expand it")
        .handles([this](W w, E) {
            bool& flag = w[1] == "outliner"    ? view_.outlinerCollapsed
                         : w[1] == "inspector" ? view_.inspectorCollapsed
                                               : view_.timelineCollapsed;
            flag = w[2] == "on";
            return true;
        });
    table.add("print_viewport")
        .helps("prints \"viewport WxH\" (the viewport's window)")
        .handles([this](W, E) {
            std::printf("viewport %dx%d\n", int(std::lround(view_.windowWidth)),
                        int(std::lround(view_.windowHeight)));
            std::fflush(stdout);
            return true;
        });
    // Auto-key and the unkeyed changes (pending_edits.hpp).
    table.add("autokey")
        .takes({onOff()})
        .helps("auto-key: every edit of an animated parameter keys it")
        .handles([this](W w, E) {
            edit_.pending.autoKey = w[1] == "on";
            return true;
        });
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
    table.add("key_pending")
        .takes({word("KEY").opt()})
        .helps("key the unkeyed change of KEY (all when none is named)")
        .handles(pendingCommand(true));
    table.add("revert_pending")
        .takes({word("KEY").opt()})
        .helps("forget the unkeyed change of KEY (all when none is named)")
        .handles(pendingCommand(false));
    table.add("expect_pending")
        .takes({count("N")})
        .helps("how many unkeyed changes there are")
        .handles([this](W w, E error) {
            double n = -1;
            if (!toNumber(w[1], n) || double(edit_.pending.size()) != n) {
                error = "expect_pending: " + std::to_string(edit_.pending.size()) +
                        " unkeyed changes, want " + w[1];
                return false;
            }
            return true;
        });
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
    table.add("key")
        .takes({word("KEY")})
        .helps("key a parameter at the current time")
        .handles(keyCommand(true));
    table.add("unkey")
        .takes({word("KEY")})
        .helps("remove a parameter's key at the current time")
        .handles(keyCommand(false));
    table.add("copy_key")
        .takes({word("KEY")})
        .helps("the timeline's Copy: KEY's key at the current time")
        .handles([this, param](W w, E error) {
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
        });
    table.add("paste_key")
        .takes({word("KEY")})
        .helps("the timeline's Paste: a key of KEY at the current time")
        .handles([this, param](W w, E error) {
            const std::optional<ParamRef> ref = param(w[1], error);
            if (!ref) return false;
            const double t = playback_.timeHours;
            bool ok = false;
            const KeyClipboard clip = edit_.keyClipboard;
            doc_.apply("Paste key", "", [&](Preset& p) { ok = pasteKey(p, *ref, clip, t); });
            if (!ok) error = "paste_key: nothing copied, or a key of another kind";
            return ok;
        });
    table.add("move_key")
        .takes({word("KEY"), timeOfDay("FROM"), timeOfDay("TO")})
        .helps("the timeline's key drag: one undo step")
        .handles([this, param](W w, E error) {
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
        });
    table.add("interp")
        .takes({word("KEY"), choice("MODE", {"step", "linear", "smooth"})})
        .helps("a track's interpolation")
        .handles([this, param](W w, E error) {
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
        });
    table.add("wrap")
        .takes({word("KEY"), onOff()})
        .helps("a track wraps through midnight (on) or holds its ends (off)")
        .handles([this, param](W w, E error) {
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
        });

    // --- time -------------------------------------------------------------------------
    table.add("time")
        .takes({timeOfDay("T")})
        .helps("jump to a time (hours or HH:MM)")
        .handles([this](W w, E) {
            playback_.jumpTo(w.number(1));
            return true;
        });
    table.add("scrub")
        .takes({timeOfDay("FROM"), timeOfDay("TO"), number("FRAMES")})
        .helps("scrub from FROM to TO over FRAMES frames")
        .handles([this](W w, E error) {
            const double from = w.number(1), to = w.number(2), frames = w.number(3);
            if (frames < 1) {
                error = "scrub: FRAMES \"" + w[3] + "\" is less than 1";
                return false;
            }
            for (int k = 0; k <= int(frames); ++k)
                runner_.times.push_back(std::min(from + (to - from) * k / frames, 24.0 - 1e-6));
            return true;
        });
    table.add("play")
        .takes({number("SPEED"), number("FRAMES")})
        .helps("play at SPEED game hours per second for FRAMES frames")
        .handles([this](W w, E error) {
            const double speed = w.number(1), frames = w.number(2);
            if (frames < 1) {
                error = "play: FRAMES \"" + w[2] + "\" is less than 1";
                return false;
            }
            playback_.speed = speed;
            playback_.playing = true;
            runner_.waitFrames = int(frames);
            return true;
        });
    table.add("pause").ignoresExtraWords().helps("stop playing").handles([this](W, E) {
        playback_.playing = false;
        return true;
    });
}

}  // namespace aerial::editor
