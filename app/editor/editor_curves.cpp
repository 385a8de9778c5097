// editor/editor_curves.cpp — the timeline's curve area: the inspector's
// parameter and the curves toggled on beside it (the curve button in the
// inspector), each normalised to its keys' range (pinned by the first drag
// until the view is fit again) and coloured by its target, with a legend
// in the label column naming objects by their names ("Haze bank density")
// and a value axis in the inspector's parameter's unit. Keys drag in time
// and value (one undo step per drag, "Move 3 keys"; time snaps to other
// keys and the quarter hour unless Shift is held; a few pixels of dead
// zone per axis keep a vertical drag at its time; the key's time and value
// show beside the cursor); where keys overlap, the inspector's parameter's
// is picked; Ctrl+click adds a key to the selection; a drag on empty curve
// area selects the keys in its box (Ctrl adds), a click there sets the
// time; a selected key of a smooth segment shows its tangent handles (drag
// an end to set the slope, one undo step; unified: the other side
// mirrors, broken: it stays); right-click a key for flat / automatic
// tangents, unified / broken handles, Follow the sun
// (anchor the selection to sunrise, sunset, a dawn or a dusk where it
// stands), Time, Value, Shift by and delete. A key that follows the sun
// wears rays and reads "sunset + 0:20 (19:52)". Below the legend: the
// selected key's Time and Value (typed: Enter sets them, one undo step;
// several keys: the time moves them all, the value sets every key of the
// same parameter), the Shift field (Enter shifts the selected keys by
// "+0:20", "-1:00", "-0.25", limited as a drag is) and the Snap step of
// drags (1, 5, 15, 60 min). The wrap
// through midnight (after the last key and before the first) is dashed; a
// track that holds its ends is drawn flat there, dimmed. The pure parts
// (zoom, normalisation, hit-testing, moves, anchors, shifts) are in
// curve_view.hpp.
#include "panels.hpp"

#include <aerial/clock.hpp>

#include <imgui.h>
#include <imgui_stdlib.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace aerial::editor {
namespace {

constexpr ImU32 kPalette[] = {
    IM_COL32(240, 190, 60, 255),  IM_COL32(80, 200, 235, 255),  IM_COL32(235, 105, 200, 255),
    IM_COL32(125, 215, 95, 255),  IM_COL32(245, 115, 70, 255),  IM_COL32(165, 135, 250, 255),
    IM_COL32(230, 230, 140, 255), IM_COL32(70, 190, 165, 255),  IM_COL32(250, 150, 150, 255),
    IM_COL32(120, 150, 255, 255), IM_COL32(200, 160, 110, 255), IM_COL32(180, 230, 200, 255)};
static_assert(int(sizeof kPalette / sizeof kPalette[0]) == kCurvePaletteSize);
constexpr float kPickRadiusPx = 6.0f;
constexpr float kDeadZonePx = 3.0f;  ///< a drag moves a key along an axis once it leaves this
constexpr ImU32 kSunRays = IM_COL32(255, 214, 110, 235);  ///< the rays of a key that follows the sun

/// A colour scaled in brightness and alpha (the components of a vector
/// curve get darker: x, y, z).
ImU32 shade(ImU32 colour, float brightness, float alpha) {
    ImVec4 c = ImGui::ColorConvertU32ToFloat4(colour);
    return ImGui::ColorConvertFloat4ToU32(
        ImVec4(c.x * brightness, c.y * brightness, c.z * brightness, c.w * alpha));
}

/// One curve in the view.
struct Drawn {
    TrackTarget target;
    ParamRef ref;
    const Track* track = nullptr;
    CompiledTrack compiled;
    CurveRange range;
    ImU32 colour = 0;
    bool primary = false;  ///< the inspector's parameter
    int components = 1;
};

std::string valueText(const glm::dvec3& v, int components) {
    char text[96];
    if (components == 1)
        std::snprintf(text, sizeof text, "%.6g", v.x);
    else if (components == 2)
        std::snprintf(text, sizeof text, "(%.4g, %.4g)", v.x, v.y);
    else
        std::snprintf(text, sizeof text, "(%.4g, %.4g, %.4g)", v.x, v.y, v.z);
    return text;
}

/// `text` cut to fit `widthPx` [px], a '~' where it was cut (whole UTF-8 characters).
std::string fitted(std::string text, float widthPx) {
    if (ImGui::CalcTextSize(text.c_str()).x <= widthPx) return text;
    while (!text.empty() && ImGui::CalcTextSize((text + "~").c_str()).x > widthPx) {
        unsigned char last;
        do {  // a continuation byte (10xxxxxx) goes with the rest of its character
            last = static_cast<unsigned char>(text.back());
            text.pop_back();
        } while (!text.empty() && (last & 0xC0) == 0x80);
    }
    return text + "~";
}

}  // namespace

