// Letters a text needs, added to the interface's fonts on a thread of its
// own. For a new script (a path or a message in Chinese, say), fontconfig's
// lookup, reading the font's file of megabytes and rasterising the atlas
// again held the window's thread for 30 to 50 ms here, in which it drew
// nothing and read no input. The window now draws on with the atlas it has (the new
// letters as the fallback glyph) and takes the new one when it is built.
#pragma once
#include <condition_variable>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "window/fonts.h"

namespace rm {

class FontLoader {
 public:
  // `fonts` is used by the loader's thread alone from now on, and must
  // outlive this object and every atlas it makes; `on_built` is called on
  // that thread when an atlas is ready (to wake the window).
  FontLoader(InterfaceFonts& fonts, std::function<void()> on_built);
  ~FontLoader();  // waits for the lookup under way, if any
  FontLoader(const FontLoader&) = delete;
  FontLoader& operator=(const FontLoader&) = delete;

  // Looks `letters` up and builds an atlas with them if a font has one.
  void ask(std::vector<ImWchar> letters);
  // Whether take() would give an atlas.
  bool ready() const;
  // The newest atlas built since the last take(), built and with its
  // RGBA32 texture data ready for the backend, which has every letter asked
  // before it: the caller's to hold from now on.
  std::optional<InterfaceFonts::Atlas> take();

 private:
  void run();

  InterfaceFonts& fonts_;
  std::function<void()> on_built_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::vector<ImWchar> asked_;                   // letters still to look up
  std::optional<InterfaceFonts::Atlas> built_;   // for take()
  bool stop_ = false;
  std::thread thread_;  // last: it starts once the rest is made
};

}  // namespace rm
