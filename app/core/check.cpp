#include "core/check.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <map>
#include <sstream>
#include <string_view>
#include <vector>

#include "core/glslang_client.h"
#include "core/lexing.h"

namespace rm {

namespace {

// The spelling of the parser tokens glslang names in "unexpected X".
const char* token_spelling(const std::string& name) {
  static const std::pair<const char*, const char*> tokens[] = {
      {"SEMICOLON", ";"}, {"COMMA", ","},       {"DOT", "."},          {"COLON", ":"},
      {"EQUAL", "="},     {"PLUS", "+"},        {"DASH", "-"},         {"STAR", "*"},
      {"SLASH", "/"},     {"LEFT_PAREN", "("},  {"RIGHT_PAREN", ")"},  {"LEFT_BRACE", "{"},
      {"RIGHT_BRACE", "}"}, {"LEFT_BRACKET", "["}, {"RIGHT_BRACKET", "]"}, {"QUESTION", "?"},
  };
  for (const auto& [token, spelling] : tokens)
    if (name == token) return spelling;
  return nullptr;
}

// A log line read from left to right. Compiler logs quote the user's code,
// which can be any length, so they are read by hand rather than by std::regex
// (whose matcher recurses once per character).
class LogLine {
 public:
  explicit LogLine(std::string_view text) : text_(text) {}
  // Takes `literal` if the line continues with it.
  bool take(std::string_view literal) {
    if (text_.substr(at_, literal.size()) != literal) return false;
    at_ += literal.size();
    return true;
  }
  // Takes a number of 1 to 9 digits.
  std::optional<int> number() {
    size_t end = at_;
    while (end < text_.size() && end - at_ < 9 && lexing::is_digit(text_[end])) ++end;
    if (end == at_) return std::nullopt;
    const int value = std::stoi(std::string(text_.substr(at_, end - at_)));
    at_ = end;
    return value;
  }
  // Takes "error: " or "warning: ".
  std::optional<Severity> severity(std::string_view error, std::string_view warning) {
    if (take(error)) return Severity::Error;
    if (take(warning)) return Severity::Warning;
    return std::nullopt;
  }
  std::string rest() const { return std::string(text_.substr(at_)); }

