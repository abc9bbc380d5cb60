#include "core/take.h"

#include <algorithm>
#include <cfloat>
#include <climits>
#include <cmath>
#include <cstdio>
#include <sstream>

#include <farmhash.h>
#include <nlohmann/json.hpp>

#include "core/capture.h"
#include "core/files.h"
#include "core/json_depth.h"
#include "core/json_errors.h"
#include "core/lexing.h"

namespace rm {

namespace {

using json = nlohmann::ordered_json;
constexpr int kFormat = 1;                     // "raymarching_take": the file's version
constexpr std::uintmax_t kMaxTakeBytes = 256u << 20;
// A frame's "w" at most (3 years): the replay adds it to iDate in the system
// clock's nanoseconds, whose int64 ends at 292 years.
constexpr double kMaxTakeSeconds = 1e8;

json floats(const float* v, int n) {
  json out = json::array();
  for (int i = 0; i < n; ++i) out.push_back(v[i]);
  return out;
}

// A uniform's text as `--set` spells it, back to numbers: "1.5", "true", "0.1,0.2".
std::vector<float> uniform_numbers(const std::string& text) {
  std::vector<float> out;
  std::stringstream parts(text);
  for (std::string part; std::getline(parts, part, ',');) {
    if (part == "true" || part == "false") out.push_back(part == "true" ? 1.0f : 0.0f);
    else out.push_back(std::strtof(part.c_str(), nullptr));
  }
  return out;
}

// A path as the take stores it: relative to the take's folder when it is below it.
std::string stored_path(const std::filesystem::path& path, const std::filesystem::path& folder) {
  const auto absolute = std::filesystem::absolute(path).lexically_normal();
  const auto relative = absolute.lexically_relative(std::filesystem::absolute(folder).lexically_normal());
  if (!relative.empty() && *relative.begin() != "..") return relative.string();
  return absolute.string();
}

std::filesystem::path resolved_path(const std::string& stored, const std::filesystem::path& folder) {
  const std::filesystem::path p(stored);
  return (p.is_absolute() ? p : std::filesystem::absolute(folder) / p).lexically_normal();
}

template <typename T>
T field(const json& object, const char* name, T fallback) {
  auto it = object.find(name);
  return it == object.end() || it->is_null() ? fallback : it->get<T>();
}

// A number of the take's that does not fit what it is read into. nlohmann
// casts unchecked (undefined past an int's or a float's range).
struct OutOfRange {
  std::string text;
  const char* kind;  // what it should have been
};
int int_of(const json& v) {
  const bool in_range = v.is_number_unsigned() ? v.get<std::uint64_t>() <= INT_MAX
                                               : v.is_number_integer() && v.get<std::int64_t>() >= INT_MIN &&
                                                     v.get<std::int64_t>() <= INT_MAX;
  if (!in_range) throw OutOfRange{v.dump(), "a whole number that fits an int"};
  return v.get<int>();
}
float float_of(const json& v) {
  if (!v.is_number() || !(std::fabs(v.get<double>()) <= FLT_MAX)) throw OutOfRange{v.dump(), "a number that fits a float"};
  return v.get<float>();
}

glm::vec4 vec4_of(const json& v) { return {float_of(v.at(0)), float_of(v.at(1)), float_of(v.at(2)), float_of(v.at(3))}; }

}  // namespace

const std::vector<Define>& Take::defines_at(int frame) const {
  static const std::vector<Define> none;
  const std::vector<Define>* out = &none;
  for (const TakeEvent& e : events)
    if (e.frame <= frame) out = &e.defines;
  return *out;
}

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
  json head;
  head["raymarching_take"] = kFormat;
  head["scene"] = stored_path(take.scene, folder);
  if (!take.media.empty()) head["media"] = stored_path(take.media, folder);
  if (std::any_of(take.channels.begin(), take.channels.end(), [](const auto& c) { return !c.empty(); })) {
    json channels = json::array();
    for (const auto& c : take.channels) channels.push_back(c.empty() ? std::string() : stored_path(c, folder));
    head["channels"] = channels;
  }
  json includes = json::array();
  for (const auto& dir : take.include_dirs) includes.push_back(stored_path(dir, folder));
  head["include_dirs"] = includes;
  if (!take.undefines.empty()) head["undefines"] = take.undefines;
  head["date"] = take.date;
  json events = json::array();
  for (const TakeEvent& e : take.events) {
    json defines = json::array();
    for (const Define& d : e.defines) defines.push_back({d.name, d.value});
    events.push_back({{"frame", e.frame}, {"defines", defines}, {"hashes", e.hashes}});
  }
  head["events"] = events;

