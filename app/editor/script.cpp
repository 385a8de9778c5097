// editor/script.cpp — see script.hpp.
#include "script.hpp"

#include <fstream>
#include <sstream>

namespace aerial::editor {

ScriptParseResult parseScript(const std::string& text, const std::string& fileName) {
    ScriptParseResult result;
    std::istringstream lines(text);
    std::string line;
    int number = 0;
    while (std::getline(lines, line)) {
        ++number;
        ScriptCommand command;
        command.line = number;
        std::string word;
        bool inWord = false, quoted = false;
        for (std::size_t i = 0; i < line.size(); ++i) {
            const char c = line[i];
            if (quoted) {
                if (c == '"')
                    quoted = false;
                else
                    word += c;
                continue;
            }
            if (c == '#') break;
            if (c == '"') {
                quoted = inWord = true;
            } else if (c == ' ' || c == '\t' || c == '\r') {
                if (inWord) command.words.push_back(word);
                word.clear();
                inWord = false;
            } else {
                word += c;
                inWord = true;
            }
        }
        if (quoted) {
            result.error = fileName + ":" + std::to_string(number) + ": unterminated quote";
            return result;
        }
        if (inWord) command.words.push_back(word);
        if (!command.words.empty()) result.commands.push_back(std::move(command));
    }
    return result;
}

ScriptParseResult loadScript(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        ScriptParseResult r;
        r.error = path + ": cannot read the script";
        return r;
    }
    std::ostringstream text;
    text << in.rdbuf();
    return parseScript(text.str(), path);
}

}  // namespace aerial::editor
