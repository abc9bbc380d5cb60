#include "core/json_depth.h"

namespace rm {

std::optional<TooDeep> json_nested_too_deep(std::string_view text, int limit) {
  int line = 1, column = 1;
  int depth = 0;
  bool in_string = false, escaped = false;
  for (char c : text) {
    if (in_string) {
      if (escaped) escaped = false;
      else if (c == '\\') escaped = true;
      else if (c == '"') in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > limit)
        return TooDeep{line, column, "arrays and objects nested deeper than " + std::to_string(limit) + " levels"};
    } else if (c == ']' || c == '}') {
      --depth;
    }
    if (c == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return std::nullopt;
}

}  // namespace rm
