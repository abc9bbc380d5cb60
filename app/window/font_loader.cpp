#include "window/font_loader.h"

#include <utility>

namespace rm {

FontLoader::FontLoader(InterfaceFonts& fonts, std::function<void()> on_built)
    : fonts_(fonts), on_built_(std::move(on_built)), thread_([this] { run(); }) {}

FontLoader::~FontLoader() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_one();
  thread_.join();
}

void FontLoader::ask(std::vector<ImWchar> letters) {
  if (letters.empty()) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    asked_.insert(asked_.end(), letters.begin(), letters.end());
  }
  wake_.notify_one();
}

bool FontLoader::ready() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return built_.has_value();
}

std::optional<InterfaceFonts::Atlas> FontLoader::take() {
  std::lock_guard<std::mutex> lock(mutex_);
  return std::exchange(built_, std::nullopt);
}

void FontLoader::run() {
  for (;;) {
    std::vector<ImWchar> letters;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] { return stop_ || !asked_.empty(); });
      if (stop_) return;
      letters.swap(asked_);
    }
    if (!fonts_.find(letters)) continue;
    InterfaceFonts::Atlas atlas = fonts_.make_atlas();
    unsigned char* pixels = nullptr;
    int width = 0, height = 0;
    atlas.atlas->GetTexDataAsRGBA32(&pixels, &width, &height);  // rasterised here, not on the window's thread
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (stop_) return;
      built_ = std::move(atlas);  // replaces one not taken: this one has its letters too
    }
    if (on_built_) on_built_();
  }
}

}  // namespace rm
