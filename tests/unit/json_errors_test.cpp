// nlohmann's parse errors cut to one short line: a string left open quotes
// the rest of the file as the token it last read.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/json_errors.h"

namespace rm {
namespace {

std::string parse_error_of(const std::string& text) {
  try {
    const nlohmann::json parsed = nlohmann::json::parse(text);
    (void)parsed;
  } catch (const nlohmann::json::parse_error& e) {
    return e.what();
  }
  return "";
}

TEST(JsonErrors, AStringLeftOpenIsQuotedByItsEnds) {
  const std::string code = "void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }" + std::string(5000, ' ') + "// end";
  const std::string what = parse_error_of("{\"code\": \"" + code);
  ASSERT_GT(what.size(), 5000u) << "nlohmann quotes the whole string";
  EXPECT_EQ(short_json_error(what),
            "[json.exception.parse_error.101] parse error at line 1, column 5073: syntax error while parsing value - "
            "invalid string: missing closing quote; last read: '\"void mainImage(out vec4...          // end'");
}

TEST(JsonErrors, AShortTokenStaysWhole) {
  const std::string what = parse_error_of("{\"a\": \"a string left open");
  ASSERT_NE(what.find("last read: '\"a string left open'"), std::string::npos) << what;
  EXPECT_EQ(short_json_error(what), what);
  EXPECT_EQ(short_json_error("no token quoted here"), "no token quoted here");
}

TEST(JsonErrors, ACutFallsBetweenCharactersNotInsideOne) {
  const std::string what = parse_error_of("{\"a\": \"" + std::string(40, 'x') + [] {
    std::string s;
    for (int i = 0; i < 40; ++i) s += "\xc3\xa9";  // é, two bytes each
    return s;
  }());
  const std::string shortened = short_json_error(what);
  const size_t cut = shortened.find("...");
  ASSERT_NE(cut, std::string::npos) << shortened;
  // After the cut, whole é's up to the closing quote: an even number of bytes, each pair C3 A9.
  const std::string tail = shortened.substr(cut + std::string("...").size());
  ASSERT_EQ(tail.back(), '\'');
  const std::string letters = tail.substr(0, tail.size() - 1);
  ASSERT_EQ(letters.size() % 2, 0u) << letters;
  for (size_t i = 0; i < letters.size(); i += 2) EXPECT_EQ(letters.substr(i, 2), "\xc3\xa9") << i;
}

}  // namespace
}  // namespace rm
