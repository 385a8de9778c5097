// editor/script.hpp — the automation script format of `aerial-editor
// --script FILE`: one command per line, words separated by blanks, "double
// quotes" around words with blanks, `#` starts a comment. The editor runs
// one command per frame through its real code paths; an error stops the run
// with the line number and a non-zero exit.
//
// The commands are the editor's actions (actions.hpp): each is declared
// once, with its typed arguments, in the one ActionTable, and a script line
// runs through ActionTable::runScript.
#pragma once

#include <string>
#include <vector>

namespace aerial::editor {

struct ScriptCommand {
    int line = 0;                    ///< 1-based line in the file
    std::vector<std::string> words;  ///< words[0] is the command
};

struct ScriptParseResult {
    std::vector<ScriptCommand> commands;
    std::string error;  ///< "FILE:LINE: reason"; empty when fine
    bool ok() const { return error.empty(); }
};

/// Splits script text into commands (blank and comment lines skipped).
ScriptParseResult parseScript(const std::string& text, const std::string& fileName = "<script>");
/// Reads and parses a script file.
ScriptParseResult loadScript(const std::string& path);

}  // namespace aerial::editor
