// Shuts stderr (fd 2) while a library that prints there besides reporting
// its errors runs: libpng prints each error to stderr although OIIO hands
// it back too (OIIO's handler returns, so libpng's own runs after it). What
// another thread writes to stderr meanwhile is lost with it, so a line that
// must be seen whatever runs (run_guard's last word) goes to a copy of the
// stderr taken before, and so does std::cerr once send_cerr_past_shuts()
// has run.
#pragma once
#include <fcntl.h>
#include <unistd.h>

namespace rm {

// Points std::cerr at a copy of stderr: a StderrShut then silences only
// what libraries write to fd 2, and not the program's own lines from
// another thread (the window's, while its builder reads a PNG).
void send_cerr_past_shuts();

class StderrShut {
 public:
  StderrShut() : saved_(fcntl(STDERR_FILENO, F_DUPFD_CLOEXEC, 0)) {
    const int null = open("/dev/null", O_WRONLY | O_CLOEXEC);
    if (saved_ >= 0 && null >= 0) dup2(null, STDERR_FILENO);
    if (null >= 0) close(null);
  }
  ~StderrShut() {
    if (saved_ < 0) return;
    dup2(saved_, STDERR_FILENO);
    close(saved_);
  }
  StderrShut(const StderrShut&) = delete;
  StderrShut& operator=(const StderrShut&) = delete;

 private:
  int saved_;
};

}  // namespace rm
