// Small, iterative readers of GLSL text: preprocessor directives, words and
// blanks. The host reads lines of any length with these, never with
// std::regex: libstdc++'s regex matcher recurses once per character, so a
// line of 100,000 blanks overflows the stack.
#pragma once
#include <algorithm>
#include <optional>
#include <string_view>

namespace rm::lexing {

// Blanks inside a line, as the GLSL preprocessor counts them (not '\n').
constexpr bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }
constexpr bool is_space(char c) { return is_blank(c) || c == '\n'; }
constexpr bool is_word_start(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
constexpr bool is_digit(char c) { return c >= '0' && c <= '9'; }
constexpr bool is_word_char(char c) { return is_word_start(c) || is_digit(c); }
// Whether `text` is one word: a macro's or a variable's name.
constexpr bool is_name(std::string_view text) {
  if (text.empty() || !is_word_start(text[0])) return false;
  for (char c : text)
    if (!is_word_char(c)) return false;
  return true;
}

// A precision qualifier, which may stand between a declaration's storage word
// and its type ("uniform highp vec3 c;").
constexpr bool is_precision(std::string_view word) { return word == "lowp" || word == "mediump" || word == "highp"; }

// How many components a value of a GLSL scalar, vector or matrix type holds
// (vec3: 3, mat4: 16), or nullopt for any other word (samplers, structs).
std::optional<int> components_of(std::string_view type);

// The first position at or after `at` that is not a blank.
size_t skip_blanks(std::string_view text, size_t at);
// The first position at or after `at` that is not blank or '\n'.
size_t skip_space(std::string_view text, size_t at);

// A preprocessor directive line: blanks, '#', blanks, a name, blanks, rest.
struct Directive {
  std::string_view name;  // "include", "version", "pragma", ...
  std::string_view rest;  // after the name and the blanks that follow it
  size_t hash = 0;        // offset of '#' in the line
  size_t rest_at = 0;     // offset of rest in the line
};
std::optional<Directive> directive(std::string_view line);
// The name a `#define NAME ...` line defines, at rest_at of its directive;
// nullopt for any other line.
std::optional<std::string_view> defined_macro(std::string_view line);

// Whether `rest` holds nothing more than blanks and perhaps a // comment.
bool nothing_but_comment(std::string_view rest);

// Calls visit(begin, end) for each word of `text` (a number, suffix and
// all, is none), in order, until it returns true; whether one did.
template <typename Visit>
bool any_word(std::string_view text, Visit visit) {
  size_t i = 0;
  while (i < text.size()) {
    if (!is_word_start(text[i])) {
      // Digits that follow a letter belong to that word; here they start a number.
      if (is_digit(text[i])) {
        while (i < text.size() && is_word_char(text[i])) ++i;
      } else {
        ++i;
      }
      continue;
    }
    const size_t begin = i;
    while (i < text.size() && is_word_char(text[i])) ++i;
    if (visit(begin, i)) return true;
  }
  return false;
}

// Calls visit(line, number) for each line of `text` (1-based numbers) until
// it returns false. Lines are views: a text of 10 million lines is not copied.
template <typename Visit>
void for_each_line(std::string_view text, Visit visit) {
  int number = 0;
  for (size_t at = 0; at <= text.size();) {
    const size_t end = std::min(text.find('\n', at), text.size());
    if (!visit(text.substr(at, end - at), ++number)) return;
    at = end + 1;
  }
}

// Where `text` first names `word` as a whole word.
std::optional<size_t> find_word(std::string_view text, std::string_view word);
// Whether `text` names `word` as a whole word.
bool has_word(std::string_view text, std::string_view word);
// Whether `text` has `name` as a whole word followed by '(' (blanks and
// newlines between are allowed); with `after`, only where that word comes
// just before it ("void main(").
bool has_call(std::string_view text, std::string_view name, std::string_view after = {});

// The text with each character of a comment blanked but its newlines: the
// comment still parts tokens, as in the compiler, and every line and column
// keeps its place. An unterminated /* runs to the end, and a // comment
// whose line ends in a backslash runs on into the next line.
std::string strip_comments(std::string_view text);

// The text as the compiler's tokens see it: comments gone, each run of
// blanks one space, none at a line's end. Two texts with the same code
// compile to the same program.
std::string code_only(std::string_view text);

}  // namespace rm::lexing
