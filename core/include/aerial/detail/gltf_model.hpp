// aerial/detail/gltf_model.hpp — what the two glTF readers share (core's
// fog volume meshes, loadFogMesh; the renderer's scenes, loadGltfScene): the
// error type, glTF enum names for messages, the bounds-checked accessor view
// and the checked node transform. Not part of the stable API (namespace
// detail); needs Debian's tinygltf headers (never TINYGLTF_IMPLEMENTATION).
//
// Every accessor is checked against its buffer view and buffer, overflow-free
// whatever count, offset and stride say, before a byte is read.
#pragma once

#include <tiny_gltf.h>

#include <glm/mat4x4.hpp>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>

namespace aerial::detail::gltf {

/// Thrown by the readers; message = "element: reason" (fail()).
struct LoadError {
    std::string message;
};

/// Throws LoadError "element: reason" (just the reason when element is "").
[[noreturn]] void fail(const std::string& element, const std::string& reason);

/// tinygltf's multi-line messages on one line.
std::string oneLine(std::string text);

/// glTF enums as the specification spells them, for messages.
const char* componentTypeName(int type);
std::uint64_t componentSize(int type);
std::uint64_t componentCount(int type);
const char* typeName(int type);
std::string modeName(int mode);

/// A checked window onto an accessor's bytes: element k starts at
/// data + k * stride and has elementSize bytes, all inside the buffer.
struct AccessorView {
    const unsigned char* data = nullptr;
    std::uint64_t stride = 0;
    std::uint64_t count = 0;
    int componentType = 0;
    std::uint64_t components = 0;
    bool normalized = false;

    double component(std::uint64_t element, std::uint64_t c) const {
        const unsigned char* p = data + element * stride + c * componentSize(componentType);
        switch (componentType) {
            case TINYGLTF_COMPONENT_TYPE_FLOAT: {
                float v;
                std::memcpy(&v, p, 4);
                return v;
            }
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
                std::uint32_t v;
                std::memcpy(&v, p, 4);
                return normalized ? v / 4294967295.0 : double(v);
            }
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
                std::uint16_t v;
                std::memcpy(&v, p, 2);
                return normalized ? v / 65535.0 : double(v);
            }
            case TINYGLTF_COMPONENT_TYPE_SHORT: {
                std::int16_t v;
                std::memcpy(&v, p, 2);
                return normalized ? std::max(v / 32767.0, -1.0) : double(v);
            }
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
                return normalized ? p[0] / 255.0 : double(p[0]);
            case TINYGLTF_COMPONENT_TYPE_BYTE: {
                const auto v = static_cast<std::int8_t>(p[0]);
                return normalized ? std::max(v / 127.0, -1.0) : double(v);
            }
            default:
                return 0.0;
        }
    }

    std::uint32_t index(std::uint64_t element) const {
        const unsigned char* p = data + element * stride;
        switch (componentType) {
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
                return p[0];
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
                std::uint16_t v;
                std::memcpy(&v, p, 2);
                return v;
            }
            default: {
                std::uint32_t v;
                std::memcpy(&v, p, 4);
                return v;
            }
        }
    }
};

/// model.accessors[index] checked against its buffer view and buffer, its
/// count at most `maxCount`; `what` names it in messages ("POSITION"),
/// `element` is the referring element. Throws LoadError.
AccessorView accessorView(const tinygltf::Model& model, int index, const std::string& what,
                          const std::string& element, std::uint64_t maxCount);

/// A node's local transform (matrix, or translation * rotation * scale),
/// checked: value counts, a unit-able quaternion, finite entries. Throws
/// LoadError naming `element`.
glm::dmat4 nodeTransform(const tinygltf::Node& node, const std::string& element);

}  // namespace aerial::detail::gltf
