#include "core/glslang_client.h"

#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <system_error>

#include "core/data_paths.h"

extern char** environ;

namespace rm {

namespace {

namespace fs = std::filesystem;

// The worker's own limit, and room for it to build the built-in symbols of a
// new #version and to answer: past this it is taken to be stuck.
constexpr std::chrono::seconds kReplyTime{static_cast<int>(kValidationSeconds) * 4};

// Installed, the worker lives in <prefix>/libexec/raymarching, else it is the
// one built beside this program.
fs::path worker_path() { return installed_or_built(RM_GLSLANG_WORKER_INSTALLED, RM_GLSLANG_WORKER_BUILT); }

class Worker {
 public:
  GlslangReply ask(const GlslangRequest& request) {
    std::lock_guard<std::mutex> lock(mutex_);
    // A worker that was already running may have gone away since (killed,
    // or ended by the terminal's signals): one fresh start, then a verdict.
    for (int attempt = 0; attempt < 2; ++attempt) {
      const bool fresh = pid_ < 0;
      if (fresh) {
        if (std::string error = start(); !error.empty()) return no_worker(error);
      }
      const auto deadline = std::chrono::steady_clock::now() + kReplyTime;
      if (write_request(socket_, request)) {
        if (auto reply = read_reply(socket_, deadline)) return *reply;
      }
      const bool timed_out = std::chrono::steady_clock::now() >= deadline;
      const std::string ended = stop();
      if (timed_out) return no_worker("it did not answer in " + std::to_string(kReplyTime.count()) + " s");
      if (fresh) return no_worker(ended);
    }
    return no_worker("it ended twice in a row");
  }

 private:
  GlslangReply no_worker(const std::string& why) const {
    GlslangReply reply;
    reply.status = GlslangReply::Status::NoWorker;
    reply.output = "the glslang worker " + path_.string() + " failed: " + why;
    return reply;
  }

  // "" when started, else why not.
  std::string start() {
    path_ = worker_path();
    int ends[2];
    if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, ends) != 0) return std::strerror(errno);
    posix_spawn_file_actions_t files;
    posix_spawn_file_actions_init(&files);
    posix_spawn_file_actions_adddup2(&files, ends[1], 0);
    posix_spawn_file_actions_adddup2(&files, ends[1], 1);
    // Nothing else of the host's: a pipe's end left open in the worker would
    // keep its reader (ffmpeg, say) from ever seeing the end.
    posix_spawn_file_actions_addclosefrom_np(&files, 3);
    posix_spawnattr_t attr;
    posix_spawnattr_init(&attr);
    // Its own process group, so that the terminal's Ctrl-C is the host's to
    // handle; and signals as a fresh program has them.
    sigset_t none, all;
    sigemptyset(&none);
    sigfillset(&all);
    posix_spawnattr_setpgroup(&attr, 0);
    posix_spawnattr_setsigmask(&attr, &none);
    posix_spawnattr_setsigdefault(&attr, &all);
    posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
    const std::string program = path_.string();
    char* argv[] = {const_cast<char*>(program.c_str()), nullptr};
    const int spawned = posix_spawn(&pid_, program.c_str(), &files, &attr, argv, environ);
    posix_spawn_file_actions_destroy(&files);
    posix_spawnattr_destroy(&attr);
    close(ends[1]);
    if (spawned != 0) {
      close(ends[0]);
      pid_ = -1;
      return std::strerror(spawned);
    }
    socket_ = ends[0];
    return "";
  }

  // Ends the worker; says how it had ended, if it had.
  std::string stop() {
    close(socket_);
    socket_ = -1;
    int status = 0;
    pid_t done = waitpid(pid_, &status, WNOHANG);
    std::string ended = "it ended";
    if (done == 0) {
      kill(pid_, SIGKILL);
      while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
      }
      ended = "it stopped answering";
    } else if (done == pid_ && WIFEXITED(status)) {
      ended = "it exited with status " + std::to_string(WEXITSTATUS(status));
    } else if (done == pid_ && WIFSIGNALED(status)) {
      ended = std::string("it was ended by ") + strsignal(WTERMSIG(status));
    }
    pid_ = -1;
    return ended;
  }

  std::mutex mutex_;
  fs::path path_;
  pid_t pid_ = -1;
  int socket_ = -1;
};

std::atomic<long> requests_asked{0};  // glslang_requests()

}  // namespace

long glslang_requests() { return requests_asked.load(); }

GlslangReply ask_glslang(const GlslangRequest& request) {
  ++requests_asked;
  // Never destroyed: at exit the socket closes with the process, and the
  // worker, reading its end, ends too.
  static Worker& worker = *new Worker;
  return worker.ask(request);
}

GlslangWarmUp::GlslangWarmUp(std::string version_line)
    : thread_([line = std::move(version_line)] {
        GlslangRequest request;
        request.version_line = line;
        request.text = line + "\nvoid main() {}\n";
        ask_glslang(request);
      }) {}

GlslangWarmUp::~GlslangWarmUp() { thread_.join(); }

}  // namespace rm
