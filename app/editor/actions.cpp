// editor/actions.cpp — see actions.hpp.
#include "actions.hpp"

#ifndef GLFW_INCLUDE_NONE
#define GLFW_INCLUDE_NONE  // the key codes only, no GL header
#endif
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cassert>

namespace aerial::editor {

std::string_view keyContextName(KeyContext context) {
    switch (context) {
        case KeyContext::Anywhere:
            return "";
        case KeyContext::OutsideTimeline:
            return "outside the timeline";
        case KeyContext::Timeline:
            return "timeline";
    }
    return "";
}

std::string shortcutText(const Shortcut& shortcut) {
    std::string text;
    if (shortcut.ctrl()) text += "Ctrl+";
    if (shortcut.shift()) text += "Shift+";
    switch (shortcut.key) {
        case GLFW_KEY_DELETE:
            return text + "Del";
        case GLFW_KEY_SPACE:
            return text + "Space";
        case GLFW_KEY_ESCAPE:
            return text + "Esc";
        case GLFW_KEY_END:
            return text + "End";
        case GLFW_KEY_HOME:
            return text + "Home";
        case GLFW_KEY_F1:
            return text + "F1";
        case GLFW_KEY_F11:
            return text + "F11";
        default:
            if ((shortcut.key >= GLFW_KEY_A && shortcut.key <= GLFW_KEY_Z) ||
                (shortcut.key >= GLFW_KEY_0 && shortcut.key <= GLFW_KEY_9))
                return text + char(shortcut.key);  // GLFW's letter and digit codes are ASCII
            return text + "?";
    }
}

Action& Action::takes(std::vector<ArgSpec> arguments, std::string usageText) {
    args = std::move(arguments);
    usage = usageText.empty() ? usageOf(name, args) : std::move(usageText);
    return *this;
}

const std::vector<std::string>& ActionTable::menus() {
    static const std::vector<std::string> names = {"File", "Edit", "Create", "View", "Help"};
    return names;
}

Action& ActionTable::add(std::string name, std::string label, std::string menu) {
    assert(!find(name) && "action names are unique");
    Action& action = actions_.emplace_back();
    action.name = std::move(name);
    action.label = std::move(label);
    action.menu = std::move(menu);
    action.usage = action.name;
    return action;
}

const Action* ActionTable::find(std::string_view name) const {
    for (const Action& a : actions_)
        if (a.name == name) return &a;
    return nullptr;
}

bool ActionTable::invoke(const Action& action, const ActionArgs& args, std::string& error) const {
    if (!action.isEnabled()) {
        error = action.whyDisabled.empty() ? action.name + ": not available now" : action.whyDisabled;
        return false;
    }
    return action.handler(args, error);
}

bool ActionTable::run(std::string_view name, std::string* error) const {
    std::string why;
    const Action* action = find(name);
    bool ok = false;
    if (!action)
        why = "unknown command \"" + std::string(name) + "\"";
    else if (!action->runsWithoutArgs())
        why = action->handler ? action->name + ": usage: " + action->usage
                              : action->name + ": a menu, not a command";
    else
        ok = invoke(*action, ActionArgs({action->name}), why);
    if (error) *error = why;
    return ok;
}

bool ActionTable::runScript(const std::vector<std::string>& words, std::string& error) const {
    const std::string& name = words.at(0);
    const Action* action = find(name);
    if (!action || !action->scriptable()) {
        error = "unknown command \"" + name + "\"";
        return false;
    }
    ActionArgs args;
    if (!parseActionArgs(words, action->args, action->extraWords, action->usage, args, error)) return false;
    return invoke(*action, args, error);
}

std::string ActionTable::shortcutOf(std::string_view name) const {
    const Action* action = find(name);
    return action && !action->keys.empty() ? shortcutText(action->keys.front()) : std::string();
}

static bool overlaps(KeyContext a, KeyContext b) {
    return a == KeyContext::Anywhere || b == KeyContext::Anywhere || a == b;
}

bool ActionTable::hasShortcut(int key, int modifiers, KeyContext context) const {
    for (const Action& a : actions_)
        for (const Shortcut& s : a.keys)
            if (s.key == key && s.modifiers == modifiers && overlaps(s.context, context)) return true;
    return false;
}

bool ActionTable::answers(const Shortcut& shortcut, int held) const {
    if (shortcut.modifiers == held) return true;
    return held == (Shortcut::kCtrl | Shortcut::kShift) && shortcut.modifiers == Shortcut::kCtrl &&
           !hasShortcut(shortcut.key, held, shortcut.context);
}

const Action* ActionTable::actionForKey(int held, KeyContext active,
                                        const std::function<bool(const Shortcut&)>& pressed) const {
    for (const Action& a : actions_)
        for (const Shortcut& s : a.keys)
            if (s.answersIn(active) && answers(s, held) && pressed(s)) return &a;
    return nullptr;
}

std::vector<std::string> ActionTable::problems() const {
    std::vector<std::string> found;
    const std::vector<std::string>& known = menus();
    for (std::size_t i = 0; i < actions_.size(); ++i) {
        const Action& a = actions_[i];
        if (!a.menu.empty() && std::find(known.begin(), known.end(), a.menu) == known.end())
            found.push_back(a.name + ": no menu \"" + a.menu + "\"");
        if (!a.handler && !a.drawMenu) found.push_back(a.name + ": neither runs nor draws a menu");
        if (a.drawMenu && a.menu.empty()) found.push_back(a.name + ": draws a menu but is in none");
        if (!a.keys.empty() && !a.runsWithoutArgs())
            found.push_back(a.name + ": has a shortcut but needs arguments");
        bool optionalSeen = false;
        for (std::size_t k = 0; k < a.args.size(); ++k) {
            const ArgSpec& arg = a.args[k];
            if (!arg.optional && optionalSeen)
                found.push_back(a.name + ": " + arg.name + " is required after an optional argument");
            optionalSeen = optionalSeen || arg.optional;
            if (arg.type == ArgType::Rest && k + 1 != a.args.size())
                found.push_back(a.name + ": " + arg.name + " takes the rest but is not last");
        }
        for (std::size_t j = 0; j < i; ++j)
            for (const Shortcut& s : a.keys)
                for (const Shortcut& t : actions_[j].keys)
                    if (s.key == t.key && s.modifiers == t.modifiers && overlaps(s.context, t.context))
                        found.push_back(a.name + ": " + shortcutText(s) + " is also " + actions_[j].name +
                                        "'s");
    }
    return found;
}

}  // namespace aerial::editor
