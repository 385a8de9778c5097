// preset_issues.cpp — PresetIssue's one-line form and the helper that makes
// a whole-file issue (preset_issues.hpp).
#include "preset_issues.hpp"

namespace aerial {

PresetIssue detail::makeIssue(std::string file, std::string message) {
    PresetIssue i;
    i.file = std::move(file);
    i.message = std::move(message);
    return i;
}

std::string PresetIssue::toString() const {
    std::string s = file.empty() ? std::string("<preset>") : file;
    if (line > 0) {  // appended piece by piece: GCC 12 warns (-Wrestrict) on the chain of +
        s += ':';
        s += std::to_string(line);
        s += ':';
        s += std::to_string(column);
    }
    s += severity == Severity::Error ? ": error: " : ": warning: ";
    if (!pointer.empty()) s += pointer + ": ";
    s += message;
    return s;
}

}  // namespace aerial
