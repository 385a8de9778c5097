// The action table: shortcuts as the menus show them, which shortcut answers
// which modifiers (Ctrl+Shift+KEY falls back to Ctrl+KEY only when it has no
// action of its own) and in which part of the window, enabled predicates,
// lookup by name, the menu and the script path running one handler, and the
// table's own checks (problems()).
#include "actions.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace aerial::editor {
namespace {

using S = Shortcut;

TEST(Actions, ShortcutTextAsTheMenusShowIt) {
    EXPECT_EQ(shortcutText({GLFW_KEY_N, S::kCtrl}), "Ctrl+N");
    EXPECT_EQ(shortcutText({GLFW_KEY_S, S::kCtrl | S::kShift}), "Ctrl+Shift+S");
    EXPECT_EQ(shortcutText({GLFW_KEY_B, S::kShift}), "Shift+B");
    EXPECT_EQ(shortcutText({GLFW_KEY_DELETE}), "Del");
    EXPECT_EQ(shortcutText({GLFW_KEY_F}), "F");
    EXPECT_EQ(shortcutText({GLFW_KEY_F11}), "F11");
    EXPECT_EQ(shortcutText({GLFW_KEY_END}), "End");
}

struct Table {
    ActionTable table;
    int undone = 0, redone = 0, created = 0, deletedObjects = 0, deletedKeys = 0;
    bool canUndo = false, gameView = false;
    Table() {
        table.add("request_new", "New", "File").key(GLFW_KEY_N, S::kCtrl).does([this] { ++created; });
        table.add("undo", "Undo", "Edit")
            .key(GLFW_KEY_Z, S::kCtrl, true)
            .enabledWhen([this] { return canUndo; }, "nothing to undo")
            .does([this] { ++undone; });
        table.add("redo", "Redo", "Edit")
            .key(GLFW_KEY_Z, S::kCtrl | S::kShift, true)
            .key(GLFW_KEY_Y, S::kCtrl, true)
            .does([this] { ++redone; });
        table.add("delete", "Delete", "Edit")
            .key(GLFW_KEY_DELETE, S::kNone, false, KeyContext::OutsideTimeline)
            .oneUndoStep()
            .does([this] { ++deletedObjects; });
        table.add("timeline_delete_keys", "Timeline: delete keys")
            .key(GLFW_KEY_DELETE, S::kNone, false, KeyContext::Timeline)
            .does([this] { ++deletedKeys; });
        // A switch: the menu toggles it, a script sets it.
        table.add("game_view", "Game view", "View")
            .key(GLFW_KEY_G)
            .takes({onOff().opt()})
            .checkedWhen([this] { return gameView; })
            .handles([this](const ActionArgs& a, std::string&) {
                gameView = a.has(1) ? a[1] == "on" : !gameView;
                return true;
            });
        table.add("time").takes({timeOfDay("T")}).handles([](const ActionArgs&, std::string&) {
            return true;
        });
        table.add("open_recent", "Open Recent", "File").drawsMenu([](const char*) {});
    }
    bool script(std::vector<std::string> words, std::string& error) { return table.runScript(words, error); }
};

TEST(Actions, FindAndShortcutOf) {
    Table t;
    ASSERT_NE(t.table.find("undo"), nullptr);
    EXPECT_EQ(t.table.find("undo")->menu, "Edit");
    EXPECT_EQ(t.table.find("undo")->whyDisabled, "nothing to undo");
    EXPECT_TRUE(t.table.find("request_new")->scriptable());
    EXPECT_TRUE(t.table.find("delete")->undo);
    EXPECT_FALSE(t.table.find("open_recent")->scriptable());  // a menu only
    EXPECT_EQ(t.table.find("open"), nullptr);
    EXPECT_EQ(t.table.shortcutOf("redo"), "Ctrl+Shift+Z");  // the first one
    EXPECT_EQ(t.table.shortcutOf("request_new"), "Ctrl+N");
    EXPECT_EQ(t.table.shortcutOf("nothing"), "");
    EXPECT_EQ(t.table.find("game_view")->usage, "game_view [on|off]");
    EXPECT_EQ(t.table.find("time")->usage, "time T");
    EXPECT_EQ(t.table.all()[0].name, "request_new");  // menu order is declaration order
}

TEST(Actions, RunOnlyWhenEnabled) {
    Table t;
    std::string error;
    EXPECT_FALSE(t.table.run("undo", &error));
    EXPECT_EQ(error, "nothing to undo");
    EXPECT_EQ(t.undone, 0);
    t.canUndo = true;
    EXPECT_TRUE(t.table.run("undo"));
    EXPECT_EQ(t.undone, 1);
    EXPECT_FALSE(t.table.run("time", &error));  // needs an argument: not from a menu
    EXPECT_EQ(error, "time: usage: time T");
    EXPECT_FALSE(t.table.run("open_recent", &error));
    EXPECT_EQ(error, "open_recent: a menu, not a command");
    EXPECT_FALSE(t.table.run("no_such_action", &error));
    EXPECT_EQ(error, "unknown command \"no_such_action\"");
}

TEST(Actions, TheMenuAndTheScriptRunTheSameHandler) {
    Table t;
    std::string error;
    EXPECT_TRUE(t.table.run("request_new"));  // the menu item, the key, a button
    EXPECT_TRUE(t.script({"request_new"}, error)) << error;
    EXPECT_EQ(t.created, 2);
    t.canUndo = true;
    EXPECT_TRUE(t.table.run("undo"));
    EXPECT_TRUE(t.script({"undo"}, error)) << error;
    EXPECT_EQ(t.undone, 2);
    t.canUndo = false;  // disabled: neither path runs it, the script says why
    EXPECT_FALSE(t.script({"undo"}, error));
    EXPECT_EQ(error, "nothing to undo");
    EXPECT_EQ(t.undone, 2);
    // A switch: the menu toggles, the script sets.
    EXPECT_TRUE(t.table.run("game_view"));
    EXPECT_TRUE(t.gameView);
    EXPECT_TRUE(t.script({"game_view", "on"}, error)) << error;
    EXPECT_TRUE(t.gameView);
    EXPECT_TRUE(t.script({"game_view", "off"}, error)) << error;
    EXPECT_FALSE(t.gameView);
    EXPECT_TRUE(t.script({"game_view"}, error)) << error;
    EXPECT_TRUE(t.gameView);
}

TEST(Actions, WhichModifiersAShortcutAnswers) {
    Table t;
    const int ctrl = S::kCtrl, ctrlShift = S::kCtrl | S::kShift, shift = S::kShift, none = S::kNone;
    const Shortcut ctrlN{GLFW_KEY_N, ctrl}, ctrlZ{GLFW_KEY_Z, ctrl}, ctrlShiftZ{GLFW_KEY_Z, ctrlShift},
        ctrlY{GLFW_KEY_Y, ctrl}, g{GLFW_KEY_G, none};
    EXPECT_TRUE(t.table.answers(ctrlN, ctrl));
    EXPECT_TRUE(t.table.answers(ctrlN, ctrlShift));  // Ctrl+Shift+N has no action of its own
    EXPECT_FALSE(t.table.answers(ctrlN, none));
    EXPECT_TRUE(t.table.answers(ctrlZ, ctrl));
    EXPECT_FALSE(t.table.answers(ctrlZ, ctrlShift));  // Ctrl+Shift+Z is Redo
    EXPECT_TRUE(t.table.answers(ctrlShiftZ, ctrlShift));
    EXPECT_FALSE(t.table.answers(ctrlShiftZ, ctrl));
    EXPECT_TRUE(t.table.answers(ctrlY, ctrlShift));
    EXPECT_TRUE(t.table.answers(g, none));
    EXPECT_FALSE(t.table.answers(g, shift));
}

TEST(Actions, AKeyRunsTheActionOfThePartOfTheWindowUnderTheMouse) {
    Table t;
    const auto pressed = [](int key) { return [key](const Shortcut& s) { return s.key == key; }; };
    const Action* outside =
        t.table.actionForKey(S::kNone, KeyContext::OutsideTimeline, pressed(GLFW_KEY_DELETE));
    const Action* over = t.table.actionForKey(S::kNone, KeyContext::Timeline, pressed(GLFW_KEY_DELETE));
    ASSERT_NE(outside, nullptr);
    ASSERT_NE(over, nullptr);
    EXPECT_EQ(outside->name, "delete");
    EXPECT_EQ(over->name, "timeline_delete_keys");
    // A shortcut for anywhere answers in both.
    EXPECT_EQ(t.table.actionForKey(S::kNone, KeyContext::Timeline, pressed(GLFW_KEY_G))->name, "game_view");
    EXPECT_EQ(t.table.actionForKey(S::kShift, KeyContext::Timeline, pressed(GLFW_KEY_G)), nullptr);
    EXPECT_TRUE(t.table.problems().empty()) << t.table.problems().front();
}

TEST(Actions, ProblemsNameTheEntryAndTheReason) {
    ActionTable table;
    const auto nothing = [] {};
    table.add("a", "A", "Edit").key(GLFW_KEY_X).does(nothing);
    table.add("b", "B", "Edit").key(GLFW_KEY_X, S::kNone, false, KeyContext::Timeline).does(nothing);
    table.add("c", "C", "Tools").does(nothing);
    table.add("d").takes({word("A").opt(), word("B")}).does(nothing);
    table.add("e").takes({rest("R"), word("B")}).does(nothing);
    table.add("f", "F", "View");
    table.add("g", "G").key(GLFW_KEY_Y).takes({word("A")}).does(nothing);
    const std::vector<std::string> want = {
        "b: X is also a's",  // Anywhere overlaps the timeline
        "c: no menu \"Tools\"",
        "d: B is required after an optional argument",
        "e: R takes the rest but is not last",
        "f: neither runs nor draws a menu",
        "g: has a shortcut but needs arguments",
    };
    EXPECT_EQ(table.problems(), want);
}

}  // namespace
}  // namespace aerial::editor
