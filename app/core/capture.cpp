#include "core/capture.h"

#include <fcntl.h>
#include <stdio.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <cmath>
#include <cstring>

#include "core/files.h"
#include "core/host_inputs.h"
#include "core/image_codecs.h"
#include "core/one_line.h"

namespace rm {

namespace {

bool is_float_format(const fs::path& path) {
  const std::string ext = lowercase_extension(path);
  return ext == ".exr" || ext == ".hdr";
}

fs::path numbered(const fs::path& path, int n) {
  return path.parent_path() / (path.stem().string() + "-" + std::to_string(n) + path.extension().string());
}

// Moves `from` to `to` only if `to` does not exist yet (atomic on Linux).
bool rename_no_replace(const fs::path& from, const fs::path& to, int* err) {
  if (renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_NOREPLACE) == 0) return true;
  if (errno != EINVAL && errno != ENOSYS) {
    *err = errno;
    return false;
  }
  // File systems without RENAME_NOREPLACE: link() also refuses to replace.
  if (link(from.c_str(), to.c_str()) != 0) {
    *err = errno;
    return false;
  }
  unlink(from.c_str());
  return true;
}

// Writes `bytes` to a new file and flushes it to the disk; 0 or an errno.
int write_durably(const fs::path& path, std::string_view bytes) {
  const int fd = open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) return errno;
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int err = n < 0 ? errno : EIO;
      close(fd);
      return err;
    }
    done += static_cast<size_t>(n);
  }
  // Without fsync a crash after the rename can leave an empty file under the name.
  if (fsync(fd) != 0) {
    const int err = errno;
    close(fd);
    return err;
  }
  return close(fd) == 0 ? 0 : errno;
}

}  // namespace

std::string writable_image_extensions(bool (*written_otherwise)(const fs::path&)) {
  const auto codecs = image_codecs();
  if (auto why = codecs->unavailable()) return *why;
  std::string out;
  for (const std::string& ext : codecs->encodable_extensions())
    if (!written_otherwise || !written_otherwise("x." + ext)) out += (out.empty() ? "." : ", .") + ext;
  return out;
}

std::string file_timestamp() {
  const auto now = std::chrono::system_clock::now();
  const std::time_t t = std::chrono::system_clock::to_time_t(now);
  std::tm local{};
  localtime_r(&t, &local);
  const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch()).count() % 1000;
  char day[32], out[48];
  std::strftime(day, sizeof day, "%Y%m%d-%H%M%S", &local);
  std::snprintf(out, sizeof out, "%s-%03d", day, static_cast<int>(ms));
  return out;
}

fs::path temporary_sibling(const fs::path& path) {
  static std::atomic<unsigned> counter{0};
  return path.parent_path() / ("." + path.stem().string() + ".tmp-" + std::to_string(getpid()) + "-" +
                               std::to_string(counter++) + path.extension().string());
}

std::optional<std::string> check_output_path(const fs::path& path) {
  if (path.extension().empty())
    return "'" + path.string() + "' has no extension to choose an image format (" + writable_image_extensions() + ")";
  const auto codecs = image_codecs();
  if (auto why = codecs->unavailable()) return *why;
  // write_image() encodes in memory, which some of OIIO's writers cannot.
  if (!codecs->can_encode(path)) {
    return "'" + path.string() + "': cannot write images of type '" + path.extension().string() + "' (" +
           writable_image_extensions() + ")";
  }
  return check_output_directory(path);
}

std::optional<std::string> check_output_directory(const fs::path& path) {
  const fs::path dir = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  std::error_code ec;
  if (!fs::exists(dir, ec)) return "'" + path.string() + "': directory '" + dir.string() + "' does not exist";
  if (!fs::is_directory(dir, ec)) return "'" + path.string() + "': '" + dir.string() + "' is not a directory";
  if (access(dir.c_str(), W_OK) != 0) {
    // "permission denied", "read-only file system"
    return "'" + path.string() + "': directory '" + dir.string() + "' is not writable: " + after_colon(std::strerror(errno));
  }
  return std::nullopt;
}

std::optional<fs::path> write_image(const fs::path& path, const Image& image, const Metadata& metadata,
                                    Overwrite overwrite, std::string* error) {
  const auto encoded = encode_image(path, image, metadata, error);
  return encoded ? write_whole_file(path, *encoded, overwrite, error) : std::nullopt;
}

