#include "core/left_open.h"

#include <algorithm>
#include <map>
#include <string_view>
#include <utility>
#include <vector>

#include "core/glslang_words.h"
#include "core/lexing.h"

namespace rm {
namespace {

bool opens_conditional(std::string_view name) { return name == "if" || name == "ifdef" || name == "ifndef"; }

// A directive that puts no code in the text and leaves every line compiled:
// the code above it is what the token after it follows.
bool emits_nothing(std::string_view name) {
  return name == "define" || name == "undef" || name == "pragma" || name == "extension";
}

bool ends_in_backslash(std::string_view line) {
  const size_t last = line.find_last_not_of(" \t\r\f\v");
  return last != std::string_view::npos && line[last] == '\\';
}

// Where the line that starts at `begin` begins as the preprocessor reads it:
// at the first of the lines before it that each end in a backslash.
size_t logical_line_start(std::string_view code, size_t begin, int* number) {
  while (begin > 0) {
    const size_t above = begin == 1 ? 0 : code.rfind('\n', begin - 2) + 1;  // npos + 1 is 0: the first line
    if (!ends_in_backslash(code.substr(above, begin - 1 - above))) break;
    begin = above;
    --*number;
  }
  return begin;
}

int file_of(const Source& source, int final_line) {
  return final_line >= 1 && static_cast<size_t>(final_line) <= source.line_map.size()
             ? source.line_map[static_cast<size_t>(final_line) - 1].file
             : kHostFile;
}

// The token a syntax error names by its grammar name (RIGHT_BRACE, RETURN),
// as that name, which the message's words spell; a class of words
// (IDENTIFIER, FLOATCONSTANT) as the code spells it, quoted, from `code`,
// which starts at the token.
std::string token_named(std::string_view grammar_name, std::string_view code) {
  if (token_spelling(grammar_name)) return std::string(grammar_name);
  const bool number = !code.empty() && (lexing::is_digit(code[0]) || code[0] == '.');
  size_t end = 0;
  auto exponent_sign = [&] { return number && (code[end] == '+' || code[end] == '-') && (code[end - 1] | 0x20) == 'e'; };
  while (end < code.size() && (lexing::is_word_char(code[end]) || (number && code[end] == '.') || exponent_sign())) ++end;
  return "'" + std::string(code.substr(0, std::max<size_t>(end, 1))) + "'";
}

}  // namespace

std::optional<LeftOpen> conditional_left_open(std::string_view code) {
  std::vector<LeftOpen> open;
  lexing::for_each_line(code, [&](std::string_view line, int number) {
    if (const auto d = lexing::directive(line)) {
      if (opens_conditional(d->name))
        open.push_back({number, static_cast<int>(d->hash) + 1, "unterminated #" + std::string(d->name)});
      else if (d->name == "endif" && !open.empty())
        open.pop_back();
    }
    return true;
  });
  if (open.empty()) return std::nullopt;
  return open.back();
}

std::optional<LeftOpen> brace_left_open_before(const Source& source, std::string_view code, int error_line) {
  struct FileState {
    std::vector<LeftOpen> open;
    int last_line = 0;
  };
  std::map<int, FileState> files;
  // Where each file ends in the whole text: a file that includes another
  // inside a block goes on after an error in it.
  for (size_t i = 0; i < source.line_map.size(); ++i)
    if (source.line_map[i].file >= 0) files[source.line_map[i].file].last_line = static_cast<int>(i) + 1;
  std::vector<bool> in_later_branch;  // per open conditional
  bool directive_goes_on = false;     // the line above was a directive's, ended by a backslash
  lexing::for_each_line(code, [&](std::string_view line, int number) {
    if (number >= error_line) return false;
    const bool continued = std::exchange(directive_goes_on, false);
    if (continued || lexing::directive(line)) directive_goes_on = ends_in_backslash(line);
    if (continued) return true;  // a #define's body: its braces are not code yet
    if (const auto d = lexing::directive(line)) {
      if (opens_conditional(d->name)) in_later_branch.push_back(false);
      else if ((d->name == "else" || d->name == "elif") && !in_later_branch.empty()) in_later_branch.back() = true;
      else if (d->name == "endif" && !in_later_branch.empty()) in_later_branch.pop_back();
      return true;
    }
    const int file = file_of(source, number);
    if (file < 0 || std::find(in_later_branch.begin(), in_later_branch.end(), true) != in_later_branch.end()) return true;
    std::vector<LeftOpen>& open = files[file].open;
    for (size_t i = 0; i < line.size(); ++i) {
      if (line[i] == '{') open.push_back({number, static_cast<int>(i) + 1, "'{' : not closed before the end of the file"});
      else if (line[i] == '}' && !open.empty()) open.pop_back();
    }
    return true;
  });
  const FileState* first = nullptr;
  for (const auto& [file, state] : files)
    if (!state.open.empty() && state.last_line < error_line && (!first || state.last_line < first->last_line))
      first = &state;
  if (!first) return std::nullopt;
  return first->open.back();
}

std::optional<LeftOpen> declaration_left_open_before(const Source& source, std::string_view code, int error_line,
                                                     int column, const std::string& message) {
  const std::string_view unexpected = "syntax error, unexpected ";
  const size_t at = message.find(unexpected);
  const size_t token_end = at == std::string::npos ? at : message.find_first_of(", ", at + unexpected.size());
  if (token_end == std::string::npos) return std::nullopt;
  size_t failing_at = std::string::npos;  // where the error's line starts
  lexing::for_each_line(code, [&](std::string_view line, int number) {
    if (number == error_line) failing_at = static_cast<size_t>(line.data() - code.data());
    return number < error_line;
  });
  if (failing_at == std::string::npos) return std::nullopt;
  // The token is the first of its line, or the text's end (which glslang
  // names INT, on the line after the last).
  const size_t token_at = lexing::skip_blanks(code, failing_at);
  const bool at_text_end = code.find_first_not_of(" \t\r\n\f\v", failing_at) == std::string::npos;
  if (!at_text_end && token_at + 1 - failing_at != static_cast<size_t>(column)) return std::nullopt;
  // Back to the code before it, past whole conditionals (the host's
  // #ifdef RM_VIEW): had one been compiled, the error would be in it.
  int depth = 0;
  bool past_directive = false;
  size_t begin = failing_at;
  for (int number = error_line - 1; number >= 1; --number) {
    const size_t end = begin - 1;  // the '\n' before the line below
    begin = end == 0 ? 0 : code.rfind('\n', end - 1) + 1;  // npos + 1 is 0: the first line
    const std::string_view line = std::string_view(code).substr(begin, end - begin);
    // A #define's body continued by backslashes is the directive's, not code.
    int head_number = number;
    const size_t head = logical_line_start(code, begin, &head_number);
    const size_t head_end = code.find('\n', head);
    if (const auto d = lexing::directive(std::string_view(code).substr(head, head_end - head))) {
      if (d->name == "endif") ++depth;
      else if (opens_conditional(d->name) && depth > 0) --depth;
      past_directive = past_directive || !emits_nothing(d->name);
      begin = head;
      number = head_number;
      continue;
    }
    if (depth > 0 || lexing::skip_blanks(line, 0) == line.size()) continue;
    const int file = file_of(source, number);
    const int last_column = static_cast<int>(line.find_last_not_of(" \t\r\f\v")) + 2;  // just past the code
    if (file >= 0 && file != file_of(source, error_line))
      return LeftOpen{number, last_column,
                      message.substr(0, at) + "syntax error at the end of the file" + message.substr(token_end)};
    // In the same file, with no conditional between (which branch was
    // compiled is not known here), the line above was left unfinished.
    const size_t expecting = message.find(", expecting ", token_end);
    if (file < 0 || past_directive || at_text_end || expecting == std::string::npos) return std::nullopt;
    const std::string_view name = std::string_view(message).substr(at + unexpected.size(), token_end - at - unexpected.size());
    return LeftOpen{number, last_column,
                    message.substr(0, at) + "syntax error" + message.substr(expecting) + " before " +
                        token_named(name, std::string_view(code).substr(token_at))};
  }
  return std::nullopt;
}

}  // namespace rm
