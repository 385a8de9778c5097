// json_tree.cpp — builds the positioned JSON tree (json_tree.hpp) from
// nlohmann's SAX events, keeping the byte offset of every value and member
// name and enforcing the depth and value-count caps.
#include "json_tree.hpp"

#include "json_text.hpp"

#include <aerial/limits.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>

namespace aerial::detail {

using sv = std::string_view;

const char* kindName(JNode::Kind k) {
    switch (k) {
        case JNode::Null:
            return "null";
        case JNode::Bool:
            return "a boolean";
        case JNode::Integer:
        case JNode::Unsigned:
        case JNode::Float:
            return "a number";
        case JNode::String:
            return "a string";
        case JNode::Array:
            return "an array";
        case JNode::Object:
            return "an object";
    }
    return "?";
}

// The JSON pointer of a node, from its parents.
std::string pointerOfNode(const std::vector<JNode>& nodes, std::int32_t node) {
    std::vector<std::string> parts;
    while (node > 0) {
        const JNode& n = nodes[std::size_t(node)];
        const JNode& parent = nodes[std::size_t(n.parent)];
        if (parent.kind == JNode::Object) {
            parts.push_back(escapePointerToken(n.key));
        } else {
            std::size_t index = 0;
            for (std::int32_t c = parent.firstChild; c != node; c = nodes[std::size_t(c)].nextSibling)
                ++index;
            parts.push_back(std::to_string(index));
        }
        node = n.parent;
    }
    std::string out;
    for (auto it = parts.rbegin(); it != parts.rend(); ++it) out += "/" + *it;
    return out;
}

namespace {

class TreeBuilder final : public nlohmann::json_sax<nlohmann::json> {
public:
    TreeBuilder(sv text, std::size_t start, std::vector<JNode>& nodes)
        : text_(text), nodes_(nodes), cursor_(start) {}

    bool null() override { return room() && add(JNode::Null); }
    bool boolean(bool v) override {
        if (!room()) return false;
        JNode& n = nodes_[std::size_t(addIndex(JNode::Bool))];
        n.boolean = v;
        return true;
    }
    bool number_integer(number_integer_t v) override {
        if (!room()) return false;
        nodes_[std::size_t(addIndex(JNode::Integer))].integer = v;
        return true;
    }
    bool number_unsigned(number_unsigned_t v) override {
        if (!room()) return false;
        nodes_[std::size_t(addIndex(JNode::Unsigned))].unsignedInteger = v;
        return true;
    }
    bool number_float(number_float_t v, const string_t&) override {
        if (!room()) return false;
        nodes_[std::size_t(addIndex(JNode::Float))].number = v;
        return true;
    }
    bool string(string_t& v) override {
        if (!room()) return false;
        nodes_[std::size_t(addIndex(JNode::String))].text = std::move(v);
        return true;
    }
    bool binary(binary_t&) override { return false; }
    bool start_object(std::size_t) override {
        if (!enter()) return false;
        stack_.push_back(addIndex(JNode::Object));
        return true;
    }
    bool key(string_t& v) override {
        pendingKeyOffset_ = std::uint32_t(nextToken());
        pendingKey_ = std::move(v);
        return true;
    }
    bool end_object() override {
        nextToken();
        stack_.pop_back();
        return true;
    }
    bool start_array(std::size_t) override {
        if (!enter()) return false;
        stack_.push_back(addIndex(JNode::Array));
        return true;
    }
    bool end_array() override {
        nextToken();
        stack_.pop_back();
        return true;
    }
    bool parse_error(std::size_t position, const std::string&,
                     const nlohmann::detail::exception& ex) override {
        // nlohmann counts the character it stopped at; report the start of
        // the offending token (after the last good one) when that is earlier.
        const std::size_t stop = std::min(position > 0 ? position - 1 : 0, text_.size());
        std::size_t start = cursor_;
        while (start < stop && isSpace(text_[start])) ++start;
        if (start < stop && (text_[start] == ',' || text_[start] == ':')) {
            ++start;
            while (start < stop && isSpace(text_[start])) ++start;
        }
        error.offset = std::min(start, stop);
        std::string what = ex.what();
        // "[json.exception.parse_error.101] parse error at line 1, column 2: reason"
        if (const std::size_t bracket = what.find("] ");
            what.rfind("[json.exception", 0) == 0 && bracket != std::string::npos)
            what.erase(0, bracket + 2);
        if (what.rfind("parse error", 0) == 0) {
            const std::size_t colon = what.find(": ");
            if (colon != std::string::npos) what.erase(0, colon + 2);
        }
        error.message = printable(what);
        pointAtOpenContainer();
        failed = true;
        return false;
    }

