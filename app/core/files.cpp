#include "core/files.h"

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstring>

namespace rm {

namespace {

// What a file is, in words, when it is not a regular file.
std::optional<std::string> not_regular(mode_t mode) {
  if (S_ISREG(mode)) return std::nullopt;
  if (S_ISDIR(mode)) return "is a directory";
  if (S_ISFIFO(mode)) return "is a named pipe (FIFO), not a regular file";
  if (S_ISSOCK(mode)) return "is a socket, not a regular file";
  if (S_ISCHR(mode)) return "is a character device, not a regular file";
  if (S_ISBLK(mode)) return "is a block device, not a regular file";
  return "is not a regular file";
}

std::string open_error(int error) {
  switch (error) {
    case ENOENT: return "no such file";
    case ENOTDIR: return "a part of the path is not a directory";
    case EACCES: return "permission denied";
    case ELOOP: return "is a symbolic link loop";
    case ENAMETOOLONG: return "the path is too long";
    default: return std::strerror(error);
  }
}

// Whether a failed call's errno is the machine's doing, not the file's.
bool machine_error(int error) {
  return error == EMFILE || error == ENFILE || error == ENOMEM || error == EIO || error == ENOBUFS;
}

// Closes the descriptor on every path out of read_shader_file.
struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) close(fd);
  }
};

}  // namespace

namespace {

std::string over(std::uintmax_t bytes, std::uintmax_t limit, const char* what) {
  return "is " + std::to_string(bytes) + " bytes, over the " + std::to_string(limit >> 20) + " MiB limit for " + what;
}

}  // namespace

std::string over_the_limit(std::uintmax_t bytes) { return over(bytes, kMaxShaderBytes, "shader files"); }

std::string within_open_file_limit() {
  rlimit files{};
  constexpr rlim_t kFewFiles = 64;  // a driver opens a dozen or so, X11 and GLX as many
  if (getrlimit(RLIMIT_NOFILE, &files) != 0 || files.rlim_cur > kFewFiles) return "";
  return " within this process's limit of open files (ulimit -n " + std::to_string(files.rlim_cur) + ")";
}

std::string after_colon(std::string words) {
  if (!words.empty()) words[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(words[0])));
  return words;
}

bool is_under(const std::filesystem::path& file, const std::filesystem::path& dir) {
  if (dir.empty()) return false;
  const std::filesystem::path rel = file.lexically_normal().lexically_relative(dir.lexically_normal());
  return !rel.empty() && *rel.begin() != "..";
}

bool exists_on_disk(const std::filesystem::path& path) {
  std::error_code ec;
  return std::filesystem::exists(path, ec);
}

std::optional<std::string> unreadable_because(const std::filesystem::path& path) {
  struct stat st {};
  if (stat(path.c_str(), &st) != 0) return open_error(errno);
  if (auto what = not_regular(st.st_mode)) return what;
  if (access(path.c_str(), R_OK) != 0) return open_error(errno);
  return std::nullopt;
}

std::optional<std::string> read_shader_file(const std::filesystem::path& path, std::string* error, bool* machine) {
  return read_regular_file(path, kMaxShaderBytes, "shader files", error, machine);
}

std::optional<std::string> read_regular_file(const std::filesystem::path& path, std::uintmax_t limit,
                                             const char* what, std::string* error, bool* machine) {
  bool ignored = false;
  if (!machine) machine = &ignored;
  *machine = false;
  // O_NONBLOCK: opening a FIFO with no writer must not wait for one. What the
  // descriptor is gets decided by fstat, so a file swapped in after a check
  // by name is still caught.
  Descriptor file{open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY)};
  if (file.fd < 0) {
    *machine = machine_error(errno);
    *error = open_error(errno);
    return std::nullopt;
  }
  struct stat st {};
  if (fstat(file.fd, &st) != 0) {
    *machine = machine_error(errno);
    *error = open_error(errno);
    return std::nullopt;
  }
  if (auto what = not_regular(st.st_mode)) {
    *error = *what;
    return std::nullopt;
  }
  const auto size = static_cast<std::uintmax_t>(st.st_size);
  if (size > limit) {
    *error = over(size, limit, what);
    return std::nullopt;
  }
  // Read to the end, not to the size fstat gave: a file still being written
  // may have grown since. The limit still holds.
  std::string bytes;
  bytes.reserve(static_cast<size_t>(size));
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = read(file.fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      *machine = true;
      *error = std::string("read error: ") + std::strerror(errno);
      return std::nullopt;
    }
    if (n == 0) break;
    bytes.append(buffer, static_cast<size_t>(n));
    if (bytes.size() > limit) {
      *error = over(bytes.size(), limit, what);
      return std::nullopt;
    }
  }
  return bytes;
}

}  // namespace rm
