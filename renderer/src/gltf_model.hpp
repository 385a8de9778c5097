// gltf_model.hpp — private to the glTF loader: its error type, the names
// of glTF enums for messages, and the bounds-checked accessor view.
// gltf_model.cpp defines the names, gltf_scene_builder.cpp turns a parsed
// tinygltf::Model into a SceneDesc, gltf_loader.cpp reads the file
// (aerial/renderer/gltf.hpp).
#pragma once

#include <aerial/renderer/gltf.hpp>

#include <tiny_gltf.h>

#include <cstdint>
#include <cstring>
#include <string>

namespace aerial::renderer::gltf {

/// Thrown inside the loader; becomes GltfLoadResult::error.
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

/// The default scene of a parsed model as a SceneDesc in result.scene (every
/// node instanced, every accessor checked, the limits of `options` applied);
/// throws LoadError.
void buildScene(const tinygltf::Model& model, const GltfLoadOptions& options, GltfLoadResult& result);

}  // namespace aerial::renderer::gltf
