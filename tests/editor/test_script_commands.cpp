// The script path of the action table (ActionTable::runScript): unknown
// commands, argument counts, typed arguments read before the handler runs
// (the exact messages: command, argument, word, reason), the handler's own
// errors, and the usage each argument list makes (parsing the script's
// lines is tested in test_autosave.cpp).
#include "actions.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace aerial::editor {
namespace {

struct Table {
    ActionTable table;
    std::vector<std::string> ran;
    ActionArgs last;
    Table() {
        const auto keep = [this](const ActionArgs& a, std::string&) {
            last = a;
            ran.push_back(a.joined(0));
            return true;
        };
        table.add("open").takes({word("PATH")}).helps("open a preset").handles(keep);
        table.add("set").takes({word("KEY"), rest("V")}).handles([](const ActionArgs&, std::string& error) {
            error = "set: no such parameter";
            return false;
        });
        table.add("wait_frames").takes({count("N")}).handles(keep);
        table.add("time").takes({timeOfDay("T")}).handles(keep);
        table.add("orbit").takes({number("DX"), number("DY"), number("FRAMES").opt()}).handles(keep);
        table.add("answer").takes({choice("ANSWER", {"save", "discard", "cancel"})}).handles(keep);
        table.add("quit").ignoresExtraWords().handles(keep);
        table.add("expect_status").takes({rest("TEXT")}).handles(keep);
    }
    bool run(std::vector<std::string> words, std::string& error) { return table.runScript(words, error); }
};

TEST(ScriptCommands, RunsTheNamedCommand) {
    Table t;
    std::string error;
    EXPECT_TRUE(t.run({"open", "a.json"}, error)) << error;
    EXPECT_EQ(t.ran, std::vector<std::string>{"open a.json"});
    ASSERT_NE(t.table.find("set"), nullptr);
    EXPECT_EQ(t.table.find("set")->usage, "set KEY V...");
    EXPECT_EQ(t.table.find("frobnicate"), nullptr);
}

TEST(ScriptCommands, TypedArgumentsReachTheHandlerRead) {
    Table t;
    std::string error;
    ASSERT_TRUE(t.run({"time", "06:30"}, error)) << error;
    EXPECT_DOUBLE_EQ(t.last.number(1), 6.5);
    ASSERT_TRUE(t.run({"time", "24"}, error)) << error;
    EXPECT_DOUBLE_EQ(t.last.number(1), 24.0);
    ASSERT_TRUE(t.run({"orbit", "-40", "12.5"}, error)) << error;
    EXPECT_DOUBLE_EQ(t.last.number(1), -40.0);
    EXPECT_DOUBLE_EQ(t.last.number(2), 12.5);
    EXPECT_FALSE(t.last.has(3));
    EXPECT_TRUE(std::isnan(t.last.number(3)));
    ASSERT_TRUE(t.run({"orbit", "1", "2", "16"}, error)) << error;
    EXPECT_DOUBLE_EQ(t.last.number(3), 16.0);
    ASSERT_TRUE(t.run({"wait_frames", "0"}, error)) << error;
    ASSERT_TRUE(t.run({"expect_status", "3", "keys", "set"}, error)) << error;
    EXPECT_EQ(t.last.joined(1), "3 keys set");
    ASSERT_TRUE(t.run({"quit", "now", "please"}, error)) << error;  // extra words ignored
}

TEST(ScriptCommands, ErrorsNameTheCommandTheArgumentAndTheReason) {
    Table t;
    std::string error;
    EXPECT_FALSE(t.run({"frobnicate"}, error));
    EXPECT_EQ(error, "unknown command \"frobnicate\"");
    EXPECT_FALSE(t.run({"open"}, error));
    EXPECT_EQ(error, "open: usage: open PATH");
    EXPECT_FALSE(t.run({"open", "a", "b"}, error));
    EXPECT_EQ(error, "open: usage: open PATH");
    EXPECT_FALSE(t.run({"set", "k"}, error));
    EXPECT_EQ(error, "set: usage: set KEY V...");
    EXPECT_FALSE(t.run({"set", "k", "1", "2", "3"}, error));  // no upper limit: the handler's error
    EXPECT_EQ(error, "set: no such parameter");
    EXPECT_FALSE(t.run({"orbit", "1", "2", "3", "4"}, error));
    EXPECT_EQ(error, "orbit: usage: orbit DX DY [FRAMES]");

    EXPECT_FALSE(t.run({"orbit", "left", "2"}, error));
    EXPECT_EQ(error, "orbit: DX \"left\" is not a number");
    EXPECT_FALSE(t.run({"orbit", "1", "2", "inf"}, error));
    EXPECT_EQ(error, "orbit: FRAMES \"inf\" is not a number");
    EXPECT_FALSE(t.run({"wait_frames", "-1"}, error));
    EXPECT_EQ(error, "wait_frames: N \"-1\" is not a count (a number >= 0)");
    EXPECT_FALSE(t.run({"time", "25"}, error));
    EXPECT_EQ(error, "time: T \"25\" is not a time of day (HH:MM or hours in [0, 24])");
    EXPECT_FALSE(t.run({"time", "noon-ish"}, error));
    EXPECT_EQ(error, "time: T \"noon-ish\" is not a time of day (HH:MM or hours in [0, 24])");
    EXPECT_FALSE(t.run({"answer", "maybe"}, error));
    EXPECT_EQ(error, "answer: ANSWER \"maybe\" is not one of save|discard|cancel");
    EXPECT_TRUE(t.ran.empty());  // no handler ran for a bad line
}

TEST(ScriptCommands, UsageFromTheArguments) {
    EXPECT_EQ(usageOf("drop", {word("PATH"), choice("shift", {"shift"}).opt()}), "drop PATH [shift]");
    EXPECT_EQ(usageOf("wrap", {word("KEY"), onOff()}), "wrap KEY on|off");
    EXPECT_EQ(usageOf("place", {rest("CITY")}), "place CITY...");
    EXPECT_EQ(minArgCount({word("A"), number("B").opt()}), 1);
    EXPECT_EQ(maxArgCount({word("A"), number("B").opt()}), 2);
    EXPECT_EQ(maxArgCount({word("A"), rest("B")}), -1);
}

}  // namespace
}  // namespace aerial::editor
