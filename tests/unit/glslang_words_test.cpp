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

TEST(GlslangWords, TypesAreWrittenAsGlslWritesThem) {
  EXPECT_EQ(plain_words("'assign' :  cannot convert from ' temp 3-component vector of float' to ' out 4-component "
                        "vector of float'"),
            "'=' : cannot convert from 'vec3' to 'out vec4'");
  EXPECT_EQ(plain_words("'*' :  wrong operand types: no operation '*' exists that takes a left-hand operand of type "
                        "' temp 3X3 matrix of float' and a right operand of type ' const 2-component vector of float' "
                        "(or there is no acceptable conversion)"),
            "'*' : wrong operand types: no operation '*' exists that takes a left-hand operand of type 'mat3' and a "
            "right operand of type 'const vec2' (or there is no acceptable conversion)");
  EXPECT_EQ(plain_words("'assign' :  cannot convert from ' temp 2X3 matrix of float' to ' temp 4-element array of "
                        "2-component vector of int'"),
            "'=' : cannot convert from 'mat2x3' to 'ivec2[4]'");
  EXPECT_EQ(plain_words("'assign' :  cannot convert from ' temp 2-component vector of double' to ' temp highp "
                        "3-component vector of bool'"),
            "'=' : cannot convert from 'dvec2' to 'highp bvec3'");
  EXPECT_EQ(plain_words("'assign' :  cannot convert from ' temp structure{ global float a,  global 2-component "
                        "vector of uint b}' to ' uniform sampler2D'"),
            "'=' : cannot convert from 'structure{ float a,  uvec2 b}' to 'uniform sampler2D'");
  // glslang cut the message inside the type.
  EXPECT_EQ(plain_words("'assign' :  cannot convert from ' temp structure{ global float a,  global 3-component vec"),
            "'=' : cannot convert from 'structure{ float a,  3-component vec");
  EXPECT_EQ(plain_words("'x' : it's"), "'x' : it's");
}

TEST(GlslangWords, OtherMessagesLoseOnlyAnEmptyTokenAndABlank) {
  EXPECT_EQ(plain_words("'foo' : undeclared identifier"), "'foo' : undeclared identifier");
  EXPECT_EQ(plain_words("'RETURN' : reserved word"), "'RETURN' : reserved word");
  EXPECT_EQ(plain_words("'' : missing #endif"), "missing #endif");
  EXPECT_EQ(plain_words("'(' :  syntax error"), "'(' : syntax error");
  EXPECT_EQ(plain_words("'' :  syntax error, parser stack overflow: memory exhausted").rfind("nested too deeply", 0), 0u);
}

}  // namespace
}  // namespace rm
