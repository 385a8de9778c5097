// editor/editor_script_curves.cpp — the script commands of the timeline's
// curve view: show a curve, pick the inspector's parameter (inspect), select
// key points (one, or a box in time and normalised value), move them as a
// drag does (one undo step, snapped unless told not to; curve_snap sets the
// step), shift them by a typed time (curve_shift "+0:20", the Shift field),
// anchor them to a moment of the sun (curve_anchor sunset, the key menu's
// Follow the sun), type the selected keys' time and value (curve_time
// 19:52:00, curve_value 0.0031: the Time and Value fields), flat tangents,
// tangent handles (curve_tangent, curve_tangent_mode, curve_handle_drag with
// the mouse, print_tangents),
// zoom and pan; print a track's keys as the view reads them ("sunset + 0:20
// (19:52)"), what the Time and Value fields show, the legend (names and
// colours) and the day's sun events; and real mouse drags over the curve
// area (curve_drag, curve_drag_box: ImGui's mouse, frame by frame). Entries
// of the script command table (see editor_script.cpp) over the functions the
// curve view uses (curve_view.hpp).
#include "editor.hpp"
#include "script_args.hpp"

#include <aerial/clock.hpp>

#include <cstdio>

namespace aerial::editor {

void Editor::declareCurveScriptCommands() {
    ActionTable& table = actions_;
    using W = const ActionArgs&;
    using E = std::string&;
    // The target of an animated parameter, or nullopt with `error` set.
    const auto animated = [this](const std::string& address,
                                 std::string& error) -> std::optional<TrackTarget> {
        const std::optional<ParamRef> ref = parseParamAddress(doc_.preset(), address, &error);
        if (!ref) return std::nullopt;
        const TrackTarget target = trackTargetOf(doc_.preset(), *ref);
        if (!findTrack(doc_.preset(), target)) {
            error = address + " has no track";
            return std::nullopt;
        }
        return target;
    };

    // A left drag over the timeline's real widgets (ImGui's mouse, one
    // frame each): hover, press, `frames` moves, release.
    const auto queueDrag = [this](glm::dvec2 from, glm::dvec2 to, bool ctrl, bool shift, int frames) {
        runner_.guiMouse.push_back({from, false, ctrl, shift});
        runner_.guiMouse.push_back({from, true, ctrl, shift});
        for (int k = 1; k <= frames; ++k)
            runner_.guiMouse.push_back({from + (to - from) * (double(k) / frames), true, ctrl, shift});
        runner_.guiMouse.push_back({to, false, ctrl, shift});
        runner_.guiMouse.push_back({to, false, false, false});
    };
    // Window pixels of time `t` [h] and height `n` (0 bottom, 1 top of a curve).
    const auto pixelOf = [this](double t, double n) {
        const CurveViewState& v = edit_.curves;
        return glm::dvec2(v.time.xOf(t, v.drawnX0, v.drawnX1),
                          v.drawnBottom + n * (v.drawnTop - v.drawnBottom));
    };

    table.add("curve")
        .takes({word("KEY"), onOff()})
        .helps("show or hide KEY's curve in the timeline (the inspector's curve button)")
        .handles([this, animated](W w, E error) {
            const std::optional<TrackTarget> target = animated(w[1], error);
            if (!target) return false;
            edit_.curves.setShown(*target, w[2] == "on");
            return true;
        });
    table.add("curve_select")
        .takes({word("KEY"), timeOfDay("T").opt(), number("COMPONENT").opt()},
               "curve_select KEY T [COMPONENT] | curve_select none")
        .helps("add the key of KEY at time T (component 0, 1, 2) to the curve selection, as Ctrl+click does")
        .handles([this, animated](W w, E error) {
            if (w[1] == "none") {
                edit_.curves.selected.clear();
                return true;
            }
            const std::optional<TrackTarget> target = animated(w[1], error);
            double t = 0.0, component = 0.0;
            if (!target || w.size() < 3 || !toTime(w[2], t) ||
                (w.size() == 4 && (!toNumber(w[3], component) || component < 0.0 || component > 2.0))) {
                if (error.empty()) error = "curve_select: curve_select KEY T [COMPONENT]";
                return false;
            }
            const int key = keyIndexAt(*findTrack(doc_.preset(), *target), t);
            if (key < 0) {
                error = "curve_select: no key of " + w[1] + " at " + w[2];
                return false;
            }
            const CurvePoint point{*target, key, int(component)};
            if (!edit_.curves.isSelected(point)) edit_.curves.selected.push_back(point);
            return true;
        });
    table.add("inspect")
        .takes({word("KEY")})
        .helps(
            "select KEY's row in the inspector without changing it: the timeline's track and the curve "
            "view's own curve (drawn on top, its keys picked first where keys overlap, its value axis)")
        .handles([this](W w, E error) {
            const std::optional<ParamRef> ref = parseParamAddress(doc_.preset(), w[1], &error);
            if (!ref) return false;
            if (!(edit_.selectedParam && *edit_.selectedParam == *ref)) edit_.selectedKey = -1;
            edit_.selectedParam = ref;
            return true;
        });
    table.add("curve_box")
        .takes({timeOfDay("FROM"), timeOfDay("TO"), number("LO").opt(), number("HI").opt()},
               "curve_box FROM TO [LO HI]")
        .helps(
            "select the keys of the shown curves from time FROM to TO and, optionally, from LO to HI of "
            "each curve's height (0 bottom, 1 top), as a drag on empty curve area does")
        .handles([this](W w, E error) {
            double from, to, lo = -1.0, hi = 2.0;
            if (!toTime(w[1], from) || !toTime(w[2], to) || w.size() == 4 ||
                (w.size() == 5 && (!toNumber(w[3], lo) || !toNumber(w[4], hi)))) {
                error = "curve_box: curve_box FROM TO [LO HI]";
                return false;
            }
            std::vector<TrackTarget> targets = edit_.curves.shown;
            if (edit_.selectedParam) {
                const TrackTarget primary = trackTargetOf(doc_.preset(), *edit_.selectedParam);
                if (!edit_.curves.isShown(primary)) targets.push_back(primary);
            }
            const CurveKeyPoints points = keyPointsOf(doc_.preset(), targets, edit_.curves);
            edit_.curves.selected.clear();
            for (int i : pointsInBox(points.timeValue, {from, lo}, {to, hi}))
                edit_.curves.selected.push_back(points.ids[std::size_t(i)]);
            std::printf("curve_box: %zu points, %d keys\n", edit_.curves.selected.size(),
                        keyCountOf(edit_.curves.selected));
            return true;
        });
    table.add("curve_move")
        .takes({number("DT"), number("DV"), choice("free", {"free"}).opt()})
        .helps(
            "move the selected keys as a drag on the curves does: DT hours (the first selected key "
            "snaps to keys and the snap step, curve_snap, unless free) and DV of each curve's height; "
            "one undo step")
        .handles([this](W w, E error) {
            double dt, dv;
            if (!toNumber(w[1], dt) || !toNumber(w[2], dv) || (w.size() == 4 && w[3] != "free")) {
                error = "curve_move: curve_move DT DV [free]";
                return false;
            }
            // As a drag: the curves keep the ranges they are drawn in (pinned).
            for (const CurvePoint& p : edit_.curves.selected) edit_.curves.pinRange(doc_.preset(), p.target);
            const std::vector<CurveDragItem> items =
                dragItemsOf(doc_.preset(), edit_.curves.selected, edit_.curves);
            if (items.empty()) {
                error = "curve_move: no keys selected";
                return false;
            }
            const CurveDragItem& lead = items.front();
            double shift = dt;
            if (w.size() == 3) {  // 6 px at the whole day on a 1000 px strip
                const double t =
                    snapKeyTime(doc_.preset(), lead.point.target, lead.point.key, lead.timeHours + dt,
                                6.0 * 24.0 / 1000.0, edit_.curves.snapHours);
                shift = t - lead.timeHours;
                if (shift - dt > 12.0) shift -= 24.0;
            }
            std::vector<CurvePoint> moved;
            for (const CurveDragItem& item : items) moved.push_back(item.point);
            double applied = 0.0;
            for (int step = 1; step <= 4; ++step)  // a drag: several moves, one step
                doc_.apply(moveLabel(moved), "curve-move", [&](Preset& p) {
                    applied = moveCurvePoints(p, items, shift * step / 4.0, dv * step / 4.0);
                });
            doc_.closeMerge();
            std::printf("curve_move: %s by %.6g h\n", moveLabel(moved).c_str(), applied);
            return true;
        });
    table.add("curve_snap")
        .takes({number("MINUTES")})
        .helps("the step dragged keys snap to: 1, 5, 15 or 60 minutes (the curve view's Snap)")
        .handles([this](W w, E error) {
            double minutes = 0.0;
            bool offered = false;
            if (toNumber(w[1], minutes))
                for (int m : kSnapStepsMinutes) offered = offered || minutes == m;
            if (!offered) {
                error = "curve_snap: curve_snap 1|5|15|60";
                return false;
            }
            edit_.curves.snapHours = minutes / 60.0;
            return true;
        });
    table.add("curve_shift")
        .takes({word("AMOUNT")})
        .helps(
            "shift the selected keys by AMOUNT, typed as in the Shift field (+0:20, -1:00, 0:05, "
            "-0.25 hours): limited as a drag is, keys that follow the sun keep their event; one undo "
            "step; prints \"curve_shift: Shift 2 keys by H h\"")
        .handles([this](W w, E error) {
            double dt = 0.0;
            if (!parseShiftHours(w[1], dt)) {
                error = "curve_shift: \"" + w[1] + "\" is not a time shift (+0:20, -1:00, -0.25)";
                return false;
            }
            const std::vector<CurvePoint> picked = edit_.curves.selected;
            if (dragItemsOf(doc_.preset(), picked).empty()) {
                error = "curve_shift: no keys selected";
                return false;
            }
            edit_.curves.shiftText = w[1];
            double applied = 0.0;
            doc_.apply(shiftLabel(picked), "", [&](Preset& p) { applied = shiftCurvePoints(p, picked, dt); });
            edit_.curves.validate(doc_.preset());
            std::printf("curve_shift: %s by %.6g h\n", shiftLabel(picked).c_str(), applied);
            return true;
        });
    table.add("curve_time")
        .takes({word("TIME")})
        .helps(
            "type TIME (HH:MM:SS, HH:MM or hours) into the curve view's Time field: the first selected "
            "key goes there, the other selected keys shift with it, limited as a drag is (keys that "
            "follow the sun keep their event, their offset changes); one undo step; prints "
            "\"curve_time: Set key time, now HH:MM:SS\"")
        .handles([this](W w, E error) {
            double t = 0.0;
            if (!parseClock(w[1], t)) {
                error = "curve_time: \"" + w[1] + "\" is not a time of day (19:52:00, 19:52, 19.5)";
                return false;
            }
            const std::vector<CurvePoint> picked = edit_.curves.selected;
            if (!leadPointOf(doc_.preset(), picked)) {
                error = "curve_time: no keys selected";
                return false;
            }
            double now = 0.0;
            doc_.apply(setTimeLabel(picked), "", [&](Preset& p) { now = setCurvePointsTime(p, picked, t); });
            edit_.curves.validate(doc_.preset());
            std::printf("curve_time: %s, now %s\n", setTimeLabel(picked).c_str(), keyClockText(now).c_str());
            return true;
        });
    table.add("curve_value")
        .takes({word("VALUE")})
        .helps(
            "type VALUE (a number, the unit optional) into the curve view's Value field: every selected "
            "key of the first selected key's parameter gets it, clamped into the valid range; one undo "
            "step; prints \"curve_value: Set key value (N changed)\"")
        .handles([this](W w, E error) {
            const std::vector<CurvePoint> picked = edit_.curves.selected;
            const std::optional<CurvePoint> lead = leadPointOf(doc_.preset(), picked);
            if (!lead) {
                error = "curve_value: no keys selected";
                return false;
            }
            const ParamDesc& desc = *findParam(lead->target.scope, lead->target.param);
            double v = 0.0;
            if (!parseKeyValue(w[1], desc.unit, v)) {
                error = "curve_value: \"" + w[1] + "\" is not a number";
                return false;
            }
            for (const CurvePoint& p : picked) edit_.curves.pinRange(doc_.preset(), p.target);
            const std::string label = setValueLabel(doc_.preset(), picked);
            int changed = 0;
            doc_.apply(label, "", [&](Preset& p) { changed = setCurvePointsValue(p, picked, v); });
            std::printf("curve_value: %s (%d changed)\n", label.c_str(), changed);
            return true;
        });
    table.add("print_curve_fields")
        .helps(
            "prints what the curve view's Time and Value fields show for the selection: \"curve_fields "
            "TIME VALUE [UNIT]\" (\"curve_fields - -\" when no key is selected)")
        .handles([this](W, E) {
            const std::optional<CurvePoint> lead = leadPointOf(doc_.preset(), edit_.curves.selected);
            if (!lead) {
                std::printf("curve_fields - -\n");
                return true;
            }
            const TrackKey& k = findTrack(doc_.preset(), lead->target)->keys[std::size_t(lead->key)];
            const ParamDesc& desc = *findParam(lead->target.scope, lead->target.param);
            std::printf("curve_fields %s %s\n", keyClockText(k.timeHours).c_str(),
                        valueWithUnit(k.value[lead->component], desc.unit, 6).c_str());
            return true;
        });
    table.add("print_legend")
        .helps(
            "prints a line per curve the view shows (those toggled on, then the inspector's parameter): "
            "\"legend KEY PALETTE_INDEX NAME\", NAME as the legend reads it (\"Haze bank density\")")
        .handles([this](W, E) {
            const std::vector<TrackTarget> targets = shownCurveTargets(doc_.preset(), edit_);
            const std::vector<int> palette = curvePaletteIndices(targets, kCurvePaletteSize);
            for (std::size_t i = 0; i < targets.size(); ++i)
                std::printf("legend %s %d %s\n", curveKey(targets[i]).c_str(), palette[i],
                            curveLabel(doc_.preset(), targets[i]).c_str());
            return true;
        });
    table.add("curve_anchor")
        .takes({word("EVENT")}, "curve_anchor EVENT|fixed")
        .helps(
            "the key menu's Follow the sun: the selected keys follow EVENT (sunrise, noon, sunset, "
            "civil_dawn, civil_dusk, nautical_dawn, nautical_dusk) where they stand, or have a fixed "
            "time again; one undo step")
        .handles([this](W w, E error) {
            static const std::string kEvents =
                "sunrise, noon, sunset, civil_dawn, civil_dusk, nautical_dawn, nautical_dusk";
            std::optional<SunEvent> event;
            if (w[1] != "fixed") {
                SunEvent parsed;
                if (!parseSunEvent(w[1], parsed)) {
                    error = "curve_anchor: \"" + w[1] + "\" is not an event (" + kEvents + ") or fixed";
                    return false;
                }
                event = parsed;
            }
            const std::vector<CurvePoint> picked = edit_.curves.selected;
            if (dragItemsOf(doc_.preset(), picked).empty()) {
                error = "curve_anchor: no keys selected";
                return false;
            }
            int changed = 0;
            doc_.apply(anchorLabel(picked, event), "",
                       [&](Preset& p) { changed = anchorCurvePoints(p, picked, event); });
            edit_.curves.validate(doc_.preset());
            std::printf("curve_anchor: %s (%d changed)\n", anchorLabel(picked, event).c_str(), changed);
            return true;
        });
    table.add("curve_interp")
        .takes({choice("MODE", {"step", "linear", "smooth", "track"})})
        .helps(
            "the key menu's Interpolation after: the segment after each selected key is step, linear or "
            "smooth, or the track's again; one undo step")
        .handles([this](W w, E error) {
            std::optional<Interpolation> mode;
            if (w[1] != "track") {
                Interpolation parsed;
                if (!parseInterpolation(w[1], parsed)) {
                    error = "curve_interp: \"" + w[1] + "\" is not step, linear, smooth or track";
                    return false;
                }
                mode = parsed;
            }
            const std::vector<CurvePoint> picked = edit_.curves.selected;
            if (dragItemsOf(doc_.preset(), picked).empty()) {
                error = "curve_interp: no keys selected";
                return false;
            }
            int changed = 0;
            doc_.apply("Interpolation: " + w[1], "",
                       [&](Preset& p) { changed = setKeyInterpolation(p, picked, mode); });
            std::printf("curve_interp: %s (%d changed)\n", w[1].c_str(), changed);
            return true;
        });
    table.add("print_keys")
        .takes({word("KEY")})
        .helps(
            "prints a line per key of KEY's track: \"key INDEX TIME_H TEXT\", TEXT as the curve view "
            "reads it (\"19:30\", \"sunset + 0:20 (19:52)\")")
        .handles([this, animated](W w, E error) {
            const std::optional<TrackTarget> target = animated(w[1], error);
            if (!target) return false;
            const Track& track = *findTrack(doc_.preset(), *target);
            for (std::size_t k = 0; k < track.keys.size(); ++k)
                std::printf("key %zu %.9f %s\n", k, track.keys[k].timeHours,
                            keyTimeText(track.keys[k]).c_str());
            return true;
        });
    table.add("print_tangents")
        .takes({word("KEY")})
        .helps(
            "prints a line per key of KEY's track: \"tangent INDEX TIME_H MODE IN OUT\", MODE unified, "
            "broken or "
            "auto (automatic), IN and OUT the first component's slopes as the curve uses them [unit per h]")
        .handles([this, animated](W w, E error) {
            const std::optional<TrackTarget> target = animated(w[1], error);
            if (!target) return false;
            const Track& track = *findTrack(doc_.preset(), *target);
            const ParamDesc* desc = findParam(target->scope, target->param);
            const CompiledTrack compiled = compileTrack(track, desc ? desc->components() : 3);
            for (std::size_t k = 0; k < track.keys.size(); ++k) {
                const std::optional<KeyTangents>& own = track.keys[k].tangents;
                const char* mode = !own ? "auto" : own->mode == TangentMode::Broken ? "broken" : "unified";
                const bool slopes = compiled.tangentsIn.size() == track.keys.size();
                std::printf("tangent %zu %.9f %s %.9g %.9g\n", k, track.keys[k].timeHours, mode,
                            slopes ? compiled.tangentsIn[k].x : 0.0, slopes ? compiled.tangents[k].x : 0.0);
            }
            return true;
        });
    table.add("print_sun")
        .helps(
            "prints the day's sun events at the preset's location and date, a line each: \"sun EVENT "
            "TIME_H\" (what keys that follow the sun are placed by)")
        .handles([this](W, E) {
            for (SunEvent event : kSunEvents)
                std::printf("sun %s %.9f\n", sunEventName(event),
                            sunEventHours(doc_.preset().environment.location, event));
            return true;
        });
    table.add("curve_drag")
        .takes({word("KEY"), timeOfDay("T"), number("DX"), number("DY"),
                choice("MODIFIER", {"shift", "ctrl"}).opt()})
        .helps(
            "drag the key of KEY at time T (its first component) on the curves by DX DY pixels with the "
            "mouse, holding Shift (no snapping) or Ctrl (add to the selection)")
        .handles([this, animated, queueDrag, pixelOf](W w, E error) {
            const std::optional<TrackTarget> target = animated(w[1], error);
            double t, dx, dy;
            if (!target || !toTime(w[2], t) || !toNumber(w[3], dx) || !toNumber(w[4], dy) ||
                (w.size() == 6 && w[5] != "shift" && w[5] != "ctrl")) {
                if (error.empty()) error = "curve_drag: curve_drag KEY T DX DY [shift|ctrl]";
                return false;
            }
            const bool primary =
                edit_.selectedParam && trackTargetOf(doc_.preset(), *edit_.selectedParam) == *target;
            if (!edit_.curves.isShown(*target) && !primary) {
                error = "curve_drag: the curve of " + w[1] + " is not shown (curve KEY on)";
                return false;
            }
            if (!(edit_.curves.drawnX1 > edit_.curves.drawnX0) ||
                !(edit_.curves.drawnBottom > edit_.curves.drawnTop)) {
                error = "curve_drag: the timeline's curve area is not shown";
                return false;
            }
            const Track& track = *findTrack(doc_.preset(), *target);
            const int key = keyIndexAt(track, t);
            if (key < 0) {
                error = "curve_drag: no key of " + w[1] + " at " + w[2];
                return false;
            }
            const TrackKey& k = track.keys[std::size_t(key)];
            const glm::dvec2 at =
                pixelOf(k.timeHours, edit_.curves.rangeOf(doc_.preset(), *target).normalised(k.value.x));
            const bool shift = w.size() == 6 && w[5] == "shift", ctrl = w.size() == 6 && w[5] == "ctrl";
            queueDrag(at, at + glm::dvec2(dx, dy), ctrl, shift, 8);
            std::printf("curve_drag: press at %.1f %.1f\n", at.x, at.y);
            return true;
        });
    table.add("curve_drag_box")
        .takes({timeOfDay("T0"), number("N0"), timeOfDay("T1"), number("N1"), choice("ctrl", {"ctrl"}).opt()})
        .helps(
            "a mouse drag on the curve area from time T0, height N0 (0 bottom, 1 top) to T1, N1: on "
            "empty area it selects the keys in the box (Ctrl adds); where it does not move, a click "
            "that sets the time")
        .handles([queueDrag, pixelOf](W w, E error) {
            double t0, n0, t1, n1;
            if (!toTime(w[1], t0) || !toNumber(w[2], n0) || !toTime(w[3], t1) || !toNumber(w[4], n1) ||
                (w.size() == 6 && w[5] != "ctrl")) {
                error = "curve_drag_box: curve_drag_box T0 N0 T1 N1 [ctrl]";
                return false;
            }
            queueDrag(pixelOf(t0, n0), pixelOf(t1, n1), w.size() == 6, false, 6);
            return true;
        });
    table.add("curve_wheel")
        .takes({number("T"), number("STEPS")})
        .helps("turn the mouse wheel STEPS steps (up: zoom in) over the curve area at time T")
        .handles([this, pixelOf](W w, E) {
            const double t = w.number(1), steps = w.number(2);
            const glm::dvec2 at = pixelOf(t, 0.5);
            runner_.guiMouse.push_back({at, false, false, false, false, 0.0f});
            runner_.guiMouse.push_back({at, false, false, false, false, float(steps)});
            runner_.guiMouse.push_back({at, false, false, false, false, 0.0f});
            return true;
        });
    table.add("curve_pan_drag")
        .takes({number("T"), number("DX")})
        .helps("a middle drag over the curve area from time T by DX pixels: pans the time")
        .handles([this, pixelOf](W w, E) {
            const double t = w.number(1), dx = w.number(2);
            const glm::dvec2 from = pixelOf(t, 0.5);
            runner_.guiMouse.push_back({from, false, false, false, false, 0.0f});
            for (int k = 0; k <= 6; ++k)
                runner_.guiMouse.push_back(
                    {from + glm::dvec2(dx * k / 6.0, 0.0), false, false, false, true, 0.0f});
            runner_.guiMouse.push_back({from + glm::dvec2(dx, 0.0), false, false, false, false, 0.0f});
            return true;
        });
    table.add("curve_flat")
        .takes({onOff()})
        .helps("flat (on) or automatic (off) tangents at the selected keys, as the key menu does")
        .handles([this](W w, E) {
            const bool flat = w[1] == "on";
            const std::vector<CurvePoint> picked = edit_.curves.selected;
            const bool one = keyCountOf(picked) == 1;
            doc_.apply(flat ? (one ? "Flat tangent" : "Flat tangents")
                            : (one ? "Automatic tangent" : "Automatic tangents"),
                       "", [&](Preset& p) { setFlatTangents(p, picked, flat); });
            return true;
        });
    // The one selected key point whose handles a tangent command works on, or nullopt with `error`.
    const auto handleKey = [this](const char* command, std::string& error) -> std::optional<CurvePoint> {
        const std::vector<CurvePoint>& picked = edit_.curves.selected;
        if (picked.size() != 1 || dragItemsOf(doc_.preset(), picked).empty()) {
            error = std::string(command) + ": select one key point first (curve_select KEY T [COMPONENT])";
            return std::nullopt;
        }
        return picked.front();
    };
    table.add("curve_tangent")
        .takes({choice("SIDE", {"in", "out"}), number("SLOPE")})
        .helps(
            "set the selected key's tangent slope arriving (in) or leaving (out) to SLOPE [value unit per "
            "h], as dragging that handle does (unified handles: both sides); one undo step")
        .handles([this, handleKey](W w, E error) {
            const std::optional<CurvePoint> point = handleKey("curve_tangent", error);
            const double slope = w.number(2);
            if (!point) return false;
            const TangentSide side = w[1] == "in" ? TangentSide::In : TangentSide::Out;
            doc_.apply("Tangent", "", [&](Preset& p) { setKeyTangent(p, *point, side, slope); });
            return true;
        });
    table.add("curve_tangent_mode")
        .takes({choice("MODE", {"unified", "broken", "auto"})})
        .helps(
            "the selected keys' handles unified (one slope, the mean of the two), broken (two) or "
            "automatic again (the key menu's Automatic tangent); one undo step")
        .handles([this](W w, E error) {
            const std::vector<CurvePoint> picked = edit_.curves.selected;
            if (dragItemsOf(doc_.preset(), picked).empty()) {
                error = "curve_tangent_mode: no keys selected";
                return false;
            }
            int changed = 0;
            if (w[1] == "auto") {
                doc_.apply(keyCountOf(picked) == 1 ? "Automatic tangent" : "Automatic tangents", "",
                           [&](Preset& p) { changed = setFlatTangents(p, picked, false); });
            } else {
                const TangentMode mode = w[1] == "broken" ? TangentMode::Broken : TangentMode::Unified;
                doc_.apply(tangentModeLabel(picked, mode), "",
                           [&](Preset& p) { changed = setTangentMode(p, picked, mode); });
            }
            std::printf("curve_tangent_mode: %s (%d changed)\n", w[1].c_str(), changed);
            return true;
        });
    table.add("curve_handle_drag")
        .takes({choice("SIDE", {"in", "out"}), number("DX"), number("DY")})
        .helps(
            "drag the selected key's in or out tangent handle by DX DY pixels with the mouse (the key "
            "must be selected, its curve shown and its segment on that side smooth)")
        .handles([this, handleKey, queueDrag, pixelOf](W w, E error) {
            const std::optional<CurvePoint> point = handleKey("curve_handle_drag", error);
            if (!point) return false;
            const CurveViewState& v = edit_.curves;
            if (!(v.drawnX1 > v.drawnX0) || !(v.drawnBottom > v.drawnTop)) {
                error = "curve_handle_drag: the timeline's curve area is not shown";
                return false;
            }
            const Track& track = *findTrack(doc_.preset(), point->target);
            const ParamDesc* desc = findParam(point->target.scope, point->target.param);
            const CompiledTrack compiled = compileTrack(track, desc ? desc->components() : 3);
            const std::size_t k = std::size_t(point->key);
            if (compiled.tangentsIn.size() != track.keys.size()) {
                error = "curve_handle_drag: the key has no smooth segment";
                return false;
            }
            const TangentSide side = w[1] == "in" ? TangentSide::In : TangentSide::Out;
            const double slope = side == TangentSide::Out ? compiled.tangents[k][point->component]
                                                          : compiled.tangentsIn[k][point->component];
            const CurveRange range = v.rangeOf(doc_.preset(), point->target);
            const TrackKey& key = track.keys[k];
            const double pxPerHour = (v.drawnX1 - v.drawnX0) / v.time.span();
            const glm::dvec2 from =
                pixelOf(key.timeHours, range.normalised(key.value[point->component])) +
                tangentHandleOffset(slope, range, pxPerHour, v.drawnBottom - v.drawnTop, side);
            queueDrag(from, from + glm::dvec2(w.number(2), w.number(3)), false, false, 8);
            std::printf("curve_handle_drag: press at %.1f %.1f\n", from.x, from.y);
            return true;
        });
    table.add("curve_zoom")
        .takes({number("FACTOR"), number("T")})
        .helps("zoom the timeline by FACTOR (> 1 in) around time T [h], as the wheel does")
        .handles([this](W w, E error) {
            const double factor = w.number(1), t = w.number(2);
            if (!(factor > 0.0)) {
                error = "curve_zoom: FACTOR \"" + w[1] + "\" is not above 0";
                return false;
            }
            edit_.curves.time = zoomView(edit_.curves.time, t, factor);
            return true;
        });
    table.add("curve_pan")
        .takes({number("HOURS")})
        .helps("pan the timeline by HOURS (a middle drag)")
        .handles([this](W w, E) {
            edit_.curves.time = panView(edit_.curves.time, w.number(1));
            return true;
        });
    table.add("print_curves")
        .helps("prints \"curves view START END shown N selected M time T\"")
        .handles([this](W, E) {
            std::printf("curves view %.6g %.6g shown %zu selected %zu time %.6g\n",
                        edit_.curves.time.startHours, edit_.curves.time.endHours, edit_.curves.shown.size(),
                        edit_.curves.selected.size(), playback_.timeHours);
            return true;
        });
}

}  // namespace aerial::editor
