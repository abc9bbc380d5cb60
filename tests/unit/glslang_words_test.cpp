// glslang's messages in the words of the code (core/glslang_words.h).
#include "core/glslang_words.h"

#include <gtest/gtest.h>

namespace rm {
namespace {

TEST(GlslangWords, ASyntaxErrorSpellsItsTokensAsTheCodeDoes) {
  EXPECT_EQ(plain_words("'' :  syntax error, unexpected RIGHT_BRACE, expecting COMMA or SEMICOLON"),
            "syntax error, unexpected '}', expecting ',' or ';'");
  EXPECT_EQ(plain_words("'' :  syntax error, unexpected RETURN, expecting COMMA or SEMICOLON"),
            "syntax error, unexpected 'return', expecting ',' or ';'");
  EXPECT_EQ(plain_words("'' :  syntax error, unexpected FLOATCONSTANT, expecting LEFT_PAREN or IDENTIFIER or LE_OP"),
            "syntax error, unexpected float constant, expecting '(' or identifier or '<='");
  EXPECT_EQ(plain_words("'' :  syntax error, unexpected VEC4"), "syntax error, unexpected 'vec4'");
  EXPECT_EQ(plain_words("'' :  syntax error, unexpected MAT2X3, expecting SAMPLERCUBE"),
            "syntax error, unexpected 'mat2x3', expecting 'samplerCube'");
  EXPECT_EQ(plain_words("'' :  syntax error at the end of the file, expecting RIGHT_PAREN"),
            "syntax error at the end of the file, expecting ')'");
  // A name the table lacks stays the grammar's.
  EXPECT_EQ(plain_words("'' :  syntax error, unexpected SAMPLER1DARRAY, expecting SUB_ASSIGN"),
            "syntax error, unexpected SAMPLER1DARRAY, expecting '-='");
}

TEST(GlslangWords, OtherMessagesLoseOnlyAnEmptyToken) {
  EXPECT_EQ(plain_words("'foo' : undeclared identifier"), "'foo' : undeclared identifier");
  EXPECT_EQ(plain_words("'RETURN' : reserved word"), "'RETURN' : reserved word");
  EXPECT_EQ(plain_words("'' : missing #endif"), "missing #endif");
  EXPECT_EQ(plain_words("'(' :  syntax error"), "'(' :  syntax error");
  EXPECT_EQ(plain_words("'' :  syntax error, parser stack overflow: memory exhausted").rfind("nested too deeply", 0), 0u);
}

}  // namespace
}  // namespace rm
