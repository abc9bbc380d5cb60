#include "core/tweak.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string_view>

#include "core/files.h"
#include "core/lexing.h"

namespace rm {

namespace {

constexpr char kMark = '\x01';

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

// Whether `word` names a float type: float, vecN, matN or matNxM.
bool is_float_type(std::string_view w) {
  const auto size = [](char c) { return c >= '2' && c <= '4'; };
  if (w == "float") return true;
  if (w.size() == 4 && (w.substr(0, 3) == "vec" || w.substr(0, 3) == "mat")) return size(w[3]);
  return w.size() == 6 && w.substr(0, 3) == "mat" && size(w[3]) && w[4] == 'x' && size(w[5]);
}

size_t word_end(std::string_view code, size_t at) {
  while (at < code.size() && lexing::is_word_char(code[at])) ++at;
  return at;
}

// Where the type ends, if the words from `at` on begin a declaration of
// variables of a float type: [const] [precision] TYPE[[n]] NAME, where NAME
// is not followed by '(' (a function's). It reads a few words, and an array
// size of at most 64 characters: a text of many `const`s stays linear.
std::optional<size_t> float_declaration(std::string_view code, size_t at) {
  size_t type_end = 0;
  for (int words = 0; type_end == 0; ++words) {
    if (words == 4 || at >= code.size() || !lexing::is_word_start(code[at])) return std::nullopt;
    const size_t end = word_end(code, at);
    const std::string_view word = code.substr(at, end - at);
    at = lexing::skip_space(code, end);
    if (word == "const" || lexing::is_precision(word) || word == "precise") continue;
    if (!is_float_type(word)) return std::nullopt;
    type_end = end;
  }
  if (at < code.size() && code[at] == '[') {  // float[3] name
    at = code.substr(0, std::min(code.size(), at + 64)).find(']', at);
    if (at == std::string_view::npos) return std::nullopt;
    at = lexing::skip_space(code, at + 1);
  }
  if (at >= code.size() || !lexing::is_word_start(code[at])) return std::nullopt;
  at = lexing::skip_space(code, word_end(code, at));
  if (at < code.size() && code[at] == '(') return std::nullopt;
  return type_end;
}

}  // namespace

LiftedLiterals lift_literals(const Source& source, const fs::path& shaderlib_dir, LiftScope scope) {
  LiftedLiterals out;
  out.scope = scope;
  const bool wide = scope == LiftScope::WithConstants;
  const std::string code = lexing::strip_comments(source.text);
  if (code.find(kMark) != std::string::npos) {
    out.ok = false;
    return out;
  }
  std::vector<bool> user_file(source.files.size());
  for (size_t f = 0; f < source.files.size(); ++f) user_file[f] = !is_under(source.files[f], shaderlib_dir);
  auto user_line = [&](size_t line) {
    if (line >= source.line_map.size()) return false;
    const int file = source.line_map[line].file;
    return file >= 0 && static_cast<size_t>(file) < user_file.size() && user_file[static_cast<size_t>(file)];
  };
  // A -D's value is the user's too: the knobs the window's controls set.
  auto option_line = [&](size_t line) {
    return line < source.line_map.size() && source.line_map[line].file == kCommandLineFile;
  };
  // Replaces a float literal by the mark; `constant`: one FunctionBodies leaves.
  auto lift = [&](const std::string& token, bool constant) {
    const float value = std::strtof(token.c_str(), nullptr);
    if (!std::isfinite(value) || out.values.size() == kMaxTweaks) out.ok = false;
    out.values.push_back(value);
    out.literals.push_back(token);
    out.constants += constant ? 1 : 0;
    out.skeleton += kMark;
  };

  out.skeleton.reserve(code.size());
  size_t line = 0;
  bool line_start = true;
  int braces = 0, parens = 0;
  bool in_function = false, in_const = false;
  // WithConstants: a local float const; a global float declaration (its type
  // ends at global_type_end, the next word may name a declarator, and an
  // initialiser may be open since init_from); file scope between statements.
  bool in_local_const = false, in_global = false, want_name = false, in_init = false, statement_start = true;
  size_t global_type_end = 0, init_from = 0;
  std::string_view target;
  auto close_initialiser = [&] {
    if (in_init) out.moved.push_back({init_from, out.skeleton.size(), std::string(target)});
    in_init = false;
  };
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
        const size_t first_line = line;
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
        const std::string_view text = std::string_view(code).substr(i, end - i);
        const std::optional<lexing::Directive> d = lexing::directive(text);
        // A #define of the user's files or of a -D: its value's literals.
        if (wide && d && d->name == "define" && (user_line(first_line) || option_line(first_line))) {
          out.skeleton.append(text.substr(0, d->rest_at));
          for (size_t k = d->rest_at; k < text.size();) {
            if (lexing::is_word_start(text[k])) {
              const size_t e = word_end(text, k);
              out.skeleton.append(text.substr(k, e - k));
              k = e;
            } else if (lexing::is_digit(text[k]) || (text[k] == '.' && k + 1 < text.size() && lexing::is_digit(text[k + 1]))) {
              const size_t e = number_end(text, k);
              const std::string token(text.substr(k, e - k));
              if (is_float_literal(token)) lift(token, true);
              else out.skeleton += token;
              k = e;
            } else {
              out.skeleton += text[k++];
            }
          }
        } else {
          out.skeleton.append(text);
        }
        i = end;
        continue;
      }
    }
    if (lexing::is_word_start(c)) {
      const size_t end = word_end(code, i);
      word = std::string_view(code).substr(i, end - i);
      if (wide && statement_start && braces == 0 && parens == 0 && user_line(line)) {
        if (const std::optional<size_t> type_end = float_declaration(code, i)) {
          in_global = true;
          global_type_end = *type_end;
        }
      }
      statement_start = false;
      if (parens == 0 && word == "const") {
        if (in_global) {
          out.dropped_consts.push_back(out.skeleton.size());
        } else if (wide && in_function && user_line(line) && float_declaration(code, i)) {
          out.dropped_consts.push_back(out.skeleton.size());
          in_local_const = true;
        } else {
          in_const = true;
        }
      }
      if (in_global && want_name) target = word, want_name = false;
      if (in_global && end == global_type_end) want_name = true;
      out.skeleton.append(code, i, end - i);
      i = end;
      last = 'a';
      continue;
    }
    if (lexing::is_digit(c) || (c == '.' && i + 1 < code.size() && lexing::is_digit(code[i + 1]))) {
      const size_t end = number_end(code, i);
      const std::string token = code.substr(i, end - i);
      const bool in_body = in_function && !in_const;
      if ((in_body || in_init) && user_line(line) && is_float_literal(token)) lift(token, in_init || in_local_const);
      else out.skeleton += token;
      statement_start = false;
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
        if (parens == 0) in_const = in_local_const = false;
        if (in_global && parens == 0 && braces == 0) close_initialiser(), in_global = false;
        break;
      case ',':
        if (in_global && parens == 0 && braces == 0) close_initialiser(), want_name = true;
        break;
      case '=':
        if (in_global && parens == 0 && braces == 0 && !in_init) in_init = true, init_from = out.skeleton.size();
        break;
      default: break;
    }
    if (!lexing::is_blank(c)) {
      last = c;
      statement_start = braces == 0 && parens == 0 && (c == ';' || (c == '}' && !in_global));
    }
    out.skeleton += c;
    ++i;
  }
  if (out.main_bodies.empty()) out.ok = false;  // nowhere to set the globals
  return out;
}