void drawSunKeyRays(float x, float y, float radius) {
    ImDrawList* dl = ImGui::GetWindowDrawList();
    for (int i = 0; i < 8; ++i) {
        const float angle = float(i) * 0.78539816f;  // 45 deg apart
        const float c = std::cos(angle), s = std::sin(angle);
        dl->AddLine(ImVec2(x + c * (radius + 1.5f), y + s * (radius + 1.5f)),
                    ImVec2(x + c * (radius + 4.0f), y + s * (radius + 4.0f)), kSunRays, 1.5f);
    }
}

std::vector<TrackTarget> shownCurveTargets(const Preset& preset, const EditState& edit) {
    std::vector<TrackTarget> targets = edit.curves.shown;
    if (edit.selectedParam) {
        const TrackTarget primary = trackTargetOf(preset, *edit.selectedParam);
        if (!edit.curves.isShown(primary)) targets.push_back(primary);
    }
    return targets;
}

unsigned curveColour(const Preset& preset, const EditState& edit, const TrackTarget& target) {
    const std::vector<TrackTarget> shown = shownCurveTargets(preset, edit);
    const std::vector<int> indices = curvePaletteIndices(shown, kCurvePaletteSize);
    for (std::size_t i = 0; i < shown.size(); ++i)
        if (shown[i] == target) return kPalette[indices[i]];
    return kPalette[curvePaletteIndex(target, kCurvePaletteSize)];
}

