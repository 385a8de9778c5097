// editor/editor_timeline.cpp — the timeline along the bottom: controls
// (play/pause, speed in game hours per real second, loop, jump to sunrise,
// noon, sunset, the time as HH:MM), a 00:00-24:00 ruler to scrub on, a
// summary row of every key in the preset, the selected parameter's track
// (select, drag in time, double-click to add, right-click to delete, flatten
// its tangent, make it follow the sun or set the interpolation; Delete, Ctrl+C / Ctrl+V while the
// mouse is over the timeline are the action table's timeline_delete_keys,
// timeline_copy_key and timeline_paste_key: Ctrl+C copies the keys selected
// on the curves, of one curve or several, else the track row's key, and
// Ctrl+V pastes them at the time, each onto its own curve; a key that follows the sun is a
// round mark with rays, "sunset + 0:20 (19:52)") and the curve area
// (editor_curves.cpp). The time axis zooms
// with the wheel around the mouse and pans with a middle or Alt drag; F or
// a double-click on the ruler fits it to the day again.
#include "panels.hpp"

#include <aerial/clock.hpp>

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <string>

namespace aerial::editor {
namespace {

/// The time field and tooltips show the minute that has begun, as a clock.
std::string clock(double hours) { return formatClock(hours, ClockResolution::Minutes); }

void diamond(ImDrawList* dl, ImVec2 c, float r, ImU32 colour, bool filled) {
    const ImVec2 p[4] = {ImVec2(c.x, c.y - r), ImVec2(c.x + r, c.y), ImVec2(c.x, c.y + r),
                         ImVec2(c.x - r, c.y)};
    if (filled)
        dl->AddConvexPolyFilled(p, 4, colour);
    else
        dl->AddPolyline(p, 4, colour, ImDrawFlags_Closed, 1.5f);
}

}  // namespace

bool deleteTimelineKeys(Document& doc, EditState& edit) {
    // The keys selected on the curves, else the track row's key.
    if (const std::vector<CurvePoint> picked = edit.curves.selected; !picked.empty()) {
        doc.apply(deleteLabel(picked), "", [&](Preset& p) { removeCurvePoints(p, picked); });
        edit.curves.selected.clear();
        edit.selectedKey = -1;
        return true;
    }
    const Track* track = edit.selectedParam ? trackOf(doc.preset(), *edit.selectedParam) : nullptr;
    if (!track || edit.selectedKey < 0 || edit.selectedKey >= int(track->keys.size())) return false;
    const TrackTarget target = trackTargetOf(doc.preset(), *edit.selectedParam);
    const int key = edit.selectedKey;
    doc.apply("Delete key", "", [&](Preset& p) { removeKey(p, target, key); });
    edit.selectedKey = -1;
    return true;
}

bool copyTimelineKey(const Document& doc, EditState& edit) {
    // The keys selected on the curves (several curves, their times relative), else the track row's key.
    if (CurveClipboard copied = copyCurvePoints(doc.preset(), edit.curves.selected); !copied.empty()) {
        edit.curveClipboard = std::move(copied);
        edit.keyClipboard = KeyClipboard{};
        return true;
    }
    const Track* t = edit.selectedParam ? trackOf(doc.preset(), *edit.selectedParam) : nullptr;
    if (!t || edit.selectedKey < 0 || edit.selectedKey >= int(t->keys.size())) return false;
    edit.keyClipboard = {true, edit.selectedParam->desc->type, t->keys[std::size_t(edit.selectedKey)].value};
    edit.curveClipboard = CurveClipboard{};
    return true;
}

bool pasteTimelineKey(Document& doc, EditState& edit, double timeHours) {
    if (!edit.curveClipboard.empty()) {  // each key onto its own curve, the earliest at `timeHours`
        const CurveClipboard clipboard = edit.curveClipboard;
        std::vector<CurvePoint> pasted;
        doc.apply(pasteLabel(clipboard), "",
                  [&](Preset& p) { pasted = pasteCurveKeys(p, clipboard, timeHours); });
        edit.curves.selected = pasted;  // the pasted keys, ready to move
        return !pasted.empty();
    }
    if (!edit.selectedParam || !edit.keyClipboard.valid) return false;
    const ParamRef ref = *edit.selectedParam;
    const KeyClipboard clip = edit.keyClipboard;
    bool ok = false;
    doc.apply("Paste key", "", [&](Preset& p) { ok = pasteKey(p, ref, clip, timeHours); });
    return ok;
}

void drawTimeline(Document& doc, EditState& edit, Playback& playback, const ActionTable& actions,
                  std::string& status) {
    const Preset& preset = doc.preset();
    const Location& where = preset.environment.location;

    // --- controls ----------------------------------------------------------
    if (ImGui::Button(playback.playing ? "Pause" : "Play", ImVec2(54, 0))) actions.run("play_pause");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Play / pause (Space)");
    ImGui::SameLine();
    float speed = float(playback.speed);
    ImGui::SetNextItemWidth(90.0f);
    if (ImGui::DragFloat("##speed", &speed, 0.02f, 0.01f, 24.0f, "%.2f h/s", ImGuiSliderFlags_Logarithmic))
        playback.speed = std::clamp(double(speed), 0.01, 24.0);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Playback speed [game hours per real second]");
    ImGui::SameLine();
    ImGui::Checkbox("Loop", &playback.loop);
    ImGui::SameLine();
    // Auto-key (off by default): shown here and on the viewport; edits of an
    // animated parameter away from its keys wait as unkeyed changes.
    if (edit.pending.autoKey) ImGui::PushStyleColor(ImGuiCol_FrameBg, ImVec4(0.6f, 0.15f, 0.12f, 1.0f));
    ImGui::Checkbox("Auto-key", &edit.pending.autoKey);
    if (edit.pending.autoKey) ImGui::PopStyleColor();
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "On: editing an animated parameter writes a key at this time.\nOff: the change "
            "waits, highlighted, until you Key or Revert it.");
    if (!edit.pending.empty()) {
        ImGui::SameLine();
        ImGui::TextColored(ImVec4(1.0f, 0.5f, 0.4f, 1.0f), "%zu unkeyed", edit.pending.size());
        ImGui::SameLine();
        if (ImGui::SmallButton("Key all")) {
            const std::vector<PendingEdit> all = edit.pending.all();
            for (const PendingEdit& e : all) keyParamNow(doc, edit, e.ref, e.timeHours);
        }
        ImGui::SameLine();
        if (ImGui::SmallButton("Revert all")) edit.pending.clear();
    }
    ImGui::SameLine();
    if (ImGui::Button("Sunrise")) playback.jumpTo(sunriseHours(where));
    ImGui::SameLine();
    if (ImGui::Button("Noon")) playback.jumpTo(solarNoonHours(where));
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("The sun's highest point today (its meridian crossing)");
    ImGui::SameLine();
    if (ImGui::Button("Sunset")) playback.jumpTo(sunsetHours(where));
    ImGui::SameLine();
    std::string timeText = clock(playback.timeHours);
    ImGui::SetNextItemWidth(60.0f);
    if (ImGui::InputText("##time", &timeText, ImGuiInputTextFlags_EnterReturnsTrue)) {
        double t;
        if (aerial::parseClock(timeText, t)) playback.jumpTo(t);
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Time of day (HH:MM or hours), %s",
                          where.timeMode == TimeMode::Clock && !where.date.empty()
                              ? "local clock time (the location's UTC offset)"
                              : "local solar time");

