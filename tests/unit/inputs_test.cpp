// Inputs: Shadertoy's iMouse rules, the pausable clock and iDate.
#include "core/inputs.h"

#include <gtest/gtest.h>

#include <ctime>

namespace rm {
namespace {

TEST(Mouse, FollowsShadertoySemantics) {
  MouseState m;
  EXPECT_EQ(m.imouse(), glm::vec4(0.0f));
  m.move({5, 6});  // hovering does not move iMouse
  EXPECT_EQ(m.imouse(), glm::vec4(0.0f));
  EXPECT_EQ(m.cursor(), glm::vec2(5, 6));

  m.press({10, 20});  // the press frame: z and w positive
  EXPECT_EQ(m.imouse(), glm::vec4(10, 20, 10, 20));
  m.end_frame();  // later frames while held: w negative
  EXPECT_EQ(m.imouse(), glm::vec4(10, 20, 10, -20));
  m.move({30, 40});  // drag: xy follows
  EXPECT_EQ(m.imouse(), glm::vec4(30, 40, 10, -20));
  m.release();  // release: xy stays, z negated
  EXPECT_EQ(m.imouse(), glm::vec4(30, 40, -10, -20));
  m.move({50, 60});
  EXPECT_EQ(m.imouse(), glm::vec4(30, 40, -10, -20));
}

TEST(Mouse, PressAndReleaseInOneFrameStillReportsTheClick) {
  MouseState m;
  m.press({3, 4});
  m.release();
  EXPECT_EQ(m.imouse(), glm::vec4(3, 4, -3, 4));
  m.end_frame();
  EXPECT_EQ(m.imouse(), glm::vec4(3, 4, -3, -4));
}

TEST(Clock, PausesStepsAndRestarts) {
  using namespace std::chrono_literals;
  const auto t0 = ShaderClock::Clock::time_point{};
  ShaderClock clock(t0);
  EXPECT_FLOAT_EQ(clock.tick(t0 + 500ms), 0.5f);
  EXPECT_DOUBLE_EQ(clock.time(), 0.5);
  clock.set_paused(true);
  EXPECT_FLOAT_EQ(clock.tick(t0 + 1500ms), 0.0f);
  EXPECT_DOUBLE_EQ(clock.time(), 0.5);
  clock.step(0.25);
  EXPECT_DOUBLE_EQ(clock.time(), 0.75);
  clock.step(-5.0);
  EXPECT_DOUBLE_EQ(clock.time(), 0.0);
  clock.next_frame();
  clock.restart();
  EXPECT_EQ(clock.frame(), 0);
}

TEST(Clock, RunsAtItsSpeedAndSeeks) {
  using namespace std::chrono_literals;
  const auto t0 = ShaderClock::Clock::time_point{};
  ShaderClock clock(t0);
  clock.set_speed(2.0);
  EXPECT_FLOAT_EQ(clock.tick(t0 + 500ms), 1.0f);  // iTimeDelta is shader time too
  EXPECT_DOUBLE_EQ(clock.time(), 1.0);
  clock.set_speed(0.01);
  EXPECT_DOUBLE_EQ(clock.speed(), ShaderClock::kMinSpeed);
  clock.set_speed(10.0);
  EXPECT_DOUBLE_EQ(clock.speed(), ShaderClock::kMaxSpeed);
  clock.seek(7.25);
  EXPECT_DOUBLE_EQ(clock.time(), 7.25);
  clock.seek(-1.0);
  EXPECT_DOUBLE_EQ(clock.time(), 0.0);
}

TEST(Clock, FrameRateIsFramesPerWallSecondHeldWhilePaused) {
  using namespace std::chrono_literals;
  const auto t0 = ShaderClock::Clock::time_point{};
  ShaderClock clock(t0);
  clock.set_speed(2.0);
  clock.tick(t0 + 20ms);
  EXPECT_FLOAT_EQ(clock.frame_rate(), 50.0f);  // 50 frames a second, whatever the clock's speed
  clock.set_paused(true);
  clock.tick(t0 + 1020ms);  // a redraw of the paused moment, a second later
  EXPECT_FLOAT_EQ(clock.frame_rate(), 50.0f);
  clock.set_paused(false);
  clock.tick(t0 + 1060ms);
  EXPECT_FLOAT_EQ(clock.frame_rate(), 25.0f);
}

TEST(Date, IsYearMonthFromZeroDaySecondsSinceMidnight) {
  std::tm tm{};
  tm.tm_year = 2024 - 1900;
  tm.tm_mon = 1;  // February
  tm.tm_mday = 29;
  tm.tm_hour = 13;
  tm.tm_min = 14;
  tm.tm_sec = 15;
  tm.tm_isdst = -1;
  auto when = std::chrono::system_clock::from_time_t(std::mktime(&tm)) + std::chrono::milliseconds(250);
  EXPECT_EQ(date_of(when), glm::vec4(2024, 1, 29, 13 * 3600 + 14 * 60 + 15.25f));
}

}  // namespace
}  // namespace rm