 private:
  std::string_view text_;
  size_t at_ = 0;
};

// glslang names no column. Where its message quotes a token, or names the
// unexpected one, find that token on the line.
int column_in_line(const std::string& message, const std::string& line_text) {
  std::string needle;
  const size_t unexpected = message.find("unexpected ");
  if (unexpected != std::string::npos) {
    size_t end = unexpected + 11;
    while (end < message.size() && ((message[end] >= 'A' && message[end] <= 'Z') || lexing::is_digit(message[end]) ||
                                    message[end] == '_'))
      ++end;
    const std::string token = message.substr(unexpected + 11, end - unexpected - 11);
    if (const char* spelling = token_spelling(token)) {
      needle = spelling;
    } else if (!token.empty() && token != "IDENTIFIER" && token != "TYPE_NAME" && token.find("CONSTANT") == token.npos) {
      // A keyword: glslang names it in capitals (VOID, VEC3, RETURN).
      std::string keyword = token;
      for (char& c : keyword) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      for (size_t at = line_text.find(keyword); at != std::string::npos; at = line_text.find(keyword, at + 1)) {
        const size_t after = at + keyword.size();
        if ((at == 0 || !lexing::is_word_char(line_text[at - 1])) &&
            (after == line_text.size() || !lexing::is_word_char(line_text[after])))
          return static_cast<int>(at) + 1;
      }
      return 0;
    }
  }
  const size_t open = message.find('\'');
  const size_t close = open == std::string::npos ? open : message.find('\'', open + 1);
  if (needle.empty() && close != std::string::npos) needle = message.substr(open + 1, close - open - 1);
  if (needle.empty()) return 0;
  size_t at = line_text.find(needle);
  return at == std::string::npos ? 0 : static_cast<int>(at) + 1;
}

// glslang's words for a parser stack that ran out, in words that say why.
std::string plain_words(std::string message) {
  if (message.size() >= 16 && message.compare(message.size() - 16, 16, "memory exhausted") == 0)
    return "nested too deeply for glslang's parser (its stack holds 10000 levels of parentheses, "
           "brackets and blocks)";
  return message;
}

// The final text's first line (1-based) and column that name function f( outside
// a comment, which is its prototype or its first call: the line to look at for
// a function that has no body, where the linker's log names no line.
std::optional<std::pair<int, int>> first_mention_of_function(const std::string& name, const Source& source) {
  if (name.empty()) return std::nullopt;
  std::istringstream code(lexing::strip_comments(source.text));
  int number = 0;
  for (std::string line; std::getline(code, line);) {
    ++number;
    if (!lexing::has_call(line, name)) continue;
    size_t column = line.find(name);
    while (column != std::string::npos && column > 0 && lexing::is_word_char(line[column - 1]))
      column = line.find(name, column + 1);
    return std::pair{number, column == std::string::npos ? 0 : static_cast<int>(column) + 1};
  }
  return std::nullopt;
}

// The function Mesa's link error names ("unresolved reference to function
// `f'" gives f), or "" for any other message.
std::string unresolved_function(const std::string& message) {
  const std::string_view prefix = "unresolved reference to function `";
  if (message.rfind(prefix, 0) != 0 || message.back() != '\'') return "";
  return message.substr(prefix.size(), message.size() - prefix.size() - 1);
}

// The conditional (#if, #ifdef, #ifndef) that glslang's "missing #endif"
// at the end of the text means: the innermost one left open, as its final
// line (1-based), column and name; nullopt when all are closed.
struct OpenConditional {
  int final_line = 0;
  int column = 0;
  std::string name;
};
std::optional<OpenConditional> innermost_open_conditional(const std::string& text) {
  const std::string code = lexing::strip_comments(text);
  std::vector<OpenConditional> open;
  int number = 0;
  for (size_t at = 0; at <= code.size();) {
    const size_t end = std::min(code.find('\n', at), code.size());
    ++number;
    if (const auto d = lexing::directive(std::string_view(code).substr(at, end - at))) {
      if (d->name == "if" || d->name == "ifdef" || d->name == "ifndef")
        open.push_back({number, static_cast<int>(d->hash) + 1, std::string(d->name)});
      else if (d->name == "endif" && !open.empty())
        open.pop_back();
    }
    at = end + 1;
  }
  if (open.empty()) return std::nullopt;
  return open.back();
}

// The '{' a file of the user's left open at its end, for an error glslang
// reports after that end (in a later file, or in the host's code after the
// scene): the innermost such brace of the first such file, as its final line
// (1-based) and column. Of a conditional's branches only the first is
// counted, since they are alternatives ("#ifdef A\nvoid f() {\n#else ...").
struct OpenBrace {
  int final_line = 0;
  int column = 0;
};
std::optional<OpenBrace> brace_left_open_before(const Source& source, int error_line) {
  const std::string code = lexing::strip_comments(source.text);
  struct FileState {
    std::vector<OpenBrace> open;
    int last_line = 0;
  };
  std::map<int, FileState> files;
  // Where each file ends in the whole text: a file that includes another
  // inside a block goes on after the error in it.
  for (size_t i = 0; i < source.line_map.size(); ++i)
    if (source.line_map[i].file >= 0) files[source.line_map[i].file].last_line = static_cast<int>(i) + 1;
  std::vector<bool> in_later_branch;  // per open conditional
  int number = 0;
  for (size_t at = 0; at < code.size() && number + 1 < error_line;) {
    const size_t end = std::min(code.find('\n', at), code.size());
    const std::string_view line = std::string_view(code).substr(at, end - at);
    const auto index = static_cast<size_t>(number);
    const int file = index < source.line_map.size() ? source.line_map[index].file : kHostFile;
    ++number;
    at = end + 1;
    if (const auto d = lexing::directive(line)) {
      if (d->name == "if" || d->name == "ifdef" || d->name == "ifndef") in_later_branch.push_back(false);
      else if ((d->name == "else" || d->name == "elif") && !in_later_branch.empty()) in_later_branch.back() = true;
      else if (d->name == "endif" && !in_later_branch.empty()) in_later_branch.pop_back();
      continue;
    }
    if (file < 0) continue;
    FileState& state = files[file];
    if (std::find(in_later_branch.begin(), in_later_branch.end(), true) != in_later_branch.end()) continue;
    for (size_t i = 0; i < line.size(); ++i) {
      if (line[i] == '{') state.open.push_back({number, static_cast<int>(i) + 1});
      else if (line[i] == '}' && !state.open.empty()) state.open.pop_back();
    }
  }
  const FileState* first = nullptr;
  for (const auto& [file, state] : files)
    if (!state.open.empty() && state.last_line < error_line && (!first || state.last_line < first->last_line))
      first = &state;
  if (!first) return std::nullopt;
  return first->open.back();
}

// A syntax error at the first token after a file of the user's (a ';' or a
// ')' missing at its end): glslang names a token of the code that follows,
// in the host's code or the including file. The error is at the end of that
// file's last code, where the ';' goes, and the token does not matter.
struct EndOfFileError {
  int final_line = 0;
  int column = 0;
  std::string message;
};
std::optional<EndOfFileError> syntax_error_after_a_file(const Source& source, int error_line,
                                                        const std::string& message) {
  const std::string_view unexpected = "syntax error, unexpected ";
  const size_t at = message.find(unexpected);
  const size_t token_end = at == std::string::npos ? at : message.find_first_of(", ", at + unexpected.size());
  if (token_end == std::string::npos || error_line < 1) return std::nullopt;
  const auto file_of = [&](int line) {
    return line >= 1 && static_cast<size_t>(line) <= source.line_map.size() ? source.line_map[line - 1].file : kHostFile;
  };
  std::vector<std::string> lines;
  std::istringstream code(lexing::strip_comments(source.text));
  for (std::string line; std::getline(code, line) && static_cast<int>(lines.size()) < error_line;) lines.push_back(line);
  if (static_cast<int>(lines.size()) < error_line) return std::nullopt;
  const std::string& failing = lines[error_line - 1];
  const int column = column_in_line(message, failing);
  if (column == 0 || lexing::skip_blanks(failing, 0) + 1 != static_cast<size_t>(column)) return std::nullopt;
  // Back to the code before it, past whole conditionals (the host's
  // #ifdef RM_VIEW): had one been compiled, the error would be in it.
  int depth = 0;
  for (int line = error_line - 1; line >= 1; --line) {
    const std::string& text = lines[line - 1];
    if (const auto d = lexing::directive(text)) {
      if (d->name == "endif") ++depth;
      else if ((d->name == "if" || d->name == "ifdef" || d->name == "ifndef") && depth > 0) --depth;
      continue;
    }
    if (depth > 0 || lexing::skip_blanks(text, 0) == text.size()) continue;
    if (file_of(line) < 0 || file_of(line) == file_of(error_line)) return std::nullopt;
    const size_t last = text.find_last_not_of(" \t\r\f\v");
    return EndOfFileError{line, static_cast<int>(last) + 2,
                          message.substr(0, at) + "syntax error at the end of the file" + message.substr(token_end)};
  }
  return std::nullopt;
}

Diagnostic locate(const Source& source, Severity severity, int final_line, int column, std::string message) {
  Diagnostic d;
  d.severity = severity;
  auto [path, line] = source.locate(final_line);
  if (path.empty()) {
    // A line the host added (wrapper or prelude): the cause is in the scene.
    d.path = source.files.empty() ? std::string() : source.files.front().string();
    d.message = "in the code the host adds around the scene: " + message;
  } else {
    d.path = path;
    d.line = line;
    d.column = column;
    d.message = std::move(message);
  }
  return d;
}

// What went wrong when glslang gave no verdict, said at the scene's file.
Diagnostic no_verdict(const Source& source, const GlslangReply& reply) {
  Diagnostic d;
  d.path = source.files.empty() ? std::string() : source.files.front().string();
  switch (reply.status) {
    case GlslangReply::Status::TimedOut:
      d.message = "glslang took more than " + std::to_string(static_cast<int>(kValidationSeconds)) +
                  " s on this shader (a macro that expands without end?)";
      break;
    case GlslangReply::Status::OutOfMemory:
      d.message = "glslang needed more than " + std::to_string(kValidationBytes >> 20) +
                  " MiB for this shader (a macro that expands without end?)";
      break;
    case GlslangReply::Status::NoWorker:
      d.message = "cannot check this shader: " + reply.output;
      break;
    default:
      d.message = std::string("glslang crashed on this shader (") +
                  (reply.signal ? strsignal(reply.signal) : "it exited with an error") + ")";
  }
  return d;
}

}  // namespace

Diagnostics validate(const Source& source, std::string* active, const std::string& appended) {
  GlslangRequest request;
  request.version_line = source.version_line;
  request.text = source.text;
  if (active) request.active_text = source.text + "\n" + appended;
  GlslangReply child = ask_glslang(request);
  if (active) {
    active->clear();
    const size_t nul = child.output.find('\0');
    if (child.status == GlslangReply::Status::Ok && nul != std::string::npos) {
      *active = child.output.substr(nul + 1);
      child.output.resize(nul);
    }
  }
  if (child.status != GlslangReply::Status::Ok) return {no_verdict(source, child)};
  const size_t newline = child.output.find('\n');
  LogLine verdict(std::string_view(child.output).substr(0, newline));
  const int depth = verdict.number().value_or(0);
  const int deepest_line = verdict.take(" ") ? verdict.number().value_or(0) : 0;
  Diagnostics out = map_log(newline == std::string::npos ? "" : child.output.substr(newline + 1), source,
                            LogFormat::Glslang);
  // The GL driver recurses over the same tree on the thread that draws, and
  // Mesa overflows 8 MiB near 15,000 levels: what it may not take is refused.
  if (depth > kMaxTreeDepth)
    out.push_back(locate(source, Severity::Error, deepest_line, 0,
                         "an expression nested " + std::to_string(depth) + " levels deep; at most " +
                             std::to_string(kMaxTreeDepth) + " are allowed (the GL driver's compiler recurses on each)"));
  return out;
}

namespace {

// glslang's preprocessed text, one output line per line of the source,
// marked as cpp marks its output: a `# LINE "FILE"` line wherever the next
// line does not follow the previous one, and no blank lines (a gap of a few
// lines in one file is kept as blank lines instead of a marker, as cpp does).
// With LineMarkers::Off, the same lines with no markers and no blank lines.
std::string with_line_markers(const std::string& expanded, const Source& source, LineMarkers markers) {
  std::vector<std::string_view> lines;
  for (size_t at = 0; at < expanded.size();) {
    size_t end = expanded.find('\n', at);
    if (end == std::string::npos) end = expanded.size();
    lines.emplace_back(expanded.data() + at, end - at);
    at = end + 1;
  }
  if (lines.size() != source.line_map.size()) return expanded;  // not line for line: leave it as glslang gave it
  constexpr int kMaxBlankGap = 8;
  std::string out, file;
  int next = 0;
  for (size_t i = 0; i < lines.size(); ++i) {
    if (lines[i].find_first_not_of(" \t\r") == std::string_view::npos) continue;
    auto [path, line] = source.locate(static_cast<int>(i) + 1);
    if (path.empty()) path = "<raymarching>", line = 0;  // a line the host adds
    if (i == 0 || markers == LineMarkers::Off) {  // #version stays first; -P wants the lines alone
    } else if (path != file || (line != 0 && line != next)) {
      if (path == file && line > next && line - next <= kMaxBlankGap) {
        out.append(static_cast<size_t>(line - next), '\n');
      } else {
        out += "# " + std::to_string(std::max(line, 1)) + " \"" + path + "\"\n";
      }
    }
    file = path;
    next = line + 1;
    out += lines[i];
    out += '\n';
  }
  return out;
}

}  // namespace

std::optional<std::string> expand_preprocessor(const Source& source, Diagnostics* diags, LineMarkers markers) {
  GlslangRequest request;
  request.kind = GlslangRequest::Kind::Preprocess;
  request.text = source.text;
  const GlslangReply child = ask_glslang(request);
  if (child.status != GlslangReply::Status::Ok) {
    *diags = {no_verdict(source, child)};
    return std::nullopt;
  }
  if (child.output.empty() || child.output[0] != '+') {
    *diags = map_log(child.output.substr(std::min<size_t>(1, child.output.size())), source, LogFormat::Glslang);
    return std::nullopt;
  }
  return with_line_markers(child.output.substr(1), source, markers);
}

std::optional<std::string> active_code(const std::string& text) {
  GlslangRequest request;
  request.kind = GlslangRequest::Kind::Preprocess;
  request.text = text;
  const GlslangReply child = ask_glslang(request);
  if (child.status != GlslangReply::Status::Ok || child.output.empty() || child.output[0] != '+') return std::nullopt;
  return child.output.substr(1);
}

Diagnostics map_log(const std::string& log, const Source& source, LogFormat format) {
  Diagnostics out;
  std::istringstream in(log);
  std::string text;
  while (std::getline(in, text)) {
    while (!text.empty() && (text.back() == ' ' || text.back() == '\r')) text.pop_back();
    if (text.empty()) continue;
    if (format == LogFormat::Glslang) {
      // "ERROR: 0:12: 'foo' : undeclared identifier", then "ERROR: 1 compilation errors. ..."
      LogLine line(text);
      const auto severity = line.severity("ERROR: ", "WARNING: ");
      if (severity && line.number()) {
        if (line.take(" compilation error")) continue;  // the summary
        const auto final_line = line.take(":") ? line.number() : std::nullopt;
        if (final_line && line.take(": ")) {
          const std::string message = line.rest();
          if (message == "'' : compilation terminated") continue;  // follows a real error
          // glslang stops at its first error, inside a conditional if it was
          // in one (or after #if nesting ran over): then of course an #endif
          // is missing.
          const bool missing_endif = message == "'' : missing #endif";
          const bool after_error = std::any_of(out.begin(), out.end(), [](const Diagnostic& d) {
            return d.severity == Severity::Error;
          });
          if (missing_endif && after_error) continue;
          // Else it is at the end of the text, where the host's code is: say
          // where the conditional left open starts, as C compilers do.
          if (const auto open = missing_endif ? innermost_open_conditional(source.text) : std::nullopt) {
            out.push_back(locate(source, *severity, open->final_line, open->column, "unterminated #" + open->name));
            continue;
          }
          // A file that ends inside a block puts what follows it there: the
          // error is the '{' it left open.
          const auto open_brace = *severity == Severity::Error && !after_error
                                      ? brace_left_open_before(source, *final_line) : std::nullopt;
          if (open_brace) {
            out.push_back(locate(source, *severity, open_brace->final_line, open_brace->column,
                                 "'{' : not closed before the end of the file"));
            continue;
          }
          const auto at_end = *severity == Severity::Error && !after_error
                                  ? syntax_error_after_a_file(source, *final_line, message) : std::nullopt;
          if (at_end) {
            out.push_back(locate(source, *severity, at_end->final_line, at_end->column, at_end->message));
            continue;
          }
          const int col = column_in_line(message, source.final_line_text(*final_line));
          out.push_back(locate(source, *severity, *final_line, col, plain_words(message)));
          continue;
        }
      }
    } else {
      // "0:12(5): error: syntax error, unexpected ';'"
      LogLine line(text);
      const bool located = line.number() && line.take(":");
      const auto final_line = located ? line.number() : std::nullopt;
      const auto column = final_line && line.take("(") ? line.number() : std::nullopt;
      const auto severity = column && line.take("): ") ? line.severity("error: ", "warning: ") : std::nullopt;
      if (severity) {
        out.push_back(locate(source, *severity, *final_line, *column, line.rest()));
        continue;
      }
    }
    // Anything else (link errors, unknown formats) is kept, attributed to the scene.
    // Mesa's link errors carry no line: "error: unresolved reference to function `f'".
    Diagnostic d;
    d.path = source.files.empty() ? std::string() : source.files.front().string();
    LogLine line(text);
    if (const auto severity = line.severity("error: ", "warning: ")) d.severity = *severity;
    d.message = line.rest();
    if (const auto at = first_mention_of_function(unresolved_function(d.message), source)) {
      const Severity severity = d.severity;
      std::string message = std::move(d.message);
      d = locate(source, severity, at->first, at->second, std::move(message));
    }
    out.push_back(std::move(d));
  }
  return out;
}

}  // namespace rm
