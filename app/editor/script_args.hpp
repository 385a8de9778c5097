// editor/script_args.hpp — printing and counting parameter values for the
// script commands (their arguments are read by action_args.hpp). Private
// to aerial-editor's script commands (editor_script*.cpp).
#pragma once

#include "action_args.hpp"
#include "preset_edit.hpp"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace aerial::editor {

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
