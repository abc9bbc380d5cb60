#include "glslang_worker/protocol.h"

#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <system_error>
#include <vector>

namespace rm {

namespace {

using Clock = std::chrono::steady_clock;

bool write_all(int fd, const char* bytes, size_t size) {
  while (size > 0) {
    // MSG_NOSIGNAL: a worker that died is an error to report, not a SIGPIPE.
    const ssize_t n = send(fd, bytes, size, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    bytes += n;
    size -= static_cast<size_t>(n);
  }
  return true;
}

bool read_all(int fd, char* bytes, size_t size, ReplyDeadline deadline) {
  while (size > 0) {
    if (deadline) {
      const auto left = std::chrono::ceil<std::chrono::milliseconds>(*deadline - Clock::now()).count();
      if (left <= 0) return false;
      pollfd ready{fd, POLLIN, 0};
      const int polled = poll(&ready, 1, static_cast<int>(left));
      if (polled == 0 || (polled < 0 && errno == EINTR)) continue;
      if (polled < 0) return false;
    }
    const ssize_t n = read(fd, bytes, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    bytes += n;
    size -= static_cast<size_t>(n);
  }
  return true;
}

// A message: the number of strings, then each string's length and bytes.
bool write_strings(int fd, const std::vector<std::string>& strings) {
  std::string out;
  const std::uint64_t count = strings.size();
  out.append(reinterpret_cast<const char*>(&count), sizeof count);
  for (const std::string& s : strings) {
    const std::uint64_t size = s.size();
    out.append(reinterpret_cast<const char*>(&size), sizeof size);
    out += s;
  }
  return write_all(fd, out.data(), out.size());
}

std::optional<std::vector<std::string>> read_strings(int fd, ReplyDeadline deadline, size_t expected) {
  std::uint64_t count = 0;
  if (!read_all(fd, reinterpret_cast<char*>(&count), sizeof count, deadline) || count != expected) return std::nullopt;
  std::vector<std::string> strings(expected);
  for (std::string& s : strings) {
    std::uint64_t size = 0;
    if (!read_all(fd, reinterpret_cast<char*>(&size), sizeof size, deadline)) return std::nullopt;
    s.resize(size);
    if (!read_all(fd, s.data(), s.size(), deadline)) return std::nullopt;
  }
  return strings;
}

}  // namespace

bool write_request(int fd, const GlslangRequest& r) {
  return write_strings(fd, {r.kind == GlslangRequest::Kind::Validate ? "validate" : "preprocess", r.version_line,
                            r.text, r.active_text ? "1" : "0", r.active_text.value_or("")});
}

std::optional<GlslangRequest> read_request(int fd) {
  const auto s = read_strings(fd, std::nullopt, 5);
  if (!s) return std::nullopt;
  GlslangRequest r;
  r.kind = (*s)[0] == "validate" ? GlslangRequest::Kind::Validate : GlslangRequest::Kind::Preprocess;
  r.version_line = (*s)[1];
  r.text = (*s)[2];
  if ((*s)[3] == "1") r.active_text = (*s)[4];
  return r;
}

bool write_reply(int fd, const GlslangReply& r) {
  return write_strings(fd, {std::to_string(static_cast<int>(r.status)), std::to_string(r.signal), r.output});
}

std::optional<GlslangReply> read_reply(int fd, ReplyDeadline deadline) {
  const auto s = read_strings(fd, deadline, 3);
  if (!s) return std::nullopt;
  // A reply that does not parse is no reply (the worker is ours: a bug).
  auto number = [](const std::string& text) -> std::optional<int> {
    int value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
    return value;
  };
  const auto status = number((*s)[0]);
  const auto signal = number((*s)[1]);
  if (!status || *status < 0 || *status > static_cast<int>(GlslangReply::Status::NoWorker) || !signal)
    return std::nullopt;
  GlslangReply r;
  r.status = static_cast<GlslangReply::Status>(*status);
  r.signal = *signal;
  r.output = (*s)[2];
  return r;
}

}  // namespace rm
