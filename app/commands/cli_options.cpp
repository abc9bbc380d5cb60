#include "commands/cli_options.h"

#include "core/shadertoy_json.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <regex>
#include <sstream>

#include "core/capture.h"
#include "core/data_paths.h"
#include "core/files.h"
#include "core/knobs.h"
#include "core/lexing.h"

namespace rm::cli {

namespace fs = std::filesystem;

namespace {

// Options are read with std::regex, whose matcher recurses once per
// character: longer text than any valid value is refused before it.
constexpr size_t kMaxValueLength = 64;

}  // namespace

glm::ivec2 parse_size(const std::string& text, const char* option) {
  if (text.size() > kMaxValueLength) throw UsageError{std::string(option) + ": expected WIDTHxHEIGHT, e.g. 640x360"};
  static const std::regex re(R"(^\s*(-?\d+)\s*[xX]\s*(-?\d+)\s*$)");
  std::smatch m;
  if (!std::regex_match(text, m, re)) throw UsageError{std::string(option) + " '" + text + "': expected WIDTHxHEIGHT, e.g. 640x360"};
  long w = 0, h = 0;
  try {
    w = std::stol(m[1].str());
    h = std::stol(m[2].str());
  } catch (const std::exception&) {
    throw UsageError{std::string(option) + " '" + text + "': number out of range"};
  }
  if (w <= 0 || h <= 0) throw UsageError{std::string(option) + " '" + text + "': width and height must be positive"};
  if (w > kMaxPictureSide || h > kMaxPictureSide)
    throw UsageError{std::string(option) + " '" + text + "': at most " + std::to_string(kMaxPictureSide) + " pixels a side"};
  return {static_cast<int>(w), static_cast<int>(h)};
}

glm::ivec2 parse_frame_range(const std::string& text, const char* option) {
  const std::string expected = std::string(option) + " '" + text + "': expected FIRST:LAST, frame numbers from 0, e.g. 0:23";
  if (text.size() > kMaxValueLength) throw UsageError{expected};
  static const std::regex re(R"(^\s*(\d{1,9})\s*:\s*(\d{1,9})\s*$)");
  std::smatch m;
  if (!std::regex_match(text, m, re)) throw UsageError{expected};
  const glm::ivec2 range(std::stoi(m[1].str()), std::stoi(m[2].str()));
  if (range.x > range.y) throw UsageError{std::string(option) + " '" + text + "': FIRST comes after LAST"};
  return range;
}

double parse_number(const std::string& text, const std::string& what) {
  size_t used = 0;
  double v = 0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || !std::isfinite(v)) throw UsageError{what + " '" + text + "': not a finite number"};
  return v;
}

CLI::Validator finite_between(double low, double high) {
  return CLI::Validator(
      [low, high](std::string& text) -> std::string {
        char range[80];
        std::snprintf(range, sizeof range, "a number from %g to %g", low, high);
        try {
          const double v = parse_number(text, "");
          return v >= low && v <= high ? "" : "'" + text + "' is not " + range;
        } catch (const UsageError&) {
          return "'" + text + "' is not " + range;
        }
      },
      "");
}

CLI::Validator whole_between(int low, int high) {
  return CLI::Validator(
      [low, high](std::string& text) -> std::string {
        const std::string said = "'" + text + "' is not a whole number from " + std::to_string(low) + " to " +
                                 std::to_string(high);
        size_t used = 0;
        long long v = 0;
        try {
          v = std::stoll(text, &used);
        } catch (const std::exception&) {
          return said;
        }
        return used == text.size() && v >= low && v <= high ? "" : said;
      },
      "INT in [" + std::to_string(low) + " - " + std::to_string(high) + "]");
}

glm::vec4 parse_mouse(const std::string& text) {
  std::vector<double> parts;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    parts.push_back(parse_number(item, "--mouse"));
    // iMouse is floats: a double past their range would be an undefined cast.
    if (std::fabs(parts.back()) > FLT_MAX) throw UsageError{"--mouse '" + text + "': " + item + " is out of a float's range"};
  }
  if (parts.size() != 2 && parts.size() != 4) throw UsageError{"--mouse '" + text + "': expected X,Y or X,Y,CX,CY"};
  if (parts.size() == 2) return glm::vec4(parts[0], parts[1], 0, 0);
  return glm::vec4(parts[0], parts[1], parts[2], parts[3]);
}

