// editor/action_args.hpp — the typed arguments of the editor's actions
// (actions.hpp): how each is declared (ArgSpec), read from a script's words
// and checked (parseActionArgs), and handed to the action's handler
// (ActionArgs). No GUI, unit-tested.
//
// An argument is a word (any text, or one of a few choices), a number, a
// count (a number >= 0), a time of day (HH:MM or hours in [0, 24]) or the
// rest of the line. A word that does not read as its type is refused with
// a message that names the command, the argument and the reason:
//   time: T "noon-ish" is not a time of day (HH:MM or hours in [0, 24])
//   wait_frames: N "-1" is not a count (a number >= 0)
//   answer: CHOICE "maybe" is not one of save|discard|cancel
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace aerial::editor {

enum class ArgType {
    Word,    ///< any word; with `choices`, one of them
    Number,  ///< a finite number
    Count,   ///< a finite number >= 0 (frames, objects, keys)
    Time,    ///< a time of day [h]: HH:MM, "7.5h" (aerial::parseClock) or hours in [0, 24]
    Rest,    ///< every word from here on (at least one when required)
};

/// One argument of an action, as its usage shows it ("PATH", "[FRAMES]").
struct ArgSpec {
    std::string name;  ///< "PATH", "T", "DX"; the usage's word
    ArgType type = ArgType::Word;
    bool optional = false;             ///< may be left out (optional arguments come last)
    std::vector<std::string> choices;  ///< Word: the only words allowed (empty: any)

    ArgSpec opt() const {
        ArgSpec a = *this;
        a.optional = true;
        return a;
    }
};

// Declaration helpers: {word("PATH"), number("FRAMES").opt()}.
inline ArgSpec word(std::string name) { return {std::move(name), ArgType::Word}; }
inline ArgSpec number(std::string name) { return {std::move(name), ArgType::Number}; }
inline ArgSpec count(std::string name) { return {std::move(name), ArgType::Count}; }
inline ArgSpec timeOfDay(std::string name) { return {std::move(name), ArgType::Time}; }
inline ArgSpec rest(std::string name) { return {std::move(name), ArgType::Rest}; }
inline ArgSpec choice(std::string name, std::vector<std::string> choices) {
    return {std::move(name), ArgType::Word, false, std::move(choices)};
}
/// The usual switch: on|off.
inline ArgSpec onOff(std::string name = "on|off") { return choice(std::move(name), {"on", "off"}); }

/// Reads a finite number (the whole word).
bool toNumber(const std::string& text, double& out);
/// A time of day: anything aerial::parseClock reads ("06:30", "7.5h"), or
/// decimal hours up to 24 inclusive (the end of the day, for a play range).
bool toTime(const std::string& text, double& hours);

/// The arguments an action is run with: the script's words (words[0] is the
/// action's name, as a script writes it) with the numbers of its Number,
/// Count and Time arguments already read. From a menu or a key there are
/// no arguments: size() == 1.
class ActionArgs {
public:
    ActionArgs() = default;
    explicit ActionArgs(std::vector<std::string> words, std::vector<double> numbers = {});

    /// Words including the name.
    std::size_t size() const { return words_.size(); }
    /// Word i (0: the name, 1: the first argument).
    const std::string& operator[](std::size_t i) const { return words_.at(i); }
    const std::string& back() const { return words_.back(); }
    const std::vector<std::string>& words() const { return words_; }
    /// Whether argument word i was given.
    bool has(std::size_t i) const { return i < words_.size(); }
    /// The value of word i when it is a Number, Count or Time argument (NaN
    /// when it is not one, or not given).
    double number(std::size_t i) const;
    /// Words from i on, joined by single blanks (a Rest argument).
    std::string joined(std::size_t from) const;

private:
    std::vector<std::string> words_;
    std::vector<double> numbers_;  ///< per word, NaN where not numeric
};

/// The usage an argument list makes: "NAME ARG [OPT] CHOICE|CHOICE REST...".
std::string usageOf(const std::string& name, const std::vector<ArgSpec>& args);
/// How many arguments `args` takes at least and at most (-1: no limit).
int minArgCount(const std::vector<ArgSpec>& args);
int maxArgCount(const std::vector<ArgSpec>& args);

/// Reads `words` (words[0] the name) as `args`: the count must fit (else
/// "NAME: usage: USAGE", unless `extraWords` lets extra words through
/// unread), each word must read as its type (else "NAME: ARG "WORD" is not
/// ..."). True with `out` set, else false with `error` set.
bool parseActionArgs(const std::vector<std::string>& words, const std::vector<ArgSpec>& args, bool extraWords,
                     const std::string& usage, ActionArgs& out, std::string& error);

}  // namespace aerial::editor
