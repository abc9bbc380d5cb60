#include "core/check.h"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include <mutex>
#include <regex>
#include <sstream>

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

// glslang names no column. Where its message quotes a token, or names the
// unexpected one, find that token on the line.
int column_in_line(const std::string& message, const std::string& line_text) {
  static const std::regex quoted(R"('([^']+)')");
  static const std::regex unexpected(R"(unexpected ([A-Z_]+))");
  std::smatch m;
  std::string needle;
  const char* spelling = std::regex_search(message, m, unexpected) ? token_spelling(m[1].str()) : nullptr;
  if (spelling) needle = spelling;
  else if (std::regex_search(message, m, quoted)) needle = m[1].str();
  if (needle.empty()) return 0;
  size_t at = line_text.find(needle);
  return at == std::string::npos ? 0 : static_cast<int>(at) + 1;
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

}  // namespace

Diagnostics validate(const Source& source) {
  ensure_glslang_initialized();
  glslang::TShader shader(EShLangFragment);
  const char* text = source.text.c_str();
  const int length = static_cast<int>(source.text.size());
  shader.setStringsWithLengths(&text, &length, 1);
  // No client API is set: plain GLSL semantics, as the GL driver applies them.
  shader.parse(GetDefaultResources(), 100, false, EShMsgDefault);
  return map_log(shader.getInfoLog(), source, LogFormat::Glslang);
}

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
  return out;
}

Diagnostics map_log(const std::string& log, const Source& source, LogFormat format) {
  // glslang: "ERROR: 0:12: 'foo' : undeclared identifier"
  static const std::regex glslang_re(R"(^(ERROR|WARNING): \d+:(\d+): (.*)$)");
  static const std::regex glslang_summary_re(R"(^(ERROR|WARNING): \d+ compilation errors?.*)");
  // Mesa: "0:12(5): error: syntax error, unexpected ';'"
  static const std::regex mesa_re(R"(^\d+:(\d+)\((\d+)\): (error|warning): (.*)$)");
  // Mesa link errors carry no line: "error: unresolved reference to function `f'"
  static const std::regex bare_re(R"(^(error|warning): (.*)$)");

  Diagnostics out;
  std::istringstream in(log);
  std::string line;
  while (std::getline(in, line)) {
    while (!line.empty() && (line.back() == ' ' || line.back() == '\r')) line.pop_back();
    if (line.empty()) continue;
    std::smatch m;
    if (format == LogFormat::Glslang) {
      if (std::regex_match(line, glslang_summary_re)) continue;
      if (line.find("'' : compilation terminated") != std::string::npos) continue;  // follows a real error
      if (std::regex_match(line, m, glslang_re)) {
        int final_line = std::stoi(m[2].str());
        std::string message = m[3].str();
        Severity sev = m[1] == "ERROR" ? Severity::Error : Severity::Warning;
        int col = column_in_line(message, source.final_line_text(final_line));
        out.push_back(locate(source, sev, final_line, col, std::move(message)));
        continue;
      }
    } else if (std::regex_match(line, m, mesa_re)) {
      Severity sev = m[3] == "error" ? Severity::Error : Severity::Warning;
      out.push_back(locate(source, sev, std::stoi(m[1].str()), std::stoi(m[2].str()), m[4].str()));
      continue;
    }
    // Anything else (link errors, unknown formats) is kept, attributed to the scene.
    Diagnostic d;
    d.path = source.files.empty() ? std::string() : source.files.front().string();
    if (std::regex_match(line, m, bare_re)) {
      d.severity = m[1] == "error" ? Severity::Error : Severity::Warning;
      d.message = m[2].str();
    } else {
      d.message = line;
    }
    out.push_back(std::move(d));
  }
  return out;
}

}  // namespace rm