    const Track* track = edit.selectedParam ? trackOf(preset, *edit.selectedParam) : nullptr;
    const TrackTarget target =
        edit.selectedParam ? trackTargetOf(preset, *edit.selectedParam) : TrackTarget{};
    // One key selection: the track row shows the curve view's. The buttons, the key menu and
    // the keyboard delete it alike (deleteTimelineKeys).
    edit.followCurveSelection(preset);
    auto deleteSelectedKey = [&] { deleteTimelineKeys(doc, edit); };
    ImGui::SameLine();
    ImGui::TextDisabled("|");
    ImGui::SameLine();
    if (!edit.selectedParam) {
        ImGui::TextDisabled("Select a parameter in the inspector to edit its keys");
    } else {
        const std::string address = paramAddress(*edit.selectedParam);
        ImGui::Text("%s", address.c_str());
        ImGui::SameLine();
    }
    // The parameter table says which parameters may carry keys: the others get no Key.
    if (edit.selectedParam && !edit.selectedParam->desc->animatable) {
        ImGui::TextDisabled("is not animated (one value for the whole day)");
    } else if (edit.selectedParam) {
        if (ImGui::Button("Key")) {
            const ParamRef ref = *edit.selectedParam;
            const double t = playback.timeHours;
            keyParamNow(doc, edit, ref, t);
            if (const Track* after = trackOf(doc.preset(), ref))
                edit.selectTrackKey(doc.preset(), keyIndexAt(*after, t));
            track = trackOf(doc.preset(), ref);
        }
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Key the parameter at the current time");
        ImGui::SameLine();
        ImGui::BeginDisabled(!(track && edit.selectedKey >= 0) && edit.curves.selected.empty());
        if (ImGui::Button("Delete key")) {
            deleteSelectedKey();
            track = trackOf(doc.preset(), *edit.selectedParam);
        }
        ImGui::SameLine();
        if (ImGui::Button("Copy") && copyTimelineKey(doc, edit)) status = "Copied key";
        ImGui::EndDisabled();
        ImGui::SameLine();
        ImGui::BeginDisabled(!edit.keyClipboard.valid);
        if (ImGui::Button("Paste")) {
            const double t = playback.timeHours;
            status = pasteTimelineKey(doc, edit, t)
                         ? "Pasted key at " + clock(t)
                         : std::string("The copied key does not fit this parameter");
            track = trackOf(doc.preset(), *edit.selectedParam);
        }
        ImGui::EndDisabled();
        if (track) {
            ImGui::SameLine();
            int interp = int(track->interpolation);
            const char* names[] = {"step", "linear", "smooth"};
            ImGui::SetNextItemWidth(80.0f);
            if (ImGui::Combo("##interp", &interp, names, 3)) {
                doc.apply("Interpolation", "", [&](Preset& p) {
                    if (Track* t = findTrack(p, target)) t->interpolation = Interpolation(interp);
                });
                track = trackOf(doc.preset(), *edit.selectedParam);
            }
            if (ImGui::IsItemHovered())
                ImGui::SetTooltip("Interpolation of the track (smooth never overshoots)");
            // Midnight: the day is cyclic (the curve runs from the last key to
            // the next day's first), or the track holds its first and last values.
            ImGui::SameLine();
            int ends = track->wrap ? 0 : 1;
            const char* endNames[] = {"wraps at midnight", "holds its ends"};
            ImGui::SetNextItemWidth(150.0f);
            if (ImGui::Combo("##ends", &ends, endNames, 2)) {
                doc.apply(ends == 0 ? "Wrap at midnight" : "Hold the ends", "", [&](Preset& p) {
                    if (Track* t = findTrack(p, target)) t->wrap = ends == 0;
                });
                track = trackOf(doc.preset(), *edit.selectedParam);
            }
            if (ImGui::IsItemHovered())
                ImGui::SetTooltip(
                    "Wraps: from the last key the curve runs on into the next day's first key "
                    "(the night between them is interpolated).\nHolds: before the first key the "
                    "first value, after the last key the last value.");
        }
    }

