// one_line: a library's message of several lines as the one line an error gives.
#include <gtest/gtest.h>

#include "core/one_line.h"

namespace rm {
namespace {

TEST(OneLine, JoinsTheLinesThatSaySomethingNew) {
  EXPECT_EQ(one_line("Read error: hit end of file\nPNG read error: IDAT: Read error: hit end of file\nPNG library error"),
            "PNG read error: IDAT: Read error: hit end of file; PNG library error")
      << "a line another one says is dropped";
  EXPECT_EQ(one_line("Not a JPEG file\nNot a JPEG file\n"), "Not a JPEG file") << "a repeated line is said once";
  EXPECT_EQ(one_line("first\n\n  \t\nsecond\n"), "first; second") << "blank lines are dropped";
  EXPECT_EQ(one_line("one line"), "one line");
  EXPECT_EQ(one_line(""), "");
}

}  // namespace
}  // namespace rm
