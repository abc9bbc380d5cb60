#include "core/check.h"

#include <glslang/Include/intermediate.h>
#include <glslang/MachineIndependent/localintermediate.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <pthread.h>

#include <algorithm>
#include <cstring>
#include <functional>
#include <map>
#include <mutex>
#include <set>
#include <sstream>
#include <string_view>

#include "core/lexing.h"
#include "core/sandbox.h"

namespace rm {

namespace {

void ensure_glslang_initialized() {
  static std::once_flag once;
  std::call_once(once, [] { glslang::InitializeProcess(); });
}

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
    while (end < message.size() && ((message[end] >= 'A' && message[end] <= 'Z') || message[end] == '_')) ++end;
    if (const char* spelling = token_spelling(message.substr(unexpected + 11, end - unexpected - 11))) needle = spelling;
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

// Runs `work` on a thread with a stack of `bytes`, and waits for it. Only the
// pages the work touches are ever backed by memory.
void run_with_stack(size_t bytes, const std::function<void()>& work) {
  pthread_attr_t attr;
  pthread_attr_init(&attr);
  pthread_t thread;
  auto call = [](void* w) -> void* {
    (*static_cast<const std::function<void()>*>(w))();
    return nullptr;
  };
  const bool started = pthread_attr_setstacksize(&attr, bytes) == 0 &&
                       pthread_create(&thread, &attr, call, const_cast<std::function<void()>*>(&work)) == 0;
  pthread_attr_destroy(&attr);
  if (!started) {
    work();  // no such stack to be had: run here, with the stack there is
    return;
  }
  pthread_join(thread, nullptr);
}

// The deepest nesting of the program's tree (one level per operator in a
// chain like x+x+x, per call, per parenthesis) and the final source line
// where it is reached. (This file builds without RTTI, as Debian's glslang
// does, so that it may derive from glslang's traverser.)
class DeepestNode : public glslang::TIntermTraverser {
 public:
  int line = 0;
  bool visitBinary(glslang::TVisit, glslang::TIntermBinary* node) override { return note(node); }
  bool visitUnary(glslang::TVisit, glslang::TIntermUnary* node) override { return note(node); }
  bool visitAggregate(glslang::TVisit, glslang::TIntermAggregate* node) override { return note(node); }
  bool visitSelection(glslang::TVisit, glslang::TIntermSelection* node) override { return note(node); }
  bool visitLoop(glslang::TVisit, glslang::TIntermLoop* node) override { return note(node); }

 private:
  bool note(TIntermNode* node) {
    // Called before the node's own level is counted: depth + 1 is its level.
    if (depth + 1 > maxDepth) line = node->getLoc().line;
    return true;
  }
};

// The calls to functions that no body defines, each with the final source
// line of its first call. The driver's linker refuses any such call, reached
// or not. glslang's own link finds them too, but its call-graph checks grow
// with the square of the calls (a chain of 20,000 functions took 81 s); this
// is one walk over the tree.
class CallsWithoutBody : public glslang::TIntermTraverser {
 public:
  bool visitAggregate(glslang::TVisit, glslang::TIntermAggregate* node) override {
    if (node->getOp() == glslang::EOpFunction) {
      defined_.insert(node->getName().c_str());
    } else if (node->getOp() == glslang::EOpFunctionCall && node->isUserDefined()) {
      const int line = node->getLoc().line;
      auto [at, added] = first_call_.emplace(node->getName().c_str(), line);
      if (!added) at->second = std::min(at->second, line);
    }
    return true;
  }
  // glslang's log lines for them, in the order of their lines.
  std::string log() const {
    std::vector<std::pair<int, std::string>> missing;
    for (const auto& [mangled, line] : first_call_)
      if (!defined_.count(mangled)) missing.emplace_back(line, mangled.substr(0, mangled.find('(')));
    std::sort(missing.begin(), missing.end());
    std::string out;
    for (const auto& [line, name] : missing)
      out += "ERROR: 0:" + std::to_string(line) + ": '" + name + "' : function is called but no body defines it\n";
    return out;
  }

