// editor/script_args.hpp — reading the script's arguments: numbers, times
// (hours or HH:MM) and parameter values. Private to aerial-editor's script
// commands (editor_script*.cpp).
#pragma once

#include "preset_edit.hpp"

#include <aerial/clock.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace aerial::editor {

/// The words of a script command; words[0] is its name.
using ScriptWords = std::vector<std::string>;

inline bool toNumber(const std::string& text, double& out) {
    if (text.empty()) return false;
    char* end = nullptr;
    out = std::strtod(text.c_str(), &end);
    return end && *end == '\0' && std::isfinite(out);
}

/// A time of day: anything aerial::parseClock reads ("06:30", "7.5h"), or
/// decimal hours up to 24 inclusive (the end of the day, for a play range).
inline bool toTime(const std::string& text, double& hours) {
    if (parseClock(text, hours)) return true;
    double value = 0.0;
    if (!toNumber(text, value) || value < 0.0 || value > 24.0) return false;
    hours = value;
    return true;
}

inline std::string formatValues(const double* v, int n) {
    std::string text;
    char part[40];
    for (int i = 0; i < n; ++i) {
        std::snprintf(part, sizeof part, "%s%.17g", i ? " " : "", v[i]);
        text += part;
    }
    return text;
}

/// How many numbers a value of `p` has.
inline int valueCount(const ParamDesc& p) {
    switch (p.type) {
        case ParamType::Vec2:
            return 2;
        case ParamType::Colour:
        case ParamType::Vec3:
            return 3;
        case ParamType::Quaternion:
            return 4;
        default:
            return 1;
    }
}

}  // namespace aerial::editor