namespace {

// The twin's global for literal i: rm_Tweak_i.
const std::string kGlobalPrefix = std::string(kTweakUniform) + "_";
std::string tweak_global(size_t i) { return kGlobalPrefix + std::to_string(i); }

}  // namespace

Source twin_source(const Source& source, const LiftedLiterals& lifted) {
  const std::string& skeleton = lifted.skeleton;
  const size_t count = lifted.values.size();
  std::string set;  // what main() does first
  for (size_t i = 0; i < count; ++i)
    set += " " + tweak_global(i) + " = " + kTweakUniform + "[" + std::to_string(i) + "];";
  // Then each moved initialiser, in order, on main()'s first line, its marks
  // numbered as where they stand.
  size_t index = 0, at = 0;
  for (const LiftedLiterals::MovedInitialiser& m : lifted.moved) {
    index += static_cast<size_t>(std::count(skeleton.begin() + static_cast<std::ptrdiff_t>(at),
                                            skeleton.begin() + static_cast<std::ptrdiff_t>(m.from), kMark));
    set += " " + m.target + " ";
    for (size_t k = m.from; k < m.to; ++k) {
      const char c = skeleton[k];
      set += c == kMark ? tweak_global(index++) : c == '\n' ? std::string(" ") : std::string(1, c);
    }
    at = m.to;
    set += ";";
  }
  Source twin = source;
  twin.text.clear();
  twin.text.reserve(skeleton.size() + count * 40 * (1 + lifted.main_bodies.size()) + set.size());
  index = 0;
  auto body = lifted.main_bodies.begin();
  auto dropped = lifted.dropped_consts.begin();
  auto moved = lifted.moved.begin();
  for (at = 0; at < skeleton.size(); ++at) {
    if (body != lifted.main_bodies.end() && *body == at) {
      twin.text += set;
      ++body;
    }
    if (dropped != lifted.dropped_consts.end() && *dropped == at) {  // "const"
      at += std::string_view("const").size() - 1;
      ++dropped;
      continue;
    }
    if (moved != lifted.moved.end() && moved->from == at) {  // main() sets it: only its lines stay
      for (; at < moved->to; ++at) {
        if (skeleton[at] == '\n') twin.text += '\n';
        if (skeleton[at] == kMark) ++index;
      }
      --at;
      ++moved;
      continue;
    }
    const char c = skeleton[at];
    if (c == kMark) twin.text += tweak_global(index++);
    else twin.text += c;
  }
  // The declaration goes before the first line of the user's files.
  size_t first = 1;  // after the #version line, which may be the user's own
  while (first < twin.line_map.size() && twin.line_map[first].file < 0) ++first;
  at = 0;
  for (size_t l = 0; l < first && at != std::string::npos; ++l) {
    at = twin.text.find('\n', at);
    if (at != std::string::npos) ++at;
  }
  if (at == std::string::npos) at = twin.text.size();
  std::string declaration = "uniform float " + std::string(kTweakUniform) + "[" + std::to_string(std::max<size_t>(count, 1)) + "];";
  for (size_t i = 0; i < count; ++i) declaration += (i == 0 ? " float " : ", ") + tweak_global(i);
  declaration += count > 0 ? ";\n" : "\n";
  twin.text.insert(at, declaration);
  twin.line_map.insert(twin.line_map.begin() + static_cast<std::ptrdiff_t>(first), Origin{});
  return twin;
}

std::string with_literals(const std::string& text, const std::vector<std::string>& literals) {
  const std::string& prefix = kGlobalPrefix;
  auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  std::string out;
  size_t at = 0;
  for (size_t found; (found = text.find(prefix, at)) != std::string::npos;) {
    size_t end = found + prefix.size();
    while (end < text.size() && std::isdigit(static_cast<unsigned char>(text[end]))) ++end;
    const bool whole = (found == 0 || !word(text[found - 1])) && end > found + prefix.size() &&
                       (end == text.size() || !word(text[end]));
    const size_t i = whole ? std::strtoul(text.c_str() + found + prefix.size(), nullptr, 10) : literals.size();
    out.append(text, at, found - at);
    out.append(i < literals.size() ? literals[i] : text.substr(found, end - found));
    at = end;
  }
  out.append(text, at, std::string::npos);
  return out;
}

bool is_lifted_name(const std::string& text) {
  const size_t n = kGlobalPrefix.size();
  return text.size() > n && text.compare(0, n, kGlobalPrefix) == 0 &&
         std::all_of(text.begin() + static_cast<std::ptrdiff_t>(n), text.end(),
                     [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
}

}  // namespace rm
