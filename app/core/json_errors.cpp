#include "core/json_errors.h"

#include <string_view>

#include "core/one_line.h"

namespace rm {

namespace {

constexpr size_t kKeptHead = 24, kKeptTail = 16;  // bytes, about; enough to find the place in an editor

}  // namespace

std::string short_json_error(const std::string& what) {
  const std::string key = "last read: '";
  const size_t open = what.find(key);
  const size_t close = what.rfind('\'');
  if (open == std::string::npos || close == std::string::npos) return what;
  const size_t begin = open + key.size();
  if (close < begin || close - begin <= kKeptHead + kKeptTail + 8) return what;  // a cut would save little
  size_t tail_begin = close - kKeptTail;
  while (tail_begin < close && continues_a_character(what[tail_begin])) ++tail_begin;
  // The token is longer than kKeptHead: brief() cuts it and adds the "...".
  return what.substr(0, begin) + brief(std::string_view(what).substr(begin, close - begin), kKeptHead) +
         what.substr(tail_begin);
}

}  // namespace rm
