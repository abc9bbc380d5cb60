// What a file of the user's leaves open at its end: an #if, a '{' or a
// declaration. glslang notices only in the code that follows, in the file
// that included it or in the host's code after the scene, and names a token
// there that makes no sense to the user. These find where it was left open,
// as a C compiler names it.
#pragma once
#include <optional>
#include <string>
#include <string_view>

#include "core/source.h"

namespace rm {

// A place in the final text (1-based line and column) and what to say there.
struct LeftOpen {
  int final_line = 0;
  int column = 0;
  std::string message;
};

// Each reads `code`, the source's final text with its comments blanked
// (lexing::strip_comments), which the caller makes once for all its errors.

// For glslang's "missing #endif" at the end of the text: the innermost
// #if, #ifdef or #ifndef left open ("unterminated #ifdef").
std::optional<LeftOpen> conditional_left_open(std::string_view code);

// For an error at `error_line`: the innermost '{' left open by the first of
// the user's files that ends before it. Of a conditional's branches only the
// first is counted, since they are alternatives.
std::optional<LeftOpen> brace_left_open_before(const Source& source, std::string_view code, int error_line);

// For glslang's "syntax error, unexpected TOKEN" at the first token of
// `error_line` (found at `column`, 0 if not), or at the end of the text: the
// end of the user's file whose code comes just before, in another file (or
// none), where the ';' or ')' goes. In the same file, with no conditional
// between (a #define may be), the end of the code above, as gcc and clang
// name a missing ';':
// "syntax error, expecting COMMA or SEMICOLON before RIGHT_BRACE".
std::optional<LeftOpen> declaration_left_open_before(const Source& source, std::string_view code, int error_line,
                                                     int column, const std::string& message);

}  // namespace rm
