#include "window/shot_writer.h"

#include <iostream>
#include <new>
#include <optional>
#include <string>

#include "window/steady_ns.h"

namespace rm {

ShotWriter::ShotWriter(bool verbose) : verbose_(verbose), thread_([this] { run(); }) {}

ShotWriter::~ShotWriter() { finish(); }

void ShotWriter::finish() {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    closing_ = true;
  }
  wake_.notify_one();
  if (thread_.joinable()) thread_.join();
}

void ShotWriter::write(Image image, std::filesystem::path path, Metadata metadata) {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    queue_.push_back(Shot{std::move(image), std::move(path), std::move(metadata)});
  }
  wake_.notify_one();
}

void ShotWriter::run() {
  for (;;) {
    Shot shot;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [this] { return closing_ || !queue_.empty(); });
      if (queue_.empty()) return;  // closing, and every shot written
      shot = std::move(queue_.front());
      queue_.pop_front();
    }
    const long long start = steady_ns();
    std::string error = "not enough memory to write it";
    std::optional<std::filesystem::path> written;
    try {
      written = write_image(shot.path, shot.image, shot.metadata, Overwrite::Never, &error);
    } catch (const std::bad_alloc&) {
    }
    // One write each, whole lines: the window's thread writes too.
    if (written) std::cout << ("screenshot: " + written->string() + "\n") << std::flush;
    else std::cerr << ("raymarching: error: screenshot: " + error + "\n");
    if (verbose_) {
      const long long end = steady_ns();
      std::cerr << ("raymarching: screenshot writer done in " + std::to_string((end - start) / 1e6) + " ms at " +
                    std::to_string(end) + "\n");
    }
  }
}

}  // namespace rm