    // --- canvas: ruler, summary row, track row, curve ----------------------------
    const ImVec2 canvasPos = ImGui::GetCursorScreenPos();
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    // The curves' legend and the typed Time and Value fields: wider in a wide
    // window, where "Valley fog density" and its fields then fit.
    const float labelW = std::clamp(avail.x * 0.16f, 190.0f, 320.0f);
    if (avail.x < labelW + 40.0f || avail.y < 50.0f) return;
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const float x0 = canvasPos.x + labelW, x1 = canvasPos.x + avail.x - 8.0f;
    const float rulerH = 18.0f, rowH = 18.0f;
    const float yRuler = canvasPos.y, ySummary = yRuler + rulerH, yTrack = ySummary + rowH,
                yCurve = yTrack + rowH;
    const float yEnd = canvasPos.y + avail.y;
    TimeView& view = edit.curves.time;
    const ImGuiIO& io = ImGui::GetIO();
    // Zoom around the mouse (wheel), pan (middle drag, or Alt + left drag).
    const bool overCanvas =
        ImGui::IsWindowHovered() && ImGui::IsMouseHoveringRect(ImVec2(x0, yRuler), ImVec2(x1, yEnd));
    if (overCanvas && io.MouseWheel != 0.0f)
        view = zoomView(view, view.tOf(io.MousePos.x, x0, x1), std::pow(1.25, double(io.MouseWheel)));
    CurveDrag& drag = edit.curves.drag;
    if (overCanvas && (ImGui::IsMouseClicked(ImGuiMouseButton_Middle) ||
                       (io.KeyAlt && ImGui::IsMouseClicked(ImGuiMouseButton_Left)))) {
        drag = CurveDrag{};
        drag.kind = CurveDrag::Kind::Pan;
        drag.from = glm::dvec2(io.MousePos.x, io.MousePos.y);
        drag.viewFrom = view;
    }
    if (drag.kind == CurveDrag::Kind::Pan) {
        if (ImGui::IsMouseDown(ImGuiMouseButton_Middle) || ImGui::IsMouseDown(ImGuiMouseButton_Left))
            view = panView(drag.viewFrom, -(io.MousePos.x - drag.from.x) * drag.viewFrom.span() /
                                              double(std::max(x1 - x0, 1.0f)));
        else
            drag = CurveDrag{};
    }
    const bool panning = drag.kind == CurveDrag::Kind::Pan;
    auto xOf = [&](double t) { return float(view.xOf(t, x0, x1)); };
    // The time of day at x: wrapped into [0, 24) (the view may show yesterday or tomorrow).
    auto tOf = [&](float x) { return wrapHours(view.tOf(x, x0, x1)); };