void drawCurveView(Document& doc, EditState& edit, Playback& playback, float labelX, float x0, float x1,
                   float top, float bottom) {
    CurveViewState& view = edit.curves;
    CurveDrag& drag = view.drag;
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const ImGuiIO& io = ImGui::GetIO();
    const Preset& preset = doc.preset();
    const float yTop = top + 6.0f, yBottom = bottom - 6.0f;
    auto xOf = [&](double t) { return float(view.time.xOf(t, x0, x1)); };
    auto yOf = [&](double n) { return yBottom - float(n) * (yBottom - yTop); };
    view.drawnX0 = x0;
    view.drawnX1 = x1;
    view.drawnBottom = yBottom;
    view.drawnTop = yTop;

    // --- the curves: those toggled on, then the inspector's parameter ---------------------------
    std::vector<Drawn> curves;
    const std::optional<TrackTarget> primary =
        edit.selectedParam ? std::optional<TrackTarget>(trackTargetOf(preset, *edit.selectedParam))
                           : std::nullopt;
    auto addCurve = [&](const TrackTarget& target) {
        const std::optional<ParamRef> ref = paramRefOf(preset, target);
        if (!ref) return;
        Drawn d;
        d.target = target;
        d.ref = *ref;
        d.track = findTrack(preset, target);
        d.components = std::clamp(ref->desc->components(), 1, 3);
        d.primary = primary && *primary == target;
        d.colour = curveColour(preset, edit, target);  // clashes among the curves shown resolved
        if (d.track) {
            d.compiled = compileTrack(*d.track, d.components);
            d.range = view.rangeOf(preset, target);  // pinned by the first drag until the view is fit
        } else {
            double base[4];
            readBaseValue(preset, *ref, base);
            double lo = base[0], hi = base[0];
            for (int c = 1; c < d.components; ++c) lo = std::min(lo, base[c]), hi = std::max(hi, base[c]);
            d.range = paddedRange(lo, hi, *ref->desc);
        }
        // A drag keeps the range it began with, so the key stays under the mouse.
        for (const CurveDragItem& item : drag.items)
            if (drag.kind == CurveDrag::Kind::Keys && item.point.target == target) d.range = item.range;
        curves.push_back(std::move(d));
    };
    for (const TrackTarget& t : view.shown) addCurve(t);
    if (primary && !view.isShown(*primary)) addCurve(*primary);

    // Day boundaries and what lies outside the day (yesterday, tomorrow).
    if (view.time.startHours < 0.0)
        dl->AddRectFilled(ImVec2(x0, top), ImVec2(std::min(xOf(0.0), x1), bottom), IM_COL32(0, 0, 0, 70));
    if (view.time.endHours > 24.0)
        dl->AddRectFilled(ImVec2(std::max(xOf(24.0), x0), top), ImVec2(x1, bottom), IM_COL32(0, 0, 0, 70));

    // The value axis of the inspector's parameter (else of the only curve): ticks in its unit.
    const Drawn* axis = nullptr;
    for (const Drawn& d : curves)
        if (d.primary) axis = &d;
    if (!axis && curves.size() == 1) axis = &curves.front();
    if (axis && yBottom - yTop > 30.0f) {
        const int maxTicks = std::clamp(int((yBottom - yTop) / 22.0f), 2, 8);
        for (double v : valueTicks(axis->range, maxTicks)) {
            const float y = yOf(axis->range.normalised(v));
            dl->AddLine(ImVec2(x0, y), ImVec2(x1, y), IM_COL32(255, 255, 255, 16));
            const std::string tick = valueWithUnit(v, axis->ref.desc->unit);
            dl->AddText(ImVec2(x0 + 3.0f, y - ImGui::GetTextLineHeight()), IM_COL32(150, 150, 150, 210),
                        tick.c_str());
        }
    }

    // Samples every few pixels; the part of a curve outside its first..last
    // key (the night between them) is dashed when it wraps, dimmed and flat
    // when the track holds its ends.
    const int samples = std::clamp(int((x1 - x0) / 3.0f), 32, 640);
    for (const Drawn& d : curves) {
        for (int c = 0; c < d.components; ++c) {
            const float brightness = c == 0 ? 1.0f : (c == 1 ? 0.72f : 0.5f);
            const float thickness = d.primary ? 2.0f : 1.5f;
            ImVec2 previous;
            for (int s = 0; s <= samples; ++s) {
                const double t = view.time.startHours + view.time.span() * s / samples;
                double v;
                if (d.track) {
                    // The last sample just inside the view: at exactly 24:00 it would read the
                    // next day's 00:00 (a held track jumps there).
                    v = evaluateTrack(d.compiled, s == samples ? t - 1e-7 : t)[c];
                } else {
                    double base[4];
                    readBaseValue(preset, d.ref, base);
                    v = base[c];
                }
                const ImVec2 p(xOf(t), yOf(d.range.normalised(v)));
                if (s > 0) {
                    bool outside = false;
                    if (d.track && !d.track->keys.empty()) {
                        const double mid = wrapHours(t - 0.5 * view.time.span() / samples);
                        outside =
                            mid < d.track->keys.front().timeHours || mid > d.track->keys.back().timeHours;
                    }
                    if (!outside)
                        dl->AddLine(previous, p, shade(d.colour, brightness, 1.0f), thickness);
                    else if (!d.track->wrap)
                        dl->AddLine(previous, p, shade(d.colour, brightness, 0.45f), thickness);
                    else if ((s / 2) % 2 == 0)  // dashes of two samples
                        dl->AddLine(previous, p, shade(d.colour, brightness, 0.6f), thickness);
                }
                previous = p;
            }
        }
    }

    // --- key points: this day's are picked; yesterday's and tomorrow's copies are dimmed ---------
    std::vector<glm::dvec2> points;
    std::vector<CurvePoint> ids;
    // The tangent handles of the selected keys of smooth segments (the first few selected).
    struct Handle {
        glm::dvec2 end{0.0}, key{0.0};
        CurvePoint point;
        TangentSide side = TangentSide::Out;
    };
    std::vector<Handle> handles;
    const double pxPerHour = double(x1 - x0) / view.time.span();
    const double heightPx = double(yBottom - yTop);
    for (const Drawn& d : curves) {
        if (!d.track) continue;
        for (std::size_t k = 0; k < d.track->keys.size(); ++k) {
            const TrackKey& key = d.track->keys[k];
            for (int c = 0; c < d.components; ++c) {
                const float brightness = c == 0 ? 1.0f : (c == 1 ? 0.72f : 0.5f);
                const float y = yOf(d.range.normalised(key.value[c]));
                for (double day : {-24.0, 24.0}) {
                    const float xg = xOf(key.timeHours + day);
                    if (xg >= x0 && xg <= x1)
                        dl->AddCircleFilled(ImVec2(xg, y), 2.5f, shade(d.colour, brightness, 0.4f));
                }
                const float x = xOf(key.timeHours);
                if (x < x0 - kPickRadiusPx || x > x1 + kPickRadiusPx) continue;
                const CurvePoint id{d.target, int(k), c};
                const bool selected = view.isSelected(id);
                if (key.flat && d.track->interpolation == Interpolation::Smooth) {  // the level tangent
                    dl->AddLine(ImVec2(x - 14.0f, y), ImVec2(x + 14.0f, y), IM_COL32(235, 235, 235, 220),
                                1.5f);
                    dl->AddRectFilled(ImVec2(x - 15.5f, y - 1.5f), ImVec2(x - 12.5f, y + 1.5f),
                                      IM_COL32(235, 235, 235, 255));
                    dl->AddRectFilled(ImVec2(x + 12.5f, y - 1.5f), ImVec2(x + 15.5f, y + 1.5f),
                                      IM_COL32(235, 235, 235, 255));
                }
                const std::size_t n = d.track->keys.size();
                if (selected && handles.size() < 16 && d.compiled.tangents.size() == n &&
                    d.compiled.tangentsIn.size() == n) {
                    // Unified handles white, broken ones orange, automatic ones grey.
                    const ImU32 colour = !key.tangents ? IM_COL32(170, 170, 170, 220)
                                         : key.tangents->mode == TangentMode::Broken
                                             ? IM_COL32(255, 170, 80, 240)
                                             : IM_COL32(240, 240, 240, 240);
                    const bool smoothAfter = d.compiled.segments[k] == Interpolation::Smooth;
                    const bool smoothBefore = d.compiled.segments[(k + n - 1) % n] == Interpolation::Smooth;
                    for (TangentSide side : {TangentSide::In, TangentSide::Out}) {
                        if (!(side == TangentSide::Out ? smoothAfter : smoothBefore)) continue;
                        const double slope = side == TangentSide::Out ? d.compiled.tangents[k][c]
                                                                      : d.compiled.tangentsIn[k][c];
                        const glm::dvec2 end =
                            glm::dvec2(x, y) + tangentHandleOffset(slope, d.range, pxPerHour, heightPx, side);
                        dl->AddLine(ImVec2(x, y), ImVec2(float(end.x), float(end.y)), colour, 1.5f);
                        dl->AddRectFilled(ImVec2(float(end.x) - 3.0f, float(end.y) - 3.0f),
                                          ImVec2(float(end.x) + 3.0f, float(end.y) + 3.0f), colour);
                        handles.push_back({end, glm::dvec2(x, y), id, side});
                    }
                }
                dl->AddCircleFilled(ImVec2(x, y), selected ? 4.5f : 3.5f, shade(d.colour, brightness, 1.0f));
                if (key.anchor) drawSunKeyRays(x, y, selected ? 4.5f : 3.5f);  // follows the sun
                if (selected)
                    dl->AddCircle(ImVec2(x, y), key.anchor ? 10.5f : 6.5f, IM_COL32(255, 255, 255, 230), 0,
                                  1.5f);
                points.push_back({x, y});
                ids.push_back(id);
            }
        }
    }

    // --- legend: the label column, one line a curve (below it, where they fit: the selected
    // key's Time and Value, then Shift and Snap) ---------------------------------------------------
    const float frameH = ImGui::GetFrameHeight();
    const float rowH = frameH + 2.0f;
    const int controlRows = x0 - labelX >= 120.0f ? std::clamp(int((bottom - top - 30.0f) / rowH), 0, 2) : 0;
    const float controlsH = float(controlRows) * rowH + (controlRows > 0 ? 2.0f : 0.0f);
    const float legendBottom = bottom - controlsH;
    float yLegend = top + 2.0f;
    int hoveredLegend = -1;
    for (std::size_t i = 0; i < curves.size() && yLegend + 13.0f <= legendBottom; ++i, yLegend += 14.0f) {
        const Drawn& d = curves[i];
        // "Haze bank density": the object's name, not its index.
        const std::string label = fitted(curveLabel(preset, d.target), x0 - labelX - 22.0f);
        dl->AddRectFilled(ImVec2(labelX + 4.0f, yLegend + 3.0f), ImVec2(labelX + 12.0f, yLegend + 11.0f),
                          d.colour);
        dl->AddText(ImVec2(labelX + 16.0f, yLegend),
                    d.primary ? IM_COL32(235, 235, 235, 255) : IM_COL32(170, 170, 170, 255), label.c_str());
        if (ImGui::IsMouseHoveringRect(ImVec2(labelX, yLegend), ImVec2(x0, yLegend + 14.0f)))
            hoveredLegend = int(i);
    }
    if (hoveredLegend >= 0 && ImGui::IsWindowHovered()) {
        const Drawn& d = curves[std::size_t(hoveredLegend)];
        ImGui::SetTooltip("%s\n%s\ndrawn from %.4g (bottom) to %.4g (top) %s%s%s",
                          curveLabel(preset, d.target).c_str(), paramAddress(d.ref).c_str(), d.range.lo,
                          d.range.hi, std::string(d.ref.desc->unit).c_str(),
                          d.components > 1 ? "\ncomponents x, y, z from bright to dark" : "",
                          d.track && !d.track->wrap ? "\nholds its first and last values" : "");
    }

    // --- mouse -----------------------------------------------------------------------------------
    if (!(bottom - top > 4.0f)) return;
    ImGui::SetCursorScreenPos(ImVec2(x0, top));
    ImGui::InvisibleButton("##curve", ImVec2(x1 - x0, bottom - top),
                           ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight);
    const bool hovered = ImGui::IsItemHovered();
    const glm::dvec2 mouse(io.MousePos.x, io.MousePos.y);
    // Where keys overlap, the inspector's parameter's is picked.
    const int hit = hovered ? pickCurvePoint(points, ids, mouse, kPickRadiusPx, primary) : -1;
    auto selectPrimaryKey = [&](const CurvePoint& p) {  // the track row and Delete / Copy follow the curve
        if (primary && p.target == *primary) edit.selectedKey = p.key;
    };
    // A selected key's tangent handle under the mouse (drawn on top of the keys, so picked first).
    int handleHit = -1;
    if (hovered) {
        double nearest = kPickRadiusPx;
        for (std::size_t i = 0; i < handles.size(); ++i) {
            const double distance = glm::length(handles[i].end - mouse);
            if (distance <= nearest) nearest = distance, handleHit = int(i);
        }
    }
    if (ImGui::IsItemClicked(ImGuiMouseButton_Left) && !io.KeyAlt) {
        drag = CurveDrag{};
        drag.from = mouse;
        if (handleHit >= 0) {
            const Handle& h = handles[std::size_t(handleHit)];
            drag.kind = CurveDrag::Kind::Handle;
            drag.handlePoint = h.point;
            drag.handleSide = h.side;
            drag.handleKeyPx = h.key;
            view.pinRange(preset, h.point.target);  // the slope reads in the range it is drawn in
        } else if (hit >= 0) {
            const CurvePoint& p = ids[std::size_t(hit)];
            if (io.KeyCtrl) {
                if (view.isSelected(p))
                    std::erase(view.selected, p);
                else
                    view.selected.push_back(p);
            } else if (!view.isSelected(p)) {
                view.selected = {p};
            }
            selectPrimaryKey(p);
            if (view.isSelected(p)) {
                drag.kind = CurveDrag::Kind::Keys;
                // The curves keep the ranges they are drawn in now, this drag and the next.
                for (const CurvePoint& s : view.selected) view.pinRange(preset, s.target);
                drag.items = dragItemsOf(preset, view.selected, view);
                for (std::size_t i = 0; i < drag.items.size(); ++i)
                    if (drag.items[i].point == p) drag.lead = int(i);
            }
        } else {
            drag.kind = CurveDrag::Kind::Box;
            drag.additive = io.KeyCtrl;
        }
    }
    if (ImGui::IsItemClicked(ImGuiMouseButton_Right) && hit >= 0) {
        const CurvePoint& p = ids[std::size_t(hit)];
        if (!view.isSelected(p)) view.selected = {p};
        selectPrimaryKey(p);
        ImGui::OpenPopup("##curvemenu");
    }
    const bool leftDown = ImGui::IsMouseDown(ImGuiMouseButton_Left);
    if (drag.kind == CurveDrag::Kind::Keys && drag.lead >= 0) {
        const glm::dvec2 delta = mouse - drag.from;
        drag.timeMoved = drag.timeMoved || std::abs(delta.x) > kDeadZonePx;
        drag.valueMoved = drag.valueMoved || std::abs(delta.y) > kDeadZonePx;
        if (leftDown) {
            const CurveDragItem& lead = drag.items[std::size_t(drag.lead)];
            double dt = 0.0;
            if (drag.timeMoved) {
                const double hoursPerPx = view.time.span() / double(std::max(x1 - x0, 1.0f));
                const double wanted = lead.timeHours + delta.x * hoursPerPx;
                double t = wanted;
                // Snapped to another key (6 px) or the snap step; Shift moves freely.
                if (!io.KeyShift) {
                    t = snapKeyTime(preset, lead.point.target, lead.point.key, wanted, 6.0 * hoursPerPx,
                                    view.snapHours);
                    if (t - wanted > 12.0) t -= 24.0;  // the quarter hour after 23:52 is 00:00
                }
                dt = t - lead.timeHours;
            }
            const double dn = drag.valueMoved ? -delta.y / double(std::max(yBottom - yTop, 1.0f)) : 0.0;
            if (dt != drag.appliedHours || dn != drag.appliedNormalised) {
                std::vector<CurvePoint> moved;
                for (const CurveDragItem& item : drag.items) moved.push_back(item.point);
                const std::vector<CurveDragItem> items = drag.items;
                doc.apply(moveLabel(moved), "curve-move",
                          [&](Preset& p) { moveCurvePoints(p, items, dt, dn); });
                drag.appliedHours = dt;
                drag.appliedNormalised = dn;
            }
            // The readout beside the cursor: the dragged key's time and value as they are now.
            if (drag.timeMoved || drag.valueMoved) {
                const CurvePoint& p = lead.point;
                const Track* track = findTrack(doc.preset(), p.target);
                const ParamDesc* desc = findParam(p.target.scope, p.target.param);
                if (track && desc && p.key < int(track->keys.size()))
                    ImGui::SetTooltip(
                        "%s", keyReadout(track->keys[std::size_t(p.key)], p.component, *desc).c_str());
            }
        } else {
            doc.closeMerge();
            drag = CurveDrag{};
        }
    } else if (drag.kind == CurveDrag::Kind::Handle) {
        if (leftDown) {
            // The slope from the key to the mouse, in the range the curve is drawn in; one undo step.
            const CurveRange range = view.rangeOf(doc.preset(), drag.handlePoint.target);
            const double slope =
                slopeOfHandle(mouse - drag.handleKeyPx, range, pxPerHour, heightPx, drag.handleSide);
            const CurvePoint point = drag.handlePoint;
            const TangentSide side = drag.handleSide;
            if (glm::length(mouse - drag.from) > 0.0)
                doc.apply("Tangent", "curve-tangent",
                          [&](Preset& p) { setKeyTangent(p, point, side, slope); });
            const ParamDesc* desc = findParam(point.target.scope, point.target.param);
            ImGui::SetTooltip("slope %s per h", valueWithUnit(slope, desc ? desc->unit : "").c_str());
        } else {
            doc.closeMerge();
            drag = CurveDrag{};
        }
    } else if (drag.kind == CurveDrag::Kind::Box) {
        const glm::dvec2 delta = mouse - drag.from;
        const bool boxed = std::abs(delta.x) > kDeadZonePx || std::abs(delta.y) > kDeadZonePx;
        if (leftDown && boxed) {
            dl->AddRectFilled(ImVec2(float(drag.from.x), float(drag.from.y)), io.MousePos,
                              IM_COL32(120, 160, 255, 40));
            dl->AddRect(ImVec2(float(drag.from.x), float(drag.from.y)), io.MousePos,
                        IM_COL32(120, 160, 255, 200));
        } else if (!leftDown) {
            if (boxed) {
                if (!drag.additive) view.selected.clear();
                for (int i : pointsInBox(points, drag.from, mouse))
                    if (!view.isSelected(ids[std::size_t(i)])) view.selected.push_back(ids[std::size_t(i)]);
            } else {  // a click on empty curve area: the time there
                if (!drag.additive) view.selected.clear();
                playback.jumpTo(view.time.tOf(drag.from.x, x0, x1));
                playback.playing = false;
            }
            drag = CurveDrag{};
        }
    } else if (drag.kind != CurveDrag::Kind::Pan && !leftDown) {
        drag = CurveDrag{};
    }

    const std::uint64_t revision = doc.revision();
    // The selected keys shifted by the Shift field's time, one undo step;
    // false when nothing is selected or the text is not a time.
    auto shiftSelection = [&] {
        double dt = 0.0;
        const std::vector<CurvePoint> picked = view.selected;
        if (picked.empty() || !parseShiftHours(view.shiftText, dt)) return false;
        doc.apply(shiftLabel(picked), "", [&](Preset& p) { shiftCurvePoints(p, picked, dt); });
        return true;
    };
    // The selected keys' Time and Value fields: what they show (the lead key's) and what Enter does.
    const std::optional<CurvePoint> lead = leadPointOf(preset, view.selected);
    const ParamDesc* leadDesc = lead ? findParam(lead->target.scope, lead->target.param) : nullptr;
    std::string timeText, valueField;
    if (lead && leadDesc) {
        const TrackKey& k = findTrack(preset, lead->target)->keys[std::size_t(lead->key)];
        timeText = keyClockText(k.timeHours);
        valueField = valueWithUnit(k.value[lead->component], leadDesc->unit, 6);
    }
    auto typeTime = [&](const std::string& text) {  // false when nothing is selected or no time typed
        double t = 0.0;
        const std::vector<CurvePoint> picked = view.selected;
        if (!lead || !parseClock(text, t)) return false;
        doc.apply(setTimeLabel(picked), "", [&](Preset& p) { setCurvePointsTime(p, picked, t); });
        return true;
    };
    auto typeValue = [&](const std::string& text) {
        double v = 0.0;
        const std::vector<CurvePoint> picked = view.selected;
        if (!lead || !leadDesc || !parseKeyValue(text, leadDesc->unit, v)) return false;
        for (const CurvePoint& p : picked) view.pinRange(doc.preset(), p.target);  // the curve stays put
        doc.apply(setValueLabel(doc.preset(), picked), "",
                  [&](Preset& p) { setCurvePointsValue(p, picked, v); });
        return true;
    };
    const int selectedKeys = keyCountOf(view.selected);
    const std::string timeHelp =
        selectedKeys > 1
            ? "The first selected key's time (HH:MM:SS); Enter moves it there and the other " +
                  std::to_string(selectedKeys - 1) +
                  " selected keys with it, as a drag does (a minute from keys that do not move)"
            : std::string(
                  "The selected key's time (HH:MM:SS or hours); Enter moves it there, a minute from "
                  "its neighbours at most. A key that follows the sun keeps its event: its offset "
                  "changes");
    const std::string valueHelp =
        std::string("The selected key's value") +
        (leadDesc && !leadDesc->unit.empty() ? " [" + std::string(leadDesc->unit) + "]" : std::string()) +
        "; Enter sets it (clamped into the valid range)" +
        (selectedKeys > 1 ? ", on every selected key of the same parameter" : "");
    double typedShift = 0.0;
    const bool shiftUnreadable = !view.shiftText.empty() && !parseShiftHours(view.shiftText, typedShift);
    const char* shiftHelp =
        "Shift the selected keys by a time: +0:20, -1:00, 0:05 or hours (-0.25); Enter shifts.\nThe keys "
        "stop a minute from keys that do not move, as in a drag; keys that follow the sun keep their "
        "event (their offset changes).";
    auto snapLabel = [](int minutes) { return std::to_string(minutes) + " min"; };
    const int snapMinutes = int(std::lround(view.snapHours * 60.0));

    if (ImGui::BeginPopup("##curvemenu")) {
        const int keys = keyCountOf(view.selected);
        const std::string suffix =
            keys == 1 ? std::string(" (1 key)") : " (" + std::to_string(keys) + " keys)";
        const std::vector<CurvePoint> picked = view.selected;
        keyShapeMenu(doc, picked, suffix);
        ImGui::Separator();
        followTheSunMenu(doc, picked, suffix);
        ImGui::SetNextItemWidth(120.0f);
        if (ImGui::InputText("Time", &timeText, ImGuiInputTextFlags_EnterReturnsTrue) && typeTime(timeText))
            ImGui::CloseCurrentPopup();
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", timeHelp.c_str());
        ImGui::SetNextItemWidth(120.0f);
        if (ImGui::InputText("Value", &valueField, ImGuiInputTextFlags_EnterReturnsTrue) &&
            typeValue(valueField))
            ImGui::CloseCurrentPopup();
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", valueHelp.c_str());
        if (shiftUnreadable) ImGui::PushStyleColor(ImGuiCol_FrameBg, ImVec4(0.55f, 0.15f, 0.12f, 1.0f));
        ImGui::SetNextItemWidth(90.0f);
        if (ImGui::InputTextWithHint("Shift by", "+0:20", &view.shiftText,
                                     ImGuiInputTextFlags_EnterReturnsTrue) &&
            shiftSelection())
            ImGui::CloseCurrentPopup();
        if (shiftUnreadable) ImGui::PopStyleColor();
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", shiftHelp);
        if (ImGui::BeginMenu(("Snap: " + snapLabel(snapMinutes)).c_str())) {
            for (int minutes : kSnapStepsMinutes)
                if (ImGui::MenuItem(snapLabel(minutes).c_str(), nullptr, minutes == snapMinutes))
                    view.snapHours = minutes / 60.0;
            ImGui::EndMenu();
        }
        ImGui::Separator();
        if (ImGui::MenuItem(deleteLabel(picked).c_str(), "Del")) {
            doc.apply(deleteLabel(picked), "", [&](Preset& p) { removeCurvePoints(p, picked); });
            view.selected.clear();
            edit.selectedKey = -1;
        }
        ImGui::EndPopup();
    }

    // --- below the legend: Time | Value, then Shift | Snap, the rows that fit ----------------------
    if (controlRows > 0) {
        const float width = x0 - labelX - 10.0f, gap = 4.0f;
        const float timeW = std::min(ImGui::CalcTextSize("00:00:00").x + 12.0f, 0.45f * width);
        const float snapW = std::min(ImGui::CalcTextSize("60 min").x + frameH + 10.0f, 0.45f * width);
        ImGui::PushID("##curvecontrols");
        // Row `i`'s left field (`leftW` wide) or its right one (the rest); false past the rows that fit.
        auto place = [&](int i, bool right, float leftW) {
            if (i >= controlRows) return false;
            const float y = bottom - controlsH + 2.0f + float(i) * rowH;
            ImGui::SetCursorScreenPos(ImVec2(labelX + 4.0f + (right ? leftW + gap : 0.0f), y));
            ImGui::SetNextItemWidth(right ? width - leftW - gap : leftW);
            return true;
        };
        ImGui::BeginDisabled(!lead);
        if (place(0, false, timeW)) {
            if (ImGui::InputTextWithHint("##keytime", "time", &timeText,
                                         ImGuiInputTextFlags_EnterReturnsTrue))
                typeTime(timeText);
            if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
                ImGui::SetTooltip("%s", lead ? timeHelp.c_str() : "Select a key to type its time");
        }
        if (place(0, true, timeW)) {
            if (ImGui::InputTextWithHint("##keyvalue", "value", &valueField,
                                         ImGuiInputTextFlags_EnterReturnsTrue))
                typeValue(valueField);
            if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
                ImGui::SetTooltip("%s", lead ? valueHelp.c_str() : "Select a key to type its value");
        }
        ImGui::EndDisabled();
        if (place(1, false, width - snapW - gap)) {
            if (shiftUnreadable) ImGui::PushStyleColor(ImGuiCol_FrameBg, ImVec4(0.55f, 0.15f, 0.12f, 1.0f));
            if (ImGui::InputTextWithHint("##shift", "shift +0:20", &view.shiftText,
                                         ImGuiInputTextFlags_EnterReturnsTrue))
                shiftSelection();
            if (shiftUnreadable) ImGui::PopStyleColor();
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", shiftHelp);
        }
        if (place(1, true, width - snapW - gap)) {
            if (ImGui::BeginCombo("##snap", snapLabel(snapMinutes).c_str())) {
                for (int minutes : kSnapStepsMinutes)
                    if (ImGui::Selectable(snapLabel(minutes).c_str(), minutes == snapMinutes))
                        view.snapHours = minutes / 60.0;
                ImGui::EndCombo();
            }
            if (ImGui::IsItemHovered())
                ImGui::SetTooltip(
                    "Snap: dragged keys snap to other keys and to this step (a key that follows the sun: "
                    "its offset from the event); hold Shift to move them freely");
        }
        ImGui::PopID();
    }

    // Tooltips: a key's time and value; elsewhere the inspector's parameter there.
    // (Not after the menu changed the preset: `curves` may point at tracks it removed.)
    if (hovered && drag.kind == CurveDrag::Kind::None && !ImGui::IsPopupOpen("##curvemenu") &&
        doc.revision() == revision) {
        if (hit >= 0) {
            const CurvePoint& p = ids[std::size_t(hit)];
            for (const Drawn& d : curves)
                if (d.target == p.target && d.track && p.key < int(d.track->keys.size())) {
                    const TrackKey& k = d.track->keys[std::size_t(p.key)];
                    ImGui::SetTooltip(
                        "%s\n%s  %s %s%s\nDrag: time and value (snaps to %s; Shift: no snapping); "
                        "Ctrl+click: add to the selection; right-click: tangent, follow the sun, time, "
                        "value, shift, delete",
                        curveLabel(preset, d.target).c_str(), keyTimeText(k).c_str(),
                        valueText(k.value, d.components).c_str(), std::string(d.ref.desc->unit).c_str(),
                        k.flat ? "  (flat)" : "", snapLabel(snapMinutes).c_str());
                }
        } else if (edit.selectedParam) {
            double v[4];
            const double t = wrapHours(view.time.tOf(mouse.x, x0, x1));
            readValueAt(preset, *edit.selectedParam, t, v);
            ImGui::SetTooltip(
                "%s  %s %s\nClick: go to this time; drag: select the keys in a box (Ctrl adds)",
                formatClock(t, ClockResolution::Minutes).c_str(),
                valueText(glm::dvec3(v[0], v[1], v[2]), edit.selectedParam->desc->components()).c_str(),
                std::string(edit.selectedParam->desc->unit).c_str());
        }
    }
}

}  // namespace aerial::editor
