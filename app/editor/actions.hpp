// editor/actions.hpp — the editor's user actions, each declared once (as
// Blender's operators): name, menu label and place, shortcut, when it is
// enabled, what it does, whether it is one undo step and whether scripts can
// call it. The menu bar, the keyboard shortcuts and the script's commands
// without arguments are all driven by the one ActionTable
// (editor_actions.cpp declares the editor's); panels run an action by name.
// No ImGui here: keys are GLFW key codes.
//
// Usage:
//   table.add("duplicate", "Duplicate", "Edit")
//       .key(GLFW_KEY_D, Shortcut::kCtrl)
//       .scriptable()
//       .oneUndoStep()
//       .enabledWhen([&] { return edit.objectSelected(); },
//                    "duplicate: select a volume or an emitter first")
//       .does([&] { duplicateSelection(); });
//   table.run("duplicate");  // an outliner or inspector button
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace aerial::editor {

/// A key with modifiers (GLFW key codes).
struct Shortcut {
    enum Modifiers { kNone = 0, kCtrl = 1, kShift = 2 };
    int key = 0;
    int modifiers = kNone;
    bool repeat = false;  ///< fires again while held (undo, redo)

    bool ctrl() const { return (modifiers & kCtrl) != 0; }
    bool shift() const { return (modifiers & kShift) != 0; }
};

/// "Ctrl+Shift+S", "Shift+B", "Del", "F" (as the menus show it).
std::string shortcutText(const Shortcut& shortcut);

struct Action {
    std::string name;   ///< unique; the script command when `script`
    std::string label;  ///< menu label
    std::string menu;   ///< the main menu it sits in ("File", "Edit", "Create", "View"); "" = none
    bool separatorBefore = false;
    std::vector<Shortcut> keys;         ///< the first is shown in the menu
    bool script = false;                ///< a script command (without arguments) of the same name
    bool undo = false;                  ///< changes the preset as one undo step
    std::function<bool()> enabled;      ///< null = always
    std::string whyDisabled;            ///< the script's error when it runs a disabled action
    std::function<bool()> checked;      ///< null = no check mark
    std::function<std::string()> text;  ///< a label that changes ("Undo Move"); null = `label`
    std::function<bool()> keyAllowed;   ///< an extra condition for the shortcut only; null = none
    std::function<void()> run;
    /// A menu entry that is more than an item (a list of files, a slider):
    /// drawn by this, given the label, instead of an item; such an entry
    /// has no `run`.
    std::function<void(const char* label)> drawMenu;

    bool isEnabled() const { return !enabled || enabled(); }

    // Declaration, one property per call (see the usage above).
    Action& separated() { return separatorBefore = true, *this; }
    Action& key(int code, int modifiers = Shortcut::kNone, bool repeats = false) {
        keys.push_back({code, modifiers, repeats});
        return *this;
    }
    Action& scriptable() { return script = true, *this; }
    Action& oneUndoStep() { return undo = true, *this; }
    Action& enabledWhen(std::function<bool()> predicate, std::string reason = {}) {
        enabled = std::move(predicate);
        whyDisabled = std::move(reason);
        return *this;
    }
    Action& checkedWhen(std::function<bool()> predicate) { return checked = std::move(predicate), *this; }
    Action& labelledBy(std::function<std::string()> make) { return text = std::move(make), *this; }
    Action& keyOnlyWhen(std::function<bool()> predicate) { return keyAllowed = std::move(predicate), *this; }
    Action& does(std::function<void()> handler) { return run = std::move(handler), *this; }
    Action& drawsMenu(std::function<void(const char* label)> draw) {
        return drawMenu = std::move(draw), *this;
    }
};

/// The actions in menu order.
class ActionTable {
public:
    /// Adds an action (names are unique, asserted) for the caller to declare.
    Action& add(std::string name, std::string label, std::string menu = {});
    /// The action called `name`, or nullptr.
    const Action* find(std::string_view name) const;
    /// Runs the action called `name` when it is enabled; false when it is
    /// not (or does not exist).
    bool run(std::string_view name) const;
    /// The shortcut of the action called `name` as the menus show it ("" = none).
    std::string shortcutOf(std::string_view name) const;
    /// Whether some action has exactly this key and these modifiers.
    bool hasShortcut(int key, int modifiers) const;
    /// Whether `shortcut` answers its key while the modifiers `held`
    /// (Shortcut::Modifiers) are down: they are its own, or Ctrl+Shift is
    /// held for a Ctrl+KEY shortcut and no action has Ctrl+Shift+KEY (so
    /// Ctrl+Shift+N is New, but Ctrl+Shift+Z is Redo, not Undo).
    bool answers(const Shortcut& shortcut, int held) const;
    const std::vector<Action>& all() const { return actions_; }

private:
    std::vector<Action> actions_;
};

}  // namespace aerial::editor
