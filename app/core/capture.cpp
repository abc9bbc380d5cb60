#include "core/capture.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <fcntl.h>
#include <stdio.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <cmath>
#include <cstring>

#include "core/host_inputs.h"
#include "core/one_line.h"

namespace rm {

namespace {

bool is_float_format(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
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

std::string writable_image_extensions() {
  // OIIO's "format:ext,ext;format:ext" list, kept to the writers that can
  // encode into memory (what write_image needs), each format's first ext.
  static const std::string list = [] {
    std::string out;
    std::string formats = OIIO::get_string_attribute("extension_list");
    for (size_t at = 0; at < formats.size();) {
      size_t end = formats.find(';', at);
      if (end == std::string::npos) end = formats.size();
      const std::string entry = formats.substr(at, end - at);
      at = end + 1;
      const size_t colon = entry.find(':');
      if (colon == std::string::npos) continue;
      std::string ext = entry.substr(colon + 1);
      ext = ext.substr(0, ext.find(','));
      if (entry.substr(0, colon) == "null") continue;  // OIIO's writer that writes nothing
      auto writer = OIIO::ImageOutput::create(entry.substr(0, colon));
      if (!writer || !writer->supports("ioproxy") || ext.empty()) continue;
      out += (out.empty() ? "." : ", .") + ext;
    }
    OIIO::geterror();  // the formats without a writer leave a message behind
    return out;
  }();
  return list;
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
  auto out = OIIO::ImageOutput::create(path.string());
  // write_image() encodes in memory, which some of OIIO's writers cannot.
  if (!out || !out->supports("ioproxy")) {
    OIIO::geterror();  // clear OIIO's pending message
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
  if (access(dir.c_str(), W_OK) != 0) return "'" + path.string() + "': directory '" + dir.string() + "' is not writable";
  return std::nullopt;
}

std::optional<fs::path> write_image(const fs::path& path, const Image& image, const Metadata& metadata,
                                    Overwrite overwrite, std::string* error) {
  if (auto problem = check_output_path(path)) {
    *error = *problem;
    return std::nullopt;
  }
  const bool as_float = is_float_format(path);
  OIIO::ImageSpec spec(image.width, image.height, 4, as_float ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
  spec.attribute("Software", "raymarching " RM_VERSION);
  for (const auto& [key, value] : metadata) spec.attribute(key, value);

  // The file is encoded in memory first and then written with checked
  // write() calls: OIIO's own file writers ignore a failing write (a full
  // disk left a truncated PNG that looked written).
  std::vector<unsigned char> encoded;
  OIIO::Filesystem::IOVecOutput memory(encoded);
  auto out = OIIO::ImageOutput::create(path.string());
  bool ok = out && out->set_ioproxy(&memory) && out->open(path.string(), spec);
  if (ok) {
    if (as_float) {
      ok = out->write_image(OIIO::TypeDesc::FLOAT, image.rgba.data());
    } else {
      ok = out->write_image(OIIO::TypeDesc::UINT8, to_rgba8(image).data());
    }
    ok = out->close() && ok;
  }
  if (!ok) {
    const std::string why = one_line(out ? out->geterror() : OIIO::geterror());
    *error = "cannot encode '" + path.string() + "'" + (why.empty() ? "" : ": " + why);
    return std::nullopt;
  }
  return write_whole_file(path, std::string_view(reinterpret_cast<const char*>(encoded.data()), encoded.size()),
                          overwrite, error);
}

std::optional<fs::path> write_whole_file(const fs::path& path, std::string_view bytes, Overwrite overwrite,
                                         std::string* error) {
  const fs::path temp = temporary_sibling(path);
  if (int err = write_durably(temp, bytes); err != 0) {
    *error = "cannot write '" + path.string() + "': " + std::strerror(err);
    std::error_code ec;
    fs::remove(temp, ec);
    return std::nullopt;
  }

  if (overwrite == Overwrite::Replace) {
    std::error_code ec;
    fs::rename(temp, path, ec);
    if (!ec) return path;
    *error = "cannot write '" + path.string() + "': " + ec.message();
  } else {
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
  }
  std::error_code ec;
  fs::remove(temp, ec);
  return std::nullopt;
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

Metadata read_metadata(const fs::path& path) {
  Metadata out;
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) {
    OIIO::geterror();
    return out;
  }
  for (const auto& p : in->spec().extra_attribs)
    if (p.type() == OIIO::TypeDesc::STRING) out.emplace_back(p.name().string(), p.get_string());
  return out;
}

}  // namespace rm
