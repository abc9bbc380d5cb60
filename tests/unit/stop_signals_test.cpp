// The signals that ask a program to stop are caught even where the process
// has no file descriptor left to make their pipe with.
#include "core/stop_signals.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>

namespace rm {
namespace {

// A window near its ulimit -n made its pipe after the scene, the watcher
// and the GL driver had taken the descriptors: there was none left, the
// signal was not caught, and SIGTERM ended the window with its take unwritten.
TEST(StopSignalsDeathTest, ASignalIsCaughtWithNoFileDescriptorLeft) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        StopSignals::prepare();  // as main() does, first
        rlimit few{};
        few.rlim_cur = few.rlim_max = 64;
        setrlimit(RLIMIT_NOFILE, &few);
        while (open("/dev/null", O_RDONLY | O_CLOEXEC) >= 0) {
        }
        StopSignals signals;
        raise(SIGTERM);
        std::_Exit(signals.received() == SIGTERM ? 0 : 3);
      },
      testing::ExitedWithCode(0), "");
}

// The pipe outlives each StopSignals: what one was sent, the next is not.
TEST(StopSignalsTest, WhatOneWasSentTheNextIsNot) {
  {
    StopSignals first;
    ASSERT_GE(first.fd(), 0);
    first.wake();
  }
  StopSignals second;
  ASSERT_GE(second.fd(), 0);
  unsigned char byte = 0;
  EXPECT_EQ(read(second.fd(), &byte, 1), -1) << "a byte left from the first";
  EXPECT_EQ(second.received(), 0);
}

}  // namespace
}  // namespace rm
