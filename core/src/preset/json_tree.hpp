// json_tree.hpp — private: a JSON document as a flat tree that remembers
// where every value and member name sits in the text, so that every error
// the preset reader reports can name its line and column.
//
// Usage:
//   std::vector<detail::JNode> nodes;
//   detail::SyntaxError error;
//   if (!detail::buildJsonTree(text, bomLength, nodes, error)) report(error);
//   // nodes[0] is the root; children are linked through firstChild/nextSibling.
//
// The tree is built from nlohmann's SAX events; the byte offsets come from
// re-scanning the token sequence those events describe. The caps of
// aerial/limits.hpp (kMaxJsonDepth, kMaxJsonValues) are enforced while it is
// built, so whatever a file holds the tree stays small.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace aerial::detail {

/// One JSON value, its position, and its links in the tree.
struct JNode {
    enum Kind : std::uint8_t { Null, Bool, Integer, Unsigned, Float, String, Array, Object };
    Kind kind = Null;
    bool boolean = false;
    std::int64_t integer = 0;
    std::uint64_t unsignedInteger = 0;
    double number = 0.0;
    std::string text;  // String value
    std::string key;   // member name when the parent is an object
    std::uint32_t offset = 0;
    std::uint32_t keyOffset = 0;
    std::int32_t parent = -1;
    std::int32_t firstChild = -1;
    std::int32_t lastChild = -1;
    std::int32_t nextSibling = -1;
    std::uint32_t childCount = 0;

    bool isNumber() const { return kind == Integer || kind == Unsigned || kind == Float; }
    double asDouble() const {
        return kind == Integer ? double(integer) : kind == Unsigned ? double(unsignedInteger) : number;
    }
};

/// "null", "a boolean", "a number", "a string", "an array", "an object".
const char* kindName(JNode::Kind k);

/// Where and why a document could not be read.
struct SyntaxError {
    std::size_t offset = 0;  ///< byte offset of the offending token
    std::string pointer;     ///< JSON pointer of the member being read ("" at the top level)
    std::string message;
};

/// The JSON pointer of a node, from its parents.
std::string pointerOfNode(const std::vector<JNode>& nodes, std::int32_t node);

/// Parses `text` (strict JSON; `start` skips a byte order mark the parser
/// also skips) into `nodes`, root first. Returns false and fills `error` on
/// a syntax error or when a cap of aerial/limits.hpp is exceeded.
bool buildJsonTree(std::string_view text, std::size_t start, std::vector<JNode>& nodes, SyntaxError& error);

}  // namespace aerial::detail