std::chrono::system_clock::time_point parse_date(const std::string& text) {
  if (text.size() > kMaxValueLength) throw UsageError{"--date: expected YYYY-MM-DDTHH:MM:SS[.sss]"};
  static const std::regex re(R"(^(\d{4})-(\d{2})-(\d{2})[T ](\d{2}):(\d{2}):(\d{2}(\.\d+)?)$)");
  std::smatch m;
  if (!std::regex_match(text, m, re)) throw UsageError{"--date '" + text + "': expected YYYY-MM-DDTHH:MM:SS[.sss]"};
  std::tm tm{};
  tm.tm_year = std::stoi(m[1].str()) - 1900;
  tm.tm_mon = std::stoi(m[2].str()) - 1;
  tm.tm_mday = std::stoi(m[3].str());
  tm.tm_hour = std::stoi(m[4].str());
  tm.tm_min = std::stoi(m[5].str());
  const double seconds = std::stod(m[6].str());
  // mktime would carry a 13th month or a 30th of February into a later date.
  const std::chrono::year_month_day day{std::chrono::year{tm.tm_year + 1900}, std::chrono::month(tm.tm_mon + 1),
                                        std::chrono::day(tm.tm_mday)};
  if (!day.ok()) throw UsageError{"--date '" + text + "': no such day"};
  if (tm.tm_hour > 23 || tm.tm_min > 59 || seconds >= 60)
    throw UsageError{"--date '" + text + "': no such time of day (00:00:00 to 23:59:59.999)"};
  tm.tm_sec = static_cast<int>(seconds);
  tm.tm_isdst = -1;
  const std::time_t t = std::mktime(&tm);
  return std::chrono::system_clock::from_time_t(t) +
         std::chrono::duration_cast<std::chrono::system_clock::duration>(std::chrono::duration<double>(seconds - tm.tm_sec));
}

void check_project_file(const std::filesystem::path& path, const std::filesystem::path& media_dir) {
  if (!is_shadertoy_json(path)) return;
  std::string error;
  if (!read_shadertoy_file(path, media_dir, &error)) throw UsageError{error};
}

void require_readable_file(const fs::path& path) {
  if (auto why = unreadable_because(path)) {
    if (*why == "is a directory") *why += ", not a shader file";
    throw UsageError{"'" + path.string() + "': " + *why};
  }
  std::error_code ec;
  const std::uintmax_t size = fs::file_size(path, ec);
  if (!ec && size > kMaxShaderBytes)
    throw UsageError{"'" + path.string() + "': " + over_the_limit(size)};
}

void SourceFlags::add_to(CLI::App& app) {
    app.add_option("-I", includes, "Add DIR to the #include search path")->type_name("DIR")->allow_extra_args(false);
    app.add_option("-D", defines, "Define macro NAME (as VALUE, default 1) after #version")->type_name("NAME[=VALUE]")->allow_extra_args(false);
    app.add_option("-U", undefines, "Undefine macro NAME: the scene's own #define of it is read as a blank line")
        ->type_name("NAME")->allow_extra_args(false);
    app.add_option("--quality", quality, "shaderlib preset: the same as -D RM_QUALITY=RM_<NAME>")
        ->check(CLI::IsMember(std::vector<std::string>(quality_presets().begin(), quality_presets().end())));
}

SourceOptions SourceFlags::source() const {
    SourceOptions out;
    out.shaderlib_dir = shaderlib_dir();
    for (const auto& dir : includes) out.include_dirs.emplace_back(dir);
    for (const auto& d : defines) {
      const auto eq = d.find('=');
      Define def{d.substr(0, eq), eq == std::string::npos ? "" : d.substr(eq + 1)};
      if (const auto why = define_problem(def)) throw UsageError{"-D '" + printable(d) + "': " + *why};
      out.defines.push_back(def);
    }
    if (!quality.empty()) out.defines.push_back({"RM_QUALITY", preset_macro(quality)});
    for (const auto& name : undefines) {
      if (!lexing::is_name(name)) throw UsageError{"-U '" + printable(name) + "': not a macro name"};
      for (const Define& d : out.defines)
        if (d.name == name) {
          const bool from_quality = !quality.empty() && &d == &out.defines.back();  // pushed last, above
          throw UsageError{"-U " + name + ": " + (from_quality ? "--quality" : "-D") + " gives " + name + " a value; give one of them"};
        }
      out.undefines.push_back(name);
    }
    return out;
}

void ChannelFlags::add_to(CLI::App& app) {
    for (int i = 0; i < 4; ++i)
      app.add_option("--channel" + std::to_string(i), paths[static_cast<size_t>(i)],
                     "Image for iChannel" + std::to_string(i))->type_name("IMAGE");
}

std::array<fs::path, 4> ChannelFlags::get() const {
    std::array<fs::path, 4> out;
    for (size_t i = 0; i < 4; ++i) out[i] = paths[i];
    return out;
}

}  // namespace rm::cli
