// A bound on how deeply a JSON file the host reads may nest. nlohmann's parser
// keeps its own stack, but copying, comparing or printing the value it gives
// recurses once a level, so a file of a million '[' parses and then overflows
// the stack. No Shadertoy export or take nests deeper than about ten levels.
#pragma once
#include <optional>
#include <string_view>

namespace rm {

constexpr int kMaxJsonDepth = 64;

// Where a place in a text is, counted from 1.
struct TextPosition {
  int line = 1;
  int column = 1;
};

// Where `text` opens its array or object nested more than `limit` deep
// (brackets inside strings do not count), or nullopt when it stays within.
std::optional<TextPosition> json_nested_too_deep(std::string_view text, int limit = kMaxJsonDepth);

}  // namespace rm
