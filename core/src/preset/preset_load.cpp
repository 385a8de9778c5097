// preset_load.cpp — loadPreset and parsePreset: bytes from a file or memory
// to a Preset or the list of what is wrong with it. Refuses what is not
// UTF-8 JSON text (UTF-16, NUL bytes) and files over the size cap before
// parsing, then builds the positioned tree (json_tree.hpp) and reads it
// (preset_read.hpp). Never throws.
#include "json_text.hpp"
#include "json_tree.hpp"
#include "preset_issues.hpp"
#include "preset_read.hpp"

#include <aerial/limits.hpp>
#include <aerial/preset.hpp>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace aerial {

using namespace detail;
using sv = std::string_view;

namespace {

std::string tooLargeMessage(std::size_t bytes, bool atLeast = false) {
    std::string m = atLeast ? "the file is at least " : "the file is ";
    m += std::to_string(bytes);
    m += " bytes, over the limit of ";
    m += std::to_string(limits::kMaxPresetFileBytes);
    m += " bytes (16 MiB) for a preset";
    return m;
}

}  // namespace

PresetLoadResult parsePreset(std::string_view jsonText, std::string_view fileName) {
    PresetLoadResult result;
    const std::string file(fileName);
    try {
        if (jsonText.size() > limits::kMaxPresetFileBytes) {
            result.errors.push_back(makeIssue(file, tooLargeMessage(jsonText.size())));
            return result;
        }
        const sv body = jsonText;
        // Text that is not UTF-8 JSON at all: say what it is.
        if (body.substr(0, 2) == "\xFF\xFE" || body.substr(0, 2) == "\xFE\xFF") {
            PresetIssue i = makeIssue(file, "UTF-16 text (byte order mark); a preset is UTF-8 JSON");
            i.line = i.column = 1;
            result.errors.push_back(std::move(i));
            return result;
        }
        if (const std::size_t nul = body.find('\0'); nul != sv::npos) {
            PresetIssue i = makeIssue(file, "a NUL byte: a preset is UTF-8 JSON text, not binary data");
            lineColumn(body, nul, i.line, i.column);
            result.errors.push_back(std::move(i));
            return result;
        }
        // nlohmann skips a UTF-8 byte order mark; so does the token re-scan.
        const std::size_t bom = body.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0;
        std::vector<JNode> nodes;
        SyntaxError syntax;
        if (!buildJsonTree(body, bom, nodes, syntax)) {
            PresetIssue i = makeIssue(file, std::move(syntax.message));
            i.pointer = std::move(syntax.pointer);
            lineColumn(body, syntax.offset, i.line, i.column);
            result.errors.push_back(std::move(i));
            return result;
        }
        Preset preset;
        readPresetTree(body, file, nodes, preset, result.errors, result.warnings);
        if (result.errors.empty()) result.preset = std::move(preset);
    } catch (const std::exception& e) {
        result.preset.reset();
        result.errors.push_back(makeIssue(file, std::string("could not load: ") + e.what()));
    } catch (...) {
        result.preset.reset();
        result.errors.push_back(makeIssue(file, "could not load: unknown failure"));
    }
    return result;
}

PresetLoadResult loadPreset(const std::string& path) {
    try {
        auto failed = [&](std::string message) {
            PresetLoadResult r;
            r.errors.push_back(makeIssue(path, std::move(message)));
            return r;
        };
        std::ifstream in(path, std::ios::binary);
        if (!in) return failed(std::string("cannot open: ") + std::strerror(errno));
        std::error_code ec;
        if (std::filesystem::is_directory(path, ec)) return failed("cannot open: Is a directory");
        // Never read more than the limit (plus one byte to tell it is over),
        // whatever the file (or a pipe, or /dev/zero) holds.
        std::string text;
        char chunk[65536];
        while (in && text.size() <= limits::kMaxPresetFileBytes) {
            in.read(chunk, sizeof chunk);
            text.append(chunk, std::size_t(in.gcount()));
        }
        if (in.bad()) return failed("read error");
        if (text.size() > limits::kMaxPresetFileBytes) {
            // The size on disk when there is one (a pipe or a device has none).
            const std::uintmax_t size = std::filesystem::file_size(path, ec);
            return failed(!ec && size >= text.size() ? tooLargeMessage(std::size_t(size))
                                                     : tooLargeMessage(text.size(), true));
        }
        return parsePreset(text, path);
    } catch (const std::exception& e) {
        PresetLoadResult r;
        r.errors.push_back(makeIssue(path, std::string("could not load: ") + e.what()));
        return r;
    }
}

}  // namespace aerial
