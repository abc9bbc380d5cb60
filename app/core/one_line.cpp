#include "core/one_line.h"

#include <sstream>
#include <vector>

namespace rm {

std::string one_line(const std::string& message) {
  std::vector<std::string> lines;
  std::istringstream in(message);
  for (std::string line; std::getline(in, line);)
    if (line.find_first_not_of(" \t") != std::string::npos) lines.push_back(line);
  std::string joined;
  for (size_t i = 0; i < lines.size(); ++i) {
    bool said_elsewhere = false;  // by another line, or by an earlier copy of this one
    for (size_t j = 0; j < lines.size() && !said_elsewhere; ++j)
      said_elsewhere = j != i && (lines[j] == lines[i] ? j < i : lines[j].find(lines[i]) != std::string::npos);
    if (!said_elsewhere) joined += (joined.empty() ? "" : "; ") + lines[i];
  }
  return joined;
}

std::string brief(std::string_view text, size_t most) {
  if (text.size() <= most) return std::string(text);
  size_t cut = most;
  while (cut > 0 && continues_a_character(text[cut])) --cut;
  return std::string(text.substr(0, cut)) + "...";
}

}  // namespace rm
