// ShotWriter: encodes and writes the window's screenshots on a thread of its
// own, one after another, so that the window keeps drawing meanwhile:
// encoding a PNG and syncing it to disk held the window (see
// docs/performance.md). Each shot says where it went as it did before:
// "screenshot: PATH" on stdout, or its error on stderr.
#pragma once
#include <condition_variable>
#include <deque>
#include <filesystem>
#include <mutex>
#include <thread>

#include "core/capture.h"
#include "core/image.h"

namespace rm {

class ShotWriter {
 public:
  // `verbose`: -v, which logs when each shot is written.
  explicit ShotWriter(bool verbose);
  ~ShotWriter();  // writes every shot handed over before it returns
  ShotWriter(const ShotWriter&) = delete;
  ShotWriter& operator=(const ShotWriter&) = delete;

  // Queues `image` for `path` (a new file: an existing one is never
  // replaced, the name is numbered instead).
  void write(Image image, std::filesystem::path path, Metadata metadata);
  // Writes every shot queued, then takes no more.
  void finish();

 private:
  struct Shot {
    Image image;
    std::filesystem::path path;
    Metadata metadata;
  };
  void run();

  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<Shot> queue_;
  bool closing_ = false;
  const bool verbose_;
  std::thread thread_;  // last: started once the rest is made
};

}  // namespace rm
