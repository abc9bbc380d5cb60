// The lexing the host does before the compiler: comments out (blanked, as
// the compiler parts tokens there), and code_only(), by which two
// texts that compile to the same program compare equal and no others do.
#include "core/lexing.h"

#include <gtest/gtest.h>

namespace rm::lexing {
namespace {

TEST(Lexing, ACommentIsBlankedAndKeepsItsNewlines) {
  EXPECT_EQ(strip_comments("a/**/b"), "a    b");
  EXPECT_EQ(strip_comments("a /* one\ntwo */ b // three\nc"), "a       \n       b         \nc");
  // A line that ends in a backslash goes on in the next, comment and all.
  EXPECT_EQ(strip_comments("a // b \\\nc\nd"), "a       \n \nd");
  EXPECT_EQ(strip_comments("a // b \\\r\nc\r\nd"), "a        \n  \nd");
  EXPECT_EQ(strip_comments("a /* open"), "a        ");
  EXPECT_EQ(strip_comments("a /"), "a /");
  // Every column keeps its place: a word after a comment is where it was.
  const std::string line = "x /* iChannel0 */ = texture(iChannel0, uv); // iChannel0";
  EXPECT_EQ(strip_comments(line).find("iChannel0"), line.find("iChannel0, uv"));
  EXPECT_EQ(strip_comments(line).size(), line.size());
}

TEST(Lexing, CodeOnlyIsTheSameForTheSameTokens) {
  const std::string code = "float f(float x) {\n  return x * 0.5;\n}\n";
  EXPECT_EQ(code_only(code), code_only("float f(float x) { // half\n    return x  *\t0.5;  /* of x */\n}\n"));
  EXPECT_EQ(code_only(code), code_only("float f(float x) {\r\n  return x * 0.5;\r\n}\r\n"));
  EXPECT_EQ(code_only("a/* x */b"), code_only("a/* yy */b"));
}

TEST(Lexing, CodeOnlyDiffersWhereTheTokensDo) {
  EXPECT_NE(code_only("ab"), code_only("a/**/b")) << "a comment parts tokens";
  EXPECT_NE(code_only("#define F(x) x"), code_only("#define F (x) x")) << "a function-like macro, an object-like one";
  EXPECT_NE(code_only("a\nb"), code_only("a b")) << "lines keep their numbers";
  EXPECT_NE(code_only("x = 1.0; // \\\ny = 2.0;"), code_only("x = 1.0; //\ny = 2.0;")) << "a line swallowed";
  EXPECT_NE(code_only("a \\ \nb"), code_only("a \\\nb")) << "blanks after a backslash splice no lines";
  EXPECT_NE(code_only("x * 0.5"), code_only("x * 0.50"));
}

TEST(Lexing, ComponentsOfEveryScalarVectorAndMatrixType) {
  EXPECT_EQ(components_of("float"), 1);
  EXPECT_EQ(components_of("uint"), 1);
  EXPECT_EQ(components_of("vec3"), 3);
  EXPECT_EQ(components_of("bvec2"), 2);
  EXPECT_EQ(components_of("dvec4"), 4);
  EXPECT_EQ(components_of("mat3"), 9);
  EXPECT_EQ(components_of("mat2x4"), 8);
  EXPECT_EQ(components_of("dmat4x3"), 12);
  for (const char* other : {"sampler2D", "vec5", "vec", "mat1", "mat3x", "mat3x5", "ivec", "uvec22", "Light", ""})
    EXPECT_EQ(components_of(other), std::nullopt) << other;
}

}  // namespace
}  // namespace rm::lexing
