// editor/editor_param_edits.cpp — the inspector's edits of one parameter
// (panels.hpp: editTextParam, editParam, keyParamNow), apart from its
// drawing: validated, clamped and said, held as an unkeyed change or
// applied as one undo step.
#include "panels.hpp"
#include "pending_edits.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace aerial::editor {

bool editTextParam(Document& doc, const ParamRef& ref, const std::string& text, std::string& error) {
    const ParamDesc& p = *ref.desc;
    if (p.type != ParamType::String || ref.scope() != ParamScope::Global) {
        error = std::string(p.path) + " is not a text parameter of the environment";
        return false;
    }
    Preset candidate = doc.preset();
    *p.string(&candidate.environment) = text;
    std::string pointer(1, '/');  // "location.date" -> "/location/date"
    pointer.append(p.path);
    std::replace(pointer.begin(), pointer.end(), '.', '/');
    for (const PresetIssue& issue : validatePreset(candidate)) {
        if (issue.pointer == pointer) {
            error = issue.message;
            return false;
        }
    }
    doc.apply(std::string("Set ") + std::string(p.label), "",
              [&](Preset& preset) { *p.string(&preset.environment) = text; });
    return true;
}

std::string editParam(Document& doc, EditState& edit, const ParamRef& ref, const double value[4],
                      bool continuous, double timeHours) {
    const ParamDesc& p = *ref.desc;
    // Out of the valid range: clamped, and said (setValueAt clamps the same way).
    std::string clamped;
    if (p.type == ParamType::Scalar || p.type == ParamType::Vec3 || p.type == ParamType::Vec2 ||
        p.type == ParamType::Colour || p.type == ParamType::Int) {
        const int n = p.type == ParamType::Vec3 || p.type == ParamType::Colour ? 3
                      : p.type == ParamType::Vec2                              ? 2
                                                                               : 1;
        // Every value that was clamped is named: one edit of a colour may clamp all three.
        const char* names = p.type == ParamType::Colour ? "rgb" : p.type == ParamType::Vec2 ? "xz" : "xyz";
        std::string values;
        int outside = 0;
        char text[256];
        for (int i = 0; i < n; ++i) {
            if (value[i] >= p.minValue && value[i] <= p.maxValue) continue;
            const double shown = std::isfinite(value[i]) ? std::clamp(value[i], p.minValue, p.maxValue) : 0.0;
            if (n == 1)
                std::snprintf(text, sizeof text, "%.6g", shown);
            else
                std::snprintf(text, sizeof text, "%s%c %.6g to %.6g", outside ? ", " : "", names[i], value[i],
                              shown);
            values += text;
            ++outside;
        }
        if (outside > 0) {
            const std::string label(p.label);
            std::string unit;  // " 1/m" (appended: GCC 12 warns falsely on " " + unit, -Wrestrict)
            if (!p.unit.empty()) unit.append(" ").append(p.unit);
            if (n == 1)
                std::snprintf(text, sizeof text, "%s clamped to %s (valid %g..%g%s)", label.c_str(),
                              values.c_str(), p.minValue, p.maxValue, unit.c_str());
            else
                std::snprintf(text, sizeof text, "%s: %d value%s clamped: %s (valid %g..%g%s)", label.c_str(),
                              outside, outside == 1 ? "" : "s", values.c_str(), p.minValue, p.maxValue,
                              unit.c_str());
            clamped = text;
        }
    }
    if (edit.pending.holds(doc.preset(), ref, timeHours)) {
        edit.pending.set(ref, value, timeHours);  // auto-key off, away from a key: unkeyed
        return clamped;
    }
    edit.pending.erase(ref);
    const std::string address = paramAddress(ref);
    const double time = timeHours;
    const bool animated = trackOf(doc.preset(), ref) != nullptr;
    std::string label(p.label);
    if (animated) label += " (key)";
    doc.apply(label, continuous ? "param:" + address : std::string(),
              [&](Preset& preset) { setValueAt(preset, ref, value, time); });
    return clamped;
}

void keyParamNow(Document& doc, EditState& edit, const ParamRef& ref, double timeHours) {
    if (const PendingEdit* held = edit.pending.find(ref)) {
        const PendingEdit e = *held;
        doc.apply("Key " + std::string(ref.desc->label), "",
                  [&](Preset& p) { setValueAt(p, e.ref, e.value, e.timeHours); });
        edit.pending.erase(ref);
        return;
    }
    doc.apply("Add key", "", [&](Preset& p) { keyParam(p, ref, timeHours); });
}

}  // namespace aerial::editor