    dl->AddRectFilled(ImVec2(x0, yRuler), ImVec2(x1, yEnd), IM_COL32(30, 30, 34, 255));
    // Night shading: where the sun is below the horizon (every day the view shows).
    const double rise = sunriseHours(where), set = sunsetHours(where);
    dl->PushClipRect(ImVec2(x0, yRuler), ImVec2(x1, yEnd), true);
    if (rise > 0.0 && rise < set)
        for (double day = std::floor(view.startHours / 24.0) * 24.0; day < view.endHours; day += 24.0) {
            dl->AddRectFilled(ImVec2(xOf(day), ySummary), ImVec2(xOf(day + rise), yEnd),
                              IM_COL32(20, 22, 40, 255));
            dl->AddRectFilled(ImVec2(xOf(day + set), ySummary), ImVec2(xOf(day + 24.0), yEnd),
                              IM_COL32(20, 22, 40, 255));
        }
    // Ticks at least 28 px apart; labels at every third hour, or every tick when zoomed in.
    const double step = tickStepHours(view, x1 - x0, 28.0);
    const double labelStep = step >= 1.0 ? std::max(3.0, step) : step * 2.0;
    for (double t = std::ceil(view.startHours / step - 1e-9) * step; t <= view.endHours + 1e-9; t += step) {
        const float x = xOf(t);
        const bool major = std::abs(std::remainder(t, labelStep)) < 1e-6;
        const bool midnight = std::abs(std::remainder(t, 24.0)) < 1e-6;
        dl->AddLine(ImVec2(x, yRuler + (major ? 0.0f : rulerH * 0.55f)), ImVec2(x, yRuler + rulerH),
                    IM_COL32(150, 150, 150, 255));
        dl->AddLine(ImVec2(x, ySummary), ImVec2(x, yEnd),
                    midnight ? IM_COL32(200, 200, 255, 90) : IM_COL32(255, 255, 255, major ? 22 : 10));
        if (major && x1 - x0 > 200.0f) {
            const std::string label = formatClock(wrapHours(t), ClockResolution::Minutes);
            dl->AddText(ImVec2(x + 3.0f, yRuler), IM_COL32(190, 190, 190, 255), label.c_str());
        }
    }
    dl->PopClipRect();
    dl->AddText(ImVec2(canvasPos.x + 4.0f, ySummary + 2.0f), IM_COL32(170, 170, 170, 255), "All keys");
    std::string rowLabel = edit.selectedParam ? curveLabel(preset, target) : std::string("(no parameter)");
    if (rowLabel.size() > 25) {  // "Haze bank density"; cut before a whole UTF-8 character
        std::size_t cut = 24;
        while (cut > 0 && (static_cast<unsigned char>(rowLabel[cut]) & 0xC0) == 0x80) --cut;
        rowLabel = rowLabel.substr(0, cut) + "~";
    }
    dl->AddText(ImVec2(canvasPos.x + 4.0f, yTrack + 2.0f), IM_COL32(230, 200, 120, 255), rowLabel.c_str());

    // Ruler: scrub.
    ImGui::SetCursorScreenPos(ImVec2(x0, yRuler));
    ImGui::InvisibleButton("##ruler", ImVec2(x1 - x0, rulerH));
    if (ImGui::IsItemHovered() && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) {
        view = fitView();
        edit.curves.resetRanges();  // the curves' value ranges follow their keys again
    }
    if (ImGui::IsItemActive() && !panning) {
        playback.timeHours = tOf(ImGui::GetIO().MousePos.x);
        playback.playing = false;
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "Drag to scrub the time of day\nWheel: zoom; middle or Alt drag: pan; F or double-click: the "
            "whole day");

