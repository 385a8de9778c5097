// param_names.cpp — the names around the parameter table
// (aerial/param_table.hpp): how many numbers a parameter type holds, the
// scopes' names and JSON keys, the interpolation modes' spellings.
#include <aerial/param_table.hpp>

#include <array>

namespace aerial {
namespace {

constexpr std::array<std::string_view, 3> kInterpolationNames = {"step", "linear", "smooth"};

}  // namespace

int ParamDesc::componentCount(ParamType type) {
    switch (type) {
        case ParamType::Scalar:
        case ParamType::Enum:
        case ParamType::Int:
            return 1;
        case ParamType::Vec2:
            return 2;
        case ParamType::Colour:
        case ParamType::Vec3:
            return 3;
        case ParamType::Quaternion:
            return 4;
        case ParamType::String:
            return 0;
    }
    return 0;
}

std::string_view scopeName(ParamScope scope) {
    switch (scope) {
        case ParamScope::Global:
            return "global";
        case ParamScope::Volume:
            return "volume";
        case ParamScope::Emitter:
            return "emitter";
        case ParamScope::CloudVolume:
            return "cloud volume";
    }
    return "";
}

std::string_view scopeKey(ParamScope scope) {
    switch (scope) {
        case ParamScope::Global:
            return "";
        case ParamScope::Volume:
            return "volume";
        case ParamScope::Emitter:
            return "emitter";
        case ParamScope::CloudVolume:
            return "cloud_volume";
    }
    return "";
}

std::string_view interpolationName(Interpolation interpolation) {
    return kInterpolationNames[std::size_t(interpolation)];
}

bool parseInterpolation(std::string_view name, Interpolation& out) {
    for (std::size_t i = 0; i < kInterpolationNames.size(); ++i) {
        if (kInterpolationNames[i] == name) {
            out = Interpolation(i);
            return true;
        }
    }
    return false;
}

}  // namespace aerial
