// gltf_model.cpp — what the two glTF readers share (aerial/detail/gltf_model.hpp):
// the error helper, the enum names, the checked accessor view and node transform.
#include <aerial/detail/gltf_model.hpp>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>

namespace aerial::detail::gltf {

[[noreturn]] void fail(const std::string& element, const std::string& reason) {
    throw LoadError{element.empty() ? reason : element + ": " + reason};
}

std::string oneLine(std::string text) {
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r' || text.back() == ' '))
        text.pop_back();
    std::string out;
    for (char c : text) {
        if (c == '\n')
            out += "; ";
        else if (c != '\r')
            out += c;
    }
    return out;
}

const char* componentTypeName(int type) {
    switch (type) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
            return "BYTE";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return "UNSIGNED_BYTE";
        case TINYGLTF_COMPONENT_TYPE_SHORT:
            return "SHORT";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return "UNSIGNED_SHORT";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
            return "UNSIGNED_INT";
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            return "FLOAT";
        default:
            return "unknown";
    }
}

std::uint64_t componentSize(int type) {
    switch (type) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return 2;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            return 4;
        default:
            return 0;
    }
}

std::uint64_t componentCount(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR:
            return 1;
        case TINYGLTF_TYPE_VEC2:
            return 2;
        case TINYGLTF_TYPE_VEC3:
            return 3;
        case TINYGLTF_TYPE_VEC4:
            return 4;
        case TINYGLTF_TYPE_MAT2:
            return 4;
        case TINYGLTF_TYPE_MAT3:
            return 9;
        case TINYGLTF_TYPE_MAT4:
            return 16;
        default:
            return 0;
    }
}

const char* typeName(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR:
            return "SCALAR";
        case TINYGLTF_TYPE_VEC2:
            return "VEC2";
        case TINYGLTF_TYPE_VEC3:
            return "VEC3";
        case TINYGLTF_TYPE_VEC4:
            return "VEC4";
        default:
            return "a matrix or unknown type";
    }
}

std::string modeName(int mode) {
    switch (mode) {
        case TINYGLTF_MODE_POINTS:
            return "POINTS";
        case TINYGLTF_MODE_LINE:
            return "LINES";
        case TINYGLTF_MODE_LINE_LOOP:
            return "LINE_LOOP";
        case TINYGLTF_MODE_LINE_STRIP:
            return "LINE_STRIP";
        case TINYGLTF_MODE_TRIANGLE_STRIP:
            return "TRIANGLE_STRIP";
        case TINYGLTF_MODE_TRIANGLE_FAN:
            return "TRIANGLE_FAN";
        default:
            return "unknown";
    }
}

AccessorView accessorView(const tinygltf::Model& model, int index, const std::string& what,
                      const std::string& element, std::uint64_t maxCount) {
    if (index < 0 || std::size_t(index) >= model.accessors.size())
        fail(element, what + " accessor " + std::to_string(index) + " does not exist (" +
                          std::to_string(model.accessors.size()) + " accessors)");
    const std::string a = "accessors[" + std::to_string(index) + "]";
    const tinygltf::Accessor& accessor = model.accessors[std::size_t(index)];
    if (accessor.sparse.isSparse) fail(a, "sparse accessors are not supported");
    if (accessor.bufferView < 0) fail(a, "has no bufferView (zero-filled accessors are not supported)");
    if (std::size_t(accessor.bufferView) >= model.bufferViews.size())
        fail(a, "bufferView " + std::to_string(accessor.bufferView) + " does not exist");
    const std::string bvName = "bufferViews[" + std::to_string(accessor.bufferView) + "]";
    const tinygltf::BufferView& bv = model.bufferViews[std::size_t(accessor.bufferView)];
    if (bv.buffer < 0 || std::size_t(bv.buffer) >= model.buffers.size())
        fail(bvName, "buffer " + std::to_string(bv.buffer) + " does not exist");
    const tinygltf::Buffer& buffer = model.buffers[std::size_t(bv.buffer)];
    const std::uint64_t bufferSize = buffer.data.size();
    const std::uint64_t bvOffset = bv.byteOffset, bvLength = bv.byteLength;
    if (bvOffset > bufferSize || bvLength > bufferSize - bvOffset)
        fail(bvName, "bytes " + std::to_string(bvOffset) + ".." + std::to_string(bvOffset + bvLength) +
                         " lie outside buffers[" + std::to_string(bv.buffer) + "] (" +
                         std::to_string(bufferSize) + " bytes)");
    AccessorView v;
    v.componentType = accessor.componentType;
    v.components = componentCount(accessor.type);
    v.normalized = accessor.normalized;
    const std::uint64_t size = componentSize(accessor.componentType);
    if (size == 0) fail(a, "unknown componentType " + std::to_string(accessor.componentType));
    if (v.components == 0) fail(a, "unknown type");
    const std::uint64_t elementSize = size * v.components;
    v.stride = bv.byteStride != 0 ? bv.byteStride : elementSize;
    if (v.stride < elementSize)
        fail(bvName, "byteStride " + std::to_string(v.stride) + " is smaller than the " +
                         std::to_string(elementSize) + "-byte elements of " + a);
    v.count = accessor.count;
    if (v.count > maxCount)
        fail(a, "count " + std::to_string(v.count) + " is over the limit of " + std::to_string(maxCount));
    const std::uint64_t offset = accessor.byteOffset;
    if (v.count > 0) {
        // Written so that nothing overflows whatever offset, stride and count say.
        const bool fits = offset <= bvLength && elementSize <= bvLength - offset &&
                          v.count - 1 <= (bvLength - offset - elementSize) / v.stride;
        if (!fits)
            fail(a, "count " + std::to_string(v.count) + " with byteOffset " + std::to_string(offset) +
                        " and stride " + std::to_string(v.stride) + " reaches past the end of " + bvName +
                        " (" + std::to_string(bvLength) + " bytes)");
    }
    v.data = buffer.data.data() + bvOffset + offset;
    return v;
}

glm::dmat4 nodeTransform(const tinygltf::Node& node, const std::string& element) {
    glm::dmat4 m(1.0);
    if (!node.matrix.empty()) {
        if (node.matrix.size() != 16)
            fail(element, "matrix has " + std::to_string(node.matrix.size()) + " values, expected 16");
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) m[c][r] = node.matrix[std::size_t(c * 4 + r)];  // column-major
    } else {
        glm::dvec3 t(0.0), s(1.0);
        glm::dquat q(1.0, 0.0, 0.0, 0.0);
        if (!node.translation.empty()) {
            if (node.translation.size() != 3) fail(element, "translation needs 3 values");
            t = {node.translation[0], node.translation[1], node.translation[2]};
        }
        if (!node.rotation.empty()) {
            if (node.rotation.size() != 4) fail(element, "rotation needs 4 values (x, y, z, w)");
            q = glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
            const double len = glm::length(q);
            if (!(len > 1e-12) || !std::isfinite(len)) fail(element, "rotation is not a unit quaternion");
            q = q / len;
        }
        if (!node.scale.empty()) {
            if (node.scale.size() != 3) fail(element, "scale needs 3 values");
            s = {node.scale[0], node.scale[1], node.scale[2]};
        }
        m = glm::translate(glm::dmat4(1.0), t) * glm::mat4_cast(q) * glm::scale(glm::dmat4(1.0), s);
    }
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) fail(element, "the transform has a non-finite value");
    return m;
}

}  // namespace aerial::detail::gltf
