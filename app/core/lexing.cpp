#include "core/lexing.h"

#include <string>

namespace rm::lexing {

std::optional<int> components_of(std::string_view type) {
  if (type == "float" || type == "int" || type == "uint" || type == "bool" || type == "double") return 1;
  const auto size = [](char c) { return c >= '2' && c <= '4' ? std::optional<int>(c - '0') : std::nullopt; };
  // vecN, ivecN, uvecN, bvecN, dvecN
  if (!type.empty() && (type[0] == 'i' || type[0] == 'u' || type[0] == 'b' || type[0] == 'd')) {
    if (type.substr(1, 3) == "vec" && type.size() == 5) return size(type[4]);
    if (type[0] == 'd') type.remove_prefix(1);  // dmatN, dmatNxM
  }
  if (type.substr(0, 3) == "vec" && type.size() == 4) return size(type[3]);
  // matN, matNxM
  if (type.substr(0, 3) != "mat" || type.size() < 4) return std::nullopt;
  const auto columns = size(type[3]);
  if (!columns) return std::nullopt;
  if (type.size() == 4) return *columns * *columns;
  if (type.size() != 6 || type[4] != 'x') return std::nullopt;
  const auto rows = size(type[5]);
  return rows ? std::optional<int>(*columns * *rows) : std::nullopt;
}

size_t skip_blanks(std::string_view text, size_t at) {
  while (at < text.size() && is_blank(text[at])) ++at;
  return at;
}

size_t skip_space(std::string_view text, size_t at) {
  while (at < text.size() && is_space(text[at])) ++at;
  return at;
}

std::optional<Directive> directive(std::string_view line) {
  Directive d;
  d.hash = skip_blanks(line, 0);
  if (d.hash >= line.size() || line[d.hash] != '#') return std::nullopt;
  const size_t name_at = skip_blanks(line, d.hash + 1);
  size_t name_end = name_at;
  while (name_end < line.size() && is_word_char(line[name_end])) ++name_end;
  d.name = line.substr(name_at, name_end - name_at);
  d.rest_at = skip_blanks(line, name_end);
  d.rest = line.substr(d.rest_at);
  return d;
}

std::optional<std::string_view> defined_macro(std::string_view line) {
  const auto d = directive(line);
  if (!d || d->name != "define") return std::nullopt;
  size_t end = 0;
  while (end < d->rest.size() && is_word_char(d->rest[end])) ++end;
  if (end == 0) return std::nullopt;
  return d->rest.substr(0, end);
}

bool nothing_but_comment(std::string_view rest) {
  const size_t at = skip_blanks(rest, 0);
  return at == rest.size() || rest.substr(at, 2) == "//";
}

std::optional<size_t> find_word(std::string_view text, std::string_view word) {
  std::optional<size_t> found;
  any_word(text, [&](size_t begin, size_t end) {
    if (text.substr(begin, end - begin) == word) found = begin;
    return found.has_value();
  });
  return found;
}

bool has_word(std::string_view text, std::string_view word) { return find_word(text, word).has_value(); }

bool has_call(std::string_view text, std::string_view name, std::string_view after) {
  std::string_view previous;
  size_t previous_end = 0;
  return any_word(text, [&](size_t begin, size_t end) {
    const std::string_view word = text.substr(begin, end - begin);
    const bool follows = after.empty() ||
                         (previous == after && skip_space(text, previous_end) == begin && previous_end < begin);
    previous = word;
    previous_end = end;
    if (word != name || !follows) return false;
    const size_t next = skip_space(text, end);
    return next < text.size() && text[next] == '(';
  });
}

std::string strip_comments(std::string_view text) {
  std::string out(text);
  for (size_t i = 0; i + 1 < text.size(); ++i) {
    size_t end = i;  // one past the comment
    if (text.compare(i, 2, "//") == 0) {
      // The compiler splices a line that ends in a backslash onto the next
      // before it looks for comments, so such a comment goes on there.
      for (;;) {
        while (end < text.size() && text[end] != '\n') ++end;
        const bool spliced = end < text.size() && ((end >= 1 && text[end - 1] == '\\') ||
                                                   (end >= 2 && text[end - 1] == '\r' && text[end - 2] == '\\'));
        if (!spliced) break;
        ++end;
      }
    } else if (text.compare(i, 2, "/*") == 0) {
      const size_t close = text.find("*/", i + 2);
      end = close == std::string_view::npos ? text.size() : close + 2;
    } else {
      continue;
    }
    for (size_t j = i; j < end; ++j)
      if (out[j] != '\n') out[j] = ' ';
    i = end - 1;
  }
  return out;
}

std::string code_only(std::string_view text) {
  const std::string code = strip_comments(text);
  std::string out;
  out.reserve(code.size());
  for (size_t i = 0; i < code.size();) {
    if (!is_blank(code[i])) {
      out += code[i++];
      continue;
    }
    size_t end = i;
    while (end < code.size() && is_blank(code[end])) ++end;
    // One space for the run, none before a line's end (unless a backslash
    // stands before it: a backslash, blanks and a newline splice no lines).
    const bool line_end = end == code.size() || code[end] == '\n';
    if (!line_end || (!out.empty() && out.back() == '\\')) out += ' ';
    i = end;
  }
  return out;
}

}  // namespace rm::lexing
