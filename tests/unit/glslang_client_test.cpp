// The glslang worker, seen from the host: its replies over the socket (a
// garbled one is none); one process answers request after request, one that
// went away is started again, and requests are answered while another thread
// of the host allocates (a fork of the host itself could hang on a lock that
// thread held).
#include "core/glslang_client.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/types.h>
#include <unistd.h>

#include <atomic>
#include <cstdint>
#include <optional>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "support.h"

namespace rm {
namespace {

GlslangRequest undeclared_name() {
  GlslangRequest request;
  request.version_line = "#version 450 core";
  request.text = "#version 450 core\nout vec4 colour;\nvoid main() { colour = vec4(nope); }\n";
  return request;
}

bool names_the_undeclared_name(const GlslangReply& reply) {
  return reply.status == GlslangReply::Status::Ok &&
         reply.output.find("ERROR: 0:3: 'nope' : undeclared identifier") != std::string::npos;
}

// The pids of this process's children that run the worker (its name as the
// kernel keeps it is cut to 15 characters).
std::vector<pid_t> worker_pids() {
  std::vector<pid_t> pids;
  for (pid_t pid : test::children_of(getpid())) {
    std::ifstream comm("/proc/" + std::to_string(pid) + "/comm");
    std::string name;
    if (std::getline(comm, name) && name.rfind("raymarching-gls", 0) == 0) pids.push_back(pid);
  }
  return pids;
}

TEST(GlslangWorker, OneWorkerAnswersRequestAfterRequest) {
  ASSERT_TRUE(names_the_undeclared_name(ask_glslang(undeclared_name())));
  const std::vector<pid_t> first = worker_pids();
  ASSERT_EQ(first.size(), 1u);
  GlslangRequest preprocess;
  preprocess.kind = GlslangRequest::Kind::Preprocess;
  preprocess.text = "#version 450 core\n#define TWICE(x) (2.0 * (x))\nfloat y = TWICE(3.0);\n";
  const GlslangReply expanded = ask_glslang(preprocess);
  ASSERT_EQ(expanded.status, GlslangReply::Status::Ok);
  EXPECT_NE(expanded.output.find("+#version 450 core"), std::string::npos) << expanded.output;
  // glslang drops the blank before a macro's expansion.
  EXPECT_NE(expanded.output.find("float y =(2.0 *(3.0));"), std::string::npos) << expanded.output;
  EXPECT_EQ(worker_pids(), first);
}

// The window and `render` start the worker while they open their display:
// the first shader is then answered by that worker, not by one it starts.
TEST(GlslangWorker, AWarmUpStartsTheWorkerThatAnswersTheFirstShader) {
  // ctest runs each test in a process of its own; run in one with the others,
  // this one finds their worker, which goes first so the warm-up must start one.
  for (pid_t pid : worker_pids()) ASSERT_EQ(kill(pid, SIGKILL), 0);
  { GlslangWarmUp warm_up("#version 450 core"); }
  const std::vector<pid_t> warmed = worker_pids();
  ASSERT_EQ(warmed.size(), 1u);
  EXPECT_TRUE(names_the_undeclared_name(ask_glslang(undeclared_name())));
  EXPECT_EQ(worker_pids(), warmed);
}

TEST(GlslangWorker, AWorkerThatWasKilledIsStartedAgain) {
  ASSERT_TRUE(names_the_undeclared_name(ask_glslang(undeclared_name())));
  const std::vector<pid_t> killed = worker_pids();
  ASSERT_EQ(killed.size(), 1u);
  ASSERT_EQ(kill(killed[0], SIGKILL), 0);
  const GlslangReply reply = ask_glslang(undeclared_name());
  EXPECT_TRUE(names_the_undeclared_name(reply)) << reply.output;
  const std::vector<pid_t> now = worker_pids();
  ASSERT_EQ(now.size(), 1u);
  EXPECT_NE(now[0], killed[0]);
}

TEST(GlslangWorker, AnswersWhileAnotherThreadAllocates) {
  // The window's thread draws and allocates while its builder thread asks
  // for validation; under the sanitizers, about one fork in a thousand of
  // such a process hung in its child for good.
  std::atomic<bool> stop{false};
  std::thread allocating([&] {
    while (!stop) {
      std::vector<std::string> strings;
      for (int i = 0; i < 100; ++i) strings.emplace_back(100 + i, 'x');
    }
  });
  int answered = 0;
  for (int i = 0; i < 200; ++i) answered += names_the_undeclared_name(ask_glslang(undeclared_name()));
  stop = true;
  allocating.join();
  EXPECT_EQ(answered, 200);
}

// A reply goes over the socket as it came; one whose status or signal is
// not a number the host knows is no reply, not an exception.
TEST(GlslangProtocol, AReplyRoundTripsAndAGarbledOneIsNone) {
  int fds[2];
  ASSERT_EQ(socketpair(AF_UNIX, SOCK_STREAM, 0, fds), 0);
  GlslangReply sent;
  sent.status = GlslangReply::Status::Crashed;
  sent.signal = SIGSEGV;
  sent.output = std::string("a\0b", 3);
  ASSERT_TRUE(write_reply(fds[0], sent));
  const std::optional<GlslangReply> got = read_reply(fds[1], std::nullopt);
  ASSERT_TRUE(got);
  EXPECT_EQ(got->status, sent.status);
  EXPECT_EQ(got->signal, SIGSEGV);
  EXPECT_EQ(got->output, sent.output);
  // The same framing as write_reply: a count, then each string's length and bytes.
  auto raw = [&](const std::vector<std::string>& strings) {
    std::string bytes;
    const std::uint64_t count = strings.size();
    bytes.append(reinterpret_cast<const char*>(&count), sizeof count);
    for (const std::string& text : strings) {
      const std::uint64_t size = text.size();
      bytes.append(reinterpret_cast<const char*>(&size), sizeof size);
      bytes += text;
    }
    ASSERT_EQ(write(fds[0], bytes.data(), bytes.size()), static_cast<ssize_t>(bytes.size()));
  };
  for (const auto& [status, signal] : std::vector<std::pair<std::string, std::string>>{
           {"x", "0"}, {"", "0"}, {"99", "0"}, {"-1", "0"}, {"1", "9x"}, {"99999999999999999999", "0"}}) {
    raw({status, signal, "out"});
    EXPECT_FALSE(read_reply(fds[1], std::nullopt)) << status << " " << signal;
  }
  raw({"0", "0", "fine"});
  const std::optional<GlslangReply> after = read_reply(fds[1], std::nullopt);
  ASSERT_TRUE(after);
  EXPECT_EQ(after->output, "fine");
  close(fds[0]);
  close(fds[1]);
}

}  // namespace
}  // namespace rm
