// The --script format: commands, comments, argument counts and the one-line errors.
#include <gtest/gtest.h>

#include "view_script.h"

namespace cetview::test {
namespace {

TEST(ViewScript, ParsesCommandsAndSkipsComments) {
  const ScriptParse p = parseScript(
      "# drive the viewer\n"
      "deflection 0.05%\n"
      "\n"
      "wait level target   # until shown\n"
      "panel progress off\n"
      "screenshot out.png\n"
      "quit\n",
      "s.txt");
  ASSERT_TRUE(p.error.empty()) << p.error;
  ASSERT_EQ(p.commands.size(), 5u);
  EXPECT_EQ(p.commands[0].name, "deflection");
  EXPECT_EQ(p.commands[0].args, std::vector<std::string>{"0.05%"});
  EXPECT_EQ(p.commands[0].line, 2);
  EXPECT_EQ(p.commands[1].name, "wait");
  EXPECT_EQ(p.commands[1].args, (std::vector<std::string>{"level", "target"}));
  EXPECT_EQ(p.commands[1].line, 4);
  EXPECT_EQ(p.commands[4].name, "quit");
}

TEST(ViewScript, RejectsUnknownCommandsAndWrongArgumentCounts) {
  EXPECT_EQ(parseScript("spin 3\n", "s.txt").error, "s.txt:1: unknown command 'spin'");
  EXPECT_EQ(parseScript("fit\nview\n", "s.txt").error, "s.txt:2: 'view' takes 1 argument(s), not 0");
  EXPECT_EQ(parseScript("wait minutes 3\n", "s.txt").error,
            "s.txt:1: 'wait' needs 'level K|target', 'frames N' or 'seconds S'");
  EXPECT_TRUE(parseScript("wait seconds 3\n", "s.txt").error.empty());
  EXPECT_TRUE(parseScript("open part.step\ncancel\n", "s.txt").error.empty());
  EXPECT_EQ(parseScript("cancel now\n", "s.txt").error, "s.txt:1: 'cancel' takes 0 argument(s), not 1");
  EXPECT_FALSE(loadScript("/nonexistent/script.txt").error.empty());
}

}  // namespace
}  // namespace cetview::test
