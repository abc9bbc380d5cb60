// A take's file format: the JSON that write_take writes and read_take reads
// (core/take.h). Kept apart from the files and the replay, so that the fuzz
// target (tests/fuzz/take_fuzz.cpp) reads and writes takes without a GL stack.
#include <algorithm>
#include <cfloat>
#include <climits>
#include <cmath>
#include <cstdio>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/capture.h"
#include "core/json_depth.h"
#include "core/json_errors.h"
#include "core/lexing.h"
#include "core/take.h"

namespace rm {

namespace {

using json = nlohmann::ordered_json;
constexpr int kFormat = 1;                     // "raymarching_take": the file's version
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

std::string take_text(const Take& take, const std::filesystem::path& folder) {
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
  return text;
}

std::optional<Take> parse_take(std::string_view text, const std::filesystem::path& folder, std::string* error) {
  if (const auto deep = json_nested_too_deep(text)) {
    *error = "at line " + std::to_string(deep->line) + ", column " + std::to_string(deep->column) + ": " +
             deep->message;
    return std::nullopt;
  }
  try {
    const json doc = json::parse(text);
    // Compared as JSON: a float there (1e300) is no version, and no cast to int.
    if (!doc.is_object() || doc.value("raymarching_take", json()) != json(kFormat)) {
      *error = "not a take of this version (no \"raymarching_take\": " + std::to_string(kFormat) + ")";
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
        *error = "-U '" + printable(name) + "': not a macro name";
        return std::nullopt;
      }
    take.date = field<std::string>(doc, "date", "");
    for (const auto& e : field<json>(doc, "events", json::array())) {
      TakeEvent event;
      event.frame = int_of(e.at("frame"));
      for (const auto& d : field<json>(e, "defines", json::array())) {
        event.defines.push_back({d.at(0).get<std::string>(), d.at(1).get<std::string>()});
        if (const auto why = define_problem(event.defines.back())) {
          *error = "a -D of frame " + std::to_string(event.frame) + ": " + *why;
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
        *error = "frame " + std::to_string(take.frames.size()) + "'s \"w\" is " + line.at("w").dump() +
                 " s, not from 0 to " + std::to_string(static_cast<long>(kMaxTakeSeconds)) + " s (3 years) into the take";
        return std::nullopt;
      }
      state.time = float_of(line.at("t"));
      state.frame = int_of(line.at("f"));
      if (line.contains("r")) state.size = {int_of(line.at("r").at(0)), int_of(line.at("r").at(1))};
      if (state.size.x <= 0 || state.size.y <= 0) {
        *error = "frame " + std::to_string(take.frames.size()) + " has no window size (\"r\": [W, H] in pixels)";
        return std::nullopt;
      }
      if (std::max(state.size.x, state.size.y) > kMaxPictureSide) {
        *error = "frame " + std::to_string(take.frames.size()) + "'s window is " +
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
      for (const auto& item : set.items()) {
        const std::string& name = item.key();
        const std::string text = item.value().get<std::string>();
        auto it = std::find_if(state.uniforms.begin(), state.uniforms.end(),
                               [&](const UniformValue& u) { return u.name == name; });
        if (it == state.uniforms.end()) state.uniforms.push_back({name, uniform_numbers(text), text});
        else *it = {name, uniform_numbers(text), text};
      }
      if (!take.frames.empty() && state.wall < take.frames.back().wall) {
        *error = "frame " + std::to_string(take.frames.size()) + " comes before the one ahead of it (\"w\")";
        return std::nullopt;
      }
      take.frames.push_back(state);
    }
    if (take.frames.empty()) {
      *error = "it holds no frames";
      return std::nullopt;
    }
    return take;
  } catch (const json::exception& e) {
    // nlohmann's own words say where: "parse error at line 3, column 7: ..." or a missing key.
    *error = short_json_error(e.what());
    return std::nullopt;
  } catch (const OutOfRange& e) {
    *error = std::string("expected ") + e.kind + ", not " + e.text;
    return std::nullopt;
  }
}

}  // namespace rm
