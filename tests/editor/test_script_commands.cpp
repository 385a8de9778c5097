// The script command table's dispatch: unknown commands, argument counts,
// the handler's own errors (parsing is tested in test_autosave.cpp).
#include "script.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace aerial::editor {
namespace {

struct Table {
    ScriptCommandTable table;
    std::vector<std::string> ran;
    Table() {
        table.add({"open", 1, 1, "open PATH", "open a preset",
                   [this](const std::vector<std::string>& w, std::string&) {
                       ran.push_back(w[1]);
                       return true;
                   }});
        table.add({"set", 2, kAnyArgs, "set KEY V...", "set a parameter",
                   [](const std::vector<std::string>&, std::string& error) {
                       error = "set: no such parameter";
                       return false;
                   }});
    }
    bool run(std::vector<std::string> words, std::string& error) {
        return table.run(ScriptCommand{1, std::move(words)}, error);
    }
};

TEST(ScriptCommandTable, RunsTheNamedCommand) {
    Table t;
    std::string error;
    EXPECT_TRUE(t.run({"open", "a.json"}, error)) << error;
    EXPECT_EQ(t.ran, std::vector<std::string>{"a.json"});
    ASSERT_NE(t.table.find("set"), nullptr);
    EXPECT_EQ(t.table.find("set")->usage, "set KEY V...");
    EXPECT_EQ(t.table.find("frobnicate"), nullptr);
}

TEST(ScriptCommandTable, ErrorsNameTheCommandAndTheReason) {
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
    EXPECT_TRUE(t.ran.empty());
}

}  // namespace
}  // namespace aerial::editor
