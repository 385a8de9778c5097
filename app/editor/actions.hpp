// editor/actions.hpp — the editor's one command registry: every user action
// and every script command is declared once (as Blender's operators): its
// name (the script command), menu label and place, shortcuts (each with the
// part of the window it answers in), typed arguments (action_args.hpp),
// when it is enabled or checked, whether it is one undo step, and its
// handler. The menu bar, the keyboard shortcuts, the Help sheet's key list
// and the `--script` language are all drawn from the one ActionTable
// (editor_actions*.cpp and editor_script*.cpp declare the editor's);
// panels run an action by name. No ImGui here: keys are GLFW key codes.
//
// Usage:
//   table.add("duplicate", "Duplicate", "Edit")          // a menu item
//       .key(GLFW_KEY_D, Shortcut::kCtrl)
//       .oneUndoStep()
//       .enabledWhen([&] { return edit.objectSelected(); },
//                    "duplicate: select a volume or an emitter first")
//       .does([&] { duplicateSelection(); });
//   table.add("time").takes({timeOfDay("T")})            // a script command
//       .helps("jump to a time (hours or HH:MM)")
//       .handles([&](const ActionArgs& a, std::string&) { jumpTo(a.number(1)); return true; });
//   table.run("duplicate");                              // a menu, key or button
//   table.runScript({"time", "6:30"}, error);            // a script line
#pragma once

#include "action_args.hpp"

#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace aerial::editor {

/// Where in the window a shortcut answers: anywhere, only while the mouse
/// is over the timeline (its keys and curves), or only while it is not
/// (Del deletes the selected object, over the timeline its keys).
enum class KeyContext { Anywhere, OutsideTimeline, Timeline };
/// "timeline", "outside the timeline", "" for Anywhere.
std::string_view keyContextName(KeyContext context);

/// A key with modifiers (GLFW key codes).
struct Shortcut {
    enum Modifiers { kNone = 0, kCtrl = 1, kShift = 2 };
    int key = 0;
    int modifiers = kNone;
    bool repeat = false;  ///< fires again while held (undo, redo)
    KeyContext context = KeyContext::Anywhere;

    bool ctrl() const { return (modifiers & kCtrl) != 0; }
    bool shift() const { return (modifiers & kShift) != 0; }
    /// Whether it answers while the window is in `active` (never Anywhere).
    bool answersIn(KeyContext active) const { return context == KeyContext::Anywhere || context == active; }
};

/// "Ctrl+Shift+S", "Shift+B", "Del", "F" (as the menus show it).
std::string shortcutText(const Shortcut& shortcut);

/// What an action does: reads its arguments (none from a menu or a key)
/// and returns false with `error` set when it cannot.
using ActionHandler = std::function<bool(const ActionArgs& args, std::string& error)>;

struct Action {
    std::string name;   ///< unique; the script command
    std::string label;  ///< menu label (and the Help sheet's)
    std::string menu;   ///< the main menu it sits in ("File", "Edit", "Create", "View", "Help"); "" = none
    bool separatorBefore = false;
    std::vector<Shortcut> keys;         ///< the first is shown in the menu
    std::vector<ArgSpec> args;          ///< typed arguments (script); none from a menu or a key
    bool extraWords = false;            ///< a script may add words it ignores ("quit now")
    std::string usage;                  ///< "open PATH"; usageOf(name, args) unless declared
    std::string help;                   ///< one line (the script's reference); `label` when empty
    bool undo = false;                  ///< changes the preset as one undo step
    std::function<bool()> enabled;      ///< null = always
    std::string whyDisabled;            ///< the script's error when it runs a disabled action
    std::function<bool()> checked;      ///< null = no check mark
    std::function<std::string()> text;  ///< a label that changes ("Undo Move"); null = `label`
    ActionHandler handler;              ///< null: a menu entry drawn by drawMenu only
    /// A menu entry that is more than an item (a list of files, a slider):
    /// drawn by this, given the label, instead of an item.
    std::function<void(const char* label)> drawMenu;

    bool isEnabled() const { return !enabled || enabled(); }
    /// A script may run it (it has a handler).
    bool scriptable() const { return bool(handler); }
    /// A menu, a key or a button may run it without arguments.
    bool runsWithoutArgs() const { return handler && minArgCount(args) == 0; }