    SyntaxError error;
    bool failed = false;

private:
    static bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

    // Refuses the value about to be added when it would nest deeper than
    // limits::kMaxJsonDepth or make more than limits::kMaxJsonValues values
    // (the caps that keep the tree small whatever the file holds).
    bool enter() {
        if (stack_.size() < limits::kMaxJsonDepth) return room();
        refuse("nested deeper than " + std::to_string(limits::kMaxJsonDepth) + " levels (the limit)");
        return false;
    }
    bool room() {
        if (nodes_.size() < limits::kMaxJsonValues) return true;
        refuse("more than " + std::to_string(limits::kMaxJsonValues) + " JSON values (the limit)");
        return false;
    }

    // Where in the document: the open container and the member being read
    // (error.pointer; left alone at the top level).
    void pointAtOpenContainer() {
        if (stack_.empty()) return;
        const std::int32_t top = stack_.back();
        const JNode& n = nodes_[std::size_t(top)];
        error.pointer = pointerOfNode(nodes_, top);
        if (n.kind == JNode::Object && !pendingKey_.empty())
            error.pointer = pointerJoin(error.pointer, pendingKey_);
        else if (n.kind == JNode::Array)
            error.pointer = pointerJoin(error.pointer, std::size_t(n.childCount));
    }

    void refuse(std::string why) {
        std::size_t i = cursor_;
        while (i < text_.size() && (isSpace(text_[i]) || text_[i] == ',' || text_[i] == ':')) ++i;
        error.offset = i;
        pointAtOpenContainer();
        error.message = std::move(why);
        failed = true;
    }

    // The start of the next token after the previous one (skipping white
    // space and the ',' and ':' separators, which raise no SAX event), and
    // moves past it.
    std::size_t nextToken() {
        std::size_t i = cursor_;
        while (i < text_.size() && (isSpace(text_[i]) || text_[i] == ',' || text_[i] == ':')) ++i;
        const std::size_t start = i;
        if (i < text_.size()) {
            const char c = text_[i];
            if (c == '{' || c == '}' || c == '[' || c == ']') {
                ++i;
            } else if (c == '"') {
                ++i;
                while (i < text_.size() && text_[i] != '"') i += text_[i] == '\\' ? 2 : 1;
                ++i;
            } else {
                while (i < text_.size() && !isSpace(text_[i]) && text_[i] != ',' && text_[i] != ']' &&
                       text_[i] != '}' && text_[i] != ':')
                    ++i;
            }
        }
        cursor_ = std::min(i, text_.size());
        return start;
    }

    bool add(JNode::Kind kind) {
        addIndex(kind);
        return true;
    }

    std::int32_t addIndex(JNode::Kind kind) {
        const std::int32_t index = std::int32_t(nodes_.size());
        nodes_.emplace_back();
        JNode& n = nodes_.back();
        n.kind = kind;
        n.offset = std::uint32_t(nextToken());
        if (!stack_.empty()) {
            const std::int32_t parentIndex = stack_.back();
            JNode& parent = nodes_[std::size_t(parentIndex)];
            n.parent = parentIndex;
            if (parent.kind == JNode::Object) {
                n.key = std::move(pendingKey_);
                pendingKey_.clear();
                n.keyOffset = pendingKeyOffset_;
            }
            if (parent.lastChild >= 0)
                nodes_[std::size_t(parent.lastChild)].nextSibling = index;
            else
                parent.firstChild = index;
            parent.lastChild = index;
            ++parent.childCount;
        }
        return index;
    }

    sv text_;
    std::vector<JNode>& nodes_;
    std::vector<std::int32_t> stack_;
    std::size_t cursor_ = 0;
    std::string pendingKey_;
    std::uint32_t pendingKeyOffset_ = 0;
};

}  // namespace

bool buildJsonTree(sv text, std::size_t start, std::vector<JNode>& nodes, SyntaxError& error) {
    nodes.clear();
    nodes.reserve(std::min(text.size() / 16 + 16, limits::kMaxJsonValues));
    TreeBuilder builder(text, start, nodes);
    const bool parsed = nlohmann::json::sax_parse(text.begin(), text.end(), &builder,
                                                  nlohmann::json::input_format_t::json, true);
    if (parsed && !builder.failed) return true;
    error = builder.error;
    if (!builder.failed) error.message = "syntax error";
    return false;
}

}  // namespace aerial::detail
