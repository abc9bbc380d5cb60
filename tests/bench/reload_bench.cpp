// Benchmark behind the start-up section of docs/performance.md (scripts/bench
// startup). Needs a display (run under xvfb-run): reload_bench RAYMARCHING SCENE_FOR_VALIDATION
// Measures, with the real program in a real window:
//   - cold start: from spawning the program to its first presented frame;
//   - whole processes: `--version` (what starting and ending one costs) and
//     `check` of the largest shader we ship, from spawning to exit;
//   - glslang validation (preprocess + check) of that shader, in process.
#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "core/check.h"
#include "core/data_paths.h"
#include "core/source.h"

extern char** environ;
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

long long now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now().time_since_epoch()).count();
}

// A child process whose stderr we read line by line.
class Child {
 public:
  Child(const std::vector<std::string>& argv) {
    int fds[2];
    if (pipe(fds) != 0) std::abort();
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[1], STDERR_FILENO);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addclose(&actions, fds[0]);
    std::vector<char*> args;
    for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    if (posix_spawn(&pid_, args[0], &actions, nullptr, args.data(), environ) != 0) std::abort();
    posix_spawn_file_actions_destroy(&actions);
    close(fds[1]);
    fd_ = fds[0];
  }
  ~Child() {
    kill(pid_, SIGTERM);
    waitpid(pid_, nullptr, 0);
    close(fd_);
  }
  // The next stderr line containing `needle`, or nullopt after `timeout`.
  std::optional<std::string> wait_line(const std::string& needle, std::chrono::milliseconds timeout) {
    const auto end = Clock::now() + timeout;
    for (;;) {
      for (size_t nl; (nl = buffer_.find('\n')) != std::string::npos;) {
        std::string line = buffer_.substr(0, nl);
        buffer_.erase(0, nl + 1);
        if (line.find(needle) != std::string::npos) return line;
      }
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(end - Clock::now()).count();
      if (left <= 0) return std::nullopt;
      pollfd p{fd_, POLLIN, 0};
      if (poll(&p, 1, static_cast<int>(left)) <= 0) continue;
      char chunk[4096];
      ssize_t n = read(fd_, chunk, sizeof chunk);
      if (n <= 0) return std::nullopt;
      buffer_.append(chunk, static_cast<size_t>(n));
    }
  }

 private:
  pid_t pid_ = 0;
  int fd_ = -1;
  std::string buffer_;
};

long long presented_at(const std::string& line) { return std::stoll(line.substr(line.rfind(' ') + 1)); }

// A 4-line scene: what the host itself costs a start, beside the shader.
std::string scene_text() {
  return "void mainImage(out vec4 c, in vec2 f) {\n  vec2 uv = f / iResolution.xy;\n"
         "  c = vec4(uv, fract(0.137 + iTime), 1.0);\n}\n";
}

// Milliseconds from spawning `argv` (output dropped) to its exit.
double run_to_exit_ms(const std::vector<std::string>& argv) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const long long start = now_ns();
  pid_t pid = 0;
  if (posix_spawn(&pid, args[0], &actions, nullptr, args.data(), environ) != 0) std::abort();
  posix_spawn_file_actions_destroy(&actions);
  int status = 0;
  waitpid(pid, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) std::fprintf(stderr, "%s failed\n", argv[1].c_str()), std::exit(1);
  return (now_ns() - start) / 1e6;
}

double percentile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  return v[static_cast<size_t>(q * static_cast<double>(v.size() - 1) + 0.5)];
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: reload_bench RAYMARCHING SCENE\n");
    return 2;
  }
  const std::string binary = argv[1];
  const fs::path big_scene = argv[2];
  const fs::path dir = fs::temp_directory_path() / ("rm-bench-" + std::to_string(getpid()));
  fs::create_directories(dir);
  const fs::path scene = dir / "scene.frag";

  // Cold start, five times.
  std::vector<double> cold_ms;
  for (int i = 0; i < 5; ++i) {
    std::ofstream(scene) << scene_text();
    const long long start = now_ns();
    Child child({binary, scene.string(), "--size", "320x180", "-v"});
    auto line = child.wait_line("presented generation 1", std::chrono::seconds(20));
    if (!line) return std::fprintf(stderr, "no first frame\n"), 1;
    cold_ms.push_back((presented_at(*line) - start) / 1e6);
  }

  // Whole processes, ten times each.
  std::vector<double> version_ms, check_ms;
  for (int i = 0; i < 10; ++i) {
    version_ms.push_back(run_to_exit_ms({binary, "--version"}));
    check_ms.push_back(run_to_exit_ms({binary, "check", big_scene.string()}));
  }

  // glslang validation of the largest shader, through the glslang worker.
  rm::SourceOptions options;
  options.shaderlib_dir = rm::shaderlib_dir();
  std::vector<double> validate_ms;
  size_t bytes = 0, lines = 0;
  for (int i = 0; i < 20; ++i) {
    const auto start = Clock::now();
    rm::Source source = rm::preprocess(big_scene, options);
    rm::Diagnostics diags = rm::validate(source);
    validate_ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
    bytes = source.text.size();
    lines = source.line_map.size();
    if (rm::count_errors(diags)) return std::fprintf(stderr, "%s", rm::join(diags).c_str()), 1;
  }
  validate_ms.erase(validate_ms.begin());  // the first run starts the worker

  fs::remove_all(dir);
  std::printf("| measure | median | p95 | runs |\n|---|---:|---:|---:|\n");
  std::printf("| cold start to first presented frame | %.1f ms | %.1f ms | %zu |\n", percentile(cold_ms, 0.5),
              percentile(cold_ms, 0.95), cold_ms.size());
  std::printf("| a whole process: `raymarching --version` | %.1f ms | %.1f ms | %zu |\n", percentile(version_ms, 0.5),
              percentile(version_ms, 0.95), version_ms.size());
  std::printf("| a whole process: `raymarching check %s` | %.1f ms | %.1f ms | %zu |\n", big_scene.filename().c_str(),
              percentile(check_ms, 0.5), percentile(check_ms, 0.95), check_ms.size());
  std::printf("| glslang preprocess + validate, %s (%zu lines, %zu bytes after includes) | %.1f ms | %.1f ms | %zu |\n",
              big_scene.filename().c_str(), lines, bytes, percentile(validate_ms, 0.5), percentile(validate_ms, 0.95),
              validate_ms.size());
  return 0;
}