std::optional<std::string> encode_image(const fs::path& path, const Image& image, const Metadata& metadata,
                                        std::string* error) {
  if (auto problem = check_output_path(path)) {
    *error = *problem;
    return std::nullopt;
  }
  const bool as_float = is_float_format(path);
  Metadata attributes{{"Software", "raymarching " RM_VERSION}};
  attributes.insert(attributes.end(), metadata.begin(), metadata.end());
  const std::vector<unsigned char> bytes = as_float ? std::vector<unsigned char>() : to_rgba8(image);
  const PixelsToEncode pixels{image.width, image.height,
                              as_float ? static_cast<const void*>(image.rgba.data()) : bytes.data(), as_float};

  // The file is encoded in memory first and then written with checked
  // write() calls: OIIO's own file writers ignore a failing write (a full
  // disk left a truncated PNG that looked written).
  std::vector<unsigned char> encoded;
  std::string why;
  if (!image_codecs()->encode(path, pixels, attributes, &encoded, &why)) {
    why = one_line(why);
    *error = "cannot encode '" + path.string() + "'" + (why.empty() ? "" : ": " + why);
    return std::nullopt;
  }
  return std::string(encoded.begin(), encoded.end());
}

std::optional<fs::path> write_whole_file(const fs::path& path, std::string_view bytes, Overwrite overwrite,
                                         std::string* error) {
  if (overwrite == Overwrite::Replace)
    return write_whole_files({{path, bytes}}, error) ? std::optional(path) : std::nullopt;
  const fs::path temp = temporary_sibling(path);
  if (int err = write_durably(temp, bytes); err != 0) {
    *error = "cannot write '" + path.string() + "': " + std::strerror(err);
    std::error_code ec;
    fs::remove(temp, ec);
    return std::nullopt;
  }
  for (int n = 0; n < 1000; ++n) {
    const fs::path target = n == 0 ? path : numbered(path, n);
    int err = 0;
    if (rename_no_replace(temp, target, &err)) return target;
    if (err != EEXIST) {
      *error = "cannot write '" + target.string() + "': " + std::strerror(err);
      break;
    }
  }
  if (error->empty()) *error = "cannot write '" + path.string() + "': too many files of that name";
  std::error_code ec;
  fs::remove(temp, ec);
  return std::nullopt;
}

bool write_whole_files(const std::vector<std::pair<fs::path, std::string_view>>& files, std::string* error) {
  std::vector<fs::path> temps;
  auto fail = [&](const fs::path& path, const std::string& why) {
    *error = "cannot write '" + path.string() + "': " + why;
    for (const fs::path& temp : temps) {
      std::error_code ec;
      fs::remove(temp, ec);
    }
    return false;
  };
  for (const auto& [path, bytes] : files) {
    temps.push_back(temporary_sibling(path));
    if (int err = write_durably(temps.back(), bytes); err != 0) return fail(path, std::strerror(err));
  }
  for (size_t i = 0; i < files.size(); ++i) {
    std::error_code ec;
    fs::rename(temps[i], files[i].first, ec);
    if (ec) {
      temps.erase(temps.begin(), temps.begin() + static_cast<std::ptrdiff_t>(i) + 1);  // those are in place
      return fail(files[i].first, ec.message());
    }
  }
  return true;
}

Metadata frame_metadata(const fs::path& scene, const SourceOptions& source, const FrameInputs& in, int samples,
                        const MotionBlur& motion) {
  Metadata out{{"raymarching:scene", fs::absolute(scene).lexically_normal().string()}};
  std::string command = "raymarching render " + scene.string();
  for (const fs::path& dir : source.include_dirs) command += " -I " + dir.string();
  for (const Define& d : source.defines) {
    const std::string value = d.value.empty() ? "1" : d.value;
    command += " -D " + d.name + "=" + value;
    out.emplace_back("raymarching:define:" + d.name, value);
  }
  for (const std::string& name : source.undefines) {
    command += " -U " + name;
    out.emplace_back("raymarching:undefine:" + name, "-U " + name);
  }
  command += " --size " + std::to_string(static_cast<int>(in.resolution.x)) + "x" +
             std::to_string(static_cast<int>(in.resolution.y));
  for (const HostInput& input : host_inputs()) {
    if (!input.record) continue;
    std::string value = input.record(in);
    command += " " + std::string(input.render_option) + " " + value;
    out.emplace_back("raymarching:" + std::string(input.name), std::move(value));
  }
  for (const UniformValue& u : in.uniforms) {
    command += " --set " + u.name + "=" + u.text;
    out.emplace_back("raymarching:uniform:" + u.name, u.text);
  }
  if (samples > 1) {
    command += " --samples " + std::to_string(samples);
    out.emplace_back("raymarching:samples", std::to_string(samples));
  }
  if (motion.steps > 1 && motion.shutter > 0) {
    // The shutter is open for a share of the frame interval: the rate goes too.
    char fps[32], shutter[32];
    std::snprintf(fps, sizeof fps, "%.9g", motion.fps);
    std::snprintf(shutter, sizeof shutter, "%.9g", motion.shutter);
    command += std::string(" --fps ") + fps + " --shutter " + shutter + " --motion-samples " + std::to_string(motion.steps);
    out.emplace_back("raymarching:shutter", shutter);
    out.emplace_back("raymarching:motion_samples", std::to_string(motion.steps));
  }
  out.emplace_back("ImageDescription", std::move(command));
  return out;
}

Metadata read_metadata(const fs::path& path) { return image_codecs()->metadata(path); }

}  // namespace rm
