// Files as the host accepts them: regular files only, and shader text up to a
// size limit. A FIFO, a device, a socket or a directory would block a read or
// never end it, so each is refused by what it is, before anything is read.
#pragma once
#include <cctype>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace rm {

// The most bytes one shader file, and one scene with all its includes, may
// hold. No real shader comes near it (the largest examples are a few KB).
constexpr std::uintmax_t kMaxShaderBytes = 16u << 20;

// Why `path` cannot be read as a regular file ("no such file", "is a
// directory", "is a named pipe (FIFO)", "is a character device", "is a
// symbolic link loop", "permission denied", ...), or nullopt when it can.
// Nothing is opened.
std::optional<std::string> unreadable_because(const std::filesystem::path& path);

// Whether anything is at `path`; false, not an exception, when it cannot be told.
bool exists_on_disk(const std::filesystem::path& path);

// Whether `file` lies inside `dir` (both compared lexically; false when dir is empty).
bool is_under(const std::filesystem::path& file, const std::filesystem::path& dir);

// The bytes of the shader file at `path`: a regular file, refused by its
// size when it holds more than kMaxShaderBytes. nullopt with *error set in
// the words above; *machine, when given, is set where the cause is the
// machine's (no file descriptor or memory left, an I/O error), not the file's.
std::optional<std::string> read_shader_file(const std::filesystem::path& path, std::string* error,
                                            bool* machine = nullptr);

// The same for any regular file, up to `limit` bytes ("... over the N MiB
// limit for WHAT").
std::optional<std::string> read_regular_file(const std::filesystem::path& path, std::uintmax_t limit,
                                             const char* what, std::string* error, bool* machine = nullptr);

// "is 17000000 bytes, over the 16 MiB limit for shader files"
std::string over_the_limit(std::uintmax_t bytes);

// " within this process's limit of open files (ulimit -n N)" where that
// limit is small enough (64 or less) to be the likely cause of a library's
// failure that does not name it (Mesa's "Failed to load GLX"), else "".
std::string within_open_file_limit();

// The system's words for an error ("Read-only file system"), to follow a
// colon in a one-line message: the first letter in lower case.
std::string after_colon(std::string words);

// `path`'s extension in lower case (".png" for "x.PNG"), as formats are
// chosen. Inline: the image module, which links no core, uses it too.
inline std::string lowercase_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

}  // namespace rm
