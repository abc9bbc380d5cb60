#include "core/dialect_names.h"

#include <algorithm>
#include <array>

#include "core/lexing.h"

namespace rm {

namespace {

// Free in GLSL ES 3.00 (WebGL 2 takes them as names), keywords in 4.50 core.
constexpr std::array<std::string_view, 3> kEsSl300Names = {"buffer", "shared", "precise"};
// Free in GLSL 1.10 and ES 1.00, keywords or reserved in 4.50 core; the
// types 4.50 adds (uint, mat2x3, samplers) are left out: no one names a
// variable so.
constexpr std::array<std::string_view, 17> kGlsl110Names = {
    "buffer", "shared",    "precise",       "sample",   "patch",  "subroutine", "coherent", "restrict",  "readonly",
    "writeonly", "noperspective", "resource", "layout", "centroid", "flat",     "smooth",   "invariant"};

constexpr std::string_view kPrefix = "rm_";

// How `code` uses `word`: as a name (a declaration, an operand, a function),
// or as the qualifier 4.50 makes of it, which another word on the same line
// follows (or, for layout, a parenthesis).
struct Uses {
  bool as_name = false;
  bool as_qualifier = false;
};

Uses uses_of(std::string_view code, std::string_view word) {
  Uses uses;
  for (size_t from = 0; from < code.size();) {
    const std::optional<size_t> at = lexing::find_word(code.substr(from), word);
    if (!at) break;
    const size_t next = lexing::skip_blanks(code, from + *at + word.size());
    const char follows = next < code.size() ? code[next] : ';';
    if (lexing::is_word_start(follows) || (word == "layout" && follows == '('))
      uses.as_qualifier = true;
    else
      uses.as_name = true;
    from += *at + word.size();
  }
  return uses;
}

bool defines_macro(std::string_view code, std::string_view word) {
  for (size_t begin = 0; begin < code.size();) {
    size_t end = code.find('\n', begin);
    if (end == std::string_view::npos) end = code.size();
    if (lexing::defined_macro(code.substr(begin, end - begin)) == word) return true;
    begin = end + 1;
  }
  return false;
}

}  // namespace

std::vector<std::string> names_core_reserves(std::string_view code, Dialect dialect) {
  std::vector<std::string> out;
  auto consider = [&](std::string_view word) {
    const Uses uses = uses_of(code, word);
    if (uses.as_name && !uses.as_qualifier && !defines_macro(code, word)) out.emplace_back(word);
  };
  if (dialect == Dialect::EsSl300)
    std::for_each(kEsSl300Names.begin(), kEsSl300Names.end(), consider);
  else
    std::for_each(kGlsl110Names.begin(), kGlsl110Names.end(), consider);
  return out;
}

std::string compiler_name(std::string_view word) { return std::string(kPrefix) + std::string(word); }

std::string with_names_restored(std::string_view message, const std::vector<std::string>& words) {
  if (words.empty()) return std::string(message);
  std::string out;
  out.reserve(message.size());
  for (size_t i = 0; i < message.size();) {
    if (!lexing::is_word_start(message[i])) {
      out += message[i++];
      continue;
    }
    const size_t begin = i;
    while (i < message.size() && lexing::is_word_char(message[i])) ++i;
    const std::string_view word = message.substr(begin, i - begin);
    const bool renamed = word.substr(0, kPrefix.size()) == kPrefix &&
                         std::find(words.begin(), words.end(), word.substr(kPrefix.size())) != words.end();
    out += renamed ? word.substr(kPrefix.size()) : word;
  }
  return out;
}

}  // namespace rm