  // One frame a line, each with only what changed since the frame before.
  std::string text = head.dump(1);
  text.resize(text.size() - 2);  // "\n}": the object goes on with the frames
  text += ",\n \"frames\": [\n";
  const TakeFrame* previous = nullptr;
  for (const TakeFrame& f : take.frames) {
    json line;
    char wall[32];
    std::snprintf(wall, sizeof wall, "%.6f", f.wall);
    line["w"] = json::parse(wall);
    line["t"] = f.time;
    line["f"] = f.frame;
    if (!previous || f.size != previous->size) line["r"] = {f.size.x, f.size.y};
    if (!previous || f.mouse != previous->mouse) line["m"] = floats(&f.mouse.x, 4);
    if (!previous || f.cursor != previous->cursor) line["c"] = floats(&f.cursor.x, 2);
    json keys = json::array();
    for (const KeyEvent& k : f.keys) keys.push_back({k.code, k.down ? 1 : 0});
    if (!keys.empty()) line["k"] = keys;
    json uniforms = json::object();
    for (const UniformValue& u : f.uniforms) {
      const bool changed = !previous || std::none_of(previous->uniforms.begin(), previous->uniforms.end(),
                                                     [&](const UniformValue& p) { return p.name == u.name && p.text == u.text; });
      if (changed) uniforms[u.name] = u.text;
    }
    if (!uniforms.empty()) line["u"] = uniforms;
    text += (previous ? ",\n" : "") + line.dump();
    previous = &f;
  }
  text += "\n ]\n}\n";
  return write_whole_file(path, text, Overwrite::Never, error);
}

std::optional<Take> read_take(const std::filesystem::path& path, std::string* error) {
  const std::string where = "take '" + path.string() + "': ";
  const auto text = read_regular_file(path, kMaxTakeBytes, "takes", error);
  if (!text) {
    *error = where + *error;
    return std::nullopt;
  }
  const std::filesystem::path folder = path.parent_path().empty() ? "." : path.parent_path();
  if (const auto deep = json_nested_too_deep(*text)) {
    *error = where + "at line " + std::to_string(deep->line) + ", column " + std::to_string(deep->column) + ": " +
             deep->message;
    return std::nullopt;
  }
  try {
    const json doc = json::parse(*text);
    // Compared as JSON: a float there (1e300) is no version, and no cast to int.
    if (!doc.is_object() || doc.value("raymarching_take", json()) != json(kFormat)) {
      *error = where + "not a take of this version (no \"raymarching_take\": " + std::to_string(kFormat) + ")";
      return std::nullopt;
    }
    Take take;
    take.scene = resolved_path(doc.at("scene").get<std::string>(), folder);
    if (doc.contains("media")) take.media = resolved_path(doc.at("media").get<std::string>(), folder);
    const json channels = field<json>(doc, "channels", json::array());
    for (size_t c = 0; c < std::min<size_t>(channels.size(), 4); ++c)
      if (const std::string stored = channels.at(c).get<std::string>(); !stored.empty())
        take.channels[c] = resolved_path(stored, folder);
    for (const auto& dir : field<json>(doc, "include_dirs", json::array()))
      take.include_dirs.push_back(resolved_path(dir.get<std::string>(), folder));
    take.undefines = field<std::vector<std::string>>(doc, "undefines", {});
    for (const std::string& name : take.undefines)
      if (!lexing::is_name(name)) {
        *error = where + "-U '" + printable(name) + "': not a macro name";
        return std::nullopt;
      }
    take.date = field<std::string>(doc, "date", "");
    for (const auto& e : field<json>(doc, "events", json::array())) {
      TakeEvent event;
      event.frame = int_of(e.at("frame"));
      for (const auto& d : field<json>(e, "defines", json::array())) {
        event.defines.push_back({d.at(0).get<std::string>(), d.at(1).get<std::string>()});
        if (const auto why = define_problem(event.defines.back())) {
          *error = where + "a -D of frame " + std::to_string(event.frame) + ": " + *why;
          return std::nullopt;
        }
      }
      event.hashes = field<std::map<std::string, std::string>>(e, "hashes", {});
      take.events.push_back(std::move(event));
    }
    TakeFrame state;
    for (const auto& line : doc.at("frames")) {
      state.wall = line.at("w").get<double>();
      if (!(state.wall >= 0 && state.wall <= kMaxTakeSeconds)) {
        *error = where + "frame " + std::to_string(take.frames.size()) + "'s \"w\" is " + line.at("w").dump() +
                 " s, not from 0 to " + std::to_string(static_cast<long>(kMaxTakeSeconds)) + " s (3 years) into the take";
        return std::nullopt;
      }
      state.time = float_of(line.at("t"));
      state.frame = int_of(line.at("f"));
      if (line.contains("r")) state.size = {int_of(line.at("r").at(0)), int_of(line.at("r").at(1))};
      if (state.size.x <= 0 || state.size.y <= 0) {
        *error = where + "frame " + std::to_string(take.frames.size()) + " has no window size (\"r\": [W, H] in pixels)";
        return std::nullopt;
      }
      if (std::max(state.size.x, state.size.y) > kMaxPictureSide) {
        *error = where + "frame " + std::to_string(take.frames.size()) + "'s window is " +
                 std::to_string(state.size.x) + "x" + std::to_string(state.size.y) + ", over " +
                 std::to_string(kMaxPictureSide) + " pixels a side";
        return std::nullopt;
      }
      if (line.contains("m")) state.mouse = vec4_of(line.at("m"));
      if (line.contains("c")) state.cursor = {float_of(line.at("c").at(0)), float_of(line.at("c").at(1))};
      state.keys.clear();
      for (const auto& k : field<json>(line, "k", json::array()))
        state.keys.push_back({int_of(k.at(0)), int_of(k.at(1)) != 0});
      const json set = field<json>(line, "u", json::object());
      for (const auto& [name, value] : set.items()) {
        const std::string text = value.get<std::string>();
        auto it = std::find_if(state.uniforms.begin(), state.uniforms.end(),
                               [&](const UniformValue& u) { return u.name == name; });
        if (it == state.uniforms.end()) state.uniforms.push_back({name, uniform_numbers(text), text});
        else *it = {name, uniform_numbers(text), text};
      }
      if (!take.frames.empty() && state.wall < take.frames.back().wall) {
        *error = where + "frame " + std::to_string(take.frames.size()) + " comes before the one ahead of it (\"w\")";
        return std::nullopt;
      }
      take.frames.push_back(state);
    }
    if (take.frames.empty()) {
      *error = where + "it holds no frames";
      return std::nullopt;
    }
    return take;
  } catch (const json::exception& e) {
    // nlohmann's own words say where: "parse error at line 3, column 7: ..." or a missing key.
    *error = where + short_json_error(e.what());
    return std::nullopt;
  } catch (const OutOfRange& e) {
    *error = where + "expected " + e.kind + ", not " + e.text;
    return std::nullopt;
  }
}

