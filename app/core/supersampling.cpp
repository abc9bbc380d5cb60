#include "core/supersampling.h"

#include <cmath>

namespace rm {

namespace {

// The radical inverse of `index` in `base`: its digits mirrored behind the point.
float radical_inverse(int index, int base) {
  double result = 0.0, digit = 1.0 / base;
  for (int i = index; i > 0; i /= base, digit /= base) result += digit * (i % base);
  return static_cast<float>(result);
}

}  // namespace

glm::vec2 sample_offset(int index) {
  // Shifted by half a pixel with wrap-around, so that index 0 (0, 0) is the centre.
  const glm::vec2 halton(radical_inverse(index, 2), radical_inverse(index, 3));
  return glm::fract(halton + 0.5f) - 0.5f;
}

float sample_weight(int index) { return 1.0f / static_cast<float>(index + 1); }

double motion_offset(int index, const MotionBlur& motion) {
  if (motion.steps <= 1 || motion.shutter <= 0) return 0.0;
  const double step = (index % motion.steps + 0.5) / motion.steps - 0.5;
  return motion.shutter / motion.fps * step;
}

}  // namespace rm