    // Summary row: every key of every track; click jumps to its time. (The
    // rows draw only inside the strip: a zoomed view hides the keys outside it.)
    dl->PushClipRect(ImVec2(x0 - 7.0f, ySummary), ImVec2(x1 + 7.0f, yCurve), true);
    std::set<double> times;
    for (const Track& t : preset.tracks)
        for (const TrackKey& k : t.keys) times.insert(k.timeHours);
    ImGui::SetCursorScreenPos(ImVec2(x0, ySummary));
    ImGui::InvisibleButton("##summary", ImVec2(x1 - x0, rowH));
    const bool summaryClicked = ImGui::IsItemClicked();
    const float mouseX = ImGui::GetIO().MousePos.x;
    double nearest = -1.0;
    for (double t : times) {
        diamond(dl, ImVec2(xOf(t), ySummary + rowH * 0.5f), 4.0f, IM_COL32(170, 170, 170, 255), true);
        if (std::abs(xOf(t) - mouseX) < 6.0f) nearest = t;
    }
    if (summaryClicked && nearest >= 0.0) playback.jumpTo(nearest);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("%zu key times in %zu tracks; click a key to jump to it", times.size(),
                          preset.tracks.size());

    // Track row: select, drag, double-click to add, right-click menu.
    ImGui::SetCursorScreenPos(ImVec2(x0, yTrack));
    ImGui::InvisibleButton("##track", ImVec2(x1 - x0, rowH));
    const bool trackHovered = ImGui::IsItemHovered(), trackActive = ImGui::IsItemActive();
    if (track && edit.selectedParam) {
        int hoveredKey = -1;
        for (std::size_t i = 0; i < track->keys.size(); ++i) {
            const float x = xOf(track->keys[i].timeHours);
            const bool selected = int(i) == edit.selectedKey;
            const ImU32 colour = selected ? IM_COL32(255, 230, 120, 255) : IM_COL32(240, 190, 60, 255);
            if (track->keys[i].anchor) {  // follows the sun: a round mark with rays
                dl->AddCircleFilled(ImVec2(x, yTrack + rowH * 0.5f), selected ? 4.0f : 3.5f, colour);
                drawSunKeyRays(x, yTrack + rowH * 0.5f, selected ? 4.0f : 3.5f);
            } else {
                diamond(dl, ImVec2(x, yTrack + rowH * 0.5f), selected ? 6.0f : 5.0f, colour, true);
            }
            if (std::abs(x - mouseX) < 6.0f) hoveredKey = int(i);
        }
        if (ImGui::IsItemClicked(0) && !io.KeyAlt) {
            edit.selectTrackKey(preset, hoveredKey);
            edit.draggingKey = hoveredKey >= 0;
        }
        if (ImGui::IsItemClicked(1) && hoveredKey >= 0) {
            edit.selectTrackKey(preset, hoveredKey);
            ImGui::OpenPopup("##keymenu");
        }
        if (trackHovered && ImGui::IsMouseDoubleClicked(0) && hoveredKey < 0) {
            const ParamRef ref = *edit.selectedParam;
            const double t = tOf(mouseX);
            doc.apply("Add key", "", [&](Preset& p) { keyParam(p, ref, t); });
            if (const Track* after = trackOf(doc.preset(), ref))
                edit.selectTrackKey(doc.preset(), keyIndexAt(*after, t));
            hoveredKey = -1;
        }
        if (edit.draggingKey && trackActive && edit.selectedKey >= 0 && ImGui::GetIO().MouseDelta.x != 0.0f) {
            const int key = edit.selectedKey;
            // Snapped to another key (6 px) or the snap step (the curve view's Snap); Shift moves freely.
            double t = std::clamp(view.tOf(mouseX, x0, x1), 0.0, 24.0 - 1e-6);
            if (!ImGui::GetIO().KeyShift)
                t = snapKeyTime(doc.preset(), target, key, t,
                                6.0 * view.span() / double(std::max(x1 - x0, 1.0f)), edit.curves.snapHours);
            doc.apply("Move key", "move-key:" + paramAddress(*edit.selectedParam), [&](Preset& p) {
                if (Track* tr = findTrack(p, target)) moveKey(*tr, key, t);
            });
        }
        if (edit.draggingKey && !trackActive) {
            edit.draggingKey = false;
            doc.closeMerge();
        }
        track = trackOf(doc.preset(), *edit.selectedParam);  // the edits above may have moved it
        if (track && trackHovered && hoveredKey >= 0 && hoveredKey < int(track->keys.size()) &&
            !ImGui::IsPopupOpen("##keymenu")) {
            const TrackKey& k = track->keys[std::size_t(hoveredKey)];
            const int components = edit.selectedParam->desc->components();
            // "19:52", or "sunset + 0:20 (19:52)" for a key that follows the sun.
            const std::string when = keyTimeText(k);
            if (components == 1)
                ImGui::SetTooltip("%s  %.6g", when.c_str(), k.value.x);
            else if (components == 2)
                ImGui::SetTooltip("%s  (%.4g, %.4g)", when.c_str(), k.value.x, k.value.y);
            else
                ImGui::SetTooltip("%s  (%.4g, %.4g, %.4g)", when.c_str(), k.value.x, k.value.y, k.value.z);
        }
    }
    if (ImGui::BeginPopup("##keymenu")) {
        const std::string deleteKeys = actions.shortcutOf("timeline_delete_keys");
        if (ImGui::MenuItem("Delete key", deleteKeys.c_str())) deleteSelectedKey();
        // Flat: the smooth curve levels out at the key (TrackKey::flat).
        if (const Track* t = edit.selectedParam ? trackOf(doc.preset(), *edit.selectedParam) : nullptr;
            t && edit.selectedKey >= 0 && edit.selectedKey < int(t->keys.size())) {
            const bool flat = t->keys[std::size_t(edit.selectedKey)].flat;
            const std::vector<CurvePoint> key = {{target, edit.selectedKey, 0}};
            if (ImGui::MenuItem("Flat tangent", nullptr, flat))
                doc.apply(flat ? "Automatic tangent" : "Flat tangent", "",
                          [&](Preset& p) { setFlatTangents(p, key, !flat); });
        }
        // Follow the sun: the curve view's key menu's, on this key.
        if (const Track* t = edit.selectedParam ? trackOf(doc.preset(), *edit.selectedParam) : nullptr;
            t && edit.selectedKey >= 0 && edit.selectedKey < int(t->keys.size()))
            followTheSunMenu(doc, {{target, edit.selectedKey, 0}}, "");
        if (ImGui::MenuItem("Copy", actions.shortcutOf("timeline_copy_key").c_str()))
            actions.run("timeline_copy_key");
        if (ImGui::MenuItem("Jump to key") && edit.selectedParam) {
            if (const Track* t = trackOf(doc.preset(), *edit.selectedParam);
                t && edit.selectedKey >= 0 && edit.selectedKey < int(t->keys.size()))
                playback.jumpTo(t->keys[std::size_t(edit.selectedKey)].timeHours);
        }
        const char* names[] = {"Step", "Linear", "Smooth"};
        for (int i = 0; i < 3; ++i)
            if (ImGui::MenuItem(names[i])) {
                doc.apply("Interpolation", "", [&](Preset& p) {
                    if (Track* t = findTrack(p, target)) t->interpolation = Interpolation(i);
                });
            }
        ImGui::EndPopup();
    }

