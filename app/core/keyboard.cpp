#include "core/keyboard.h"

#include <algorithm>

namespace rm {

void KeyboardState::press(int code) {
  if (!valid(code) || down(code)) return;
  const size_t k = static_cast<size_t>(code);
  texels_[k] = 255;
  texels_[kKeys + k] = 255;
  texels_[2 * kKeys + k] ^= 255;
}

void KeyboardState::release(int code) {
  if (valid(code)) texels_[static_cast<size_t>(code)] = 0;
}

void KeyboardState::end_frame() { std::fill_n(texels_.begin() + kKeys, kKeys, std::uint8_t{0}); }

void KeyboardState::clear() { texels_.fill(0); }

}  // namespace rm
