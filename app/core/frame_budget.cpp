#include "core/frame_budget.h"

#include <algorithm>
#include <cmath>

namespace rm {

double ScaleController::scale_of(int step) { return std::pow(2.0, -step / 8.0); }

namespace {

// The median of the first `count` values (the mean of two).
double median_of(std::array<double, 3> v, int count) {
  if (count == 0) return 0;
  if (count == 1) return v[0];
  if (count == 2) return (v[0] + v[1]) / 2;
  std::sort(v.begin(), v.end());
  return v[1];
}

}  // namespace

double ScaleController::full_frame_ms() const { return median_of(estimates_, count_); }
double ScaleController::overhead_ms() const { return median_of(overheads_, count_); }

void ScaleController::measured(double scale, double ms, double overhead_ms) {
  estimates_[next_] = ms / (scale * scale);
  overheads_[next_] = std::max(0.0, overhead_ms);
  next_ = (next_ + 1) % estimates_.size();
  count_ = std::min(count_ + 1, 3);
  // Over budget where it is: down at once, as far as the estimate says.
  const int hold = std::min(first_step_under(kHoldAt, kSteps), kSteps - 1);
  if (hold > step_) {
    step_ = hold;
    raise_votes_ = 0;
    return;
  }
  // Room for a larger picture: up only when three frames in a row agree.
  const int raise = first_step_under(kRaiseAt, step_);
  if (raise < step_ && ++raise_votes_ >= 3) {
    step_ = raise;
    raise_votes_ = 0;
  } else if (raise >= step_) {
    raise_votes_ = 0;
  }
}

int ScaleController::first_step_under(double share, int to) const {
  const double full = full_frame_ms(), fixed = overhead_ms();
  for (int k = 0; k < to; ++k)
    if (full * scale_of(k) * scale_of(k) + fixed <= share * budget_ms_) return k;
  return to;
}

void ScaleController::resized(double pixels) {
  if (pixels <= 0 || pixels == full_pixels_) return;
  if (full_pixels_ > 0 && count_ > 0 && full_pixels_ < kFewPixels && pixels > full_pixels_) {
    // What a window this small draws in is what any draw costs: it says
    // nothing of the cost of a pixel. Measured again, from the lowest step.
    forget();
    step_ = kSteps - 1;
  } else if (full_pixels_ > 0 && count_ > 0) {
    for (int i = 0; i < count_; ++i) estimates_[static_cast<size_t>(i)] *= pixels / full_pixels_;
    step_ = std::min(first_step_under(kHoldAt, kSteps), kSteps - 1);
    raise_votes_ = 0;
  }
  full_pixels_ = pixels;
}

void ScaleController::forget() {
  count_ = 0;
  next_ = 0;
  raise_votes_ = 0;
}

TilePlan::TilePlan(glm::ivec2 size, double tile_ms, double per_pixel_ms)
    : size_(size), tile_ms_(tile_ms), per_pixel_ms_(per_pixel_ms), typical_ms_(per_pixel_ms), y_top_(size.y),
      last_pixels_(per_pixel_ms > 0 ? double(size.x) * size.y : 0) {}

namespace {

// The side of a band's tiles for tiles of about `pixels`: a probe's, or for
// a shader too heavy for that in the time, the largest of 8 and 4 that fits
// (4 at the least).
int band_side(double pixels) {
  int side = TilePlan::kProbe;
  while (side > TilePlan::kSmallest && double(side) * side > pixels) side /= 2;
  return side;
}

}  // namespace

glm::ivec4 TilePlan::next() const {
  // Twice the last tile at most: the cost of the rows ahead is unknown, and
  // cheap sky above must not send the whole scene below into one tile. A
  // picture of unknown cost starts with the smallest tile: a shader of
  // seconds a probe holds the window for a sixteenth of that.
  const double probe = double(kProbe) * kProbe;
  const double pixels = per_pixel_ms_ > 0 ? std::min(tile_ms_ / per_pixel_ms_, std::max(probe, 2.0 * last_pixels_))
                                          : double(kSmallest) * kSmallest;
  if (x_ == 0) {
    const int rows = static_cast<int>(std::min(pixels / size_.x, double(size_.y)));
    if (rows >= kSmallest || rows >= y_top_) {  // whole rows
      const int h = std::min(rows, y_top_);
      return {0, y_top_ - h, size_.x, h};
    }
  }
  // A band of rows, drawn in parts from the left.
  const int band = x_ > 0 ? band_ : std::min(band_side(pixels), y_top_);
  int width = std::clamp(static_cast<int>(pixels / band), std::min(band, size_.x - x_), size_.x - x_);
  // A rest of the band narrower than its tiles' side goes with this tile: a
  // sliver costs a draw of its own, and its cost per pixel, mostly the
  // draw's, would send the next tile back to the smallest (a reload's first
  // picture of cubes took 61 tiles, not 10). Not when the cost is known to
  // be too high for both in one tile: a shader too heavy for a probe in the
  // time is drawn in tiles no larger than its band's side, so the watchdog
  // times each of them.
  const int rest = size_.x - x_ - width;
  const bool too_heavy = per_pixel_ms_ > 0 && double(width + rest) * band * per_pixel_ms_ > tile_ms_;
  if (rest < band && !too_heavy) width += rest;
  return {x_, y_top_ - band, width, band};
}

void TilePlan::drawn(glm::ivec4 tile, double ms) {
  drawn_ms_ += ms;
  // A band's last part is what was left of it, not a size the plan chose:
  // it does not hold back the next tile's growth.
  const double pixels = double(tile.z) * tile.w;
  const bool ends_band = tile.x + tile.z >= size_.x;
  last_pixels_ = ends_band && tile.x > 0 ? std::max(last_pixels_, pixels) : pixels;
  // The cost of this tile, but falling by at most half per tile, and never
  // under the picture's average when that is known.
  const double cost = std::max(ms, 1e-6) / pixels;
  per_pixel_ms_ = std::max({cost, per_pixel_ms_ / 2, typical_ms_});
  if (ends_band) {
    x_ = 0;
    band_ = 0;
    y_top_ = tile.y;
  } else {
    x_ = tile.x + tile.z;
    band_ = tile.w;
  }
}

}  // namespace rm
