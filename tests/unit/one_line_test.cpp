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

// A value a message quotes: whole up to 40 bytes, else cut before a character, not inside one.
TEST(OneLine, BriefCutsBetweenCharacters) {
  EXPECT_EQ(brief(std::string(40, 'x')), std::string(40, 'x'));
  EXPECT_EQ(brief(std::string(41, 'x')), std::string(40, 'x') + "...");
  std::string letters = "x";
  for (int i = 0; i < 30; ++i) letters += "\xc3\xa9";  // é, two bytes each: byte 40 is inside one
  std::string kept = "x";
  for (int i = 0; i < 19; ++i) kept += "\xc3\xa9";
  EXPECT_EQ(brief(letters), kept + "...");
}

}  // namespace
}  // namespace rm
