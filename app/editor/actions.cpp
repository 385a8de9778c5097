// editor/actions.cpp — see actions.hpp.
#include "actions.hpp"

#ifndef GLFW_INCLUDE_NONE
#define GLFW_INCLUDE_NONE  // the key codes only, no GL header
#endif
#include <GLFW/glfw3.h>

#include <cassert>

namespace aerial::editor {

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
        default:
            if ((shortcut.key >= GLFW_KEY_A && shortcut.key <= GLFW_KEY_Z) ||
                (shortcut.key >= GLFW_KEY_0 && shortcut.key <= GLFW_KEY_9))
                return text + char(shortcut.key);  // GLFW's letter and digit codes are ASCII
            return text + "?";
    }
}

Action& ActionTable::add(std::string name, std::string label, std::string menu) {
    assert(!find(name) && "action names are unique");
    Action& action = actions_.emplace_back();
    action.name = std::move(name);
    action.label = std::move(label);
    action.menu = std::move(menu);
    return action;
}

const Action* ActionTable::find(std::string_view name) const {
    for (const Action& a : actions_)
        if (a.name == name) return &a;
    return nullptr;
}

bool ActionTable::run(std::string_view name) const {
    const Action* action = find(name);
    if (!action || !action->run || !action->isEnabled()) return false;
    action->run();
    return true;
}

std::string ActionTable::shortcutOf(std::string_view name) const {
    const Action* action = find(name);
    return action && !action->keys.empty() ? shortcutText(action->keys.front()) : std::string();
}

bool ActionTable::hasShortcut(int key, int modifiers) const {
    for (const Action& a : actions_)
        for (const Shortcut& s : a.keys)
            if (s.key == key && s.modifiers == modifiers) return true;
    return false;
}

bool ActionTable::answers(const Shortcut& shortcut, int held) const {
    if (shortcut.modifiers == held) return true;
    return held == (Shortcut::kCtrl | Shortcut::kShift) && shortcut.modifiers == Shortcut::kCtrl &&
           !hasShortcut(shortcut.key, held);
}

}  // namespace aerial::editor
