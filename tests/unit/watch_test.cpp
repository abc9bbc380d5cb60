// Watcher: each way editors save a file gives exactly one change, for both
// backends; includes are watched; a half-written file is not reported.
#include "core/watch.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <thread>

#include "core/wake_on_readable.h"
#include "support.h"

namespace rm {
namespace {

using namespace std::chrono_literals;
using test::TempDir;
using test::write_file;

// Counts settled changes reported during `window`.
int changes_during(Watcher& w, std::chrono::milliseconds window) {
  int n = 0;
  const auto end = WatchClock::now() + window;
  while (WatchClock::now() < end) {
    if (w.changed()) ++n;
    std::this_thread::sleep_for(2ms);
  }
  return n;
}

// Long enough for the quiet period and the grace for deleted files.
constexpr auto kSettle = 600ms;

class WatchTest : public ::testing::TestWithParam<WatchBackend> {
 protected:
  void SetUp() override {
    scene_ = dir_ / "scene.frag";
    include_ = dir_ / "lib" / "inc.glsl";
    write_file(scene_, "v1\n");
    write_file(include_, "i1\n");
    write_file(dir_ / "other.txt", "x\n");
    watcher_ = make_watcher(GetParam());
    ASSERT_TRUE(watcher_);
    watcher_->watch({scene_, include_});
    ASSERT_EQ(changes_during(*watcher_, 50ms), 0);
  }

