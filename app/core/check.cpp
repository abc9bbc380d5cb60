#include "core/check.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <deque>
#include <map>
#include <set>
#include <sstream>
#include <string_view>
#include <tuple>
#include <vector>

#include "core/dialect_names.h"
#include "core/glslang_client.h"
#include "core/glslang_words.h"
#include "core/left_open.h"
#include "core/lexing.h"

namespace rm {

namespace {

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

// glslang's 'assign' is an '=' of the line: the line's only one, if it has
// one ('==', '<=', '+=' and their like are other tokens).
std::optional<size_t> sole_assignment(std::string_view line) {
  std::optional<size_t> found;
  for (size_t i = 0; i < line.size(); ++i) {
    if (line[i] != '=') continue;
    if (i + 1 < line.size() && line[i + 1] == '=') {
      ++i;
      continue;
    }
    if (i > 0 && std::strchr("=!<>+-*/%&|^", line[i - 1])) continue;
    if (found) return std::nullopt;
    found = i;
  }
  return found;
}

// Where `line` has its only word that `is_subject(word, its end)` takes, or
// its only `mark` character besides; nullopt where it has none or several.
template <typename IsSubject>
std::optional<size_t> sole_place(std::string_view line, IsSubject is_subject, char mark = 0) {
  std::optional<size_t> found;
  int count = 0;
  lexing::any_word(line, [&](size_t begin, size_t end) {
    if (is_subject(line.substr(begin, end - begin), end)) found = begin, ++count;
    return count > 1;
  });
  for (size_t i = 0; mark && i < line.size(); ++i)
    if (line[i] == mark) found = i, ++count;
  return count == 1 ? found : std::nullopt;
}

// Where `line` has its only integer literal past 32 bits, the one that
// glslang's "numeric (hexadecimal, octal) literal too big" is about.
std::optional<size_t> sole_literal_too_big(std::string_view line) {
  std::optional<size_t> found;
  int count = 0;
  for (size_t start = 0, end = 0; start < line.size(); start = std::max(start + 1, end)) {
    const bool starts_number = lexing::is_digit(line[start]) &&
                               (start == 0 || !(lexing::is_word_char(line[start - 1]) || line[start - 1] == '.'));
    if (!starts_number) continue;
    for (end = start; end < line.size() && lexing::is_word_char(line[end]);) ++end;
    if (end < line.size() && line[end] == '.') continue;  // a float
    std::string_view digits = line.substr(start, end - start);
    if (digits.back() == 'u' || digits.back() == 'U') digits.remove_suffix(1);
    int base = digits.size() > 1 && digits[0] == '0' ? 8 : 10;
    if (digits.size() > 2 && (digits[1] == 'x' || digits[1] == 'X')) base = 16, digits.remove_prefix(2);
    unsigned long long value = 0;
    bool integer = !digits.empty();
    for (const char c : digits) {
      const int digit = lexing::is_digit(c)                                          ? c - '0'
                        : std::isxdigit(static_cast<unsigned char>(c)) ? std::tolower(static_cast<unsigned char>(c)) - 'a' + 10
                                                                       : base;
      integer = integer && digit < base;  // else a float (1e5)
      value = std::min(value * static_cast<unsigned>(base) + static_cast<unsigned>(digit), 1ULL << 40);
    }
    if (integer && value > 0xFFFFFFFFULL) found = start, ++count;
  }
  return count == 1 ? found : std::nullopt;
}

// The column of what a message that quotes no token is about, where the
// line leaves no doubt: a stray break or continue, the function that
// returns no value, the condition that is no bool (glslang puts it at the
// `if`, `while` or `?`), a constructor's arguments.
std::optional<size_t> unquoted_subject(std::string_view message, std::string_view line) {
  constexpr std::string_view kNoValue = "function does not return a value: ";
  if (message.starts_with("'' : ")) message.remove_prefix(5);  // glslang's empty token
  while (!message.empty() && lexing::is_blank(message.back())) message.remove_suffix(1);
  if (message.starts_with("break statement")) return lexing::find_word(line, "break");
  if (message.starts_with("continue statement")) return lexing::find_word(line, "continue");
  if (message.starts_with(kNoValue)) return lexing::find_word(line, message.substr(kNoValue.size()));
  if (message.ends_with(" literal too big")) return sole_literal_too_big(line);
  if (message == "boolean expression expected")
    return sole_place(line, [](std::string_view word, size_t) { return word == "if" || word == "while"; }, '?');
  if (message.starts_with("'constructor' : ")) {  // a scalar, vector or matrix type's: `vec2(`
    return sole_place(line, [&](std::string_view word, size_t end) {
      const size_t after = lexing::skip_blanks(line, end);
      return after < line.size() && line[after] == '(' && lexing::components_of(word).has_value();
    });
  }
  return std::nullopt;
}

// glslang names no column (the worker adds one for an unexpected token
// where its search is quick enough). Where the message quotes a token, or
// names the unexpected one, find that token's first spelling on the line.
int column_in_line(const std::string& message, const std::string& line_text) {
  const std::string code = lexing::strip_comments(line_text);  // the line, its comments blanked
  if (const auto subject = unquoted_subject(message, code))
    return static_cast<int>(*subject) + 1;
  std::string needle;
  const size_t unexpected = message.find("unexpected ");
  if (unexpected != std::string::npos) {
    size_t end = unexpected + 11;
    while (end < message.size() && ((message[end] >= 'A' && message[end] <= 'Z') || lexing::is_digit(message[end]) ||
                                    message[end] == '_'))
      ++end;
    const std::string token = message.substr(unexpected + 11, end - unexpected - 11);
    if (const std::optional<std::string> spelling = token_spelling(token)) {
      if (!lexing::is_word_start((*spelling)[0])) {
        needle = *spelling;
      } else {  // a keyword, as a word of its own
        const std::optional<size_t> at = lexing::find_word(line_text, *spelling);
        return at ? static_cast<int>(*at) + 1 : 0;
      }
    }
  }
  const size_t open = message.find('\'');
  const size_t close = open == std::string::npos ? open : message.find('\'', open + 1);
  if (needle.empty() && close != std::string::npos) needle = message.substr(open + 1, close - open - 1);
  if (needle == "assign") {
    const std::optional<size_t> at = sole_assignment(line_text);
    return at ? static_cast<int>(*at) + 1 : 0;
  }
  if (needle.empty()) return 0;
  // A name as a word of its own, outside comments: 'g' is not the g of mainImage.
  std::optional<size_t> at;
  if (lexing::is_name(needle)) at = lexing::find_word(code, needle);
  else if (const size_t found = code.find(needle); found != std::string::npos) at = found;
  return at ? static_cast<int>(*at) + 1 : 0;
}

// The first line (1-based) and column of `code`, the final text without its
// comments, that name `name` as a word; with `call`, only where a '(' follows: a
// function's prototype or its first call. The place to show for what the
// linker's log names with no line: a function with no body, an input.
std::optional<std::pair<int, int>> first_mention(const std::string& name, std::string_view code, bool call) {
  if (name.empty()) return std::nullopt;
  std::optional<std::pair<int, int>> found;
  lexing::for_each_line(code, [&](std::string_view line, int number) {
    if (call && !lexing::has_call(line, name)) return true;
    if (const auto at = lexing::find_word(line, name)) found = std::pair{number, static_cast<int>(*at) + 1};
    return !found;
  });
  return found;
}

// The input a link error finds nothing to feed ("fragment shader input
// `v_color' has no matching output in the previous stage" gives v_color; an
// input block's "Input block `Data' is not an output of the previous stage"
// gives Data), or "" for any other message.
std::string unfed_input(const std::string& message) {
  constexpr std::pair<std::string_view, std::string_view> kForms[] = {
      {"fragment shader input `", "' has no matching output in the previous stage"},
      {"Input block `", "' is not an output of the previous stage"},
  };
  for (const auto& [prefix, suffix] : kForms)
    if (message.rfind(prefix, 0) == 0 && message.size() >= prefix.size() + suffix.size() &&
        message.compare(message.size() - suffix.size(), suffix.size(), suffix) == 0)
      return message.substr(prefix.size(), message.size() - prefix.size() - suffix.size());
  return "";
}

// The uniform of the scene's own code with the most components, with the
// final text's line and column of its name: the place for the driver's
// "Too many fragment shader default uniform block components", which names
// none. A size the code spells with a macro counts as 1.
struct LargestUniform {
  int line = 0, column = 0;
  std::string name;
  long long components = 0;
};
std::optional<LargestUniform> largest_uniform(const Source& source, std::string_view code) {
  std::optional<LargestUniform> largest;
  lexing::for_each_line(code, [&](std::string_view line, int number) {
    std::vector<std::string_view> words;
    lexing::any_word(line, [&](size_t begin, size_t end) {
      words.push_back(line.substr(begin, end - begin));
      return words.size() >= 4;
    });
    if (words.size() < 3 || words[0] != "uniform" || source.locate(number).first.empty()) return true;
    const size_t type = lexing::is_precision(words[1]) ? 2 : 1;
    const std::optional<int> known = lexing::components_of(words[type]);
    if (!known || type + 1 >= words.size()) return true;
    const std::string_view name = words[type + 1];
    // Sizes and their product stop at 2^40, far past any driver's limit, so
    // that `u[99999999999][99999999999]` cannot overflow.
    constexpr long long kCap = 1LL << 40;
    long long components = *known;
    const size_t after = static_cast<size_t>(name.data() - line.data()) + name.size();
    for (size_t at = lexing::skip_blanks(line, after); at < line.size() && line[at] == '[';) {
      size_t digits = at + 1;
      long long size = 0;
      while (digits < line.size() && lexing::is_digit(line[digits]) && size < kCap)
        size = size * 10 + (line[digits++] - '0');
      if (size > 0) components = size > kCap / components ? kCap : components * size;
      const size_t close = line.find(']', at);
      if (close == std::string::npos) break;
      at = lexing::skip_blanks(line, close + 1);
    }
    if (!largest || components > largest->components)
      largest = LargestUniform{number, static_cast<int>(name.data() - line.data()) + 1, std::string(name), components};
    return true;
  });
  return largest;
}

// Whether a link error says the uniforms take more than the driver allows
// ("Too many fragment shader uniform components", "... default uniform
// block components", "count of uniform locations > MAX_UNIFORM_LOCATIONS").
bool uniforms_past_limit(const std::string& message) {
  return (message.rfind("Too many fragment shader ", 0) == 0 && message.find(" uniform ") != std::string::npos) ||
         message.rfind("count of uniform locations > MAX_UNIFORM_LOCATIONS", 0) == 0;
}

// The function Mesa's link error names ("unresolved reference to function
// `f'" gives f), or "" for any other message.
std::string unresolved_function(const std::string& message) {
  const std::string_view prefix = "unresolved reference to function `";
  if (message.rfind(prefix, 0) != 0 || message.back() != '\'') return "";
  return message.substr(prefix.size(), message.size() - prefix.size() - 1);
}

// The entry points the host's main() calls, as it calls them.
constexpr std::pair<const char*, const char*> kEntryPoints[] = {
    {"mainImage", "(out vec4, in vec2)"},
    {"mainCubemap", "(out vec4, in vec2, in vec3, in vec3)"},
};

// Where the scene's code makes the host's line `final_line` fail: the scene's
// entry point where the host's call finds no match for it, or the scene's
// last #define before that line of a word the line uses. The final text's
// line and column, and what to say there; nullopt when neither is found.
struct HostLineCause {
  int final_line = 0, column = 0;
  std::string message;
};
std::optional<HostLineCause> host_line_cause(const Source& source, std::string_view code, int final_line,
                                             const std::string& message) {
  for (const auto& [name, parameters] : kEntryPoints)
    if (message == "'" + std::string(name) + "' : no matching overloaded function found")
      if (const auto at = first_mention(name, code, true); at && !source.locate(at->first).first.empty())
        return HostLineCause{at->first, at->second,
                             "'" + std::string(name) + "' : the host calls " + name + parameters +
                                 ", and no " + name + " takes those parameters"};
  const std::string host_line = source.final_line_text(final_line);
  std::optional<HostLineCause> cause;
  lexing::for_each_line(code, [&](std::string_view line, int number) {
    if (number >= final_line) return false;
    const std::optional<std::string_view> name = lexing::defined_macro(line);
    if (!name || !lexing::has_word(host_line, *name) || source.locate(number).first.empty()) return true;
    cause = HostLineCause{number, static_cast<int>(name->data() - line.data()) + 1,
                          "the scene's #define " + std::string(*name) +
                              " changes the code the host adds around the scene: " + message};
    return true;
  });
  return cause;
}

// For a constructor's error on a line with no constructor of its own:
// glslang names the line where the call ends. The final text's line and
// column of the one scalar, vector or matrix constructor whose call, begun
// on a line above, closes on this one; nullopt where none or several do.
std::optional<std::pair<int, int>> constructor_closed_on(std::string_view code, int final_line) {
  size_t line_start = 0;
  for (int number = 1; number < final_line; ++number) {
    const size_t newline = code.find('\n', line_start);
    if (newline == std::string_view::npos) return std::nullopt;
    line_start = newline + 1;
  }
  const size_t line_end = std::min(code.find('\n', line_start), code.size());
  std::optional<std::pair<int, int>> found;
  int depth = 0, constructors = 0, closers = 0;
  constexpr int kMostClosers = 8;  // each is a walk back: a line of thousands would be slow
  for (size_t at = line_start; at < line_end; ++at) {
    if (code[at] == '(') ++depth;
    if (code[at] != ')' || depth-- > 0) continue;
    depth = 0;
    if (++closers > kMostClosers) return std::nullopt;
    // A ')' whose '(' is on a line above: back to that '(', a few lines at most.
    constexpr size_t kMostBytesBack = 1 << 14;
    int nesting = 0, lines_up = 0;
    size_t open = line_start;
    while (open-- > 0 && line_start - open < kMostBytesBack) {
      if (code[open] == '\n') ++lines_up;
      else if (code[open] == ')') ++nesting;
      else if (code[open] == '(' && nesting-- == 0) break;
    }
    if (open == std::string_view::npos || line_start - open >= kMostBytesBack) continue;
    size_t word_end = open;
    while (word_end > 0 && lexing::is_blank(code[word_end - 1])) --word_end;
    size_t word_start = word_end;
    while (word_start > 0 && lexing::is_word_char(code[word_start - 1])) --word_start;
    if (!lexing::components_of(code.substr(word_start, word_end - word_start))) continue;
    const size_t its_line = code.rfind('\n', word_start);
    found = {final_line - lines_up, static_cast<int>(word_start - (its_line == std::string_view::npos ? 0 : its_line + 1)) + 1};
    if (++constructors > 1) return std::nullopt;
  }
  return found;
}

// For an error that quotes `message`'s name on a line that does not spell
// it: the one macro the line calls whose expansion does, directly or
// through the macros it calls (the last #define of each before the line).
// Its column on the line, and what to add to the message: which macro, and
// where it is defined, as a C compiler's "in expansion of macro" note says.
struct MacroExpansion {
  int column = 0;
  std::string note;
};
std::optional<MacroExpansion> macro_spelling(const Source& source, std::string_view code, int final_line,
                                             const std::string& message) {
  const size_t close = message[0] == '\'' ? message.find('\'', 1) : std::string::npos;
  if (close == std::string::npos || !lexing::is_name(std::string_view(message).substr(1, close - 1))) return std::nullopt;
  const std::string_view token = std::string_view(message).substr(1, close - 1);
  struct Define {
    int final_line = 0, column = 0;
    std::string body;  // its parameters and replacement, continued lines and all
  };
  std::map<std::string, Define, std::less<>> defines;
  std::string_view line_text;  // at the walk's end, the error's line
  Define* continued = nullptr;
  lexing::for_each_line(code, [&](std::string_view line, int number) {
    line_text = line;
    if (number >= final_line) return false;
    if (continued) {
      continued->body += " ";
      continued->body += line;
    } else if (const auto name = lexing::defined_macro(line)) {
      const size_t at = static_cast<size_t>(name->data() - line.data());
      continued = &(defines[std::string(*name)] = {number, static_cast<int>(at) + 1, std::string(line.substr(at + name->size()))});
    }
    if (continued && (continued->body.empty() || continued->body.back() != '\\')) continued = nullptr;
    return true;
  });
  // The macros whose expansion spells the token: those whose body does,
  // then, back along the uses, those whose body names one of them. Each
  // body is read once: macros that name others many times over, many
  // levels deep, would otherwise be walked once per path.
  std::map<std::string_view, std::vector<std::string_view>, std::less<>> named_by;  // a macro -> those naming it
  std::map<std::string_view, std::vector<std::string_view>, std::less<>> names;     // a macro -> those it names
  std::vector<std::string_view> spelling;
  for (const auto& entry : defines) {
    const std::string& name = entry.first;  // named, not bound: clang 14 captures no structured binding
    const std::string& body = entry.second.body;
    lexing::any_word(body, [&](size_t begin, size_t end) {
      const std::string_view word = std::string_view(body).substr(begin, end - begin);
      if (word == token) spelling.push_back(name);
      else if (const auto named = defines.find(word); word != name && named != defines.end())
        named_by[named->first].push_back(name), names[name].push_back(named->first);
      return false;
    });
  }
  const std::set<std::string_view, std::less<>> spells_itself(spelling.begin(), spelling.end());
  std::set<std::string_view, std::less<>> spells(spelling.begin(), spelling.end());
  while (!spelling.empty()) {
    const std::string_view name = spelling.back();
    spelling.pop_back();
    if (const auto users = named_by.find(name); users != named_by.end())
      for (const std::string_view user : users->second)
        if (spells.insert(user).second) spelling.push_back(user);
  }
  std::optional<std::pair<size_t, std::string_view>> cause;  // the call's place and the macro
  int causes = 0;
  lexing::any_word(line_text, [&](size_t begin, size_t end) {
    const std::string_view word = line_text.substr(begin, end - begin);
    if (spells.count(word) && (!cause || cause->second != word)) cause = {begin, word}, ++causes;
    return causes > 1;
  });
  if (causes != 1) return std::nullopt;
  // Where a macro is defined, as the note says it; "" for the host's own.
  auto defined_at = [&](std::string_view name) {
    const Define& define = defines.find(name)->second;
    const auto [path, line] = source.locate(define.final_line);
    return path.empty() ? path : path + ":" + std::to_string(line) + ":" + std::to_string(define.column);
  };
  const std::string called_at = defined_at(cause->second);
  if (called_at.empty()) return std::nullopt;  // the host's own macros are not the user's to read
  std::string note = " (in expansion of macro '" + std::string(cause->second) + "', defined at " + called_at;
  // The macro that spells the token itself, where the called one does not,
  // nearest along the macros it calls: the place to fix, which gcc names in
  // a note for each level. Here the levels between are counted.
  std::map<std::string_view, std::string_view> came_from;
  std::deque<std::string_view> queue{cause->second};
  std::string_view speller;
  while (!queue.empty() && speller.empty()) {
    const std::string_view name = queue.front();
    queue.pop_front();
    if (spells_itself.count(name)) speller = name;
    else if (const auto called = names.find(name); called != names.end())
      for (const std::string_view next : called->second)
        if (spells.count(next) && next != cause->second && came_from.emplace(next, name).second) queue.push_back(next);
  }
  int between = 0;
  for (std::string_view at = speller; !at.empty() && at != cause->second; at = came_from[at]) ++between;
  if (const std::string spelled_at = between > 0 ? defined_at(speller) : ""; !spelled_at.empty()) {
    note += between == 1 ? ", through macro '"
                         : ", through " + std::to_string(between - 1) + (between == 2 ? " more macro" : " more macros") + " to '";
    note += std::string(speller) + "', defined at " + spelled_at;
  }
  return MacroExpansion{static_cast<int>(cause->first) + 1, note + ")"};
}

// An include not found in an #if branch that the compiler took: the
// preprocessor left an #error of kMissingIncludeMark in its place.
std::optional<Diagnostic> missing_include(const Source& source, std::string_view message) {
  // glslang's wording, then Mesa's (where the driver takes a branch that
  // glslang did not: a macro only Mesa defines, such as GL_MESA_shader_integer_functions).
  std::string_view index_text;
  for (const std::string_view said : {"'#error' : ", "#error "})
    if (message.starts_with(said) && message.substr(said.size()).starts_with(kMissingIncludeMark))
      index_text = message.substr(said.size() + std::string_view(kMissingIncludeMark).size());
  if (index_text.empty()) return std::nullopt;
  size_t index = 0;
  for (char c : index_text) {
    if (!lexing::is_digit(c) || index >= source.missing_includes.size()) return std::nullopt;
    index = index * 10 + static_cast<size_t>(c - '0');
  }
  if (index >= source.missing_includes.size()) return std::nullopt;
  return source.missing_includes[index];
}

// `code` is the final text without its comments, for an error in the host's lines.
Diagnostic locate(const Source& source, std::string_view code, Severity severity, int final_line, int column,
                  std::string message) {
  if (auto missing = missing_include(source, message)) return *missing;
  Diagnostic d;
  d.severity = severity;
  auto [path, line] = source.locate(final_line);
  if (path.empty()) {
    // A line the host added (wrapper or prelude): the cause is in the scene.
    if (const auto cause = host_line_cause(source, code, final_line, message)) {
      auto [cause_path, cause_line] = source.locate(cause->final_line);
      d.path = cause_path;
      d.line = cause_line;
      d.column = cause->column;
      d.message = cause->message;
      return d;
    }
    d.path = source.scene_path();
    d.message = "in the code the host adds around the scene: " + message;
  } else {
    d.path = path;
    d.line = line;
    d.column = column;
    d.message = std::move(message);
  }
  return d;
}

// Why glslang may have run out of time or memory. All of shaderlib is under
// 100 KiB, so a shader of megabytes is the likely cause itself (one of 4 MiB
// needs over 512 MiB), and naming its size says so. A small one grew in
// the preprocessor.
std::string likely_cause(const Source& source) {
  constexpr size_t kLargeShaderBytes = size_t{1} << 20;
  if (source.text.size() < kLargeShaderBytes) return "(a macro that expands without end?)";
  char size[32];
  std::snprintf(size, sizeof size, "%.1f", static_cast<double>(source.text.size()) / (1 << 20));
  return "of " + std::string(size) + " MiB in " + std::to_string(source.line_map.size()) +
         " lines (more code than one shader can hold?)";
}

// What went wrong when glslang gave no verdict, said at the scene's file.
Diagnostic no_verdict(const Source& source, const GlslangReply& reply) {
  Diagnostic d;
  d.path = source.scene_path();
  switch (reply.status) {
    case GlslangReply::Status::TimedOut:
      d.message = "glslang took more than " + std::to_string(static_cast<int>(kValidationSeconds)) +
                  " s on this shader " + likely_cause(source);
      break;
    case GlslangReply::Status::OutOfMemory:
      d.message = "glslang needed more than " + std::to_string(kValidationBytes >> 20) +
                  " MiB for this shader " + likely_cause(source);
      break;
    case GlslangReply::Status::NoWorker:
      d.message = "cannot check this shader: " + reply.output;
      d.unchecked = true;
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
  const int chain = verdict.take(" ") ? verdict.number().value_or(0) : 0;
  const int chain_line = verdict.take(" ") ? verdict.number().value_or(0) : 0;
  Diagnostics out = map_log(newline == std::string::npos ? "" : child.output.substr(newline + 1), source,
                            LogFormat::Glslang);
  // The GL driver recurses over the same tree on the thread that draws, and
  // Mesa overflows 8 MiB near 15,000 levels: what it may not take is refused.
  if (depth > kMaxTreeDepth)
    out.push_back(locate(source, lexing::strip_comments(source.text), Severity::Error, deepest_line, 0,
                         "an expression nested " + std::to_string(depth) + " levels deep; at most " +
                             std::to_string(kMaxTreeDepth) + " are allowed (the GL driver's compiler recurses on each)"));
  // The driver builds such a tree itself from single-use variables and
  // inlined calls.
  else if (chain > kMaxChainDepth)
    out.push_back(locate(source, lexing::strip_comments(source.text), Severity::Error, chain_line, 0,
                         "a value computed " + std::to_string(chain) +
                             " operations deep, through variables and calls; at most " + std::to_string(kMaxChainDepth) +
                             " are allowed (the GL driver inlines the calls, puts each expression in place of "
                             "its variable, and recurses on the tree)"));
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
  request.version_line = source.version_line;
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

std::optional<std::string> active_code(const std::string& text, const std::string& version_line) {
  GlslangRequest request;
  request.kind = GlslangRequest::Kind::Preprocess;
  request.version_line = version_line;
  request.text = text;
  const GlslangReply child = ask_glslang(request);
  if (child.status != GlslangReply::Status::Ok || child.output.empty() || child.output[0] != '+') return std::nullopt;
  return child.output.substr(1);
}

namespace {

// Whether glslang's error `d`, at a line of the final text that the host
// added (`in_host_code`) or not, follows from the error before it, `last`.
// glslang names every error it finds (glslang_worker), in the order of the
// text, and some are an earlier one's echo: the host's code fails once for
// whatever broke it, and on a line that failed already, a later error is
// most often the first one's (no such field, then a failed assignment; an
// undeclared sampler, then no texture() that takes it). A second undeclared
// name on that line is news of its own.
bool follows_earlier_error(const Diagnostic& last, const Diagnostic& d, bool in_host_code,
                           bool earlier_in_host_code) {
  if (in_host_code) return earlier_in_host_code;
  if (d.message.ends_with(" : undeclared identifier")) return false;
  return last.line == d.line && last.path == d.path;
}

}  // namespace

Diagnostics map_log(const std::string& log, const Source& source, LogFormat format) {
  Diagnostics out;
  bool said_uniforms_past_limit = false;
  // glslang read on past a cause the host found (a '{' or a declaration left
  // open, then misread everything after it), or failed in the host's code.
  bool said_left_open = false, said_host_code_error = false;
  std::optional<size_t> last_error;  // in out
  constexpr int kMostErrorsNamed = 20;
  int errors_named = 0;
  // glslang ends its input at an error when it runs as it does by default:
  // what follows ("compilation terminated", a missing #endif) is its echo.
  const bool stopped_at_error = log.find(": '' : compilation terminated") != std::string::npos;
  // The final text without its comments, which the searches for an error's
  // cause read: made once, at the first line of the log.
  const std::string code = log.empty() ? std::string() : lexing::strip_comments(source.text);
  std::istringstream in(log);
  std::string text;
  while (std::getline(in, text)) {
    while (!text.empty() && (text.back() == ' ' || text.back() == '\r')) text.pop_back();
    if (text.empty()) continue;
    text = with_names_restored(text, source.renamed);
    if (format == LogFormat::Glslang) {
      // "ERROR: 0:12: 'foo' : undeclared identifier", then "ERROR: 1 compilation errors. ..."
      LogLine line(text);
      const auto severity = line.severity("ERROR: ", "WARNING: ");
      if (severity && line.number()) {
        if (line.take(" compilation error")) continue;  // the summary
        const auto final_line = line.take(":") ? line.number() : std::nullopt;
        // "0:12:7: ": the worker gives the column of an unexpected token.
        std::optional<int> given_column;
        bool located = final_line && line.take(": ");
        if (final_line && !located && line.take(":")) {
          given_column = line.number();
          located = given_column && line.take(": ");
        }
        if (located) {
          const std::string message = line.rest();
          if (message == "'' : compilation terminated") continue;  // follows a real error
          // glslang stops reading a required extension it lacks at its name,
          // then calls the rest of the line extra: one error is the news.
          if (message == "'#extension' : extra tokens -- expected newline" && !out.empty() &&
              out.back().message.rfind("'#extension' : ", 0) == 0 &&
              out.back().line == source.locate(*final_line).second)
            continue;
          // glslang run by default stops at its first error, inside a
          // conditional if it was in one (or after #if nesting ran over):
          // then of course an #endif is missing.
          const bool missing_endif = message == "'' : missing #endif";
          const bool after_error = last_error.has_value();
          if (missing_endif && after_error && stopped_at_error) continue;
          if (said_left_open) continue;
          // What a file of the user's left open at its end (an #if, a '{',
          // a declaration) is named where it was, not where glslang noticed.
          const int col = given_column ? *given_column : column_in_line(message, source.final_line_text(*final_line));
          std::optional<LeftOpen> left_open;
          if (missing_endif) {
            left_open = conditional_left_open(code);
          } else if (*severity == Severity::Error) {
            // An earlier error may have misled the brace count; a syntax
            // error is the last glslang's parser names.
            if (!after_error) left_open = brace_left_open_before(source, code, *final_line);
            if (!left_open) left_open = declaration_left_open_before(source, code, *final_line, col, message);
          }
          if (left_open) {
            out.push_back(
                locate(source, code, *severity, left_open->final_line, left_open->column, plain_words(left_open->message)));
            said_left_open = true;
            last_error = out.size() - 1;
            continue;
          }
          std::string said = plain_words(message);
          int place_line = *final_line, place = col;
          if (col == 0) {
            if (const auto expansion = macro_spelling(source, code, *final_line, said)) {
              place = expansion->column;
              said += expansion->note;
            } else if (message.starts_with("'constructor' :")) {
              if (const auto call = constructor_closed_on(code, *final_line)) std::tie(place_line, place) = *call;
            }
          }
          Diagnostic d = locate(source, code, *severity, place_line, place, std::move(said));
          const bool in_host_code = source.locate(*final_line).first.empty();
          if (*severity == Severity::Error) {
            if (after_error && follows_earlier_error(out[*last_error], d, in_host_code, said_host_code_error)) continue;
            // As clang does: past a screenful, the first error would scroll
            // out of sight, and it is the one to fix first.
            if (++errors_named > kMostErrorsNamed) {
              out.push_back({Severity::Error, source.scene_path(), 0, 0,
                             "too many errors; only the first " + std::to_string(kMostErrorsNamed) + " are named"});
              break;
            }
            said_host_code_error = said_host_code_error || in_host_code;
            last_error = out.size();
          }
          out.push_back(std::move(d));
          continue;
        }
      }
    } else {
      // "0:12(5): error: syntax error, unexpected ';'"
      LogLine line(text);
      const bool located = line.number() && line.take(":");
      const auto final_line = located ? line.number() : std::nullopt;
      const auto column = final_line && line.take("(") ? line.number() : std::nullopt;
      // Its preprocessor says "preprocessor error: " (an #error, an
      // #include it does not know).
      const bool after_place = column && line.take("): ");
      if (after_place) line.take("preprocessor ");
      const auto severity = after_place ? line.severity("error: ", "warning: ") : std::nullopt;
      if (severity) {
        out.push_back(locate(source, code, *severity, *final_line, *column, line.rest()));
        continue;
      }
    }
    // Anything else (link errors, unknown formats) is kept, attributed to the scene.
    // Mesa's link errors carry no line: "error: unresolved reference to function `f'".
    Diagnostic d;
    d.path = source.scene_path();
    LogLine line(text);
    if (const auto severity = line.severity("error: ", "warning: ")) d.severity = *severity;
    d.message = line.rest();
    if (const auto at = first_mention(unresolved_function(d.message), code, true)) {
      const Severity severity = d.severity;
      std::string message = std::move(d.message);
      d = locate(source, code, severity, at->first, at->second, std::move(message));
    } else if (uniforms_past_limit(d.message)) {
      // Mesa says so in up to three ways, one glued to the next: one error is the news.
      if (said_uniforms_past_limit) continue;
      said_uniforms_past_limit = true;
      const std::string reason = d.message.substr(0, d.message.find("error: "));
      if (const auto largest = largest_uniform(source, code))
        d = locate(source, code, d.severity, largest->line, largest->column,
                   "'" + largest->name + "' : its " + std::to_string(largest->components) +
                       " components take the fragment shader's uniforms past what the driver allows (" + reason + ")");
    } else if (const std::string input = unfed_input(d.message); !input.empty()) {
      // The host's vertex shader passes nothing on; its declaration is the place.
      const Severity severity = d.severity;
      const std::string message =
          "'" + input + "' is an input from a vertex shader, and the host's passes on nothing " +
          (input == "v_texcoord" ? "(it supplies glslViewer's v_texcoord declared on a line of its own: "
                                   "`varying vec2 v_texcoord;`)"
                                 : "(glslViewer's v_texcoord is the one input it supplies)");
      if (const auto at = first_mention(input, code, false)) d = locate(source, code, severity, at->first, at->second, message);
      else d.message = message;
    }
    out.push_back(std::move(d));
  }
  return out;
}

}  // namespace rm
