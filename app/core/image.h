// Image: RGBA float pixels, top row first, as image files store them. GL's
// row 0 is the bottom; the code that talks to GL flips rows at that border.
#pragma once
#include <cstddef>
#include <vector>

namespace rm {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<float> rgba;
  const float* pixel(int x, int y) const { return &rgba[(static_cast<size_t>(y) * width + x) * 4]; }
  // Row order flipped: turns file order into GL order and back.
  Image flipped() const;
};

// The pixels as an 8-bit file or a video stores them: clamped to [0, 1], NaN
// as 0, rounded to the nearest of 256 steps.
std::vector<unsigned char> to_rgba8(const Image& image);

// Copies `piece` into `whole` with its bottom left corner at GL's (x0, y0)
// (origin at the bottom left): a tile of a picture drawn in parts.
void paste(Image& whole, const Image& piece, int x0, int y0);

}  // namespace rm