  TempDir dir_;
  std::filesystem::path scene_, include_;
  std::unique_ptr<Watcher> watcher_;
};

TEST_P(WatchTest, InPlaceWrite) {
  write_file(scene_, "v2 longer\n");
  EXPECT_EQ(changes_during(*watcher_, kSettle), 1);
}

TEST_P(WatchTest, WriteTemporaryThenRename) {
  write_file(dir_ / ".scene.frag.swp", "v2\n");
  std::filesystem::rename(dir_ / ".scene.frag.swp", scene_);
  EXPECT_EQ(changes_during(*watcher_, kSettle), 1);
}

TEST_P(WatchTest, VimStyleBackupRenameThenWrite) {
  write_file(dir_ / "4913", "");
  std::filesystem::remove(dir_ / "4913");
  std::filesystem::rename(scene_, dir_ / "scene.frag~");
  write_file(scene_, "v2 from vim\n");
  std::filesystem::remove(dir_ / "scene.frag~");
  EXPECT_EQ(changes_during(*watcher_, kSettle), 1);
}

TEST_P(WatchTest, DeleteThenRecreate) {
  std::filesystem::remove(scene_);
  std::this_thread::sleep_for(40ms);
  write_file(scene_, "v2 recreated\n");
  EXPECT_EQ(changes_during(*watcher_, kSettle), 1);
}

TEST_P(WatchTest, SedInPlace) {
  ASSERT_EQ(std::system(("sed -i s/v1/v2/ '" + scene_.string() + "'").c_str()), 0);
  EXPECT_EQ(changes_during(*watcher_, kSettle), 1);
}

TEST_P(WatchTest, GitCheckout) {
  const std::string git = "git -C '" + dir_.path().string() + "' -c user.name=t -c user.email=t@t ";
  ASSERT_EQ(std::system((git + "init -q && " + git + "add -A && " + git + "commit -qm one").c_str()), 0);
  write_file(scene_, "v2 committed\n");
  ASSERT_EQ(std::system((git + "commit -qam two").c_str()), 0);
  changes_during(*watcher_, kSettle);  // the edit above
  ASSERT_EQ(std::system((git + "checkout -q HEAD~1 -- scene.frag").c_str()), 0);
  EXPECT_EQ(changes_during(*watcher_, kSettle), 1);
  EXPECT_EQ(test::read_file(scene_), "v1\n");
}

TEST_P(WatchTest, BurstOfWritesIsOneChange) {
  for (int i = 0; i < 20; ++i) {
    write_file(scene_, "burst " + std::to_string(i) + "\n");
    std::this_thread::sleep_for(2ms);
  }
  EXPECT_EQ(changes_during(*watcher_, kSettle), 1);
}

TEST_P(WatchTest, IncludeChangeIsAChange) {
  write_file(include_, "i2\n");
  EXPECT_EQ(changes_during(*watcher_, kSettle), 1);
}

TEST_P(WatchTest, OtherFilesInTheDirectoryAreIgnored) {
  write_file(dir_ / "other.txt", "y\n");
  EXPECT_EQ(changes_during(*watcher_, kSettle), 0);
}

TEST_P(WatchTest, NewWatchListIsHonoured) {
  watcher_->watch({scene_});
  write_file(include_, "i2\n");
  EXPECT_EQ(changes_during(*watcher_, kSettle), 0);
}

// A scene opened through a symbolic link, saved where the link points: by
// rename there (the editor opened the target), in place through the link,
// and the link pointed at another file.
TEST_P(WatchTest, ASceneOpenedThroughALinkIsWatchedWhereItLives) {
  const auto link = dir_ / "link" / "scene.frag";
  std::filesystem::create_directories(link.parent_path());
  std::filesystem::create_symlink("../scene.frag", link);
  watcher_->watch({link});
  write_file(dir_ / ".scene.frag.swp", "v2\n");
  std::filesystem::rename(dir_ / ".scene.frag.swp", scene_);
  EXPECT_EQ(changes_during(*watcher_, kSettle), 1) << "the target saved by rename";
  write_file(link, "v3 through the link\n");
  EXPECT_EQ(changes_during(*watcher_, kSettle), 1) << "written in place through the link";
  EXPECT_EQ(test::read_file(scene_), "v3 through the link\n");
  std::filesystem::remove(link);
  std::filesystem::create_symlink("../other.txt", link);
  EXPECT_EQ(changes_during(*watcher_, kSettle), 1) << "the link pointed elsewhere";
}

INSTANTIATE_TEST_SUITE_P(Backends, WatchTest, ::testing::Values(WatchBackend::Inotify, WatchBackend::Poll),
                         [](const auto& info) { return info.param == WatchBackend::Inotify ? "inotify" : "poll"; });

// An inotify watcher of `scene`, written first with "v1".
std::unique_ptr<Watcher> inotify_watching(const std::filesystem::path& scene, WatchTiming timing = {}) {
  write_file(scene, "v1\n");
  auto w = make_watcher(WatchBackend::Inotify, timing);
  w->watch({scene});
  return w;
}

TEST(InotifyWatch, HalfWrittenFileIsNotReportedUntilClosed) {
  TempDir dir;
  const auto scene = dir / "scene.frag";
  auto w = inotify_watching(scene);
  int fd = open(scene.c_str(), O_WRONLY | O_TRUNC);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(write(fd, "void mainImage(", 15), 15);
  EXPECT_EQ(changes_during(*w, 300ms), 0);  // still open for writing
  ASSERT_EQ(write(fd, "...)\n", 5), 5);
  close(fd);
  EXPECT_EQ(changes_during(*w, kSettle), 1);
}

// A rename puts a whole file in place: it is a change at once, where a write
// waits for the quiet period (long here, so that the difference shows).
TEST(InotifyWatch, ARenameIsReportedWithoutTheQuietPeriod) {
  TempDir dir;
  const auto scene = dir / "scene.frag";
  WatchTiming timing;
  timing.quiet = 400ms;
  auto w = inotify_watching(scene, timing);
  write_file(dir / ".scene.frag.tmp", "v2\n");
  std::filesystem::rename(dir / ".scene.frag.tmp", scene);
  EXPECT_TRUE(w->changed());
  EXPECT_EQ(changes_during(*w, 600ms), 0);  // and once
  write_file(scene, "v3 in place\n");
  EXPECT_EQ(changes_during(*w, 200ms), 0);  // within the quiet period
  EXPECT_EQ(changes_during(*w, 600ms), 1);
}


// The window sleeps until a save instead of waking every 20 ms to ask: the
// watcher's descriptor wakes it, once per rearm(), and a burst still
// settling says so (the loop must then ask again soon, events or not).
TEST(InotifyWatch, ASaveWakesASleepingLoopOncePerRearm) {
  TempDir dir;
  const auto scene = dir / "scene.frag";
  auto w = inotify_watching(scene);
  std::atomic<int> wakes{0};
  WakeOnReadable waker(w->event_fd(), [&] { ++wakes; });
  ASSERT_TRUE(waker.active());
  auto wakes_within = [&](std::chrono::milliseconds limit, int n) {
    const auto end = WatchClock::now() + limit;
    while (wakes < n && WatchClock::now() < end) std::this_thread::sleep_for(1ms);
    return wakes.load();
  };
  std::this_thread::sleep_for(50ms);
  EXPECT_EQ(wakes, 0) << "nothing happened yet";
  write_file(scene, "v2 in place\n");
  EXPECT_EQ(wakes_within(2000ms, 1), 1);
  write_file(scene, "v3 in place\n");
  std::this_thread::sleep_for(100ms);
  EXPECT_EQ(wakes, 1) << "woken again before the loop read the first";
  EXPECT_FALSE(w->changed());  // the loop reads: the burst is noted, not settled
  EXPECT_TRUE(w->settling());
  waker.rearm();
  EXPECT_EQ(changes_during(*w, kSettle), 1);
  EXPECT_FALSE(w->settling());
  waker.rearm();
  write_file(dir / ".scene.frag.tmp", "v4\n");
  std::filesystem::rename(dir / ".scene.frag.tmp", scene);
  EXPECT_EQ(wakes_within(2000ms, 2), 2) << "the next save, after rearm()";
}

TEST(PollWatch, HasNoDescriptorToSleepOn) {
  auto w = make_watcher(WatchBackend::Poll);
  EXPECT_EQ(w->event_fd(), -1);
  WakeOnReadable waker(w->event_fd(), [] {});
  EXPECT_FALSE(waker.active());
}

}  // namespace
}  // namespace rm
