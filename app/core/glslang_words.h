// glslang's messages in the words a reader of the code knows.
//
// glslang reports a syntax error as its parser's grammar names it:
// `'' :  syntax error, unexpected RIGHT_BRACE, expecting COMMA or SEMICOLON`.
// The empty token in front says nothing, and RIGHT_BRACE is `}` in the
// code. The words here are what a compiler says:
// `syntax error, unexpected '}', expecting ',' or ';'`. Types are as
// glslang describes them: `'assign' :  cannot convert from ' temp
// 3-component vector of float' to ' out 4-component vector of float'` is
// `'=' : cannot convert from 'vec3' to 'out vec4'`.
#pragma once
#include <optional>
#include <string>
#include <string_view>

namespace rm {

// `message` (glslang's, after its `ERROR: 0:LINE:`) with an empty token's
// `'' : ` dropped, each of the grammar's token names in a syntax error
// spelt as the code spells it ('}', 'return', 'vec4') or named as what it
// stands for (identifier, float constant), each quoted type as GLSL writes
// it, and a parser stack that ran out said in words that say why.
std::string plain_words(std::string_view message);

// The code's spelling of a token glslang's grammar names: "}" for
// RIGHT_BRACE, "return" for RETURN, "vec4" for VEC4; nullopt for a class of
// words (IDENTIFIER, FLOATCONSTANT) and a name it does not know.
std::optional<std::string> token_spelling(std::string_view grammar_name);

}  // namespace rm
