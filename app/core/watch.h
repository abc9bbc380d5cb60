// Watch: tells when the files of a scene have changed and settled.
//
// The directories of the files are watched, not the files, so saves that
// replace a file (write a temporary and rename it over the original, as vim,
// VS Code, JetBrains and `sed -i` do), delete-then-recreate and `git
// checkout` are all seen. Bursts are debounced into one change, and a file
// still open for writing is waited for, so a half-written file is not read.
// A rename onto a watched file needs no quiet period: it puts the whole new
// text in place at once, the last step of an editor's save.
// A file that is a symbolic link is watched both as the link (pointed
// elsewhere) and as its target (saved, in place or by rename).
// inotify on Linux; polling of mtime (ns) and size behind the same interface.
#pragma once
#include <chrono>
#include <filesystem>
#include <memory>
#include <set>
#include <vector>

namespace rm {

namespace fs = std::filesystem;
using WatchClock = std::chrono::steady_clock;

struct WatchTiming {
  std::chrono::milliseconds quiet{15};            // no event for this long ends a burst
  std::chrono::milliseconds open_write_limit{1000};  // longest wait for a writer to close
  std::chrono::milliseconds missing_grace{300};   // wait this long for a deleted file to return
  std::chrono::milliseconds poll_interval{20};    // polling backend only
};

// The debounce rules both backends share.
class Debouncer {
 public:
  enum class Event { Writing, Closed, Gone, RenamedOnto };
  explicit Debouncer(WatchTiming timing) : timing_(timing) {}
  void note(WatchClock::time_point now, const fs::path& file, Event event);
  bool settled(WatchClock::time_point now);
  bool pending() const { return pending_; }

 private:
  WatchTiming timing_;
  bool pending_ = false;
  bool renamed_last_ = false;  // the burst's last event put a whole file in place
  WatchClock::time_point last_{};
  std::set<fs::path> touched_;
  std::set<fs::path> writing_;
};

class Watcher {
 public:
  virtual ~Watcher() = default;
  // Replaces the set of watched files (absolute paths).
  virtual void watch(const std::vector<fs::path>& files) = 0;
  // Takes in what happened since the last call; true once per settled change.
  virtual bool changed(WatchClock::time_point now = WatchClock::now()) = 0;
  virtual const char* backend() const = 0;
  // A descriptor that turns readable when something happens in a watched
  // directory, for a loop to sleep on (core/wake_on_readable.h); -1 where
  // there is none (polling), and changed() must be asked every few ms.
  virtual int event_fd() const { return -1; }
  // A burst not settled yet: changed() must be asked again soon, events or not.
  virtual bool settling() const = 0;
};

enum class WatchBackend { Auto, Inotify, Poll };
std::unique_ptr<Watcher> make_watcher(WatchBackend backend = WatchBackend::Auto, WatchTiming timing = {});

}  // namespace rm
