#include "core/image.h"

#include <algorithm>
#include <cmath>

namespace rm {

Image Image::flipped() const {
  Image out{width, height, std::vector<float>(rgba.size())};
  const size_t stride = static_cast<size_t>(width) * 4;
  for (int y = 0; y < height; ++y)
    std::copy_n(&rgba[static_cast<size_t>(height - 1 - y) * stride], stride, &out.rgba[static_cast<size_t>(y) * stride]);
  return out;
}

std::vector<unsigned char> to_rgba8(const Image& image) {
  std::vector<unsigned char> bytes(image.rgba.size());
  std::transform(image.rgba.begin(), image.rgba.end(), bytes.begin(), [](float v) {
    v = std::isnan(v) ? 0.0f : std::clamp(v, 0.0f, 1.0f);
    return static_cast<unsigned char>(v * 255.0f + 0.5f);
  });
  return bytes;
}

void paste(Image& whole, const Image& piece, int x0, int y0) {
  // piece row 0 is its top, which is row whole.height - (y0 + piece.height) of whole.
  const int top = whole.height - (y0 + piece.height);
  for (int y = 0; y < piece.height; ++y)
    std::copy_n(&piece.rgba[static_cast<size_t>(y) * piece.width * 4], static_cast<size_t>(piece.width) * 4,
                &whole.rgba[(static_cast<size_t>(top + y) * whole.width + x0) * 4]);
}

}  // namespace rm
