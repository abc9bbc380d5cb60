#include "core/stderr_shut.h"

#include <cerrno>
#include <iostream>
#include <streambuf>

namespace rm {

namespace {

// Unbuffered, as std::cerr is: each write goes out whole, at once.
class FdWriter : public std::streambuf {
 public:
  explicit FdWriter(int fd) : fd_(fd) {}

 protected:
  int overflow(int c) override {
    if (c == traits_type::eof()) return 0;
    const char byte = static_cast<char>(c);
    return write_all(&byte, 1) ? c : traits_type::eof();
  }
  std::streamsize xsputn(const char* s, std::streamsize n) override { return write_all(s, n) ? n : 0; }

 private:
  bool write_all(const char* s, std::streamsize n) {
    while (n > 0) {
      const ssize_t written = write(fd_, s, static_cast<size_t>(n));
      if (written < 0 && errno == EINTR) continue;
      if (written <= 0) return false;
      s += written;
      n -= written;
    }
    return true;
  }
  int fd_;
};

}  // namespace

void send_cerr_past_shuts() {
  static const int copy = fcntl(STDERR_FILENO, F_DUPFD_CLOEXEC, 0);
  if (copy < 0) return;
  // Never destroyed: std::cerr is flushed at exit, after every static.
  static FdWriter* const writer = new FdWriter(copy);
  std::cerr.rdbuf(writer);
}

}  // namespace rm
