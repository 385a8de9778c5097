// editor/action_args.cpp — see action_args.hpp.
#include "action_args.hpp"

#include <aerial/clock.hpp>

#include <cmath>
#include <cstdlib>
#include <limits>

namespace aerial::editor {

bool toNumber(const std::string& text, double& out) {
    if (text.empty()) return false;
    char* end = nullptr;
    out = std::strtod(text.c_str(), &end);
    return end && *end == '\0' && std::isfinite(out);
}

bool toTime(const std::string& text, double& hours) {
    if (parseClock(text, hours)) return true;
    double value = 0.0;
    if (!toNumber(text, value) || value < 0.0 || value > 24.0) return false;
    hours = value;
    return true;
}

ActionArgs::ActionArgs(std::vector<std::string> words, std::vector<double> numbers)
    : words_(std::move(words)), numbers_(std::move(numbers)) {
    numbers_.resize(words_.size(), std::numeric_limits<double>::quiet_NaN());
}

double ActionArgs::number(std::size_t i) const {
    return i < numbers_.size() ? numbers_[i] : std::numeric_limits<double>::quiet_NaN();
}

std::string ActionArgs::joined(std::size_t from) const {
    std::string text;
    for (std::size_t i = from; i < words_.size(); ++i) {
        if (i > from) text += ' ';
        text += words_[i];
    }
    return text;
}

// (std::string::append throughout: GCC 12 warns falsely on chains of `+`.)
static std::string shownName(const ArgSpec& a) {
    std::string text;
    if (a.choices.empty()) {
        text.append(a.name);
        if (a.type == ArgType::Rest) text.append("...");
        return text;
    }
    for (const std::string& c : a.choices) {
        if (!text.empty()) text.append("|");
        text.append(c);
    }
    return text;
}

std::string usageOf(const std::string& name, const std::vector<ArgSpec>& args) {
    std::string text = name;
    for (const ArgSpec& a : args) {
        text.append(a.optional ? " [" : " ");
        text.append(shownName(a));
        if (a.optional) text.append("]");
    }
    return text;
}

int minArgCount(const std::vector<ArgSpec>& args) {
    int n = 0;
    for (const ArgSpec& a : args) n += a.optional ? 0 : 1;
    return n;
}

int maxArgCount(const std::vector<ArgSpec>& args) {
    for (const ArgSpec& a : args)
        if (a.type == ArgType::Rest) return -1;
    return int(args.size());
}

// Why `word` does not read as `a` ("" when it does), and its value.
static std::string readArg(const ArgSpec& a, const std::string& word, double& value) {
    switch (a.type) {
        case ArgType::Word:
        case ArgType::Rest:
            if (a.choices.empty()) return {};
            for (const std::string& c : a.choices)
                if (word == c) return {};
            return "is not one of " + shownName(a);
        case ArgType::Number:
            return toNumber(word, value) ? std::string() : "is not a number";
        case ArgType::Count:
            return toNumber(word, value) && value >= 0.0 ? std::string() : "is not a count (a number >= 0)";
        case ArgType::Time:
            return toTime(word, value) ? std::string() : "is not a time of day (HH:MM or hours in [0, 24])";
    }
    return {};
}

bool parseActionArgs(const std::vector<std::string>& words, const std::vector<ArgSpec>& args, bool extraWords,
                     const std::string& usage, ActionArgs& out, std::string& error) {
    const std::string& name = words.at(0);
    const int given = int(words.size()) - 1, most = maxArgCount(args);
    if (given < minArgCount(args) || (most >= 0 && given > most && !extraWords)) {
        error = name + ": usage: " + usage;
        return false;
    }
    std::vector<double> numbers(words.size(), std::numeric_limits<double>::quiet_NaN());
    for (std::size_t i = 1; i < words.size(); ++i) {
        if (args.empty()) break;
        if (i - 1 >= args.size() && args.back().type != ArgType::Rest) break;  // extra words, unread
        const ArgSpec& a = args[std::min(i - 1, args.size() - 1)];
        const std::string why = readArg(a, words[i], numbers[i]);
        if (!why.empty()) {
            error.assign(name)
                .append(": ")
                .append(a.name)
                .append(" \"")
                .append(words[i])
                .append("\" ")
                .append(why);
            return false;
        }
    }
    out = ActionArgs(words, std::move(numbers));
    return true;
}

}  // namespace aerial::editor
