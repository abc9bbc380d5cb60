// The keyboard as Shadertoy hands it to a shader: a 256x3 texture indexed by
// the browser's key code (65 is A, 37 to 40 the arrows). Row 0 holds the
// keys down, row 1 the keys pressed in this frame, row 2 a toggle per key,
// each 255 or 0. No GL and no window system here.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>

namespace rm {

class KeyboardState {
 public:
  static constexpr int kKeys = 256;
  void press(int code);    // a key went down (repeats are ignored)
  void release(int code);
  void end_frame();        // after each drawn frame: nothing is "pressed in this frame" any more
  void clear();            // every key up, every toggle off
  // kKeys * 3 bytes, row by row.
  const std::array<std::uint8_t, kKeys * 3>& texels() const { return texels_; }
  bool down(int code) const { return valid(code) && texels_[static_cast<size_t>(code)] != 0; }

 private:
  static bool valid(int code) { return code >= 0 && code < kKeys; }
  std::array<std::uint8_t, kKeys * 3> texels_{};
};

}  // namespace rm
