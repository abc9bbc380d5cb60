// A bound on how deeply a JSON file the host reads may nest. nlohmann's parser
// keeps its own stack, but copying, comparing or printing the value it gives
// recurses once a level, so a file of a million '[' parses and then overflows
// the stack. No Shadertoy export or take nests deeper than about ten levels.
#pragma once
#include <optional>
#include <string>
#include <string_view>

namespace rm {

constexpr int kMaxJsonDepth = 64;

// Where a text nests too deep, counted from 1, and the words for it
// ("arrays and objects nested deeper than 64 levels"), which each reader
// puts after the place as its own errors do.
struct TooDeep {
  int line = 1;
  int column = 1;
  std::string message;
};

// Where `text` opens its array or object nested more than `limit` deep
// (brackets inside strings do not count), or nullopt when it stays within.
std::optional<TooDeep> json_nested_too_deep(std::string_view text, int limit = kMaxJsonDepth);

}  // namespace rm
