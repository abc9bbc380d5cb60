#include "core/image.h"

#include <algorithm>

namespace rm {

Image Image::flipped() const {
  Image out{width, height, std::vector<float>(rgba.size())};
  const size_t stride = static_cast<size_t>(width) * 4;
  for (int y = 0; y < height; ++y)
    std::copy_n(&rgba[static_cast<size_t>(height - 1 - y) * stride], stride, &out.rgba[static_cast<size_t>(y) * stride]);
  return out;
}

}  // namespace rm