 private:
  std::set<std::string> defined_;               // mangled names: "f(vf3;"
  std::map<std::string, int> first_call_;
};

// glslang's verdict as the sandbox sends it: "DEPTH LINE\n" (the tree's
// deepest level and its final source line, 0 0 when it did not parse), then
// the info log.
// glslang's preprocessor over `text`, or nullopt if it fails. Call on a big stack.
std::optional<std::string> preprocessed(const std::string& text) {
  glslang::TShader shader(EShLangFragment);
  const char* chars = text.c_str();
  const int length = static_cast<int>(text.size());
  shader.setStringsWithLengths(&chars, &length, 1);
  glslang::TShader::ForbidIncluder includer;
  std::string expanded;
  if (!shader.preprocess(GetDefaultResources(), 100, ENoProfile, false, false, EShMsgDefault, &expanded, includer))
    return std::nullopt;
  return expanded;
}

// The verdict line ("DEPTH LINE"), then glslang's log; with `active_text`,
// then a NUL and its preprocessed text (a NUL never comes out of the log).
std::string parse_in_child(const Source& source, const std::string* active_text) {
  std::string verdict;
  // glslang's traversals recurse once per level of the tree, and a 30,000-term
  // sum (60 KB of text) overflows an 8 MiB stack.
  run_with_stack(kValidationStack, [&] {
    glslang::TShader shader(EShLangFragment);
    const char* text = source.text.c_str();
    const int length = static_cast<int>(source.text.size());
    shader.setStringsWithLengths(&text, &length, 1);
    // No client API is set: plain GLSL semantics, as the GL driver applies them.
    const bool parsed = shader.parse(GetDefaultResources(), 100, false, EShMsgDefault);
    glslang::TIntermediate* tree = parsed ? shader.getIntermediate() : nullptr;
    DeepestNode deepest;
    CallsWithoutBody calls;
    if (tree && tree->getTreeRoot()) {
      tree->getTreeRoot()->traverse(&deepest);
      tree->getTreeRoot()->traverse(&calls);
    }
    verdict = std::to_string(deepest.getMaxDepth()) + " " + std::to_string(deepest.line) + "\n" + shader.getInfoLog() +
              calls.log();
    if (active_text) verdict += '\0' + preprocessed(*active_text).value_or("");
  });
  return verdict;
}

// glslang builds the built-in symbols of each #version once per process, in
// about 80 ms, and keeps them. A sandboxed child would build them again every
// time and throw them away, so the parent builds them first, from a shader
// that holds nothing of the user's but the #version line preprocess() checked.
void build_builtins_for(const std::string& version_line) {
  static std::mutex mutex;
  static std::set<std::string> built;
  std::lock_guard<std::mutex> lock(mutex);
  if (!built.insert(version_line).second) return;
  glslang::TShader shader(EShLangFragment);
  const std::string text = version_line + "\nvoid main() {}\n";
  const char* chars = text.c_str();
  shader.setStrings(&chars, 1);
  shader.parse(GetDefaultResources(), 100, false, EShMsgDefault);
}

}  // namespace

Diagnostics validate(const Source& source, std::string* active, const std::string& appended) {
  ensure_glslang_initialized();
  build_builtins_for(source.version_line);
  SandboxLimits limits;
  limits.seconds = kValidationSeconds;
  limits.bytes = kValidationBytes;
  const std::string active_text = active ? source.text + "\n" + appended : std::string();
  SandboxResult child = run_sandboxed([&] { return parse_in_child(source, active ? &active_text : nullptr); }, limits);
  if (active) {
    active->clear();
    const size_t nul = child.output.find('\0');
    if (child.status == SandboxResult::Status::Ok && nul != std::string::npos) {
      *active = child.output.substr(nul + 1);
      child.output.resize(nul);
    }
  }
  if (child.status != SandboxResult::Status::Ok) {
    Diagnostic d;
    d.path = source.files.empty() ? std::string() : source.files.front().string();
    switch (child.status) {
      case SandboxResult::Status::TimedOut:
        d.message = "glslang took more than " + std::to_string(static_cast<int>(kValidationSeconds)) +
                    " s on this shader (a macro that expands without end?)";
        break;
      case SandboxResult::Status::OutOfMemory:
        d.message = "glslang needed more than " + std::to_string(kValidationBytes >> 20) +
                    " MiB for this shader (a macro that expands without end?)";
        break;
      default:
        d.message = std::string("glslang crashed on this shader (") +
                    (child.signal ? strsignal(child.signal) : "it exited with an error") + ")";
    }
    return {d};
  }
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
std::string with_line_markers(const std::string& expanded, const Source& source) {
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
    if (i == 0) {  // #version stays first
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

std::optional<std::string> expand_preprocessor(const Source& source, Diagnostics* diags) {
  ensure_glslang_initialized();
  glslang::TShader shader(EShLangFragment);
  const char* text = source.text.c_str();
  const int length = static_cast<int>(source.text.size());
  shader.setStringsWithLengths(&text, &length, 1);
  glslang::TShader::ForbidIncluder includer;  // includes are already expanded
  std::string out;
  if (!shader.preprocess(GetDefaultResources(), 100, ENoProfile, false, false, EShMsgDefault, &out, includer)) {
    *diags = map_log(shader.getInfoLog(), source, LogFormat::Glslang);
    return std::nullopt;
  }
  return with_line_markers(out, source);
}

std::optional<std::string> active_code(const std::string& text) {
  ensure_glslang_initialized();
  SandboxLimits limits;
  limits.seconds = kValidationSeconds;
  limits.bytes = kValidationBytes;
  const SandboxResult child = run_sandboxed(
      [&] {
        std::string out;
        run_with_stack(kValidationStack, [&] {
          if (auto expanded = preprocessed(text)) out = "+" + *expanded;
        });
        return out;
      },
      limits);
  if (child.status != SandboxResult::Status::Ok || child.output.empty()) return std::nullopt;
  return child.output.substr(1);
}

Diagnostics map_log(const std::string& log, const Source& source, LogFormat format) {
  Diagnostics out;
  bool nesting_exceeded = false;
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
          // At the end of the file, after #if nesting ran over, of course an #endif is missing.
          if (nesting_exceeded && message == "'' : missing #endif") continue;
          nesting_exceeded |= message.find("maximum nesting depth exceeded") != std::string::npos;
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