    // Its keys (Delete, Ctrl+C, Ctrl+V, F): the action table's, while the mouse is here.
    edit.timelineHovered = ImGui::IsWindowHovered(ImGuiHoveredFlags_ChildWindows);

    dl->PopClipRect();
    // Curve area: the inspector's parameter and the curves toggled on beside it.
    drawCurveView(doc, edit, playback, canvasPos.x, x0, x1, yCurve, yEnd);
    // Playhead (today's; yesterday's and tomorrow's when the view shows them).
    dl->PushClipRect(ImVec2(x0 - 6.0f, yRuler), ImVec2(x1 + 6.0f, yEnd), true);
    for (double day : {-24.0, 24.0})
        if (const float xd = xOf(playback.timeHours + day); xd >= x0 && xd <= x1)
            dl->AddLine(ImVec2(xd, yRuler), ImVec2(xd, yEnd), IM_COL32(255, 90, 70, 90), 1.0f);
    const float xt = xOf(playback.timeHours);
    dl->AddLine(ImVec2(xt, yRuler), ImVec2(xt, yEnd), IM_COL32(255, 90, 70, 255), 2.0f);
    dl->AddTriangleFilled(ImVec2(xt - 5.0f, yRuler), ImVec2(xt + 5.0f, yRuler), ImVec2(xt, yRuler + 7.0f),
                          IM_COL32(255, 90, 70, 255));
    dl->PopClipRect();
}

}  // namespace aerial::editor
