#include "core/left_open.h"

#include <algorithm>
#include <map>
#include <string_view>
#include <vector>

#include "core/lexing.h"

namespace rm {
namespace {

// The final text without comments, one string per line.
std::vector<std::string> code_lines(const Source& source) {
  const std::string code = lexing::strip_comments(source.text);
  std::vector<std::string> lines;
  for (size_t at = 0; at <= code.size();) {
    const size_t end = std::min(code.find('\n', at), code.size());
    lines.emplace_back(code, at, end - at);
    at = end + 1;
  }
  return lines;
}

bool opens_conditional(std::string_view name) { return name == "if" || name == "ifdef" || name == "ifndef"; }

int file_of(const Source& source, int final_line) {
  return final_line >= 1 && static_cast<size_t>(final_line) <= source.line_map.size()
             ? source.line_map[static_cast<size_t>(final_line) - 1].file
             : kHostFile;
}

}  // namespace

std::optional<LeftOpen> conditional_left_open(const Source& source) {
  const std::vector<std::string> lines = code_lines(source);
  std::vector<LeftOpen> open;
  for (size_t i = 0; i < lines.size(); ++i) {
    const auto d = lexing::directive(lines[i]);
    if (!d) continue;
    if (opens_conditional(d->name))
      open.push_back({static_cast<int>(i) + 1, static_cast<int>(d->hash) + 1, "unterminated #" + std::string(d->name)});
    else if (d->name == "endif" && !open.empty())
      open.pop_back();
  }
  if (open.empty()) return std::nullopt;
  return open.back();
}

std::optional<LeftOpen> brace_left_open_before(const Source& source, int error_line) {
  struct FileState {
    std::vector<LeftOpen> open;
    int last_line = 0;
  };
  std::map<int, FileState> files;
  // Where each file ends in the whole text: a file that includes another
  // inside a block goes on after an error in it.
  for (size_t i = 0; i < source.line_map.size(); ++i)
    if (source.line_map[i].file >= 0) files[source.line_map[i].file].last_line = static_cast<int>(i) + 1;
  const std::vector<std::string> lines = code_lines(source);
  std::vector<bool> in_later_branch;  // per open conditional
  for (int number = 1; number < error_line && static_cast<size_t>(number) <= lines.size(); ++number) {
    const std::string& line = lines[static_cast<size_t>(number) - 1];
    if (const auto d = lexing::directive(line)) {
      if (opens_conditional(d->name)) in_later_branch.push_back(false);
      else if ((d->name == "else" || d->name == "elif") && !in_later_branch.empty()) in_later_branch.back() = true;
      else if (d->name == "endif" && !in_later_branch.empty()) in_later_branch.pop_back();
      continue;
    }
    const int file = file_of(source, number);
    if (file < 0 || std::find(in_later_branch.begin(), in_later_branch.end(), true) != in_later_branch.end()) continue;
    std::vector<LeftOpen>& open = files[file].open;
    for (size_t i = 0; i < line.size(); ++i) {
      if (line[i] == '{') open.push_back({number, static_cast<int>(i) + 1, "'{' : not closed before the end of the file"});
      else if (line[i] == '}' && !open.empty()) open.pop_back();
    }
  }
  const FileState* first = nullptr;
  for (const auto& [file, state] : files)
    if (!state.open.empty() && state.last_line < error_line && (!first || state.last_line < first->last_line))
      first = &state;
  if (!first) return std::nullopt;
  return first->open.back();
}

std::optional<LeftOpen> declaration_left_open_before(const Source& source, int error_line, int column,
                                                     const std::string& message) {
  const std::string_view unexpected = "syntax error, unexpected ";
  const size_t at = message.find(unexpected);
  const size_t token_end = at == std::string::npos ? at : message.find_first_of(", ", at + unexpected.size());
  if (token_end == std::string::npos || column == 0) return std::nullopt;
  const std::vector<std::string> lines = code_lines(source);
  if (error_line < 1 || static_cast<size_t>(error_line) > lines.size()) return std::nullopt;
  const std::string& failing = lines[static_cast<size_t>(error_line) - 1];
  if (lexing::skip_blanks(failing, 0) + 1 != static_cast<size_t>(column)) return std::nullopt;  // not its first token
  // Back to the code before it, past whole conditionals (the host's
  // #ifdef RM_VIEW): had one been compiled, the error would be in it.
  int depth = 0;
  for (int number = error_line - 1; number >= 1; --number) {
    const std::string& line = lines[static_cast<size_t>(number) - 1];
    if (const auto d = lexing::directive(line)) {
      if (d->name == "endif") ++depth;
      else if (opens_conditional(d->name) && depth > 0) --depth;
      continue;
    }
    if (depth > 0 || lexing::skip_blanks(line, 0) == line.size()) continue;
    const int file = file_of(source, number);
    if (file < 0 || file == file_of(source, error_line)) return std::nullopt;
    const size_t last = line.find_last_not_of(" \t\r\f\v");
    return LeftOpen{number, static_cast<int>(last) + 2,
                    message.substr(0, at) + "syntax error at the end of the file" + message.substr(token_end)};
  }
  return std::nullopt;
}

}  // namespace rm
