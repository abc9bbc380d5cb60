#include "glslang_worker/sandbox.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

namespace rm {

namespace {

// How often the parent looks at the child's memory.
constexpr std::chrono::milliseconds kMemoryCheck{10};

// The resident memory of a process, from /proc/PID/statm; 0 if it is gone.
std::uintmax_t resident_bytes(const std::string& pid) {
  std::ifstream statm("/proc/" + pid + "/statm");
  std::uintmax_t size = 0, resident = 0;
  statm >> size >> resident;
  return resident * static_cast<std::uintmax_t>(sysconf(_SC_PAGESIZE));
}

void write_all(int fd, const std::string& bytes) {
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) _exit(1);
    done += static_cast<size_t>(n);
  }
}

[[noreturn]] void run_child(int out, const std::function<std::string()>& work) {
  const rlimit no_core{0, 0};
  setrlimit(RLIMIT_CORE, &no_core);
  // A crash ends the child plainly, so the parent learns which signal it was
  // (sanitizer runtimes would otherwise report it and exit with a status).
  for (int fatal : {SIGSEGV, SIGBUS, SIGFPE, SIGILL}) signal(fatal, SIG_DFL);
  write_all(out, work());
  _exit(0);  // no atexit handlers, no destructors of state shared with the parent
}

}  // namespace

SandboxResult run_sandboxed(const std::function<std::string()>& work, const SandboxLimits& limits) {
  int pipe_fds[2];
  if (pipe2(pipe_fds, O_CLOEXEC) != 0) return {SandboxResult::Status::Crashed, "", 0};
  // The child starts out sharing the parent's pages, and counts them as its
  // own: its budget is on top of what the parent holds now. (The memory is
  // watched from outside rather than capped with RLIMIT_AS, which sanitizer
  // runtimes cannot live under.)
  const std::uintmax_t budget = resident_bytes("self") + limits.bytes;
  const pid_t pid = fork();
  if (pid == 0) {
    close(pipe_fds[0]);
    run_child(pipe_fds[1], work);
  }
  close(pipe_fds[1]);
  SandboxResult result;
  if (pid < 0) {
    close(pipe_fds[0]);
    result.status = SandboxResult::Status::Crashed;
    return result;
  }
  // Read while the child writes (a full pipe would stall it), until it
  // closes its end, its time is up, its memory is over budget or the
  // requester hangs up.
  const std::string child = std::to_string(pid);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(limits.seconds);
  std::optional<SandboxResult::Status> killed;
  std::vector<char> buffer(1 << 16);  // not on the stack: `ulimit -s 64` leaves the worker 64 KiB
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) killed = SandboxResult::Status::TimedOut;
    else if (resident_bytes(child) > budget) killed = SandboxResult::Status::OutOfMemory;
    if (killed) break;
    pollfd ready[2] = {{pipe_fds[0], POLLIN, 0}, {limits.requester, POLLRDHUP, 0}};  // poll skips an fd of -1
    const int polled = poll(ready, 2, static_cast<int>(std::min(left, kMemoryCheck).count()));
    if (polled <= 0) continue;  // EINTR, or time to look at the clock and the memory again
    if (ready[1].revents & (POLLRDHUP | POLLHUP | POLLERR)) {
      killed = SandboxResult::Status::Abandoned;
      break;
    }
    if (ready[0].revents == 0) continue;
    const ssize_t n = read(pipe_fds[0], buffer.data(), buffer.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    result.output.append(buffer.data(), static_cast<size_t>(n));
  }
  close(pipe_fds[0]);
  if (killed) kill(pid, SIGKILL);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (killed) {
    result.status = *killed;
  } else if (WIFEXITED(status) && WEXITSTATUS(status) == 0) {
    result.status = SandboxResult::Status::Ok;
    return result;
  } else {
    result.status = SandboxResult::Status::Crashed;
    result.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
  }
  result.output.clear();
  return result;
}

}  // namespace rm
