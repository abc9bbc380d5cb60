#include "glslang_worker/glslang_work.h"

#include <glslang/MachineIndependent/localintermediate.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/deep_stack.h"
#include "core/lexing.h"
#include "glslang_worker/sandbox.h"
#include "glslang_worker/tree_checks.h"

namespace rm {

namespace {

// glslang's preprocessor over `text` in `shader`, or nullopt if it fails
// (its log says why). Call on a big stack.
std::optional<std::string> preprocessed(const std::string& text, glslang::TShader* shader) {
  const char* chars = text.c_str();
  const int length = static_cast<int>(text.size());
  shader->setStringsWithLengths(&chars, &length, 1);
  glslang::TShader::ForbidIncluder includer;  // includes are already expanded
  std::string expanded;
  if (!shader->preprocess(GetDefaultResources(), 100, ENoProfile, false, false, EShMsgDefault, &expanded, includer))
    return std::nullopt;
  return expanded;
}

// How glslang goes on after an error. By default it ends its input there
// ("compilation terminated"), so a shader with three mistakes took three
// saves to show them all. Cascading, it reads on and names each, as a
// compiler does (a syntax error still stops its parser). glslang warns
// that its recovery may then crash: the parse runs in a sandboxed child,
// and one that crashes is run again by default.
enum class AfterError { GoOn, Stop };

// Going on past an error, glslang parses the rest and keeps every error:
// 10 MB of statements after an error ran out of the child's 512 MiB, where
// stopping named the error in under a second. Past this size of text (1 MiB
// of 128,000 undeclared names took 0.5 s) glslang stops at the first error.
constexpr std::size_t kGoOnBytes = std::size_t{1} << 20;

// glslang's parser and semantic checks over `text`, as every validation
// runs them: no client API is set, so plain GLSL semantics, as the GL
// driver applies them. Call on a big stack.
bool parse(const std::string& text, glslang::TShader* shader, AfterError after_error) {
  const char* chars = text.c_str();
  const int length = static_cast<int>(text.size());
  shader->setStringsWithLengths(&chars, &length, 1);
  return shader->parse(GetDefaultResources(), 100, false,
                       after_error == AfterError::GoOn ? EShMsgCascadingErrors : EShMsgDefault);
}

// glslang's log of `text`. Call on a big stack.
std::string parse_log(const std::string& text, AfterError after_error) {
  glslang::TShader shader(EShLangFragment);
  parse(text, &shader, after_error);
  return shader.getInfoLog();
}

// GLSL's operators of more than one character, longest first: a line's
// signs are read as the compiler reads them, the longest that fits.
constexpr std::string_view kLongSigns[] = {"<<=", ">>=", "<<", ">>", "++", "--", "<=", ">=", "==", "!=",
                                           "&&",  "||",  "^^", "*=", "/=", "+=", "%=", "-=", "&=", "^=", "|="};

// The tokens of one line of code (names, keywords, type names, literals and
// signs; not those in a comment), as [begin, end) offsets.
std::vector<std::pair<size_t, size_t>> line_tokens(std::string_view line) {
  using lexing::is_blank, lexing::is_digit, lexing::is_word_char;
  std::vector<std::pair<size_t, size_t>> tokens;
  for (size_t i = 0; i < line.size();) {
    if (line.compare(i, 2, "//") == 0) break;
    if (line.compare(i, 2, "/*") == 0) {
      const size_t close = line.find("*/", i + 2);
      if (close == std::string_view::npos) break;
      i = close + 2;
      continue;
    }
    if (is_blank(line[i])) {
      ++i;
      continue;
    }
    const size_t begin = i;
    const bool number = is_digit(line[i]) || (line[i] == '.' && i + 1 < line.size() && is_digit(line[i + 1]));
    if (number || is_word_char(line[i])) {
      const bool hex = number && (line.compare(i, 2, "0x") == 0 || line.compare(i, 2, "0X") == 0);
      for (++i; i < line.size(); ++i) {
        const char c = line[i];
        const bool exponent_sign =
            number && !hex && (c == '+' || c == '-') && (line[i - 1] == 'e' || line[i - 1] == 'E');
        if (!is_word_char(c) && !(number && c == '.') && !exponent_sign) break;
      }
    } else {
      const auto sign = std::find_if(std::begin(kLongSigns), std::end(kLongSigns),
                                     [&](std::string_view s) { return line.compare(i, s.size(), s) == 0; });
      i += sign == std::end(kLongSigns) ? 1 : sign->size();
    }
    tokens.emplace_back(begin, i);
  }
  return tokens;
}

// glslang names the line of an unexpected token, not which one it is. Its
// parser stops at that token whatever follows, so the text cut just after it
// fails there too, and a text cut before it fails only at its end: a binary
// search over the line's tokens, cutting after each, finds it. Each cut ends
// with a newline: glslang parses a few tokens of its own after the text, and
// they must fail on the next line, not as an unexpected ';' on this one.
// The 1-based column, or 0 if no cut fails the same way, or if the search
// would take over a second at `parse_seconds` a parse (a huge text: the
// line is named all the same). Call on a big stack.
int unexpected_token_column(const std::string& text, int line, const std::string& error, double parse_seconds,
                            AfterError after_error) {
  size_t start = 0;
  for (int n = 1; n < line && start != std::string::npos; ++n) {
    start = text.find('\n', start);
    if (start != std::string::npos) ++start;
  }
  if (start == std::string::npos) return 0;
  const size_t end = text.find('\n', start);
  const auto tokens =
      line_tokens(std::string_view(text).substr(start, end == std::string::npos ? end : end - start));
  if (parse_seconds * std::ceil(std::log2(tokens.size() + 1.0)) > 1.0) return 0;
  auto fails_there = [&](size_t token) {
    return parse_log(text.substr(0, start + tokens[token].second) + "\n", after_error).find(error) !=
           std::string::npos;
  };
  size_t low = 0, high = tokens.size();  // the culprit is the first token whose cut fails there
  while (low < high) {
    const size_t middle = (low + high) / 2;
    if (fails_there(middle)) high = middle;
    else low = middle + 1;
  }
  return low < tokens.size() ? static_cast<int>(tokens[low].first) + 1 : 0;
}

// glslang's log with the column of an unexpected token added ("ERROR:
// 0:12:7: '' :  syntax error, unexpected IDENTIFIER", as glslang places a
// column where it prints one). Without one (the search was too slow), the
// host finds the column by the token's spelling (core/glslang_words.h).
std::string with_unexpected_column(std::string log, const std::string& text, double parse_seconds,
                                   AfterError after_error) {
  static const std::string kUnexpected = ": '' :  syntax error, unexpected ";
  const size_t found = log.find(kUnexpected);
  if (found == std::string::npos) return log;
  const size_t head = log.rfind("ERROR: 0:", found);
  const size_t name = found + kUnexpected.size();
  const size_t name_end = log.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_", name);
  if (head == std::string::npos || name_end == name) return log;  // "unexpected $end": no token to point at
  const size_t number = head + 9;
  if (number >= found || log.find_first_not_of("0123456789", number) != found) return log;
  const int line = std::stoi(log.substr(number, found - number));
  const int column =
      unexpected_token_column(text, line, log.substr(head, name_end - head), parse_seconds, after_error);
  if (column > 0) log.insert(found, ":" + std::to_string(column));
  return log;
}

// The verdict line ("DEPTH LINE CHAIN LINE", from check_tree), then
// glslang's log and check_tree's; with `active_text`, then a NUL and its
// preprocessed text (a NUL never comes out of the log).
std::string parse_in_child(const std::string& source_text, const std::string* active_text, AfterError after_error) {
  std::string verdict;
  // glslang's traversals recurse once per level of the tree, and a 30,000-term
  // sum (60 KB of text) overflows an 8 MiB stack.
  run_with_deep_stack([&] {
    glslang::TShader shader(EShLangFragment);
    const auto start = std::chrono::steady_clock::now();
    const bool parsed = parse(source_text, &shader, after_error);
    const double parse_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    glslang::TIntermediate* tree = parsed ? shader.getIntermediate() : nullptr;
    const TreeVerdict checked = check_tree(tree ? tree->getTreeRoot() : nullptr);
    verdict = std::to_string(checked.depth) + " " + std::to_string(checked.depth_line) + " " +
              std::to_string(checked.chain) + " " + std::to_string(checked.chain_line) + "\n" +
              (parsed ? std::string(shader.getInfoLog())
                      : with_unexpected_column(shader.getInfoLog(), source_text, parse_seconds, after_error)) +
              checked.log;
    if (active_text) {
      glslang::TShader active(EShLangFragment);
      verdict += '\0' + preprocessed(*active_text, &active).value_or("");
    }
  }, kValidationStack);
  return verdict;
}

// glslang builds the built-in symbols of each #version once per process, in
// about 80 ms, and keeps them. A sandboxed child would build them again every
// time and throw them away, so the worker builds them first, from a shader
// that holds nothing of the user's but the #version line preprocess() checked.
void build_builtins_for(const std::string& version_line) {
  static std::set<std::string> built;
  if (version_line.empty() || !built.insert(version_line).second) return;
  // Not on the worker's own stack, which is what `ulimit -s` gave it:
  // glslang's parser overflowed 64 KiB. The built-ins need no deep stack,
  // and under a `ulimit -v` the host's share of the limit leaves them room.
  run_with_deep_stack([&] {
    glslang::TShader shader(EShLangFragment);
    parse(version_line + "\nvoid main() {}\n", &shader, AfterError::Stop);
  });
}

}  // namespace

std::optional<GlslangReply> serve(const GlslangRequest& request, int requester) {
  SandboxLimits limits;
  limits.seconds = kValidationSeconds;
  limits.bytes = kValidationBytes;
  limits.requester = requester;
  SandboxResult child;
  if (request.kind == GlslangRequest::Kind::Validate) {
    build_builtins_for(request.version_line);
    const std::string* active = request.active_text ? &*request.active_text : nullptr;
    const AfterError after_error = request.text.size() <= kGoOnBytes ? AfterError::GoOn : AfterError::Stop;
    child = run_sandboxed([&] { return parse_in_child(request.text, active, after_error); }, limits);
    if (child.status == SandboxResult::Status::Crashed && after_error == AfterError::GoOn)
      child = run_sandboxed([&] { return parse_in_child(request.text, active, AfterError::Stop); }, limits);
  } else {
    build_builtins_for(request.version_line);  // a preprocess builds them too
    child = run_sandboxed(
        [&] {
          std::string out;
          run_with_deep_stack([&] {
            glslang::TShader shader(EShLangFragment);
            if (auto expanded = preprocessed(request.text, &shader)) out = "+" + *expanded;
            else out = "-" + std::string(shader.getInfoLog());
          }, kValidationStack);
          return out;
        },
        limits);
  }
  GlslangReply reply;
  reply.signal = child.signal;
  reply.output = std::move(child.output);
  switch (child.status) {
    case SandboxResult::Status::Ok: reply.status = GlslangReply::Status::Ok; break;
    case SandboxResult::Status::TimedOut: reply.status = GlslangReply::Status::TimedOut; break;
    case SandboxResult::Status::OutOfMemory: reply.status = GlslangReply::Status::OutOfMemory; break;
    case SandboxResult::Status::Crashed: reply.status = GlslangReply::Status::Crashed; break;
    case SandboxResult::Status::Abandoned: return std::nullopt;
  }
  return reply;
}

}  // namespace rm
