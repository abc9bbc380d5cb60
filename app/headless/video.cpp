#include "headless/video.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <vector>

#include "core/capture.h"
#include "core/files.h"

extern char** environ;

namespace rm {

namespace fs = std::filesystem;

namespace {

// One row per container: what `-o NAME.ext` writes. A new container is one
// more row.
struct Container {
  const char* extension;
  const char* codec;         // ffmpeg's encoder by default
  const char* pixel_format;  // of the default codec; nullptr: the encoder's own
  int crf;                   // the default codec's quality; -1: it has none
  std::vector<std::string> options;
};

const std::vector<Container>& containers() {
  // H.264 in yuv420p plays everywhere; crf 18 is close to lossless to the eye.
  static const std::vector<Container> table = {
      {".mp4", "libx264", "yuv420p", 18, {"-movflags", "+faststart"}},
      {".mov", "libx264", "yuv420p", 18, {"-movflags", "+faststart"}},
      {".webm", "libvpx-vp9", "yuv420p", 32, {"-b:v", "0", "-row-mt", "1"}},
      // One palette for the whole clip, made from its own frames.
      {".gif", "gif", nullptr, -1, {"-filter_complex", "split[a][b];[a]palettegen[p];[b][p]paletteuse"}},
  };
  return table;
}

const Container* container_of(const fs::path& path) {
  const std::string ext = lowercase_extension(path);
  for (const Container& c : containers())
    if (ext == c.extension) return &c;
  return nullptr;
}

// " (killed by signal 11, Segmentation fault)" for an ffmpeg that a signal
// ended, else "": x264's threads crash on a stack of 64 KiB (`ulimit -s`).
std::string killed_by(int status) {
  if (!WIFSIGNALED(status)) return "";
  const int signal = WTERMSIG(status);
  return " (killed by signal " + std::to_string(signal) + ", " + strsignal(signal) + ")";
}

std::string format_number(double value) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", value);
  return buf;
}

}  // namespace

bool is_video_path(const fs::path& path) { return container_of(path) != nullptr; }

std::string video_extensions() {
  std::string out;
  for (const Container& c : containers()) out += (out.empty() ? "" : ", ") + std::string(c.extension);
  return out;
}

std::optional<std::string> check_video(const fs::path& path, const VideoSettings& settings) {
  const Container* c = container_of(path);
  if (!c) return "'" + path.string() + "' is not a video (" + video_extensions() + ")";
  if (settings.crf && c->crf < 0 && settings.codec.empty())
    return "--crf does not apply to " + std::string(c->extension) + ", which has no quality setting";
  if (settings.codec.empty() && c->pixel_format && std::string(c->pixel_format) == "yuv420p" &&
      (settings.size.x % 2 || settings.size.y % 2))
    return "--size " + std::to_string(settings.size.x) + "x" + std::to_string(settings.size.y) + ": " +
           c->codec + " in yuv420p needs an even width and height";
  return check_output_directory(path);
}

