// editor/script.hpp — the automation script format of `aerial-editor
// --script FILE`: one command per line, words separated by blanks, "double
// quotes" around words with blanks, `#` starts a comment. The editor runs
// one command per frame through its real code paths; an error stops the run
// with the line number and a non-zero exit.
//
// The commands are declared in a ScriptCommandTable (name, argument count,
// usage, help, handler): editor_script.cpp declares those with arguments,
// and the action table (actions.hpp) adds the user actions scripts may call.
#pragma once

#include <functional>
#include <string>
#include <string_view>
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

/// ScriptCommandSpec::maxArgs for a command that ignores extra arguments.
inline constexpr int kAnyArgs = -1;

/// One script command.
struct ScriptCommandSpec {
    std::string name;
    int minArgs = 0;
    int maxArgs = 0;    ///< kAnyArgs: no upper limit
    std::string usage;  ///< "open PATH": quoted by the error for a wrong argument count
    std::string help;   ///< one line
    /// Runs the command (`words[0]` is its name); false with `error` set on failure.
    std::function<bool(const std::vector<std::string>& words, std::string& error)> run;
};

/// The script language: every command, found by name.
class ScriptCommandTable {
public:
    /// Adds a command (names are unique, asserted).
    void add(ScriptCommandSpec spec);
    const ScriptCommandSpec* find(std::string_view name) const;
    /// Runs `command`. Errors: `unknown command "NAME"`, `NAME: usage:
    /// USAGE` for a wrong argument count, else the handler's.
    bool run(const ScriptCommand& command, std::string& error) const;
    const std::vector<ScriptCommandSpec>& commands() const { return commands_; }

private:
    std::vector<ScriptCommandSpec> commands_;
};

}  // namespace aerial::editor
