#include "core/watch.h"

#include <sys/inotify.h>
#include <sys/stat.h>
#include <unistd.h>

#include <map>

namespace rm {

void Debouncer::note(WatchClock::time_point now, const fs::path& file, Event event) {
  pending_ = true;
  renamed_last_ = event == Event::RenamedOnto;
  last_ = now;
  touched_.insert(file);
  if (event == Event::Writing) writing_.insert(file);
  else writing_.erase(file);
}

bool Debouncer::settled(WatchClock::time_point now) {
  if (!pending_) return false;
  const auto since = now - last_;
  if (since < timing_.quiet && !(renamed_last_ && writing_.empty())) return false;
  if (!writing_.empty() && since < timing_.open_write_limit) return false;
  if (since < timing_.missing_grace) {
    for (const auto& file : touched_) {
      std::error_code ec;
      if (!fs::exists(file, ec)) return false;  // deleted: give it a moment to come back
    }
  }
  pending_ = false;
  touched_.clear();
  writing_.clear();
  return true;
}

namespace {

bool is_link(const fs::path& file) {
  std::error_code ec;
  return fs::is_symlink(file, ec);
}

class InotifyWatcher final : public Watcher {
 public:
  InotifyWatcher(int fd, WatchTiming timing) : fd_(fd), debounce_(timing) {}
  ~InotifyWatcher() override { close(fd_); }

  void watch(const std::vector<fs::path>& files) override {
    files_.clear();
    for (const auto& f : files) {
      files_.insert(f);
      // A save through a symbolic link lands in its target's folder, whose
      // events the link's folder never sees: watch the target as well.
      if (is_link(f)) {
        std::error_code ec;
        fs::path target = fs::canonical(f, ec);
        if (!ec) files_.insert(std::move(target));
      }
    }
    std::set<fs::path> dirs;
    for (const auto& f : files_) dirs.insert(f.parent_path());
    for (auto it = dirs_.begin(); it != dirs_.end();) {
      if (dirs.count(it->second)) {
        ++it;
      } else {
        inotify_rm_watch(fd_, it->first);
        it = dirs_.erase(it);
      }
    }
    constexpr uint32_t mask = IN_MODIFY | IN_CLOSE_WRITE | IN_CREATE | IN_DELETE | IN_MOVED_FROM | IN_MOVED_TO;
    for (const auto& dir : dirs) {
      int wd = inotify_add_watch(fd_, dir.c_str(), mask);
      if (wd >= 0) dirs_[wd] = dir;  // a missing directory simply is not watched
    }
  }

  bool changed(WatchClock::time_point now) override {
    alignas(inotify_event) char buffer[16384];
    for (;;) {
      ssize_t n = read(fd_, buffer, sizeof buffer);
      if (n <= 0) break;
      for (char* p = buffer; p < buffer + n;) {
        const auto* event = reinterpret_cast<const inotify_event*>(p);
        p += sizeof(inotify_event) + event->len;
        auto dir = dirs_.find(event->wd);
        if (dir == dirs_.end() || event->len == 0) continue;
        const fs::path file = dir->second / event->name;
        if (!files_.count(file)) continue;
        using E = Debouncer::Event;
        const E kind = (event->mask & IN_CREATE) && is_link(file) ? E::Closed  // made whole, never written
                       : (event->mask & (IN_MODIFY | IN_CREATE))  ? E::Writing
                       : (event->mask & (IN_DELETE | IN_MOVED_FROM)) ? E::Gone
                       : (event->mask & IN_MOVED_TO)                  ? E::RenamedOnto
                                                                    : E::Closed;
        debounce_.note(now, file, kind);
      }
    }
    return debounce_.settled(now);
  }

  const char* backend() const override { return "inotify"; }
  int event_fd() const override { return fd_; }
  bool settling() const override { return debounce_.pending(); }

 private:
  int fd_;
  Debouncer debounce_;
  std::set<fs::path> files_;
  std::map<int, fs::path> dirs_;
};

class PollWatcher final : public Watcher {
 public:
  explicit PollWatcher(WatchTiming timing) : timing_(timing), debounce_(timing) {}

  void watch(const std::vector<fs::path>& files) override {
    std::map<fs::path, Stamp> next;
    for (const auto& f : files) {
      auto it = stamps_.find(f);
      next[f] = it != stamps_.end() ? it->second : stamp(f);
    }
    stamps_ = std::move(next);
  }

  bool changed(WatchClock::time_point now) override {
    if (now - last_poll_ >= timing_.poll_interval) {
      last_poll_ = now;
      for (auto& [file, old] : stamps_) {
        Stamp fresh = stamp(file);
        if (fresh == old) continue;
        old = fresh;
        debounce_.note(now, file, fresh.exists ? Debouncer::Event::Closed : Debouncer::Event::Gone);
      }
    }
    return debounce_.settled(now);
  }

  const char* backend() const override { return "poll"; }
  bool settling() const override { return debounce_.pending(); }

 private:
  struct Stamp {
    bool exists = false;
    long long mtime_ns = 0;
    long long size = 0;
    long long inode = 0;
    bool operator==(const Stamp&) const = default;
  };
  static Stamp stamp(const fs::path& file) {
    struct stat st {};
    if (stat(file.c_str(), &st) != 0) return {};
    return {true, st.st_mtim.tv_sec * 1000000000LL + st.st_mtim.tv_nsec, static_cast<long long>(st.st_size),
            static_cast<long long>(st.st_ino)};
  }

  WatchTiming timing_;
  Debouncer debounce_;
  std::map<fs::path, Stamp> stamps_;
  WatchClock::time_point last_poll_{};
};

}  // namespace

std::unique_ptr<Watcher> make_watcher(WatchBackend backend, WatchTiming timing) {
  if (backend != WatchBackend::Poll) {
    int fd = inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
    if (fd >= 0) return std::make_unique<InotifyWatcher>(fd, timing);
    if (backend == WatchBackend::Inotify) return nullptr;
  }
  return std::make_unique<PollWatcher>(timing);
}

}  // namespace rm
