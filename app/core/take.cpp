// A take's files, and the sources it was recorded from (core/take.h).
#include "core/take.h"

#include <cstdio>
#include <sstream>

#include <farmhash.h>

#include "core/capture.h"
#include "core/files.h"

namespace rm {

namespace {

constexpr std::uintmax_t kMaxTakeBytes = 256u << 20;

}  // namespace

std::string source_hash(const Source& source) {
  std::string user;
  std::istringstream lines(source.text);
  size_t index = 0;
  for (std::string line; std::getline(lines, line); ++index)
    if (index < source.line_map.size() && source.line_map[index].file >= 0) user += line + '\n';
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx",
                static_cast<unsigned long long>(util::Fingerprint64(user.data(), user.size())));
  return hex;
}

std::map<std::string, std::string> pass_hashes(const Project& project) {
  std::map<std::string, std::string> out;
  const std::filesystem::path folder = project.path().parent_path();
  for (const Pass& pass : project.passes())
    out[pass.file.lexically_relative(folder).string()] = source_hash(pass.scene->source());
  return out;
}

std::optional<std::string> take_source_changes(const Take& take, const std::map<std::string, std::string>& now) {
  // Each pass's hash at the end of the take, and where a save changed it while recording.
  std::map<std::string, std::string> last;
  std::map<std::string, int> edited_at;
  for (const TakeEvent& e : take.events)
    for (const auto& [pass, hash] : e.hashes) {
      auto it = last.find(pass);
      if (it != last.end() && it->second != hash && !edited_at.count(pass)) edited_at[pass] = e.frame;
      last[pass] = hash;
    }
  std::vector<std::string> changed;
  for (const auto& [pass, hash] : now)
    if (!last.count(pass)) changed.push_back(pass + " (new)");
    else if (last[pass] != hash) changed.push_back(pass);
  for (const auto& [pass, hash] : last)
    if (!now.count(pass)) changed.push_back(pass + " (gone)");
  if (changed.empty() && edited_at.empty()) return std::nullopt;
  auto list = [](const std::vector<std::string>& items) {
    std::string out;
    for (size_t i = 0; i < items.size(); ++i) out += (i ? ", " : "") + items[i];
    return out;
  };
  std::string out;
  if (!changed.empty()) out = "changed since the take was recorded: " + list(changed);
  if (!edited_at.empty()) {
    std::vector<std::string> edits;
    for (const auto& [pass, frame] : edited_at) edits.push_back(pass + " at frame " + std::to_string(frame));
    out += (out.empty() ? "" : "; ") + std::string("saved while it recorded: ") + list(edits);
  }
  return out + "; every frame is drawn from the files as they are now";
}

std::optional<std::filesystem::path> write_take(const std::filesystem::path& path, const Take& take,
                                                std::string* error) {
  const std::filesystem::path folder = path.parent_path().empty() ? "." : path.parent_path();
  return write_whole_file(path, take_text(take, folder), Overwrite::Never, error);
}

std::optional<Take> read_take(const std::filesystem::path& path, std::string* error) {
  const auto text = read_regular_file(path, kMaxTakeBytes, "takes", error);
  const std::filesystem::path folder = path.parent_path().empty() ? "." : path.parent_path();
  std::optional<Take> take = text ? parse_take(*text, folder, error) : std::nullopt;
  if (!take) *error = "take '" + path.string() + "': " + *error;
  return take;
}

}  // namespace rm