    // Declaration, one property per call (see the usage above).
    Action& separated() { return separatorBefore = true, *this; }
    Action& key(int code, int modifiers = Shortcut::kNone, bool repeats = false,
                KeyContext context = KeyContext::Anywhere) {
        keys.push_back({code, modifiers, repeats, context});
        return *this;
    }
    Action& oneUndoStep() { return undo = true, *this; }
    Action& takes(std::vector<ArgSpec> arguments, std::string usageText = {});
    Action& ignoresExtraWords() { return extraWords = true, *this; }
    Action& helps(std::string line) { return help = std::move(line), *this; }
    Action& enabledWhen(std::function<bool()> predicate, std::string reason = {}) {
        enabled = std::move(predicate);
        whyDisabled = std::move(reason);
        return *this;
    }
    Action& checkedWhen(std::function<bool()> predicate) { return checked = std::move(predicate), *this; }
    Action& labelledBy(std::function<std::string()> make) { return text = std::move(make), *this; }
    /// A handler that reads arguments and may fail.
    Action& handles(ActionHandler h) { return handler = std::move(h), *this; }
    /// A handler without arguments that cannot fail.
    Action& does(std::function<void()> run) {
        handler = [run = std::move(run)](const ActionArgs&, std::string&) {
            run();
            return true;
        };
        return *this;
    }
    Action& drawsMenu(std::function<void(const char* label)> draw) {
        return drawMenu = std::move(draw), *this;
    }
};

/// The actions in menu order.
class ActionTable {
public:
    /// The main menus, in the menu bar's order.
    static const std::vector<std::string>& menus();

    /// Adds an action (names are unique, asserted) for the caller to declare.
    Action& add(std::string name, std::string label = {}, std::string menu = {});
    /// The action called `name`, or nullptr.
    const Action* find(std::string_view name) const;

    /// The menu, key and button path: runs the action called `name` without
    /// arguments when it is enabled. False (with `error` set when given)
    /// when it does not exist, needs arguments, is disabled or fails.
    bool run(std::string_view name, std::string* error = nullptr) const;
    /// The script path: `words` as a script line (words[0] the name).
    /// Errors: `unknown command "NAME"`, `NAME: usage: USAGE` for a wrong
    /// argument count, `NAME: ARG "WORD" is not ...` for a word that does
    /// not read as its type, the action's whyDisabled when it is disabled,
    /// else the handler's.
    bool runScript(const std::vector<std::string>& words, std::string& error) const;

    /// The shortcut of the action called `name` as the menus show it ("" = none).
    std::string shortcutOf(std::string_view name) const;
    /// Whether some action has exactly this key and these modifiers in a
    /// context that overlaps `context`.
    bool hasShortcut(int key, int modifiers, KeyContext context = KeyContext::Anywhere) const;
    /// Whether `shortcut` answers its key while the modifiers `held`
    /// (Shortcut::Modifiers) are down: they are its own, or Ctrl+Shift is
    /// held for a Ctrl+KEY shortcut and no action has Ctrl+Shift+KEY (so
    /// Ctrl+Shift+N is New, but Ctrl+Shift+Z is Redo, not Undo).
    bool answers(const Shortcut& shortcut, int held) const;
    /// The action a key press runs: the first whose shortcut for `key`
    /// answers `held` in the `active` part of the window; nullptr if none.
    /// `pressed(shortcut)` says whether the key went down this frame.
    const Action* actionForKey(int held, KeyContext active,
                               const std::function<bool(const Shortcut&)>& pressed) const;

    /// What is wrong with the table, a line each (empty when nothing): two
    /// shortcuts on one key in overlapping contexts, an entry in no known
    /// menu, an entry that neither runs nor draws a menu, a required
    /// argument after an optional one, a Rest argument that is not last.
    std::vector<std::string> problems() const;

    const std::vector<Action>& all() const { return actions_; }

private:
    bool invoke(const Action& action, const ActionArgs& args, std::string& error) const;

    std::vector<Action> actions_;
};

}  // namespace aerial::editor