FrameInputs take_inputs_at(const Take& take, double wall, glm::ivec2 size, const UserUniforms& types) {
  const auto& frames = take.frames;
  // The last frame at or before `wall`, and the one after it.
  auto after = std::upper_bound(frames.begin(), frames.end(), wall,
                                [](double w, const TakeFrame& f) { return w < f.wall; });
  const TakeFrame& a = after == frames.begin() ? frames.front() : *std::prev(after);
  const TakeFrame& b = after == frames.end() ? a : *after;
  const double span = b.wall - a.wall;
  const float k = span > 0 ? static_cast<float>(std::clamp((wall - a.wall) / span, 0.0, 1.0)) : 0.0f;

  FrameInputs in;
  // A restart or a seek back is a jump, not a slope.
  in.time = b.time >= a.time ? glm::mix(a.time, b.time, k) : a.time;
  in.frame = a.frame;
  in.mouse = a.mouse;
  const bool held = a.mouse.z > 0 && b.mouse.z > 0;
  if (held) in.mouse = glm::vec4(glm::mix(glm::vec2(a.mouse), glm::vec2(b.mouse), k), a.mouse.z, a.mouse.w);
  in.mouse.w = a.mouse.w > 0 ? -a.mouse.w : a.mouse.w;  // a press happens in one frame: the caller's (TakeReplay)
  in.cursor = glm::mix(a.cursor, b.cursor, k);
  const glm::vec2 scale = glm::vec2(size) / glm::vec2(a.size);
  in.resolution = glm::vec3(size, 1.0f);
  in.mouse *= glm::vec4(scale, scale);
  in.cursor *= scale;
  for (const UniformValue& u : a.uniforms) {
    UniformValue v = u;
    const UserUniform* type = types.find(u.name);
    auto next = std::find_if(b.uniforms.begin(), b.uniforms.end(), [&](const UniformValue& o) { return o.name == u.name; });
    const bool continuous = type && type->type != UserUniform::Type::Int && type->type != UserUniform::Type::Bool;
    if (continuous && next != b.uniforms.end() && next->value.size() == u.value.size() && k > 0) {
      for (size_t i = 0; i < v.value.size(); ++i) v.value[i] = glm::mix(u.value[i], next->value[i], k);
      v.text = uniform_value_text(type->type, v.value);
    }
    in.uniforms.push_back(std::move(v));
  }
  return in;
}

int TakeReplay::frames() const {
  if (fps_ <= 0) return static_cast<int>(take_.frames.size());
  // A take of hours at a high rate is more frames than an int holds: say the most.
  const double count = std::floor(take_.duration() * fps_ + 1e-9) + 1;
  return count < INT_MAX ? static_cast<int>(count) : INT_MAX;
}

double TakeReplay::wall(int index) const {
  if (fps_ <= 0) return take_.frames[static_cast<size_t>(std::clamp(index, 0, frames() - 1))].wall;
  return index / fps_;
}

std::pair<int, int> TakeReplay::crossed(int index) const {
  if (fps_ <= 0) return {index, index + 1};
  auto count_until = [&](double w) {  // recorded frames at or before w
    return static_cast<int>(std::upper_bound(take_.frames.begin(), take_.frames.end(), w,
                                             [](double x, const TakeFrame& f) { return x < f.wall; }) -
                            take_.frames.begin());
  };
  const int first = index == 0 ? 0 : count_until(wall(index - 1));
  return {first, count_until(wall(index))};
}

}  // namespace rm
