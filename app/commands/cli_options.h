// What every command reads from its command line in the same way: sizes,
// numbers, the mouse, dates, -I/-D/--quality, --channelN, and the scene file.
// A bad value throws UsageError, which main() prints as one line (exit 2).
#pragma once
#include <CLI/CLI.hpp>
#include <array>
#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/source.h"

namespace rm::cli {

struct UsageError {
  std::string message;
};

glm::ivec2 parse_size(const std::string& text, const char* option);
double parse_number(const std::string& text, const std::string& what);
// FIRST:LAST, both frame numbers (from 0, LAST included), FIRST <= LAST.
glm::ivec2 parse_frame_range(const std::string& text, const char* option);
// An option's check: a finite number from `low` to `high`. CLI11's Range
// lets NaN through, and prints DBL_MAX in full when a bound is open.
CLI::Validator finite_between(double low, double high);
// The same for an int option: "'1.5' is not a whole number from 1 to 1024".
CLI::Validator whole_between(int low, int high);
glm::vec4 parse_mouse(const std::string& text);
std::chrono::system_clock::time_point parse_date(const std::string& text);

// A scene that cannot be read, or is over the size limit, is an I/O error
// (exit 2), not a shader error.
void require_readable_file(const std::filesystem::path& path);

// A Shadertoy .json that `render` or `check` runs is read once up front:
// malformed JSON is a usage error (exit 2, with its line and column). Its
// warnings (stand-ins) come with the build's diagnostics. The window does not
// ask: it opens with the JSON's error and waits for a save that mends it, as
// it does for a broken shader.
void check_project_file(const std::filesystem::path& path, const std::filesystem::path& media_dir);

// -I DIR, -D NAME[=VALUE], -U NAME and --quality, as a C compiler takes the
// first three.
struct SourceFlags {
  std::vector<std::string> includes;
  std::vector<std::string> defines;
  std::vector<std::string> undefines;
  std::string quality;

  void add_to(CLI::App& app);
  SourceOptions source() const;
};

// --channel0..3 IMAGE.
struct ChannelFlags {
  std::array<std::string, 4> paths;

  void add_to(CLI::App& app);
  std::array<std::filesystem::path, 4> get() const;
};

}  // namespace rm::cli
