// The action table: shortcuts as the menus show them, which shortcut answers
// which modifiers (Ctrl+Shift+KEY falls back to Ctrl+KEY only when it has no
// action of its own), enabled predicates, lookup by name.
#include "actions.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <gtest/gtest.h>

#include <string>

namespace aerial::editor {
namespace {

using S = Shortcut;

TEST(Actions, ShortcutTextAsTheMenusShowIt) {
    EXPECT_EQ(shortcutText({GLFW_KEY_N, S::kCtrl}), "Ctrl+N");
    EXPECT_EQ(shortcutText({GLFW_KEY_S, S::kCtrl | S::kShift}), "Ctrl+Shift+S");
    EXPECT_EQ(shortcutText({GLFW_KEY_B, S::kShift}), "Shift+B");
    EXPECT_EQ(shortcutText({GLFW_KEY_DELETE}), "Del");
    EXPECT_EQ(shortcutText({GLFW_KEY_F}), "F");
}

struct Table {
    ActionTable table;
    int undone = 0, redone = 0, created = 0;
    bool canUndo = false;
    Table() {
        table.add("request_new", "New", "File").key(GLFW_KEY_N, S::kCtrl).scriptable().does([this] {
            ++created;
        });
        table.add("undo", "Undo", "Edit")
            .key(GLFW_KEY_Z, S::kCtrl, true)
            .enabledWhen([this] { return canUndo; }, "nothing to undo")
            .does([this] { ++undone; });
        table.add("redo", "Redo", "Edit")
            .key(GLFW_KEY_Z, S::kCtrl | S::kShift, true)
            .key(GLFW_KEY_Y, S::kCtrl, true)
            .does([this] { ++redone; });
        table.add("add_box_volume", "Box volume", "Create").key(GLFW_KEY_B, S::kShift).oneUndoStep();
    }
};

TEST(Actions, FindAndShortcutOf) {
    Table t;
    ASSERT_NE(t.table.find("undo"), nullptr);
    EXPECT_EQ(t.table.find("undo")->menu, "Edit");
    EXPECT_EQ(t.table.find("undo")->whyDisabled, "nothing to undo");
    EXPECT_TRUE(t.table.find("request_new")->script);
    EXPECT_TRUE(t.table.find("add_box_volume")->undo);
    EXPECT_EQ(t.table.find("open"), nullptr);
    EXPECT_EQ(t.table.shortcutOf("redo"), "Ctrl+Shift+Z");  // the first one
    EXPECT_EQ(t.table.shortcutOf("request_new"), "Ctrl+N");
    EXPECT_EQ(t.table.shortcutOf("nothing"), "");
    ASSERT_EQ(t.table.all().size(), 4u);
    EXPECT_EQ(t.table.all()[0].name, "request_new");  // menu order is declaration order
}

TEST(Actions, RunOnlyWhenEnabled) {
    Table t;
    EXPECT_FALSE(t.table.run("undo"));
    EXPECT_EQ(t.undone, 0);
    t.canUndo = true;
    EXPECT_TRUE(t.table.run("undo"));
    EXPECT_EQ(t.undone, 1);
    EXPECT_FALSE(t.table.run("add_box_volume"));  // declared without a handler
    EXPECT_FALSE(t.table.run("no_such_action"));
}

TEST(Actions, WhichModifiersAShortcutAnswers) {
    Table t;
    const int ctrl = S::kCtrl, ctrlShift = S::kCtrl | S::kShift, shift = S::kShift, none = S::kNone;
    const Shortcut ctrlN{GLFW_KEY_N, ctrl}, ctrlZ{GLFW_KEY_Z, ctrl}, ctrlShiftZ{GLFW_KEY_Z, ctrlShift},
        ctrlY{GLFW_KEY_Y, ctrl}, shiftB{GLFW_KEY_B, shift};
    EXPECT_TRUE(t.table.answers(ctrlN, ctrl));
    EXPECT_TRUE(t.table.answers(ctrlN, ctrlShift));  // Ctrl+Shift+N has no action of its own
    EXPECT_FALSE(t.table.answers(ctrlN, none));
    EXPECT_TRUE(t.table.answers(ctrlZ, ctrl));
    EXPECT_FALSE(t.table.answers(ctrlZ, ctrlShift));  // Ctrl+Shift+Z is Redo
    EXPECT_TRUE(t.table.answers(ctrlShiftZ, ctrlShift));
    EXPECT_FALSE(t.table.answers(ctrlShiftZ, ctrl));
    EXPECT_TRUE(t.table.answers(ctrlY, ctrlShift));
    EXPECT_TRUE(t.table.answers(shiftB, shift));
    EXPECT_FALSE(t.table.answers(shiftB, none));
    EXPECT_FALSE(t.table.answers(shiftB, ctrlShift));
}

}  // namespace
}  // namespace aerial::editor
