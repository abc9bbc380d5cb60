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
// variable so. `texture` is 4.50's sampling function, and a common name
// for a sampler in those dialects (`uniform sampler2D texture;`), which
// hides the function.
constexpr std::array<std::string_view, 18> kGlsl110Names = {
    "buffer",   "shared", "precise",  "sample", "patch",    "subroutine", "coherent",  "restrict", "readonly",
    "writeonly", "noperspective", "resource", "layout", "centroid", "flat", "smooth", "invariant", "texture"};

constexpr std::string_view kPrefix = "rm_";

// How `code` uses a word: as a name (a declaration, an operand, a
// function), or as 4.50 does: a qualifier, which another word on the same
// line follows, or (layout, texture) a word a parenthesis follows.
struct Uses {
  bool as_name = false;
  bool as_core_word = false;
};

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
  const std::string_view* words = dialect == Dialect::EsSl300 ? kEsSl300Names.data() : kGlsl110Names.data();
  const size_t count = dialect == Dialect::EsSl300 ? kEsSl300Names.size() : kGlsl110Names.size();
  std::vector<Uses> uses(count);
  // One pass over the code's words: a scene may be megabytes long.
  lexing::any_word(code, [&](size_t begin, size_t end) {
    const std::string_view word = code.substr(begin, end - begin);
    const std::string_view* found = std::find(words, words + count, word);
    if (found == words + count) return false;
    const size_t next = lexing::skip_blanks(code, end);
    const char follows = next < code.size() ? code[next] : ';';
    Uses& use = uses[static_cast<size_t>(found - words)];
    if (lexing::is_word_start(follows) || ((word == "layout" || word == "texture") && follows == '('))
      use.as_core_word = true;
    else
      use.as_name = true;
    return false;
  });
  std::vector<std::string> out;
  for (size_t w = 0; w < count; ++w)
    if (uses[w].as_name && !uses[w].as_core_word && !defines_macro(code, words[w])) out.emplace_back(words[w]);
  return out;
}

std::string compiler_name(std::string_view word) { return std::string(kPrefix) + std::string(word); }

std::string with_names_restored(std::string_view message, const std::vector<std::string>& words) {
  if (words.empty()) return std::string(message);
  std::string out;
  out.reserve(message.size());
  size_t copied = 0;  // message[0, copied) is in out
  lexing::any_word(message, [&](size_t begin, size_t end) {
    const std::string_view word = message.substr(begin, end - begin);
    if (word.substr(0, kPrefix.size()) == kPrefix &&
        std::find(words.begin(), words.end(), word.substr(kPrefix.size())) != words.end()) {
      out += message.substr(copied, begin - copied);
      out += word.substr(kPrefix.size());
      copied = end;
    }
    return false;
  });
  out += message.substr(copied);
  return out;
}

}  // namespace rm
