// Helpers shared by the tests: a temporary directory and file writing.
#pragma once
#include <unistd.h>

#include <sys/resource.h>
#include <sys/wait.h>

#include <OpenImageIO/imageio.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace rm::test {

namespace fs = std::filesystem;

// The children of process `pid`, those of all its threads (from /proc).
inline std::vector<pid_t> children_of(pid_t pid) {
  std::vector<pid_t> pids;
  std::error_code error;
  for (const auto& task : fs::directory_iterator("/proc/" + std::to_string(pid) + "/task", error)) {
    std::ifstream children(task.path() / "children");
    for (pid_t child; children >> child;) pids.push_back(child);
  }
  return pids;
}

// A fresh directory, removed with everything in it at scope exit.
class TempDir {
 public:
  TempDir() {
    static std::atomic<int> counter{0};
    path_ = fs::temp_directory_path() /
            ("rm-test-" + std::to_string(getpid()) + "-" + std::to_string(counter++));
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  const fs::path& path() const { return path_; }
  fs::path operator/(const std::string& name) const { return path_ / name; }

 private:
  fs::path path_;
};

inline void write_file(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
}

// A function `many` of at least `bytes` of plain code, one line
// `a += 0.5 * sin(f.x + N.0);` after another: a shader huge by its size alone.
inline std::string many_lines_of_code(size_t bytes) {
  std::string code = "float many(vec2 f) {\n  float a = 0.0;\n";
  for (int i = 0; code.size() < bytes; ++i) code += "  a += 0.5 * sin(f.x + " + std::to_string(i % 97) + ".0);\n";
  return code + "  return a;\n}\n";
}

inline std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// An image file's pixels as RGBA floats, top row first; empty if unreadable.
inline std::vector<float> read_pixels(const fs::path& path) {
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) return {};
  std::vector<float> px(static_cast<size_t>(in->spec().image_pixels()) * 4);
  in->read_image(0, 0, 0, 4, OIIO::TypeDesc::FLOAT, px.data());
  return px;
}

struct Outcome {
  int status;          // exit status, -1 if the process did not exit normally
  std::string err;     // what it wrote to stderr
  double seconds = 0;  // wall-clock time it ran
  long peak_kib = 0;   // its peak resident memory
};

// Runs the raymarching binary with `args` (shell syntax); stdout is dropped.
// The shell execs the binary, so the time and memory measured are its own.
// `shell_before` runs in that shell first (a ulimit).
inline Outcome run_binary(const std::string& args, const std::string& shell_before = "") {
  TempDir dir;
  // Redirected before `shell_before`: under a small ulimit -n, dash cannot
  // save a descriptor to redirect a command's (it dups it to 10 and above).
  const std::string cmd = "exec 2> '" + (dir / "err.txt").string() + "' >/dev/null; " + shell_before + "exec " +
                          std::string(RM_BINARY) + " " + args;
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid == 0) {
    closefrom(3);  // the test's own files are not the binary's (a ulimit -n counts them)
    execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  int raw = 0;
  rusage usage{};
  while (wait4(pid, &raw, 0, &usage) < 0 && errno == EINTR) {
  }
  Outcome out{WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, read_file(dir / "err.txt")};
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out.peak_kib = usage.ru_maxrss;
  return out;
}

}  // namespace rm::test