std::unique_ptr<VideoEncoder> VideoEncoder::start(const fs::path& path, const VideoSettings& settings,
                                                  std::string* error) {
  if (auto problem = check_video(path, settings)) {
    *error = *problem;
    return nullptr;
  }
  const Container& c = *container_of(path);
  const fs::path temp = temporary_sibling(path);
  // -xerror: without it ffmpeg 5 exits 0 when its last write fails (a full
  // disk: "Error writing trailer ... No space left on device"), and a cut
  // video would be renamed into place.
  std::vector<std::string> args = {"ffmpeg", "-hide_banner", "-loglevel", "error", "-xerror", "-nostdin", "-y",
                                   "-f", "rawvideo", "-pix_fmt", "rgba",
                                   "-video_size", std::to_string(settings.size.x) + "x" + std::to_string(settings.size.y),
                                   "-framerate", format_number(settings.fps), "-i", "pipe:0"};
  args.insert(args.end(), c.options.begin(), c.options.end());
  args.insert(args.end(), {"-c:v", settings.codec.empty() ? c.codec : settings.codec});
  if (settings.codec.empty() && c.pixel_format) args.insert(args.end(), {"-pix_fmt", c.pixel_format});
  const int crf = settings.crf.value_or(settings.codec.empty() ? c.crf : -1);
  if (crf >= 0) args.insert(args.end(), {"-crf", std::to_string(crf)});
  args.push_back(temp.string());

  // ffmpeg's stderr goes to an unlinked file: read back for the message when it fails.
  char log_name[] = "/tmp/raymarching-ffmpeg-XXXXXX";
  const int log = mkostemp(log_name, O_CLOEXEC);
  if (log < 0) {
    *error = std::string("cannot start ffmpeg: ") + std::strerror(errno);
    return nullptr;
  }
  unlink(log_name);
  int pipe_fds[2];
  if (pipe2(pipe_fds, O_CLOEXEC) != 0) {
    *error = std::string("cannot start ffmpeg: ") + std::strerror(errno);
    close(log);
    return nullptr;
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, pipe_fds[0], STDIN_FILENO);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, log, STDERR_FILENO);
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  // Its own process group: the terminal's Ctrl-C is the host's to handle
  // (headless/run_guard.h), which abandons the video; ffmpeg would else
  // finish a part of it on its own.
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  posix_spawnattr_setpgroup(&attr, 0);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP);
  pid_t pid = 0;
  const int err = posix_spawnp(&pid, "ffmpeg", &actions, &attr, argv.data(), environ);
  posix_spawnattr_destroy(&attr);
  posix_spawn_file_actions_destroy(&actions);
  close(pipe_fds[0]);
  if (err != 0) {
    close(pipe_fds[1]);
    close(log);
    *error = "'" + path.string() + "': a video needs ffmpeg, " +
             (err == ENOENT ? std::string("which is not on PATH (Debian: apt-get install ffmpeg)")
                            : "which did not start: " + std::string(std::strerror(err)));
    return nullptr;
  }
  // A write to an ffmpeg that has gone must fail with EPIPE, not end this process.
  signal(SIGPIPE, SIG_IGN);
  return std::unique_ptr<VideoEncoder>(new VideoEncoder(path, temp, pid, pipe_fds[1], log));
}

VideoEncoder::VideoEncoder(fs::path path, fs::path temp, pid_t pid, int input, int log)
    : path_(std::move(path)), temp_(std::move(temp)), pid_(pid), input_(input), log_(log) {}

VideoEncoder::~VideoEncoder() {
  if (!done_) abandon();
  if (input_ >= 0) close(input_);
  close(log_);
}

bool VideoEncoder::add(const Image& frame, std::string* error) {
  const std::vector<unsigned char> bytes = to_rgba8(frame);
  for (size_t sent = 0; sent < bytes.size();) {
    const ssize_t n = write(input_, bytes.data() + sent, bytes.size() - sent);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      // ffmpeg closed its input: it failed or was stopped. Its status says which.
      const int status = end_input_and_wait();
      const std::string said = ffmpeg_said();
      *error = "ffmpeg stopped while writing '" + path_.string() + "'" + killed_by(status) +
               (said.empty() ? "" : ": " + said);
      return false;
    }
    sent += static_cast<size_t>(n);
  }
  return true;
}

int VideoEncoder::end_input_and_wait() {
  close(input_);
  input_ = -1;
  int status = 0;
  while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
  pid_ = -1;
  return status;
}

bool VideoEncoder::finish(std::string* error) {
  const int status = end_input_and_wait();
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    const std::string said = ffmpeg_said();
    *error = "ffmpeg could not write '" + path_.string() + "'" + killed_by(status) + (said.empty() ? "" : ": " + said);
    abandon();
    return false;
  }
  std::error_code ec;
  fs::rename(temp_, path_, ec);
  if (ec) {
    *error = "cannot write '" + path_.string() + "': " + ec.message();
    abandon();
    return false;
  }
  done_ = true;
  return true;
}

void VideoEncoder::abandon() {
  if (pid_ > 0) {
    kill(pid_, SIGKILL);
    waitpid(pid_, nullptr, 0);
    pid_ = -1;
  }
  std::error_code ec;
  fs::remove(temp_, ec);
  done_ = true;
}

std::string VideoEncoder::ffmpeg_said() const {
  std::string text;
  char buf[4096];
  for (off_t at = 0;;) {
    const ssize_t n = pread(log_, buf, sizeof buf, at);
    if (n <= 0) break;
    text.append(buf, static_cast<size_t>(n));
    at += n;
  }
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r' || text.back() == ' ')) text.pop_back();
  const size_t line = text.find_last_of('\n');
  if (line != std::string::npos) text.erase(0, line + 1);
  // ffmpeg names the file it wrote, the temporary one: the person named the other.
  const std::string temp = temp_.string(), path = path_.string();
  for (size_t at = text.find(temp); at != std::string::npos; at = text.find(temp, at + path.size()))
    text.replace(at, temp.size(), path);
  return text;
}

}  // namespace rm
