#include "core/json_depth.h"

#include <gtest/gtest.h>

#include <string>

namespace rm {
namespace {

TEST(JsonDepth, NamesTheFirstBracketPastTheLimit) {
  EXPECT_FALSE(json_nested_too_deep("[[{\"a\": [1]}]]", 4));
  const auto at = json_nested_too_deep("{\n  \"a\": [[1]]}", 2);
  ASSERT_TRUE(at);
  EXPECT_EQ(at->line, 2);
  EXPECT_EQ(at->column, 9);
}

TEST(JsonDepth, BracketsInStringsDoNotCount) {
  EXPECT_FALSE(json_nested_too_deep("[\"[[[{{{\", \"\\\"[[[\"]", 1));
  EXPECT_TRUE(json_nested_too_deep("[\"\\\\\", [1]]", 1));  // the string ends after an escaped backslash
}

TEST(JsonDepth, ClosingBracketsGiveTheLevelsBack) {
  EXPECT_FALSE(json_nested_too_deep(std::string(1000, '[') + std::string(1000, ']') + "[[]]", 1000));
  EXPECT_TRUE(json_nested_too_deep(std::string(1001, '['), 1000));
}

}  // namespace
}  // namespace rm
