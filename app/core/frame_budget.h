// The frame budget: how large a picture that is changing can be drawn so that
// a frame holds the target rate, and how to cut a picture that cannot be
// drawn within it into tiles, so that the program keeps reading its input
// between them. Both decide from measured draw times only; no GL here.
#pragma once
#include <array>
#include <glm/glm.hpp>

namespace rm {

// Picks the scale per axis (1 down to 1/8) at which a changing picture is
// drawn. A frame's cost is taken to grow with its pixels, so each measured
// frame gives an estimate of the full-size cost: ms / scale². The median of
// the last three estimates (one slow frame does not move it) chooses a step
// of a ladder 2^(-k/8). The scale goes down as soon as that median is over
// budget, and up only when three frames in a row say a larger step would
// take at most kRaiseAt of the budget: the band between kRaiseAt and kHoldAt
// is wider than one step, so it cannot oscillate between two. A frame also
// costs what does not grow with its pixels (the present, the events): the
// window measures that overhead between frames, and the steps are chosen
// so that drawing and overhead together fit.
class ScaleController {
 public:
  static constexpr int kSteps = 25;          // 1, 2^-1/8, ..., 1/8: each step 19% more pixels
  static constexpr double kHoldAt = 0.9;     // of the budget: above it, go down
  static constexpr double kRaiseAt = 0.65;   // of the budget: a larger step must fit under it
  // A window of fewer pixels draws in about what any draw costs: its frames
  // are not scaled up to a larger window's (resized).
  static constexpr double kFewPixels = 64.0 * 64.0;

  explicit ScaleController(double budget_ms) : budget_ms_(budget_ms) {}

  double scale() const { return scale_of(step_); }
  static double scale_of(int step);
  double budget_ms() const { return budget_ms_; }

  // A frame drawn at `scale` took `ms` to draw, and `overhead_ms` besides
  // (the rest of the interval since the frame before; 0: not known).
  void measured(double scale, double ms, double overhead_ms = 0);
  // The overhead the controller believes in: the median of the last three.
  double overhead_ms() const;
  // The full-size cost the controller believes in; 0 before any frame.
  double full_frame_ms() const;
  // What a frame at `scale` is expected to take; 0 before any frame.
  double predict_ms(double scale) const { return full_frame_ms() * scale * scale; }
  // Forget the measurements (a new program costs what it costs).
  void forget();
  // The window's full size is now `pixels`: the estimates, made at the size
  // before, grow or shrink with it, and the scale is chosen again from them
  // at once. (A window made larger would else draw its next frame at the old
  // scale: many budgets long, in one tile.) The first call only records it.
  // From fewer than kFewPixels, a larger window is measured again instead,
  // from the lowest step.
  void resized(double pixels);

 private:
  // The largest picture (the smallest step up to `to`) whose estimate fits
  // under `share` of the budget.
  int first_step_under(double share, int to) const;

  double budget_ms_;
  double full_pixels_ = 0;  // the window's pixels the estimates are for; 0: not told
  int step_ = 0;
  std::array<double, 3> estimates_{};  // full-size ms of the last frames
  std::array<double, 3> overheads_{};  // and what each cost besides its drawing
  size_t next_ = 0;                    // where the next estimate goes
  int count_ = 0;                      // how many of them are filled
  int raise_votes_ = 0;
};

// The next tile of a picture drawn in parts, rows from the top, sized so that
// it takes about `tile_ms` at the cost per pixel measured on the last tile
// (or the picture's average, if higher), and at most twice the last tile's
// pixels (a probe's at the least), plus the rest of its band when that is
// narrower than the band's tiles and both fit the time: no such sliver is
// drawn alone. A shader too heavy for a probe kProbe pixels square in the
// time is drawn in tiles of 8 or 4 pixels a side, and a picture of unknown
// cost starts with one kSmallest pixels square, so that however heavy the
// shader, one tile holds the window for as little as it can.
class TilePlan {
 public:
  static constexpr int kProbe = 16;    // a band's tiles' side, unless too heavy for it
  static constexpr int kSmallest = 4;  // the smallest tile's side, in pixels

  // size: the picture's; per_pixel_ms: its average cost per pixel when
  // known (the last frame's), or 0: then a smallest tile finds out.
  TilePlan(glm::ivec2 size, double tile_ms, double per_pixel_ms = 0);

  bool done() const { return y_top_ <= 0; }
  // The next tile as x, y, width, height in GL's coordinates (origin at the
  // bottom left). Tiles are whole rows of the picture when a row fits the
  // time, and else parts of one band of rows.
  glm::ivec4 next() const;
  // The tile next() gave was drawn in `ms`.
  void drawn(glm::ivec4 tile, double ms);
  double per_pixel_ms() const { return per_pixel_ms_; }
  double drawn_ms() const { return drawn_ms_; }  // the sum over the tiles drawn

 private:
  glm::ivec2 size_;
  double tile_ms_;
  double per_pixel_ms_;
  double typical_ms_;  // the picture's known average per pixel; 0: unknown
  int y_top_;       // rows above it are drawn (GL rows, counted from the bottom)
  int x_ = 0;       // in the band being drawn in parts: columns left of it are drawn
  int band_ = 0;    // the band's height while it is drawn in parts; 0: none
  double drawn_ms_ = 0;
  double last_pixels_ = 0;  // of the last tile drawn
};

}  // namespace rm
