#include "core/tweak.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "core/lexing.h"

namespace rm {

namespace {

constexpr char kMark = '\x01';

bool under(const fs::path& file, const fs::path& dir) {
  if (dir.empty()) return false;
  const fs::path rel = file.lexically_normal().lexically_relative(dir.lexically_normal());
  return !rel.empty() && *rel.begin() != "..";
}

// A float literal by its spelling: a '.' or an exponent, not hex, not a double.
bool is_float_literal(std::string_view token) {
  if (token.size() > 1 && token[0] == '0' && (token[1] == 'x' || token[1] == 'X')) return false;
  if (token.size() > 2 && (token.substr(token.size() - 2) == "lf" || token.substr(token.size() - 2) == "LF")) return false;
  return token.find_first_of(".eE") != std::string_view::npos;
}

// The end of the number that starts at `at`: digits, letters (suffixes, hex),
// '.', and a sign right after an exponent's e.
size_t number_end(std::string_view code, size_t at) {
  const bool hex = code.size() > at + 1 && code[at] == '0' && (code[at + 1] == 'x' || code[at + 1] == 'X');
  size_t i = at;
  while (i < code.size()) {
    const char c = code[i];
    if (lexing::is_word_char(c) || c == '.') {
      ++i;
    } else if ((c == '+' || c == '-') && !hex && (code[i - 1] == 'e' || code[i - 1] == 'E')) {
      ++i;
    } else {
      break;
    }
  }
  return i;
}

}  // namespace

LiftedLiterals lift_literals(const Source& source, const fs::path& shaderlib_dir) {
  LiftedLiterals out;
  const std::string code = lexing::strip_comments(source.text);
  if (code.find(kMark) != std::string::npos) {
    out.ok = false;
    return out;
  }
  std::vector<bool> user_file(source.files.size());
  for (size_t f = 0; f < source.files.size(); ++f) user_file[f] = !under(source.files[f], shaderlib_dir);
  auto user_line = [&](size_t line) {
    if (line >= source.line_map.size()) return false;
    const int file = source.line_map[line].file;
    return file >= 0 && static_cast<size_t>(file) < user_file.size() && user_file[static_cast<size_t>(file)];
  };

  out.skeleton.reserve(code.size());
  size_t line = 0;
  bool line_start = true;
  int braces = 0, parens = 0;
  bool in_function = false, in_const = false;
  char last = 0;  // the last character that was not blank
  std::string_view word, callee;  // the last word; the one before a '(' at file scope
  for (size_t i = 0; i < code.size();) {
    const char c = code[i];
    if (c == '\n') {
      out.skeleton += c;
      ++line, ++i;
      line_start = true;
      continue;
    }
    if (line_start) {
      line_start = false;
      const size_t first = lexing::skip_blanks(code, i);
      if (first < code.size() && code[first] == '#') {  // a directive, with its continuation lines
        size_t end = i;
        while (true) {
          end = code.find('\n', end);
          if (end == std::string::npos) {
            end = code.size();
            break;
          }
          if (code[end - 1] != '\\') break;
          ++line, ++end;  // a continuation line
        }
        out.skeleton.append(code, i, end - i);
        i = end;
        continue;
      }
    }
    if (lexing::is_word_start(c)) {
      size_t end = i;
      while (end < code.size() && lexing::is_word_char(code[end])) ++end;
      word = std::string_view(code).substr(i, end - i);
      if (parens == 0 && word == "const") in_const = true;
      out.skeleton.append(code, i, end - i);
      i = end;
      last = 'a';
      continue;
    }
    if (lexing::is_digit(c) || (c == '.' && i + 1 < code.size() && lexing::is_digit(code[i + 1]))) {
      const size_t end = number_end(code, i);
      const std::string token = code.substr(i, end - i);
      if (in_function && !in_const && user_line(line) && is_float_literal(token)) {
        const float value = std::strtof(token.c_str(), nullptr);
        if (!std::isfinite(value) || out.values.size() == kMaxTweaks) out.ok = false;
        out.values.push_back(value);
        out.skeleton += kMark;
      } else {
        out.skeleton += token;
      }
      i = end;
      last = '0';
      continue;
    }
    switch (c) {
      case '(':
        if (parens++ == 0 && braces == 0) callee = last == 'a' ? word : std::string_view();
        break;
      case ')': --parens; break;
      case '{':
        if (braces++ == 0) in_function = last == ')';  // a body, not a struct or an initializer list
        if (braces == 1 && in_function && callee == "main") out.main_bodies.push_back(out.skeleton.size() + 1);
        break;
      case '}':
        if (--braces <= 0) braces = 0, in_function = false;
        break;
      case ';':
        if (parens == 0) in_const = false;
        break;
      default: break;
    }
    if (!lexing::is_blank(c)) last = c;
    out.skeleton += c;
    ++i;
  }
  if (out.main_bodies.empty()) out.ok = false;  // nowhere to set the globals
  return out;
}

Source twin_source(const Source& source, const LiftedLiterals& lifted) {
  const size_t count = lifted.values.size();
  auto global = [](size_t i) { return std::string(kTweakUniform) + "_" + std::to_string(i); };
  std::string set;  // what main() does first
  for (size_t i = 0; i < count; ++i) set += " " + global(i) + " = " + kTweakUniform + "[" + std::to_string(i) + "];";
  Source twin = source;
  twin.text.clear();
  twin.text.reserve(lifted.skeleton.size() + count * 40 * (1 + lifted.main_bodies.size()));
  size_t index = 0;
  auto body = lifted.main_bodies.begin();
  for (size_t at = 0; at < lifted.skeleton.size(); ++at) {
    if (body != lifted.main_bodies.end() && *body == at) {
      twin.text += set;
      ++body;
    }
    const char c = lifted.skeleton[at];
    if (c == kMark) twin.text += global(index++);
    else twin.text += c;
  }
  // The declaration goes before the first line of the user's files.
  size_t first = 1;  // after the #version line, which may be the user's own
  while (first < twin.line_map.size() && twin.line_map[first].file < 0) ++first;
  size_t at = 0;
  for (size_t l = 0; l < first && at != std::string::npos; ++l) {
    at = twin.text.find('\n', at);
    if (at != std::string::npos) ++at;
  }
  if (at == std::string::npos) at = twin.text.size();
  std::string declaration = "uniform float " + std::string(kTweakUniform) + "[" + std::to_string(std::max<size_t>(count, 1)) + "];";
  for (size_t i = 0; i < count; ++i) declaration += (i == 0 ? " float " : ", ") + global(i);
  declaration += count > 0 ? ";\n" : "\n";
  twin.text.insert(at, declaration);
  twin.line_map.insert(twin.line_map.begin() + static_cast<std::ptrdiff_t>(first), Origin{});
  return twin;
}

}  // namespace rm
